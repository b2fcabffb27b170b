//! The OSL dialect in the renderer (`--dialect osl`). Its vertices (docs/language.md
//! §18.12):
//!
//! | renderer vertex | OSL vertex |
//! |---|---|
//! | camera | `C,~` |
//! | scattering off a lobe, reflected / transmitted | `R` / `T`, then `D` (Lambert, diffuse transmission), `G` (GGX) or `S` (dielectric: a delta lobe), then the object's `lpegroup` |
//! | light reached by a bounce or a light sample | `L,~`, then the light's group |
//! | area light seen straight from the camera, glowing object | `O,~`, then the light's group / the object's `lpegroup` |
//!
//! A vertex carries at most one custom label: light objects have no `lpegroup`, and no
//! other vertex has a light group. Emitters and the camera scatter NONE (`~`).
//!
//! AOVs are parsed by `lpe::osl` under the registration (nothing registered unless a
//! caller registers labels), then checked for RenderMan notions that OSL would read as
//! something else. A clear error beats a silent difference:
//!
//! - prefixes (`shadows;`) and RenderMan macros (`directDiffuse`): OSL has neither (and
//!   would fail on their first letter with a less helpful message);
//! - an unquoted digit or `U` inside `<…>`: RenderMan's lobe numbers and user lobes. OSL
//!   reads each as a label of its own (`<RD2>` wants the custom label `2`, `<RU>` the
//!   scattering `U`), which no vertex of `lpe-render` carries: the AOV would stay black.
//!   Quoted (`<RD'2'>`) the label is meant and accepted.
//!
//! A leading `lpe:` is what marks a display channel's or RenderVar's source as an LPE,
//! not part of the expression: it is skipped, and positions still count from the start
//! of the source as written.

use lpe::osl::{self, Osl, Registered, Symbol};
use lpe::renderman::macros::MacroTable;
use lpe::renderman::{Limits, LobeMap, Prefix, VertexType};

use super::declare::Declared;
use super::dialect::{IniRefusal, ParsedAov, SceneDialect};
use super::flags::AovFlags;
use super::vertex::SceneVertex;
use crate::material::Scattering;
use crate::scene::Scene;

impl SceneDialect for Osl {
    const BASIC_PARTITION: &'static str = "OSL basic AOVs";
    const MESSAGE_TAG: &'static str = " (OSL dialect)";
    /// OSL has no pseudo paths (docs/language.md §18.12).
    const USER_LOBES: bool = false;
    const NATIVE: bool = false;
    const EMITTER: &'static str = "[LO]";
    const BENCH_EXTRA: &'static [(&'static str, &'static str)] = &[
        ("glossy", "C<.G>.*[LO]"),
        ("delta", "C<.S>.*[LO]"),
        ("directGlossy", "C<RG>[LO]"),
        ("indirectGlossy", "C<RG>.+[LO]"),
        ("directDelta", "C<RS>[LO]"),
        ("indirectDelta", "C<RS>.+[LO]"),
        ("glossyTransmission", "C<TG>.*[LO]"),
        ("deltaTransmission", "C<TS>.*[LO]"),
        ("caustics", "C<.D>.*<.[GS]>.*[LO]"),
        ("key", "C.*<L.'key'>"),
        ("fill", "C.*<L.'fill'>"),
        ("rim", "C.*<L.'rim'>"),
        ("lights", "C.*L"),
        ("objects", "C.*O"),
        ("floor", "C<.D'floor'>.*[LO]"),
        ("glass", "C<.S'glass'>.*[LO]"),
        ("directKey", "C<RD><L.'key'>"),
        ("indirectKey", "C<RD>.+<L.'key'>"),
        ("twoBounce", "C.{2}[LO]"),
        ("threeBounce", "C.{3}[LO]"),
        ("diffuseOnly", "C<RD>+[LO]"),
        ("specThenDiffuse", "C<R[GS]>.*<RD>.*[LO]"),
        ("diffuseThenGlossy", "C<RD>.*<RG>.*[LO]"),
        ("noDelta", "C[^S]*[LO]"),
        ("fourBouncesOrMore", "C.{4,}[LO]"),
    ];

    /// See the module docs for the mapping.
    fn scene_vertex(v: &SceneVertex) -> osl::Vertex {
        let (event, scattering, group) = match *v {
            SceneVertex::Camera => ("C", None, None),
            SceneVertex::Scatter {
                side,
                scattering,
                group,
                ..
            } => {
                let event = if side == VertexType::T { "T" } else { "R" };
                (event, Some(scattering_label(scattering)), group)
            }
            SceneVertex::Light { group } => ("L", None, group),
            SceneVertex::Emissive { group } => ("O", None, group),
        };
        let mut symbols = vec![
            Symbol::label(event),
            scattering.map_or(Symbol::None, Symbol::label),
        ];
        symbols.extend(group.map(Symbol::label));
        osl::Vertex::new(symbols)
    }

    /// `lpe::osl::BASIC`, under RenderMan's basic names.
    fn basic_aovs() -> Vec<(&'static str, String)> {
        osl::BASIC
            .iter()
            .map(|(n, s)| (*n, s.to_string()))
            .collect()
    }

    /// The basic set alone: OSL cannot say "a light of no group" (a quoted negation
    /// needs a label to be present), so there is no default light-group split.
    fn defaults(_: &Scene) -> Declared {
        Self::basic()
    }

    /// Bounce 0 is `CO`: OSL refuses a `{0}` item after the first.
    fn furnace_bounce(k: u32) -> String {
        match k {
            0 => "CO".to_string(),
            _ => format!("C<RD>{{{k}}}O"),
        }
    }

    /// OSL has no prefixes: every OSL AOV accumulates like a plain one.
    fn parse_aov(source: &str, registered: &Registered) -> Result<ParsedAov<osl::Lpe>, String> {
        let lpe = parse(source, registered).map_err(|e| e.to_string())?;
        Ok(ParsedAov {
            warnings: lpe
                .warnings
                .iter()
                .map(|w| format!("warning: {w}"))
                .collect(),
            lpe,
            flags: AovFlags::default(),
        })
    }

    fn names_labels(lpe: &osl::Lpe) -> bool {
        names_labels(lpe)
    }

    /// A scene label is a custom label, which OSL's eater skips only if it is not a
    /// built-in label: a light group `S` would stop `L` from matching its lights.
    fn refused_label(label: &str) -> Option<&'static str> {
        is_builtin_label(label).then_some(
            "is a built-in OSL label: under --dialect osl scene labels are custom labels, \
             and OSL's eater would not skip this one (so `L` or `R` would miss its \
             vertices); rename it",
        )
    }

    fn from_ini(_: &str) -> Result<(Registered, LobeMap), IniRefusal> {
        Err(IniRefusal::NotTaken(
            "--ini holds RenderMan macros and lobe mappings; it does not apply to --dialect \
             osl (OSL vertices scatter D, G or S by the lobe's model, whatever its lobe \
             number)",
        ))
    }

    fn whole_path(vertices: Vec<osl::Vertex>) -> Option<osl::Path> {
        Some(osl::Path::new(vertices))
    }
}

