//! OSL expressions as regexes over a byte encoding of the path's symbol stream.
//!
//! OSL defines a match over symbols: each vertex is its symbols (event, scattering,
//! custom labels) followed by STOP. Here every symbol is one byte:
//!
//! | byte | symbol |
//! |---|---|
//! | `0x00` | STOP (ends every vertex) |
//! | `0x01` | NONE (`x` in an expression, `~` in a path) |
//! | `0x02` | OTHER: every label no expression of the set mentions and that is not basic |
//! | `0x03..` | the basic labels `C L B V T R O D G S s`, then every other label the set mentions, sorted |
//!
//! A label the expressions never name can only be told apart from the named ones, never
//! from another unnamed one (every slot pattern, `[^…]` and the eater treat all of them
//! alike), so one OTHER byte for all of them is exact. The basic labels are interned
//! whether or not an expression names them: they keep the encoding readable and cost
//! nothing.
//!
//! A vertex pattern becomes: one byte class per slot pattern (`.` and `[^…]` are
//! complements within the symbol bytes, so they never match STOP), then the eater as a
//! star over the symbol bytes minus its exclusions, then the STOP byte. This is a
//! symbol-level model: it shares nothing with lpe's whole-vertex classes.

use std::collections::BTreeSet;

use lpe::automata::ir::Repetition;
use lpe::osl::{Expr, Lpe, Osl, Path, Symbol, SymbolPattern};
use regex_syntax::hir::Hir;

use super::hir::{byte_class, repeat, to_the_end};
use crate::dialect::Encoder;
use crate::error::BuildError;

/// The STOP byte.
pub const STOP: u8 = 0x00;
/// The NONE byte.
pub const NONE: u8 = 0x01;
/// The byte of every label the set does not intern.
pub const OTHER: u8 = 0x02;
/// The first interned label's byte.
const FIRST_LABEL: u8 = 0x03;
/// Most labels one compiled set may intern (the basic eleven included).
pub const MAX_SYMBOLS: usize = (u8::MAX - FIRST_LABEL) as usize + 1;
/// OSL's built-in labels, interned first.
const BASIC: [&str; 11] = ["C", "L", "B", "V", "T", "R", "O", "D", "G", "S", "s"];

/// The symbol interning of one compiled set.
#[derive(Clone, Debug)]
pub struct Symbols {
    /// Interned labels, sorted, with their byte.
    labels: Vec<(String, u8)>,
}

impl Symbols {
    /// Interns the basic labels and `mentioned`; an error if there are too many.
    pub fn new<'a>(mentioned: impl IntoIterator<Item = &'a str>) -> Result<Symbols, BuildError> {
        let mut order: Vec<&str> = BASIC.to_vec();
        let rest: BTreeSet<&str> = mentioned
            .into_iter()
            .filter(|l| !BASIC.contains(l))
            .collect();
        order.extend(rest);
        if order.len() > MAX_SYMBOLS {
            return Err(BuildError::TooManyLabels {
                labels: order.len(),
                max: MAX_SYMBOLS,
            });
        }
        let mut labels: Vec<(String, u8)> = order
            .iter()
            .enumerate()
            .map(|(i, l)| (l.to_string(), FIRST_LABEL + i as u8))
            .collect();
        labels.sort();
        Ok(Symbols { labels })
    }

    /// The byte of one symbol.
    pub fn byte(&self, s: &Symbol) -> u8 {
        match s {
            Symbol::None => NONE,
            Symbol::Label(l) => self
                .labels
                .binary_search_by(|(x, _)| x.as_str().cmp(l))
                .map_or(OTHER, |i| self.labels[i].1),
        }
    }

    /// Every symbol byte (STOP excluded).
    fn symbol_bytes(&self) -> impl Iterator<Item = u8> {
        // At least the eleven basic labels, at most MAX_SYMBOLS: the last byte fits.
        NONE..=FIRST_LABEL + (self.labels.len() - 1) as u8
    }

    /// The byte class of the symbols not in `excluded` (never STOP).
    fn all_but(&self, excluded: &[Symbol]) -> Hir {
        let out: BTreeSet<u8> = excluded.iter().map(|s| self.byte(s)).collect();
        byte_class(self.symbol_bytes().filter(|b| !out.contains(b)))
    }

    /// The regex of one slot pattern: one symbol byte.
    fn pattern(&self, p: &SymbolPattern) -> Hir {
        match p {
            SymbolPattern::Any => self.all_but(&[]),
            SymbolPattern::One(s) => byte_class([self.byte(s)]),
            SymbolPattern::Set(xs) => byte_class(xs.iter().map(|s| self.byte(s))),
            SymbolPattern::NotIn(xs) => self.all_but(xs),
        }
    }

    /// The regex of an expression, without anchors.
    pub fn expr(&self, e: &Expr) -> Hir {
        match e {
            Expr::Vertex(v) => {
                let mut seq: Vec<Hir> = v.symbols.iter().map(|p| self.pattern(p)).collect();
                if let Some(excluded) = &v.eater {
                    seq.push(repeat(self.all_but(excluded), Repetition::STAR));
                }
                seq.push(byte_class([STOP]));
                Hir::concat(seq)
            }
            Expr::Concat(es) => Hir::concat(es.iter().map(|e| self.expr(e)).collect()),
            Expr::Alt(es) => Hir::alternation(es.iter().map(|e| self.expr(e)).collect()),
            Expr::Repeat(body, r) => repeat(self.expr(body), *r),
            Expr::Empty => Hir::empty(),
            Expr::Nothing => Hir::fail(),
        }
    }

    /// A path's symbol stream, STOP after every vertex.
    pub fn encode_path(&self, path: &Path) -> Vec<u8> {
        let mut out = Vec::new();
        for v in &path.vertices {
            out.extend(v.symbols.iter().map(|s| self.byte(s)));
            out.push(STOP);
        }
        out
    }
}

