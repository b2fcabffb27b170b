//! `lpe-check lint` and `explain` end to end on the fixtures in tests/testdata/usd and
//! tests/testdata/lint: every fixture's findings, exactly, and the exit codes.

mod common;
use common::{lpe_check, root};

use std::path::PathBuf;

fn json(args: &[&str]) -> (i32, serde_json::Value) {
    let mut all = vec!["lint", "--format", "json"];
    all.extend_from_slice(args);
    let (code, out, err) = lpe_check(&all);
    let v = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out} {err}"));
    (code, v)
}

/// `(kind, subject, where)` of every finding, `where` the prim or `line:column`.
fn findings(v: &serde_json::Value) -> Vec<(String, String, String)> {
    v["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let loc = &f["location"];
            let at = match loc["prim"].as_str() {
                Some(p) => p.to_string(),
                None => format!("{}:{}", loc["line"], loc["column"]),
            };
            (
                f["kind"].as_str().unwrap().to_string(),
                f["subject"].as_str().unwrap().to_string(),
                at,
            )
        })
        .collect()
}

fn triples(list: &[(&str, &str, &str)]) -> Vec<(String, String, String)> {
    list.iter()
        .map(|(a, b, c)| (a.to_string(), b.to_string(), c.to_string()))
        .collect()
}

#[test]
fn solaris_karma_fixture() {
    let (code, v) = json(&["tests/testdata/usd/solaris_karma.usda"]);
    assert_eq!(code, 1);
    assert_eq!(
        findings(&v),
        triples(&[
            (
                "unknown_light_group",
                "diffuse_fill",
                "/Render/Products/Vars/diffuse_fill"
            ),
            // The stage does not say its dialect, and Karma reads `<RS>` as OSL's
            // singular scattering only.
            (
                "ambiguous_dialect",
                "specular_key",
                "/Render/Products/Vars/specular_key"
            ),
        ])
    );
    assert_eq!(v["findings"][1]["witness"], "C RS1 L'key'");
    let f = &v["findings"][0];
    assert_eq!(f["help"], "did you mean 'fill'?");
    assert_eq!(f["source"], "C<RD>.*<L.'fil'>");
    assert_eq!(f["span"], serde_json::json!([10, 15]));
    // The inactive RenderVar and the raw one are not AOVs of the stage.
    assert_eq!(v["aovs"].as_array().unwrap().len(), 4);
}

#[test]
fn hdprman_fixture() {
    let (code, v) = json(&["tests/testdata/usd/hdprman.usda"]);
    assert_eq!(code, 1);
    assert_eq!(
        findings(&v),
        triples(&[
            ("parse_error", "rimLight", "/Render/vars/rimLight"),
            (
                "empty",
                "lightBehindCamera",
                "/Render/vars/lightBehindCamera"
            ),
            ("equivalent", "diffuseAgain", "/Render/vars/diffuseAgain"),
            ("unfed_lobe", "wetness", "/Render/vars/wetness"),
            // Undeclared: user lobes have no OSL view, so the OSL reading never matches.
            ("ambiguous_dialect", "albedo", "/Render/vars/albedo"),
            ("ambiguous_dialect", "wetness", "/Render/vars/wetness"),
        ])
    );
    assert_eq!(v["findings"][4]["witness"], "C RU2 L");
    assert_eq!(v["findings"][0]["help"], "write `<L.'rim'>`");
    assert_eq!(v["findings"][2]["other"], "directDiffuse");
    assert_eq!(v["aovs"][3]["name"], "rimLight");
    assert_eq!(v["aovs"][3]["expression"], serde_json::Value::Null);
    assert_eq!(v["aovs"][0]["expression"], "C<RD>[<L.>O]");
}

