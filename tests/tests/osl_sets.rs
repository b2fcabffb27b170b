//! OSL sets through the public API: a blow-up expression steps the NFA, the basic set
//! gets a DFA and both modes agree, emptiness warnings, and the dialect seam between
//! RenderMan and OSL sets.

use lpe::osl::{self, parse, Registered};
use lpe::{AovSet, Options};

fn set(srcs: &[&str], reg: &Registered, opts: &Options) -> AovSet<lpe::osl::Osl> {
    let aovs: Vec<_> = srcs
        .iter()
        .map(|s| (s.to_string(), parse(s, reg).unwrap()))
        .collect();
    AovSet::compile_under(&aovs, reg, opts).unwrap()
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
    assert_eq!(s.dialect(), "osl");
    let m = |p: &str| s.match_path(&p.parse().unwrap()).contains(0);
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
            let hit: Vec<usize> = s.match_path(&p).iter().collect();
            assert_eq!(hit, [want], "{p}");
        }
    }
    // `R,D,D`: the eater refuses the basic label D: no AOV.
    let p = "C,_ R,D,D L,_".parse().unwrap();
    assert!(dfa.match_path(&p).is_empty());
    assert!(nfa.match_path(&p).is_empty());
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

/// A set is of one dialect by type: an OSL vertex or path given to a RenderMan set does
/// not compile (the `compile_fail` example on `lpe::AovSet`), where it used to give a
/// class past the set's last, which stepped to the dead state. What is left to check at
/// run time: the set's dialect has its name, and the set keeps its own expressions.
/// An OSL set attempts the eager DFA within its dialect's own budget (2^20), however
/// large the caller's: `C.*<RD>.{12}L` has a DFA of 12 290 states that the default
/// 16 MiB would hold, and stays lazy; `.{10}` (3 074 states) gets its DFA. RenderMan sets
/// attempt within the caller's budget.
#[test]
fn the_dfa_attempt_has_its_own_budget_in_the_osl_dialect() {
    let reg = Registered::none();
    let ten = set(&["C.*<RD>.{10}L"], &reg, &Options::default());
    assert_eq!(ten.dfa_states(), Some(3074));
    let twelve = set(&["C.*<RD>.{12}L"], &reg, &Options::default());
    assert!(!twelve.uses_dfa());
    let p = format!("C,_ R,D {}L,_", "T,S ".repeat(12));
    assert!(twelve.match_path(&p.parse().unwrap()).contains(0));
    let rm = lpe::renderman::parse("C.*<RD>.{12}L").unwrap();
    assert!(AovSet::compile(&[("a".into(), rm)]).unwrap().uses_dfa());
}

/// A set keeps the registration it was compiled under.
#[test]
fn sets_keep_their_registration_in_the_osl_dialect() {
    let reg: Registered = "events=U;scatters=Y".parse().unwrap();
    let s = set(&["C<UY>L"], &reg, &Options::default());
    assert_eq!(s.registration(), &reg);
    assert!(s.match_path(&"C,_ U,Y L,_".parse().unwrap()).contains(0));
}

#[test]
fn renderman_sets_say_their_dialect_and_keep_their_expressions() {
    let s = AovSet::compile(&[("d".into(), lpe::renderman::parse("C<RD>L").unwrap())]).unwrap();
    assert_eq!(s.dialect(), "renderman");
    assert_eq!(s.lpes()[0].to_string(), "C<RD>L");
}

/// Dead states of OSL sets with set algebra, on every stepping mode: a complement `^A`
/// matches after every operand died, so "no active position" is not dead there. Exact
/// soundness of `is_dead` over every reachable state (one vertex per class), and
/// completeness on the DFA; and against the reference: once a path prefix is dead, no
/// AOV matches that prefix spliced with the tail of any path.
#[test]
fn dead_states_of_osl_set_algebra_are_sound_and_dfa_dead_states_complete() {
    use lpe::rng::SplitMix64;
    use lpe_testkit::generate::osl as gen;

    let cfg = gen::Config::default().with_max_vertices(5);
    let modes = [
        ("dfa", Options::default()),
        (
            "nfa",
            Options {
                dfa_budget: 0,
                lazy_cache: 0,
                ..Options::default()
            },
        ),
        (
            "lazy",
            Options {
                dfa_budget: 0,
                lazy_cache: 1,
                ..Options::default()
            },
        ),
    ];
    let (mut complements, mut dead_seen, mut complete_checked) = (0, 0, 0);
    for seed in 0..60u64 {
        let mut rng = SplitMix64::new(seed);
        let reg = gen::registered(&mut rng);
        let mut aovs: Vec<(String, osl::Lpe)> = Vec::new();
        while aovs.len() < 1 + (seed % 3) as usize {
            let l = gen::lpe(&mut rng, &reg, &cfg);
            if l.algebra.is_some() {
                aovs.push((format!("a{}", aovs.len()), l));
            }
        }
        if aovs.iter().any(|(_, l)| l.to_string().contains('^')) {
            complements += 1;
        }
        let mut paths: Vec<osl::Path> = Vec::new();
        for (_, l) in &aovs {
            for e in l.operands() {
                paths.extend((0..3).map(|_| gen::biased_path(e, &mut rng, &reg, &cfg)));
            }
        }
        paths.extend((0..6).map(|_| gen::uniform_path(&mut rng, &reg, &cfg)));
        for (mode, opts) in &modes {
            let set = AovSet::compile_under(&aovs, &reg, opts).unwrap();
            let letters: Vec<lpe::Class> = (0..set.class_count())
                .map(|c| set.classify(&set.class_vertex(c).unwrap()))
                .collect();
            // Every state reachable over the letters, and which can reach a match.
            let (states, live, explored) =
                match lpe_tests::reachable_and_live(&set, &letters, 20_000) {
                    Some((states, live)) => (states, live, true),
                    None => (Vec::new(), Vec::new(), false),
                };
            let complete = *mode == "dfa" && explored;
            complete_checked += usize::from(complete);
            for (s, &l) in states.iter().zip(&live) {
                if set.is_dead(*s) {
                    dead_seen += 1;
                    assert!(
                        !explored || !l,
                        "seed {seed} {mode}: a dead state reaches a match"
                    );
                    assert!(
                        set.matches(*s).is_empty(),
                        "seed {seed} {mode}: a dead state matches"
                    );
                } else if complete {
                    assert!(l, "seed {seed} {mode}: a live DFA state reaches no match");
                }
            }
            for p in &paths {
                let mut s = set.start();
                for k in 0..p.vertices.len() {
                    s = set.step_class(s, set.classify(&p.vertices[k]));
                    if !set.is_dead(s) {
                        continue;
                    }
                    for q in &paths {
                        for cut in 0..=q.vertices.len() {
                            let v = p.vertices[..=k].iter().chain(&q.vertices[cut..]);
                            let e = osl::Path::new(v.cloned().collect());
                            for (n, l) in &aovs {
                                assert!(
                                    !lpe_reference::lpe_tree::is_match(l, &e),
                                    "seed {seed} {mode}: dead after {k} vertices of `{p}` but \
                                     {n} `{l}` matches `{e}`"
                                );
                            }
                        }
                    }
                    break;
                }
            }
        }
    }
    // The run saw complements, dead states and complete DFA checks: none of the checks
    // above was vacuous.
    assert!(complements >= 10, "{complements}");
    assert!(dead_seen >= 20, "{dead_seen}");
    assert!(complete_checked >= 50, "{complete_checked}");
}
