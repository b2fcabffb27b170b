//! Render dispatch: the one place that picks the matcher a render uses.

use lpe::renderman::LobeMap;
use lpe::DialectName;

use super::settings::{Render, RenderError, Settings};
use super::setup::Integrator;
use crate::aov::matcher::{Reference, ReferenceMatcher, RenderMatcher};
use crate::aov::osl::is_builtin_label;
use crate::aov::AovList;
use crate::scene::Scene;

/// Renders `scene` with `aovs`.
///
/// ENGINE: the one place that picks the matcher: the fast matcher (`lpe::AovSet`),
/// or, for a RenderMan set it refuses to compile (over its size limits), the memoized
/// reference matcher with a warning on stderr. Both give the same image; only the time
/// differs. An OSL list compiles with `AovSet::compile_osl` (nothing registered), whose
/// lazy DFA takes what the eager one cannot; a set it still refuses is an error.
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
    if aovs.dialect == DialectName::Osl {
        check_osl_labels(scene)?;
        let set = lpe::AovSet::compile_under(
            &aovs.named::<lpe::osl::Osl>(),
            &lpe::osl::Registered::none(),
            &lpe::Options::default(),
        )
        .map_err(|e| RenderError::Compile {
            reason: e.to_string(),
        })?;
        return render_with(&set, scene, aovs, lobes, settings, on_plan);
    }
    match lpe::AovSet::compile(&aovs.named::<lpe::renderman::RenderMan>()) {
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

/// Under OSL a scene label is a custom label, which OSL's eater skips only if it is not
/// a built-in label: a light group `S` would stop `L` from matching its lights. Refused.
fn check_osl_labels(scene: &Scene) -> Result<(), RenderError> {
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
        .find(|(_, label)| is_builtin_label(label))
    {
        Some((owner, label)) => Err(RenderError::OslBuiltinLabel {
            owner,
            label: label.clone(),
        }),
        None => Ok(()),
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
