//! The bodies of the fuzz targets in `fuzz/`, as plain functions.
//!
//! Each takes the fuzzer's raw input and panics when a property fails, so the same
//! function serves `cargo fuzz run TARGET` (nightly or `-s none` on stable) and the
//! stable `cargo test` that replays every committed corpus and regression file
//! (`tests/tests/fuzz_replay.rs`).
//!
//! The bodies are written once over the dialect ([`parse`], [`path_text`],
//! [`differential()`]); a target is a body applied to a dialect (and, for the
//! differential ones, a set size and generator bounds), one row of the table that
//! [`run`] (the `fuzz/fuzz_targets/*.rs` files), [`target`] and [`compared_target`]
//! (the replay) read:
//!
//! | target | body | property |
//! |---|---|---|
//! | `parse` | `parse::<RenderMan>` | any bytes: the parser never panics; a parsed expression prints to text that parses back to the same AST and prints the same again |
//! | `path_text` | `path_text::<RenderMan>` | any bytes: the path parser never panics; a parsed path prints and re-parses to itself |
//! | `differential` | `differential::<RenderMan>`, 1 | a structured expression and paths aimed at it: every engine agrees |
//! | `aov_set` | `differential::<RenderMan>`, 2-6 | 2-6 structured expressions compiled as one set, paths aimed at them: every engine agrees |
//! | `osl_parse` | `parse::<Osl>` | any bytes (a first line that parses as a registration applies): the OSL parser never panics; a parsed expression prints to text that parses back to the same tree |
//! | `osl_differential` | `differential::<Osl>`, 1-4 | a structured registration, 1-4 OSL expressions (a set) and paths aimed at them: every engine agrees |

use std::ops::RangeInclusive;

use arbitrary::Unstructured;
use lpe::algebra::SetExpr;
use lpe::osl::Osl;
use lpe::renderman::RenderMan;
use lpe::{Dialect, Options};
use lpe_testkit::generate::Choices;
use lpe_testkit::grammar::Coverage;

use crate::adapters::{compile_set, nfa_only, Fast, Reference};
use crate::dialect::{EngineDialect, ReferenceDialect, WireDialect};
use crate::differential::{self, draw, Agreement, Generate, Outcome};
use crate::engine::{Engine, EngineError, Matcher};
use crate::registry;

/// `parse`, `osl_parse`: never panics; parse -> print -> parse gives the same tree
/// ([`WireDialect::same_tree`]) and prints the same again. A first line that is a
/// registration ([`WireDialect::registration_line`], OSL's `events=U;scatters=Y`)
/// applies to the rest.
pub fn parse<D: WireDialect>(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let (registration, src) = text
        .split_once('\n')
        .and_then(|(first, rest)| Some((D::registration_line(first)?, rest)))
        .unwrap_or_else(|| (D::Registration::default(), &*text));
    let context = D::context(&registration);
    let Ok(lpe) = D::parse(src, &registration) else {
        return;
    };
    let printed = lpe.to_string();
    let again = D::parse(&printed, &registration).unwrap_or_else(|e| {
        panic!("`{src}` [{context}] printed as `{printed}`, which does not parse: {e}")
    });
    assert!(
        D::same_tree(&again, &lpe),
        "`{src}` [{context}] printed as `{printed}` parses differently"
    );
    assert_eq!(again.to_string(), printed, "printing is not stable");
}

/// `path_text`: never panics; a parsed path prints and re-parses to itself.
pub fn path_text<D: Dialect>(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let Ok(path) = text.parse::<D::Path>() else {
        return;
    };
    let printed = path.to_string();
    let again: D::Path = printed
        .parse()
        .unwrap_or_else(|e| panic!("`{text}` printed as `{printed}`, which does not parse: {e}"));
    assert_eq!(
        again, path,
        "`{text}` printed as `{printed}` parses differently"
    );
}

