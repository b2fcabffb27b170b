//! Translation between the dialects, checked from outside the translation.
//!
//! The verdicts come from `lpe::translate`'s searches on lpe's automata; these tests judge
//! them with the reference matchers (their own front ends, reading the printed texts) on
//! paths drawn here, not from the searches' universe. What they share with the
//! translation is the correspondence's vertex map (`Correspondence::view`), which
//! `render/tests/translate.rs` checks against the renderer's own two views of its
//! vertices.
//!
//! - every built-in RenderMan macro and the OSL basic set, with verdicts and translations
//!   worked by hand in `tests/translate/builtin.toml` (outside `testdata/`, whose files are conformance suites);
//! - generated expressions of both dialects: the lower translation implies the source,
//!   the source implies the upper one, an exact translation agrees on every drawn path,
//!   witnesses show what they claim, and translating back an exact translation gives an
//!   expression equivalent to the source;
//! - the same bounds where rounding turns round: generated operands whose translation is
//!   not exact, under `^` and on the right of `-`, judged on their own witnesses too.

use std::collections::BTreeSet;

use lpe::osl::Osl;
use lpe::osl::{self, Registered};
use lpe::renderman::RenderMan;
use lpe::renderman::{self, Event, VertexType};
use lpe::rng::SplitMix64;
use lpe::translate::{translate, Correspondence, Reason, Translate, Translation};
use lpe::Dialect;
use lpe_reference::is_match;
use lpe_testkit::grammar;
use serde::Deserialize;

#[derive(Deserialize)]
struct Builtin {
    renderman: Vec<RenderManCase>,
    osl: Vec<OslCase>,
}

#[derive(Deserialize)]
struct RenderManCase {
    name: String,
    verdict: String,
    osl: String,
}

#[derive(Deserialize)]
struct OslCase {
    source: String,
    verdict: String,
    renderman: String,
}

fn verdict<L>(t: &lpe::translate::Translation<L>) -> &'static str {
    match t.reasons.first() {
        None => "exact",
        Some(Reason::Collision(_)) => "collision",
        Some(Reason::NoOslView(_)) => "no OSL view",
        Some(Reason::Unsayable) => "unsayable",
    }
}

#[test]
fn builtin_macros_and_the_osl_basic_set_translate_as_worked_by_hand() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/translate/builtin.toml"
    ))
    .unwrap();
    let data: Builtin = toml::from_str(&text).unwrap();
    let corr = Correspondence::default();
    // Self-guarding: every built-in macro once, every OSL basic AOV once.
    let names: BTreeSet<&str> = data.renderman.iter().map(|c| c.name.as_str()).collect();
    let builtin = renderman::macros::MacroTable::builtin();
    assert_eq!(
        names,
        builtin.names().collect(),
        "one case per built-in macro"
    );
    assert_eq!(names.len(), data.renderman.len());
    let sources: Vec<&str> = data.osl.iter().map(|c| c.source.as_str()).collect();
    let basic: Vec<&str> = osl::BASIC.iter().map(|(_, s)| *s).collect();
    assert_eq!(sources, basic);
    for c in &data.renderman {
        let t = translate::<RenderMan>(&renderman::parse(&c.name).unwrap(), &corr).unwrap();
        assert_eq!(verdict(&t), c.verdict, "{}", c.name);
        assert_eq!(t.text.to_string(), c.osl, "{}", c.name);
    }
    for c in &data.osl {
        let f = osl::parse(&c.source, &Registered::none()).unwrap();
        let t = translate::<Osl>(&f, &corr).unwrap();
        assert_eq!(verdict(&t), c.verdict, "{}", c.source);
        assert_eq!(t.text.to_string(), c.renderman, "{}", c.source);
    }
}

/// Labels for drawn paths: the expression's, one OSL reads as built in, and others.
fn path_labels(mentioned: impl IntoIterator<Item = String>) -> Vec<Option<String>> {
    let mut out: Vec<Option<String>> = vec![None, Some("stranger".into()), Some("D".into())];
    out.extend(mentioned.into_iter().map(Some));
    out
}

