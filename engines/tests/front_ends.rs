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
fn front_ends_agree_on_every_corpus_expression_in_the_osl_dialect() {
    assert_agree::<Osl>(300);
}

/// Noisy texts over both grammars' characters: the front ends agree on each (mostly on
/// rejecting it, with positions that may differ).
fn noise_agrees<D: FrontEnds>(alphabet: &[char], registration: D::Registration) {
    let mut rng = lpe::rng::SplitMix64::new(11);
    let cases = (0..3000).map(|i| {
        let len = 1 + rng.below(14);
        front::FrontCase::<D> {
            text: (0..len)
                .map(|_| alphabet[rng.below(alphabet.len())])
                .collect(),
            registration: registration.clone(),
            origin: format!("noise {i}"),
        }
    });
    let t = front::run::<D>(cases.collect::<Vec<_>>(), 1, 10);
    let report: Vec<String> = t.disagreements.iter().map(|d| d.to_string()).collect();
    assert!(t.count() == 0, "{}:\n{}", t.summary(), report.join("\n\n"));
}

#[test]
fn renderman_front_ends_agree_on_noise() {
    let alphabet = [
        'C', 'R', 'T', 'L', 'O', 'D', 'S', 'U', 'x', 'c', '.', '\'', '<', '>', '[', ']', '^', '(',
        ')', '|', '*', '+', '?', '{', '}', ',', '1', '2', ' ', '&', '-', ';', '_', 'a',
    ];
    noise_agrees::<RenderMan>(&alphabet, Default::default());
}

#[test]
fn front_ends_agree_on_noise_in_the_osl_dialect() {
    let alphabet = [
        'C', 'R', 'T', 'L', 'O', 'D', 'G', 'S', 's', 'B', 'x', '.', '\'', '<', '>', '[', ']', '^',
        '(', ')', '|', '*', '+', '{', '}', ',', '0', '1', ' ', '&', '-', 'a', 'U',
    ];
    noise_agrees::<Osl>(&alphabet, "events=U".parse().unwrap());
}
