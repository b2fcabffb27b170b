//! Translation between the RenderMan and OSL dialects, with a proof (docs/language.md
//! §19).
//!
//! A [`Correspondence`] says which OSL vertex each RenderMan vertex is. An OSL expression
//! `f` means the same as a RenderMan expression `e` when, for every RenderMan path `p`,
//! `e` matches `p` exactly when `f` matches the OSL view of `p` ([`cross::compare`]).
//! Translation is syntax-directed (the expression keeps its shape; atoms become the
//! patterns of their views, or of their preimages), and its verdict is decided on the
//! automata of the printed translation read back: exact, or not expressible with the
//! reason, the translations from above and below, and a witness for each difference.
//!
//! This module is the one place that knows both dialects; no shared layer imports it.

mod bound;
pub mod correspondence;
pub mod cross;
mod labels;
mod to_osl;
mod to_renderman;

use std::fmt;

use crate::analysis::AnalysisError;
use crate::dialect::Dialect;
use crate::osl::{self, Osl};
use crate::renderman::{self, RenderMan};

pub use bound::Bound;
pub use correspondence::{Correspondence, DeclarationError, Scattering};
pub use cross::{Collision, CrossComparison, Witness};

/// Why a translation is not exact.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reason {
    /// Two RenderMan paths with one OSL view, only one of them matched: no OSL expression
    /// can tell them apart.
    Collision(Collision),
    /// The RenderMan expression matches a path with no OSL view (a user lobe).
    NoOslView(renderman::Path),
    /// The target dialect has no spelling for what some atom matches (a label set the
    /// witness of the upper translation shows).
    Unsayable,
}

/// A translation and its verdict.
#[derive(Clone, Debug, PartialEq)]
pub struct Translation<L> {
    /// The translation: exact when [`Translation::exact`], else the one from above.
    pub text: L,
    /// Whether the translation means exactly what the source means.
    pub exact: bool,
    /// Why not, when not exact.
    pub reasons: Vec<Reason>,
    /// When not exact: a shortest path the translation from above adds.
    pub upper_witness: Option<Witness>,
    /// The translation from below (a subset).
    pub lower: L,
    /// When not exact: a shortest path the source matches and the translation from below
    /// misses (`None`: the lower translation is exact, or matches every path the source
    /// matches on which OSL can agree).
    pub lower_witness: Option<Witness>,
    /// What does not carry over and changes no match (prefixes).
    pub notes: Vec<String>,
}

impl<L> Translation<L> {
    /// An exact translation (`lower` means the same; no witnesses).
    fn exact(text: L, lower: L, notes: Vec<String>) -> Translation<L> {
        Translation {
            text,
            exact: true,
            reasons: Vec::new(),
            upper_witness: None,
            lower,
            lower_witness: None,
            notes,
        }
    }
}

/// Why a translation gave no answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TranslateError {
    /// A search gave up ([`AnalysisError`]).
    Analysis(AnalysisError),
    /// The printed translation did not read back in its dialect: a bug, reported rather
    /// than judged on a tree the text does not say.
    Unreadable {
        /// The printed text.
        text: String,
        /// The parse error.
        message: String,
    },
}

impl fmt::Display for TranslateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TranslateError::Analysis(e) => write!(f, "{e}"),
            TranslateError::Unreadable { text, message } => write!(
                f,
                "internal error: the translation `{text}` does not read back ({message})"
            ),
        }
    }
}

impl std::error::Error for TranslateError {}

impl From<AnalysisError> for TranslateError {
    fn from(e: AnalysisError) -> Self {
        TranslateError::Analysis(e)
    }
}

/// The printed `e` read back in its dialect (nothing registered): the translation judged
/// is the text a user copies.
fn read_back<D: Dialect>(e: &D::Lpe) -> Result<D::Lpe, TranslateError> {
    let text = e.to_string();
    D::parse(&text, &D::Registration::default()).map_err(|err| TranslateError::Unreadable {
        text: text.clone(),
        message: err.to_string(),
    })
}

/// A dialect expressions translate from: into the other one, [`Translate::Target`].
pub trait Translate: Dialect {
    /// The dialect translations are written in.
    type Target: Dialect;
    /// The translation of `source` under `corr`, with its verdict.
    fn translate(
        source: &Self::Lpe,
        corr: &Correspondence,
    ) -> Result<Translation<<Self::Target as Dialect>::Lpe>, TranslateError>;
    /// A witness's path in this dialect (the RenderMan path, or its OSL view).
    fn source_path(w: &Witness) -> Option<&Self::Path>;
    /// A witness's path in the target dialect.
    fn target_path(w: &Witness) -> Option<&<Self::Target as Dialect>::Path>;
}

