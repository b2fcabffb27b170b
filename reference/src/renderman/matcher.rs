//! The reference matcher: the expression semantics of docs/language.md §4–§5 executed as
//! plainly as possible, on this crate's own tree ([`super::ast`]).
//!
//! [`is_match`] runs recursive backtracking over the tree on a complete path. It is
//! written to be obviously right, not fast; it is the engine the others are compared
//! with (and docs/language.md is the tie-breaker when they disagree, §13).
//!
//! # How each rule maps to code
//!
//! | rule (docs/language.md) | here |
//! |---|---|
//! | an expression matches the **whole** path (anchored at both ends) | [`is_expr_match`] accepts only if the continuation sees position `len` |
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
//! | set algebra `A & B`, `A - B`, `^A` over whole expressions | [`is_match`] |
//!
//! Prefixes do not affect matching and are ignored here. Paths are lpe's
//! (`lpe::renderman::Path`): the path parser is not what the reference front end checks.
//!
//! Recursion depth grows with the path length (a few frames per vertex) and the
//! expression's nesting; run very long paths on a thread with a large stack, as
//! `lpe-check` does.

use std::collections::HashSet;

use lpe::renderman::{Path, Vertex};

use super::ast::{Atom, Event, Expr, Item, Kind, Lpe, Position, Triple, Type};
use crate::error::Count;

/// Whether `lpe` matches the whole of `path`. Set algebra by its definition: each
/// operand matched on its own, the answers combined (`&` and, `-` and not, `^` not).
pub fn is_match(lpe: &Lpe, path: &Path) -> bool {
    lpe.body.eval(&mut |e| is_expr_match(e, path))
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
        Expr::Seq(parts) => match_seq(parts, v, i, k),
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
/// such a body the lower bound is dropped (`e{n,m}` = `e{0,m}` when `e` is nullable,
/// §5.3). With that, `(x?)*` terminates and recursion depth is bounded by the path length.
///
/// Failures are remembered per `(count, i)` for this one call (the continuation is fixed
/// within it), so `(.?){256}` does not explore every way to split the path.
fn match_repeat(
    body: &Expr,
    r: Count,
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
        Expr::Seq(parts) => parts.iter().all(nullable),
        Expr::Alt(alts) => alts.iter().any(nullable),
        Expr::Repeat(body, r) => r.min == 0 || nullable(body),
    }
}

/// The vertex's type, in this tree's terms.
fn ty(v: &Vertex) -> Type {
    Type::from_letter(v.ty().letter()).unwrap_or_else(|| unreachable!("a vertex type letter"))
}

/// The vertex's event (kind and lobe), in this tree's terms.
fn vertex_event(v: &Vertex) -> Option<(Kind, u8)> {
    let e = v.event()?;
    Some((Kind::from_letter(e.kind().letter())?, e.lobe()))
}

fn scattering(t: Type) -> bool {
    matches!(t, Type::R | Type::T)
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
    scattering(ty(v)) && vertex_event(v).is_some_and(|(k, _)| k != Kind::U)
}

fn event_matches(p: Event, v: &Vertex) -> bool {
    vertex_event(v).is_some_and(|(k, l)| k == p.kind && p.lobe.is_none_or(|x| x == l))
}

/// One item against one vertex (docs/language.md §4.1).
pub fn item_matches(item: &Item, v: &Vertex) -> bool {
    match item {
        Item::Type(t @ (Type::C | Type::L | Type::O)) => ty(v) == *t,
        Item::Type(t) => ty(v) == *t && dot(v),
        Item::Event(p) => scattering(ty(v)) && event_matches(*p, v),
        Item::Any => dot(v),
        Item::Label(l) => dot(v) && v.label() == Some(l.as_str()),
        Item::Triple(t) => triple_matches(t, v),
    }
}

/// `<t e l>`: each position against its field; a negated class is the position's `.`
/// minus its items (§4.4).
pub fn triple_matches(t: &Triple, v: &Vertex) -> bool {
    let ty_ok = match &t.ty {
        Position::Any => scattering(ty(v)),
        Position::One(x) => ty(v) == *x,
        Position::Class { negated, items } => {
            let listed = items.contains(&ty(v));
            if *negated {
                scattering(ty(v)) && !listed
            } else {
                listed
            }
        }
    };
    // `.` in the event position: D or S for R/T, and "no event" for C/L/O.
    let ev_any = match vertex_event(v) {
        Some((k, _)) => k != Kind::U,
        None => true,
    };
    let ev_ok = match &t.event {
        Position::Any => ev_any,
        Position::One(p) => event_matches(*p, v),
        Position::Class { negated, items } => {
            let listed = items.iter().any(|p| event_matches(*p, v));
            if *negated {
                ev_any && !listed
            } else {
                listed
            }
        }
    };
    let label_ok = match &t.label {
        Position::Any => true,
        Position::One(l) => v.label() == Some(l.as_str()),
        Position::Class { negated, items } => {
            let listed = v.label().is_some_and(|x| items.iter().any(|l| l == x));
            listed != *negated
        }
    };
    ty_ok && ev_ok && label_ok
}
