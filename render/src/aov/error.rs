//! Why an AOV list could not be built: a leaf every part of the AOV glue reports with.

use lpe_lint::RibProblem;

/// Why an AOV list could not be built.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum AovError {
    #[error(
        "AOV name `{name}`: use letters, digits, `_` and `-` (it names an EXR layer and a file)"
    )]
    BadName { name: String },
    #[error("AOV name `{name}` is used twice (`beauty` is reserved)")]
    DuplicateName { name: String },
    /// The expression did not parse in the list's dialect; `dialect` is how messages
    /// name that dialect after the AOV's name ([`crate::aov::SceneDialect::MESSAGE_TAG`]).
    #[error("AOV `{name}`{dialect}: {error}")]
    Parse {
        name: String,
        dialect: &'static str,
        error: String,
    },
    #[error("--aov `{arg}`: expected NAME=LPE, e.g. diffuse=lpe:C<RD>[<L.>O]")]
    BadArgument { arg: String },
    #[error("at most {max} AOVs, got {count}")]
    TooMany { count: usize, max: usize },
    #[error("{file}:{line}: {problem}")]
    DisplayChannel {
        file: String,
        line: usize,
        problem: RibProblem,
    },
}
