//! Reading the subcommands' shared input: `--engine`, `--dialect` with `--ini` or
//! `--register` (read by each dialect's [`CliDialect`]), and the errors they report.

use std::path::PathBuf;

use lpe::osl::Osl;
use lpe::renderman::RenderMan;
use lpe_engines::Engine;

use crate::dialect::CliDialect;

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
}

/// `--dialect` and OSL's `--register`, shared by the subcommands that read expressions.
#[derive(clap::Args, Debug, Clone)]
pub struct DialectArgs {
    /// The expression language: `renderman` or `osl`.
    #[arg(long, default_value_t = lpe::DialectName::RenderMan)]
    pub dialect: lpe::DialectName,
    /// OSL only: user labels registered before parsing, `events=U;scatters=Y`.
    #[arg(long)]
    pub register: Option<String>,
}

impl DialectArgs {
    /// The registration of dialect `D` from `--ini` and `--register`
    /// ([`CliDialect::registration`]).
    pub fn registration<D: CliDialect>(
        &self,
        ini: Option<&std::path::Path>,
    ) -> Result<D::Registration, InputError> {
        D::registration(ini, self.register.as_deref())
    }

    /// Whether the OSL dialect is asked for; with RenderMan, `--register` is an error.
    /// For `match` and `external`, which do not go through [`CliDialect`] yet.
    pub fn is_osl(&self) -> Result<bool, InputError> {
        match (self.dialect, &self.register) {
            (lpe::DialectName::Osl, _) => Ok(true),
            (_, Some(_)) => Err(InputError::RegisterWithoutOsl),
            (_, None) => Ok(false),
        }
    }

    /// The OSL registration (`-` when not given); `--ini` is an error with OSL. For
    /// `match` and `external`, which do not go through [`CliDialect`] yet.
    pub fn registered(
        &self,
        ini: Option<&std::path::Path>,
    ) -> Result<lpe::osl::Registered, InputError> {
        self.registration::<Osl>(ini)
    }
}

impl From<lpe::renderman::Error> for InputError {
    fn from(e: lpe::renderman::Error) -> Self {
        InputError::Expr(e)
    }
}

/// Reports bad input (an argument, a file, an expression) on stderr: exit status 2.
pub fn bad_input(message: impl std::fmt::Display) -> std::process::ExitCode {
    eprintln!("{message}");
    std::process::ExitCode::from(2)
}

/// `--engine` values: one engine name, or `all`.
pub fn select_engines(name: &str) -> Result<Vec<&'static dyn Engine>, InputError> {
    if name == "all" {
        return Ok(lpe_engines::all());
    }
    lpe_engines::by_name(name)
        .map(|e| vec![e])
        .ok_or_else(|| InputError::UnknownEngine {
            name: name.to_string(),
            available: lpe_engines::names(),
        })
}

/// The parser for the built-in macros, or for those plus an ini file's. For `match`,
/// which does not go through [`CliDialect`] yet.
pub fn load_parser(ini: Option<&std::path::Path>) -> Result<lpe::renderman::Parser, InputError> {
    RenderMan::registration(ini, None)
}

/// An OSL parse error with the expression and a caret under the byte it points at
/// ([`CliDialect::show_error`]). For `match`, which does not go through [`CliDialect`]
/// yet.
pub fn osl_error(src: &str, e: &lpe::osl::Error) -> String {
    Osl::show_error(src, e)
}
