//! Reading the subcommands' shared input: `--engine`, `--dialect` with `--ini` or
//! `--register` (read by each dialect's [`CliDialect`]); the errors they report are
//! [`InputError`]'s.

use lpe::osl::Osl;
use lpe::renderman::RenderMan;
use lpe_engines::{Engine, EngineDialect};

use crate::dialect::CliDialect;
pub use crate::error::InputError;

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

/// Reports bad input (an argument, a file, an expression) on stderr: exit status 2.
pub fn bad_input(message: impl std::fmt::Display) -> std::process::ExitCode {
    eprintln!("{message}");
    std::process::ExitCode::from(2)
}

/// `--engine` values: one engine name, or `all`, of dialect `D`'s registry.
pub fn select_engines<D: EngineDialect>(
    name: &str,
) -> Result<Vec<&'static dyn Engine<D>>, InputError> {
    if name == "all" {
        return Ok(lpe_engines::all::<D>());
    }
    lpe_engines::by_name::<D>(name)
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