/// OSL's scattering label of a lobe.
fn scattering_label(s: Scattering) -> &'static str {
    match s {
        Scattering::Diffuse => "D",
        Scattering::Glossy => "G",
        Scattering::Delta => "S",
    }
}

/// Why an OSL AOV was refused. Positions are byte offsets, printed as OSL prints its own
/// (`at char N`).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum OslAovError {
    /// OSL's own parse error.
    #[error("{0}")]
    Parse(osl::Error),
    #[error(
        "`{prefix}` at char {pos} is a RenderMan prefix: the OSL dialect has none (an OSL \
         AOV accumulates like a RenderMan one without prefixes); drop it, or use \
         --dialect renderman"
    )]
    Prefix { prefix: String, pos: usize },
    #[error(
        "`{name}` is a RenderMan macro: the OSL dialect has none{}",
        hint.as_ref().map_or(String::new(), |h| format!(" (in OSL: `{h}`)"))
    )]
    Macro { name: String, hint: Option<String> },
    #[error(
        "unquoted `{c}` at char {pos} inside <...> is a RenderMan lobe number: OSL has none \
         and would read it as the custom label '{c}', which no vertex carries; write \
         '{c}' (quoted) if you mean that label"
    )]
    LobeNumber { c: char, pos: usize },
    #[error(
        "unquoted `U` at char {pos} inside <...> is a RenderMan user lobe: OSL has none \
         and lpe-render's OSL vertices scatter only D, G or S; write 'U' (quoted) if you \
         mean a label"
    )]
    UserLobe { pos: usize },
}

/// Parses an OSL AOV for the renderer under `registered`, with the default limits.
pub fn parse(source: &str, registered: &Registered) -> Result<osl::Lpe, OslAovError> {
    let Some(expr) = source.strip_prefix(osl::SOURCE_MARK) else {
        return parse_expr(source, registered);
    };
    let shift = osl::SOURCE_MARK.len();
    let mut lpe = parse_expr(expr, registered).map_err(|e| e.shifted(shift))?;
    lpe.shift_warnings(shift);
    Ok(lpe)
}

