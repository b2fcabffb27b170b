//! How much work one analysis may do, and the answer it gives past that: a decision
//! ([`Decision::Decided`]) or [`Decision::Undecided`], never an error and never a hang.

use std::fmt;
use std::time::{Duration, Instant};

/// Search steps an analysis takes by default before it answers undecided.
pub const DEFAULT_STEPS: usize = 4_000_000;

/// The work one call of [`crate::analysis::compare_within`],
/// [`crate::analysis::partition_within`] or [`crate::analysis::warnings_within`] may do.
///
/// A *step* is one unit of search work: one search node made (a run position tuple with
/// a path-shape state and a subset of positions, or a state of the lazy DFA on the
/// fallback route for set algebra), or one stored subset a new node is compared with.
/// The count is summed over every search of the call (a partition makes several). Steps
/// make the outcome depend on the input alone; `time` adds a wall-clock limit, which
/// does not (a loaded machine answers undecided sooner).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AnalysisBudget {
    /// Most search steps; default [`DEFAULT_STEPS`].
    pub steps: usize,
    /// Most wall-clock time, if any; default none.
    pub time: Option<Duration>,
}

impl Default for AnalysisBudget {
    fn default() -> Self {
        AnalysisBudget {
            steps: DEFAULT_STEPS,
            time: None,
        }
    }
}

impl AnalysisBudget {
    /// A budget of `steps` search steps and no time limit.
    pub fn steps(steps: usize) -> AnalysisBudget {
        AnalysisBudget { steps, time: None }
    }
}

/// The answer of an analysis with a budget.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Decision<T> {
    /// Decided within the budget.
    Decided(T),
    /// The budget ran out first: nothing is known (not even a partial answer).
    Undecided(Undecided),
}

impl<T> Decision<T> {
    /// The decided answer, if any.
    pub fn decided(self) -> Option<T> {
        match self {
            Decision::Decided(t) => Some(t),
            Decision::Undecided(_) => None,
        }
    }

    /// Applies `f` to a decided answer.
    pub fn map<U>(self, f: impl FnOnce(T) -> U) -> Decision<U> {
        match self {
            Decision::Decided(t) => Decision::Decided(f(t)),
            Decision::Undecided(u) => Decision::Undecided(u),
        }
    }
}

/// Which limit of an [`AnalysisBudget`] ended a search.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Limit {
    /// [`AnalysisBudget::steps`] (the number given).
    Steps(usize),
    /// [`AnalysisBudget::time`] (the duration given).
    Time(Duration),
}

/// An analysis that ran out of budget, with the limit it reached.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Undecided {
    /// The limit reached.
    pub limit: Limit,
}

impl fmt::Display for Undecided {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.limit {
            Limit::Steps(n) => write!(f, "undecided within the budget of {n} search steps"),
            Limit::Time(t) => write!(f, "undecided within the time budget of {t:?}"),
        }
    }
}

/// Steps between two reads of the clock: the clock costs more than a step.
const CLOCK_EVERY: usize = 1024;

/// A running budget: steps left and the deadline.
#[derive(Debug)]
pub(super) struct Meter {
    limit: usize,
    left: usize,
    time: Option<(Instant, Duration)>,
    until_clock: usize,
}

impl Meter {
    pub(super) fn new(budget: &AnalysisBudget) -> Meter {
        Meter {
            limit: budget.steps,
            left: budget.steps,
            time: budget.time.map(|t| (Instant::now(), t)),
            until_clock: CLOCK_EVERY,
        }
    }

    /// Spends `n` steps; `Err` once a limit is passed.
    #[inline]
    pub(super) fn spend(&mut self, n: usize) -> Result<(), Undecided> {
        if n > self.left {
            self.left = 0;
            return Err(Undecided {
                limit: Limit::Steps(self.limit),
            });
        }
        self.left -= n;
        if self.time.is_some() {
            self.until_clock = self.until_clock.saturating_sub(n);
            if self.until_clock == 0 {
                self.until_clock = CLOCK_EVERY;
                return self.check_clock();
            }
        }
        Ok(())
    }

