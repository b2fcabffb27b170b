//! Declared partitions: do the members split the universe (beauty), and if not, each
//! overlap, the gap and stray paths with shortest witnesses, and the remainder AOV.
//! [`report`] is the text `lpe-check partition` prints, every witness re-checked first;
//! [`check`] runs it for the re-check.

use std::fmt::Display;

use lpe::analysis::{Decision, Partition};
use lpe::DialectLpe;

use super::dialect::{Lint, LintDialect};
use super::finding::{Finding, Kind};
use super::outcome::{CheckedPartition, Linted};
use crate::witness::{self, Checked, Disagreement, Expect, PathOf};
use crate::PartitionDecl;

/// Checks one partition over `aovs` (members are looked up by name, first match).
pub fn check<D: LintDialect>(
    file: &str,
    decl: &PartitionDecl,
    aovs: &[Linted<D::Lpe>],
    dialect: &Lint<'_, D>,
    universe: &D::Lpe,
    findings: &mut Vec<Finding>,
) -> Result<CheckedPartition, Disagreement> {
    let new = |kind, message| Finding::new(kind, file, &decl.name, &decl.location, message);
    let mut named = Vec::new();
    let mut complete = true;
    for m in &decl.members {
        match aovs.iter().find(|a| &a.decl.name == m) {
            Some(Linted { lpe: Some(lpe), .. }) => named.push((m.clone(), lpe.clone())),
            // Its parse error is reported on the AOV itself.
            Some(_) => complete = false,
            None => {
                complete = false;
                findings.push(new(
                    Kind::UnknownMember,
                    format!("partition member `{m}` names no LPE AOV of this file"),
                ));
            }
        }
    }
    let mut out = CheckedPartition {
        file: file.to_string(),
        decl: decl.clone(),
        checked: false,
        clean: false,
    };
    if !complete || named.is_empty() {
        return Ok(out);
    }
    let p = match dialect.partition(&named, universe) {
        Ok(Decision::Decided(p)) => p,
        Ok(Decision::Undecided(u)) => {
            findings.push(new(
                Kind::Undecided,
                format!("whether the members partition {universe} is {u}"),
            ));
            return Ok(out);
        }
        Err(_) => return Ok(out),
    };
    // The partition command's report re-checks every witness with the reference matcher.
    report(&named, universe, &p)?;
    out.checked = true;
    out.clean = p.is_clean();
    for (i, j, path) in &p.overlaps {
        let mut f = new(
            Kind::Overlap,
            format!(
                "`{}` and `{}` both match some paths: they count that light twice",
                named[*i].0, named[*j].0
            ),
        );
        f.other = Some(format!("{} & {}", named[*i].0, named[*j].0));
        f.witness = Some(path.to_string());
        findings.push(f);
    }
    if let Some(path) = &p.gap {
        let mut f = new(
            Kind::Gap,
            format!("some paths of {universe} land in no member: that light is lost"),
        );
        f.witness = Some(path.to_string());
        f.remainder = dialect.remainder(&named, universe);
        if f.remainder.is_none() {
            f.help = Some(
                "add an AOV that matches the witness path (no remainder expression \
                 could be written and confirmed)"
                    .into(),
            );
        }
        findings.push(f);
    }
    for (i, path) in &p.outside {
        let mut f = new(
            Kind::Outside,
            format!("`{}` matches paths outside {universe}", named[*i].0),
        );
        f.other = Some(named[*i].0.clone());
        f.witness = Some(path.to_string());
        findings.push(f);
    }
    Ok(out)
}

/// The text printed for a partition check (`lpe-check partition`), after re-checking
/// every witness.
pub fn report<L>(
    aovs: &[(String, L)],
    universe: &L,
    p: &Partition<PathOf<L>>,
) -> Result<String, Disagreement>
where
    L: DialectLpe + Display,
    L::Dialect: Checked,
{
    let remainder = recheck(aovs, universe, p)?;
    let mut out = format!("partition of {universe} by {} AOVs\n", aovs.len());
    for (i, j, path) in &p.overlaps {
        out.push_str(&format!(
            "overlap: {} & {}: {path}\n",
            aovs[*i].0, aovs[*j].0
        ));
    }
    if let (Some(path), Some(rest)) = (&p.gap, &remainder) {
        out.push_str(&format!("gap: {path}\nremainder: {rest}\n"));
    }
    for (i, path) in &p.outside {
        out.push_str(&format!("outside: {}: {path}\n", aovs[*i].0));
    }
    if p.is_clean() {
        out.push_str("clean partition\n");
    }
    Ok(out)
}