impl OslAovError {
    /// The error with its position moved `by` bytes on.
    fn shifted(self, by: usize) -> OslAovError {
        match self {
            OslAovError::Parse(e) => OslAovError::Parse(osl::Error {
                pos: e.pos + by,
                ..e
            }),
            OslAovError::Prefix { prefix, pos } => OslAovError::Prefix {
                prefix,
                pos: pos + by,
            },
            OslAovError::LobeNumber { c, pos } => OslAovError::LobeNumber { c, pos: pos + by },
            OslAovError::UserLobe { pos } => OslAovError::UserLobe { pos: pos + by },
            e @ OslAovError::Macro { .. } => e,
        }
    }
}

fn parse_expr(source: &str, registered: &Registered) -> Result<osl::Lpe, OslAovError> {
    check_prefix(source)?;
    let lpe =
        osl::parse_with(source, registered, &Limits::default()).map_err(|e| {
            match macro_name(source, &MacroTable::builtin()) {
                Some(name) => OslAovError::Macro {
                    hint: osl::BASIC
                        .iter()
                        .find(|(n, _)| *n == name)
                        .map(|(_, s)| s.to_string()),
                    name: name.to_string(),
                },
                None => OslAovError::Parse(e),
            }
        })?;
    check_renderman_lobes(source)?;
    Ok(lpe)
}

/// A RenderMan prefix (`name;`, any case) at the start, after whitespace.
fn check_prefix(source: &str) -> Result<(), OslAovError> {
    let pos = source.len() - source.trim_start().len();
    let rest = &source[pos..];
    let word_len = rest
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(rest.len());
    let (word, after) = rest.split_at(word_len);
    match after.starts_with(';') && Prefix::from_name(word).is_some() {
        true => Err(OslAovError::Prefix {
            prefix: format!("{word};"),
            pos,
        }),
        false => Ok(()),
    }
}

/// The RenderMan macro (with or without a light-group suffix) the whole source names.
fn macro_name<'a>(source: &'a str, macros: &MacroTable) -> Option<&'a str> {
    let name = source.trim();
    let known = |n: &str| macros.get(n).is_some();
    if known(name) {
        return Some(name);
    }
    name.rsplit_once('_')
        .map(|(base, _)| base)
        .filter(|base| known(base))
}

/// An unquoted ASCII digit or `U` inside `<…>` (the source already parsed as OSL, so
/// quotes and brackets are balanced; a quote inside `<…>` or `[^…]` runs to the next one,
/// OSL having no escapes).
fn check_renderman_lobes(source: &str) -> Result<(), OslAovError> {
    let mut quoted = false;
    let mut in_group = false;
    for (pos, c) in source.char_indices() {
        match c {
            '\'' => quoted = !quoted,
            _ if quoted => {}
            '<' => in_group = true,
            '>' => in_group = false,
            _ if !in_group => {}
            'U' => return Err(OslAovError::UserLobe { pos }),
            c if c.is_ascii_digit() => return Err(OslAovError::LobeNumber { c, pos }),
            _ => {}
        }
    }
    Ok(())
}

/// Whether an expression can tell a labelled vertex from an unlabelled one. `lpe-render`
/// puts labels only in custom slots, and never a built-in label (the integrator refuses
/// such group names), so a pattern with no custom slot and OSL's eater accepts a vertex
/// exactly when it accepts it without its label. Every operand of set algebra counts.
fn names_labels(lpe: &osl::Lpe) -> bool {
    let mut any = false;
    for e in lpe.operands() {
        e.for_each_vertex(&mut |v| {
            any |= v.symbols.len() > 2 || v.eater.is_none();
        });
    }
    any
}