    fn check_clock(&self) -> Result<(), Undecided> {
        match self.time {
            Some((start, t)) if start.elapsed() >= t => Err(Undecided {
                limit: Limit::Time(t),
            }),
            _ => Ok(()),
        }
    }

    /// Steps left.
    pub(super) fn left(&self) -> usize {
        self.left
    }

    /// A meter for a sub-search that may spend at most `steps` of this one's, with its
    /// deadline; [`Meter::absorb`] charges what it spent back here.
    pub(super) fn share(&self, steps: usize) -> Meter {
        Meter {
            limit: steps.min(self.left),
            left: steps.min(self.left),
            time: self.time,
            until_clock: CLOCK_EVERY,
        }
    }

    /// Charges a sub-search's spending from [`Meter::share`] (never past what is left).
    pub(super) fn absorb(&mut self, sub: &Meter) {
        self.left = self.left.saturating_sub(sub.limit - sub.left);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_meter_stops_past_its_steps_and_a_share_charges_back() {
        // Breaking `spend`'s comparison (`>=`) fails the first assert: spending exactly
        // the budget is allowed.
        let mut m = Meter::new(&AnalysisBudget::steps(10));
        assert!(m.spend(10).is_ok());
        assert_eq!(
            m.spend(1),
            Err(Undecided {
                limit: Limit::Steps(10)
            })
        );
        let mut m = Meter::new(&AnalysisBudget::steps(10));
        let mut sub = m.share(4);
        assert!(sub.spend(3).is_ok());
        assert!(sub.spend(2).is_err());
        m.absorb(&sub);
        assert_eq!(m.left(), 6);
    }

    #[test]
    fn a_zero_time_budget_stops_at_the_first_clock_read() {
        let mut m = Meter::new(&AnalysisBudget {
            steps: usize::MAX,
            time: Some(Duration::ZERO),
        });
        let stopped = (0..2 * CLOCK_EVERY).any(|_| m.spend(1).is_err());
        assert!(stopped);
    }

    /// The clock is read once every `CLOCK_EVERY` steps, and only a passed deadline
    /// stops: with no time at all, step 1 024 is the first refused, with an hour none of
    /// 3 000 is. Planted faults (cargo-mutants), each seen failing: the clock read at
    /// every other step (`until_clock == 0` as `!=`: step 1 refused); any deadline taken
    /// as passed (the hour's first clock read refused).
    #[test]
    fn the_clock_is_read_every_1024_steps_and_stops_only_past_the_deadline() {
        let mut m = Meter::new(&AnalysisBudget {
            steps: usize::MAX,
            time: Some(Duration::ZERO),
        });
        assert!((1..1024).all(|_| m.spend(1).is_ok()));
        assert_eq!(
            m.spend(1),
            Err(Undecided {
                limit: Limit::Time(Duration::ZERO)
            })
        );
        let mut m = Meter::new(&AnalysisBudget {
            steps: usize::MAX,
            time: Some(Duration::from_secs(3600)),
        });
        assert!((0..3000).all(|_| m.spend(1).is_ok()));
    }

    /// What an undecided answer says, and a decision's answer. Planted faults
    /// (cargo-mutants), each seen failing: `Display` writing nothing; `decided` always
    /// `None`.
    #[test]
    fn an_undecided_answer_names_its_limit_and_a_decision_gives_its_answer() {
        let steps = Undecided {
            limit: Limit::Steps(10),
        };
        assert_eq!(
            steps.to_string(),
            "undecided within the budget of 10 search steps"
        );
        let time = Undecided {
            limit: Limit::Time(Duration::from_millis(5)),
        };
        assert_eq!(time.to_string(), "undecided within the time budget of 5ms");
        assert_eq!(Decision::Decided(2).decided(), Some(2));
        assert_eq!(Decision::<u32>::Undecided(steps).decided(), None);
        assert_eq!(Decision::Decided(2).map(|x| x + 1), Decision::Decided(3));
    }
}
