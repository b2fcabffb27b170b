//! `lpe-check equiv --dialect-a renderman --dialect-b osl A B` (or the other way round):
//! does a RenderMan expression mean what an OSL expression means, under the
//! correspondence ([`lpe::translate::cross::compare`])?
//!
//! Prints `equivalent` (exit 0), or `not equivalent` and, for each side that has one, a
//! shortest RenderMan path with its OSL view that only that side matches (exit 1). Every
//! witness is re-checked with both reference matchers first; a failed re-check exits 3.
//! Errors exit 2.

use std::process::ExitCode;

use lpe::osl;
use lpe::renderman;
use lpe::translate::{cross, Correspondence, CrossComparison, Witness};
use lpe::DialectName;

use crate::input::bad_input;
use crate::witness::{self, recheck, Disagreement, Expect};

/// What `equiv` passes on: the two expressions, A's dialect (B's is the other one), the
/// `--correspondence` text, and whether `--ini` or `--register` was given.
pub struct Request<'a> {
    /// Expression A.
    pub a: &'a str,
    /// Expression B.
    pub b: &'a str,
    /// A's dialect.
    pub a_dialect: DialectName,
    /// The declaration applied to the default correspondence.
    pub correspondence: &'a str,
    /// `--ini` or `--register` given (refused here).
    pub registration_given: bool,
}

/// Runs the cross-dialect comparison.
pub fn run(args: &Request) -> ExitCode {
    if args.registration_given {
        return bad_input(
            "error: --ini and --register are not read by a cross-dialect comparison \
             (the correspondence is over the default registrations)",
        );
    }
    let corr = match Correspondence::parse(args.correspondence) {
        Ok(c) => c,
        Err(e) => return bad_input(format!("error: --correspondence: {e}")),
    };
    let (rm_text, osl_text, rm_name, osl_name) = match args.a_dialect {
        DialectName::RenderMan => (args.a, args.b, "A", "B"),
        DialectName::Osl => (args.b, args.a, "B", "A"),
    };
    let rm = match renderman::parse(rm_text) {
        Ok(e) => e,
        Err(e) => return bad_input(format!("error: {rm_name} (RenderMan): {e}")),
    };
    let f = match osl::parse_source(osl_text, &osl::Registered::none()) {
        Ok(e) => e,
        Err(e) => return bad_input(format!("error: {osl_name} (OSL): {e}")),
    };
    let c = match cross::compare(&rm, &f, &corr) {
        Ok(c) => c,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    witness::exit_with(report(&rm, &f, &c, rm_name, osl_name), c.equivalent())
}

fn show(w: &Witness) -> String {
    match &w.osl {
        Some(o) => format!("{} (OSL {o})", w.renderman),
        None => format!("{} (no OSL view)", w.renderman),
    }
}

/// The text printed for a cross comparison, after re-checking its witnesses.
pub fn report(
    rm: &renderman::Lpe,
    f: &osl::Lpe,
    c: &CrossComparison,
    rm_name: &str,
    osl_name: &str,
) -> Result<String, Disagreement> {
    if c.equivalent() {
        return Ok("equivalent\n".to_string());
    }
    let (rs, os) = (rm.to_string(), f.to_string());
    let check = |w: &Witness, rm_matches: bool| -> Result<(), Disagreement> {
        recheck(
            &w.renderman,
            &[Expect {
                name: &rs,
                lpe: rm,
                matches: rm_matches,
            }],
        )?;
        if let Some(o) = &w.osl {
            recheck(
                o,
                &[Expect {
                    name: &os,
                    lpe: f,
                    matches: !rm_matches,
                }],
            )?;
        }
        Ok(())
    };
    let mut lines: Vec<(String, String)> = Vec::new();
    if let Some(w) = &c.renderman_only {
        check(w, true)?;
        lines.push((rm_name.to_string(), show(w)));
    }
    if let Some(w) = &c.osl_only {
        check(w, false)?;
        lines.push((osl_name.to_string(), show(w)));
    }
    if let Some(p) = &c.outside {
        recheck(
            p,
            &[Expect {
                name: &rs,
                lpe: rm,
                matches: true,
            }],
        )?;
        lines.push((rm_name.to_string(), format!("{p} (no OSL view)")));
    }
    lines.sort();
    let mut out = String::from("not equivalent\n");
    for (side, w) in lines {
        out.push_str(&format!("only {side}: {w}\n"));
    }
    Ok(out)
}
