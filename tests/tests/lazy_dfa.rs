//! Sets over the DFA budget step a lazy DFA (`lpe::automata::lazy`): a registry of NFA
//! states shared by the set, and per-thread transition caches that are cleared when
//! full. Checked against the reference matcher (expected answers never come from lpe):
//! - states in flight survive cache clears (many paths stepped round-robin through one
//!   tiny cache, so every path's state crosses many clears);
//! - one cache handed from one set to another answers for the new set;
//! - threads stepping one set concurrently, each with its own cache, agree;
//! - two sets stepped in lockstep through the State API's per-thread cache agree;
//! - the wide-state NFA matcher and the hash-free interned classification agree;
//! - a blow-up set goes lazy without a long eager attempt first;
//! - `step_batch` (a wavefront of paths, one step each) answers per path.

use lpe::renderman::macros::BASIC;
use lpe::renderman::{parse, Lpe, Path, Vertex};
use lpe::rng::SplitMix64;
use lpe::{AovMask, AovSet, Class, Options, PathMatcher, State};
use lpe_tests::{named, vertex_pool};

fn lazy(cache: usize) -> Options {
    Options {
        dfa_budget: 0,
        lazy_cache: cache,
        ..Options::default()
    }
}

/// Basic AOVs, label AOVs and a blow-up shape, so that paths reach many NFA states.
fn exprs() -> Vec<Lpe> {
    let mut srcs: Vec<String> = BASIC.iter().map(|(_, s)| s.to_string()).collect();
    srcs.extend(
        [
            "C.*D.{6}[LO]",
            "C<.D'floor'>.*[<L.>O]",
            "C[^'glass']+<L.>",
            "C(<RS>|<TS>)*<RD>.{0,3}L",
        ]
        .map(String::from),
    );
    srcs.iter().map(|s| parse(s).unwrap()).collect()
}

/// Random camera-to-emitter paths over the pool, 0..=`max_bounces` scattering vertices.
fn random_paths(seed: u64, n: usize, max_bounces: usize) -> Vec<Path> {
    let pool = vertex_pool();
    let scatter: Vec<&Vertex> = pool.iter().filter(|v| v.ty().is_scattering()).collect();
    let emit: Vec<&Vertex> = pool
        .iter()
        .filter(|v| !v.ty().is_scattering() && v.event().is_none() && **v != Vertex::camera())
        .collect();
    let mut rng = SplitMix64::new(seed);
    let mut pick = |k: usize| (rng.next_u64() % k as u64) as usize;
    (0..n)
        .map(|_| {
            let mut vs = vec![Vertex::camera()];
            for _ in 0..pick(max_bounces + 1) {
                vs.push(scatter[pick(scatter.len())].clone());
            }
            vs.push(emit[pick(emit.len())].clone());
            Path::new(vs).unwrap()
        })
        .collect()
}

fn reference_mask(exprs: &[Lpe], p: &Path) -> AovMask {
    exprs
        .iter()
        .enumerate()
        .filter(|(_, e)| lpe_reference::is_match(e, p))
        .map(|(i, _)| i)
        .collect()
}

#[test]
fn states_in_flight_survive_cache_clears() {
    let exprs = exprs();
    let paths = random_paths(1, 400, 10);
    let want: Vec<AovMask> = paths.iter().map(|p| reference_mask(&exprs, p)).collect();
    assert!(
        want.iter().filter(|m| !m.is_empty()).count() >= 40,
        "too few matching paths to mean anything"
    );
    // One byte of budget: the cache holds its minimum of two rows.
    let set = AovSet::compile_with(&named(&exprs), &lazy(1)).unwrap();
    assert!(!set.uses_dfa());
    let mut cache = set.cache();
    let classes: Vec<Vec<Class>> = paths
        .iter()
        .map(|p| p.vertices().iter().map(|v| set.classify(v)).collect())
        .collect();
    // Round-robin: one step of every live path, then the next step of each.
    let mut states: Vec<State> = vec![set.start(); paths.len()];
    let longest = classes.iter().map(Vec::len).max().unwrap();
    for i in 0..longest {
        for (s, cs) in states.iter_mut().zip(&classes) {
            if let Some(&c) = cs.get(i) {
                *s = set.step_with(&mut cache, *s, c);
            }
        }
    }
    assert!(cache.clears() > 100, "{} clears", cache.clears());
    assert!(cache.rows() <= 2, "{} rows", cache.rows());
    for ((p, s), w) in paths.iter().zip(&states).zip(&want) {
        assert_eq!(set.matches_with(&mut cache, *s), *w, "{p}");
        // The State API (its own per-thread cache) reads the same state alike.
        assert_eq!(set.matches(*s), *w, "{p}");
    }
}

