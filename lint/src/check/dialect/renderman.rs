//! RenderMan's dialect as lint sees it: the parser's own error with its span and hint,
//! the labels and lobes [`crate::check::labels`] finds, the lobe mappings of the ini
//! files, and prefixes that change what an AOV accumulates.

use lpe::renderman::{LobeCategory, LobeMap, Lpe, Parser, Path, RenderMan};

use super::{LintDialect, ParseFailure};
use crate::check::labels::{self, Carrier};
use crate::witness::Checked;

impl Checked for RenderMan {
    fn reference_match(lpe: &Lpe, path: &Path) -> bool {
        lpe_reference::is_match(lpe, path)
    }
}

impl LintDialect for RenderMan {
    type Lobes = LobeMap;

    fn parse_source(src: &str, parser: &Parser) -> Result<Lpe, ParseFailure> {
        parser.parse(src).map_err(|e| ParseFailure {
            message: e.message().to_string(),
            source: e.source_text().to_string(),
            span: e.span(),
            help: e.help().map(str::to_string),
        })
    }

    fn labels(e: &Lpe) -> Vec<(Carrier, String)> {
        labels::labels(e)
    }

    fn unfed_lobes(e: &Lpe, lobes: &LobeMap) -> Vec<(LobeCategory, u8)> {
        labels::lobes(e)
            .into_iter()
            .filter(|&(c, n)| !lobes.is_fed(c, n))
            .collect()
    }

    fn accumulate_alike(a: &Lpe, b: &Lpe) -> bool {
        a.prefixes == b.prefixes
    }
}