/// A RenderMan path of up to five scattering vertices, now and then a user lobe.
fn draw_path(rng: &mut SplitMix64, labels: &[Option<String>]) -> renderman::Path {
    let events: Vec<Event> = Event::all().collect();
    let label = |rng: &mut SplitMix64| labels[rng.below(labels.len())].clone();
    let mut vs = vec![renderman::Vertex::camera()];
    for _ in 0..rng.below(6) {
        let ty = if rng.below(2) == 0 {
            VertexType::R
        } else {
            VertexType::T
        };
        let e = if rng.below(8) == 0 {
            events[rng.below(events.len())]
        } else {
            events[rng.below(12)] // transport lobes come first
        };
        vs.push(renderman::Vertex::scatter(ty, e, label(rng).as_deref()));
    }
    let l = label(rng);
    vs.push(if rng.below(3) == 0 {
        renderman::Vertex::emissive(l.as_deref())
    } else {
        renderman::Vertex::light(l.as_deref())
    });
    renderman::Path::new(vs).unwrap()
}

fn has_user_lobe(p: &renderman::Path) -> bool {
    p.vertices()
        .iter()
        .any(|v| v.event().is_some_and(|e| !e.is_transport()))
}

fn labels_named_in(f: &osl::Lpe) -> Vec<String> {
    let mut out = Vec::new();
    for op in f.operands() {
        op.for_each_vertex(&mut |v| {
            for s in &v.symbols {
                for sym in s.symbols() {
                    if let osl::Symbol::Label(l) = sym {
                        out.push(l.clone());
                    }
                }
            }
        });
    }
    out
}

/// A RenderMan source `e` (written `text`) against its translation `t` on `paths`, judged
/// by the reference matchers: the lower translation implies the source and the source
/// implies the upper one on every path with an OSL view; an exact translation agrees
/// there and matches no path with a user lobe.
fn renderman_within_bounds(
    text: &str,
    e: &renderman::Lpe,
    t: &Translation<osl::Lpe>,
    corr: &Correspondence,
    paths: &[renderman::Path],
) {
    let (up_ref, low_ref) = (&t.text, &t.lower);
    for p in paths {
        let m = is_match(e, p);
        match corr.view_path(p) {
            Some(o) => {
                let (up, low) = (is_match(up_ref, &o), is_match(low_ref, &o));
                assert!(
                    !low || m,
                    "`{text}`: lower `{low_ref}` matches {o}, source not {p}"
                );
                if m && !has_user_lobe(p) {
                    assert!(up, "`{text}`: upper `{up_ref}` misses {o} ({p})");
                }
                if t.exact {
                    assert_eq!(m, up, "`{text}` exact as `{up_ref}`, differs on {p} / {o}");
                }
            }
            None if has_user_lobe(p) && t.exact => {
                assert!(!m, "`{text}` exact, yet matches {p}, which has no OSL view");
            }
            None => {}
        }
    }
}

/// An OSL source `f` (written `text`) against its translation `t` on `paths` (RenderMan
/// paths, the source judged on their OSL views), as [`renderman_within_bounds`].
fn osl_within_bounds(
    text: &str,
    f: &osl::Lpe,
    t: &Translation<renderman::Lpe>,
    corr: &Correspondence,
    paths: &[renderman::Path],
) {
    for p in paths {
        let (up, low) = (is_match(&t.text, p), is_match(&t.lower, p));
        match corr.view_path(p) {
            Some(o) => {
                let m = is_match(f, &o);
                assert!(
                    !low || m,
                    "`{text}`: lower `{}` matches {p}, source not {o}",
                    t.lower
                );
                assert!(!m || up, "`{text}`: upper `{}` misses {p} ({o})", t.text);
                if t.exact {
                    assert_eq!(m, up, "`{text}` exact as `{}`, differs on {p}", t.text);
                }
            }
            None if has_user_lobe(p) && t.exact => {
                assert!(!up, "`{text}` exact as `{}`, yet matches {p}", t.text);
            }
            None => {}
        }
    }
}

const EXPRESSIONS: usize = 300;
const PATHS: usize = 120;

#[test]
fn renderman_expressions_translate_to_osl_within_their_bounds_and_back() {
    renderman_round_trip("plain OSL", &Correspondence::default(), 41);
}

