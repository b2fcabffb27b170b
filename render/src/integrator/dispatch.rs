//! Render dispatch: the one place that picks the matcher a render uses.

use lpe::renderman::LobeMap;
use lpe::AovSet;

use super::settings::{Render, RenderError, Settings};
use super::setup::Integrator;
use crate::aov::matcher::{Reference, ReferenceMatcher, RenderMatcher};
use crate::aov::{AovList, SceneDialect};
use crate::scene::Scene;

/// Renders `scene` with `aovs`.
///
/// ENGINE: the one place that picks the matcher: the fast matcher (`lpe::AovSet`,
/// nothing registered; its lazy DFA takes what the eager one cannot), or, for a set it
/// refuses to compile (over its size limits), the memoized reference matcher with a
/// warning on stderr. Both give the same image; only the time differs.
pub fn render<D: SceneDialect>(
    scene: &Scene,
    aovs: &AovList<D>,
    lobes: &LobeMap,
    settings: &Settings,
) -> Result<Render, RenderError> {
    render_announcing(scene, aovs, lobes, settings, &mut |_| {})
}

/// [`render`], calling `on_plan` with the effects plan once it is decided, before any
/// sample is traced (the CLI prints it).
pub fn render_announcing<D: SceneDialect>(
    scene: &Scene,
    aovs: &AovList<D>,
    lobes: &LobeMap,
    settings: &Settings,
    on_plan: &mut dyn FnMut(&crate::aov::plan::Plan),
) -> Result<Render, RenderError> {
    check_labels::<D>(scene)?;
    match AovSet::<D>::compile(&aovs.named()) {
        Ok(set) => render_with(&set, scene, aovs, lobes, settings, on_plan),
        Err(e) => {
            eprintln!(
                "warning: the fast matcher refused this AOV set ({e}); using the reference matcher"
            );
            let matcher = ReferenceMatcher::<D>::memoized(Reference::new(&aovs.lpes())?);
            render_with(&matcher, scene, aovs, lobes, settings, on_plan)
        }
    }
}

/// The scene's labels, each as the dialect can show it ([`SceneDialect::refused_label`]).
fn check_labels<D: SceneDialect>(scene: &Scene) -> Result<(), RenderError> {
    let objects = scene.objects.iter().filter_map(|o| {
        Some((
            format!("object `{}` lpegroup", o.name),
            o.lpegroup.as_ref()?,
        ))
    });
    let lights = scene
        .lights
        .iter()
        .enumerate()
        .filter_map(|(i, l)| Some((format!("light {i} group"), l.group.as_ref()?)));
    match objects
        .chain(lights)
        .find_map(|(owner, label)| Some((owner, label, D::refused_label(label)?)))
    {
        Some((owner, label, why)) => Err(RenderError::SceneLabel {
            owner,
            label: label.clone(),
            why,
        }),
        None => Ok(()),
    }
}

/// Renders with a given matcher, calling `on_plan` with the effects plan first.
pub fn render_with<M: RenderMatcher>(
    matcher: &M,
    scene: &Scene,
    aovs: &AovList<M::Dialect>,
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
