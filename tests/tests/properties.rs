//! Cross-crate property tests (proptest). The expression print/parse round trip is in
//! `roundtrip.rs`; the path text round trip is here.
//!
//! Case counts are small enough that the whole suite runs in well under three minutes
//! in release mode; `PROPTEST_CASES=N` raises every suite to N cases. Failures found
//! by proptest are persisted under `tests/proptest-regressions/` (commit them) and,
//! because persisted seeds stop reproducing when a strategy changes, should also be
//! copied into a named unit test.

use lpe::renderman::ast::Expr;
use lpe::renderman::macros::{MacroTable, BASIC};
use lpe::renderman::{Event, EventKind, Lpe, Parser, Path, Prefixes, RenderMan, Vertex};
use lpe_engines::differential::{self, Outcome};
use lpe_engines::{Engine, Reference};
use lpe_testkit::strategy;
use lpe_tests::cases;
use proptest::prelude::*;

/// The engines compared: the registry plus the eager (dense DFA) form of the
/// regex-automata engine (`oracle`), which the registry does not use. The eager form
/// falls back to the lazy DFA over its size limit without saying so; that engine's unit
/// tests check that it really builds the dense DFA on the conformance cases and the
/// basic AOVs.
fn engines() -> Vec<&'static dyn Engine<RenderMan>> {
    let mut all = lpe_engines::all::<RenderMan>();
    all.push(&lpe_engines::regex::EAGER);
    all
}

fn lpe_of(expr: Expr) -> Lpe {
    Lpe::new(Prefixes::NONE, expr)
}

fn assert_agree(exprs: &[Lpe], paths: &[Path]) -> Result<(), TestCaseError> {
    match differential::check_with(&engines(), exprs, paths) {
        // The strategies stay under every engine's size limits, so an engine that did
        // not build would make this "agreement" a comparison of fewer engines than
        // claimed (one engine always agrees with itself).
        Outcome::Agree(a) => {
            prop_assert!(a.skipped.is_empty(), "skipped: {:?}", a.skipped);
            prop_assert_eq!(a.engines, engines().len());
            Ok(())
        }
        Outcome::Disagree(c) => Err(TestCaseError::fail(c.to_string())),
    }
}

/// A light-transport path (no user lobe), of 2..=8 vertices: user lobes of a random
/// path become diffuse lobes (rejecting them instead would discard most long paths).
fn transport_path() -> impl Strategy<Value = Path> {
    strategy::path(8).prop_map(|p| {
        let v = p
            .vertices()
            .iter()
            .map(|v| match v.event() {
                Some(e) if !e.is_transport() => {
                    let lobe = 1 + (e.lobe() - 1) % EventKind::D.max_lobe();
                    let d = Event::new(EventKind::D, lobe).unwrap();
                    Vertex::scatter(v.ty(), d, v.label())
                }
                _ => v.clone(),
            })
            .collect();
        Path::new(v).unwrap()
    })
}

proptest! {
    #![proptest_config(cases(4096))]

    #[test]
    fn path_text_round_trips(path in strategy::path(10)) {
        let text = path.to_string();
        prop_assert_eq!(text.parse::<Path>().unwrap(), path);
    }
}

