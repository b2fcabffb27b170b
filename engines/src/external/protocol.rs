//! The wire format of the external-matcher protocol (docs/protocol.md): one JSON object
//! per line each way, one reply per request, the reply echoing the request's `id`.
//!
//! Requests are built here and serialized whole; replies are read into a permissive raw
//! form (unknown fields are ignored, so later protocol versions may add some) and then
//! checked against the request they answer, so every way a reply can be wrong has its
//! own [`Violation`].

use serde::{Deserialize, Serialize};

use crate::dialect::WireRegistration;

/// The protocol version this harness speaks: a matcher must answer `hello` with it.
pub const PROTOCOL_VERSION: u32 = 1;

/// The minor version, sent in `hello` as `minor`: it grows when requests gain fields a
/// matcher of an older minor version may ignore. 1: OSL `compile` requests carry the
/// registered labels. 2: `compile` requests may name a renderer profile (`renderer`).
pub const PROTOCOL_MINOR: u32 = 2;

/// One request line.
#[derive(Clone, Debug, Serialize)]
pub struct Request {
    /// Increases by one per request over the harness's whole run; the reply echoes it.
    pub id: u64,
    /// What is asked.
    #[serde(flatten)]
    pub body: Body,
}

/// The operations.
#[derive(Clone, Debug, Serialize)]
#[serde(tag = "op", rename_all = "lowercase")]
pub enum Body {
    /// The first request of every process: the version and the dialect of expressions
    /// and paths.
    Hello {
        /// [`PROTOCOL_VERSION`].
        protocol: u32,
        /// [`PROTOCOL_MINOR`].
        minor: u32,
        /// `renderman` or `osl`.
        dialect: String,
    },
    /// Compile an AOV set, replacing the previous one.
    Compile {
        /// The AOVs, in order.
        aovs: Vec<AovSource>,
        /// OSL only (absent for RenderMan): the labels to register before parsing.
        #[serde(skip_serializing_if = "Option::is_none")]
        registered: Option<WireRegistration>,
        /// The renderer profile the set reads under (docs/profiles.md: its letters,
        /// prefixes and built-in names), absent for none; the client fills it in
        /// ([`crate::external::client::Client::renderer`]).
        #[serde(skip_serializing_if = "Option::is_none")]
        renderer: Option<String>,
    },
    /// Which AOVs of the compiled set each path lands in.
    Match {
        /// Paths in the dialect's text form; the reply has one list per path.
        paths: Vec<String>,
    },
    /// The harness is done; the process replies and exits.
    Quit,
}

/// One AOV of a compile request.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct AovSource {
    /// Its name (unique within the set).
    pub name: String,
    /// Its expression, in the dialect's notation.
    pub expr: String,
}

impl Request {
    /// The request as one line of JSON (no trailing newline).
    pub fn to_line(&self) -> String {
        // Serializing strings, numbers and lists cannot fail.
        serde_json::to_string(self).expect("a request always serializes")
    }
}

/// A reply as read, before it is checked against its request.
#[derive(Debug, Default, Deserialize)]
struct RawReply {
    id: Option<serde_json::Value>,
    ok: Option<bool>,
    protocol: Option<u32>,
    name: Option<String>,
    matches: Option<Vec<Vec<String>>>,
    error: Option<RawError>,
    unsupported: Option<String>,
}

#[derive(Debug, Deserialize)]
struct RawError {
    message: String,
    aov: Option<usize>,
    position: Option<usize>,
}

/// An expression the external matcher rejects.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rejection {
    /// Its message.
    pub message: String,
    /// Which AOV of the request (index), if it says.
    pub aov: Option<usize>,
    /// Byte position in that AOV's expression, if it says.
    pub position: Option<usize>,
}

