//! The RenderMan dialect in the renderer: a vertex is its type, the event the lobe map
//! gives its lobe (with the lobe number) and one label; AOVs carry prefixes and may name
//! macros, including those of a `rendermn.ini`; the defaults add the per-lobe set and a
//! split per light group to the basic AOVs.

use lpe::renderman::macros::{BASIC, OTHER, PER_LOBE};
use lpe::renderman::{Config, EventKind, LobeMap, Lpe, Parser, Path, Prefix, RenderMan, Vertex};

use super::declare::Declared;
use super::dialect::{IniRefusal, ParsedAov, SceneDialect};
use super::flags::AovFlags;
use super::vertex::SceneVertex;
use crate::scene::Scene;

impl SceneDialect for RenderMan {
    const BASIC_PARTITION: &'static str = "basic AOVs";
    const MESSAGE_TAG: &'static str = "";
    const USER_LOBES: bool = true;
    const NATIVE: bool = true;
    const EMITTER: &'static str = "[<L.>O]";
    const BENCH_EXTRA: &'static [(&'static str, &'static str)] = &[
        ("caustics", "lpe:caustics"),
        ("diffuseLegacy", "lpe:diffuse"),
        ("specularLegacy", "lpe:specular"),
        ("emissionLegacy", "lpe:emission"),
        ("twoBounce", "C.{2}[<L.>O]"),
        ("threeBounce", "C.{3}[<L.>O]"),
        ("diffuseOnly", "C<RD>+[<L.>O]"),
        ("specThenDiffuse", "C<RS>.*<RD>.*[<L.>O]"),
    ];

    /// Type, the event the lobe map gives the lobe (with its number), one label.
    fn scene_vertex(v: &SceneVertex) -> Vertex {
        match *v {
            SceneVertex::Camera => Vertex::camera(),
            SceneVertex::Scatter {
                side, event, group, ..
            } => Vertex::scatter(side, event, group),
            SceneVertex::Light { group } => Vertex::light(group),
            SceneVertex::Emissive { group } => Vertex::emissive(group),
        }
    }

    /// The basic macros, by name.
    fn basic_aovs() -> Vec<(&'static str, String)> {
        BASIC
            .iter()
            .map(|(n, _)| (*n, format!("lpe:{n}")))
            .collect()
    }

    /// The basic AOVs, the per-lobe set (a partition of this scene's beauty when every
    /// lobe maps into it) and, when the scene has light groups, one AOV per group plus
    /// the lights of no group and emission (a partition of every path).
    fn defaults(scene: &Scene) -> Declared {
        let mut d = Self::basic();
        let emissive = d.partitions[0].members[6];

        let glass_t = OTHER.iter().find(|(n, _)| *n == "transmissiveGlassLobe");
        let per_lobe = PER_LOBE
            .iter()
            .chain(glass_t)
            .map(|(n, _)| (n.to_string(), format!("lpe:{n}")));
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
            d.push_partition("per-lobe AOVs + emissive", per_lobe, false);
            let p = d.partitions.last_mut().expect("just pushed");
            p.members.push(emissive);
        } else {
            for (n, s) in per_lobe {
                d.push(n, s);
            }
            d.notes.push(format!(
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
            let quoted: Vec<String> = groups.iter().map(|g| format!("'{g}'")).collect();
            let split = groups
                .iter()
                .map(|g| {
                    (
                        format!("lightgroup_{}", sanitize(g)),
                        format!("C.*<L.'{g}'>"),
                    )
                })
                .chain([
                    (
                        "lightgroup_default".to_string(),
                        format!("C.*<L.[^{}]>", quoted.join(" ")),
                    ),
                    ("lightgroup_emission".to_string(), "C.*O".to_string()),
                ]);
            d.push_partition("light groups + default group + emission", split, true);
        }
        d
    }

    fn furnace_bounce(k: u32) -> String {
        format!("C<RD>{{{k}}}O")
    }

    fn parse_aov(source: &str, parser: &Parser) -> Result<ParsedAov<Lpe>, String> {
        let lpe = parser.parse(source).map_err(|e| e.to_string())?;
        Ok(ParsedAov {
            flags: flags(&lpe),
            lpe,
            warnings: Vec::new(),
        })
    }

    fn names_labels(lpe: &Lpe) -> bool {
        lpe.operands().iter().any(|e| !e.labels().is_empty())
    }

    /// Its macros and limits make the parser; its lobe mappings the lobe map.
    fn from_ini(text: &str) -> Result<(Parser, LobeMap), IniRefusal> {
        let config = Config::from_ini(text).map_err(|e| IniRefusal::Unreadable(Box::new(e)))?;
        Ok((Parser::new(config.limits, config.macros), config.lobes))
    }

    /// A RenderMan path is a camera, scattering vertices and one emitter: anything else
    /// (a path stopped before an emitter) is none.
    fn whole_path(vertices: Vec<Vertex>) -> Option<Path> {
        Path::new(vertices).ok()
    }
}

/// The accumulation flags of an expression's prefixes.
fn flags(lpe: &Lpe) -> AovFlags {
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

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::{Event, VertexType};

    use crate::material::Scattering;

    #[test]
    fn scene_vertices_keep_the_lobe_event_and_label() {
        let glass = SceneVertex::Scatter {
            side: VertexType::T,
            event: Event::new(EventKind::S, 4).unwrap(),
            scattering: Scattering::Delta,
            group: Some("glass"),
        };
        let shown = |v: &SceneVertex| RenderMan::scene_vertex(v).to_string();
        assert_eq!(shown(&glass), "TS4'glass'");
        assert_eq!(shown(&SceneVertex::Light { group: None }), "L");
        assert_eq!(
            shown(&SceneVertex::Emissive { group: Some("key") }),
            "O'key'"
        );
        assert_eq!(shown(&SceneVertex::Camera), "C");
    }

    #[test]
    fn prefixes_become_flags() {
        let parsed = |s: &str| RenderMan::parse_aov(s, &Parser::default()).unwrap().flags;
        assert_eq!(parsed("C<RD>L"), AovFlags::default());
        let f = parsed("shadows;nothruput;C<RD>L");
        assert!(f.shadows && f.nothruput && !f.unoccluded && !f.values_like_beauty());
        assert!(parsed("holdouts;C.*L").holdouts);
    }

    #[test]
    fn only_a_path_ending_at_an_emitter_is_whole() {
        let v = |s: &str| s.parse::<Path>().unwrap().vertices().to_vec();
        assert!(RenderMan::whole_path(v("C RD2 L")).is_some());
        let mut stopped = v("C RD2 L");
        stopped.pop();
        assert!(RenderMan::whole_path(stopped).is_none());
    }
}
