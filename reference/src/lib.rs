//! The reference matcher: the expression semantics of docs/language.md §4–§5 executed as
//! plainly as possible.
//!
//! [`is_match`] runs recursive backtracking over the AST on a complete path. It is
//! written to be obviously right, not fast; it is the engine the others are compared
//! with (and docs/language.md is the tie-breaker when they disagree, §13).
//!
//! # How each rule maps to code
//!
//! | rule (docs/language.md) | here |
//! |---|---|
//! | an expression matches the **whole** path (anchored at both ends) | [`is_match`] accepts only if the continuation sees position `len` |
//! | concatenation, alternation (`\|` binds only its neighbours: that is the parser's job; here an `Alt` node is plain "either") | `match_expr` |
//! | `e{n,m}`, `*`, `+`, `?`, `{0}` matching the empty sequence | `match_repeat` |
//! | one atom matches one vertex | [`atom_matches`] |
//! | `C L O` any label; `R T` need a D/S event | [`item_matches`], `Item::Type` |
//! | `D S D2…`: R/T with that kind/lobe; `U`: only explicitly | [`item_matches`], `Item::Event` |
//! | `.`: R/T with a D or S event | [`dot`] |
//! | `'g'`: R/T, D or S, label `g` | [`item_matches`], `Item::Label` |
//! | `<t e l>`: all three positions | [`triple_matches`] |
//! | `[^…]`: matched by `.` and by no item | [`atom_matches`] |
//! | negation inside a triple: the position's `.` minus the items; `[^'foo']` matches no label | [`triple_matches`] |
//!
//! | set algebra `A & B`, `A - B`, `^A` over whole expressions | [`is_match`] |
//!
//! Prefixes do not affect matching and are ignored here.
//!
//! Recursion depth grows with the path length (a few frames per vertex) and the
//! expression's nesting; run very long paths on a thread with a large stack, as
//! `lpe-check` does.
//!
//! The OSL dialect has its own reference in [`osl`]: OSL defines matching over a
//! stream of symbols, not of vertices.

#![forbid(unsafe_code)]

use std::collections::HashSet;

pub mod osl;

use lpe::renderman::ast::{
    Atom, EventPattern, EventPos, Expr, Item, LabelPos, Repetition, Triple, TypePos,
};
use lpe::renderman::{Lpe, Path, Vertex, VertexType};

/// Whether `lpe` matches the whole of `path`. Set algebra by its definition: each
/// operand matched on its own, the answers combined (`&` and, `-` and not, `^` not).
pub fn is_match(lpe: &Lpe, path: &Path) -> bool {
    lpe.eval(&mut |e| is_expr_match(e, path))
}

/// Whether `expr` matches the whole of `path`.
pub fn is_expr_match(expr: &Expr, path: &Path) -> bool {
    let v = path.vertices();
    match_expr(expr, v, 0, &mut |end| end == v.len())
}

/// Tries to match `e` against `v` starting at `i`; for every way it can end at `j`, asks
/// the continuation `k(j)` whether the rest matches. True as soon as one way succeeds.
fn match_expr(e: &Expr, v: &[Vertex], i: usize, k: &mut dyn FnMut(usize) -> bool) -> bool {
    match e {
        Expr::Atom(a) => i < v.len() && atom_matches(a, &v[i]) && k(i + 1),
        Expr::Concat(parts) => match_seq(parts, v, i, k),
        Expr::Alt(alts) => alts.iter().any(|a| match_expr(a, v, i, k)),
        Expr::Repeat(body, r) => match_repeat(body, *r, v, i, k),
    }
}

/// `parts[0] parts[1] ...` in order.
fn match_seq(parts: &[Expr], v: &[Vertex], i: usize, k: &mut dyn FnMut(usize) -> bool) -> bool {
    match parts.split_first() {
        None => k(i),
        Some((first, rest)) => match_expr(first, v, i, &mut |j| match_seq(rest, v, j, k)),
    }
}

