//! The expressions the front-end comparison runs on besides generated ones, read from a
//! workspace checkout: every expression of the conformance suites
//! (`tests/testdata/**/*.toml`, read by `lpe_testkit::suite`: `expr`, `same_as` and
//! every AOV of a case, under the case's registration), the fuzz corpora and regression
//! inputs of the dialect's parse targets (`fuzz/corpus/<target>/*`,
//! `fuzz/regressions/<target>/*`, a first line that is a registration applying to the
//! rest, as the fuzz body reads them), and the hand-written constructs
//! ([`super::constructs`]).

use std::path::Path;

use lpe_testkit::suite;

use super::case::{FrontCase, FrontEnds};

/// Every corpus expression of dialect `D` under the workspace root `root`, then the
/// hand-written constructs. A missing directory contributes nothing; an unreadable
/// suite is an error.
pub fn corpus<D: FrontEnds>(root: &Path) -> Result<Vec<FrontCase<D>>, String> {
    let mut out = Vec::new();
    let testdata = root.join("tests/testdata");
    if testdata.is_dir() {
        let cases = suite::load_dir(&testdata).map_err(|e| e.to_string())?;
        for loaded in &cases {
            let Some(registration) = D::suite_registration(loaded) else {
                continue;
            };
            let case = &loaded.case;
            let texts = case
                .expr
                .iter()
                .chain(&case.same_as)
                .chain(case.aovs.iter().map(|a| &a.expr));
            for text in texts {
                out.push(FrontCase {
                    text: text.clone(),
                    registration: registration.clone(),
                    origin: loaded.location(),
                });
            }
        }
    }
    for target in D::FUZZ_TARGETS {
        for dir in ["fuzz/corpus", "fuzz/regressions"] {
            let Ok(entries) = std::fs::read_dir(root.join(dir).join(target)) else {
                continue;
            };
            let mut files: Vec<_> = entries.filter_map(|e| e.ok()).map(|e| e.path()).collect();
            files.sort();
            for file in files {
                if file.extension().is_some_and(|x| x == "md") {
                    continue;
                }
                let Ok(bytes) = std::fs::read(&file) else {
                    continue;
                };
                let text = String::from_utf8_lossy(&bytes);
                let (registration, src) = text
                    .split_once('\n')
                    .and_then(|(first, rest)| Some((D::registration_line(first)?, rest)))
                    .unwrap_or_else(|| (D::Registration::default(), &*text));
                out.push(FrontCase {
                    text: src.to_string(),
                    registration,
                    origin: file
                        .strip_prefix(root)
                        .unwrap_or(&file)
                        .display()
                        .to_string(),
                });
            }
        }
    }
    for (registration, text) in D::constructs() {
        out.push(FrontCase {
            text,
            registration,
            origin: "hand-written construct".into(),
        });
    }
    Ok(out)
}
