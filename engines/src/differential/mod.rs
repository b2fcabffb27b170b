//! The differential harness: every engine on the same expressions and paths.
//!
//! Everything here is written once over the dialect traits of [`crate::dialect`] (what
//! a dialect's expressions, paths and registration are, how they shrink, how a report
//! shows the registration); what a case shares is the dialect's registration, passed
//! beside the expressions.
//!
//! - [`check`](mod@check): [`check()`] (one expression), [`check_set`] (an AOV set
//!   compiled at once), [`check_with`] (chosen engines) and [`check_in`] (under a
//!   registration) run each engine and compare the answers path by path. Agreement comes back with counts (pairs compared, how
//!   many matched, which engines could not build); a disagreement comes back as a
//!   minimized [`Counterexample`].
//! - [`minimize`](mod@minimize): the minimizer, which takes each dialect's
//!   [`ShrinkDialect`](crate::dialect::ShrinkDialect) steps (expression subtrees dropped
//!   or simplified, set members dropped, and path vertices dropped or unlabelled) for as
//!   long as the engines still disagree, so what is printed is small enough to read;
//!   [`shrink`]: those steps, the moves all dialects share and each dialect's own
//!   ([`shrink::renderman`], [`shrink::osl`]); [`answers`]: each engine's answers on one
//!   path, which both the comparison and the minimizer ask.
//! - [`counterexample`]: what a disagreement reports, and how it prints.
//! - [`generate`]: [`Generate`], a dialect's case generators (from `lpe_testkit`): trees,
//!   and text from the dialect's grammar ([`draw`]: half of each, a rejected text kept
//!   as a finding); [`cases`]: generated cases (a registration, expressions or AOV sets, with paths
//!   aimed at them), deterministic per seed and index, and a run over a range of them
//!   (`lpe-check diff`).
//! - [`front`]: the front-end comparison, lpe's parser against the reference's own
//!   front end on source text (acceptance, reprint, meaning on generated paths,
//!   equivalence), minimized by deleting characters, over generated and corpus
//!   expressions.
//!
//! An engine that cannot build the input ([`EngineError`](crate::EngineError)) does not
//! take part in that comparison; the skip is recorded in [`Agreement::skipped`] and
//! reported by callers, never hidden.

pub mod answers;
pub mod cases;
pub mod check;
pub mod counterexample;
pub mod front;
pub mod generate;
pub mod minimize;
pub mod shrink;

pub use answers::answers_in;
pub use cases::{case_rng, generate_case, run_cases, Case, Rejected, Run, Totals};
pub use check::{check, check_in, check_set, check_with, Agreement, Outcome};
pub use counterexample::Counterexample;
pub use generate::{draw, Drawn, Generate};
pub use minimize::{minimize_by, minimize_in};

#[cfg(test)]
pub(crate) mod tests {
    use lpe::renderman::ast::{Atom, Item};
    use lpe::renderman::{Lpe, Parser, RenderMan};

    use crate::adapters::ReferenceMatcher;
    use crate::engine::{Engine, EngineError, Matcher};

    /// A deliberately wrong engine: it ignores labels in `'g'` items by answering like
    /// the reference on the expression with every label item replaced by `.`.
    pub(crate) struct LabelBlind;

    impl Engine<RenderMan> for LabelBlind {
        fn name(&self) -> &'static str {
            "label-blind"
        }
        fn compile(
            &self,
            exprs: &[Lpe],
            parser: &Parser,
        ) -> Result<Box<dyn Matcher<RenderMan> + '_>, EngineError> {
            let mut blind = exprs.to_vec();
            for e in &mut blind {
                e.operands_mut(&mut |x| {
                    x.for_each_atom_mut(&mut |a| {
                        if matches!(a, Atom::Item(Item::Label(_))) {
                            *a = Atom::Item(Item::Any);
                        }
                    })
                });
            }
            Ok(Box::new(ReferenceMatcher::<RenderMan>::new(
                &blind, parser,
            )?))
        }
    }
}
