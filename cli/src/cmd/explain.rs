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

#[cfg(test)]
use lpe::renderman::{Lpe, Parser, RenderMan};
use lpe::{with_dialect, AovSet, Dialect, State};
use lpe_lint::read::{self, Limits};
use lpe_lint::Document;
use tabled::builder::Builder;
use tabled::settings::Style;

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
    match with_dialect!(args.lang.dialect, D => run_in::<D>(&args)) {
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
        (&args.usd, read::usd::read),
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

/// What `explain` found.
pub struct Explanation {
    /// Indices of the AOVs the whole path matches.
    pub landed: Vec<usize>,
    /// The printed report.
    pub text: String,
}

/// Steps `path` through the set of `aovs` (parsed under `registration`) and through each
/// AOV alone.
pub fn explain<D: Dialect>(
    aovs: &[(String, D::Lpe)],
    registration: &D::Registration,
    path: &D::Path,
) -> Result<Explanation, lpe::CompileError> {
    let opts = lpe::Options::default();
    let set = AovSet::<D>::compile_under(aovs, registration, &opts)?;
    let alone: Vec<AovSet<D>> = aovs
        .iter()
        .map(|a| AovSet::<D>::compile_under(std::slice::from_ref(a), registration, &opts))
        .collect::<Result<_, _>>()?;
    Ok(walk(aovs, &set, &alone, D::vertices(path)))
}

/// The report of one path, `vertices`, through `set` and through each AOV `alone` (the
/// joint state only says whether any AOV is still reachable). States are numbered in the
/// order this path first reaches them, the start `s0`; `dead` once no AOV can match.
fn walk<D: Dialect>(
    aovs: &[(String, D::Lpe)],
    set: &AovSet<D>,
    alone: &[AovSet<D>],
    vertices: &[D::Vertex],
) -> Explanation {
    let mut states: Vec<_> = alone.iter().map(|a| a.start()).collect();
    // How many vertices each AOV stayed reachable through.
    let mut alive_for = vec![0usize; aovs.len()];
    let mut s = set.start();
    let mut seen: Vec<State> = vec![s];
    let mut table = Builder::default();
    table.push_record(["#", "vertex", "class", "state", "still reachable"]);
    for (k, v) in vertices.iter().enumerate() {
        let class = set.classify(v);
        s = set.step_class(s, class);
        let mut reachable = Vec::new();
        for (i, a) in alone.iter().enumerate() {
            states[i] = a.step_class(states[i], a.classify(v));
            if !a.is_dead(states[i]) {
                alive_for[i] = k + 1;
                reachable.push(aovs[i].0.as_str());
            }
        }
        let reach = if reachable.is_empty() {
            "(none: dead)".to_string()
        } else {
            reachable.join(", ")
        };
        let state = if set.is_dead(s) {
            "dead".to_string()
        } else {
            let id = seen.iter().position(|&x| x == s).unwrap_or_else(|| {
                seen.push(s);
                seen.len() - 1
            });
            format!("s{id}")
        };
        table.push_record([
            (k + 1).to_string(),
            v.to_string(),
            class.index().to_string(),
            state,
            reach,
        ]);
    }
    let landed: Vec<usize> = set.matches(s).iter().collect();
    let shown: Vec<String> = vertices.iter().map(ToString::to_string).collect();
    let mut text = format!(
        "path {} against {} AOVs\n{}\n",
        shown.join(" "),
        aovs.len(),
        table.build().with(Style::markdown())
    );
    if landed.is_empty() {
        let longest = alive_for.iter().copied().max().unwrap_or(0);
        text.push_str("lands in no AOV\n");
        if longest == 0 {
            text.push_str("no AOV can match any path starting with its first vertex\n");
        } else {
            let closest = alive_for
                .iter()
                .position(|&n| n == longest)
                .expect("the maximum is in the list");
            let how = if longest == vertices.len() {
                "still reachable after the last vertex: the path ends too early for it".to_string()
            } else {
                format!("dead at vertex {}", longest + 1)
            };
            text.push_str(&format!(
                "longest live prefix: {} ({longest} of {} vertices)\nclosest AOV: {} ({how})\n",
                shown[..longest].join(" "),
                vertices.len(),
                aovs[closest].0
            ));
        }
    } else {
        let names: Vec<&str> = landed.iter().map(|&i| aovs[i].0.as_str()).collect();
        text.push_str(&format!("lands in: {}\n", names.join(", ")));
    }
    Explanation { landed, text }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn aovs(list: &[(&str, &str)]) -> Vec<(String, Lpe)> {
        list.iter()
            .map(|(n, e)| (n.to_string(), lpe::renderman::parse(e).unwrap()))
            .collect()
    }

    #[test]
    fn a_landing_path_names_its_aovs() {
        let a = aovs(&[
            ("direct", "C<RD>L"),
            ("indirect", "C<RD>.+L"),
            ("any", "C.*L"),
        ]);
        let e =
            explain::<RenderMan>(&a, &Parser::default(), &"C RD RS L".parse().unwrap()).unwrap();
        assert_eq!(e.landed, [1, 2]);
        assert!(e.text.ends_with("lands in: indirect, any\n"), "{}", e.text);
        // After `C RD`, direct is still reachable; after `C RD RS` it is not.
        let reach: Vec<&str> = e
            .text
            .lines()
            .filter(|l| l.starts_with("| "))
            .skip(1)
            .map(|l| l.trim_end_matches('|').rsplit('|').next().unwrap().trim())
            .collect();
        assert_eq!(
            reach,
            [
                "direct, indirect, any",
                "direct, indirect, any",
                "indirect, any",
                "indirect, any"
            ]
        );
    }

    #[test]
    fn a_missing_path_gets_its_closest_aov() {
        let a = aovs(&[("spec", "C<RS>L"), ("diffuse2", "C<RD><RD>L")]);
        let e =
            explain::<RenderMan>(&a, &Parser::default(), &"C RD RS L".parse().unwrap()).unwrap();
        assert!(e.landed.is_empty());
        assert!(
            e.text.contains("longest live prefix: C RD1 (2 of 4 vertices)\nclosest AOV: diffuse2 (dead at vertex 3)\n"),
            "{}",
            e.text
        );
        // Dead states ignore the path shape: an AOV asking for more after the emitter
        // is still reachable when the path ends.
        let a = aovs(&[("spec", "C<RS>L"), ("twice", "C<RD>L<RD>L")]);
        let e = explain::<RenderMan>(&a, &Parser::default(), &"C RD L".parse().unwrap()).unwrap();
        assert!(
            e.text
                .contains("closest AOV: twice (still reachable after the last vertex"),
            "{}",
            e.text
        );
    }
}
