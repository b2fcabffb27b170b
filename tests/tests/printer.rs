//! The canonical printer of both dialects, as round-trip properties: an expression's
//! printed form parses back to the same tree, for expressions written from the grammar
//! (`lpe_testkit::grammar`: the constructs no tree generator draws, such as OSL's
//! groups inside `<…>`, which the printer spells out), for generated OSL trees, and for
//! every expression of the conformance suite under its case's registration.
//!
//! Where they share: both sides of each comparison are lpe's own parser, so these tests
//! check the printer against the parser, not the parser against the documentation (the
//! conformance suite's verdicts and the grammar texts' acceptance do that). RenderMan's
//! generated trees are in `roundtrip.rs`.

use lpe::osl::{Osl, Registered};
use lpe::renderman::{Parser, RenderMan};
use lpe::rng::SplitMix64;
use lpe::DialectName;
use lpe_engines::EngineDialect;
use lpe_testkit::grammar::{self, Config};

/// `text` parses under `reg`, and its printed form parses back to the same tree.
fn round_trips<D: EngineDialect>(text: &str, reg: &D::Registration) -> Result<(), String> {
    let e = D::parse(text, reg).map_err(|err| format!("`{text}` does not parse: {err}"))?;
    let printed = e.to_string();
    let back = D::parse(&printed, reg)
        .map_err(|err| format!("`{text}` printed as `{printed}`, which does not parse: {err}"))?;
    if !D::same_tree(&back, &e) {
        return Err(format!(
            "`{text}` printed as `{printed}`, which parses to another tree (printed `{back}`)"
        ));
    }
    // Printing is stable: the canonical text is its own canonical text.
    if back.to_string() != printed {
        return Err(format!("`{printed}` reprints as `{back}`"));
    }
    Ok(())
}

#[test]
fn grammar_texts_print_and_reparse_to_the_same_tree() {
    let cfg = Config::default();
    let mut rng = SplitMix64::new(21);
    let mut cov = grammar::renderman::coverage();
    for _ in 0..5000 {
        let text = grammar::renderman::source(&mut rng, &cfg, &mut cov);
        round_trips::<RenderMan>(&text, &Parser::default()).unwrap();
    }
    let registered = Registered {
        events: vec!["U".into(), "1".into()],
        scatters: vec!["Y".into()],
        ..Registered::default()
    };
    let mut cov = grammar::osl::coverage();
    for i in 0..5000 {
        let reg = if i % 2 == 0 {
            Registered::none()
        } else {
            registered.clone()
        };
        let short = grammar::osl::Shorthand::of(&reg.events, &reg.scatters);
        let text = grammar::osl::source(&mut rng, &short, &cfg, &mut cov);
        round_trips::<Osl>(&text, &reg).unwrap();
    }
}

#[test]
fn generated_trees_print_and_reparse_in_the_osl_dialect() {
    let cfg = lpe_testkit::generate::osl::Config::default();
    let mut rng = SplitMix64::new(22);
    for _ in 0..3000 {
        let reg = lpe_testkit::generate::osl::registered(&mut rng);
        let e = lpe_testkit::generate::osl::lpe(&mut rng, &reg, &cfg);
        round_trips::<Osl>(&e.to_string(), &reg).unwrap();
    }
}

/// Hand-picked OSL texts whose printed form differs from the source: the printer's
/// spelling of each, written out by hand from docs/language.md §18.
#[test]
fn groups_inside_vertex_patterns_print_as_alternations_in_the_osl_dialect() {
    let none = Registered::none();
    for (text, printed) in [
        // `|` binds tighter than concatenation (§18.5): no parentheses needed.
        ("C<(R|T)D>L", "<C.><RD>|<TD><L.>"),
        // The group is one item: the scattering slot is padded with `.` after it.
        ("C<(RD)>L", "<C.><RD.><L.>"),
        // `|` takes one item each side inside a group too: R or T, D or G, then S.
        ("C<((R|T)D|GS)>L", "<C.><RDS.>|<RGS.>|<TDS.>|<TGS.><L.>"),
        // `-` inside `<…>` is a label, not set algebra.
        ("C<R-D>L", "<C.><R-D><L.>"),
    ] {
        let e = lpe::osl::parse(text, &none).unwrap();
        assert_eq!(e.to_string(), printed, "{text}");
        round_trips::<Osl>(text, &none).unwrap();
    }
}

#[test]
fn every_conformance_expression_prints_and_reparses_to_the_same_tree() {
    let suite = lpe_testkit::suite::load_dir(&lpe_testkit::suite::testdata_dir()).unwrap();
    let mut checked = [0usize; 2];
    for l in &suite {
        let case = &l.case;
        if case.error.is_some() {
            continue;
        }
        let sources = case
            .expr
            .iter()
            .chain(&case.same_as)
            .chain(case.aovs.iter().map(|a| &a.expr));
        for src in sources {
            let result = match l.dialect {
                DialectName::RenderMan => {
                    let parser = match &case.ini {
                        None => Parser::default(),
                        Some(ini) => lpe::renderman::Config::from_ini(ini).unwrap().parser(),
                    };
                    checked[0] += 1;
                    round_trips::<RenderMan>(src, &parser)
                }
                DialectName::Osl => {
                    checked[1] += 1;
                    round_trips::<Osl>(src, &l.registered)
                }
            };
            if let Err(why) = result {
                panic!("{}: {why}", l.location());
            }
        }
    }
    // The suite holds 174 RenderMan and 62 OSL expressions outside error cases; a loader that found
    // none would make this test pass vacuously.
    assert!(checked[0] > 150 && checked[1] > 50, "{checked:?}");
}
