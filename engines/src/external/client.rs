//! The typed client: requests in, checked replies or [`Fault`]s out, restarting the
//! process after any fault.
//!
//! A fault (crash, timeout, malformed or unknown reply, a reply to another request)
//! leaves the process in an unknown state, so the client kills it on the spot and starts
//! a fresh one (with a new `hello`) at the next request. Nothing here blocks longer than
//! the per-request timeout.

use std::fmt;
use std::time::Duration;

use super::process::{Line, Process, Wait, MAX_LINE};
use super::protocol::{
    self, AovSource, Body, Reply, Request, Violation, PROTOCOL_MINOR, PROTOCOL_VERSION,
};
use crate::dialect::WireRegistration;

/// What went wrong on one request.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FaultKind {
    /// The process exited (or closed stdout) before replying.
    Crash {
        /// Exit status, or how it was stopped.
        status: String,
        /// The last lines it wrote to stderr.
        stderr: Vec<String>,
    },
    /// No reply within the timeout; the process was killed.
    Timeout {
        /// The timeout.
        after: Duration,
        /// The last lines it wrote to stderr (what it was doing, often).
        stderr: Vec<String>,
    },
    /// A reply line that is not a valid answer.
    Reply {
        /// The line (shortened if long).
        line: String,
        /// What is wrong with it.
        violation: Violation,
    },
    /// Lines arrived with no request pending: more replies than requests.
    Extra(String),
    /// The process could not be started again.
    Restart(String),
}

/// A fault with the request that caused it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fault {
    /// The request line (shortened if long).
    pub request: String,
    /// What happened.
    pub kind: FaultKind,
}

impl FaultKind {
    /// A short name for summaries.
    pub fn label(&self) -> &'static str {
        match self {
            FaultKind::Crash { .. } => "crash",
            FaultKind::Timeout { .. } => "timeout",
            FaultKind::Reply { violation, .. } => match violation {
                Violation::Malformed(_) => "malformed reply",
                Violation::WrongId { .. } => "reply to another request",
                Violation::Unknown(_) => "unknown reply",
                Violation::Count { .. } => "wrong answer count",
            },
            FaultKind::Extra(_) => "extra reply",
            FaultKind::Restart(_) => "restart failed",
        }
    }
}

impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            FaultKind::Crash { status, stderr } => {
                write!(f, "the external process died ({status})")?;
                for l in stderr {
                    write!(f, "\n    stderr: {l}")?;
                }
            }
            FaultKind::Timeout { after, stderr } => {
                write!(
                    f,
                    "no reply within {} ms; the process was killed",
                    after.as_millis()
                )?;
                for l in stderr {
                    write!(f, "\n    stderr: {l}")?;
                }
            }
            FaultKind::Reply { line, violation } => write!(f, "{violation}\n    reply: {line}")?,
            FaultKind::Extra(line) => {
                write!(f, "a reply line nobody asked for: {line}")?;
            }
            FaultKind::Restart(why) => write!(f, "cannot restart the external process: {why}")?,
        }
        write!(f, "\n    request: {}", self.request)
    }
}

/// Why the external matcher could not be used at all (bad input, exit status 2).
#[derive(Debug, thiserror::Error)]
pub enum StartError {
    /// The command line is empty or has an unclosed quote.
    #[error("bad --external command `{command}`: {why}")]
    Command {
        /// The command as given.
        command: String,
        /// What is wrong.
        why: String,
    },
    /// The program cannot be started.
    #[error("cannot start `{program}`: {error}")]
    Spawn {
        /// argv[0].
        program: String,
        /// Why.
        error: std::io::Error,
    },
    /// The first `hello` failed.
    #[error("the external matcher failed the hello: {0}")]
    Hello(Fault),
    /// The matcher does not support the dialect (or the protocol).
    #[error("the external matcher refused the hello: {0}")]
    Refused(String),
}

/// Shortens long lines in reports to their first and last bytes.
pub fn shorten(line: &str) -> String {
    const KEEP: usize = 300;
    if line.len() <= 2 * KEEP {
        return line.to_string();
    }
    let mut head = KEEP;
    while !line.is_char_boundary(head) {
        head -= 1;
    }
    let mut tail = line.len() - KEEP;
    while !line.is_char_boundary(tail) {
        tail += 1;
    }
    format!(
        "{} ... ({} bytes) ... {}",
        &line[..head],
        line.len(),
        &line[tail..]
    )
}

