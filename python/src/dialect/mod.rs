//! What a dialect says to Python: [`PyDialect`] (its registration from `ini=` or
//! `register=`, the text of a `(type, event, label)` vertex tuple), implemented on
//! `lpe`'s markers in [`renderman`] and [`osl`]; and the argument conversions written
//! once over it: the dialect and renderer's profile ([`Language::of`], from `dialect=`,
//! `renderer=` and `profile=`), the registration ([`Language::registration`]), an
//! expression ([`parse`]), a path as text or tuples ([`path`]).

pub mod osl;
pub mod renderman;

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use lpe::{Dialect, DialectName};
use lpe_lint::check::dialect::LintDialect;
use lpe_profile::{Profile, ProfileDialect};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyString, PyTuple};

use crate::error::{syntax_error, value_error};

/// An expression language as the Python package reads it; a renderer's profile adds
/// its letters, prefixes and built-in names to the registration ([`ProfileDialect`]).
pub trait PyDialect: LintDialect + ProfileDialect {
    /// The registration `ini` (a `rendermn.ini` file) or `register` (OSL's user
    /// labels, `events=U;scatters=Y`) give; the one the dialect does not take is an
    /// error.
    fn registration(
        ini: Option<&std::path::Path>,
        register: Option<&str>,
    ) -> Result<Self::Registration, String>;

    /// The text of one vertex given as `(type, event, label)` (event and label may be
    /// `None`), in the dialect's path notation.
    fn vertex_text(ty: &str, event: Option<&str>, label: Option<&str>) -> String;
}

/// The language the arguments `dialect=`, `renderer=` and `profile=` name: the dialect
/// and, when a renderer is named, its profile.
pub struct Language {
    /// The dialect expressions are read in: the profile's base, else `dialect=`, else
    /// RenderMan's.
    pub dialect: DialectName,
    /// The renderer's profile: a shipped one (`renderer=`) or a user's file (`profile=`).
    pub profile: Option<Cow<'static, Profile>>,
}

impl Language {
    /// Resolves the arguments once. `ValueError` for an unknown dialect, an unknown
    /// renderer (the message lists the shipped ones and the nearest), a profile file
    /// that does not load, both `renderer=` and `profile=`, or a `dialect=` other than
    /// the profile's base.
    pub fn of(
        dialect: Option<&str>,
        renderer: Option<&str>,
        profile: Option<&Path>,
    ) -> PyResult<Language> {
        let given = dialect.map(dialect_name).transpose()?;
        let profile: Option<Cow<'static, Profile>> = match (renderer, profile) {
            (Some(_), Some(_)) => {
                return Err(value_error(
                    "renderer= and profile= each name a profile; give one of them",
                ))
            }
            (Some(name), None) => Some(Cow::Borrowed(
                lpe_profile::by_name(name).map_err(value_error)?,
            )),
            (None, Some(file)) => Some(Cow::Owned(Profile::from_file(file).map_err(value_error)?)),
            (None, None) => None,
        };
        let Some(p) = profile else {
            return Ok(Language {
                dialect: given.unwrap_or_default(),
                profile: None,
            });
        };
        let base = p.dialect();
        if let Some(given) = given.filter(|d| *d != base) {
            // Reading a renderer's expressions in the other dialect would check
            // something the renderer never reads: refused, as `lpe-check` refuses it.
            return Err(value_error(format!(
                "dialect=\"{given}\" contradicts renderer \"{}\", which reads {base}'s \
                 dialect; drop dialect=",
                p.name
            )));
        }
        Ok(Language {
            dialect: base,
            profile: Some(p),
        })
    }

    /// The registration of `D` from `ini=` and `register=` (`ValueError` when they are
    /// bad), with the profile's letters, prefixes and built-in names on top.
    pub fn registration<D: PyDialect>(
        &self,
        ini: Option<&PathBuf>,
        register: Option<&str>,
    ) -> PyResult<D::Registration> {
        self.registration_of::<D>(ini.map(PathBuf::as_path), register)
            .map_err(value_error)
    }

    /// [`Language::registration`] with the error as text, for lint's run (which names
    /// the ini file itself).
    pub fn registration_of<D: PyDialect>(
        &self,
        ini: Option<&Path>,
        register: Option<&str>,
    ) -> Result<D::Registration, String> {
        let base = D::registration(ini, register)?;
        Ok(match &self.profile {
            Some(p) => D::with_profile(p, base),
            None => base,
        })
    }
}

/// The dialect a `dialect=` argument names (`ValueError` for any other name).
pub fn dialect_name(name: &str) -> PyResult<DialectName> {
    name.parse().map_err(value_error)
}

/// Parses `src` as an AOV's source (a leading `lpe:` included); `LpeSyntaxError` if it
/// does not parse.
pub fn parse<D: PyDialect>(
    py: Python<'_>,
    src: &str,
    registration: &D::Registration,
    aov: Option<&str>,
) -> PyResult<D::Lpe> {
    D::parse_source(src, registration).map_err(|f| syntax_error(py, &f, aov))
}

/// The text of a path argument: a `str` as it is, or a sequence of `(type, event,
/// label)` tuples (`TypeError` for anything else).
pub fn path_text<D: PyDialect>(obj: &Bound<'_, PyAny>) -> PyResult<String> {
    if let Ok(s) = obj.downcast::<PyString>() {
        return Ok(s.to_str()?.to_string());
    }
    let bad = || {
        PyTypeError::new_err(format!(
            "a path is a str such as \"C RD L\" or a list of (type, event, label) tuples, \
             not {}",
            obj.get_type()
                .name()
                .map_or("this".to_string(), |n| n.to_string())
        ))
    };
    let items = obj.try_iter().map_err(|_| bad())?;
    let mut vertices = Vec::new();
    for item in items {
        let item = item?;
        let tuple = item.downcast::<PyTuple>().map_err(|_| bad())?;
        let (ty, event, label): (String, Option<String>, Option<String>) = match tuple.len() {
            3 => tuple.extract().map_err(|_| vertex_error(&item))?,
            _ => return Err(vertex_error(&item)),
        };
        vertices.push(D::vertex_text(&ty, event.as_deref(), label.as_deref()));
    }
    Ok(vertices.join(" "))
}

fn vertex_error(item: &Bound<'_, PyAny>) -> PyErr {
    PyTypeError::new_err(format!(
        "a vertex is a (type, event, label) tuple of str or None, not {item}"
    ))
}

/// A path argument, parsed (`ValueError` with the path and the reason if it is not a
/// path of the dialect).
pub fn path<D: PyDialect>(obj: &Bound<'_, PyAny>) -> PyResult<D::Path> {
    let text = path_text::<D>(obj)?;
    parse_path::<D>(&text).map_err(value_error)
}

/// A path's text, parsed; the error names the path.
pub fn parse_path<D: Dialect>(text: &str) -> Result<D::Path, String> {
    text.parse::<D::Path>()
        .map_err(|e| format!("path `{text}`: {e}"))
}
