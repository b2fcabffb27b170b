//! Prints the reference tree of an OSL expression as text lpe's OSL parser reads back to
//! the same meaning: every vertex pattern as `<…>` with its slot items (labels that are
//! not one plain character quoted, NONE as `x`), groups kept, every alternation and
//! compound repeat body parenthesized, counts without `?` (OSL has none). The eater is
//! implied by the number of custom items, as in the source.

use std::fmt;

use super::ast::{Expr, Lpe, Pattern, Slot, Sym};

/// A label as one slot item: a plain character as it is, anything else quoted.
fn label(l: &str) -> String {
    let mut chars = l.chars();
    match (chars.next(), chars.next()) {
        (Some(c), None) if !".x<>()[]'*+{}|^ \t\n".contains(c) => c.to_string(),
        _ => format!("'{l}'"),
    }
}

fn sym(s: &Sym) -> String {
    match s {
        Sym::None => "x".into(),
        Sym::Label(l) => label(l),
    }
}

fn pattern(p: &Pattern) -> String {
    match p {
        Pattern::Any => ".".into(),
        Pattern::Is(s) => sym(s),
        // Its items read as slot items: `x` NONE, `.` any, labels all quoted.
        Pattern::Either(ps) => {
            let items: String = ps
                .iter()
                .map(|p| match p {
                    Pattern::Is(Sym::Label(l)) => format!("'{l}'"),
                    p => pattern(p),
                })
                .collect();
            format!("[{items}]")
        }
        Pattern::NotIn(xs) => {
            let items: String = xs
                .iter()
                .map(|s| match s {
                    Sym::None => "x".into(),
                    Sym::Label(l) => format!("'{l}'"),
                })
                .collect();
            format!("[^{items}]")
        }
    }
}

fn slot(s: &Slot) -> String {
    match s {
        Slot::One(p) => pattern(p),
        // `|` takes one item on each side (§18.4): a longer alternative is one `( … )`.
        Slot::Group(alts) => {
            let texts: Vec<String> = alts
                .iter()
                .map(|seq| {
                    let text: String = seq.iter().map(slot).collect();
                    if alts.len() > 1 && seq.len() > 1 {
                        format!("({text})")
                    } else {
                        text
                    }
                })
                .collect();
            format!("({})", texts.join("|"))
        }
    }
}

/// The text of one expression.
pub fn expr(e: &Expr) -> String {
    match e {
        Expr::Vertex(v) => format!("<{}>", v.slots.iter().map(slot).collect::<String>()),
        Expr::Seq(es) => es.iter().map(unit).collect(),
        Expr::Alt(es) => {
            let es: Vec<String> = es.iter().map(unit).collect();
            format!("({})", es.join("|"))
        }
        Expr::Repeat(b, c) => format!("{}{}", unit(b), c.text(false)),
        Expr::Nothing => "[]".into(),
    }
}

/// An expression as one item: vertex patterns, lists and alternations as they are,
/// anything else in parentheses.
fn unit(e: &Expr) -> String {
    match e {
        Expr::Vertex(_) | Expr::Nothing | Expr::Alt(_) => expr(e),
        _ => format!("({})", expr(e)),
    }
}

impl fmt::Display for Lpe {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.body.print(&expr))
    }
}
