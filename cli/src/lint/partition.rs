//! Declared partitions: do the members split the universe (beauty), and if not, each
//! overlap, the gap and stray paths with shortest witnesses, and the remainder AOV.

use lpe_lint::PartitionDecl;

use super::dialect::Dialect;
use super::finding::{Finding, Kind};
use super::{CheckedPartition, Linted};
use crate::cmd;
use crate::witness::Disagreement;

/// Checks one partition over `aovs` (members are looked up by name, first match).
pub fn check<D: Dialect>(
    file: &str,
    decl: &PartitionDecl,
    aovs: &[Linted<D::Expr>],
    dialect: &D,
    universe: &D::Expr,
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
    let Ok(p) = dialect.partition(&named, universe) else {
        return Ok(out);
    };
    // The partition command's report re-checks every witness with the reference matcher.
    cmd::partition::report(&named, universe, &p)?;
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
