//! Renderer profiles: how one renderer reads LPEs, as data (docs/profiles.md).
//!
//! A profile names its base dialect (RenderMan's or OSL's), the event and scattering
//! letters the renderer adds, the vertices it never produces, the prefixes it reads, its
//! built-in AOV names, the USD attributes its groups come from, how it treats a
//! `sourceName`'s `lpe:` mark and how RenderMan's lobes become its letters; every rule
//! names the document or source it comes from. The shipped profiles are in `data/`
//! ([`shipped`]); a user's own loads the same way ([`Profile::from_file`]).
//!
//! - `schema`: the file format, read with serde;
//! - `check`: what a loaded profile may not say (a built-in letter redefined, a source
//!   that is not listed, an expression that does not parse), each refusal at its line;
//! - `error`: [`ProfileError`], naming the file, line and key;
//! - `shipped`: the profiles compiled into the crate, looked up by name;
//! - `registration`: [`ProfileDialect`], a profile made into a dialect's registration.

mod check;
mod error;
mod registration;
mod schema;
mod shipped;

pub use error::ProfileError;
pub use registration::ProfileDialect;
pub use schema::{Builtin, Groups, LpeMark, Never, Prefix, Profile, Rule, Source};
pub use shipped::{by_name, names, shipped};

#[cfg(test)]
mod tests;
