//! The renderer's matchers behind `lpe::PathMatcher`, the seam the integrator is generic
//! over (each in one dialect `D`, written once for every dialect): it classifies every
//! vertex the scene can produce once, before rendering, then per path carries a `Copy`
//! state from `start` (before any vertex: the integrator steps the camera itself) one
//! vertex at a time, and at every emitter asks which AOVs match.
//! The fast matcher (`lpe::AovSet`) implements it in `lpe`; this module adds the
//! whole-path engines.
//!
//! Engines that only judge whole paths plug in through [`WholePathMatcher`]: its state
//! records the vertices, and at an emitter the engine ([`WholePath`]) answers for the
//! whole path. [`ReferenceMatcher`] does this with `lpe_reference::is_match`, memoized per
//! distinct path (renders revisit the same few vertex sequences millions of times) so
//! a render on the fallback stays within budget; `CheckEngine` (feature `engines`) does
//! it with any engine of the `lpe-engines` registry, which is how `converge` times the
//! regex-automata engine (`oracle`).

use lpe_reference::lpe_tree::ReferenceMatch;

use super::dialect::{SceneClassifier, SceneDialect};
use std::hash::{Hash, Hasher};
use std::sync::{Mutex, RwLock};

/// Most AOVs one render can route to, the mask of AOVs that match, and the matcher
/// trait: lpe's own, shared so engines hand masks over without converting.
pub use lpe::{AovMask, PathMatcher, MAX_AOVS};

/// What the integrator needs of a matcher: one shared by every render worker, whose
/// states compare (the film sums a pixel's contributions per final state and asks
/// [`PathMatcher::matches`] once per state), and which classifies the renderer's
/// vertices in its dialect ([`SceneClassifier`]). Every such matcher is one.
pub trait RenderMatcher: PathMatcher<State: PartialEq> + SceneClassifier + Sync {}

impl<M: PathMatcher<State: PartialEq> + SceneClassifier + Sync> RenderMatcher for M {}

/// Why a whole-path matcher could not be built.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum MatcherError {
    #[error("at most {max} AOVs, got {count}")]
    TooMany { count: usize, max: usize },
    #[error("{engine}: {reason}")]
    Engine {
        engine: &'static str,
        reason: String,
    },
}

// ---------------------------------------------------------------------------------------

/// Longest path the reference matcher's state holds: camera, up to
/// [`crate::scene::MAX_DEPTH_LIMIT`] scattering vertices, the vertex of an NEE lobe,
/// and the emitter.
pub const REF_MAX_VERTICES: usize = crate::scene::MAX_DEPTH_LIMIT as usize + 3;

/// The reference matcher's path state: the class ids of the vertices stepped, the
/// camera's first.
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
        // One hasher step per id (a `[u16]` slice would reach `write` as bytes: one
        // step per byte); equal states have equal lengths, so no length prefix.
        for &id in &self.ids[..self.len as usize] {
            h.write_u16(id);
        }
    }
}

/// FxHash (rustc's hasher, lpe's copy): the memo keys are short integer sequences, not
/// attacker controlled, so a fast non-cryptographic hash is the right trade.
type Memo = lpe::fxhash::FxMap<RefState, AovMask>;

/// Slots of per-thread tables (memo, compiled engines): each rayon worker locks its own
/// slot, so lookups do not contend (a collision of two threads on one slot is only
/// slower, never wrong).
const SLOTS: usize = 32;

fn thread_slot() -> usize {
    rayon::current_thread_index().map_or(0, |i| i + 1) % SLOTS
}

/// An engine that answers for whole paths of dialect `D` only (it cannot be stepped per
/// vertex): which AOVs match `path`, a complete path ending at an emitter.
pub trait WholePath<D: SceneDialect>: Sync {
    fn which(&self, path: &D::Path) -> AovMask;
}

/// The reference matcher on each expression, each read once by the reference's own
/// front end (from lpe's print) when the engine is built, not per path.
pub struct Reference<D: SceneDialect>(Vec<<D::Lpe as ReferenceMatch>::Tree>);

impl<D: SceneDialect> Reference<D> {
    /// The reference engine for these expressions (at most [`MAX_AOVS`]).
    pub fn new(aovs: &[D::Lpe]) -> Result<Reference<D>, MatcherError> {
        check_count(aovs)?;
        Ok(Reference(
            aovs.iter().map(ReferenceMatch::reference_tree).collect(),
        ))
    }
}

impl<D: SceneDialect> WholePath<D> for Reference<D> {
    fn which(&self, path: &D::Path) -> AovMask {
        (0..self.0.len())
            .filter(|&i| D::Lpe::tree_matches(&self.0[i], path))
            .collect()
    }
}

