//! An OSL set's compile step: the Glushkov NFA of its vertex patterns (the same
//! construction as RenderMan's, through [`Regex`]), its vertex classes, and its emptiness
//! warnings. [`crate::AovSet::compile_osl`] turns the NFA into the stepped automaton.

use super::ast::{Expr, Lpe, VertexPattern};
use super::classes::{TooManyVertexStates, VertexClasses};
use super::path::Vertex;
use super::symbol::Registered;
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
    /// The vertex classes and NFA of `operands` (every operand of `aovs`, each a hidden
    /// AOV of the NFA; repetitions bounded by `max_path_len`, step tables within
    /// `nfa_budget`), and the operands that can match nothing (named by `hidden_names`,
    /// numbered as hidden AOVs).
    pub(crate) fn build(
        aovs: &[(String, Lpe)],
        operands: &[&Expr],
        hidden_names: &[String],
        registered: &Registered,
        max_path_len: Option<u32>,
        nfa_budget: usize,
    ) -> Result<(Compiled, Nfa, Vec<Warning>), TooManyVertexStates> {
        let (builder, parts) = Builder::of_all(operands.iter().copied(), max_path_len);
        let classes = VertexClasses::new(&builder.atoms)?;
        let atoms = builder.atoms.clone();
        let nfa = Nfa::new(builder, parts, &classes, nfa_budget);
        let warnings = empty_aovs(&nfa, &classes, &atoms, hidden_names, operands);
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
    operands: &[&Expr],
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
            operands[i].for_each_vertex(&mut |v| {
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
