//! Expressions of a stage that does not say its dialect, read both ways: a USD stage is
//! moved between render delegates (hdPrman reads RenderMan's dialect; Karma, hdArnold
//! and MoonRay OSL's), and most expressions parse in both with different answers, so an
//! AOV whose two readings differ renders a different image depending on who renders it.
//!
//! For each AOV of a document with no [`crate::DialectDecl`] that parses in both
//! dialects, [`lpe::translate::cross::compare`] decides under the default
//! correspondence whether the RenderMan reading matches a path exactly when the OSL
//! reading matches its OSL view; when not, one witness is re-checked with both reference
//! matchers and reported ([`Kind::AmbiguousDialect`]). A run whose dialect the user
//! named (`--dialect`, `dialect=`) reads every file in it and does not run this check:
//! the user has said which renderer the stage is for.

use lpe::osl::{self, Registered};
use lpe::renderman;
use lpe::translate::{cross, Correspondence, CrossComparison};

use super::finding::{Finding, Kind};
use super::outcome::Linted;
use crate::witness::{recheck, Disagreement, Expect};
use crate::Document;

/// How the check reads an expression in each dialect.
pub struct BothDialects {
    /// RenderMan's parser with the macros of the run's ini files.
    pub renderman: renderman::Parser,
    /// Which OSL vertex each RenderMan vertex is.
    pub correspondence: Correspondence,
}

impl BothDialects {
    /// RenderMan read with `renderman`, OSL with no registered labels (the cross
    /// comparison compiles OSL expressions so), the default correspondence.
    pub fn new(renderman: renderman::Parser) -> BothDialects {
        BothDialects {
            renderman,
            correspondence: Correspondence::default(),
        }
    }
}

/// Appends an [`Kind::AmbiguousDialect`] finding for each AOV of `doc` (linted as
/// `linted`) whose two readings differ, when `doc` declares no dialect. A witness the
/// reference matchers refuse is an engine bug, returned as the error.
pub fn check<E>(
    doc: &Document,
    linted: &[Linted<E>],
    both: &BothDialects,
    findings: &mut Vec<Finding>,
) -> Result<(), Disagreement> {
    if doc.dialect.is_some() {
        return Ok(());
    }
    for l in linted {
        let source = &l.decl.source;
        let (Ok(rm), Ok(osl)) = (
            both.renderman.parse(source),
            osl::parse_source(source, &Registered::none()),
        ) else {
            continue;
        };
        // A search over the limit answers nothing: no finding rather than a guess.
        let Ok(c) = cross::compare(&rm, &osl, &both.correspondence) else {
            continue;
        };
        if let Some(reading) = differing_reading(&c) {
            reading.recheck(&l.decl.name, &rm, &osl)?;
            let mut f = Finding::new(
                Kind::AmbiguousDialect,
                &l.file,
                &l.decl.name,
                &l.decl.location,
                format!(
                    "parses in both dialects and means different things: {}",
                    reading.describe()
                ),
            );
            f.witness = Some(reading.renderman().to_string());
            f.help = Some(
                "say which dialect the stage is written in: `custom string lpe:dialect = \
                 \"renderman\"` (hdPrman) or `\"osl\"` (Karma, hdArnold, MoonRay) on its \
                 RenderSettings prim"
                    .into(),
            );
            findings.push(f);
        }
    }
    Ok(())
}

/// A RenderMan path the two readings disagree on.
enum Reading<'a> {
    /// RenderMan's reading matches the path, OSL's does not match its view.
    RenderMan(&'a renderman::Path, &'a osl::Path),
    /// OSL's reading matches the view, RenderMan's does not match the path.
    Osl(&'a renderman::Path, &'a osl::Path),
    /// RenderMan's reading matches a path with no OSL view (a user lobe).
    NoView(&'a renderman::Path),
}

/// The first difference of `c`, in the order RenderMan-only, OSL-only, no OSL view (each
/// a shortest of its kind); `None` when the readings agree.
fn differing_reading(c: &CrossComparison) -> Option<Reading<'_>> {
    c.renderman_only
        .as_ref()
        .map(|w| viewed(w, Reading::RenderMan))
        .or_else(|| c.osl_only.as_ref().map(|w| viewed(w, Reading::Osl)))
        .or_else(|| c.outside.as_ref().map(Reading::NoView))
}

/// `reading` of a witness with its OSL view; a witness without one is the no-view case
/// (the comparison gives RenderMan-only and OSL-only paths with their views).
fn viewed<'a>(
    w: &'a cross::Witness,
    reading: fn(&'a renderman::Path, &'a osl::Path) -> Reading<'a>,
) -> Reading<'a> {
    match &w.osl {
        Some(v) => reading(&w.renderman, v),
        None => Reading::NoView(&w.renderman),
    }
}