/// The same property under each OSL-based renderer profile's correspondence
/// (docs/profiles.md: Karma's specular lobes all `G`, Arnold's all `S`, ...): every
/// translation within its bounds, and an exact translation translated back equivalent
/// to its source. Planted fault, checked by hand: translating back with the default
/// correspondence instead of the profile's fails it on Karma and Arnold.
#[test]
fn renderman_expressions_round_trip_through_every_renderer_profile() {
    let mut seen = 0;
    for (i, p) in lpe_profile::shipped().iter().enumerate() {
        if p.dialect() != lpe::DialectName::Osl {
            continue;
        }
        let corr = p.correspondence();
        renderman_round_trip(&p.name, &corr, 100 + i as u64);
        seen += 1;
    }
    assert!(seen >= 4, "{seen} OSL-based profiles");
}

/// Generated RenderMan expressions translated to OSL under `corr`: within their bounds on
/// drawn paths, witnesses and reasons as claimed, and exact ones equivalent to their
/// source once translated back.
fn renderman_round_trip(what: &str, corr: &Correspondence, seed: u64) {
    let corr = corr.clone();
    let mut rng = SplitMix64::new(seed);
    let cfg = grammar::Config::default();
    let mut cov = grammar::renderman::coverage();
    let (mut exact, mut back_exact) = (0, 0);
    let mut verdicts = std::collections::BTreeMap::new();
    for _ in 0..EXPRESSIONS {
        let text = grammar::renderman::source(&mut rng, &cfg, &mut cov);
        let e = renderman::Parser::default().parse(&text).unwrap();
        let t = translate::<RenderMan>(&e, &corr).unwrap();
        *verdicts.entry(verdict(&t)).or_insert(0) += 1;
        let labels = path_labels(e.operands().iter().flat_map(|op| op.labels()));
        let paths: Vec<renderman::Path> =
            (0..PATHS).map(|_| draw_path(&mut rng, &labels)).collect();
        renderman_within_bounds(&text, &e, &t, &corr, &paths);
        if let Some(w) = &t.upper_witness {
            assert!(!is_match(&e, &w.renderman), "`{text}`: upper witness {w:?}");
            assert!(
                is_match(&t.text, w.osl.as_ref().unwrap()),
                "`{text}`: {w:?}"
            );
        }
        if let Some(w) = &t.lower_witness {
            assert!(is_match(&e, &w.renderman), "`{text}`: lower witness {w:?}");
            assert!(
                !is_match(&t.lower, w.osl.as_ref().unwrap()),
                "`{text}`: {w:?}"
            );
        }
        for r in &t.reasons {
            match r {
                Reason::Collision(c) => {
                    assert!(
                        is_match(&e, &c.matched) && !is_match(&e, &c.unmatched),
                        "{c:?}"
                    );
                    assert_eq!(corr.view_path(&c.matched), corr.view_path(&c.unmatched));
                }
                Reason::NoOslView(p) => {
                    assert!(is_match(&e, p) && corr.view_path(p).is_none(), "{p}")
                }
                Reason::Unsayable => {}
            }
        }
        if t.exact {
            exact += 1;
            let back = translate::<Osl>(&t.text, &corr).unwrap();
            if back.exact {
                back_exact += 1;
                let c = lpe::analysis::compare(&e, &back.text).unwrap();
                assert!(
                    c.equivalent(),
                    "`{text}` -> `{}` -> `{}`: {c:?}",
                    t.text,
                    back.text
                );
            }
        }
    }
    eprintln!(
        "RenderMan, {what}: {exact} of {EXPRESSIONS} exact, {back_exact} exact back; {verdicts:?}"
    );
    assert!(
        exact > EXPRESSIONS / 10,
        "{what}: {exact}: the property is near vacuous"
    );
    assert!(back_exact * 2 > exact, "{what}: {back_exact} of {exact}");
}