/// A well-formed reply, checked against its request.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reply {
    /// `hello` accepted: the matcher's self-reported name, if any.
    Hello(Option<String>),
    /// `compile` or `quit` succeeded.
    Done,
    /// `compile` rejected an expression.
    Rejected(Rejection),
    /// `match`: for each path, the names of the AOVs it lands in.
    Matches(Vec<Vec<String>>),
    /// The matcher does not implement what was asked (a construct, a dialect): the case
    /// is counted as unsupported, not as a disagreement.
    Unsupported(String),
}

/// Why a reply line is not an answer to its request.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum Violation {
    /// Not JSON, or JSON of the wrong shape.
    #[error("malformed reply: {0}")]
    Malformed(String),
    /// The `id` is missing or answers another request.
    #[error("reply to request id {got}, expected {expected} (a missing or extra reply)")]
    WrongId {
        /// The request's id.
        expected: u64,
        /// What the reply carried (`none` if nothing).
        got: String,
    },
    /// JSON, but not a reply this request allows.
    #[error("unknown reply: {0}")]
    Unknown(String),
    /// A `match` reply with another number of answers than paths asked.
    #[error("{got} answers to {expected} paths")]
    Count {
        /// Paths in the request.
        expected: usize,
        /// Lists in the reply.
        got: usize,
    },
}

