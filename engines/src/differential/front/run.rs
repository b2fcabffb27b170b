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
    /// The disagreements, minimized (the first ones of the run).
    pub disagreements: Vec<FrontDisagreement>,
    /// Disagreements found after the kept ones (counted, not minimized).
    pub more: u64,
}

impl FrontTotals {
    /// The report line of `lpe-check diff`.
    pub fn summary(&self) -> String {
        format!(
            "front ends compared {} expressions ({} rejected by both), {} disagreements",
            self.compared,
            self.both_rejected,
            self.count()
        )
    }

    /// Every disagreement found, kept or not.
    pub fn count(&self) -> u64 {
        self.disagreements.len() as u64 + self.more
    }
}

/// Compares every case; keeps at most `max_disagreements` (minimizing each).
pub fn run<D: FrontEnds>(
    cases: impl IntoIterator<Item = FrontCase<D>>,
    seed: u64,
    max_disagreements: usize,
) -> FrontTotals {
    let mut t = FrontTotals::default();
    for case in cases {
        t.compared += 1;
        if D::parse(&case.text, &case.registration).is_err()
            && D::reference_parse(&case.text, &case.registration).is_err()
        {
            t.both_rejected += 1;
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
