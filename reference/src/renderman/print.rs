//! Prints the reference tree of a RenderMan expression as text lpe's parser reads back
//! to the same meaning: no whitespace outside labels, every group and alternation
//! parenthesized where it could bind otherwise, prefixes first, set algebra with every
//! compound operand in parentheses. The front-end comparison re-parses this with lpe to
//! decide equivalence.

use std::fmt;

use super::ast::{Atom, Event, Expr, Item, Lpe, Position, Triple};

fn event(e: &Event) -> String {
    match e.lobe {
        Some(n) => format!("{}{n}", e.kind.letter()),
        None => e.kind.letter().to_string(),
    }
}

fn label(l: &str) -> String {
    format!("'{l}'")
}

fn position<T>(p: &Position<T>, one: &dyn Fn(&T) -> String, sep: &str) -> String {
    match p {
        Position::Any => ".".into(),
        Position::One(x) => one(x),
        Position::Class { negated, items } => {
            let items: Vec<String> = items.iter().map(one).collect();
            format!("[{}{}]", if *negated { "^" } else { "" }, items.join(sep))
        }
    }
}

fn triple(t: &Triple) -> String {
    let ty = position(&t.ty, &|x| x.letter().to_string(), "");
    let ev = position(&t.event, &event, "");
    let lb = match &t.label {
        Position::Any => String::new(),
        other => position(other, &|l: &String| label(l), ""),
    };
    format!("<{ty}{ev}{lb}>")
}

fn item(i: &Item) -> String {
    match i {
        Item::Type(t) => t.letter().to_string(),
        Item::Event(e) => event(e),
        Item::Any => ".".into(),
        Item::Label(l) => label(l),
        Item::Triple(t) => triple(t),
    }
}

/// The text of one expression.
pub fn expr(e: &Expr) -> String {
    match e {
        Expr::Atom(Atom::Item(i)) => item(i),
        Expr::Atom(Atom::Class { negated, items }) => {
            let items: Vec<String> = items.iter().map(item).collect();
            format!("[{}{}]", if *negated { "^" } else { "" }, items.concat())
        }
        Expr::Seq(es) => es
            .iter()
            .map(|e| match e {
                Expr::Seq(_) => format!("({})", expr(e)),
                _ => expr(e),
            })
            .collect(),
        Expr::Alt(es) => {
            let es: Vec<String> = es
                .iter()
                .map(|e| match e {
                    Expr::Atom(_) | Expr::Repeat(..) => expr(e),
                    _ => format!("({})", expr(e)),
                })
                .collect();
            format!("({})", es.join("|"))
        }
        Expr::Repeat(b, c) => match **b {
            Expr::Atom(_) => format!("{}{}", expr(b), c.text(true)),
            _ => format!("({}){}", expr(b), c.text(true)),
        },
    }
}

impl fmt::Display for Lpe {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for p in &self.prefixes {
            write!(f, "{};", p.name())?;
        }
        f.write_str(&self.body.print(&expr))
    }
}
