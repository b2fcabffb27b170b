//! The RenderMan rows of the benchmark: every workload ([`crate::workload`]) through
//! every engine and caller shape on the sampled paths, each engine's answers checked
//! against the RenderMan reference matcher first, and regex-automata's DFAs on their own
//! encoding ([`crate::baseline`]) as the yardstick of the ratio column. Also the timed
//! loops only RenderMan rows run: on vertices (classification included) and on the
//! baseline's bytes.

use std::hint::black_box;
use std::time::{Duration, Instant};

use lpe::renderman::{Lpe, Path, RenderMan, Vertex};
use lpe::{AovMask, AovSet, Options, PathMatcher};
use regex_automata::dfa::dense;
use regex_automata::hybrid;
use regex_automata::util::primitives::StateID;

use crate::baseline;
use crate::harness::{
    best_times, chunked, classify, digest, row, run_classes, timed_build, BenchError, Config,
    Disagreement, Flat, Job, Row,
};
use crate::shapes;
use crate::workload;

/// The rows of every RenderMan workload `cfg` names, and the engines that disagree with
/// the reference on the first `cfg.reference_paths` of `paths`.
pub fn run(cfg: &Config, paths: &[Path]) -> Result<(Vec<Row>, Vec<Disagreement>), BenchError> {
    let flat = chunked(paths, flatten);
    let vertices: usize = paths.iter().map(Path::len).sum();
    let checked = &paths[..cfg.reference_paths.min(paths.len())];
    let checked_vertices: usize = checked.iter().map(Path::len).sum();
    let ns = |d: Duration, n: usize| d.as_secs_f64() * 1e9 / n as f64;
    let mut rows = Vec::new();
    let mut disagreements = Vec::new();
    for w in workload::all() {
        if !cfg.runs(w.name) {
            continue;
        }
        let aovs = &w.aovs;
        let want: Vec<AovMask> = checked.iter().map(|p| reference_mask(aovs, p)).collect();
        let mut check = |engine: &str, got: &mut dyn FnMut(&Path) -> Option<AovMask>| {
            let bad = checked
                .iter()
                .zip(&want)
                .filter(|(p, w)| got(p).is_some_and(|g| g != **w))
                .count();
            if bad > 0 {
                disagreements.push(Disagreement {
                    workload: w.name,
                    engine: engine.to_string(),
                    paths: bad,
                });
            }
        };

        // Build everything, check it against the reference, then time it.
        let (fast, fast_time) = timed_build(|| AovSet::compile(aovs));
        let fast = fast.map_err(|error| BenchError::Compile {
            workload: w.name,
            error,
        })?;
        check("fast", &mut |p| Some(fast.match_path(p)));
        let fast_classes = chunked(paths, |c| classify(&fast, c));
        let nfa_opts = Options {
            dfa_budget: 0,
            ..Options::default()
        };
        let (nfa_set, nfa_set_time) = timed_build(|| AovSet::compile_with(aovs, &nfa_opts));
        let nfa_set = nfa_set.ok();
        if let Some(set) = &nfa_set {
            check("nfa", &mut |p| Some(set.match_path(p)));
            let mut cache = set.cache();
            check("lazy DFA, own cache", &mut |p| {
                Some(set.match_path_with(&mut cache, p))
            });
            if let Some(wide) = set.nfa() {
                check("bitset NFA", &mut |p| {
                    Some(wide.match_vertices(p.vertices()))
                });
            }
        }
        let interned = chunked(paths, |c| shapes::intern(&fast, c));
        check("fast, on interned vertices", &mut |p| {
            let s = p.vertices().iter().fold(fast.start(), |s, v| {
                let l = fast.label_id(v.label());
                fast.step_class(s, fast.classify_interned(v.ty(), v.event(), l))
            });
            Some(fast.matches(s))
        });
        let wavefronts: Vec<shapes::Wavefront> =
            fast_classes.iter().map(shapes::Wavefront::new).collect();
        let bare = fast
            .dfa_states()
            .map(|n| shapes::BareTable::new(n, fast.class_count(), cfg.seed));
        let nfa_classes = nfa_set.as_ref().map(|s| chunked(paths, |c| classify(s, c)));

        let enc = baseline::Encoding::new(aovs)?;
        let bytes = chunked(paths, |c| encode(&enc, c));
        let (ra_nfa, ra_nfa_time) = timed_build(|| baseline::nfa(&enc, aovs));
        let ra_nfa = ra_nfa?;
        let (dense, dense_time) = timed_build(|| baseline::dense(&ra_nfa));
        let dense = dense.and_then(|d| baseline::dense_start(&d).map(|s| (d, s)));
        if let Ok((dfa, start)) = &dense {
            check("regex-automata dense", &mut |p| {
                let mut b = Vec::new();
                enc.encode(p, &mut b);
                Some(baseline::dense_run(dfa, *start, &b))
            });
        }
        let (lazy, lazy_time) = timed_build(|| baseline::lazy(ra_nfa.clone()));
        let mut lazy = lazy.map(|d| {
            let c = d.create_cache();
            (d, c)
        });
        if let Ok((dfa, cache)) = &mut lazy {
            check("regex-automata lazy", &mut |p| {
                let mut b = Vec::new();
                enc.encode(p, &mut b);
                baseline::lazy_run(dfa, cache, &b)
            });
        }

        let lazy_gave_up = std::cell::Cell::new(false);
        let mut jobs: Vec<Job<'_>> = vec![
            Box::new(|c| run_vertices(&fast, &flat[c])),
            Box::new(|c| shapes::run_interned(&fast, &interned[c])),
            Box::new(|c| run_classes(fast.automaton(), &fast_classes[c])),
            Box::new(|c| shapes::run_renderer(&fast, &fast_classes[c])),
            Box::new(|c| shapes::run_heap_record(&fast, &fast_classes[c])),
        ];
        if let Some(t) = &bare {
            jobs.push(Box::new(|c| shapes::run_bare(t, &fast_classes[c])));
        }
        jobs.push(Box::new(|c| shapes::run_batch(&fast, &wavefronts[c])));
        if !fast.uses_dfa() {
            let mut cache = fast.cache();
            let (set, classes) = (&fast, &fast_classes);
            jobs.push(Box::new(move |c| {
                shapes::run_cached(set, &mut cache, &classes[c])
            }));
        }
        if let (Some(set), Some(classes)) = (&nfa_set, &nfa_classes) {
            let mut cache = set.cache();
            jobs.push(Box::new(move |c| {
                shapes::run_cached(set, &mut cache, &classes[c])
            }));
            if let Some(wide) = set.nfa() {
                jobs.push(Box::new(move |c| shapes::run_renderer(&wide, &classes[c])));
            }
        }
        if let Ok((dfa, start)) = &dense {
            jobs.push(Box::new(|c| run_dense(dfa, *start, &bytes[c])));
            let (enc, flat) = (&enc, &flat);
            jobs.push(Box::new(move |c| {
                run_dense_encoding(dfa, *start, enc, &flat[c])
            }));
        }
        if let Ok((dfa, cache)) = &mut lazy {
            let (bytes, gave_up) = (&bytes, &lazy_gave_up);
            jobs.push(Box::new(move |c| {
                run_lazy(dfa, cache, &bytes[c]).unwrap_or_else(|| {
                    gave_up.set(true);
                    0
                })
            }));
        }
        let mut times = best_times(cfg.reps, flat.len(), &mut jobs).into_iter();
        drop(jobs);

        let mut wrows = Vec::new();
        let mut r = row(w.name, "fast, on vertices");
        r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
        r.compile = Some(fast_time);
        r.memory = Some(fast.memory_bytes());
        r.note = match fast.dfa_states() {
            Some(n) => format!("DFA, {n} states, {} classes", fast.class_count()),
            None => format!("lazy DFA, {} positions", fast.nfa_positions()),
        };
        wrows.push(r);
        let mut r = row(w.name, "fast, on interned vertices");
        r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
        r.note = "labels interned at load: classify_interned, no hashing".into();
        wrows.push(r);
        let mut r = row(w.name, "fast, on classes");
        r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
        if !fast.uses_dfa() {
            r.note = "lazy DFA, the State API's per-thread cache".into();
        }
        wrows.push(r);
        let mut shaped = Vec::new();
        let mut r = row(w.name, "renderer-shaped caller");
        r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
        r.note = "for loop, state in a local, PathMatcher::step".into();
        shaped.push(r);
        let mut r = row(w.name, "state in a heap path record");
        r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
        r.note = "read and written back through memory every step".into();
        shaped.push(r);
        let mut r = row(w.name, "bare dependent-load chain, same table shape");
        let bare_ns = match &bare {
            Some(_) => {
                r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
                r.note = format!(
                    "s = table[s + class], {} rows of {}, mask read at the end",
                    fast.dfa_states().unwrap_or(0),
                    fast.class_count().next_power_of_two()
                );
                r.ns_per_vertex
            }
            None => {
                r.note = "no DFA table".into();
                None
            }
        };
        if let Some(b) = bare_ns {
            for s in &mut shaped {
                if let Some(x) = s.ns_per_vertex {
                    s.note = format!("{}; {:.2}x the bare chain", s.note, x / b);
                }
            }
        }
        wrows.extend(shaped);
        wrows.push(r);
        let mut r = row(w.name, "batch step, wavefront");
        r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
        r.note = "step_batch over the paths alive at each depth".into();
        let one = wrows
            .iter()
            .find(|r| r.engine == "renderer-shaped caller")
            .and_then(|r| r.ns_per_vertex);
        if let (Some(x), Some(one)) = (r.ns_per_vertex, one) {
            r.note = format!("{}; {:.2}x the renderer-shaped caller", r.note, x / one);
        }
        wrows.push(r);
        let mut lazy_rows = Vec::new();
        if !fast.uses_dfa() {
            let mut r = row(w.name, "fast, own cache");
            r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
            r.note = format!(
                "lazy DFA, {} NFA states determinized",
                fast.lazy_states().unwrap_or(0)
            );
            lazy_rows.push(r);
        }
        let mut r = row(w.name, "lazy DFA (dfa_budget 0), own cache");
        let mut r_nfa = row(w.name, "bitset NFA, on classes");
        match &nfa_set {
            Some(set) => {
                r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
                r.compile = Some(nfa_set_time);
                r.memory = Some(set.memory_bytes());
                r.note = format!("{} NFA states determinized", set.lazy_states().unwrap_or(0));
                lazy_rows.push(r);
                if set.nfa().is_some() {
                    r_nfa.ns_per_vertex = times.next().map(|t| ns(t, vertices));
                }
                r_nfa.note = format!("{} positions, wide state", set.nfa_positions());
            }
            None => {
                r_nfa.note = format!(
                    "over the {} positions a stepping state holds",
                    64 * lpe::automata::mask::NFA_STATE_WORDS
                )
            }
        }
        lazy_rows.push(r_nfa);
        wrows.extend(lazy_rows);
        let mut r = row(w.name, "regex-automata dense DFA");
        r.compile = Some(ra_nfa_time + dense_time);
        let dense_ns = match &dense {
            Ok((dfa, _)) => {
                r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
                r.memory = Some(dfa.memory_usage());
                r.note = "on its bytes, encoded beforehand".into();
                r.ns_per_vertex
            }
            Err(e) => {
                r.note = format!("no DFA: {e}");
                None
            }
        };
        wrows.push(r);
        if dense.is_ok() {
            let mut r = row(w.name, "regex-automata dense DFA, encoding included");
            r.ns_per_vertex = times.next().map(|t| ns(t, vertices));
            r.note = "encodes each path from its vertices, like `fast, on vertices`".into();
            wrows.push(r);
        }
        let mut r = row(w.name, "regex-automata lazy DFA");
        r.compile = Some(ra_nfa_time + lazy_time);
        match &lazy {
            Ok((dfa, cache)) => {
                let t = times.next();
                if lazy_gave_up.get() {
                    r.note = "cache gave up".into();
                } else {
                    r.ns_per_vertex = t.map(|t| ns(t, vertices));
                }
                r.memory = Some(dfa.memory_usage() + cache.memory_usage());
            }
            Err(e) => r.note = format!("no lazy DFA: {e}"),
        }
        let lazy_ns = r.ns_per_vertex;
        wrows.push(r);
        // Lazy stepping against its peer, regex-automata's lazy DFA.
        if let Some(l) = lazy_ns {
            for r in wrows.iter_mut().filter(|r| {
                r.engine.ends_with("own cache")
                    || (!fast.uses_dfa() && r.engine == "fast, on classes")
            }) {
                if let Some(x) = r.ns_per_vertex {
                    r.note = format!("{}; {:.2}x RA lazy", r.note, x / l);
                }
            }
        }

        let mut r = row(w.name, "reference, per path");
        let t = Instant::now();
        black_box(checked.iter().fold(0u64, |acc, p| {
            acc.wrapping_add(digest(reference_mask(aovs, p)))
        }));
        r.ns_per_vertex = Some(ns(t.elapsed(), checked_vertices));
        r.note = format!("{} paths", checked.len());
        wrows.push(r);

        for r in &mut wrows {
            r.ratio = match (r.ns_per_vertex, dense_ns) {
                (Some(x), Some(d)) => Some(x / d),
                _ => None,
            };
        }
        rows.extend(wrows);
    }
    Ok((rows, disagreements))
}

/// The baseline's bytes for every path.
pub fn encode(enc: &baseline::Encoding, paths: &[Path]) -> Flat<u8> {
    Flat::build(paths, |p, out| enc.encode(p, out))
}

/// Every vertex, back to back (labels cloned in order, so they sit in order on the heap
/// too): the vertices a renderer just made are in cache; `Vec<Path>` would add a cache
/// miss per path that no other engine pays.
pub fn flatten(paths: &[Path]) -> Flat<Vertex> {
    Flat::build(paths, |p, out| out.extend(p.vertices().iter().cloned()))
}

/// The fast matcher on vertices (classification included).
pub fn run_vertices(set: &AovSet<RenderMan>, vertices: &Flat<Vertex>) -> u64 {
    vertices.paths().fold(0u64, |acc, p| {
        let s = p.iter().fold(set.start(), |s, v| set.step(s, v));
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
