//! The seam between a renderer and an LPE engine: one incremental matcher trait.
//!
//! A renderer never needs a whole path at once. It classifies every vertex its scene can
//! produce once, at load ([`PathMatcher::classify`]: one [`Class`](PathMatcher::Class)
//! per material lobe, light and camera), then per path carries a small `Copy` state from
//! [`PathMatcher::start`] (before any vertex, the camera included), steps it one vertex
//! at a time ([`PathMatcher::step`]), asks at every emitter which AOVs match
//! ([`PathMatcher::matches`]) and stops tracking a path once no AOV can match any
//! continuation ([`PathMatcher::is_dead`]). [`AovSet`] implements it
//! with one table step per vertex; whole-path engines implement it with a state that
//! records the classes and answer at the emitter.
//!
//! ```
//! use lpe::renderman::{parse, Event, EventKind, Lpe, Vertex, VertexType};
//! use lpe::{AovSet, PathMatcher};
//!
//! /// Routes the two-bounce path of one camera sample, sampling the key light at each
//! /// bounce: the AOV names that receive each light sample.
//! fn route<M: PathMatcher<Vertex = Vertex> + Sync>(m: &M, names: &[String]) -> Vec<Vec<String>> {
//!     // Scene load: classify every material lobe, light and the camera once.
//!     let lobe = |ty, kind, n, group| {
//!         m.classify(&Vertex::scatter(ty, Event::new(kind, n).unwrap(), Some(group)))
//!     };
//!     let floor_diffuse = lobe(VertexType::R, EventKind::D, 2, "floor");
//!     let glass_specular = lobe(VertexType::T, EventKind::S, 8, "glass");
//!     let camera = m.classify(&Vertex::camera());
//!     let key_light = m.classify(&Vertex::light(Some("key")));
//!
//!     // Render threads share the matcher; per path, one step per vertex.
//!     std::thread::scope(|scope| {
//!         let worker = scope.spawn(|| {
//!             let mut routed = Vec::new();
//!             let mut s = m.step(m.start(), camera);
//!             for bounce in [floor_diffuse, glass_specular] {
//!                 s = m.step(s, bounce);
//!                 if m.is_dead(s) {
//!                     break; // no AOV can match any continuation: stop tracking the path
//!                 }
//!                 // Next-event estimation: the state is `Copy`, the path goes on after.
//!                 let hit = m.matches(m.step(s, key_light));
//!                 routed.push(hit.iter().map(|i| names[i].clone()).collect());
//!             }
//!             routed
//!         });
//!         worker.join().unwrap()
//!     })
//! }
//!
//! let aovs: Vec<(String, Lpe)> = ["directDiffuse", "indirectDiffuse", "emissive", "caustics"]
//!     .iter()
//!     .map(|name| (name.to_string(), parse(name).unwrap()))
//!     .collect();
//! let set = AovSet::compile(&aovs).unwrap();
//! assert_eq!(
//!     route(&set, set.names()),
//!     [vec!["directDiffuse"], vec!["indirectDiffuse", "caustics"]]
//! );
//! ```

use crate::aov::{AovSet, Automaton};
use crate::automata::ir::VertexClasses;
use crate::automata::mask::{AovMask, Class, NfaState, State};
use crate::automata::wide::NfaMatcher;
use crate::dialect::Dialect;

/// An incremental LPE matcher over a list of AOVs: AOV `i` is the `i`-th expression the
/// matcher was built from, bit `i` of every [`AovMask`] it returns. See the
/// [module docs](self) for the loop a renderer runs.
pub trait PathMatcher {
    /// The vertex of the matcher's dialect ([`crate::Dialect::Vertex`]).
    type Vertex;
    /// A vertex after classification: compute it once per kind of scene vertex.
    type Class: Copy + Send + Sync;
    /// Where one path is: small, carried per path and copied at every branch.
    type State: Copy + Send;

    /// The class of a vertex.
    fn classify(&self, v: &Self::Vertex) -> Self::Class;
    /// The state before any vertex: step the camera vertex `C` first.
    fn start(&self) -> Self::State;
    /// The state after one more vertex.
    fn step(&self, s: Self::State, c: Self::Class) -> Self::State;
    /// The AOVs whose expression matches the vertices stepped so far as a complete path
    /// (empty unless the last one is an emitter).
    fn matches(&self, s: Self::State) -> AovMask;
    /// No continuation can match any AOV. `false` is always a sound answer: it only
    /// costs the caller the early exit.
    fn is_dead(&self, s: Self::State) -> bool;

