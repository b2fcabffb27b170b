//! The workspace as git tracks it: what the checkout holds apart from what builds and
//! runs write into it (`target/`, `out/`, a scratch folder), which the docs may name as
//! outputs but which are no part of the workspace.

use std::collections::BTreeSet;
use std::process::Command;

use crate::imports::workspace;

/// The tracked files, workspace-relative with `/` separators (`git ls-files`). Panics
/// with what to do when git is missing or the workspace is no git checkout: the tests
/// that read this list would otherwise check nothing.
pub fn tracked_files() -> Vec<String> {
    let out = Command::new("git")
        .args(["ls-files", "-z"])
        .current_dir(workspace())
        .output()
        .unwrap_or_else(|e| panic!("git is required to list the workspace's files: {e}"));
    assert!(
        out.status.success(),
        "`git ls-files` failed in {} (the workspace must be a git checkout): {}",
        workspace().display(),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .expect("tracked paths are UTF-8")
        .split('\0')
        .filter(|p| !p.is_empty())
        .map(str::to_string)
        .collect()
}

/// The top-level folders that hold tracked files: the folders a path in the docs may
/// start with to be a workspace path.
pub fn top_folders(tracked: &[String]) -> BTreeSet<String> {
    tracked
        .iter()
        .filter_map(|p| p.split_once('/').map(|(top, _)| top.to_string()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn top_folders_are_those_holding_tracked_files() {
        let tracked = [
            "README.md",
            "lpe/src/aov.rs",
            "docs/accuracy.md",
            "lpe/Cargo.toml",
        ]
        .map(String::from);
        assert_eq!(
            top_folders(&tracked).into_iter().collect::<Vec<_>>(),
            ["docs", "lpe"]
        );
    }

    /// Sanity: this checkout's list holds the workspace's own files and no build output.
    #[test]
    fn this_checkout_is_listed() {
        let tracked = tracked_files();
        assert!(
            tracked.iter().any(|p| p == "tests/Cargo.toml"),
            "{tracked:?}"
        );
        assert!(!tracked.iter().any(|p| p.starts_with("target/")));
    }
}