impl Encoder<Osl> for Symbols {
    fn encode(&self, path: &Path) -> Vec<u8> {
        self.encode_path(path)
    }
}

/// Every label an expression names (in slot patterns and eater exclusions).
fn mentioned<'a>(e: &'a Expr, out: &mut Vec<&'a str>) {
    let mut symbols = |xs: &'a [Symbol]| {
        out.extend(xs.iter().filter_map(|s| match s {
            Symbol::Label(l) => Some(l.as_str()),
            Symbol::None => None,
        }))
    };
    match e {
        Expr::Vertex(v) => {
            for p in &v.symbols {
                match p {
                    SymbolPattern::Any => {}
                    SymbolPattern::One(s) => symbols(std::slice::from_ref(s)),
                    SymbolPattern::Set(xs) | SymbolPattern::NotIn(xs) => symbols(xs),
                }
            }
            if let Some(excluded) = &v.eater {
                symbols(excluded);
            }
        }
        Expr::Concat(es) | Expr::Alt(es) => es.iter().for_each(|e| mentioned(e, out)),
        Expr::Repeat(body, _) => mentioned(body, out),
        Expr::Empty | Expr::Nothing => {}
    }
}

/// The anchored regex of each operand of each expression (one for a plain expression,
/// one per operand of set algebra, in [`Lpe::operands`] order), plus the symbol
/// interning they share.
pub fn translate(exprs: &[Lpe]) -> Result<(Symbols, Vec<Hir>), BuildError> {
    let operands: Vec<&Expr> = exprs.iter().flat_map(|e| e.operands()).collect();
    let mut names = Vec::new();
    for e in &operands {
        mentioned(e, &mut names);
    }
    let symbols = Symbols::new(names)?;
    let hirs = operands
        .iter()
        .map(|e| to_the_end(symbols.expr(e)))
        .collect();
    Ok((symbols, hirs))
}

#[cfg(test)]
mod tests {
    use lpe::osl::{parse, Registered};

    use super::*;
    use crate::engine::{bits, Engine, EngineError, Matcher};
    use crate::regex::LAZY;

    /// The oracle's OSL matcher for `exprs`, nothing registered.
    fn compile(exprs: &[Lpe]) -> Result<Box<dyn Matcher<Osl>>, EngineError> {
        Engine::<Osl>::compile(&LAZY, exprs, &Registered::none())
    }

    fn lpe(s: &str) -> Lpe {
        parse(s, &Registered::none()).unwrap()
    }

    #[test]
    fn the_stream_is_symbols_then_stop_per_vertex() {
        let (symbols, _) = translate(&[lpe("C'foo'L")]).unwrap();
        let p: Path = "C,_ R,~,foo,bar L".parse().unwrap();
        let b = |l: &str| symbols.byte(&Symbol::label(l));
        // `_` and `bar` are named by no expression: both OTHER.
        assert_eq!(
            symbols.encode_path(&p),
            [
                b("C"),
                OTHER,
                STOP,
                b("R"),
                NONE,
                b("foo"),
                OTHER,
                STOP,
                b("L"),
                STOP
            ]
        );
        assert_ne!(b("foo"), OTHER);
    }

    #[test]
    fn unmentioned_labels_share_other_and_stay_distinct_from_named_ones() {
        let m = compile(&[lpe("C<R.[^'a']>L"), lpe("C'a'L")]).unwrap();
        let which = |p: &str| bits(m.which(&p.parse().unwrap()), 2);
        assert_eq!(which("C,_ R,D,zz L,_"), [true, false]);
        assert_eq!(which("C,_ R,D,a L,_"), [false, true]);
        // The eater skips OTHER labels but no basic one.
        assert_eq!(which("C,_ R,D,zz,a L,_"), [true, false]);
        assert_eq!(which("C,_ R,D,a,zz L,_"), [false, true]);
        assert_eq!(which("C,_ R,D,a,D L,_"), [false, false]);
    }

    #[test]
    fn too_many_labels_is_a_typed_refusal() {
        let set = |n: usize| {
            let labels: String = (0..n).map(|i| format!("'l{i}'")).collect();
            lpe(&format!("C<R.[{labels}]>L"))
        };
        let fits = MAX_SYMBOLS - BASIC.len();
        let r = compile(&[set(fits + 1)]);
        assert!(matches!(
            r,
            Err(EngineError::Regex(BuildError::TooManyLabels { labels, max }))
                if labels == MAX_SYMBOLS + 1 && max == MAX_SYMBOLS
        ));
        // One fewer fits (the last byte, 0xff, in use), and a label still matches only
        // itself.
        let m = compile(&[set(fits)]).unwrap();
        let last = format!("C,_ R,D,l{} L,_", fits - 1);
        assert!(m.which(&last.parse().unwrap()).contains(0));
        assert!(m.which(&"C,_ R,D,zz L,_".parse().unwrap()).is_empty());
    }
}
