//! `lpe-check serve [--port N] [--renderer NAME] [--dialect D]`: the LPE explorer, a
//! local web page over `lpe_explore`'s JSON API.
//!
//! Binds 127.0.0.1 only and prints the page's URL (`--port 0` takes a free port); runs
//! until Ctrl-C. `GET /` is the page ([`page`], one self-contained HTML file, started in
//! the dialect or renderer the arguments name); `POST /api/VIEW` hands the body to
//! `lpe_explore::answer` and returns its JSON. Requests from another host name or
//! another page's origin are refused (403), so a web page elsewhere cannot reach the
//! server through a name that resolves to 127.0.0.1. The connections, the worker pool
//! and the request limits are [`http`]'s. A port in use, an unknown renderer or a
//! dialect contradicting the renderer's are bad input (exit 2).

pub mod http;
pub mod page;

use std::net::TcpListener;
use std::process::ExitCode;

use crate::input::bad_input;
use http::{Limits, Request, Response};

/// Arguments of `lpe-check serve`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The port on 127.0.0.1; 0 takes a free one (the URL printed at start says which).
    #[arg(long, default_value_t = 7890)]
    pub port: u16,
    /// The renderer whose reading the page starts in (docs/profiles.md).
    #[arg(long, value_name = "NAME")]
    pub renderer: Option<String>,
    /// The dialect the page starts in: `renderman` (the default) or `osl`.
    #[arg(long)]
    pub dialect: Option<lpe::DialectName>,
}

/// Runs `lpe-check serve` until the process is stopped.
pub fn run(args: Args) -> ExitCode {
    let start = match page::Start::new(args.dialect, args.renderer.as_deref()) {
        Ok(s) => s,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let listener = match TcpListener::bind(("127.0.0.1", args.port)) {
        Ok(l) => l,
        Err(e) => {
            let hint = if e.kind() == std::io::ErrorKind::AddrInUse {
                " (another program has it: choose another --port, or --port 0 for a free one)"
            } else {
                ""
            };
            return bad_input(format!(
                "error: cannot listen on 127.0.0.1:{}: {e}{hint}",
                args.port
            ));
        }
    };
    let port = match listener.local_addr() {
        Ok(a) => a.port(),
        Err(e) => return bad_input(format!("error: the listening socket has no address: {e}")),
    };
    let html = page::serving(&start);
    println!("lpe-check serve: the LPE explorer is at http://127.0.0.1:{port}/ (Ctrl-C stops it)");
    // The tests and scripts read the URL from a pipe: it must not wait in a buffer.
    let _ = std::io::Write::flush(&mut std::io::stdout());
    let limits = Limits {
        max_body: lpe_explore::MAX_BODY_BYTES,
        ..Limits::default()
    };
    match http::serve(listener, &limits, move |r| route(r, &html, port)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: serving: {e}");
            ExitCode::from(101)
        }
    }
}

/// The page on `GET /`, the API on `POST /api/VIEW`.
fn route(request: &Request, html: &str, port: u16) -> Response {
    if let Err(refusal) = same_origin(request, port) {
        return Response::error(403, &refusal);
    }
    let api_view = request.path.strip_prefix("/api/");
    match (request.method.as_str(), request.path.as_str(), api_view) {
        ("GET", "/", _) => {
            let mut r = Response::html(html.to_string());
            // The page may reach this server and nothing else.
            r.headers.push((
                "Content-Security-Policy",
                page::CONTENT_SECURITY_POLICY.into(),
            ));
            r
        }
        ("POST", _, Some(view)) => {
            let reply = lpe_explore::answer(view, &request.body);
            Response::json(reply.status, reply.json)
        }
        (_, "/", _) | (_, _, Some(_)) => Response::error(
            405,
            &format!(
                "{} {}: the page is `GET /`, the API `POST /api/VIEW`",
                request.method, request.path
            ),
        ),
        _ => Response::error(
            404,
            &format!(
                "no page at {}: the page is `GET /`, the API `POST /api/VIEW`",
                request.path
            ),
        ),
    }
}

/// Refuses a request whose `Host` is not this server's loopback address, or that a page
/// of another origin sent.
fn same_origin(request: &Request, port: u16) -> Result<(), String> {
    let hosts = [format!("127.0.0.1:{port}"), format!("localhost:{port}")];
    match request.header("host") {
        Some(h) if hosts.iter().any(|ok| ok == h) => {}
        Some(h) => {
            return Err(format!(
                "Host `{h}` is not this server ({}): it answers only on its loopback address",
                hosts[0]
            ))
        }
        None => return Err("the request has no Host header".into()),
    }
    match request.header("origin") {
        None => Ok(()),
        Some(o) if hosts.iter().any(|ok| o == format!("http://{ok}")) => Ok(()),
        Some(o) => Err(format!("a page of origin `{o}` may not use this server")),
    }
}
