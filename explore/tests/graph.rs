//! The `graph` view against automata worked out by hand, and its drawing's ids.

use lpe_explore::draw::{self, CROSSING_LIMIT};
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

/// The reply's counts, whether it is too large, its layout's size and whether it is drawn.
fn limits(aovs: &str) -> (u64, u64, bool, Option<u64>, bool) {
    let (status, v) = ask(&serde_json::json!({ "aovs": aovs }).to_string());
    assert_eq!(status, 200, "{v}");
    (
        v["state_count"].as_u64().unwrap(),
        v["edge_count"].as_u64().unwrap(),
        v["too_large"].as_bool().unwrap(),
        v["layout_nodes"].as_u64(),
        v["svg"].is_string(),
    )
}

/// The state limit is exact. `C<RD>{256}<RS>{41}L` is a chain: the start, the state
/// after `C`, one after each of its 297 scatters and one after `L`, 300 states and 299
/// edges, laid out as 300 states and a connector per label (599 nodes): drawn. One more
/// `RS` makes 301 states (300 edges): too large, with no layout computed.
///
/// Kills the mutants `graph.rs` graph_of: `state_count > DRAW_LIMIT` as `>=` or `==`,
/// and the `||` of the two limits as `&&` (301 states within the edge limit drawn).
#[test]
fn the_state_limit_is_exact() {
    assert_eq!(
        limits("a = C<RD>{256}<RS>{41}L"),
        (300, 299, false, Some(599), true)
    );
    assert_eq!(
        limits("a = C<RD>{256}<RS>{42}L"),
        (301, 300, true, None, false)
    );
}

/// The edge limit is exact. `C(<RD><RS>*){199}L`: the start, after `C`, after each of
/// the 199 `RD`s and after `L`, 202 states; edges `C`, the 199 `RD`s, an `RS` loop on
/// each state after an `RD` and `L`, 400 (602 layout nodes): drawn. A `TD` before `L`
/// adds a state and an edge: 401 edges, too large.
///
/// Kills the mutants `graph.rs` graph_of: `edge_count > DRAW_EDGE_LIMIT` as `>=` or
/// `==`.
#[test]
fn the_edge_limit_is_exact() {
    assert_eq!(
        limits("a = C(<RD><RS>*){199}L"),
        (202, 400, false, Some(602), true)
    );
    assert_eq!(
        limits("a = C(<RD><RS>*){199}<TD>L"),
        (203, 401, true, None, false)
    );
}

/// The layout limit is exact: a layout of exactly 2 000 nodes is drawn. `a =
/// C<RD>{0,41}L`: the start, after `C`, after each of up to 41 `RD`s (42 states that
/// take `L`) and after `L`: 44 states; edges `C`, 41 `RD`s, 42 `L`s: 84, each with a
/// label connector. The `L` edge from the state after `k` `RD`s skips 41 - k ranks of
/// states, and each state rank is two layout ranks (the label's and the state's), so it
/// passes `2 (41 - k)` more connectors: 2 (0 + 1 + … + 41) = 1 722. `b = C<RS>{74}L`
/// adds a chain of 74 states and the state after its `L`, 75 states and 75 edges, no
/// rank skipped. 44 + 84 + 1 722 + 75 + 75 = 2 000.
///
/// Kills the mutant `graph.rs` graph_of: `nodes > LAYOUT_NODE_LIMIT` as `>=`.
#[test]
fn a_layout_of_exactly_the_limit_is_drawn() {
    assert_eq!(
        limits("a = C<RD>{0,41}L"),
        (44, 84, false, Some(1850), true)
    );
    assert_eq!(
        limits("a = C<RD>{0,41}L\nb = C<RS>{74}L"),
        (119, 159, false, Some(2000), true)
    );
}

