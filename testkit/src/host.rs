//! What tests need of the host beyond the toolchain, checked so that a missing tool is a
//! failure that names it, never a test that returns early and counts as a pass.

use std::process::Command;

/// Fails the calling test unless `python3` runs: the tests that drive the Python adapters
/// of the external-matcher protocol need it (CI has it), and returning early without it
/// would report them as passing when nothing was checked.
///
/// Planted fault: with `PATH` emptied (`PATH= cargo test ...`, the test binary run
/// directly) every such test in `cli/tests/diff_external.rs` and
/// `engines/tests/external.rs` fails with this message instead of passing.
pub fn require_python3() {
    let found = Command::new("python3")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    assert!(
        found,
        "python3 is required for this test: install it (e.g. `apt-get install python3`) \
         and put it on PATH"
    );
}