#[test]
fn a_cache_moved_to_another_set_answers_for_it() {
    let exprs = exprs();
    let (a, b) = exprs.split_at(5);
    let paths = random_paths(2, 300, 8);
    let sa = AovSet::compile_with(&named(a), &lazy(64 << 10)).unwrap();
    let sb = AovSet::compile_with(&named(b), &lazy(64 << 10)).unwrap();
    let mut cache = sa.cache();
    for p in &paths {
        for (set, exprs) in [(&sa, a), (&sb, b)] {
            let s = p.vertices().iter().fold(set.start(), |s, v| {
                set.step_with(&mut cache, s, set.classify(v))
            });
            assert_eq!(
                set.matches_with(&mut cache, s),
                reference_mask(exprs, p),
                "{p}"
            );
        }
    }
    // A clone has its own registry: the original's cache is reset for it, not misread.
    let sc = sa.clone();
    for p in &paths {
        let s = p.vertices().iter().fold(sc.start(), |s, v| {
            sc.step_with(&mut cache, s, sc.classify(v))
        });
        assert_eq!(sc.matches_with(&mut cache, s), reference_mask(a, p), "{p}");
    }
}

#[test]
fn two_lazy_sets_share_one_threads_state_api_cache() {
    // The State API keeps one cache per thread: stepping two lazy sets in lockstep on
    // one thread hands it back and forth at every step, and neither may read the
    // other's rows.
    let exprs = exprs();
    let (a, b) = exprs.split_at(5);
    let sa = AovSet::compile_with(&named(a), &lazy(64 << 10)).unwrap();
    let sb = AovSet::compile_with(&named(b), &lazy(64 << 10)).unwrap();
    for p in random_paths(5, 300, 8) {
        let (mut s, mut t) = (sa.start(), sb.start());
        for v in p.vertices() {
            s = sa.step_class(s, sa.classify(v));
            t = sb.step_class(t, sb.classify(v));
        }
        assert_eq!(sa.matches(s), reference_mask(a, &p), "{p}");
        assert_eq!(sb.matches(t), reference_mask(b, &p), "{p}");
    }
    // And one set alone, so that its steps hit the thread's cache.
    for p in random_paths(6, 300, 8) {
        assert_eq!(sa.match_path(&p), reference_mask(a, &p), "{p}");
    }
}

#[test]
fn threads_share_one_lazy_set() {
    let exprs = exprs();
    let set = AovSet::compile_with(&named(&exprs), &lazy(16 << 10)).unwrap();
    std::thread::scope(|scope| {
        for t in 0..4 {
            let (set, exprs) = (&set, &exprs);
            scope.spawn(move || {
                let mut cache = set.cache();
                for p in random_paths(10 + t, 300, 10) {
                    let s = p.vertices().iter().fold(set.start(), |s, v| {
                        set.step_with(&mut cache, s, set.classify(v))
                    });
                    assert_eq!(set.matches_with(&mut cache, s), reference_mask(exprs, &p));
                    // The plain State API steps through this thread's own cache.
                    assert_eq!(set.match_path(&p), reference_mask(exprs, &p), "{p}");
                }
            });
        }
    });
    assert!(set.lazy_states().unwrap() > 10);
}

#[test]
fn the_wide_nfa_and_interned_classes_agree_with_the_reference() {
    let exprs = exprs();
    let lazy_set = AovSet::compile_with(&named(&exprs), &lazy(0)).unwrap();
    let wide = lazy_set.nfa().expect("a lazy set keeps its NFA");
    let dfa_set = AovSet::compile(&named(&exprs)).unwrap();
    assert!(dfa_set.uses_dfa() && dfa_set.nfa().is_none());
    for p in random_paths(3, 500, 10) {
        let want = reference_mask(&exprs, &p);
        assert_eq!(wide.match_vertices(p.vertices()), want, "{p}");
        for set in [&lazy_set, &dfa_set] {
            let s = p.vertices().iter().fold(set.start(), |s, v| {
                let c = set.classify_interned(v.ty(), v.event(), set.label_id(v.label()));
                assert_eq!(c, set.classify(v), "{v}");
                set.step_class(s, c)
            });
            assert_eq!(set.matches(s), want, "{p}");
        }
    }
    // Labels no expression mentions share one id; ids and states of another set never
    // panic.
    assert_eq!(dfa_set.label_id(Some("zz")), dfa_set.label_id(Some("yy")));
    assert_ne!(dfa_set.label_id(Some("floor")), dfa_set.label_id(None));
    let small = AovSet::compile(&named(&[parse("CL").unwrap()])).unwrap();
    let foreign = dfa_set.label_id(Some("glass"));
    // With a cache too: a foreign id must not size the cache's per-id index.
    let cached = AovSet::compile_with(&named(&exprs), &lazy(1 << 20)).unwrap();
    for set in [&small, &lazy_set, &cached] {
        let c = set.classify_interned(lpe::renderman::VertexType::L, None, foreign);
        let s = set.step_class(State::from_u32(u32::MAX - 3), c);
        let _ = (set.matches(s), set.is_dead(s));
        let mut cache = set.cache();
        let s = set.step_with(&mut cache, State::from_u32(u32::MAX - 3), c);
        let _ = set.matches_with(&mut cache, State::from_u32(u32::MAX - 7));
        let _ = (set.matches_with(&mut cache, s), set.is_dead(s));
        assert!(cache.memory_bytes() < 1 << 20, "{}", cache.memory_bytes());
    }
}

