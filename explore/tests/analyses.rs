//! The `explain`, `paths`, `partition` and `equiv` views against answers worked out by
//! hand, and their error statuses.

use lpe_explore::answer;
use serde_json::{json, Value};

/// The reply of `view` for `body`, its status and its JSON.
fn ask(view: &str, body: Value) -> (u16, Value) {
    let reply = answer(view, body.to_string().as_bytes());
    (reply.status, serde_json::from_str(&reply.json).unwrap())
}

/// `C RD RS L` against `direct = C<RD>L`, `ind = C<RD>.+L`: after `RS` only `ind` is
/// reachable, and the path lands in it. Every state and edge the trace names is one the
/// `graph` view draws (same list, same ids).
///
/// Caught a planted fault: the edge named from the state after the vertex to the one
/// before it (`e3-1`, which the graph does not have).
#[test]
fn explain_steps_with_the_graph_ids() {
    let aovs = "direct = C<RD>L\nind = C<RD>.+L";
    let (status, v) = ask("explain", json!({"aovs": aovs, "path": "C RD RS L"}));
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["path"], "C RD1 RS1 L");
    assert_eq!(v["landed"], json!(["ind"]));
    assert_eq!(v["dies_at"], Value::Null);
    let steps = v["steps"].as_array().unwrap();
    assert_eq!(steps.len(), 4);
    assert_eq!(
        (steps[0]["from"].as_str(), steps[0]["to"].as_str()),
        (Some("s0"), Some("s1"))
    );
    assert_eq!(steps[0]["edge"], "e0-1");
    assert_eq!(steps[1]["reachable"], json!(["direct", "ind"]));
    assert_eq!(steps[2]["reachable"], json!(["ind"]));
    let (_, g) = ask("graph", json!({"aovs": aovs}));
    let edges: Vec<&str> = g["edges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e["id"].as_str().unwrap())
        .collect();
    let states: Vec<&str> = g["states"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["id"].as_str().unwrap())
        .collect();
    for s in steps {
        assert!(
            edges.contains(&s["edge"].as_str().unwrap()),
            "{s} not in {edges:?}"
        );
        assert!(states.contains(&s["to"].as_str().unwrap()));
    }
    let last = steps[3]["to"].as_str().unwrap();
    let accepting = &g["states"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["id"] == last)
        .unwrap()["accepts"];
    assert_eq!(accepting, &json!(["ind"]));
}

/// `C RD RS L` against `spec = C<RS>L`, `diffuse2 = C<RD><RD>L`: `spec` dies at `RD`,
/// `diffuse2` at `RS` (vertex 3), where the whole set dies; the closest miss is
/// `diffuse2`, alive for two vertices.
///
/// Caught a planted fault: `dies_at` 0-based (2).
#[test]
fn explain_says_where_a_path_dies() {
    let (_, v) = ask(
        "explain",
        json!({"aovs": "spec = C<RS>L\ndiffuse2 = C<RD><RD>L", "path": "C RD RS L"}),
    );
    assert_eq!(v["dies_at"], 3);
    assert_eq!(v["landed"], json!([]));
    assert_eq!(
        v["closest"],
        json!({"aov": "diffuse2", "alive_for": 2, "ends_too_early": false})
    );
    let third = &v["steps"][2];
    assert_eq!(
        (
            third["dead"].as_bool(),
            third["to"].clone(),
            third["edge"].clone()
        ),
        (Some(true), Value::Null, Value::Null)
    );
    assert_eq!(third["from"], "s2");
}

/// OSL paths are OSL's text; a path that does not read is a 422, a missing one a 400.
#[test]
fn explain_reads_the_dialects_path() {
    let (status, v) = ask(
        "explain",
        json!({"aovs": "a = C<RD>L", "dialect": "osl", "path": "C,_ R,D L,_"}),
    );
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["landed"], json!(["a"]));
    let (status, v) = ask("explain", json!({"aovs": "a = C<RD>L", "path": "RD L"}));
    assert_eq!(status, 422);
    assert!(
        v["error"].as_str().unwrap().starts_with("`path`: vertex 1"),
        "{v}"
    );
    let (status, _) = ask("explain", json!({"aovs": "a = C<RD>L"}));
    assert_eq!(status, 400);
}

