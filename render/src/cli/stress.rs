//! `lpe-render stress`: the hard-case scene set.

use lpe_render::verify::stress;

use crate::args::InputError;

pub fn run(quick: bool) -> Result<bool, InputError> {
    let rows = stress::run(quick)?;
    println!("{}", lpe_render::verify::tables::stress(&rows));
    Ok(rows.iter().all(|r| r.passed))
}
