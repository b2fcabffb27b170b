//! The benchmark's harness, shared by every dialect's rows ([`crate::renderman`],
//! [`crate::osl`]) and the caller shapes: flattened paths, the timed loop on classes
//! (the automaton alone, the same code for every dialect), the timing discipline, what to
//! run, rows and errors. Nothing here knows a dialect.

use std::hint::black_box;
use std::time::{Duration, Instant};

use lpe::aov::Automaton;
use lpe::{AovMask, AovSet, Class};

use crate::baseline;

/// Paths flattened for the timed loops: one contiguous buffer and path end offsets.
pub struct Flat<T> {
    /// Every path's items, back to back.
    pub items: Vec<T>,
    /// End offset of each path in `items`.
    pub ends: Vec<u32>,
}

impl<T> Flat<T> {
    pub(crate) fn build<P>(paths: &[P], mut f: impl FnMut(&P, &mut Vec<T>)) -> Flat<T> {
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

/// Paths per timed chunk: short enough (a fraction of a millisecond) that some
/// repetition of each chunk runs without being preempted on a shared machine.
pub(crate) const CHUNK_PATHS: usize = 4096;

/// `f` applied to each chunk of paths.
pub(crate) fn chunked<P, T>(paths: &[P], f: impl Fn(&[P]) -> Flat<T>) -> Vec<Flat<T>> {
    paths.chunks(CHUNK_PATHS).map(f).collect()
}

/// A digest of a mask, so the loops' results cannot be optimized away.
#[inline]
pub(crate) fn digest(m: AovMask) -> u64 {
    m.count() as u64 + u64::from(m.contains(0))
}

/// The fast matcher (DFA or NFA) on classes computed beforehand: the automaton alone,
/// the same code for every dialect's set.
pub fn run_classes(set: &Automaton, classes: &Flat<Class>) -> u64 {
    classes.paths().fold(0u64, |acc, p| {
        let s = p.iter().fold(set.start(), |s, &c| set.step_class(s, c));
        acc.wrapping_add(digest(set.matches(s)))
    })
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

impl Config {
    /// Whether the workload named `name` is to run.
    pub fn runs(&self, name: &str) -> bool {
        self.workloads.is_empty() || self.workloads.iter().any(|n| n == name)
    }
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
pub(crate) type Job<'a> = Box<dyn FnMut(usize) -> u64 + 'a>;

/// Times every job on every chunk `reps` times, round-robin so that every engine sees
/// the same machine load, and sums each job's best time per chunk: preemption on this
/// shared machine then only costs a repetition, not the measurement. Each timed run
/// follows an untimed one of the same job on the same chunk, so that every job finds its
/// input in cache (else the job after one with other input pays the misses).
pub(crate) fn best_times(reps: usize, chunks: usize, jobs: &mut [Job<'_>]) -> Vec<Duration> {
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
pub(crate) fn timed_build<T>(mut f: impl FnMut() -> T) -> (T, Duration) {
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

pub(crate) fn row(workload: &str, engine: &str) -> Row {
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
