//! # lpe-lint — the LPE AOVs pipelines declare, read with their locations
//!
//! Lighting pipelines declare LPE AOVs in three places; this crate reads each into one
//! [`Document`] model, keeping where every declaration sits so a checker can point at it:
//!
//! - USD stages ([`read::usd`], through the `openusd` crate): `RenderVar` prims with
//!   `sourceType = "lpe"`, `RenderProduct.orderedVars`, the light-group and object-group
//!   attributes the render delegates read, and declared partitions
//!   (`custom string lpe:partition` on a `RenderSettings` prim);
//! - RIB ([`read::rib`]): `DisplayChannel` lines with an `lpe:` source, streamed;
//! - `rendermn.ini` ([`read::ini`]): macros and lobe mappings, through [`lpe::renderman::Config`].
//!
//! Every reader has a documented size limit ([`read::Limits`]) and turns bad bytes into a
//! [`ReadError`] with the file and, where there is one, the line; none panics.
//!
//! Modules: [`decl`] (what a file declares: AOVs, partitions, groups, lobe mappings),
//! [`read`] (the readers, one per format, and their limits), [`error`] (why a file could
//! not be read).
//!
//! The checks on the declarations (emptiness, equivalence, groups, partitions) are in
//! `lpe-check lint`; `lpe-render --usd` takes its AOVs from [`read::usd`].

#![warn(missing_docs)]

pub mod decl;
pub mod error;
pub mod read;

pub use decl::{AovDecl, Document, Format, Location, PartitionDecl};
pub use error::{ReadError, RibProblem};
