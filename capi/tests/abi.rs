//! The extern fns called as C would: answers equal lpe's own, and every bad argument an
//! error status rather than a crash.

use std::ffi::{c_char, CStr, CString};
use std::ptr::{null, null_mut};

use lpe_capi::classify::{lpe_classify, lpe_classify_symbols, lpe_classify_text};
use lpe_capi::error::{
    lpe_error_aov, lpe_error_free, lpe_error_message, lpe_error_position, lpe_error_status,
};
use lpe_capi::set::*;
use lpe_capi::status::lpe_status_message;
use lpe_capi::step::{
    lpe_cache_free, lpe_cache_new, lpe_is_dead, lpe_matches, lpe_matches_with, lpe_start, lpe_step,
    lpe_step_n, lpe_step_with,
};
use lpe_capi::view::lpe_set_step_view;
use lpe_capi::{lpe_class, lpe_error, lpe_set, lpe_state, lpe_status, lpe_step_view, lpe_vertex};
use lpe_testkit::suite::{load_dir, load_file, rows, testdata_dir, Loaded, Plan, Row};

struct Set(*mut lpe_set);

// The set is immutable once compiled; the C API documents it as thread-safe.
unsafe impl Send for Set {}
unsafe impl Sync for Set {}

impl Drop for Set {
    fn drop(&mut self) {
        lpe_set_free(self.0);
    }
}

fn cstrings(xs: &[&str]) -> (Vec<CString>, Vec<*const c_char>) {
    let owned: Vec<CString> = xs.iter().map(|s| CString::new(*s).unwrap()).collect();
    let ptrs = owned.iter().map(|c| c.as_ptr()).collect();
    (owned, ptrs)
}

/// What a failed compile reports: status, message, AOV index, byte position.
type Failure = (lpe_status, String, i64, i64);

fn compile(names: &[&str], exprs: &[&str], ini: Option<&str>) -> Result<Set, Failure> {
    compile_in(LPE_DIALECT_RENDERMAN, names, exprs, ini, None)
}

fn compile_in(
    dialect: u32,
    names: &[&str],
    exprs: &[&str],
    ini: Option<&str>,
    options: Option<&lpe_options>,
) -> Result<Set, Failure> {
    let (_n, np) = cstrings(names);
    let (_e, ep) = cstrings(exprs);
    let ini = ini.map(|s| CString::new(s).unwrap());
    let mut out = null_mut();
    let mut err: *mut lpe_error = null_mut();
    let st = lpe_set_compile(
        np.as_ptr(),
        ep.as_ptr(),
        names.len(),
        dialect,
        ini.as_ref().map_or(null(), |c| c.as_ptr()),
        options.map_or(null(), |o| o as *const lpe_options),
        &mut out,
        &mut err,
    );
    if st == lpe_status::LPE_OK {
        assert!(err.is_null() && !out.is_null());
        return Ok(Set(out));
    }
    assert!(out.is_null());
    let msg = unsafe { CStr::from_ptr(lpe_error_message(err)) }
        .to_str()
        .unwrap()
        .to_string();
    let r = (
        lpe_error_status(err),
        msg,
        lpe_error_aov(err),
        lpe_error_position(err),
    );
    assert_eq!(r.0, st);
    lpe_error_free(err);
    Err(r)
}

fn class(set: &Set, text: &str) -> lpe_class {
    let t = CString::new(text).unwrap();
    let mut c = lpe_class { id: u32::MAX };
    assert_eq!(
        lpe_classify_text(set.0, t.as_ptr(), &mut c),
        lpe_status::LPE_OK,
        "{text}"
    );
    c
}

fn route(set: &Set, path: &[&str]) -> (Vec<u64>, usize) {
    let mut s = lpe_state { opaque: 7 };
    assert_eq!(lpe_start(set.0, &mut s), lpe_status::LPE_OK);
    let classes: Vec<lpe_class> = path.iter().map(|v| class(set, v)).collect();
    let mut whole = s;
    for &c in &classes {
        assert_eq!(lpe_step(set.0, &mut s, c), lpe_status::LPE_OK);
    }
    // One call per path steps to the same state.
    assert_eq!(
        lpe_step_n(set.0, &mut whole, classes.as_ptr(), classes.len()),
        lpe_status::LPE_OK
    );
    assert_eq!(whole, s);
    let mut words = vec![u64::MAX; lpe_set_mask_words(set.0) + 1];
    let mut count = 99;
    assert_eq!(
        lpe_matches(set.0, &s, words.as_mut_ptr(), words.len(), &mut count),
        lpe_status::LPE_OK
    );
    (words, count)
}

