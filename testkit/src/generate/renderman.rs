//! Random RenderMan expressions, AOV sets and paths aimed at them.
//!
//! Besides random ASTs ([`expr`], [`path_shaped_expr`], [`lpe`]), this builds **paths
//! from an expression**: [`matching_path`] walks the AST choosing a concrete vertex for
//! every atom (and a count for every quantifier), [`near_miss`] changes one vertex of a
//! path (mutate a field, drop it, duplicate it), and [`uniform_path`] draws noise.
//! [`biased_path`] mixes the three.
//!
//! # Testing your own matcher
//!
//! ```
//! use lpe_testkit::generate::renderman::{self, Config};
//! use lpe::rng::SplitMix64;
//!
//! let cfg = Config::default();
//! let mut rng = SplitMix64::new(42);
//! for _ in 0..100 {
//!     let expr = renderman::path_shaped_expr(&mut rng, &cfg);
//!     let path = renderman::biased_path(&expr, &mut rng, &cfg);
//!     // Compare your matcher with a reference on (expr, path) here, e.g. with
//!     // `lpe-reference`'s `lpe_reference::is_expr_match(&expr, &path)`.
//!     assert!(path.len() >= 2);
//!     // Every generated expression prints to text that parses back to itself.
//!     assert_eq!(lpe::renderman::parse(&expr.to_string()).unwrap().expr, expr);
//! }
//! ```
//!
//! `strategy` (feature `proptest` of this crate) has proptest strategies for the same
//! shapes.

use super::choices::Choices;
use super::set_algebra::algebra_over;
use lpe::algebra::Algebra;
use lpe::renderman::ast::{
    Atom, EventPattern, EventPos, Expr, Item, LabelPos, Lpe, Repetition, Triple, TypePos,
};
use lpe::renderman::path::{Event, EventKind, Path, Vertex, VertexType};
use lpe::renderman::prefix::{Prefix, Prefixes};

/// Shape and size bounds for generated values.
#[derive(Clone, Debug)]
pub struct Config {
    /// Most atoms in one expression.
    pub max_atoms: usize,
    /// Deepest nesting of concatenation, alternation and repetition.
    pub max_depth: usize,
    /// Largest count in `{n,m}` (occasionally used, to exercise counted repetition).
    pub max_count: u32,
    /// Most vertices in a generated path.
    pub max_path_len: usize,
    /// Most atom positions a quantified subtree may unroll to ([`Expr::positions`]); a
    /// count that would exceed it is replaced by `*`. Keeps generated expressions within
    /// the parser's limit (65 536 by default, so that their canonical text parses) and
    /// cheap to compile.
    pub max_positions: u64,
    /// Labels expressions and paths share (no `'`). Paths also use one label that no
    /// expression mentions, [`Config::stranger`].
    pub labels: Vec<String>,
    /// A path label the expressions never mention.
    pub stranger: String,
    /// Whether [`lpe`] sometimes draws set algebra (`&`, `-`, `^`): this toolkit's
    /// extension, which other programs' matchers do not speak.
    pub set_algebra: bool,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            max_atoms: 10,
            max_depth: 4,
            max_count: 256,
            max_path_len: 12,
            max_positions: 2048,
            labels: ["key", "fill", "floor", "a b", "", "é"]
                .map(str::to_string)
                .to_vec(),
            stranger: "stranger".into(),
            set_algebra: true,
        }
    }
}

impl Config {
    /// This config without set algebra.
    pub fn without_set_algebra(mut self) -> Config {
        self.set_algebra = false;
        self
    }

    /// This config with at most `max_atoms` atoms per expression.
    pub fn with_max_atoms(mut self, max_atoms: usize) -> Config {
        self.max_atoms = max_atoms.max(1);
        self
    }
}

fn label(c: &mut impl Choices, cfg: &Config) -> String {
    if cfg.labels.is_empty() {
        return "key".into();
    }
    c.pick(&cfg.labels).clone()
}

fn vertex_type(c: &mut impl Choices) -> VertexType {
    // R and T three times as often: most of a path is scattering vertices.
    use VertexType::*;
    *c.pick(&[C, R, R, R, T, T, T, L, O])
}

