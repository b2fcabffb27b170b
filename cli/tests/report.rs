//! `lpe-check report FILE... --html OUT.html` end to end: the page of the USD fixtures
//! holds every AOV and every lint finding of each file and refers to nothing on the
//! network; an AOV list file is read with its line numbers; a bad file is an error
//! naming it, and no page is written.

mod common;
use common::{lpe_check, root};

use std::path::{Path, PathBuf};

use serde_json::Value;

/// A fresh scratch directory for one test.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lpe-report-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The data the page was written with.
fn data(page: &str) -> Value {
    let open = r#"<script type="application/json" id="lpe-data">"#;
    let start = page.find(open).expect("the data slot") + open.len();
    let end = start + page[start..].find("</script>").unwrap();
    serde_json::from_str(&page[start..end]).unwrap()
}

fn fixtures() -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(root().join("tests/testdata/usd"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "usda"))
        .map(|p| {
            format!(
                "tests/testdata/usd/{}",
                p.file_name().unwrap().to_str().unwrap()
            )
        })
        .collect();
    files.sort();
    files
}

/// Every fixture's AOVs and lint findings are in the page: the AOV names in its text,
/// and per file the findings `lpe-check lint --format json` gives for that file alone,
/// kind, subject and message; every file has its check view. Fault caught: the
/// findings of one kind (`gap`) left out of the page.
#[test]
fn the_report_of_the_usd_fixtures_holds_every_aov_and_finding() {
    let dir = scratch("fixtures");
    let out = dir.join("report.html");
    let files = fixtures();
    assert!(files.len() >= 5, "{files:?}");
    let mut args = vec!["report"];
    args.extend(files.iter().map(String::as_str));
    args.extend(["--html", out.to_str().unwrap()]);
    let (code, stdout, stderr) = lpe_check(&args);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("report.html"), "{stdout}");
    let page = std::fs::read_to_string(&out).unwrap();
    let written = data(&page);
    assert_eq!(written["mode"], "report");
    let entries = written["files"].as_array().unwrap();
    assert_eq!(entries.len(), files.len());
    for (file, entry) in files.iter().zip(entries) {
        assert_eq!(entry["file"], file.as_str());
        let (_, lint, _) = lpe_check(&["lint", "--format", "json", file]);
        let lint: Value = serde_json::from_str(&lint).unwrap();
        let names: Vec<&str> = lint["aovs"]
            .as_array()
            .unwrap()
            .iter()
            .map(|a| a["name"].as_str().unwrap())
            .collect();
        assert!(!names.is_empty(), "{file}");
        for name in &names {
            assert!(page.contains(name), "{file}: AOV {name} not in the page");
        }
        let shown: Vec<&str> = entry["aovs"]
            .as_array()
            .unwrap()
            .iter()
            .map(|a| a["name"].as_str().unwrap())
            .collect();
        assert_eq!(shown, names, "{file}");
        let triple = |f: &Value| {
            (
                f["kind"].as_str().unwrap().to_string(),
                f["subject"].as_str().unwrap().to_string(),
                f["message"].as_str().unwrap().to_string(),
            )
        };
        let expected: Vec<_> = lint["findings"]
            .as_array()
            .unwrap()
            .iter()
            .map(triple)
            .collect();
        let got: Vec<_> = entry["findings"]
            .as_array()
            .unwrap()
            .iter()
            .map(triple)
            .collect();
        assert_eq!(got, expected, "{file}");
        assert_eq!(
            entry["views"]["check"]["lines"].as_array().unwrap().len(),
            names.len(),
            "{file}"
        );
    }
    // Some fixture has findings, so the comparison above compared something.
    assert!(entries
        .iter()
        .any(|e| !e["findings"].as_array().unwrap().is_empty()));
}

