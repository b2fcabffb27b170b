//! The `check` view: every line parsed, its canonical form or its error with a caret
//! under the line as written, and the warnings of the lines that parse, compiled as one
//! set (an AOV that can match no path).

use lpe::analysis;
use lpe_lint::check::dialect::ParseFailure;
use serde::Serialize;

use crate::lines::{caret, Line};
use crate::list::{compile, ExploreDialect, Parsed};
use crate::request::{Request, Setting};

/// The `check` view's answer.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct Check {
    /// The dialect the lines were read in.
    pub dialect: String,
    /// The renderer whose profile was applied, if any.
    pub renderer: Option<String>,
    /// Every AOV line, in order.
    pub lines: Vec<CheckedLine>,
    /// Warnings on the lines that parse, compiled together.
    pub warnings: Vec<CheckWarning>,
    /// Why the lines that parse do not compile together (over lpe's limits), if so;
    /// there are then no warnings.
    pub compile_error: Option<String>,
}

/// One AOV line's verdict.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct CheckedLine {
    /// 1-based line number in the list.
    pub line: usize,
    /// The AOV's name.
    pub name: String,
    /// The expression as written.
    pub source: String,
    /// Whether it parses.
    pub ok: bool,
    /// Its canonical form, when it parses.
    pub canonical: Option<String>,
    /// Its parse error, when it does not.
    pub error: Option<LineError>,
    /// What the parser warns of in a line it accepts (OSL: a reversed `{m,n}`, labels of
    /// different slots in one `[^...]`), positions counted in the expression.
    pub warnings: Vec<String>,
}

/// A parse error placed in the list's text.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct LineError {
    /// 1-based line number.
    pub line: usize,
    /// 1-based column of the error's first character, in characters of the line.
    pub column: usize,
    /// The span's length in characters (at least 1).
    pub length: usize,
    /// What is wrong.
    pub message: String,
    /// How to fix it, if the parser knows.
    pub hint: Option<String>,
    /// The line, a line break, and `^` under the span: shown as-is in a monospace font.
    pub caret: String,
}

/// A warning on one AOV.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct CheckWarning {
    /// The AOV's name.
    pub aov: String,
    /// Its line number.
    pub line: usize,
    /// Why it can match no path.
    pub message: String,
}

/// The `check` view of `request`.
pub(crate) fn check_in<D: ExploreDialect>(request: &Request, setting: &Setting) -> Check {
    let parsed = Parsed::<D>::read(request, setting);
    let lines = parsed
        .lines
        .iter()
        .map(|(line, result)| CheckedLine {
            line: line.number,
            name: line.name.clone(),
            source: line.source.clone(),
            ok: result.is_ok(),
            canonical: result.as_ref().ok().map(ToString::to_string),
            error: result.as_ref().err().map(|e| placed(line, e)),
            warnings: result
                .as_ref()
                .map_or_else(|_| Vec::new(), D::parse_warnings),
        })
        .collect();
    let good: Vec<&Line> = parsed
        .lines
        .iter()
        .filter(|(_, r)| r.is_ok())
        .map(|(l, _)| l)
        .collect();
    let aovs = parsed.parsed();
    let (warnings, compile_error) = if aovs.is_empty() {
        (Vec::new(), None)
    } else {
        match compile::<D>(&aovs, &parsed.registration) {
            Ok(set) => (
                analysis::warnings(&set)
                    .into_iter()
                    .map(|w| CheckWarning {
                        line: good.get(w.aov).map_or(0, |l| l.number),
                        aov: w.name,
                        message: w.message,
                    })
                    .collect(),
                None,
            ),
            Err(e) => (Vec::new(), Some(e.message)),
        }
    };
    Check {
        dialect: D::NAME.to_string(),
        renderer: setting.renderer(),
        lines,
        warnings,
        compile_error,
    }
}

/// `e` placed in the line: its span moved by where the expression starts. Both dialects
/// report a failure in the text they were given (RenderMan a macro's own failure at
/// the macro's name), so the span is always in the expression.
fn placed(line: &Line, e: &ParseFailure) -> LineError {
    let at = line.offset;
    let (caret, column, length) = caret(&line.text, at + e.span.start..at + e.span.end);
    LineError {
        line: line.number,
        column,
        length,
        message: e.message.clone(),
        hint: e.help.clone(),
        caret,
    }
}