fn event_pattern(c: &mut impl Choices) -> EventPattern {
    // User lobes are rarer in real expressions; keep them present but not dominant.
    let kind = *c.pick(&[
        EventKind::D,
        EventKind::D,
        EventKind::S,
        EventKind::S,
        EventKind::U,
    ]);
    let lobe = c
        .chance(50)
        .then(|| 1 + c.below(usize::from(kind.max_lobe())) as u8);
    EventPattern { kind, lobe }
}

/// A random triple `<t e l>`.
pub fn triple(c: &mut impl Choices, cfg: &Config) -> Triple {
    let ty = match c.below(4) {
        0 => TypePos::Any,
        1 | 2 => TypePos::One(vertex_type(c)),
        _ => {
            let negated = c.chance(40);
            let n = 1 + c.below(3);
            TypePos::Class {
                negated,
                types: (0..n).map(|_| vertex_type(c)).collect(),
            }
        }
    };
    let event = match c.below(4) {
        0 => EventPos::Any,
        1 | 2 => EventPos::One(event_pattern(c)),
        _ => {
            let negated = c.chance(40);
            let n = 1 + c.below(3);
            EventPos::Class {
                negated,
                events: (0..n).map(|_| event_pattern(c)).collect(),
            }
        }
    };
    let label = match c.below(4) {
        0 | 1 => LabelPos::Any,
        2 => LabelPos::One(label(c, cfg)),
        _ => {
            let negated = c.chance(50);
            let n = 1 + c.below(3);
            LabelPos::Class {
                negated,
                labels: (0..n).map(|_| label(c, cfg)).collect(),
            }
        }
    };
    Triple { ty, event, label }
}

/// A random item: type or event letter, `.`, label or triple.
pub fn item(c: &mut impl Choices, cfg: &Config) -> Item {
    match c.below(10) {
        0 | 1 => Item::Type(vertex_type(c)),
        2..=4 => Item::Event(event_pattern(c)),
        5 => Item::Any,
        6 => Item::Label(label(c, cfg)),
        _ => Item::Triple(triple(c, cfg)),
    }
}

/// A random atom: an item, or a class of 1-3 items (negated or not).
pub fn atom(c: &mut impl Choices, cfg: &Config) -> Atom {
    if c.chance(75) {
        Atom::Item(item(c, cfg))
    } else {
        let negated = c.chance(40);
        let n = 1 + c.below(3);
        Atom::Class {
            negated,
            items: (0..n).map(|_| item(c, cfg)).collect(),
        }
    }
}

/// A random quantifier, mostly small, sometimes with a large upper bound.
pub fn repetition(c: &mut impl Choices, cfg: &Config) -> Repetition {
    let n = c.below(3) as u32;
    match c.below(20) {
        0..=4 => Repetition::STAR,
        5..=7 => Repetition::PLUS,
        8..=10 => Repetition::OPTIONAL,
        11..=12 => Repetition {
            min: n,
            max: Some(n),
        },
        13..=14 => Repetition { min: n, max: None },
        15..=18 => Repetition {
            min: n,
            max: Some(n + c.below(3) as u32),
        },
        _ => {
            // An upper bound beyond any generated path: equal to `{n,}` on every path,
            // which is exactly the rewrite a fast matcher may make and must get right.
            let lo = (cfg.max_path_len as u32).max(n);
            let hi = cfg.max_count.max(lo);
            let m = lo + c.below((hi - lo) as usize + 1) as u32;
            Repetition {
                min: n,
                max: Some(m),
            }
        }
    }
}

/// A random normalized expression with at most `cfg.max_atoms` atoms.
pub fn expr(c: &mut impl Choices, cfg: &Config) -> Expr {
    let mut budget = cfg.max_atoms.max(1);
    expr_in(c, cfg, cfg.max_depth, &mut budget)
}

