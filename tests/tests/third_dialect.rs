//! A third dialect, written for this test only, checks the claim of docs/architecture.md:
//! a new dialect is one implementation of `lpe::DialectName` and nothing below the seam
//! changes. `Letters` is RenderMan with three letters swapped (`E` for the camera `C`,
//! `B` for reflection `R`, `P` for transmission `T`, and back), no macros (their names
//! would be swapped too). It lowers to RenderMan's tree and class alphabet, so its own
//! code is only the surface: text in, text out.
//!
//! Through it run the layers written once: `AovSet` compile, step, warnings and
//! `PathMatcher`; the analyses (comparison, partition, remainder, set-algebra
//! warnings); a differential check of the set against the reference matcher, which
//! shares no automaton with it (both read RenderMan's parser, so that part is checked
//! by RenderMan's own suites, not here); and the tools of `lpe-engines`, which need one
//! more implementation each (`ReferenceDialect`: its reference verdict; `OracleDialect`:
//! none, the default; `ShrinkDialect`: its shrinking; `WireDialect`: its parse errors;
//! `Generate`: its generators): the engine registry (`oracle` has no translation for it
//! and says so), the differential harness on generated cases, and a planted bug found
//! and minimized; and the front-end comparison (`FrontEnds`), whose "reference" side
//! here is lpe's parser with planted faults, one per kind of disagreement it reports.

use std::fmt;
use std::str::FromStr;

use lpe::algebra::{Algebra, SetExpr};
use lpe::analysis;
use lpe::automata::ir::PathShape;
use lpe::renderman::ast::Item;
use lpe::renderman::{self, alphabet::Alphabet, ast::Atom, Expr, Parser, RenderMan, Vertex};
use lpe::{AovMask, AovSet, CompileError, Dialect, DialectLpe, PathMatcher};
use lpe_engines::differential::front::{self, FrontCase, FrontEnds};
use lpe_engines::differential::{self, Generate, Outcome, Run};
use lpe_engines::{
    Engine, EngineError, Matcher, OracleDialect, Reference, ReferenceDialect, ShrinkDialect,
    WireDialect,
};
use lpe_testkit::generate::{self, Choices, Config};
use lpe_testkit::grammar::{self, Coverage};

/// Swaps `C`/`E`, `R`/`B` and `T`/`P` outside single-quoted labels: Letters text to
/// RenderMan text and back (the swap is its own inverse).
fn swap(text: &str) -> String {
    let mut quoted = false;
    text.chars()
        .map(|c| {
            if c == '\'' {
                quoted = !quoted;
            }
            match (quoted, c) {
                (false, 'C') => 'E',
                (false, 'E') => 'C',
                (false, 'R') => 'B',
                (false, 'B') => 'R',
                (false, 'T') => 'P',
                (false, 'P') => 'T',
                (_, c) => c,
            }
        })
        .collect()
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
struct Letters;

thread_local! {
    /// Plants a front-end bug in [`Letters`]'s parser on this thread: a tab between
    /// tokens is rejected (the grammar allows it).
    static PLANTED_TAB_REJECTION: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    /// Plants faults in [`Letters`]'s "reference" front end on this thread ([`FrontFaults`]).
    static PLANTED_FRONT_FAULTS: std::cell::Cell<FrontFaults> = const { std::cell::Cell::new(FrontFaults::NONE) };
}

/// Faults of the stand-in reference front end, one per kind of front-end disagreement
/// the comparison reports.
#[derive(Clone, Copy, Debug, Default)]
struct FrontFaults {
    /// The tree reads every `D` (diffuse) as `S`: the matchers differ (a meaning finding).
    reads_diffuse_as_specular: bool,
    /// The printer writes every `D` as `S`, the tree is right (a print finding).
    prints_diffuse_as_specular: bool,
    /// The printer appends `)` (lpe's parser rejects the print: a reprint finding).
    prints_a_stray_paren: bool,
    /// Text without an `O` is rejected (an acceptance finding).
    rejects_text_without_o: bool,
    /// The tree reads every `D` as `D1`: a narrower reading, so the only paths the two
    /// readings answer differently are ones lpe's matches and the reference's does not
    /// (use on texts without lobe numbers).
    reads_diffuse_as_first_lobe: bool,
    /// The tree reads every `D1` as `D`: a wider reading, so the only paths answered
    /// differently are ones the reference's matches and lpe's does not.
    reads_first_lobe_as_diffuse: bool,
}

impl FrontFaults {
    const NONE: FrontFaults = FrontFaults {
        reads_diffuse_as_specular: false,
        prints_diffuse_as_specular: false,
        prints_a_stray_paren: false,
        rejects_text_without_o: false,
        reads_diffuse_as_first_lobe: false,
        reads_first_lobe_as_diffuse: false,
    };
    const READS_D_AS_D1: FrontFaults = FrontFaults {
        reads_diffuse_as_first_lobe: true,
        ..FrontFaults::NONE
    };
    const READS_D1_AS_D: FrontFaults = FrontFaults {
        reads_first_lobe_as_diffuse: true,
        ..FrontFaults::NONE
    };
    const READS_D_AS_S: FrontFaults = FrontFaults {
        reads_diffuse_as_specular: true,
        ..FrontFaults::NONE
    };
    const PRINTS_D_AS_S: FrontFaults = FrontFaults {
        prints_diffuse_as_specular: true,
        ..FrontFaults::NONE
    };
    const REJECTS_WITHOUT_O: FrontFaults = FrontFaults {
        rejects_text_without_o: true,
        ..FrontFaults::NONE
    };
}

#[derive(Clone, Debug, PartialEq)]
struct LettersLpe(renderman::Lpe);

#[derive(Clone, Debug, PartialEq)]
struct LettersPath(renderman::Path);

impl fmt::Display for LettersLpe {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&swap(&self.0.to_string()))
    }
}

