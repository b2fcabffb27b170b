//! What lint asks of an expression language: parse an AOV with a caret on failure, its
//! emptiness warnings, equivalence, the labels the scene must carry, the lobes a mapping
//! must feed, and partitions with their remainder. [`RenderMan`] and [`Osl`] answer;
//! the checks themselves ([`super::aovs`], [`super::partition`]) are written once.

use std::fmt;
use std::ops::Range;

use lpe::analysis::{self, AnalysisError, Partition, Warning};
use lpe::osl::{self, Registered, Symbol, SymbolPattern};
use lpe::renderman::{LobeCategory, LobeMap, Lpe, Parser};
use lpe::{AovSet, Options};

use super::labels::{self, Carrier};
use crate::witness::Checked;

/// A parse error as a finding shows it.
#[derive(Debug)]
pub struct ParseFailure {
    /// The message, without position.
    pub message: String,
    /// The text the span points into.
    pub source: String,
    /// Bytes of `source` to underline.
    pub span: Range<usize>,
    /// How to fix it, if known.
    pub help: Option<String>,
}

/// An expression language as lint sees it.
pub trait Dialect {
    /// A parsed AOV.
    type Expr: Checked + Clone + fmt::Display;

    /// Parses one AOV's source.
    fn parse(&self, src: &str) -> Result<Self::Expr, ParseFailure>;

    /// The emptiness warnings of `aovs` compiled as one set (set-algebra AOVs included:
    /// `analysis::warnings`); `None` if they do not compile together.
    fn warnings(&self, aovs: &[(String, Self::Expr)]) -> Option<Vec<Warning>>;

    /// Whether two AOVs render the same image.
    fn equivalent(&self, a: &Self::Expr, b: &Self::Expr) -> bool;

    /// The group labels the AOV asks lights or objects of the scene to carry.
    fn labels(&self, e: &Self::Expr) -> Vec<(Carrier, String)>;

    /// Numbered lobes the AOV names that no lobe mapping feeds.
    fn unfed_lobes(&self, e: &Self::Expr) -> Vec<(LobeCategory, u8)>;

    /// The partition check of `aovs` over `universe`.
    fn partition(
        &self,
        aovs: &[(String, Self::Expr)],
        universe: &Self::Expr,
    ) -> Result<Partition<<Self::Expr as Checked>::Path>, AnalysisError>;

    /// The remainder AOV as printed, when the printed text parses and closes the gap.
    fn remainder(&self, aovs: &[(String, Self::Expr)], universe: &Self::Expr) -> Option<String> {
        let printed = Self::Expr::remainder(aovs, universe).to_string();
        let mut closed = aovs.to_vec();
        closed.push(("remainder".into(), self.parse(&printed).ok()?));
        let p = self.partition(&closed, universe).ok()?;
        p.gap.is_none().then_some(printed)
    }
}

/// RenderMan's dialect, with the macros and lobe mappings of the ini files read.
pub struct RenderMan<'a> {
    /// Built-in and ini macros.
    pub parser: &'a Parser,
    /// The lobe mappings.
    pub lobes: &'a LobeMap,
}

impl Dialect for RenderMan<'_> {
    type Expr = Lpe;

    fn parse(&self, src: &str) -> Result<Lpe, ParseFailure> {
        self.parser.parse(src).map_err(|e| ParseFailure {
            message: e.message().to_string(),
            source: e.source_text().to_string(),
            span: e.span(),
            help: e.help().map(str::to_string),
        })
    }

    fn warnings(&self, aovs: &[(String, Lpe)]) -> Option<Vec<Warning>> {
        AovSet::compile(aovs).ok().map(|s| analysis::warnings(&s))
    }

    fn equivalent(&self, a: &Lpe, b: &Lpe) -> bool {
        a.prefixes == b.prefixes && analysis::compare(a, b).is_ok_and(|c| c.equivalent())
    }

    fn labels(&self, e: &Lpe) -> Vec<(Carrier, String)> {
        labels::labels(e)
    }

    fn unfed_lobes(&self, e: &Lpe) -> Vec<(LobeCategory, u8)> {
        labels::lobes(e)
            .into_iter()
            .filter(|&(c, n)| !self.lobes.is_fed(c, n))
            .collect()
    }

    fn partition(
        &self,
        aovs: &[(String, Lpe)],
        universe: &Lpe,
    ) -> Result<Partition<lpe::renderman::Path>, AnalysisError> {
        analysis::partition(aovs, universe, &lpe::renderman::Parser::default())
    }
}

