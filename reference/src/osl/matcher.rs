//! The reference matcher for the OSL dialect: OSL's definition of a match executed as
//! plainly as possible (docs/language.md §18.8), on this crate's own tree
//! ([`super::ast`]).
//!
//! OSL matches an expression against the path's **symbol stream**: for every vertex its
//! symbols (event, scattering, custom labels) followed by STOP, camera first, anchored
//! at both ends. Each vertex pattern of the expression stands for a symbol-level
//! sequence: its slot items (a `( … )` item a sub-expression over symbols), then (if the
//! pattern has an eater) zero or more symbols outside the eater's exclusions, then STOP.
//! This module rewrites the expression into that symbol-level regular expression
//! ([`Node`]) and matches it on the stream by computing, for a node and a start
//! position, the set of positions where a match of the node can end. Results are
//! memoized on (node, position), so the time is polynomial in the stream length
//! whatever the expression's shape.
//!
//! It shares nothing with lpe's vertex-class automata (which classify a whole vertex at
//! once): the two check each other. Paths are lpe's (`lpe::osl::Path`): the path parser
//! is not what the reference front end checks.

use std::collections::{BTreeSet, HashMap};

use lpe::osl::{Path, Symbol};

use super::ast::{Expr, Lpe, Pattern, Slot, Sym};
use crate::error::Count;

/// One token of a path's symbol stream.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Token {
    Symbol(Sym),
    Stop,
}

/// The symbol-level expression, nodes in an arena (children by index).
#[derive(Debug)]
enum Node<'a> {
    /// One symbol (never STOP) accepted by the pattern.
    Symbol(&'a Pattern),
    /// Zero or more symbols, none STOP and none in the list (OSL's eater).
    Eater(&'a [Sym]),
    /// The end of a vertex.
    Stop,
    Concat(Vec<usize>),
    Alt(Vec<usize>),
    Repeat(usize, Count),
    /// No sequence at all.
    Nothing,
}

/// Whether one symbol (never STOP) satisfies a slot pattern.
pub fn symbol_matches(p: &Pattern, s: &Sym) -> bool {
    match p {
        Pattern::Any => true,
        Pattern::Is(x) => x == s,
        Pattern::Either(ps) => ps.iter().any(|p| symbol_matches(p, s)),
        Pattern::NotIn(xs) => !xs.contains(s),
    }
}

struct Matcher<'a> {
    nodes: Vec<Node<'a>>,
    stream: Vec<Token>,
    memo: HashMap<(usize, usize), BTreeSet<usize>>,
}

impl<'a> Matcher<'a> {
    fn push(&mut self, n: Node<'a>) -> usize {
        self.nodes.push(n);
        self.nodes.len() - 1
    }

    /// Lowers one slot item to symbol level.
    fn lower_slot(&mut self, s: &'a Slot) -> usize {
        match s {
            Slot::One(p) => self.push(Node::Symbol(p)),
            Slot::Group(alts) => {
                let parts = alts
                    .iter()
                    .map(|seq| {
                        let seq = seq.iter().map(|s| self.lower_slot(s)).collect();
                        self.push(Node::Concat(seq))
                    })
                    .collect();
                self.push(Node::Alt(parts))
            }
        }
    }

    /// Lowers the vertex-level tree to symbol level.
    fn lower(&mut self, e: &'a Expr) -> usize {
        match e {
            Expr::Vertex(v) => {
                let mut seq: Vec<usize> = v.slots.iter().map(|s| self.lower_slot(s)).collect();
                if let Some(excluded) = &v.eater {
                    seq.push(self.push(Node::Eater(excluded)));
                }
                seq.push(self.push(Node::Stop));
                self.push(Node::Concat(seq))
            }
            Expr::Seq(es) => {
                let parts = es.iter().map(|e| self.lower(e)).collect();
                self.push(Node::Concat(parts))
            }
            Expr::Alt(es) => {
                let parts = es.iter().map(|e| self.lower(e)).collect();
                self.push(Node::Alt(parts))
            }
            Expr::Repeat(body, r) => {
                let b = self.lower(body);
                self.push(Node::Repeat(b, *r))
            }
            Expr::Nothing => self.push(Node::Nothing),
        }
    }

