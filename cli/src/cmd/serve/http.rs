//! The HTTP side of `lpe-check serve`: one request per connection, read within
//! [`Limits`] and parsed by `httparse`, answered by a handler on a fixed pool of worker
//! threads.
//!
//! The acceptor hands each connection to a bounded queue; the workers take from it.
//! When the queue is full the connection goes to a single refuser thread, which answers
//! 503 (and, when its own queue is full too, the connection is closed unanswered): so
//! however many clients come, the server runs `workers + 2` threads and holds at most
//! `2 * queue` waiting connections. A request head over its limit, a body over its
//! limit, a chunked body, a malformed head or a client that stops sending get a 4xx
//! with a message; a handler that panics gets a 500 and its worker goes on.

use std::io::{self, Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::mpsc::{self, Receiver, TrySendError};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// How much the server takes on.
#[derive(Clone, Debug)]
pub struct Limits {
    /// Threads answering requests.
    pub workers: usize,
    /// Connections waiting for a worker (and, apart, for the refuser).
    pub queue: usize,
    /// Bytes of a request line and its headers.
    pub max_head: usize,
    /// Bytes of a request body.
    pub max_body: usize,
    /// How long a client may take to send its request, and to take the answer.
    pub timeout: Duration,
}

impl Default for Limits {
    fn default() -> Self {
        let cores = std::thread::available_parallelism().map_or(2, |n| n.get());
        Limits {
            workers: cores.clamp(2, 8),
            queue: 32,
            max_head: 16 << 10,
            max_body: 1 << 20,
            timeout: Duration::from_secs(10),
        }
    }
}

/// A request as the handler sees it: read whole, body included.
#[derive(Debug)]
pub struct Request {
    /// `GET`, `POST`, ...
    pub method: String,
    /// The path without its query string.
    pub path: String,
    /// Header names (lowercase) and values.
    pub headers: Vec<(String, String)>,
    /// The body, exactly `Content-Length` bytes.
    pub body: Vec<u8>,
}

impl Request {
    /// The value of header `name` (lowercase), if sent.
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }
}

/// An answer: status, content type, body and any further headers.
#[derive(Debug)]
pub struct Response {
    /// The HTTP status.
    pub status: u16,
    /// The `Content-Type`.
    pub content_type: &'static str,
    /// The body.
    pub body: Vec<u8>,
    /// More headers, name and value.
    pub headers: Vec<(&'static str, String)>,
}

impl Response {
    /// A JSON body already serialized.
    pub fn json(status: u16, json: String) -> Self {
        Response {
            status,
            content_type: "application/json",
            body: json.into_bytes(),
            headers: Vec::new(),
        }
    }

    /// An error: `{"error": message}`.
    pub fn error(status: u16, message: &str) -> Self {
        Response::json(status, serde_json::json!({ "error": message }).to_string())
    }

