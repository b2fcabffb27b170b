//! The glue between AOVs and the integrator, written once for every dialect: the AOV
//! list ([`list`]: AOVs in one dialect, with their [`flags`] and the partitions a
//! dialect [`declare`]s), what the renderer needs of a dialect ([`dialect`]: the
//! `SceneDialect` trait, over the renderer's own [`vertex`]), the matchers ([`matcher`]),
//! the effects plan ([`plan`]) and its [`error`]. The dialects are siblings, one file
//! each: [`renderman`] and [`osl`].

pub mod declare;
pub mod dialect;
pub mod error;
pub mod flags;
pub mod list;
pub mod matcher;
pub mod osl;
pub mod plan;
pub mod renderman;
pub mod vertex;

pub use declare::{Declared, Partition};
pub use dialect::{IniRefusal, ParsedAov, SceneClassifier, SceneDialect};
pub use error::AovError;
pub use flags::AovFlags;
pub use list::{split_aov_arg, Aov, AovList};
pub use vertex::SceneVertex;
