//! `lpe-check equiv A B`: are two expressions equivalent on every path?
//!
//! Prints `equivalent` (exit 0), or `not equivalent` with the shortest path matched by
//! one and not the other, for each direction that has one, and which inclusion holds
//! (exit 1). Every witness is re-checked with the reference matcher first
//! ([`crate::witness`]); a failed re-check exits 3. Errors exit 2.
//!
//! `--dialect osl [--register …]` compares two OSL expressions; witnesses are OSL paths.
//! `--dialect-a renderman --dialect-b osl` (either way round) compares a RenderMan and an
//! OSL expression under the correspondence of docs/language.md §19 (`--correspondence`
//! changes it): witnesses are RenderMan paths with their OSL views.

use std::process::ExitCode;

use std::fmt::Display;

use lpe::analysis::{self, Comparison, Decision};
use lpe::{with_dialect, DialectLpe};

use crate::dialect::CliDialect;
use crate::input::{bad_input, DialectArgs};
use crate::witness::{self, Checked, Disagreement, PathOf};

/// Arguments of `lpe-check equiv`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// A rendermn.ini-style file with user macros and lobe mappings.
    #[arg(long)]
    pub ini: Option<std::path::PathBuf>,
    /// The first expression.
    pub a: String,
    /// The second expression.
    pub b: String,
    /// `--dialect` and `--register`.
    #[command(flatten)]
    pub lang: DialectArgs,
    /// The dialect of A, when it differs from B's (default: `--dialect`).
    #[arg(long)]
    pub dialect_a: Option<lpe::DialectName>,
    /// The dialect of B, when it differs from A's (default: `--dialect`).
    #[arg(long)]
    pub dialect_b: Option<lpe::DialectName>,
    /// Cross-dialect only: changes to the default correspondence (docs/language.md §19.1).
    #[arg(long, default_value = "")]
    pub correspondence: String,
    /// `--max-steps` and `--max-seconds`.
    #[command(flatten)]
    pub budget: witness::BudgetArgs,
}

/// Runs `lpe-check equiv`.
pub fn run(args: Args) -> ExitCode {
    let a = args.dialect_a.unwrap_or(args.lang.dialect());
    let b = args.dialect_b.unwrap_or(args.lang.dialect());
    if a != b {
        return super::equiv_cross::run(&super::equiv_cross::Request {
            a: &args.a,
            b: &args.b,
            a_dialect: a,
            correspondence: &args.correspondence,
            registration_given: args.ini.is_some() || args.lang.register.is_some(),
        });
    }
    let mut args = args;
    if args.dialect_a.is_some() {
        args.lang.dialect = Some(a);
    }
    with_dialect!(a, D => run_in::<D>(&args))
}

fn run_in<D: CliDialect>(args: &Args) -> ExitCode {
    let registration = match args.lang.registration::<D>(args.ini.as_deref()) {
        Ok(r) => r,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let parse = |s: &str| D::parse_arg(s, &registration).map_err(|e| D::error_line(s, &e));
    let (a, b) = match (parse(&args.a), parse(&args.b)) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(e), _) | (_, Err(e)) => return bad_input(e),
    };
    let c = match analysis::compare_within(&a, &b, &args.budget.budget()) {
        Ok(Decision::Decided(c)) => c,
        Ok(Decision::Undecided(u)) => return witness::exit_undecided(&u),
        Err(e) => return bad_input(format!("error: {e}")),
    };
    witness::exit_with(report(&a, &b, &c), c.equivalent())
}

/// The text printed for a comparison, after re-checking its witnesses.
pub fn report<L>(a: &L, b: &L, c: &Comparison<PathOf<L>>) -> Result<String, Disagreement>
where
    L: DialectLpe + Display,
    L::Dialect: Checked,
{
    let (sa, sb) = (a.to_string(), b.to_string());
    lpe_lint::witness::recheck_comparison((&sa, a), (&sb, b), c)?;
    if c.equivalent() {
        return Ok("equivalent\n".to_string());
    }
    let mut out = String::from("not equivalent\n");
    if let Some(p) = &c.first_only {
        out.push_str(&format!("only A: {p}\n"));
    }
    if let Some(p) = &c.second_only {
        out.push_str(&format!("only B: {p}\n"));
    }
    match (&c.first_only, &c.second_only) {
        (None, Some(_)) => out.push_str("A is strictly included in B\n"),
        (Some(_), None) => out.push_str("B is strictly included in A\n"),
        _ => {}
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::Lpe;

    fn lpe(s: &str) -> Lpe {
        lpe::renderman::parse(s).unwrap()
    }

    #[test]
    fn reports_inclusion_with_a_rechecked_witness() {
        let (a, b) = (lpe("C.+L"), lpe("C.*L"));
        let text = report(&a, &b, &analysis::compare(&a, &b).unwrap()).unwrap();
        assert_eq!(
            text,
            "not equivalent\nonly B: C L\nA is strictly included in B\n"
        );
    }

    #[test]
    fn a_wrong_witness_is_refused_not_printed() {
        let (a, b) = (lpe("C.+L"), lpe("C.*L"));
        // `C RD L` is matched by both: claiming it is only in A must fail the re-check.
        let forged = Comparison {
            first_only: Some("C RD L".parse().unwrap()),
            second_only: None,
        };
        let err = report(&a, &b, &forged).unwrap_err().to_string();
        assert!(err.contains("internal disagreement"), "{err}");
    }
}
