//! The AOV list: from `--aov NAME=LPE`, RenderMan `DisplayChannel` lines, or the
//! defaults (the seven basic AOVs, the per-lobe set, per-light-group splits), plus the
//! partitions of beauty the defaults are known to form. A list is in one dialect:
//! RenderMan's, or OSL's (`--dialect osl`, whose defaults are the OSL basic set).

use std::any::Any;
use std::fmt;

use lpe::osl::{self, Osl};
use lpe::renderman::macros::{OTHER, PER_LOBE};
use lpe::renderman::{EventKind, Lpe, Parser, Prefix, RenderMan};
use lpe::DialectName;
use lpe_lint::read::rib::{display_channel, Channel};
use lpe_lint::{AovDecl, Location, RibProblem};

use super::vertex::SceneDialect;
use crate::scene::Scene;

/// Why an AOV list could not be built.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum AovError {
    #[error(
        "AOV name `{name}`: use letters, digits, `_` and `-` (it names an EXR layer and a file)"
    )]
    BadName { name: String },
    #[error("AOV name `{name}` is used twice (`beauty` is reserved)")]
    DuplicateName { name: String },
    #[error("AOV `{name}`: {error}")]
    Parse {
        name: String,
        error: Box<lpe::renderman::Error>,
    },
    #[error("AOV `{name}` (OSL dialect): {error}")]
    OslParse {
        name: String,
        error: Box<super::osl::OslAovError>,
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

/// How an AOV accumulates: its prefixes, decoded (docs/language.md §7; the integrator
/// documents each one where it applies it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AovFlags {
    pub unoccluded: bool,
    pub shadows: bool,
    pub nothruput: bool,
    pub noclamp: bool,
    pub overwrite: bool,
    pub noinfinitecheck: bool,
    pub holdouts: bool,
}

impl AovFlags {
    /// No prefix that changes what a contribution adds (weights, throughput, clamp,
    /// holdouts): such an AOV receives exactly beauty's contribution. `overwrite` and
    /// `noinfinitecheck` act when a sample is committed, not per contribution.
    pub fn values_like_beauty(&self) -> bool {
        !(self.unoccluded || self.shadows || self.nothruput || self.noclamp || self.holdouts)
    }

    pub fn of(lpe: &Lpe) -> AovFlags {
        let p = lpe.prefixes;
        AovFlags {
            unoccluded: p.contains(Prefix::Unoccluded),
            shadows: p.contains(Prefix::Shadows),
            nothruput: p.contains(Prefix::Nothruput),
            noclamp: p.contains(Prefix::Noclamp),
            overwrite: p.contains(Prefix::Overwrite),
            noinfinitecheck: p.contains(Prefix::Noinfinitecheck),
            holdouts: p.contains(Prefix::Holdouts),
        }
    }
}

/// A parsed AOV expression, in the dialect its list reads.
#[derive(Clone, Debug)]
pub enum AovExpr {
    RenderMan(Lpe),
    Osl(osl::Lpe),
}

impl AovExpr {
    pub fn dialect(&self) -> DialectName {
        match self {
            AovExpr::RenderMan(_) => DialectName::RenderMan,
            AovExpr::Osl(_) => DialectName::Osl,
        }
    }

    /// The expression as an `L` (a dialect's `Lpe`), if the AOV is in that dialect.
    pub fn get<L: Any>(&self) -> Option<&L> {
        let any: &dyn Any = match self {
            AovExpr::RenderMan(l) => l,
            AovExpr::Osl(l) => l,
        };
        any.downcast_ref()
    }

    /// Whether the expression can tell vertices apart by their labels (else the
    /// integrator classifies them without).
    pub fn names_labels(&self) -> bool {
        match self {
            AovExpr::RenderMan(l) => l.operands().iter().any(|e| !e.labels().is_empty()),
            AovExpr::Osl(l) => super::osl::names_labels(l),
        }
    }
}

impl fmt::Display for AovExpr {
    /// The canonical form (RenderMan) or the expanded OSL text.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AovExpr::RenderMan(l) => l.fmt(f),
            AovExpr::Osl(l) => l.fmt(f),
        }
    }
}

/// One AOV: its layer name, the source as given, and the parsed expression.
#[derive(Clone, Debug)]
pub struct Aov {
    pub name: String,
    pub source: String,
    pub expr: AovExpr,
    pub flags: AovFlags,
}

