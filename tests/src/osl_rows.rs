//! Rows of the OSL verdict files (`testdata/osl/*.tsv`):
//! `EXPR<TAB>REGISTERED<TAB>PATH<TAB>MATCH|NOMATCH`, `#` comment lines. One loader for
//! every suite that runs them (the accum test on `AovSet`, the engines' conformance).

use std::fmt;

use lpe::osl::{Path, Registered};

/// One verdict: what OSL answers for `path` under rule `expr`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OslRow {
    /// 1-based line in its file.
    pub line: usize,
    /// The expression, unparsed (parsing it is part of what a suite checks).
    pub expr: String,
    /// Labels registered before the rule is parsed.
    pub registered: Registered,
    /// The path fed to the rule.
    pub path: Path,
    /// Whether OSL's accumulator fires.
    pub matches: bool,
}

/// A malformed row.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RowError {
    /// 1-based line.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for RowError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

/// The rows of a verdict file's text.
pub fn parse_osl_rows(text: &str) -> Result<Vec<OslRow>, RowError> {
    let mut rows = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        if raw.is_empty() || raw.starts_with('#') {
            continue;
        }
        let err = |message: String| RowError { line, message };
        let cols: Vec<&str> = raw.split('\t').collect();
        let [expr, registered, path, verdict] = cols[..] else {
            return Err(err(format!("{} columns, expected 4", cols.len())));
        };
        let registered = registered
            .parse()
            .map_err(|e| err(format!("REGISTERED: {e}")))?;
        let path = path.parse().map_err(|e| err(format!("PATH: {e}")))?;
        let matches = match verdict {
            "MATCH" => true,
            "NOMATCH" => false,
            v => return Err(err(format!("verdict `{v}`, expected MATCH or NOMATCH"))),
        };
        rows.push(OslRow {
            line,
            expr: expr.to_string(),
            registered,
            path,
            matches,
        });
    }
    Ok(rows)
}

/// The rows of `testdata/osl/<name>`.
pub fn load_osl_rows(name: &str) -> Result<Vec<OslRow>, RowError> {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/testdata/osl/").to_string() + name;
    let text = std::fs::read_to_string(&file).map_err(|e| RowError {
        line: 0,
        message: format!("{file}: {e}"),
    })?;
    parse_osl_rows(&text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_parse_and_malformed_rows_name_their_line() {
        let text = "# comment\nC<RD>L\t-\tC,_ R,D L,_\tMATCH\nCL\tevents=U\tC,_ R,D\tNOMATCH\n";
        let rows = parse_osl_rows(text).unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0].line, 2);
        assert!(rows[0].matches && !rows[1].matches);
        assert_eq!(rows[1].registered.events, ["U"]);
        assert_eq!(rows[1].path.len(), 2);
        let e = parse_osl_rows("# x\nCL\t-\tC,_\tYES\n").unwrap_err();
        assert_eq!(e.line, 2);
        assert_eq!(parse_osl_rows("CL\t-\n").unwrap_err().line, 1);
        assert_eq!(parse_osl_rows("CL\t-\tC,,_\tMATCH\n").unwrap_err().line, 1);
    }
}