    /// An HTML page.
    pub fn html(page: String) -> Self {
        Response {
            status: 200,
            content_type: "text/html; charset=utf-8",
            body: page.into_bytes(),
            headers: Vec::new(),
        }
    }
}

/// Why a request was not handed to the handler: the answer, and how many body bytes
/// the client may still send (read and dropped before closing, so that the client reads
/// the answer instead of a connection reset).
struct Refused {
    response: Response,
    unread: usize,
}

fn refused(status: u16, message: &str) -> Refused {
    Refused {
        response: Response::error(status, message),
        unread: 0,
    }
}

/// Serves `listener` until the process ends: every connection's request goes to
/// `handler` on one of `limits.workers` threads, or is refused with 503 when
/// `limits.queue` connections already wait.
pub fn serve<H>(listener: TcpListener, limits: &Limits, handler: H) -> io::Result<()>
where
    H: Fn(&Request) -> Response + Send + Sync + 'static,
{
    let handler = Arc::new(handler);
    let (to_workers, waiting) = mpsc::sync_channel::<TcpStream>(limits.queue);
    let waiting = Arc::new(Mutex::new(waiting));
    for i in 0..limits.workers {
        let (waiting, handler, limits) = (waiting.clone(), handler.clone(), limits.clone());
        std::thread::Builder::new()
            .name(format!("serve-worker-{i}"))
            // The reference matcher recurses a few frames per path vertex (as in main).
            .stack_size(256 << 20)
            .spawn(move || work(&waiting, &limits, &*handler))?;
    }
    let (to_refuser, refusing) = mpsc::sync_channel::<TcpStream>(limits.queue);
    let refuser_limits = limits.clone();
    std::thread::Builder::new()
        .name("serve-refuser".into())
        .spawn(move || {
            for stream in refusing {
                let busy = Response::error(503, "the server is busy: try again");
                answer(stream, &busy, &refuser_limits, Some(0));
            }
        })?;
    for stream in listener.incoming() {
        let stream = match stream {
            Ok(s) => s,
            // Out of file descriptors, or a connection reset before it was accepted:
            // the next accept may work.
            Err(e) => {
                eprintln!("warning: accepting a connection: {e}");
                std::thread::sleep(Duration::from_millis(10));
                continue;
            }
        };
        match to_workers.try_send(stream) {
            Ok(()) => {}
            Err(TrySendError::Full(stream)) => {
                // Dropping the stream when the refuser is behind too closes it unanswered.
                let _ = to_refuser.try_send(stream);
            }
            Err(TrySendError::Disconnected(_)) => {
                return Err(io::Error::other("every worker thread has stopped"))
            }
        }
    }
    Ok(())
}

/// A worker: takes connections until the acceptor is gone.
fn work(
    waiting: &Mutex<Receiver<TcpStream>>,
    limits: &Limits,
    handler: &(dyn Fn(&Request) -> Response + Sync),
) {
    loop {
        // A worker that panicked while holding the lock cannot have left the receiver
        // half-changed: `recv` is the only use.
        let next = waiting.lock().unwrap_or_else(|p| p.into_inner()).recv();
        let Ok(mut stream) = next else { return };
        if stream.set_read_timeout(Some(limits.timeout)).is_err() {
            continue;
        }
        let (response, unread) = match read_request(&mut stream, limits) {
            Ok(request) => {
                let response =
                    catch_unwind(AssertUnwindSafe(|| handler(&request))).unwrap_or_else(|_| {
                        Response::error(500, "internal failure (please report it with the request)")
                    });
                (response, None)
            }
            Err(r) => (r.response, Some(r.unread)),
        };
        answer(stream, &response, limits, unread);
    }
}

/// Writes `response`; for a refused request, then reads and drops what the client still
/// sends (`unread` body bytes and a head, within 2 s) before closing: closing a
/// socket with unread input resets the connection, and the client would see the reset
/// instead of the answer. A request read whole needs no such wait.
fn answer(mut stream: TcpStream, response: &Response, limits: &Limits, unread: Option<usize>) {
    let _ = stream.set_write_timeout(Some(limits.timeout));
    if write_response(&mut stream, response).is_err() {
        return;
    }
    let _ = stream.shutdown(Shutdown::Write);
    let Some(unread) = unread else { return };
    let deadline = Instant::now() + Duration::from_secs(2);
    let mut left = unread + limits.max_head;
    let mut sink = [0u8; 8192];
    while left > 0 {
        let Some(rest) = deadline.checked_duration_since(Instant::now()) else {
            return;
        };
        if rest.is_zero() || stream.set_read_timeout(Some(rest)).is_err() {
            return;
        }
        match stream.read(&mut sink) {
            Ok(0) | Err(_) => return,
            Ok(n) => left = left.saturating_sub(n),
        }
    }
}

fn write_response(stream: &mut impl Write, r: &Response) -> io::Result<()> {
    let mut head = format!(
        "HTTP/1.1 {} {}\r\nContent-Type: {}\r\nContent-Length: {}\r\nConnection: close\r\n\
         Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n",
        r.status,
        reason(r.status),
        r.content_type,
        r.body.len()
    );
    for (name, value) in &r.headers {
        head.push_str(&format!("{name}: {value}\r\n"));
    }
    head.push_str("\r\n");
    stream.write_all(head.as_bytes())?;
    stream.write_all(&r.body)?;
    stream.flush()
}

fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        411 => "Length Required",
        413 => "Content Too Large",
        422 => "Unprocessable Content",
        431 => "Request Header Fields Too Large",
        500 => "Internal Server Error",
        503 => "Service Unavailable",
        _ => "Status",
    }
}

