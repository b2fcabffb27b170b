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

use std::path::PathBuf;
use std::process::ExitCode;

use lpe::with_dialect;
use lpe_lint::check::renderer;
use lpe_lint::check::run::{self, Request, RunError};

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

/// Runs `lpe-check lint`: the files are read first, so that without `--renderer`,
/// `--profile` or `--dialect` the renderer the stages name (`lpe:renderer`, or one
/// renderer's RenderSettings attributes) chooses the dialect and adds its rules.
pub fn run(args: Args) -> ExitCode {
    let given = match args.lang.renderer_profile() {
        Ok(p) => p,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let mut req = Request {
        files: &args.files,
        ini: args.ini.as_deref(),
        partitions: &args.partition,
        universe: args.universe.as_deref(),
        dialect_given: args.lang.dialect.is_some() || given.is_some(),
        profile: None,
    };
    let read = run::read(&req);
    let profile = match given {
        Some(p) => Some(p),
        None if args.lang.dialect.is_none() => match renderer::named_by(&read.docs) {
            Ok(Some((p, how))) => {
                if args.format == OutputFormat::Text {
                    eprintln!("note: reading as {} ({}), named by {how}", p.title, p.name);
                }
                req.dialect_given = true;
                Some(p.clone())
            }
            Ok(None) => None,
            Err(e) => return bad_input(format!("error: {e}")),
        },
        None => None,
    };
    req.profile = profile.as_ref();
    let dialect = profile
        .as_ref()
        .map_or(args.lang.dialect(), lpe_profile::Profile::dialect);
    with_dialect!(dialect, D => run_in::<D>(&args, &req, read))
}

fn run_in<D: CliDialect>(args: &Args, req: &Request<'_>, read: run::Inputs) -> ExitCode {
    let registration =
        |ini: Option<&std::path::Path>| args.lang.registration_under::<D>(ini, req.profile);
    let out = match run::check::<D, _>(req, read, registration) {
        Ok(out) => out,
        Err(RunError::Disagreement(e)) => {
            eprintln!("{e}");
            return ExitCode::from(DISAGREE);
        }
        Err(e) => return bad_input(format!("error: {e}")),
    };
    match args.format {
        OutputFormat::Text => {
            for e in out.read_errors() {
                eprintln!("error: {e}");
            }
            print!("{}", out.text());
        }
        OutputFormat::Json => println!(
            "{}",
            serde_json::to_string_pretty(&out.json()).expect("JSON values serialize")
        ),
    }
    let code = if out.read_errors().next().is_some() {
        2
    } else {
        u8::from(!out.outcome.findings.is_empty())
    };
    ExitCode::from(code)
}
