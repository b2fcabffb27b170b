//! The `equiv` view: two expressions, each given as text or as the name of a line of
//! the list, compared on every path (`lpe::analysis::compare_within`, as `lpe-check
//! equiv`): equivalent, one included in the other, or neither, with the shortest path
//! each side matches alone, re-checked by the reference matcher. A comparison past the
//! budget is `undecided`, a value of the reply.

use lpe::analysis::{self, Decision};
use lpe_lint::witness::recheck_comparison;
use serde::Serialize;

use crate::list::{budget, disagreement, expression, ExploreDialect, Parsed};
use crate::request::{ApiError, Request, Setting};

/// The `equiv` view's answer.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct Equiv {
    /// The left side.
    pub left: Side,
    /// The right side.
    pub right: Side,
    /// `equivalent`, `left_in_right` (every path of the left is one of the right, not
    /// the other way round), `right_in_left`, `incomparable`, or `undecided`.
    pub verdict: &'static str,
    /// Why the comparison is undecided, if it is.
    pub undecided: Option<String>,
    /// A shortest path the left matches and the right does not.
    pub only_left: Option<String>,
    /// A shortest path the right matches and the left does not.
    pub only_right: Option<String>,
}

/// One side of the comparison.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct Side {
    /// As given.
    pub given: String,
    /// The line it names, if it names one.
    pub line: Option<String>,
    /// The expression compared, as printed.
    pub expression: String,
}

/// Reads `field`: a line's name of the list, else an expression.
fn side<D: ExploreDialect>(
    parsed: &Parsed<D>,
    field: &str,
    given: Option<&str>,
) -> Result<(Side, D::Lpe), ApiError> {
    let given = given.ok_or_else(|| ApiError::bad_request(format!("`equiv` needs `{field}`")))?;
    let (line, lpe) = match parsed.line(given) {
        Some(l) => (Some(given.to_string()), l.clone()),
        None => (None, expression::<D>(field, given, &parsed.registration)?),
    };
    let side = Side {
        given: given.to_string(),
        line,
        expression: lpe.to_string(),
    };
    Ok((side, lpe))
}

/// The `equiv` view of a request: 400 without `left` or `right`, 422 for a side that is
/// neither a line's name nor an expression that parses.
pub(crate) fn equiv_in<D: ExploreDialect>(
    request: &Request,
    setting: &Setting,
) -> Result<Equiv, ApiError> {
    let parsed = Parsed::<D>::read(request, setting);
    let (left, a) = side(&parsed, "left", request.left.as_deref())?;
    let (right, b) = side(&parsed, "right", request.right.as_deref())?;
    let mut view = Equiv {
        left,
        right,
        verdict: "undecided",
        undecided: None,
        only_left: None,
        only_right: None,
    };
    let c = match analysis::compare_within(&a, &b, &budget()) {
        Ok(Decision::Decided(c)) => c,
        Ok(Decision::Undecided(u)) => {
            view.undecided = Some(u.to_string());
            return Ok(view);
        }
        Err(e) => return Err(ApiError::unprocessable(e.to_string())),
    };
    recheck_comparison(
        (&view.left.expression, &a),
        (&view.right.expression, &b),
        &c,
    )
    .map_err(disagreement)?;
    view.verdict = match (&c.first_only, &c.second_only) {
        (None, None) => "equivalent",
        (None, Some(_)) => "left_in_right",
        (Some(_), None) => "right_in_left",
        (Some(_), Some(_)) => "incomparable",
    };
    view.only_left = c.first_only.map(|p| p.to_string());
    view.only_right = c.second_only.map(|p| p.to_string());
    Ok(view)
}
