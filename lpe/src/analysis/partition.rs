//! Partition checks: does a list of AOVs split a universe of paths into disjoint parts
//! that cover it, and if not, shortest witnesses of each overlap, gap and stray path.

use super::budget::{AnalysisBudget, Decision, Meter, Undecided};
use super::problem::{Problem, Stop};
use super::search::{analysis_options, explore_metered, AnalysisError};
use crate::algebra::{Algebra, SetExpr};
use crate::aov::AovSet;
use crate::automata::mask::AovMask;
use crate::dialect::{Dialect, DialectLpe};

/// The result of a partition check, with witnesses of dialect paths `P`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Partition<P> {
    /// `(i, j, path)`: a shortest universe path matched by both AOV `i` and AOV `j`
    /// (`i < j`), one entry per overlapping pair.
    pub overlaps: Vec<(usize, usize, P)>,
    /// A shortest universe path matched by no AOV.
    pub gap: Option<P>,
    /// `(i, path)`: a shortest path outside the universe that AOV `i` matches.
    pub outside: Vec<(usize, P)>,
}

impl<P> Partition<P> {
    /// Every universe path matches exactly one AOV and no AOV matches outside.
    pub fn is_clean(&self) -> bool {
        self.overlaps.is_empty() && self.gap.is_none() && self.outside.is_empty()
    }
}

/// Checks whether `aovs`, parsed under `registration`, partition `universe` (default
/// [`default_universe`]): every universe path matched by exactly one AOV, none matching
/// outside it. A dialect with a [`Dialect::domain`] (OSL) is checked on the paths of
/// that domain only: overlaps and gaps inside `universe`, and AOV matches on such paths
/// outside it. [`partition_within`] with the default [`AnalysisBudget`]; past it, the
/// error [`AnalysisError::TooLarge`].
pub fn partition<D, L>(
    aovs: &[(String, L)],
    universe: &L,
    registration: &D::Registration,
) -> Result<Partition<D::Path>, AnalysisError>
where
    L: DialectLpe<Dialect = D>,
    D: Dialect<Lpe = L>,
{
    let budget = AnalysisBudget::default();
    match partition_in::<D>(aovs, universe, registration, &budget)? {
        Decision::Decided(p) => Ok(p),
        Decision::Undecided(_) => Err(AnalysisError::TooLarge(budget.steps)),
    }
}

/// [`partition`] within `budget` (summed over its searches: one per pair of AOVs, one
/// for the gap, one per AOV outside the universe): [`Decision::Undecided`] when it runs
/// out first. Decided on the NFA of the expressions as
/// [`crate::analysis::compare_within`] is, with half the budget; for set algebra with
/// many conjuncts, or past that half, on their lazy DFA ([`partition_by_lazy_dfa`]).
pub fn partition_within<D, L>(
    aovs: &[(String, L)],
    universe: &L,
    registration: &D::Registration,
    budget: &AnalysisBudget,
) -> Result<Decision<Partition<D::Path>>, AnalysisError>
where
    L: DialectLpe<Dialect = D>,
    D: Dialect<Lpe = L>,
{
    partition_in::<D>(aovs, universe, registration, budget)
}

/// [`partition_within`] by one breadth-first search of the lazy DFA of every AOV, one
/// budget step per state: the oracle the NFA route is tested against.
pub fn partition_by_lazy_dfa<D, L>(
    aovs: &[(String, L)],
    universe: &L,
    registration: &D::Registration,
    budget: &AnalysisBudget,
) -> Result<Decision<Partition<D::Path>>, AnalysisError>
where
    L: DialectLpe<Dialect = D>,
    D: Dialect<Lpe = L>,
{
    let (all, domain) = with_universe::<D>(aovs, universe, registration);
    by_lazy_dfa::<D>(&all, domain, registration, &mut Meter::new(budget))
}

/// The expressions a partition check compiles: the domain (if the dialect has one), the
/// universe, the AOVs; and whether there is a domain.
fn with_universe<D: Dialect>(
    aovs: &[(String, D::Lpe)],
    universe: &D::Lpe,
    registration: &D::Registration,
) -> (Vec<(String, D::Lpe)>, bool) {
    let domain = D::domain(registration);
    let mut all = Vec::with_capacity(aovs.len() + 2);
    if let Some(d) = &domain {
        all.push(("paths".to_string(), d.clone()));
    }
    all.push(("universe".to_string(), universe.clone()));
    all.extend_from_slice(aovs);
    (all, domain.is_some())
}