    /// The AOVs matching a whole path, given by its vertices: every vertex classified
    /// and stepped from [`PathMatcher::start`].
    fn match_vertices(&self, vertices: &[Self::Vertex]) -> AovMask {
        let s = vertices
            .iter()
            .fold(self.start(), |s, v| self.step(s, self.classify(v)));
        self.matches(s)
    }
}

/// One table step per vertex (see [`AovSet`]).
impl<D: Dialect> PathMatcher for AovSet<D> {
    type Vertex = D::Vertex;
    type Class = Class;
    type State = State;

    #[inline]
    fn classify(&self, v: &D::Vertex) -> Class {
        AovSet::classify(self, v)
    }

    #[inline]
    fn start(&self) -> State {
        Automaton::start(self)
    }

    #[inline]
    fn step(&self, s: State, c: Class) -> State {
        Automaton::step_class(self, s, c)
    }

    #[inline]
    fn matches(&self, s: State) -> AovMask {
        Automaton::matches(self, s)
    }

    #[inline]
    fn is_dead(&self, s: State) -> bool {
        Automaton::is_dead(self, s)
    }
}

/// The bitset NFA on its wide state (see [`NfaMatcher`]).
impl<C: VertexClasses> PathMatcher for NfaMatcher<'_, C> {
    type Vertex = C::Vertex;
    type Class = Class;
    type State = NfaState;

    #[inline]
    fn classify(&self, v: &C::Vertex) -> Class {
        NfaMatcher::classify(self, v)
    }

    #[inline(always)]
    fn start(&self) -> NfaState {
        NfaMatcher::start(self)
    }

    #[inline(always)]
    fn step(&self, s: NfaState, c: Class) -> NfaState {
        NfaMatcher::step(self, s, c)
    }

    #[inline(always)]
    fn matches(&self, s: NfaState) -> AovMask {
        NfaMatcher::matches(self, s)
    }

    #[inline(always)]
    fn is_dead(&self, s: NfaState) -> bool {
        NfaMatcher::is_dead(self, s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aov::Options;
    use crate::renderman::{parse, Lpe, Path};

    /// Through the trait, generically: the same answers as the set's own methods, on
    /// both of the set's engines.
    fn generic_match<M: PathMatcher<Vertex = crate::renderman::Vertex>>(
        m: &M,
        path: &Path,
    ) -> (AovMask, bool) {
        let mut s = m.start();
        let mut died = false;
        for v in path.vertices() {
            s = m.step(s, m.classify(v));
            died |= m.is_dead(s);
        }
        (m.matches(s), died)
    }

    #[test]
    fn aov_set_through_the_trait_agrees_with_its_methods() {
        let srcs = [
            "C<RD>[<L.>O]",
            "C.*D.{3}[LO]",
            "C<RS>+<TD'glass'>?L",
            "CR<CD>L",
        ];
        let aovs: Vec<(String, Lpe)> = srcs
            .iter()
            .map(|s| (s.to_string(), parse(s).unwrap()))
            .collect();
        let paths = [
            "C RD L",
            "C RD RS RS RS L",
            "C RS RS TD'glass' L",
            "C RD O",
            "C TS L",
        ];
        for opts in [
            Options::default(),
            Options {
                dfa_budget: 0,
                ..Options::default()
            },
        ] {
            let set = AovSet::compile_with(&aovs, &opts).unwrap();
            for p in paths {
                let p: Path = p.parse().unwrap();
                let (mask, _) = generic_match(&set, &p);
                assert_eq!(mask, set.match_path(&p), "{p}");
                assert_eq!(PathMatcher::match_vertices(&set, p.vertices()), mask, "{p}");
            }
            let s = PathMatcher::start(&set);
            assert_eq!(s, AovSet::start(&set), "start is before the camera");
            // Every AOV needs a vertex between the camera and the emitter.
            let (mask, died) = generic_match(&set, &"C L".parse().unwrap());
            assert!(mask.is_empty() && died);
            let (mask, died) = generic_match(&set, &"C RD L".parse().unwrap());
            assert!(mask.contains(0) && !died);
        }
    }
}