impl fmt::Display for LettersPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&swap(&self.0.to_string()))
    }
}

impl FromStr for LettersPath {
    type Err = renderman::PathError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        swap(s).parse().map(LettersPath)
    }
}

impl SetExpr for LettersLpe {
    type Operand = Expr;
    fn first(&self) -> &Expr {
        self.0.first()
    }
    fn algebra(&self) -> Option<&Algebra<Expr>> {
        self.0.algebra()
    }
}

impl DialectLpe for LettersLpe {
    type Dialect = Letters;
}

impl Dialect for Letters {
    const NAME: &'static str = "letters";
    const SHAPE: PathShape = PathShape::CameraScattersEmitter;
    const DEFAULT_UNIVERSE: &'static str = "E.*[<L.>O]";

    type Lpe = LettersLpe;
    type Expr = Expr;
    type Atom = Atom;
    type Vertex = Vertex;
    type Path = LettersPath;
    type PathError = renderman::PathError;
    type Registration = ();
    type ParseError = renderman::Error;
    type Classes = Alphabet;

    fn parse(source: &str, _: &()) -> Result<LettersLpe, renderman::Error> {
        if PLANTED_TAB_REJECTION.with(|p| p.get()) && source.contains('\t') {
            // A parser bug to plant: whitespace it should skip, rejected.
            return renderman::parse("C\u{7}L").map(LettersLpe);
        }
        renderman::parse(&swap(source)).map(LettersLpe)
    }
    fn vertices(path: &LettersPath) -> &[Vertex] {
        path.0.vertices()
    }
    fn path(vertices: Vec<Vertex>) -> LettersPath {
        LettersPath(RenderMan::path(vertices))
    }
    fn positions(e: &Expr, max_path_len: Option<u32>) -> u64 {
        RenderMan::positions(e, max_path_len)
    }
    fn classes(atoms: &[&Atom], operands: &[&Expr]) -> Result<Alphabet, CompileError> {
        RenderMan::classes(atoms, operands)
    }
    fn accepts(atom: &Atom, vertex: &Vertex) -> bool {
        RenderMan::accepts(atom, vertex)
    }
    fn alt(alternatives: Vec<Expr>) -> Expr {
        RenderMan::alt(alternatives)
    }
    fn from_algebra(tree: Algebra<Expr>) -> LettersLpe {
        LettersLpe(RenderMan::from_algebra(tree))
    }
}

fn lpe(src: &str) -> LettersLpe {
    Letters::parse(src, &()).unwrap()
}

fn path(text: &str) -> LettersPath {
    text.parse().unwrap()
}

fn named(srcs: &[(&str, &str)]) -> Vec<(String, LettersLpe)> {
    srcs.iter().map(|(n, s)| (n.to_string(), lpe(s))).collect()
}

/// The basic set of docs/language.md in the swapped letters.
const BASIC: [(&str, &str); 7] = [
    ("directDiffuse", "E<BD>[<L.>O]"),
    ("indirectDiffuse", "E<BD>.+[<L.>O]"),
    ("subsurface", "E<PD>.*[<L.>O]"),
    ("directSpecular", "E<BS>[<L.>O]"),
    ("indirectSpecular", "E<BS>.+[<L.>O]"),
    ("transmissive", "E<PS>.*[<L.>O]"),
    ("emissive", "E[<L.>O]"),
];

#[test]
fn the_surface_is_its_own() {
    assert_eq!(lpe("E<BD>'a C'L").to_string(), "E<BD>'a C'L");
    // RenderMan's letters are not this dialect's.
    let err = Letters::parse("C<RD>L", &()).unwrap_err();
    assert_eq!(err.span().start, 0, "{err}");
    assert_eq!(
        path("E BD2'floor' PS L'key'").to_string(),
        "E BD2'floor' PS1 L'key'"
    );
    assert!("C RD L".parse::<LettersPath>().is_err());
}

