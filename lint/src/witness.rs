//! Re-checking analysis witnesses with the reference matcher before printing them.
//!
//! The analysis in `lpe` builds witnesses from its own automata; printing one that the
//! executable semantics disagrees with would present an engine bug as a fact about the
//! user's expressions. So every witness goes through [`recheck`] first, and a failure is
//! reported as an internal disagreement (`lpe-check` exits 3), not as the answer.

use lpe::renderman::Lpe;
use lpe::{Dialect, DialectLpe};

/// A dialect whose expressions the reference matcher reads: the executable semantics
/// every witness is re-checked against. Implemented on `lpe`'s dialect markers
/// ([`crate::check::dialect::renderman`], [`crate::check::dialect::osl`]).
pub trait Checked: Dialect {
    /// The reference matcher's answer for `lpe` on `path`.
    fn reference_match(lpe: &Self::Lpe, path: &Self::Path) -> bool;
}

/// The path type of the dialect of the expression `L`.
pub type PathOf<L> = <<L as DialectLpe>::Dialect as Dialect>::Path;

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
pub fn recheck<L>(path: &PathOf<L>, expects: &[Expect<'_, L>]) -> Result<(), Disagreement>
where
    L: DialectLpe,
    L::Dialect: Checked,
{
    for e in expects {
        let got = L::Dialect::reference_match(e.lpe, path);
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

/// Re-checks both witnesses of a comparison of `a` (named `a_name`) with `b`: the path
/// only `a` matches, and the path only `b` matches, each as claimed.
pub fn recheck_comparison<L>(
    (a_name, a): (&str, &L),
    (b_name, b): (&str, &L),
    c: &lpe::analysis::Comparison<PathOf<L>>,
) -> Result<(), Disagreement>
where
    L: DialectLpe,
    L::Dialect: Checked,
{
    for (path, in_a) in [(&c.first_only, true), (&c.second_only, false)] {
        if let Some(path) = path {
            recheck(
                path,
                &[
                    Expect {
                        name: a_name,
                        lpe: a,
                        matches: in_a,
                    },
                    Expect {
                        name: b_name,
                        lpe: b,
                        matches: !in_a,
                    },
                ],
            )?;
        }
    }
    Ok(())
}