fn expr_in(c: &mut impl Choices, cfg: &Config, depth: usize, budget: &mut usize) -> Expr {
    if depth == 0 || *budget <= 1 || c.chance(35) {
        *budget = budget.saturating_sub(1);
        return Expr::Atom(atom(c, cfg));
    }
    match c.below(10) {
        0..=4 => {
            let n = 2 + c.below(3);
            let mut parts = vec![expr_in(c, cfg, depth - 1, budget)];
            while parts.len() < n && *budget > 0 {
                parts.push(expr_in(c, cfg, depth - 1, budget));
            }
            Expr::concat(parts)
        }
        5..=7 => {
            let n = 2 + c.below(2);
            let mut alts = vec![expr_in(c, cfg, depth - 1, budget)];
            while alts.len() < n && *budget > 0 {
                alts.push(expr_in(c, cfg, depth - 1, budget));
            }
            Expr::alt(alts)
        }
        _ => {
            let body = expr_in(c, cfg, depth - 1, budget);
            let mut r = repetition(c, cfg);
            if body.positions().saturating_mul(r.copies()) > cfg.max_positions {
                r = Repetition::STAR;
            }
            Expr::Repeat(Box::new(body), r)
        }
    }
}

/// An atom that can match the camera vertex.
fn start_atom(c: &mut impl Choices, cfg: &Config) -> Atom {
    match c.below(10) {
        0..=5 => Atom::Item(Item::Type(VertexType::C)),
        6 => Atom::Item(Item::Triple(Triple {
            ty: TypePos::One(VertexType::C),
            event: EventPos::Any,
            label: LabelPos::Any,
        })),
        7 | 8 => Atom::Class {
            negated: false,
            items: vec![Item::Type(VertexType::C), item(c, cfg)],
        },
        _ => atom(c, cfg),
    }
}

/// An atom that can match the emitter at the end.
fn end_atom(c: &mut impl Choices, cfg: &Config) -> Atom {
    let light = |label| {
        Item::Triple(Triple {
            ty: TypePos::One(VertexType::L),
            event: EventPos::Any,
            label,
        })
    };
    match c.below(8) {
        0 | 1 => Atom::Item(Item::Type(VertexType::L)),
        2 => Atom::Item(Item::Type(VertexType::O)),
        3 | 4 => Atom::Class {
            negated: false,
            items: vec![light(LabelPos::Any), Item::Type(VertexType::O)],
        },
        5 => Atom::Item(light(LabelPos::One(label(c, cfg)))),
        6 => Atom::Item(Item::Triple(Triple {
            ty: TypePos::Class {
                negated: false,
                types: vec![VertexType::L, VertexType::O],
            },
            event: EventPos::Any,
            label: if c.chance(50) {
                LabelPos::Any
            } else {
                LabelPos::Class {
                    negated: true,
                    labels: vec![label(c, cfg)],
                }
            },
        })),
        _ => atom(c, cfg),
    }
}

/// An expression shaped like an AOV: something that can match the camera, a random
/// middle (sometimes none), something that can match an emitter. Such expressions match
/// a fair share of the paths generated for them, unlike fully random ones.
pub fn path_shaped_expr(c: &mut impl Choices, cfg: &Config) -> Expr {
    let start = Expr::Atom(start_atom(c, cfg));
    let end = Expr::Atom(end_atom(c, cfg));
    if c.chance(15) {
        return Expr::concat(vec![start, end]);
    }
    let inner = Config {
        max_atoms: cfg.max_atoms.saturating_sub(2).max(1),
        ..cfg.clone()
    };
    Expr::concat(vec![start, expr(c, &inner), end])
}

/// Random prefixes plus [`path_shaped_expr`] (or, one time in ten, [`expr`]); one
/// time in twelve, [`algebra`] instead (when [`Config::set_algebra`]).
pub fn lpe(c: &mut impl Choices, cfg: &Config) -> Lpe {
    let prefixes: Prefixes = (0..c.below(3)).map(|_| *c.pick(&Prefix::ALL)).collect();
    if c.chance(8) && cfg.set_algebra {
        return Lpe::from_algebra(prefixes, algebra(c, cfg));
    }
    let expr = if c.chance(90) {
        path_shaped_expr(c, cfg)
    } else {
        expr(c, cfg)
    };
    Lpe::new(prefixes, expr)
}

