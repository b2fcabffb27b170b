//! RenderMan on this crate's seams: its [`EngineDialect`] (the reference matcher of
//! `lpe_reference`, the oracle's translation of `regex/translate.rs`, the shrinker's
//! moves) and its generators ([`Generate`], `lpe_testkit::generate`).

use lpe::renderman::{Error, Expr, Lpe, Parser, Path, Prefixes, RenderMan};
use lpe_testkit::generate::{self, Choices, Config};
use lpe_testkit::grammar::{self, Coverage};

use crate::dialect::EngineDialect;
use crate::differential::shrink;
use crate::differential::Generate;
use crate::engine::EngineError;
use crate::regex::{self, Translation};

impl EngineDialect for RenderMan {
    fn reference(lpe: &Lpe, path: &Path) -> bool {
        lpe_reference::is_match(lpe, path)
    }

    fn oracle(exprs: &[Lpe]) -> Result<Translation<RenderMan>, EngineError> {
        let (labels, hirs) = regex::translate(exprs)?;
        Ok(Translation {
            encoder: Box::new(labels),
            hirs,
        })
    }

    /// The expression's shrinks without prefixes ([`shrink::shrink_lpe`]), then the same
    /// expression without them (prefixes never affect matching; dropping them helps
    /// reading).
    fn shrink_expr(e: &Lpe, _: &Parser) -> Vec<Lpe> {
        let mut out = shrink::shrink_lpe(e);
        if !e.prefixes.is_empty() {
            let mut bare = e.clone();
            bare.prefixes = Prefixes::NONE;
            out.push(bare);
        }
        out
    }

    fn shrink_path(p: &Path) -> Vec<Path> {
        shrink::shrink_path(p)
    }

    fn parse_error(e: &Error) -> (usize, String) {
        (e.span().start, e.message().to_string())
    }
}

/// Generated cases parse with the default parser (no macros, default limits): the
/// registration draws nothing.
impl Generate for RenderMan {
    type Config = Config;

    fn config(max_size: usize) -> Config {
        Config::default().with_max_atoms(max_size)
    }

    fn without_set_algebra(cfg: Config) -> Config {
        cfg.without_set_algebra()
    }

    fn registration(_: &mut impl Choices) -> Parser {
        Parser::default()
    }

    fn lpe(c: &mut impl Choices, _: &Parser, cfg: &Config) -> Lpe {
        generate::lpe(c, cfg)
    }

    fn productions() -> &'static [&'static str] {
        grammar::renderman::PRODUCTIONS
    }

    fn text(c: &mut impl Choices, _: &Parser, cfg: &Config, coverage: &mut Coverage) -> String {
        let bounds = grammar::Config {
            max_units: cfg.max_atoms,
            set_algebra: cfg.set_algebra,
            ..grammar::Config::default()
        };
        grammar::renderman::source(c, &bounds, coverage)
    }

    fn biased_path(target: &Expr, c: &mut impl Choices, _: &Parser, cfg: &Config) -> Path {
        generate::biased_path(target, c, cfg)
    }
}
