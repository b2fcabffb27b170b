//! `lpe-check parse EXPR`: the canonical form, or the error with a caret (exit 2).
//!
//! `--dialect osl` parses OSL (with `--register`'d user labels) and prints the expanded
//! form (every item a whole vertex pattern `<event scattering custom…>`), OSL's
//! warnings on stderr.

use std::process::ExitCode;

use lpe::with_dialect;

use crate::dialect::CliDialect;
use crate::input::{bad_input, DialectArgs};

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
    with_dialect!(args.lang.dialect(), D => run_in::<D>(&args))
}

fn run_in<D: CliDialect>(args: &Args) -> ExitCode {
    let registration = match args.lang.registration::<D>(args.ini.as_deref()) {
        Ok(r) => r,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    match D::parse_arg(&args.expr, &registration) {
        Ok(lpe) => {
            for w in D::parse_warnings(&lpe) {
                eprintln!("warning: {w}");
            }
            println!("{lpe}");
            ExitCode::SUCCESS
        }
        Err(e) => bad_input(D::show_error(&args.expr, &e)),
    }
}