/// `differential`, `aov_set`, `osl_differential`: a registration, a set of `sizes`
/// structured expressions under it, and 1-8 paths aimed at them; every engine agrees.
/// Returns whether engines were compared: the reference and at least one other built
/// the set. Fuzzed sets may exceed an engine's size limits, so fewer engines is not a
/// failure; it is just not an agreement, and the caller can count it.
pub fn differential<D: Generate>(
    data: &[u8],
    sizes: RangeInclusive<usize>,
    cfg: &D::Config,
) -> bool {
    let mut u = Unstructured::new(data);
    let registration = D::registration(&mut u);
    // A fixed size draws nothing, so the input's bytes all go to the expressions.
    let n = if sizes.start() == sizes.end() {
        *sizes.start()
    } else {
        sizes.start() + u.below(sizes.end() - sizes.start() + 1)
    };
    // Trees and grammar texts, as `lpe-check diff` draws them; a documented text the
    // parser rejects is a finding.
    let mut coverage = Coverage::new(D::productions());
    let exprs: Vec<D::Lpe> = (0..n)
        .map(|_| {
            let drawn = draw::<D>(&mut u, &registration, cfg, &mut coverage);
            if let Some((text, error)) = drawn.rejected {
                panic!("the parser rejects `{text}`, a text of the documented grammar: {error}");
            }
            drawn.lpe
        })
        .collect();
    let paths: Vec<D::Path> = (0..1 + u.below(8))
        .map(|_| {
            let operands = exprs[u.below(exprs.len())].operands();
            let target = operands[u.below(operands.len())];
            D::biased_path(target, &mut u, &registration, cfg)
        })
        .collect();
    compare::<D>(&registration, &exprs, &paths).engines >= 2
}

/// The agreement of every engine on `paths` (panics with the counterexample if two
/// differ, or if the reference refused the set).
fn compare<D: EngineDialect>(
    registration: &D::Registration,
    exprs: &[D::Lpe],
    paths: &[D::Path],
) -> Agreement {
    // The expression must survive its own canonical text, or the counterexample printed
    // below would not reproduce.
    for e in exprs {
        let text = e.to_string();
        match D::parse(&text, registration) {
            Ok(back) => assert!(
                D::same_tree(&back, e),
                "`{text}` parses to another expression"
            ),
            Err(err) => panic!("generated `{text}` does not parse: {err}"),
        }
    }
    let longest = paths
        .iter()
        .map(|p| D::vertices(p).len())
        .max()
        .unwrap_or(0);
    let bounded: Vec<ForPaths> = ["fast", "nfa"]
        .map(|name| ForPaths::new(name, longest))
        .into();
    let engines: Vec<&dyn Engine<D>> = if needs_bounding::<D>(exprs) {
        registry::all::<D>()
            .into_iter()
            .map(|e| match bounded.iter().find(|b| b.name == e.name()) {
                Some(b) => b as &dyn Engine<D>,
                None => e,
            })
            .collect()
    } else {
        registry::all::<D>()
    };
    agreement(differential::check_in(&engines, registration, exprs, paths))
}

/// The agreement of an outcome; panics on a disagreement, or if the reference refused.
fn agreement<D: ReferenceDialect + WireDialect>(outcome: Outcome<D>) -> Agreement {
    match outcome {
        Outcome::Disagree(c) => panic!("{c}"),
        Outcome::Agree(a) => {
            // The reference has no size limit; without it nothing says who is right.
            let reference = Engine::<D>::name(&Reference);
            assert!(
                a.skipped.iter().all(|(name, _)| *name != reference),
                "the reference refused: {:?}",
                a.skipped
            );
            a
        }
    }
}

/// Sets that unroll to more atom positions than this (counted repetitions such as
/// `{0,123}`) compile the `fast` and `nfa` engines for the case's own paths only
/// ([`ForPaths`]). Such sets are about 5 % of fuzzed cases but took over 90 % of the
/// target's time, building and minimizing DFAs for paths hundreds of vertices long when
/// the case's paths have at most a dozen; smaller sets, most cases, still compile exact.
const EXACT_POSITIONS: u64 = 32;

