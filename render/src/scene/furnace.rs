//! What makes a scene the furnace (a closed form the checks compare with, and AOVs the
//! renderer adds for it): below both the AOV list that adds them and the checks.

use super::Scene;
use crate::material::Model;

/// The furnace's parameters `(albedo a, emission Le)` if `scene` is a furnace: one
/// material, one Lambert lobe, grey albedo and glow.
pub fn furnace_params(scene: &Scene) -> Option<(f64, f64)> {
    if scene.name != "furnace" || scene.materials.len() != 1 {
        return None;
    }
    let m = &scene.materials[0];
    let [lobe] = m.lobes.as_slice() else {
        return None;
    };
    let Model::Lambert { albedo } = lobe.model else {
        return None;
    };
    Some((albedo.x as f64, m.glow.x as f64))
}

/// Diffuse bounce counts the furnace AOVs cover.
pub const FURNACE_BOUNCES: u32 = 4;
