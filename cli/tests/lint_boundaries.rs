//! Lint findings that must not fire: for every finding kind of `lpe-check lint` that
//! warns about a valid expression (all but `parse_error`), in each dialect it applies to,
//! the smallest stage that reports it beside the closest stages that must lint clean. A
//! finding tested only where it appears survives a fault that makes it fire everywhere,
//! or one step too early; these pairs fail on either. Each stage is written to a scratch
//! `.usda` file and linted end to end.

use std::path::PathBuf;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// A stage: its declared dialect, the groups its one light and one mesh carry (`None`:
/// no such prim, a settings-only layer), its AOVs and its `lpe:partition`; and the
/// `--universe` it is linted with (`None`: the default).
struct Stage<'a> {
    declared: Option<&'a str>,
    light: Option<&'a str>,
    object: Option<&'a str>,
    aovs: Vec<(&'a str, &'a str)>,
    partition: Option<&'a str>,
    universe: Option<&'a str>,
}

fn stage<'a>(dialect: &'a str, aovs: &[(&'a str, &'a str)]) -> Stage<'a> {
    Stage {
        declared: Some(dialect),
        light: None,
        object: None,
        aovs: aovs.to_vec(),
        partition: None,
        universe: None,
    }
}

impl Stage<'_> {
    fn usda(&self) -> String {
        let mut s = String::from("#usda 1.0\n\ndef RenderSettings \"settings\"\n{\n");
        if let Some(d) = self.declared {
            s += &format!("    custom string lpe:dialect = \"{d}\"\n");
        }
        if let Some(p) = self.partition {
            s += &format!("    custom string lpe:partition = \"{p}\"\n");
        }
        s += "}\n\ndef Scope \"vars\"\n{\n";
        for (name, expr) in &self.aovs {
            s += &format!(
                "    def RenderVar \"{name}\"\n    {{\n        uniform token sourceType = \"lpe\"\n        uniform string sourceName = \"lpe:{expr}\"\n    }}\n"
            );
        }
        s += "}\n\ndef Xform \"World\"\n{\n";
        if let Some(g) = self.light {
            s += &format!("    def SphereLight \"light\"\n    {{\n        string ri:light:lightGroup = \"{g}\"\n    }}\n");
        }
        if let Some(g) = self.object {
            s += &format!("    def Mesh \"mesh\"\n    {{\n        string primvars:ri:attributes:identifier:lpegroup = \"{g}\"\n    }}\n");
        }
        s + "}\n"
    }

    /// The finding kinds `lpe-check lint --dialect run` reports on this stage, in order
    /// (`run` empty: no `--dialect`, RenderMan's by default with undeclared stages read
    /// both ways).
    fn kinds(&self, run: &str) -> Vec<String> {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let file: PathBuf = std::env::temp_dir().join(format!(
            "lpe-lint-boundaries-{}-{}.usda",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::write(&file, self.usda()).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
            .args(["lint", "--format", "json"])
            .args(["--dialect", run].iter().filter(|_| !run.is_empty()))
            .args(self.universe.iter().flat_map(|u| ["--universe", u]))
            .arg(&file)
            .output()
            .expect("lpe-check runs");
        std::fs::remove_file(&file).unwrap();
        let text = String::from_utf8(out.stdout).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap_or_else(|e| {
            panic!(
                "{e}: {text} {}\n{}",
                String::from_utf8_lossy(&out.stderr),
                self.usda()
            )
        });
        let kinds: Vec<String> = v["findings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["kind"].as_str().unwrap().to_string())
            .collect();
        // Exit 1 exactly when something was found.
        let code = out.status.code();
        assert_eq!(code, Some(i32::from(!kinds.is_empty())), "{kinds:?}");
        kinds
    }
}

/// `kind` alone is reported on `warns`, and nothing on each of `quiet`.
fn pair(run: &str, kind: &str, warns: Stage, quiet: &[Stage]) {
    let got = warns.kinds(run);
    assert_eq!(
        got,
        [kind],
        "{run}: should report {kind}:\n{}",
        warns.usda()
    );
    for q in quiet {
        let got = q.kinds(run);
        assert!(
            got.is_empty(),
            "{run}: must lint clean, reported {got:?}:\n{}",
            q.usda()
        );
    }
}

/// The AOVs of one stage.
type Aovs<'a> = &'a [(&'a str, &'a str)];

/// `(dialect, AOVs that report the kind, AOVs of the closest stages that lint clean)`.
type AovPairs<'a> = &'a [(&'a str, Aovs<'a>, &'a [Aovs<'a>])];

fn aov_pairs(kind: &str, pairs: AovPairs) {
    for &(run, warns, quiet) in pairs {
        let quiet: Vec<Stage> = quiet.iter().map(|q| stage(run, q)).collect();
        pair(run, kind, stage(run, warns), &quiet);
    }
}

#[test]
fn an_aov_that_matches_nothing_and_the_closest_that_matches() {
    aov_pairs(
        "empty",
        &[
            (
                "renderman",
                &[("a", "C[^CRTLO]L")],
                &[&[("a", "C[^CRTLO]*L")], &[("a", "C[^CTLO]L")]],
            ),
            (
                "osl",
                &[("a", "C<R[]>L")],
                &[&[("a", "C<R[]>*L")], &[("a", "C<R[D]>L")]],
            ),
        ],
    );
}

#[test]
fn an_aov_equal_to_an_earlier_one_and_the_closest_that_differ() {
    aov_pairs(
        "equivalent",
        &[
            (
                "renderman",
                &[("a", "CDL"), ("b", "C<.D>L")],
                // One type apart, and equal paths under different prefixes: other images.
                &[
                    &[("a", "CDL"), ("b", "C<RD>L")],
                    &[("a", "CDL"), ("b", "unoccluded;CDL")],
                ],
            ),
            (
                "osl",
                &[("a", "C<RD>+L"), ("b", "C<RD><RD>*L")],
                &[&[("a", "C<RD>+L"), ("b", "C<RD>*L")]],
            ),
        ],
    );
}

#[test]
fn a_group_label_the_stage_lacks_and_the_closest_it_carries() {
    for (run, light_aov, object_aov, typo_light, typo_object, negated) in [
        (
            "renderman",
            "C.*<L.'key'>",
            "C'floor'.*L",
            "C.*<L.'kye'>",
            "C'flor'.*L",
            "C.*<L.[^'kye']>",
        ),
        (
            "osl",
            "C.*<L.'key'>",
            "C<..'floor'>.*L",
            "C.*<L.'kye'>",
            "C<..'flor'>.*L",
            "C.*<L.[^'kye']>",
        ),
    ] {
        let scene = |aovs: &[(&'static str, &'static str)]| Stage {
            light: Some("key"),
            object: Some("floor"),
            ..stage(run, aovs)
        };
        // Unknown, known, negated (asks nothing of the scene), and a stage without the
        // prim at all (a settings layer: nothing to check against).
        pair(
            run,
            "unknown_light_group",
            scene(&[("a", typo_light)]),
            &[
                scene(&[("a", light_aov)]),
                scene(&[("a", negated)]),
                stage(run, &[("a", typo_light)]),
            ],
        );
        pair(
            run,
            "unknown_object_group",
            scene(&[("a", typo_object)]),
            &[
                scene(&[("a", object_aov)]),
                stage(run, &[("a", typo_object)]),
            ],
        );
    }
}

#[test]
fn a_lobe_no_mapping_feeds_and_the_closest_lobes_the_defaults_feed() {
    // docs/language.md §2.4: by default D1-D3 and U1-U4, U6 are fed, D4 and U5 are not.
    aov_pairs(
        "unfed_lobe",
        &[
            (
                "renderman",
                &[("a", "C<.D4>L")],
                &[&[("a", "C<.D3>L")], &[("a", "C<.D1>L")]],
            ),
            (
                "renderman",
                &[("a", "C<.U5>L")],
                &[&[("a", "C<.U4>L")], &[("a", "C<.U6>L")]],
            ),
        ],
    );
}

#[test]
fn an_undeclared_stage_whose_readings_differ_and_the_closest_whose_agree() {
    let undeclared = |aovs: &[(&'static str, &'static str)]| Stage {
        declared: None,
        ..stage("", aovs)
    };
    pair(
        "",
        "ambiguous_dialect",
        undeclared(&[("a", "C<RS>L")]),
        &[
            undeclared(&[("a", "C<RD>L")]),
            stage("renderman", &[("a", "C<RS>L")]),
        ],
    );
    // The same stage with the dialect named on the command line lints clean.
    let (ambiguous, named) = (undeclared(&[("a", "C<RS>L")]), "renderman");
    assert_eq!(ambiguous.kinds(named), Vec::<String>::new());
}

#[test]
fn partitions_one_step_from_clean() {
    for (run, all, bounce, direct) in [
        ("renderman", "C.*[<L.>O]", "C.+[<L.>O]", "C[<L.>O]"),
        ("osl", "C.*[LO]", "C.+[LO]", "C[LO]"),
    ] {
        let part = |p, aovs: &[(&'static str, &'static str)]| Stage {
            partition: Some(p),
            ..stage(run, aovs)
        };
        let clean = [part("a,b", &[("a", bounce), ("b", direct)])];
        // A member missing (the rest is a gap), named but absent, overlapping.
        pair(
            run,
            "gap",
            part("a", &[("a", bounce), ("b", direct)]),
            &clean,
        );
        pair(
            run,
            "unknown_member",
            part("a,c", &[("a", bounce), ("b", direct)]),
            &clean,
        );
        pair(
            run,
            "overlap",
            part("a,b", &[("a", all), ("b", direct)]),
            &clean,
        );
        // Reaching past a narrower universe (the default holds every path).
        let indirect = |aovs| Stage {
            universe: Some(bounce),
            ..part("a", aovs)
        };
        pair(
            run,
            "outside",
            indirect(&[("a", all)]),
            &[indirect(&[("a", bounce)])],
        );
    }
}
