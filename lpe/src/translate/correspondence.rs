//! The correspondence between the two path models: which OSL vertex a RenderMan vertex
//! is (docs/language.md §19.1). One map, from RenderMan's view of a vertex to OSL's, as a
//! renderer produces both views from one scene vertex; both directions of translation
//! and the cross-dialect comparison are judged on it.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;

use crate::osl::symbol::{EVENT_LABELS, SCATTERING_LABELS};
use crate::osl::{self, Symbol};
use crate::renderman::{self, Event, EventKind, VertexType};

/// OSL's scattering label of a transport lobe.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Scattering {
    /// `D`: diffuse.
    Diffuse,
    /// `G`: glossy.
    Glossy,
    /// `S`: singular (a delta lobe).
    Singular,
    /// `s`: straight through.
    Straight,
}

impl Scattering {
    /// All four, in OSL's order.
    pub const ALL: [Scattering; 4] = [
        Scattering::Diffuse,
        Scattering::Glossy,
        Scattering::Singular,
        Scattering::Straight,
    ];

    /// The OSL label.
    pub fn label(self) -> &'static str {
        match self {
            Scattering::Diffuse => "D",
            Scattering::Glossy => "G",
            Scattering::Singular => "S",
            Scattering::Straight => "s",
        }
    }

    fn from_label(s: &str) -> Option<Scattering> {
        Scattering::ALL.into_iter().find(|x| x.label() == s)
    }
}

/// Why a correspondence declaration did not read: the byte where the bad part starts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeclarationError {
    /// Byte offset of the bad part in the declaration.
    pub pos: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for DeclarationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "correspondence at byte {}: {}", self.pos, self.message)
    }
}

impl std::error::Error for DeclarationError {}

/// How a RenderMan vertex is seen in OSL.
///
/// - the camera is `C,~`; a light `L,~` and an emissive object `O,~`, each followed by its
///   label (light group, `lpegroup`) as a custom label;
/// - an `R`/`T` vertex with a transport lobe is `R`/`T`, then the lobe's scattering
///   ([`Correspondence::scattering`]), then its label;
/// - a user-lobe vertex has no OSL counterpart (OSL has no user lobes), and neither has
///   a vertex whose label would be one of OSL's built-in labels (`C L B V T R O D G S s`:
///   OSL's eater does not skip them, so `R` would miss such a vertex; `lpe-render` refuses
///   such scenes).
///
/// Labels carry over unchanged unless renamed ([`Correspondence::rename`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Correspondence {
    diffuse: [Scattering; 4],
    specular: [Scattering; 8],
    labels: BTreeMap<String, String>,
}

impl Default for Correspondence {
    /// The one `lpe-render --dialect osl` renders with on its shipped scenes: diffuse lobes
    /// are `D`; `S8` (`Glass`, the dielectric) is `S`; the other specular lobes (`Specular`,
    /// `RoughSpecular`, `Clearcoat`, … GGX lobes) are `G`; labels unchanged.
    fn default() -> Self {
        let mut specular = [Scattering::Glossy; 8];
        specular[7] = Scattering::Singular;
        Correspondence {
            diffuse: [Scattering::Diffuse; 4],
            specular,
            labels: BTreeMap::new(),
        }
    }
}

impl Correspondence {
    /// The default with `declaration` applied: parts separated by commas or whitespace,
    /// each `LOBES=SCATTERING` (`S4=S`, `S1-S7=G`, `D3=s`; lobes `D1`-`D4`, `S1`-`S8`,
    /// scatterings `D G S s`) or `'rm'='osl'` (the RenderMan label `rm` is the OSL custom
    /// label `osl`).
    pub fn parse(declaration: &str) -> Result<Correspondence, DeclarationError> {
        Correspondence::default().apply(declaration)
    }