#[test]
fn expressions_of_the_osl_dialect_translate_to_renderman_within_their_bounds_and_back() {
    let corr = Correspondence::default();
    let mut rng = SplitMix64::new(42);
    let cfg = grammar::Config::default();
    let short = grammar::osl::Shorthand::of(&[], &[]);
    let mut cov = grammar::osl::coverage();
    let (mut exact, mut back_exact) = (0, 0);
    let mut verdicts = std::collections::BTreeMap::new();
    for _ in 0..EXPRESSIONS {
        let text = grammar::osl::source(&mut rng, &short, &cfg, &mut cov);
        let f = osl::parse(&text, &Registered::none()).unwrap();
        let t = translate::<Osl>(&f, &corr).unwrap();
        *verdicts.entry(verdict(&t)).or_insert(0) += 1;
        let labels = path_labels(labels_named_in(&f));
        let back = if t.exact {
            Some(translate::<RenderMan>(&t.text, &corr).unwrap())
        } else {
            None
        };
        let paths: Vec<renderman::Path> =
            (0..PATHS).map(|_| draw_path(&mut rng, &labels)).collect();
        osl_within_bounds(&text, &f, &t, &corr, &paths);
        if let Some(b) = back.as_ref().filter(|b| b.exact) {
            for o in paths.iter().filter_map(|p| corr.view_path(p)) {
                assert_eq!(
                    is_match(&f, &o),
                    is_match(&b.text, &o),
                    "`{text}` back as `{}` on {o}",
                    b.text
                );
            }
        }
        if let Some(w) = &t.upper_witness {
            assert!(is_match(&t.text, &w.renderman), "`{text}`: {w:?}");
            if let Some(o) = &w.osl {
                assert!(!is_match(&f, o), "`{text}`: {w:?}");
            }
        }
        if let Some(w) = &t.lower_witness {
            assert!(!is_match(&t.lower, &w.renderman), "`{text}`: {w:?}");
            assert!(is_match(&f, w.osl.as_ref().unwrap()), "`{text}`: {w:?}");
        }
        if t.exact {
            exact += 1;
            back_exact += usize::from(back.is_some_and(|b| b.exact));
        }
    }
    eprintln!("OSL: {exact} of {EXPRESSIONS} exact, {back_exact} exact back; {verdicts:?}");
    assert!(
        exact > EXPRESSIONS / 10,
        "{exact}: the property is near vacuous"
    );
    assert!(back_exact > 0, "no round trip was exact");
}

/// Operands drawn per dialect for the set-algebra properties below.
const INEXACT_OPERANDS: usize = 80;

/// Whether a translation is not exact and rounds somewhere: a path its upper translation
/// adds or its lower one misses (one matching only paths without an OSL view has none).
fn rounded<L>(t: &Translation<L>) -> bool {
    !t.exact && (t.upper_witness.is_some() || t.lower_witness.is_some())
}

/// One dialect's side of [`inexact_operands_round_the_other_way`].
struct Side<D: Translate> {
    /// A grammar text of the dialect, without set algebra.
    text: Box<dyn FnMut(&mut SplitMix64) -> String>,
    parse: fn(&str) -> D::Lpe,
    /// The labels an expression names, for drawn paths.
    labels: fn(&D::Lpe) -> Vec<String>,
    /// [`renderman_within_bounds`] or [`osl_within_bounds`].
    within: WithinBounds<D>,
    /// The light-transport universe in the dialect, exactly expressible in the other.
    universe: &'static str,
}

/// A bound check of one dialect's translations on RenderMan paths.
type WithinBounds<D> = fn(
    &str,
    &<D as Dialect>::Lpe,
    &Translation<<<D as Translate>::Target as Dialect>::Lpe>,
    &Correspondence,
    &[renderman::Path],
);

