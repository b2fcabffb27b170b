//! The `partition` view: does the list split the universe (default the dialect's) into
//! disjoint parts that cover it? Every overlapping pair, the gap and each AOV matching
//! outside the universe, each with its shortest witness re-checked by the reference
//! matcher (lint's [`lpe_lint::check::partition::recheck`], as `lpe-check partition`),
//! as rows for a table; the remainder AOV that closes a gap.

use lpe::analysis::{self, Decision};
use lpe_lint::check::partition::recheck;
use serde::Serialize;

use crate::list::{budget, disagreement, expression, ExploreDialect, Parsed};
use crate::request::{ApiError, Request, Setting};

/// The `partition` view's answer.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct PartitionView {
    /// The universe, as printed.
    pub universe: String,
    /// Whether the check finished within the budget; if not, `undecided` says which
    /// limit ended it and there are no rows.
    pub decided: bool,
    /// Why the check is undecided.
    pub undecided: Option<String>,
    /// Whether every universe path lands in exactly one AOV and none outside.
    pub clean: bool,
    /// The findings, overlaps first, then the gap, then the AOVs matching outside.
    pub rows: Vec<PartitionRow>,
    /// The AOV that closes the gap (the universe minus every AOV), if there is a gap.
    pub remainder: Option<String>,
}

/// One finding.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct PartitionRow {
    /// `overlap`, `gap` or `outside`.
    pub kind: &'static str,
    /// The AOVs involved: two for an overlap, none for the gap, one outside.
    pub aovs: Vec<String>,
    /// The shortest path showing it.
    pub witness: String,
}

/// The `partition` view of a request: 422 when the list or the universe do not parse.
pub(crate) fn partition_in<D: ExploreDialect>(
    request: &Request,
    setting: &Setting,
) -> Result<PartitionView, ApiError> {
    let parsed = Parsed::<D>::read(request, setting);
    let aovs = parsed.all()?;
    let universe = match &request.universe {
        Some(text) => expression::<D>("universe", text, &parsed.registration)?,
        None => analysis::default_universe::<D>(&parsed.registration),
    };
    let mut view = PartitionView {
        universe: universe.to_string(),
        decided: false,
        undecided: None,
        clean: false,
        rows: Vec::new(),
        remainder: None,
    };
    let p = match analysis::partition_within(&aovs, &universe, &parsed.registration, &budget()) {
        Ok(Decision::Decided(p)) => p,
        Ok(Decision::Undecided(u)) => {
            view.undecided = Some(u.to_string());
            return Ok(view);
        }
        Err(e) => return Err(ApiError::unprocessable(e.to_string())),
    };
    let remainder = recheck(&aovs, &universe, &p).map_err(disagreement)?;
    let name = |i: usize| aovs[i].0.clone();
    for (i, j, path) in &p.overlaps {
        view.rows.push(PartitionRow {
            kind: "overlap",
            aovs: vec![name(*i), name(*j)],
            witness: path.to_string(),
        });
    }
    if let Some(path) = &p.gap {
        view.rows.push(PartitionRow {
            kind: "gap",
            aovs: Vec::new(),
            witness: path.to_string(),
        });
    }
    for (i, path) in &p.outside {
        view.rows.push(PartitionRow {
            kind: "outside",
            aovs: vec![name(*i)],
            witness: path.to_string(),
        });
    }
    view.decided = true;
    view.clean = p.is_clean();
    view.remainder = remainder.map(|r| r.to_string());
    Ok(view)
}
