//! Render dispatch: the one place that picks the matcher a render uses.

use lpe::LobeMap;

use super::{Integrator, Render, RenderError, Settings};
use crate::aov::matcher::{Reference, ReferenceMatcher, RenderMatcher};
use crate::aov::AovList;
use crate::scene::Scene;

/// Renders `scene` with `aovs`.
///
/// ENGINE: the one place that picks the matcher: the fast matcher (`lpe::AovSet`),
/// or, for a set it refuses to compile (over its size limits), the memoized reference
/// matcher with a warning on stderr. Both give the same image; only the time differs.
pub fn render(
    scene: &Scene,
    aovs: &AovList,
    lobes: &LobeMap,
    settings: &Settings,
) -> Result<Render, RenderError> {
    render_announcing(scene, aovs, lobes, settings, &mut |_| {})
}

/// [`render`], calling `on_plan` with the effects plan once it is decided, before any
/// sample is traced (the CLI prints it).
pub fn render_announcing(
    scene: &Scene,
    aovs: &AovList,
    lobes: &LobeMap,
    settings: &Settings,
    on_plan: &mut dyn FnMut(&crate::aov::plan::Plan),
) -> Result<Render, RenderError> {
    match lpe::AovSet::compile(&aovs.named()) {
        Ok(set) => render_with(&set, scene, aovs, lobes, settings, on_plan),
        Err(e) => {
            eprintln!(
                "warning: the fast matcher refused this AOV set ({e}); using the reference matcher"
            );
            let matcher = ReferenceMatcher::memoized(Reference::new(&aovs.lpes())?);
            render_with(&matcher, scene, aovs, lobes, settings, on_plan)
        }
    }
}

/// Renders with a given matcher, calling `on_plan` with the effects plan first.
pub fn render_with<M: RenderMatcher>(
    matcher: &M,
    scene: &Scene,
    aovs: &AovList,
    lobes: &LobeMap,
    settings: &Settings,
    on_plan: &mut dyn FnMut(&crate::aov::plan::Plan),
) -> Result<Render, RenderError> {
    let integrator = Integrator::new(scene, aovs, matcher, lobes, settings);
    on_plan(&integrator.plan());
    integrator.render()
}

/// Name of the engine [`render`] uses, for reports.
pub const ENGINE: &str = "fast (lpe::aov::AovSet; reference if the set cannot compile)";
