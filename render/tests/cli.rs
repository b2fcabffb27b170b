//! The command line: bad input is a clear error with exit status 2, never a panic.

mod common;

use common::run;

#[test]
fn bad_input_is_reported_not_panicked() {
    let dir = std::env::temp_dir().join(format!("lpe-render-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad_scene = dir.join("bad.toml");
    std::fs::write(&bad_scene, "[camera]\nposition = [0,0,0]\nlook_at = [0,0,1]\n\n[[objects]]\nmaterial = \"missing\"\nsphere = { center = [0,0,2], radius = 1 }\n").unwrap();
    let display = dir.join("display.rib");
    std::fs::write(
        &display,
        "DisplayChannel \"color x\" \"string source\" [\"color lpe:C<L'key'>\"]\n",
    )
    .unwrap();
    let ini = dir.join("rendermn.ini");
    std::fs::write(&ini, "/prman/lpe/diffuse9 Diffuse\n").unwrap();
    let out = dir.join("out");
    let out_s = out.to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--res", "12"], "WIDTHxHEIGHT"),
        (vec!["--res", "0x5"], "WIDTHxHEIGHT"),
        (vec!["--spp", "0"], "positive"),
        (vec!["--res", "16384x16384"], "GiB of film"),
        (vec!["--scene", "nowhere"], "not a built-in scene"),
        (
            vec!["--scene", bad_scene.to_str().unwrap()],
            "bad.toml:5: object `object0`: unknown material `missing`",
        ),
        (vec!["--aov", "noequals"], "NAME=LPE"),
        (vec!["--aov", "x=C<L'key'>"], "write `<L.'key'>`"),
        (vec!["--aov", "a=CL", "--aov", "a=CO"], "used twice"),
        (vec!["--display", display.to_str().unwrap()], "display.rib"),
        (vec!["--ini", ini.to_str().unwrap()], "rendermn.ini:line 1"),
        (vec!["--display", "/nonexistent/file"], "/nonexistent/file"),
    ];
    for (args, needle) in cases {
        let (code, err) = run(&args
            .iter()
            .chain(["--out", out_s].iter())
            .copied()
            .collect::<Vec<_>>());
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(
            err.contains(needle),
            "{args:?}: expected `{needle}` in: {err}"
        );
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    assert!(!out.exists(), "nothing is written on bad input");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_tiny_render_writes_everything_and_exits_zero() {
    let dir = std::env::temp_dir().join(format!("lpe-render-cli-ok-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (display, ini) = common::display_and_ini(&dir, "key");
    let out = dir.join("out");
    let args = [
        "--res=16x12",
        "--spp=2",
        &format!("--out={}", out.display()),
        &format!("--display={}", display.display()),
        &format!("--ini={}", ini.display()),
        "--aov=rest=C.*<L.[^'key']>",
        "--aov=glow=C.*O",
    ];
    let (code, err) = run(&args.iter().map(|s| s.as_ref()).collect::<Vec<&str>>());
    assert_eq!(code, 0, "{err}");
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    // The AOV table row of `mine`, cells trimmed (the table writer pads columns).
    let row = |line: &str| -> Vec<String> {
        line.split(" | ")
            .map(|c| {
                c.trim_matches(|ch: char| ch == '|' || ch.is_whitespace())
                    .to_string()
            })
            .collect()
    };
    assert!(
        report
            .lines()
            .any(|l| row(l) == ["`mine`", "`lpe:myDirect`", "`C<RD>[<L.>O]`"]),
        "{report}"
    );
    for f in [
        "cornell.exr",
        "contact_sheet.png",
        "report.md",
        "report.json",
        "png/key.png",
        "png/mine.png",
        "png/rest.png",
        "png/beauty.png",
    ] {
        assert!(out.join(f).exists(), "{f}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