/// The built-in OSL label a scene label must not be: it would stop OSL's eater, so `L`
/// would no longer match a light of that group, nor `R` an object of it.
fn is_builtin_label(label: &str) -> bool {
    Registered::none().kind_of(label).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_default(src: &str) -> Result<osl::Lpe, OslAovError> {
        parse(src, &Registered::none())
    }

    #[test]
    fn renderman_prefixes_are_refused_at_their_position() {
        for (src, prefix, pos) in [
            ("shadows;C<RD>L", "shadows;", 0),
            ("  Unoccluded;C<RD>L", "Unoccluded;", 2),
            ("lpe:holdouts;C<RD>L", "holdouts;", 4),
        ] {
            assert_eq!(
                parse_default(src).unwrap_err(),
                OslAovError::Prefix {
                    prefix: prefix.into(),
                    pos
                },
                "{src}"
            );
        }
        // `lpe:` marks a source as an LPE; errors count from the source as written.
        assert!(parse_default("lpe:C<RD>L").is_ok());
        assert_eq!(
            parse_default("lpe:C<RD2>L").unwrap_err(),
            OslAovError::LobeNumber { c: '2', pos: 8 }
        );
        match parse_default("lpe:CE").unwrap_err() {
            OslAovError::Parse(e) => assert_eq!(e.pos, 5),
            e => panic!("{e:?}"),
        }
        // Warnings too: the reversed range's `{` is byte 6 of the source, 2 of the LPE.
        for (src, pos) in [("lpe:C.{3,1}L", 6), ("C.{3,1}L", 2)] {
            let w = parse_default(src).unwrap().warnings;
            assert_eq!(w.iter().map(|w| w.pos).collect::<Vec<_>>(), [pos], "{src}");
        }
        // Not a prefix: OSL's own error.
        assert!(matches!(
            parse_default("shadow;C<RD>L").unwrap_err(),
            OslAovError::Parse(_)
        ));
    }

    #[test]
    fn renderman_macros_are_named_with_the_osl_spelling() {
        let e = parse_default("directDiffuse").unwrap_err();
        assert_eq!(
            e.to_string(),
            "`directDiffuse` is a RenderMan macro: the OSL dialect has none \
             (in OSL: `C<RD>[LO]`)"
        );
        let e = parse_default("caustics_key").unwrap_err();
        assert_eq!(
            e,
            OslAovError::Macro {
                name: "caustics".into(),
                hint: None
            }
        );
    }

    #[test]
    fn lobe_numbers_and_user_lobes_are_refused_unless_quoted() {
        assert_eq!(
            parse_default("C<RD2>L").unwrap_err(),
            OslAovError::LobeNumber { c: '2', pos: 4 }
        );
        assert_eq!(
            parse_default("C<R[D1]>L").unwrap_err(),
            OslAovError::LobeNumber { c: '1', pos: 5 }
        );
        assert_eq!(
            parse_default("C<RU>L").unwrap_err(),
            OslAovError::UserLobe { pos: 3 }
        );
        // Quoted, the label is meant; outside <...> digits and `U` are OSL's errors.
        assert!(parse_default("C<RD'2'>L").is_ok());
        assert!(parse_default("C<RD'U'>'U2'L").is_ok());
        assert!(matches!(
            parse_default("CU L").unwrap_err(),
            OslAovError::Parse(_)
        ));
    }

    #[test]
    fn labels_matter_only_with_custom_slots() {
        let p = |s: &str| names_labels(&parse_default(s).unwrap());
        assert!(!p("C<RD>.*[LO]"));
        assert!(!p("C[^S]*L"));
        assert!(p("C.*<L.'key'>"));
        assert!(p("C'floor'L"));
        assert!(p("C<R...[^'floor']>L"));
    }

    #[test]
    fn builtin_labels_are_known() {
        for l in ["C", "R", "T", "L", "O", "B", "V", "D", "G", "S", "s"] {
            assert!(is_builtin_label(l), "{l}");
        }
        for l in ["key", "floor", "x", "U", "E"] {
            assert!(!is_builtin_label(l), "{l}");
        }
    }

    #[test]
    fn a_label_in_any_operand_of_set_algebra_counts() {
        let l = |src: &str| parse_default(src).unwrap();
        assert!(!names_labels(&l("C.*[LO] - C<RD>.*[LO]")));
        assert!(names_labels(&l("C.*[LO] - C.*<L.'key'>")));
    }

    /// Hand-written OSL path text of each kind of vertex (§18.1's notation), as the
    /// module's table gives it.
    #[test]
    fn every_kind_of_scene_vertex_is_shown_as_the_mapping_table_says() {
        let scatter = |side, scattering, group| SceneVertex::Scatter {
            side,
            // The lobe number is RenderMan's: OSL shows the scattering, never the event.
            event: lpe::renderman::Event::new(lpe::renderman::EventKind::S, 4).unwrap(),
            scattering,
            group,
        };
        let cases = [
            (SceneVertex::Camera, "C,~"),
            (
                scatter(VertexType::R, Scattering::Diffuse, Some("floor")),
                "R,D,floor",
            ),
            (scatter(VertexType::R, Scattering::Glossy, None), "R,G"),
            (
                scatter(VertexType::T, Scattering::Delta, Some("glass")),
                "T,S,glass",
            ),
            (scatter(VertexType::R, Scattering::Delta, None), "R,S"),
            (SceneVertex::Light { group: Some("key") }, "L,~,key"),
            (SceneVertex::Light { group: None }, "L,~"),
            (
                SceneVertex::Emissive {
                    group: Some("ember"),
                },
                "O,~,ember",
            ),
            (SceneVertex::Emissive { group: None }, "O,~"),
        ];
        for (v, want) in cases {
            assert_eq!(Osl::scene_vertex(&v).to_string(), want, "{v:?}");
        }
    }

    #[test]
    fn a_builtin_label_is_refused_in_a_scene_and_an_ini_always() {
        assert!(Osl::refused_label("S").is_some());
        assert!(Osl::refused_label("key").is_none());
        assert!(matches!(Osl::from_ini(""), Err(IniRefusal::NotTaken(_))));
    }
}