/// Set algebra over two to four [`path_shaped_expr`] operands: `A - B`, `A & B - C`,
/// `A - (B & C)`, `^A & B`, `^(A - B)`.
pub fn algebra(c: &mut impl Choices, cfg: &Config) -> Algebra<Expr> {
    algebra_over(c, &mut |c| path_shaped_expr(c, cfg))
}

fn transport_event(c: &mut impl Choices) -> Event {
    let kind = if c.chance(50) {
        EventKind::D
    } else {
        EventKind::S
    };
    event_of(c, EventPattern { kind, lobe: None })
}

fn event_of(c: &mut impl Choices, p: EventPattern) -> Event {
    let lobe = p
        .lobe
        .unwrap_or_else(|| 1 + c.below(usize::from(p.kind.max_lobe())) as u8);
    Event::new(p.kind, lobe).unwrap_or_else(|| Event::new(p.kind, 1).expect("lobe 1 exists"))
}

/// A label for a path vertex: none, a shared one, or the stranger.
fn path_label(c: &mut impl Choices, cfg: &Config) -> Option<String> {
    match c.below(10) {
        0..=3 => None,
        4..=8 => Some(label(c, cfg)),
        _ => Some(cfg.stranger.clone()),
    }
}

fn make_vertex(ty: VertexType, event: Event, label: Option<String>) -> Vertex {
    match ty {
        VertexType::C => Vertex::camera(),
        VertexType::L => Vertex::light(label.as_deref()),
        VertexType::O => Vertex::emissive(label.as_deref()),
        VertexType::R | VertexType::T => Vertex::scatter(ty, event, label.as_deref()),
    }
}

fn scatter_type(c: &mut impl Choices) -> VertexType {
    if c.chance(50) {
        VertexType::R
    } else {
        VertexType::T
    }
}

/// A vertex chosen to be matched by `item` (aimed, not guaranteed).
fn vertex_for_item(item: &Item, c: &mut impl Choices, cfg: &Config) -> Vertex {
    match item {
        Item::Type(t) => make_vertex(*t, transport_event(c), path_label(c, cfg)),
        Item::Event(p) => make_vertex(scatter_type(c), event_of(c, *p), path_label(c, cfg)),
        Item::Any => make_vertex(scatter_type(c), transport_event(c), path_label(c, cfg)),
        Item::Label(l) => make_vertex(scatter_type(c), transport_event(c), Some(l.clone())),
        Item::Triple(t) => {
            let ty = match &t.ty {
                TypePos::Any => scatter_type(c),
                TypePos::One(ty) => *ty,
                TypePos::Class {
                    negated: false,
                    types,
                } => *c.pick(types),
                TypePos::Class {
                    negated: true,
                    types,
                } => {
                    let left: Vec<VertexType> = [VertexType::R, VertexType::T]
                        .into_iter()
                        .filter(|t| !types.contains(t))
                        .collect();
                    if left.is_empty() {
                        scatter_type(c)
                    } else {
                        *c.pick(&left)
                    }
                }
            };
            let event = match &t.event {
                EventPos::One(p) => event_of(c, *p),
                EventPos::Class {
                    negated: false,
                    events,
                } => {
                    let p = *c.pick(events);
                    event_of(c, p)
                }
                EventPos::Any | EventPos::Class { negated: true, .. } => transport_event(c),
            };
            let label = match &t.label {
                LabelPos::Any => path_label(c, cfg),
                LabelPos::One(l) => Some(l.clone()),
                LabelPos::Class {
                    negated: false,
                    labels,
                } => Some(c.pick(labels).clone()),
                LabelPos::Class {
                    negated: true,
                    labels,
                } => {
                    let l = path_label(c, cfg);
                    if l.as_ref().is_some_and(|l| labels.contains(l)) {
                        None
                    } else {
                        l
                    }
                }
            };
            make_vertex(ty, event, label)
        }
    }
}

