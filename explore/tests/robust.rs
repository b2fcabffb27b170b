//! No input makes a view panic: random bytes, random JSON and random requests of
//! LPE-like text thrown at every view each get a 200 or a 4xx with an `error` message.

use lpe::rng::SplitMix64;
use lpe_explore::{answer, VIEWS};
use serde_json::{json, Map, Value};

/// Characters expressions, paths and names are made of, and a few that are not.
const ALPHABET: &[char] = &[
    'C', 'R', 'T', 'D', 'S', 'G', 'L', 'O', 'U', 'A', '<', '>', '[', ']', '(', ')', '{', '}', '.',
    '*', '+', '?', '|', '^', '&', '-', '\'', '"', ',', ';', ':', '_', '1', '2', '0', ' ', '\n',
    '=', '#', 'x', 'é', '\t', 'l', 'p', 'e',
];

/// Random text over [`ALPHABET`], up to `max` characters.
fn text(rng: &mut SplitMix64, max: usize) -> String {
    let n = rng.below(max + 1);
    (0..n)
        .map(|_| ALPHABET[rng.below(ALPHABET.len())])
        .collect()
}

/// Pieces of expressions that read, so that most random lists parse and compile and
/// the views past parsing (the automaton, its drawing, the analyses) run too.
const PIECES: &[&str] = &[
    "<RD>",
    "<RS>",
    "<TD>",
    "<TS>",
    ".",
    "[RT]",
    "(<RD>|<TS>)",
    "*",
    "+",
    "{2}",
    "{0,3}",
    "<.D'floor'>",
    "[^'glass']",
    "<L'key'>",
];

/// Paths of both dialects, so that `explain` gets paths that read.
const PATHS: &[&str] = &[
    "C RD L",
    "C L",
    "C RD RS L'key'",
    "C TS TD O",
    "C RD1'floor' RS L",
    "C,_ R,D L,_",
    "C,_ T,S R,D L,_",
];

/// An expression from [`PIECES`] between `C` and an emitter: it mostly reads in
/// RenderMan's dialect and in OSL's.
fn expression(rng: &mut SplitMix64) -> String {
    let mut e = String::from("C");
    for _ in 0..rng.below(6) {
        e.push_str(PIECES[rng.below(PIECES.len())]);
    }
    e.push_str(["L", "[LO]", "<L.>", "O"][rng.below(4)]);
    e
}

/// A random JSON value, nested up to `depth`.
fn value(rng: &mut SplitMix64, depth: usize) -> Value {
    match rng.below(if depth == 0 { 4 } else { 6 }) {
        0 => Value::Null,
        1 => json!(rng.below(2) == 1),
        2 => json!(rng.next_u64() as i64),
        3 => json!(text(rng, 40)),
        4 => Value::Array((0..rng.below(4)).map(|_| value(rng, depth - 1)).collect()),
        _ => {
            let mut m = Map::new();
            for _ in 0..rng.below(4) {
                m.insert(text(rng, 6), value(rng, depth - 1));
            }
            Value::Object(m)
        }
    }
}

/// A request with the API's fields, each present or not, of LPE-like text or of a
/// wrong type now and then.
fn request(rng: &mut SplitMix64) -> Value {
    let mut m = Map::new();
    let lines: Vec<String> = (0..rng.below(6))
        .map(|i| match rng.below(12) {
            0 => format!("a{i} = {}", text(rng, 24)),
            _ => format!("a{i} = {}", expression(rng)),
        })
        .collect();
    m.insert("aovs".into(), json!(lines.join("\n")));
    let dialects = ["renderman", "osl", "karma", "x"];
    for (key, pick) in [("dialect", 0usize), ("renderer", 1)] {
        if rng.below(3) == 0 {
            let name = dialects[rng.below(dialects.len())];
            let name = if pick == 1 && name == "osl" {
                "arnold"
            } else {
                name
            };
            m.insert(key.into(), json!(name));
        }
    }
    for key in ["universe", "path", "left", "right"] {
        if rng.below(2) == 0 {
            let good = match key {
                "path" => PATHS[rng.below(PATHS.len())].to_string(),
                _ => expression(rng),
            };
            m.insert(key.into(), json!(good));
            continue;
        }
        match rng.below(5) {
            4 => {
                m.insert(key.into(), json!(expression(rng)));
            }
            0 => {}
            1 => {
                m.insert(key.into(), value(rng, 1));
            }
            2 => {
                m.insert(key.into(), json!(format!("a{}", rng.below(6))));
            }
            _ => {
                m.insert(key.into(), json!(text(rng, 16)));
            }
        }
    }
    Value::Object(m)
}

/// Asks `view` for `body` and checks the reply is an answer, not a crash; returns its
/// status.
fn answered(view: &str, body: &[u8]) -> u16 {
    let reply = answer(view, body);
    let v: Value = serde_json::from_str(&reply.json)
        .unwrap_or_else(|e| panic!("{view}: reply is no JSON ({e}): {}", reply.json));
    match reply.status {
        200 => assert!(v.is_object(), "{view}: {v}"),
        400..=499 => assert!(v["error"].is_string(), "{view}: {v}"),
        s => panic!("{view}: status {s} for {}", String::from_utf8_lossy(body)),
    }
    reply.status
}

/// Random bytes, random JSON and random requests, 300 of each per view.
///
/// Caught a planted fault: a warning's line looked up one AOV too far (an index out of
/// bounds on a list whose last AOV is empty).
#[test]
fn every_view_answers_every_input() {
    let mut rng = SplitMix64::new(0x0065_7870_6c6f_7265);
    for view in VIEWS.iter().chain(&["", "../check"]) {
        let mut ok = 0;
        for _ in 0..300 {
            let bytes: Vec<u8> = (0..rng.below(64)).map(|_| rng.next_u64() as u8).collect();
            answered(view, &bytes);
            answered(view, value(&mut rng, 3).to_string().as_bytes());
            ok += usize::from(answered(view, request(&mut rng).to_string().as_bytes()) == 200);
        }
        // The requests reach past reading and parsing: the views themselves ran.
        if VIEWS.contains(view) {
            assert!(ok >= 15, "{view}: {ok} of 300 requests answered 200");
        }
    }
}
