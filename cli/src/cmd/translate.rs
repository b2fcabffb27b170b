//! `lpe-check translate --from renderman --to osl EXPR…` (and `--from osl --to
//! renderman`): each expression in the other dialect, with a verdict proved on the
//! automata ([`lpe::translate`], docs/language.md §19). `--from` and `--to` name renderer
//! profiles (docs/profiles.md; `renderman` and `osl` are the base dialects' own): the
//! OSL-based side's correspondence says which of its letters RenderMan's lobes become
//! (`--from renderman --to karma`: every specular lobe is Karma's `G`), and its letters,
//! prefixes and built-in names read the OSL source.
//!
//! Exit 0 when every translation is exact, 1 when one is not expressible, 2 on bad input
//! (an expression that does not parse is reported on stderr and the others are still
//! translated), 3 when a witness fails its re-check with the reference matchers. `--from-file` reads a
//! USD stage, RIB file or `rendermn.ini` (its user macros) instead of arguments;
//! `--format json` or `usda` (a layer of RenderVars) writes the translated set.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use lpe::osl;
use lpe::osl::Osl;
use lpe::renderman::macros::MacroTable;
use lpe::renderman::RenderMan;
use lpe::renderman::{self, Config};
use lpe::translate::{self, Correspondence, Reason, Translate, Translation, Witness};
use lpe::Dialect;
use lpe::DialectName;
use lpe_lint::read::{self, Limits};

use lpe_profile::Profile;

use crate::dialect::CliDialect;
use crate::input::bad_input;
use crate::witness::{recheck, Checked, Disagreement, Expect, DISAGREE};

/// How the translated set is written.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// One block per expression: translation, verdict, bounds and witnesses.
    Text,
    /// One JSON object per expression, in an array.
    Json,
    /// A USD layer of RenderVars (`sourceType = "lpe"`, `lpe:dialect` set), one per AOV.
    Usda,
}

/// Arguments of `lpe-check translate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The renderer (or dialect) the expressions are written for: `renderman`, `osl`,
    /// `hdprman`, `karma`, `arnold`, `vray`, `moonray`.
    #[arg(long, value_name = "RENDERER")]
    pub from: String,
    /// The renderer (or dialect) to write them for, reading the other dialect.
    #[arg(long, value_name = "RENDERER")]
    pub to: String,
    /// Changes to the correspondence (the OSL-based renderer's, else the default), e.g.
    /// `S4=S S5-S6=s 'key'='lg_key'` (docs/language.md §19.1).
    #[arg(long, default_value = "")]
    pub correspondence: String,
    /// RenderMan source only: a rendermn.ini-style file with user macros.
    #[arg(long)]
    pub ini: Option<PathBuf>,
    /// Read the AOVs of a USD stage, RIB file or rendermn.ini (its user macros) instead.
    #[arg(long, conflicts_with = "exprs")]
    pub from_file: Option<PathBuf>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// The expressions.
    #[arg(required_unless_present = "from_file")]
    pub exprs: Vec<String>,
}

/// One AOV to translate.
struct Source {
    name: String,
    text: String,
}

/// One AOV translated: the text of each bound, the verdict and the report lines.
struct Translated {
    name: String,
    source: String,
    text: String,
    exact: bool,
    lower: String,
    reasons: Vec<String>,
    adds: Option<String>,
    misses: Option<String>,
    notes: Vec<String>,
}

/// The two sides' profiles: `--from`, `--to`.
struct Sides {
    from: &'static Profile,
    to: &'static Profile,
}

impl Sides {
    fn read(args: &Args) -> Result<Sides, String> {
        let side =
            |flag: &str, name: &str| lpe_profile::by_name(name).map_err(|e| format!("{flag}: {e}"));
        let sides = Sides {
            from: side("--from", &args.from)?,
            to: side("--to", &args.to)?,
        };
        if sides.from.dialect() == sides.to.dialect() {
            return Err(format!(
                "--from {} and --to {} both read {}'s dialect; translation is between the two \
                 dialects (docs/profiles.md): compare two renderers' expressions with \
                 `lpe-check equiv --renderer`",
                args.from,
                args.to,
                sides.from.dialect()
            ));
        }
        Ok(sides)
    }

