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
//!   expression equivalent to the source.

use std::collections::BTreeSet;

use lpe::osl::Osl;
use lpe::osl::{self, Registered};
use lpe::renderman::RenderMan;
use lpe::renderman::{self, Event, VertexType};
use lpe::rng::SplitMix64;
use lpe::translate::{translate, Correspondence, Reason};
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

const EXPRESSIONS: usize = 300;
const PATHS: usize = 120;

#[test]
fn renderman_expressions_translate_to_osl_within_their_bounds_and_back() {
    let corr = Correspondence::default();
    let mut rng = SplitMix64::new(41);
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
        let (e_ref, up_ref, low_ref) = (&e, &t.text, &t.lower);
        for _ in 0..PATHS {
            let p = draw_path(&mut rng, &labels);
            let m = is_match(e_ref, &p);
            match corr.view_path(&p) {
                Some(o) => {
                    let (up, low) = (is_match(up_ref, &o), is_match(low_ref, &o));
                    assert!(
                        !low || m,
                        "`{text}`: lower `{low_ref}` matches {o}, source not {p}"
                    );
                    if m && !has_user_lobe(&p) {
                        assert!(up, "`{text}`: upper `{up_ref}` misses {o} ({p})");
                    }
                    if t.exact {
                        assert_eq!(m, up, "`{text}` exact as `{up_ref}`, differs on {p} / {o}");
                    }
                }
                None if has_user_lobe(&p) && t.exact => {
                    assert!(!m, "`{text}` exact, yet matches {p}, which has no OSL view");
                }
                None => {}
            }
        }
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
    eprintln!("RenderMan: {exact} of {EXPRESSIONS} exact, {back_exact} exact back; {verdicts:?}");
    assert!(
        exact > EXPRESSIONS / 10,
        "{exact}: the property is near vacuous"
    );
    assert!(back_exact * 2 > exact, "{back_exact} of {exact}");
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
        for _ in 0..PATHS {
            let p = draw_path(&mut rng, &labels);
            let (up, low) = (is_match(&t.text, &p), is_match(&t.lower, &p));
            match corr.view_path(&p) {
                Some(o) => {
                    let m = is_match(&f, &o);
                    assert!(
                        !low || m,
                        "`{text}`: lower `{}` matches {p}, source not {o}",
                        t.lower
                    );
                    assert!(!m || up, "`{text}`: upper `{}` misses {p} ({o})", t.text);
                    if t.exact {
                        assert_eq!(m, up, "`{text}` exact as `{}`, differs on {p}", t.text);
                    }
                    if let Some(b) = back.as_ref().filter(|b| b.exact) {
                        assert_eq!(
                            m,
                            is_match(&b.text, &o),
                            "`{text}` back as `{}` on {o}",
                            b.text
                        );
                    }
                }
                None if has_user_lobe(&p) && t.exact => {
                    assert!(!up, "`{text}` exact as `{}`, yet matches {p}", t.text);
                }
                None => {}
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
