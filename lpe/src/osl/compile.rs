//! An OSL set's compile step: the Glushkov NFA of its vertex patterns (the same
//! construction as RenderMan's, through [`Regex`]), its vertex classes, and its emptiness
//! warnings. [`crate::AovSet::compile_osl`] turns the NFA into the stepped automaton.

use super::ast::{Expr, Lpe, VertexPattern};
use super::classes::{TooManyVertexStates, VertexClasses, MAX_VERTEX_STATES};
use super::path::Vertex;
use super::symbol::Registered;
use crate::aov::{CompileError, Options};
use crate::automata::alphabet::AcceptTable;
use crate::automata::emptiness::{nonempty_under, Warning};
use crate::automata::mask::Class;
use crate::automata::nfa::{Builder, Nfa, Node, Regex};
use crate::automata::shape::ANY;

impl Regex for Expr {
    type Atom = VertexPattern;
    fn node(&self) -> Node<'_, Expr> {
        match self {
            Expr::Vertex(v) => Node::Atom(v),
            Expr::Concat(es) => Node::Concat(es),
            Expr::Alt(es) => Node::Alt(es),
            Expr::Repeat(e, r) => Node::Repeat(e, *r),
            Expr::Empty => Node::Empty,
            Expr::Nothing => Node::Alt(&[]),
        }
    }
}

/// What an OSL set keeps besides its automaton.
#[derive(Clone, Debug)]
pub(crate) struct Compiled {
    classes: VertexClasses,
    lpes: Vec<Lpe>,
    registered: Registered,
}

impl Compiled {
    /// The vertex classes and NFA of `aovs`, and the AOVs that can match nothing.
    pub(crate) fn build(
        aovs: &[(String, Lpe)],
        names: &[String],
        registered: &Registered,
        opts: &Options,
    ) -> Result<(Compiled, Nfa, Vec<Warning>), CompileError> {
        let (builder, parts) =
            Builder::of_all(aovs.iter().map(|(_, l)| &l.expr), opts.max_path_len);
        let classes = VertexClasses::new(&builder.atoms).map_err(|TooManyVertexStates| {
            CompileError::TooManyVertexStates {
                max: MAX_VERTEX_STATES,
            }
        })?;
        let atoms = builder.atoms.clone();
        let nfa = Nfa::new(builder, parts, &classes, opts.nfa_budget);
        let warnings = empty_aovs(&nfa, &classes, &atoms, names, aovs);
        let lpes = aovs.iter().map(|(_, l)| l.clone()).collect();
        Ok((
            Compiled {
                classes,
                lpes,
                registered: registered.clone(),
            },
            nfa,
            warnings,
        ))
    }

    #[inline]
    pub(crate) fn classify(&self, v: &Vertex) -> Class {
        self.classes.classify(v)
    }

    pub(crate) fn class_count(&self) -> usize {
        self.classes.class_count()
    }

    /// A shortest vertex of class `c`.
    pub(crate) fn representative(&self, c: usize) -> &Vertex {
        self.classes.representative(c)
    }

    pub(crate) fn lpes(&self) -> &[Lpe] {
        &self.lpes
    }

    pub(crate) fn registered(&self) -> &Registered {
        &self.registered
    }

    pub(crate) fn memory_bytes(&self) -> usize {
        self.classes.memory_bytes()
    }
}

/// AOVs that match no sequence of vertices at all. An OSL path has no fixed shape (the
/// renderer decides when to accumulate), so this is the only emptiness OSL sets report.
fn empty_aovs(
    nfa: &Nfa,
    classes: &VertexClasses,
    atoms: &[&VertexPattern],
    names: &[String],
    aovs: &[(String, Lpe)],
) -> Vec<Warning> {
    let live: Vec<bool> = (0..atoms.len())
        .map(|a| (0..classes.class_count()).any(|c| classes.accepts(c, a)))
        .collect();
    // Every live vertex pattern counts as one group under the any-sequence shape.
    let groups: Vec<u8> = live.iter().map(|&l| u8::from(l)).collect();
    let found = nonempty_under(nfa, &groups, &ANY, names.len());
    (0..names.len())
        .filter(|&i| !found[i])
        .map(|i| {
            let mut dead = None;
            aovs[i].1.expr.for_each_vertex(&mut |v| {
                if dead.is_none() {
                    if let Some(a) = atoms.iter().position(|&x| x == v) {
                        if !live[a] {
                            dead = Some(v.to_string());
                        }
                    }
                }
            });
            let message = match dead {
                Some(v) => {
                    format!("it matches no sequence of vertices at all (`{v}` matches no vertex)")
                }
                None => "it matches no sequence of vertices at all".to_string(),
            };
            Warning {
                aov: i,
                name: names[i].clone(),
                message,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use crate::osl::{parse, Registered};
    use crate::{AovSet, Dialect, Options};

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
        let srcs = crate::osl::BASIC.map(|(_, src)| src);
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
        let s = AovSet::compile(&[("d".into(), crate::parse("C<RD>L").unwrap())]).unwrap();
        assert_eq!(s.dialect(), Dialect::RenderMan);
        assert!(s.osl_lpes().is_empty());
        let p = "C,_ R,D L,_".parse().unwrap();
        assert!(s.match_osl_path(&p).is_empty());
    }
}