fn check_count<L>(aovs: &[L]) -> Result<(), MatcherError> {
    match aovs.len() {
        n if n > MAX_AOVS => Err(MatcherError::TooMany {
            count: n,
            max: MAX_AOVS,
        }),
        _ => Ok(()),
    }
}

/// An engine of the `lpe-engines` registry, e.g. the regex-automata engine (`oracle`).
/// Its compiled matchers keep a mutable cache (the lazy DFA), so each thread slot
/// compiles its own on first use.
#[cfg(feature = "engines")]
pub struct CheckEngine<D: lpe_engines::EngineDialect> {
    engine: &'static dyn lpe_engines::Engine<D>,
    aovs: Vec<D::Lpe>,
    compiled: Vec<Mutex<Option<Box<dyn lpe_engines::Matcher<D>>>>>,
}

#[cfg(feature = "engines")]
impl<D: lpe_engines::EngineDialect> CheckEngine<D> {
    /// Compiles `aovs` with `engine` once up front (nothing registered), so an engine
    /// that cannot build the set says so here and not mid-render.
    pub fn new(
        engine: &'static dyn lpe_engines::Engine<D>,
        aovs: &[D::Lpe],
    ) -> Result<CheckEngine<D>, MatcherError> {
        check_count(aovs)?;
        let first = engine
            .compile(aovs, &D::Registration::default())
            .map_err(|e| MatcherError::Engine {
                engine: engine.name(),
                reason: e.to_string(),
            })?;
        let mut compiled: Vec<_> = (0..SLOTS).map(|_| Mutex::new(None)).collect();
        compiled[0] = Mutex::new(Some(first));
        Ok(CheckEngine {
            engine,
            aovs: aovs.to_vec(),
            compiled,
        })
    }
}
#[cfg(feature = "engines")]
impl<D: lpe_engines::EngineDialect + SceneDialect> WholePath<D> for CheckEngine<D> {
    fn which(&self, path: &D::Path) -> AovMask {
        let mut slot = self.compiled[thread_slot()]
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        let m = slot.get_or_insert_with(|| {
            self.engine
                .compile(&self.aovs, &D::Registration::default())
                .expect("the engine compiled this set in CheckEngine::new")
        });
        m.which(path)
    }
}

/// [`PathMatcher`] over a [`WholePath`] engine of dialect `D`: the state records the
/// path's vertices, and at an emitter the engine judges the whole path, optionally
/// memoized per distinct vertex sequence.
pub struct WholePathMatcher<D: SceneDialect, W> {
    engine: W,
    /// Class id -> vertex; grows during classification (before rendering), then only
    /// read, by every thread at every emitter: a read lock does not serialize them.
    alphabet: RwLock<Vec<D::Vertex>>,
    memo: Vec<Mutex<Memo>>,
    /// Answer from the memo (the renderer's default); off, every emitter reached runs
    /// the engine (what the verification engines cost, shown by `converge`).
    memoize: bool,
}

/// The reference engine memoized: the renderer's fallback when the fast matcher
/// cannot build a set.
pub type ReferenceMatcher<D> = WholePathMatcher<D, Reference<D>>;

impl<D: SceneDialect, W: WholePath<D>> WholePathMatcher<D, W> {
    /// Answers each distinct path once.
    pub fn memoized(engine: W) -> WholePathMatcher<D, W> {
        WholePathMatcher {
            engine,
            alphabet: RwLock::new(Vec::new()),
            memo: (0..SLOTS).map(|_| Mutex::new(Memo::default())).collect(),
            memoize: true,
        }
    }

    /// Runs the engine at every emitter reached.
    pub fn direct(engine: W) -> WholePathMatcher<D, W> {
        WholePathMatcher {
            memoize: false,
            ..WholePathMatcher::memoized(engine)
        }
    }

    fn compute(&self, s: &RefState) -> AovMask {
        let alphabet = self.alphabet.read().unwrap_or_else(|e| e.into_inner());
        let mut vertices = Vec::with_capacity(s.len as usize);
        vertices.extend(
            s.ids[..s.len as usize]
                .iter()
                .map(|&i| alphabet[i as usize].clone()),
        );
        drop(alphabet);
        // A sequence the integrator asks about is always a whole path; if not, no AOV
        // can match it.
        match D::whole_path(vertices) {
            Some(path) => self.engine.which(&path),
            None => AovMask::EMPTY,
        }
    }
}

impl<D: SceneDialect, W: WholePath<D>> PathMatcher for WholePathMatcher<D, W> {
    type Vertex = D::Vertex;
    type Class = u16;
    type State = RefState;

