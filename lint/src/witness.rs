//! Re-checking analysis witnesses with the reference matcher before printing them.
//!
//! The analysis in `lpe` builds witnesses from its own automata; printing one that the
//! executable semantics disagrees with would present an engine bug as a fact about the
//! user's expressions. So every witness goes through [`recheck`] first, and a failure is
//! reported as an internal disagreement (`lpe-check` exits 3), not as the answer.

use std::fmt::Display;

use lpe::osl;
use lpe::renderman::{Lpe, Path};

/// An expression of either dialect, as the reference matcher of its dialect reads it.
pub trait Checked: Display {
    /// The dialect's path.
    type Path: Display;
    /// The reference matcher's answer on `path`.
    fn reference_match(&self, path: &Self::Path) -> bool;
    /// The expression that closes a partition's gap: the universe minus every AOV.
    fn remainder(aovs: &[(String, Self)], universe: &Self) -> Self
    where
        Self: Sized;
}

impl Checked for Lpe {
    type Path = Path;
    fn reference_match(&self, path: &Path) -> bool {
        lpe_reference::is_match(self, path)
    }
    fn remainder(aovs: &[(String, Lpe)], universe: &Lpe) -> Lpe {
        lpe::analysis::remainder(aovs, universe)
    }
}

impl Checked for osl::Lpe {
    type Path = osl::Path;
    fn reference_match(&self, path: &osl::Path) -> bool {
        lpe_reference::osl::is_match(self, path)
    }
    fn remainder(aovs: &[(String, osl::Lpe)], universe: &osl::Lpe) -> osl::Lpe {
        lpe::analysis::remainder(aovs, universe)
    }
}

/// What one expression must answer on a witness.
pub struct Expect<'a, E = Lpe> {
    /// Display name of the expression.
    pub name: &'a str,
    /// The expression.
    pub lpe: &'a E,
    /// Whether it must match.
    pub matches: bool,
}

/// A witness the reference matcher does not confirm: an engine bug, not an answer.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "internal disagreement: the analysis says `{name}` {} `{path}`, the reference \
     matcher says it {} (please report this)",
    if *.claimed { "matches" } else { "does not match" },
    if *.claimed { "does not" } else { "does" }
)]
pub struct Disagreement {
    /// Display name of the expression.
    pub name: String,
    /// The witness, as text.
    pub path: String,
    /// Whether the analysis claimed the expression matches the witness (the reference
    /// says the opposite).
    pub claimed: bool,
}

/// `Ok` if the reference agrees with every expectation on `path`, else the first
/// expression it disagrees on.
pub fn recheck<E: Checked>(path: &E::Path, expects: &[Expect<'_, E>]) -> Result<(), Disagreement> {
    for e in expects {
        let got = e.lpe.reference_match(path);
        if got != e.matches {
            return Err(Disagreement {
                name: e.name.to_string(),
                path: path.to_string(),
                claimed: e.matches,
            });
        }
    }
    Ok(())
}
