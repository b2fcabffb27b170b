//! The bodies of the fuzz targets in `fuzz/`, as plain functions.
//!
//! Each takes the fuzzer's raw input and panics when a property fails, so the same
//! function serves `cargo fuzz run TARGET` (nightly or `-s none` on stable) and the
//! stable `cargo test` that replays every committed corpus and regression file
//! (`tests/tests/fuzz_replay.rs`).
//!
//! | target | property |
//! |---|---|
//! | `parse` | any bytes: the parser never panics; a parsed expression prints to text that parses back to the same AST and prints the same again |
//! | `path_text` | any bytes: the path parser never panics; a parsed path prints and re-parses to itself |
//! | `differential` | a structured expression and paths aimed at it: every engine agrees |
//! | `aov_set` | 2-6 structured expressions compiled as one set, paths aimed at them: every engine agrees |

use arbitrary::Unstructured;
use lpe::generate::{self, Choices, Config};
use lpe::{Lpe, Path};

use crate::adapters::Reference;
use crate::differential::{self, Outcome};
use crate::engine::Engine;

/// `parse`: never panics; parse -> print -> parse is the identity on the AST.
pub fn parse(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let Ok(lpe) = lpe::parse(&text) else {
        return;
    };
    let printed = lpe.to_string();
    let again = lpe::parse(&printed)
        .unwrap_or_else(|e| panic!("`{text}` printed as `{printed}`, which does not parse: {e}"));
    assert_eq!(
        again, lpe,
        "`{text}` printed as `{printed}` parses differently"
    );
    assert_eq!(again.to_string(), printed, "printing is not stable");
}

/// `path_text`: never panics; a parsed path prints and re-parses to itself.
pub fn path_text(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let Ok(path) = text.parse::<Path>() else {
        return;
    };
    let printed = path.to_string();
    let again: Path = printed
        .parse()
        .unwrap_or_else(|e| panic!("`{text}` printed as `{printed}`, which does not parse: {e}"));
    assert_eq!(
        again, path,
        "`{text}` printed as `{printed}` parses differently"
    );
}

fn paths_for(exprs: &[Lpe], u: &mut Unstructured<'_>, cfg: &Config) -> Vec<Path> {
    let n = 1 + u.below(8);
    (0..n)
        .map(|_| {
            let operands = exprs[u.below(exprs.len())].operands();
            let target = operands[u.below(operands.len())];
            generate::biased_path(target, u, cfg)
        })
        .collect()
}

/// Whether the engines were compared: the reference and at least one other engine
/// built the set. Fuzzed sets may exceed an engine's size limits, so fewer engines is
/// not a failure; it is just not an agreement, and the caller can count it.
fn agree(exprs: &[Lpe], paths: &[Path]) -> bool {
    // The expression must survive its own canonical text, or the counterexample printed
    // below would not reproduce.
    for e in exprs {
        let text = e.to_string();
        match lpe::parse(&text) {
            Ok(back) => assert_eq!(&back, e, "`{text}` parses to another expression"),
            Err(err) => panic!("generated `{text}` does not parse: {err}"),
        }
    }
    match differential::check_set(exprs, paths) {
        Outcome::Disagree(c) => panic!("{c}"),
        Outcome::Agree(a) => {
            // The reference has no size limit; without it nothing says who is right.
            let reference = Reference.name();
            assert!(
                a.skipped.iter().all(|(name, _)| *name != reference),
                "the reference refused: {:?}",
                a.skipped
            );
            a.engines >= 2
        }
    }
}

/// `differential`: one structured expression, paths aimed at it, every engine agrees.
pub fn differential(data: &[u8]) {
    differential_compared(data);
}

/// [`differential()`], returning whether at least two engines (the reference and
/// another) were compared.
pub fn differential_compared(data: &[u8]) -> bool {
    let mut u = Unstructured::new(data);
    let cfg = Config::default();
    let e = generate::lpe(&mut u, &cfg);
    let paths = paths_for(std::slice::from_ref(&e), &mut u, &cfg);
    agree(std::slice::from_ref(&e), &paths)
}

/// `aov_set`: 2-6 structured expressions compiled as one set; every engine agrees on
/// which of them match each path.
pub fn aov_set(data: &[u8]) {
    aov_set_compared(data);
}

/// [`aov_set`], returning whether at least two engines (the reference and another)
/// were compared.
pub fn aov_set_compared(data: &[u8]) -> bool {
    let mut u = Unstructured::new(data);
    let cfg = Config::default().with_max_atoms(6);
    let n = 2 + u.below(5);
    let exprs: Vec<Lpe> = (0..n).map(|_| generate::lpe(&mut u, &cfg)).collect();
    let paths = paths_for(&exprs, &mut u, &cfg);
    agree(&exprs, &paths)
}

/// The differential target called `name`, returning whether engines were compared,
/// so a replay can count inputs that only one engine could build.
pub fn compared_target(name: &str) -> Option<fn(&[u8]) -> bool> {
    Some(match name {
        "differential" => differential_compared,
        "aov_set" => aov_set_compared,
        _ => return None,
    })
}

/// The target called `name`, for replaying files by directory name.
pub fn target(name: &str) -> Option<fn(&[u8])> {
    Some(match name {
        "parse" => parse,
        "path_text" => path_text,
        "differential" => differential,
        "aov_set" => aov_set,
        _ => return None,
    })
}