#[test]
fn sets_compile_step_and_warn_through_the_shared_layers() {
    let set = AovSet::compile_under(&named(&BASIC), &(), &lpe::Options::default()).unwrap();
    assert_eq!(set.dialect(), "letters");
    assert!(set.uses_dfa());
    let hits = |p: &str| set.match_path(&path(p)).iter().collect::<Vec<_>>();
    assert_eq!(hits("E BD L"), [0]);
    assert_eq!(hits("E BD BS L'key'"), [1]);
    assert_eq!(hits("E PD O"), [2]);
    assert_eq!(hits("E L"), [6]);
    assert_eq!(hits("E BU1 L"), Vec::<usize>::new());
    // The generic incremental seam answers the same.
    let p = path("E PS BS L");
    assert_eq!(
        PathMatcher::match_vertices(&set, Letters::vertices(&p)),
        set.match_path(&p)
    );
    // The lazy DFA, forced.
    let lazy = AovSet::compile_under(
        &named(&BASIC),
        &(),
        &lpe::Options {
            dfa_budget: 0,
            ..lpe::Options::default()
        },
    )
    .unwrap();
    assert!(!lazy.uses_dfa());
    assert_eq!(lazy.match_path(&p), set.match_path(&p));
    // Emptiness warnings come from the shared automata, worded by the path shape.
    let dead = AovSet::compile(&named(&[("x", "E<BD>"), ("y", "E<BD>L - E<BD>L")])).unwrap();
    let warned: Vec<String> = analysis::warnings(&dead)
        .iter()
        .map(|w| w.name.clone())
        .collect();
    assert_eq!(warned, ["x", "y"]);
}

#[test]
fn the_analyses_run_on_it() {
    let c = analysis::compare(&lpe("E<BD>.+L"), &lpe("E<BD>.*L")).unwrap();
    assert_eq!(c.first_only, None);
    assert_eq!(c.second_only.unwrap().to_string(), "E BD1 L");
    let universe = analysis::default_universe::<Letters>(&());
    assert_eq!(universe.to_string(), "E.*[<L.>O]");
    let p = analysis::partition(&named(&BASIC), &universe, &()).unwrap();
    assert!(p.is_clean(), "{p:?}");
    // Without `emissive`, the remainder is exactly `E[<L.>O]`, printed in this dialect.
    let six = named(&BASIC[..6]);
    let gap = analysis::partition(&six, &universe, &())
        .unwrap()
        .gap
        .unwrap();
    assert_eq!(gap.to_string(), "E L");
    let rest = analysis::remainder(&six, &universe);
    assert!(rest.to_string().starts_with("E.*[<L.>O] - ("), "{rest}");
    assert!(analysis::compare(&rest, &lpe("E[<L.>O]"))
        .unwrap()
        .equivalent());
}

/// Differential: the set against the reference matcher, on every path of up to four
/// vertices over a small alphabet. The reference shares RenderMan's parser with this
/// dialect, not its automata.
#[test]
fn the_set_agrees_with_the_reference_matcher() {
    let exprs = [
        "E<BD>.+[<L.>O]",
        "E(B|P)*[DS]<L.'key'>",
        "E[^<BS>]{1,2}O - E.*DO",
        "^E.*L",
    ];
    let aovs: Vec<(String, LettersLpe)> = exprs.iter().map(|s| (s.to_string(), lpe(s))).collect();
    let set = AovSet::compile(&aovs).unwrap();
    let middle = ["BD", "BS", "PD", "PS'key'", "BU2"];
    let ends = ["L", "L'key'", "O"];
    let mut checked = 0;
    let mut paths = vec![String::from("E")];
    for _ in 0..3 {
        for end in ends {
            for p in &paths {
                let text = format!("{p} {end}");
                let lp = path(&text);
                let want: Vec<usize> = (0..aovs.len())
                    .filter(|&i| lpe_reference::is_match(&aovs[i].1 .0, &lp.0))
                    .collect();
                let got: Vec<usize> = set.match_path(&lp).iter().collect();
                assert_eq!(got, want, "{text}");
                checked += 1;
            }
        }
        paths = paths
            .iter()
            .flat_map(|p| middle.iter().map(move |m| format!("{p} {m}")))
            .collect();
    }
    assert_eq!(checked, 3 * (1 + 5 + 25));
}

// --- The tools of `lpe-engines`: one implementation of each of their traits. ---

/// The reference is RenderMan's on the same trees (through lpe's printer: this dialect
/// has no front end of its own in the reference).
impl ReferenceDialect for Letters {
    type ReferenceTree = LettersLpe;
    fn reference_tree(lpe: &LettersLpe, _: &()) -> Result<LettersLpe, EngineError> {
        Ok(lpe.clone())
    }
    fn reference(lpe: &LettersLpe, path: &LettersPath) -> bool {
        lpe_reference::is_match(&lpe.0, &path.0)
    }
}

/// No oracle translation (the default): the `oracle` engine refuses this dialect.
impl OracleDialect for Letters {}

/// Shrinking is RenderMan's on the same trees.
impl ShrinkDialect for Letters {
    fn shrink_expr(e: &LettersLpe, _: &()) -> Vec<LettersLpe> {
        RenderMan::shrink_expr(&e.0, &Parser::default())
            .into_iter()
            .map(LettersLpe)
            .collect()
    }
    fn shrink_path(p: &LettersPath) -> Vec<LettersPath> {
        RenderMan::shrink_path(&p.0)
            .into_iter()
            .map(LettersPath)
            .collect()
    }
}

/// Errors as RenderMan's; nothing registered to report or send.
impl WireDialect for Letters {
    fn parse_error(e: &renderman::Error) -> (usize, String) {
        RenderMan::parse_error(e)
    }
}

