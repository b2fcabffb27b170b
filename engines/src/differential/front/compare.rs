//! One comparison of the two front ends on one text ([`compare`]), its minimization by
//! deleting characters ([`minimize`]), and the report of a disagreement
//! ([`FrontDisagreement`]); the module doc of [`super`] says what is compared.

use std::fmt;

use lpe::algebra::SetExpr;
use lpe::analysis;
use lpe::rng::SplitMix64 as Rng;
use lpe::AovMask;

use super::case::{FrontCase, FrontEnds};
use crate::adapters::Fast;
use crate::engine::Engine;

/// What kind of disagreement.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Finding {
    /// One side accepts, the other rejects.
    Acceptance,
    /// lpe's parser rejects the reference's printed tree.
    Reprint,
    /// The matchers answer differently on a path.
    Meaning {
        /// The path.
        path: String,
        /// lpe's answer.
        lpe: bool,
        /// The reference's answer.
        reference: bool,
    },
    /// lpe's tree and lpe's re-parse of the reference's print differ, on a path where
    /// the two matchers agree (the reference's printer or lpe's reading of it).
    Print {
        /// A shortest path telling them apart.
        witness: String,
    },
}

impl Finding {
    fn same_kind(&self, other: &Finding) -> bool {
        std::mem::discriminant(self) == std::mem::discriminant(other)
    }
}

/// A disagreement between the two front ends, minimized.
#[derive(Clone, Debug)]
pub struct FrontDisagreement {
    /// Where the expression came from.
    pub origin: String,
    /// The registration, as a report line (empty: nothing registered).
    pub context: String,
    /// The text as found.
    pub original: String,
    /// The shortest text found that still disagrees the same way.
    pub text: String,
    /// What disagrees.
    pub finding: Finding,
    /// What lpe's parser made of `text`: its canonical print or its error.
    pub lpe: String,
    /// What the reference front end made of it: its print or its error.
    pub reference: String,
}

impl fmt::Display for FrontDisagreement {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "front ends disagree on `{}` ({})",
            self.text, self.origin
        )?;
        if self.text != self.original {
            writeln!(f, "  minimized from `{}`", self.original)?;
        }
        if !self.context.is_empty() {
            writeln!(f, "  {}", self.context)?;
        }
        match &self.finding {
            Finding::Acceptance => writeln!(f, "  one side accepts, the other rejects")?,
            Finding::Reprint => writeln!(f, "  lpe rejects the reference's printed tree")?,
            Finding::Meaning {
                path,
                lpe,
                reference,
            } => writeln!(
                f,
                "  on `{path}`: lpe {}, reference {}",
                answer(*lpe),
                answer(*reference)
            )?,
            Finding::Print { witness } => writeln!(
                f,
                "  lpe's tree and lpe's reading of the reference's print differ on `{witness}`"
            )?,
        }
        writeln!(f, "  lpe reads:       {}", self.lpe)?;
        write!(f, "  reference reads: {}", self.reference)
    }
}

fn answer(m: bool) -> &'static str {
    if m {
        "match"
    } else {
        "no-match"
    }
}

/// A side's reading as a report line.
fn reading<T: fmt::Display>(r: &Result<T, (usize, String)>) -> String {
    match r {
        Ok(t) => format!("`{t}`"),
        Err((pos, msg)) => format!("error at byte {pos}: {msg}"),
    }
}

/// Past this many atom positions (lpe's tree and its re-parse of the reference's print
/// together, after unrolling) [`compare`] checks acceptance and the reprint only: the
/// fuzz corpora hold expressions whose matching and analysis take seconds each.
pub const MAX_COMPARED_POSITIONS: u64 = 1024;

/// Past this many positions [`compare`] skips the equivalence check (a product search).
pub const MAX_EQUIVALENCE_POSITIONS: u64 = 128;

/// Paths generated per operand by [`compare`].
pub const PATHS_PER_OPERAND: usize = 12;