/// Whether `item` can aim at a vertex of a type in `want`.
fn can_be(item: &Item, want: &[VertexType]) -> bool {
    match item {
        Item::Type(t) => want.contains(t),
        Item::Event(_) | Item::Any | Item::Label(_) => want.iter().any(|t| t.is_scattering()),
        Item::Triple(t) => match &t.ty {
            TypePos::Any => want.iter().any(|t| t.is_scattering()),
            TypePos::One(ty) => want.contains(ty),
            TypePos::Class {
                negated: false,
                types,
            } => types.iter().any(|t| want.contains(t)),
            TypePos::Class { negated: true, .. } => want.iter().any(|t| t.is_scattering()),
        },
    }
}

/// A vertex aimed at `a`; `first` says it will be the path's first vertex, so a class
/// aims at an item that can be the camera (and otherwise at one that can scatter).
fn vertex_for_atom(a: &Atom, first: bool, c: &mut impl Choices, cfg: &Config) -> Vertex {
    match a {
        Atom::Item(i) => vertex_for_item(i, c, cfg),
        Atom::Class {
            negated: false,
            items,
        } => {
            let want: &[VertexType] = if first {
                &[VertexType::C]
            } else {
                &[VertexType::R, VertexType::T]
            };
            let fitting: Vec<&Item> = items.iter().filter(|i| can_be(i, want)).collect();
            let i = if fitting.is_empty() || c.chance(10) {
                c.pick(items).clone()
            } else {
                (*c.pick(&fitting)).clone()
            };
            vertex_for_item(&i, c, cfg)
        }
        // `.` minus the items: any transport vertex, hoping to miss the items.
        Atom::Class { negated: true, .. } => {
            make_vertex(scatter_type(c), transport_event(c), path_label(c, cfg))
        }
    }
}

/// The walk picks from every list; an AST built by hand may have an empty one (the
/// parser and these generators never do), which has nothing to aim at.
fn has_no_empty_lists(e: &Expr) -> bool {
    fn item_ok(i: &Item) -> bool {
        let Item::Triple(t) = i else { return true };
        !matches!(&t.ty, TypePos::Class { types, .. } if types.is_empty())
            && !matches!(&t.event, EventPos::Class { events, .. } if events.is_empty())
            && !matches!(&t.label, LabelPos::Class { labels, .. } if labels.is_empty())
    }
    let mut ok = true;
    e.for_each_atom(&mut |a| {
        ok &= match a {
            Atom::Item(i) => item_ok(i),
            Atom::Class { items, .. } => !items.is_empty() && items.iter().all(item_ok),
        }
    });
    fn lists(e: &Expr) -> bool {
        match e {
            Expr::Atom(_) => true,
            Expr::Concat(es) | Expr::Alt(es) => !es.is_empty() && es.iter().all(lists),
            Expr::Repeat(b, _) => lists(b),
        }
    }
    ok && lists(e)
}

fn walk(e: &Expr, c: &mut impl Choices, cfg: &Config, out: &mut Vec<Vertex>) -> bool {
    if out.len() > cfg.max_path_len {
        return false;
    }
    match e {
        Expr::Atom(a) => {
            let first = out.is_empty();
            out.push(vertex_for_atom(a, first, c, cfg));
            true
        }
        Expr::Concat(es) => es.iter().all(|e| walk(e, c, cfg, out)),
        Expr::Alt(es) => {
            let e = c.pick(es);
            walk(e, c, cfg, out)
        }
        Expr::Repeat(body, r) => {
            // Few extra iterations: nested quantifiers multiply, and a path over
            // `max_path_len` is wasted.
            let extra_max = r.max.map_or(2, |m| (m.saturating_sub(r.min)).min(2));
            let n = r.min as usize + c.below(extra_max as usize + 1);
            (0..n).all(|_| walk(body, c, cfg, out))
        }
    }
}

/// A path built by walking `expr`, choosing a vertex for each atom, an alternative for
/// each `|` and a count for each quantifier. `None` when the walk does not give a
/// well-formed path (not camera first, too long, …).
pub fn matching_path(expr: &Expr, c: &mut impl Choices, cfg: &Config) -> Option<Path> {
    if !has_no_empty_lists(expr) {
        return None;
    }
    let mut out = Vec::new();
    if !walk(expr, c, cfg, &mut out) || out.len() > cfg.max_path_len {
        return None;
    }
    Path::new(out).ok()
}