#[test]
fn blow_up_sets_go_lazy_at_once_and_answer_right() {
    let src = "C.*D.{20}[LO]";
    let exprs = vec![parse(src).unwrap()];
    let set = AovSet::compile(&named(&exprs)).unwrap();
    // The eager attempt stops at its state cap, far below the 2^21 states and the
    // default budget: the registry holds only the two initial states until stepped.
    assert!(!set.uses_dfa());
    assert_eq!(set.lazy_states(), Some(2));
    let mut p = "C RD".to_string();
    p.push_str(&" RS".repeat(20));
    p.push_str(" L");
    let p: Path = p.parse().unwrap();
    assert!(lpe_reference::is_match(&exprs[0], &p));
    assert!(set.match_path(&p).contains(0));
    for p in random_paths(4, 200, 30) {
        assert_eq!(set.match_path(&p), reference_mask(&exprs, &p), "{p}");
    }
}

#[test]
fn batch_steps_answer_per_path() {
    let exprs = exprs();
    let paths = random_paths(5, 300, 10);
    // A DFA (the batch reads its table alone), a lazy DFA with a cache that clears all
    // the time, one that holds everything, and none (every step on the NFA).
    for opts in [Options::default(), lazy(1), lazy(1 << 20), lazy(0)] {
        let set = AovSet::compile_with(&named(&exprs), &opts).unwrap();
        // A state of no set steps as `step_class` steps it.
        let c = set.classify(&paths[0].vertices()[0]);
        for bad in [u32::MAX, u32::MAX - 1, 1 << 20] {
            let mut batch = [State::from_u32(bad)];
            set.step_batch(&mut batch, &[c]);
            assert_eq!(batch[0], set.step_class(State::from_u32(bad), c), "{bad}");
        }
        let mut states = vec![set.start(); paths.len()];
        let longest = paths.iter().map(Path::len).max().unwrap();
        for d in 0..longest {
            // Paths past their end step on nothing: the batch's classes are the alive
            // paths' only, so a shorter class slice leaves the rest alone.
            let alive: Vec<usize> = (0..paths.len()).filter(|&i| paths[i].len() > d).collect();
            let mut batch: Vec<State> = alive.iter().map(|&i| states[i]).collect();
            let classes: Vec<Class> = alive
                .iter()
                .map(|&i| set.classify(&paths[i].vertices()[d]))
                .collect();
            batch.push(set.start());
            set.step_batch(&mut batch, &classes);
            assert_eq!(
                batch.last(),
                Some(&set.start()),
                "past the classes: untouched"
            );
            for (&i, &s) in alive.iter().zip(&batch) {
                states[i] = s;
            }
        }
        for (p, &s) in paths.iter().zip(&states) {
            assert_eq!(set.matches(s), reference_mask(&exprs, p), "{p}");
        }
    }
}

/// `C<RD>L` stepped lazily along `C RD L` through `cache`: the final state.
fn step_cdl(set: &AovSet<lpe::renderman::RenderMan>, cache: &mut lpe::Cache) -> State {
    let p: Path = "C RD L".parse().unwrap();
    p.vertices()
        .iter()
        .fold(set.start(), |s, v| set.step_with(cache, s, set.classify(v)))
}

