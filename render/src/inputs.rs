//! What a render reads before it starts: the scene, the `rendermn.ini` (in a dialect that
//! takes one) and the AOVs, from a RenderMan display file's `DisplayChannel` lines, a USD
//! stage's RenderVars and `NAME=LPE` arguments, or else the dialect's defaults for the
//! scene. [`gather`] does it for the command line, in dialect `D`.

use std::path::{Path, PathBuf};

use lpe::renderman::LobeMap;
use lpe::Dialect;
use lpe_lint::read::rib::{display_channel, Channel};
use lpe_lint::{AovDecl, Location};

use crate::aov::{split_aov_arg, AovError, AovList, IniRefusal, SceneDialect};
use crate::integrator::USER_SIGNALS;
use crate::scene::{Scene, SceneError};

/// Why a render's inputs could not be read.
#[derive(Debug, thiserror::Error)]
pub enum SourceError {
    #[error("{}: {source}", path.display())]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{}:{source}", path.display())]
    Ini {
        path: PathBuf,
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// The dialect takes no `rendermn.ini`: why.
    #[error("{0}")]
    IniNotTaken(&'static str),
    #[error("{}:{at}: {source}", path.display())]
    DisplayAov {
        path: PathBuf,
        at: Box<Location>,
        source: AovError,
    },
    #[error(transparent)]
    Usd(#[from] lpe_lint::ReadError),
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error(transparent)]
    Aov(#[from] AovError),
}

/// Where a render's inputs come from, as the command line names them.
#[derive(Clone, Copy, Debug, Default)]
pub struct Sources<'a> {
    /// A built-in scene's name or a TOML scene file.
    pub scene: &'a str,
    /// A `rendermn.ini` with macros and lobe mappings.
    pub ini: Option<&'a Path>,
    /// RenderMan `DisplayChannel` lines.
    pub display: Option<&'a Path>,
    /// A USD stage whose LPE RenderVars are AOVs.
    pub usd: Option<&'a Path>,
    /// `NAME=LPE` arguments.
    pub aovs: &'a [String],
    /// The renderer whose letters, prefixes and built-in names every AOV reads with
    /// (`--renderer`), on top of the ini's registration.
    pub profile: Option<&'a lpe_profile::Profile>,
}

/// A render's inputs in dialect `D`.
#[derive(Debug)]
pub struct Inputs<D: Dialect> {
    pub scene: Scene,
    /// The lobe map the scene's lobes took their events from.
    pub lobes: LobeMap,
    pub aovs: AovList<D>,
    /// What was skipped while reading (channels that are no LPE, RenderVars left out).
    pub warnings: Vec<String>,
}

/// Reads the inputs `sources` name: the ini first (it changes how the scene's lobes and
/// the AOVs read), then the scene, then the AOVs of the display file, the USD stage and
/// the arguments, in that order, or, if none is named, the dialect's defaults for the
/// scene.
pub fn gather<D: SceneDialect>(sources: &Sources) -> Result<Inputs<D>, SourceError> {
    let (registration, lobes) = match sources.ini {
        None => (D::Registration::default(), LobeMap::default()),
        Some(path) => D::from_ini(&read(path)?).map_err(|refusal| match refusal {
            IniRefusal::Unreadable(source) => SourceError::Ini {
                path: path.to_path_buf(),
                source,
            },
            IniRefusal::NotTaken(why) => SourceError::IniNotTaken(why),
        })?,
    };
    let registration = match sources.profile {
        Some(p) => D::with_profile(p, registration),
        None => registration,
    };
    let scene = Scene::load(sources.scene, &lobes)?;

    let mut aovs = AovList::new();
    let mut warnings = Vec::new();
    let mut push_channels = |aovs: &mut AovList<D>, read: DisplayChannels, path: &Path| {
        warnings.extend(read.warnings);
        read.channels.iter().try_for_each(|c| {
            aovs.push(&c.name, &c.source, &registration)
                .map(drop)
                .map_err(|source| SourceError::DisplayAov {
                    path: path.to_path_buf(),
                    at: Box::new(c.location.clone()),
                    source,
                })
        })
    };
    if let Some(path) = sources.display {
        let read = parse_display_channels(&read(path)?, &path.display().to_string())?;
        push_channels(&mut aovs, read, path)?;
    }
    if let Some(path) = sources.usd {
        let stage = lpe_lint::read::read_usd(path, &lpe_lint::read::Limits::default())?;
        let mut read = usd_render_vars(&stage);
        for w in &mut read.warnings {
            *w = format!("{}: {w}", path.display());
        }
        push_channels(&mut aovs, read, path)?;
    }
    for arg in sources.aovs {
        let (name, source) = split_aov_arg(arg)?;
        aovs.push(name, source, &registration)?;
    }
    if sources.display.is_none() && sources.usd.is_none() && sources.aovs.is_empty() {
        aovs = AovList::for_render(&scene, &registration)?;
    }
    for (lobe, names) in lobes.user_collisions(&USER_SIGNALS) {
        aovs.notes.push(format!(
            "user signals {} share lobe {lobe}: they overwrite each other",
            names.join(", ")
        ));
    }
    Ok(Inputs {
        scene,
        lobes,
        aovs,
        warnings,
    })
}

fn read(path: &Path) -> Result<String, SourceError> {
    std::fs::read_to_string(path).map_err(|source| SourceError::Read {
        path: path.to_path_buf(),
        source,
    })
}

/// AOVs read from `DisplayChannel` lines.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DisplayChannels {
    /// Each LPE channel (name, source, where it is), in file order.
    pub channels: Vec<AovDecl>,
    /// Channels skipped because their source is not an LPE, with file and line.
    pub warnings: Vec<String>,
}

/// Reads RenderMan `DisplayChannel` lines:
/// `DisplayChannel "color NAME" "string source" ["color lpe:EXPR"]`.
pub fn parse_display_channels(text: &str, file: &str) -> Result<DisplayChannels, AovError> {
    let mut out = Vec::new();
    let mut warnings = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let at = |m: String| format!("{file}:{}: {m}", n + 1);
        let channel = display_channel(line).map_err(|problem| AovError::DisplayChannel {
            file: file.into(),
            line: n + 1,
            problem,
        })?;
        match channel {
            None => {}
            Some(Channel::Lpe {
                name,
                source,
                column,
            }) => out.push(AovDecl {
                name,
                source,
                location: Location::Line { line: n + 1, column },
                source_type: None,
            }),
            Some(Channel::NoSource { name }) => warnings.push(at(format!(
                "channel `{name}` has no \"string source\": skipped"
            ))),
            Some(Channel::Other { name, source }) => warnings.push(at(format!(
                "channel `{name}` has source `{source}`, not an LPE: skipped (beauty is always written)"
            ))),
        }
    }
    Ok(DisplayChannels {
        channels: out,
        warnings,
    })
}

