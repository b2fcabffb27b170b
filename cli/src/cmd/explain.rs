//! `lpe-check explain PATH`: which AOVs a path lands in, and how it got there.
//!
//! AOVs come from `--aov NAME=EXPR`, `--display FILE.rib`, `--usd FILE.usda` and
//! `--from FILE` (anything `lint` reads), in that order. Prints one row per vertex: the
//! vertex, its class in the compiled set, the set's state after it (numbered in the order
//! the path reaches them: `s0` the start, `dead` once no AOV can match) and the AOVs that
//! can still match some continuation; then the AOVs the whole
//! path lands in. A path landing nowhere also gets the longest prefix after which some
//! AOV could still match, and the AOV that stayed reachable longest (the closest miss).
//! Exit 0 when the path lands in some AOV, 1 when in none, 2 on bad input. With
//! `--dialect osl` the AOVs and the path are OSL's (`C,_ R,D L,_`).

use std::path::PathBuf;
use std::process::ExitCode;

use lpe::with_dialect;
use lpe_lint::explain::{explain, Explanation};
use lpe_lint::read::{self, Limits};
use lpe_lint::Document;

use crate::dialect::CliDialect;
use crate::input::{bad_input, DialectArgs};

/// Arguments of `lpe-check explain`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The path, e.g. "C RD2'floor' TS8 L'key'".
    pub path: String,
    /// An AOV `NAME=EXPR` (repeatable).
    #[arg(long = "aov", value_name = "NAME=EXPR")]
    pub aovs: Vec<String>,
    /// A RIB file: its `DisplayChannel` LPE channels.
    #[arg(long)]
    pub display: Option<PathBuf>,
    /// A USD stage: its LPE RenderVars.
    #[arg(long)]
    pub usd: Option<PathBuf>,
    /// Any file `lpe-check lint` reads.
    #[arg(long)]
    pub from: Option<PathBuf>,
    /// A rendermn.ini-style file with user macros and lobe mappings.
    #[arg(long)]
    pub ini: Option<PathBuf>,
    /// `--dialect` (the path is then an OSL path, `C,_ R,D L,_`) and `--register`.
    #[command(flatten)]
    pub lang: DialectArgs,
}

/// Runs `lpe-check explain`.
pub fn run(args: Args) -> ExitCode {
    match with_dialect!(args.lang.dialect(), D => run_in::<D>(&args)) {
        Ok(e) => {
            print!("{}", e.text);
            ExitCode::from(u8::from(e.landed.is_empty()))
        }
        Err(e) => bad_input(format!("error: {e}")),
    }
}

fn run_in<D: CliDialect>(args: &Args) -> Result<Explanation, String> {
    let registration = args
        .lang
        .registration::<D>(args.ini.as_deref())
        .map_err(|e| e.to_string())?;
    let path: D::Path = args
        .path
        .parse()
        .map_err(|e| D::path_error(&args.path, &e))?;
    let aovs = load(args, |src| {
        D::parse_arg(src, &registration).map_err(|e| D::show_error(src, &e))
    })?;
    explain::<D>(&aovs, &registration, &path).map_err(|e| e.to_string())
}

/// The AOVs of the arguments, each parsed by `parse` (its error with a caret).
fn load<E>(
    args: &Args,
    parse: impl Fn(&str) -> Result<E, String>,
) -> Result<Vec<(String, E)>, String> {
    let limits = Limits::default();
    let mut sources: Vec<(String, String, String)> = Vec::new();
    for a in &args.aovs {
        let (n, e) = a
            .split_once('=')
            .ok_or_else(|| format!("--aov `{a}`: expected NAME=EXPR"))?;
        sources.push((n.trim().into(), e.trim().into(), "--aov".into()));
    }
    let files = [
        (&args.display, read::rib::read as fn(&_, &_) -> _),
        (&args.usd, read::read_usd),
        (&args.from, read::read_file),
    ];
    for (file, reader) in files {
        if let Some(f) = file {
            let doc: Document = reader(f, &limits).map_err(|e| e.to_string())?;
            for a in doc.aovs {
                let at = format!("{}:{}", f.display(), a.location);
                sources.push((a.name, a.source, at));
            }
        }
    }
    if sources.is_empty() {
        return Err("no AOVs: give --aov, --display, --usd or --from".into());
    }
    sources
        .into_iter()
        .map(|(name, src, at)| {
            parse(&src)
                .map(|l| (name.clone(), l))
                .map_err(|e| format!("{at}: AOV `{name}`: {e}"))
        })
        .collect()
}
