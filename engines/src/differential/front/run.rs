//! A front-end comparison run over many texts: [`run`] and its [`FrontTotals`].

use super::case::{FrontCase, FrontEnds};
use super::compare::{check, compare, FrontDisagreement};

/// Totals of a front-end comparison run.
#[derive(Debug, Default)]
pub struct FrontTotals {
    /// Expressions compared.
    pub compared: u64,
    /// Of those, rejected by both front ends (agreement).
    pub both_rejected: u64,
    /// Of those, rejected at different byte positions (still agreement: each side
    /// reports where its own reading failed).
    pub other_positions: u64,
    /// The first few of those: the text, lpe's error and the reference's.
    pub position_examples: Vec<String>,
    /// The disagreements, minimized (the first ones of the run).
    pub disagreements: Vec<FrontDisagreement>,
    /// Disagreements found after the kept ones (counted, not minimized).
    pub more: u64,
}

impl FrontTotals {
    /// The report line of `lpe-check diff`.
    pub fn summary(&self) -> String {
        format!(
            "front ends compared {} expressions ({} rejected by both, {} of them at other positions), {} disagreements",
            self.compared,
            self.both_rejected,
            self.other_positions,
            self.count()
        )
    }

    /// Every disagreement found, kept or not.
    pub fn count(&self) -> u64 {
        self.disagreements.len() as u64 + self.more
    }
}

/// How many rejections at other positions [`FrontTotals`] keeps as examples.
pub const POSITION_EXAMPLES: usize = 3;

/// Compares every case; keeps at most `max_disagreements` (minimizing each).
pub fn run<D: FrontEnds>(
    cases: impl IntoIterator<Item = FrontCase<D>>,
    seed: u64,
    max_disagreements: usize,
) -> FrontTotals {
    let mut t = FrontTotals::default();
    for case in cases {
        t.compared += 1;
        if let (Err(a), Err((b, why))) = (
            D::parse(&case.text, &case.registration),
            D::reference_parse(&case.text, &case.registration),
        ) {
            t.both_rejected += 1;
            let (a, lpe_why) = D::parse_error(&a);
            if a != b {
                t.other_positions += 1;
                if t.position_examples.len() < POSITION_EXAMPLES {
                    let mut shown: String = case.text.chars().take(60).collect();
                    if shown.len() < case.text.len() {
                        shown.push('…');
                    }
                    t.position_examples.push(format!(
                        "`{shown}`: lpe at byte {a} ({lpe_why}), reference at byte {b} ({why})"
                    ));
                }
            }
            continue;
        }
        if t.disagreements.len() < max_disagreements {
            if let Some(d) = check::<D>(&case, seed) {
                t.disagreements.push(d);
            }
        } else if compare::<D>(&case.text, &case.registration, seed).is_some() {
            t.more += 1;
        }
    }
    t
}
