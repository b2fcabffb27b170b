//! `lpe-render`: not built yet (see the renderer issue). Exits with an error rather
//! than pretending to render.

fn main() {
    eprintln!("lpe-render is not implemented yet; use `lpe-check` (see README.md)");
    std::process::exit(2);
}
