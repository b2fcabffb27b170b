//! RenderMan on this crate's seams: the dialect traits of [`crate::dialect`] (the
//! reference matcher of `lpe_reference`, the oracle's translation of `regex/renderman/`,
//! the shrinker's moves of `differential/shrink/renderman.rs`, parse errors as the
//! external protocol compares them), its front ends ([`FrontEnds`]) and its generators
//! ([`Generate`], `lpe_testkit::generate`).

use lpe::renderman::macros::MacroTable;
use lpe::renderman::{Error, Expr, Lpe, Parser, Path, Prefixes, RenderMan};
use lpe_testkit::generate::{self, Choices, Config};
use lpe_testkit::grammar::{self, Coverage};

use lpe::renderman::Config as Ini;
use lpe::DialectName;
use lpe_testkit::suite::Loaded;

use crate::dialect::{OracleDialect, ReferenceDialect, ShrinkDialect, Translation, WireDialect};
use crate::differential::front::{constructs, FrontEnds};
use crate::differential::shrink::renderman as shrink;
use crate::differential::Generate;
use crate::error::EngineError;
use crate::regex::renderman as oracle;

impl ReferenceDialect for RenderMan {
    type ReferenceTree = lpe_reference::renderman::Lpe;

    /// lpe's print has its macros expanded; the user macros go along anyway (as plain
    /// name-to-text data), with the parser's limits.
    fn reference_tree(
        lpe: &Lpe,
        parser: &Parser,
    ) -> Result<lpe_reference::renderman::Lpe, EngineError> {
        let text = lpe.to_string();
        lpe_reference::renderman::parse(&text, &reference_registration(parser)).map_err(|e| {
            EngineError::Reference {
                text,
                why: e.to_string(),
            }
        })
    }

    fn reference(tree: &lpe_reference::renderman::Lpe, path: &Path) -> bool {
        lpe_reference::renderman::is_match(tree, path)
    }
}

impl OracleDialect for RenderMan {
    fn oracle(exprs: &[Lpe]) -> Result<Translation<RenderMan>, EngineError> {
        let (labels, hirs) = oracle::translate(exprs)?;
        Ok(Translation {
            encoder: Box::new(labels),
            hirs,
        })
    }
}

impl ShrinkDialect for RenderMan {
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
}

/// Nothing registered travels: the parser's macros are expanded in the printed trees.
impl WireDialect for RenderMan {
    fn parse_error(e: &Error) -> (usize, String) {
        (e.span().start, e.message().to_string())
    }
}

/// The reference front end on text, its printer, and RenderMan's corpora.
impl FrontEnds for RenderMan {
    fn reference_parse(
        text: &str,
        parser: &Parser,
    ) -> Result<lpe_reference::renderman::Lpe, (usize, String)> {
        lpe_reference::renderman::parse(text, &reference_registration(parser))
            .map_err(|e| (e.pos, e.message))
    }

    fn reference_print(tree: &lpe_reference::renderman::Lpe) -> String {
        tree.to_string()
    }

    fn suite_registration(case: &Loaded) -> Option<Parser> {
        if case.dialect != DialectName::RenderMan {
            return None;
        }
        match &case.case.ini {
            None => Some(Parser::default()),
            Some(text) => Ini::from_ini(text).ok().map(|c| c.parser()),
        }
    }

    const FUZZ_TARGETS: &'static [&'static str] = &["parse"];

    /// [`constructs::RENDERMAN`], each under the parser of its `rendermn.ini` text.
    fn constructs() -> Vec<(Parser, String)> {
        constructs::RENDERMAN
            .iter()
            .map(|(ini, text)| {
                let parser = Ini::from_ini(ini)
                    .unwrap_or_else(|e| panic!("construct ini `{ini}`: {e}"))
                    .parser();
                (parser, text.to_string())
            })
            .collect()
    }
}

/// What a RenderMan parser is registered with, as the reference front end takes it:
/// the user macros (those of the parser's table that are not built-ins with their
/// built-in text) and the limits, as plain data.
pub fn reference_registration(parser: &Parser) -> lpe_reference::renderman::Registration {
    let builtin = MacroTable::builtin();
    let macros = parser
        .macros()
        .iter()
        .filter(|(name, src)| builtin.get(name) != Some(*src))
        .map(|(name, src)| (name.to_string(), src.to_string()))
        .collect();
    let l = parser.limits();
    lpe_reference::renderman::Registration {
        macros,
        limits: lpe_reference::Limits {
            max_repeat: l.max_repeat,
            max_positions: l.max_positions as u64,
            max_depth: l.max_depth,
            max_macro_depth: l.max_macro_depth,
        },
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