#[test]
fn answers_equal_lpe_on_the_basic_aovs() {
    let names: Vec<&str> = lpe::renderman::macros::BASIC
        .iter()
        .map(|(n, _)| *n)
        .collect();
    let exprs: Vec<&str> = lpe::renderman::macros::BASIC
        .iter()
        .map(|(_, e)| *e)
        .collect();
    let set = compile(&names, &exprs, None).unwrap();
    assert_eq!(lpe_set_len(set.0), names.len());
    for (i, n) in names.iter().enumerate() {
        let got = unsafe { CStr::from_ptr(lpe_set_name(set.0, i)) };
        assert_eq!(got.to_str().unwrap(), *n);
    }
    assert!(lpe_set_name(set.0, names.len()).is_null());
    let aovs: Vec<(String, lpe::renderman::Lpe)> = lpe::renderman::macros::BASIC
        .iter()
        .map(|(n, e)| (n.to_string(), lpe::renderman::parse(e).unwrap()))
        .collect();
    let rust = lpe::AovSet::compile(&aovs).unwrap();
    for p in [
        "C RD2'floor' RD L'key'",
        "C RD L",
        "C RS TS RD L",
        "C O",
        "C TD L",
        "C RU3 L",
    ] {
        let path: lpe::renderman::Path = p.parse().unwrap();
        let want: Vec<usize> = rust.match_path(&path).iter().collect();
        let texts: Vec<String> = path.vertices().iter().map(|v| v.to_string()).collect();
        let texts: Vec<&str> = texts.iter().map(|s| s.as_str()).collect();
        let (words, count) = route(&set, &texts);
        let got: Vec<usize> = (0..64 * words.len())
            .filter(|i| words[i / 64] >> (i % 64) & 1 == 1)
            .collect();
        assert_eq!(got, want, "{p}");
        assert_eq!(count, want.len(), "{p}");
    }
}

#[test]
fn fields_and_text_classify_alike_and_dead_paths_are_seen() {
    let set = compile(&["d"], &["C<RD'floor'>L"], None).unwrap();
    let label = CString::new("floor").unwrap();
    let mut by_fields = lpe_class { id: 0 };
    let v = lpe_vertex {
        vertex_type: b'R',
        event: b'D',
        lobe: 2,
        label: label.as_ptr(),
    };
    assert_eq!(lpe_classify(set.0, &v, &mut by_fields), lpe_status::LPE_OK);
    assert_eq!(by_fields, class(&set, "RD2'floor'"));
    assert_ne!(by_fields, class(&set, "RD2'wall'"));
    let mut s = lpe_state { opaque: 0 };
    lpe_start(set.0, &mut s);
    let mut dead = true;
    assert_eq!(lpe_is_dead(set.0, &s, &mut dead), lpe_status::LPE_OK);
    assert!(!dead);
    lpe_step(set.0, &mut s, class(&set, "C"));
    lpe_step(set.0, &mut s, class(&set, "RS"));
    assert_eq!(lpe_is_dead(set.0, &s, &mut dead), lpe_status::LPE_OK);
    assert!(dead);
    // Bad fields: unknown letters, lobes out of range, an event on a light, a camera label.
    for (t, e, l, lab) in [
        (b'X', 0, 0, null()),
        (b'R', b'D', 5, null()),
        (b'R', b'Q', 1, null()),
        (b'L', b'D', 1, null()),
        (b'C', 0, 0, label.as_ptr()),
    ] {
        let v = lpe_vertex {
            vertex_type: t,
            event: e,
            lobe: l,
            label: lab,
        };
        assert_eq!(
            lpe_classify(set.0, &v, &mut by_fields),
            lpe_status::LPE_ERR_RANGE
        );
    }
}

#[test]
fn bad_arguments_are_errors_not_crashes() {
    let set = compile(&["a"], &["C.L"], None).unwrap();
    let mut s = lpe_state { opaque: 0 };
    let mut c = lpe_class { id: 0 };
    assert_eq!(lpe_start(null(), &mut s), lpe_status::LPE_ERR_NULL);
    assert_eq!(lpe_start(set.0, null_mut()), lpe_status::LPE_ERR_NULL);
    lpe_start(set.0, &mut s);
    let before = s;
    let n = lpe_set_class_count(set.0) as u32;
    assert_eq!(
        lpe_step(set.0, &mut s, lpe_class { id: n }),
        lpe_status::LPE_ERR_RANGE
    );
    assert_eq!(s, before, "a refused step leaves the state alone");
    assert_eq!(lpe_step(null(), &mut s, c), lpe_status::LPE_ERR_NULL);
    let mixed = [c, lpe_class { id: n }];
    assert_eq!(
        lpe_step_n(set.0, &mut s, mixed.as_ptr(), 2),
        lpe_status::LPE_ERR_RANGE
    );
    assert_eq!(s, before, "no step of a refused segment is taken");
    assert_eq!(
        lpe_step_n(set.0, &mut s, null(), 1),
        lpe_status::LPE_ERR_NULL
    );
    assert_eq!(lpe_step_n(set.0, &mut s, null(), 0), lpe_status::LPE_OK);
    assert_eq!(lpe_step(set.0, null_mut(), c), lpe_status::LPE_ERR_NULL);
    assert_eq!(
        lpe_classify_text(set.0, null(), &mut c),
        lpe_status::LPE_ERR_NULL
    );
    let two = CString::new("RD RS").unwrap();
    assert_eq!(
        lpe_classify_text(set.0, two.as_ptr(), &mut c),
        lpe_status::LPE_ERR_PARSE
    );
    let bad_utf8 = [b'R', b'D', b'\'', 0xff, b'\'', 0];
    assert_eq!(
        lpe_classify_text(set.0, bad_utf8.as_ptr().cast(), &mut c),
        lpe_status::LPE_ERR_UTF8
    );
    assert_eq!(
        lpe_classify(set.0, null(), &mut c),
        lpe_status::LPE_ERR_NULL
    );
    let mut w = [0u64; 1];
    assert_eq!(
        lpe_matches(set.0, &s, w.as_mut_ptr(), 0, null_mut()),
        lpe_status::LPE_OK
    );
    assert_eq!(
        lpe_matches(set.0, &s, null_mut(), 1, null_mut()),
        lpe_status::LPE_ERR_NULL
    );
    assert_eq!(lpe_is_dead(set.0, &s, null_mut()), lpe_status::LPE_ERR_NULL);
    assert_eq!(lpe_set_len(null()), 0);
    assert!(lpe_set_name(null(), 0).is_null());
    assert_eq!(lpe_set_warning_aov(set.0, 0), -1);
    // An OSL vertex on a RenderMan set is the wrong dialect, not a crash.
    let syms = [null::<c_char>()];
    assert_eq!(
        lpe_classify_symbols(set.0, syms.as_ptr(), 1, &mut c),
        lpe_status::LPE_ERR_UNSUPPORTED
    );
    assert_eq!(
        unsafe { CStr::from_ptr(lpe_status_message(12345)) }
            .to_str()
            .unwrap(),
        "unknown status"
    );
    // A mask too small for a set of 65 AOVs is refused, not truncated.
    let names: Vec<String> = (0..65).map(|i| format!("a{i}")).collect();
    let names: Vec<&str> = names.iter().map(|s| s.as_str()).collect();
    let big = compile(&names, &vec!["C.L"; 65], None).unwrap();
    assert_eq!(lpe_set_mask_words(big.0), 2);
    let mut bs = lpe_state { opaque: 0 };
    lpe_start(big.0, &mut bs);
    assert_eq!(
        lpe_matches(big.0, &bs, w.as_mut_ptr(), 1, null_mut()),
        lpe_status::LPE_ERR_RANGE
    );
    lpe_set_free(null_mut());
    lpe_error_free(null_mut());
    let mut out = null_mut();
    assert_eq!(
        lpe_set_compile(null(), null(), 1, 0, null(), null(), &mut out, null_mut()),
        lpe_status::LPE_ERR_NULL
    );
    assert_eq!(
        lpe_set_compile(null(), null(), 0, 9, null(), null(), &mut out, null_mut()),
        lpe_status::LPE_ERR_RANGE
    );
}

