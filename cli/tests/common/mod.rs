//! What the CLI's integration tests that run `lpe-check` from the repository root share:
//! the root, and one run of the binary there with its exit code and output.

use std::path::PathBuf;
use std::process::Command;

/// The repository root (the workspace, one folder above this crate).
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Runs lpe-check in the repository root (so file names in reports are relative): exit
/// code, stdout, stderr.
pub fn lpe_check(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
        .current_dir(root())
        .args(args)
        .output()
        .expect("lpe-check runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}
