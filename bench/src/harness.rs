//! The benchmark's harness: flattened paths, one timed loop per engine, the timing
//! discipline, rows and errors. A leaf below the benchmark ([`super::run`]) and its OSL
//! rows and shapes, which all use it.

use std::hint::black_box;
use std::time::{Duration, Instant};

use lpe::aov::Automaton;
use lpe::renderman::{Lpe, Path, Vertex};
use lpe::{AovMask, AovSet, Class};
use regex_automata::dfa::dense;
use regex_automata::hybrid;
use regex_automata::util::primitives::StateID;

use super::baseline;

/// Paths flattened for the timed loops: one contiguous buffer and path end offsets.
pub struct Flat<T> {
    /// Every path's items, back to back.
    pub items: Vec<T>,
    /// End offset of each path in `items`.
    pub ends: Vec<u32>,
}

impl<T> Flat<T> {
    pub(super) fn build<P>(paths: &[P], mut f: impl FnMut(&P, &mut Vec<T>)) -> Flat<T> {
        let mut items = Vec::new();
        let mut ends = Vec::with_capacity(paths.len());
        for p in paths {
            f(p, &mut items);
            ends.push(items.len() as u32);
        }
        Flat { items, ends }
    }

    /// The paths, one slice each.
    pub fn paths(&self) -> impl Iterator<Item = &[T]> + '_ {
        let mut start = 0usize;
        self.ends.iter().map(move |&e| {
            let s = &self.items[start..e as usize];
            start = e as usize;
            s
        })
    }
}

/// Classes of every vertex, for one set of any dialect.
pub fn classify<D: lpe::Dialect>(set: &AovSet<D>, paths: &[D::Path]) -> Flat<Class> {
    Flat::build(paths, |p, out| {
        out.extend(D::vertices(p).iter().map(|v| set.classify(v)))
    })
}

/// The baseline's bytes for every path.
pub fn encode(enc: &baseline::Encoding, paths: &[Path]) -> Flat<u8> {
    Flat::build(paths, |p, out| enc.encode(p, out))
}

/// Paths per timed chunk: short enough (a fraction of a millisecond) that some
/// repetition of each chunk runs without being preempted on a shared machine.
pub(super) const CHUNK_PATHS: usize = 4096;

/// `f` applied to each chunk of paths.
pub(super) fn chunked<P, T>(paths: &[P], f: impl Fn(&[P]) -> Flat<T>) -> Vec<Flat<T>> {
    paths.chunks(CHUNK_PATHS).map(f).collect()
}

/// A digest of a mask, so the loops' results cannot be optimized away.
#[inline]
pub(super) fn digest(m: AovMask) -> u64 {
    m.count() as u64 + u64::from(m.contains(0))
}

/// Every vertex, back to back (labels cloned in order, so they sit in order on the heap
/// too): the vertices a renderer just made are in cache; `Vec<Path>` would add a cache
/// miss per path that no other engine pays.
pub fn flatten(paths: &[Path]) -> Flat<Vertex> {
    Flat::build(paths, |p, out| out.extend(p.vertices().iter().cloned()))
}

/// The fast matcher on vertices (classification included).
pub fn run_vertices(set: &AovSet<lpe::renderman::RenderMan>, vertices: &Flat<Vertex>) -> u64 {
    vertices.paths().fold(0u64, |acc, p| {
        let s = p.iter().fold(set.start(), |s, v| set.step(s, v));
        acc.wrapping_add(digest(set.matches(s)))
    })
}

/// The fast matcher (DFA or NFA) on classes computed beforehand: the automaton alone,
/// the same code for every dialect's set.
pub fn run_classes(set: &Automaton, classes: &Flat<Class>) -> u64 {
    classes.paths().fold(0u64, |acc, p| {
        let s = p.iter().fold(set.start(), |s, &c| set.step_class(s, c));
        acc.wrapping_add(digest(set.matches(s)))
    })
}

/// regex-automata's dense DFA, `next_state` per byte.
pub fn run_dense(dfa: &dense::DFA<Vec<u32>>, start: StateID, bytes: &Flat<u8>) -> u64 {
    bytes.paths().fold(0u64, |acc, p| {
        acc.wrapping_add(digest(baseline::dense_run(dfa, start, p)))
    })
}

/// regex-automata's dense DFA, encoding each path from its vertices first (into a
/// reused buffer): the like-for-like comparison with [`run_vertices`].
pub fn run_dense_encoding(
    dfa: &dense::DFA<Vec<u32>>,
    start: StateID,
    enc: &baseline::Encoding,
    vertices: &Flat<Vertex>,
) -> u64 {
    let mut buf = Vec::with_capacity(64);
    vertices.paths().fold(0u64, |acc, p| {
        buf.clear();
        enc.encode_vertices(p, &mut buf);
        acc.wrapping_add(digest(baseline::dense_run(dfa, start, &buf)))
    })
}

