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