/// This dialect has no front end in the reference, so the front-end comparison's
/// "reference" side is lpe's parser again, with the faults of [`PLANTED_FRONT_FAULTS`]:
/// what it checks here is the comparison itself (that each kind of disagreement is
/// found, kept while minimizing and reported), not a second reading of the grammar.
impl FrontEnds for Letters {
    fn reference_parse(text: &str, _: &()) -> Result<LettersLpe, (usize, String)> {
        let faults = PLANTED_FRONT_FAULTS.with(|f| f.get());
        if faults.rejects_text_without_o && !text.contains('O') {
            return Err((0, "planted: no O".into()));
        }
        let mut text = text.to_string();
        if faults.reads_diffuse_as_specular {
            text = text.replace('D', "S");
        }
        if faults.reads_diffuse_as_first_lobe {
            text = text.replace('D', "D1");
        }
        if faults.reads_first_lobe_as_diffuse {
            text = text.replace("D1", "D");
        }
        renderman::parse(&swap(&text))
            .map(LettersLpe)
            .map_err(|e| RenderMan::parse_error(&e))
    }
    fn reference_print(tree: &LettersLpe) -> String {
        let faults = PLANTED_FRONT_FAULTS.with(|f| f.get());
        let mut text = tree.to_string();
        if faults.prints_diffuse_as_specular {
            text = text.replace('D', "S");
        }
        if faults.prints_a_stray_paren {
            text.push(')');
        }
        text
    }
    fn suite_registration(_: &lpe_testkit::suite::Loaded) -> Option<()> {
        None
    }
    /// Read by the corpus test from a scratch root, not from the workspace's fuzz/.
    const FUZZ_TARGETS: &'static [&'static str] = &["letters"];
    fn constructs() -> Vec<((), String)> {
        Vec::new()
    }
}

/// Runs `f` with `faults` planted in the stand-in reference front end.
fn with_front_faults<T>(faults: FrontFaults, f: impl FnOnce() -> T) -> T {
    PLANTED_FRONT_FAULTS.with(|p| p.set(faults));
    let out = f();
    PLANTED_FRONT_FAULTS.with(|p| p.set(FrontFaults::NONE));
    out
}

/// RenderMan's generators, wrapped.
impl Generate for Letters {
    type Config = Config;
    fn config(max_size: usize) -> Config {
        Config::default().with_max_atoms(max_size)
    }
    fn without_set_algebra(cfg: Config) -> Config {
        cfg.without_set_algebra()
    }
    fn registration(_: &mut impl Choices) {}
    fn lpe(c: &mut impl Choices, _: &(), cfg: &Config) -> LettersLpe {
        LettersLpe(generate::lpe(c, cfg))
    }
    /// RenderMan's grammar text with the letters swapped: a dialect's text generator.
    fn productions() -> &'static [&'static str] {
        grammar::renderman::PRODUCTIONS
    }
    fn text(c: &mut impl Choices, _: &(), cfg: &Config, coverage: &mut Coverage) -> String {
        let bounds = grammar::Config {
            max_units: cfg.max_atoms,
            set_algebra: cfg.set_algebra,
            ..grammar::Config::default()
        };
        swap(&grammar::renderman::source(c, &bounds, coverage))
    }
    fn biased_path(target: &Expr, c: &mut impl Choices, _: &(), cfg: &Config) -> LettersPath {
        LettersPath(generate::biased_path(target, c, cfg))
    }
}

#[test]
fn the_engine_registry_runs_it_and_the_oracle_refuses_it() {
    let exprs: Vec<LettersLpe> = BASIC.iter().map(|(_, s)| lpe(s)).collect();
    let set = AovSet::compile(&named(&BASIC)).unwrap();
    let engines = lpe_engines::all::<Letters>();
    assert_eq!(
        engines.iter().map(|e| e.name()).collect::<Vec<_>>(),
        lpe_engines::names()
    );
    let mut answered = 0;
    for e in &engines {
        match e.compile(&exprs, &()) {
            Ok(m) => {
                for p in ["E BD L", "E BD BS L'key'", "E PD O", "E L", "E BU1 L"] {
                    let p = path(p);
                    assert_eq!(m.which(&p), set.match_path(&p), "{} on {p}", e.name());
                }
                answered += 1;
            }
            Err(why) => {
                assert_eq!(e.name(), "oracle");
                assert!(
                    matches!(why, EngineError::Unsupported("letters")),
                    "{why:?}"
                );
                assert_eq!(
                    why.to_string(),
                    "cannot build: this engine does not support the letters dialect"
                );
            }
        }
    }
    assert_eq!(answered, 3);
    assert!(lpe_engines::by_name::<Letters>("fast").is_some());
}

#[test]
fn the_differential_harness_runs_generated_cases() {
    let args = Run {
        cases: 60,
        seed: 7,
        first: 0,
        max_size: 8,
        paths: 4,
        max_failures: 1,
    };
    let t = differential::run_cases::<Letters>(&args, &lpe_engines::all());
    if let Some((i, c)) = t.failures.first() {
        panic!("case {i}:\n{c}");
    }
    assert_eq!(t.cases, 60);
    assert_eq!(t.uncompared, 0);
    assert!(
        t.pairs >= 240 && t.matched > 0,
        "{} of {}",
        t.matched,
        t.pairs
    );
    // The oracle skipped every case, and said why; nothing else skipped.
    assert_eq!(t.skips.len(), 1, "{:?}", t.skips);
    assert_eq!(t.skips[0].0, "oracle");
    assert_eq!(t.skips[0].1, 60);
    assert!(t.skips[0].2.contains("letters"), "{}", t.skips[0].2);
    // Half the expressions were written from the grammar and parsed; none rejected.
    assert!(t.rejected.is_empty(), "{:?}", t.rejected);
    assert!(t.coverage.exercised() > 20, "{:?}", t.coverage.missing());
    // The generated text is this dialect's: it reads back.
    let case = differential::generate_case::<Letters>(7, 3, &Letters::config(8), 2);
    for e in &case.exprs {
        assert_eq!(Letters::parse(&e.to_string(), &()).unwrap(), *e);
    }
}

