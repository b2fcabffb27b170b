//! # lpe-lint — the LPE AOVs pipelines declare, read with their locations
//!
//! Lighting pipelines declare LPE AOVs in three places; this crate reads each into one
//! [`Document`] model, keeping where every declaration sits so a checker can point at it:
//!
//! - USD stages ([`read::usd`], through the `openusd` crate, or [`read::flat`] for a
//!   `.usda` that composes nothing, both behind [`read::read_usd`]): `RenderVar` prims with
//!   `sourceType = "lpe"`, `RenderProduct.orderedVars`, the light-group and object-group
//!   attributes the render delegates read, declared partitions
//!   (`custom string lpe:partition` on a `RenderSettings` prim) and the declared dialect
//!   (`custom string lpe:dialect`);
//! - RIB ([`read::rib`]): `DisplayChannel` lines with an `lpe:` source, streamed;
//! - `rendermn.ini` ([`read::ini`]): macros and lobe mappings, through [`lpe::renderman::Config`].
//!
//! Every reader has a documented size limit ([`read::Limits`]) and turns bad bytes into a
//! [`ReadError`] with the file and, where there is one, the line; none panics.
//!
//! The checks on the declarations are [`check`]'s (parse errors, emptiness, equivalence,
//! group labels, lobes, partitions, expressions of an undeclared dialect that mean
//! different things in RenderMan's and OSL's) with its text and JSON reports; `lpe-check lint`
//! parses its arguments, calls them and prints. Every partition witness is re-checked
//! with the reference matcher first ([`witness`], which `lpe-check equiv` and
//! `partition` use too). `lpe-render --usd` takes its AOVs from [`read::usd`].
//!
//! Modules: [`decl`] (the document model), [`error`] (read errors), [`explain`] (which
//! AOVs a path lands in, vertex by vertex), [`read`] (the three
//! readers and their limits), [`check`] (the lint checks and reports), [`witness`]
//! (the reference re-check).

#![warn(missing_docs)]

pub mod check;
pub mod decl;
pub mod error;
pub mod explain;
pub mod read;
pub mod witness;

pub use decl::{AovDecl, DialectDecl, Document, Format, Location, PartitionDecl};
pub use error::{DialectProblem, ReadError, RibProblem};
