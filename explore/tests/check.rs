//! The `check` view and the request errors every view shares, through [`answer`] as the
//! server calls it, against values worked out by hand from the text.

use lpe_explore::{answer, ApiError, MAX_BODY_BYTES};
use serde_json::Value;

/// The reply of `view` for `body`, its status and its JSON.
fn ask(view: &str, body: &str) -> (u16, Value) {
    let reply = answer(view, body.as_bytes());
    let json = serde_json::from_str(&reply.json).expect("every reply is JSON");
    (reply.status, json)
}

/// Canonical forms, names (`lineN` for a line without `name =`), skipped comments and
/// blank lines, and the caret of an error placed under the line as typed: `bad = C<RD`
/// has its unclosed `<` at character 8.
///
/// Caught a planted fault: the caret's span not moved by the expression's offset in
/// its line (column 2 instead of 8).
#[test]
fn lines_parse_or_point_at_their_error() {
    let (status, v) = ask(
        "check",
        r#"{"aovs": "diffuse = C<RD>L\n\n# a comment\nbad = C<RD\nC<RS>+ L"}"#,
    );
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["dialect"], "renderman");
    assert_eq!(v["renderer"], Value::Null);
    let lines = v["lines"].as_array().unwrap();
    assert_eq!(lines.len(), 3);
    assert_eq!(lines[0]["name"], "diffuse");
    assert_eq!(lines[0]["ok"], true);
    assert_eq!(lines[0]["canonical"], "C<RD>L");
    assert_eq!(lines[1]["line"], 4);
    assert_eq!(lines[1]["ok"], false);
    let e = &lines[1]["error"];
    assert_eq!(
        (e["line"].as_u64(), e["column"].as_u64()),
        (Some(4), Some(8))
    );
    assert_eq!(e["length"], 1);
    assert_eq!(e["message"], "unclosed `<`");
    assert_eq!(e["caret"], "bad = C<RD\n       ^");
    assert_eq!(lines[2]["name"], "line5");
    // The canonical form drops the blank between `+` and `L`.
    assert_eq!(lines[2]["canonical"], "C<RS>+L");
    assert_eq!(v["warnings"], Value::Array(vec![]));
    assert_eq!(v["compile_error"], Value::Null);
}