#[test]
fn errors_name_the_aov_and_the_byte() {
    let (st, msg, aov, pos) = compile(&["ok", "bad"], &["C.L", "C<L'key'>"], None)
        .err()
        .unwrap();
    assert_eq!(st, lpe_status::LPE_ERR_PARSE);
    assert_eq!((aov, pos), (1, 3));
    assert!(
        msg.contains("bad") && msg.contains("third position"),
        "{msg}"
    );
    let (st, _, aov, line) = compile(&["a"], &["C.L"], Some("/prman/lpe/macro/x C(\n"))
        .err()
        .unwrap();
    assert_eq!((st, aov, line), (lpe_status::LPE_ERR_INI, -1, 1));
    // User macros from the ini text are available.
    let set = compile(
        &["mine"],
        &["myDiffuse"],
        Some("/prman/lpe/macro/myDiffuse C<RD>L\n"),
    )
    .unwrap();
    assert_eq!(route(&set, &["C", "RD", "L"]).1, 1);
    let names: Vec<String> = (0..=lpe::MAX_AOVS).map(|i| format!("a{i}")).collect();
    let names: Vec<&str> = names.iter().map(|s| s.as_str()).collect();
    let (st, msg, _, _) = compile(&names, &vec!["C.L"; names.len()], None)
        .err()
        .unwrap();
    assert_eq!(st, lpe_status::LPE_ERR_COMPILE);
    assert!(msg.contains("over the limit"), "{msg}");
    let set = compile(&["never", "ok"], &["C.*", "C.L"], None).unwrap();
    assert_eq!(lpe_set_warning_count(set.0), 1);
    assert_eq!(lpe_set_warning_aov(set.0, 0), 0);
    let w = unsafe { CStr::from_ptr(lpe_set_warning(set.0, 0)) }
        .to_str()
        .unwrap();
    assert!(w.contains("never"), "{w}");
}

#[test]
fn one_set_serves_many_threads() {
    let set = compile(&["d", "s"], &["C<RD>+L", "C<RS>+L"], None).unwrap();
    let rd = class(&set, "RD");
    let rs = class(&set, "RS");
    let (c, l) = (class(&set, "C"), class(&set, "L"));
    std::thread::scope(|scope| {
        for t in 0..4 {
            let set = &set;
            scope.spawn(move || {
                for n in 1..200 {
                    let mut s = lpe_state { opaque: 0 };
                    lpe_start(set.0, &mut s);
                    lpe_step(set.0, &mut s, c);
                    let bounce = if (n + t) % 2 == 0 { rd } else { rs };
                    for _ in 0..n % 5 + 1 {
                        lpe_step(set.0, &mut s, bounce);
                    }
                    lpe_step(set.0, &mut s, l);
                    let mut w = [0u64];
                    lpe_matches(set.0, &s, w.as_mut_ptr(), 1, null_mut());
                    assert_eq!(w[0], if (n + t) % 2 == 0 { 1 } else { 2 });
                }
            });
        }
    });
}

