//! Reading the subcommands' shared input: `--engine`, `--dialect` with `--ini` or
//! `--register` (read by each dialect's [`CliDialect`]); the errors they report are
//! [`InputError`]'s.

use lpe_engines::{Engine, EngineDialect};

use crate::dialect::CliDialect;
pub use crate::error::InputError;

/// `--dialect` and OSL's `--register`, shared by the subcommands that read expressions.
#[derive(clap::Args, Debug, Clone)]
pub struct DialectArgs {
    /// The expression language: `renderman` or `osl`.
    #[arg(long, default_value_t = lpe::DialectName::default())]
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
