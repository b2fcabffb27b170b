//! `lpe-check parse EXPR`: the canonical form, or the error with a caret (exit 2).
//!
//! `--dialect osl` parses OSL (with `--register`'d user labels) and prints the expanded
//! form (every item a whole vertex pattern `<event scattering custom…>`), OSL's
//! warnings on stderr.

use std::process::ExitCode;

use lpe::osl;

use crate::input::{bad_input, load_parser, osl_error, DialectArgs};

/// Arguments of `lpe-check parse`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The expression, e.g. `lpe:C<RD>.+[<L.>O]` or a macro name such as `directDiffuse_key`.
    pub expr: String,
    /// A rendermn.ini-style file with user macros and lobe mappings.
    #[arg(long)]
    pub ini: Option<std::path::PathBuf>,
    /// `--dialect` and `--register`.
    #[command(flatten)]
    pub lang: DialectArgs,
}

/// Prints the canonical form of the expression.
pub fn run(args: Args) -> ExitCode {
    match args.lang.is_osl() {
        Ok(true) => return run_osl(&args),
        Ok(false) => {}
        Err(e) => return bad_input(format!("error: {e}")),
    }
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

/// `parse --dialect osl`.
fn run_osl(args: &Args) -> ExitCode {
    let registered = match args.lang.registered(args.ini.as_deref()) {
        Ok(r) => r,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    match osl::parse_source(&args.expr, &registered) {
        Ok(lpe) => {
            for w in &lpe.warnings {
                eprintln!("warning: {w}");
            }
            println!("{lpe}");
            ExitCode::SUCCESS
        }
        Err(e) => bad_input(osl_error(&args.expr, &e)),
    }
}
