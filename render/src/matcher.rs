//! The seam between the renderer and an LPE engine.
//!
//! The integrator is generic over [`PathMatcher`]: it classifies every vertex the scene
//! can produce once, before rendering, then per path carries a `Copy` state that it steps
//! one vertex at a time, and at every emitter asks which AOVs match. This is exactly the
//! shape of the fast matcher's API (`lpe::aov::AovSet`: `classify`, `start`,
//! `step_class`, `matches`, `is_dead`), which the renderer uses by default through the
//! thin adapter below.
//!
//! [`ReferenceMatcher`] implements the trait over
//! `reference::is_match`: slow per call, but it memoizes the answer per distinct path
//! (renders revisit the same few vertex sequences millions of times), so the default
//! render stays within budget.

use lpe::{Lpe, Path, Vertex, VertexType};
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hash, Hasher};
use std::sync::Mutex;

/// Most AOVs one render can route to, and the mask of AOVs that match: the fast
/// matcher's own types, shared so engines hand masks over without converting.
pub use lpe::aov::{AovMask, MAX_AOVS};

/// An LPE engine as the integrator uses it. AOV `i` is the `i`-th expression the
/// matcher was built from.
pub trait PathMatcher: Sync {
    /// A vertex after classification (computed once per scene vertex kind).
    type Class: Copy + Send + Sync;
    /// The state of one path: the camera vertex and the vertices stepped since.
    type State: Copy + Send;

    fn classify(&self, v: &Vertex) -> Self::Class;
    /// The state after the camera vertex `C`.
    fn start(&self) -> Self::State;
    fn step(&self, s: Self::State, c: Self::Class) -> Self::State;
    /// AOVs whose expression matches the path stepped so far as a complete path (empty
    /// unless the last vertex is an emitter).
    fn matches(&self, s: Self::State) -> AovMask;
    /// True if no continuation can match any AOV (a sound "maybe alive" is `false`).
    fn is_dead(&self, s: Self::State) -> bool;
}

/// The fast matcher: one automaton for all AOVs, stepped once per vertex on the classes
/// computed at scene setup.
impl PathMatcher for lpe::aov::AovSet {
    type Class = lpe::aov::Class;
    type State = lpe::aov::State;

    fn classify(&self, v: &Vertex) -> Self::Class {
        lpe::aov::AovSet::classify(self, v)
    }

    /// `AovSet::start` is the state before any vertex; ours is after the camera.
    fn start(&self) -> Self::State {
        lpe::aov::AovSet::step(self, lpe::aov::AovSet::start(self), &Vertex::camera())
    }

    fn step(&self, s: Self::State, c: Self::Class) -> Self::State {
        self.step_class(s, c)
    }

    fn matches(&self, s: Self::State) -> AovMask {
        lpe::aov::AovSet::matches(self, s)
    }

    fn is_dead(&self, s: Self::State) -> bool {
        lpe::aov::AovSet::is_dead(self, s)
    }
}

// ---------------------------------------------------------------------------------------

/// Longest path the reference matcher's state holds: camera, up to
/// [`crate::scene::MAX_DEPTH_LIMIT`] scattering vertices, the vertex of an NEE lobe,
/// and the emitter.
pub const REF_MAX_VERTICES: usize = crate::scene::MAX_DEPTH_LIMIT as usize + 3;

/// The reference matcher's path state: the class ids of the vertices after `C`.
#[derive(Clone, Copy, Debug)]
pub struct RefState {
    len: u8,
    ids: [u16; REF_MAX_VERTICES],
}

impl PartialEq for RefState {
    fn eq(&self, o: &Self) -> bool {
        self.ids[..self.len as usize] == o.ids[..o.len as usize]
    }
}

impl Eq for RefState {}

impl Hash for RefState {
    fn hash<H: Hasher>(&self, h: &mut H) {
        self.ids[..self.len as usize].hash(h)
    }
}

/// FxHash (rustc's hasher): the memo keys are short integer sequences, not attacker
/// controlled, so a fast non-cryptographic hash is the right trade.
#[derive(Default)]
struct FxHasher(u64);

impl Hasher for FxHasher {
    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.write_u64(*b as u64);
        }
    }
    fn write_u16(&mut self, x: u16) {
        self.write_u64(x as u64)
    }
    fn write_usize(&mut self, x: usize) {
        self.write_u64(x as u64)
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
    fn finish(&self) -> u64 {
        self.0
    }
}

type Memo = HashMap<RefState, AovMask, BuildHasherDefault<FxHasher>>;

/// Slots of per-thread memo tables: each rayon worker locks its own slot, so lookups do
/// not contend (a collision of two threads on one slot is only slower, never wrong).
const MEMO_SLOTS: usize = 32;

