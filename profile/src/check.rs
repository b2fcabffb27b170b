//! What a profile may not say, checked when it loads: each refusal names the key and the
//! line. A profile that contradicts its base dialect (a built-in letter redefined, a
//! prefix on RenderMan's base, whose prefixes are its own), cites a source it does not
//! list, defines a name twice, or holds an expression or vertex that does not parse in
//! its own terms is refused.

use toml::Spanned;

use lpe::osl::{EVENT_LABELS, SCATTERING_LABELS};
use lpe::translate::Correspondence;

use crate::error::{line_of, ProfileError};
use crate::registration::registered_with;
use crate::schema::Profile;

/// A refusal: the key, where it is, and why.
struct Refusal {
    key: String,
    at: Option<usize>,
    message: String,
}

fn refuse<T>(key: String, value: &Spanned<T>, message: String) -> Refusal {
    Refusal {
        key,
        at: Some(value.span().start),
        message,
    }
}

/// Checks `profile`, read from `text` of `file`.
pub(crate) fn check(file: &str, text: &str, profile: &Profile) -> Result<(), ProfileError> {
    refusal(profile).map_or(Ok(()), |r| {
        Err(ProfileError::Invalid {
            file: file.to_string(),
            line: r.at.map(|at| line_of(text, at)),
            key: Some(r.key),
            message: r.message,
        })
    })
}

fn refusal(p: &Profile) -> Option<Refusal> {
    let name_ok = !p.name.is_empty()
        && p.name
            .bytes()
            .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_' || b == b'-');
    if !name_ok {
        return Some(Refusal {
            key: "name".into(),
            at: None,
            message: format!(
                "`{}` is not a profile name (lowercase letters, digits, `_`, `-`)",
                p.name
            ),
        });
    }
    let base = p.base.get_ref().as_str();
    if base != "osl" && base != "renderman" {
        return Some(refuse(
            "base".into(),
            &p.base,
            format!("`{base}` is not a base dialect: expected \"osl\" or \"renderman\""),
        ));
    }
    sources(p)
        .or_else(|| letters(p))
        .or_else(|| prefixes(p))
        .or_else(|| expressions(p))
        .or_else(|| groups(p))
        .or_else(|| translation(p))
}

/// Every cited source is listed, and listed once.
fn sources(p: &Profile) -> Option<Refusal> {
    for (i, s) in p.sources.iter().enumerate() {
        if p.sources[..i].iter().any(|t| t.id == s.id) {
            return Some(Refusal {
                key: format!("sources[{i}].id"),
                at: None,
                message: format!("source `{}` is listed twice", s.id),
            });
        }
    }
    let mut all: Vec<(String, Spanned<String>)> = Vec::new();
    for (i, r) in p.events.iter().enumerate() {
        all.push((format!("events[{i}].source"), r.source.clone()));
    }
    for (i, r) in p.scatterings.iter().enumerate() {
        all.push((format!("scatterings[{i}].source"), r.source.clone()));
    }
    for (i, r) in p.never.iter().enumerate() {
        all.push((format!("never[{i}].source"), r.source.clone()));
    }
    for (i, r) in p.prefixes.iter().enumerate() {
        all.push((format!("prefixes[{i}].source"), r.source.clone()));
    }
    for (i, r) in p.builtins.iter().enumerate() {
        all.push((format!("builtins[{i}].source"), r.source.clone()));
    }
    if let Some(g) = &p.groups {
        all.push(("groups.source".into(), g.source.clone()));
    }
    if let Some(s) = &p.source_name {
        all.push(("source_name.source".into(), s.source.clone()));
    }
    if let Some(t) = &p.translate {
        all.push(("translate.source".into(), t.source.clone()));
    }
    for (key, s) in &all {
        if p.source(s.get_ref()).is_none() {
            let listed: Vec<&str> = p.sources.iter().map(|s| s.id.as_str()).collect();
            return Some(refuse(
                key.clone(),
                s,
                format!(
                    "cites `{}`, which is not in [[sources]] (listed: {})",
                    s.get_ref(),
                    if listed.is_empty() {
                        "none".to_string()
                    } else {
                        listed.join(", ")
                    }
                ),
            ));
        }
    }
    None
}

/// Added letters: OSL base only, none of OSL's own, none twice, each a label OSL's
/// syntax can write (letters and digits, no quote or bracket).
fn letters(p: &Profile) -> Option<Refusal> {
    let added = p
        .events
        .iter()
        .enumerate()
        .map(|(i, r)| ("events", i, r))
        .chain(
            p.scatterings
                .iter()
                .enumerate()
                .map(|(i, r)| ("scatterings", i, r)),
        );
    let mut seen: Vec<&str> = Vec::new();
    for (list, i, r) in added {
        let key = format!("{list}[{i}].letter");
        let letter = r.letter.get_ref().as_str();
        if p.dialect() == lpe::DialectName::RenderMan {
            return Some(refuse(
                key,
                &r.letter,
                "RenderMan's dialect registers no letters: its events and lobes are fixed \
                 (docs/language.md §2); rename lobes with a rendermn.ini instead"
                    .into(),
            ));
        }
        if letter.is_empty() || !letter.chars().all(|c| c.is_ascii_alphanumeric()) {
            return Some(refuse(
                key,
                &r.letter,
                format!("`{letter}` is not a label OSL's syntax can write (letters and digits)"),
            ));
        }
        if EVENT_LABELS.contains(&letter) || SCATTERING_LABELS.contains(&letter) || letter == "x" {
            return Some(refuse(
                key,
                &r.letter,
                format!(
                    "`{letter}` is one of OSL's own letters ({} and `x`); a profile adds \
                     letters, it does not redefine them",
                    EVENT_LABELS
                        .iter()
                        .chain(&SCATTERING_LABELS)
                        .map(|l| format!("`{l}`"))
                        .collect::<Vec<_>>()
                        .join(" ")
                ),
            ));
        }
        if seen.contains(&letter) {
            return Some(refuse(key, &r.letter, format!("`{letter}` is added twice")));
        }
        seen.push(letter);
    }
    None
}