/// `a = C<RD>L` and `b = C.*L` over `C.*[<L.>O]`: both match `C RD L` (the shortest
/// overlap), neither matches `C O` (the shortest gap: `C L` is `b`'s), and the
/// remainder is the universe minus both.
///
/// Caught a planted fault: the gap row dropped when there are overlaps.
#[test]
fn partition_rows_with_witnesses_and_remainder() {
    let (status, v) = ask("partition", json!({"aovs": "a = C<RD>L\nb = C.*L"}));
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["universe"], "C.*[<L.>O]");
    assert_eq!(
        (v["decided"].as_bool(), v["clean"].as_bool()),
        (Some(true), Some(false))
    );
    assert_eq!(
        v["rows"],
        json!([
            {"kind": "overlap", "aovs": ["a", "b"], "witness": "C RD1 L"},
            {"kind": "gap", "aovs": [], "witness": "C O"}
        ])
    );
    assert_eq!(v["remainder"], "C.*[<L.>O] - ((C<RD>L)|(C.*L))");
}

/// RenderMan's seven basic AOVs partition the default universe. Against the universe
/// `C<RD>[<L.>O]`, `d` covers it alone and `e` matches only outside it, shortest `C L`.
#[test]
fn partition_clean_and_outside() {
    let basic = "directDiffuse\nindirectDiffuse\nsubsurface\ndirectSpecular\nindirectSpecular\ntransmissive\nemissive";
    let (_, v) = ask("partition", json!({"aovs": basic}));
    assert_eq!(
        (v["clean"].as_bool(), v["rows"].clone()),
        (Some(true), json!([]))
    );
    let (_, v) = ask(
        "partition",
        json!({"aovs": "d = C<RD>[<L.>O]\ne = C[<L.>O]", "universe": "C<RD>[<L.>O]"}),
    );
    assert_eq!(
        v["rows"],
        json!([{"kind": "outside", "aovs": ["e"], "witness": "C L"}])
    );
    let (status, v) = ask(
        "partition",
        json!({"aovs": "d = C<RD>L", "universe": "C<RD"}),
    );
    assert_eq!(status, 422);
    assert_eq!(v["error"], "`universe` column 2: unclosed `<`");
}

/// `C.+L` against `C.*L`: the left is strictly included; `C L` is the right's alone.
/// A side may name a line; two names of one expression are equivalent.
///
/// Caught a planted fault: the verdict's sides swapped (`right_in_left`).
#[test]
fn equiv_verdicts_and_witnesses() {
    let (status, v) = ask(
        "equiv",
        json!({"aovs": "plus = C.+L", "left": "plus", "right": "C.*L"}),
    );
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["verdict"], "left_in_right");
    assert_eq!(
        (v["only_left"].clone(), v["only_right"].as_str()),
        (Value::Null, Some("C L"))
    );
    assert_eq!(
        v["left"],
        json!({"given": "plus", "line": "plus", "expression": "C.+L"})
    );
    assert_eq!(v["right"]["line"], Value::Null);
    let (_, v) = ask(
        "equiv",
        json!({"aovs": "", "left": "C<RD>L", "right": "(C<RD>L)|(C<RS>L)"}),
    );
    assert_eq!(v["verdict"], "left_in_right");
    let (_, v) = ask(
        "equiv",
        json!({"aovs": "", "left": "C<RD>L", "right": "C<RS>L"}),
    );
    assert_eq!(
        (
            v["verdict"].as_str(),
            v["only_left"].as_str(),
            v["only_right"].as_str()
        ),
        (Some("incomparable"), Some("C RD1 L"), Some("C RS1 L"))
    );
    let (_, v) = ask(
        "equiv",
        json!({"aovs": "", "left": "directDiffuse", "right": "C<RD>[<L.>O]"}),
    );
    assert_eq!(v["verdict"], "equivalent");
    let (status, _) = ask("equiv", json!({"aovs": "", "left": "C L"}));
    assert_eq!(status, 400);
    let (status, v) = ask("equiv", json!({"aovs": "", "left": "C L", "right": "C<"}));
    assert_eq!(status, 422);
    assert!(
        v["error"]
            .as_str()
            .unwrap()
            .starts_with("`right` column 2:"),
        "{v}"
    );
}

