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
//! entry point without a registration ([`is_match`]) reads the registered labels
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

/// An lpe tree the reference can answer for: one implementation per dialect.
pub trait ReferenceMatch {
    /// The dialect's path.
    type Path;
    /// The reference's own tree of the dialect.
    type Tree: Send + Sync;
    /// The reference's parse of the tree's canonical print (panics if the reference
    /// refuses it: a front-end disagreement). Parse once, match many paths.
    fn reference_tree(&self) -> Self::Tree;
    /// Whether the reference's tree matches the whole of `path`.
    fn tree_matches(tree: &Self::Tree, path: &Self::Path) -> bool;
}

/// Whether lpe's tree (either dialect) matches the whole of `path`, by the reference.
/// Parses the print on every call: hold [`ReferenceMatch::reference_tree`] to match
/// many paths.
pub fn is_match<L: ReferenceMatch>(lpe: &L, path: &L::Path) -> bool {
    L::tree_matches(&lpe.reference_tree(), path)
}

/// A reference to a tree answers as the tree (callers iterating over `&Lpe`).
impl<T: ReferenceMatch> ReferenceMatch for &T {
    type Path = T::Path;
    type Tree = T::Tree;
    fn reference_tree(&self) -> T::Tree {
        (*self).reference_tree()
    }
    fn tree_matches(tree: &T::Tree, path: &T::Path) -> bool {
        T::tree_matches(tree, path)
    }
}

/// RenderMan: macros are expanded in the print.
impl ReferenceMatch for lpe::renderman::Lpe {
    type Path = Path;
    type Tree = renderman::Lpe;
    fn reference_tree(&self) -> renderman::Lpe {
        let reg = renderman::Registration {
            limits: generous(),
            ..Default::default()
        };
        let text = self.to_string();
        renderman::parse(&text, &reg).unwrap_or_else(|e| refused(&text, e))
    }
    fn tree_matches(tree: &renderman::Lpe, path: &Path) -> bool {
        renderman::is_match(tree, path)
    }
}

/// OSL: parsed under the registration the tree's eaters carry ([`registered_in`]).
impl ReferenceMatch for lpe::osl::Lpe {
    type Path = lpe::osl::Path;
    type Tree = osl::Lpe;
    fn reference_tree(&self) -> osl::Lpe {
        let registered = registered_in(self);
        let reg = osl::Registration {
            events: registered.events,
            scatters: registered.scatters,
            // The printed tree starts with the prefix it was written with, if any.
            prefixes: self.prefix.iter().cloned().collect(),
            builtins: Vec::new(),
            limits: generous(),
        };
        let text = self.to_string();
        osl::parse(&text, &reg).unwrap_or_else(|e| refused(&text, e))
    }
    fn tree_matches(tree: &osl::Lpe, path: &lpe::osl::Path) -> bool {
        osl::is_match(tree, path)
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
        ..Default::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rm(src: &str) -> lpe::renderman::Lpe {
        lpe::renderman::parse(src).unwrap()
    }

    fn parsed_under(src: &str, reg: &lpe::osl::Registered) -> lpe::osl::Lpe {
        lpe::osl::parse(src, reg).unwrap()
    }

    #[test]
    fn both_dialects_answer_through_a_borrowed_tree() {
        let rd = rm("C<RD>L");
        assert!(is_match(&&rd, &"C RD L".parse().unwrap()));
        assert!(!is_match(&&rd, &"C RS L".parse().unwrap()));
        let none = lpe::osl::Registered::none();
        let o = parsed_under("C<RD>L", &none);
        assert!(is_match(&&o, &"C,_ R,D L,_".parse().unwrap()));
        assert!(!is_match(&o, &"C,_ R,G L,_".parse().unwrap()));
        let tree = o.reference_tree();
        assert!(!<&lpe::osl::Lpe>::tree_matches(
            &tree,
            &"C,_ R,G L,_".parse().unwrap()
        ));
    }

    #[test]
    fn expressions_and_atoms_answer_by_the_reference() {
        let e = rm("C<RD>L");
        assert!(is_expr_match(&e.expr, &"C RD L".parse().unwrap()));
        assert!(!is_expr_match(&e.expr, &"C RS L".parse().unwrap()));
        let mut atoms = Vec::new();
        e.expr.for_each_atom(&mut |a| atoms.push(a.clone()));
        let path: Path = "C RD L".parse().unwrap();
        assert!(atom_matches(&atoms[1], &path.vertices()[1]));
        assert!(!atom_matches(&atoms[1], &path.vertices()[0]));
    }

    /// lpe's limits may be raised past the reference's defaults: the canonical print of
    /// what lpe accepted still parses.
    #[test]
    fn trees_past_the_default_limits_still_answer() {
        let limits = lpe::renderman::Limits {
            max_repeat: 1000,
            ..lpe::renderman::Limits::default()
        };
        let parser = lpe::renderman::Parser::new(limits.clone(), Default::default());
        let long = parser.parse("C.{300}L").unwrap();
        let path: Path = format!("C{} L", " RD".repeat(300)).parse().unwrap();
        assert!(is_match(&long, &path));
        let none = lpe::osl::Registered::none();
        let o = lpe::osl::parse_with("C.{300}L", &none, &limits).unwrap();
        let path: lpe::osl::Path = format!("C,_{} L,_", " R,D".repeat(300)).parse().unwrap();
        assert!(is_match(&o, &path));
    }

    #[test]
    fn registered_labels_are_read_back_from_the_eaters_once_each() {
        let reg: lpe::osl::Registered = "events=U;scatters=Y".parse().unwrap();
        let o = parsed_under("C<RD>U<TY>L", &reg);
        let back = registered_in(&o);
        assert_eq!(
            (back.events, back.scatters),
            (vec!["U".to_string(), "Y".to_string()], vec![])
        );
        // Nothing registered: only built-in labels in the eaters, none read back.
        let plain = parsed_under("C<RD>L", &lpe::osl::Registered::none());
        assert!(registered_in(&plain).events.is_empty());
        // The registered label stays basic for the reference: `U` is not eaten.
        assert!(!is_match(&o, &"C,_ R,D,U U,_ T,Y L,_".parse().unwrap()));
        assert!(is_match(&o, &"C,_ R,D,u U,_ T,Y L,_".parse().unwrap()));
    }
}