/// Prefixes: OSL base only (RenderMan's are its dialect's), words, none twice.
fn prefixes(p: &Profile) -> Option<Refusal> {
    for (i, x) in p.prefixes.iter().enumerate() {
        let key = format!("prefixes[{i}].name");
        let name = x.name.get_ref().as_str();
        if p.dialect() == lpe::DialectName::RenderMan {
            return Some(refuse(
                key,
                &x.name,
                "RenderMan's prefixes are part of its dialect (docs/language.md); a profile \
                 on it adds none"
                    .into(),
            ));
        }
        if name.is_empty() || !name.bytes().all(|b| b.is_ascii_alphabetic() || b == b'_') {
            return Some(refuse(
                key,
                &x.name,
                format!("`{name}` is not a prefix name (letters and `_`)"),
            ));
        }
        if p.prefixes[..i].iter().any(|y| y.name.get_ref() == name) {
            return Some(refuse(key, &x.name, format!("`{name}` is listed twice")));
        }
    }
    None
}

/// Never-produced vertices and built-in expressions parse in the profile's own terms;
/// built-in names are words, each once.
fn expressions(p: &Profile) -> Option<Refusal> {
    let parses = |src: &str| -> Result<(), String> {
        match p.dialect() {
            lpe::DialectName::Osl => {
                lpe::osl::parse(src, &registered_with(p, Default::default(), false))
                    .map(drop)
                    .map_err(|e| e.to_string())
            }
            lpe::DialectName::RenderMan => lpe::renderman::parse(src)
                .map(drop)
                .map_err(|e| e.to_string()),
        }
    };
    for (i, n) in p.never.iter().enumerate() {
        if let Err(e) = parses(n.vertex.get_ref()) {
            return Some(refuse(
                format!("never[{i}].vertex"),
                &n.vertex,
                format!("`{}` does not parse: {e}", n.vertex.get_ref()),
            ));
        }
    }
    for (i, b) in p.builtins.iter().enumerate() {
        let name = b.name.get_ref().as_str();
        // An AOV name as renderers spell them (`diffuse_direct`, Arnold's `RGBA`); a name
        // that OSL could also read as an expression (`RGBA`, `sss`) reads as the built-in.
        let word = name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && name.bytes().all(|c| c.is_ascii_alphanumeric() || c == b'_');
        if !word {
            return Some(refuse(
                format!("builtins[{i}].name"),
                &b.name,
                format!(
                    "`{name}` is not a built-in name (letters, digits and `_`, not first a digit)"
                ),
            ));
        }
        if p.builtins[..i].iter().any(|c| c.name.get_ref() == name) {
            return Some(refuse(
                format!("builtins[{i}].name"),
                &b.name,
                format!("`{name}` is defined twice"),
            ));
        }
        if let Err(e) = parses(b.expr.get_ref()) {
            return Some(refuse(
                format!("builtins[{i}].expr"),
                &b.expr,
                format!("`{}` does not parse: {e}", b.expr.get_ref()),
            ));
        }
    }
    None
}

/// A group table names at least one attribute, each a USD attribute name.
fn groups(p: &Profile) -> Option<Refusal> {
    let g = p.groups.as_ref()?;
    if g.light.is_empty() && g.object.is_empty() {
        return Some(refuse(
            "groups".into(),
            &g.source,
            "names no attribute: a group needs a carrier, `light` or `object`".into(),
        ));
    }
    for (list, names) in [("light", &g.light), ("object", &g.object)] {
        for (i, a) in names.iter().enumerate() {
            let ok = !a.is_empty()
                && a.bytes()
                    .all(|b| b.is_ascii_alphanumeric() || b == b':' || b == b'_');
            if !ok {
                return Some(refuse(
                    format!("groups.{list}[{i}]"),
                    &g.source,
                    format!("`{a}` is not a USD attribute name"),
                ));
            }
        }
    }
    None
}

/// A correspondence parses, and only an OSL-based renderer has one.
fn translation(p: &Profile) -> Option<Refusal> {
    let t = p.translate.as_ref()?;
    if p.dialect() == lpe::DialectName::RenderMan {
        return Some(refuse(
            "translate.correspondence".into(),
            &t.correspondence,
            "a RenderMan-based renderer reads RenderMan's lobes: there is nothing to translate"
                .into(),
        ));
    }
    Correspondence::parse(t.correspondence.get_ref())
        .err()
        .map(|e| {
            refuse(
                "translate.correspondence".into(),
                &t.correspondence,
                e.to_string(),
            )
        })
}
