//! OSL vertices folded into the classes a compiled set can tell apart.
//!
//! A vertex is a sequence of symbols over an open alphabet. Every symbol no pattern of the
//! set mentions behaves like every other one (slot patterns compare for equality with the
//! symbols they list, the eater with the basic labels), so symbols are interned into
//! *symbol ids*: NONE, each mentioned label, and OTHER. A vertex is then read by a small
//! automaton over symbol ids whose state is `(symbols read, capped; which patterns are
//! still alive)`: it is built once at compile time by a breadth-first search from the
//! empty vertex, deduplicating states, so only satisfiable combinations are ever
//! enumerated (never the product of every slot's answers). A class is the vector of which
//! patterns accept a vertex that ends in a state, interned; each class keeps the shortest
//! vertex reaching it as its representative. Classifying a vertex is one hash lookup and
//! one table load per symbol.

use crate::fxhash::FxMap;

use super::ast::{SymbolPattern, VertexPattern};
use super::path::Vertex;
use super::symbol::Symbol;
use crate::automata::ir::{Place, VertexClasses as ClassTable};
use crate::automata::mask::Class;
use crate::bits;

/// Most states the vertex-reading automaton may have before compiling gives up.
pub const MAX_VERTEX_STATES: usize = 1 << 16;

/// Symbol id of NONE; labels follow, OTHER is last.
const NONE_ID: u32 = 0;

/// The vertex classes of one compiled OSL set.
#[derive(Clone, Debug)]
pub struct VertexClasses {
    /// Mentioned labels to their symbol ids.
    label_ids: FxMap<Box<str>, u32>,
    /// The symbol id of every one-byte ASCII label, without hashing: most symbols a
    /// renderer feeds are built-in one-letter labels.
    ascii_ids: [u32; 128],
    /// NONE, the labels by id, then OTHER's stand-in label.
    symbols: Vec<Symbol>,
    /// `trans[state * symbols.len() + symbol id]`: the vertex-reading automaton.
    trans: Vec<u32>,
    /// The class of a vertex that ends in each state.
    class_of: Vec<u32>,
    /// `accept[class * words ..][..words]`: the atoms (distinct patterns) accepting it.
    accept: Vec<u64>,
    words: usize,
    /// One shortest vertex per class.
    reps: Vec<Vertex>,
}

/// The vertex-reading automaton passed [`MAX_VERTEX_STATES`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct TooManyVertexStates;