/// Reads one request: the head up to its blank line (at most `max_head` bytes), then
/// exactly `Content-Length` body bytes (at most `max_body`).
fn read_request(stream: &mut impl Read, limits: &Limits) -> Result<Request, Refused> {
    let timed_out = || {
        refused(
            408,
            &format!(
                "the request did not arrive within {} s",
                limits.timeout.as_secs()
            ),
        )
    };
    let mut buf = Vec::with_capacity(2048);
    let mut chunk = [0u8; 8192];
    // How far the blank line was looked for: each read's bytes are searched once.
    let mut searched: usize = 0;
    let head_len = loop {
        // The blank line may straddle two reads: look from 3 bytes before the new ones.
        let from = searched.saturating_sub(3);
        searched = buf.len();
        if let Some(at) = buf[from..].windows(4).position(|w| w == b"\r\n\r\n") {
            let end = from + at + 4;
            if end <= limits.max_head {
                break end;
            }
        }
        if buf.len() >= limits.max_head {
            return Err(refused(
                431,
                &format!("the request head is over {} bytes", limits.max_head),
            ));
        }
        match stream.read(&mut chunk) {
            Ok(0) => {
                return Err(refused(
                    400,
                    "the connection closed before the request head ended (a blank line)",
                ))
            }
            Ok(n) => buf.extend_from_slice(&chunk[..n]),
            Err(e) if is_timeout(&e) => return Err(timed_out()),
            Err(e) => return Err(refused(400, &format!("reading the request: {e}"))),
        }
    };
    let mut header_slots = [httparse::EMPTY_HEADER; 64];
    let mut parsed = httparse::Request::new(&mut header_slots);
    match parsed.parse(&buf[..head_len]) {
        Ok(httparse::Status::Complete(_)) => {}
        Ok(httparse::Status::Partial) => {
            return Err(refused(400, "malformed request: the head is incomplete"))
        }
        Err(httparse::Error::TooManyHeaders) => {
            return Err(refused(431, "the request has more than 64 headers"))
        }
        Err(e) => return Err(refused(400, &format!("malformed request: {e}"))),
    }
    let method = parsed.method.unwrap_or_default().to_string();
    let target = parsed.path.unwrap_or_default();
    let path = target.split('?').next().unwrap_or_default().to_string();
    let mut headers = Vec::with_capacity(parsed.headers.len());
    for h in parsed.headers.iter() {
        let Ok(value) = std::str::from_utf8(h.value) else {
            return Err(refused(400, &format!("header `{}` is not UTF-8", h.name)));
        };
        headers.push((h.name.to_ascii_lowercase(), value.trim().to_string()));
    }
    let mut request = Request {
        method,
        path,
        headers,
        body: Vec::new(),
    };
    if request.header("transfer-encoding").is_some() {
        return Err(refused(
            411,
            "bodies in chunks are not read: send the body with a Content-Length",
        ));
    }
    let mut lengths = request
        .headers
        .iter()
        .filter(|(n, _)| n == "content-length")
        .map(|(_, v)| v.as_str());
    let length = match (lengths.next(), lengths.next()) {
        (None, _) => 0,
        (Some(v), None) => v.parse::<usize>().map_err(|_| {
            refused(
                400,
                &format!("Content-Length `{v}` is not a number of bytes"),
            )
        })?,
        (Some(_), Some(_)) => return Err(refused(400, "Content-Length is given twice")),
    };
    let mut body = buf.split_off(head_len);
    if length > limits.max_body {
        return Err(Refused {
            response: Response::error(
                413,
                &format!(
                    "the request body of {length} bytes is over the limit of {} bytes",
                    limits.max_body
                ),
            ),
            unread: length.saturating_sub(body.len()),
        });
    }
    // Bytes past the body (a second, pipelined request) are dropped: one request per
    // connection, and the answer says `Connection: close`.
    body.truncate(length);
    while body.len() < length {
        let want = (length - body.len()).min(chunk.len());
        match stream.read(&mut chunk[..want]) {
            Ok(0) => {
                return Err(refused(
                    400,
                    &format!("the body ended after {} of {length} bytes", body.len()),
                ))
            }
            Ok(n) => body.extend_from_slice(&chunk[..n]),
            Err(e) if is_timeout(&e) => return Err(timed_out()),
            Err(e) => return Err(refused(400, &format!("reading the request: {e}"))),
        }
    }
    request.body = body;
    Ok(request)
}

