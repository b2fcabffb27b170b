//! `lpe-check lint FILE...`: check the LPE AOVs a pipeline declares in USD stages
//! (`.usda`/`.usdc`/`.usdz`), RIB files and `rendermn.ini` before anything renders.
//!
//! Per AOV, with file and line (or prim path) and a caret: parse errors, AOVs that can
//! match no path (and why), AOVs equivalent to an earlier one, group labels no light or
//! object of the stage carries, numbered lobes no lobe mapping feeds; per declared
//! partition (`lpe:partition` in USD, `# lpe:partition` comments in RIB and ini, or
//! `--partition`), each overlap, the gap and stray paths with shortest witnesses and the
//! remainder AOV. ini files (positional or `--ini`) configure the parsing of every file.
//! Exit 0 clean, 1 findings, 2 an unreadable file or bad argument, 3 a witness the
//! reference matcher refused. docs/lint.md has the JSON schema.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use lpe::analysis;
use lpe_lint::read::{self, Limits};
use lpe_lint::{Document, Format, Location, PartitionDecl};

use crate::input::{bad_input, Dialect};
use crate::lint::json::FileStatus;
use crate::lint::{self, json, text};
use crate::witness::DISAGREE;

/// Output format.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputFormat {
    /// Human-readable blocks with carets.
    Text,
    /// One JSON document (schema `lpe-lint/1`, docs/lint.md).
    Json,
}

/// Arguments of `lpe-check lint`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// `.usda`/`.usdc`/`.usd`/`.usdz`, `.rib` and `.ini` files.
    #[arg(required = true)]
    pub files: Vec<PathBuf>,
    /// A rendermn.ini-style file with user macros and lobe mappings (like a positional
    /// `.ini`).
    #[arg(long)]
    pub ini: Option<PathBuf>,
    /// AOV names that must partition the universe, comma-separated (repeatable).
    #[arg(long, value_name = "NAME,NAME,...")]
    pub partition: Vec<String>,
    /// The universe partitions split.
    #[arg(long, default_value = analysis::DEFAULT_UNIVERSE)]
    pub universe: String,
    /// Output format.
    #[arg(long, value_enum, default_value_t = OutputFormat::Text)]
    pub format: OutputFormat,
    /// Expression dialect.
    #[arg(long, value_enum, default_value_t = Dialect::Renderman)]
    pub dialect: Dialect,
}

/// Runs `lpe-check lint`.
pub fn run(args: Args) -> ExitCode {
    if let Err(e) = args.dialect.check_available() {
        return bad_input(format!("error: {e}"));
    }
    let limits = Limits::default();
    let mut config = lpe::Config::default();
    let mut statuses = Vec::new();
    let mut docs = Vec::new();
    let (inis, others): (Vec<&Path>, Vec<&Path>) = args
        .ini
        .iter()
        .map(PathBuf::as_path)
        .chain(args.files.iter().map(PathBuf::as_path))
        .partition(|p| read::format_of(p) == Some(Format::Ini));
    for path in inis {
        let read = read::ini::read_into(path, &limits, &mut config);
        record(path, read, &mut statuses, &mut docs);
    }
    for path in others {
        record(
            path,
            read::read_file(path, &limits),
            &mut statuses,
            &mut docs,
        );
    }
    let parser = config.parser();
    let universe = match parser.parse(&args.universe) {
        Ok(u) => u,
        Err(e) => return bad_input(format!("error: --universe: {e}")),
    };
    let extra: Vec<PartitionDecl> = args
        .partition
        .iter()
        .enumerate()
        .map(|(i, list)| PartitionDecl {
            name: format!("--partition #{}", i + 1),
            members: lpe_lint::decl::split_members(list),
            location: Location::Line { line: 0, column: 0 },
        })
        .collect();
    let out = match lint::lint(&docs, &parser, &config.lobes, &universe, &extra) {
        Ok(out) => out,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(DISAGREE);
        }
    };
    match args.format {
        OutputFormat::Text => {
            for s in &statuses {
                if let Some(e) = &s.error {
                    eprintln!("error: {e}");
                }
            }
            print!("{}", text::render(&out));
        }
        OutputFormat::Json => println!(
            "{}",
            serde_json::to_string_pretty(&json::render(&out, &statuses))
                .expect("JSON values serialize")
        ),
    }
    let code = if statuses.iter().any(|s| s.error.is_some()) {
        2
    } else {
        u8::from(!out.findings.is_empty())
    };
    ExitCode::from(code)
}

fn record(
    path: &Path,
    read: Result<Document, lpe_lint::ReadError>,
    statuses: &mut Vec<FileStatus>,
    docs: &mut Vec<Document>,
) {
    statuses.push(FileStatus {
        file: path.display().to_string(),
        format: read::format_of(path).map(Format::name),
        error: read.as_ref().err().map(ToString::to_string),
    });
    if let Ok(doc) = read {
        docs.push(doc);
    }
}
