//! The bodies of the fuzz targets in `fuzz/`, as plain functions.
//!
//! Each takes the fuzzer's raw input and panics when a property fails, so the same
//! function serves `cargo fuzz run TARGET` (nightly or `-s none` on stable) and the
//! stable `cargo test` that replays every committed corpus and regression file
//! (`tests/tests/fuzz_replay.rs`).
//!
//! | target | property |
//! |---|---|
//! | `parse` | any bytes: the parser never panics; a parsed expression prints to text that parses back to the same AST and prints the same again |
//! | `path_text` | any bytes: the path parser never panics; a parsed path prints and re-parses to itself |
//! | `differential` | a structured expression and paths aimed at it: every engine agrees |
//! | `aov_set` | 2-6 structured expressions compiled as one set, paths aimed at them: every engine agrees |
//! | `osl_parse` | any bytes (a first line that parses as a registration applies): the OSL parser never panics; a parsed expression prints to text that parses back to the same tree |
//! | `osl_differential` | a structured registration, 1-4 OSL expressions (a set) and paths aimed at them: every engine agrees |

use arbitrary::Unstructured;
use lpe::renderman::{Lpe, Path};
use lpe::{osl, Options};
use lpe_testkit::generate::{self, Choices, Config};

use crate::adapters::{compile_set, Fast, Reference};
use crate::differential::{self, Agreement, Osl, Outcome};
use crate::engine::{Engine, EngineError, Matcher};
use crate::registry;

/// `parse`: never panics; parse -> print -> parse is the identity on the AST.
pub fn parse(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let Ok(lpe) = lpe::renderman::parse(&text) else {
        return;
    };
    let printed = lpe.to_string();
    let again = lpe::renderman::parse(&printed)
        .unwrap_or_else(|e| panic!("`{text}` printed as `{printed}`, which does not parse: {e}"));
    assert_eq!(
        again, lpe,
        "`{text}` printed as `{printed}` parses differently"
    );
    assert_eq!(again.to_string(), printed, "printing is not stable");
}

/// `path_text`: never panics; a parsed path prints and re-parses to itself.
pub fn path_text(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let Ok(path) = text.parse::<Path>() else {
        return;
    };
    let printed = path.to_string();
    let again: Path = printed
        .parse()
        .unwrap_or_else(|e| panic!("`{text}` printed as `{printed}`, which does not parse: {e}"));
    assert_eq!(
        again, path,
        "`{text}` printed as `{printed}` parses differently"
    );
}

fn paths_for(exprs: &[Lpe], u: &mut Unstructured<'_>, cfg: &Config) -> Vec<Path> {
    let n = 1 + u.below(8);
    (0..n)
        .map(|_| {
            let operands = exprs[u.below(exprs.len())].operands();
            let target = operands[u.below(operands.len())];
            generate::biased_path(target, u, cfg)
        })
        .collect()
}

/// Whether the engines were compared: the reference and at least one other engine
/// built the set. Fuzzed sets may exceed an engine's size limits, so fewer engines is
/// not a failure; it is just not an agreement, and the caller can count it.
fn agree(exprs: &[Lpe], paths: &[Path]) -> bool {
    compare(exprs, paths).engines >= 2
}

/// The agreement of every engine on `paths` (panics with the counterexample if two
/// differ, or if the reference refused the set).
fn compare(exprs: &[Lpe], paths: &[Path]) -> differential::Agreement {
    // The expression must survive its own canonical text, or the counterexample printed
    // below would not reproduce.
    for e in exprs {
        let text = e.to_string();
        match lpe::renderman::parse(&text) {
            Ok(back) => assert_eq!(&back, e, "`{text}` parses to another expression"),
            Err(err) => panic!("generated `{text}` does not parse: {err}"),
        }
    }
    let longest = paths.iter().map(Path::len).max().unwrap_or(0);
    let bounded: Vec<ForPaths> = ["fast", "nfa"]
        .map(|name| ForPaths::new(name, longest))
        .into();
    let engines: Vec<&dyn Engine> = if needs_bounding(exprs) {
        registry::all()
            .into_iter()
            .map(|e| match bounded.iter().find(|b| b.name == e.name()) {
                Some(b) => b as &dyn Engine,
                None => e,
            })
            .collect()
    } else {
        registry::all()
    };
    agreement(differential::check_with(&engines, exprs, paths))
}

