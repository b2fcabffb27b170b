//! Named material lobes to LPE lobes (docs/language.md §2.4).
//!
//! Materials name their lobes (`Diffuse`, `Clearcoat`, `Albedo`…); a [`LobeMap`] turns a
//! named lobe of a given [`LobeCategory`] into the [`Event`] a vertex records. Names not
//! listed fall back to lobe 1 of their category (`D1`, `S1`, `U1`). Names compare
//! case-sensitively, as RenderMan's do.

use std::collections::BTreeMap;
use std::fmt;

use crate::renderman::path::{Event, EventKind};

/// Which family a named lobe belongs to; decides the fallback and the allowed lobes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LobeCategory {
    /// Diffuse lobes: D1..D4.
    Diffuse,
    /// Specular and glossy lobes: S1..S8.
    Specular,
    /// User signals (material properties): U1..U12.
    User,
}

impl LobeCategory {
    /// Every category, in declaration order (`c as usize` indexes this).
    pub const ALL: [LobeCategory; 3] = [
        LobeCategory::Diffuse,
        LobeCategory::Specular,
        LobeCategory::User,
    ];

    /// The event kind of this category.
    pub fn kind(self) -> EventKind {
        match self {
            LobeCategory::Diffuse => EventKind::D,
            LobeCategory::Specular => EventKind::S,
            LobeCategory::User => EventKind::U,
        }
    }

    /// The `rendermn.ini` key stem: `diffuse`, `specular`, `user`.
    pub fn ini_name(self) -> &'static str {
        match self {
            LobeCategory::Diffuse => "diffuse",
            LobeCategory::Specular => "specular",
            LobeCategory::User => "user",
        }
    }
}

/// RenderMan's default mapping.
const DEFAULTS: &[(LobeCategory, u8, &[&str])] = &[
    (LobeCategory::Diffuse, 2, &["Diffuse", "HairDiffuse"]),
    (LobeCategory::Diffuse, 3, &["Subsurface"]),
    (LobeCategory::Specular, 2, &["Specular", "HairSpecularR"]),
    (
        LobeCategory::Specular,
        3,
        &["RoughSpecular", "HairSpecularTRT"],
    ),
    (LobeCategory::Specular, 4, &["Clearcoat"]),
    (LobeCategory::Specular, 5, &["Iridescence"]),
    (LobeCategory::Specular, 6, &["Fuzz", "HairSpecularGLINTS"]),
    (
        LobeCategory::Specular,
        7,
        &["SingleScatter", "HairSpecularTT"],
    ),
    (LobeCategory::Specular, 8, &["Glass"]),
    (
        LobeCategory::User,
        2,
        &["Albedo", "DiffuseAlbedo", "SubsurfaceAlbedo", "HairAlbedo"],
    ),
    (LobeCategory::User, 3, &["Position"]),
    (LobeCategory::User, 4, &["UserColor"]),
    (
        LobeCategory::User,
        6,
        &[
            "Normal",
            "DiffuseNormal",
            "HairTangent",
            "SubsurfaceNormal",
            "SpecularNormal",
            "RoughSpecularNormal",
            "SingleScatterNormal",
            "FuzzNormal",
            "IridescenceNormal",
            "GlassNormal",
        ],
    ),
];

/// Named lobe -> LPE lobe, per category (indexed by `LobeCategory as usize`, so a
/// lookup borrows the name instead of building a `(category, String)` key).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LobeMap {
    maps: [BTreeMap<String, u8>; 3],
}

impl Default for LobeMap {
    fn default() -> Self {
        let mut m = LobeMap {
            maps: Default::default(),
        };
        for (cat, lobe, names) in DEFAULTS {
            m.assign(*cat, *lobe, names.iter().copied())
                .expect("default lobes are in range");
        }
        m
    }
}

impl LobeMap {
    /// The event of a named lobe: its mapped lobe, or lobe 1 of the category.
    pub fn event(&self, category: LobeCategory, name: &str) -> Event {
        let lobe = self.maps[category as usize].get(name).copied().unwrap_or(1);
        Event::new(category.kind(), lobe).expect("map holds only in-range lobes")
    }

    /// Whether any material lobe lands in `lobe` of `category`: lobe 1 takes every
    /// unmapped name, any other lobe only the names mapped to it. An AOV asking for a lobe
    /// nothing lands in renders black.
    pub fn is_fed(&self, category: LobeCategory, lobe: u8) -> bool {
        lobe == 1 || self.maps[category as usize].values().any(|&l| l == lobe)
    }

    /// Maps `names` to lobe `lobe` of `category` (like `/prman/lpe/diffuse2 A,B`). Each
    /// name moves from wherever it was. Errors if the lobe is out of range.
    pub fn assign<'a>(
        &mut self,
        category: LobeCategory,
        lobe: u8,
        names: impl IntoIterator<Item = &'a str>,
    ) -> Result<(), LobeError> {
        let kind = category.kind();
        if Event::new(kind, lobe).is_none() {
            return Err(LobeError::OutOfRange {
                category,
                lobe,
                max: kind.max_lobe(),
            });
        }
        let map = &mut self.maps[category as usize];
        for n in names {
            map.insert(n.to_string(), lobe);
        }
        Ok(())
    }

    /// Among `signals` (user signals one material emits), those that share a U lobe with
    /// another: they overwrite each other in that lobe's AOV. Returns `(lobe, names)`.
    pub fn user_collisions<'a>(&self, signals: &[&'a str]) -> Vec<(Event, Vec<&'a str>)> {
        let mut by_lobe: BTreeMap<Event, Vec<&'a str>> = BTreeMap::new();
        for s in signals {
            by_lobe
                .entry(self.event(LobeCategory::User, s))
                .or_default()
                .push(s);
        }
        by_lobe.into_iter().filter(|(_, v)| v.len() > 1).collect()
    }
}

