//! Random OSL expressions, registrations and paths aimed at them.
//!
//! The same approach as the RenderMan generators beside it ([`super::renderman`]):
//! expressions are built as expanded trees ([`lpe::osl::Expr`]) that keep the parser's
//! invariants (two slot patterns and up to a few custom items per vertex pattern, an
//! eater excluding the registration's basic labels exactly when there are fewer than
//! five custom items), and paths are built **from** an expression (a walk choosing
//! symbols each slot accepts and sometimes extra labels for the eater), then mutated into
//! near misses, or drawn as noise. Paths use the expressions' labels often, and also
//! NONE, `_`, registered labels, labels with a space and one label ([`STRANGER`]) no
//! expression mentions.

use lpe::osl::{Expr, Lpe, Path, Registered, Symbol, SymbolPattern, Vertex, VertexPattern};
use lpe::renderman::ast::Repetition;

use super::choices::Choices;
use super::set_algebra::algebra_over;

/// A path label no generated expression mentions.
pub const STRANGER: &str = "zz";
/// Custom labels expressions and paths share.
const CUSTOM: [&str; 7] = ["1", "2", "a", "foo", "_", "a b", "|"];
const EVENTS: [&str; 7] = ["C", "L", "B", "V", "T", "R", "O"];
const SCATTERS: [&str; 4] = ["D", "G", "S", "s"];
/// Custom items from which a vertex pattern has no eater (OSL's rule).
const NO_EATER_FROM: usize = 5;

/// Shape and size bounds for generated OSL values.
#[derive(Clone, Debug)]
pub struct Config {
    /// Most vertex patterns in one expression.
    pub max_vertices: usize,
    /// Deepest nesting of concatenation, alternation and repetition.
    pub max_depth: usize,
    /// Most vertices in a generated path.
    pub max_path_len: usize,
    /// Whether [`lpe`] sometimes draws set algebra (`&`, `-`, `^`): this toolkit's
    /// extension, which OSL's own matcher does not speak.
    pub set_algebra: bool,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            max_vertices: 8,
            max_depth: 4,
            max_path_len: 10,
            set_algebra: true,
        }
    }
}

impl Config {
    /// This config with at most `n` vertex patterns per expression.
    pub fn with_max_vertices(mut self, n: usize) -> Config {
        self.max_vertices = n.max(1);
        self
    }

    /// This config without set algebra.
    pub fn without_set_algebra(mut self) -> Config {
        self.set_algebra = false;
        self
    }
}

/// A registration: half the time nothing, else some of `U`, `1` as events and `Y`, `a`
/// as scatterings (`1` and `a` are also custom labels, whose meaning then changes).
pub fn registered(c: &mut impl Choices) -> Registered {
    let mut r = Registered::none();
    if c.chance(50) {
        return r;
    }
    for (l, percent, scatter) in [
        ("U", 70, false),
        ("1", 20, false),
        ("Y", 70, true),
        ("a", 20, true),
    ] {
        if c.chance(percent) {
            let list = if scatter {
                &mut r.scatters
            } else {
                &mut r.events
            };
            list.push(l.to_string());
        }
    }
    r
}

fn label(l: &str) -> Symbol {
    Symbol::label(l)
}

/// The labels of slot `slot` (0 event, 1 scattering, else custom), registration included.
fn pool(slot: usize, reg: &Registered) -> Vec<Symbol> {
    let (builtin, extra): (&[&str], &[String]) = match slot {
        0 => (&EVENTS, &reg.events),
        1 => (&SCATTERS, &reg.scatters),
        _ => (&CUSTOM, &[]),
    };
    builtin
        .iter()
        .map(|l| label(l))
        .chain(extra.iter().map(|l| label(l)))
        .collect()
}

/// A symbol for slot `slot`: mostly from its own pool, sometimes NONE or another slot's.
fn symbol(c: &mut impl Choices, slot: usize, reg: &Registered) -> Symbol {
    match c.below(20) {
        0 if slot < 2 => Symbol::None,
        1 => {
            let other = c.below(3);
            c.pick(&pool(other, reg)).clone()
        }
        2 if slot == 1 => label("_"),
        _ => c.pick(&pool(slot, reg)).clone(),
    }
}

/// Labels only (a negated list never holds NONE), 1..=`n`, distinct.
fn labels(c: &mut impl Choices, slot: usize, reg: &Registered, n: usize) -> Vec<Symbol> {
    let mut out: Vec<Symbol> = Vec::new();
    for _ in 0..1 + c.below(n) {
        let s = c.pick(&pool(slot, reg)).clone();
        if !out.contains(&s) {
            out.push(s);
        }
    }
    out
}

