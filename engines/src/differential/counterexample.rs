//! What a disagreement reports, and how it prints.

use std::fmt;

use super::language::{Language, RenderMan};

/// Engines that disagree, on a minimized input.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Counterexample<L: Language = RenderMan> {
    /// The dialect, with what the expressions share (OSL's registered labels).
    pub lang: L,
    /// The minimized expressions (one for [`check`](super::check())).
    pub exprs: Vec<L::Expr>,
    /// The minimized path.
    pub path: L::Path,
    /// Each engine's answer per expression on `path`, or why it could not build.
    pub answers: Vec<(&'static str, Result<Vec<bool>, String>)>,
    /// The input before minimization.
    pub original: (Vec<L::Expr>, L::Path),
}

impl<L: Language> fmt::Display for Counterexample<L> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "engines disagree (minimized):")?;
        let context = self.lang.context();
        if !context.is_empty() {
            writeln!(f, "  {context}")?;
        }
        for (i, e) in self.exprs.iter().enumerate() {
            writeln!(f, "  expression {i}: {e}")?;
        }
        writeln!(f, "  path:         {}", self.path)?;
        for (name, answer) in &self.answers {
            match answer {
                Ok(bits) => {
                    let shown: Vec<&str> = bits
                        .iter()
                        .map(|&b| if b { "match" } else { "no-match" })
                        .collect();
                    writeln!(f, "  {name:>12}: {}", shown.join(" "))?;
                }
                Err(why) => writeln!(f, "  {name:>12}: skipped ({why})")?,
            }
        }
        writeln!(f, "  from the original case:")?;
        for (i, e) in self.original.0.iter().enumerate() {
            writeln!(f, "    expression {i}: {e}")?;
        }
        write!(f, "    path:         {}", self.original.1)
    }
}