/// Compares the two front ends on `text`: `None` when they agree, else the finding and
/// what each side read.
pub fn compare<D: FrontEnds>(
    text: &str,
    registration: &D::Registration,
    seed: u64,
) -> Option<(Finding, String, String)> {
    let ours = D::parse(text, registration);
    let theirs = D::reference_parse(text, registration);
    let lpe_side = reading(&ours.as_ref().map_err(D::parse_error));
    let ref_side = reading(
        &theirs
            .as_ref()
            .map(|t| D::reference_print(t))
            .map_err(Clone::clone),
    );
    let (l, r) = match (ours, theirs) {
        (Err(_), Err(_)) => return None,
        (Ok(_), Err(_)) | (Err(_), Ok(_)) => {
            return Some((Finding::Acceptance, lpe_side, ref_side))
        }
        (Ok(l), Ok(r)) => (l, r),
    };
    let found = |f: Finding| Some((f, lpe_side.clone(), ref_side.clone()));
    let Ok(again) = D::parse(&D::reference_print(&r), registration) else {
        return found(Finding::Reprint);
    };
    let size: u64 = l
        .operands()
        .into_iter()
        .chain(again.operands())
        .map(|e| D::positions(e, None))
        .fold(0, u64::saturating_add);
    if size > MAX_COMPARED_POSITIONS {
        return None;
    }
    // lpe's answers from its AOV set; without one (over a limit) paths are not compared.
    let fast = Engine::<D>::compile(&Fast, std::slice::from_ref(&l), registration).ok();
    let lpe_answer = |p: &D::Path| fast.as_ref().map(|m| m.which(p) != AovMask::EMPTY);
    let mut rng = Rng::new(seed ^ fnv(text));
    let cfg = D::config(16);
    let targets: Vec<&D::Expr> = l.operands().into_iter().chain(again.operands()).collect();
    for target in targets {
        for _ in 0..PATHS_PER_OPERAND {
            let p = D::biased_path(target, &mut rng, registration, &cfg);
            let Some(a) = lpe_answer(&p) else { break };
            let b = D::reference(&r, &p);
            if a != b {
                return found(Finding::Meaning {
                    path: p.to_string(),
                    lpe: a,
                    reference: b,
                });
            }
        }
    }
    if size > MAX_EQUIVALENCE_POSITIONS {
        return None;
    }
    if let Ok(c) = analysis::compare::<D, D::Lpe>(&l, &again) {
        if let Some(w) = c.first_only.or(c.second_only) {
            let b = D::reference(&r, &w);
            return match lpe_answer(&w) {
                Some(a) if a != b => found(Finding::Meaning {
                    path: w.to_string(),
                    lpe: a,
                    reference: b,
                }),
                _ => found(Finding::Print {
                    witness: w.to_string(),
                }),
            };
        }
    }
    None
}

/// FNV-1a of the text, so each text draws its own paths under one seed.
fn fnv(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// Most candidate texts [`minimize`] tries.
pub const MINIMIZE_BUDGET: usize = 4000;

/// Shortens `text` while [`compare`] still finds a disagreement of the same kind as
/// `finding`: deletes one character, then two adjacent ones, anywhere, greedily, until
/// no deletion keeps it (or [`MINIMIZE_BUDGET`] candidates were tried).
pub fn minimize<D: FrontEnds>(
    text: &str,
    registration: &D::Registration,
    seed: u64,
    finding: &Finding,
) -> String {
    let mut cur = text.to_string();
    let mut budget = MINIMIZE_BUDGET;
    'shorter: loop {
        let bounds: Vec<usize> = cur.char_indices().map(|(i, _)| i).collect();
        for width in 1..=2 {
            for (k, &at) in bounds.iter().enumerate() {
                let end = match bounds.get(k + width) {
                    Some(&end) => end,
                    None if k + width == bounds.len() => cur.len(),
                    None => continue,
                };
                if budget == 0 {
                    break 'shorter;
                }
                budget -= 1;
                let candidate = format!("{}{}", &cur[..at], &cur[end..]);
                if compare::<D>(&candidate, registration, seed)
                    .is_some_and(|(f, _, _)| f.same_kind(finding))
                {
                    cur = candidate;
                    continue 'shorter;
                }
            }
        }
        break;
    }
    cur
}

/// Compares one case and, on a disagreement, minimizes it.
pub fn check<D: FrontEnds>(case: &FrontCase<D>, seed: u64) -> Option<FrontDisagreement> {
    let (finding, _, _) = compare::<D>(&case.text, &case.registration, seed)?;
    let text = minimize::<D>(&case.text, &case.registration, seed, &finding);
    let (finding, lpe, reference) = compare::<D>(&text, &case.registration, seed)
        .unwrap_or_else(|| unreachable!("a minimized text keeps its disagreement"));
    Some(FrontDisagreement {
        origin: case.origin.clone(),
        context: D::context(&case.registration),
        original: case.text.clone(),
        text,
        finding,
        lpe,
        reference,
    })
}
