//! The matchers `converge` times ([`MatcherRow`]), apart from `converge` so that the
//! known-answer scenes ([`super::known`]), which `converge` renders, can render with one.

use lpe::renderman::{LobeMap, RenderMan};
use serde::Serialize;

#[cfg(feature = "engines")]
use crate::aov::matcher::CheckEngine;
use crate::aov::matcher::{Reference, WholePathMatcher};
use crate::aov::AovList;
use crate::integrator::{Render, RenderError, Settings};
use crate::scene::Scene;

/// The matchers `converge` times, one row group each, named as the engine registry
/// names them (`lpe-check --engine`). Each renders the same image (same paths, same AOV
/// masks); only the cost differs. A new matcher is one arm in [`MatcherRow::render`] and
/// one entry in [`MatcherRow::ALL`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum MatcherRow {
    /// The fast matcher (`lpe::AovSet`) with its DFA, as renders use it (the default).
    Fast,
    /// The fast matcher with its DFA budget at 0: the bitset NFA stepped per vertex.
    Nfa,
    /// The regex-automata engine (lazy DFA over the encoded path), run on every emitter
    /// reached. Only with the `engines` feature.
    #[cfg(feature = "engines")]
    Oracle,
    /// `lpe_reference::is_match`, memoized per distinct vertex sequence.
    ReferenceMemo,
    /// `lpe_reference::is_match` on every emitter reached: the verification engine's cost.
    Reference,
}

impl MatcherRow {
    #[cfg(feature = "engines")]
    pub const ALL: [MatcherRow; 5] = [
        MatcherRow::Fast,
        MatcherRow::Nfa,
        MatcherRow::Oracle,
        MatcherRow::ReferenceMemo,
        MatcherRow::Reference,
    ];
    #[cfg(not(feature = "engines"))]
    pub const ALL: [MatcherRow; 4] = [
        MatcherRow::Fast,
        MatcherRow::Nfa,
        MatcherRow::ReferenceMemo,
        MatcherRow::Reference,
    ];

    pub fn name(self) -> &'static str {
        match self {
            MatcherRow::Fast => "fast",
            MatcherRow::Nfa => "nfa",
            #[cfg(feature = "engines")]
            MatcherRow::Oracle => "oracle",
            MatcherRow::ReferenceMemo => "reference-memo",
            MatcherRow::Reference => "reference",
        }
    }

    pub fn render(
        self,
        scene: &Scene,
        aovs: &AovList<RenderMan>,
        lobes: &LobeMap,
        settings: &Settings,
    ) -> Result<Render, RenderError> {
        let lpes = aovs.lpes();
        let fast = |dfa_budget| {
            let opts = lpe::Options {
                dfa_budget,
                ..lpe::Options::default()
            };
            lpe::AovSet::compile_with(&aovs.named(), &opts).map_err(|e| RenderError::Compile {
                reason: e.to_string(),
            })
        };
        use crate::integrator::render_with;
        let quiet = &mut |_: &crate::aov::plan::Plan| {};
        match self {
            MatcherRow::Fast => {
                let set = fast(lpe::Options::default().dfa_budget)?;
                render_with(&set, scene, aovs, lobes, settings, quiet)
            }
            MatcherRow::Nfa => render_with(&fast(0)?, scene, aovs, lobes, settings, quiet),
            #[cfg(feature = "engines")]
            MatcherRow::Oracle => {
                let m = WholePathMatcher::<RenderMan, _>::direct(CheckEngine::new(
                    &lpe_engines::regex::LAZY,
                    &lpes,
                )?);
                render_with(&m, scene, aovs, lobes, settings, quiet)
            }
            MatcherRow::ReferenceMemo => {
                let m = WholePathMatcher::<RenderMan, _>::memoized(Reference::new(&lpes)?);
                render_with(&m, scene, aovs, lobes, settings, quiet)
            }
            MatcherRow::Reference => {
                let m = WholePathMatcher::<RenderMan, _>::direct(Reference::new(&lpes)?);
                render_with(&m, scene, aovs, lobes, settings, quiet)
            }
        }
    }
}