/// OSL's own unit test (`tests/testdata/osl/accum_test.toml`), one row per (rule,
/// path): expression, registration, path in accum_test notation, and OSL's verdict.
fn accum_rows() -> Vec<Row> {
    let cases = load_file("osl/accum_test.toml").unwrap_or_else(|e| panic!("{e}"));
    let rows = rows(&cases);
    assert_eq!(rows.len(), 130);
    rows
}

/// How a test steps an OSL set through the C ABI.
#[derive(Clone, Copy, Debug)]
enum Stepping {
    /// `lpe_step` and `lpe_matches` (a lazy set uses the thread-local cache).
    Plain,
    /// `lpe_step_with` and `lpe_matches_with` through an `lpe_cache`.
    OwnCache,
}

/// Steps an OSL path given in accum_test notation (no quotes in that file: vertices split
/// on spaces, symbols on commas, `~` for NONE), each vertex classified from its symbols
/// as C strings, and returns the match mask's first word.
fn route_by_symbols(set: &Set, path: &str, stepping: Stepping) -> u64 {
    let cache = lpe_cache_new(set.0);
    assert!(!cache.is_null());
    let mut s = lpe_state { opaque: 12345 };
    assert_eq!(lpe_start(set.0, &mut s), lpe_status::LPE_OK);
    for vertex in path.split(' ') {
        let owned: Vec<Option<CString>> = vertex
            .split(',')
            .map(|sym| (sym != "~").then(|| CString::new(sym).unwrap()))
            .collect();
        let ptrs: Vec<*const c_char> = owned
            .iter()
            .map(|o| o.as_ref().map_or(null(), |c| c.as_ptr()))
            .collect();
        let mut c = lpe_class { id: u32::MAX };
        assert_eq!(
            lpe_classify_symbols(set.0, ptrs.as_ptr(), ptrs.len(), &mut c),
            lpe_status::LPE_OK,
            "{vertex}"
        );
        let st = match stepping {
            Stepping::Plain => lpe_step(set.0, &mut s, c),
            Stepping::OwnCache => lpe_step_with(set.0, cache, &mut s, c),
        };
        assert_eq!(st, lpe_status::LPE_OK);
    }
    let mut w = [u64::MAX];
    let st = match stepping {
        Stepping::Plain => lpe_matches(set.0, &s, w.as_mut_ptr(), 1, null_mut()),
        Stepping::OwnCache => lpe_matches_with(set.0, cache, &s, w.as_mut_ptr(), 1, null_mut()),
    };
    assert_eq!(st, lpe_status::LPE_OK);
    lpe_cache_free(cache);
    w[0]
}

fn options_with_registration(
    registered: &CString,
    dfa_budget: Option<usize>,
    lazy_cache: usize,
) -> lpe_options {
    let mut o = lpe_options_default();
    o.osl_registered = registered.as_ptr();
    if let Some(b) = dfa_budget {
        o.dfa_budget = b;
    }
    o.lazy_cache = lazy_cache;
    o
}

#[test]
fn accum_test_rows_answer_as_osl_and_the_reference_do_through_the_c_abi() {
    let default_cache = lpe_options_default().lazy_cache;
    // The eager DFA; the lazy DFA (budget 0) through the thread-local cache, through a
    // cache of the caller's, and with caching off (every step on the bitset NFA).
    let modes = [
        (None, default_cache, Stepping::Plain),
        (Some(0), default_cache, Stepping::Plain),
        (Some(0), default_cache, Stepping::OwnCache),
        (Some(0), 0, Stepping::OwnCache),
    ];
    let rows = accum_rows();
    for (budget, cache, stepping) in modes {
        let mut matched = 0;
        for row in &rows {
            let registered = CString::new(row.registered.to_string()).unwrap();
            let opts = options_with_registration(&registered, budget, cache);
            let set = compile_in(LPE_DIALECT_OSL, &["rule"], &[&row.expr], None, Some(&opts))
                .unwrap_or_else(|e| panic!("{}: {e:?}", row.expr));
            let got = route_by_symbols(&set, &row.path, stepping) == 1;
            let lpe = lpe::osl::parse(&row.expr, &row.registered).unwrap();
            let path: lpe::osl::Path = row.path.parse().unwrap();
            let reference = lpe_reference::lpe_tree::is_match(&lpe, &path);
            assert_eq!(
                (got, reference),
                (row.matches, row.matches),
                "{} on {} ({budget:?}, {stepping:?}): C ABI, reference, OSL",
                row.expr,
                row.path
            );
            matched += usize::from(got);
        }
        // Both verdicts occur in the file, so neither constant answer passes.
        assert!(matched > 0 && matched < rows.len(), "{matched}");
    }
}

