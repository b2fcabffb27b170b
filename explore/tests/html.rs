//! The notebook fragments: a set's drawing and table, a partition's table; names and
//! expressions escaped.

use lpe::renderman::parse;
use lpe::AovSet;
use lpe_explore::html;
use lpe_explore::partition::PartitionRow;

/// `C<RD>L` (states by hand: start, after `C`, after `C RD`, after `C RD L`) under a
/// name with markup: the drawing, and one row naming the accepting state, escaped.
///
/// Caught a planted fault: the AOV's name written into the table unescaped.
#[test]
fn a_set_is_its_drawing_and_a_table() {
    let set = AovSet::compile(&[("d<x>".to_string(), parse("C<RD>L").unwrap())]).unwrap();
    let out = html::aov_set(&set);
    assert!(
        out.starts_with(
            "<div class=\"lpe-aovset\"><p>1 AOVs (renderman), 4 states, 3 edges</p><svg "
        ),
        "{out}"
    );
    assert!(
        out.contains("<tr><td>d&lt;x&gt;</td><td><code>C&lt;RD&gt;L</code></td><td>s3</td></tr>")
    );
    assert!(!out.contains("d<x>"), "{out}");
    assert!(out.ends_with("</tbody></table></div>"));
}

/// Rows in their order with their kinds, the remainder, and a clean check without a
/// table.
///
/// Caught a planted fault: the remainder left out.
#[test]
fn a_partition_is_a_table_of_findings() {
    let rows = [
        PartitionRow {
            kind: "overlap",
            aovs: vec!["a".into(), "b".into()],
            witness: "C RD1 L".into(),
        },
        PartitionRow {
            kind: "gap",
            aovs: vec![],
            witness: "C O".into(),
        },
    ];
    let out = html::partition("C.*[<L.>O]", &rows, Some("C.*[<L.>O] - (a|b)"));
    assert_eq!(
        out,
        "<div class=\"lpe-partition\"><p>partition of <code>C.*[&lt;L.&gt;O]</code>: 2 \
         findings</p><table><thead><tr><th>finding</th><th>AOVs</th><th>witness</th></tr>\
         </thead><tbody><tr><td>overlap</td><td>a, b</td><td><code>C RD1 L</code></td></tr>\
         <tr><td>gap</td><td></td><td><code>C O</code></td></tr></tbody></table><p>remainder: \
         <code>C.*[&lt;L.&gt;O] - (a|b)</code></p></div>"
    );
    let clean = html::partition("C.*[<L.>O]", &[], None);
    assert_eq!(
        clean,
        "<div class=\"lpe-partition\"><p>partition of <code>C.*[&lt;L.&gt;O]</code>: \
         clean</p></div>"
    );
}