/// A front end that rejects documented syntax (a tab between tokens) is caught by the
/// grammar's texts: each rejection is a finding with its case, its text and the error.
#[test]
fn a_parser_that_rejects_documented_text_is_a_finding() {
    let args = Run {
        cases: 400,
        seed: 7,
        first: 0,
        max_size: 8,
        paths: 2,
        max_failures: 1,
    };
    PLANTED_TAB_REJECTION.with(|p| p.set(true));
    let t = differential::run_cases::<Letters>(&args, &lpe_engines::all());
    PLANTED_TAB_REJECTION.with(|p| p.set(false));
    assert!(!t.rejected.is_empty(), "no text with a tab in 400 cases");
    for r in &t.rejected {
        assert!(r.text.contains('\t'), "{r:?}");
        assert!(r.case < 400, "{r:?}");
        assert!(r.error.contains("byte 1"), "{r:?}");
    }
    // The cases still ran (a tree in place of each rejected text) and agreed.
    assert!(t.failures.is_empty());
    assert_eq!(t.cases, 400);
}

/// A deliberately wrong engine: it ignores labels in `'g'` items by answering like the
/// reference on the expression with every label item replaced by `.`.
struct LabelBlind;

struct LabelBlindMatcher(Vec<LettersLpe>);

impl Matcher<Letters> for LabelBlindMatcher {
    fn which(&self, path: &LettersPath) -> AovMask {
        (0..self.0.len())
            .filter(|&i| Letters::reference(&self.0[i], path))
            .collect()
    }
}

impl Engine<Letters> for LabelBlind {
    fn name(&self) -> &'static str {
        "label-blind"
    }
    fn compile(
        &self,
        exprs: &[LettersLpe],
        _: &(),
    ) -> Result<Box<dyn Matcher<Letters> + '_>, EngineError> {
        let mut blind = exprs.to_vec();
        for e in &mut blind {
            e.0.operands_mut(&mut |x| {
                x.for_each_atom_mut(&mut |a| {
                    if matches!(a, Atom::Item(Item::Label(_))) {
                        *a = Atom::Item(Item::Any);
                    }
                })
            });
        }
        Ok(Box::new(LabelBlindMatcher(blind)))
    }
}

#[test]
fn a_planted_bug_is_found_and_minimized() {
    let engines: Vec<&dyn Engine<Letters>> = vec![&Reference, &LabelBlind];
    let exprs = [
        lpe("E<BD>[<L.>O]"),
        lpe("unoccluded;E(<BD>|<PS>)*'floor'(.|U2)+[<L.>O]"),
    ];
    let p = path("E BD PS BD'wall' BS1 PS2 L");
    // The right engines agree on it (the oracle refuses).
    assert!(differential::check_set(&exprs, std::slice::from_ref(&p)).is_agreement());
    let Outcome::Disagree(c) = differential::check_with(&engines, &exprs, &[p]) else {
        panic!("the planted bug went unnoticed");
    };
    // Down to the label item against a vertex with another label, between the camera
    // and the emitter, printed in this dialect's letters.
    assert_eq!(c.exprs.len(), 1);
    assert_eq!(c.exprs[0].to_string(), "E'floor'<L.>");
    assert_eq!(Letters::vertices(&c.path).len(), 3, "{}", c.path);
    assert!(c.path.to_string().starts_with("E "), "{}", c.path);
    let text = c.to_string();
    assert!(text.contains("reference: no-match"), "{text}");
    assert!(text.contains("label-blind: match"), "{text}");
    assert!(text.contains("E BD1 PS1 BD1'wall' BS1 PS2 L"), "{text}");
}

/// The front-end comparison of `text` with `faults` planted.
fn compared(faults: FrontFaults, text: &str) -> Option<(front::Finding, String, String)> {
    with_front_faults(faults, || front::compare::<Letters>(text, &(), 1))
}

/// A front-end case of `text`, from the planted tests.
fn planted(text: &str) -> FrontCase<Letters> {
    FrontCase {
        text: text.into(),
        registration: (),
        origin: "planted".into(),
    }
}

/// A meaning finding's path and the two answers (lpe's, the reference's).
fn meaning(found: Option<(front::Finding, String, String)>) -> (String, bool, bool) {
    match found {
        Some((
            front::Finding::Meaning {
                path,
                lpe,
                reference,
            },
            _,
            _,
        )) => (path, lpe, reference),
        other => panic!("not a meaning finding: {other:?}"),
    }
}

/// Without faults the two sides agree: on what both accept and on what both reject.
#[test]
fn the_front_end_comparison_agrees_without_a_fault() {
    for text in ["E<BD>L", "E<BD>[OL]", "E(BD|PS)*L", "E<BD", ")"] {
        assert_eq!(compared(FrontFaults::NONE, text), None, "{text}");
    }
}

