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
//! matcher before printing ([`crate::witness`]); a failed re-check exits 3; errors exit 2.
//!
//! `--dialect osl [--register …]` checks OSL AOVs (default universe
//! `C<[RT][DGS]>*[LO]`, which is also the domain every OSL search runs over).

use std::process::ExitCode;

use lpe::analysis::{self, Partition};
use lpe::renderman::Lpe;
use lpe::{osl, AovSet, Options};

use crate::input::{bad_input, load_parser, osl_error, DialectArgs, InputError};
use crate::witness::{self, Checked, Disagreement, Expect};

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
}

/// Runs `lpe-check partition`.
pub fn run(args: Args) -> ExitCode {
    match args.lang.is_osl() {
        Ok(true) => return run_osl(&args),
        Ok(false) => {}
        Err(e) => return bad_input(format!("error: {e}")),
    }
    match prepare(&args) {
        Ok((aovs, universe)) => {
            let warnings = AovSet::compile(&aovs)
                .map(|s| analysis::warnings(&s))
                .unwrap_or_default();
            for w in warnings {
                println!("warning: {w}");
            }
            let p = match analysis::partition(&aovs, &universe, &lpe::renderman::Parser::default())
            {
                Ok(p) => p,
                Err(e) => return bad_input(format!("error: {e}")),
            };
            witness::exit_with(report(&aovs, &universe, &p), p.is_clean())
        }
        Err(e) => bad_input(format!("error: {e}")),
    }
}