#[test]
fn an_osl_set_of_several_rules_routes_each_path_to_its_rules() {
    let registered = CString::new("events=U;scatters=Y").unwrap();
    let opts = options_with_registration(&registered, None, lpe_options_default().lazy_cache);
    // OSL's basic set plus two rules on the registered labels and a custom label.
    let mut names: Vec<&str> = lpe::osl::BASIC.iter().map(|(n, _)| *n).collect();
    let mut exprs: Vec<&str> = lpe::osl::BASIC.iter().map(|(_, e)| *e).collect();
    names.extend(["user", "floor"]);
    exprs.extend(["CDY+U", "C<.D'floor'>L"]);
    let set = compile_in(LPE_DIALECT_OSL, &names, &exprs, None, Some(&opts)).unwrap();
    // Expected AOVs worked out by hand from each rule.
    for (path, want) in [
        ("C,_ R,D L,_", &["directDiffuse"][..]),
        ("C,_ R,D,floor L,_", &["directDiffuse", "floor"]),
        ("C,_ R,D R,G L,_", &["indirectDiffuse"]),
        ("C,_ T,S L,_", &["transmissive"]),
        ("C,_ L,_", &["emissive"]),
        ("C,_ R,D R,Y U,_", &["user"]),
        ("C,_ R,D U,_", &[]),
        // A NONE scattering: no AOV's `<R...>`-style pattern takes it.
        ("C,_ R,~ L,_", &[]),
    ] {
        let mask = route_by_symbols(&set, path, Stepping::Plain);
        let got: Vec<&str> = (0..names.len())
            .filter(|i| mask >> i & 1 == 1)
            .map(|i| names[i])
            .collect();
        assert_eq!(got, want, "{path}");
    }
}

/// `options->renderer`: Karma's `A`, prefix and refusals through the ABI; the other
/// dialect's profile and an unknown name are refused with the reason.
#[test]
fn a_set_compiles_under_a_renderer_profile_named_in_the_options() {
    let with = |name: &str| {
        let mut o = lpe_options_default();
        o.renderer = Box::leak(CString::new(name).unwrap().into_boxed_c_str()).as_ptr();
        o
    };
    let karma = with("karma");
    // `A` is Karma's albedo event: plain OSL refuses it, Karma reads it.
    assert!(compile_in(LPE_DIALECT_OSL, &["albedo"], &["C<RD>A"], None, None).is_err());
    let set = compile_in(
        LPE_DIALECT_OSL,
        &["albedo", "unshadowed"],
        &["C<RD>A", "unoccluded;C<RD>L"],
        None,
        Some(&karma),
    )
    .unwrap();
    drop(set);
    let (st, msg, aov, pos) = compile_in(
        LPE_DIALECT_OSL,
        &["a"],
        &["shadw;C<RD>L"],
        None,
        Some(&karma),
    )
    .err()
    .unwrap();
    assert_eq!((st, aov, pos), (lpe_status::LPE_ERR_PARSE, 0, 0), "{msg}");
    assert!(msg.contains("`unoccluded;`"), "{msg}");
    let (st, msg, _, _) = compile_in(
        LPE_DIALECT_RENDERMAN,
        &["a"],
        &["C<RD>L"],
        None,
        Some(&karma),
    )
    .err()
    .unwrap();
    assert_eq!(st, lpe_status::LPE_ERR_UNSUPPORTED, "{msg}");
    assert!(msg.contains("reads osl's dialect"), "{msg}");
    let (st, msg, _, _) = compile_in(
        LPE_DIALECT_OSL,
        &["a"],
        &["C<RD>L"],
        None,
        Some(&with("karm")),
    )
    .err()
    .unwrap();
    assert_eq!(st, lpe_status::LPE_ERR_UNSUPPORTED, "{msg}");
    assert!(msg.contains("did you mean `karma`?"), "{msg}");
    // hdPrman reads RenderMan's dialect unchanged.
    assert!(compile_in(
        LPE_DIALECT_RENDERMAN,
        &["a"],
        &["C<RD>L"],
        None,
        Some(&with("hdprman"))
    )
    .is_ok());
}

#[test]
fn compile_errors_name_the_aov_the_byte_and_the_registration_in_the_osl_dialect() {
    let registered = CString::new("events=U;colors=Y").unwrap();
    let opts = options_with_registration(&registered, None, 0);
    let (st, msg, aov, pos) = compile_in(LPE_DIALECT_OSL, &["a"], &["CDL"], None, Some(&opts))
        .err()
        .unwrap();
    assert_eq!((st, aov, pos), (lpe_status::LPE_ERR_PARSE, -1, 9), "{msg}");
    assert!(
        msg.contains("osl_registered") && msg.contains("colors=Y"),
        "{msg}"
    );
    // OSL's own message for an unclosed group, at the end of the expression.
    let (st, msg, aov, pos) = compile_in(
        LPE_DIALECT_OSL,
        &["ok", "bad"],
        &["CDL", "C<RD"],
        None,
        None,
    )
    .err()
    .unwrap();
    assert_eq!((st, aov, pos), (lpe_status::LPE_ERR_PARSE, 1, 4), "{msg}");
    assert!(
        msg.contains("bad") && msg.contains("looking for >"),
        "{msg}"
    );
    // A registered label parses only when registered.
    assert!(compile_in(LPE_DIALECT_OSL, &["u"], &["CDY+U"], None, None).is_err());
    let registered = CString::new("events=U;scatters=Y").unwrap();
    let opts = options_with_registration(&registered, None, 0);
    assert!(compile_in(LPE_DIALECT_OSL, &["u"], &["CDY+U"], None, Some(&opts)).is_ok());
    // Each dialect's configuration belongs to that dialect only.
    let (st, msg, _, _) = compile_in(LPE_DIALECT_OSL, &["a"], &["CDL"], Some(""), None)
        .err()
        .unwrap();
    assert_eq!(st, lpe_status::LPE_ERR_UNSUPPORTED, "{msg}");
    let (st, msg, _, _) = compile_in(LPE_DIALECT_RENDERMAN, &["a"], &["C.L"], None, Some(&opts))
        .err()
        .unwrap();
    assert_eq!(st, lpe_status::LPE_ERR_UNSUPPORTED, "{msg}");
}