/// regex-automata's lazy DFA; `None` if its cache gave up.
pub fn run_lazy(
    dfa: &hybrid::dfa::DFA,
    cache: &mut hybrid::dfa::Cache,
    bytes: &Flat<u8>,
) -> Option<u64> {
    let mut acc = 0u64;
    for p in bytes.paths() {
        acc = acc.wrapping_add(digest(baseline::lazy_run(dfa, cache, p)?));
    }
    Some(acc)
}

/// The reference matcher, one expression at a time.
pub fn reference_mask(aovs: &[(String, Lpe)], p: &Path) -> AovMask {
    let mut m = AovMask::EMPTY;
    for (i, (_, l)) in aovs.iter().enumerate() {
        if lpe_reference::is_match(l, p) {
            m.insert(i);
        }
    }
    m
}

/// What to run.
#[derive(Clone, Debug)]
pub struct Config {
    /// Total vertices of sampled paths (at least).
    pub vertices: usize,
    /// Paths the reference matcher runs on (and all engines are checked on).
    pub reference_paths: usize,
    /// Timed repetitions per engine; the best counts.
    pub reps: usize,
    /// Sampler seed.
    pub seed: u64,
    /// Workload names to run (all if empty).
    pub workloads: Vec<String>,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            vertices: 1_000_000,
            reference_paths: 20_000,
            reps: 5,
            seed: 1,
            workloads: Vec::new(),
        }
    }
}

/// One table row.
#[derive(Clone, Debug)]
pub struct Row {
    /// Workload name.
    pub workload: String,
    /// Engine and mode.
    pub engine: String,
    /// Nanoseconds per vertex, if it ran.
    pub ns_per_vertex: Option<f64>,
    /// Ratio to the regex-automata dense DFA's ns/vertex.
    pub ratio: Option<f64>,
    /// Build time.
    pub compile: Option<Duration>,
    /// Automaton bytes.
    pub memory: Option<usize>,
    /// Anything to know: size, fallbacks, failures, disagreements.
    pub note: String,
}

/// A timed loop over the paths of one chunk; returns a digest of the answers.
pub(super) type Job<'a> = Box<dyn FnMut(usize) -> u64 + 'a>;

/// Times every job on every chunk `reps` times, round-robin so that every engine sees
/// the same machine load, and sums each job's best time per chunk: preemption on this
/// shared machine then only costs a repetition, not the measurement. Each timed run
/// follows an untimed one of the same job on the same chunk, so that every job finds its
/// input in cache (else the job after one with other input pays the misses).
pub(super) fn best_times(reps: usize, chunks: usize, jobs: &mut [Job<'_>]) -> Vec<Duration> {
    let mut best = vec![vec![Duration::MAX; chunks]; jobs.len()];
    for _ in 0..reps.max(1) {
        for c in 0..chunks {
            for (job, b) in jobs.iter_mut().zip(&mut best) {
                black_box(job(c));
                let t = Instant::now();
                black_box(job(c));
                b[c] = b[c].min(t.elapsed());
            }
        }
    }
    best.into_iter().map(|b| b.into_iter().sum()).collect()
}

/// Builds `f` up to 5 times (fewer if slow), returning the last result and the fastest
/// build time.
pub(super) fn timed_build<T>(mut f: impl FnMut() -> T) -> (T, Duration) {
    let t = Instant::now();
    let mut out = f();
    let mut fastest = t.elapsed();
    let mut spent = fastest;
    for _ in 0..4 {
        if spent > Duration::from_millis(300) {
            break;
        }
        let t = Instant::now();
        out = f();
        let d = t.elapsed();
        fastest = fastest.min(d);
        spent += d;
    }
    (out, fastest)
}

pub(super) fn row(workload: &str, engine: &str) -> Row {
    Row {
        workload: workload.to_string(),
        engine: engine.to_string(),
        ns_per_vertex: None,
        ratio: None,
        compile: None,
        memory: None,
        note: String::new(),
    }
}

/// An engine whose answers differ from the reference's on some checked paths.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{workload}: {engine} disagrees with the reference on {paths} paths")]
pub struct Disagreement {
    /// The workload.
    pub workload: &'static str,
    /// The engine and mode.
    pub engine: String,
    /// How many checked paths it answered differently.
    pub paths: usize,
}

/// Why the benchmark produced no table.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    /// lpe could not compile a workload.
    #[error("{workload}: {error}")]
    Compile {
        /// The workload.
        workload: &'static str,
        /// Why.
        error: lpe::CompileError,
    },
    /// The regex-automata baseline could not be built for a workload.
    #[error("{0}")]
    Baseline(#[from] baseline::BaselineError),
    /// Some engines disagree with the reference (one line each).
    #[error("{}", .0.iter().map(ToString::to_string).collect::<Vec<_>>().join("\n"))]
    Disagree(Vec<Disagreement>),
}