    /// This correspondence with `declaration` applied on top (a renderer profile's, then
    /// the user's changes), in [`Correspondence::parse`]'s syntax; error positions count
    /// in `declaration`.
    pub fn apply(self, declaration: &str) -> Result<Correspondence, DeclarationError> {
        let mut c = self;
        let mut pos = 0;
        for part in declaration.split(|ch: char| ch == ',' || ch.is_whitespace()) {
            let at = pos;
            pos += part.len() + 1;
            if part.is_empty() {
                continue;
            }
            let err = |message: String| DeclarationError { pos: at, message };
            let Some((lhs, rhs)) = part.split_once('=') else {
                return Err(err(format!(
                    "`{part}` is not `LOBES=SCATTERING` or `'label'='label'`"
                )));
            };
            if lhs.starts_with('\'') {
                let quoted = |s: &str| {
                    s.strip_prefix('\'')
                        .and_then(|s| s.strip_suffix('\''))
                        .filter(|s| !s.contains('\''))
                        .map(str::to_string)
                };
                match (quoted(lhs), quoted(rhs)) {
                    (Some(a), Some(b)) => {
                        c.labels.insert(a, b);
                    }
                    _ => {
                        return Err(err(format!(
                            "`{part}`: a label renaming is `'renderman'='osl'` (labels without \
                             spaces, commas or quotes)"
                        )))
                    }
                }
                continue;
            }
            let scattering = Scattering::from_label(rhs)
                .ok_or_else(|| err(format!("`{rhs}` is not an OSL scattering (D, G, S or s)")))?;
            let (first, last) = match lhs.split_once('-') {
                Some((a, b)) => (a, b),
                None => (lhs, lhs),
            };
            let (first, last) = match (transport_lobe(first), transport_lobe(last)) {
                (Some(a), Some(b)) if a.kind() == b.kind() && a.lobe() <= b.lobe() => (a, b),
                _ => {
                    return Err(err(format!(
                        "`{lhs}` is not a transport lobe (D1-D4, S1-S8) or a range of one kind \
                         (S1-S7); user lobes have no OSL counterpart"
                    )))
                }
            };
            for lobe in first.lobe()..=last.lobe() {
                let e = Event::new(first.kind(), lobe).expect("within the range's bounds");
                *c.slot(e) = scattering;
            }
        }
        Ok(c)
    }

    fn slot(&mut self, e: Event) -> &mut Scattering {
        let i = usize::from(e.lobe() - 1);
        match e.kind() {
            EventKind::D => &mut self.diffuse[i],
            _ => &mut self.specular[i],
        }
    }

    /// The OSL scattering of a transport lobe; `None` for a user lobe.
    pub fn scattering(&self, e: Event) -> Option<Scattering> {
        let i = usize::from(e.lobe() - 1);
        match e.kind() {
            EventKind::D => Some(self.diffuse[i]),
            EventKind::S => Some(self.specular[i]),
            EventKind::U => None,
        }
    }

    /// Whether some transport lobe is shown as `s`.
    pub fn shows(&self, s: Scattering) -> bool {
        self.diffuse.contains(&s) || self.specular.contains(&s)
    }

    /// The OSL custom label of a RenderMan label.
    pub fn rename<'a>(&'a self, label: &'a str) -> &'a str {
        self.labels.get(label).map_or(label, String::as_str)
    }

    /// The RenderMan lobes of each scattering, for the docs and reports: `S1-S7=G S8=S`
    /// for the default (diffuse lobes `D` and unchanged labels are not written).
    pub fn declaration(&self) -> String {
        let mut parts = Vec::new();
        for kind in [EventKind::D, EventKind::S] {
            let lobes: Vec<(u8, Scattering)> = (1..=kind.max_lobe())
                .filter_map(|l| Event::new(kind, l))
                .map(|e| (e.lobe(), self.scattering(e).expect("transport")))
                .collect();
            let mut i = 0;
            while i < lobes.len() {
                let mut j = i;
                while j + 1 < lobes.len() && lobes[j + 1].1 == lobes[i].1 {
                    j += 1;
                }
                let k = kind.letter();
                let s = lobes[i].1;
                if !(kind == EventKind::D && s == Scattering::Diffuse) {
                    if i == j {
                        parts.push(format!("{k}{}={}", lobes[i].0, s.label()));
                    } else {
                        parts.push(format!("{k}{}-{k}{}={}", lobes[i].0, lobes[j].0, s.label()));
                    }
                }
                i = j + 1;
            }
        }
        for (a, b) in &self.labels {
            parts.push(format!("'{a}'='{b}'"));
        }
        parts.join(" ")
    }

    /// The OSL vertex of a RenderMan vertex, or `None` when it has no counterpart (a user
    /// lobe, or a label that would be a built-in OSL label).
    pub fn view(&self, v: &renderman::Vertex) -> Option<osl::Vertex> {
        let (event, scattering) = match v.ty() {
            VertexType::C => ("C", None),
            VertexType::L => ("L", None),
            VertexType::O => ("O", None),
            ty => {
                let s = self.scattering(v.event()?)?;
                (if ty == VertexType::R { "R" } else { "T" }, Some(s))
            }
        };
        let mut symbols = vec![
            Symbol::label(event),
            scattering.map_or(Symbol::None, |s| Symbol::label(s.label())),
        ];
        if let Some(l) = v.label() {
            let l = self.rename(l);
            if is_builtin(l) {
                return None;
            }
            symbols.push(Symbol::label(l));
        }
        Some(osl::Vertex::new(symbols))
    }