/// [`partition_within`] with the dialect named (the expressions' bounds are the dialect's).
fn partition_in<D: Dialect>(
    aovs: &[(String, D::Lpe)],
    universe: &D::Lpe,
    registration: &D::Registration,
    budget: &AnalysisBudget,
) -> Result<Decision<Partition<D::Path>>, AnalysisError> {
    let (all, domain) = with_universe::<D>(aovs, universe, registration);
    let mut meter = Meter::new(budget);
    let problem = Problem::<D>::new(&all, &analysis_options())?;
    // Half the budget for the NFA route, the rest for the lazy DFA if it gives up (as
    // `compare_within` splits it).
    let mut nfa_meter = meter.share(meter.left() / 2);
    let on_nfa = on_nfa(&problem, domain, aovs.len(), &mut nfa_meter);
    meter.absorb(&nfa_meter);
    match on_nfa {
        Ok(p) => Ok(Decision::Decided(p)),
        Err(_) => by_lazy_dfa::<D>(&all, domain, registration, &mut meter),
    }
}

/// The partition report from one NFA search per question: per pair of AOVs (their
/// overlap), the gap, per AOV (its paths outside the universe). `problem`'s formulas are
/// the domain's (if `domain`), the universe's, then the `n` AOVs'.
fn on_nfa<D: Dialect>(
    problem: &Problem<D>,
    domain: bool,
    n: usize,
    meter: &mut Meter,
) -> Result<Partition<D::Path>, Stop> {
    let f = &problem.formulas;
    let first = usize::from(domain) + 1;
    let universe = f[first - 1].clone();
    // Every question is asked on the domain's paths only.
    let within = |q: Algebra<usize>| match domain {
        true => Algebra::and(f[0].clone(), q),
        false => q,
    };
    let mut out = Partition {
        overlaps: Vec::new(),
        gap: None,
        outside: Vec::new(),
    };
    for i in 0..n {
        for j in i + 1..n {
            let both = Algebra::and(f[first + i].clone(), f[first + j].clone());
            let q = within(Algebra::and(universe.clone(), both));
            if let Some(w) = problem.witness(&q, meter)? {
                out.overlaps.push((i, j, w));
            }
        }
    }
    let gap = (0..n).fold(universe.clone(), |acc, i| {
        Algebra::minus(acc, f[first + i].clone())
    });
    out.gap = problem.witness(&within(gap), meter)?;
    for i in 0..n {
        let q = within(Algebra::minus(f[first + i].clone(), universe.clone()));
        if let Some(w) = problem.witness(&q, meter)? {
            out.outside.push((i, w));
        }
    }
    Ok(out)
}

/// The partition report from one search of the lazy DFA of `all` (the domain if
/// `domain`, the universe, the AOVs).
fn by_lazy_dfa<D: Dialect>(
    all: &[(String, D::Lpe)],
    domain: bool,
    registration: &D::Registration,
    meter: &mut Meter,
) -> Result<Decision<Partition<D::Path>>, AnalysisError> {
    let set = AovSet::compile_under(all, registration, &analysis_options())?;
    let report = if !domain {
        split(|visit| explore_metered(&set, meter, visit), 1)
    } else {
        split(
            |visit| {
                explore_metered(&set, meter, &mut |m: AovMask, w: &dyn Fn() -> D::Path| {
                    // Outside the domain nothing counts: drop bit 0 there as if unmatched.
                    m.contains(0) && visit(m.iter().skip(1).map(|i| i - 1).collect(), w)
                })
            },
            1,
        )
    };
    Ok(match report {
        Ok(p) => Decision::Decided(p),
        Err(u) => Decision::Undecided(u),
    })
}

/// Overlaps, the gap and strays from a search over a set whose AOV 0 is the universe and
/// AOVs `first..` the parts (reported from 0).
fn split<P>(
    run: impl FnOnce(&mut dyn FnMut(AovMask, &dyn Fn() -> P) -> bool) -> Result<(), Undecided>,
    first: usize,
) -> Result<Partition<P>, Undecided> {
    let mut out = Partition {
        overlaps: Vec::new(),
        gap: None,
        outside: Vec::new(),
    };
    run(&mut |m, witness| {
        let members: Vec<usize> = m
            .iter()
            .filter(|&i| i >= first)
            .map(|i| i - first)
            .collect();
        if m.contains(0) {
            if members.is_empty() && out.gap.is_none() {
                out.gap = Some(witness());
            }
            for (x, &i) in members.iter().enumerate() {
                for &j in &members[x + 1..] {
                    if !out.overlaps.iter().any(|o| (o.0, o.1) == (i, j)) {
                        out.overlaps.push((i, j, witness()));
                    }
                }
            }
        } else {
            for &i in &members {
                if !out.outside.iter().any(|o| o.0 == i) {
                    out.outside.push((i, witness()));
                }
            }
        }
        false
    })?;
    out.overlaps.sort_by_key(|o| (o.0, o.1));
    out.outside.sort_by_key(|o| o.0);
    Ok(out)
}