/// `d = C<RD>L`: its shortest path is `C RD L`; deleting the `RD` gives `C L`, which
/// `any = C.*L` takes; replacing it by `RS` lands in `any` too. `any`'s shortest is `C
/// L`. Every path shown reads back and matches.
///
/// Caught a planted fault: near misses kept when the AOV matches them (`d`'s own paths
/// listed as misses).
#[test]
fn paths_shortest_and_near_misses() {
    let (status, v) = ask("paths", json!({"aovs": "d = C<RD>L\nany = C.*L"}));
    assert_eq!(status, 200, "{v}");
    let d = &v["aovs"][0];
    assert_eq!(d["name"], "d");
    assert_eq!(d["shortest"][0], "C RD1 L");
    let misses = d["near_misses"].as_array().unwrap();
    assert_eq!(
        misses[0],
        json!({"path": "C L", "edit": "delete vertex 2 (RD1)", "lands_in": ["any"]})
    );
    assert!(
        misses
            .iter()
            .any(|m| m["path"] == "C RS1 L" && m["lands_in"] == json!(["any"])),
        "{misses:?}"
    );
    for m in misses {
        assert_ne!(
            m["lands_in"].as_array().unwrap().first(),
            Some(&json!("d")),
            "{m}"
        );
    }
    // `any`'s shortest is `C L`: deleting a vertex or replacing one by another class's
    // representative (C, L, RU1, RD1, RS1) leaves no path; inserting a scatter keeps it
    // in `any`, except a user lobe (`RU1`), which `.` does not match.
    let any = &v["aovs"][1];
    assert_eq!(any["shortest"][0], "C L");
    assert_eq!(
        any["near_misses"],
        json!([{"path": "C RU1 L", "edit": "insert RU1 before vertex 2", "lands_in": []}])
    );
    assert_eq!(v["truncated"], false);
}

/// `explain` names only the states `graph` can draw: the first 301 of the breadth-first
/// order. `a = C.*<RD>.{8}L` remembers which of the last nine scatters were `RD`, a
/// window `w` of nine bits (the newest lowest). After `C` (`s1`, `w = 0`) each layer of
/// `k` scatters adds the windows whose highest `RD` is `k` back; an `RD` (class 3)
/// comes before the other scatters (class 4), so layer `k` holds those windows in
/// descending order from `s(2^(k-1) + 1)`: window `w` of layer 9 is `s(257 + 511 - w)`.
/// `RD RD RD RS RD RS RD RS RS` is `w = 111010100b = 468`: `s300`, the last state with
/// an id; `RD RD RD RS RD RS RS RD RD` (`w = 467`) would be `s301`, and the state after
/// `L`, reached only from layer 9, `s513`: both past it. The step numbers count from 1.
///
/// Kills the mutants: `explain.rs` `DRAW_LIMIT + 1` as `-` or `*` (`s300` unnamed),
/// `index: k + 1` as `-` or `*`; `automaton.rs` Explored::of: the limit guard as `false`
/// (the state after `L` named `s513`).
#[test]
fn explain_names_the_states_graph_can_draw() {
    let aovs = "a = C.*<RD>.{8}L";
    let (status, v) = ask(
        "explain",
        json!({"aovs": aovs, "path": "C RD RD RD RS RD RS RD RS RS L"}),
    );
    assert_eq!(status, 200, "{v}");
    let steps = v["steps"].as_array().unwrap();
    let index: Vec<u64> = steps.iter().map(|s| s["index"].as_u64().unwrap()).collect();
    assert_eq!(index, (1..=11).collect::<Vec<u64>>());
    let to: Vec<Value> = steps.iter().map(|s| s["to"].clone()).collect();
    let want: Vec<Value> = [
        "s1", "s2", "s3", "s5", "s10", "s19", "s38", "s75", "s150", "s300",
    ]
    .iter()
    .map(|s| json!(s))
    .chain([Value::Null])
    .collect();
    assert_eq!(to, want);
    assert_eq!(steps[9]["edge"], "e150-300");
    assert_eq!(
        (
            steps[10]["from"].as_str(),
            steps[10]["edge"].clone(),
            steps[10]["dead"].as_bool()
        ),
        (Some("s300"), Value::Null, Some(false))
    );
    assert_eq!(v["landed"], json!(["a"]));
    let (_, v) = ask(
        "explain",
        json!({"aovs": aovs, "path": "C RD RD RD RS RD RS RS RD RD L"}),
    );
    assert_eq!(v["steps"][8]["to"], "s151");
    assert_eq!(v["steps"][9]["to"], Value::Null);
}

