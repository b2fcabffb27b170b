//! `lpe-workspace-hack`: no code, only dependencies. It names every third-party crate
//! whose features would otherwise differ between the workspace's builds (`cargo run -p
//! lpe-render`, `cargo test --workspace`, `cargo build -p lpe-cli`, ...), with the union
//! of those features, so that each build selects the same features and reuses the
//! others' artifacts instead of compiling the dependency graph again. `cargo hakari`
//! writes its `Cargo.toml` (`cargo hakari generate`, then `cargo hakari manage-deps`) from
//! `.config/hakari.toml`; `tests/tests/workspace_hack.rs` fails when it is out of date.