/// The AOV that closes every gap of a partition: the universe minus every AOV, as set
/// algebra that prints as text the dialect's parser reads back (`C.*[<L.>O] - (a|b|c)`;
/// in OSL under the registration the AOVs were parsed with). Plain AOVs are subtracted
/// as one alternation, set-algebra AOVs one by one; RenderMan's prefixes are dropped
/// (they never change what matches). Overlaps are not its business: it only covers what
/// no AOV covers.
pub fn remainder<D, L>(aovs: &[(String, L)], universe: &L) -> L
where
    L: DialectLpe<Dialect = D>,
    D: Dialect<Lpe = L>,
{
    remainder_in::<D>(aovs, universe)
}

/// [`remainder`] with the dialect named (the expressions' bounds are the dialect's).
fn remainder_in<D: Dialect>(aovs: &[(String, D::Lpe)], universe: &D::Lpe) -> D::Lpe {
    D::from_algebra(remainder_tree(aovs, universe, D::alt))
}

/// The universe minus the plain AOVs as one alternation (`alt`), then minus each
/// set-algebra AOV.
fn remainder_tree<L: SetExpr>(
    aovs: &[(String, L)],
    universe: &L,
    alt: impl FnOnce(Vec<L::Operand>) -> L::Operand,
) -> Algebra<L::Operand> {
    let plain: Vec<L::Operand> = aovs
        .iter()
        .filter(|(_, l)| l.algebra().is_none())
        .map(|(_, l)| l.first().clone())
        .collect();
    let mut t = universe.tree();
    if !plain.is_empty() {
        t = Algebra::minus(t, Algebra::Leaf(alt(plain)));
    }
    for (_, l) in aovs.iter().filter(|(_, l)| l.algebra().is_some()) {
        t = Algebra::minus(t, l.tree());
    }
    t
}

