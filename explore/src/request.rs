//! A view's request: the JSON body read into [`Request`] (within [`MAX_BODY_BYTES`]),
//! the dialect and renderer profile it names ([`Setting`]), and [`ApiError`], the reply
//! of everything that can go wrong before or while a view answers.

use std::fmt;

use lpe::DialectName;
use lpe_profile::Profile;
use serde::Deserialize;

/// The largest body a view reads: 1 MiB, far above any AOV list a renderer declares
/// (a 64-AOV list of long expressions is a few KiB), small enough that a page pasting a
/// whole file by mistake gets a clear refusal instead of a long parse.
pub const MAX_BODY_BYTES: usize = 1 << 20;

/// The body of every view (docs/usage.md, "The explorer's JSON API"). Fields a view
/// does not read are ignored, so one page can send one body to every view.
#[derive(Clone, Debug, Default, Deserialize, PartialEq, Eq)]
pub struct Request {
    /// The AOV list: one `name = expression` per line; blank lines and `#` comments
    /// skipped; a line without `name =` is named `lineN` ([`crate::lines`]).
    pub aovs: String,
    /// `renderman` or `osl`; default: the renderer's dialect, else RenderMan's.
    #[serde(default)]
    pub dialect: Option<String>,
    /// A shipped renderer profile's name (`karma`, `arnold`, …).
    #[serde(default)]
    pub renderer: Option<String>,
    /// `partition`: the expression the list should cover; default the dialect's.
    #[serde(default)]
    pub universe: Option<String>,
    /// `explain`: the path, in the dialect's path syntax.
    #[serde(default)]
    pub path: Option<String>,
    /// `equiv`: the left side, an expression or a line's name.
    #[serde(default)]
    pub left: Option<String>,
    /// `equiv`: the right side, an expression or a line's name.
    #[serde(default)]
    pub right: Option<String>,
}

/// Why a view gave no answer: the HTTP status and a message naming what to fix.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ApiError {
    /// 400 (malformed body, missing or unknown field value), 404 (unknown view), 413
    /// (body over [`MAX_BODY_BYTES`]), 422 (an expression or path that does not read,
    /// or a list that does not compile within lpe's limits), or 500 (a witness the
    /// reference matcher does not confirm: a bug of lpe's).
    pub status: u16,
    /// What went wrong, with the position where there is one.
    pub message: String,
}

impl ApiError {
    /// A 400: the request is not what the API reads.
    pub fn bad_request(message: impl Into<String>) -> ApiError {
        ApiError {
            status: 400,
            message: message.into(),
        }
    }

    /// A 422: the request reads, but its expressions do not parse or compile.
    pub fn unprocessable(message: impl Into<String>) -> ApiError {
        ApiError {
            status: 422,
            message: message.into(),
        }
    }
}

impl fmt::Display for ApiError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.status, self.message)
    }
}

impl std::error::Error for ApiError {}

impl Request {
    /// Reads a body: 413 over [`MAX_BODY_BYTES`], 400 for text that is not UTF-8, not a
    /// JSON object, or lacks `aovs` (serde's message names the line and column).
    pub fn from_body(body: &[u8]) -> Result<Request, ApiError> {
        if body.len() > MAX_BODY_BYTES {
            return Err(ApiError {
                status: 413,
                message: format!(
                    "the body is {} bytes, over the limit of {MAX_BODY_BYTES}",
                    body.len()
                ),
            });
        }
        serde_json::from_slice(body)
            .map_err(|e| ApiError::bad_request(format!("the body is no request: {e}")))
    }

    /// The dialect and renderer profile the request names: 400 for an unknown name, or a
    /// `dialect` other than the renderer's.
    pub fn setting(&self) -> Result<Setting, ApiError> {
        let given = match &self.dialect {
            Some(d) => Some(
                d.parse::<DialectName>()
                    .map_err(|e| ApiError::bad_request(format!("`dialect`: {e}")))?,
            ),
            None => None,
        };
        let profile = match &self.renderer {
            Some(name) => Some(
                lpe_profile::by_name(name)
                    .map_err(|e| ApiError::bad_request(format!("`renderer`: {e}")))?,
            ),
            None => None,
        };
        let dialect = match (given, profile) {
            (Some(d), Some(p)) if d != p.dialect() => {
                return Err(ApiError::bad_request(format!(
                    "`dialect` is `{d}` but renderer `{}` reads `{}`",
                    p.name,
                    p.dialect()
                )))
            }
            (_, Some(p)) => p.dialect(),
            (Some(d), None) => d,
            (None, None) => DialectName::default(),
        };
        Ok(Setting { dialect, profile })
    }
}

/// The dialect a request reads expressions in, and the renderer's profile if it named
/// one.
#[derive(Clone, Copy, Debug)]
pub struct Setting {
    /// The dialect.
    pub dialect: DialectName,
    /// The renderer's profile.
    pub profile: Option<&'static Profile>,
}

impl Setting {
    /// The registration of dialect `D`: the profile's on top of the default.
    pub fn registration<D: lpe_profile::ProfileDialect>(&self) -> D::Registration {
        let base = D::Registration::default();
        match self.profile {
            Some(p) => D::with_profile(p, base),
            None => base,
        }
    }

    /// The renderer's name, if a profile was named.
    pub fn renderer(&self) -> Option<String> {
        self.profile.map(|p| p.name.clone())
    }
}
