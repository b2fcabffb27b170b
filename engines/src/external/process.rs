//! The external process: spawned with piped stdin/stdout, its replies read on a thread so
//! that every wait has a deadline.
//!
//! A reader thread turns stdout into [`Line`]s on a channel; the caller waits on the
//! channel with a timeout, so a hung process costs the timeout, never a hang. stderr is
//! drained on another thread into a short tail, shown when the process dies. Dropping a
//! [`Process`] kills and reaps it.

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Longest reply line read, in bytes: a longer one is a malformed reply, not an
/// unbounded allocation.
pub const MAX_LINE: usize = 16 << 20;

/// stderr lines kept for a crash report.
const STDERR_TAIL: usize = 20;

/// What the reader thread saw on stdout.
#[derive(Debug)]
pub enum Line {
    /// One line, without its newline.
    Text(String),
    /// Bytes that are not UTF-8 (the line, lossily decoded).
    NotUtf8(String),
    /// A line longer than [`MAX_LINE`].
    TooLong,
    /// stdout closed (the process exited or closed it).
    Eof,
}

/// stdin is closed: the process is gone.
#[derive(Debug)]
pub struct Closed;

/// How waiting for a line ended without one.
#[derive(Debug)]
pub enum Wait {
    /// No line within the timeout.
    Timeout,
    /// The reader thread is gone (after [`Line::Eof`]).
    Closed,
}

/// A running external matcher.
pub struct Process {
    child: Child,
    /// Lines for the writer thread: a send never blocks, even on a process that stopped
    /// reading with its pipe full.
    stdin: Option<Sender<String>>,
    lines: Receiver<Line>,
    stderr: Arc<Mutex<VecDeque<String>>>,
}

impl Process {
    /// Starts `argv[0]` with the rest as arguments.
    pub fn spawn(argv: &[String]) -> std::io::Result<Process> {
        let (program, args) = argv.split_first().ok_or_else(|| {
            std::io::Error::new(std::io::ErrorKind::InvalidInput, "empty command")
        })?;
        let mut child = Command::new(program)
            .args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()?;
        let pipe = child.stdin.take().expect("stdin is piped");
        let (stdin, queue) = mpsc::channel();
        std::thread::spawn(move || write_lines(pipe, &queue));
        let stdout = child.stdout.take().expect("stdout is piped");
        let stderr = child.stderr.take().expect("stderr is piped");
        let (tx, lines) = mpsc::channel();
        std::thread::spawn(move || read_lines(BufReader::new(stdout), &tx));
        let tail = Arc::new(Mutex::new(VecDeque::new()));
        let sink = Arc::clone(&tail);
        std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines() {
                let Ok(line) = line else { break };
                let Ok(mut t) = sink.lock() else { break };
                if t.len() == STDERR_TAIL {
                    t.pop_front();
                }
                t.push_back(line);
            }
        });
        Ok(Process {
            child,
            stdin: Some(stdin),
            lines,
            stderr: tail,
        })
    }

    /// Queues one line for stdin (the newline is added). Fails once the writer thread
    /// has stopped (the pipe broke: the process is gone).
    pub fn send(&mut self, line: &str) -> Result<(), Closed> {
        let stdin = self.stdin.as_ref().ok_or(Closed)?;
        stdin.send(format!("{line}\n")).map_err(|_| Closed)
    }

    /// The next stdout line, waiting at most `timeout`.
    pub fn recv(&self, timeout: Duration) -> Result<Line, Wait> {
        self.lines.recv_timeout(timeout).map_err(|e| match e {
            RecvTimeoutError::Timeout => Wait::Timeout,
            RecvTimeoutError::Disconnected => Wait::Closed,
        })
    }

    /// A line already waiting, if any (a reply nobody asked for).
    pub fn pending(&self) -> Option<Line> {
        self.lines.try_recv().ok()
    }

    /// Kills the process and describes how it ended (its exit status if it had already
    /// exited), with the tail of its stderr.
    pub fn kill(&mut self) -> (String, Vec<String>) {
        self.stdin = None;
        let status = match self.child.try_wait() {
            Ok(Some(s)) => s.to_string(),
            _ => {
                // Give a process that is exiting a moment, so its status is reported
                // rather than "killed".
                std::thread::sleep(Duration::from_millis(20));
                match self.child.try_wait() {
                    Ok(Some(s)) => s.to_string(),
                    _ => {
                        let _ = self.child.kill();
                        let _ = self.child.wait();
                        "killed by the harness".to_string()
                    }
                }
            }
        };
        // The stderr thread may still be reading the last lines of a dead process.
        std::thread::sleep(Duration::from_millis(10));
        let tail = self
            .stderr
            .lock()
            .map(|t| t.iter().cloned().collect())
            .unwrap_or_default();
        (status, tail)
    }

    /// Closes stdin and waits up to `timeout` for the process to exit, else kills it.
    pub fn finish(mut self, timeout: Duration) {
        self.stdin = None;
        let deadline = std::time::Instant::now() + timeout;
        while std::time::Instant::now() < deadline {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Drop for Process {
    fn drop(&mut self) {
        if let Ok(None) = self.child.try_wait() {
            let _ = self.child.kill();
        }
        let _ = self.child.wait();
    }
}

/// The writer thread: queued lines to stdin until the queue or the pipe closes.
fn write_lines(mut pipe: ChildStdin, queue: &Receiver<String>) {
    while let Ok(line) = queue.recv() {
        // Batch what is already queued into one write.
        let mut chunk = line;
        while let Ok(more) = queue.try_recv() {
            chunk.push_str(&more);
        }
        if pipe
            .write_all(chunk.as_bytes())
            .and_then(|()| pipe.flush())
            .is_err()
        {
            return;
        }
    }
}

/// The reader thread: lines of at most [`MAX_LINE`] bytes until EOF or a send fails.
fn read_lines(mut out: impl BufRead, tx: &mpsc::Sender<Line>) {
    loop {
        let mut buf = Vec::new();
        let line = match (&mut out)
            .take(MAX_LINE as u64 + 1)
            .read_until(b'\n', &mut buf)
        {
            Ok(0) | Err(_) => Line::Eof,
            Ok(_) if buf.len() > MAX_LINE => Line::TooLong,
            Ok(_) => {
                if buf.last() == Some(&b'\n') {
                    buf.pop();
                }
                match String::from_utf8(buf) {
                    Ok(s) => Line::Text(s),
                    Err(e) => Line::NotUtf8(String::from_utf8_lossy(e.as_bytes()).into_owned()),
                }
            }
        };
        let stop = matches!(line, Line::Eof | Line::TooLong);
        if tx.send(line).is_err() || stop {
            return;
        }
    }
}
