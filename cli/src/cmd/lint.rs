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
//! error: their macros and lobe mappings are RenderMan's). Without `--dialect` the run
//! reads RenderMan's, and a stage that declares no dialect is also read as OSL's to
//! report the AOVs whose two readings differ (`ambiguous_dialect`); naming the dialect
//! says which renderer the files are for, and that check is not run.
//! Exit 0 clean, 1 findings, 2 an unreadable file or bad argument, 3 a witness the
//! reference matcher refused. docs/lint.md has the JSON schema.
//!
//! The reading, the checks and both reports are [`lpe_lint::check`]'s (one run:
//! [`lpe_lint::check::run`]); this module
//! parses the arguments, prints and gives the exit code.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use lpe::with_dialect;
use lpe_lint::check::renderer;
use lpe_lint::check::run::{self, Request, RunError};
use lpe_lint::read::{self, Limits};

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
    /// The expression language every file's AOVs are read in: `--dialect renderman` or
    /// `osl` (default `renderman`, with undeclared stages also checked for readings that
    /// differ between the two), or a renderer's (`--renderer`, `--profile`), whose rules
    /// lint then checks too.
    #[command(flatten)]
    pub lang: DialectArgs,
}

/// Runs `lpe-check lint`.
pub fn run(args: Args) -> ExitCode {
    let files = Files {
        files: &args.files,
        ini: args.ini.as_deref(),
        partitions: &args.partition,
        universe: args.universe.as_deref(),
    };
    let linted = match lint(&files, &args.lang, &mut |p| {
        read::read_file(p, &Limits::default())
    }) {
        Ok(l) => l,
        Err(Failed::Disagreement(e)) => {
            eprintln!("{e}");
            return ExitCode::from(DISAGREE);
        }
        Err(Failed::BadInput(e)) => return bad_input(format!("error: {e}")),
    };
    match args.format {
        OutputFormat::Text => {
            if let (Some(p), Some(how)) = (&linted.profile, &linted.named_by) {
                eprintln!("note: reading as {} ({}), named by {how}", p.title, p.name);
            }
            for e in &linted.read_errors {
                eprintln!("error: {e}");
            }
            print!("{}", linted.text);
        }
        OutputFormat::Json => println!(
            "{}",
            serde_json::to_string_pretty(&linted.json).expect("JSON values serialize")
        ),
    }
    let code = if linted.read_errors.is_empty() {
        u8::from(!linted.outcome.findings.is_empty())
    } else {
        2
    };
    ExitCode::from(code)
}

/// The files of one lint run and what to check across them.
pub struct Files<'a> {
    /// USD, RIB and ini files, in order.
    pub files: &'a [PathBuf],
    /// `--ini`.
    pub ini: Option<&'a Path>,
    /// `--partition` lists.
    pub partitions: &'a [String],
    /// `--universe`.
    pub universe: Option<&'a str>,
}

/// One lint run's result, as `lint` prints it and `report` shows it.
pub struct Linted {
    /// The dialect the files were read in.
    pub dialect: lpe::DialectName,
    /// The renderer's profile the files were read under, if any.
    pub profile: Option<lpe_profile::Profile>,
    /// How the stages named that profile, when the arguments did not.
    pub named_by: Option<String>,
    /// The JSON report (schema `lpe-lint/1`).
    pub json: serde_json::Value,
    /// The text report.
    pub text: String,
    /// The errors of the files that could not be read.
    pub read_errors: Vec<String>,
    /// The AOVs, partitions and findings, each expression printed in its canonical form.
    pub outcome: lpe_lint::check::Outcome<String>,
}

/// Why a lint run checked nothing.
pub enum Failed {
    /// A bad argument or configuration (exit 2).
    BadInput(String),
    /// A witness the reference matcher refused (exit 3).
    Disagreement(String),
}

/// Lints `files` read by `read_other` (ini files apart): the files are read first, so
/// that without `--renderer`, `--profile` or `--dialect` the renderer the stages name
/// (`lpe:renderer`, or one renderer's RenderSettings attributes) chooses the dialect and
/// adds its rules.
pub fn lint(
    files: &Files<'_>,
    lang: &DialectArgs,
    read_other: &mut dyn FnMut(&Path) -> Result<lpe_lint::Document, lpe_lint::ReadError>,
) -> Result<Linted, Failed> {
    let given = lang
        .renderer_profile()
        .map_err(|e| Failed::BadInput(e.to_string()))?;
    let mut req = Request {
        files: files.files,
        ini: files.ini,
        partitions: files.partitions,
        universe: files.universe,
        dialect_given: lang.dialect.is_some() || given.is_some(),
        profile: None,
    };
    let read = run::read_by(&req, read_other);
    let mut named_by = None;
    let profile = match given {
        Some(p) => Some(p),
        None if lang.dialect.is_none() => match renderer::named_by(&read.docs) {
            Ok(Some((p, how))) => {
                named_by = Some(how.to_string());
                req.dialect_given = true;
                Some(p.clone())
            }
            Ok(None) => None,
            Err(e) => return Err(Failed::BadInput(e.to_string())),
        },
        None => None,
    };
    req.profile = profile.as_ref();
    let dialect = profile
        .as_ref()
        .map_or(lang.dialect(), lpe_profile::Profile::dialect);
    let out = with_dialect!(dialect, D => lint_in::<D>(lang, &req, read))?;
    Ok(Linted {
        dialect,
        named_by,
        json: out.json,
        text: out.text,
        read_errors: out.read_errors,
        outcome: out.outcome,
        profile,
    })
}

/// The run's reports, without the dialect's expression type.
struct Reports {
    json: serde_json::Value,
    text: String,
    read_errors: Vec<String>,
    outcome: lpe_lint::check::Outcome<String>,
}

fn lint_in<D: CliDialect>(
    lang: &DialectArgs,
    req: &Request<'_>,
    read: run::Inputs,
) -> Result<Reports, Failed> {
    let registration = |ini: Option<&Path>| lang.registration_under::<D>(ini, req.profile);
    match run::check::<D, _>(req, read, registration) {
        Ok(out) => Ok(Reports {
            json: out.json(),
            text: out.text(),
            read_errors: out.read_errors().map(str::to_string).collect(),
            outcome: lpe_lint::check::Outcome {
                aovs: out
                    .outcome
                    .aovs
                    .into_iter()
                    .map(|a| lpe_lint::check::Linted {
                        file: a.file,
                        decl: a.decl,
                        lpe: a.lpe.map(|e| e.to_string()),
                    })
                    .collect(),
                partitions: out.outcome.partitions,
                findings: out.outcome.findings,
            },
        }),
        Err(RunError::Disagreement(e)) => Err(Failed::Disagreement(e.to_string())),
        Err(e) => Err(Failed::BadInput(e.to_string())),
    }
}
