//! The `graph` view against automata worked out by hand, and its drawing's ids.

use lpe_explore::{answer, graph, Request};
use serde_json::Value;

/// The reply of `graph` for `body`, its status and its JSON.
fn ask(body: &str) -> (u16, Value) {
    let reply = answer("graph", body.as_bytes());
    (reply.status, serde_json::from_str(&reply.json).unwrap())
}

/// The typed view of an AOV list in RenderMan's dialect.
fn graph_of(aovs: &str) -> lpe_explore::Graph {
    graph(&Request {
        aovs: aovs.into(),
        ..Request::default()
    })
    .unwrap()
}

/// `C<RD>L` by hand: start, after `C`, after `C RD`, after `C RD L` (accepting `d`);
/// three edges, one class each; four classes (`C`, `L`, `RD`, every other scatter).
///
/// Caught a planted fault: transitions into the dead state kept (every state then had
/// edges to a fifth state).
#[test]
fn a_chain_has_its_four_states_and_three_edges() {
    let (status, v) = ask(r#"{"aovs": "d = C<RD>L"}"#);
    assert_eq!(status, 200, "{v}");
    assert_eq!(
        (v["state_count"].as_u64(), v["edge_count"].as_u64()),
        (Some(4), Some(3))
    );
    assert_eq!(v["complete"], true);
    assert_eq!(v["too_large"], false);
    assert_eq!(v["classes"].as_array().unwrap().len(), 4);
    let states = v["states"].as_array().unwrap();
    let ids: Vec<&str> = states.iter().map(|s| s["id"].as_str().unwrap()).collect();
    assert_eq!(ids, ["s0", "s1", "s2", "s3"]);
    assert_eq!(states[0]["start"], true);
    assert_eq!(states[3]["accepts"], serde_json::json!(["d"]));
    assert_eq!(states[2]["accepts"], serde_json::json!([]));
    let edges: Vec<(&str, &str)> = v["edges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| (e["id"].as_str().unwrap(), e["label"].as_str().unwrap()))
        .collect();
    assert_eq!(edges, [("e0-1", "C"), ("e1-2", "RD1"), ("e2-3", "L")]);
}

/// `C<RD>*L`: the diffuse loop is an edge from `s1` to itself; three states.
#[test]
fn a_star_is_a_self_loop() {
    let g = graph_of("a = C<RD>*L");
    assert_eq!(g.state_count, 3);
    let ids: Vec<&str> = g.edges.iter().map(|e| e.id.as_str()).collect();
    assert_eq!(ids, ["e0-1", "e1-1", "e1-2"]);
    assert_eq!(g.edges[1].vertices, ["RD1"]);
}

/// Classes from one state to the same state are one edge. After `C RD` only `a`
/// (`C.*L`) and `b` are alive; each of the four transport scatter classes (RD, RS, TD,
/// TS; user lobes match no `.`) leads on to the state where only `a` is: one edge of
/// four vertices, labelled with three and `+1`.
///
/// Caught a planted fault: a pair's classes overwritten instead of merged (one vertex left).
#[test]
fn classes_between_two_states_merge_into_one_edge() {
    let g = graph_of("a = C.*L\nb = C<RD>L\nc = C<RS>L\nd = C<TD>L\ne = C<TS>L\nf = C<RU>L");
    let ids: std::collections::BTreeSet<&str> = g.edges.iter().map(|e| e.id.as_str()).collect();
    assert_eq!(ids.len(), g.edges.len(), "{:#?}", g.edges);
    assert_eq!(g.edges[1].id, "e1-2");
    let after_rd = g
        .edges
        .iter()
        .find(|e| e.id == "e3-9")
        .expect("C RD then a scatter");
    assert_eq!(after_rd.vertices, ["RD1", "RS1", "TD1", "TS1"]);
    assert_eq!(after_rd.label, "RD1 | RS1 | TD1 +1");
}

/// The drawing has one shape per state and one path per edge, with the ids of the
/// JSON, accepting states ringed, and labels escaped (`L'key'`).
///
/// Caught a planted fault: the state's properties not decoded (no `id` on the
/// ellipses).
#[test]
fn the_drawing_carries_the_ids() {
    let g = graph_of("k = C<RD>[<L.'key'>]");
    let svg = g.svg.expect("a small set is drawn");
    assert!(
        svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""),
        "{svg}"
    );
    for id in ["s0", "s1", "s2", "s3"] {
        assert_eq!(
            svg.matches(&format!("<ellipse id=\"{id}\"")).count(),
            1,
            "{id}: {svg}"
        );
    }
    for id in ["e0-1", "e1-2", "e2-3"] {
        assert_eq!(
            svg.matches(&format!("<path id=\"{id}\"")).count(),
            1,
            "{id}: {svg}"
        );
    }
    assert_eq!(svg.matches("class=\"ring\"").count(), 1);
    assert!(svg.contains(">L&apos;key&apos;</text>"), "{svg}");
    assert!(!svg.contains("L'key'"), "{svg}");
    assert!(svg.contains("<title>s3: k</title>"), "{svg}");
}

/// `C.*<RD>.{8}L` remembers which of the last nine scatter vertices were diffuse: 2^9
/// window states, the start and the one state after `L`, 514; edges: from each window
/// an `RD` edge and one merged edge for the other scatters (1024), an `L` edge from
/// the 256 windows whose ninth-last vertex was diffuse, and `C` from the start: 1281.
/// Over the limit of 300: counts only.
///
/// Caught a planted fault: the limit check dropped (the states listed and drawn).
#[test]
fn a_large_automaton_gives_its_counts_only() {
    let (status, v) = ask(r#"{"aovs": "a = C.*<RD>.{8}L"}"#);
    assert_eq!(status, 200);
    assert_eq!(v["state_count"], 514);
    assert_eq!(v["edge_count"], 1281);
    assert_eq!(
        (v["too_large"].as_bool(), v["limit"].as_u64()),
        (Some(true), Some(300))
    );
    assert_eq!(v["states"], serde_json::json!([]));
    assert_eq!(v["svg"], Value::Null);
}

/// `C.*<RD>.{6}L`: 2^7 windows, the start and the state after `L`, 130 states; 256
/// window edges, 64 `L` edges and `C`, 321 edges: within the state and edge limits,
/// but its layout needs over 2 000 nodes (each back edge crosses many ranks), so it is
/// `too_large` with its layout's size.
///
/// Caught a planted fault: the layout-node check dropped (the set was drawn).
#[test]
fn a_dense_automaton_is_refused_by_its_layout_size() {
    let (_, v) = ask(r#"{"aovs": "a = C.*<RD>.{6}L"}"#);
    assert_eq!(
        (v["state_count"].as_u64(), v["edge_count"].as_u64()),
        (Some(130), Some(321))
    );
    assert_eq!(v["too_large"], true);
    assert!(v["layout_nodes"].as_u64().unwrap() > 2000, "{v}");
    assert_eq!(v["layout_limit"], 2000);
    assert_eq!(v["svg"], Value::Null);
    // The chain of `C<RD>L` places its four states and a connector per label.
    let (_, v) = ask(r#"{"aovs": "d = C<RD>L"}"#);
    assert_eq!(v["layout_nodes"], 7);
}

/// OSL's vertices print as OSL writes them (`R,D`).
#[test]
fn osl_edges_print_osl_vertices() {
    let (_, v) = ask(r#"{"aovs": "a = C<RD>L", "dialect": "osl"}"#);
    let labels: Vec<&str> = v["edges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e["label"].as_str().unwrap())
        .collect();
    assert_eq!(labels, ["C,~", "R,D", "L,~"]);
}

/// A list that does not parse, or has no AOV, is a 422 naming the line.
#[test]
fn a_broken_list_is_unprocessable() {
    let (status, v) = ask(r#"{"aovs": "ok = C.*L\nbad = C<RD"}"#);
    assert_eq!(status, 422);
    assert_eq!(v["error"], "line 2 column 8 (AOV `bad`): unclosed `<`");
    let (status, v) = ask(r##"{"aovs": "# nothing"}"##);
    assert_eq!(status, 422);
    assert_eq!(v["error"], "the list has no AOV");
}
