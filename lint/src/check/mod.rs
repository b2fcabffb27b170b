//! The checks of `lpe-check lint` on the declarations [`crate::read`] reads, and their
//! text and JSON reports.
//!
//! [`inputs`] reads the files in the command's order. Per file: parse errors
//! ([`aovs`]), AOVs that can match no path and AOVs equivalent to an earlier one
//! ([`aovs`]), group labels no light or object of the stage carries and numbered lobes
//! no mapping feeds ([`labels`], [`aovs`]), and the declared partitions ([`partition`]),
//! each a [`Finding`]; [`text`] and [`json`] print them. [`dialect`] is what the checks
//! ask of the expression language (RenderMan's or OSL's), so they are written once.

pub mod aovs;
pub mod dialect;
pub mod finding;
pub mod inputs;
pub mod json;
pub mod labels;
pub mod partition;
pub mod text;

pub use finding::{Finding, Kind};

use lpe::Lpe;

use dialect::Dialect;

use crate::witness::Disagreement;
use crate::{AovDecl, Document, PartitionDecl};

/// One AOV as linted: its declaration and, when it parsed, its expression.
#[derive(Clone, Debug)]
pub struct Linted<E = Lpe> {
    /// The file, as given.
    pub file: String,
    /// The declaration.
    pub decl: AovDecl,
    /// The parsed expression, `None` after a parse error.
    pub lpe: Option<E>,
}

/// A partition as checked.
#[derive(Clone, Debug)]
pub struct CheckedPartition {
    /// The file declaring it (`--partition`: `(command line)`).
    pub file: String,
    /// The declaration.
    pub decl: PartitionDecl,
    /// Whether it could be checked (every member known and parsed).
    pub checked: bool,
    /// Checked and clean.
    pub clean: bool,
}

/// Everything lint found.
#[derive(Clone, Debug)]
pub struct Outcome<E = Lpe> {
    /// Every LPE AOV read, in file order.
    pub aovs: Vec<Linted<E>>,
    /// Every partition.
    pub partitions: Vec<CheckedPartition>,
    /// The findings, per file in check order.
    pub findings: Vec<Finding>,
}

/// Lints the documents read (ini documents contribute only partitions), then the
/// `extra` partitions over the AOVs of every file. Partition witnesses are re-checked
/// with the reference matcher; a failed re-check is an engine bug, returned as the error.
pub fn lint<D: Dialect>(
    docs: &[Document],
    dialect: &D,
    universe: &D::Expr,
    extra: &[PartitionDecl],
) -> Result<Outcome<D::Expr>, Disagreement> {
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