#[test]
fn arnold_partition_fixture() {
    let (code, v) = json(&["tests/testdata/usd/arnold_partition.usda"]);
    assert_eq!(code, 1);
    assert_eq!(
        findings(&v),
        triples(&[
            // Undeclared, and hdArnold reads `S` as OSL's singular scattering only.
            ("ambiguous_dialect", "direct", "/Render/Vars/direct"),
            ("ambiguous_dialect", "indirect", "/Render/Vars/indirect"),
            ("overlap", "beauty", "/Render/settings"),
            ("gap", "beauty", "/Render/settings"),
            ("gap", "lightgroups", "/Render/settings"),
        ])
    );
    // The partition findings.
    let f = &v["findings"].as_array().unwrap()[2..];
    assert_eq!(f[0]["other"], "direct & indirect");
    // Witnesses checked by hand: `C RD L` is direct (C[DS]L) and indirect (C[DS]+...);
    // `C L` (the camera sees a light) is in no member of either partition.
    assert_eq!(f[0]["witness"], "C RD1 L");
    assert_eq!(f[1]["witness"], "C L");
    assert_eq!(f[2]["witness"], "C L");
    // The remainders parse and close the gaps, by the partition command.
    assert_eq!(
        f[1]["remainder"],
        "C.*[<L.>O] - ((C[DS]L)|(C[DS]+[<L.>O])|(CO))"
    );
    assert_eq!(
        f[2]["remainder"],
        "C.*[<L.>O] - ((C.*<L.'key'>)|(C.*<L.'env'>)|(C.*O))"
    );
    for (finding, members) in [
        (&f[1], ["C[DS]L", "C[DS]+[<L.>O]", "CO"]),
        (&f[2], ["C.*<L.'key'>", "C.*<L.'env'>", "C.*O"]),
    ] {
        let rest = format!("rest={}", finding["remainder"].as_str().unwrap());
        let mut args = vec!["partition", rest.as_str()];
        args.extend(members);
        let (_, out, err) = lpe_check(&args);
        assert!(
            out.starts_with("partition of C.*[<L.>O] by 4 AOVs\n"),
            "{out}{err}"
        );
        assert!(!out.contains("gap:"), "{out}");
        assert!(
            !out.contains("& rest"),
            "the remainder overlaps nothing: {out}"
        );
    }
    let parts = v["partitions"].as_array().unwrap();
    assert_eq!(parts.len(), 2);
    assert!(parts
        .iter()
        .all(|p| p["checked"] == true && p["clean"] == false));
}

#[test]
fn clean_fixture_exits_zero() {
    let (code, out, err) = lpe_check(&["lint", "tests/testdata/usd/clean_basic.usda"]);
    assert_eq!((code, err.as_str()), (0, ""));
    assert_eq!(
        out,
        "clean: 7 AOVs, 1 file, 1 partition checked (1 clean)\n"
    );
}

#[test]
fn rib_without_and_with_its_ini() {
    let rib = "tests/testdata/lint/display.rib";
    let (code, v) = json(&[rib]);
    assert_eq!(code, 1);
    assert_eq!(
        findings(&v),
        triples(&[
            ("parse_error", "keyDiffuse", "12:59"),
            ("parse_error", "broken", "13:55"),
            ("unfed_lobe", "wetness", "11:56"),
            ("gap", "beauty", "3:1"),
        ])
    );
    // The ini defines the keyDiffuse macro and feeds U5.
    let (code, v) = json(&["tests/testdata/lint/rendermn.ini", rib]);
    assert_eq!(code, 1);
    assert_eq!(
        findings(&v),
        triples(&[("parse_error", "broken", "13:55"), ("gap", "beauty", "3:1")])
    );
    assert_eq!(
        v["findings"][1]["remainder"],
        "C.*[<L.>O] - ((C<.D>.*[<L.>O])|(C<.S>.*[<L.>O])|(CO))"
    );
    let (_, v2) = json(&["--ini", "tests/testdata/lint/rendermn.ini", rib]);
    assert_eq!(findings(&v2), findings(&v));
}

#[test]
fn text_report_points_at_the_expression() {
    let (code, out, _) = lpe_check(&["lint", "tests/testdata/lint/display.rib"]);
    assert_eq!(code, 1);
    let want = "tests/testdata/lint/display.rib:13:55: parse_error: `broken`: the label belongs in the third position of `<type event label>`
  | lpe:C<RD>.*<L'key'>
  |              ^^^^^
  = help: write `<L.'key'>`
";
    assert!(out.contains(want), "{out}");
    assert!(out.ends_with("4 findings: 6 AOVs, 1 file, 1 partition checked (0 clean)\n"));
}

#[test]
fn partition_from_the_command_line() {
    let (code, v) = json(&[
        "--partition",
        "lg_key,lg_env,lg_emission",
        "--partition",
        "direct,nosuch",
        "tests/testdata/usd/arnold_partition.usda",
    ]);
    assert_eq!(code, 1);
    let got = findings(&v);
    assert!(got.contains(&(
        "unknown_member".into(),
        "--partition #2".into(),
        "0:0".into()
    )));
    assert!(got.contains(&("gap".into(), "--partition #1".into(), "0:0".into())));
}