/// Least time a process has to start and answer its `hello`.
pub const HELLO_TIMEOUT: Duration = Duration::from_secs(10);

/// A connection to an external matcher that survives its crashes.
pub struct Client {
    argv: Vec<String>,
    dialect: String,
    timeout: Duration,
    process: Option<Process>,
    next_id: u64,
    /// The name the matcher gave in its first hello.
    pub name: Option<String>,
    /// Processes started after the first.
    pub restarts: u64,
    /// The renderer profile every `compile` request names (`lpe-check diff --external
    /// --renderer`, a suite case under a profile), if any.
    pub renderer: Option<String>,
}

impl Client {
    /// Splits `command` like a shell, starts it and says hello.
    pub fn start(command: &str, dialect: &str, timeout: Duration) -> Result<Client, StartError> {
        let argv = shell_words::split(command).map_err(|e| StartError::Command {
            command: command.to_string(),
            why: e.to_string(),
        })?;
        if argv.is_empty() {
            return Err(StartError::Command {
                command: command.to_string(),
                why: "no program".into(),
            });
        }
        let mut c = Client {
            argv,
            dialect: dialect.to_string(),
            timeout,
            process: None,
            next_id: 0,
            name: None,
            restarts: 0,
            renderer: None,
        };
        let process = Process::spawn(&c.argv).map_err(|error| StartError::Spawn {
            program: c.argv[0].clone(),
            error,
        })?;
        c.process = Some(process);
        match c.hello() {
            Ok(Reply::Hello(name)) => c.name = name,
            Ok(Reply::Unsupported(why)) => return Err(StartError::Refused(why)),
            Ok(other) => return Err(StartError::Refused(format!("{other:?}"))),
            Err(f) => return Err(StartError::Hello(f)),
        }
        Ok(c)
    }

    /// The first request of a process. It also waits for the process to start (an
    /// interpreter on a loaded machine can take seconds), so it gets at least
    /// [`HELLO_TIMEOUT`].
    fn hello(&mut self) -> Result<Reply, Fault> {
        let timeout = self.timeout;
        self.timeout = timeout.max(HELLO_TIMEOUT);
        let reply = self.request(Body::Hello {
            protocol: PROTOCOL_VERSION,
            minor: PROTOCOL_MINOR,
            dialect: self.dialect.clone(),
        });
        self.timeout = timeout;
        reply
    }

    /// Compiles a set (OSL: under `registered`): [`Reply::Done`], [`Reply::Rejected`]
    /// or [`Reply::Unsupported`].
    pub fn compile(
        &mut self,
        aovs: Vec<AovSource>,
        registered: Option<WireRegistration>,
    ) -> Result<Reply, Fault> {
        self.ensure()?;
        self.request(Body::Compile {
            aovs,
            registered,
            renderer: None,
        })
    }

    /// Matches paths against the last compiled set: [`Reply::Matches`] or
    /// [`Reply::Unsupported`].
    pub fn match_paths(&mut self, paths: Vec<String>) -> Result<Reply, Fault> {
        self.ensure()?;
        self.request(Body::Match { paths })
    }

    /// Says `quit` and lets the process exit.
    pub fn quit(mut self) {
        if self.process.is_some() && self.request(Body::Quit).is_ok() {
            if let Some(p) = self.process.take() {
                p.finish(self.timeout);
            }
        }
    }

    /// Whether the next request must start a fresh process (the last one was killed
    /// after a fault): a restart, which `--max-restarts` bounds.
    pub fn needs_restart(&self) -> bool {
        self.process.is_none()
    }

    /// Whether another request may be sent with at most `max` restarts in all: the
    /// process is up, or it is down and fewer than `max` restarts have been made.
    pub fn may_continue(&self, max: u64) -> bool {
        !self.needs_restart() || self.restarts < max
    }

    /// A fresh process (and hello) if the last one was killed.
    fn ensure(&mut self) -> Result<(), Fault> {
        if self.process.is_some() {
            return Ok(());
        }
        self.restarts += 1;
        let process = Process::spawn(&self.argv).map_err(|e| Fault {
            request: "(restart)".into(),
            kind: FaultKind::Restart(e.to_string()),
        })?;
        self.process = Some(process);
        match self.hello()? {
            Reply::Hello(_) => Ok(()),
            other => Err(Fault {
                request: "(hello after restart)".into(),
                kind: FaultKind::Restart(format!("hello answered {other:?}")),
            }),
        }
    }

