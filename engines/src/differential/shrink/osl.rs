//! One-step simplifications of OSL expressions and paths, for the minimizer.
//!
//! A vertex pattern keeps OSL's eater rule while it shrinks (an eater, excluding the
//! basic labels, exactly when it has fewer than five custom items), so every candidate
//! is something the parser could have produced and its printed text means the same.

use lpe::osl::{Expr, Path, Symbol, SymbolPattern, VertexPattern};

use super::{shrink_parts, shrink_repeat};

/// Custom items from which a vertex pattern has no eater (OSL's rule).
const NO_EATER_FROM: usize = 5;

/// Simpler paths: one vertex dropped, or one custom label of a vertex dropped.
pub fn shrink_path(path: &Path) -> Vec<Path> {
    let v = &path.vertices;
    let mut out = Vec::new();
    if v.len() > 1 {
        for i in 0..v.len() {
            let mut w = v.clone();
            w.remove(i);
            out.push(Path::new(w));
        }
    }
    for (i, vertex) in v.iter().enumerate() {
        for j in 2..vertex.symbols.len() {
            let mut w = v.clone();
            w[i].symbols.remove(j);
            out.push(Path::new(w));
        }
    }
    out
}

/// One-step simplifications of an expression, whole subtrees first; `basic` is the
/// eater's exclusion list (the registration's basic labels). Every candidate has
/// fewer nodes, fewer slots, looser slots or smaller counts, so shrinking terminates.
pub fn shrink_expr(e: &Expr, basic: &[Symbol]) -> Vec<Expr> {
    let mut out = Vec::new();
    match e {
        Expr::Vertex(v) => out.extend(shrink_vertex(v, basic).into_iter().map(Expr::Vertex)),
        Expr::Concat(es) | Expr::Alt(es) => {
            let rebuild = |mut parts: Vec<Expr>| match (parts.len(), e) {
                (1, _) => parts.pop().expect("one part"),
                (_, Expr::Concat(_)) => Expr::Concat(parts),
                _ => Expr::Alt(parts),
            };
            shrink_parts(es, rebuild, |x| shrink_expr(x, basic), &mut out);
        }
        Expr::Repeat(body, r) => shrink_repeat(
            &**body,
            *r,
            |b, r| Expr::Repeat(Box::new(b), r),
            |x| shrink_expr(x, basic),
            &mut out,
        ),
        Expr::Empty | Expr::Nothing => {}
    }
    out
}

fn shrink_vertex(v: &VertexPattern, basic: &[Symbol]) -> Vec<VertexPattern> {
    let mut out = Vec::new();
    let with = |symbols: Vec<SymbolPattern>| VertexPattern {
        eater: (symbols.len() - 2 < NO_EATER_FROM).then(|| basic.to_vec()),
        symbols,
    };
    // A custom item dropped.
    for i in 2..v.symbols.len() {
        let mut s = v.symbols.clone();
        s.remove(i);
        out.push(with(s));
    }
    // One slot loosened: to `.`, or one listed symbol fewer.
    for (i, p) in v.symbols.iter().enumerate() {
        let mut looser = Vec::new();
        match p {
            SymbolPattern::Any => {}
            SymbolPattern::One(_) => looser.push(SymbolPattern::Any),
            SymbolPattern::Set(xs) | SymbolPattern::NotIn(xs) => {
                looser.push(SymbolPattern::Any);
                if xs.len() > 1 {
                    for j in 0..xs.len() {
                        let mut fewer = xs.clone();
                        fewer.remove(j);
                        looser.push(match p {
                            SymbolPattern::Set(_) => SymbolPattern::Set(fewer),
                            _ => SymbolPattern::NotIn(fewer),
                        });
                    }
                }
            }
        }
        for l in looser {
            let mut s = v.symbols.clone();
            s[i] = l;
            out.push(VertexPattern {
                symbols: s,
                eater: v.eater.clone(),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use lpe::osl::{self, Osl, Registered};
    use lpe_reference::osl::ast::Expr;

    use super::*;
    use crate::adapters::{Reference, ReferenceMatcher};
    use crate::differential::{check_in, Outcome};
    use crate::engine::{Engine, EngineError, Matcher};

    /// A deliberately wrong engine: its eaters skip every symbol, basic labels included
    /// (OSL's comment says "everything but STOP"; its code excludes the basic set).
    struct EaterBlind;

    fn blind(e: &mut Expr) {
        match e {
            Expr::Vertex(v) => {
                if let Some(ex) = &mut v.eater {
                    ex.clear();
                }
            }
            Expr::Seq(es) | Expr::Alt(es) => es.iter_mut().for_each(blind),
            Expr::Repeat(b, _) => blind(b),
            Expr::Nothing => {}
        }
    }

    impl Engine<Osl> for EaterBlind {
        fn name(&self) -> &'static str {
            "eater-blind"
        }
        fn compile(
            &self,
            exprs: &[osl::Lpe],
            registered: &Registered,
        ) -> Result<Box<dyn Matcher<Osl> + '_>, EngineError> {
            // The reference's own trees, every eater then emptied.
            let mut m = ReferenceMatcher::<Osl>::new(exprs, registered)?;
            for t in &mut m.0 {
                t.body.for_each_mut(&mut blind);
            }
            Ok(Box::new(m))
        }
    }

    #[test]
    fn a_planted_bug_is_found_and_minimized_in_the_osl_dialect() {
        let engines: Vec<&dyn Engine<Osl>> = vec![&Reference, &EaterBlind];
        let reg: Registered = "events=U".parse().unwrap();
        let exprs: Vec<osl::Lpe> = ["C<RD>[LO]", "C(<.[GS]>|'foo')*<TD'key'>.*[LO]"]
            .iter()
            .map(|s| osl::parse(s, &reg).unwrap())
            .collect();
        let path: Path = "C,_ R,G T,S,foo T,D,key,U,x L,_,key".parse().unwrap();
        let Outcome::Disagree(c) = check_in(&engines, &reg, &exprs, &[path]) else {
            panic!("the planted bug went unnoticed");
        };
        // Down to one vertex pattern and one vertex whose only extra label is the
        // registered U: the reference's eater refuses it, the planted bug's eats it.
        assert_eq!(c.exprs.len(), 1);
        assert_eq!(c.path.to_string(), "T,D,U", "{c}");
        assert_eq!(c.exprs[0].to_string(), "<..>");
        let text = c.to_string();
        assert!(text.contains("registered: events=U"), "{text}");
        assert!(text.contains("reference: no-match"), "{text}");
        assert!(text.contains("eater-blind: match"), "{text}");
    }

    #[test]
    fn shrinking_keeps_the_eater_rule_and_terminates() {
        let reg = Registered::none();
        let basic = reg.basic_labels();
        let e = osl::parse("C(<R[DG]'a'>|<T[^S]abcde>{2,3})*[^'b']L", &reg)
            .unwrap()
            .expr;
        let mut frontier = vec![e];
        let mut seen = 0;
        while let Some(x) = frontier.pop() {
            seen += 1;
            assert!(seen < 200_000, "shrinking does not terminate");
            for y in shrink_expr(&x, &basic) {
                // What the parser makes of the printed candidate is the candidate.
                let text = y.to_string();
                if !text.is_empty() {
                    if let Ok(back) = osl::parse(&text, &reg) {
                        assert_eq!(back.expr, y, "{text}");
                    }
                }
                y.for_each_vertex(&mut |v| {
                    assert_eq!(v.eater.is_some(), v.symbols.len() < 7, "{text}");
                });
                if seen < 500 {
                    frontier.push(y);
                }
            }
        }
    }
}