#[test]
fn unreadable_files_exit_two_and_the_rest_is_linted() {
    let dir = std::env::temp_dir().join(format!("lpe-lint-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let garbage = dir.join("garbage.usda");
    std::fs::write(&garbage, b"#usda 1.0\n\x00\x9f\x92\x96").unwrap();
    let truncated = dir.join("truncated.usda");
    let full = std::fs::read(root().join("tests/testdata/usd/hdprman.usda")).unwrap();
    std::fs::write(&truncated, &full[..full.len() * 2 / 3]).unwrap();
    let (code, out, err) = lpe_check(&[
        "lint",
        garbage.to_str().unwrap(),
        truncated.to_str().unwrap(),
        "tests/testdata/usd/clean_basic.usda",
    ]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(err.contains("garbage.usda: byte 10: not text"), "{err}");
    assert!(err.contains("truncated.usda: USD: "), "{err}");
    assert!(out.starts_with("clean: 7 AOVs"), "{out}");
    let (code, _, err) = lpe_check(&["lint", "nothere.rib"]);
    assert_eq!(code, 2);
    assert!(err.contains("nothere.rib"), "{err}");
}

#[test]
fn a_fifty_megabyte_rib_streams_in_bounded_memory() {
    let dir = std::env::temp_dir().join(format!("lpe-lint-big-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let big = dir.join("big.rib");
    {
        use std::io::Write;
        let mut f = std::io::BufWriter::new(std::fs::File::create(&big).unwrap());
        writeln!(
            f,
            "DisplayChannel \"color d\" \"string source\" [\"color lpe:C<RD>L\"]"
        )
        .unwrap();
        let line = format!("Polygon \"P\" [{}]\n", "0 1 2 ".repeat(20));
        for _ in 0..(50 << 20) / line.len() {
            f.write_all(line.as_bytes()).unwrap();
        }
    }
    assert!(std::fs::metadata(&big).unwrap().len() >= 49 << 20);
    let (code, out, err) = lpe_check(&["lint", big.to_str().unwrap()]);
    assert_eq!((code, err.as_str()), (0, ""), "{out}");
    assert!(out.starts_with("clean: 1 AOV, 1 file"), "{out}");
    // One line over the 1 MiB line limit: a clear error with the line, no slurping.
    let long = dir.join("long.rib");
    let mut text = "Option \"a\"\n".to_string();
    text.push_str(&"x".repeat((1 << 20) + 1));
    std::fs::write(&long, text).unwrap();
    let (code, _, err) = lpe_check(&["lint", long.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.contains("long.rib:2: line longer than 1048576 bytes"),
        "{err}"
    );
    std::fs::remove_file(&big).unwrap();
}

#[test]
fn an_undeclared_stage_reports_what_its_two_readings_disagree_on_unless_the_dialect_is_named() {
    let file = "tests/testdata/usd/undeclared_dialect.usda";
    let both = "parses in both dialects and means different things: ";
    // Named, the dialect says which renderer the stage is for: nothing is ambiguous.
    for dialect in ["renderman", "osl"] {
        let (_, v) = json(&["--dialect", dialect, file]);
        let kinds: Vec<&str> = v["findings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["kind"].as_str().unwrap())
            .collect();
        assert!(
            !kinds.contains(&"ambiguous_dialect"),
            "{dialect}: {kinds:?}"
        );
    }
    // `C<RD>L` and `C.*L` mean the same in both; the other two do not, and without
    // `--dialect` the stage does not say who reads it.
    {
        let (code, v) = json(&[file]);
        assert_eq!(code, 1);
        assert_eq!(
            findings(&v),
            triples(&[
                ("ambiguous_dialect", "specular", "/Render/Vars/specular"),
                ("ambiguous_dialect", "diffuse2", "/Render/Vars/diffuse2"),
            ])
        );
        let f = &v["findings"];
        // RenderMan's `S` is every specular lobe, OSL's only the singular one (S8).
        assert_eq!(
            f[0]["message"],
            format!(
                "{both}as RenderMan it matches `C RS1 L`; as OSL it does not match that \
                 path's OSL view `C,~ R,G L,~`"
            )
        );
        assert_eq!(f[0]["witness"], "C RS1 L");
        // OSL reads the `2` of `<RD2>` as a custom label, not a lobe.
        assert_eq!(
            f[1]["message"],
            format!(
                "{both}as RenderMan it matches `C RD2 L`; as OSL it does not match that \
                 path's OSL view `C,~ R,D L,~`"
            )
        );
        assert_eq!(f[1]["witness"], "C RD2 L");
        assert!(f[1]["help"]
            .as_str()
            .unwrap()
            .contains("`custom string lpe:dialect = \"renderman\"`"));
    }
    let (code, out, _) = lpe_check(&["lint", file]);
    assert_eq!(code, 1);
    let want = "tests/testdata/usd/undeclared_dialect.usda:</Render/Vars/specular>.sourceName: \
                ambiguous_dialect: `specular`: parses in both dialects and means different \
                things: as RenderMan it matches `C RS1 L`; as OSL it does not match that \
                path's OSL view `C,~ R,G L,~`
  = witness: C RS1 L
  = help: say which dialect the stage is written in: `custom string lpe:dialect = \"renderman\"` (hdPrman) or `\"osl\"` (Karma, hdArnold, MoonRay) on its RenderSettings prim
";
    assert!(out.starts_with(want), "{out}");
    assert!(out.ends_with("2 findings: 4 AOVs, 1 file, 0 partitions checked (0 clean)\n"));
}

#[test]
fn a_declared_dialect_silences_the_check_and_a_bad_one_is_a_located_error() {
    // The undeclared stage as a sublayer, with `lpe:dialect = "renderman"` over it.
    let (code, out, err) = lpe_check(&["lint", "tests/testdata/usd/declared_dialect.usda"]);
    assert_eq!(
        (code, out.as_str(), err.as_str()),
        (
            0,
            "clean: 4 AOVs, 1 file, 0 partitions checked (0 clean)\n",
            ""
        )
    );
    // `lpe:dialect = "arnold"`: unreadable (exit 2), at the attribute, with the dialect
    // Arnold reads.
    let bad = "tests/testdata/lint/bad_dialect.usda";
    let message = "tests/testdata/lint/bad_dialect.usda: </Render/settings>.lpe:dialect: \
                   unknown dialect `arnold` (expected `renderman` or `osl`); did you mean \
                   `osl`?";
    let (code, out, err) = lpe_check(&["lint", bad]);
    assert_eq!(code, 2);
    assert_eq!(err, format!("error: {message}\n"));
    assert_eq!(
        out,
        "clean: 0 AOVs, 0 files, 0 partitions checked (0 clean)\n"
    );
    let (code, v) = json(&[bad]);
    assert_eq!(code, 2);
    assert_eq!(v["files"][0]["error"], message);
    assert_eq!(v["findings"], serde_json::json!([]));
}

#[test]
fn rib_channels_are_renderman_and_never_ambiguous() {
    // The expressions the undeclared stage is reported for, as RIB channels.
    let dir = std::env::temp_dir().join(format!("lpe-lint-dialect-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let rib = dir.join("channels.rib");
    let text: String = ["C<RS>L", "C<RD>L", "C<RD2>L", "C.*L"]
        .iter()
        .enumerate()
        .map(|(i, e)| {
            format!("DisplayChannel \"color a{i}\" \"string source\" [\"color lpe:{e}\"]\n")
        })
        .collect();
    std::fs::write(&rib, text).unwrap();
    let (code, out, err) = lpe_check(&["lint", "--dialect", "osl", rib.to_str().unwrap()]);
    // In the OSL run the channels are read as OSL (no check fires on these), and the
    // dialect check stays quiet: RIB says RenderMan by its format.
    assert_eq!(
        (code, out.as_str(), err.as_str()),
        (
            0,
            "clean: 4 AOVs, 1 file, 0 partitions checked (0 clean)\n",
            ""
        )
    );
    let (code, out, _) = lpe_check(&["lint", rib.to_str().unwrap()]);
    assert_eq!(
        (code, out.as_str()),
        (0, "clean: 4 AOVs, 1 file, 0 partitions checked (0 clean)\n")
    );
}

#[test]
fn karma_stage_in_the_osl_dialect() {
    let file = "tests/testdata/usd/karma_osl.usda";
    let (code, v) = json(&["--dialect", "osl", file]);
    assert_eq!(code, 1);
    let vars = "/Render/Products/Vars";
    assert_eq!(
        findings(&v),
        triples(&[
            ("parse_error", "sss", &format!("{vars}/sss")),
            ("empty", "not_key", &format!("{vars}/not_key")),
            ("empty", "never", &format!("{vars}/never")),
            (
                "equivalent",
                "direct_diffuse_copy",
                &format!("{vars}/direct_diffuse_copy")
            ),
            (
                "unknown_light_group",
                "diffuse_fill",
                &format!("{vars}/diffuse_fill")
            ),
            ("gap", "beauty", "/Render/rendersettings"),
        ])
    );
    let f = &v["findings"];
    // OSL's own message, at the `*` OSL refuses inside `<...>`.
    assert_eq!(f[0]["message"], "Repetitions not allowed inside '<...>'");
    assert_eq!(f[0]["span"], serde_json::json!([5, 6]));
    // Every path to the key light also ends in a light: nothing is left.
    let message = |k: usize| f[k]["message"].as_str().unwrap().to_string();
    assert!(
        message(1).contains("set algebra leaves no path"),
        "{}",
        message(1)
    );
    assert!(
        message(2).contains("`<R[]>` matches no vertex"),
        "{}",
        message(2)
    );
    assert_eq!(f[3]["other"], "diffuse_direct");
    assert_eq!(f[4]["help"], "did you mean 'fill'?");
    // Every member needs a bounce: a camera straight into a light is lost.
    assert_eq!(f[5]["witness"], "C,~ L,~");
    let rest = f[5]["remainder"].as_str().unwrap();
    assert!(rest.starts_with("<C.><[RT][DGS]>*<L.>|<O.> - (("), "{rest}");
    // The remainder covers exactly the direct paths (worked out by hand: every member
    // starts with one bounce), and the equivalence check confirms it.
    let (code, out, _) = lpe_check(&["equiv", "--dialect", "osl", rest, "C[LO]"]);
    assert_eq!((code, out.as_str()), (0, "equivalent\n"), "{rest}");
    // `floor` is a Karma object tag of the stage, so `floor_bounce` is clean.
    assert!(!findings(&v).iter().any(|f| f.1 == "floor_bounce"));
    // The text report carries OSL's caret on the same byte.
    let (_, out, _) = lpe_check(&["lint", "--dialect", "osl", file]);
    assert!(
        out.contains("Repetitions not allowed inside '<...>'\n  | C<TD.*[LO]\n  |      ^\n"),
        "{out}"
    );
}

#[test]
fn set_algebra_members_make_a_clean_osl_partition() {
    let (code, out, err) = lpe_check(&[
        "lint",
        "--dialect",
        "osl",
        "tests/testdata/usd/arnold_osl_algebra.usda",
    ]);
    assert_eq!(
        (code, out.as_str()),
        (0, "clean: 3 AOVs, 1 file, 1 partition checked (1 clean)\n"),
        "{err}"
    );
    // Without the algebra member the key light's complement is a gap.
    let (code, v) = json(&[
        "--dialect",
        "osl",
        "--partition",
        "lg_key,lg_env",
        "tests/testdata/usd/arnold_osl_algebra.usda",
    ]);
    assert_eq!(code, 1);
    let gap = v["findings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|f| f["kind"] == "gap")
        .unwrap();
    assert_eq!(gap["witness"], "C,~ L,~");
}

#[test]
fn lint_in_the_osl_dialect_refuses_ini_files_and_renderman_refuses_register() {
    // An ini file holds RenderMan macros and lobe mappings: nothing OSL can use.
    let (code, _, err) = lpe_check(&[
        "lint",
        "--dialect",
        "osl",
        "tests/testdata/lint/rendermn.ini",
        "tests/testdata/usd/karma_osl.usda",
    ]);
    assert_eq!(code, 2);
    assert_eq!(
        err,
        "error: tests/testdata/lint/rendermn.ini: --ini holds RenderMan macros; it does not \
         apply to --dialect osl\n"
    );
    let (code, _, err) = lpe_check(&[
        "lint",
        "--register",
        "events=U",
        "tests/testdata/usd/clean_basic.usda",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("--register is for --dialect osl"), "{err}");
    // `--register` goes with `--dialect osl`.
    let (code, _, _) = lpe_check(&[
        "lint",
        "--dialect",
        "osl",
        "--register",
        "scatters=Y",
        "tests/testdata/usd/arnold_osl_algebra.usda",
    ]);
    assert_eq!(code, 0);
}

#[test]
fn explain_an_osl_path() {
    let (code, out, err) = lpe_check(&[
        "explain",
        "--dialect",
        "osl",
        "--usd",
        "tests/testdata/usd/arnold_osl_algebra.usda",
        "C,_ R,D R,G L,_,env",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.starts_with("path C,_ R,D R,G L,_,env against 3 AOVs\n"),
        "{out}"
    );
    // Not the key light: the set-algebra AOV takes it, with the env light group.
    assert!(out.ends_with("lands in: lg_rest, lg_env\n"), "{out}");
    let (code, out, _) = lpe_check(&[
        "explain",
        "--dialect",
        "osl",
        "--aov",
        "spec=C<RG>L",
        "--aov",
        "twice=C<RD><RD>L",
        "C,_ R,D R,G L,_",
    ]);
    assert_eq!(code, 1, "{out}");
    // States read `s1`, `s2` in the order the path reaches them, `dead` after `R,G`.
    let rows: Vec<(String, String, String)> = out
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| #"))
        .map(|l| {
            let c: Vec<&str> = l.split('|').map(str::trim).collect();
            (c[2].to_string(), c[4].to_string(), c[5].to_string())
        })
        .collect();
    let row = |v: &str, s: &str, r: &str| (v.to_string(), s.to_string(), r.to_string());
    assert_eq!(
        rows,
        [
            row("C,_", "s1", "spec, twice"),
            row("R,D", "s2", "twice"),
            row("R,G", "dead", "(none: dead)"),
            row("L,_", "dead", "(none: dead)"),
        ]
    );
    assert!(
        out.ends_with("longest live prefix: C,_ R,D (2 of 4 vertices)\nclosest AOV: twice (dead at vertex 3)\n"),
        "{out}"
    );
    // A path that is no OSL path is bad input, named.
    let (code, _, err) = lpe_check(&["explain", "--dialect", "osl", "--aov", "a=CL", "C,'x"]);
    assert_eq!(code, 2);
    assert!(err.contains("path `C,'x`"), "{err}");
}

#[test]
fn explain_from_a_stage() {
    let (code, out, _) = lpe_check(&[
        "explain",
        "--usd",
        "tests/testdata/usd/solaris_karma.usda",
        "C RD RS L'key'",
    ]);
    assert_eq!(code, 0, "{out}");
    assert!(out.ends_with("lands in: diffuse_key\n"), "{out}");
    let (code, out, _) = lpe_check(&[
        "explain",
        "--from",
        "tests/testdata/lint/display.rib",
        "--ini",
        "tests/testdata/lint/rendermn.ini",
        "--aov",
        "glass=C<TS>+L",
        "C RS TD L",
    ]);
    // `broken` does not parse: bad input.
    assert_eq!(code, 2, "{out}");
    let (code, out, _) = lpe_check(&[
        "explain",
        "--aov",
        "glass=C<TS>+L",
        "--aov",
        "mirror=C<RS><RS>L",
        "C RS TD L",
    ]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.ends_with("lands in no AOV\nlongest live prefix: C RS1 (2 of 4 vertices)\nclosest AOV: mirror (dead at vertex 3)\n"),
        "{out}"
    );
}

/// `--renderer karma`: the Solaris stage's `specular_key` (`C<RS>.*<L.'key'>`) asks for an
/// `S` scattering, which Karma never produces (docs/profiles.md, Karma): `never_produced`,
/// citing the rule and its page; the other findings are the stage's own, and no
/// `ambiguous_dialect` (the renderer names the dialect). A typo'd renderer, or a
/// `--dialect` the renderer does not read, is bad input.
#[test]
fn lint_under_karmas_profile_flags_what_karma_never_renders() {
    let file = "tests/testdata/usd/solaris_karma.usda";
    let (code, v) = json(&["--renderer", "karma", file]);
    assert_eq!(code, 1);
    assert_eq!(
        findings(&v),
        triples(&[
            (
                "unknown_light_group",
                "diffuse_fill",
                "/Render/Products/Vars/diffuse_fill"
            ),
            (
                "never_produced",
                "specular_key",
                "/Render/Products/Vars/specular_key"
            ),
        ])
    );
    let message = v["findings"][1]["message"].as_str().unwrap();
    assert!(
        message.contains("renders black in Karma") && message.contains("`<.[Ss]>`"),
        "{message}"
    );
    assert!(
        message.contains("sidefx.com/docs/houdini/solaris"),
        "{message}"
    );
    let (code, _, err) = lpe_check(&["lint", "--renderer", "karm", file]);
    assert_eq!(code, 2);
    assert!(err.contains("did you mean `karma`?"), "{err}");
    let (code, _, err) = lpe_check(&[
        "lint",
        "--renderer",
        "karma",
        "--dialect",
        "renderman",
        file,
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("contradicts --renderer karma"), "{err}");
}

/// `--renderer hdprman`: every `lpe:`-marked sourceName of sourceType lpe is a
/// `doubled_lpe_mark` (hdPrman prepends the mark itself), with the unmarked source as
/// help, and the raw `P` RenderVar is not; `--renderer renderman` reads the same stage
/// with RenderMan's rules and no ambiguity finding.
#[test]
fn lint_under_hdprmans_profile_flags_the_doubled_lpe_mark() {
    let file = "tests/testdata/usd/hdprman.usda";
    let (code, v) = json(&["--renderer", "hdprman", file]);
    assert_eq!(code, 1);
    let doubled: Vec<(String, String)> = v["findings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["kind"] == "doubled_lpe_mark")
        .map(|f| {
            (
                f["subject"].as_str().unwrap().to_string(),
                f["help"].as_str().unwrap().to_string(),
            )
        })
        .collect();
    let subjects: Vec<&str> = doubled.iter().map(|(s, _)| s.as_str()).collect();
    assert_eq!(
        subjects,
        [
            "directDiffuse",
            "indirectDiffuse",
            "diffuseAgain",
            "rimLight",
            "albedo",
            "wetness",
            "lightBehindCamera"
        ]
    );
    assert_eq!(
        doubled[0].1,
        "write the sourceName without its mark: `C<RD>[<L.>O]`"
    );
    let (_, rm) = json(&["--renderer", "renderman", file]);
    let kinds: Vec<&str> = rm["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["parse_error", "empty", "equivalent", "unfed_lobe"]);
}

/// Without `--renderer`, a stage names its renderer: `karma_settings.usda` by its
/// `karma:` RenderSettings attributes (Karma's `A` and `unoccluded;` parse, its `S` is
/// never produced), `renderer_declared.usda` by `lpe:renderer = "hdprman"` (the marked
/// sourceName is doubled). Two stages naming different renderers, and an `lpe:renderer`
/// that names no profile, are bad input (exit 2) with the names.
#[test]
fn a_stage_names_its_renderer_by_attribute_or_by_its_settings_namespace() {
    let (code, v) = json(&["tests/testdata/usd/karma_settings.usda"]);
    assert_eq!(code, 1);
    assert_eq!(
        findings(&v),
        triples(&[("never_produced", "specular", "/vars/specular")])
    );
    let (code, v) = json(&["tests/testdata/usd/renderer_declared.usda"]);
    assert_eq!(code, 1);
    assert_eq!(
        findings(&v),
        triples(&[("doubled_lpe_mark", "marked", "/vars/marked")])
    );
    let (code, _, err) = lpe_check(&[
        "lint",
        "tests/testdata/usd/karma_settings.usda",
        "tests/testdata/usd/renderer_declared.usda",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("names renderer `hdprman`, but tests/testdata/usd/karma_settings.usda"),
        "{err}"
    );
    // Naming the dialect reads as told, with no renderer: plain OSL refuses Karma's `A`
    // and `unoccluded;`, and nothing is never_produced.
    let (_, v) = json(&["--dialect", "osl", "tests/testdata/usd/karma_settings.usda"]);
    let kinds: Vec<&str> = v["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["parse_error", "parse_error"], "{v}");
    let dir = std::env::temp_dir().join(format!("lpe-renderer-attr-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.usda");
    std::fs::write(
        &bad,
        "#usda 1.0\ndef RenderSettings \"s\"\n{\n    custom string lpe:renderer = \"karm\"\n}\n",
    )
    .unwrap();
    let (code, _, err) = lpe_check(&["lint", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.contains("</s>.lpe:renderer") && err.contains("did you mean `karma`?"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A scratch folder of `.usda` stages for one test, removed when dropped.
struct Stages(PathBuf);

impl Stages {
    fn new(name: &str) -> Stages {
        let dir = std::env::temp_dir().join(format!("lpe-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Stages(dir)
    }

    /// Writes `NAME.usda`: RenderSettings with `settings` as its attributes, then one LPE
    /// RenderVar per `(name, sourceName)` under `/vars`; returns its path.
    fn write(&self, name: &str, settings: &str, vars: &[(&str, &str)]) -> String {
        let mut text = format!("#usda 1.0\ndef RenderSettings \"settings\"\n{{\n{settings}}}\n");
        text += "def Scope \"vars\"\n{\n";
        for (var, source) in vars {
            text += &format!(
                "    def RenderVar \"{var}\"\n    {{\n        uniform token sourceType = \"lpe\"\n        \
                 uniform string sourceName = \"{source}\"\n    }}\n"
            );
        }
        text += "}\n";
        let path = self.0.join(format!("{name}.usda"));
        std::fs::write(&path, text).unwrap();
        path.to_str().unwrap().to_string()
    }
}

impl Drop for Stages {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// `(kind, subject, file)` of every finding.
fn kinds_by_file(v: &serde_json::Value) -> Vec<(String, String, String)> {
    v["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let file = f["file"].as_str().unwrap();
            let name = file.rsplit('/').next().unwrap();
            (
                f["kind"].as_str().unwrap().to_string(),
                f["subject"].as_str().unwrap().to_string(),
                name.to_string(),
            )
        })
        .collect()
}

/// Under Karma, `C<RD>L - C<RD>L` matches no path at all, so every path it matches
/// passes `S` vacuously: it is reported `empty` and not also `never_produced`. The skip is for that
/// AOV of that file only: `specular` beside it and `dark` of another file, which asks for
/// `S`, are `never_produced`. A marked sourceName is no finding under Karma, which reads
/// it as authored. Planted faults (cargo-mutants), each seen failing: the skip's `kind ==
/// Empty`, `subject` or `file` test as `!=`, either `&&` as `||`; the doubled-mark check
/// run for a renderer that does not prepend the mark (`&&` as `||`).
#[test]
fn under_karma_an_empty_aov_is_only_empty_and_the_skip_is_per_aov_and_file() {
    let stages = Stages::new("karma-empty");
    let a = stages.write(
        "a",
        "",
        &[
            ("dark", "C<RD>L - C<RD>L"),
            ("specular", "C<RS>.*L"),
            ("marked", "lpe:C<RD>L"),
        ],
    );
    let b = stages.write("b", "", &[("dark", "C<RS>.*L")]);
    let (code, v) = json(&["--renderer", "karma", &a, &b]);
    assert_eq!(code, 1);
    let want = [
        ("empty", "dark", "a.usda"),
        ("never_produced", "specular", "a.usda"),
        ("never_produced", "dark", "b.usda"),
    ];
    assert_eq!(kinds_by_file(&v), triples(&want), "{v}");
}

/// A stage whose RenderSettings use two renderers' namespaces (`karma:` and hdPrman's
/// `ri:`) names neither: it lints as a stage with no namespace, with no renderer's rule.
/// Two stages that both name Karma agree: both are linted under it. Planted faults, each
/// seen failing: `of_document` taking the first of two namespaces (by hand); `named_by`
/// calling any two namings a conflict (cargo-mutants).
#[test]
fn two_namespaces_name_no_renderer_and_two_stages_naming_one_agree() {
    let stages = Stages::new("two-namespaces");
    let vars = [("specular", "C<RS>.*L"), ("marked", "lpe:C<RD>L")];
    let both = stages.write(
        "both",
        "    uniform int karma:global:pathtracedsamples = 8\n    uniform int ri:hider:maxsamples = 8\n",
        &vars,
    );
    let none = stages.write("none", "", &vars);
    let (code_both, v_both) = json(&[&both]);
    let (code_none, v_none) = json(&[&none]);
    assert_eq!(code_both, code_none);
    assert_eq!(findings(&v_both), findings(&v_none));
    assert!(!findings(&v_both)
        .iter()
        .any(|(kind, _, _)| kind == "never_produced" || kind == "doubled_lpe_mark"));

    let karma = "    uniform int karma:global:pathtracedsamples = 8\n";
    let one = stages.write("one", karma, &[("specular", "C<RS>.*L")]);
    let two = stages.write(
        "two",
        "    custom string lpe:renderer = \"karma\"\n",
        &[("specular", "C<RS>.*L")],
    );
    let (code, v) = json(&[&one, &two]);
    assert_eq!(code, 1);
    let want = [
        ("never_produced", "specular", "one.usda"),
        ("never_produced", "specular", "two.usda"),
    ];
    assert_eq!(kinds_by_file(&v), triples(&want), "{v}");
}
