//! RenderMan's dialect as lint sees it: the parser's own error with its span and hint,
//! what an expression asks of the scene (the group labels it names, by the vertex kind
//! that must carry them: [`labels`]; the numbered lobes it names: [`lobes`]), the lobe
//! mappings of the ini files, and prefixes that change what an AOV accumulates.
//! Negated classes are skipped: a label or lobe named only to be excluded makes no AOV
//! black. Every operand of set algebra counts (a typo in `A - B` is a typo too).

use lpe::renderman::ast::{Atom, EventPos, Item, LabelPos, TypePos};
use lpe::renderman::{EventKind, LobeCategory, LobeMap, Lpe, Parser, Path, RenderMan, VertexType};

use super::{LintDialect, ParseFailure};
use crate::check::labels::Carrier;
use crate::witness::Checked;

impl Checked for RenderMan {
    fn reference_match(lpe: &Lpe, path: &Path) -> bool {
        lpe_reference::is_match(lpe, path)
    }
}

impl LintDialect for RenderMan {
    type Lobes = LobeMap;

    const READS_INI: bool = true;

    fn configured(_: Parser, config: &lpe::renderman::Config) -> (Parser, LobeMap) {
        (config.parser(), config.lobes.clone())
    }

    fn parse_source(src: &str, parser: &Parser) -> Result<Lpe, ParseFailure> {
        parser.parse(src).map_err(|e| ParseFailure {
            message: e.message().to_string(),
            source: e.source_text().to_string(),
            span: e.span(),
            help: e.help().map(str::to_string),
        })
    }

    fn labels(e: &Lpe) -> Vec<(Carrier, String)> {
        labels(e)
    }

    fn unfed_lobes(e: &Lpe, map: &LobeMap) -> Vec<(LobeCategory, u8)> {
        lobes(e)
            .into_iter()
            .filter(|&(c, n)| !map.is_fed(c, n))
            .collect()
    }

    fn accumulate_alike(a: &Lpe, b: &Lpe) -> bool {
        a.prefixes == b.prefixes
    }
}

/// `(carrier, label)` for every label named in a non-negated position, deduplicated,
/// in first-mention order.
pub fn labels(lpe: &Lpe) -> Vec<(Carrier, String)> {
    let mut out: Vec<(Carrier, String)> = Vec::new();
    let mut add = |c: Carrier, l: &str| {
        if !out.iter().any(|(c2, l2)| *c2 == c && l2 == l) {
            out.push((c, l.to_string()));
        }
    };
    for_each_positive_item(lpe, &mut |item| match item {
        Item::Label(l) => add(Carrier::Object, l),
        Item::Triple(t) => {
            let named: Vec<&String> = match &t.label {
                LabelPos::One(l) => vec![l],
                LabelPos::Class {
                    negated: false,
                    labels,
                } => labels.iter().collect(),
                _ => Vec::new(),
            };
            let types: Vec<VertexType> = match &t.ty {
                TypePos::Any => vec![VertexType::R],
                TypePos::One(ty) => vec![*ty],
                TypePos::Class {
                    negated: false,
                    types,
                } => types.clone(),
                TypePos::Class { negated: true, .. } => vec![VertexType::R],
            };
            for ty in types {
                let carrier = match ty {
                    VertexType::L => Carrier::Light,
                    VertexType::C => continue,
                    _ => Carrier::Object,
                };
                for l in &named {
                    add(carrier, l);
                }
            }
        }
        _ => {}
    });
    out
}

/// `(category, lobe)` for every numbered lobe named in a non-negated position.
pub fn lobes(lpe: &Lpe) -> Vec<(LobeCategory, u8)> {
    let mut out = Vec::new();
    let mut add = |kind: EventKind, lobe: Option<u8>| {
        let category = match kind {
            EventKind::D => LobeCategory::Diffuse,
            EventKind::S => LobeCategory::Specular,
            EventKind::U => LobeCategory::User,
        };
        if let Some(n) = lobe {
            if !out.contains(&(category, n)) {
                out.push((category, n));
            }
        }
    };
    for_each_positive_item(lpe, &mut |item| match item {
        Item::Event(e) => add(e.kind, e.lobe),
        Item::Triple(t) => match &t.event {
            EventPos::One(e) => add(e.kind, e.lobe),
            EventPos::Class {
                negated: false,
                events,
            } => events.iter().for_each(|e| add(e.kind, e.lobe)),
            _ => {}
        },
        _ => {}
    });
    out
}

/// Every item of every operand, outside negated classes.
fn for_each_positive_item(lpe: &Lpe, f: &mut impl FnMut(&Item)) {
    for e in lpe.operands() {
        e.for_each_atom(&mut |atom| {
            let items: &[Item] = match atom {
                Atom::Item(i) => std::slice::from_ref(i),
                Atom::Class {
                    negated: false,
                    items,
                } => items,
                Atom::Class { negated: true, .. } => &[],
            };
            items.iter().for_each(&mut *f);
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn expr(s: &str) -> Lpe {
        lpe::renderman::parse(s).unwrap()
    }

    #[test]
    fn labels_by_carrier() {
        assert_eq!(
            labels(&expr("C'floor'.*<L.'key'>")),
            [
                (Carrier::Object, "floor".to_string()),
                (Carrier::Light, "key".to_string())
            ]
        );
        assert_eq!(
            labels(&expr("C.*<[LO].['a' 'b']>")),
            [
                (Carrier::Light, "a".to_string()),
                (Carrier::Light, "b".to_string()),
                (Carrier::Object, "a".to_string()),
                (Carrier::Object, "b".to_string()),
            ]
        );
        // Excluded labels ask nothing of the scene.
        assert_eq!(labels(&expr("C.*<L.[^'key']>")), []);
        assert_eq!(labels(&expr("C[^'floor']L")), []);
        assert_eq!(
            labels(&expr("C<R.'x'>.*O")),
            [(Carrier::Object, "x".into())]
        );
        // Every operand of set algebra.
        assert_eq!(
            labels(&expr("C.*<L.'a'> - C.*<L.'b'>")),
            [(Carrier::Light, "a".into()), (Carrier::Light, "b".into())]
        );
    }

    #[test]
    fn numbered_lobes_only() {
        assert_eq!(
            lobes(&expr("C<.U9>L|C<R[D4S]>L")),
            [(LobeCategory::User, 9), (LobeCategory::Diffuse, 4)]
        );
        assert_eq!(lobes(&expr("C<RD>.*[^S3]L")), []);
        assert_eq!(
            lobes(&expr("CD2S8L")),
            [(LobeCategory::Diffuse, 2), (LobeCategory::Specular, 8)]
        );
    }
}
