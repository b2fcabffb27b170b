//! The reference matchers on lpe's trees, for callers that hold one (lint, the
//! renderer's verification, the engines' `reference`, tests): each tree is printed with
//! lpe's canonical printer (docs/language.md §15; `Display` of `lpe::renderman::Lpe`,
//! `lpe::osl::Lpe`) and that text parsed by this crate's own front end, whose tree the
//! matcher runs on.
//!
//! What this path shares with lpe is exactly its printer: a printer bug that changes
//! meaning would show here as the reference answering for the printed text. The
//! front-end comparison (`lpe_engines::differential::front`) checks the printer too: it
//! parses the source text with both front ends and compares their matchers.
//!
//! An OSL tree carries its registration in its eaters' exclusions (the basic set); the
//! entry points without a registration ([`osl_is_match`]) read the registered labels
//! back from there ([`registered_in`]): inside `<…>`, where lpe prints every vertex
//! pattern, a label's kind does not matter, only whether it is basic.
//!
//! The printed form is lpe's own output for a tree lpe accepted, so it is parsed with
//! limits that never refuse it (lpe's limits may have been raised); a refusal is a
//! front-end disagreement and panics with both texts.

use lpe::renderman::{Path, Vertex};

use crate::error::{FrontError, Limits};
use crate::{osl, renderman};

/// Limits that accept whatever lpe's parser accepted (its own limits are configurable);
/// nesting stays bounded so the parse cannot overflow the stack.
fn generous() -> Limits {
    Limits {
        max_repeat: u32::MAX,
        max_positions: u64::MAX,
        max_depth: 4096,
        max_macro_depth: 16,
    }
}

fn refused(text: &str, e: FrontError) -> ! {
    panic!("the reference front end refuses lpe's canonical print `{text}`: {e}")
}

/// The reference tree of lpe's RenderMan tree (macros are expanded in the print).
pub fn renderman_tree(lpe: &lpe::renderman::Lpe) -> Result<renderman::Lpe, FrontError> {
    let reg = renderman::Registration {
        limits: generous(),
        ..Default::default()
    };
    renderman::parse(&lpe.to_string(), &reg)
}

/// The reference tree of lpe's OSL tree, parsed under the same registered labels.
pub fn osl_tree(
    lpe: &lpe::osl::Lpe,
    registered: &lpe::osl::Registered,
) -> Result<osl::Lpe, FrontError> {
    let reg = osl::Registration {
        events: registered.events.clone(),
        scatters: registered.scatters.clone(),
        limits: generous(),
    };
    osl::parse(&lpe.to_string(), &reg)
}

/// Whether lpe's RenderMan tree matches the whole of `path`, by the reference.
pub fn is_match(lpe: &lpe::renderman::Lpe, path: &Path) -> bool {
    match renderman_tree(lpe) {
        Ok(t) => renderman::is_match(&t, path),
        Err(e) => refused(&lpe.to_string(), e),
    }
}

/// Whether lpe's RenderMan expression (no algebra, no prefixes) matches `path`.
pub fn is_expr_match(expr: &lpe::renderman::Expr, path: &Path) -> bool {
    let text = expr.to_string();
    match renderman::parse(&text, &renderman::Registration::default()) {
        Ok(t) => renderman::is_match(&t, path),
        Err(e) => refused(&text, e),
    }
}

/// Whether lpe's atom matches one vertex, by the reference.
pub fn atom_matches(atom: &lpe::renderman::ast::Atom, v: &Vertex) -> bool {
    let text = atom.to_string();
    let tree = renderman::parse(&text, &renderman::Registration::default())
        .unwrap_or_else(|e| refused(&text, e));
    match &tree.body {
        crate::algebra::Algebra::Operand(renderman::ast::Expr::Atom(a)) => {
            renderman::matcher::atom_matches(a, v)
        }
        other => panic!("lpe's atom `{text}` printed as more than one atom: {other:?}"),
    }
}

/// The labels lpe's OSL tree treats as basic beyond the built-in ones (its eaters'
/// exclusions), as registered event labels.
pub fn registered_in(lpe: &lpe::osl::Lpe) -> lpe::osl::Registered {
    let builtin = osl::Registration::default().basic();
    let mut events: Vec<String> = Vec::new();
    for e in lpe.operands() {
        e.for_each_vertex(&mut |v| {
            for s in v.eater.iter().flatten() {
                if let lpe::osl::Symbol::Label(l) = s {
                    let sym = osl::ast::Sym::Label(l.clone());
                    if !builtin.contains(&sym) && !events.contains(l) {
                        events.push(l.clone());
                    }
                }
            }
        });
    }
    lpe::osl::Registered {
        events,
        scatters: Vec::new(),
    }
}

/// Whether lpe's OSL tree matches the whole of `path`, by the reference, under the
/// registration its eaters carry ([`registered_in`]).
pub fn osl_is_match(lpe: &lpe::osl::Lpe, path: &lpe::osl::Path) -> bool {
    let registered = registered_in(lpe);
    match osl_tree(lpe, &registered) {
        Ok(t) => osl::is_match(&t, path),
        Err(e) => refused(&lpe.to_string(), e),
    }
}
