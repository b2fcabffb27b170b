//! The LPE explorer's JSON API: one entry point, [`answer`], that `lpe-check serve`,
//! `lpe-check report` and the Python package's HTML views call, and one typed function
//! per view for Rust callers. docs/usage.md ("The explorer's JSON API") is the
//! reference of every view's request and reply.
//!
//! - [`request`]: the body read into [`Request`] (within [`MAX_BODY_BYTES`]), the dialect
//!   and renderer it names ([`Setting`]), [`ApiError`] (the replies other than 200).
//! - [`lines`]: the AOV list's text, one `name = expression` per line.
//! - [`list`]: the lines parsed in one dialect ([`list::ExploreDialect`]), the list
//!   compiled.
//! - [`check`](mod@check): the `check` view.
//! - [`automaton`]: the list's automaton explored from its start ([`automaton::Explored`]),
//!   the `graph` view's reply types and the state and edge ids every view shares.
//! - [`graph`](mod@graph): the `graph` view: the automaton with its limits for drawing.
//! - [`draw`]: the graph drawn as SVG (layout by `layout-rs`), with ids per state and edge.
//! - [`paths`](mod@paths): the `paths` view: each AOV's shortest paths and near misses.
//! - [`partition`](mod@partition): the `partition` view: overlaps, gap and outside paths as rows.
//! - [`explain`](mod@explain): the `explain` view: a path stepped through the automaton.
//! - [`equiv`](mod@equiv): the `equiv` view: two expressions or lines compared.
//! - [`html`]: HTML fragments for notebooks (the Python package's `_repr_html_`).
//!
//! Every view answers within lpe's budgets and never panics: a body it cannot read is a
//! 4xx, never a crash (`tests/robust.rs` throws random bytes and random JSON at each).

pub mod automaton;
pub mod check;
pub mod draw;
pub mod equiv;
pub mod explain;
pub mod graph;
pub mod html;
pub mod lines;
pub mod list;
pub mod partition;
pub mod paths;
pub mod request;

use lpe::with_dialect;
use serde::Serialize;

pub use automaton::Graph;
pub use check::Check;
pub use equiv::Equiv;
pub use explain::Explain;
pub use partition::PartitionView;
pub use paths::Paths;
pub use request::{ApiError, Request, Setting, MAX_BODY_BYTES};

/// The views, by the name the URL ends with (`/api/check`).
pub const VIEWS: [&str; 6] = ["check", "graph", "paths", "partition", "explain", "equiv"];

/// A view's reply: an HTTP status and its JSON body (`{"error": "..."}` otherwise).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Reply {
    /// 200, or [`ApiError::status`]: a 4xx for the request, 500 only for a bug of
    /// lpe's (a witness the reference matcher does not confirm).
    pub status: u16,
    /// The JSON body.
    pub json: String,
}

impl Reply {
    fn ok(value: &impl Serialize) -> Reply {
        match serde_json::to_string(value) {
            Ok(json) => Reply { status: 200, json },
            // The replies are plain structs of strings and numbers: serializing cannot
            // fail, but a failure would still be an answer, not a panic.
            Err(e) => Reply::error(&ApiError {
                status: 500,
                message: format!("the reply did not serialize: {e}"),
            }),
        }
    }

    fn error(e: &ApiError) -> Reply {
        Reply {
            status: e.status,
            json: serde_json::json!({ "error": e.message }).to_string(),
        }
    }
}

/// Answers `view` (the URL's last segment) for the JSON `body`: 200 with the view's
/// reply, 404 for an unknown view, 400/413/422 as [`ApiError`] says.
///
/// ```
/// let reply = lpe_explore::answer("check", br#"{"aovs": "diffuse = C<RD>L"}"#);
/// assert_eq!(reply.status, 200);
/// assert!(reply.json.contains(r#""canonical":"C<RD>L""#));
/// assert_eq!(lpe_explore::answer("nope", b"{}").status, 404);
/// ```
pub fn answer(view: &str, body: &[u8]) -> Reply {
    let reply = match view {
        "check" => run(body, check),
        "graph" => run(body, graph),
        "paths" => run(body, paths),
        "partition" => run(body, partition),
        "explain" => run(body, explain),
        "equiv" => run(body, equiv),
        _ => Err(ApiError {
            status: 404,
            message: format!("no view `{view}` (views: {})", VIEWS.join(", ")),
        }),
    };
    reply.unwrap_or_else(|e| Reply::error(&e))
}

/// Reads `body` and answers it with `view`.
fn run<T: Serialize>(
    body: &[u8],
    view: fn(&Request) -> Result<T, ApiError>,
) -> Result<Reply, ApiError> {
    let request = Request::from_body(body)?;
    Ok(Reply::ok(&view(&request)?))
}

/// The `check` view: each line's canonical form or parse error, and the warnings.
pub fn check(request: &Request) -> Result<Check, ApiError> {
    let setting = request.setting()?;
    Ok(with_dialect!(setting.dialect, D => check::check_in::<D>(request, &setting)))
}

/// The `graph` view: the list's automaton, drawn when small enough.
pub fn graph(request: &Request) -> Result<Graph, ApiError> {
    let setting = request.setting()?;
    with_dialect!(setting.dialect, D => graph::graph_in::<D>(request, &setting))
}

/// The `paths` view: each AOV's shortest paths and near misses.
pub fn paths(request: &Request) -> Result<Paths, ApiError> {
    let setting = request.setting()?;
    with_dialect!(setting.dialect, D => paths::paths_in::<D>(request, &setting))
}

/// The `partition` view: the list against the universe.
pub fn partition(request: &Request) -> Result<PartitionView, ApiError> {
    let setting = request.setting()?;
    with_dialect!(setting.dialect, D => partition::partition_in::<D>(request, &setting))
}

/// The `explain` view: `path` stepped through the list's automaton.
pub fn explain(request: &Request) -> Result<Explain, ApiError> {
    let setting = request.setting()?;
    with_dialect!(setting.dialect, D => explain::explain_in::<D>(request, &setting))
}

/// The `equiv` view: `left` against `right`.
pub fn equiv(request: &Request) -> Result<Equiv, ApiError> {
    let setting = request.setting()?;
    with_dialect!(setting.dialect, D => equiv::equiv_in::<D>(request, &setting))
}