/// `body{min,max}`: after `count` iterations at position `i`, either stop (if `count >=
/// min`) or run one more iteration.
///
/// Every iteration must consume at least one vertex. That loses nothing: an empty
/// iteration leaves the position unchanged, so it only ever helps to reach `min`, and a
/// body that can match the empty sequence can pad any count up to `min` that way, so for
/// such a body the lower bound is dropped (`e{n,m}` = `e{0,m}` when `e` is nullable).
/// With that, `(x?)*` terminates and recursion depth is bounded by the path length.
///
/// Failures are remembered per `(count, i)` for this one call (the continuation is fixed
/// within it), so `(.?){256}` does not explore every way to split the path.
fn match_repeat(
    body: &Expr,
    r: Repetition,
    v: &[Vertex],
    i: usize,
    k: &mut dyn FnMut(usize) -> bool,
) -> bool {
    struct Rep<'a> {
        body: &'a Expr,
        min: u32,
        max: Option<u32>,
        v: &'a [Vertex],
        failed: HashSet<(u32, usize)>,
    }
    fn go(s: &mut Rep<'_>, count: u32, i: usize, k: &mut dyn FnMut(usize) -> bool) -> bool {
        if s.failed.contains(&(count, i)) {
            return false;
        }
        let ok = (count >= s.min && k(i))
            || (s.max.is_none_or(|m| count < m) && {
                let (body, v) = (s.body, s.v);
                match_expr(body, v, i, &mut |j| j > i && go(s, count + 1, j, k))
            });
        if !ok {
            s.failed.insert((count, i));
        }
        ok
    }
    let min = if nullable(body) { 0 } else { r.min };
    let mut s = Rep {
        body,
        min,
        max: r.max,
        v,
        failed: HashSet::new(),
    };
    go(&mut s, 0, i, k)
}

/// Can `e` match the empty sequence?
fn nullable(e: &Expr) -> bool {
    match e {
        Expr::Atom(_) => false,
        Expr::Concat(parts) => parts.iter().all(nullable),
        Expr::Alt(alts) => alts.iter().any(nullable),
        Expr::Repeat(body, r) => r.min == 0 || nullable(body),
    }
}

/// Does one atom match one vertex?
pub fn atom_matches(a: &Atom, v: &Vertex) -> bool {
    match a {
        Atom::Item(item) => item_matches(item, v),
        Atom::Class {
            negated: false,
            items,
        } => items.iter().any(|it| item_matches(it, v)),
        Atom::Class {
            negated: true,
            items,
        } => dot(v) && !items.iter().any(|it| item_matches(it, v)),
    }
}

/// `.` at the top level: an R or T vertex with a D or S event.
pub fn dot(v: &Vertex) -> bool {
    v.ty().is_scattering() && v.event().is_some_and(|e| e.is_transport())
}

fn event_matches(p: EventPattern, v: &Vertex) -> bool {
    v.event()
        .is_some_and(|e| e.kind() == p.kind && p.lobe.is_none_or(|l| l == e.lobe()))
}

/// One item against one vertex (docs/language.md §4.1).
pub fn item_matches(item: &Item, v: &Vertex) -> bool {
    match item {
        Item::Type(t @ (VertexType::C | VertexType::L | VertexType::O)) => v.ty() == *t,
        Item::Type(t) => v.ty() == *t && dot(v),
        Item::Event(p) => v.ty().is_scattering() && event_matches(*p, v),
        Item::Any => dot(v),
        Item::Label(l) => dot(v) && v.label() == Some(l.as_str()),
        Item::Triple(t) => triple_matches(t, v),
    }
}

/// `<t e l>`: each position against its field; a negated class is the position's `.`
/// minus its items.
pub fn triple_matches(t: &Triple, v: &Vertex) -> bool {
    let ty_any = |ty: VertexType| ty.is_scattering();
    let ty_ok = match &t.ty {
        TypePos::Any => ty_any(v.ty()),
        TypePos::One(ty) => v.ty() == *ty,
        TypePos::Class { negated, types } => {
            let listed = types.contains(&v.ty());
            if *negated {
                ty_any(v.ty()) && !listed
            } else {
                listed
            }
        }
    };
    // `.` in the event position: D or S for R/T, and "no event" for C/L/O.
    let ev_any = match v.event() {
        Some(e) => e.is_transport(),
        None => true,
    };
    let ev_ok = match &t.event {
        EventPos::Any => ev_any,
        EventPos::One(p) => event_matches(*p, v),
        EventPos::Class { negated, events } => {
            let listed = events.iter().any(|p| event_matches(*p, v));
            if *negated {
                ev_any && !listed
            } else {
                listed
            }
        }
    };
    let label_ok = match &t.label {
        LabelPos::Any => true,
        LabelPos::One(l) => v.label() == Some(l.as_str()),
        LabelPos::Class { negated, labels } => {
            let listed = v.label().is_some_and(|x| labels.iter().any(|l| l == x));
            listed != *negated
        }
    };
    ty_ok && ev_ok && label_ok
}
