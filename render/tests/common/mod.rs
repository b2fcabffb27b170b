//! Fixtures the CLI-level render tests share.

use std::path::{Path, PathBuf};

/// Writes into `dir` a RenderMan display file with two channels (`key_name`, the light
/// group `key`, and `mine`, a user macro) and the `rendermn.ini` defining that macro
/// (`myDirect` = `C<RD>[<L.>O]`); returns their paths.
pub fn display_and_ini(dir: &Path, key_name: &str) -> (PathBuf, PathBuf) {
    let display = dir.join("display.rib");
    std::fs::write(
        &display,
        format!(
            "DisplayChannel \"color {key_name}\" \"string source\" [\"color lpe:C.*<L.'key'>\"]\n\
             DisplayChannel \"color mine\" \"string source\" [\"color lpe:myDirect\"]\n"
        ),
    )
    .unwrap();
    let ini = dir.join("rendermn.ini");
    std::fs::write(&ini, "/prman/lpe/macro/myDirect C<RD>[<L.>O]\n").unwrap();
    (display, ini)
}
