//! What a disagreement reports, and how it prints.

use std::fmt;

use lpe::Dialect;

use crate::dialect::WireDialect;

/// Engines that disagree, on a minimized input.
#[derive(Clone, Debug)]
pub struct Counterexample<D: Dialect> {
    /// What the expressions were parsed under (OSL's registered labels), printed as
    /// the report's context line ([`WireDialect::context`]).
    pub registration: D::Registration,
    /// The minimized expressions (one for [`check`](super::check())).
    pub exprs: Vec<D::Lpe>,
    /// The minimized path.
    pub path: D::Path,
    /// Each engine's answer per expression on `path`, or why it could not build.
    pub answers: Vec<(&'static str, Result<Vec<bool>, String>)>,
    /// The input before minimization.
    pub original: (Vec<D::Lpe>, D::Path),
}

impl<D: WireDialect> fmt::Display for Counterexample<D> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "engines disagree (minimized):")?;
        let context = D::context(&self.registration);
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
