//! What a subcommand reports as bad input (an argument, a file, an expression):
//! [`InputError`], printed on stderr with exit status 2. Its own file so that the
//! dialects' argument handling ([`crate::dialect`]) and the shared input
//! ([`crate::input`]) both report it.

use std::path::PathBuf;

/// Bad input to a subcommand: reported on stderr, exit status 2.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    /// `--engine` names no registered engine.
    #[error("unknown engine `{name}`: available engines are {}, or `all`", .available.join(", "))]
    UnknownEngine {
        /// What was asked for.
        name: String,
        /// The registered names.
        available: Vec<&'static str>,
    },
    /// The `--ini` file cannot be read.
    #[error("cannot read {}: {error}", .path.display())]
    ReadIni {
        /// The file.
        path: PathBuf,
        /// Why.
        error: std::io::Error,
    },
    /// The `--ini` file has a bad line (the line number is in `error`).
    #[error("{}: {error}", .path.display())]
    Ini {
        /// The file.
        path: PathBuf,
        /// Which line, and what.
        error: lpe::renderman::IniError,
    },
    /// An expression does not parse (the error shows the byte position with a caret).
    #[error("{0}")]
    Expr(lpe::renderman::Error),
    /// `--ini` with `--dialect osl`: its macros and lobe mappings are RenderMan's.
    #[error("--ini holds RenderMan macros; it does not apply to --dialect osl")]
    IniWithOsl,
    /// `--register` without `--dialect osl`.
    #[error("--register is for --dialect osl")]
    RegisterWithoutOsl,
    /// `--register` does not parse (the error gives the byte position).
    #[error("--register: {0}")]
    Register(lpe::osl::RegisteredError),
    /// `--renderer` or `--profile` did not give a profile (an unknown name, with the
    /// known ones; a file that does not load, with its line and key).
    #[error("{0}")]
    Profile(lpe_profile::ProfileError),
    /// `--dialect` names another dialect than the renderer's profile reads.
    #[error("--dialect {given} contradicts --renderer {renderer}, which reads {base}'s dialect; drop --dialect")]
    DialectOfProfile {
        /// The dialect given.
        given: lpe::DialectName,
        /// The profile's name.
        renderer: String,
        /// The profile's base dialect.
        base: lpe::DialectName,
    },
}

impl From<lpe::renderman::Error> for InputError {
    fn from(e: lpe::renderman::Error) -> Self {
        InputError::Expr(e)
    }
}