#[test]
fn classifying_symbols_checks_its_arguments_and_the_dialect() {
    let set = compile_in(LPE_DIALECT_OSL, &["d"], &["C<RD>L"], None, None).unwrap();
    let mut c = lpe_class { id: 0 };
    let r = CString::new("R").unwrap();
    let d = CString::new("D").unwrap();
    let syms = [r.as_ptr(), d.as_ptr()];
    assert_eq!(
        lpe_classify_symbols(set.0, syms.as_ptr(), 2, &mut c),
        lpe_status::LPE_OK
    );
    assert!(c.id < lpe_set_class_count(set.0) as u32);
    assert_eq!(
        lpe_classify_symbols(set.0, syms.as_ptr(), 0, &mut c),
        lpe_status::LPE_ERR_RANGE
    );
    assert_eq!(
        lpe_classify_symbols(set.0, null(), 2, &mut c),
        lpe_status::LPE_ERR_NULL
    );
    assert_eq!(
        lpe_classify_symbols(null(), syms.as_ptr(), 2, &mut c),
        lpe_status::LPE_ERR_NULL
    );
    let bad_utf8 = [0xffu8, 0];
    let bad = [r.as_ptr(), bad_utf8.as_ptr().cast::<c_char>()];
    assert_eq!(
        lpe_classify_symbols(set.0, bad.as_ptr(), 2, &mut c),
        lpe_status::LPE_ERR_UTF8
    );
    // RenderMan vertices on an OSL set are the wrong dialect.
    assert_eq!(
        lpe_classify_text(set.0, r.as_ptr(), &mut c),
        lpe_status::LPE_ERR_UNSUPPORTED
    );
    let v = lpe_vertex {
        vertex_type: b'R',
        event: b'D',
        lobe: 1,
        label: null(),
    };
    assert_eq!(
        lpe_classify(set.0, &v, &mut c),
        lpe_status::LPE_ERR_UNSUPPORTED
    );
}

#[test]
fn a_state_is_four_bytes_and_caches_check_their_arguments() {
    assert_eq!(std::mem::size_of::<lpe_state>(), 4);
    assert!(lpe_cache_new(null()).is_null());
    lpe_cache_free(null_mut());
    let set = compile(&["a"], &["C.L"], None).unwrap();
    let mut s = lpe_state { opaque: 0 };
    lpe_start(set.0, &mut s);
    let c = class(&set, "C");
    assert_eq!(
        lpe_step_with(set.0, null_mut(), &mut s, c),
        lpe_status::LPE_ERR_NULL
    );
    let mut w = [0u64];
    assert_eq!(
        lpe_matches_with(set.0, null_mut(), &s, w.as_mut_ptr(), 1, null_mut()),
        lpe_status::LPE_ERR_NULL
    );
    // A cache of another set is reset for this one, never misread.
    let other = compile(&["b"], &["C<RS>L"], None).unwrap();
    let cache = lpe_cache_new(other.0);
    for v in ["C", "RD", "L"] {
        assert_eq!(
            lpe_step_with(set.0, cache, &mut s, class(&set, v)),
            lpe_status::LPE_OK
        );
    }
    assert_eq!(
        lpe_matches_with(set.0, cache, &s, w.as_mut_ptr(), 1, null_mut()),
        lpe_status::LPE_OK
    );
    assert_eq!(w[0], 1);
    lpe_cache_free(cache);
}

/// Every state `lpe_step` reaches from the start, breadth first.
fn reachable_states(set: &Set) -> Vec<u32> {
    let mut s = lpe_state { opaque: 0 };
    assert_eq!(lpe_start(set.0, &mut s), lpe_status::LPE_OK);
    let mut seen = vec![s.opaque];
    let mut at = 0;
    while at < seen.len() {
        for c in 0..lpe_set_class_count(set.0) as u32 {
            let mut t = lpe_state { opaque: seen[at] };
            assert_eq!(
                lpe_step(set.0, &mut t, lpe_class { id: c }),
                lpe_status::LPE_OK
            );
            if !seen.contains(&t.opaque) {
                seen.push(t.opaque);
            }
        }
        at += 1;
    }
    seen
}

