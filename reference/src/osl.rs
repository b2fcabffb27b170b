//! The reference matcher for the OSL dialect: OSL's definition of a match executed as
//! plainly as possible (docs/language.md, OSL chapter).
//!
//! OSL matches an expression against the path's **symbol stream**: for every vertex its
//! symbols (event, scattering, custom labels) followed by STOP, camera first, anchored
//! at both ends. Each vertex pattern of the expression stands for a symbol-level
//! sequence: one symbol per slot pattern, then (if the pattern has an eater) zero or
//! more symbols outside the eater's exclusions, then STOP. This module rewrites the
//! expression into that symbol-level regular expression ([`Node`]) and matches it on
//! the stream by computing, for a node and a start position, the set of positions where
//! a match of the node can end. Results are memoized on (node, position), so the time
//! is polynomial in the stream length whatever the expression's shape.
//!
//! It shares nothing with lpe's vertex-class automata (which classify a whole vertex at
//! once): the two check each other.

use std::collections::{BTreeSet, HashMap};

use lpe::automata::ir::Repetition;
use lpe::osl::{Expr, Lpe, Path, Symbol, SymbolPattern};

/// One token of a path's symbol stream.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Token<'a> {
    Symbol(&'a Symbol),
    Stop,
}

/// The symbol-level expression, nodes in an arena (children by index).
#[derive(Debug)]
enum Node<'a> {
    /// One symbol (never STOP) accepted by the pattern.
    Symbol(&'a SymbolPattern),
    /// Zero or more symbols, none STOP and none in the list (OSL's eater).
    Eater(&'a [Symbol]),
    /// The end of a vertex.
    Stop,
    Concat(Vec<usize>),
    Alt(Vec<usize>),
    Repeat(usize, Repetition),
    /// The empty sequence.
    Empty,
    /// No sequence at all.
    Nothing,
}

/// Whether one symbol (never STOP) satisfies a slot pattern.
pub fn symbol_matches(p: &SymbolPattern, s: &Symbol) -> bool {
    match p {
        SymbolPattern::Any => true,
        SymbolPattern::One(x) => x == s,
        SymbolPattern::Set(xs) => xs.contains(s),
        SymbolPattern::NotIn(xs) => !xs.contains(s),
    }
}

struct Matcher<'a> {
    nodes: Vec<Node<'a>>,
    stream: Vec<Token<'a>>,
    memo: HashMap<(usize, usize), BTreeSet<usize>>,
}

impl<'a> Matcher<'a> {
    fn push(&mut self, n: Node<'a>) -> usize {
        self.nodes.push(n);
        self.nodes.len() - 1
    }