/// The AOVs of a USD stage: its LPE RenderVars, in the order of the first
/// RenderProduct's `orderedVars` when it has them (vars it leaves out are skipped, names
/// that are no LPE RenderVar are warned about: beauty is always written), else in stage
/// order.
pub fn usd_render_vars(stage: &lpe_lint::Document) -> DisplayChannels {
    let lpe_var = |name: &str| stage.aovs.iter().find(|a| a.name == name);
    let mut out = DisplayChannels::default();
    match &stage.ordered_vars {
        Some(order) => {
            for name in order {
                match lpe_var(name) {
                    Some(a) => out.channels.push(a.clone()),
                    None => out.warnings.push(format!(
                        "orderedVars names `{name}`, not an LPE RenderVar: skipped"
                    )),
                }
            }
            for a in &stage.aovs {
                if !order.contains(&a.name) {
                    out.warnings.push(format!(
                        "RenderVar `{}` is not in the product's orderedVars: skipped",
                        a.name
                    ));
                }
            }
        }
        None => {
            out.channels = stage.aovs.clone();
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_channels_are_read() {
        let text = r#"
# a comment
DisplayChannel "color directDiffuse" "string source" ["color lpe:C<RD>[<L.>O]"]
DisplayChannel "varying color key" "string source" "color lpe:C.*<L.'key'>"
DisplayChannel "color Ci"
DisplayChannel "color beauty2" "string source" ["color Ci"]
"#;
        let DisplayChannels {
            channels: ch,
            warnings: warn,
        } = parse_display_channels(text, "d.rib").unwrap();
        let read: Vec<(&str, &str, String)> = ch
            .iter()
            .map(|c| (c.name.as_str(), c.source.as_str(), c.location.to_string()))
            .collect();
        assert_eq!(
            read,
            vec![
                ("directDiffuse", "lpe:C<RD>[<L.>O]", "3:62".to_string()),
                ("key", "lpe:C.*<L.'key'>", "4:59".to_string()),
            ]
        );
        assert_eq!(warn.len(), 2);
        assert!(warn[0].starts_with("d.rib:5:"), "{warn:?}");
        let e = parse_display_channels("DisplayChannel \"color x", "d.rib").unwrap_err();
        assert!(e.to_string().starts_with("d.rib:1:"), "{e}");
    }
}
