//! The conformance suite (`tests/testdata/**/*.toml`, both dialects) on the matchers the
//! renderer routes paths with, driven through the seam the integrator uses
//! (`lpe::PathMatcher`: classify each vertex, `start`, `step` per vertex, `matches`):
//! lpe's `AovSet` as `integrator::dispatch` compiles it (RenderMan: `AovSet::compile`;
//! OSL: `AovSet::compile_osl`, here with each case's registration), and for RenderMan
//! the memoized reference matcher the renderer falls back to. That matcher's state holds
//! at most `REF_MAX_VERTICES` vertices (the longest path the integrator builds), so it
//! is not asked about longer paths (counted, and printed).

use lpe::osl;
use lpe::renderman::Lpe;
use lpe::{AovMask, AovSet, DialectName, PathMatcher};
use lpe_render::aov::matcher::{Reference, ReferenceMatcher, REF_MAX_VERTICES};
use lpe_testkit::suite::{load_dir, rows, testdata_dir, Loaded, Plan};

/// The AOVs a path lands in, stepped vertex by vertex as the integrator does.
fn route<M: PathMatcher>(m: &M, classes: impl IntoIterator<Item = M::Class>) -> AovMask {
    let mut s = m.start();
    for c in classes {
        s = m.step(s, c);
    }
    m.matches(s)
}

/// Per path of the plan, the matcher's mask (`None`: a path longer than the matcher
/// takes), or why it refused the set.
type Masks = Result<Vec<Option<AovMask>>, String>;

/// The RenderMan matchers on a case: (name, masks).
fn matchers_in_the_renderman_dialect(l: &Loaded, plan: &Plan) -> Vec<(&'static str, Masks)> {
    let parser = match &l.case.ini {
        Some(ini) => lpe::renderman::Config::from_ini(ini).unwrap().parser(),
        None => lpe::renderman::Parser::default(),
    };
    let lpes: Vec<Lpe> = plan
        .sources
        .iter()
        .map(|s| {
            parser
                .parse(s)
                .unwrap_or_else(|e| panic!("{}: {e}", l.location()))
        })
        .collect();
    let paths: Vec<lpe::renderman::Path> = plan
        .expected
        .iter()
        .map(|(p, _)| p.parse().unwrap())
        .collect();
    let named: Vec<(String, Lpe)> = lpes
        .iter()
        .enumerate()
        .map(|(i, e)| (format!("e{i}"), e.clone()))
        .collect();
    let steps = |max: usize, m: &dyn Fn(&lpe::renderman::Path) -> AovMask| {
        paths
            .iter()
            .map(|p| (p.len() <= max).then(|| m(p)))
            .collect::<Vec<_>>()
    };
    let fast: Masks = AovSet::compile(&named)
        .map(|set| {
            steps(usize::MAX, &|p| {
                route(&set, p.vertices().iter().map(|v| set.classify(v)))
            })
        })
        .map_err(|e| e.to_string());
    let reference: Masks = Reference::new(&lpes)
        .map(|r| {
            let m = ReferenceMatcher::memoized(r);
            steps(REF_MAX_VERTICES, &|p| {
                route(&m, p.vertices().iter().map(|v| m.classify(v)))
            })
        })
        .map_err(|e| e.to_string());
    vec![("aovset", fast), ("reference", reference)]
}

/// The OSL matcher on a case.
fn matchers_in_the_osl_dialect(l: &Loaded, plan: &Plan) -> Vec<(&'static str, Masks)> {
    let named: Vec<(String, osl::Lpe)> = plan
        .sources
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let e =
                osl::parse(s, &l.registered).unwrap_or_else(|e| panic!("{}: {e}", l.location()));
            (format!("e{i}"), e)
        })
        .collect();
    let fast: Masks = AovSet::compile_under(&named, &l.registered, &lpe::Options::default())
        .map(|set| {
            plan.expected
                .iter()
                .map(|(p, _)| {
                    let path: osl::Path = p.parse().unwrap();
                    Some(route(&set, path.vertices.iter().map(|v| set.classify(v))))
                })
                .collect()
        })
        .map_err(|e| e.to_string());
    vec![("aovset", fast)]
}

/// Every case with paths through the renderer's matchers: failures, the answers
/// checked per dialect, and the paths too long for a matcher.
fn run(cases: &[Loaded]) -> (Vec<String>, [usize; 2], usize) {
    let mut failures = Vec::new();
    let mut checked = [0; 2];
    let mut too_long = 0;
    for l in cases {
        let plan = Plan::of(&l.case);
        if plan.expected.is_empty() {
            continue; // error and path-text cases: the parser's, not a matcher's
        }
        let matchers = match l.dialect {
            DialectName::RenderMan => matchers_in_the_renderman_dialect(l, &plan),
            DialectName::Osl => matchers_in_the_osl_dialect(l, &plan),
        };
        for (name, masks) in matchers {
            let masks = match masks {
                Ok(m) => m,
                Err(_) if l.case.refused_by.iter().any(|r| r.starts_with(name)) => continue,
                Err(why) => {
                    failures.push(format!("{}: {name}: refused: {why}", l.location()));
                    continue;
                }
            };
            for ((path, want), mask) in plan.expected.iter().zip(masks) {
                let Some(mask) = mask else {
                    too_long += 1;
                    continue;
                };
                for (j, &w) in want.iter().enumerate() {
                    checked[usize::from(l.dialect == DialectName::Osl)] += 1;
                    if mask.contains(j) != w {
                        failures.push(format!(
                            "{}: {name}: `{}` on `{path}`: expected {w}, got {}",
                            l.location(),
                            plan.sources[j],
                            !w
                        ));
                    }
                }
            }
        }
    }
    (failures, checked, too_long)
}

#[test]
fn every_suite_case_of_both_dialects_routes_through_the_renderers_matchers() {
    let cases = load_dir(&testdata_dir()).unwrap_or_else(|e| panic!("{e}"));
    let (failures, checked, too_long) = run(&cases);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    eprintln!(
        "renderer's matchers: {} RenderMan and {} OSL answers checked; {too_long} paths \
         longer than the reference matcher's {REF_MAX_VERTICES} vertices not asked",
        checked[0], checked[1]
    );
    // Only the suite's few very long paths (limits.toml) are left out.
    assert!(too_long < 10, "{too_long}");
    // Every OSL verdict once (one OSL matcher).
    let osl: Vec<Loaded> = cases
        .iter()
        .filter(|l| l.dialect == DialectName::Osl)
        .cloned()
        .collect();
    assert_eq!(checked[1], rows(&osl).len());
    assert!(checked[0] > 600, "{}", checked[0]);
}

#[test]
fn a_wrong_verdict_fails_on_each_of_the_renderers_matchers() {
    let text = "[[case]]\nname = \"flipped\"\nexpr = \"C<RD>L\"\nmatch = [\"C RS L\"]\n\n\
                [[case]]\nname = \"flipped osl\"\ndialect = \"osl\"\nexpr = \"C<RD>L\"\n\
                no_match = [\"C,_ R,D L,_\"]\n";
    let cases = lpe_testkit::suite::load_str("flipped.toml", text).unwrap();
    let (failures, checked, too_long) = run(&cases);
    assert_eq!((checked, too_long), ([2, 1], 0));
    assert_eq!(failures.len(), 3, "{failures:#?}");
    assert!(failures[0].starts_with("flipped.toml: case `flipped`: aovset"));
    assert!(failures[1].starts_with("flipped.toml: case `flipped`: reference"));
    assert!(failures[2].starts_with("flipped.toml: case `flipped osl`: aovset"));
}