/// A path of 2..=`cfg.max_path_len` random vertices.
pub fn uniform_path(c: &mut impl Choices, cfg: &Config) -> Path {
    let n = c.below(cfg.max_path_len.max(2) - 1);
    let mut v = vec![Vertex::camera()];
    for _ in 0..n {
        let event = if c.chance(15) {
            event_of(
                c,
                EventPattern {
                    kind: EventKind::U,
                    lobe: None,
                },
            )
        } else {
            transport_event(c)
        };
        v.push(make_vertex(scatter_type(c), event, path_label(c, cfg)));
    }
    let end = if c.chance(60) {
        VertexType::L
    } else {
        VertexType::O
    };
    v.push(make_vertex(end, transport_event(c), path_label(c, cfg)));
    Path::new(v).expect("camera, scattering vertices, emitter")
}

/// `path` with one change: a field of one vertex mutated (type, lobe, kind, label), or
/// one scattering vertex dropped or duplicated. Always a valid path.
pub fn near_miss(path: &Path, c: &mut impl Choices, cfg: &Config) -> Path {
    let mut v = path.vertices().to_vec();
    let n = v.len();
    let interior = n - 2;
    match c.below(6) {
        0 if interior > 0 => {
            v.remove(1 + c.below(interior));
        }
        1 if interior > 0 && n < cfg.max_path_len => {
            let i = 1 + c.below(interior);
            v.insert(i, v[i].clone());
        }
        2 if n < cfg.max_path_len => {
            // Insert a new random scattering vertex.
            let i = 1 + c.below(interior + 1);
            v.insert(
                i,
                make_vertex(scatter_type(c), transport_event(c), path_label(c, cfg)),
            );
        }
        _ => {
            // Mutate one field of one vertex (never the camera: it has nothing to vary).
            let i = 1 + c.below(n - 1);
            let old = v[i].clone();
            let label = old.label().map(str::to_string);
            v[i] = match old.event() {
                Some(e) => match c.below(4) {
                    0 => {
                        let ty = if old.ty() == VertexType::R {
                            VertexType::T
                        } else {
                            VertexType::R
                        };
                        make_vertex(ty, e, label)
                    }
                    1 => {
                        let p = EventPattern {
                            kind: e.kind(),
                            lobe: None,
                        };
                        make_vertex(old.ty(), event_of(c, p), label)
                    }
                    2 => {
                        let kind = *c.pick(&EventKind::ALL);
                        make_vertex(
                            old.ty(),
                            event_of(c, EventPattern { kind, lobe: None }),
                            label,
                        )
                    }
                    _ => make_vertex(old.ty(), e, path_label(c, cfg)),
                },
                None => {
                    let ty = if c.chance(50) {
                        old.ty()
                    } else if old.ty() == VertexType::L {
                        VertexType::O
                    } else {
                        VertexType::L
                    };
                    make_vertex(ty, transport_event(c), path_label(c, cfg))
                }
            };
        }
    }
    Path::new(v).expect("mutations keep the camera first and the emitter last")
}