/// Each planted fault of the reference side is found as its kind, with what each side
/// read.
#[test]
fn each_planted_front_end_fault_is_found_as_its_kind() {
    // lpe reads E<BD>L (RenderMan's C<RD>L), the reference E<BS>L: a path aimed at
    // either tells them apart, and the two answers differ.
    let found = compared(FrontFaults::READS_D_AS_S, "E<BD>L");
    let (_, l, r) = found.clone().unwrap();
    assert_eq!((l.as_str(), r.as_str()), ("`E<BD>L`", "`E<BS>L`"));
    let (path, ours, reference) = meaning(found);
    assert_ne!(ours, reference, "{path}");
    let on = LettersPath::from_str(&path).unwrap();
    assert_eq!(Letters::reference(&lpe("E<BD>L"), &on), ours, "{path}");
    assert_eq!(Letters::reference(&lpe("E<BS>L"), &on), reference, "{path}");
    // Both reject: no finding, whatever the reference reads.
    assert_eq!(compared(FrontFaults::READS_D_AS_S, "E<BD"), None);

    // The printer writes E<BS>L for the right tree: the matchers agree on every path,
    // lpe's tree and its reading of the print do not; the witness is a path of one.
    let found = compared(FrontFaults::PRINTS_D_AS_S, "E<BD>L");
    let Some((front::Finding::Print { witness }, l, r)) = found else {
        panic!("{found:?}");
    };
    let on = LettersPath::from_str(&witness).unwrap();
    assert_ne!(
        Letters::reference(&lpe("E<BD>L"), &on),
        Letters::reference(&lpe("E<BS>L"), &on),
        "{witness}"
    );
    assert_eq!((l.as_str(), r.as_str()), ("`E<BD>L`", "`E<BS>L`"));

    let paren = FrontFaults {
        prints_a_stray_paren: true,
        ..FrontFaults::NONE
    };
    assert_eq!(
        compared(paren, "E<BD>L"),
        Some((
            front::Finding::Reprint,
            "`E<BD>L`".into(),
            "`E<BD>L)`".into()
        ))
    );

    // One side rejects: an acceptance finding, with the error's byte and message.
    let rejects = FrontFaults::REJECTS_WITHOUT_O;
    assert_eq!(
        compared(rejects, "E<BD>L"),
        Some((
            front::Finding::Acceptance,
            "`E<BD>L`".into(),
            "error at byte 0: planted: no O".into()
        ))
    );
}

/// Meaning is compared on paths up to 1 024 positions (lpe's tree and its re-parse of
/// the print together) and equivalence up to 128; past each, the fault goes unseen by
/// that step, as documented.
#[test]
fn the_front_end_comparison_stops_at_its_position_limits() {
    // E(<BD'a0'>|…|<BD'a{n-1}'>)L: n + 2 positions a side, and short paths (a repeat
    // count would need paths longer than the generator draws).
    let text = |n: u64| {
        let alternatives: Vec<String> = (0..n).map(|i| format!("<BD'a{i}'>")).collect();
        format!("E({})L", alternatives.join("|"))
    };
    assert_eq!(Letters::positions(lpe(&text(2)).first(), None), 4);
    let reads = |n| compared(FrontFaults::READS_D_AS_S, &text(n));
    meaning(reads(510)); // 1 024 positions are compared
    assert_eq!(reads(511), None, "1 026 positions are not");
    let prints = |n| compared(FrontFaults::PRINTS_D_AS_S, &text(n));
    assert!(
        matches!(prints(62), Some((front::Finding::Print { .. }, _, _))),
        "128 positions are checked for equivalence"
    );
    assert_eq!(prints(63), None, "130 positions are not");
}

/// A misreading the generated paths miss (they are shorter than the 32 vertices it takes
/// here) is found by the equivalence step, and its witness, answered differently by the
/// two matchers, is reported as a meaning disagreement, not as a printer one.
#[test]
fn a_misreading_only_a_long_path_shows_is_a_meaning_finding() {
    let (path, ours, reference) = meaning(compared(FrontFaults::READS_D_AS_S, "E<BD>{30}L"));
    assert_eq!(path.split(' ').count(), 32, "{path}");
    assert!(ours && !reference, "{path}");
}

