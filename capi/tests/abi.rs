//! The extern fns called as C would: answers equal lpe's own, and every bad argument an
//! error status rather than a crash.

use std::ffi::{c_char, CStr, CString};
use std::ptr::{null, null_mut};

use lpe_capi::classify::{lpe_classify, lpe_classify_osl, lpe_classify_text};
use lpe_capi::error::{
    lpe_error_aov, lpe_error_free, lpe_error_message, lpe_error_position, lpe_error_status,
};
use lpe_capi::set::*;
use lpe_capi::status::lpe_status_message;
use lpe_capi::step::{lpe_is_dead, lpe_matches, lpe_start, lpe_step, lpe_step_n};
use lpe_capi::{lpe_class, lpe_error, lpe_set, lpe_state, lpe_status, lpe_vertex};

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

fn compile(
    names: &[&str],
    exprs: &[&str],
    ini: Option<&str>,
) -> Result<Set, (lpe_status, String, i64, i64)> {
    let (_n, np) = cstrings(names);
    let (_e, ep) = cstrings(exprs);
    let ini = ini.map(|s| CString::new(s).unwrap());
    let mut out = null_mut();
    let mut err: *mut lpe_error = null_mut();
    let st = lpe_set_compile(
        np.as_ptr(),
        ep.as_ptr(),
        names.len(),
        LPE_DIALECT_RENDERMAN,
        ini.as_ref().map_or(null(), |c| c.as_ptr()),
        null(),
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
    let mut s = lpe_state { opaque: [7; 4] };
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
    let names: Vec<&str> = lpe::macros::BASIC.iter().map(|(n, _)| *n).collect();
    let exprs: Vec<&str> = lpe::macros::BASIC.iter().map(|(_, e)| *e).collect();
    let set = compile(&names, &exprs, None).unwrap();
    assert_eq!(lpe_set_len(set.0), names.len());
    for (i, n) in names.iter().enumerate() {
        let got = unsafe { CStr::from_ptr(lpe_set_name(set.0, i)) };
        assert_eq!(got.to_str().unwrap(), *n);
    }
    assert!(lpe_set_name(set.0, names.len()).is_null());
    let aovs: Vec<(String, lpe::Lpe)> = lpe::macros::BASIC
        .iter()
        .map(|(n, e)| (n.to_string(), lpe::parse(e).unwrap()))
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
        let path: lpe::Path = p.parse().unwrap();
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
    let mut s = lpe_state { opaque: [0; 4] };
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
    let mut s = lpe_state { opaque: [0; 4] };
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
    let syms = [null::<c_char>()];
    assert_eq!(
        lpe_classify_osl(set.0, syms.as_ptr(), 1, &mut c),
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
    let mut bs = lpe_state { opaque: [0; 4] };
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
    assert_eq!(
        lpe_set_compile(
            null(),
            null(),
            0,
            LPE_DIALECT_OSL,
            null(),
            null(),
            &mut out,
            null_mut()
        ),
        lpe_status::LPE_ERR_UNSUPPORTED
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
                    let mut s = lpe_state { opaque: [0; 4] };
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