/// Re-checks every witness of `p` with the reference matcher: an overlap's path is in
/// the universe and both AOVs, the gap's in the universe and no AOV and in the
/// remainder, an outside path in its AOV and not the universe. Returns the remainder
/// AOV (the universe minus every AOV) when there is a gap.
pub fn recheck<L>(
    aovs: &[(String, L)],
    universe: &L,
    p: &Partition<PathOf<L>>,
) -> Result<Option<L>, Disagreement>
where
    L: DialectLpe + Display,
    L::Dialect: Checked,
{
    let uname = format!("universe {universe}");
    for (i, j, path) in &p.overlaps {
        let (a, b) = (&aovs[*i], &aovs[*j]);
        witness::recheck(
            path,
            &[
                expect(&uname, universe, true),
                expect(&a.0, &a.1, true),
                expect(&b.0, &b.1, true),
            ],
        )?;
    }
    let mut remainder = None;
    if let Some(path) = &p.gap {
        let mut expects = vec![expect(&uname, universe, true)];
        expects.extend(aovs.iter().map(|(n, l)| expect(n, l, false)));
        witness::recheck(path, &expects)?;
        let rest = lpe::analysis::remainder(aovs, universe);
        witness::recheck(path, &[expect("remainder", &rest, true)])?;
        remainder = Some(rest);
    }
    for (i, path) in &p.outside {
        let a = &aovs[*i];
        witness::recheck(
            path,
            &[expect(&uname, universe, false), expect(&a.0, &a.1, true)],
        )?;
    }
    Ok(remainder)
}

/// What `lpe` must answer on a witness.
fn expect<'a, L>(name: &'a str, lpe: &'a L, matches: bool) -> Expect<'a, L> {
    Expect { name, lpe, matches }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::analysis;
    use lpe::renderman::macros::BASIC;

    fn basic() -> Vec<(String, lpe::renderman::Lpe)> {
        BASIC
            .iter()
            .map(|(n, s)| (n.to_string(), lpe::renderman::parse(s).unwrap()))
            .collect()
    }

    #[test]
    fn basic_set_is_clean() {
        let u = analysis::default_universe::<lpe::renderman::RenderMan>(
            &lpe::renderman::Parser::default(),
        );
        let p = analysis::partition(&basic(), &u, &lpe::renderman::Parser::default()).unwrap();
        let text = report(&basic(), &u, &p).unwrap();
        assert!(text.ends_with("clean partition\n"), "{text}");
    }

    #[test]
    fn caustics_overlap_is_printed_with_its_witness() {
        let mut aovs = basic();
        aovs.push((
            "caustics".into(),
            lpe::renderman::parse("caustics").unwrap(),
        ));
        let u = analysis::default_universe::<lpe::renderman::RenderMan>(
            &lpe::renderman::Parser::default(),
        );
        let p = analysis::partition(&aovs, &u, &lpe::renderman::Parser::default()).unwrap();
        let text = report(&aovs, &u, &p).unwrap();
        assert!(
            text.contains("overlap: indirectDiffuse & caustics: C RD"),
            "{text}"
        );
        assert!(!text.contains("clean"), "{text}");
    }

    #[test]
    fn a_wrong_witness_is_refused_not_printed() {
        let aovs = basic();
        let u = analysis::default_universe::<lpe::renderman::RenderMan>(
            &lpe::renderman::Parser::default(),
        );
        // `C RD L` is directDiffuse alone: not a gap.
        let forged = Partition {
            overlaps: Vec::new(),
            gap: Some("C RD L".parse().unwrap()),
            outside: Vec::new(),
        };
        let err = report(&aovs, &u, &forged).unwrap_err().to_string();
        assert!(err.contains("directDiffuse"), "{err}");
    }

    #[test]
    fn a_gap_comes_with_a_remainder_that_parses_and_closes_it() {
        let mut aovs = basic();
        aovs.retain(|(n, _)| n != "subsurface" && n != "emissive");
        let u = analysis::default_universe::<lpe::renderman::RenderMan>(
            &lpe::renderman::Parser::default(),
        );
        let p = analysis::partition(&aovs, &u, &lpe::renderman::Parser::default()).unwrap();
        let text = report(&aovs, &u, &p).unwrap();
        let line = text
            .lines()
            .find_map(|l| l.strip_prefix("remainder: "))
            .unwrap_or_else(|| panic!("{text}"));
        assert!(line.starts_with("C.*[<L.>O] - ((C<RD>[<L.>O])|"), "{line}");
        // Added as an AOV, the printed text closes the gap (and overlaps nothing).
        aovs.push(("rest".into(), lpe::renderman::parse(line).unwrap()));
        let closed = analysis::partition(&aovs, &u, &lpe::renderman::Parser::default()).unwrap();
        assert!(closed.is_clean(), "{closed:?}");
        // It covers exactly the two AOVs left out (their union, within the universe).
        let union = "C.*[<L.>O] - (C.*[<L.>O] - subsurface - emissive)";
        let c = analysis::compare(
            &lpe::renderman::parse(line).unwrap(),
            &lpe::renderman::parse(union).unwrap(),
        );
        assert!(c.unwrap().equivalent(), "{line}");
    }
}
