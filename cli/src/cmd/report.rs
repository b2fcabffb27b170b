//! `lpe-check report FILE... --html OUT.html`: one self-contained HTML page a person can
//! read, with every file's AOVs, its lint findings and the explorer's views of its AOVs
//! (the errors and canonical forms, the automaton drawn, the shortest paths and near
//! misses, the partition), answered now and written into the page as data: the page
//! opens offline and asks nothing of any server.
//!
//! The files are those `lpe-check lint` reads (USD, RIB, `rendermn.ini`; ini files
//! configure the others' parsing, as for lint) and AOV lists: a file of any other
//! extension is read as the explorer's list, one `name = expression` per line. Each file
//! is linted on its own (with the ini files), read as lint reads it: in the dialect or
//! renderer the arguments or the stage name. A file that cannot be read is an error
//! naming it (exit 2) and no page is written; findings are shown, not an exit code
//! (`lpe-check lint` gates, the report is for people).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use lpe_lint::check::Finding;
use lpe_lint::read::{self, Limits};
use lpe_lint::{AovDecl, Document, Format, Location, ReadError};
use serde_json::{json, Value};

use super::lint::{self, Failed, Files, Linted};
use super::serve::page;
use crate::input::{bad_input, DialectArgs};
use crate::witness::DISAGREE;

/// The views a report shows for each file, in the order the API names them.
const VIEWS: [&str; 4] = ["check", "graph", "paths", "partition"];

/// Arguments of `lpe-check report`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// USD (`.usda`/`.usdc`/`.usd`/`.usdz`), RIB, `.ini` files, and AOV lists (any other
    /// extension: one `name = expression` per line).
    #[arg(required = true)]
    pub files: Vec<PathBuf>,
    /// Where to write the page.
    #[arg(long, value_name = "OUT.html")]
    pub html: PathBuf,
    /// Read every file's AOVs as this renderer does (default: as the stage names, else
    /// RenderMan's dialect).
    #[arg(long, value_name = "NAME")]
    pub renderer: Option<String>,
    /// Read every file's AOVs in this dialect: `renderman` or `osl`.
    #[arg(long)]
    pub dialect: Option<lpe::DialectName>,
}

/// Runs `lpe-check report`.
pub fn run(args: Args) -> ExitCode {
    let lang = DialectArgs {
        dialect: args.dialect,
        renderer: args.renderer.clone(),
        ..DialectArgs::default()
    };
    let inis: Vec<PathBuf> = args
        .files
        .iter()
        .filter(|f| read::format_of(f) == Some(Format::Ini))
        .cloned()
        .collect();
    let mut entries = Vec::new();
    for file in &args.files {
        match entry(file, &inis, &lang) {
            Ok(e) => entries.push(e),
            Err(Failed::BadInput(e)) => return bad_input(format!("error: {e}")),
            Err(Failed::Disagreement(e)) => {
                eprintln!("{e}");
                return ExitCode::from(DISAGREE);
            }
        }
    }
    let html = page::report(Value::Array(entries));
    if let Err(e) = std::fs::write(&args.html, html) {
        return bad_input(format!("error: cannot write {}: {e}", args.html.display()));
    }
    println!(
        "wrote {} ({} file{})",
        args.html.display(),
        args.files.len(),
        if args.files.len() == 1 { "" } else { "s" }
    );
    ExitCode::SUCCESS
}

/// One file's part of the page: linted (with the ini files, unless it is one), then its
/// AOVs asked of every view.
fn entry(file: &Path, inis: &[PathBuf], lang: &DialectArgs) -> Result<Value, Failed> {
    let mut files: Vec<PathBuf> = inis.iter().filter(|i| *i != file).cloned().collect();
    files.push(file.to_path_buf());
    let linted = lint::lint(
        &Files {
            files: &files,
            ini: None,
            partitions: &[],
            universe: None,
        },
        lang,
        &mut read_any,
    )?;
    if let Some(e) = linted.read_errors.first() {
        return Err(Failed::BadInput(e.clone()));
    }
    let name = file.display().to_string();
    let aovs: Vec<&lpe_lint::check::Linted<String>> = linted
        .outcome
        .aovs
        .iter()
        .filter(|a| a.file == name)
        .collect();
    let findings: Vec<Value> = linted
        .outcome
        .findings
        .iter()
        .filter(|f| f.file == name)
        .map(finding)
        .collect();
    let line =
        |a: &lpe_lint::check::Linted<String>, text: &str| format!("{} = {text}\n", a.decl.name);
    // The check view reads every AOV: an AOV list as written, so that its line numbers
    // are the file's; else lint's canonical form where the AOV parsed (the ini files'
    // macros expanded and a renderer's `lpe:` mark read, which the views, given no ini,
    // could not do), the source as written where it did not, so its error shows.
    let every = if read::format_of(file).is_none() {
        std::fs::read_to_string(file).map_err(|e| Failed::BadInput(format!("{name}: {e}")))?
    } else {
        aovs.iter()
            .map(|a| line(a, a.lpe.as_deref().unwrap_or(&a.decl.source)))
            .collect()
    };
    // The other views need the whole list to parse: they get the AOVs that do, so a
    // file with one bad line still has its drawing and partition.
    let parsed: String = aovs
        .iter()
        .filter_map(|a| a.lpe.as_deref().map(|e| line(a, e)))
        .collect();
    let parsed_count = aovs.iter().filter(|a| a.lpe.is_some()).count();
    Ok(json!({
        "file": name,
        "reading": reading(&linted),
        "aovs": aovs.iter().map(|a| json!({
            "name": a.decl.name,
            "source": a.decl.source,
            "location": a.decl.location.to_string(),
        })).collect::<Vec<_>>(),
        "findings": findings,
        "parsed": parsed_count,
        "views": views(&every, &parsed, &linted),
    }))
}