fn slot_pattern(c: &mut impl Choices, slot: usize, reg: &Registered) -> SymbolPattern {
    match c.below(10) {
        0..=2 if slot < 2 => SymbolPattern::Any,
        0..=5 => SymbolPattern::One(symbol(c, slot, reg)),
        6 | 7 => SymbolPattern::Set(labels(c, slot, reg, 3)),
        _ => SymbolPattern::NotIn(labels(c, slot, reg, 2)),
    }
}

/// A vertex pattern whose eater follows OSL's rule for `reg`.
pub fn vertex_pattern(c: &mut impl Choices, reg: &Registered) -> VertexPattern {
    let customs = match c.below(10) {
        0..=5 => 0,
        6 | 7 => 1,
        8 => 2,
        _ => 5,
    };
    let symbols: Vec<SymbolPattern> = (0..2 + customs)
        .map(|slot| slot_pattern(c, slot, reg))
        .collect();
    VertexPattern {
        eater: (customs < NO_EATER_FROM).then(|| reg.basic_labels()),
        symbols,
    }
}

/// `<E.>`: event `event`, any scattering, the eater.
fn event_vertex(event: &str, reg: &Registered) -> Expr {
    Expr::Vertex(VertexPattern {
        symbols: vec![SymbolPattern::One(label(event)), SymbolPattern::Any],
        eater: Some(reg.basic_labels()),
    })
}

fn repetition(c: &mut impl Choices) -> Repetition {
    let n = c.below(3) as u32;
    match c.below(6) {
        0 | 1 => Repetition { min: 0, max: None },
        2 => Repetition { min: 1, max: None },
        3 => Repetition {
            min: n + 1,
            max: Some(n + 1),
        },
        4 => Repetition { min: n, max: None },
        _ => Repetition {
            min: n,
            max: Some(n + 1 + c.below(2) as u32),
        },
    }
}

/// A random expression of at most `budget` vertex patterns.
fn expr_sized(c: &mut impl Choices, reg: &Registered, depth: usize, budget: usize) -> Expr {
    if depth == 0 || budget <= 1 || c.chance(35) {
        return if c.chance(2) {
            Expr::Nothing
        } else {
            Expr::Vertex(vertex_pattern(c, reg))
        };
    }
    if c.chance(70) {
        let n = 2 + c.below(2);
        let parts = (0..n)
            .map(|_| expr_sized(c, reg, depth - 1, budget / n))
            .collect();
        if c.chance(60) {
            Expr::Concat(flatten(parts, |e| matches!(e, Expr::Concat(_))))
        } else {
            Expr::Alt(flatten(parts, |e| matches!(e, Expr::Alt(_))))
        }
    } else {
        let body = expr_sized(c, reg, depth - 1, budget - 1);
        Expr::Repeat(Box::new(body), repetition(c))
    }
}

/// `parts` with every part of the same kind (`same`) replaced by its own parts, as the
/// parser builds them (`(a|b)|c` is one alternation of three).
fn flatten(parts: Vec<Expr>, same: impl Fn(&Expr) -> bool) -> Vec<Expr> {
    let mut out = Vec::new();
    for p in parts {
        match p {
            Expr::Concat(inner) | Expr::Alt(inner) if same(&p) => out.extend(inner),
            p => out.push(p),
        }
    }
    out
}

/// A random expression.
pub fn expr(c: &mut impl Choices, reg: &Registered, cfg: &Config) -> Expr {
    expr_sized(c, reg, cfg.max_depth, cfg.max_vertices)
}

/// An expression shaped like a real AOV most of the time: a camera vertex, a middle, a
/// light or emitter vertex (`C … [LO]`); one time in twelve set algebra over such
/// expressions instead (when [`Config::set_algebra`]).
pub fn lpe(c: &mut impl Choices, reg: &Registered, cfg: &Config) -> Lpe {
    if c.chance(8) && cfg.set_algebra {
        return Lpe::from_algebra(algebra_over(c, &mut |c| aov_shaped(c, reg, cfg)));
    }
    Lpe::new(aov_shaped(c, reg, cfg))
}

fn aov_shaped(c: &mut impl Choices, reg: &Registered, cfg: &Config) -> Expr {
    if c.chance(70) {
        let end = if c.chance(50) {
            event_vertex("L", reg)
        } else {
            Expr::Alt(vec![event_vertex("L", reg), event_vertex("O", reg)])
        };
        let budget = cfg.max_vertices.saturating_sub(2).max(1);
        let middle = expr_sized(c, reg, cfg.max_depth, budget);
        Expr::Concat(vec![event_vertex("C", reg), middle, end])
    } else {
        expr(c, reg, cfg)
    }
}

/// A symbol `p` accepts, if the generator finds one.
fn accepted(
    c: &mut impl Choices,
    p: &SymbolPattern,
    slot: usize,
    reg: &Registered,
) -> Option<Symbol> {
    match p {
        SymbolPattern::Any => Some(symbol(c, slot, reg)),
        SymbolPattern::One(s) => Some(s.clone()),
        SymbolPattern::Set(xs) if xs.is_empty() => None,
        SymbolPattern::Set(xs) => Some(c.pick(xs).clone()),
        SymbolPattern::NotIn(xs) => {
            for _ in 0..6 {
                let s = symbol(c, slot, reg);
                if !xs.contains(&s) {
                    return Some(s);
                }
            }
            Some(label(STRANGER))
        }
    }
}