    /// Lowers the vertex-level tree to symbol level.
    fn lower(&mut self, e: &'a Expr) -> usize {
        match e {
            Expr::Vertex(v) => {
                let mut seq: Vec<usize> = v
                    .symbols
                    .iter()
                    .map(|p| self.push(Node::Symbol(p)))
                    .collect();
                if let Some(excluded) = &v.eater {
                    seq.push(self.push(Node::Eater(excluded)));
                }
                seq.push(self.push(Node::Stop));
                self.push(Node::Concat(seq))
            }
            Expr::Concat(es) => {
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
            Expr::Empty => self.push(Node::Empty),
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
            Node::Empty => BTreeSet::from([i]),
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
    fn repeat(&mut self, body: usize, r: Repetition, i: usize) -> BTreeSet<usize> {
        // After exactly `min` iterations. The sequence of position sets is determined by
        // its last element, so once a set repeats it cycles: jump ahead instead of
        // iterating a large `min` one by one.
        let mut seen: HashMap<BTreeSet<usize>, u32> = HashMap::new();
        let mut history = vec![BTreeSet::from([i])];
        let mut k = 0u32;
        let at_min = loop {
            let cur = &history[k as usize];
            if k == r.min {
                break cur.clone();
            }
            if let Some(&j) = seen.get(cur) {
                let period = k - j;
                break history[(j + (r.min - j) % period) as usize].clone();
            }
            seen.insert(cur.clone(), k);
            let next = self.step(body, &cur.clone());
            history.push(next);
            k += 1;
        };
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
    lpe.eval(&mut |e| is_expr_match(e, path))
}

/// Whether `expr` matches the whole of `path`'s symbol stream.
pub fn is_expr_match(expr: &Expr, path: &Path) -> bool {
    let mut stream = Vec::new();
    for v in &path.vertices {
        stream.extend(v.symbols.iter().map(Token::Symbol));
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

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::osl::{parse, Registered};

    fn m_reg(expr: &str, reg: &str, path: &str) -> bool {
        let reg: Registered = reg.parse().unwrap();
        let lpe = parse(expr, &reg).unwrap_or_else(|e| panic!("{expr}: {e}"));
        is_match(&lpe, &path.parse().unwrap())
    }

    fn m(expr: &str, path: &str) -> bool {
        m_reg(expr, "-", path)
    }

    // Expected values are the facts of docs/language.md's OSL chapter, written by hand.
    #[test]
    fn vertex_patterns_and_the_eater() {
        assert!(m("C.L", "C,_ R,D L,_"));
        assert!(m("C.*L", "C,_ L,_"));
        assert!(!m("C.+L", "C,_ L,_"));
        // The eater skips custom labels that are not basic labels.
        assert!(m("CRL", "C,_ R,D,foo,bar L,_"));
        assert!(!m("CRL", "C,_ R,D,D L,_"), "a basic label is never eaten");
        assert!(m("CRL", "C,_ R,D,U L,_"));
        assert!(
            !m_reg("CRL", "events=U", "C,_ R,D,U L,_"),
            "registered: basic"
        );
        // A vertex of one symbol matches nothing, not even `.`.
        assert!(!m("C.L", "C,_ R L,_"));
        // `'foo'` must be the first custom label.
        assert!(m("C'foo'L", "C,_ R,D,foo,bar L,_"));
        assert!(!m("C'foo'L", "C,_ R,D,bar,foo L,_"));
        // The quoted negation needs a custom label, and accepts a basic one.
        assert!(m("C[^'foo']L", "C,_ R,D,D L,_"));
        assert!(!m("C[^'foo']L", "C,_ R,D L,_"));
        assert!(!m("C[^'foo']L", "C,_ R,D,foo L,_"));
    }

    #[test]
    fn none_negation_and_slots() {
        assert!(m("C[^D]L", "C,_ R,~ L,_"));
        assert!(m("C[^D]L", "C,_ R,G L,_"));
        assert!(!m("C[^D]L", "C,_ R,D L,_"));
        assert!(m("<Cx>L", "C,~ L,_"));
        assert!(!m("<Cx>L", "C,_ L,_"));
        // No check that a letter sits in its usual slot.
        assert!(m("C<DR>L", "C,_ D,R L,_"));
        assert!(!m("C<DR>L", "C,_ R,D L,_"));
        // A group in a slot is a sequence of symbols, then one more slot.
        assert!(m("C<(RD)>L", "C,_ R,D,x L,_"));
        assert!(!m("C<(RD)>L", "C,_ R,D L,_"));
        // Five custom items: no eater, the vertex has exactly those labels.
        assert!(m("C<RDabcde>L", "C,_ R,D,a,b,c,d,e L,_"));
        assert!(!m("C<RDabcde>L", "C,_ R,D,a,b,c,d,e,f L,_"));
        assert!(m("C<RDabcd>L", "C,_ R,D,a,b,c,d,f L,_"));
    }

    #[test]
    fn operators() {
        // `|` binds tighter than concatenation.
        assert!(m("CD|GL", "C,_ R,G L,_"));
        assert!(m("CD*|GL", "C,_ R,D R,D L,_"));
        assert!(m("C.{0,1}L", "C,_ L,_"));
        assert!(m("C.{2,3}L", "C,_ T,S T,S T,S L,_"));
        assert!(!m("C.{2,3}L", "C,_ T,S T,S T,S T,S L,_"));
        assert!(m("C.{2,}L", "C,_ T,S T,S T,S T,S L,_"));
        assert!(!m("C.{2,}L", "C,_ T,S L,_"));
        assert!(!m("C[]L", "C,_ L,_"));
        assert!(m("C[C*]L", "C,_ C,D C,D L,_"));
    }

    #[test]
    fn large_counts_do_not_iterate_one_by_one() {
        // Over the parser's count limit, so built by hand: C (.*){10^6} L and C .{10^6} L.
        let none = Registered::none();
        let vertex = |s: &str| parse(s, &none).unwrap().expr;
        let count = |body: Expr| {
            let r = Repetition {
                min: 1_000_000,
                max: Some(1_000_000),
            };
            Expr::Concat(vec![
                vertex("C"),
                Expr::Repeat(Box::new(body), r),
                vertex("L"),
            ])
        };
        let path: Path = "C,_ R,D L,_".parse().unwrap();
        let star = Expr::Repeat(Box::new(vertex(".")), Repetition { min: 0, max: None });
        assert!(is_expr_match(&count(star), &path));
        assert!(!is_expr_match(&count(vertex(".")), &path));
    }
}
