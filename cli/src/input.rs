//! Reading the subcommands' shared input: `--engine`, `--dialect` or a renderer's
//! profile (`--renderer NAME`, `--profile FILE`) with `--ini` or `--register` (read by
//! each dialect's [`CliDialect`]); the errors they report are [`InputError`]'s.

use std::path::PathBuf;

use lpe_engines::{Engine, EngineDialect};
use lpe_profile::Profile;

use crate::dialect::CliDialect;
pub use crate::error::InputError;

/// `--dialect`, `--renderer`/`--profile` and OSL's `--register`, shared by the
/// subcommands that read expressions.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct DialectArgs {
    /// The expression language: `renderman` (the default) or `osl`; a renderer's profile
    /// names its own.
    #[arg(long)]
    pub dialect: Option<lpe::DialectName>,
    /// OSL only: user labels registered before parsing, `events=U;scatters=Y`.
    #[arg(long)]
    pub register: Option<String>,
    /// Read expressions as this renderer does (docs/profiles.md): `renderman`, `osl`,
    /// `karma`, `arnold`, `hdprman`, `vray`, `moonray`.
    #[arg(long, value_name = "NAME", conflicts_with = "profile")]
    pub renderer: Option<String>,
    /// Read expressions as the renderer described in this profile file does.
    #[arg(long, value_name = "FILE")]
    pub profile: Option<PathBuf>,
}

impl DialectArgs {
    /// The renderer's profile `--renderer` or `--profile` names, if any.
    pub fn renderer_profile(&self) -> Result<Option<Profile>, InputError> {
        let profile = match (&self.renderer, &self.profile) {
            (Some(name), _) => lpe_profile::by_name(name).cloned(),
            (None, Some(file)) => Profile::from_file(file),
            (None, None) => return Ok(None),
        };
        profile.map(Some).map_err(InputError::Profile)
    }

    /// The dialect expressions are read in: the profile's base, else `--dialect`, else
    /// RenderMan's. A profile that does not load leaves `--dialect`'s (the error is
    /// reported by [`DialectArgs::registration`], which every subcommand asks).
    pub fn dialect(&self) -> lpe::DialectName {
        match self.renderer_profile() {
            Ok(Some(p)) => p.dialect(),
            _ => self.dialect.unwrap_or_default(),
        }
    }

    /// The registration of dialect `D` from `--ini` and `--register`
    /// ([`CliDialect::registration`]), with the profile's letters, prefixes and built-in
    /// names on top; a `--dialect` other than the profile's base is an error.
    pub fn registration<D: CliDialect>(
        &self,
        ini: Option<&std::path::Path>,
    ) -> Result<D::Registration, InputError> {
        self.registration_under::<D>(ini, self.renderer_profile()?.as_ref())
    }

    /// [`DialectArgs::registration`] under `profile` (the one the arguments name, or one
    /// a stage names).
    pub fn registration_under<D: CliDialect>(
        &self,
        ini: Option<&std::path::Path>,
        profile: Option<&Profile>,
    ) -> Result<D::Registration, InputError> {
        let base = D::registration(ini, self.register.as_deref())?;
        let Some(profile) = profile else {
            return Ok(base);
        };
        if let Some(given) = self.dialect.filter(|d| *d != profile.dialect()) {
            return Err(InputError::DialectOfProfile {
                given,
                renderer: profile.name.clone(),
                base: profile.dialect(),
            });
        }
        Ok(D::with_profile(profile, base))
    }

    /// The arguments that select the profile again, as a replay command writes them.
    pub fn profile_args(&self) -> Vec<String> {
        match (&self.renderer, &self.profile) {
            (Some(name), _) => vec!["--renderer".into(), name.clone()],
            (None, Some(file)) => vec!["--profile".into(), file.display().to_string()],
            (None, None) => Vec::new(),
        }
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
