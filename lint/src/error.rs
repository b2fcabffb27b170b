//! Why a file could not be read: every variant names the file, and the line (or the
//! prim and attribute) when there is one.

use std::path::PathBuf;

use crate::decl::Location;

/// A file that could not be read as declared (exit status 2 in `lpe-check lint`).
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    /// The file cannot be opened or read.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The file is larger than its format's limit ([`crate::read::Limits`]).
    #[error("{}: {bytes} bytes, over the {limit}-byte limit for {what} files", path.display())]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size.
        bytes: u64,
        /// The limit.
        limit: u64,
        /// Which format's limit.
        what: &'static str,
    },
    /// A text format holding a NUL byte or invalid UTF-8: not text.
    #[error("{}: byte {offset}: not text (binary data or a truncated download?)", path.display())]
    NotText {
        /// The file.
        path: PathBuf,
        /// 0-based byte offset of the first bad byte.
        offset: u64,
    },
    /// The extension names no format lint reads.
    #[error(
        "{}: unknown file type: expected .usda, .usdc, .usd, .usdz, .rib or .ini",
        path.display()
    )]
    UnknownFormat {
        /// The file.
        path: PathBuf,
    },
    /// The USD library refused the file (its message carries the line for text layers).
    #[error("{}: USD: {message}", path.display())]
    Usd {
        /// The file.
        path: PathBuf,
        /// The USD library's message.
        message: String,
    },
    /// A RIB line lint cannot read.
    #[error("{}:{line}: {problem}", path.display())]
    Rib {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// What is wrong.
        problem: RibProblem,
    },
    /// An `lpe:dialect` declaration lint cannot read: the file's expressions would be
    /// read in a dialect it does not mean.
    #[error("{}: {at}: {problem}", path.display())]
    Dialect {
        /// The file.
        path: PathBuf,
        /// The attribute (boxed, as `problem`: this rare variant would otherwise make
        /// every `Result` of the readers larger).
        at: Box<Location>,
        /// What is wrong.
        problem: Box<DialectProblem>,
    },
    /// An `lpe:renderer` declaration that names no renderer profile, or two that name
    /// different ones.
    #[error("{}: {at}: {message}", path.display())]
    Renderer {
        /// The file.
        path: PathBuf,
        /// The attribute.
        at: Box<Location>,
        /// What is wrong (the known renderers, with a did-you-mean).
        message: String,
    },
    /// A bad `rendermn.ini` line (the line number is in `error`).
    #[error("{}: {error}", path.display())]
    Ini {
        /// The file.
        path: PathBuf,
        /// Which line, and what.
        error: lpe::renderman::IniError,
    },
}

/// What is wrong with a RIB line.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RibProblem {
    /// A line longer than [`crate::read::Limits::line_bytes`].
    #[error("line longer than {limit} bytes")]
    LineTooLong {
        /// The limit.
        limit: usize,
    },
    /// A `"` with no closing `"` on the line.
    #[error("unterminated string")]
    UnterminatedString,
    /// `DisplayChannel` without its `"TYPE NAME"` declaration.
    #[error("expected `DisplayChannel \"color NAME\" ...`")]
    NoDeclaration,
    /// `"string source"` as the last token.
    #[error("channel `{name}`: \"string source\" needs a value")]
    SourceWithoutValue {
        /// The channel.
        name: String,
    },
    /// More `DisplayChannel` lines than [`crate::read::Limits::channels`].
    #[error("more than {limit} DisplayChannel lines")]
    TooManyChannels {
        /// The limit.
        limit: usize,
    },
}

/// What is wrong with an `lpe:dialect` declaration.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DialectProblem {
    /// A name that is no dialect, with the dialect it most likely means (a renderer
    /// reading it, or a name in other case).
    #[error("{unknown}{}", suggestion.map(|d| format!("; did you mean `{d}`?")).unwrap_or_default())]
    Unknown {
        /// The name, with the dialects there are.
        unknown: lpe::UnknownDialect,
        /// The dialect it likely means.
        suggestion: Option<lpe::DialectName>,
    },
    /// A value that is not a string or token, or no value at all.
    #[error("expected a string or token, `renderman` or `osl`")]
    NotAName,
    /// A second declaration naming another dialect.
    #[error("declares `{dialect}`, but {first} declares `{earlier}`")]
    Conflict {
        /// The dialect this one names.
        dialect: lpe::DialectName,
        /// The earlier declaration's.
        earlier: lpe::DialectName,
        /// Where the earlier one is.
        first: Location,
    },
}