    /// The OSL path of a RenderMan path, when every vertex has a counterpart.
    pub fn view_path(&self, p: &renderman::Path) -> Option<osl::Path> {
        p.vertices()
            .iter()
            .map(|v| self.view(v))
            .collect::<Option<Vec<_>>>()
            .map(osl::Path::new)
    }

    /// One RenderMan vertex for each way the given labels can tell vertices apart: every
    /// type and lobe, each with no label, each label of `renderman_labels`, each
    /// RenderMan label that becomes one of `osl_labels`, and one label neither side
    /// mentions. Every RenderMan vertex is matched by an atom mentioning only these
    /// labels, and its OSL view by a vertex pattern mentioning only these, exactly when
    /// the representative of the same type, lobe and label kind is: so searches over
    /// these vertices decide questions about all vertices. Returns the vertices and the
    /// label nobody mentions.
    pub fn universe(
        &self,
        renderman_labels: &BTreeSet<String>,
        osl_labels: &BTreeSet<String>,
    ) -> (Vec<renderman::Vertex>, String) {
        // The OSL labels in play, and every RenderMan label that becomes one of them
        // (itself unrenamed, or renamed onto it): those are the vertices a renaming can
        // merge.
        let mut targets: BTreeSet<String> = osl_labels.clone();
        targets.extend(renderman_labels.iter().map(|l| self.rename(l).to_string()));
        let mut labels: BTreeSet<String> = renderman_labels.clone();
        labels.extend(targets.iter().cloned());
        labels.extend(
            self.labels
                .iter()
                .filter(|(_, b)| targets.contains(*b))
                .map(|(a, _)| a.clone()),
        );
        // A label OSL would read as built in is outside the correspondence.
        labels.retain(|l| !is_builtin(self.rename(l)));
        // The fresh label must be mentioned by neither side and be its own OSL label (not
        // a renamed one, which could be renamed onto a built-in label or a mentioned one).
        // Candidates start `other`, so none is built in.
        // (The OSL labels are among `labels`, but for those a key renames onto a built-in
        // label, and keys are taken.)
        let taken = |s: &str| labels.contains(s) || self.labels.contains_key(s);
        let mut fresh = String::from("other");
        while taken(&fresh) {
            fresh.push('_');
        }
        labels.insert(fresh.clone());
        let labels: Vec<Option<&str>> = std::iter::once(None)
            .chain(labels.iter().map(|l| Some(l.as_str())))
            .collect();
        let mut out = vec![renderman::Vertex::camera()];
        for &l in &labels {
            out.push(renderman::Vertex::light(l));
            out.push(renderman::Vertex::emissive(l));
            for ty in [VertexType::R, VertexType::T] {
                out.extend(Event::all().map(|e| renderman::Vertex::scatter(ty, e, l)));
            }
        }
        (out, fresh)
    }
}

/// `D1`..`D4`, `S1`..`S8`.
fn transport_lobe(s: &str) -> Option<Event> {
    let mut cs = s.chars();
    let kind = EventKind::from_letter(cs.next()?)?;
    if kind == EventKind::U {
        return None;
    }
    let lobe: u8 = cs.as_str().parse().ok()?;
    Event::new(kind, lobe)
}