/// A misreading shows in one direction only: a narrower reading (`D` as `D1`) leaves
/// only paths lpe's reading matches and the reference's does not, a wider one (`D1` as
/// `D`) only the reverse. Each is found, with its own pair of answers, both by the drawn
/// paths (an alternation of 70 labelled operands: 144 positions, past the equivalence
/// limit of 128, so only paths can find it) and by the equivalence step (a repeat of 30:
/// paths of 32 vertices, longer than any drawn). The expected answers are worked out by
/// hand from the two readings; the path found is checked on the reference matcher with
/// each reading written out.
///
/// Faults planted in `engines/src/differential/front/compare.rs`, each seen to fail this
/// test and reverted: the drawn paths compared as `a && !b` (blind to reference-only
/// matches) and as `!a && b` (blind to lpe-only ones); paths aimed only at lpe's
/// operands (`l.operands()` alone as targets); the equivalence witness taken from
/// `c.first_only` alone and from `c.second_only` alone; a witness reported as a meaning
/// finding only when `a && !b`.
#[test]
fn a_misreading_in_either_direction_is_found_by_paths_and_by_equivalence() {
    let alternation = |lobe: &str| {
        let alternatives: Vec<String> = (0..70).map(|i| format!("<BD{lobe}'a{i}'>")).collect();
        format!("E({})L", alternatives.join("|"))
    };
    // (fault, text (lpe's reading), the reference's reading, vertices on the path, lpe's
    // answer, the reference's)
    let cases = [
        (
            FrontFaults::READS_D_AS_D1,
            alternation(""),
            alternation("1"),
            3,
            true,
            false,
        ),
        (
            FrontFaults::READS_D1_AS_D,
            alternation("1"),
            alternation(""),
            3,
            false,
            true,
        ),
        (
            FrontFaults::READS_D_AS_D1,
            "E<BD>{30}L".into(),
            "E<BD1>{30}L".into(),
            32,
            true,
            false,
        ),
        (
            FrontFaults::READS_D1_AS_D,
            "E<BD1>{30}L".into(),
            "E<BD>{30}L".into(),
            32,
            false,
            true,
        ),
    ];
    for (faults, text, theirs_read, vertices, want_ours, want_theirs) in cases {
        let (path, ours, reference) = meaning(compared(faults, &text));
        assert_eq!(
            (ours, reference),
            (want_ours, want_theirs),
            "{text}: {path}"
        );
        assert_eq!(path.split(' ').count(), vertices, "{text}: {path}");
        let on = LettersPath::from_str(&path).unwrap();
        assert_eq!(Letters::reference(&lpe(&text), &on), ours, "{path}");
        assert_eq!(
            Letters::reference(&lpe(&theirs_read), &on),
            reference,
            "{path}"
        );
        // The two readings differ only on the lobe of a diffuse vertex: the path's
        // differing vertices are diffuse ones of lobe 2 to 4.
        assert!(
            path.split(' ')
                .any(|v| ["BD2", "BD3", "BD4"].iter().any(|d| v.starts_with(d))),
            "{path}"
        );
    }
    // 70 alternatives, the camera and the emitter: 72 positions a side, 144 together,
    // past the equivalence limit, so it was the drawn paths that found the alternation.
    assert_eq!(Letters::positions(lpe(&alternation("")).first(), None), 72);
}

/// A disagreement is minimized only through texts that disagree the same way: deleting
/// the `O` would turn a print finding into an acceptance one, so the `O` stays. The
/// report shows the minimized text, the original and both readings.
#[test]
fn a_front_end_disagreement_is_minimized_within_its_kind_and_reported() {
    let faults = FrontFaults {
        rejects_text_without_o: true,
        ..FrontFaults::PRINTS_D_AS_S
    };
    let d = with_front_faults(faults, || front::check::<Letters>(&planted("E<BD>[OL]"), 1))
        .expect("found");
    assert!(matches!(d.finding, front::Finding::Print { .. }), "{d}");
    assert!(d.text.len() < d.original.len(), "not minimized: {d}");
    assert!(d.text.contains('O') && d.text.contains('D'), "{d}");
    assert_eq!(d.original, "E<BD>[OL]");
    let shown = d.to_string();
    let lines: Vec<&str> = shown.lines().collect();
    assert_eq!(
        lines[0],
        format!("front ends disagree on `{}` (planted)", d.text)
    );
    assert_eq!(lines[1], "  minimized from `E<BD>[OL]`");
    // No registration line: this dialect registers nothing.
    assert!(
        lines[2].starts_with("  lpe's tree and lpe's reading"),
        "{shown}"
    );
    assert_eq!(lines[3], format!("  lpe reads:       {}", d.lpe));
    assert_eq!(lines[4], format!("  reference reads: {}", d.reference));
    assert_eq!(lines.len(), 5, "{shown}");

    // A text that is already minimal is reported without a "minimized from" line, and a
    // meaning finding names both answers.
    let d = with_front_faults(FrontFaults::READS_D_AS_S, || {
        front::check::<Letters>(&planted("EDL"), 1)
    })
    .expect("found");
    let front::Finding::Meaning {
        lpe: ours,
        reference,
        ..
    } = &d.finding
    else {
        panic!("{d}");
    };
    let word = |m: bool| if m { "match" } else { "no-match" };
    let shown = d.to_string();
    assert!(!shown.contains("minimized from"), "{shown}");
    assert!(
        shown.contains(&format!(
            ": lpe {}, reference {}\n",
            word(*ours),
            word(*reference)
        )),
        "{shown}"
    );
}