#[test]
fn a_cache_holds_as_many_rows_as_its_budget_pays_for() {
    // `C<RD>L` has 4 classes (camera, `RD`, light, the rest): a stride of 4, so a row is
    // 4 * 4 + 40 = 56 bytes (Options::lazy_cache). `C RD L` makes 4 rows: the start and
    // the states after `C` and `RD` (stepped from), the state after `L` (matched in).
    let exprs = [parse("C<RD>L").unwrap()];
    let compile = |budget| AovSet::compile_with(&named(&exprs), &lazy(budget)).unwrap();
    assert_eq!(compile(0).class_count(), 4);
    for (budget, clears, rows) in [(4 * 56, 0, 4), (4 * 56 - 1, 1, 1), (3 * 56, 1, 1)] {
        let set = compile(budget);
        let mut cache = set.cache();
        let s = step_cdl(&set, &mut cache);
        assert_eq!(set.matches_with(&mut cache, s), AovMask::from_iter([0]));
        assert_eq!(
            (cache.clears(), cache.rows()),
            (clears, rows),
            "{budget} bytes"
        );
        if clears == 0 {
            // u32s: a row index per id up to 4 (5), 4 rows of 4 transitions, the 4 ids
            // with a row; and 4 masks of 32 bytes.
            assert_eq!(cache.memory_bytes(), (5 + 16 + 4) * 4 + 4 * 32);
        }
        // Dead, start, and the three states `C RD L` reaches.
        assert_eq!(set.lazy_states(), Some(5));
    }
    // A budget of 0 caches nothing: every step runs the NFA.
    let set = compile(0);
    let mut cache = set.cache();
    let s = step_cdl(&set, &mut cache);
    assert_eq!(set.matches_with(&mut cache, s), AovMask::from_iter([0]));
    assert_eq!(
        (cache.rows(), cache.clears(), cache.memory_bytes()),
        (0, 0, 0)
    );
}

#[test]
fn a_state_the_set_never_gave_out_leaves_no_row_behind() {
    // Id 2 is the next one the registry gives out (0 dead, 1 start): stepped before the
    // set reaches it, it reads as dead, and must not be cached as dead, or the path
    // that later gets id 2 (`C`) would step from the stale row.
    let exprs = [parse("C<RD>L").unwrap()];
    let set = AovSet::compile_with(&named(&exprs), &lazy(1 << 20)).unwrap();
    let mut cache = set.cache();
    let next = State::from_u32(2);
    assert_eq!(set.lazy_states(), Some(2));
    let p: Path = "C RD L".parse().unwrap();
    let rd = set.classify(&p.vertices()[1]);
    assert!(set.matches_with(&mut cache, next).is_empty());
    assert!(set.is_dead(set.step_with(&mut cache, next, rd)));
    let s = step_cdl(&set, &mut cache);
    assert_eq!(
        set.matches_with(&mut cache, s),
        AovMask::from_iter([0]),
        "{p}"
    );
}

#[test]
fn a_cache_never_changes_a_step() {
    // Every sequence of up to 4 classes (the camera's mid-sequence too, so that rows
    // store transitions of every class), stepped through a cache and on a set with
    // caching off. The two registries intern the same subsets in the same order, so
    // equal answers mean equal ids; a hit that reads another row's or another class's
    // entry gives another id.
    let exprs = [parse("C<RD>L").unwrap(), parse("C<RD>+[LO]").unwrap()];
    let uncached = AovSet::compile_with(&named(&exprs), &lazy(0)).unwrap();
    let mut classes: Vec<Class> = vertex_pool().iter().map(|v| uncached.classify(v)).collect();
    classes.sort();
    classes.dedup();
    assert_eq!(classes.len(), uncached.class_count());
    for budget in [1, 1 << 20] {
        let cached = AovSet::compile_with(&named(&exprs), &lazy(budget)).unwrap();
        let mut cache = cached.cache();
        let mut seqs: Vec<Vec<Class>> = vec![Vec::new()];
        for _ in 0..4 {
            let longer: Vec<Vec<Class>> = seqs
                .iter()
                .flat_map(|s| classes.iter().map(move |&c| [s.as_slice(), &[c]].concat()))
                .collect();
            for seq in &longer {
                let (mut a, mut b) = (cached.start(), uncached.start());
                for &c in seq {
                    a = cached.step_with(&mut cache, a, c);
                    b = uncached.step_class(b, c);
                    assert_eq!(a, b, "{seq:?}, {budget} bytes");
                    assert_eq!(cached.matches_with(&mut cache, a), uncached.matches(b));
                }
            }
            seqs = longer;
        }
    }
}

#[test]
fn a_cache_of_another_set_is_not_read_for_matches() {
    // The cache's rows are `C<RD>L`'s, where id 4 (after `C RD L`) matches. Handed to
    // `C<RD><RD>L` for a match before any step, it must be reset, not read: there id 4
    // is the state after `C RD RD`, which matches nothing.
    let a = AovSet::compile_with(&named(&[parse("C<RD>L").unwrap()]), &lazy(1 << 20)).unwrap();
    let b = AovSet::compile_with(&named(&[parse("C<RD><RD>L").unwrap()]), &lazy(1 << 20)).unwrap();
    let mut cache = a.cache();
    let s = step_cdl(&a, &mut cache);
    assert_eq!(
        (s.to_u32(), a.matches_with(&mut cache, s)),
        (4, AovMask::from_iter([0]))
    );
    let p: Path = "C RD RD L".parse().unwrap();
    let s = p.vertices()[..3]
        .iter()
        .fold(b.start(), |s, v| b.step(s, v));
    assert_eq!(s.to_u32(), 4);
    assert!(b.matches_with(&mut cache, s).is_empty());
}