/// The views, read as `linted` read the file: `check` of `every` line, the others of
/// the `parsed` ones; each view's reply, or `{"error": ...}` when it gave none.
fn views(every: &str, parsed: &str, linted: &Linted) -> Value {
    let renderer = linted
        .profile
        .as_ref()
        .filter(|p| lpe_profile::by_name(&p.name).is_ok())
        .map(|p| p.name.clone());
    let body = |aovs: &str| {
        json!({ "aovs": aovs, "dialect": linted.dialect.name(), "renderer": renderer }).to_string()
    };
    let mut out = serde_json::Map::new();
    for view in VIEWS {
        let list = if view == "check" { every } else { parsed };
        let reply = lpe_explore::answer(view, body(list).as_bytes());
        let value = serde_json::from_str(&reply.json).unwrap_or_else(
            |e| json!({ "error": format!("the {view} view's reply is no JSON: {e}") }),
        );
        out.insert(view.to_string(), value);
    }
    Value::Object(out)
}

/// How the file was read, in a sentence.
fn reading(linted: &Linted) -> String {
    match (&linted.profile, &linted.named_by) {
        (Some(p), Some(how)) => format!("Read as {} does ({}), named by {how}.", p.title, p.name),
        (Some(p), None) => format!("Read as {} does ({}).", p.title, p.name),
        (None, _) => format!("Read in the {} dialect.", linted.dialect.name()),
    }
}

/// A finding as the page shows it: the caret line drawn under its expression.
fn finding(f: &Finding) -> Value {
    json!({
        "kind": f.kind.name(),
        "subject": f.subject,
        "location": f.location.to_string(),
        "message": f.message,
        "help": f.help,
        "caret": f.caret.as_ref().map(|(source, span)| lpe_explore::lines::caret(source, span.clone()).0),
    })
}

/// Reads a file lint reads, or else an AOV list.
fn read_any(path: &Path) -> Result<Document, ReadError> {
    if read::format_of(path).is_some() {
        return read::read_file(path, &Limits::default());
    }
    read_list(path)
}

/// An AOV list file: its lines as the explorer reads them, each AOV at its line and
/// column. Lint reads it as it reads a stage that names no dialect.
fn read_list(path: &Path) -> Result<Document, ReadError> {
    let io = |source| ReadError::Io {
        path: path.to_path_buf(),
        source,
    };
    let bytes = std::fs::metadata(path).map_err(io)?.len();
    let limit = lpe_explore::MAX_BODY_BYTES as u64;
    if bytes > limit {
        return Err(ReadError::TooLarge {
            path: path.to_path_buf(),
            bytes,
            limit,
            what: "AOV list",
        });
    }
    let data = std::fs::read(path).map_err(io)?;
    let text = String::from_utf8(data).map_err(|e| ReadError::NotText {
        path: path.to_path_buf(),
        offset: e.utf8_error().valid_up_to() as u64,
    })?;
    if let Some(offset) = text.find('\0') {
        return Err(ReadError::NotText {
            path: path.to_path_buf(),
            offset: offset as u64,
        });
    }
    let mut doc = Document::new(path, Format::Usd);
    doc.aovs = lpe_explore::lines::read(&text)
        .into_iter()
        .map(|l| AovDecl {
            name: l.name,
            source: l.source,
            location: Location::Line {
                line: l.number,
                column: l.offset + 1,
            },
            source_type: None,
        })
        .collect();
    Ok(doc)
}
