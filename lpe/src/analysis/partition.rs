//! Partition checks: does a list of AOVs split a universe of paths into disjoint parts
//! that cover it, and if not, shortest witnesses of each overlap, gap and stray path.

use super::search::{analysis_options, explore, AnalysisError};
use crate::algebra::Algebra;
use crate::aov::AovSet;
use crate::path::Path;
use crate::{parse, Expr, Lpe, Prefixes};

/// The default universe of a partition check: every light-transport path.
pub const DEFAULT_UNIVERSE: &str = "C.*[<L.>O]";

/// The result of a partition check.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Partition {
    /// `(i, j, path)`: a shortest universe path matched by both AOV `i` and AOV `j`
    /// (`i < j`), one entry per overlapping pair.
    pub overlaps: Vec<(usize, usize, Path)>,
    /// A shortest universe path matched by no AOV.
    pub gap: Option<Path>,
    /// `(i, path)`: a shortest path outside the universe that AOV `i` matches.
    pub outside: Vec<(usize, Path)>,
}

impl Partition {
    /// Every universe path matches exactly one AOV and no AOV matches outside.
    pub fn is_clean(&self) -> bool {
        self.overlaps.is_empty() && self.gap.is_none() && self.outside.is_empty()
    }
}

/// Checks whether `aovs` partition `universe` (default [`DEFAULT_UNIVERSE`]): every
/// universe path matched by exactly one AOV, none matching outside it.
pub fn partition(aovs: &[(String, Lpe)], universe: &Lpe) -> Result<Partition, AnalysisError> {
    let mut all = vec![("universe".to_string(), universe.clone())];
    all.extend_from_slice(aovs);
    let set = AovSet::compile_with(&all, &analysis_options())?;
    let mut out = Partition {
        overlaps: Vec::new(),
        gap: None,
        outside: Vec::new(),
    };
    explore(&set, |m, witness| {
        let members: Vec<usize> = m.iter().filter(|&i| i > 0).map(|i| i - 1).collect();
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
/// algebra that prints as text the parser reads back (`C.*[<L.>O] - (a|b|c)`). Plain
/// AOVs are subtracted as one alternation, set-algebra AOVs one by one; prefixes are
/// dropped (they never change what matches). Overlaps are not its business: it only
/// covers what no AOV covers.
pub fn remainder(aovs: &[(String, Lpe)], universe: &Lpe) -> Lpe {
    let plain: Vec<Expr> = aovs
        .iter()
        .filter(|(_, l)| l.algebra.is_none())
        .map(|(_, l)| l.expr.clone())
        .collect();
    let mut t = universe.tree();
    if !plain.is_empty() {
        t = Algebra::minus(t, Algebra::Leaf(Expr::alt(plain)));
    }
    for (_, l) in aovs.iter().filter(|(_, l)| l.algebra.is_some()) {
        t = Algebra::minus(t, l.tree());
    }
    Lpe::from_algebra(Prefixes::NONE, t)
}

/// The default universe, parsed.
pub fn default_universe() -> Lpe {
    parse(DEFAULT_UNIVERSE).expect("the default universe parses")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::macros::BASIC;

    fn lpe(s: &str) -> Lpe {
        parse(s).unwrap()
    }

    fn basic() -> Vec<(String, Lpe)> {
        BASIC.iter().map(|(n, s)| (n.to_string(), lpe(s))).collect()
    }

    #[test]
    fn basic_aovs_partition_the_universe() {
        let p = partition(&basic(), &default_universe()).unwrap();
        assert!(p.is_clean(), "{p:?}");
    }

    #[test]
    fn caustics_overlap_with_a_short_witness() {
        let mut aovs = basic();
        aovs.push(("caustics".into(), lpe("CDS+[<L.>O]")));
        let p = partition(&aovs, &default_universe()).unwrap();
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
            let p = partition(&aovs, &default_universe()).unwrap();
            assert!(p.gap.is_some(), "{name}");
            let r = remainder(&aovs, &default_universe());
            let text = r.to_string();
            assert!(text.starts_with("C.*[<L.>O] - ("), "{text}");
            assert_eq!(parse(&text).unwrap(), r, "{text}");
            let mut closed = aovs.clone();
            closed.push(("rest".into(), r.clone()));
            let q = partition(&closed, &default_universe()).unwrap();
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
}