/// Translates `source` into the other dialect under `corr`.
///
/// ```
/// use lpe::renderman::RenderMan;
/// use lpe::translate::{translate, Correspondence};
///
/// let corr = Correspondence::default();
/// let t = translate::<RenderMan>(&lpe::renderman::parse("C<RD>.*L").unwrap(), &corr).unwrap();
/// assert!(t.exact);
/// assert_eq!(t.text.to_string(), "<C.><RD><[RT].>*<L.>");
/// // Lobe numbers are not OSL's: `D2` and `D1` are both `R,D`.
/// let t = translate::<RenderMan>(&lpe::renderman::parse("C<RD2>L").unwrap(), &corr).unwrap();
/// assert!(!t.exact);
/// ```
pub fn translate<D: Translate>(
    source: &D::Lpe,
    corr: &Correspondence,
) -> Result<Translation<<D::Target as Dialect>::Lpe>, TranslateError> {
    D::translate(source, corr)
}

impl Translate for RenderMan {
    type Target = Osl;

    fn source_path(w: &Witness) -> Option<&renderman::Path> {
        Some(&w.renderman)
    }

    fn target_path(w: &Witness) -> Option<&osl::Path> {
        w.osl.as_ref()
    }

    fn translate(
        e: &renderman::Lpe,
        corr: &Correspondence,
    ) -> Result<Translation<osl::Lpe>, TranslateError> {
        let upper = read_back::<Osl>(&to_osl::translate(e, corr, Bound::Upper))?;
        let lower = read_back::<Osl>(&to_osl::translate(e, corr, Bound::Lower))?;
        let cu = cross::compare(e, &upper, corr)?;
        let mut notes = Vec::new();
        if e.prefixes != renderman::Prefixes::NONE {
            let mut bare = e.clone();
            bare.prefixes = renderman::Prefixes::NONE;
            notes.push(format!(
                "the prefixes of `{e}` are not carried: OSL has none (the OSL AOV accumulates \
             as `{bare}` does)"
            ));
        }
        if cu.equivalent() {
            return Ok(Translation::exact(upper, lower, notes));
        }
        let mut reasons = Vec::new();
        if let Some(c) = cross::collision(e, corr)? {
            reasons.push(Reason::Collision(c));
        }
        if let Some(p) = cu.outside.clone() {
            reasons.push(Reason::NoOslView(p));
        }
        if reasons.is_empty() {
            reasons.push(Reason::Unsayable);
        }
        let cl = cross::compare(e, &lower, corr)?;
        Ok(Translation {
            text: upper,
            exact: false,
            reasons,
            upper_witness: cu.osl_only,
            lower,
            lower_witness: cl.renderman_only,
            notes,
        })
    }
}

/// OSL to RenderMan: the RenderMan expression that matches a path exactly when the OSL one
/// matches its OSL view.
impl Translate for Osl {
    type Target = RenderMan;

    fn source_path(w: &Witness) -> Option<&osl::Path> {
        w.osl.as_ref()
    }

    fn target_path(w: &Witness) -> Option<&renderman::Path> {
        Some(&w.renderman)
    }

    fn translate(
        f: &osl::Lpe,
        corr: &Correspondence,
    ) -> Result<Translation<renderman::Lpe>, TranslateError> {
        let upper = read_back::<RenderMan>(&to_renderman::translate(f, corr, Bound::Upper))?;
        let lower = read_back::<RenderMan>(&to_renderman::translate(f, corr, Bound::Lower))?;
        let cu = cross::compare(&upper, f, corr)?;
        if cu.equivalent() {
            return Ok(Translation::exact(upper, lower, Vec::new()));
        }
        let cl = cross::compare(&lower, f, corr)?;
        Ok(Translation {
            text: upper,
            exact: false,
            reasons: vec![Reason::Unsayable],
            upper_witness: cu.renderman_only.or(cu.outside.map(|renderman| Witness {
                renderman,
                osl: None,
            })),
            lower,
            lower_witness: cl.osl_only,
            notes: Vec::new(),
        })
    }
}

#[cfg(test)]
mod tests;
