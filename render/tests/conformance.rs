//! The conformance suite (`tests/testdata/**/*.toml`, both dialects) on the matchers the
//! renderer routes paths with, driven through the seam the integrator uses
//! (`lpe::PathMatcher`: classify each vertex, `start`, `step` per vertex, `matches`):
//! lpe's `AovSet` as `integrator::dispatch` compiles it (here under each case's
//! registration), and the memoized reference matcher the renderer falls back to. That
//! matcher's state holds at most `REF_MAX_VERTICES` vertices (the longest path the
//! integrator builds), so it is not asked about longer paths (counted, and printed).

use lpe::osl::Osl;
use lpe::renderman::RenderMan;
use lpe::{AovMask, AovSet, DialectName, PathMatcher};
use lpe_render::aov::matcher::{Reference, ReferenceMatcher, REF_MAX_VERTICES};
use lpe_render::aov::SceneDialect;
use lpe_testkit::suite::{load_dir, rows, testdata_dir, Loaded, Plan};

/// The AOVs a path lands in, stepped vertex by vertex as the integrator does.
fn route<M: PathMatcher>(m: &M, path: &[M::Vertex]) -> AovMask {
    let mut s = m.start();
    for v in path {
        s = m.step(s, m.classify(v));
    }
    m.matches(s)
}

/// Per path of the plan, the matcher's mask (`None`: a path longer than the matcher
/// takes), or why it refused the set.
type Masks = Result<Vec<Option<AovMask>>, String>;

/// The renderer's matchers on a case in dialect `D`, parsed under `registration`:
/// (name, masks).
fn matchers<D: SceneDialect>(
    l: &Loaded,
    plan: &Plan,
    registration: &D::Registration,
) -> Vec<(&'static str, Masks)> {
    let lpes: Vec<D::Lpe> = plan
        .sources
        .iter()
        .map(|s| D::parse(s, registration).unwrap_or_else(|e| panic!("{}: {e}", l.location())))
        .collect();
    let paths: Vec<D::Path> = plan
        .expected
        .iter()
        .map(|(p, _)| {
            p.parse()
                .unwrap_or_else(|e| panic!("{}: {e}", l.location()))
        })
        .collect();
    let named: Vec<(String, D::Lpe)> = lpes
        .iter()
        .enumerate()
        .map(|(i, e)| (format!("e{i}"), e.clone()))
        .collect();
    let steps = |max: usize, m: &dyn Fn(&[D::Vertex]) -> AovMask| {
        paths
            .iter()
            .map(|p| {
                let vertices = D::vertices(p);
                (vertices.len() <= max).then(|| m(vertices))
            })
            .collect::<Vec<_>>()
    };
    let fast: Masks = AovSet::<D>::compile_under(&named, registration, &lpe::Options::default())
        .map(|set| steps(usize::MAX, &|p| route(&set, p)))
        .map_err(|e| e.to_string());
    let reference: Masks = Reference::<D>::new(&lpes)
        .map(|r| {
            let m = ReferenceMatcher::<D>::memoized(r);
            steps(REF_MAX_VERTICES, &|p| route(&m, p))
        })
        .map_err(|e| e.to_string());
    vec![("aovset", fast), ("reference", reference)]
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
            DialectName::RenderMan => {
                let parser = match &l.case.ini {
                    Some(ini) => lpe::renderman::Config::from_ini(ini).unwrap().parser(),
                    None => lpe::renderman::Parser::default(),
                };
                matchers::<RenderMan>(l, &plan, &parser)
            }
            DialectName::Osl => matchers::<Osl>(l, &plan, &l.registered),
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
    // Every OSL verdict of a path the reference takes, twice (two matchers).
    let osl: Vec<Loaded> = cases
        .iter()
        .filter(|l| l.dialect == DialectName::Osl)
        .cloned()
        .collect();
    assert!(checked[1] <= 2 * rows(&osl).len() && checked[1] > rows(&osl).len());
    assert!(checked[0] > 600, "{}", checked[0]);
}

#[test]
fn a_wrong_verdict_fails_on_each_of_the_renderers_matchers() {
    let text = "[[case]]\nname = \"flipped\"\nexpr = \"C<RD>L\"\nmatch = [\"C RS L\"]\n\n\
                [[case]]\nname = \"flipped osl\"\ndialect = \"osl\"\nexpr = \"C<RD>L\"\n\
                no_match = [\"C,_ R,D L,_\"]\n";
    let cases = lpe_testkit::suite::load_str("flipped.toml", text).unwrap();
    let (failures, checked, too_long) = run(&cases);
    assert_eq!((checked, too_long), ([2, 2], 0));
    assert_eq!(failures.len(), 4, "{failures:#?}");
    assert!(failures[0].starts_with("flipped.toml: case `flipped`: aovset"));
    assert!(failures[1].starts_with("flipped.toml: case `flipped`: reference"));
    assert!(failures[2].starts_with("flipped.toml: case `flipped osl`: aovset"));
    assert!(failures[3].starts_with("flipped.toml: case `flipped osl`: reference"));
}
