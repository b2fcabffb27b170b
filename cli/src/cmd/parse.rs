//! `lpe-check parse EXPR`: the canonical form, or the error with a caret (exit 2).

use std::process::ExitCode;

use crate::input::{bad_input, load_parser};

/// Arguments of `lpe-check parse`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The expression, e.g. `lpe:C<RD>.+[<L.>O]` or a macro name such as `directDiffuse_key`.
    pub expr: String,
    /// A rendermn.ini-style file with user macros and lobe mappings.
    #[arg(long)]
    pub ini: Option<std::path::PathBuf>,
}

/// Prints the canonical form of the expression.
pub fn run(args: Args) -> ExitCode {
    let parser = match load_parser(args.ini.as_deref()) {
        Ok(p) => p,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    match parser.parse(&args.expr) {
        Ok(lpe) => {
            println!("{lpe}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{e}");
            ExitCode::from(2)
        }
    }
}