/// A path aimed at `expr`: 65% a walk of it, 25% a near miss of such a walk, otherwise
/// (and whenever the walk fails) uniform.
pub fn biased_path(expr: &Expr, c: &mut impl Choices, cfg: &Config) -> Path {
    let roll = c.below(100);
    if roll < 90 {
        // A walk can fail (an alternative that cannot start a path, say); retry a few
        // times before settling for noise.
        for _ in 0..4 {
            if let Some(p) = matching_path(expr, c, cfg) {
                return if roll < 65 { p } else { near_miss(&p, c, cfg) };
            }
        }
    }
    uniform_path(c, cfg)
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::rng::SplitMix64;

    #[test]
    fn generated_expressions_are_normalized_and_bounded() {
        let cfg = Config::default();
        let mut rng = SplitMix64::new(7);
        for _ in 0..20_000 {
            let e = if rng.chance(50) {
                expr(&mut rng, &cfg)
            } else {
                path_shaped_expr(&mut rng, &cfg)
            };
            let mut atoms = 0;
            e.for_each_atom(&mut |_| atoms += 1);
            assert!(atoms <= cfg.max_atoms + 2, "{e}: {atoms} atoms");
            // At most `max_atoms` repeats, each unrolling to at most `max_positions`.
            assert!(
                e.positions() <= (cfg.max_atoms as u64 + 2) * cfg.max_positions,
                "{e}"
            );
            let text = e.to_string();
            let back = lpe::renderman::parse(&text).unwrap_or_else(|err| panic!("{text}: {err}"));
            assert_eq!(back.expr, e, "{text}");
        }
    }

    /// Always the last option: the deepest nesting of the largest counts.
    struct Greedy;

    impl Choices for Greedy {
        fn below(&mut self, n: usize) -> usize {
            n.saturating_sub(1)
        }
    }

    /// Regression (fuzz/regressions/differential/nested-counts-over-position-limit):
    /// nested large counts once unrolled past the parser's limit, so the printed
    /// expression did not parse back.
    #[test]
    fn nested_large_counts_stay_within_the_parser_limit() {
        let cfg = Config::default();
        let e = expr(&mut Greedy, &cfg);
        assert!(matches!(e, Expr::Repeat(..)), "{e}");
        assert!(e.positions() <= cfg.max_positions, "{e}");
        assert_eq!(lpe::renderman::parse(&e.to_string()).unwrap().expr, e);
    }

    #[test]
    fn hand_built_empty_lists_give_no_walk_instead_of_a_panic() {
        let cfg = Config::default();
        let empty_alt = Expr::Concat(vec![
            Expr::Atom(Atom::Item(Item::Type(VertexType::C))),
            Expr::Alt(vec![]),
        ]);
        let empty_class = Expr::Atom(Atom::Class {
            negated: false,
            items: vec![],
        });
        for e in [empty_alt, empty_class] {
            assert_eq!(matching_path(&e, &mut SplitMix64::new(1), &cfg), None);
            // biased_path falls back to noise.
            assert!(biased_path(&e, &mut SplitMix64::new(1), &cfg).len() >= 2);
        }
    }

    #[test]
    fn same_seed_same_cases() {
        let cfg = Config::default();
        let run = |seed| {
            let mut rng = SplitMix64::new(seed);
            (0..50)
                .map(|_| {
                    let e = path_shaped_expr(&mut rng, &cfg);
                    let p = biased_path(&e, &mut rng, &cfg);
                    format!("{e} / {p}")
                })
                .collect::<Vec<_>>()
        };
        assert_eq!(run(3), run(3));
        assert_ne!(run(3), run(4));
    }

    #[test]
    fn walks_of_simple_expressions_give_the_expected_shapes() {
        let cfg = Config::default();
        let mut rng = SplitMix64::new(1);
        let e = lpe::renderman::parse("C<RD'floor'><TS8>[<L.'key'>]")
            .unwrap()
            .expr;
        let p = matching_path(&e, &mut rng, &cfg).unwrap();
        let v = p.vertices();
        assert_eq!(v.len(), 4);
        assert_eq!(v[1].ty(), VertexType::R);
        assert_eq!(v[1].event().unwrap().kind(), EventKind::D);
        assert_eq!(v[1].label(), Some("floor"));
        assert_eq!(v[2].event(), Event::new(EventKind::S, 8));
        assert_eq!(v[3].label(), Some("key"));
    }

    #[test]
    fn near_misses_differ_from_their_path_and_stay_valid() {
        let cfg = Config::default();
        let mut rng = SplitMix64::new(9);
        let mut changed = 0;
        for _ in 0..500 {
            let p = uniform_path(&mut rng, &cfg);
            let q = near_miss(&p, &mut rng, &cfg);
            assert!(q.len() >= 2 && q.len() <= cfg.max_path_len.max(p.len()));
            changed += usize::from(p != q);
        }
        // A label swap can pick the same label again; most mutations change the path.
        assert!(
            changed > 400,
            "only {changed} of 500 near misses changed the path"
        );
    }
}
