//! Generated cases for the harness, and a run over a range of them.
//!
//! Each case is one expression (or, one time in five, an AOV set of 2-5 expressions
//! compiled at once) and paths generated *from* it (walks of the expression, near
//! misses, uniform noise; see `lpe_testkit::generate`). Half the expressions are drawn
//! as trees (`Generate::lpe`), half as text from the dialect's grammar
//! (`Generate::text`, `lpe_testkit::grammar`) and parsed with the dialect's parser: the
//! text reaches productions no tree printer writes, and a text the parser rejects is a
//! finding (the generator writes only what docs/language.md allows).
//!
//! Case `i` of seed `s` is generated from its own PRNG stream, so a run is deterministic
//! for a seed and a reported case can be regenerated alone (`--first i --cases 1`).

use lpe::algebra::SetExpr;
use lpe::rng::SplitMix64 as Rng;
use lpe::Dialect;
use lpe_testkit::generate::Choices;
use lpe_testkit::grammar::Coverage;

use super::check::{check_in, Outcome};
use super::counterexample::Counterexample;
use super::generate::{draw, Generate};
use crate::engine::Engine;

/// One generated case.
#[derive(Clone, Debug)]
pub struct Case<D: Dialect> {
    /// What the expressions were parsed under (OSL's registered labels).
    pub registration: D::Registration,
    /// The expressions (one, or an AOV set).
    pub exprs: Vec<D::Lpe>,
    /// Paths aimed at the expressions.
    pub paths: Vec<D::Path>,
    /// The source text of each expression drawn from the grammar (`None`: a tree).
    pub texts: Vec<Option<String>>,
    /// Grammar texts the dialect's parser rejected: the text and the error (the case
    /// then uses a tree in its place).
    pub rejected: Vec<(String, String)>,
    /// The grammar productions the case's texts wrote.
    pub coverage: Coverage,
}

/// A rejected grammar text: the generator writes only documented syntax, so either the
/// parser or the generator (or the documentation) is wrong.
#[derive(Clone, Debug)]
pub struct Rejected {
    /// The case.
    pub case: u64,
    /// The text.
    pub text: String,
    /// The parser's error.
    pub error: String,
}

/// The PRNG of case `index` under `seed`: independent streams per case.
pub fn case_rng(seed: u64, index: u64) -> Rng {
    let mut mix = Rng::new(seed);
    Rng::new(mix.next_u64() ^ index.wrapping_mul(0xD1B5_4A32_D192_ED03))
}

/// How many expressions a case compiles at once: one time in five an AOV set of 2-5.
fn set_size(rng: &mut Rng) -> usize {
    if rng.chance(20) {
        2 + rng.below(4)
    } else {
        1
    }
}

/// Generates case `index` of `seed`: a registration, expressions under it, and paths
/// aimed at them.
pub fn generate_case<D: Generate>(seed: u64, index: u64, cfg: &D::Config, paths: usize) -> Case<D> {
    let mut rng = case_rng(seed, index);
    let registration = D::registration(&mut rng);
    let n = set_size(&mut rng);
    let mut coverage = Coverage::new(D::productions());
    let mut texts = Vec::with_capacity(n);
    let mut rejected = Vec::new();
    let mut exprs: Vec<D::Lpe> = Vec::with_capacity(n);
    for _ in 0..n {
        let drawn = draw::<D>(&mut rng, &registration, cfg, &mut coverage);
        exprs.push(drawn.lpe);
        texts.push(drawn.text);
        rejected.extend(drawn.rejected);
    }
    let paths = (0..paths)
        .map(|_| {
            // Aim at one operand: for set algebra, paths near each side of `A - B`.
            let operands = rng.pick(&exprs).operands();
            let target = *rng.pick(&operands);
            D::biased_path(target, &mut rng, &registration, cfg)
        })
        .collect();
    Case {
        registration,
        exprs,
        paths,
        texts,
        rejected,
        coverage,
    }
}