impl VertexClasses {
    /// The classes that `atoms` (the set's distinct vertex patterns) tell apart.
    pub(crate) fn new(atoms: &[&VertexPattern]) -> Result<VertexClasses, TooManyVertexStates> {
        let mut labels: Vec<&str> = atoms
            .iter()
            .flat_map(|p| {
                p.symbols
                    .iter()
                    .flat_map(SymbolPattern::symbols)
                    .chain(p.eater.iter().flatten())
            })
            .filter_map(|s| match s {
                Symbol::None => None,
                Symbol::Label(l) => Some(l.as_str()),
            })
            .collect();
        labels.sort_unstable();
        labels.dedup();
        let label_ids: FxMap<Box<str>, u32> = labels
            .iter()
            .enumerate()
            .map(|(i, l)| (Box::from(*l), i as u32 + 1))
            .collect();
        let other_id = labels.len() as u32 + 1;
        let mut ascii_ids = [other_id; 128];
        for (l, &id) in &label_ids {
            if let [b] = l.as_bytes() {
                if b.is_ascii() {
                    ascii_ids[*b as usize] = id;
                }
            }
        }
        let mut symbols = vec![Symbol::None];
        symbols.extend(labels.iter().map(|l| Symbol::label(*l)));
        // OTHER: any label no pattern mentions; a fresh name stands for it in witnesses.
        let other = (0..)
            .map(|i| {
                format!(
                    "other{}",
                    if i == 0 { String::new() } else { i.to_string() }
                )
            })
            .find(|n| !label_ids.contains_key(n.as_str()))
            .expect("some name is free");
        symbols.push(Symbol::label(other));
        let nsym = symbols.len();

        // Per atom: its slot patterns and eater exclusions evaluated on every symbol id.
        let slot_accepts: Vec<Vec<Vec<bool>>> = atoms
            .iter()
            .map(|p| {
                p.symbols
                    .iter()
                    .map(|sp| symbols.iter().map(|s| sp.accepts(s)).collect())
                    .collect()
            })
            .collect();
        let eater_skips: Vec<Option<Vec<bool>>> = atoms
            .iter()
            .map(|p| {
                p.eater
                    .as_ref()
                    .map(|ex| symbols.iter().map(|s| !ex.contains(s)).collect())
            })
            .collect();
        // A vertex needs two symbols before anything can accept it (OSL's slot patterns
        // exclude STOP); past the longest pattern, the count no longer matters.
        let need = |a: usize| atoms[a].symbols.len().max(2);
        let cap = (0..atoms.len()).map(need).max().unwrap_or(2) + 1;
        let words = atoms.len().div_ceil(64).max(1);

        // Breadth-first search over (count, alive patterns).
        let mut states: Vec<(usize, Box<[u64]>)> = Vec::new();
        let mut parent: Vec<(u32, u32)> = Vec::new();
        let mut ids: FxMap<(usize, Box<[u64]>), u32> = FxMap::default();
        let mut all = vec![0u64; words];
        (0..atoms.len()).for_each(|a| bits::set(&mut all, a));
        let start = (0usize, all.into_boxed_slice());
        ids.insert(start.clone(), 0);
        states.push(start);
        parent.push((u32::MAX, 0));
        let mut trans = Vec::new();
        let mut i = 0;
        while i < states.len() {
            let (n, alive) = states[i].clone();
            for sym in 0..nsym {
                let mut next = vec![0u64; words];
                for a in bits::ones(alive.iter().copied()) {
                    let slots = &slot_accepts[a];
                    let ok = match slots.get(n) {
                        Some(acc) => acc[sym],
                        None => eater_skips[a].as_ref().is_some_and(|e| e[sym]),
                    };
                    if ok {
                        bits::set(&mut next, a);
                    }
                }
                let key = ((n + 1).min(cap), next.into_boxed_slice());
                let id = match ids.get(&key) {
                    Some(&id) => id,
                    None => {
                        if states.len() >= MAX_VERTEX_STATES {
                            return Err(TooManyVertexStates);
                        }
                        let id = states.len() as u32;
                        ids.insert(key.clone(), id);
                        states.push(key);
                        parent.push((i as u32, sym as u32));
                        id
                    }
                };
                trans.push(id);
            }
            i += 1;
        }

        // Classes: the accept vectors of states reached by at least one symbol, in BFS
        // order so that each representative is a shortest vertex.
        let accept_of = |(n, alive): &(usize, Box<[u64]>)| -> Box<[u64]> {
            let mut out = vec![0u64; words];
            for a in bits::ones(alive.iter().copied()) {
                if *n >= need(a) {
                    bits::set(&mut out, a);
                }
            }
            out.into_boxed_slice()
        };
        let mut class_ids: FxMap<Box<[u64]>, u32> = FxMap::default();
        let mut accept = Vec::new();
        let mut reps = Vec::new();
        let mut class_of = vec![0u32; states.len()];
        for (s, state) in states.iter().enumerate().skip(1) {
            let vec = accept_of(state);
            let next = class_ids.len() as u32;
            let c = *class_ids.entry(vec.clone()).or_insert_with(|| {
                accept.extend_from_slice(&vec);
                let mut syms = Vec::new();
                let mut at = s;
                while parent[at].0 != u32::MAX {
                    syms.push(symbols[parent[at].1 as usize].clone());
                    at = parent[at].0 as usize;
                }
                syms.reverse();
                reps.push(Vertex::new(syms));
                next
            });
            class_of[s] = c;
        }
        // The empty vertex accepts nothing, like every one-symbol vertex (state 1).
        class_of[0] = class_of[1];
        Ok(VertexClasses {
            label_ids,
            ascii_ids,
            symbols,
            trans,
            class_of,
            accept,
            words,
            reps,
        })
    }

    #[inline]
    fn symbol_id(&self, s: &Symbol) -> usize {
        match s {
            Symbol::None => NONE_ID as usize,
            Symbol::Label(l) if l.len() == 1 && l.as_bytes()[0].is_ascii() => {
                self.ascii_ids[l.as_bytes()[0] as usize] as usize
            }
            Symbol::Label(l) => self
                .label_ids
                .get(l.as_str())
                .map_or(self.symbols.len() - 1, |&i| i as usize),
        }
    }