/// One of OSL's built-in event or scattering labels.
pub fn is_builtin(label: &str) -> bool {
    EVENT_LABELS.contains(&label) || SCATTERING_LABELS.contains(&label)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(text: &str) -> renderman::Vertex {
        let p: renderman::Path = format!("C {text} L").parse().unwrap();
        p.vertices()[1].clone()
    }

    fn view_text(c: &Correspondence, text: &str) -> Option<String> {
        c.view(&v(text)).map(|w| w.to_string())
    }

    #[test]
    fn the_default_follows_the_shipped_scenes() {
        let c = Correspondence::default();
        assert_eq!(view_text(&c, "RD2'floor'").as_deref(), Some("R,D,floor"));
        assert_eq!(view_text(&c, "TD3").as_deref(), Some("T,D"));
        assert_eq!(view_text(&c, "RS2").as_deref(), Some("R,G"));
        assert_eq!(view_text(&c, "RS7").as_deref(), Some("R,G"));
        assert_eq!(view_text(&c, "TS8").as_deref(), Some("T,S"));
        assert_eq!(view_text(&c, "RU2"), None);
        assert_eq!(view_text(&c, "RD1'G'"), None);
        let p: renderman::Path = "C RS8'glass' L'key'".parse().unwrap();
        assert_eq!(
            c.view_path(&p).unwrap().to_string(),
            "C,~ R,S,glass L,~,key"
        );
        let p: renderman::Path = "C O'glow'".parse().unwrap();
        assert_eq!(c.view_path(&p).unwrap().to_string(), "C,~ O,~,glow");
        assert_eq!(c.declaration(), "S1-S7=G S8=S");
    }

    #[test]
    fn declarations_change_lobes_and_labels() {
        let c = Correspondence::parse("S4=S, S5-S6=s 'key'='lg_key' D4=G").unwrap();
        assert_eq!(view_text(&c, "RS4").as_deref(), Some("R,S"));
        assert_eq!(view_text(&c, "RS5").as_deref(), Some("R,s"));
        assert_eq!(view_text(&c, "RS6").as_deref(), Some("R,s"));
        assert_eq!(view_text(&c, "RS7").as_deref(), Some("R,G"));
        assert_eq!(view_text(&c, "RD4'key'").as_deref(), Some("R,G,lg_key"));
        assert_eq!(
            c.declaration(),
            "D4=G S1-S3=G S4=S S5-S6=s S7=G S8=S 'key'='lg_key'"
        );
        assert_eq!(Correspondence::parse(&c.declaration()).unwrap(), c);
    }

    #[test]
    fn bad_declarations_name_their_byte() {
        let e = |s: &str| Correspondence::parse(s).unwrap_err();
        assert_eq!(e("S4=S U2=G").pos, 5);
        assert!(e("S4=S U2=G").message.contains("user lobes"));
        assert_eq!(e("S4=X").pos, 0);
        assert_eq!(e("S1 S2").pos, 0);
        assert_eq!(e("S7-S2=G").pos, 0);
        assert_eq!(e("D1-S2=G").pos, 0);
        assert_eq!(e("S9=G").pos, 0);
        assert_eq!(e("  'a'=b").pos, 2);
    }

    #[test]
    fn the_universe_has_a_label_nobody_mentions() {
        let c = Correspondence::parse("'a'='other'").unwrap();
        let rm: BTreeSet<String> = ["other_".to_string()].into();
        let osl: BTreeSet<String> = ["other".to_string()].into();
        let (u, fresh) = c.universe(&rm, &osl);
        assert_eq!(fresh, "other__");
        let labels: BTreeSet<Option<&str>> = u.iter().map(|v| v.label()).collect();
        // `a` becomes `other`; `other_` is mentioned: the fresh label is `other__`.
        assert_eq!(
            labels,
            [
                None,
                Some("a"),
                Some("other"),
                Some("other_"),
                Some("other__")
            ]
            .into()
        );
        // camera + per label (L, O, 2 x 24 lobes).
        assert_eq!(u.len(), 1 + 5 * (2 + 2 * 24));
    }

    #[test]
    fn the_fresh_label_is_never_a_renamed_one() {
        // Renamed onto a built-in label, `other` would have no OSL view at all.
        let c = Correspondence::parse("'other'='D'").unwrap();
        let (u, fresh) = c.universe(&BTreeSet::new(), &BTreeSet::new());
        assert_eq!(fresh, "other_");
        assert!(u
            .iter()
            .all(|v| v.event().is_some_and(|e| !e.is_transport()) || c.view(v).is_some()));
        // Mentioned on the OSL side only.
        let osl: BTreeSet<String> = ["other".to_string()].into();
        let (_, fresh) = Correspondence::default().universe(&BTreeSet::new(), &osl);
        assert_eq!(fresh, "other_");
    }

    #[test]
    fn shows_names_the_scatterings_some_lobe_becomes() {
        let default = Correspondence::default();
        assert!(default.shows(Scattering::Glossy) && default.shows(Scattering::Singular));
        assert!(!default.shows(Scattering::Straight));
        // Karma's: every specular lobe glossy, so no lobe is singular any more.
        let karma = Correspondence::parse("S1-S8=G").unwrap();
        assert!(!karma.shows(Scattering::Singular));
        assert!(Correspondence::parse("D3=s")
            .unwrap()
            .shows(Scattering::Straight));
    }
}