#[test]
fn the_step_view_is_the_dfa_table_lpe_step_reads() {
    let exprs = ["C<RD>+<L.'key'>", "C.*S.*L", "^(C.*D.*L)"];
    let set = compile(&["a", "b", "c"], &exprs, None).unwrap();
    let mut view = std::mem::MaybeUninit::<lpe_step_view>::uninit();
    assert_eq!(
        lpe_set_step_view(set.0, view.as_mut_ptr()),
        lpe_status::LPE_OK
    );
    // SAFETY: filled by the call above.
    let view = unsafe { view.assume_init() };
    assert_eq!(view.set, set.0 as *const lpe_set);
    assert_eq!(view.class_count, lpe_set_class_count(set.0));
    let mut start = lpe_state { opaque: 7 };
    lpe_start(set.0, &mut start);
    assert_eq!(view.start, start);
    // SAFETY: the view's table has `table_len` entries while the set lives.
    let table = unsafe { std::slice::from_raw_parts(view.table, view.table_len) };
    // One row of a power-of-two stride per state, state ids being row offsets: the states
    // reached, and the dead state 0, which a DFA always has (the complement keeps these
    // paths from reaching it).
    let mut states = reachable_states(&set);
    assert!(!states.contains(&0));
    states.push(0);
    let stride = view.class_count.next_power_of_two();
    assert_eq!(table.len(), states.len() * stride);
    assert!(states.iter().all(|&s| (s as usize).is_multiple_of(stride)));
    for &s in &states {
        for c in 0..view.class_count as u32 {
            let mut t = lpe_state { opaque: s };
            lpe_step(set.0, &mut t, lpe_class { id: c });
            assert_eq!(table[(s + c) as usize], t.opaque, "state {s} class {c}");
        }
    }
    // A DFA's state 0 is dead, whatever the AOVs.
    let mut dead = false;
    lpe_is_dead(set.0, &lpe_state { opaque: 0 }, &mut dead);
    assert!(dead && view.zero_is_dead);

    // A lazy set has no table; with a complement its state 0 is not dead.
    let lazy = lpe_options {
        dfa_budget: 0,
        ..lpe_options_default()
    };
    let set = compile_in(
        LPE_DIALECT_RENDERMAN,
        &["c"],
        &exprs[2..],
        None,
        Some(&lazy),
    )
    .unwrap();
    let mut view = std::mem::MaybeUninit::<lpe_step_view>::uninit();
    assert_eq!(
        lpe_set_step_view(set.0, view.as_mut_ptr()),
        lpe_status::LPE_OK
    );
    // SAFETY: filled by the call above.
    let view = unsafe { view.assume_init() };
    assert!(view.table.is_null() && view.table_len == 0);
    assert!(!view.zero_is_dead);

    assert_eq!(
        lpe_set_step_view(null(), &mut { view }),
        lpe_status::LPE_ERR_NULL
    );
    assert_eq!(
        lpe_set_step_view(set.0, null_mut()),
        lpe_status::LPE_ERR_NULL
    );
}

/// One case of the conformance suite through the C ABI, compiled with `dfa_budget`
/// (`None`: the default): its failures, and the answers it checked.
fn suite_case(l: &Loaded, dfa_budget: Option<usize>) -> (Vec<String>, usize) {
    let case = &l.case;
    let plan = Plan::of(case);
    let names: Vec<String> = (0..plan.sources.len()).map(|i| format!("e{i}")).collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let registered = CString::new(l.registered.to_string()).unwrap();
    let renderer = l.profile.as_deref().map(|p| CString::new(p).unwrap());
    let cache = lpe_options_default().lazy_cache;
    let (dialect, mut opts) = match l.dialect {
        lpe::DialectName::RenderMan => {
            let mut o = lpe_options_default();
            if let Some(b) = dfa_budget {
                o.dfa_budget = b;
            }
            (LPE_DIALECT_RENDERMAN, o)
        }
        lpe::DialectName::Osl => (
            LPE_DIALECT_OSL,
            options_with_registration(&registered, dfa_budget, cache),
        ),
    };
    // Under a profile, the set is compiled with `renderer` naming it (its letters,
    // prefixes and built-in names come through the ABI, not from the case's text).
    if let Some(r) = &renderer {
        opts.renderer = r.as_ptr();
        opts.osl_registered = null();
    }
    let at = format!("{} ({dfa_budget:?})", l.location());
    let compiled = compile_in(
        dialect,
        &names,
        &plan.sources,
        case.ini.as_deref(),
        Some(&opts),
    );
    let set = match (compiled, &case.error) {
        (Err(f), Some(want)) => {
            return if f.3 == want.at as i64 {
                (vec![], 1)
            } else {
                (
                    vec![format!(
                        "{at}: a {} error at byte {}, got {f:?}",
                        want.kind, want.at
                    )],
                    1,
                )
            };
        }
        (Ok(_), Some(want)) => {
            return (
                vec![format!("{at}: expected a {} error, got a set", want.kind)],
                1,
            );
        }
        // A refusal the case allows lpe's AOV set (over a size budget), which the C ABI
        // compiles with.
        (Err(_), None) if case.refused_by.iter().any(|r| r.starts_with("aovset")) => {
            return (vec![], 0)
        }
        (Err(f), None) => return (vec![format!("{at}: expected a set, got {f:?}")], 0),
        (Ok(set), None) => set,
    };
    let mut failures = Vec::new();
    let mut checked = 0;
    for (path, want) in &plan.expected {
        let words = match l.dialect {
            lpe::DialectName::RenderMan => {
                let vertices: Vec<&str> = path.split(' ').collect();
                route(&set, &vertices).0
            }
            lpe::DialectName::Osl => vec![route_by_symbols(&set, path, Stepping::Plain)],
        };
        for (j, &w) in want.iter().enumerate() {
            checked += 1;
            let got = words[j / 64] >> (j % 64) & 1 == 1;
            if got != w {
                failures.push(format!(
                    "{at}: `{}` on `{path}`: expected {w}, got {got}",
                    plan.sources[j]
                ));
            }
        }
    }
    (failures, checked)
}