    /// The class of a whole vertex.
    #[inline]
    pub(crate) fn classify(&self, v: &Vertex) -> Class {
        let n = self.symbols.len();
        let end = v.symbols.iter().fold(0usize, |s, sym| {
            self.trans[s * n + self.symbol_id(sym)] as usize
        });
        Class(self.class_of[end])
    }

    /// A shortest vertex of class `c`.
    #[cfg(test)]
    fn representative(&self, c: usize) -> &Vertex {
        &self.reps[c]
    }

    pub(crate) fn memory_bytes(&self) -> usize {
        (self.trans.len() + self.class_of.len()) * 4
            + self.accept.len() * 8
            + self.label_ids.keys().map(|k| k.len() + 24).sum::<usize>()
    }
}

impl ClassTable for VertexClasses {
    type Vertex = Vertex;

    #[inline]
    fn classify(&self, v: &Vertex) -> Class {
        VertexClasses::classify(self, v)
    }

    fn class_count(&self) -> usize {
        self.reps.len()
    }

    fn accepts(&self, c: usize, a: usize) -> bool {
        bits::get(&self.accept[c * self.words..][..self.words], a)
    }

    /// Every class occurs anywhere (OSL paths have no fixed shape).
    fn representative(&self, c: usize, _: Place) -> Option<Vertex> {
        self.reps.get(c).cloned()
    }

