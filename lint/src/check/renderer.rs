//! The checks a renderer's profile adds (`--renderer`, `--profile`; docs/profiles.md),
//! each finding naming the rule and the document it comes from:
//! - `never_produced`: every path the AOV matches passes a vertex the renderer never
//!   produces (Karma's `<[RT]S>`: its specular scatterings are all `G`), so it renders
//!   black there, decided as inclusion in `.*(<v>|…).*` over the profile's vertices;
//! - `doubled_lpe_mark`: a USD `sourceName` written with `lpe:` for a renderer that
//!   prepends the mark itself (hdPrman), which then reads `lpe:lpe:…`.
//!
//! A prefix the renderer does not read and a name that is none of its built-in AOVs are
//! parse errors under the profile's registration (`parse_error`, with the accepted
//! prefixes or the nearest built-in name in the message).
//!
//! Without `--renderer`, a stage names its renderer ([`named_by`]): an `lpe:renderer`
//! attribute, else the one profile whose settings namespace (`karma:`) its
//! `RenderSettings` attributes use.

use lpe::analysis::{self, Decision};
use lpe_profile::{Never, Profile};

use super::dialect::{Lint, LintDialect};
use super::finding::{Finding, Kind};
use super::outcome::Linted;
use crate::{Document, Format};

/// The renderer `doc` names, with how it names it: its `lpe:renderer`, else the one
/// shipped profile whose settings namespace its `RenderSettings` attributes use (`None`
/// when none does, or several do: a stage set up for two renderers names neither).
pub fn of_document(doc: &Document) -> Option<(&'static Profile, String)> {
    if let Some((name, at)) = &doc.renderer {
        let profile = lpe_profile::by_name(name).ok()?;
        return Some((profile, format!("`lpe:renderer` at {at}")));
    }
    let mut found = lpe_profile::shipped().iter().filter_map(|p| {
        let ns = p.settings_namespace()?;
        let prim = doc.settings_namespaces.get(ns)?;
        Some((p, format!("the `{ns}:` attributes of <{prim}>")))
    });
    let first = found.next()?;
    found.next().is_none().then_some(first)
}

/// The renderer the documents name ([`of_document`]): the one they agree on, `None` when
/// none names one, an error naming two that differ.
pub fn named_by(docs: &[Document]) -> Result<Option<(&'static Profile, String)>, String> {
    let mut named: Option<(&'static Profile, String)> = None;
    for doc in docs {
        let Some((p, how)) = of_document(doc) else {
            continue;
        };
        let how = format!("{} ({how})", doc.file.display());
        match &named {
            Some((q, first)) if q.name != p.name => {
                return Err(format!(
                    "{how} names renderer `{}`, but {first} names `{}`: lint them apart, or \
                     name one with --renderer",
                    p.name, q.name
                ))
            }
            Some(_) => {}
            None => named = Some((p, how)),
        }
    }
    Ok(named)
}

/// Appends the profile's findings on the AOVs of one file (`linted`, read as `format`)
/// to `findings`, after the per-AOV checks (an AOV already reported empty is skipped).
pub fn check<D: LintDialect>(
    profile: &Profile,
    format: Format,
    linted: &[Linted<D::Lpe>],
    dialect: &Lint<'_, D>,
    findings: &mut Vec<Finding>,
) {
    if profile.prepends_lpe_mark() && format == Format::Usd {
        for l in linted {
            doubled_mark(profile, l, findings);
        }
    }
    let Some(never) = never_pattern::<D>(profile, dialect) else {
        return;
    };
    for l in linted {
        let Some(lpe) = &l.lpe else { continue };
        let reported_empty = findings
            .iter()
            .any(|f| f.kind == Kind::Empty && f.subject == l.decl.name && f.file == l.file);
        if reported_empty {
            continue;
        }
        if let Ok(Decision::Decided(c)) = analysis::compare_within(lpe, &never, &dialect.budget) {
            if c.first_only.is_none() {
                findings.push(never_finding(profile, l));
            }
        }
    }
}

/// `.*(<v1>|<v2>|…).*` over the profile's never-produced vertices, parsed in its terms;
/// `None` when it lists none.
fn never_pattern<D: LintDialect>(profile: &Profile, dialect: &Lint<'_, D>) -> Option<D::Lpe> {
    if profile.never.is_empty() {
        return None;
    }
    let any: Vec<String> = profile
        .never
        .iter()
        .map(|n| format!("({})", n.vertex.get_ref()))
        .collect();
    // The vertices parsed when the profile loaded; their union does too.
    dialect.parse(&format!(".*({}).*", any.join("|"))).ok()
}

/// The rule, its reason and its source, as a finding cites them.
fn cite(profile: &Profile, rule: &Never) -> String {
    let source = profile
        .source(rule.source.get_ref())
        .map(|s| format!("; {}, {}", s.title, s.location))
        .unwrap_or_default();
    format!("`{}` ({}{source})", rule.vertex.get_ref(), rule.why)
}

fn never_finding<E>(profile: &Profile, l: &Linted<E>) -> Finding {
    let rules: Vec<String> = profile.never.iter().map(|r| cite(profile, r)).collect();
    let mut f = Finding::new(
        Kind::NeverProduced,
        &l.file,
        &l.decl.name,
        &l.decl.location,
        format!(
            "renders black in {}: every path it matches passes a vertex it never produces: {}",
            profile.title,
            rules.join(" or ")
        ),
    );
    f.help = Some(format!(
        "ask for what {} produces instead (docs/profiles.md, `{}`)",
        profile.title, profile.name
    ));
    f
}

fn doubled_mark<E>(profile: &Profile, l: &Linted<E>, findings: &mut Vec<Finding>) {
    // RenderMan reads the mark in any case (`LPE:`), and hdPrman's check is textual.
    let mark = lpe::osl::SOURCE_MARK;
    let marked = l
        .decl
        .source
        .get(..mark.len())
        .is_some_and(|s| s.eq_ignore_ascii_case(mark));
    if !marked {
        return;
    }
    let (written_mark, body) = l.decl.source.split_at(mark.len());
    if l.decl.source_type.as_deref() != Some("lpe") {
        return;
    }
    let source = profile
        .source_name
        .as_ref()
        .and_then(|s| profile.source(s.source.get_ref()))
        .map(|s| format!(" ({}, {})", s.title, s.location))
        .unwrap_or_default();
    let mut f = Finding::new(
        Kind::DoubledLpeMark,
        &l.file,
        &l.decl.name,
        &l.decl.location,
        format!(
            "{} prepends `lpe:` to every sourceName of sourceType \"lpe\", so this one reaches \
             the renderer as `lpe:{}`{source}",
            profile.title, l.decl.source
        ),
    )
    .with_caret_on(&l.decl.source, written_mark);
    f.help = Some(format!("write the sourceName without its mark: `{body}`"));
    findings.push(f);
}