/// The shortest walks the `paths` view keeps, worked out by hand:
/// - `any = C.*L` beside `d = C<RD>L`: exactly three, `C L`, then `C RD1 L` and `C RS1
///   L` (classes in order: `RD1`, then `RS1` for the other scatters), no fourth;
/// - `p = C..L`: the walks after `C` and two scatters all reach one state, which keeps
///   the first three to reach it (`C RD RD`, `C RD RS`, `C RS RD`): those three;
/// - `x = C(C|<RD>)+L` (classes `C`, `L`, `RS1`, `RD1`): its state after `C` and one or
///   more items is first reached, at three vertices, by `C C C`, `C C RD` and `C RD C`,
///   which read as no path however they go on; the fourth, `C RD RD`, is not kept, so
///   only `C RD1 L` is shown;
/// - `x = CLL` matches only a sequence that is no path (two emitters): no shortest path
///   and no near miss around it;
/// - with `d`, `e`, `f`, `g` one scatter each and `any`, the four one-path AOVs keep the
///   search going through all 12 lengths; at most three walks per state keep it within
///   [`lpe_explore::paths::MAX_STEPS`] (a few states times six classes times 12).
///
/// Kills the `paths.rs` mutants: `found[i].len() < SHORTEST` as `<=` and the `&&`
/// before `confirmed` as `||` (a fourth path); `*n += 1` as `-=` (one walk kept per
/// state: `p` shows one path) or `*=` (every walk kept: 4^11 walks, `truncated`);
/// `*n < SHORTEST` as `<=` (`C RD1 RD1 L` shown for `x`); `confirmed` as `true` (near
/// misses around `C L L`).
#[test]
fn paths_keep_three_walks_per_state() {
    let shortest = |aovs: &str| {
        let (status, v) = ask("paths", json!({ "aovs": aovs }));
        assert_eq!(status, 200, "{v}");
        v
    };
    let v = shortest("d = C<RD>L\nany = C.*L");
    assert_eq!(
        v["aovs"][1]["shortest"],
        json!(["C L", "C RD1 L", "C RS1 L"])
    );
    let v = shortest("p = C..L\nd = C<RD>L");
    assert_eq!(
        v["aovs"][0]["shortest"],
        json!(["C RD1 RD1 L", "C RD1 RS1 L", "C RS1 RD1 L"])
    );
    let v = shortest("x = C(C|<RD>)+L");
    assert_eq!(v["aovs"][0]["shortest"], json!(["C RD1 L"]));
    let v = shortest("x = CLL\nd = C<RD>L");
    assert_eq!(
        v["aovs"][0],
        json!({"name": "x", "shortest": [], "near_misses": []})
    );
    let v = shortest("d = C<RD>L\ne = C<RS>L\nf = C<TD>L\ng = C<TS>L\nany = C.*L");
    assert_eq!(v["truncated"], false);
    assert_eq!(v["aovs"][0]["shortest"], json!(["C RD1 L"]));
}

/// Every analysis of a view runs within lpe's default steps and 2 seconds
/// (docs/usage.md: past either the answer is `undecided`).
///
/// Kills the mutant `list.rs` budget as `Default::default()` (no time limit).
#[test]
fn analyses_run_within_the_default_steps_and_two_seconds() {
    let b = lpe_explore::list::budget();
    assert_eq!(b.steps, lpe::analysis::DEFAULT_STEPS);
    assert_eq!(b.time, Some(std::time::Duration::from_secs(2)));
}

/// Near misses are distinct paths. `e = C<RD><RD>L`'s shortest is `C RD1 RD1 L`
/// (classes `C`, `L`, `RS1` for the other scatters, `RD1`): deleting vertex 2 or 3
/// both give `C RD1 L`, listed once; then each `RD1` replaced by `RS1`, then `RS1` and
/// `RD1` inserted before vertex 2 (the candidates that read as no path skipped), five
/// in all.
///
/// Kills the mutant `paths.rs` near_misses: the second `||` of the skip as `&&`
/// (`a || b && c`: a path the AOV does not match listed again).
#[test]
fn near_misses_are_distinct_paths() {
    let (_, v) = ask("paths", json!({"aovs": "e = C<RD><RD>L"}));
    assert_eq!(v["aovs"][0]["shortest"], json!(["C RD1 RD1 L"]));
    let misses: Vec<(&str, &str)> = v["aovs"][0]["near_misses"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| (m["path"].as_str().unwrap(), m["edit"].as_str().unwrap()))
        .collect();
    assert_eq!(
        misses,
        [
            ("C RD1 L", "delete vertex 2 (RD1)"),
            ("C RS1 RD1 L", "replace vertex 2 (RD1) by RS1"),
            ("C RD1 RS1 L", "replace vertex 3 (RD1) by RS1"),
            ("C RS1 RD1 RD1 L", "insert RS1 before vertex 2"),
            ("C RD1 RD1 RD1 L", "insert RD1 before vertex 2"),
        ]
    );
}

