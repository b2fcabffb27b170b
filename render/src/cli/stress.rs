//! `lpe-render stress`: the hard-case scene set.

use lpe_render::verify::stress;

use crate::args::InputError;

pub fn run(quick: bool) -> Result<bool, InputError> {
    let rows = stress::run(quick)?;
    println!("{}", stress::markdown(&rows));
    Ok(rows.iter().all(|r| r.passed))
}