/// An edge of exactly three vertices shows them all and no count. With `a = C.*L`, `b
/// = C<RD>L`, `c = C<RS>L`, the scatters split into `RD`, `RS` and the rest (`TD1`
/// represents `TD` and `TS`); after `C RD` only `a` and `b` are alive, and each of the
/// three leads to the state where only `a` is.
///
/// Kills the mutant `graph.rs` label: `vertices.len() > LABEL_VERTICES` as `>=` (a
/// `+0`).
#[test]
fn an_edge_of_three_vertices_is_labelled_without_a_count() {
    let g = graph_of("a = C.*L\nb = C<RD>L\nc = C<RS>L");
    let three: Vec<&str> = g
        .edges
        .iter()
        .filter(|e| e.vertices.len() == 3)
        .map(|e| e.label.as_str())
        .collect();
    assert!(!three.is_empty(), "{:#?}", g.edges);
    for label in three {
        assert_eq!(label, "RD1 | RS1 | TD1");
    }
}

/// The opening tags of the `element` elements of `svg`.
fn tags<'a>(svg: &'a str, element: &str) -> Vec<&'a str> {
    svg.split('<')
        .filter(|t| t.starts_with(&format!("{element} ")))
        .collect()
}

/// Attribute `name` of `tag`.
fn attr<'a>(tag: &'a str, name: &str) -> &'a str {
    let key = format!(" {name}=\"");
    let start = tag.find(&key).unwrap_or_else(|| panic!("no {name}: {tag}")) + key.len();
    &tag[start..start + tag[start..].find('"').unwrap()]
}

/// Attribute `name` of `tag`, a number.
fn num(tag: &str, name: &str) -> f64 {
    attr(tag, name).parse().unwrap()
}

/// The points of a path's `d`, in order.
fn points(d: &str) -> Vec<(f64, f64)> {
    let n: Vec<f64> = d.split([' ', ',']).filter_map(|s| s.parse().ok()).collect();
    n.chunks(2).map(|p| (p[0], p[1])).collect()
}

