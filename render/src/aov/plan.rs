//! The effects plan: which effects this render simulates, decided from the scene and the
//! AOV list before rendering (and printed), so that a render pays only for what its AOVs
//! can see. `--all-effects` forces every effect on; requested AOVs come out bit-identical
//! either way (tested), because no decision here changes the random numbers a sample
//! draws or the value of any contribution an AOV receives, only whether work whose
//! result no AOV can receive is done.

use serde::Serialize;

use super::dialect::SceneDialect;
use super::list::{Aov, AovList};
use crate::scene::Scene;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Plan {
    /// Step the matcher at all (some AOV is requested).
    pub matching: bool,
    /// Classify vertices with their labels (some expression names a label); without,
    /// label-free expressions see fewer distinct vertices.
    pub labels: bool,
    /// Emit user-lobe pseudo paths `C <R Un> L` at camera hits (some AOV matches one).
    pub user_lobes: bool,
    /// Evaluate occluded light samples too (some AOV is `unoccluded;` or `shadows;`).
    pub unshadowed: bool,
    /// Consider lights behind the surface (some material transmits); otherwise light
    /// samples below the shading hemisphere are dropped before the shadow ray.
    pub transmission: bool,
    /// Track whether a path touched a holdout object (the scene has one).
    pub holdouts: bool,
    /// Stop a path when its matcher state is dead for every AOV (beauty not needed).
    pub stop_dead: bool,
}

impl Plan {
    /// The plan the scene and AOVs call for. `user_lobes` is settled later, by asking
    /// the matcher whether any AOV matches a pseudo path the scene can produce.
    pub fn derive<D: SceneDialect>(scene: &Scene, aovs: &AovList<D>, beauty: bool) -> Plan {
        let any = |f: &dyn Fn(&Aov<D>) -> bool| aovs.aovs.iter().any(f);
        Plan {
            matching: !aovs.aovs.is_empty(),
            labels: any(&|a| D::names_labels(&a.expr)),
            user_lobes: true,
            unshadowed: any(&|a| a.flags.unoccluded || a.flags.shadows),
            transmission: scene.materials.iter().any(|m| m.transmits()),
            holdouts: scene.objects.iter().any(|o| o.holdout),
            stop_dead: !beauty && !aovs.aovs.is_empty(),
        }
    }

    /// Every effect on: the generic path.
    pub fn all_effects<D: SceneDialect>(aovs: &AovList<D>) -> Plan {
        Plan {
            matching: !aovs.aovs.is_empty(),
            labels: true,
            user_lobes: true,
            unshadowed: true,
            transmission: true,
            holdouts: true,
            stop_dead: false,
        }
    }

    /// One line per effect, for the console and the report.
    pub fn describe(&self) -> Vec<String> {
        let on = |b: bool| if b { "on " } else { "off" };
        vec![
            format!("{} LPE matching (AOVs requested)", on(self.matching)),
            format!(
                "{} vertex labels (an expression names a label)",
                on(self.labels)
            ),
            format!(
                "{} user-lobe pseudo paths C<RUn>L (an AOV matches one)",
                on(self.user_lobes)
            ),
            format!(
                "{} unshadowed light evaluation (unoccluded/shadows AOVs)",
                on(self.unshadowed)
            ),
            format!(
                "{} lights behind surfaces (a material transmits)",
                on(self.transmission)
            ),
            format!(
                "{} holdout tracking (a holdout object exists)",
                on(self.holdouts)
            ),
            format!(
                "{} stop paths dead for every AOV (beauty not requested)",
                on(self.stop_dead)
            ),
        ]
    }
}