fn is_timeout(e: &io::Error) -> bool {
    matches!(
        e.kind(),
        io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn limits() -> Limits {
        Limits {
            workers: 1,
            queue: 1,
            max_head: 64,
            max_body: 10,
            timeout: Duration::from_secs(1),
        }
    }

    /// A reader handing out its bytes a few at a time, as a socket may.
    struct Trickle<'a>(&'a [u8], usize);

    impl Read for Trickle<'_> {
        fn read(&mut self, out: &mut [u8]) -> io::Result<usize> {
            let n = self.0.len().min(self.1).min(out.len());
            out[..n].copy_from_slice(&self.0[..n]);
            self.0 = &self.0[n..];
            Ok(n)
        }
    }

    fn read(bytes: &[u8], step: usize) -> Result<Request, (u16, String)> {
        read_request(&mut Trickle(bytes, step), &limits()).map_err(|r| {
            let v: serde_json::Value = serde_json::from_slice(&r.response.body).unwrap();
            (r.response.status, v["error"].as_str().unwrap().to_string())
        })
    }

    /// The blank line split over two reads is still found, and the body is exactly
    /// Content-Length bytes. Fault caught: searching only the newly read bytes for the
    /// blank line (a request split after `\r\n\r` then waits for bytes that never come).
    #[test]
    fn a_request_arriving_a_byte_at_a_time_is_read_whole() {
        let text = b"POST /api/check?x=1 HTTP/1.1\r\nContent-Length: 5\r\n\r\nhelloEXTRA";
        for step in [1, 2, 3, 7, 100] {
            let r = read(text, step).unwrap();
            assert_eq!((r.method.as_str(), r.path.as_str()), ("POST", "/api/check"));
            assert_eq!(r.header("content-length"), Some("5"));
            assert_eq!(r.body, b"hello", "step {step}");
        }
    }

    /// Each bad request gets its status and a message saying what is wrong, and a body
    /// of exactly the limit is read.
    #[test]
    fn bad_requests_get_their_status_and_message() {
        let cases: [(&[u8], u16, &str); 8] = [
            (
                b"GET / HTTP/1.1\r\nX: aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa",
                431,
                "request head is over 64 bytes",
            ),
            (
                b"GET / HTTP/1.1\r\nHost: x\r\n",
                400,
                "before the request head ended",
            ),
            (b"G@T / HTTP/1.1\r\n\r\n", 400, "malformed request"),
            (
                b"POST / HTTP/1.1\r\nContent-Length: 11\r\n\r\n",
                413,
                "11 bytes is over the limit of 10",
            ),
            (
                b"POST / HTTP/1.1\r\nContent-Length: x1\r\n\r\n",
                400,
                "`x1` is not a number",
            ),
            (
                b"POST / HTTP/1.1\r\nContent-Length: 4\r\n\r\nab",
                400,
                "body ended after 2 of 4 bytes",
            ),
            (
                b"POST / HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n",
                411,
                "Content-Length",
            ),
            (
                b"POST / HTTP/1.1\r\nContent-Length: 1\r\nContent-Length: 1\r\n\r\n",
                400,
                "twice",
            ),
        ];
        for (text, status, message) in cases {
            let (got, said) = read(text, 5).unwrap_err();
            assert_eq!(got, status, "{}", String::from_utf8_lossy(text));
            assert!(said.contains(message), "{said:?} lacks {message:?}");
        }
        assert_eq!(
            read(
                b"POST / HTTP/1.1\r\nContent-Length: 10\r\n\r\n0123456789",
                5
            )
            .unwrap()
            .body,
            b"0123456789"
        );
    }

    /// With one worker busy and one connection waiting, the next clients are refused
    /// with 503 and a message, and once the worker is free the server answers again.
    /// Fault caught: a connection past the queue dropped unanswered (the client reads
    /// no status).
    #[test]
    fn clients_past_the_queue_get_503_and_the_server_goes_on() {
        use std::sync::mpsc::channel;
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let port = listener.local_addr().unwrap().port();
        let (release, released) = channel::<()>();
        let released = Mutex::new(released);
        let (started, handler_started) = channel::<()>();
        let started = Mutex::new(started);
        std::thread::spawn(move || {
            serve(listener, &limits(), move |r: &Request| {
                if r.path == "/block" {
                    started.lock().unwrap().send(()).unwrap();
                    released.lock().unwrap().recv().unwrap();
                }
                Response::json(200, "{}".into())
            })
        });
        let ask = move |path: &str| {
            let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
            s.write_all(format!("GET {path} HTTP/1.1\r\n\r\n").as_bytes())
                .unwrap();
            s
        };
        let read = |mut s: TcpStream| {
            let mut out = String::new();
            s.read_to_string(&mut out).unwrap();
            out
        };
        let busy = ask("/block");
        handler_started.recv().unwrap();
        let queued = ask("/");
        // Give the acceptor time to queue it before the next clients come.
        std::thread::sleep(Duration::from_millis(200));
        for _ in 0..3 {
            let answer = read(ask("/"));
            assert!(answer.starts_with("HTTP/1.1 503 "), "{answer}");
            assert!(answer.contains("the server is busy"), "{answer}");
        }
        release.send(()).unwrap();
        assert!(read(busy).starts_with("HTTP/1.1 200 "));
        assert!(read(queued).starts_with("HTTP/1.1 200 "));
        assert!(read(ask("/")).starts_with("HTTP/1.1 200 "));
    }
    /// A handler runs with room for deep recursion (the reference matcher recurses a few
    /// frames per path vertex): one that takes 16 MiB of stack, 8 times a spawned
    /// thread's default, answers. Fault caught: the workers' `256 << 20` bytes of stack
    /// as `256 >> 20` (0: the smallest stack the system allows, and the test process
    /// dies of a stack overflow).
    #[test]
    fn a_handler_has_room_for_deep_recursion() {
        /// Recurses `n` deep on frames of at least 1 KiB; 0.
        fn deep(n: usize) -> usize {
            let frame = std::hint::black_box([0u8; 1024]);
            if n == 0 {
                return usize::from(frame[0]);
            }
            deep(n - 1) + usize::from(std::hint::black_box(frame[n % 1024]))
        }
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let port = listener.local_addr().unwrap().port();
        std::thread::spawn(move || {
            serve(listener, &limits(), |_: &Request| {
                Response::json(200, deep(16 << 10).to_string())
            })
        });
        let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
        s.write_all(b"GET / HTTP/1.1\r\n\r\n").unwrap();
        let mut out = String::new();
        s.read_to_string(&mut out).unwrap();
        assert!(out.starts_with("HTTP/1.1 200 OK"), "{out}");
        assert!(out.ends_with("\r\n\r\n0"), "{out}");
    }

    /// A reader that hands out its bytes, then fails with an error of `kind`.
    struct FailAfter<'a>(&'a [u8], io::ErrorKind);

    impl Read for FailAfter<'_> {
        fn read(&mut self, out: &mut [u8]) -> io::Result<usize> {
            if self.0.is_empty() {
                return Err(io::Error::new(self.1, "planted"));
            }
            let n = self.0.len().min(out.len());
            out[..n].copy_from_slice(&self.0[..n]);
            self.0 = &self.0[n..];
            Ok(n)
        }
    }

    /// A client that stops sending (the read timeout: `WouldBlock` or `TimedOut`) gets
    /// 408 with the limit, in the head and in the body; any other read error is a 400
    /// that says what failed. Faults caught: either match guard `is_timeout(&e)` as
    /// `true` or `false`, `is_timeout` as `true` or `false`.
    #[test]
    fn a_client_that_stops_sending_gets_408_and_a_failed_read_400() {
        let head: &[u8] = b"GET / HTTP/1.1\r\nHost: x\r\n";
        let body: &[u8] = b"POST / HTTP/1.1\r\nContent-Length: 4\r\n\r\nab";
        let stopped = "the request did not arrive within 1 s";
        let failed = "reading the request: planted";
        for text in [head, body] {
            for (kind, status, message) in [
                (io::ErrorKind::WouldBlock, 408, stopped),
                (io::ErrorKind::TimedOut, 408, stopped),
                (io::ErrorKind::ConnectionReset, 400, failed),
            ] {
                let r = read_request(&mut FailAfter(text, kind), &limits()).unwrap_err();
                let said: serde_json::Value = serde_json::from_slice(&r.response.body).unwrap();
                assert_eq!(
                    (r.response.status, said["error"].as_str().unwrap()),
                    (status, message),
                    "{kind:?} after {}",
                    String::from_utf8_lossy(text)
                );
            }
        }
    }

    /// The head goes out with the status's reason phrase (RFC 9110), the fixed headers,
    /// the response's own and the body. Faults caught: each arm of `reason` deleted (its
    /// status then goes out as `Status`), `reason` as `""` or `"xyzzy"`.
    #[test]
    fn a_response_goes_out_with_its_reason_phrase_and_headers() {
        let phrases = [
            (200, "OK"),
            (400, "Bad Request"),
            (403, "Forbidden"),
            (404, "Not Found"),
            (405, "Method Not Allowed"),
            (408, "Request Timeout"),
            (411, "Length Required"),
            (413, "Content Too Large"),
            (422, "Unprocessable Content"),
            (431, "Request Header Fields Too Large"),
            (500, "Internal Server Error"),
            (503, "Service Unavailable"),
            (418, "Status"),
        ];
        for (status, phrase) in phrases {
            let mut r = Response::json(status, "{}".into());
            r.headers.push(("X-Test", "1".into()));
            let mut out = Vec::new();
            write_response(&mut out, &r).unwrap();
            assert_eq!(
                String::from_utf8(out).unwrap(),
                format!(
                    "HTTP/1.1 {status} {phrase}\r\nContent-Type: application/json\r\n\
                     Content-Length: 2\r\nConnection: close\r\nCache-Control: no-store\r\n\
                     X-Content-Type-Options: nosniff\r\nX-Test: 1\r\n\r\n{{}}"
                )
            );
        }
    }

    /// After a refusal the worker waits for what the client still owes (up to 2 s) and
    /// no longer: a client that sends nothing more holds it about 2 s, not the request
    /// timeout (30 s here), and one that sends more than the refused body and a head
    /// is cut off once it has read that much. Either way the next client is answered
    /// after. Faults caught: the drain's `||` as `&&` (the read timeout never set: the
    /// worker waits 30 s); its deadline now - 2 s, `left > 0` as `==` (no wait: the next
    /// client answered at once); `unread + max_head` as `-` (0 - 64 wraps) or `*`,
    /// `left > 0` as `>=` (the worker reads on to the deadline).
    #[test]
    fn a_refused_client_holds_its_worker_for_at_most_2_s() {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let port = listener.local_addr().unwrap().port();
        // A queue of 4: the next client may come before the worker took the last.
        let limits = Limits {
            queue: 4,
            timeout: Duration::from_secs(30),
            ..limits()
        };
        std::thread::spawn(move || {
            serve(listener, &limits, |_: &Request| {
                Response::json(200, "{}".into())
            })
        });
        let connect = || TcpStream::connect(("127.0.0.1", port)).unwrap();
        // How long the next client waits for its answer, which must be a 200.
        let next_waits = || {
            let started = Instant::now();
            let mut s = connect();
            s.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
            s.write_all(b"GET / HTTP/1.1\r\n\r\n").unwrap();
            let mut out = String::new();
            s.read_to_string(&mut out).unwrap();
            assert!(out.starts_with("HTTP/1.1 200 OK"), "{out}");
            started.elapsed()
        };
        // A body of 11 bytes over the limit of 10, none of it sent.
        let mut silent = connect();
        silent
            .write_all(b"POST / HTTP/1.1\r\nContent-Length: 11\r\n\r\n")
            .unwrap();
        let mut answer = vec![0u8; 13];
        silent.read_exact(&mut answer).unwrap();
        assert_eq!(answer, b"HTTP/1.1 413 ");
        let waited = next_waits();
        assert!(
            waited >= Duration::from_secs(1) && waited < Duration::from_secs(5),
            "{waited:?}"
        );
        // A body over the limit sent whole and 400 000 bytes more, the socket left open:
        // the worker reads the body and at most a head more (unread + 64 bytes; with 11,
        // fewer than the head, with 100 000, far fewer than unread times 64), then
        // closes.
        let mut floods = Vec::new();
        for length in [11, 100_000] {
            let mut flood = connect();
            let mut raw =
                format!("POST / HTTP/1.1\r\nContent-Length: {length}\r\n\r\n").into_bytes();
            raw.resize(raw.len() + length + 400_000, b'x');
            // The server may close while this is still being sent: the write may fail.
            let _ = flood.write_all(&raw);
            let waited = next_waits();
            assert!(waited < Duration::from_secs(1), "{length}: {waited:?}");
            floods.push(flood);
        }
        drop((silent, floods));
    }
}