fn needs_bounding<D: Dialect>(exprs: &[D::Lpe]) -> bool {
    let operands = exprs.iter().flat_map(|e| e.operands());
    operands.map(|o| D::positions(o, None)).sum::<u64>() > EXACT_POSITIONS
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
        // Engine names are the same in every dialect.
        let fast = name == Engine::<RenderMan>::name(&Fast);
        ForPaths {
            name,
            opts: Options {
                max_path_len: Some(u32::try_from(longest).unwrap_or(u32::MAX)),
                ..if fast { Options::default() } else { nfa_only() }
            },
        }
    }
}

impl<D: Dialect> Engine<D> for ForPaths {
    fn name(&self) -> &'static str {
        self.name
    }

    fn compile(
        &self,
        exprs: &[D::Lpe],
        registration: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
        compile_set(exprs, registration, &self.opts)
    }
}

/// A fuzz target's body: it panics when its property fails, and answers whether
/// engines were compared (a differential target) or `true` (a property alone).
pub type Body = fn(&[u8]) -> bool;

/// The one table of target names and their bodies (`true`: a differential target),
/// which `fuzz/fuzz_targets/*.rs` ([`run`]) and the corpus replay ([`target`],
/// [`compared_target`]) read.
fn table(name: &str) -> Option<(Body, bool)> {
    let parses: [(&str, Body); 3] = [
        ("parse", |d| {
            parse::<RenderMan>(d);
            true
        }),
        ("path_text", |d| {
            path_text::<RenderMan>(d);
            true
        }),
        ("osl_parse", |d| {
            parse::<Osl>(d);
            true
        }),
    ];
    let differentials: [(&str, Body); 3] = [
        ("differential", |d| {
            differential::<RenderMan>(d, 1..=1, &Default::default())
        }),
        ("aov_set", |d| {
            differential::<RenderMan>(d, 2..=6, &RenderMan::config(6))
        }),
        ("osl_differential", |d| {
            differential::<Osl>(d, 1..=4, &Default::default())
        }),
    ];
    let find = |list: &[(&str, Body)]| list.iter().find(|(n, _)| *n == name).map(|(_, b)| *b);
    find(&parses)
        .map(|b| (b, false))
        .or_else(|| find(&differentials).map(|b| (b, true)))
}

/// Runs the fuzz target called `name` on `data` (what `fuzz/fuzz_targets/NAME.rs`
/// calls); panics on an unknown name.
pub fn run(name: &str, data: &[u8]) {
    let (body, _) = table(name).unwrap_or_else(|| panic!("no fuzz target `{name}`"));
    body(data);
}

/// The differential target called `name`, returning whether engines were compared,
/// so a replay can count inputs that only one engine could build.
pub fn compared_target(name: &str) -> Option<Body> {
    table(name)
        .filter(|(_, differential)| *differential)
        .map(|(f, _)| f)
}

/// The target called `name`, for replaying files by directory name; it panics when
/// its property fails.
pub fn target(name: &str) -> Option<Body> {
    table(name).map(|(f, _)| f)
}

#[cfg(test)]
mod tests {
    use super::*;

    use lpe::renderman::{Lpe, Parser, Path};

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
        assert!(!needs_bounding::<RenderMan>(&set(&["C(<RD>|<RS>){0,15}L"])));
        assert!(needs_bounding::<RenderMan>(&set(&["C(<RD>|<RS>){0,16}L"])));
        assert!(needs_bounding::<RenderMan>(&set(&[
            "C<RD>{0,20}L",
            "C<RS>{0,20}L"
        ])));
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
        assert!(needs_bounding::<RenderMan>(&exprs));
        let rd = |n: usize| vec!["RD"; n].join(" ");
        let texts = [
            "C RD RD L".to_string(),
            format!("C {} L", rd(3)),
            format!("C {} L", rd(12)),
            format!("C {} RS RS L", rd(10)),
            "C RS L".to_string(),
        ];
        let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
        let a = compare::<RenderMan>(&Parser::default(), &exprs, &paths(&texts));
        assert_eq!(
            a.engines,
            registry::all::<RenderMan>().len(),
            "skipped: {:?}",
            a.skipped
        );
        assert_eq!(a.pairs, 3 * texts.len());
        // Matches: the 3- and 12-RD paths (first), the RD..RS RS path (second), the 2-
        // and 3-RD paths (third).
        assert_eq!(a.matched, 5);
    }
}
