//! What lint asks of an expression language: [`LintDialect`], implemented on `lpe`'s
//! dialect markers, holds what is truly the dialect's (how a parse failure is shown, the
//! labels the scene must carry, the lobes a mapping must feed); [`Lint`] is one
//! dialect's view with what the files configured (registration, lobe mappings), and
//! answers the checks' questions (parse, emptiness, equivalence, partition, remainder)
//! with `lpe::analysis`, written once. The impls are in [`renderman`] and [`osl`]; the
//! checks themselves ([`super::aovs`], [`super::partition`]) are generic.

pub mod osl;
pub mod renderman;

use std::ops::Range;

use lpe::analysis::{self, AnalysisBudget, AnalysisError, Decision, Partition, Warning};
use lpe::renderman::LobeCategory;
use lpe::{AovSet, Options};

use super::labels::Carrier;
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

/// An expression language as lint sees it: what lint cannot derive from
/// [`lpe::Dialect`]. The re-check of witnesses ([`Checked`]) comes with it.
pub trait LintDialect: Checked {
    /// What the configuration maps besides the registration and an AOV may need fed:
    /// RenderMan's lobe mappings; `()` for a dialect without numbered lobes.
    type Lobes: Default;

    /// Whether the dialect reads `rendermn.ini` files (their macros and lobe mappings);
    /// lint then reads them with the other files. For any other dialect an ini file is
    /// refused ([`super::run::RunError::IniWithoutRenderMan`]).
    const READS_INI: bool;

    /// The registration and lobe mappings once lint has read its ini files into
    /// `config`, from the registration the caller gave.
    fn configured(
        registration: Self::Registration,
        config: &lpe::renderman::Config,
    ) -> (Self::Registration, Self::Lobes);

    /// Parses one AOV's source as a file declares it (a leading `lpe:` included), the
    /// failure with its span in `src`.
    fn parse_source(
        src: &str,
        registration: &Self::Registration,
    ) -> Result<Self::Lpe, ParseFailure>;

    /// The warnings a parse gives for an expression it accepts (OSL's reversed ranges
    /// and mixed negations, which OSL prints on stderr): `lpe-check parse` prints them,
    /// the explorer's `check` view shows them per line; none by default.
    fn parse_warnings(lpe: &Self::Lpe) -> Vec<String> {
        let _ = lpe;
        Vec::new()
    }

    /// The group labels the AOV asks lights or objects of the scene to carry.
    fn labels(e: &Self::Lpe) -> Vec<(Carrier, String)>;

    /// Numbered lobes the AOV names that `lobes` does not feed.
    fn unfed_lobes(e: &Self::Lpe, lobes: &Self::Lobes) -> Vec<(LobeCategory, u8)>;

    /// Whether two AOVs matching the same paths accumulate alike (RenderMan's prefixes
    /// change what is accumulated); `true` for a dialect without such decorations.
    fn accumulate_alike(a: &Self::Lpe, b: &Self::Lpe) -> bool {
        let _ = (a, b);
        true
    }
}

/// Dialect `D` with what the files configured: the checks' questions, answered once for
/// every dialect.
pub struct Lint<'a, D: LintDialect> {
    /// How expressions read (RenderMan's macros, OSL's user labels).
    pub registration: &'a D::Registration,
    /// The lobe mappings.
    pub lobes: &'a D::Lobes,
    /// The budget of each equivalence and partition question; past it the check
    /// reports an `undecided` finding.
    pub budget: AnalysisBudget,
}

impl<D: LintDialect> Lint<'_, D> {
    /// Parses one AOV's source.
    pub fn parse(&self, src: &str) -> Result<D::Lpe, ParseFailure> {
        D::parse_source(src, self.registration)
    }

    /// The emptiness warnings of `aovs` compiled as one set (set-algebra AOVs included:
    /// `analysis::warnings`); `None` if they do not compile together.
    pub fn warnings(&self, aovs: &[(String, D::Lpe)]) -> Option<Vec<Warning>> {
        AovSet::<D>::compile_under(aovs, self.registration, &Options::default())
            .ok()
            .map(|s| analysis::warnings(&s))
    }

    /// Whether two AOVs render the same image, or [`Decision::Undecided`] when the
    /// comparison ran out of [`Lint::budget`] (a compile error is "no").
    pub fn equivalent(&self, a: &D::Lpe, b: &D::Lpe) -> Decision<bool> {
        if !D::accumulate_alike(a, b) {
            return Decision::Decided(false);
        }
        match analysis::compare_within(a, b, &self.budget) {
            Ok(d) => d.map(|c| c.equivalent()),
            Err(_) => Decision::Decided(false),
        }
    }

    /// The group labels the AOV asks lights or objects of the scene to carry.
    pub fn labels(&self, e: &D::Lpe) -> Vec<(Carrier, String)> {
        D::labels(e)
    }

    /// Numbered lobes the AOV names that no lobe mapping feeds.
    pub fn unfed_lobes(&self, e: &D::Lpe) -> Vec<(LobeCategory, u8)> {
        D::unfed_lobes(e, self.lobes)
    }

    /// The partition check of `aovs` over `universe`.
    pub fn partition(
        &self,
        aovs: &[(String, D::Lpe)],
        universe: &D::Lpe,
    ) -> Result<Decision<Partition<D::Path>>, AnalysisError> {
        analysis::partition_within(aovs, universe, self.registration, &self.budget)
    }

    /// The remainder AOV as printed, when the printed text parses and closes the gap.
    pub fn remainder(&self, aovs: &[(String, D::Lpe)], universe: &D::Lpe) -> Option<String> {
        let printed = analysis::remainder(aovs, universe).to_string();
        let mut closed = aovs.to_vec();
        closed.push(("remainder".into(), self.parse(&printed).ok()?));
        let p = self.partition(&closed, universe).ok()?.decided()?;
        p.gap.is_none().then_some(printed)
    }
}