/// Whether an outcome compared the reference with at least one other engine; panics on
/// a disagreement, or if the reference refused.
fn compared<L: differential::Language>(outcome: Outcome<L>) -> bool {
    agreement(outcome).engines >= 2
}

/// The agreement of an outcome; panics on a disagreement, or if the reference refused.
fn agreement<L: differential::Language>(outcome: Outcome<L>) -> Agreement {
    match outcome {
        Outcome::Disagree(c) => panic!("{c}"),
        Outcome::Agree(a) => {
            // The reference has no size limit; without it nothing says who is right.
            let reference = Reference.name();
            assert!(
                a.skipped.iter().all(|(name, _)| *name != reference),
                "the reference refused: {:?}",
                a.skipped
            );
            a
        }
    }
}

/// `osl_parse`: never panics; parse -> print -> parse gives the same tree. A first line
/// that parses as a registration (`events=U;scatters=Y`) applies to the rest.
pub fn osl_parse(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let (registered, src) = match text.split_once('\n') {
        Some((first, rest)) => match first.parse::<osl::Registered>() {
            Ok(r) => (r, rest),
            Err(_) => (osl::Registered::none(), &*text),
        },
        None => (osl::Registered::none(), &*text),
    };
    let Ok(lpe) = osl::parse(src, &registered) else {
        return;
    };
    let printed = lpe.to_string();
    let again = osl::parse(&printed, &registered).unwrap_or_else(|e| {
        panic!("`{src}` [{registered}] printed as `{printed}`, which does not parse: {e}")
    });
    assert_eq!(
        again.expr, lpe.expr,
        "`{src}` [{registered}] printed as `{printed}` parses differently"
    );
    assert_eq!(again.to_string(), printed, "printing is not stable");
}

/// `osl_differential`: a registration, a set of 1-4 OSL expressions and paths aimed at
/// them; every engine agrees.
pub fn osl_differential(data: &[u8]) {
    osl_differential_compared(data);
}

/// [`osl_differential`], returning whether at least two engines (the reference and
/// another) were compared.
pub fn osl_differential_compared(data: &[u8]) -> bool {
    let mut u = Unstructured::new(data);
    let cfg = generate::osl::Config::default();
    let registered = generate::osl::registered(&mut u);
    let n = 1 + u.below(4);
    let exprs: Vec<osl::Lpe> = (0..n)
        .map(|_| generate::osl::lpe(&mut u, &registered, &cfg))
        .collect();
    let paths: Vec<osl::Path> = (0..1 + u.below(8))
        .map(|_| {
            let operands = exprs[u.below(exprs.len())].operands();
            let target = operands[u.below(operands.len())];
            generate::osl::biased_path(target, &mut u, &registered, &cfg)
        })
        .collect();
    let lang = Osl { registered };
    compared(differential::check_in(
        &lang,
        &registry::all(),
        &exprs,
        &paths,
    ))
}

/// Sets that unroll to more atom positions than this (counted repetitions such as
/// `{0,123}`) compile the `fast` and `nfa` engines for the case's own paths only
/// ([`ForPaths`]). Such sets are about 5 % of fuzzed cases but took over 90 % of the
/// target's time, building and minimizing DFAs for paths hundreds of vertices long when
/// the case's paths have at most a dozen; smaller sets, most cases, still compile exact.
const EXACT_POSITIONS: u64 = 32;

fn needs_bounding(exprs: &[Lpe]) -> bool {
    let operands = exprs.iter().flat_map(|e| e.operands());
    operands.map(|o| o.positions()).sum::<u64>() > EXACT_POSITIONS
}

/// The `fast` or `nfa` engine (same name, same options otherwise) compiled with
/// [`Options::max_path_len`] set to the case's longest path: exact on every path the case
/// asks about, with `e{n,m}`, `m` over that length, built as `e{n,}`.
struct ForPaths {
    name: &'static str,
    opts: Options,
}

impl ForPaths {
    fn new(name: &'static str, longest: usize) -> ForPaths {
        let base = Options::default();
        ForPaths {
            name,
            opts: Options {
                dfa_budget: if name == Fast.name() {
                    base.dfa_budget
                } else {
                    0
                },
                lazy_cache: if name == Fast.name() {
                    base.lazy_cache
                } else {
                    0
                },
                max_path_len: Some(u32::try_from(longest).unwrap_or(u32::MAX)),
                ..base
            },
        }
    }
}

