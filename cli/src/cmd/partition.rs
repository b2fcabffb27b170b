//! `lpe-check partition EXPR... [--universe U]`: does a set of AOVs split the universe
//! (default `C.*[<L.>O]`) into disjoint parts that cover it?
//!
//! Each `EXPR` is `name=expression` or just an expression or macro (then named by its
//! text). Prints the emptiness warnings, then every overlapping pair with the shortest
//! path both match, the shortest universe path no AOV matches, and for each AOV that
//! matches outside the universe the shortest such path; `clean partition` if there is
//! none of these (exit 0), else exit 1. A gap comes with the remainder AOV that closes
//! it, the universe minus every AOV in set algebra (`C.*[<L.>O] - (a|b|c)`), which
//! parses as printed. Witnesses are re-checked with the reference
//! matcher before printing ([`report`], in `lpe-lint`); a failed re-check exits 3; errors
//! exit 2.
//!
//! `--dialect osl [--register …]` checks OSL AOVs (default universe
//! `C<[RT][DGS]>*[LO]`, which is also the domain every OSL search runs over).

use std::process::ExitCode;

use lpe::analysis::{self, Decision};
use lpe::{with_dialect, AovSet, Options};
use lpe_lint::check::partition::report;

use crate::dialect::CliDialect;
use crate::input::{bad_input, DialectArgs};
use crate::witness;

/// Arguments of `lpe-check partition`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The universe to partition (default `C.*[<L.>O]`, OSL: `C<[RT][DGS]>*[LO]`).
    #[arg(long)]
    pub universe: Option<String>,
    /// `--dialect` and `--register`.
    #[command(flatten)]
    pub lang: DialectArgs,
    /// A rendermn.ini-style file with user macros and lobe mappings.
    #[arg(long)]
    pub ini: Option<std::path::PathBuf>,
    /// The AOVs: `name=expression`, or an expression or macro name.
    #[arg(required = true)]
    pub aovs: Vec<String>,
    /// `--max-steps` and `--max-seconds`.
    #[command(flatten)]
    pub budget: witness::BudgetArgs,
}

/// Runs `lpe-check partition`.
pub fn run(args: Args) -> ExitCode {
    with_dialect!(args.lang.dialect(), D => run_in::<D>(&args))
}

fn run_in<D: CliDialect>(args: &Args) -> ExitCode {
    let registration = match args.lang.registration::<D>(args.ini.as_deref()) {
        Ok(r) => r,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let parse = |s: &str| D::parse_arg(s, &registration).map_err(|e| D::error_line(s, &e));
    let universe_text = args.universe.as_deref().unwrap_or(D::DEFAULT_UNIVERSE);
    let prepared = parse(universe_text).and_then(|u| Ok((named(&args.aovs, parse)?, u)));
    let (aovs, universe) = match prepared {
        Ok(p) => p,
        Err(e) => return bad_input(e),
    };
    if let Ok(set) = AovSet::<D>::compile_under(&aovs, &registration, &Options::default()) {
        for w in analysis::warnings(&set) {
            println!("warning: {w}");
        }
    }
    let budget = args.budget.budget();
    let p = match analysis::partition_within(&aovs, &universe, &registration, &budget) {
        Ok(Decision::Decided(p)) => p,
        Ok(Decision::Undecided(u)) => return witness::exit_undecided(&u),
        Err(e) => return bad_input(format!("error: {e}")),
    };
    witness::exit_with(report(&aovs, &universe, &p), p.is_clean())
}

/// The AOV arguments, each `name=expression` or an expression named by its text.
fn named<E, X>(
    aovs: &[String],
    parse: impl Fn(&str) -> Result<E, X>,
) -> Result<Vec<(String, E)>, X> {
    aovs.iter()
        .map(|a| {
            // `name=expr` only when the part before `=` is a plain name: `=` never
            // occurs in expressions, but keep odd input an expression error.
            match a.split_once('=') {
                Some((n, e))
                    if !n.is_empty() && n.chars().all(|c| c.is_alphanumeric() || c == '_') =>
                {
                    Ok((n.to_string(), parse(e)?))
                }
                _ => Ok((a.clone(), parse(a)?)),
            }
        })
        .collect()
}
