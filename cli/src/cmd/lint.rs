//! `lpe-check lint FILE...`: check the LPE AOVs a pipeline declares in USD stages
//! (`.usda`/`.usdc`/`.usdz`), RIB files and `rendermn.ini` before anything renders.
//!
//! Per AOV, with file and line (or prim path) and a caret: parse errors, AOVs that can
//! match no path (and why), AOVs equivalent to an earlier one, group labels no light or
//! object of the stage carries, numbered lobes no lobe mapping feeds; per declared
//! partition (`lpe:partition` in USD, `# lpe:partition` comments in RIB and ini, or
//! `--partition`), each overlap, the gap and stray paths with shortest witnesses and the
//! remainder AOV. ini files (positional or `--ini`) configure the parsing of every file.
//! `--dialect osl [--register …]` reads every AOV as OSL's dialect (ini files are then an
//! error: their macros and lobe mappings are RenderMan's).
//! Exit 0 clean, 1 findings, 2 an unreadable file or bad argument, 3 a witness the
//! reference matcher refused. docs/lint.md has the JSON schema.
//!
//! The reading, the checks and both reports are [`lpe_lint::check`]'s; this module
//! parses the arguments, prints and gives the exit code.

use std::path::PathBuf;
use std::process::ExitCode;

use lpe::with_dialect;
use lpe_lint::check::dialect::Lint;
use lpe_lint::check::{self, inputs, json, text};
use lpe_lint::read::Limits;

use crate::dialect::CliDialect;
use crate::input::{bad_input, DialectArgs};
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
    /// The universe partitions split (default `C.*[<L.>O]`, OSL: `C<[RT][DGS]>*[LO]`).
    #[arg(long)]
    pub universe: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = OutputFormat::Text)]
    pub format: OutputFormat,
    /// `--dialect` (every file's AOVs are read in it) and `--register`.
    #[command(flatten)]
    pub lang: DialectArgs,
}

/// Runs `lpe-check lint`.
pub fn run(args: Args) -> ExitCode {
    with_dialect!(args.lang.dialect, D => run_in::<D>(&args))
}

fn run_in<D: CliDialect>(args: &Args) -> ExitCode {
    let limits = Limits::default();
    let (inis, others) = inputs::split(args.ini.as_deref(), &args.files);
    // A dialect that reads ini files reads them with the others; for any other an ini
    // file (RenderMan macros, lobe mappings and partitions) is an error.
    let ini = if D::READS_INI {
        None
    } else {
        inis.first().copied()
    };
    let registration = match args.lang.registration::<D>(ini) {
        Ok(r) => r,
        Err(e) => {
            let file = ini.map_or(String::new(), |p| format!("{}: ", p.display()));
            return bad_input(format!("error: {file}{e}"));
        }
    };
    let read = inputs::read_all(&inis, &others, &limits);
    let (registration, lobes) = D::configured(registration, &read.config);
    let dialect = Lint::<D> {
        registration: &registration,
        lobes: &lobes,
    };
    let universe = args.universe.as_deref().unwrap_or(D::DEFAULT_UNIVERSE);
    let universe = match dialect.parse(universe) {
        Ok(u) => u,
        Err(e) => return bad_input(format!("error: --universe: {}", e.message)),
    };
    let extra = inputs::command_line_partitions(&args.partition);
    let out = match check::lint(&read.docs, &dialect, &universe, &extra) {
        Ok(out) => out,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(DISAGREE);
        }
    };
    match args.format {
        OutputFormat::Text => {
            for s in &read.statuses {
                if let Some(e) = &s.error {
                    eprintln!("error: {e}");
                }
            }
            print!("{}", text::render(&out));
        }
        OutputFormat::Json => println!(
            "{}",
            serde_json::to_string_pretty(&json::render(&out, &read.statuses))
                .expect("JSON values serialize")
        ),
    }
    let code = if read.statuses.iter().any(|s| s.error.is_some()) {
        2
    } else {
        u8::from(!out.findings.is_empty())
    };
    ExitCode::from(code)
}