impl Engine for ForPaths {
    fn name(&self) -> &'static str {
        self.name
    }

    fn compile(&self, exprs: &[Lpe]) -> Result<Box<dyn Matcher + '_>, EngineError> {
        compile_set(exprs, &self.opts)
    }
}

/// `differential`: one structured expression, paths aimed at it, every engine agrees.
pub fn differential(data: &[u8]) {
    differential_compared(data);
}

/// [`differential()`], returning whether at least two engines (the reference and
/// another) were compared.
pub fn differential_compared(data: &[u8]) -> bool {
    let mut u = Unstructured::new(data);
    let cfg = Config::default();
    let e = generate::lpe(&mut u, &cfg);
    let paths = paths_for(std::slice::from_ref(&e), &mut u, &cfg);
    agree(std::slice::from_ref(&e), &paths)
}

/// `aov_set`: 2-6 structured expressions compiled as one set; every engine agrees on
/// which of them match each path.
pub fn aov_set(data: &[u8]) {
    aov_set_compared(data);
}

/// [`aov_set`], returning whether at least two engines (the reference and another)
/// were compared.
pub fn aov_set_compared(data: &[u8]) -> bool {
    let mut u = Unstructured::new(data);
    let cfg = Config::default().with_max_atoms(6);
    let n = 2 + u.below(5);
    let exprs: Vec<Lpe> = (0..n).map(|_| generate::lpe(&mut u, &cfg)).collect();
    let paths = paths_for(&exprs, &mut u, &cfg);
    agree(&exprs, &paths)
}

/// The differential target called `name`, returning whether engines were compared,
/// so a replay can count inputs that only one engine could build.
pub fn compared_target(name: &str) -> Option<fn(&[u8]) -> bool> {
    Some(match name {
        "differential" => differential_compared,
        "aov_set" => aov_set_compared,
        "osl_differential" => osl_differential_compared,
        _ => return None,
    })
}

/// The target called `name`, for replaying files by directory name.
pub fn target(name: &str) -> Option<fn(&[u8])> {
    Some(match name {
        "parse" => parse,
        "path_text" => path_text,
        "differential" => differential,
        "aov_set" => aov_set,
        "osl_parse" => osl_parse,
        "osl_differential" => osl_differential,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(srcs: &[&str]) -> Vec<Lpe> {
        srcs.iter()
            .map(|s| lpe::renderman::parse(s).unwrap())
            .collect()
    }

    fn paths(texts: &[&str]) -> Vec<Path> {
        texts.iter().map(|t| t.parse().unwrap()).collect()
    }

    #[test]
    fn only_sets_over_the_exact_limit_are_bounded() {
        // 2 positions per repetition of `(<RD>|<RS>)`, and C and L: 2 + 2n.
        assert!(!needs_bounding(&set(&["C(<RD>|<RS>){0,15}L"])));
        assert!(needs_bounding(&set(&["C(<RD>|<RS>){0,16}L"])));
        assert!(needs_bounding(&set(&["C<RD>{0,20}L", "C<RS>{0,20}L"])));
    }

    #[test]
    fn bounded_engines_are_exact_on_the_case_paths_and_all_four_are_compared() {
        // Counted repetitions far over the longest path (14 vertices), and one under it
        // that a bound shorter than the longest path would open up (`{1,4}` as `{1,}`
        // matches the 12-RD path): the bounded `fast` and `nfa` engines must answer
        // like the reference on every path, or `compare` panics with the counterexample.
        let exprs = set(&[
            "C<RD>{3,200}L",
            "C(<RD>|<RS>){0,100}<RS>{2}L",
            "C<RD>{1,4}L",
        ]);
        assert!(needs_bounding(&exprs));
        let rd = |n: usize| vec!["RD"; n].join(" ");
        let texts = [
            "C RD RD L".to_string(),
            format!("C {} L", rd(3)),
            format!("C {} L", rd(12)),
            format!("C {} RS RS L", rd(10)),
            "C RS L".to_string(),
        ];
        let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
        let a = compare(&exprs, &paths(&texts));
        assert_eq!(a.engines, registry::all().len(), "skipped: {:?}", a.skipped);
        assert_eq!(a.pairs, 3 * texts.len());
        // Matches: the 3- and 12-RD paths (first), the RD..RS RS path (second), the 2-
        // and 3-RD paths (third).
        assert_eq!(a.matched, 5);
    }
}