/// Draws operands `b` whose translation is not exact and that round somewhere
/// ([`rounded`]) and an operand `a` of any kind, and checks `^b`, `U - b` (the universe),
/// `a - b` and `a & ^b` within their bounds on drawn paths and on `b`'s own witnesses
/// (the path its upper translation adds, the one its lower translation misses), where
/// the two rounding directions part: `^b` matches the first, so its upper translation
/// must; `b` matches the second, so `^b`'s lower translation must not.
fn inexact_operands_round_the_other_way<D: Translate>(seed: u64, mut side: Side<D>) {
    let corr = Correspondence::default();
    let mut rng = SplitMix64::new(seed);
    let (mut above, mut below, mut over_budget) = (0, 0, 0);
    // Grammar texts until one reads without prefixes (it stands as an operand) and
    // `keep` takes it.
    let mut draw = |rng: &mut SplitMix64, keep: &dyn Fn(&D::Lpe) -> bool| loop {
        let t = (side.text)(rng);
        if t.contains(';') || t.to_ascii_lowercase().contains("lpe:") {
            continue;
        }
        if keep(&(side.parse)(&t)) {
            return t;
        }
    };
    for _ in 0..INEXACT_OPERANDS {
        let a = draw(&mut rng, &|_| true);
        let b = draw(&mut rng, &|e| rounded(&translate::<D>(e, &corr).unwrap()));
        let tb = translate::<D>(&(side.parse)(&b), &corr).unwrap();
        let mut named = (side.labels)(&(side.parse)(&a));
        named.extend((side.labels)(&(side.parse)(&b)));
        let labels = path_labels(named);
        let mut paths: Vec<renderman::Path> = (0..PATHS / 2)
            .map(|_| draw_path(&mut rng, &labels))
            .collect();
        for w in [&tb.upper_witness, &tb.lower_witness].into_iter().flatten() {
            paths.push(w.renderman.clone());
        }
        above += usize::from(tb.upper_witness.is_some());
        below += usize::from(tb.lower_witness.is_some());
        let wholes = [
            format!("^{b}"),
            format!("{} - {b}", side.universe),
            format!("{a} - {b}"),
            format!("{a} & ^{b}"),
        ];
        for whole in wholes {
            let e = (side.parse)(&whole);
            // A product of two drawn operands may exceed the verdict's search budget.
            let Ok(t) = translate::<D>(&e, &corr) else {
                over_budget += 1;
                continue;
            };
            (side.within)(&whole, &e, &t, &corr, &paths);
        }
    }
    eprintln!(
        "{}: {above} operands with a path added above, {below} missed below; \
         {over_budget} wholes over budget",
        D::NAME
    );
    assert!(
        over_budget < INEXACT_OPERANDS / 4,
        "{over_budget} over budget"
    );
    assert!(
        above > INEXACT_OPERANDS / 4 && below > INEXACT_OPERANDS / 4,
        "{above} {below}: the witnesses that part the two directions were rarely drawn"
    );
}

/// Smaller operands than the default: the verdict on a whole searches a product.
fn operand_config() -> grammar::Config {
    grammar::Config {
        max_units: 6,
        set_algebra: false,
        ..grammar::Config::default()
    }
}

/// The bound properties drawn on purpose where rounding changes direction (docs/
/// language.md §19.2: the right side of `-` and the operand of `^` round the other way),
/// from RenderMan: generated expressions whose translation to OSL is not exact, under
/// `^` and on the right of `-`.
///
/// Faults planted in `lpe/src/translate/bound.rs`, each seen to fail this test and
/// reverted (the properties over generated expressions above pass both): `^` not
/// flipping its operand's bound; the right side of `-` not flipping it.
#[test]
fn renderman_complements_and_differences_of_inexact_operands_stay_within_their_bounds() {
    let cfg = operand_config();
    let mut cov = grammar::renderman::coverage();
    inexact_operands_round_the_other_way::<RenderMan>(
        43,
        Side {
            text: Box::new(move |rng| grammar::renderman::source(rng, &cfg, &mut cov)),
            parse: |t| renderman::Parser::default().parse(t).unwrap(),
            labels: |e| e.operands().iter().flat_map(|op| op.labels()).collect(),
            within: renderman_within_bounds,
            universe: "C.*[<L.>O]",
        },
    );
}

/// The same from the OSL dialect: operands whose translation to RenderMan is not exact.
///
/// Faults planted in `lpe/src/translate/bound.rs`, each seen to fail this test and
/// reverted: `^` not flipping its operand's bound; the right side of `-` not flipping it.
#[test]
fn osl_complements_and_differences_of_inexact_operands_stay_within_their_bounds() {
    let cfg = operand_config();
    let short = grammar::osl::Shorthand::of(&[], &[]);
    let mut cov = grammar::osl::coverage();
    inexact_operands_round_the_other_way::<Osl>(
        44,
        Side {
            text: Box::new(move |rng| grammar::osl::source(rng, &short, &cfg, &mut cov)),
            parse: |t| osl::parse(t, &Registered::none()).unwrap(),
            labels: labels_named_in,
            within: osl_within_bounds,
            universe: "C.*[LO]",
        },
    );
}
