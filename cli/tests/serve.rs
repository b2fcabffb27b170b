//! `lpe-check serve` end to end: the binary started on port 0, its printed URL read, and
//! every route asked over plain TCP: the page, the API, bad requests, an oversized body,
//! 50 clients at once, a port in use.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::process::{Child, Command, Stdio};

/// A running `lpe-check serve`, stopped when dropped.
struct Server {
    child: Child,
    port: u16,
}

impl Server {
    fn start() -> Server {
        let mut child = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
            .args(["serve", "--port", "0"])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("lpe-check starts");
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        let url = &line[line.find("http://127.0.0.1:").expect("the URL is printed")..];
        let port = url["http://127.0.0.1:".len()..]
            .split('/')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        Server { child, port }
    }

    /// Sends `raw` and reads the whole answer: status, headers, body.
    fn raw(&self, raw: &[u8]) -> (u16, String, String) {
        let mut s = TcpStream::connect(("127.0.0.1", self.port)).unwrap();
        s.write_all(raw).unwrap();
        let mut out = Vec::new();
        s.read_to_end(&mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let (head, body) = text.split_once("\r\n\r\n").expect("a head and a body");
        let status = head[9..12].parse().unwrap();
        (status, head.to_string(), body.to_string())
    }

    fn get(&self, path: &str) -> (u16, String, String) {
        let host = format!("127.0.0.1:{}", self.port);
        self.raw(format!("GET {path} HTTP/1.1\r\nHost: {host}\r\n\r\n").as_bytes())
    }

    fn post(&self, path: &str, body: &str) -> (u16, serde_json::Value) {
        let host = format!("127.0.0.1:{}", self.port);
        let (status, _, body) = self.raw(
            format!(
                "POST {path} HTTP/1.1\r\nHost: {host}\r\nContent-Type: application/json\r\n\
                 Content-Length: {}\r\n\r\n{body}",
                body.len()
            )
            .as_bytes(),
        );
        (
            status,
            serde_json::from_str(&body).expect("every answer is JSON"),
        )
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// `GET /` is the page with the serving data written in and a policy that lets it reach
/// nothing but this server; `POST /api/check` answers exactly what `lpe_explore::answer`
/// does for the same body, a 45 KB list included. Fault caught: the body handed to the
/// API cut at the first read (a 400: the JSON ends early).
#[test]
fn the_page_and_the_api_answer() {
    let server = Server::start();
    let (status, head, page) = server.get("/");
    assert_eq!(status, 200, "{head}");
    assert!(
        head.contains("Content-Type: text/html; charset=utf-8"),
        "{head}"
    );
    assert!(
        head.contains("Content-Security-Policy: default-src 'none';"),
        "{head}"
    );
    assert!(
        page.contains(r#"<script type="application/json" id="lpe-data">{"#),
        "no data"
    );
    assert!(page.contains(r#""mode":"serve""#));
    // Every shipped renderer is offered.
    for name in ["karma", "arnold", "hdprman", "vray", "moonray"] {
        assert!(
            page.contains(&format!(r#""name":"{name}""#)),
            "{name} missing"
        );
    }
    // A long list arrives in several reads: it must reach the API whole.
    let mut list: String = (0..3000).map(|i| format!("a{i} = C<RD>L\\n")).collect();
    list.push_str("last = C<R");
    let body = format!(r#"{{"aovs": "{list}"}}"#);
    let (status, v) = server.post("/api/check", &body);
    assert_eq!(status, 200, "{v}");
    let lines = v["lines"].as_array().unwrap();
    assert_eq!(lines.len(), 3001);
    assert_eq!(lines[0]["canonical"], "C<RD>L");
    assert_eq!(lines[3000]["error"]["message"], "unclosed `<`");
    let direct = lpe_explore::answer("check", body.as_bytes());
    assert_eq!(
        v,
        serde_json::from_str::<serde_json::Value>(&direct.json).unwrap()
    );
    // Every view answers through the server as the API does.
    let body = r#"{"aovs": "d = C<RD>.*L\ns = C<RS>.*L", "path": "C RD1 L", "left": "d", "right": "C<RD>L"}"#;
    for view in ["check", "graph", "paths", "partition", "explain", "equiv"] {
        let (status, v) = server.post(&format!("/api/{view}"), body);
        assert_eq!(status, 200, "{view}: {v}");
        let direct = lpe_explore::answer(view, body.as_bytes());
        let direct: serde_json::Value = serde_json::from_str(&direct.json).unwrap();
        assert_eq!(v, direct, "{view}");
    }
}

/// Each malformed or misdirected request gets its 4xx and a message saying what to
/// do. Faults caught: the Host check skipped (a page reaching the server through
/// another name that resolves to 127.0.0.1 would be answered); GET on the API answered.
#[test]
fn bad_requests_get_a_4xx_with_a_message() {
    let server = Server::start();
    let host = format!("127.0.0.1:{}", server.port);
    let error = |body: &str| -> String {
        let v: serde_json::Value = serde_json::from_str(body).unwrap();
        v["error"].as_str().unwrap().to_string()
    };
    let (status, _, body) = server.get("/nope");
    assert_eq!(
        (status, error(&body).contains("no page at /nope")),
        (404, true),
        "{body}"
    );
    let (status, _, body) = server.get("/api/check");
    assert_eq!(
        (status, error(&body).contains("POST /api/VIEW")),
        (405, true),
        "{body}"
    );
    let (status, _, body) = server.raw(b"NONSENSE\r\n\r\n");
    assert_eq!(
        (status, error(&body).contains("malformed request")),
        (400, true),
        "{body}"
    );
    let (status, _, body) = server.raw(b"GET / HTTP/1.1\r\nHost: attacker.example:80\r\n\r\n");
    assert_eq!(
        (status, error(&body).contains("is not this server")),
        (403, true),
        "{body}"
    );
    let (status, _, body) = server.raw(
        format!("POST /api/check HTTP/1.1\r\nHost: {host}\r\nOrigin: http://elsewhere.example\r\nContent-Length: 2\r\n\r\n{{}}")
            .as_bytes(),
    );
    assert_eq!(
        (status, error(&body).contains("may not use this server")),
        (403, true),
        "{body}"
    );
    let (status, _, body) = server.raw(
        format!("POST /api/check HTTP/1.1\r\nHost: {host}\r\nTransfer-Encoding: chunked\r\n\r\n0\r\n\r\n").as_bytes(),
    );
    assert_eq!(
        (status, error(&body).contains("Content-Length")),
        (411, true),
        "{body}"
    );
    // The API's own refusals come through with their status.
    let (status, v) = server.post("/api/nope", r#"{"aovs": ""}"#);
    assert_eq!(status, 404, "{v}");
    assert!(
        v["error"].as_str().unwrap().contains("no view `nope`"),
        "{v}"
    );
    let (status, v) = server.post("/api/check", "{");
    assert_eq!(status, 400, "{v}");
    // The page's own origin is welcome.
    let (status, _, _) = server.raw(
        format!("POST /api/check HTTP/1.1\r\nHost: {host}\r\nOrigin: http://{host}\r\nContent-Length: 12\r\n\r\n{{\"aovs\": \"\"}}")
            .as_bytes(),
    );
    assert_eq!(status, 200);
}

/// A body over the 1 MiB limit is refused with 413 and the sizes, after the whole body
/// was sent: the client reads the answer, not a reset connection. Fault caught: the
/// refusal closing the socket with the body unread (the client's write of the body then
/// fails: the connection is reset).
#[test]
fn an_oversized_body_is_refused_with_413() {
    let server = Server::start();
    let body = vec![b'x'; 16 << 20];
    let mut raw = format!(
        "POST /api/check HTTP/1.1\r\nHost: 127.0.0.1:{}\r\nContent-Length: {}\r\n\r\n",
        server.port,
        body.len()
    )
    .into_bytes();
    raw.extend_from_slice(&body);
    let (status, _, answer) = server.raw(&raw);
    assert_eq!(status, 413, "{answer}");
    assert!(
        answer.contains("16777216 bytes is over the limit of 1048576 bytes"),
        "{answer}"
    );
    // And the server goes on.
    assert_eq!(server.get("/").0, 200);
}

/// 50 clients at once each get 200 or 503, never a dropped connection, and the server
/// still answers after. (A refusal that drops the connection instead of answering 503
/// is `clients_past_the_queue_get_503_and_the_server_goes_on`'s fault, in
/// `cli/src/cmd/serve/http.rs`, where the queue is small enough to fill for sure.)
#[test]
fn fifty_concurrent_clients_are_served_or_refused() {
    let server = Server::start();
    let port = server.port;
    let body =
        r#"{"aovs": "diffuse = C<RD>.*L\nspecular = C<RS>.*L\nrest = C.*[<L.>O] - C<R.>.*L"}"#;
    let clients: Vec<_> = (0..50)
        .map(|_| {
            std::thread::spawn(move || {
                let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
                let raw = format!(
                    "POST /api/check HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Length: {}\r\n\r\n{body}",
                    body.len()
                );
                s.write_all(raw.as_bytes()).unwrap();
                let mut out = String::new();
                s.read_to_string(&mut out).unwrap();
                out.get(9..12).unwrap_or("none").to_string()
            })
        })
        .collect();
    let statuses: Vec<String> = clients.into_iter().map(|c| c.join().unwrap()).collect();
    let served = statuses.iter().filter(|s| *s == "200").count();
    assert!(
        statuses.iter().all(|s| s == "200" || s == "503"),
        "{statuses:?}"
    );
    assert!(served > 0, "{statuses:?}");
    assert_eq!(server.get("/").0, 200);
}

/// A port another program holds is bad input (exit 2) with a message naming it and
/// the way out.
#[test]
fn a_port_in_use_is_exit_2() {
    let holder = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = holder.local_addr().unwrap().port();
    let out = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
        .args(["serve", "--port", &port.to_string()])
        .output()
        .unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains(&format!("cannot listen on 127.0.0.1:{port}")),
        "{err}"
    );
    assert!(err.contains("--port 0"), "{err}");
    drop(holder);
}

/// An unknown renderer, or a dialect that contradicts the renderer's, is exit 2.
#[test]
fn a_bad_start_language_is_exit_2() {
    for (args, says) in [
        (&["--renderer", "karm"][..], "karma"),
        (
            &["--renderer", "karma", "--dialect", "renderman"][..],
            "contradicts",
        ),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
            .args(["serve", "--port", "0"])
            .args(args)
            .output()
            .unwrap();
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains(says), "{err}");
    }
}

/// Ctrl-C (SIGINT) stops the server: the process ends and the port is free again.
#[test]
fn ctrl_c_stops_the_server() {
    let mut server = Server::start();
    assert_eq!(server.get("/").0, 200);
    let sent = Command::new("kill")
        .args(["-INT", &server.child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(10);
    while server.child.try_wait().unwrap().is_none() {
        assert!(
            std::time::Instant::now() < deadline,
            "still running after SIGINT"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(TcpListener::bind(("127.0.0.1", server.port)).is_ok());
}