/// The dialect's default universe ([`Dialect::DEFAULT_UNIVERSE`]), parsed under
/// `registration`.
pub fn default_universe<D: Dialect>(registration: &D::Registration) -> D::Lpe {
    D::parse(D::DEFAULT_UNIVERSE, registration).expect("the default universe parses")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::osl::{self, Osl};
    use crate::renderman::macros::BASIC;
    use crate::renderman::{parse, Lpe, Parser, RenderMan};

    fn rm_universe() -> Lpe {
        default_universe::<RenderMan>(&Parser::default())
    }

    fn lpe(s: &str) -> Lpe {
        parse(s).unwrap()
    }

    fn basic() -> Vec<(String, Lpe)> {
        BASIC.iter().map(|(n, s)| (n.to_string(), lpe(s))).collect()
    }

    #[test]
    fn basic_aovs_partition_the_universe() {
        let p = partition(&basic(), &rm_universe(), &Parser::default()).unwrap();
        assert!(p.is_clean(), "{p:?}");
    }

    #[test]
    fn caustics_overlap_with_a_short_witness() {
        let mut aovs = basic();
        aovs.push(("caustics".into(), lpe("CDS+[<L.>O]")));
        let p = partition(&aovs, &rm_universe(), &Parser::default()).unwrap();
        assert!(p.gap.is_none() && p.outside.is_empty(), "{p:?}");
        // `D` is reflected or transmitted diffuse, so caustics lie inside indirectDiffuse
        // (`C RD S L`) and subsurface (`C TD S L`); 4 vertices is the shortest caustic.
        let pairs: Vec<(&str, &str, usize)> = p
            .overlaps
            .iter()
            .map(|(i, j, w)| (aovs[*i].0.as_str(), aovs[*j].0.as_str(), w.len()))
            .collect();
        assert_eq!(
            pairs,
            [
                ("indirectDiffuse", "caustics", 4),
                ("subsurface", "caustics", 4)
            ]
        );
    }

    #[test]
    fn the_remainder_parses_back_and_closes_the_gap() {
        use crate::analysis::compare;
        let all = basic();
        for missing in 0..all.len() {
            let mut aovs = all.clone();
            let (name, dropped) = aovs.remove(missing);
            // One set-algebra AOV among the rest: subtracted on its own.
            let (n, first) = aovs.remove(0);
            let split = lpe(&format!("{first} - C<RS>.*[<L.>O]"));
            aovs.insert(0, (n, split));
            let p = partition(&aovs, &rm_universe(), &Parser::default()).unwrap();
            assert!(p.gap.is_some(), "{name}");
            let r = remainder(&aovs, &rm_universe());
            let text = r.to_string();
            assert!(text.starts_with("C.*[<L.>O] - ("), "{text}");
            assert_eq!(parse(&text).unwrap(), r, "{text}");
            let mut closed = aovs.clone();
            closed.push(("rest".into(), r.clone()));
            let q = partition(&closed, &rm_universe(), &Parser::default()).unwrap();
            assert_eq!(q.gap, None, "{name}: {text}");
            assert!(q.outside.is_empty(), "{name}: {text}");
            // What it covers is exactly what the dropped AOV covered and the split-off
            // first AOV no longer does, both within the universe.
            let want = lpe(&format!(
                "C.*[<L.>O] & ^(^{dropped} & ^({first} & C<RS>.*[<L.>O]))"
            ));
            let c = compare(&r, &want).unwrap();
            assert!(c.equivalent(), "{name}: {text}: {c:?}");
        }
    }

    fn set_in_the_osl_dialect(srcs: &[&str]) -> Vec<(String, osl::Lpe)> {
        let reg = osl::Registered::none();
        srcs.iter()
            .map(|s| (s.to_string(), osl::parse(s, &reg).unwrap()))
            .collect()
    }

    #[test]
    fn the_basic_set_partitions_the_universe_in_the_osl_dialect() {
        let reg = osl::Registered::none();
        let p = partition(
            &set_in_the_osl_dialect(&osl::BASIC.map(|(_, src)| src)),
            &default_universe::<Osl>(&reg),
            &reg,
        )
        .unwrap();
        assert!(p.is_clean(), "{p:?}");
    }

    #[test]
    fn partition_witnesses_in_the_osl_dialect() {
        let reg = osl::Registered::none();
        // Without `C[LO]` the direct paths are a gap; doubling `C<RD>[LO]` overlaps.
        let mut aovs = set_in_the_osl_dialect(&osl::BASIC.map(|(_, src)| src)[..6]);
        aovs.push(("again".into(), osl::parse("C<RD>L", &reg).unwrap()));
        let p = partition(&aovs, &default_universe::<Osl>(&reg), &reg).unwrap();
        assert_eq!(p.gap.unwrap().to_string(), "C,~ L,~");
        let o: Vec<(usize, usize, String)> = p
            .overlaps
            .iter()
            .map(|(i, j, w)| (*i, *j, w.to_string()))
            .collect();
        assert_eq!(o, [(0, 6, "C,~ R,D L,~".to_string())]);
        assert!(p.outside.is_empty());
        // A universe without glossy: glossy AOVs match outside it.
        let u = osl::parse("C<[RT]D>*[LO]", &reg).unwrap();
        let p = partition(
            &set_in_the_osl_dialect(&osl::BASIC.map(|(_, src)| src)),
            &u,
            &reg,
        )
        .unwrap();
        let out: Vec<(usize, String)> =
            p.outside.iter().map(|(i, w)| (*i, w.to_string())).collect();
        // Each a shortest one: the glossy bounce comes first, or right after the
        // diffuse one (`.+`, `.*` accept any vertex).
        assert_eq!(
            out,
            [
                (1, "C,~ R,D R,G L,~".to_string()),
                (2, "C,~ T,D R,G L,~".to_string()),
                (3, "C,~ R,G L,~".to_string()),
                (4, "C,~ R,G R,D L,~".to_string()),
                (5, "C,~ T,G L,~".to_string())
            ]
        );
        assert_eq!(p.overlaps.len(), 0);
    }

    #[test]
    fn algebra_members_and_the_remainder_in_the_osl_dialect() {
        use crate::analysis::compare;
        let reg = osl::Registered::none();
        let universe = default_universe::<Osl>(&reg);
        // The basic set without `C[LO]`, its first member split: `C<RD>O` now goes
        // nowhere either.
        let mut aovs = set_in_the_osl_dialect(&osl::BASIC.map(|(_, src)| src)[1..6]);
        aovs.insert(
            0,
            (
                "split".into(),
                osl::parse("C<RD>[LO] - C<RD>O", &reg).unwrap(),
            ),
        );
        let p = partition(&aovs, &universe, &reg).unwrap();
        assert_eq!(p.gap.as_ref().unwrap().to_string(), "C,~ L,~");
        assert!(p.overlaps.is_empty() && p.outside.is_empty(), "{p:?}");
        let r = remainder(&aovs, &universe);
        let text = r.to_string();
        assert!(text.starts_with("<C.><[RT][DGS]>*<L.>|<O.> - (("), "{text}");
        assert!(
            text.ends_with(" - (<C.><RD><L.>|<O.> - <C.><RD><O.>)"),
            "{text}"
        );
        assert_eq!(osl::parse(&text, &reg).unwrap(), r, "{text}");
        // Exactly the two missing parts, worked out by hand.
        let want = osl::parse("(C[LO])|(C<RD>O)", &reg).unwrap();
        assert!(compare(&r, &want).unwrap().equivalent(), "{text}");
        aovs.push(("rest".into(), r));
        assert!(partition(&aovs, &universe, &reg).unwrap().is_clean());
    }
}
