//! The one table writer: every Markdown and console table goes through [`markdown`].

use tabled::builder::Builder;
use tabled::settings::Style;

/// A Markdown table (also readable on a console) with `header` and `rows`, ending in a
/// newline.
pub fn markdown<R, C>(header: &[&str], rows: R) -> String
where
    R: IntoIterator<Item = C>,
    C: IntoIterator<Item = String>,
{
    let mut b = Builder::default();
    b.push_record(header.iter().map(|h| h.to_string()));
    for r in rows {
        b.push_record(r);
    }
    let mut t = b.build();
    t.with(Style::markdown());
    let mut s = t.to_string();
    s.push('\n');
    s
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_markdown_table_has_a_header_rule_and_one_line_per_row() {
        let t = super::markdown(&["a", "bb"], [vec!["1".to_string(), "x|y".to_string()]]);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines.len(), 3, "{t}");
        assert!(
            lines[0].starts_with("| a") && lines[1].starts_with("|-"),
            "{t}"
        );
        assert!(lines[2].contains("x|y"), "{t}");
    }
}