/// AOVs whose sum should equal beauty, by construction of the default set.
#[derive(Clone, Debug)]
pub struct Partition {
    pub name: String,
    pub members: Vec<usize>,
    /// Whether the members partition *every* light-transport path, or only this scene's
    /// (the per-lobe set covers just the lobes the scene's materials map into it).
    pub universal: bool,
}

#[derive(Clone, Debug, Default)]
pub struct AovList {
    /// The dialect every AOV of the list is parsed in.
    pub dialect: DialectName,
    pub aovs: Vec<Aov>,
    pub partitions: Vec<Partition>,
    /// Why a default partition was not checked (e.g. lobes outside the per-lobe set).
    pub notes: Vec<String>,
}

impl AovList {
    /// An empty list reading AOVs in `dialect`.
    pub fn new(dialect: DialectName) -> AovList {
        AovList {
            dialect,
            ..AovList::default()
        }
    }

    /// Parses and appends one AOV in the list's dialect (an OSL AOV with the parser's
    /// limits and nothing registered; its warnings join the notes); names must be unique
    /// and usable as EXR layer and file names.
    pub fn push(&mut self, name: &str, source: &str, parser: &Parser) -> Result<usize, AovError> {
        if name.is_empty()
            || !name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
        {
            return Err(AovError::BadName { name: name.into() });
        }
        if name == "beauty" || self.aovs.iter().any(|a| a.name == name) {
            return Err(AovError::DuplicateName { name: name.into() });
        }
        let (flags, expr) = match self.dialect {
            DialectName::RenderMan => {
                let lpe = parser.parse(source).map_err(|error| AovError::Parse {
                    name: name.into(),
                    error: Box::new(error),
                })?;
                (AovFlags::of(&lpe), AovExpr::RenderMan(lpe))
            }
            DialectName::Osl => {
                let lpe = super::osl::parse(source, parser.limits(), parser.macros()).map_err(
                    |error| AovError::OslParse {
                        name: name.into(),
                        error: Box::new(error),
                    },
                )?;
                for w in &lpe.warnings {
                    self.notes.push(format!("AOV `{name}`: warning: {w}"));
                }
                // OSL has no prefixes: every OSL AOV accumulates like a plain one.
                (AovFlags::default(), AovExpr::Osl(lpe))
            }
        };
        self.aovs.push(Aov {
            name: name.to_string(),
            source: source.to_string(),
            expr,
            flags,
        });
        Ok(self.aovs.len() - 1)
    }

    /// `(name, expression)` pairs of the AOVs in dialect `D`, as `lpe::AovSet::compile`
    /// takes them (none in a list of another dialect).
    pub fn named<D: SceneDialect>(&self) -> Vec<(String, D::Lpe)>
    where
        D::Lpe: 'static,
    {
        self.aovs
            .iter()
            .filter_map(|a| Some((a.name.clone(), a.expr.get::<D::Lpe>()?.clone())))
            .collect()
    }

    /// The RenderMan expressions (none in an OSL list).
    pub fn lpes(&self) -> Vec<Lpe> {
        self.named::<RenderMan>()
            .into_iter()
            .map(|(_, l)| l)
            .collect()
    }

    pub fn index(&self, name: &str) -> Option<usize> {
        self.aovs.iter().position(|a| a.name == name)
    }

    /// The basic AOVs of dialect `D` ([`SceneDialect::basic_aovs`]: RenderMan's seven
    /// basic macros, OSL's `lpe::osl::BASIC` under the same names), declared as the
    /// partition of beauty they are.
    pub fn basic<D: SceneDialect>(parser: &Parser) -> Result<AovList, AovError> {
        let dialect = DialectName::of::<D>().expect("the renderer's dialects are lpe's");
        let mut list = AovList::new(dialect);
        let members = D::basic_aovs()
            .iter()
            .map(|(n, src)| list.push(n, src, parser))
            .collect::<Result<_, _>>()?;
        list.partitions.push(Partition {
            name: D::BASIC_PARTITION.into(),
            members,
            universal: true,
        });
        Ok(list)
    }

    /// The AOV list for a render: the defaults, plus for the furnace the per-bounce AOVs
    /// `furnace_bounceK = C<RD>{K}O`.
    pub fn for_render(scene: &Scene, parser: &Parser) -> Result<AovList, AovError> {
        AovList::for_render_in(DialectName::RenderMan, scene, parser)
    }

