//! The timed loops that differ in how the caller holds the state, rather than in the
//! engine: the physical limit (a bare chain of dependent table loads of the DFA's
//! shape), a renderer-shaped `for` loop through the public API, a state kept in a
//! heap-allocated path record, the hash-free interned classification, the lazy DFA with
//! the caller's cache, and the bitset NFA on its wide state.

use std::hint::black_box;

use lpe::renderman::{Event, Path, VertexType};
use lpe::rng::SplitMix64;
use lpe::{AovMask, AovSet, Cache, Class, LabelId, PathMatcher};

use super::harness::{digest, Flat};

/// A random transition table with the DFA's shape: `states` rows of `stride` entries
/// (class count rounded up to a power of two), premultiplied row offsets, as
/// `lpe::automata::dfa` lays its table out.
pub struct BareTable {
    table: Vec<u32>,
    /// One mask per row, as the DFA keeps: the chain reads the final state's at each
    /// path's end, like the callers it bounds.
    masks: Vec<AovMask>,
    shift: u32,
    start: u32,
}

impl BareTable {
    /// `states` rows for `classes` classes, drawn from `seed`.
    pub fn new(states: usize, classes: usize, seed: u64) -> BareTable {
        let stride = classes.next_power_of_two();
        let mut rng = SplitMix64::new(seed);
        let states = states.max(1);
        let table = (0..states * stride)
            .map(|_| ((rng.next_u64() % states as u64) as usize * stride) as u32)
            .collect();
        let masks = (0..states)
            .map(|_| AovMask::from_iter((0..8).filter(|_| rng.next_u64().is_multiple_of(4))))
            .collect();
        BareTable {
            table,
            masks,
            shift: stride.trailing_zeros(),
            start: (states.min(2) - 1) as u32 * stride as u32,
        }
    }
}

/// The physical limit of table-driven stepping: `s = table[s + class]` per vertex, the
/// final state's mask read at each path's end.
pub fn run_bare(t: &BareTable, classes: &Flat<Class>) -> u64 {
    let mut acc = 0u64;
    for p in classes.paths() {
        let mut s = t.start;
        for c in p {
            s = t.table[(s + c.index() as u32) as usize];
        }
        acc = acc.wrapping_add(digest(t.masks[(s >> t.shift) as usize]));
    }
    acc
}

/// A renderer's loop: per path, the state in a local, one `PathMatcher::step` per vertex
/// in a plain `for` loop, the mask read at the end.
pub fn run_renderer<M: PathMatcher<Class = Class>>(m: &M, classes: &Flat<Class>) -> u64 {
    let mut acc = 0u64;
    for p in classes.paths() {
        let mut s = m.start();
        for &c in p {
            s = m.step(s, c);
        }
        acc = acc.wrapping_add(digest(m.matches(s)));
    }
    acc
}

/// What a renderer keeps per path between bounces.
struct PathRecord<S> {
    state: S,
    throughput: [f32; 3],
    depth: u32,
}

/// The state in a heap-allocated path record between steps: every path of the chunk has
/// a record in one `Vec`, and each step reads the state from it and writes it back
/// (`black_box` keeps the compiler from holding it in a register, as other work between
/// bounces would).
pub fn run_heap_record<M: PathMatcher<Class = Class>>(m: &M, classes: &Flat<Class>) -> u64 {
    let mut records: Vec<PathRecord<M::State>> = classes
        .ends
        .iter()
        .map(|_| PathRecord {
            state: m.start(),
            throughput: [1.0; 3],
            depth: 0,
        })
        .collect();
    let mut acc = 0u64;
    for (r, p) in records.iter_mut().zip(classes.paths()) {
        for &c in p {
            let r = black_box(&mut *r);
            r.state = m.step(r.state, c);
            r.depth += 1;
        }
        r.throughput[0] *= 0.5;
        acc = acc.wrapping_add(digest(m.matches(r.state)) + u64::from(r.depth));
    }
    acc
}

/// A vertex as a renderer holds it after scene load: type and event from the BSDF lobe,
/// the label interned for the set.
pub type Interned = (VertexType, Option<Event>, LabelId);

/// Every vertex with its label interned for `set`.
pub fn intern(set: &AovSet<lpe::renderman::RenderMan>, paths: &[Path]) -> Flat<Interned> {
    Flat::build(paths, |p, out| {
        out.extend(
            p.vertices()
                .iter()
                .map(|v| (v.ty(), v.event(), set.label_id(v.label()))),
        )
    })
}

/// The fast matcher classifying each vertex from its interned parts, then stepping.
pub fn run_interned(set: &AovSet<lpe::renderman::RenderMan>, vertices: &Flat<Interned>) -> u64 {
    let mut acc = 0u64;
    for p in vertices.paths() {
        let mut s = set.start();
        for &(ty, e, l) in p {
            s = set.step_class(s, set.classify_interned(ty, e, l));
        }
        acc = acc.wrapping_add(digest(set.matches(s)));
    }
    acc
}

/// Stepping with the caller's [`Cache`] (a lazy set's fast path).
pub fn run_cached(
    set: &AovSet<lpe::renderman::RenderMan>,
    cache: &mut Cache,
    classes: &Flat<Class>,
) -> u64 {
    let mut acc = 0u64;
    for p in classes.paths() {
        let mut s = set.start();
        for &c in p {
            s = set.step_with(cache, s, c);
        }
        acc = acc.wrapping_add(digest(set.matches_with(cache, s)));
    }
    acc
}

/// The paths of a chunk as a wavefront renderer holds them: sorted longest first, so that
/// the paths still alive at depth `d` are the first few, with each depth's classes in
/// one array (what a shading stage hands the matcher).
pub struct Wavefront {
    /// Per depth, the classes of the paths alive at it, in sorted order.
    depths: Vec<Vec<Class>>,
    paths: usize,
}

impl Wavefront {
    /// The wavefront of one chunk of classified paths.
    pub fn new(classes: &Flat<Class>) -> Wavefront {
        let mut paths: Vec<&[Class]> = classes.paths().collect();
        paths.sort_by_key(|p| std::cmp::Reverse(p.len()));
        let longest = paths.first().map_or(0, |p| p.len());
        let depths = (0..longest)
            .map(|d| paths.iter().map_while(|p| p.get(d).copied()).collect())
            .collect();
        Wavefront {
            depths,
            paths: paths.len(),
        }
    }
}

/// Every path of the wavefront one depth at a time through [`AovSet::step_batch`], the
/// masks read at the end.
pub fn run_batch(set: &AovSet<lpe::renderman::RenderMan>, wf: &Wavefront) -> u64 {
    let mut states = vec![set.start(); wf.paths];
    for d in &wf.depths {
        set.step_batch(&mut states[..d.len()], d);
    }
    states
        .iter()
        .fold(0u64, |acc, &s| acc.wrapping_add(digest(set.matches(s))))
}
