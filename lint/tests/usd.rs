//! The USD reader on the repository's fixtures and on broken files, the `lpe:dialect`
//! declaration included.

use std::path::{Path, PathBuf};

use lpe::DialectName;
use lpe_lint::read::{self, Limits};
use lpe_lint::{DialectDecl, DialectProblem, Document, Location, ReadError};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/testdata/usd")
        .join(name)
}

fn read(name: &str) -> Document {
    read::read_file(&fixture(name), &Limits::default()).unwrap()
}

fn scratch(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lpe-lint-usd-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

fn prim(loc: &Location) -> &str {
    match loc {
        Location::Prim { prim, .. } => prim,
        Location::Line { .. } => panic!("a USD location is a prim"),
    }
}

#[test]
fn solaris_uniform_token_and_string() {
    let d = read("solaris_karma.usda");
    let got: Vec<(&str, &str, &str)> = d
        .aovs
        .iter()
        .map(|a| (a.name.as_str(), prim(&a.location), a.source.as_str()))
        .collect();
    assert_eq!(
        got,
        [
            (
                "diffuse_key",
                "/Render/Products/Vars/diffuse_key",
                "C<RD>.*<L.'key'>"
            ),
            (
                "diffuse_fill",
                "/Render/Products/Vars/diffuse_fill",
                "C<RD>.*<L.'fil'>"
            ),
            (
                "specular_key",
                "/Render/Products/Vars/specular_key",
                "C<RS>.*<L.'key'>"
            ),
            (
                "floor_bounce",
                "/Render/Products/Vars/floor_bounce",
                "C.*<R.'floor'>.*[<L.>O]"
            ),
        ]
    );
    assert_eq!(
        d.ordered_vars.as_deref(),
        Some(&["C", "diffuse_key", "diffuse_fill", "specular_key"].map(String::from)[..])
    );
    let lights: Vec<&str> = d
        .light_groups
        .as_ref()
        .unwrap()
        .iter()
        .map(String::as_str)
        .collect();
    assert_eq!(lights, ["fill", "key"]);
    let objects: Vec<&str> = d
        .object_groups
        .as_ref()
        .unwrap()
        .iter()
        .map(String::as_str)
        .collect();
    assert_eq!(objects, ["floor"]);
    assert!(d.partitions.is_empty());
}

#[test]
fn hdprman_non_uniform_and_primvar_vars_skipped() {
    let d = read("hdprman.usda");
    let names: Vec<&str> = d.aovs.iter().map(|a| a.name.as_str()).collect();
    assert_eq!(
        names,
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
    assert_eq!(d.aovs[0].source, "lpe:C<RD>[<L.>O]");
    assert_eq!(d.aovs[0].source_type.as_deref(), Some("lpe"));
    assert_eq!(
        d.light_groups.unwrap().into_iter().collect::<Vec<_>>(),
        ["rim"]
    );
    assert_eq!(
        d.object_groups.unwrap().into_iter().collect::<Vec<_>>(),
        ["hero"]
    );
}

#[test]
fn arnold_string_source_type_and_partitions() {
    let d = read("arnold_partition.usda");
    assert_eq!(d.aovs.len(), 6);
    let parts: Vec<(&str, Vec<&str>)> = d
        .partitions
        .iter()
        .map(|p| {
            (
                p.name.as_str(),
                p.members.iter().map(String::as_str).collect(),
            )
        })
        .collect();
    assert_eq!(
        parts,
        [
            ("beauty", vec!["direct", "indirect", "emission"]),
            ("lightgroups", vec!["lg_key", "lg_env", "lg_emission"]),
        ]
    );
    assert_eq!(
        d.partitions[0].location,
        Location::Prim {
            prim: "/Render/settings".into(),
            attribute: "lpe:partition".into()
        }
    );
    assert_eq!(
        d.light_groups.unwrap().into_iter().collect::<Vec<_>>(),
        ["env", "key", "sun"]
    );
    // No geometry in the stage: object groups cannot be checked.
    assert_eq!(d.object_groups, None);
    assert_eq!(d.ordered_vars, None);
}

#[test]
fn truncated_usda_is_an_error_not_a_panic() {
    let full = std::fs::read(fixture("solaris_karma.usda")).unwrap();
    // Cut at many points, including inside strings and prim bodies.
    for cut in (20..full.len()).step_by(97) {
        let p = scratch("cut.usda", &full[..cut]);
        match read::read_file(&p, &Limits::default()) {
            Err(ReadError::Usd { .. }) => {}
            // A cut between prims can still be a valid (shorter) layer.
            Ok(_) => {}
            Err(e) => panic!("cut at {cut}: unexpected error {e}"),
        }
    }
    let p = scratch("half.usda", &full[..full.len() / 2]);
    let e = read::read_file(&p, &Limits::default()).unwrap_err();
    assert!(matches!(e, ReadError::Usd { .. }), "{e}");
    assert!(e.to_string().contains("half.usda: USD: "), "{e}");
}

#[test]
fn binary_garbage_is_refused_with_its_offset() {
    let mut bytes = b"#usda 1.0\n".to_vec();
    bytes.extend((0u32..4096).map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8));
    let p = scratch("garbage.usda", &bytes);
    let e = read::read_file(&p, &Limits::default()).unwrap_err();
    assert!(matches!(e, ReadError::NotText { .. }), "{e}");
    // Garbage that is text is the USD parser's to refuse.
    let p = scratch("words.usda", b"#usda 1.0\nthis is not usd {{{");
    let e = read::read_file(&p, &Limits::default()).unwrap_err();
    assert!(matches!(e, ReadError::Usd { .. }), "{e}");
    // Not even a header.
    let p = scratch("noheader.usda", b"hello");
    assert!(read::read_file(&p, &Limits::default()).is_err());
}

#[test]
fn over_the_size_limit_is_refused_before_parsing() {
    let limits = Limits {
        usd_bytes: 100,
        ..Limits::default()
    };
    let e = read::read_file(&fixture("hdprman.usda"), &limits).unwrap_err();
    match e {
        ReadError::TooLarge { limit, bytes, .. } => {
            assert_eq!(limit, 100);
            assert_eq!(
                bytes,
                std::fs::metadata(fixture("hdprman.usda")).unwrap().len()
            );
        }
        other => panic!("{other}"),
    }
}

#[test]
fn missing_file_and_unknown_extension() {
    let e = read::read_file(Path::new("/nonexistent/x.usda"), &Limits::default()).unwrap_err();
    assert!(matches!(e, ReadError::Io { .. }), "{e}");
    let e = read::read_file(Path::new("x.txt"), &Limits::default()).unwrap_err();
    assert!(matches!(e, ReadError::UnknownFormat { .. }), "{e}");
}

fn dialect_at(prim: &str) -> Location {
    Location::Prim {
        prim: prim.into(),
        attribute: "lpe:dialect".into(),
    }
}

#[test]
fn the_declared_dialect_and_where_it_is() {
    assert_eq!(read("undeclared_dialect.usda").dialect, None);
    assert_eq!(read("hdprman.usda").dialect, None);
    // Declared in a layer over the undeclared stage (a sublayer): the composed stage.
    let d = read("declared_dialect.usda");
    assert_eq!(d.aovs.len(), 4);
    assert_eq!(
        d.dialect,
        Some(DialectDecl {
            dialect: DialectName::RenderMan,
            location: Some(dialect_at("/Render/settings")),
        })
    );
    // RIB is RenderMan's own format: declared without an attribute.
    let rib = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/testdata/lint/display.rib");
    let d = read::read_file(&rib, &Limits::default()).unwrap();
    assert_eq!(
        d.dialect,
        Some(DialectDecl {
            dialect: DialectName::RenderMan,
            location: None,
        })
    );
}

/// A stage with `body` under `/Render`, as a scratch file.
fn stage(name: &str, body: &str) -> PathBuf {
    scratch(
        name,
        format!("#usda 1.0\n\ndef Scope \"Render\"\n{{\n{body}\n}}\n").as_bytes(),
    )
}

#[test]
fn a_token_on_any_prim_and_agreeing_declarations() {
    let p = stage(
        "token.usda",
        "    uniform token lpe:dialect = \"osl\"\n    def Scope \"a\"\n    {\n        custom string lpe:dialect = \"osl\"\n    }",
    );
    let d = read::read_file(&p, &Limits::default()).unwrap();
    assert_eq!(
        d.dialect,
        Some(DialectDecl {
            dialect: DialectName::Osl,
            location: Some(dialect_at("/Render")),
        })
    );
}

#[test]
fn a_bad_declaration_is_an_error_at_its_attribute() {
    let e = read::read_file(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/testdata/lint/bad_dialect.usda"),
        &Limits::default(),
    )
    .unwrap_err();
    let ReadError::Dialect { at, problem, .. } = &e else {
        panic!("{e}")
    };
    assert_eq!(**at, dialect_at("/Render/settings"));
    assert_eq!(
        **problem,
        DialectProblem::Unknown {
            unknown: lpe::UnknownDialect("arnold".into()),
            suggestion: Some(DialectName::Osl),
        }
    );
    assert!(
        e.to_string().ends_with(
            "bad_dialect.usda: </Render/settings>.lpe:dialect: unknown dialect `arnold` \
             (expected `renderman` or `osl`); did you mean `osl`?"
        ),
        "{e}"
    );
    let error = |body: &str| {
        read::read_file(&stage("bad.usda", body), &Limits::default())
            .unwrap_err()
            .to_string()
    };
    let tail = |e: String| e.split_once(".usda: ").map(|(_, t)| t.to_string()).unwrap();
    assert_eq!(
        tail(error("    custom string lpe:dialect = \"RenderMan\"")),
        "</Render>.lpe:dialect: unknown dialect `RenderMan` (expected `renderman` or \
         `osl`); did you mean `renderman`?"
    );
    assert_eq!(
        tail(error("    custom string lpe:dialect = \"mantra\"")),
        "</Render>.lpe:dialect: unknown dialect `mantra` (expected `renderman` or `osl`)"
    );
    // A number, or an attribute without a value, names no dialect.
    for body in [
        "    custom int lpe:dialect = 1",
        "    custom string lpe:dialect",
    ] {
        assert_eq!(
            tail(error(body)),
            "</Render>.lpe:dialect: expected a string or token, `renderman` or `osl`"
        );
    }
    assert_eq!(
        tail(error(
            "    custom string lpe:dialect = \"osl\"\n    def Scope \"a\"\n    {\n        custom string lpe:dialect = \"renderman\"\n    }"
        )),
        "</Render/a>.lpe:dialect: declares `renderman`, but </Render>.lpe:dialect declares `osl`"
    );
}