    fn memory_bytes(&self) -> usize {
        VertexClasses::memory_bytes(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::osl::{parse, Registered};

    fn patterns(srcs: &[&str], reg: &Registered) -> Vec<VertexPattern> {
        let mut out: Vec<VertexPattern> = Vec::new();
        for s in srcs {
            parse(s, reg).unwrap().expr.for_each_vertex(&mut |v| {
                if !out.contains(v) {
                    out.push(v.clone());
                }
            });
        }
        out
    }

    fn classes(pats: &[VertexPattern]) -> VertexClasses {
        VertexClasses::new(&pats.iter().collect::<Vec<_>>()).unwrap()
    }

    /// The memory model: every table at its element's size, and each mentioned label's
    /// text plus 24 bytes (its box and map entry).
    #[test]
    fn memory_counts_every_table_at_its_element_size_and_each_label() {
        let vc = classes(&patterns(
            &["C<RD'key'>[LO]", "C'lamp'L"],
            &Registered::none(),
        ));
        assert!(!vc.trans.is_empty() && !vc.class_of.is_empty() && !vc.accept.is_empty());
        let tables = std::mem::size_of_val(vc.trans.as_slice())
            + std::mem::size_of_val(vc.class_of.as_slice())
            + std::mem::size_of_val(vc.accept.as_slice());
        // Every built-in label is mentioned (the eater tells them from the rest), then
        // the custom ones of the patterns.
        let mentioned = [
            "B", "C", "D", "G", "L", "O", "R", "S", "T", "V", "key", "lamp", "s",
        ];
        let labels: usize = mentioned.iter().map(|l| l.len() + 24).sum();
        let mut keys: Vec<&str> = vc.label_ids.keys().map(|k| &**k).collect();
        keys.sort_unstable();
        assert_eq!(keys, mentioned);
        assert_eq!(vc.memory_bytes(), tables + labels);
        // The automaton layer asks through the trait: the same count.
        assert_eq!(ClassTable::memory_bytes(&vc), tables + labels);
    }

    #[test]
    fn classes_agree_with_each_pattern_on_every_vertex() {
        let reg: Registered = "events=U;scatters=Y".parse().unwrap();
        let pats = patterns(
            &[
                "C<RD>[LO]",
                "C[^D]'foo'<R[GS]'a'>",
                "<Cx><(RD)>U<RD12345>Y",
                "[^'foo']",
            ],
            &reg,
        );
        let vc = classes(&pats);
        let words = [
            "R", "D", "G", "C", "L", "foo", "a", "1", "2", "3", "4", "5", "zz", "U", "Y", "_",
        ];
        let mut vertices: Vec<Vec<Symbol>> = vec![vec![]];
        // Every vertex of up to 4 symbols over these words and NONE (a sample beyond).
        for len in 1..=4 {
            let mut idx = vec![0usize; len];
            loop {
                vertices.push(
                    idx.iter()
                        .map(|&i| words.get(i).map_or(Symbol::None, |w| Symbol::label(*w)))
                        .collect(),
                );
                let mut k = 0;
                while k < len {
                    idx[k] += 1;
                    if idx[k] <= words.len() {
                        break;
                    }
                    idx[k] = 0;
                    k += 1;
                }
                if k == len {
                    break;
                }
            }
        }
        vertices.push(
            ["R", "D", "1", "2", "3", "4", "5"]
                .map(Symbol::label)
                .to_vec(),
        );
        vertices.push(
            ["R", "D", "1", "2", "3", "4", "5", "6"]
                .map(Symbol::label)
                .to_vec(),
        );
        for syms in vertices {
            let c = vc.classify(&Vertex::new(syms.clone())).index();
            for (a, p) in pats.iter().enumerate() {
                assert_eq!(vc.accepts(c, a), p.accepts(&syms), "{p} on {syms:?}");
            }
        }
        // Representatives are members of their class.
        for c in 0..vc.class_count() {
            assert_eq!(vc.classify(vc.representative(c)).index(), c);
        }
    }

    /// Past 64 patterns a class's accepting atoms take more than one word: each class
    /// reads its own row.
    #[test]
    fn classes_of_more_than_64_patterns_accept_across_words() {
        let srcs: Vec<String> = (0..70).map(|i| format!("<R.'l{i}'>")).collect();
        let srcs: Vec<&str> = srcs.iter().map(String::as_str).collect();
        let pats = patterns(&srcs, &Registered::none());
        assert_eq!(pats.len(), 70);
        let vc = classes(&pats);
        for i in [0, 1, 63, 64, 69] {
            let label = format!("l{i}");
            let syms = ["R", "D", label.as_str()].map(Symbol::label).to_vec();
            let c = vc.classify(&Vertex::new(syms.clone())).index();
            for (a, p) in pats.iter().enumerate() {
                assert_eq!(vc.accepts(c, a), a == i, "{p} on {syms:?}");
                assert_eq!(p.accepts(&syms), a == i, "{p} on {syms:?}");
            }
        }
    }

    #[test]
    fn short_vertices_and_unmentioned_labels() {
        let pats = patterns(&["C<RD>L"], &Registered::none());
        let vc = classes(&pats);
        let c = |v: &[&str]| vc.classify(&Vertex::labels(v));
        // Nothing accepts a vertex of fewer than two symbols.
        let none_class = c(&["R"]);
        assert!((0..pats.len()).all(|a| !vc.accepts(none_class.index(), a)));
        assert_eq!(c(&[]), none_class);
        // Unmentioned labels are alike; basic ones are not skipped by the eater.
        assert_eq!(c(&["R", "D", "zz"]), c(&["R", "D", "yy"]));
        assert_eq!(c(&["R", "D", "zz"]), c(&["R", "D"]));
        assert_ne!(c(&["R", "D", "G"]), c(&["R", "D"]));
        // C, L, <RD> and "none": four classes.
        assert_eq!(vc.class_count(), 4);
        assert_eq!(vc.representative(none_class.index()).symbols.len(), 1);
    }

    #[test]
    fn too_many_states_is_an_error_not_a_hang() {
        // Pattern j has 20 slots `[^j]`: reading label j kills pattern j only, so after 20
        // symbols every subset of the 20 patterns is alive in some state (2^20 of them).
        let pats: Vec<VertexPattern> = (0..20)
            .map(|j| VertexPattern {
                symbols: vec![SymbolPattern::NotIn(vec![Symbol::label(j.to_string())]); 20],
                eater: None,
            })
            .collect();
        let r = VertexClasses::new(&pats.iter().collect::<Vec<_>>());
        assert_eq!(r.unwrap_err(), TooManyVertexStates);
        // Eight such patterns fit (2^8 subsets per depth).
        assert!(VertexClasses::new(&pats[..8].iter().collect::<Vec<_>>()).is_ok());
    }
}
