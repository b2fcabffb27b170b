//! proptest strategies for expressions and paths (feature `proptest` of lpe-testkit).
//!
//! Exported so a renderer can property-test its own matcher against these ASTs. The
//! ASTs are normalized (see [`lpe::ast`]) so they print and re-parse to themselves.
//! Labels come from a small pool so that expressions and paths share them.
//!
//! To test your own matcher against the reference, draw an [`aov_expr`] (or [`expr`])
//! and then [`biased_paths`] for it, and compare answers on each path.

use proptest::prelude::*;

use lpe::algebra::Algebra;
use lpe::renderman::ast::{
    Atom, EventPattern, EventPos, Expr, Item, LabelPos, Lpe, Repetition, Triple, TypePos,
};
use lpe::renderman::path::{Event, EventKind, Path, Vertex, VertexType};
use lpe::renderman::prefix::{Prefix, Prefixes};

/// The label pool shared by expressions and paths.
pub const LABELS: [&str; 4] = ["key", "fill", "floor", "a b"];

fn label() -> impl Strategy<Value = String> {
    prop::sample::select(&LABELS[..]).prop_map(str::to_string)
}

fn vertex_type() -> impl Strategy<Value = VertexType> {
    prop::sample::select(&VertexType::ALL[..])
}

fn event_pattern() -> impl Strategy<Value = EventPattern> {
    prop::sample::select(&EventKind::ALL[..]).prop_flat_map(|kind| {
        prop::option::of(1..=kind.max_lobe()).prop_map(move |lobe| EventPattern { kind, lobe })
    })
}

fn small_vec<T: std::fmt::Debug>(s: impl Strategy<Value = T>) -> impl Strategy<Value = Vec<T>> {
    prop::collection::vec(s, 1..=3)
}

fn triple() -> impl Strategy<Value = Triple> {
    let ty = prop_oneof![
        Just(TypePos::Any),
        vertex_type().prop_map(TypePos::One),
        (any::<bool>(), small_vec(vertex_type()))
            .prop_map(|(negated, types)| TypePos::Class { negated, types }),
    ];
    let event = prop_oneof![
        Just(EventPos::Any),
        event_pattern().prop_map(EventPos::One),
        (any::<bool>(), small_vec(event_pattern()))
            .prop_map(|(negated, events)| EventPos::Class { negated, events }),
    ];
    let lab = prop_oneof![
        Just(LabelPos::Any),
        label().prop_map(LabelPos::One),
        (any::<bool>(), small_vec(label()))
            .prop_map(|(negated, labels)| LabelPos::Class { negated, labels }),
    ];
    (ty, event, lab).prop_map(|(ty, event, label)| Triple { ty, event, label })
}

/// One item: type or event letter, `.`, label or triple.
pub fn item() -> impl Strategy<Value = Item> {
    prop_oneof![
        vertex_type().prop_map(Item::Type),
        event_pattern().prop_map(Item::Event),
        Just(Item::Any),
        label().prop_map(Item::Label),
        triple().prop_map(Item::Triple),
    ]
}

/// One atom: an item or a (possibly negated) class.
pub fn atom() -> impl Strategy<Value = Atom> {
    prop_oneof![
        3 => item().prop_map(Atom::Item),
        1 => (any::<bool>(), small_vec(item()))
            .prop_map(|(negated, items)| Atom::Class { negated, items }),
    ]
}

/// A quantifier with small counts.
pub fn repetition() -> impl Strategy<Value = Repetition> {
    prop_oneof![
        Just(Repetition::STAR),
        Just(Repetition::PLUS),
        Just(Repetition::OPTIONAL),
        (0u32..4).prop_map(|n| Repetition {
            min: n,
            max: Some(n)
        }),
        (0u32..3).prop_map(|n| Repetition { min: n, max: None }),
        (0u32..3, 0u32..3).prop_map(|(n, d)| Repetition {
            min: n,
            max: Some(n + d)
        }),
    ]
}

/// A normalized expression of bounded size.
pub fn expr() -> impl Strategy<Value = Expr> {
    atom()
        .prop_map(Expr::Atom)
        .prop_recursive(4, 24, 4, |inner| {
            prop_oneof![
                prop::collection::vec(inner.clone(), 2..=4).prop_map(Expr::Concat),
                prop::collection::vec(inner.clone(), 2..=3).prop_map(Expr::Alt),
                (inner, repetition()).prop_map(|(e, r)| Expr::Repeat(Box::new(e), r)),
            ]
        })
}

/// A full expression with random prefixes; one in eleven is [`algebra`].
pub fn lpe() -> impl Strategy<Value = Lpe> {
    let body = prop_oneof![
        10 => expr().prop_map(Algebra::Leaf),
        1 => algebra(),
    ];
    (
        prop::collection::vec(prop::sample::select(&Prefix::ALL[..]), 0..3),
        body,
    )
        .prop_map(|(ps, t)| Lpe::from_algebra(ps.into_iter().collect::<Prefixes>(), t))
}