/// `b`: `C L`, `C TD* L`, a path `C RS'kN' L` through each of 300 labelled scatters,
/// and `C.*<RD>.{10}L`, which keeps a window of the last 11 scatters: at each length ℓ
/// up to 12 its automaton has about 2^(ℓ-2) states, each kept with three walks and
/// stepped over the 306 classes (`C`, `L`, `RU`, `RD`, `TD`, the 300 labelled `RS`,
/// the other scatters). A search through every length takes about 306 × 3 × (2 + 4 + … +
/// 1 024) ≈ 1.9 million steps, past [`lpe_explore::paths::MAX_STEPS`].
fn windowed() -> String {
    let labelled: Vec<String> = (0..300).map(|n| format!("(C<RS'k{n}'>L)")).collect();
    format!("b = (C<TD>*L)|(C.*<RD>.{{10}}L)|{}", labelled.join("|"))
}

/// The `paths` search stops as soon as every AOV has its three paths: [`windowed`]'s
/// `b` is done at length 3 (`C L`, two labelled paths), far from the step limit.
///
/// Kills the mutant `paths.rs` shortest: the stop `next.is_empty() || found.iter()…` as
/// `&&` (the search going on once every AOV is done, to the step limit).
#[test]
fn paths_stop_once_every_aov_has_its_paths() {
    let (status, v) = ask("paths", json!({ "aovs": windowed() }));
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["truncated"], false);
    let shortest = v["aovs"][0]["shortest"].as_array().unwrap();
    assert_eq!(shortest.len(), 3);
    assert_eq!(shortest[0], "C L");
    for p in &shortest[1..] {
        assert_eq!(p.as_str().unwrap().split(' ').count(), 3, "{p}");
    }
}

/// A search past [`lpe_explore::paths::MAX_STEPS`] stops there and says so, with what
/// it found: beside [`windowed`]'s `b`, `a = C<RD>{20}L` has no path within 12
/// vertices, so the search would go through every length (about 1.9 million steps).
///
/// Kills the mutant `paths.rs` shortest: `steps += 1` as `*=` (the count stuck at 0).
#[test]
fn paths_stop_at_the_step_limit_and_say_so() {
    let aovs = format!("a = C<RD>{{20}}L\n{}", windowed());
    let (status, v) = ask("paths", json!({ "aovs": aovs }));
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["truncated"], true);
    assert_eq!(v["aovs"][0]["shortest"], json!([]));
    assert_eq!(v["aovs"][1]["shortest"].as_array().unwrap().len(), 3);
}

/// A list whose `paths` search takes exactly [`lpe_explore::paths::MAX_STEPS`] steps
/// finishes; one step more would stop it. `a = C<RD>{20}L` has no path within 12
/// vertices, so the search goes through all 12 lengths. `b = C(…)L` with 246 operands
/// `(<RS'kN'><RS'kN'>*)` and one `<RS'q'>`; `z = C<RD>{30}(…)L` with `m` operands
/// `<TS'zM'>`, which no walk of 12 vertices reaches but which are classes: 4 + 246 + 1 +
/// `m` classes (`C`, `L`, `RD`, the rest; the labelled ones). Walks per length, each
/// stepped over every class: the start, `C`; then at length 2 the `RD` chain's state,
/// the 246 states of `kN` and the one of `q`: 248; from length 3 to 11 the chain, the
/// 246 `kN` loops and 3 walks kept of the accepted state after `L`: 250 each. 1 + 1 +
/// 248 + 9 × 250 = 2 500 walks; with `m = 149`, 400 classes: 1 000 000 steps, not
/// truncated; with `m = 150`, 1 002 500: truncated.
///
/// Kills the mutants `paths.rs` shortest: `steps > MAX_STEPS` as `>=` or `==`.
#[test]
fn the_step_limit_is_exact() {
    let aovs = |m: usize| {
        let k: Vec<String> = (0..246)
            .map(|n| format!("(<RS'k{n}'><RS'k{n}'>*)"))
            .collect();
        let z: Vec<String> = (0..m).map(|n| format!("<TS'z{n}'>")).collect();
        format!(
            "a = C<RD>{{20}}L\nb = C({}|<RS'q'>)L\nz = C<RD>{{30}}({})L",
            k.join("|"),
            z.join("|")
        )
    };
    for (m, truncated) in [(149, false), (150, true)] {
        let (status, v) = ask("paths", json!({ "aovs": aovs(m) }));
        assert_eq!(status, 200, "{v}");
        assert_eq!(v["truncated"], truncated, "m = {m}");
    }
    let (_, g) = ask("graph", json!({ "aovs": aovs(149) }));
    assert_eq!(g["classes"].as_array().unwrap().len(), 400);
}
