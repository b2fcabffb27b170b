//! OSL sets through the public API: a blow-up expression steps the NFA, the basic set
//! gets a DFA and both modes agree, emptiness warnings, and the dialect seam between
//! RenderMan and OSL sets.

use lpe::osl::{self, parse, Registered};
use lpe::{AovSet, Dialect, Options};

fn set(srcs: &[&str], reg: &Registered, opts: &Options) -> AovSet {
    let aovs: Vec<_> = srcs
        .iter()
        .map(|s| (s.to_string(), parse(s, reg).unwrap()))
        .collect();
    AovSet::compile_osl(&aovs, reg, opts).unwrap()
}

#[test]
fn redos_expression_steps_the_nfa_and_answers_right() {
    // C R ( (('a'+|G) [^S]{2} [^OC]){2,} | ((L|T*) [sBO]{2,})+ )
    let reg = Registered::none();
    let s = set(
        &["C(R('a'+|G[^S]{2}[^OC]){2,}|(L|T*[sBO]{2,})+)"],
        &reg,
        &Options::default(),
    );
    assert!(!s.uses_dfa());
    assert_eq!(s.dialect(), Dialect::Osl);
    let m = |p: &str| s.match_osl_path(&p.parse().unwrap()).contains(0);
    assert!(m("C,_ R,D L,_ B,_ O,_"));
    assert!(!m("C,_ R,D L,_ B,_"));
    assert!(m("C,_ R,D T,D T,G s,s B,_"));
    let x = "R,D,a R,D R,D R,D";
    assert!(m(&format!("C,_ R,D {x} {x}")));
    assert!(!m(&format!("C,_ R,D {x} R,D,a R,D R,D")));
    // `[^OC]` ends each repetition: an O event there breaks it.
    assert!(!m(&format!("C,_ R,D {x} R,D,a R,D R,D O,D")));
}

#[test]
fn basic_set_gets_a_dfa_and_both_modes_agree() {
    let reg = Registered::none();
    let srcs = osl::BASIC.map(|(_, src)| src);
    let dfa = set(&srcs, &reg, &Options::default());
    let nfa = set(
        &srcs,
        &reg,
        &Options {
            dfa_budget: 0,
            ..Options::default()
        },
    );
    assert!(dfa.uses_dfa() && !nfa.uses_dfa());
    let cases = [
        ("C,_ R,D L,_", 0),
        ("C,_ R,D R,G O,_", 1),
        ("C,_ T,D L,_", 2),
        ("C,_ T,D T,S R,D L,_", 2),
        ("C,_ R,S,glass L,_", 3),
        ("C,_ R,G R,D L,_", 4),
        ("C,_ T,S O,_", 5),
        ("C,_ L,_", 6),
    ];
    for (p, want) in cases {
        let p = p.parse().unwrap();
        for s in [&dfa, &nfa] {
            let hit: Vec<usize> = s.match_osl_path(&p).iter().collect();
            assert_eq!(hit, [want], "{p}");
        }
    }
    // `R,D,D`: the eater refuses the basic label D: no AOV.
    let p = "C,_ R,D,D L,_".parse().unwrap();
    assert!(dfa.match_osl_path(&p).is_empty());
    assert!(nfa.match_osl_path(&p).is_empty());
}

#[test]
fn emptiness_warnings_name_the_dead_vertex() {
    let reg = Registered::none();
    let s = set(&["C<R[]>L", "C[]L", "CL"], &reg, &Options::default());
    let w = s.warnings();
    assert_eq!(w.len(), 2, "{w:?}");
    assert_eq!((w[0].aov, w[1].aov), (0, 1));
    assert!(
        w[0].message.contains("`<R[]>` matches no vertex"),
        "{}",
        w[0]
    );
    assert!(w[1].message.contains("matches no sequence"), "{}", w[1]);
}

#[test]
fn renderman_sets_say_their_dialect_and_give_osl_vertices_no_class() {
    let s = AovSet::compile(&[("d".into(), lpe::parse("C<RD>L").unwrap())]).unwrap();
    assert_eq!(s.dialect(), Dialect::RenderMan);
    assert!(s.osl_lpes().is_empty());
    let p = "C,_ R,D L,_".parse().unwrap();
    assert!(s.match_osl_path(&p).is_empty());
    let c = s.classify_osl(&"C,_".parse().unwrap());
    assert_eq!(c.index(), s.class_count());
    assert!(s.is_dead(s.step_class(s.start(), c)));
}