/// The drawing of `d = C<RD>L` measured against itself:
/// - every edge starts on its source state's circle and ends on its target's (a point
///   on the ellipse of radii `rx`, `ry` around (`cx`, `cy`) has `((x-cx)/rx)² +
///   ((y-cy)/ry)² = 1`, here to the 0.1 the SVG is written to);
/// - states are filled white (under their name) and the accepting state's outer ring
///   is not filled;
/// - each label lies on a white box centred on it, 0.6 of the 11-unit font wide per
///   character plus 4 and 15 high (`RD1`: 23.8);
/// - the document reaches 5 past the furthest shape edge, path point or label centre
///   (rounded up), on both axes;
/// - [`draw::svg`] draws what the view drew.
///
/// Kills the `draw.rs` mutants: `index` as `Some(0)` or `Some(1)` (edges drawn from the
/// wrong state); the radii `size / 2.0` as `%` or `*`; `class == "state"` as `!=` (the
/// ring filled white over the state); each operator of the label box's width and
/// height; `Canvas::cover` as a no-op, its `+ margin` as `-` or `*`; the circle's
/// margin `/ 2.0` as `%` or `*`; the `+ 5.0` of `finish` as `-` or `*`; `svg` as an empty
/// or other text.
#[test]
fn the_drawing_holds_together() {
    let g = graph_of("d = C<RD>L");
    let svg = g.svg.clone().expect("a small set is drawn");
    assert_eq!(draw::svg(&g), svg);
    let ellipses = tags(&svg, "ellipse");
    let state = |id: &str| {
        let tag = ellipses
            .iter()
            .find(|t| t.contains(&format!("id=\"{id}\"")))
            .unwrap_or_else(|| panic!("no {id}: {svg}"));
        (
            num(tag, "cx"),
            num(tag, "cy"),
            num(tag, "rx"),
            num(tag, "ry"),
        )
    };
    let on = |(x, y): (f64, f64), id: &str| {
        let (cx, cy, rx, ry) = state(id);
        let r = ((x - cx) / rx).powi(2) + ((y - cy) / ry).powi(2);
        assert!((r - 1.0).abs() < 0.02, "({x}, {y}) not on {id}: {svg}");
    };
    let paths = tags(&svg, "path");
    assert_eq!(paths.len(), 3);
    for e in &g.edges {
        let tag = paths
            .iter()
            .find(|t| attr(t, "id") == e.id)
            .unwrap_or_else(|| panic!("no {}: {svg}", e.id));
        let p = points(attr(tag, "d"));
        on(p[0], &e.from);
        on(p[p.len() - 1], &e.to);
    }
    for tag in &ellipses {
        let fill = if attr(tag, "class") == "state" {
            "white"
        } else {
            "none"
        };
        assert_eq!(attr(tag, "fill"), fill, "{tag}");
    }
    assert_eq!(
        ellipses
            .iter()
            .filter(|t| attr(t, "class") == "ring")
            .count(),
        1
    );
    // Each white box and the text after it.
    let pieces: Vec<&str> = svg.split('<').collect();
    let mut labels = 0;
    for (k, tag) in pieces.iter().enumerate() {
        if !tag.starts_with("rect ") {
            continue;
        }
        let text = pieces[k + 1];
        let shown = &text[text.find('>').unwrap() + 1..];
        let width = shown.chars().count() as f64 * 0.6 * 11.0 + 4.0;
        assert!((num(tag, "width") - width).abs() < 0.06, "{tag} {shown}");
        assert_eq!(num(tag, "height"), 15.0, "{tag}");
        assert!(
            (num(tag, "x") + width / 2.0 - num(text, "x")).abs() < 0.11,
            "{tag}"
        );
        assert!((num(tag, "y") + 7.5 - num(text, "y")).abs() < 0.11, "{tag}");
        labels += 1;
    }
    // The four state names and the three edge labels.
    assert_eq!(labels, 7);
    assert!(svg.contains(">RD1</text>"));
    // The extent: the furthest point of every shape.
    let (mut x, mut y) = (0f64, 0f64);
    for tag in &ellipses {
        x = x.max(num(tag, "cx") + num(tag, "rx"));
        y = y.max(num(tag, "cy") + num(tag, "ry"));
    }
    for tag in &paths {
        for (px, py) in points(attr(tag, "d")) {
            (x, y) = (x.max(px), y.max(py));
        }
    }
    for tag in tags(&svg, "text") {
        (x, y) = (x.max(num(tag, "x")), y.max(num(tag, "y")));
    }
    let top = tags(&svg, "svg")[0];
    for (size, furthest) in [(num(top, "width"), x), (num(top, "height"), y)] {
        let over = size - 5.0 - furthest;
        assert!(over > -0.06 && over < 1.06, "{size} for {furthest}: {top}");
    }
}

/// The layout's rank optimization and crossing reduction run up to [`CROSSING_LIMIT`]
/// layout nodes, not past it: the list of six AOVs below drawn as if its layout had
/// `CROSSING_LIMIT` nodes is drawn as with 0, and as if it had one more, differently
/// (without the optimizations its states fall on other ranks and in another order).
///
/// Kills the mutants `draw.rs` svg_with: `nodes > CROSSING_LIMIT` as `>=`, `==` or `<`.
#[test]
fn the_layout_is_optimized_up_to_its_limit() {
    let g = graph_of("a = C.*L\nb = C<RD>L\nc = C<RS>L\nd = C<TD>L\ne = C<TS>L\nf = C<RU>L");
    let optimized = draw::svg_with(&g, 0);
    assert_eq!(draw::svg_with(&g, CROSSING_LIMIT), optimized);
    assert_ne!(draw::svg_with(&g, CROSSING_LIMIT + 1), optimized);
}

/// Text made safe for SVG and HTML: the five markup characters as entities, control
/// characters (a tab, a bell) as blanks.
///
/// Kills the mutant `draw.rs` escape: the `c.is_control()` guard as `false`.
#[test]
fn escape_writes_entities_and_blanks_control_characters() {
    assert_eq!(
        draw::escape("a\tb\u{7}<&>\"'é"),
        "a b &lt;&amp;&gt;&quot;&apos;é"
    );
}