/// Set algebra (`&`, `-`, `^`) over two to four [`expr`] operands.
pub fn algebra() -> impl Strategy<Value = Algebra<Expr>> {
    let leaf = expr().prop_map(Algebra::Leaf).boxed();
    let op = (leaf.clone(), leaf.clone(), any::<bool>())
        .prop_map(|(a, b, and)| {
            if and {
                Algebra::and(a, b)
            } else {
                Algebra::minus(a, b)
            }
        })
        .boxed();
    prop_oneof![
        op.clone(),
        (op.clone(), leaf.clone(), any::<bool>()).prop_map(|(a, b, and)| if and {
            Algebra::and(a, b)
        } else {
            Algebra::minus(a, b)
        }),
        (leaf.clone(), op.clone()).prop_map(|(a, b)| Algebra::minus(a, b)),
        (leaf.clone(), leaf).prop_map(|(a, b)| Algebra::and(Algebra::complement(a), b)),
        op.prop_map(Algebra::complement),
    ]
}

/// A vertex of type R/T with any event, optionally labelled.
pub fn scatter_vertex() -> impl Strategy<Value = Vertex> {
    let event = prop::sample::select(Event::all().collect::<Vec<_>>());
    (
        prop::sample::select(&[VertexType::R, VertexType::T][..]),
        event,
        prop::option::of(label()),
    )
        .prop_map(|(ty, ev, l)| Vertex::scatter(ty, ev, l.as_deref()))
}

/// A valid path of 2..=`max_len` vertices.
pub fn path(max_len: usize) -> impl Strategy<Value = Path> {
    let end = (any::<bool>(), prop::option::of(label())).prop_map(|(light, l)| {
        if light {
            Vertex::light(l.as_deref())
        } else {
            Vertex::emissive(l.as_deref())
        }
    });
    (
        prop::collection::vec(scatter_vertex(), 0..=max_len.saturating_sub(2)),
        end,
    )
        .prop_map(|(mid, end)| {
            let mut v = vec![Vertex::camera()];
            v.extend(mid);
            v.push(end);
            Path::new(v).expect("generated paths are valid")
        })
}

/// An atom that can match the camera vertex (the start of an AOV-like expression).
fn start_atom() -> impl Strategy<Value = Expr> {
    prop_oneof![
        3 => Just(Expr::Atom(Atom::Item(Item::Type(VertexType::C)))),
        1 => atom().prop_map(|a| Expr::Atom(Atom::Class {
            negated: false,
            items: match a {
                Atom::Item(i) => vec![Item::Type(VertexType::C), i],
                Atom::Class { items, .. } => {
                    let mut v = vec![Item::Type(VertexType::C)];
                    v.extend(items);
                    v
                }
            }
        })),
    ]
}

/// An atom that can match an emitter (the end of an AOV-like expression).
fn end_atom() -> impl Strategy<Value = Expr> {
    let light = |label| {
        Item::Triple(Triple {
            ty: TypePos::One(VertexType::L),
            event: EventPos::Any,
            label,
        })
    };
    prop_oneof![
        Just(Atom::Item(Item::Type(VertexType::L))),
        Just(Atom::Item(Item::Type(VertexType::O))),
        Just(Atom::Class {
            negated: false,
            items: vec![light(LabelPos::Any), Item::Type(VertexType::O)],
        }),
        label().prop_map(move |l| Atom::Item(light(LabelPos::One(l)))),
    ]
    .prop_map(Expr::Atom)
}

/// An AOV-shaped expression: camera-ish start, a random [`expr`] middle, emitter-ish
/// end. Unlike a fully random expression it matches a fair share of the paths
/// [`biased_paths`] generates for it, so comparisons are not all "no match".
pub fn aov_expr() -> impl Strategy<Value = Expr> {
    (start_atom(), expr(), end_atom()).prop_map(|(s, m, e)| Expr::Concat(vec![s, m, e]))
}

/// `n` paths aimed at `expr` (walks, near misses, noise: see
/// [`crate::generate::renderman::biased_path`]), drawn from a seed.
///
/// The seed does not shrink meaningfully; pair this with an expression strategy, whose
/// shrinking does the work, or with a minimizer such as the differential harness's.
pub fn biased_paths(expr: &Expr, n: usize) -> impl Strategy<Value = Vec<Path>> {
    let expr = expr.clone();
    any::<u64>().prop_map(move |seed| {
        let cfg = crate::generate::renderman::Config {
            labels: LABELS.map(str::to_string).to_vec(),
            ..crate::generate::renderman::Config::default()
        };
        let mut rng = lpe::rng::SplitMix64::new(seed);
        (0..n)
            .map(|_| crate::generate::renderman::biased_path(&expr, &mut rng, &cfg))
            .collect()
    })
}
