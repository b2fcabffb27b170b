//! What lint found, as the checks and the reports share it: each AOV as linted, each
//! partition as checked, and the findings. A leaf, so that the checks (`aovs`,
//! `partition`) and the driver (`lint`) both use it without using each other.

use lpe::renderman::Lpe;

use super::finding::Finding;
use crate::{AovDecl, PartitionDecl};

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
