//! OSL's dialect (Arnold, Karma, …) as lint sees it: parse failures pointed into the
//! whole source, the custom labels an AOV names ([`labels`]), no numbered lobes.

use lpe::osl::{self, Osl, Registered, Symbol, SymbolPattern};
use lpe::renderman::LobeCategory;

use super::{LintDialect, ParseFailure};
use crate::check::labels::Carrier;
use crate::witness::Checked;

impl Checked for Osl {
    fn reference_match(lpe: &osl::Lpe, path: &osl::Path) -> bool {
        lpe_reference::lpe_tree::is_match(lpe, path)
    }
}

impl LintDialect for Osl {
    /// OSL has no numbered lobes.
    type Lobes = ();

    const READS_INI: bool = false;

    fn configured(registered: Registered, _: &lpe::renderman::Config) -> (Registered, ()) {
        (registered, ())
    }

    /// A leading `lpe:` (how RIB channels and some USD RenderVars mark an expression) is
    /// skipped, and the caret still points into the whole source.
    fn parse_source(src: &str, registered: &Registered) -> Result<osl::Lpe, ParseFailure> {
        osl::parse_source(src, registered).map_err(|e| {
            let at = e.pos;
            let len = src[at.min(src.len())..]
                .chars()
                .next()
                .map_or(0, char::len_utf8);
            ParseFailure {
                message: e.message(),
                source: src.to_string(),
                span: at..at + len,
                help: None,
            }
        })
    }

    fn parse_warnings(lpe: &osl::Lpe) -> Vec<String> {
        lpe.warnings.iter().map(ToString::to_string).collect()
    }

    fn labels(e: &osl::Lpe) -> Vec<(Carrier, String)> {
        labels(e)
    }

    fn unfed_lobes(_: &osl::Lpe, _: &()) -> Vec<(LobeCategory, u8)> {
        Vec::new()
    }
}

/// The custom labels an OSL AOV names (slots after the scattering, outside `[^…]`), by
/// who must carry them: on an `L` vertex the light (its light group), on `C` nobody, on
/// any other or any event the object (its lpegroup / lpetag). A set of events counts
/// for each of its members. Every operand of set algebra counts.
pub fn labels(e: &osl::Lpe) -> Vec<(Carrier, String)> {
    let mut out: Vec<(Carrier, String)> = Vec::new();
    for operand in e.operands() {
        operand.for_each_vertex(&mut |v| {
            let events: Vec<Option<&str>> = match &v.symbols[0] {
                SymbolPattern::One(s) => vec![label(s)],
                SymbolPattern::Set(xs) => xs.iter().map(label).collect(),
                SymbolPattern::Any | SymbolPattern::NotIn(_) => vec![None],
            };
            let carriers: Vec<Carrier> = events
                .into_iter()
                .filter_map(|ev| match ev {
                    Some("L") => Some(Carrier::Light),
                    Some("C") => None,
                    _ => Some(Carrier::Object),
                })
                .collect();
            for slot in &v.symbols[2..] {
                let named: &[Symbol] = match slot {
                    SymbolPattern::One(s) => std::slice::from_ref(s),
                    SymbolPattern::Set(xs) => xs,
                    SymbolPattern::Any | SymbolPattern::NotIn(_) => &[],
                };
                for l in named.iter().filter_map(label) {
                    for &c in &carriers {
                        if !out.iter().any(|(c2, l2)| *c2 == c && l2 == l) {
                            out.push((c, l.to_string()));
                        }
                    }
                }
            }
        });
    }
    out
}

fn label(s: &Symbol) -> Option<&str> {
    match s {
        Symbol::Label(l) => Some(l),
        Symbol::None => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn of(s: &str) -> Vec<(Carrier, String)> {
        labels(&osl::parse(s, &Registered::none()).unwrap())
    }

    fn parse(src: &str) -> Result<osl::Lpe, ParseFailure> {
        Osl::parse_source(src, &Registered::none())
    }

    #[test]
    fn an_lpe_prefix_is_skipped_and_carets_point_into_the_whole_source() {
        assert_eq!(parse("lpe:C<RD>L").unwrap(), parse("C<RD>L").unwrap());
        let e = parse("lpe:C<RD").unwrap_err();
        assert_eq!(
            (e.message.as_str(), e.span),
            ("Reached end of line looking for > to end a group", 8..8)
        );
        let e = parse("lpe:C<R*>L").unwrap_err();
        assert_eq!(e.span, 7..8);
        assert_eq!(e.source, "lpe:C<R*>L");
    }

    #[test]
    fn labels_by_carrier() {
        let light = |l: &str| (Carrier::Light, l.to_string());
        let object = |l: &str| (Carrier::Object, l.to_string());
        assert_eq!(of("C.*<L.'key'>"), [light("key")]);
        assert_eq!(of("C'floor'.*L"), [object("floor")]);
        assert_eq!(
            of("C<RD'floor'>.*<[LO].'lamp'>"),
            [object("floor"), light("lamp"), object("lamp")]
        );
        // A camera label, an excluded label and NONE ask nothing of the scene.
        assert_eq!(of("<C.'cam'>.*<L.[^'key']><L.x>"), []);
        // Every operand of set algebra; several labels per vertex.
        assert_eq!(
            of("C.*<L.'a'> - C.*<L.'b''c'>"),
            [light("a"), light("b"), light("c")]
        );
    }
}
