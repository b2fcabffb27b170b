//! `lpe-render --usd`: AOVs from a stage's LPE RenderVars, picked and ordered by the
//! RenderProduct's `orderedVars`, one EXR layer each, named after the RenderVar.

use std::path::PathBuf;
use std::process::Command;

use exr::meta::MetaData;

fn fixture(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/testdata/usd")
        .join(name)
        .display()
        .to_string()
}

/// Renders a tiny cornell with `--usd stage`; returns (exit code, stderr, AOV names in
/// the report's order, EXR channel names).
fn render(stage: &str, tag: &str) -> (i32, String, Vec<String>, Vec<String>) {
    let out = std::env::temp_dir().join(format!("lpe-render-usd-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let output = Command::new(env!("CARGO_BIN_EXE_lpe-render"))
        .args(["--res=8x6", "--spp=1", "--usd", stage])
        .arg(format!("--out={}", out.display()))
        .output()
        .expect("lpe-render runs");
    let stderr = String::from_utf8_lossy(&output.stderr).to_string();
    let code = output.status.code().unwrap_or(-1);
    if code != 0 {
        return (code, stderr, Vec::new(), Vec::new());
    }
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    let names = report["aovs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a["name"].as_str().unwrap().to_string())
        .collect();
    let meta = MetaData::read_from_file(out.join("cornell.exr"), true).unwrap();
    let channels = meta.headers[0]
        .channels
        .list
        .iter()
        .map(|c| c.name.to_string())
        .collect();
    let _ = std::fs::remove_dir_all(&out);
    (code, stderr, names, channels)
}

#[test]
fn ordered_vars_pick_and_order_the_layers() {
    let (code, stderr, names, channels) = render(&fixture("solaris_karma.usda"), "solaris");
    assert_eq!(code, 0, "{stderr}");
    // orderedVars: C (raw: beauty), diffuse_key, diffuse_fill, specular_key;
    // floor_bounce is left out of the product.
    assert_eq!(names, ["diffuse_key", "diffuse_fill", "specular_key"]);
    for layer in ["diffuse_key", "diffuse_fill", "specular_key"] {
        assert!(channels.contains(&format!("{layer}.R")), "{channels:?}");
    }
    assert!(!channels.iter().any(|c| c.starts_with("floor_bounce")));
    assert!(stderr.contains("orderedVars names `C`, not an LPE RenderVar: skipped"));
    assert!(stderr.contains("RenderVar `floor_bounce` is not in the product's orderedVars"));
}

#[test]
fn without_a_product_every_lpe_var_in_stage_order() {
    let (code, stderr, names, _) = render(&fixture("arnold_partition.usda"), "arnold");
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(
        names,
        [
            "direct",
            "indirect",
            "emission",
            "lg_key",
            "lg_env",
            "lg_emission"
        ]
    );
}

#[test]
fn a_broken_stage_is_a_clear_error() {
    let bad = std::env::temp_dir().join(format!("lpe-render-bad-{}.usda", std::process::id()));
    std::fs::write(&bad, "#usda 1.0\ndef RenderVar \"x\" {\n").unwrap();
    let (code, stderr, _, _) = render(bad.to_str().unwrap(), "bad");
    assert_eq!(code, 2);
    assert!(
        stderr.contains(&format!("error: {}: USD: ", bad.display())),
        "{stderr}"
    );
    let _ = std::fs::remove_file(&bad);
}
