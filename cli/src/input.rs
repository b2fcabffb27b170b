//! Reading the subcommands' shared input: `--engine`, `--ini`, expressions.

use std::path::PathBuf;

use lpe_engines::{Engine, EngineDialect};

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
    /// Whether the OSL dialect is asked for; with RenderMan, `--register` is an error.
    pub fn is_osl(&self) -> Result<bool, InputError> {
        match (self.dialect, &self.register) {
            (lpe::DialectName::Osl, _) => Ok(true),
            (_, Some(_)) => Err(InputError::RegisterWithoutOsl),
            (_, None) => Ok(false),
        }
    }

    /// The OSL registration (`-` when not given); `--ini` is an error with OSL.
    pub fn registered(
        &self,
        ini: Option<&std::path::Path>,
    ) -> Result<lpe::osl::Registered, InputError> {
        if ini.is_some() {
            return Err(InputError::IniWithOsl);
        }
        self.register
            .as_deref()
            .unwrap_or("-")
            .parse()
            .map_err(InputError::Register)
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

/// The parser for the built-in macros, or for those plus an ini file's.
pub fn load_parser(ini: Option<&std::path::Path>) -> Result<lpe::renderman::Parser, InputError> {
    let Some(path) = ini else {
        return Ok(lpe::renderman::Parser::default());
    };
    let text = std::fs::read_to_string(path).map_err(|error| InputError::ReadIni {
        path: path.to_path_buf(),
        error,
    })?;
    lpe::renderman::Config::from_ini(&text)
        .map(|c| c.parser())
        .map_err(|error| InputError::Ini {
            path: path.to_path_buf(),
            error,
        })
}

/// An OSL parse error with the expression and a caret under the byte it points at.
pub fn osl_error(src: &str, e: &lpe::osl::Error) -> String {
    let col = src.get(..e.pos).map_or(e.pos, |s| s.chars().count());
    format!("error: {e}\n  {src}\n  {}^", " ".repeat(col))
}
