//! RenderMan's translation for the `oracle` engine: each operand of a set as a regex over
//! the fixed-width byte encoding of vertices ([`encode`]), built by set algebra over the
//! finite vertex universe ([`translate`](mod@translate)).

pub mod encode;
pub mod translate;

use lpe::renderman::{Expr, Lpe};
use regex_syntax::hir::Hir;

use super::hir::to_the_end;
use crate::error::BuildError;
use encode::Labels;

/// The anchored regex of each operand of each expression (one for a plain expression,
/// one per operand of set algebra, in [`Lpe::operands`] order), plus the label interning
/// they share.
pub fn translate(exprs: &[Lpe]) -> Result<(Labels, Vec<Hir>), BuildError> {
    let operands: Vec<&Expr> = exprs.iter().flat_map(|e| e.operands()).collect();
    let mut all = Vec::new();
    for e in &operands {
        all.extend(e.labels());
    }
    all.sort();
    all.dedup();
    let labels = Labels::new(&all).ok_or(BuildError::TooManyLabels {
        labels: all.len(),
        max: encode::MAX_LABELS,
    })?;
    let tr = translate::Translator::new(&labels);
    let hirs = operands.iter().map(|e| to_the_end(tr.expr(e))).collect();
    Ok((labels, hirs))
}

#[cfg(test)]
mod tests {
    use lpe::renderman::{Parser, RenderMan};

    use super::*;
    use crate::engine::{Engine, EngineError, Matcher};
    use crate::regex::LAZY;

    /// The oracle's RenderMan matcher for `exprs`, under the default parser.
    fn compile(exprs: &[Lpe]) -> Result<Box<dyn Matcher<RenderMan>>, EngineError> {
        Engine::<RenderMan>::compile(&LAZY, exprs, &Parser::default())
    }

    fn is_match(lpe: &Lpe, path: &str) -> bool {
        let m = compile(std::slice::from_ref(lpe)).unwrap();
        m.which(&path.parse().unwrap()).contains(0)
    }

    #[test]
    fn too_many_labels_is_a_typed_refusal() {
        let labels: String = (0..encode::MAX_LABELS + 1)
            .map(|i| format!("'l{i}'"))
            .collect();
        let lpe = lpe::renderman::parse(&format!("C[{labels}]L")).unwrap();
        let r = compile(std::slice::from_ref(&lpe));
        assert!(matches!(
            r,
            Err(EngineError::Regex(BuildError::TooManyLabels { labels, max }))
                if labels == encode::MAX_LABELS + 1 && max == encode::MAX_LABELS
        ));
        // One fewer fits, and the last label still gets its own byte.
        let labels: String = (0..encode::MAX_LABELS).map(|i| format!("'l{i}'")).collect();
        let lpe = lpe::renderman::parse(&format!("C[{labels}]L")).unwrap();
        let last = format!("C RD'l{}' L", encode::MAX_LABELS - 1);
        assert!(is_match(&lpe, &last));
        assert!(!is_match(&lpe, "C RD'other' L"));
    }
}
