//! What the C ABI asks of a dialect beyond [`lpe::Dialect`]: [`CDialect`], implemented
//! on `lpe`'s markers in [`renderman`] and [`osl`] (its `LPE_DIALECT_*` number, what
//! `lpe_set_compile` registers from its `ini_text` or `osl_registered` argument, how a
//! parse error reads), with the reading of one vertex of its C types beside it, and
//! [`DialectSet`], a compiled set of any of them. Compiling is written once over it; classifying is per
//! dialect only where the C types differ.

pub(crate) mod osl;
pub(crate) mod renderman;

use std::ffi::c_char;

use lpe::aov::Automaton;
use lpe::osl::Osl;
use lpe::renderman::RenderMan;
use lpe::{AovSet, Dialect, DialectName};

use crate::error::lpe_error;

/// A dialect as the C ABI compiles it.
pub(crate) trait CDialect: Dialect + lpe_profile::ProfileDialect {
    /// The `LPE_DIALECT_*` number `lpe_set_compile` takes for the dialect.
    const ID: u32;

    /// The registration of `lpe_set_compile`'s `ini_text` and
    /// `options->osl_registered` (each NULL when not given); the one the dialect does not
    /// take is an error.
    fn registration(
        ini_text: *const c_char,
        registered: *const c_char,
    ) -> Result<Self::Registration, lpe_error>;

    /// The message and byte position an `lpe_error` gives for a parse error.
    fn parse_error(e: &Self::ParseError) -> (String, usize);

    /// The set, as an `lpe_set` holds it.
    fn wrap(set: AovSet<Self>) -> DialectSet;

    /// `set`, if it is this dialect's.
    fn set_of(set: &DialectSet) -> Option<&AovSet<Self>>;
}

/// The dialect numbered `id` (an `LPE_DIALECT_*`), if any.
pub(crate) fn by_id(id: u32) -> Option<DialectName> {
    DialectName::ALL
        .into_iter()
        .find(|&d| lpe::with_dialect!(d, D => D::ID) == id)
}

/// A compiled set of any dialect: its vertex classes differ, its automaton does not.
///
/// An enum, not a generic parameter or a trait object, for two reasons. The C ABI has
/// one `lpe_set` type for every dialect, so the set it holds cannot be generic. And
/// every `lpe_step` reads the automaton through it: a match on the discriminant, which
/// inlines into the step and costs a predictable branch, where a trait object would
/// cost an indirect call per vertex. The enum only stores: which dialect an
/// `LPE_DIALECT_*` number names is decided in [`by_id`] through `lpe::registry`
/// (`DialectName`, `with_dialect!`), the one place names map to types; each dialect
/// reaches its variant through its own [`CDialect::wrap`] and [`CDialect::set_of`].
// The variants differ in size, but there is one per `lpe_set`, which the caller holds
// behind a pointer already; boxing the larger would add a load to every OSL step.
#[allow(clippy::large_enum_variant)]
pub(crate) enum DialectSet {
    RenderMan(AovSet<RenderMan>),
    Osl(AovSet<Osl>),
}

impl DialectSet {
    /// What every dialect's set steps.
    #[inline(always)]
    pub(crate) fn automaton(&self) -> &Automaton {
        match self {
            DialectSet::RenderMan(s) => s.automaton(),
            DialectSet::Osl(s) => s.automaton(),
        }
    }

    pub(crate) fn len(&self) -> usize {
        match self {
            DialectSet::RenderMan(s) => s.len(),
            DialectSet::Osl(s) => s.len(),
        }
    }

    pub(crate) fn warnings(&self) -> &[lpe::analysis::Warning] {
        match self {
            DialectSet::RenderMan(s) => s.warnings(),
            DialectSet::Osl(s) => s.warnings(),
        }
    }

    pub(crate) fn class_count(&self) -> usize {
        match self {
            DialectSet::RenderMan(s) => s.class_count(),
            DialectSet::Osl(s) => s.class_count(),
        }
    }
}