/// The page loads nothing from the network: no `src=`, `href=`, CSS `url(` or
/// `@import` names another host. (Findings may cite a renderer's documentation by its
/// address: that is text, not a reference the browser follows.) Fault caught: a
/// stylesheet linked from a web address in the page's head.
#[test]
fn the_report_refers_to_nothing_on_the_network() {
    let dir = scratch("offline");
    let out = dir.join("report.html");
    let files = fixtures();
    let mut args = vec!["report"];
    args.extend(files.iter().map(String::as_str));
    args.extend(["--html", out.to_str().unwrap()]);
    assert_eq!(lpe_check(&args).0, 0);
    let page = std::fs::read_to_string(&out).unwrap().to_ascii_lowercase();
    for reference in ["src=", "href=", "url(", "@import"] {
        for (at, _) in page.match_indices(reference) {
            let value = page[at + reference.len()..].trim_start_matches(['"', '\'', ' ']);
            assert!(
                !value.starts_with("//")
                    && !value.starts_with("http:")
                    && !value.starts_with("https:"),
                "{} refers elsewhere",
                &page[at..(at + 60).min(page.len())]
            );
        }
    }
}

/// An AOV list file (any other extension) is read line by line: lint's parse error and
/// the check view's both sit on the file's line 3 (a comment line counted), and the
/// other views are of the lines that parse. Fault caught: every line handed to the
/// drawing (the list then does not compile: no drawing, a 422).
#[test]
fn an_aov_list_file_keeps_its_line_numbers() {
    let dir = scratch("list");
    let list = dir.join("aovs.txt");
    std::fs::write(&list, "diffuse = C<RD>.*L\n# a comment\nbad = C<RD\n").unwrap();
    let out = dir.join("report.html");
    let (code, _, stderr) = lpe_check(&[
        "report",
        list.to_str().unwrap(),
        "--html",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    let written = data(&std::fs::read_to_string(&out).unwrap());
    let entry = &written["files"][0];
    let names: Vec<&str> = entry["aovs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["diffuse", "bad"]);
    assert_eq!(entry["aovs"][1]["location"], "3:7");
    let parse_errors: Vec<&Value> = entry["findings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["kind"] == "parse_error")
        .collect();
    assert_eq!(parse_errors.len(), 1, "{entry}");
    assert_eq!(parse_errors[0]["subject"], "bad");
    let check = &entry["views"]["check"]["lines"][1];
    assert_eq!(check["error"]["line"], 3);
    assert_eq!(check["error"]["message"], "unclosed `<`");
    // The drawing and the partition are of the one AOV that parses.
    assert_eq!(entry["parsed"], 1);
    let graph = &entry["views"]["graph"];
    assert!(graph["error"].is_null(), "{graph}");
    let accepting: Vec<&Value> = graph["states"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|s| s["accepts"].as_array().unwrap())
        .collect();
    assert_eq!(accepting, ["diffuse"]);
    assert_eq!(entry["views"]["partition"]["rows"][0]["kind"], "gap");
}

/// A file that cannot be read is an error naming it (exit 2), and no page is written.
#[test]
fn a_bad_file_is_an_error_naming_it() {
    let dir = scratch("bad");
    let broken = dir.join("broken.usda");
    std::fs::write(
        &broken,
        "#usda 1.0\ndef Scope \"Render\" {\n  def RenderVar \"x\" {\n",
    )
    .unwrap();
    let missing = dir.join("missing.usda");
    let out = dir.join("report.html");
    for bad in [&broken, &missing] {
        let (code, _, stderr) = lpe_check(&[
            "report",
            "tests/testdata/usd/clean_basic.usda",
            bad.to_str().unwrap(),
            "--html",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, 2, "{stderr}");
        assert!(stderr.contains(bad.to_str().unwrap()), "{stderr}");
        assert!(!Path::new(&out).exists());
    }
}

/// A RIB file with the ini that defines its macro: the views read the AOV with the
/// macro expanded (they are given no ini), and the ini's own part has no AOV. Fault
/// caught: the views given each AOV's source as written (`keyDiffuse` is then an
/// unknown macro and the drawing is missing).
#[test]
fn the_views_read_ini_macros_expanded() {
    let dir = scratch("ini");
    let out = dir.join("report.html");
    let (code, _, stderr) = lpe_check(&[
        "report",
        "tests/testdata/lint/display.rib",
        "tests/testdata/lint/rendermn.ini",
        "--html",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    let written = data(&std::fs::read_to_string(&out).unwrap());
    let rib = &written["files"][0];
    let lines = rib["views"]["check"]["lines"].as_array().unwrap();
    let key = lines.iter().find(|l| l["name"] == "keyDiffuse").unwrap();
    assert_eq!(key["canonical"], "C<RD>.*<L.'key'>", "{key}");
    assert!(written["files"][1]["aovs"].as_array().unwrap().is_empty());
}

/// `--dialect` and `--renderer` choose how every file is read, and the page says how
/// each was read: `C<TG>L` (a glossy transmission, OSL only) is a parse error in
/// RenderMan's dialect and reads in OSL's and under Karma; a stage that names its
/// renderer says where. Faults caught: `--dialect` or `--renderer` not handed to lint
/// (the list is read in RenderMan's dialect), the sentence empty or any other.
#[test]
fn the_dialect_and_renderer_arguments_choose_the_reading_the_page_names() {
    let dir = scratch("reading");
    let list = dir.join("aovs.txt");
    std::fs::write(&list, "glossy = C<TG>L\n").unwrap();
    let out = dir.join("report.html");
    let read = |file: &str, args: &[&str]| -> Value {
        let mut all = vec!["report", file, "--html", out.to_str().unwrap()];
        all.extend(args);
        let (code, _, stderr) = lpe_check(&all);
        assert_eq!(code, 0, "{stderr}");
        data(&std::fs::read_to_string(&out).unwrap())["files"][0].clone()
    };
    let list = list.to_str().unwrap();
    let kinds = |entry: &Value| -> Vec<String> {
        entry["findings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["kind"].as_str().unwrap().to_string())
            .collect()
    };
    let plain = read(list, &[]);
    assert_eq!(plain["reading"], "Read in the renderman dialect.");
    assert_eq!(kinds(&plain), ["parse_error"]);
    let osl = read(list, &["--dialect", "osl"]);
    assert_eq!(osl["reading"], "Read in the osl dialect.");
    assert_eq!(kinds(&osl), Vec::<String>::new());
    assert!(
        osl["views"]["check"]["lines"][0]["error"].is_null(),
        "{osl}"
    );
    let karma = read(list, &["--renderer", "karma"]);
    assert_eq!(
        karma["reading"],
        "Read as Karma (Houdini Solaris) does (karma)."
    );
    assert_eq!(kinds(&karma), Vec::<String>::new());
    let stage = "tests/testdata/usd/karma_settings.usda";
    assert_eq!(
        read(stage, &[])["reading"],
        format!(
            "Read as Karma (Houdini Solaris) does (karma), named by {stage} (the `karma:` \
             attributes of </settings>)."
        )
    );
}

/// An AOV list of exactly the explorer's body limit (1 MiB) is read; one byte more is
/// an error naming the file, its size and the limit (exit 2), and no page is written.
/// Faults caught: the size check as `>=` (the list at the limit refused) or as `==`
/// (the larger list read).
#[test]
fn an_aov_list_is_read_up_to_1_mib() {
    let dir = scratch("limit");
    let list = dir.join("big.txt");
    let out = dir.join("report.html");
    let run = || {
        lpe_check(&[
            "report",
            list.to_str().unwrap(),
            "--html",
            out.to_str().unwrap(),
        ])
    };
    // One AOV, then a comment up to the limit.
    let mut text = String::from("d = C<RD>L\n#");
    text.push_str(&"x".repeat((1 << 20) - text.len()));
    std::fs::write(&list, &text).unwrap();
    let (code, _, stderr) = run();
    assert_eq!(code, 0, "{stderr}");
    let entry = &data(&std::fs::read_to_string(&out).unwrap())["files"][0];
    assert_eq!(entry["aovs"][0]["name"], "d");
    std::fs::remove_file(&out).unwrap();
    text.push('x');
    std::fs::write(&list, &text).unwrap();
    let (code, _, stderr) = run();
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("big.txt: 1048577 bytes, over the 1048576-byte limit for AOV list files"),
        "{stderr}"
    );
    assert!(!out.exists());
}
