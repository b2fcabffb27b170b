//! The front-end comparison (`lpe_engines::differential::front`) over every corpus
//! expression of both dialects: the conformance suites (`tests/testdata/**/*.toml`), the
//! fuzz corpora of the parse targets, and the hand-written constructs that exercise every
//! production of both grammars. Fails, printing each minimized disagreement, if lpe's
//! parser and the reference's independent front end disagree on any of them.

use std::path::{Path, PathBuf};

use lpe::osl::Osl;
use lpe::renderman::RenderMan;
use lpe_engines::differential::front::{self, FrontEnds};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the engines crate sits in the workspace root")
        .to_path_buf()
}

fn run<D: FrontEnds>() -> front::FrontTotals {
    let cases = front::corpus::<D>(&root()).expect("the corpora load");
    front::run::<D>(cases, 1, 50)
}

fn assert_agree<D: FrontEnds>(min_cases: u64) {
    let t = run::<D>();
    eprintln!("{}", t.summary());
    let report: Vec<String> = t.disagreements.iter().map(|d| d.to_string()).collect();
    assert!(t.count() == 0, "{}:\n{}", t.summary(), report.join("\n\n"));
    assert!(
        t.compared >= min_cases,
        "only {} expressions compared: a corpus went missing",
        t.compared
    );
}

#[test]
fn renderman_front_ends_agree_on_every_corpus_expression() {
    assert_agree::<RenderMan>(400);
}

#[test]
fn osl_front_ends_agree_on_every_corpus_expression() {
    assert_agree::<Osl>(300);
}
