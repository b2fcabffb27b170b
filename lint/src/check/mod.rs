//! The checks of `lpe-check lint` on the declarations [`crate::read`] reads, and their
//! text and JSON reports.
//!
//! [`inputs`] reads the files in the command's order. Per file: parse errors
//! ([`aovs`]), AOVs that can match no path and AOVs equivalent to an earlier one
//! ([`aovs`]), group labels no light or object of the stage carries and numbered lobes
//! no mapping feeds ([`labels`], [`dialect`], [`aovs`]), expressions of a stage that does
//! not declare its dialect that mean different things in RenderMan's and OSL's
//! ([`ambiguity`], unless the user named the run's dialect), and the declared partitions
//! ([`partition`]), each a [`Finding`], collected in an [`outcome`]; [`text`] and
//! [`json`] print them. [`dialect`] is what the checks
//! ask of the expression language ([`dialect::LintDialect`], implemented on `lpe`'s
//! RenderMan and OSL markers), so they are written once.

pub mod ambiguity;
pub mod aovs;
pub mod dialect;
pub mod finding;
pub mod inputs;
pub mod json;
pub mod labels;
pub mod outcome;
pub mod partition;
pub mod renderer;
pub mod run;
pub mod text;

pub use finding::{Finding, Kind};
pub use outcome::{CheckedPartition, Linted, Outcome};

use ambiguity::BothDialects;
use dialect::{Lint, LintDialect};

use crate::witness::Disagreement;
use crate::{Document, PartitionDecl};

/// Lints the documents read (ini documents contribute only partitions) in `dialect`, and
/// the AOVs of those that declare no dialect in `both` too (`None`: the user named the
/// dialect, nothing is ambiguous), with the rules of the renderer's `profile` when there
/// is one ([`renderer`]); then the `extra` partitions
/// over the AOVs of every file. Witnesses are re-checked with the reference matcher; a
/// failed re-check is an engine bug, returned as the error.
pub fn lint<D: LintDialect>(
    docs: &[Document],
    dialect: &Lint<'_, D>,
    both: Option<&BothDialects>,
    profile: Option<&lpe_profile::Profile>,
    universe: &D::Lpe,
    extra: &[PartitionDecl],
) -> Result<Outcome<D::Lpe>, Disagreement> {
    let mut out = Outcome {
        aovs: Vec::new(),
        partitions: Vec::new(),
        findings: Vec::new(),
    };
    for doc in docs {
        let file = doc.file.display().to_string();
        let first = out.aovs.len();
        out.aovs.extend(doc.aovs.iter().map(|decl| Linted {
            file: file.clone(),
            decl: decl.clone(),
            lpe: None,
        }));
        aovs::check(doc, &mut out.aovs[first..], dialect, &mut out.findings);
        if let Some(profile) = profile {
            renderer::check(
                profile,
                doc.format,
                &out.aovs[first..],
                dialect,
                &mut out.findings,
            );
        }
        if let Some(both) = both {
            ambiguity::check(doc, &out.aovs[first..], both, &mut out.findings)?;
        }
        for p in &doc.partitions {
            let checked = partition::check(
                &file,
                p,
                &out.aovs[first..],
                dialect,
                universe,
                &mut out.findings,
            )?;
            out.partitions.push(checked);
        }
    }
    for p in extra {
        let checked = partition::check(
            "(command line)",
            p,
            &out.aovs,
            dialect,
            universe,
            &mut out.findings,
        )?;
        out.partitions.push(checked);
    }
    Ok(out)
}

#[cfg(test)]
mod undecided_tests {
    use super::*;
    use crate::{AovDecl, Format, Location};
    use lpe::analysis::AnalysisBudget;
    use lpe::renderman::RenderMan;

    /// Two AOVs whose equivalence and partition take more than 50 search steps: with a
    /// budget of 50, lint reports an `undecided` finding for the pair and one for the
    /// partition, and neither an `equivalent` finding nor a clean partition. Treating an
    /// undecided comparison as "not equivalent" without a finding fails it.
    #[test]
    fn questions_past_the_budget_are_undecided_findings() {
        let mut doc = Document::new("scene.rib", Format::Rib);
        for (name, source) in [("a", "C.*D.{12}L"), ("b", "(C.*D.{12}L)|(C.*S.{12}L)")] {
            doc.aovs.push(AovDecl {
                name: name.to_string(),
                source: source.to_string(),
                location: Location::Line { line: 1, column: 1 },
                source_type: None,
            });
        }
        doc.partitions.push(PartitionDecl {
            name: "beauty".to_string(),
            members: vec!["a".to_string(), "b".to_string()],
            location: Location::Line { line: 2, column: 1 },
        });
        let registration = lpe::renderman::Parser::default();
        let lobes = Default::default();
        let dialect = Lint::<RenderMan> {
            registration: &registration,
            lobes: &lobes,
            budget: AnalysisBudget::steps(50),
        };
        let both = BothDialects::new(lpe::renderman::Parser::default());
        let universe = dialect
            .parse(<RenderMan as lpe::Dialect>::DEFAULT_UNIVERSE)
            .unwrap();
        let out = lint(&[doc], &dialect, Some(&both), None, &universe, &[]).unwrap();
        let kinds: Vec<(&str, &str)> = out
            .findings
            .iter()
            .map(|f| (f.kind.name(), f.subject.as_str()))
            .collect();
        assert_eq!(
            kinds,
            [("undecided", "b"), ("undecided", "beauty")],
            "{out:?}"
        );
        assert!(out.findings[0]
            .message
            .contains("undecided within the budget of 50"));
    }
}
