//! Contributions: the hand-over of each contribution (its path's AOV mask) to the film,
//! from the vertices classified once for the matcher ([`super::setup::Vertices`]).

use super::setup::{Integrator, UserSignal};
use crate::aov::matcher::RenderMatcher;
use crate::film::{Contribution, SampleValues, Strategy};
use crate::geometry::Hit;
use crate::material::Material;
use glam::Vec3;

/// The per-path state the integrator carries from vertex to vertex.
pub(super) struct PathState<S> {
    pub(super) matcher: S,
    /// Throughput to reach the last scattering vertex.
    pub(super) beta: Vec3,
    /// `f cos / (p_pick pdf) / q` of the last scattering vertex.
    pub(super) bounce: Vec3,
    /// The last scattering vertex, for MIS: position and BSDF-strategy density
    /// (`None` after the camera or a delta lobe: light sampling could not compete).
    pub(super) prev: Option<(Vec3, f32)>,
    pub(super) holdout: bool,
}

/// What one worker accumulates for the camera sample it traces: the sample's values
/// and the rays cast.
pub(super) struct Tally<K> {
    pub(super) values: SampleValues<K>,
    pub(super) rays: u64,
}

impl<M: RenderMatcher> Integrator<'_, M> {
    /// Hands a contribution whose complete path ended in matcher state `state` to the
    /// sample's values.
    pub(super) fn splat(&self, state: M::State, c: &Contribution, acc: &mut Tally<M::State>) {
        acc.values
            .add(&self.weighting, c, state, |s| self.matcher.matches(s));
    }

    /// The path reached an emitter of radiance `le` through vertex class `class`.
    pub(super) fn arrive(
        &self,
        path: &PathState<M::State>,
        class: M::Class,
        le: Vec3,
        strategy: Strategy,
        holdout: bool,
        acc: &mut Tally<M::State>,
    ) {
        let state = if self.plan.matching {
            self.matcher.step(path.matcher, class)
        } else {
            path.matcher
        };
        let c = Contribution {
            beta: path.beta,
            local: path.bounce * le,
            strategy,
            holdout,
        };
        self.splat(state, &c, acc);
    }

    /// User-lobe pseudo paths `C <R Un> L` at a camera hit: material properties, not
    /// light transport (never in beauty).
    pub(super) fn user_lobes(&self, hit: &Hit, mat: &Material, acc: &mut Tally<M::State>) {
        for &(signal, mask) in &self.vertices.user[hit.object as usize] {
            let value = match signal {
                UserSignal::Albedo => mat.albedo(),
                UserSignal::Position => hit.p,
                UserSignal::Normal => hit.n,
            }
            .as_dvec3();
            for i in mask.iter() {
                acc.values.add_signal(&self.weighting, i, value);
            }
        }
    }
}
