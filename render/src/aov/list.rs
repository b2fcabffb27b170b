//! The AOV list of a render: named expressions in one dialect `D`, how each accumulates,
//! and the partitions of beauty they are known to form. Built from a dialect's defaults
//! ([`AovList::for_render`]) or AOV by AOV ([`AovList::push`]).

use lpe::Dialect;

use super::declare::{Declared, Partition};
use super::dialect::SceneDialect;
use super::error::AovError;
use super::flags::AovFlags;
use crate::scene::furnace::{furnace_params, FURNACE_BOUNCES};
use crate::scene::Scene;

/// One AOV: its layer name, the source as given, and the parsed expression.
#[derive(Clone, Debug)]
pub struct Aov<D: Dialect> {
    pub name: String,
    pub source: String,
    pub expr: D::Lpe,
    pub flags: AovFlags,
}

/// AOVs in dialect `D`, in layer order (layer `1 + i` is AOV `i`; layer 0 is beauty).
#[derive(Clone, Debug)]
pub struct AovList<D: Dialect> {
    pub aovs: Vec<Aov<D>>,
    pub partitions: Vec<Partition>,
    /// Why a default partition was not checked, and the expressions' warnings.
    pub notes: Vec<String>,
    /// The registration the AOVs were read under (the latest [`AovList::push`]'s): the
    /// formal checks read the universe under it too, so that a label a renderer
    /// registers (Karma's `A`) means the same on both sides.
    pub registration: D::Registration,
}

impl<D: Dialect> Default for AovList<D> {
    fn default() -> Self {
        AovList {
            aovs: Vec::new(),
            partitions: Vec::new(),
            notes: Vec::new(),
            registration: D::Registration::default(),
        }
    }
}

impl<D: Dialect> AovList<D> {
    /// An empty list.
    pub fn new() -> AovList<D> {
        AovList::default()
    }

    /// `(name, expression)` pairs, as `lpe::AovSet::compile` takes them.
    pub fn named(&self) -> Vec<(String, D::Lpe)> {
        self.aovs
            .iter()
            .map(|a| (a.name.clone(), a.expr.clone()))
            .collect()
    }

    /// The expressions, in layer order.
    pub fn lpes(&self) -> Vec<D::Lpe> {
        self.aovs.iter().map(|a| a.expr.clone()).collect()
    }

    pub fn index(&self, name: &str) -> Option<usize> {
        self.aovs.iter().position(|a| a.name == name)
    }

    /// How each AOV accumulates, in layer order.
    pub fn flags(&self) -> Vec<AovFlags> {
        self.aovs.iter().map(|a| a.flags).collect()
    }

    /// The layer names after beauty.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.aovs.iter().map(|a| a.name.as_str())
    }
}

impl<D: SceneDialect> AovList<D> {
    /// Parses and appends one AOV under `registration` (its warnings join the notes);
    /// names must be unique and usable as EXR layer and file names.
    pub fn push(
        &mut self,
        name: &str,
        source: &str,
        registration: &D::Registration,
    ) -> Result<usize, AovError> {
        if name.is_empty()
            || !name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
        {
            return Err(AovError::BadName { name: name.into() });
        }
        if name == "beauty" || self.index(name).is_some() {
            return Err(AovError::DuplicateName { name: name.into() });
        }
        let parsed = D::parse_aov(source, registration).map_err(|error| AovError::Parse {
            name: name.into(),
            dialect: D::MESSAGE_TAG,
            error,
        })?;
        for w in parsed.warnings {
            self.notes.push(format!("AOV `{name}`: {w}"));
        }
        self.aovs.push(Aov {
            name: name.to_string(),
            source: source.to_string(),
            expr: parsed.lpe,
            flags: parsed.flags,
        });
        self.registration = registration.clone();
        Ok(self.aovs.len() - 1)
    }

    /// The list of `declared` AOVs, parsed under `registration`, with their partitions
    /// and notes.
    pub fn declared(
        declared: Declared,
        registration: &D::Registration,
    ) -> Result<AovList<D>, AovError> {
        let mut list = AovList::new();
        for (name, source) in &declared.aovs {
            list.push(name, source, registration)?;
        }
        list.partitions = declared.partitions;
        list.notes.extend(declared.notes);
        Ok(list)
    }

    /// The basic AOVs ([`SceneDialect::basic_aovs`]), declared as the partition of
    /// beauty they are.
    pub fn basic(registration: &D::Registration) -> Result<AovList<D>, AovError> {
        AovList::declared(D::basic(), registration)
    }

    /// The dialect's default AOVs for `scene` ([`SceneDialect::defaults`]).
    pub fn defaults(scene: &Scene, registration: &D::Registration) -> Result<AovList<D>, AovError> {
        AovList::declared(D::defaults(scene), registration)
    }

    /// The AOV list for a render: the defaults, plus for the furnace the per-bounce AOVs
    /// `furnace_bounceK` ([`SceneDialect::furnace_bounce`]).
    pub fn for_render(
        scene: &Scene,
        registration: &D::Registration,
    ) -> Result<AovList<D>, AovError> {
        let mut list = AovList::defaults(scene, registration)?;
        if furnace_params(scene).is_some() {
            for k in 0..=FURNACE_BOUNCES {
                let name = format!("furnace_bounce{k}");
                list.push(&name, &D::furnace_bounce(k), registration)?;
            }
        }
        Ok(list)
    }
}

/// Splits `NAME=LPE` (the first `=` separates: expressions never contain one).
pub fn split_aov_arg(arg: &str) -> Result<(&str, &str), AovError> {
    arg.split_once('=')
        .map(|(n, s)| (n.trim(), s.trim()))
        .ok_or_else(|| AovError::BadArgument { arg: arg.into() })
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::{Parser, RenderMan};

    #[test]
    fn names_and_expressions_are_checked() {
        let p = Parser::default();
        let mut l = AovList::<RenderMan>::new();
        l.push("a", "C<RD>L", &p).unwrap();
        assert!(l
            .push("a", "CL", &p)
            .unwrap_err()
            .to_string()
            .contains("twice"));
        assert!(l.push("beauty", "CL", &p).is_err());
        assert!(l
            .push("a.b", "CL", &p)
            .unwrap_err()
            .to_string()
            .contains("letters"));
        assert!(l
            .push("b", "C<L'key'>", &p)
            .unwrap_err()
            .to_string()
            .starts_with("AOV `b`: "));
        assert!(split_aov_arg("noequals").is_err());
        assert_eq!(split_aov_arg("x=C.*L").unwrap(), ("x", "C.*L"));
    }
}