impl Reading<'_> {
    fn renderman(&self) -> &renderman::Path {
        match self {
            Reading::RenderMan(p, _) | Reading::Osl(p, _) | Reading::NoView(p) => p,
        }
    }

    fn describe(&self) -> String {
        match self {
            Reading::RenderMan(p, v) => format!(
                "as RenderMan it matches `{p}`; as OSL it does not match that path's OSL \
                 view `{v}`"
            ),
            Reading::Osl(p, v) => format!(
                "as OSL it matches `{v}`, the OSL view of `{p}`; as RenderMan it does not \
                 match `{p}`"
            ),
            Reading::NoView(p) => format!(
                "as RenderMan it matches `{p}`, which has no OSL view (a user lobe): as OSL \
                 it never matches that path"
            ),
        }
    }

    /// Both reference matchers must give the answers the comparison claims.
    fn recheck(&self, name: &str, rm: &renderman::Lpe, osl: &osl::Lpe) -> Result<(), Disagreement> {
        let rm_name = format!("{name} (as RenderMan)");
        let osl_name = format!("{name} (as OSL)");
        let renderman = |matches| Expect {
            name: &rm_name,
            lpe: rm,
            matches,
        };
        let osl = |matches| Expect {
            name: &osl_name,
            lpe: osl,
            matches,
        };
        match self {
            Reading::RenderMan(p, v) => {
                recheck(*p, &[renderman(true)])?;
                recheck(*v, &[osl(false)])
            }
            Reading::Osl(p, v) => {
                recheck(*p, &[renderman(false)])?;
                recheck(*v, &[osl(true)])
            }
            Reading::NoView(p) => recheck(*p, &[renderman(true)]),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{AovDecl, DialectDecl, Format, Location};
    use lpe::DialectName;

    /// A document of `format` holding one AOV per source.
    fn doc(format: Format, sources: &[&str]) -> (Document, Vec<Linted<()>>) {
        let mut d = Document::new("t", format);
        let mut linted = Vec::new();
        for (i, s) in sources.iter().enumerate() {
            let decl = AovDecl {
                name: format!("a{i}"),
                source: s.to_string(),
                location: Location::Line {
                    line: i + 1,
                    column: 1,
                },
                source_type: None,
            };
            d.aovs.push(decl.clone());
            linted.push(Linted {
                file: "t".into(),
                decl,
                lpe: None,
            });
        }
        (d, linted)
    }

    /// `(subject, message, witness)` of each finding on `sources` in an undeclared stage.
    fn findings(sources: &[&str]) -> Vec<(String, String, Option<String>)> {
        let (d, linted) = doc(Format::Usd, sources);
        let mut out = Vec::new();
        let both = BothDialects::new(renderman::Parser::default());
        check(&d, &linted, &both, &mut out).unwrap();
        assert!(out.iter().all(|f| f.kind == Kind::AmbiguousDialect));
        out.into_iter()
            .map(|f| (f.subject, f.message, f.witness))
            .collect()
    }

    const BOTH: &str = "parses in both dialects and means different things: ";

    #[test]
    fn each_kind_of_difference_names_its_witness() {
        assert_eq!(
            findings(&["C<RS>L", "C[^S]L", "C<.U2>L"]),
            [
                (
                    "a0".into(),
                    format!(
                        "{BOTH}as RenderMan it matches `C RS1 L`; as OSL it does not match \
                         that path's OSL view `C,~ R,G L,~`"
                    ),
                    Some("C RS1 L".into())
                ),
                (
                    "a1".into(),
                    format!(
                        "{BOTH}as OSL it matches `C,~ R,G L,~`, the OSL view of `C RS1 L`; \
                         as RenderMan it does not match `C RS1 L`"
                    ),
                    Some("C RS1 L".into())
                ),
                (
                    "a2".into(),
                    format!(
                        "{BOTH}as RenderMan it matches `C RU2 L`, which has no OSL view (a \
                         user lobe): as OSL it never matches that path"
                    ),
                    Some("C RU2 L".into())
                ),
            ]
        );
    }

    #[test]
    fn same_meaning_or_one_reading_is_no_finding() {
        // The same paths both ways; RenderMan only (a macro); OSL only (`G`); neither.
        assert_eq!(
            findings(&["C<RD>L", "lpe:C.*L", "lpe:directDiffuse", "C<RG>L", "C<RD"]),
            []
        );
    }

    #[test]
    fn a_comparison_over_the_limits_reports_nothing() {
        // Parses in both dialects (40 003 positions), but no automaton of it fits the
        // analysis budget: the comparison gives up, and the check says nothing.
        let big = "C(<RS>{200}){200}L";
        let rm = renderman::parse(big).unwrap();
        let osl = osl::parse(big, &Registered::none()).unwrap();
        assert!(cross::compare(&rm, &osl, &Correspondence::default()).is_err());
        assert_eq!(findings(&[big]), []);
    }

    #[test]
    fn a_declared_dialect_or_a_renderman_format_is_not_checked() {
        let both = BothDialects::new(renderman::Parser::default());
        for format in [Format::Rib, Format::Ini] {
            let (d, linted) = doc(format, &["C<RS>L"]);
            let mut out = Vec::new();
            check(&d, &linted, &both, &mut out).unwrap();
            assert_eq!(out, [], "{format:?}");
        }
        for dialect in DialectName::ALL {
            let (mut d, linted) = doc(Format::Usd, &["C<RS>L"]);
            d.dialect = Some(DialectDecl {
                dialect,
                location: Some(Location::Prim {
                    prim: "/Render".into(),
                    attribute: "lpe:dialect".into(),
                }),
            });
            let mut out = Vec::new();
            check(&d, &linted, &both, &mut out).unwrap();
            assert_eq!(out, [], "{dialect}");
        }
    }
}
