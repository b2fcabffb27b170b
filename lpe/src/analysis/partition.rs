//! Partition checks: does a list of AOVs split a universe of paths into disjoint parts
//! that cover it, and if not, shortest witnesses of each overlap, gap and stray path.

use super::search::{analysis_options, explore, AnalysisError};
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
/// outside it.
pub fn partition<D, L>(
    aovs: &[(String, L)],
    universe: &L,
    registration: &D::Registration,
) -> Result<Partition<D::Path>, AnalysisError>
where
    L: DialectLpe<Dialect = D>,
    D: Dialect<Lpe = L>,
{
    partition_in::<D>(aovs, universe, registration)
}

/// [`partition`] with the dialect named (the expressions' bounds are the dialect's).
fn partition_in<D: Dialect>(
    aovs: &[(String, D::Lpe)],
    universe: &D::Lpe,
    registration: &D::Registration,
) -> Result<Partition<D::Path>, AnalysisError> {
    let domain = D::domain(registration);
    let mut all = Vec::with_capacity(aovs.len() + 2);
    if let Some(d) = &domain {
        all.push(("paths".to_string(), d.clone()));
    }
    all.push(("universe".to_string(), universe.clone()));
    all.extend_from_slice(aovs);
    let set = AovSet::compile_under(&all, registration, &analysis_options())?;
    if domain.is_none() {
        return split(|visit| explore(&set, visit), 1);
    }
    split(
        |visit| {
            explore(&set, &mut |m: AovMask, w: &dyn Fn() -> D::Path| {
                // Outside the domain nothing counts: drop bit 0 there as if unmatched.
                m.contains(0) && visit(m.iter().skip(1).map(|i| i - 1).collect(), w)
            })
        },
        1,
    )
}

/// Overlaps, the gap and strays from a search over a set whose AOV 0 is the universe and
/// AOVs `first..` the parts (reported from 0).
fn split<P>(
    run: impl FnOnce(&mut dyn FnMut(AovMask, &dyn Fn() -> P) -> bool) -> Result<(), AnalysisError>,
    first: usize,
) -> Result<Partition<P>, AnalysisError> {
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