    /// The OSL-based side, whose correspondence and registration apply.
    fn osl(&self) -> &'static Profile {
        if self.from.dialect() == DialectName::Osl {
            self.from
        } else {
            self.to
        }
    }
}

/// Runs `lpe-check translate`.
pub fn run(args: Args) -> ExitCode {
    let sides = match Sides::read(&args) {
        Ok(s) => s,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    // The profile's correspondence first (checked when it loaded), then the user's
    // changes to it.
    let corr = match sides.osl().correspondence().apply(&args.correspondence) {
        Ok(c) => c,
        Err(e) => return bad_input(format!("error: --correspondence: {e}")),
    };
    let osl_registration =
        <Osl as lpe_profile::ProfileDialect>::with_profile(sides.osl(), osl::Registered::none());
    let (sources, parser) = match sources(&args, &sides) {
        Ok(s) => s,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let mut out = Vec::new();
    // An expression that does not parse is reported and skipped: the rest of a file's
    // set is still translated, and the exit status says something was bad.
    let mut bad = false;
    for s in &sources {
        let result = match sides.from.dialect() {
            DialectName::RenderMan => translate_source::<RenderMan>(s, &parser, &corr),
            DialectName::Osl => translate_source::<Osl>(s, &osl_registration, &corr),
        };
        match result {
            Ok(Ok(t)) => out.push(t),
            Ok(Err(e)) => {
                eprintln!("{e}");
                return ExitCode::from(DISAGREE);
            }
            Err(e) => {
                eprintln!("{e}");
                bad = true;
            }
        }
    }
    let exact = out.iter().all(|t| t.exact);
    let text = match args.format {
        Format::Text => text(&out),
        Format::Json => json(&out, &args, &corr),
        Format::Usda => usda(&out, &args, sides.to),
    };
    print!("{text}");
    if bad {
        return ExitCode::from(2);
    }
    ExitCode::from(u8::from(!exact))
}

/// The AOVs from the arguments or the file, and the RenderMan parser (`--ini`, or the
/// ini file read).
fn sources(args: &Args, sides: &Sides) -> Result<(Vec<Source>, renderman::Parser), String> {
    let mut parser = renderman::Parser::default();
    if let Some(ini) = &args.ini {
        if sides.from.dialect() != DialectName::RenderMan {
            return Err("--ini holds RenderMan macros; it needs --from renderman".into());
        }
        let text = std::fs::read_to_string(ini)
            .map_err(|e| format!("cannot read {}: {e}", ini.display()))?;
        parser = Config::from_ini(&text)
            .map_err(|e| format!("{}: {e}", ini.display()))?
            .parser();
    }
    let Some(file) = &args.from_file else {
        let named = args
            .exprs
            .iter()
            .map(|e| Source {
                name: String::new(),
                text: e.clone(),
            })
            .collect();
        return Ok((named, parser));
    };
    let doc = read::read_file(file, &Limits::default()).map_err(|e| e.to_string())?;
    if let Some(config) = &doc.config {
        // A rendermn.ini: its user macros are the set.
        let builtin = MacroTable::builtin();
        let sources = config
            .macros
            .iter()
            .filter(|(n, body)| builtin.get(n) != Some(*body))
            .map(|(n, body)| Source {
                name: n.to_string(),
                text: body.to_string(),
            })
            .collect();
        return Ok((sources, config.parser()));
    }
    let sources = doc
        .aovs
        .iter()
        .map(|a| Source {
            name: a.name.clone(),
            text: a.source.clone(),
        })
        .collect();
    Ok((sources, parser))
}

fn label(s: &Source) -> String {
    if s.name.is_empty() {
        String::new()
    } else {
        format!("{}: ", s.name)
    }
}

/// `Err`: the expression does not parse (bad input); `Ok(Err)`: a witness failed its
/// re-check.
type Outcome = Result<Result<Translated, Disagreement>, String>;

/// One source read in dialect `D` (a leading `lpe:` as `D` reads it), translated, and its
/// witnesses re-checked.
fn translate_source<D>(s: &Source, registration: &D::Registration, corr: &Correspondence) -> Outcome
where
    D: CliDialect + Translate + Checked,
    D::Target: Checked,
{
    let e = D::parse_arg(&s.text, registration)
        .map_err(|err| format!("{}error in `{}`: {err}", label(s), s.text))?;
    let t = translate::translate::<D>(&e, corr).map_err(|err| format!("{}{err}", label(s)))?;
    Ok(recheck_witnesses::<D>(&e, &t).map(|()| translated(s, &t)))
}

/// Every witness of a translation, re-checked with the reference matchers of both
/// dialects: the source on its side of each witness, the bounds on theirs.
fn recheck_witnesses<D>(
    e: &D::Lpe,
    t: &Translation<<D::Target as Dialect>::Lpe>,
) -> Result<(), Disagreement>
where
    D: Translate + Checked,
    D::Target: Checked,
{
    let (src, up, low) = (e.to_string(), t.text.to_string(), t.lower.to_string());
    let source = |w: &Witness, matches: bool| match D::source_path(w) {
        Some(p) => recheck(
            p,
            &[Expect {
                name: &src,
                lpe: e,
                matches,
            }],
        ),
        None => Ok(()),
    };
    let target = |w: &Witness, name: &str, lpe, matches: bool| match D::target_path(w) {
        Some(p) => recheck(p, &[Expect { name, lpe, matches }]),
        None => Ok(()),
    };
    let on = |renderman: &renderman::Path, osl: Option<&osl::Path>| Witness {
        renderman: renderman.clone(),
        osl: osl.cloned(),
    };
    for r in &t.reasons {
        match r {
            Reason::Collision(c) => {
                source(&on(&c.matched, Some(&c.osl)), true)?;
                source(&on(&c.unmatched, Some(&c.osl)), false)?;
            }
            Reason::NoOslView(p) => source(&on(p, None), true)?,
            Reason::Unsayable => {}
        }
    }
    if let Some(w) = &t.upper_witness {
        source(w, false)?;
        target(w, &up, &t.text, true)?;
    }
    if let Some(w) = &t.lower_witness {
        source(w, true)?;
        target(w, &low, &t.lower, false)?;
    }
    Ok(())
}

fn show(w: &Witness) -> String {
    match &w.osl {
        Some(o) => format!("`{}` (OSL `{o}`)", w.renderman),
        None => format!("`{}` (no OSL view)", w.renderman),
    }
}

fn translated<L: std::fmt::Display>(s: &Source, t: &Translation<L>) -> Translated {
    let reasons = t
        .reasons
        .iter()
        .map(|r| match r {
            Reason::Collision(c) => format!(
                "`{}` and `{}` have one OSL view `{}` and only the first matches",
                c.matched, c.unmatched, c.osl
            ),
            Reason::NoOslView(p) => format!(
                "it matches `{p}`, which has no OSL view (user lobes and labels OSL reads as \
                 built in have none)"
            ),
            Reason::Unsayable => {
                "the target dialect cannot say which labels (or none) a vertex carries here"
                    .to_string()
            }
        })
        .collect();
    Translated {
        name: s.name.clone(),
        source: s.text.clone(),
        text: t.text.to_string(),
        exact: t.exact,
        lower: t.lower.to_string(),
        reasons,
        adds: t.upper_witness.as_ref().map(show),
        misses: t.lower_witness.as_ref().map(show),
        notes: t.notes.clone(),
    }
}

fn text(out: &[Translated]) -> String {
    let mut s = String::new();
    for t in out {
        let name = if t.name.is_empty() {
            String::new()
        } else {
            format!("{}: ", t.name)
        };
        if t.exact {
            let _ = writeln!(s, "{name}{}  ->  {}  (exact)", t.source, t.text);
        } else {
            let _ = writeln!(s, "{name}{}  ->  not expressible", t.source);
            for r in &t.reasons {
                let _ = writeln!(s, "  why: {r}");
            }
            let _ = write!(s, "  from above: {}", t.text);
            match &t.adds {
                Some(w) => {
                    let _ = writeln!(s, "  (adds {w})");
                }
                None => s.push('\n'),
            }
            let _ = write!(s, "  from below: {}", t.lower);
            match &t.misses {
                Some(w) => {
                    let _ = writeln!(s, "  (misses {w})");
                }
                None => s.push('\n'),
            }
        }
        for n in &t.notes {
            let _ = writeln!(s, "  note: {n}");
        }
    }
    s
}

fn json(out: &[Translated], args: &Args, corr: &Correspondence) -> String {
    let items: Vec<serde_json::Value> = out
        .iter()
        .map(|t| {
            serde_json::json!({
                "name": t.name,
                "source": t.source,
                "translation": t.text,
                "exact": t.exact,
                "reasons": t.reasons,
                "lower": t.lower,
                "adds": t.adds,
                "misses": t.misses,
                "notes": t.notes,
            })
        })
        .collect();
    let doc = serde_json::json!({
        "from": args.from.to_string(),
        "to": args.to.to_string(),
        "correspondence": corr.declaration(),
        "aovs": items,
    });
    let mut s = serde_json::to_string_pretty(&doc).expect("JSON of strings");
    s.push('\n');
    s
}

/// A USD prim name from an AOV name: letters, digits and `_`, not starting with a digit.
fn prim_name(name: &str, i: usize) -> String {
    let mut s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if s.is_empty() {
        s = format!("aov{i}");
    } else if s.starts_with(|c: char| c.is_ascii_digit()) {
        s.insert(0, '_');
    }
    s
}

/// A USD string literal.
fn usd_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The layer of RenderVars: `lpe:dialect` says the target's dialect and, for a renderer
/// other than a base dialect, `lpe:renderer` names it, so `lpe-check lint` reads the
/// layer with that renderer's rules.
fn usda(out: &[Translated], args: &Args, to: &Profile) -> String {
    let mut s = String::from("#usda 1.0\n(\n");
    let _ = writeln!(
        s,
        "    doc = {}\n)\n",
        usd_string(&format!(
            "LPE AOVs translated from {} to {} by lpe-check translate",
            args.from, args.to
        ))
    );
    let _ = writeln!(s, "def Scope \"Render\"\n{{");
    let _ = writeln!(
        s,
        "    custom string lpe:dialect = {}",
        usd_string(to.dialect().name())
    );
    if to.name != to.dialect().name() {
        let _ = writeln!(
            s,
            "    custom string lpe:renderer = {}",
            usd_string(&to.name)
        );
    }
    let _ = writeln!(s, "    def Scope \"Vars\"\n    {{");
    let mut used = std::collections::BTreeSet::new();
    for (i, t) in out.iter().enumerate() {
        let mut name = prim_name(&t.name, i);
        while !used.insert(name.clone()) {
            name.push('_');
        }
        let verdict = if t.exact {
            "exact".to_string()
        } else {
            format!(
                "not expressible: written from above; from below: {}",
                t.lower
            )
        };
        let _ = writeln!(s, "        def RenderVar \"{name}\"\n        {{");
        let _ = writeln!(s, "            uniform token dataType = \"color3f\"");
        let _ = writeln!(
            s,
            "            uniform string sourceName = {}",
            usd_string(&format!("lpe:{}", t.text))
        );
        let _ = writeln!(s, "            uniform token sourceType = \"lpe\"");
        let _ = writeln!(
            s,
            "            custom string lpe:translatedFrom = {}",
            usd_string(&t.source)
        );
        let _ = writeln!(
            s,
            "            custom string lpe:translation = {}",
            usd_string(&verdict)
        );
        let _ = writeln!(s, "        }}");
    }
    let _ = writeln!(s, "    }}\n}}");
    s
}