    /// Every position where a match of node `n` starting at `i` can end.
    fn ends(&mut self, n: usize, i: usize) -> BTreeSet<usize> {
        if let Some(known) = self.memo.get(&(n, i)) {
            return known.clone();
        }
        let out = match &self.nodes[n] {
            Node::Symbol(p) => match self.stream.get(i) {
                Some(Token::Symbol(s)) if symbol_matches(p, s) => BTreeSet::from([i + 1]),
                _ => BTreeSet::new(),
            },
            Node::Eater(excluded) => {
                let mut out = BTreeSet::from([i]);
                let mut j = i;
                while let Some(Token::Symbol(s)) = self.stream.get(j) {
                    if excluded.contains(s) {
                        break;
                    }
                    j += 1;
                    out.insert(j);
                }
                out
            }
            Node::Stop => match self.stream.get(i) {
                Some(Token::Stop) => BTreeSet::from([i + 1]),
                _ => BTreeSet::new(),
            },
            Node::Concat(parts) => {
                let parts = parts.clone();
                let mut at = BTreeSet::from([i]);
                for p in parts {
                    at = self.step(p, &at);
                }
                at
            }
            Node::Alt(parts) => {
                let parts = parts.clone();
                let mut out = BTreeSet::new();
                for p in parts {
                    out.extend(self.ends(p, i));
                }
                out
            }
            &Node::Repeat(body, r) => self.repeat(body, r, i),
            Node::Nothing => BTreeSet::new(),
        };
        self.memo.insert((n, i), out.clone());
        out
    }

    /// Every end of node `n` from any of the starts `from`.
    fn step(&mut self, n: usize, from: &BTreeSet<usize>) -> BTreeSet<usize> {
        let mut out = BTreeSet::new();
        for &j in from {
            out.extend(self.ends(n, j));
        }
        out
    }

    /// `body{min,max}` from `i`: the positions after exactly `k` iterations, united over
    /// `min <= k <= max`.
    fn repeat(&mut self, body: usize, r: Count, i: usize) -> BTreeSet<usize> {
        // After exactly `min` iterations. The sequence of position sets S(k+1) =
        // step(S(k)) reaches a fixpoint within (stream length + 1) steps, so a large `min`
        // stops there: a body that can match nothing ends where it starts, so every set
        // holds the one before it and the sets only grow; a body that cannot ends past
        // its start, so the smallest position rises until the set is empty, which steps
        // to itself.
        let mut at_min = BTreeSet::from([i]);
        let mut k = 0u32;
        while k < r.min {
            let next = self.step(body, &at_min);
            if next == at_min {
                break;
            }
            at_min = next;
            k += 1;
        }
        // Then the union over the optional iterations: U' = at_min ∪ step(U) only grows,
        // so it reaches its fixpoint within (stream length + 1) rounds.
        let mut union = at_min.clone();
        let mut extra = 0u32;
        while r.max.is_none_or(|m| r.min.saturating_add(extra) < m) {
            let mut next = self.step(body, &union);
            next.extend(at_min.iter().copied());
            if next == union {
                break;
            }
            union = next;
            extra += 1;
        }
        union
    }
}

/// Whether `lpe` matches the whole of `path`.
pub fn is_match(lpe: &Lpe, path: &Path) -> bool {
    // Set algebra by its definition: each operand matched, the answers combined.
    lpe.body.eval(&mut |e| is_expr_match(e, path))
}

/// Whether `expr` matches the whole of `path`'s symbol stream.
pub fn is_expr_match(expr: &Expr, path: &Path) -> bool {
    let mut stream = Vec::new();
    for v in &path.vertices {
        stream.extend(v.symbols.iter().map(|s| {
            Token::Symbol(match s {
                Symbol::None => Sym::None,
                Symbol::Label(l) => Sym::Label(l.clone()),
            })
        }));
        stream.push(Token::Stop);
    }
    let mut m = Matcher {
        nodes: Vec::new(),
        stream,
        memo: HashMap::new(),
    };
    let root = m.lower(expr);
    let end = m.stream.len();
    m.ends(root, 0).contains(&end)
}
