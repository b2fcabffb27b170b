//! What the external harness needs of a dialect beyond [`Language`]: its name in
//! `hello`, how the texts it sends parse on lpe's side, what a `compile` request carries
//! besides the AOVs, and the arguments that restore a case in a replay command.

use lpe::osl;
use lpe::DialectName;

use super::protocol::Registration;
use crate::differential::{Language, Osl, RenderMan};

/// A dialect as the external harness speaks it.
pub trait Wire: Language {
    /// The dialect of `hello`.
    fn dialect(&self) -> DialectName;

    /// An expression parsed as the CLI parses it, or where and why not.
    fn parse_expr(&self, src: &str) -> Result<Self::Expr, (usize, String)>;

    /// A path in the dialect's text form.
    fn parse_path(&self, src: &str) -> Option<Self::Path>;

    /// What a `compile` request carries besides the AOVs.
    fn registration(&self) -> Option<Registration>;

    /// `lpe-check diff` arguments that restore this context in a replay.
    fn replay_args(&self) -> Vec<String>;
}

impl Wire for RenderMan {
    fn dialect(&self) -> DialectName {
        DialectName::RenderMan
    }

    fn parse_expr(&self, src: &str) -> Result<lpe::renderman::Lpe, (usize, String)> {
        lpe::renderman::parse(src).map_err(|e| (e.span().start, e.message().to_string()))
    }

    fn parse_path(&self, src: &str) -> Option<lpe::renderman::Path> {
        src.parse().ok()
    }

    fn registration(&self) -> Option<Registration> {
        None
    }

    fn replay_args(&self) -> Vec<String> {
        Vec::new()
    }
}

impl Wire for Osl {
    fn dialect(&self) -> DialectName {
        DialectName::Osl
    }

    fn parse_expr(&self, src: &str) -> Result<osl::Lpe, (usize, String)> {
        osl::parse(src, &self.registered).map_err(|e| (e.pos, e.message()))
    }

    fn parse_path(&self, src: &str) -> Option<osl::Path> {
        src.parse().ok()
    }

    /// Always sent, empty lists when nothing is registered: an OSL matcher's
    /// registration is per set.
    fn registration(&self) -> Option<Registration> {
        Some(Registration::from(&self.registered))
    }

    fn replay_args(&self) -> Vec<String> {
        if self.registered == osl::Registered::none() {
            Vec::new()
        } else {
            vec!["--register".into(), self.registered.to_string()]
        }
    }
}