    /// [`AovList::for_render`] in `dialect`: under OSL the defaults are the OSL basic
    /// set alone (OSL cannot say "a light of no group": a quoted negation needs a label
    /// to be present, so there is no default light-group split), and the furnace's
    /// bounce 0 is `CO` (OSL refuses a `{0}` item after the first).
    pub fn for_render_in(
        dialect: DialectName,
        scene: &Scene,
        parser: &Parser,
    ) -> Result<AovList, AovError> {
        let mut list = match dialect {
            DialectName::RenderMan => AovList::defaults(scene, parser)?,
            DialectName::Osl => AovList::basic::<Osl>(parser)?,
        };
        if crate::scene::furnace::furnace_params(scene).is_some() {
            for k in 0..=crate::scene::furnace::FURNACE_BOUNCES {
                let source = match (dialect, k) {
                    (DialectName::Osl, 0) => "CO".to_string(),
                    _ => format!("C<RD>{{{k}}}O"),
                };
                list.push(&format!("furnace_bounce{k}"), &source, parser)?;
            }
        }
        Ok(list)
    }

    /// The default AOVs for `scene` and the partitions they form.
    pub fn defaults(scene: &Scene, parser: &Parser) -> Result<AovList, AovError> {
        let mut list = AovList::basic::<RenderMan>(parser)?;
        let basic = list.partitions[0].members.clone();

        let glass_t = OTHER.iter().find(|(n, _)| *n == "transmissiveGlassLobe");
        let mut lobes: Vec<usize> = PER_LOBE
            .iter()
            .chain(glass_t)
            .map(|(n, _)| list.push(n, &format!("lpe:{n}"), parser))
            .collect::<Result<_, _>>()?;
        // The per-lobe set splits paths by the event of their first vertex: it covers
        // beauty only if every lobe in the scene maps to D2, D3 or S2..S8.
        let outside: Vec<String> = scene
            .materials
            .iter()
            .flat_map(|m| &m.lobes)
            .filter(|l| {
                let e = l.event;
                !matches!(
                    (e.kind(), e.lobe()),
                    (EventKind::D, 2 | 3) | (EventKind::S, 2..=8)
                )
            })
            .map(|l| format!("{} ({})", l.name, l.event))
            .collect();
        if outside.is_empty() {
            lobes.push(basic[6]); // emissive
            list.partitions.push(Partition {
                name: "per-lobe AOVs + emissive".into(),
                members: lobes,
                universal: false,
            });
        } else {
            list.notes.push(format!(
                "per-lobe partition not checked: lobes outside the per-lobe set: {}",
                outside.join(", ")
            ));
        }

        let groups: Vec<String> = scene
            .light_groups()
            .into_iter()
            .filter(|g| !g.contains('\''))
            .collect();
        if !groups.is_empty() {
            let mut members = Vec::new();
            for g in &groups {
                members.push(list.push(
                    &format!("lightgroup_{}", sanitize(g)),
                    &format!("C.*<L.'{g}'>"),
                    parser,
                )?);
            }
            let quoted: Vec<String> = groups.iter().map(|g| format!("'{g}'")).collect();
            members.push(list.push(
                "lightgroup_default",
                &format!("C.*<L.[^{}]>", quoted.join(" ")),
                parser,
            )?);
            members.push(list.push("lightgroup_emission", "C.*O", parser)?);
            list.partitions.push(Partition {
                name: "light groups + default group + emission".into(),
                members,
                universal: true,
            });
        }
        Ok(list)
    }
}

/// A light group name as a layer-name fragment.
fn sanitize(g: &str) -> String {
    g.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// Splits `NAME=LPE` (the first `=` separates: expressions never contain one).
pub fn split_aov_arg(arg: &str) -> Result<(&str, &str), AovError> {
    arg.split_once('=')
        .map(|(n, s)| (n.trim(), s.trim()))
        .ok_or_else(|| AovError::BadArgument { arg: arg.into() })
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

    #[test]
    fn names_and_expressions_are_checked() {
        let p = Parser::default();
        let mut l = AovList::default();
        l.push("a", "C<RD>L", &p).unwrap();
        assert!(l
            .push("a", "CL", &p)
            .unwrap_err()
            .to_string()
            .contains("twice"));
        assert!(l.push("beauty", "CL", &p).is_err());
        assert!(l
            .push("a.b", "CL", &p)
            .unwrap_err()
            .to_string()
            .contains("letters"));
        assert!(l
            .push("b", "C<L'key'>", &p)
            .unwrap_err()
            .to_string()
            .contains("AOV `b`"));
        assert!(split_aov_arg("noequals").is_err());
        assert_eq!(split_aov_arg("x=C.*L").unwrap(), ("x", "C.*L"));
    }
}