proptest! {
    #![proptest_config(cases(1024))]

    #[test]
    fn reference_and_oracle_agree_on_single_expressions(
        (expr, paths) in strategy::aov_expr().prop_flat_map(|e| {
            let paths = strategy::biased_paths(&e, 6);
            (Just(e), paths)
        })
    ) {
        assert_agree(&[lpe_of(expr)], &paths)?;
    }

    #[test]
    fn reference_and_oracle_agree_on_random_expressions(
        expr in strategy::expr(),
        paths in prop::collection::vec(strategy::path(8), 4),
    ) {
        assert_agree(&[lpe_of(expr)], &paths)?;
    }

    #[test]
    fn reference_and_oracle_agree_on_aov_sets(
        (exprs, paths) in prop::collection::vec(strategy::aov_expr(), 2..5).prop_flat_map(|es| {
            let first = es[0].clone();
            (Just(es), strategy::biased_paths(&first, 6), prop::collection::vec(strategy::path(8), 2))
        }).prop_map(|(es, mut a, b)| { a.extend(b); (es, a) })
    ) {
        let exprs: Vec<Lpe> = exprs.into_iter().map(lpe_of).collect();
        assert_agree(&exprs, &paths)?;
    }

    /// Every light-transport path matches exactly one of the seven basic AOVs; a path
    /// with a user-lobe vertex (outside `C.*[<L.>O]`) matches none.
    #[test]
    fn basic_aovs_are_disjoint_and_exhaustive(path in strategy::path(8)) {
        let exprs: Vec<Lpe> = BASIC.iter().map(|(_, s)| lpe::renderman::parse(s).unwrap()).collect();
        // Decided from the path alone, not by any engine.
        let transport = path.vertices().iter().all(|v| v.event().is_none_or(|e| e.is_transport()));
        for e in engines() {
            let which = e.compile(&exprs, &Parser::default()).unwrap().which(&path);
            let hits = which.count();
            prop_assert_eq!(hits, usize::from(transport), "{} on {}: {:?}", e.name(), path, which);
        }
    }

    #[test]
    fn light_transport_paths_always_land_in_one_basic_aov(path in transport_path()) {
        let exprs: Vec<Lpe> = BASIC.iter().map(|(_, s)| lpe::renderman::parse(s).unwrap()).collect();
        for e in engines() {
            let which = e.compile(&exprs, &Parser::default()).unwrap().which(&path);
            prop_assert_eq!(which.count(), 1, "{} on {}", e.name(), path);
        }
    }

    /// Any spelling of a built-in macro name (case, `lpe:`, surrounding blanks) expands
    /// to the AST of its written form, and matches the same paths.
    #[test]
    fn macro_expansion_equals_its_written_form(
        index in 0usize..MacroTable::builtin().names().count(),
        upper in prop::collection::vec(any::<bool>(), 64),
        lpe_prefix in any::<bool>(),
        path in strategy::path(6),
    ) {
        let table = MacroTable::builtin();
        let (name, source) = table.iter().nth(index).unwrap();
        let spelled: String = name
            .chars()
            .zip(upper.iter().cycle())
            .map(|(c, &u)| if u { c.to_ascii_uppercase() } else { c.to_ascii_lowercase() })
            .collect();
        let text = format!("{} {spelled} ", if lpe_prefix { "lpe:" } else { "" });
        let expanded = lpe::renderman::parse(&text).unwrap();
        let written = lpe::renderman::parse(source).unwrap();
        prop_assert_eq!(&expanded, &written, "{}", text);
        assert_agree(&[expanded, written], &[path])?;
    }

    /// `NAME_group` equals the macro's text with every `<L.>` written as `<L.'group'>`
    /// by hand (a string edit, independent of the parser's AST rewrite).
    #[test]
    fn light_group_suffix_equals_the_hand_written_expression(
        index in 0usize..BASIC.len(),
        group in "[A-Za-z0-9_]{1,8}",
        path in strategy::path(6),
        grouped_light in any::<bool>(),
    ) {
        let (name, source) = BASIC[index];
        let suffixed = lpe::renderman::parse(&format!("{name}_{group}")).unwrap();
        let by_hand = lpe::renderman::parse(&source.replace("<L.>", &format!("<L.'{group}'>"))).unwrap();
        prop_assert_eq!(&suffixed, &by_hand);
        // Give the path's light the group half the time, so the label matters.
        let mut v = path.vertices().to_vec();
        let last = v.len() - 1;
        if grouped_light && v[last].ty() == lpe::renderman::VertexType::L {
            v[last] = Vertex::light(Some(&group));
        }
        let path = Path::new(v).unwrap();
        assert_agree(&[suffixed, by_hand], &[path])?;
    }
}

#[test]
fn the_reference_engine_is_in_the_comparison() {
    let names: Vec<&str> = engines().iter().map(|e| e.name()).collect();
    assert_eq!(names[0], Engine::<RenderMan>::name(&Reference));
    assert!(names.contains(&"oracle"));
}