/// Totals of a run.
#[derive(Debug)]
pub struct Totals<D: Dialect> {
    /// Cases run.
    pub cases: u64,
    /// Expression/path pairs compared.
    pub pairs: u64,
    /// Pairs that matched.
    pub matched: u64,
    /// Cases some engine could not build, per engine name.
    pub skips: Vec<(&'static str, u64, String)>,
    /// Cases where fewer than two engines could build (nothing compared).
    pub uncompared: u64,
    /// Minimized disagreements.
    pub failures: Vec<(u64, Counterexample<D>)>,
    /// Grammar texts the dialect's parser rejected.
    pub rejected: Vec<Rejected>,
    /// Grammar productions the run's texts wrote.
    pub coverage: Coverage,
}

/// Which cases a run generates, and when it stops.
#[derive(Clone, Debug)]
pub struct Run {
    /// Number of cases (expressions or AOV sets) to generate.
    pub cases: u64,
    /// Seed of the generator; the same seed gives the same cases.
    pub seed: u64,
    /// Index of the first case (to regenerate one case of a run).
    pub first: u64,
    /// Most atoms (OSL: vertex patterns) in one generated expression.
    pub max_size: usize,
    /// Paths generated per case.
    pub paths: usize,
    /// Stop after this many disagreements.
    pub max_failures: usize,
}

/// Runs cases `first..first + cases` and returns the totals.
pub fn run_cases<D: Generate>(args: &Run, engines: &[&dyn Engine<D>]) -> Totals<D> {
    let cfg = D::config(args.max_size);
    let mut t = Totals {
        cases: 0,
        pairs: 0,
        matched: 0,
        skips: Vec::new(),
        uncompared: 0,
        failures: Vec::new(),
        rejected: Vec::new(),
        coverage: Coverage::new(D::productions()),
    };
    for index in args.first..args.first.saturating_add(args.cases) {
        let case = generate_case::<D>(args.seed, index, &cfg, args.paths);
        t.cases += 1;
        t.coverage.merge(&case.coverage);
        t.rejected
            .extend(case.rejected.iter().map(|(text, error)| Rejected {
                case: index,
                text: text.clone(),
                error: error.clone(),
            }));
        // Long runs report progress on stderr every tenth, so stdout stays the summary.
        if args.cases >= 10_000 && t.cases % (args.cases / 10) == 0 {
            eprintln!(
                "diff: {} of {} cases, {} disagreement(s) so far",
                t.cases,
                args.cases,
                t.failures.len()
            );
        }
        match check_in(engines, &case.registration, &case.exprs, &case.paths) {
            Outcome::Agree(a) => {
                t.pairs += a.pairs as u64;
                t.matched += a.matched as u64;
                if a.engines < 2 {
                    t.uncompared += 1;
                }
                for (name, why) in a.skipped {
                    match t.skips.iter_mut().find(|(n, _, _)| *n == name) {
                        Some(s) => s.1 += 1,
                        None => t.skips.push((name, 1, why)),
                    }
                }
            }
            Outcome::Disagree(c) => {
                t.failures.push((index, *c));
                if t.failures.len() >= args.max_failures {
                    break;
                }
            }
        }
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::osl::Osl;
    use lpe::renderman::RenderMan;
    use lpe_testkit::generate::{self, Config};

    #[test]
    fn cases_are_deterministic_per_seed_and_index() {
        let cfg = Config::default();
        let a = generate_case::<RenderMan>(5, 17, &cfg, 4);
        let b = generate_case::<RenderMan>(5, 17, &cfg, 4);
        assert_eq!(a.exprs, b.exprs);
        assert_eq!(a.paths, b.paths);
        let c = generate_case::<RenderMan>(6, 17, &cfg, 4);
        assert!(a.exprs != c.exprs || a.paths != c.paths);
    }

    #[test]
    fn a_small_run_agrees_with_a_useful_match_rate() {
        let args = Run {
            cases: 300,
            seed: 1,
            first: 0,
            max_size: 10,
            paths: 4,
            max_failures: 1,
        };
        let t = run_cases::<RenderMan>(&args, &crate::registry::all());
        if let Some((i, c)) = t.failures.first() {
            panic!("case {i}:\n{c}");
        }
        // Every case compared engines: an agreement of one engine with itself would
        // count pairs that nothing checked. `fast` and `nfa` legitimately refuse a few
        // sets over their position limit; the reference and the oracle must not.
        assert_eq!(t.uncompared, 0);
        assert!(
            t.skips
                .iter()
                .all(|(name, _, _)| !["reference", "oracle"].contains(name)),
            "{:?}",
            t.skips
        );
        let rate = t.matched as f64 / t.pairs as f64;
        assert!((0.2..=0.8).contains(&rate), "match rate {rate}");
    }

    #[test]
    fn a_small_run_agrees_with_a_useful_match_rate_in_the_osl_dialect() {
        let args = Run {
            cases: 400,
            seed: 1,
            first: 0,
            max_size: 8,
            paths: 4,
            max_failures: 1,
        };
        let t = run_cases::<Osl>(&args, &crate::registry::all());
        if let Some((i, c)) = t.failures.first() {
            panic!("case {i}:\n{c}");
        }
        assert_eq!(t.uncompared, 0);
        assert!(t.skips.is_empty(), "{:?}", t.skips);
        let rate = t.matched as f64 / t.pairs as f64;
        assert!((0.2..=0.8).contains(&rate), "match rate {rate}");
    }

    #[test]
    fn cases_are_deterministic_and_vary_the_registration_in_the_osl_dialect() {
        let cfg = generate::osl::Config::default();
        let a = generate_case::<Osl>(5, 17, &cfg, 4);
        let b = generate_case::<Osl>(5, 17, &cfg, 4);
        assert_eq!(
            (&a.registration, &a.exprs, &a.paths),
            (&b.registration, &b.exprs, &b.paths)
        );
        let regs: std::collections::HashSet<String> = (0..50)
            .map(|i| generate_case::<Osl>(5, i, &cfg, 1).registration.to_string())
            .collect();
        assert!(regs.contains("-") && regs.len() > 3, "{regs:?}");
    }

    /// About one expression in twelve holds set algebra (low weight, but every run of a
    /// few hundred cases has dozens), and paths aimed at operands: some algebra
    /// expression matches some of its paths (by the reference), so the algebra is not
    /// only ever checked on non-matches.
    fn assert_some_algebra_that_matches<D: lpe::Dialect>(
        cases: &[Case<D>],
        has_algebra: impl Fn(&D::Lpe) -> bool,
        reference_match: impl Fn(&D::Lpe, &D::Path) -> bool,
    ) {
        let with_algebra: Vec<&Case<D>> = cases
            .iter()
            .filter(|c| c.exprs.iter().any(&has_algebra))
            .collect();
        assert!(
            (16..=80).contains(&with_algebra.len()),
            "{}",
            with_algebra.len()
        );
        let hits = with_algebra
            .iter()
            .flat_map(|c| {
                c.exprs
                    .iter()
                    .flat_map(|e| c.paths.iter().map(move |p| (e, p)))
            })
            .filter(|(e, p)| has_algebra(e) && reference_match(e, p))
            .count();
        assert!(hits >= 10, "{hits}");
    }

    #[test]
    fn some_cases_hold_set_algebra_that_matches_some_of_their_paths_in_the_osl_dialect() {
        let cfg = generate::osl::Config::default();
        let cases: Vec<Case<Osl>> = (0..400)
            .map(|i| generate_case::<Osl>(3, i, &cfg, 4))
            .collect();
        assert_some_algebra_that_matches(
            &cases,
            |e| e.algebra.is_some(),
            lpe_reference::lpe_tree::is_match,
        );
        // Without set algebra when asked (for matchers that do not speak it).
        let plain = generate::osl::Config::default().without_set_algebra();
        assert!((0..400).all(|i| generate_case::<Osl>(3, i, &plain, 1)
            .exprs
            .iter()
            .all(|e| e.algebra.is_none())));
    }

    #[test]
    fn some_cases_hold_set_algebra_and_their_paths_aim_at_operands() {
        let cfg = Config::default();
        let cases: Vec<Case<RenderMan>> = (0..400)
            .map(|i| generate_case::<RenderMan>(3, i, &cfg, 4))
            .collect();
        assert_some_algebra_that_matches(&cases, |e| e.algebra.is_some(), lpe_reference::is_match);
    }
}