/// `partition --dialect osl`.
fn run_osl(args: &Args) -> ExitCode {
    let registered = match args.lang.registered(args.ini.as_deref()) {
        Ok(r) => r,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let parse = |s: &str| osl::parse_source(s, &registered).map_err(|e| osl_error(s, &e));
    let universe_text = args.universe.as_deref().unwrap_or(lpe::osl::UNIVERSE);
    let prepared = parse(universe_text).and_then(|u| Ok((named(&args.aovs, |e| parse(e))?, u)));
    let (aovs, universe) = match prepared {
        Ok(p) => p,
        Err(e) => return bad_input(e),
    };
    if let Ok(set) = AovSet::compile_under(&aovs, &registered, &Options::default()) {
        for w in set.warnings() {
            println!("warning: {w}");
        }
    }
    let p = match analysis::partition(&aovs, &universe, &registered) {
        Ok(p) => p,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    witness::exit_with(report(&aovs, &universe, &p), p.is_clean())
}

type Named = Vec<(String, Lpe)>;

fn prepare(args: &Args) -> Result<(Named, Lpe), InputError> {
    let parser = load_parser(args.ini.as_deref())?;
    let parse = |s: &str| parser.parse(s).map_err(InputError::from);
    let universe = parse(
        args.universe
            .as_deref()
            .unwrap_or(<lpe::renderman::RenderMan as lpe::Dialect>::DEFAULT_UNIVERSE),
    )?;
    Ok((named(&args.aovs, parse)?, universe))
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

/// The text printed for a partition check, after re-checking every witness.
pub fn report<E: Checked>(
    aovs: &[(String, E)],
    universe: &E,
    p: &Partition<E::Path>,
) -> Result<String, Disagreement> {
    let uname = format!("universe {universe}");
    let mut out = format!("partition of {universe} by {} AOVs\n", aovs.len());
    for (i, j, path) in &p.overlaps {
        let (a, b) = (&aovs[*i], &aovs[*j]);
        witness::recheck(
            path,
            &[
                Expect {
                    name: &uname,
                    lpe: universe,
                    matches: true,
                },
                Expect {
                    name: &a.0,
                    lpe: &a.1,
                    matches: true,
                },
                Expect {
                    name: &b.0,
                    lpe: &b.1,
                    matches: true,
                },
            ],
        )?;
        out.push_str(&format!("overlap: {} & {}: {path}\n", a.0, b.0));
    }
    if let Some(path) = &p.gap {
        let mut expects = vec![Expect {
            name: &uname,
            lpe: universe,
            matches: true,
        }];
        expects.extend(aovs.iter().map(|(n, l)| Expect {
            name: n,
            lpe: l,
            matches: false,
        }));
        witness::recheck(path, &expects)?;
        out.push_str(&format!("gap: {path}\n"));
        let rest = E::remainder(aovs, universe);
        witness::recheck(
            path,
            &[Expect {
                name: "remainder",
                lpe: &rest,
                matches: true,
            }],
        )?;
        out.push_str(&format!("remainder: {rest}\n"));
    }
    for (i, path) in &p.outside {
        let a = &aovs[*i];
        witness::recheck(
            path,
            &[
                Expect {
                    name: &uname,
                    lpe: universe,
                    matches: false,
                },
                Expect {
                    name: &a.0,
                    lpe: &a.1,
                    matches: true,
                },
            ],
        )?;
        out.push_str(&format!("outside: {}: {path}\n", a.0));
    }
    if p.is_clean() {
        out.push_str("clean partition\n");
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::macros::BASIC;

    fn basic() -> Named {
        BASIC
            .iter()
            .map(|(n, s)| (n.to_string(), lpe::renderman::parse(s).unwrap()))
            .collect()
    }

    #[test]
    fn basic_set_is_clean() {
        let u = analysis::default_universe::<lpe::renderman::RenderMan>(
            &lpe::renderman::Parser::default(),
        );
        let p = analysis::partition(&basic(), &u, &lpe::renderman::Parser::default()).unwrap();
        let text = report(&basic(), &u, &p).unwrap();
        assert!(text.ends_with("clean partition\n"), "{text}");
    }

    #[test]
    fn caustics_overlap_is_printed_with_its_witness() {
        let mut aovs = basic();
        aovs.push((
            "caustics".into(),
            lpe::renderman::parse("caustics").unwrap(),
        ));
        let u = analysis::default_universe::<lpe::renderman::RenderMan>(
            &lpe::renderman::Parser::default(),
        );
        let p = analysis::partition(&aovs, &u, &lpe::renderman::Parser::default()).unwrap();
        let text = report(&aovs, &u, &p).unwrap();
        assert!(
            text.contains("overlap: indirectDiffuse & caustics: C RD"),
            "{text}"
        );
        assert!(!text.contains("clean"), "{text}");
    }

    #[test]
    fn a_wrong_witness_is_refused_not_printed() {
        let aovs = basic();
        let u = analysis::default_universe::<lpe::renderman::RenderMan>(
            &lpe::renderman::Parser::default(),
        );
        // `C RD L` is directDiffuse alone: not a gap.
        let forged = Partition {
            overlaps: Vec::new(),
            gap: Some("C RD L".parse().unwrap()),
            outside: Vec::new(),
        };
        let err = report(&aovs, &u, &forged).unwrap_err().to_string();
        assert!(err.contains("directDiffuse"), "{err}");
    }

    #[test]
    fn a_gap_comes_with_a_remainder_that_parses_and_closes_it() {
        let mut aovs = basic();
        aovs.retain(|(n, _)| n != "subsurface" && n != "emissive");
        let u = analysis::default_universe::<lpe::renderman::RenderMan>(
            &lpe::renderman::Parser::default(),
        );
        let p = analysis::partition(&aovs, &u, &lpe::renderman::Parser::default()).unwrap();
        let text = report(&aovs, &u, &p).unwrap();
        let line = text
            .lines()
            .find_map(|l| l.strip_prefix("remainder: "))
            .unwrap_or_else(|| panic!("{text}"));
        assert!(line.starts_with("C.*[<L.>O] - ((C<RD>[<L.>O])|"), "{line}");
        // Added as an AOV, the printed text closes the gap (and overlaps nothing).
        aovs.push(("rest".into(), lpe::renderman::parse(line).unwrap()));
        let closed = analysis::partition(&aovs, &u, &lpe::renderman::Parser::default()).unwrap();
        assert!(closed.is_clean(), "{closed:?}");
        // It covers exactly the two AOVs left out (their union, within the universe).
        let union = "C.*[<L.>O] - (C.*[<L.>O] - subsurface - emissive)";
        let c = analysis::compare(
            &lpe::renderman::parse(line).unwrap(),
            &lpe::renderman::parse(union).unwrap(),
        );
        assert!(c.unwrap().equivalent(), "{line}");
    }
}