/// Checks one reply line against the request it answers.
pub fn read_reply(request: &Request, line: &str) -> Result<Reply, Violation> {
    let raw: RawReply = serde_json::from_str(line.trim_end())
        .map_err(|e| Violation::Malformed(format!("{e} (column {})", e.column())))?;
    match raw.id.as_ref().and_then(serde_json::Value::as_u64) {
        Some(id) if id == request.id => {}
        _ => {
            return Err(Violation::WrongId {
                expected: request.id,
                got: raw.id.map_or("none".into(), |v| v.to_string()),
            })
        }
    }
    let Some(ok) = raw.ok else {
        return Err(Violation::Unknown("no `ok` field".into()));
    };
    if !ok {
        if let Some(what) = raw.unsupported {
            return Ok(Reply::Unsupported(what));
        }
        return match (raw.error, &request.body) {
            (Some(e), Body::Compile { aovs, .. }) => match e.aov {
                Some(i) if i >= aovs.len() => Err(Violation::Unknown(format!(
                    "error names AOV {i} of a set of {}",
                    aovs.len()
                ))),
                _ => Ok(Reply::Rejected(Rejection {
                    message: e.message,
                    aov: e.aov,
                    position: e.position,
                })),
            },
            (Some(e), _) => Err(Violation::Unknown(format!(
                "error on a request that cannot fail: {}",
                e.message
            ))),
            (None, _) => Err(Violation::Unknown(
                "`ok: false` without `error` or `unsupported`".into(),
            )),
        };
    }
    match &request.body {
        Body::Hello { .. } => match raw.protocol {
            Some(PROTOCOL_VERSION) => Ok(Reply::Hello(raw.name)),
            Some(v) => Err(Violation::Unknown(format!(
                "protocol version {v}, this harness speaks {PROTOCOL_VERSION}"
            ))),
            None => Err(Violation::Unknown("hello reply without `protocol`".into())),
        },
        Body::Compile { .. } | Body::Quit => Ok(Reply::Done),
        Body::Match { paths } => match raw.matches {
            Some(m) if m.len() == paths.len() => Ok(Reply::Matches(m)),
            Some(m) => Err(Violation::Count {
                expected: paths.len(),
                got: m.len(),
            }),
            None => Err(Violation::Unknown("match reply without `matches`".into())),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn matching(id: u64, paths: &[&str]) -> Request {
        Request {
            id,
            body: Body::Match {
                paths: paths.iter().map(|p| p.to_string()).collect(),
            },
        }
    }

    #[test]
    fn requests_are_one_json_line_with_op_and_id() {
        let r = Request {
            id: 7,
            body: Body::Compile {
                aovs: vec![AovSource {
                    name: "a0".into(),
                    expr: "C'a b'L".into(),
                }],
                registered: None,
                renderer: None,
            },
        };
        assert_eq!(
            r.to_line(),
            r#"{"id":7,"op":"compile","aovs":[{"name":"a0","expr":"C'a b'L"}]}"#
        );
        let osl = Request {
            id: 9,
            body: Body::Compile {
                aovs: vec![AovSource {
                    name: "a0".into(),
                    expr: "CDY+U".into(),
                }],
                registered: Some(WireRegistration {
                    events: vec!["U".into()],
                    scatters: vec!["Y".into()],
                }),
                renderer: Some("karma".into()),
            },
        };
        assert_eq!(
            osl.to_line(),
            r#"{"id":9,"op":"compile","aovs":[{"name":"a0","expr":"CDY+U"}],"registered":{"events":["U"],"scatters":["Y"]},"renderer":"karma"}"#
        );
        let hello = Request {
            id: 0,
            body: Body::Hello {
                protocol: PROTOCOL_VERSION,
                minor: PROTOCOL_MINOR,
                dialect: "osl".into(),
            },
        };
        assert_eq!(
            hello.to_line(),
            r#"{"id":0,"op":"hello","protocol":1,"minor":2,"dialect":"osl"}"#
        );
        let q = Request {
            id: 8,
            body: Body::Quit,
        };
        assert_eq!(q.to_line(), r#"{"id":8,"op":"quit"}"#);
    }

    #[test]
    fn replies_are_checked_against_their_request() {
        let r = matching(3, &["C RD1 L", "C L"]);
        assert_eq!(
            read_reply(&r, r#"{"id":3,"ok":true,"matches":[["a"],[]],"extra":1}"#),
            Ok(Reply::Matches(vec![vec!["a".into()], vec![]]))
        );
        assert_eq!(
            read_reply(&r, r#"{"id":3,"ok":true,"matches":[["a"]]}"#),
            Err(Violation::Count {
                expected: 2,
                got: 1
            })
        );
        assert!(matches!(
            read_reply(&r, r#"{"id":2,"ok":true,"matches":[[],[]]}"#),
            Err(Violation::WrongId { expected: 3, .. })
        ));
        assert!(matches!(
            read_reply(&r, "not json"),
            Err(Violation::Malformed(_))
        ));
        assert!(matches!(
            read_reply(&r, r#"{"id":3,"ok":true}"#),
            Err(Violation::Unknown(_))
        ));
        assert!(matches!(
            read_reply(&r, r#"{"id":3,"ok":false,"error":{"message":"x"}}"#),
            Err(Violation::Unknown(_))
        ));
        assert_eq!(
            read_reply(&r, r#"{"id":3,"ok":false,"unsupported":"labels"}"#),
            Ok(Reply::Unsupported("labels".into()))
        );
    }

    #[test]
    fn compile_errors_carry_aov_and_position() {
        let r = Request {
            id: 1,
            body: Body::Compile {
                aovs: vec![AovSource {
                    name: "x".into(),
                    expr: "C(".into(),
                }],
                registered: None,
                renderer: None,
            },
        };
        assert_eq!(
            read_reply(
                &r,
                r#"{"id":1,"ok":false,"error":{"message":"open group","aov":0,"position":1}}"#
            ),
            Ok(Reply::Rejected(Rejection {
                message: "open group".into(),
                aov: Some(0),
                position: Some(1)
            }))
        );
        assert!(matches!(
            read_reply(&r, r#"{"id":1,"ok":false,"error":{"message":"m","aov":1}}"#),
            Err(Violation::Unknown(_))
        ));
        let hello = Request {
            id: 0,
            body: Body::Hello {
                protocol: 1,
                minor: PROTOCOL_MINOR,
                dialect: "renderman".into(),
            },
        };
        assert_eq!(
            read_reply(&hello, r#"{"id":0,"ok":true,"protocol":1,"name":"n"}"#),
            Ok(Reply::Hello(Some("n".into())))
        );
        assert!(read_reply(&hello, r#"{"id":0,"ok":true,"protocol":2}"#).is_err());
    }
}