/// OSL's dialect (Arnold, Karma, …), with the labels the renderer registers.
pub struct Osl {
    /// `--register`.
    pub registered: Registered,
}

impl Dialect for Osl {
    type Expr = osl::Lpe;

    /// A leading `lpe:` (how RIB channels and some USD RenderVars mark an expression) is
    /// skipped, and the caret still points into the whole source.
    fn parse(&self, src: &str) -> Result<osl::Lpe, ParseFailure> {
        osl::parse_source(src, &self.registered).map_err(|e| {
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

    fn warnings(&self, aovs: &[(String, osl::Lpe)]) -> Option<Vec<Warning>> {
        AovSet::compile_under(aovs, &self.registered, &Options::default())
            .ok()
            .map(|s| analysis::warnings(&s))
    }

    fn equivalent(&self, a: &osl::Lpe, b: &osl::Lpe) -> bool {
        analysis::compare(a, b).is_ok_and(|c| c.equivalent())
    }

    fn labels(&self, e: &osl::Lpe) -> Vec<(Carrier, String)> {
        osl_labels(e)
    }

    /// OSL has no numbered lobes.
    fn unfed_lobes(&self, _: &osl::Lpe) -> Vec<(LobeCategory, u8)> {
        Vec::new()
    }

    fn partition(
        &self,
        aovs: &[(String, osl::Lpe)],
        universe: &osl::Lpe,
    ) -> Result<Partition<osl::Path>, AnalysisError> {
        analysis::partition(aovs, universe, &self.registered)
    }
}

/// The custom labels an OSL AOV names (slots after the scattering, outside `[^…]`), by
/// who must carry them: on an `L` vertex the light (its light group), on `C` nobody, on
/// any other or any event the object (its lpegroup / lpetag). A set of events counts
/// for each of its members. Every operand of set algebra counts.
pub fn osl_labels(e: &osl::Lpe) -> Vec<(Carrier, String)> {
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

    fn labels(s: &str) -> Vec<(Carrier, String)> {
        osl_labels(&osl::parse(s, &Registered::none()).unwrap())
    }

    #[test]
    fn an_lpe_prefix_is_skipped_and_carets_point_into_the_whole_source() {
        let osl = Osl {
            registered: Registered::none(),
        };
        assert_eq!(
            osl.parse("lpe:C<RD>L").unwrap(),
            osl.parse("C<RD>L").unwrap()
        );
        let e = osl.parse("lpe:C<RD").unwrap_err();
        assert_eq!(
            (e.message.as_str(), e.span),
            ("Reached end of line looking for > to end a group", 8..8)
        );
        let e = osl.parse("lpe:C<R*>L").unwrap_err();
        assert_eq!(e.span, 7..8);
        assert_eq!(e.source, "lpe:C<R*>L");
    }

    #[test]
    fn osl_labels_by_carrier() {
        let light = |l: &str| (Carrier::Light, l.to_string());
        let object = |l: &str| (Carrier::Object, l.to_string());
        assert_eq!(labels("C.*<L.'key'>"), [light("key")]);
        assert_eq!(labels("C'floor'.*L"), [object("floor")]);
        assert_eq!(
            labels("C<RD'floor'>.*<[LO].'lamp'>"),
            [object("floor"), light("lamp"), object("lamp")]
        );
        // A camera label, an excluded label and NONE ask nothing of the scene.
        assert_eq!(labels("<C.'cam'>.*<L.[^'key']><L.x>"), []);
        // Every operand of set algebra; several labels per vertex.
        assert_eq!(
            labels("C.*<L.'a'> - C.*<L.'b''c'>"),
            [light("a"), light("b"), light("c")]
        );
    }
}