fn walk(e: &Expr, c: &mut impl Choices, reg: &Registered, out: &mut Vec<Vertex>) -> bool {
    match e {
        Expr::Vertex(v) => {
            let mut symbols = Vec::new();
            for (slot, p) in v.symbols.iter().enumerate() {
                match accepted(c, p, slot, reg) {
                    Some(s) => symbols.push(s),
                    None => return false,
                }
            }
            if let Some(excluded) = &v.eater {
                // Something for the eater: a custom label it may skip, or (a near miss)
                // one it never does.
                if c.chance(25) {
                    symbols.push(c.pick(&pool(2, reg)).clone());
                } else if c.chance(5) && !excluded.is_empty() {
                    symbols.push(c.pick(excluded).clone());
                }
            }
            out.push(Vertex::new(symbols));
            true
        }
        Expr::Concat(es) => es.iter().all(|e| walk(e, c, reg, out)),
        Expr::Alt(es) => {
            let e = c.pick(es);
            walk(e, c, reg, out)
        }
        Expr::Repeat(body, r) => {
            let extra_max = r.max.map_or(2, |m| m.saturating_sub(r.min).min(2));
            let n = r.min as usize + c.below(extra_max as usize + 1);
            (0..n).all(|_| walk(body, c, reg, out))
        }
        Expr::Empty => true,
        Expr::Nothing => false,
    }
}

/// A path built by walking `expr`; `None` when the walk fails or is too long.
pub fn matching_path(
    expr: &Expr,
    c: &mut impl Choices,
    reg: &Registered,
    cfg: &Config,
) -> Option<Path> {
    let mut out = Vec::new();
    (walk(expr, c, reg, &mut out) && out.len() <= cfg.max_path_len).then(|| Path::new(out))
}

fn random_vertex(c: &mut impl Choices, reg: &Registered) -> Vertex {
    let n = match c.below(20) {
        0 => 1,
        1..=12 => 2,
        13..=17 => 3,
        _ => 4,
    };
    let symbols = (0..n)
        .map(|slot| {
            if slot >= 2 && c.chance(10) {
                label(STRANGER)
            } else {
                symbol(c, slot, reg)
            }
        })
        .collect();
    Vertex::new(symbols)
}

/// A path of 1..=`cfg.max_path_len` random vertices, most of them camera first.
pub fn uniform_path(c: &mut impl Choices, reg: &Registered, cfg: &Config) -> Path {
    let n = 1 + c.below(cfg.max_path_len.max(1));
    let mut v: Vec<Vertex> = (0..n).map(|_| random_vertex(c, reg)).collect();
    if c.chance(70) {
        v[0] = Vertex::labels(&["C", "_"]);
    }
    Path::new(v)
}

/// `path` with one change: a symbol replaced, a custom label added or dropped, a vertex
/// dropped, duplicated or inserted.
pub fn near_miss(path: &Path, c: &mut impl Choices, reg: &Registered, cfg: &Config) -> Path {
    let mut v = path.vertices.clone();
    if v.is_empty() {
        return uniform_path(c, reg, cfg);
    }
    let i = c.below(v.len());
    match c.below(6) {
        0 if v.len() > 1 => {
            v.remove(i);
        }
        1 if v.len() < cfg.max_path_len => v.insert(i, v[i].clone()),
        2 if v.len() < cfg.max_path_len => {
            let new = random_vertex(c, reg);
            v.insert(i, new);
        }
        3 => {
            let slot = c.below(3);
            let s = symbol(c, slot, reg);
            v[i].symbols.push(s);
        }
        4 if v[i].symbols.len() > 2 => {
            v[i].symbols.pop();
        }
        _ if !v[i].symbols.is_empty() => {
            let j = c.below(v[i].symbols.len());
            v[i].symbols[j] = symbol(c, j.min(2), reg);
        }
        _ => {}
    }
    Path::new(v)
}

/// A path aimed at `expr`: 65% a walk of it, 25% a near miss of such a walk, otherwise
/// (and whenever the walk fails) uniform.
pub fn biased_path(expr: &Expr, c: &mut impl Choices, reg: &Registered, cfg: &Config) -> Path {
    let roll = c.below(100);
    if roll < 90 {
        for _ in 0..4 {
            if let Some(p) = matching_path(expr, c, reg, cfg) {
                return if roll < 65 {
                    p
                } else {
                    near_miss(&p, c, reg, cfg)
                };
            }
        }
    }
    uniform_path(c, reg, cfg)
}