/// What [`front::minimize`] promises: no single character and no two adjacent ones can
/// come off its result with a disagreement of the same kind left (checked here by
/// trying every such deletion, independently of its search order).
#[test]
fn a_minimized_front_end_disagreement_is_one_minimal() {
    let no_o = FrontFaults::REJECTS_WITHOUT_O;
    for (faults, text) in [
        (no_o, "E<BD>L'xy'"),
        (FrontFaults::PRINTS_D_AS_S, "E<BD>[OL]"),
        (FrontFaults::READS_D_AS_S, "E(<BD>|<PS>)*[LO]"),
    ] {
        let case = planted(text);
        let d = with_front_faults(faults, || front::check::<Letters>(&case, 1)).expect(text);
        let chars: Vec<char> = d.text.chars().collect();
        for width in 1..=2 {
            for at in 0..=chars.len().saturating_sub(width) {
                let shorter: String = chars[..at].iter().chain(&chars[at + width..]).collect();
                let again = compared(faults, &shorter);
                assert!(
                    !again.as_ref().is_some_and(|(f, _, _)| {
                        std::mem::discriminant(f) == std::mem::discriminant(&d.finding)
                    }),
                    "{text}: `{}` minimized to `{}`, but `{shorter}` still disagrees: {again:?}",
                    d.original,
                    d.text
                );
            }
        }
    }
}

/// Minimization stops after [`front::MINIMIZE_BUDGET`] candidates: a label of 3 000
/// characters, each deletable but only after the few before it were tried, is far
/// from gone when the budget runs out.
#[test]
fn front_end_minimization_stops_at_its_budget() {
    let no_o = FrontFaults::REJECTS_WITHOUT_O;
    let text = format!("E<BD>L'{}'", "x".repeat(3000));
    let d = with_front_faults(no_o, || front::check::<Letters>(&planted(&text), 1)).expect("found");
    assert_eq!(d.finding, front::Finding::Acceptance);
    assert!(d.text.len() < text.len(), "nothing came off");
    assert!(
        d.text.len() > 1000,
        "{} characters left: more than {} candidates were tried",
        d.text.len(),
        front::MINIMIZE_BUDGET
    );
}

/// A run's totals: every case counted once, agreement on rejection split by position
/// (the first three kept as examples, long texts cut at 60 characters), disagreements
/// minimized up to the limit and counted past it.
#[test]
fn a_front_end_run_counts_and_keeps_what_it_found() {
    let no_o = FrontFaults::REJECTS_WITHOUT_O;
    let long = format!("E<{}", "B".repeat(70));
    let texts = [
        "E<BD>L",    // lpe accepts, the reference rejects: disagreement 1
        "E<BS>[LO]", // both accept and agree
        "E<BD",      // both reject, at other positions: example 1
        "E<BO",      // both reject at the same byte (the O passes the fault)
        "EL",        // disagreement 2
        "E<BS>L",    // disagreement 3: past the limit of 2, counted only
        &long,       // both reject, at other positions: example 2, cut
        "E<BDD",     // example 3
        "E<BSS",     // at other positions, past the three examples
    ];
    let cases: Vec<FrontCase<Letters>> = texts.iter().map(|t| planted(t)).collect();
    let t = with_front_faults(no_o, || front::run::<Letters>(cases, 1, 2));
    assert_eq!(t.compared, 9);
    assert_eq!(t.both_rejected, 5);
    assert_eq!(t.other_positions, 4);
    assert_eq!(t.disagreements.len(), 2);
    assert_eq!(t.more, 1);
    assert_eq!(t.count(), 3);
    assert_eq!(
        t.summary(),
        "front ends compared 9 expressions (5 rejected by both, 4 of them at other positions), 3 disagreements"
    );
    let originals: Vec<&str> = t
        .disagreements
        .iter()
        .map(|d| d.original.as_str())
        .collect();
    assert_eq!(originals, ["E<BD>L", "EL"]);
    assert_eq!(t.position_examples.len(), 3);
    let suffix = ", reference at byte 0 (planted: no O)";
    for (example, text) in
        t.position_examples
            .iter()
            .zip(["`E<BD`", &format!("`{}…`", &long[..60]), "`E<BDD`"])
    {
        assert!(
            example.starts_with(&format!("{text}: lpe at byte ")),
            "{example}"
        );
        assert!(example.ends_with(suffix), "{example}");
    }
}

/// The corpus of a dialect's fuzz targets: every file of `fuzz/corpus/<target>/` and
/// `fuzz/regressions/<target>/`, in name order, named by its path; notes (`*.md`) are
/// not expressions.
#[test]
fn the_front_end_corpus_reads_the_fuzz_files_and_skips_notes() {
    let root = std::env::temp_dir().join(format!("lpe-front-corpus-{}", std::process::id()));
    let corpus = root.join("fuzz/corpus/letters");
    let regressions = root.join("fuzz/regressions/letters");
    std::fs::create_dir_all(&corpus).unwrap();
    std::fs::create_dir_all(&regressions).unwrap();
    std::fs::write(corpus.join("b"), "E<BD>L").unwrap();
    std::fs::write(corpus.join("a"), "EL").unwrap();
    std::fs::write(corpus.join("README.md"), "# not an expression").unwrap();
    std::fs::write(regressions.join("crash-1"), "E<BS").unwrap();
    let cases = front::corpus::<Letters>(&root);
    std::fs::remove_dir_all(&root).unwrap();
    let got: Vec<(String, String)> = cases
        .unwrap()
        .into_iter()
        .map(|c| (c.origin, c.text))
        .collect();
    let want = [
        ("fuzz/corpus/letters/a", "EL"),
        ("fuzz/corpus/letters/b", "E<BD>L"),
        ("fuzz/regressions/letters/crash-1", "E<BS"),
    ];
    assert_eq!(
        got,
        want.map(|(o, t)| (o.to_string(), t.to_string())).to_vec()
    );
}
