//! Cross-crate property tests and the data-driven conformance suite live in `tests/`;
//! this library holds what the test files share, and the suite's loader and runner
//! ([`conformance`]).

pub mod conformance;

use proptest::test_runner::{Config, TestRunner};

/// `PROPTEST_CASES` if set, else `default`. An explicit case count in a config would
/// otherwise override the variable, and it is documented to raise every suite.
pub fn cases(default: u32) -> Config {
    let n = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default);
    Config::with_cases(n)
}

/// A runner for properties driven by hand (to gather statistics across cases), with
/// [`cases`]`(default_cases)`. No failure persistence: a persisted seed would replay
/// into a strategy these tests build inline and may change.
pub fn runner(default_cases: u32) -> TestRunner {
    TestRunner::new(Config {
        failure_persistence: None,
        ..cases(default_cases)
    })
}
