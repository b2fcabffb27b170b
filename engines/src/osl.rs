//! OSL on this crate's seams: the dialect traits of [`crate::dialect`] (the
//! symbol-stream reference matcher of `lpe_reference::osl`, the oracle's translation of
//! `regex/osl.rs`, the shrinker's moves of `differential/shrink/osl.rs`, its registered
//! labels in reports, on the wire and in fuzz inputs), its front ends ([`FrontEnds`])
//! and its generators ([`Generate`], `lpe_testkit::generate::osl`).

use lpe::osl::{Error, Expr, Lpe, Osl, Path, Registered};
use lpe_testkit::generate::{self, Choices};
use lpe_testkit::grammar::{self, Coverage};

use lpe::DialectName;
use lpe_testkit::suite::Loaded;

use crate::dialect::{
    OracleDialect, ReferenceDialect, ShrinkDialect, Translation, WireDialect, WireRegistration,
};
use crate::differential::front::{constructs, FrontEnds};
use crate::differential::shrink;
use crate::differential::Generate;
use crate::error::EngineError;
use crate::regex::osl as oracle;

impl ReferenceDialect for Osl {
    type ReferenceTree = lpe_reference::osl::Lpe;

    fn reference_tree(
        lpe: &Lpe,
        registered: &Registered,
    ) -> Result<lpe_reference::osl::Lpe, EngineError> {
        // A renderer's prefix (`unoccluded;`) changes what accumulates, never what
        // matches, and OSL's grammar has none: the reference reads the expression alone.
        let text = match &lpe.prefix {
            None => lpe.to_string(),
            Some(_) => Lpe {
                prefix: None,
                ..lpe.clone()
            }
            .to_string(),
        };
        lpe_reference::osl::parse(&text, &reference_registration(registered)).map_err(|e| {
            EngineError::Reference {
                text,
                why: e.to_string(),
            }
        })
    }

    fn reference(tree: &lpe_reference::osl::Lpe, path: &Path) -> bool {
        lpe_reference::osl::is_match(tree, path)
    }
}

impl OracleDialect for Osl {
    fn oracle(exprs: &[Lpe]) -> Result<Translation<Osl>, EngineError> {
        let (symbols, hirs) = oracle::translate(exprs)?;
        Ok(Translation {
            encoder: Box::new(symbols),
            hirs,
        })
    }
}

impl ShrinkDialect for Osl {
    fn shrink_expr(e: &Lpe, registered: &Registered) -> Vec<Lpe> {
        let basic = registered.basic_labels();
        shrink::shrink_set_expr(
            e,
            |x| shrink::osl::shrink_expr(x, &basic),
            Lpe::from_algebra,
        )
    }

    fn shrink_path(p: &Path) -> Vec<Path> {
        shrink::osl::shrink_path(p)
    }
}

impl WireDialect for Osl {
    fn context(registered: &Registered) -> String {
        format!("registered: {registered}")
    }

    /// Always sent, empty lists when nothing is registered: an OSL matcher's
    /// registration is per set.
    fn wire_registration(registered: &Registered) -> Option<WireRegistration> {
        Some(WireRegistration::from(registered))
    }

    fn parse_error(e: &Error) -> (usize, String) {
        (e.pos, e.message())
    }

    fn registration_line(line: &str) -> Option<Registered> {
        line.parse().ok()
    }

    /// The trees only: warnings carry source positions, which reprinting moves.
    fn same_tree(a: &Lpe, b: &Lpe) -> bool {
        a.expr == b.expr
    }
}

/// OSL's registered labels as a `compile` request carries them.
impl From<&Registered> for WireRegistration {
    fn from(r: &Registered) -> WireRegistration {
        WireRegistration {
            events: r.events.clone(),
            scatters: r.scatters.clone(),
        }
    }
}

/// The reference front end on text, its printer, and OSL's corpora.
impl FrontEnds for Osl {
    fn reference_parse(
        text: &str,
        registered: &Registered,
    ) -> Result<lpe_reference::osl::Lpe, (usize, String)> {
        lpe_reference::osl::parse(text, &reference_registration(registered))
            .map_err(|e| (e.pos, e.message))
    }

    fn reference_print(tree: &lpe_reference::osl::Lpe) -> String {
        tree.to_string()
    }

    fn suite_registration(case: &Loaded) -> Option<Registered> {
        (case.dialect == DialectName::Osl).then(|| case.registered.clone())
    }

    const FUZZ_TARGETS: &'static [&'static str] = &["osl_parse"];

    /// [`constructs::OSL`], each under its registration text.
    fn constructs() -> Vec<(Registered, String)> {
        constructs::OSL
            .iter()
            .map(|(reg, text)| {
                let registered = reg
                    .parse()
                    .unwrap_or_else(|e| panic!("construct registration `{reg}`: {e}"));
                (registered, text.to_string())
            })
            .collect()
    }
}

/// OSL's registered labels as the reference front end takes them: plain strings, with
/// the default limits.
pub fn reference_registration(registered: &Registered) -> lpe_reference::osl::Registration {
    lpe_reference::osl::Registration {
        events: registered.events.clone(),
        scatters: registered.scatters.clone(),
        prefixes: registered.prefixes.clone().unwrap_or_default(),
        builtins: registered.builtins.clone(),
        limits: lpe_reference::Limits::default(),
    }
}

impl Generate for Osl {
    type Config = generate::osl::Config;

    fn config(max_size: usize) -> Self::Config {
        generate::osl::Config::default().with_max_vertices(max_size)
    }

    fn without_set_algebra(cfg: Self::Config) -> Self::Config {
        cfg.without_set_algebra()
    }

    fn registration(c: &mut impl Choices) -> Registered {
        generate::osl::registered(c)
    }

    fn lpe(c: &mut impl Choices, registered: &Registered, cfg: &Self::Config) -> Lpe {
        generate::osl::lpe(c, registered, cfg)
    }

    fn productions() -> &'static [&'static str] {
        grammar::osl::PRODUCTIONS
    }

    fn text(
        c: &mut impl Choices,
        registered: &Registered,
        cfg: &Self::Config,
        coverage: &mut Coverage,
    ) -> String {
        let bounds = grammar::Config {
            max_units: cfg.max_vertices,
            set_algebra: cfg.set_algebra,
            ..grammar::Config::default()
        };
        let shorthand = grammar::osl::Shorthand::of(&registered.events, &registered.scatters);
        grammar::osl::source(c, &shorthand, &bounds, coverage)
    }

    fn biased_path(
        target: &Expr,
        c: &mut impl Choices,
        registered: &Registered,
        cfg: &Self::Config,
    ) -> Path {
        generate::osl::biased_path(target, c, registered, cfg)
    }
}