    /// One request, one reply; any fault kills the process.
    fn request(&mut self, body: Body) -> Result<Reply, Fault> {
        let (mut replies, fault) = self.exchange(vec![body]);
        match fault {
            Some(f) => Err(f),
            None => Ok(replies.remove(0)),
        }
    }

    /// Sends every request at once, then reads the replies in order: the protocol is
    /// one reply per request, so a matcher that reads lines one by one needs nothing
    /// to be pipelined, and a batch costs one round trip instead of one per request.
    /// Returns the replies read before the first fault, and that fault (which killed
    /// the process; the requests after it went unanswered). Each reply has the
    /// per-request timeout.
    pub fn pipeline(&mut self, bodies: Vec<Body>) -> (Vec<Reply>, Option<Fault>) {
        if let Err(f) = self.ensure() {
            return (Vec::new(), Some(f));
        }
        self.exchange(bodies)
    }

    fn exchange(&mut self, bodies: Vec<Body>) -> (Vec<Reply>, Option<Fault>) {
        let requests: Vec<Request> = bodies
            .into_iter()
            .map(|mut body| {
                if let Body::Compile { renderer, .. } = &mut body {
                    renderer.clone_from(&self.renderer);
                }
                self.next_id += 1;
                Request {
                    id: self.next_id - 1,
                    body,
                }
            })
            .collect();
        let lines: Vec<String> = requests.iter().map(Request::to_line).collect();
        let mut replies = Vec::with_capacity(requests.len());
        let mut outcome = self.send_all(&lines);
        if outcome.is_ok() {
            for (k, r) in requests.iter().enumerate() {
                match self.receive(r) {
                    Ok(reply) => replies.push(reply),
                    Err(kind) => {
                        outcome = Err((k, kind));
                        break;
                    }
                }
            }
        }
        let Err((k, mut kind)) = outcome else {
            return (replies, None);
        };
        if let Some(mut p) = self.process.take() {
            let (status, stderr) = p.kill();
            match kind {
                FaultKind::Crash { .. } => kind = FaultKind::Crash { status, stderr },
                FaultKind::Timeout { after, .. } => kind = FaultKind::Timeout { after, stderr },
                _ => {}
            }
        }
        let fault = Fault {
            request: shorten(&lines[k]),
            kind,
        };
        (replies, Some(fault))
    }

    /// Writes the lines, after checking that no reply is waiting that nobody asked for.
    fn send_all(&mut self, lines: &[String]) -> Result<(), (usize, FaultKind)> {
        let p = self.process.as_mut().expect("ensure() ran");
        if let Some(extra) = p.pending() {
            return Err((
                0,
                match extra {
                    Line::Text(l) | Line::NotUtf8(l) => FaultKind::Extra(shorten(&l)),
                    Line::TooLong => FaultKind::Extra(format!("(over {MAX_LINE} bytes)")),
                    Line::Eof => crash(),
                },
            ));
        }
        for (k, line) in lines.iter().enumerate() {
            if p.send(line).is_err() {
                return Err((k, crash()));
            }
        }
        Ok(())
    }

    fn receive(&mut self, request: &Request) -> Result<Reply, FaultKind> {
        let p = self.process.as_mut().expect("ensure() ran");
        let reply = match p.recv(self.timeout) {
            Ok(Line::Text(l)) => l,
            Ok(Line::NotUtf8(l)) => {
                return Err(FaultKind::Reply {
                    line: shorten(&l),
                    violation: Violation::Malformed("not UTF-8".into()),
                })
            }
            Ok(Line::TooLong) => {
                return Err(FaultKind::Reply {
                    line: format!("(over {MAX_LINE} bytes)"),
                    violation: Violation::Malformed("line too long".into()),
                })
            }
            Ok(Line::Eof) | Err(Wait::Closed) => return Err(crash()),
            Err(Wait::Timeout) => {
                return Err(FaultKind::Timeout {
                    after: self.timeout,
                    stderr: Vec::new(),
                })
            }
        };
        protocol::read_reply(request, &reply).map_err(|violation| FaultKind::Reply {
            line: shorten(&reply),
            violation,
        })
    }
}

/// A crash before its status is known (filled in once the process is reaped).
fn crash() -> FaultKind {
    FaultKind::Crash {
        status: String::new(),
        stderr: Vec::new(),
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        // Process's own Drop kills and reaps it.
        self.process.take();
    }
}