#[test]
fn every_suite_case_of_both_dialects_answers_through_the_c_abi() {
    let cases = load_dir(&testdata_dir()).unwrap_or_else(|e| panic!("{e}"));
    let mut failures = Vec::new();
    let mut checked = [0usize; 2];
    for l in &cases {
        // Path-text checks (`bad_path`) are the path parser's, not the C ABI's.
        if l.case.expr.is_none() && l.case.aovs.is_empty() {
            continue;
        }
        for budget in [None, Some(0)] {
            let (f, n) = suite_case(l, budget);
            failures.extend(f);
            checked[usize::from(l.dialect == lpe::DialectName::Osl)] += n;
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    eprintln!(
        "C ABI: {} cases, {} RenderMan and {} OSL answers checked (DFA and lazy DFA)",
        cases.len(),
        checked[0],
        checked[1]
    );
    // Every OSL verdict of the suite, in both modes: 130 accum_test rows and the
    // hand-worked ones.
    let osl: Vec<Loaded> = cases
        .iter()
        .filter(|l| l.dialect == lpe::DialectName::Osl)
        .cloned()
        .collect();
    assert_eq!(checked[1], 2 * rows(&osl).len());
    assert!(checked[0] > 600, "{}", checked[0]);
}

#[test]
fn a_wrong_suite_verdict_fails_through_the_c_abi() {
    let text = "dialect = \"osl\"\n[[case]]\nname = \"flipped\"\nexpr = \"C<RD>L\"\nno_match = [\"C,_ R,D L,_\"]\n";
    let cases = lpe_testkit::suite::load_str("flipped.toml", text).unwrap();
    let (failures, checked) = suite_case(&cases[0], None);
    assert_eq!(checked, 1);
    assert_eq!(failures.len(), 1, "{failures:?}");
    assert!(
        failures[0].starts_with("flipped.toml: case `flipped`"),
        "{}",
        failures[0]
    );
}

/// Labels one byte apart at every position and length, UTF-8 included
/// (`lpe_testkit::labels`), through the C ABI: a set of `C<L.'label'>` per label of a
/// group, DFA and lazy, routes a light carrying each label (classified from fields and
/// from text) to its own AOV alone, and a light carrying a label the set does not name
/// to none.
#[test]
fn labels_one_byte_apart_stay_apart_through_the_c_abi() {
    let mut checked = 0;
    for group in lpe_testkit::labels::groups() {
        let names: Vec<String> = (0..group.named.len()).map(|i| format!("a{i}")).collect();
        let exprs: Vec<String> = group.named.iter().map(|l| format!("C<L.'{l}'>")).collect();
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let exprs: Vec<&str> = exprs.iter().map(String::as_str).collect();
        let lazy = lpe_options {
            dfa_budget: 0,
            ..lpe_options_default()
        };
        for options in [None, Some(&lazy)] {
            let set = compile_in(LPE_DIALECT_RENDERMAN, &names, &exprs, None, options).unwrap();
            let land = |label: &str| -> Vec<usize> {
                let c = CString::new(label).unwrap();
                let v = lpe_vertex {
                    vertex_type: b'L',
                    event: 0,
                    lobe: 0,
                    label: c.as_ptr(),
                };
                let mut by_fields = lpe_class { id: u32::MAX };
                assert_eq!(lpe_classify(set.0, &v, &mut by_fields), lpe_status::LPE_OK);
                assert_eq!(by_fields, class(&set, &format!("L'{label}'")), "{label}");
                let (words, count) = route(&set, &["C", &format!("L'{label}'")]);
                let bits: Vec<usize> = (0..64 * words.len())
                    .filter(|&i| words[i / 64] >> (i % 64) & 1 == 1)
                    .collect();
                assert_eq!(bits.len(), count, "{label}");
                bits
            };
            for (i, label) in group.named.iter().enumerate() {
                assert_eq!(land(label), [i], "`{label}`");
                checked += 1;
            }
            for label in &group.unnamed {
                assert!(land(label).is_empty(), "`{label}`");
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 2 * lpe_testkit::labels::LABELS_CHECKED);
}

/// A set of 1 437 NFA positions, over its DFA budget, compiles through the C ABI and
/// answers as the reference (the lazy DFA steps states of any width).
#[test]
fn a_set_of_thousands_of_positions_compiles_and_answers_through_the_c_abi() {
    let src = "C((('fill'[^<T[^D2US]'fill'>R])U1)|(.[O<..'a b'>])*|\
               U6((<.[^DD]'floor'><[^R].>){1,238}){1,3})'floor'L";
    let set = compile(&["wide"], &[src], None).unwrap();
    let lpe = lpe::renderman::parse(src).unwrap();
    let mut matched = 0;
    for k in [1, 238, 714, 715] {
        let mut path = vec!["C".to_string(), "RU6".to_string()];
        for _ in 0..k {
            path.extend(["RS1'floor'".to_string(), "TD1".to_string()]);
        }
        path.extend(["RD1'floor'".to_string(), "L".to_string()]);
        let text = path.join(" ");
        let want = lpe_reference::is_match(&lpe, &text.parse().unwrap());
        let refs: Vec<&str> = path.iter().map(String::as_str).collect();
        let (words, count) = route(&set, &refs);
        assert_eq!((words[0] & 1 == 1, count == 1), (want, want), "{k}");
        matched += usize::from(want);
    }
    assert_eq!(matched, 3, "714 copies at most");
}