/// [`PathMatcher`] over `reference::is_match`, memoized per distinct path.
pub struct ReferenceMatcher {
    aovs: Vec<Lpe>,
    /// Class id -> vertex; grows during classification (before rendering).
    alphabet: Mutex<Vec<Vertex>>,
    memo: Vec<Mutex<Memo>>,
    /// Answer from the memo (the renderer's default); off, every emitter reached runs
    /// `reference::is_match` (what the verification engine costs, shown by `converge`).
    memoize: bool,
}

impl ReferenceMatcher {
    /// A matcher for these expressions (at most [`MAX_AOVS`]).
    pub fn new(aovs: &[Lpe]) -> Result<ReferenceMatcher, String> {
        if aovs.len() > MAX_AOVS {
            return Err(format!("at most {MAX_AOVS} AOVs, got {}", aovs.len()));
        }
        Ok(ReferenceMatcher {
            aovs: aovs.to_vec(),
            alphabet: Mutex::new(Vec::new()),
            memo: (0..MEMO_SLOTS)
                .map(|_| Mutex::new(Memo::default()))
                .collect(),
            memoize: true,
        })
    }

    /// The same matcher without the memo: every [`PathMatcher::matches`] runs the
    /// reference engine.
    pub fn unmemoized(aovs: &[Lpe]) -> Result<ReferenceMatcher, String> {
        Ok(ReferenceMatcher {
            memoize: false,
            ..ReferenceMatcher::new(aovs)?
        })
    }

    fn compute(&self, s: &RefState) -> AovMask {
        let alphabet = self.alphabet.lock().unwrap_or_else(|e| e.into_inner());
        let mut vertices = Vec::with_capacity(s.len as usize + 1);
        vertices.push(Vertex::camera());
        vertices.extend(
            s.ids[..s.len as usize]
                .iter()
                .map(|&i| alphabet[i as usize].clone()),
        );
        drop(alphabet);
        if !vertices
            .last()
            .is_some_and(|v| matches!(v.ty(), VertexType::L | VertexType::O))
        {
            return AovMask::EMPTY;
        }
        // A sequence the integrator builds is always a well-formed path; if not, no AOV
        // can match it.
        let Ok(path) = Path::new(vertices) else {
            return AovMask::EMPTY;
        };
        (0..self.aovs.len())
            .filter(|&i| reference::is_match(&self.aovs[i], &path))
            .collect()
    }
}

impl PathMatcher for ReferenceMatcher {
    type Class = u16;
    type State = RefState;

    fn classify(&self, v: &Vertex) -> u16 {
        let mut a = self.alphabet.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(i) = a.iter().position(|x| x == v) {
            return i as u16;
        }
        a.push(v.clone());
        // Scenes have at most MAX_LABELS labels, so at most 1025 labels x 24 events x 2
        // types plus emitters: well under 65 536 distinct vertices.
        u16::try_from(a.len() - 1).expect("fewer than 65536 distinct vertices")
    }

    fn start(&self) -> RefState {
        RefState {
            len: 0,
            ids: [0; REF_MAX_VERTICES],
        }
    }

    fn step(&self, mut s: RefState, c: u16) -> RefState {
        // The integrator bounds depth by MAX_DEPTH_LIMIT, so this never truncates.
        if (s.len as usize) < REF_MAX_VERTICES {
            s.ids[s.len as usize] = c;
            s.len += 1;
        }
        s
    }

    fn matches(&self, s: RefState) -> AovMask {
        if !self.memoize {
            return self.compute(&s);
        }
        let slot = rayon::current_thread_index().map_or(0, |i| i + 1) % MEMO_SLOTS;
        let mut memo = self.memo[slot].lock().unwrap_or_else(|e| e.into_inner());
        if let Some(m) = memo.get(&s) {
            return *m;
        }
        let m = self.compute(&s);
        memo.insert(s, m);
        m
    }

    fn is_dead(&self, _: RefState) -> bool {
        // Deciding this needs the automaton; "never dead" is sound.
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mask_iterates_in_order() {
        let m: AovMask = [3, 64, 200, 0].into_iter().collect();
        assert_eq!(m.iter().collect::<Vec<_>>(), vec![0, 3, 64, 200]);
        assert!(m.contains(200) && !m.contains(199));
    }

    #[test]
    fn reference_matcher_agrees_with_is_match() {
        let exprs: Vec<Lpe> = ["C<RD>[<L.>O]", "C<RD>.+[<L.>O]", "C.*<L.'key'>", "CO"]
            .iter()
            .map(|s| lpe::parse(s).unwrap())
            .collect();
        let m = ReferenceMatcher::new(&exprs).unwrap();
        for text in ["C RD2 L'key'", "C RD2 RS1 L", "C O", "C RD2'floor' RD2 O"] {
            let path: Path = text.parse().unwrap();
            let mut s = m.start();
            for v in &path.vertices()[1..] {
                s = m.step(s, m.classify(v));
            }
            let want: AovMask = (0..exprs.len())
                .filter(|&i| reference::is_match(&exprs[i], &path))
                .collect();
            assert_eq!(m.matches(s), want, "{text}");
            assert_eq!(m.matches(s), want, "{text} (memoized)");
        }
    }
}