/// A column counts characters, not bytes, and the parser's hint comes along: `é` is
/// two bytes but one column, and RenderMan names the letters it reads.
///
/// Caught a planted fault: `column` from the byte offset (7 instead of 6).
#[test]
fn columns_count_characters_and_hints_come_along() {
    let (_, v) = ask("check", r#"{"aovs": "é = C<RD\n  é x = C<R"}"#);
    let e = &v["lines"][0]["error"];
    assert_eq!(v["lines"][0]["name"], "é");
    assert_eq!(e["column"], 6);
    assert_eq!(e["caret"], "é = C<RD\n     ^");
    let e = &v["lines"][1]["error"];
    assert_eq!(v["lines"][1]["name"], "line2");
    assert_eq!(e["column"], 3);
    assert_eq!(e["caret"], "  é x = C<R\n  ^");
    assert!(e["hint"].as_str().unwrap().contains("event letters"), "{e}");
}

/// An AOV whose set algebra leaves no path gets the warning, on its own line number
/// (counted over the lines that parse: the broken line before it must not shift it).
///
/// Caught a planted fault: the warning's line looked up by the AOV's index among all
/// lines (line 1, the broken one).
#[test]
fn an_aov_that_matches_nothing_is_warned_on_its_line() {
    let (_, v) = ask(
        "check",
        r#"{"aovs": "broken = C<\nnone = C<TD>L & C<RD>L\nfine = C.*L"}"#,
    );
    let w = v["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1, "{v}");
    assert_eq!(w[0]["aov"], "none");
    assert_eq!(w[0]["line"], 2);
}

/// OSL reads `,`-separated vertices; its end-of-line error sits one past the text, and
/// a renderer's profile picks the dialect and reads its `lpe:` mark.
#[test]
fn dialect_and_renderer_choose_the_reading() {
    let (_, v) = ask(
        "check",
        r#"{"aovs": "a = C<RD>L\nb = C<R,D,,L", "dialect": "osl"}"#,
    );
    assert_eq!(v["dialect"], "osl");
    assert_eq!(v["lines"][0]["canonical"], "<C.><RD><L.>");
    let e = &v["lines"][1]["error"];
    assert_eq!(e["column"], 13);
    assert_eq!(e["caret"], "b = C<R,D,,L\n            ^");
    let (status, v) = ask(
        "check",
        r#"{"aovs": "a = lpe:C<RD>L", "renderer": "karma"}"#,
    );
    assert_eq!(status, 200);
    assert_eq!(
        (v["dialect"].as_str(), v["renderer"].as_str()),
        (Some("osl"), Some("karma"))
    );
    assert_eq!(v["lines"][0]["ok"], true);
}

/// OSL accepts `{3,2}` and reads it as `{3}` with a warning, which the line carries
/// (its position counted in the expression: the `{` is character 2 of `CD{3,2}L`).
///
/// Caught a planted fault: the warnings of every line left empty.
#[test]
fn a_line_that_parses_carries_its_warnings() {
    let (_, v) = ask(
        "check",
        r#"{"aovs": "a = CD{3,2}L\nb = C<RD>L", "dialect": "osl"}"#,
    );
    assert_eq!(v["lines"][0]["ok"], true);
    assert_eq!(
        v["lines"][0]["warnings"],
        serde_json::json!(["{3,2} at char 2 has its bounds reversed: read as {3}"])
    );
    assert_eq!(v["lines"][1]["warnings"], serde_json::json!([]));
}

/// Every way a request can be wrong, with its status and a message naming the field.
#[test]
fn bad_requests_get_their_status() {
    let cases: &[(&str, &str, u16, &str)] = &[
        ("nope", "{}", 404, "no view `nope`"),
        ("check", "{", 400, "the body is no request"),
        ("check", "[]", 400, "the body is no request"),
        ("check", "{}", 400, "missing field `aovs`"),
        ("check", r#"{"aovs": 3}"#, 400, "invalid type"),
        (
            "check",
            r#"{"aovs": "", "dialect": "OSL"}"#,
            400,
            "unknown dialect `OSL`",
        ),
        ("check", r#"{"aovs": "", "renderer": "karm"}"#, 400, "karma"),
        (
            "check",
            r#"{"aovs": "", "renderer": "karma", "dialect": "renderman"}"#,
            400,
            "renderer `karma` reads `osl`",
        ),
    ];
    for (view, body, status, message) in cases {
        let (got, v) = ask(view, body);
        assert_eq!(got, *status, "{view} {body}: {v}");
        let text = v["error"].as_str().unwrap();
        assert!(text.contains(message), "{body}: {text}");
    }
    let big = format!(r#"{{"aovs": "{}"}}"#, "C".repeat(MAX_BODY_BYTES));
    let (status, v) = ask("check", &big);
    assert_eq!(status, 413);
    assert!(v["error"]
        .as_str()
        .unwrap()
        .contains("over the limit of 1048576"));
}

/// An error whose span is longer than one character is underlined whole, from where
/// the expression starts in its line: `holdoutz;` is an unknown prefix of 9 characters
/// at character 5 of `a = holdoutz;C.*L`.
///
/// Kills the mutant `check.rs` placed: `at + e.span.end` as `at - e.span.end` (the
/// end before the start, clamped to the line's end: 13 carets).
#[test]
fn a_long_span_is_underlined_whole() {
    let (_, v) = ask("check", r#"{"aovs": "a = holdoutz;C.*L"}"#);
    let e = &v["lines"][0]["error"];
    assert_eq!(e["message"], "unknown prefix `holdoutz`");
    assert_eq!(
        (e["column"].as_u64(), e["length"].as_u64()),
        (Some(5), Some(9))
    );
    assert_eq!(e["caret"], "a = holdoutz;C.*L\n    ^^^^^^^^^");
}

/// A `dialect` that names the renderer's own dialect is no conflict: karma reads OSL.
///
/// Kills the mutant `request.rs` setting: the conflict guard `d != p.dialect()` as
/// `true` (every request naming both refused).
#[test]
fn a_dialect_agreeing_with_the_renderer_is_accepted() {
    let (status, v) = ask(
        "check",
        r#"{"aovs": "a = C<RD>L", "renderer": "karma", "dialect": "osl"}"#,
    );
    assert_eq!(status, 200, "{v}");
    assert_eq!(
        (v["dialect"].as_str(), v["renderer"].as_str()),
        (Some("osl"), Some("karma"))
    );
    assert_eq!(v["lines"][0]["canonical"], "<C.><RD><L.>");
}

/// The body limit is exact: a body of exactly [`MAX_BODY_BYTES`] bytes (an empty list
/// padded with blanks, which JSON allows) is read, one byte more is a 413.
///
/// Kills the mutant `request.rs` from_body: `body.len() > MAX_BODY_BYTES` as `>=`.
#[test]
fn the_body_limit_is_exact() {
    let body = |len: usize| {
        let head = r#"{"aovs": """#;
        format!("{head}{}}}", " ".repeat(len - head.len() - 1))
    };
    assert_eq!(body(MAX_BODY_BYTES).len(), MAX_BODY_BYTES);
    let (status, v) = ask("check", &body(MAX_BODY_BYTES));
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["lines"], serde_json::json!([]));
    let (status, v) = ask("check", &body(MAX_BODY_BYTES + 1));
    assert_eq!(status, 413);
    assert_eq!(
        v["error"],
        "the body is 1048577 bytes, over the limit of 1048576"
    );
}

/// An [`ApiError`] prints as its status and message (the `Display` that makes it a
/// `std::error::Error` for Rust callers).
///
/// Kills the mutant `request.rs`: `Display for ApiError` writing nothing.
#[test]
fn an_api_error_prints_its_status_and_message() {
    assert_eq!(
        ApiError::bad_request("no `aovs`").to_string(),
        "400 no `aovs`"
    );
    assert_eq!(
        ApiError::unprocessable("line 1 column 2").to_string(),
        "422 line 1 column 2"
    );
}

/// A renderer's profile registers what its renderer adds to the dialect: karma's
/// `unoccluded;` prefix (profile/data/karma.toml) reads under `"renderer": "karma"` and
/// is an unknown label in plain OSL.
///
/// Kills the mutant `request.rs` Setting::registration as `Default::default()` (the
/// profile ignored).
#[test]
fn a_renderer_s_profile_registers_its_additions() {
    let aovs = "b = unoccluded;C<RD>L";
    let (_, v) = ask(
        "check",
        &serde_json::json!({"aovs": aovs, "renderer": "karma"}).to_string(),
    );
    assert_eq!(v["lines"][0]["canonical"], "unoccluded;<C.><RD><L.>", "{v}");
    let (_, v) = ask(
        "check",
        &serde_json::json!({"aovs": aovs, "dialect": "osl"}).to_string(),
    );
    assert_eq!(v["lines"][0]["ok"], false, "{v}");
    assert_eq!(
        v["lines"][0]["error"]["message"],
        "Unrecognized basic label: u"
    );
}
