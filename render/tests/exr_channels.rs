//! The EXR output contract, as the README states it: one part, beauty as the channels
//! `R G B`, each AOV as `NAME.R NAME.G NAME.B`, 32-bit float, and nothing else. The file
//! is read back with the `exr` crate's own header reader, not the renderer's.

mod common;

use std::process::Command;

use exr::meta::attribute::SampleType;
use exr::meta::MetaData;

#[test]
fn exr_holds_exactly_beauty_and_one_rgb_layer_per_aov() {
    let dir = std::env::temp_dir().join(format!("lpe-render-exr-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let (display, ini) = common::display_and_ini(&dir, "keyOnly");
    let out = dir.join("out");
    let out_arg = format!("--out={}", out.display());
    let display_arg = format!("--display={}", display.display());
    let ini_arg = format!("--ini={}", ini.display());
    let output = Command::new(env!("CARGO_BIN_EXE_lpe-render"))
        .args([
            "--res=8x6",
            "--spp=1",
            &out_arg,
            &display_arg,
            &ini_arg,
            "--aov=indirect_key=C<RD>.+<L.'key'>",
            "--aov=Glow=C.*O",
        ])
        .output()
        .expect("lpe-render runs");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );

    // The AOVs in the order given (display channels, then --aov), each with its three
    // channels, after beauty; written by hand from the arguments above.
    let aov_names = ["keyOnly", "mine", "indirect_key", "Glow"];
    let mut want: Vec<String> = ["R", "G", "B"].iter().map(|s| s.to_string()).collect();
    for n in aov_names {
        for c in ["R", "G", "B"] {
            want.push(format!("{n}.{c}"));
        }
    }
    // OpenEXR stores channels sorted by name.
    want.sort();

    let meta = MetaData::read_from_file(out.join("cornell.exr"), true).unwrap();
    assert_eq!(meta.headers.len(), 1, "one part");
    let header = &meta.headers[0];
    let got: Vec<String> = header
        .channels
        .list
        .iter()
        .map(|c| c.name.to_string())
        .collect();
    assert_eq!(got, want);
    for c in &header.channels.list {
        assert_eq!(c.sample_type, SampleType::F32, "{}", c.name);
    }
    assert_eq!(
        (header.layer_size.0, header.layer_size.1),
        (8, 6),
        "image size"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