/// Why a lobe mapping was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LobeError {
    /// `lobe` is not in `1..=max` for its category.
    OutOfRange {
        /// The category the name was mapped in.
        category: LobeCategory,
        /// The lobe asked for.
        lobe: u8,
        /// The category's last lobe.
        max: u8,
    },
}

impl fmt::Display for LobeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LobeError::OutOfRange {
                category,
                lobe,
                max,
            } => {
                let name = category.ini_name();
                write!(f, "{name}{lobe}: {name} lobes are 1 to {max}")
            }
        }
    }
}

impl std::error::Error for LobeError {}

#[cfg(test)]
mod tests {
    use super::*;

    fn ev(kind: EventKind, lobe: u8) -> Event {
        Event::new(kind, lobe).unwrap()
    }

    #[test]
    fn fed_lobes_follow_the_mappings() {
        let mut m = LobeMap::default();
        // docs/language.md §2.4: D4, U5 and U7..U12 are free by default; lobe 1 takes
        // every unmapped name.
        assert!(m.is_fed(LobeCategory::Diffuse, 1));
        assert!(m.is_fed(LobeCategory::Diffuse, 3));
        assert!(!m.is_fed(LobeCategory::Diffuse, 4));
        assert!(m.is_fed(LobeCategory::User, 2));
        assert!(!m.is_fed(LobeCategory::User, 5));
        assert!(m.is_fed(LobeCategory::Specular, 5));
        m.assign(LobeCategory::User, 5, ["Wetness"]).unwrap();
        assert!(m.is_fed(LobeCategory::User, 5));
        // Moving the only name of U3 away leaves U3 unfed.
        m.assign(LobeCategory::User, 5, ["Position"]).unwrap();
        assert!(!m.is_fed(LobeCategory::User, 3));
    }

    #[test]
    fn categories_index_their_own_map() {
        for (i, c) in LobeCategory::ALL.into_iter().enumerate() {
            assert_eq!(c as usize, i);
        }
        // The same name in two categories maps independently.
        let mut m = LobeMap::default();
        m.assign(LobeCategory::Diffuse, 3, ["Shared"]).unwrap();
        m.assign(LobeCategory::Specular, 5, ["Shared"]).unwrap();
        assert_eq!(
            m.event(LobeCategory::Diffuse, "Shared"),
            ev(EventKind::D, 3)
        );
        assert_eq!(
            m.event(LobeCategory::Specular, "Shared"),
            ev(EventKind::S, 5)
        );
        assert_eq!(m.event(LobeCategory::User, "Shared"), ev(EventKind::U, 1));
    }

    #[test]
    fn defaults_follow_the_design_table() {
        let m = LobeMap::default();
        use LobeCategory::*;
        assert_eq!(m.event(Diffuse, "Diffuse"), ev(EventKind::D, 2));
        assert_eq!(m.event(Diffuse, "Subsurface"), ev(EventKind::D, 3));
        assert_eq!(m.event(Diffuse, "SomethingElse"), ev(EventKind::D, 1));
        assert_eq!(m.event(Specular, "Specular"), ev(EventKind::S, 2));
        assert_eq!(m.event(Specular, "RoughSpecular"), ev(EventKind::S, 3));
        assert_eq!(m.event(Specular, "Clearcoat"), ev(EventKind::S, 4));
        assert_eq!(m.event(Specular, "Iridescence"), ev(EventKind::S, 5));
        assert_eq!(m.event(Specular, "Fuzz"), ev(EventKind::S, 6));
        assert_eq!(m.event(Specular, "SingleScatter"), ev(EventKind::S, 7));
        assert_eq!(m.event(Specular, "Glass"), ev(EventKind::S, 8));
        assert_eq!(m.event(Specular, "Sheen"), ev(EventKind::S, 1));
        assert_eq!(m.event(User, "Albedo"), ev(EventKind::U, 2));
        assert_eq!(m.event(User, "Position"), ev(EventKind::U, 3));
        assert_eq!(m.event(User, "UserColor"), ev(EventKind::U, 4));
        assert_eq!(m.event(User, "GlassNormal"), ev(EventKind::U, 6));
        assert_eq!(m.event(User, "Whatever"), ev(EventKind::U, 1));
    }

    #[test]
    fn assign_moves_names_and_checks_range() {
        let mut m = LobeMap::default();
        m.assign(LobeCategory::Specular, 4, ["Sheen"]).unwrap();
        assert_eq!(
            m.event(LobeCategory::Specular, "Sheen"),
            ev(EventKind::S, 4)
        );
        m.assign(LobeCategory::Diffuse, 4, ["Diffuse"]).unwrap();
        assert_eq!(
            m.event(LobeCategory::Diffuse, "Diffuse"),
            ev(EventKind::D, 4)
        );
        assert!(m.assign(LobeCategory::Diffuse, 5, ["X"]).is_err());
        assert!(m.assign(LobeCategory::User, 0, ["X"]).is_err());
    }

    #[test]
    fn user_signals_sharing_a_lobe_collide() {
        let m = LobeMap::default();
        let c = m.user_collisions(&["Albedo", "DiffuseAlbedo", "Position"]);
        assert_eq!(
            c,
            vec![(ev(EventKind::U, 2), vec!["Albedo", "DiffuseAlbedo"])]
        );
    }
}
