//! `lpe-check explain PATH`: which AOVs a path lands in, and how it got there.
//!
//! AOVs come from `--aov NAME=EXPR`, `--display FILE.rib`, `--usd FILE.usda` and
//! `--from FILE` (anything `lint` reads), in that order. Prints one row per vertex: the
//! vertex, its class in the compiled set, the set's state after it (its `Debug` form,
//! opaque) and the AOVs that can still match some continuation; then the AOVs the whole
//! path lands in. A path landing nowhere also gets the longest prefix after which some
//! AOV could still match, and the AOV that stayed reachable longest (the closest miss).
//! Exit 0 when the path lands in some AOV, 1 when in none, 2 on bad input.

use std::path::PathBuf;
use std::process::ExitCode;

use lpe::{AovSet, Lpe, Path};
use lpe_lint::read::{self, Limits};
use lpe_lint::Document;
use tabled::builder::Builder;
use tabled::settings::Style;

use crate::input::{bad_input, load_parser, Dialect};

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
    /// Expression dialect.
    #[arg(long, value_enum, default_value_t = Dialect::Renderman)]
    pub dialect: Dialect,
}

/// Runs `lpe-check explain`.
pub fn run(args: Args) -> ExitCode {
    if let Err(e) = args.dialect.check_available() {
        return bad_input(format!("error: {e}"));
    }
    let path: Path = match args.path.parse() {
        Ok(p) => p,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let aovs = match load(&args) {
        Ok(a) if a.is_empty() => {
            return bad_input("error: no AOVs: give --aov, --display, --usd or --from")
        }
        Ok(a) => a,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    match explain(&aovs, &path) {
        Ok(e) => {
            print!("{}", e.text);
            ExitCode::from(u8::from(e.landed.is_empty()))
        }
        Err(e) => bad_input(format!("error: {e}")),
    }
}

/// The AOVs of the arguments, parsed.
fn load(args: &Args) -> Result<Vec<(String, Lpe)>, String> {
    let parser = load_parser(args.ini.as_deref()).map_err(|e| e.to_string())?;
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
    sources
        .into_iter()
        .map(|(name, src, at)| {
            parser
                .parse(&src)
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

/// Steps `path` through the set of `aovs` and through each AOV alone.
pub fn explain(aovs: &[(String, Lpe)], path: &Path) -> Result<Explanation, lpe::CompileError> {
    let set = AovSet::compile(aovs)?;
    // Per-AOV sets say which AOVs are still reachable: the joint state only says
    // whether any is.
    let alone: Vec<AovSet> = aovs
        .iter()
        .map(|a| AovSet::compile(std::slice::from_ref(a)))
        .collect::<Result<_, _>>()?;
    let mut states: Vec<_> = alone.iter().map(AovSet::start).collect();
    // How many vertices each AOV stayed reachable through.
    let mut alive_for = vec![0usize; aovs.len()];
    let mut s = set.start();
    let mut table = Builder::default();
    table.push_record(["#", "vertex", "class", "state", "still reachable"]);
    for (k, v) in path.vertices().iter().enumerate() {
        s = set.step(s, v);
        let mut reachable = Vec::new();
        for (i, a) in alone.iter().enumerate() {
            states[i] = a.step(states[i], v);
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
        table.push_record([
            (k + 1).to_string(),
            v.to_string(),
            set.classify(v).index().to_string(),
            format!("{s:?}"),
            reach,
        ]);
    }
    let landed: Vec<usize> = set.matches(s).iter().collect();
    let mut text = format!(
        "path {path} against {} AOVs\n{}\n",
        aovs.len(),
        table.build().with(Style::markdown())
    );
    if landed.is_empty() {
        let longest = alive_for.iter().copied().max().unwrap_or(0);
        let prefix: Vec<String> = path.vertices()[..longest]
            .iter()
            .map(ToString::to_string)
            .collect();
        text.push_str("lands in no AOV\n");
        if longest == 0 {
            text.push_str("no AOV can match any path starting with its first vertex\n");
        } else {
            let closest = alive_for
                .iter()
                .position(|&n| n == longest)
                .expect("the maximum is in the list");
            let how = if longest == path.len() {
                "still reachable after the last vertex: the path ends too early for it".to_string()
            } else {
                format!("dead at vertex {}", longest + 1)
            };
            text.push_str(&format!(
                "longest live prefix: {} ({longest} of {} vertices)\nclosest AOV: {} ({how})\n",
                prefix.join(" "),
                path.len(),
                aovs[closest].0
            ));
        }
    } else {
        let names: Vec<&str> = landed.iter().map(|&i| aovs[i].0.as_str()).collect();
        text.push_str(&format!("lands in: {}\n", names.join(", ")));
    }
    Ok(Explanation { landed, text })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn aovs(list: &[(&str, &str)]) -> Vec<(String, Lpe)> {
        list.iter()
            .map(|(n, e)| (n.to_string(), lpe::parse(e).unwrap()))
            .collect()
    }

    #[test]
    fn a_landing_path_names_its_aovs() {
        let a = aovs(&[
            ("direct", "C<RD>L"),
            ("indirect", "C<RD>.+L"),
            ("any", "C.*L"),
        ]);
        let e = explain(&a, &"C RD RS L".parse().unwrap()).unwrap();
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
        let e = explain(&a, &"C RD RS L".parse().unwrap()).unwrap();
        assert!(e.landed.is_empty());
        assert!(
            e.text.contains("longest live prefix: C RD1 (2 of 4 vertices)\nclosest AOV: diffuse2 (dead at vertex 3)\n"),
            "{}",
            e.text
        );
        // Dead states ignore the path shape: an AOV asking for more after the emitter
        // is still reachable when the path ends.
        let a = aovs(&[("spec", "C<RS>L"), ("twice", "C<RD>L<RD>L")]);
        let e = explain(&a, &"C RD L".parse().unwrap()).unwrap();
        assert!(
            e.text
                .contains("closest AOV: twice (still reachable after the last vertex"),
            "{}",
            e.text
        );
    }
}
