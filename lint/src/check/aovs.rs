//! Per-AOV checks of one file: parse errors, emptiness, equivalence, group labels, lobes.

use crate::Document;
use lpe::analysis::Decision;
use lpe::renderman::LobeCategory;

use super::dialect::{Lint, LintDialect};
use super::finding::{Finding, Kind};
use super::labels::Carrier;
use super::outcome::Linted;

/// Parses the AOVs of `doc` into `linted` and appends the findings on them.
pub fn check<D: LintDialect>(
    doc: &Document,
    linted: &mut [Linted<D::Lpe>],
    dialect: &Lint<'_, D>,
    findings: &mut Vec<Finding>,
) {
    for l in linted.iter_mut() {
        match dialect.parse(&l.decl.source) {
            Ok(lpe) => l.lpe = Some(lpe),
            Err(e) => {
                let mut f = finding(l, Kind::ParseError, e.message);
                f.caret = Some((e.source, e.span));
                f.help = e.help;
                findings.push(f);
            }
        }
    }
    let empty = empty_aovs(linted, dialect);
    for (i, reason) in &empty {
        findings.push(finding(
            &linted[*i],
            Kind::Empty,
            format!("can match no path: {reason}"),
        ));
    }
    let live: Vec<usize> = (0..linted.len())
        .filter(|i| linted[*i].lpe.is_some() && !empty.iter().any(|(e, _)| e == i))
        .collect();
    for (x, &j) in live.iter().enumerate() {
        let b = linted[j].lpe.as_ref().expect("live AOVs parsed");
        let twin = live[..x].iter().copied().find(|&i| {
            let a = linted[i].lpe.as_ref().expect("live AOVs parsed");
            match dialect.equivalent(a, b) {
                Decision::Decided(same) => same,
                Decision::Undecided(u) => {
                    findings.push(against(
                        &linted[j],
                        &linted[i],
                        Kind::Undecided,
                        format!(
                            "whether it matches exactly the paths `{}` matches is {u}",
                            linted[i].decl.name
                        ),
                    ));
                    false
                }
            }
        });
        if let Some(i) = twin {
            findings.push(against(
                &linted[j],
                &linted[i],
                Kind::Equivalent,
                format!(
                    "matches exactly the paths `{}` matches: both render the same image",
                    linted[i].decl.name
                ),
            ));
        }
    }
    for l in linted.iter() {
        if let Some(lpe) = &l.lpe {
            group_findings(doc, l, &dialect.labels(lpe), findings);
            lobe_findings(l, &dialect.unfed_lobes(lpe), findings);
        }
    }
}

/// `(index, reason)` of the parsed AOVs that can match no path.
fn empty_aovs<D: LintDialect>(
    linted: &[Linted<D::Lpe>],
    dialect: &Lint<'_, D>,
) -> Vec<(usize, String)> {
    let parsed: Vec<(usize, (String, D::Lpe))> = linted
        .iter()
        .enumerate()
        .filter_map(|(i, l)| l.lpe.clone().map(|lpe| (i, (l.decl.name.clone(), lpe))))
        .collect();
    let named: Vec<(String, D::Lpe)> = parsed.iter().map(|(_, n)| n.clone()).collect();
    let warnings = match dialect.warnings(&named) {
        Some(w) => w,
        // Too many or too large together: each alone (its emptiness does not depend on
        // the others).
        None => named
            .iter()
            .enumerate()
            .flat_map(|(k, n)| {
                dialect
                    .warnings(std::slice::from_ref(n))
                    .unwrap_or_default()
                    .into_iter()
                    .map(move |mut w| {
                        w.aov = k;
                        w
                    })
            })
            .collect(),
    };
    warnings
        .into_iter()
        .map(|w| (parsed[w.aov].0, w.message))
        .collect()
}

fn group_findings<E>(
    doc: &Document,
    l: &Linted<E>,
    labels: &[(Carrier, String)],
    findings: &mut Vec<Finding>,
) {
    for (carrier, label) in labels {
        let (known, kind, who) = match carrier {
            Carrier::Light => (&doc.light_groups, Kind::UnknownLightGroup, "light"),
            Carrier::Object => (&doc.object_groups, Kind::UnknownObjectGroup, "object"),
        };
        // A stage with no lights (objects) at all is a settings layer: nothing to check.
        let Some(known) = known else { continue };
        if known.contains(label) {
            continue;
        }
        let carried = if known.is_empty() {
            "none carries a group".to_string()
        } else {
            format!(
                "they carry {}",
                known
                    .iter()
                    .map(|g| format!("'{g}'"))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        let mut f = finding(
            l,
            kind,
            format!("no {who} in this stage carries group '{label}' ({carried})"),
        )
        .with_caret_on(&l.decl.source, &format!("'{label}'"));
        f.help = closest(label, known).map(|g| format!("did you mean '{g}'?"));
        findings.push(f);
    }
}

fn lobe_findings<E>(l: &Linted<E>, unfed: &[(LobeCategory, u8)], findings: &mut Vec<Finding>) {
    for &(category, lobe) in unfed {
        let letter = category.kind().letter();
        let key = category.ini_name();
        let what = match category {
            LobeCategory::User => "user signal",
            _ => "material lobe",
        };
        let mut f = finding(
            l,
            Kind::UnfedLobe,
            format!("no {what} maps to lobe {letter}{lobe}: this part renders black"),
        )
        .with_caret_on(&l.decl.source, &format!("{letter}{lobe}"));
        f.help = Some(format!(
            "map names to it in rendermn.ini: /prman/lpe/{key}{lobe} NAME,..."
        ));
        findings.push(f);
    }
}

fn finding<E>(l: &Linted<E>, kind: Kind, message: String) -> Finding {
    Finding::new(kind, &l.file, &l.decl.name, &l.decl.location, message)
}

/// A finding on `l` about how it compares with the earlier AOV `other`, which it names.
fn against<E>(l: &Linted<E>, other: &Linted<E>, kind: Kind, message: String) -> Finding {
    let mut f = finding(l, kind, message);
    f.other = Some(other.decl.name.clone());
    f
}

/// The known group within edit distance 2 of `label` (a typo), if exactly one is closest.
fn closest<'a>(label: &str, known: &'a std::collections::BTreeSet<String>) -> Option<&'a str> {
    let mut best: Option<(usize, &str)> = None;
    let mut tie = false;
    for g in known {
        let d = lpe::renderman::syntax::edit_distance(label, g);
        match best {
            Some((b, _)) if d > b => {}
            Some((b, _)) if d == b => tie = true,
            _ => {
                best = Some((d, g));
                tie = false;
            }
        }
    }
    best.filter(|(d, _)| *d <= 2 && !tie).map(|(_, g)| g)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closest_group() {
        let known = ["fill".to_string(), "key".to_string()]
            .into_iter()
            .collect();
        assert_eq!(closest("fil", &known), Some("fill"));
        assert_eq!(closest("kye", &known), Some("key"));
        assert_eq!(closest("zzzzz", &known), None);
        // A tie suggests nothing.
        let tied = ["ab".to_string(), "ba".to_string()].into_iter().collect();
        assert_eq!(closest("aa", &tied), None);
    }
}