    fn classify(&self, v: &D::Vertex) -> u16 {
        let mut a = self.alphabet.write().unwrap_or_else(|e| e.into_inner());
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
        let mut memo = self.memo[thread_slot()]
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        *memo.entry(s).or_insert_with(|| self.compute(&s))
    }

    fn is_dead(&self, _: RefState) -> bool {
        // Deciding this needs the automaton; "never dead" is sound.
        false
    }
}

impl<D: SceneDialect, W: WholePath<D>> SceneClassifier for WholePathMatcher<D, W> {
    type Dialect = D;
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::{Lpe, Path, RenderMan, Vertex};

    #[test]
    fn mask_iterates_in_order() {
        let m: AovMask = [3, 64, 200, 0].into_iter().collect();
        assert_eq!(m.iter().collect::<Vec<_>>(), vec![0, 3, 64, 200]);
        assert!(m.contains(200) && !m.contains(199));
    }

    /// Steps `m` along each path and compares its answer (twice: a memo must not
    /// change it) with `lpe_reference::is_match` per expression.
    fn agrees_with_is_match(
        m: &(impl PathMatcher<Vertex = Vertex> + Sync),
        exprs: &[Lpe],
        paths: &[&str],
    ) {
        for text in paths {
            let path: Path = text.parse().unwrap();
            let mut s = m.start();
            for v in path.vertices() {
                s = m.step(s, m.classify(v));
            }
            let want: AovMask = (0..exprs.len())
                .filter(|&i| lpe_reference::is_match(&exprs[i], &path))
                .collect();
            assert_eq!(m.matches(s), want, "{text}");
            assert_eq!(m.matches(s), want, "{text} (again)");
        }
    }

    const EXPRS: [&str; 5] = [
        "C<RD>[<L.>O]",
        "C<RD>.+[<L.>O]",
        "C.*<L.'key'>",
        "CO",
        "C[^<RS>]*<L.[^'key']>",
    ];
    const PATHS: [&str; 6] = [
        "C RD2 L'key'",
        "C RD2 RS1 L",
        "C O",
        "C RD2'floor' RD2 O",
        "C TD1 RD2 L'fill'",
        "C RS1 L'key'",
    ];

    fn exprs() -> Vec<Lpe> {
        EXPRS
            .iter()
            .map(|s| lpe::renderman::parse(s).unwrap())
            .collect()
    }

    #[test]
    fn reference_matcher_agrees_with_is_match() {
        let exprs = exprs();
        let m = ReferenceMatcher::<RenderMan>::memoized(Reference::new(&exprs).unwrap());
        agrees_with_is_match(&m, &exprs, &PATHS);
    }

    #[test]
    fn the_reference_matcher_judges_osl_paths_like_is_match() {
        let none = lpe::osl::Registered::none();
        let exprs: Vec<lpe::osl::Lpe> = ["C<RD>[LO]", "C.*<L.'key'>", "C<.G>.*[LO]", "CO"]
            .iter()
            .map(|s| lpe::osl::parse(s, &none).unwrap())
            .collect();
        let m = ReferenceMatcher::<lpe::osl::Osl>::memoized(Reference::new(&exprs).unwrap());
        for (text, want) in [
            ("C,~ R,D L,~,key", vec![0, 1]),
            ("C,~ R,G R,D L,~", vec![2]),
            ("C,~ O,~", vec![3]),
            ("C,~ T,S L,~,fill", vec![]),
        ] {
            let path: lpe::osl::Path = text.parse().unwrap();
            let mut s = m.start();
            for v in &path.vertices {
                s = m.step(s, m.classify(v));
            }
            let want: AovMask = want.into_iter().collect();
            assert_eq!(m.matches(s), want, "{text}");
        }
    }

    #[cfg(feature = "engines")]
    #[test]
    fn the_oracle_through_check_engine_agrees_with_is_match_on_every_thread() {
        let exprs = exprs();
        let m = WholePathMatcher::direct(
            CheckEngine::<RenderMan>::new(&lpe_engines::regex::LAZY, &exprs).unwrap(),
        );
        // Slot 0 holds the matcher compiled up front; rayon workers compile their own.
        agrees_with_is_match(&m, &exprs, &PATHS);
        rayon::scope(|s| {
            for _ in 0..4 {
                s.spawn(|_| agrees_with_is_match(&m, &exprs, &PATHS));
            }
        });
    }

    #[test]
    fn too_many_aovs_is_an_error_for_every_whole_path_engine() {
        let many = vec![lpe::renderman::parse("CL").unwrap(); MAX_AOVS + 1];
        assert!(Reference::<RenderMan>::new(&many).is_err());
        #[cfg(feature = "engines")]
        assert!(CheckEngine::<RenderMan>::new(&lpe_engines::regex::LAZY, &many).is_err());
    }
}
