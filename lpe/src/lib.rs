//! # lpe — Light Path Expressions, parsed and matched right
//!
//! Renderers route every light path into AOVs with expressions such as
//! `C<RD>.+[<L.>O]` ("indirect diffuse"). This crate holds the language, the automata a
//! set of expressions compiles into, and the formal analysis on them. It depends on no
//! other crate of the workspace.
//!
//! # Modules, bottom-up
//!
//! - The seam ([`dialect`]): the [`Dialect`] trait every layer above is generic over; its
//!   two implementations, each in its folder: [`renderman`] ([`renderman::RenderMan`]:
//!   path model, expression tree, front end with prefixes, macros, lobe maps and
//!   `rendermn.ini`, and the class alphabet it lowers to) and [`osl`] ([`osl::Osl`]: the
//!   same for Open Shading Language's dialect); [`registry`] names them at run time
//!   ([`DialectName`], [`with_dialect!`]); [`translate`] carries expressions between the
//!   two with a proof (the correspondence, cross-dialect comparison). Shared by both front
//!   ends: [`limits`] (what an
//!   expression may cost) and `print` (sequences and alternations with their
//!   parentheses); set algebra over whole expressions (`A & B`, `A - B`, `^A`:
//!   [`algebra`]).
//! - The automata ([`automata`]): the shared ids in the leaf [`automata::mask`]
//!   ([`AovMask`], [`Class`], [`State`], [`MAX_AOVS`]), the intermediate form dialects
//!   lower to ([`automata::ir`]), [`CompileError`], then the bitset Glushkov NFA, the
//!   minimized DFA and the lazy DFA.
//! - The facade ([`aov`]): [`AovSet`] compiles a list of AOVs of any dialect under
//!   [`Options`] into one automaton and steps it; [`CompileError`] says why a set did
//!   not compile. [`direct`]'s [`DirectSet`] answers whole paths on the expression
//!   trees, with no automaton: for a set asked about a few paths.
//! - The seam ([`matcher`]): [`PathMatcher`], the incremental matcher trait renderers
//!   program against; [`AovSet`] implements it.
//! - The formal side ([`analysis`]): emptiness warnings (on the NFA alone), equivalence
//!   and inclusion, partition checks, each with a shortest witness path.
//! - Utilities: [`rng`] (the workspace's one SplitMix64), [`fxhash`] (fast maps for small
//!   keys), [`suggest`] ("did you mean" by edit distance), the crate-private `bits` (bitsets in `u64` words) and `print` (the printing
//!   both dialects' trees and paths share). The test generators (random expressions and
//!   paths, proptest strategies) are in the `lpe-testkit` crate.
//!
//! The semantics are specified in the repository's docs/language.md and executed by the
//! `lpe-reference` crate; the decisions this crate makes where a renderer could expect
//! either answer are documented on the items that make them ([`renderman::path`],
//! [`renderman::ast`], [`renderman::syntax`], [`osl`]). docs/architecture.md says which
//! files a new dialect touches.
//!
//! # Matching in a renderer
//!
//! [`AovSet`] compiles a list of AOVs into one automaton (a minimized DFA over
//! compressed vertex classes, or a bitset Glushkov NFA when the DFA is over its memory
//! budget). Compile once at scene load, classify each material lobe once, share the set
//! across render threads (it is `Send + Sync`, lock-free and immutable), and step one
//! vertex at a time; a step never allocates (the same loop, generic over any engine, is
//! in [`matcher`]):
//!
//! ```
//! use lpe::renderman::{parse, Event, EventKind, Lpe, Vertex, VertexType};
//! use lpe::{AovSet, Class};
//!
//! // Scene load: compile the AOVs, classify every material lobe once.
//! let aovs: Vec<(String, Lpe)> = ["directDiffuse", "indirectDiffuse", "emissive", "caustics"]
//!     .iter()
//!     .map(|name| (name.to_string(), parse(name).unwrap()))
//!     .collect();
//! let set = AovSet::compile(&aovs).unwrap();
//! for w in set.warnings() {
//!     eprintln!("warning: {w}");
//! }
//! let lobe = |ty, kind, n, group| {
//!     set.classify(&Vertex::scatter(ty, Event::new(kind, n).unwrap(), Some(group)))
//! };
//! let floor_diffuse: Class = lobe(VertexType::R, EventKind::D, 2, "floor");
//! let glass_specular: Class = lobe(VertexType::T, EventKind::S, 8, "glass");
//! let camera = set.classify(&Vertex::camera());
//! let key_light = set.classify(&Vertex::light(Some("key")));
//!
//! // Render threads: per path, one table step per vertex.
//! let routed = std::thread::scope(|scope| {
//!     let worker = scope.spawn(|| {
//!         let mut routed = Vec::new();
//!         let mut s = set.start();
//!         s = set.step_class(s, camera);
//!         for bounce in [floor_diffuse, glass_specular] {
//!             s = set.step_class(s, bounce);
//!             if set.is_dead(s) {
//!                 break; // no AOV can match any continuation: stop tracking the path
//!             }
//!             // At each bounce the integrator samples the light; the state is `Copy`.
//!             let hit = set.matches(set.step_class(s, key_light));
//!             // ... accumulate the sample into AOV `set.names()[i]` for i in hit.iter()
//!             routed.push(hit.iter().map(|i| set.names()[i].as_str()).collect::<Vec<_>>());
//!         }
//!         routed
//!     });
//!     worker.join().unwrap()
//! });
//! assert_eq!(routed, [vec!["directDiffuse"], vec!["indirectDiffuse", "caustics"]]);
//! ```
//!
//! The formal side, on the same automata ([`analysis`]): emptiness warnings at compile
//! time, equivalence and inclusion of two expressions, and partition checks of an AOV set,
//! each with a shortest witness path.

#![warn(missing_docs)]
#![forbid(unsafe_code)]

pub mod algebra;
pub mod analysis;
pub mod aov;
pub mod automata;
mod bits;
pub mod dialect;
pub mod direct;
pub mod fxhash;
pub mod limits;
pub mod matcher;
pub mod osl;
mod print;
pub mod registry;
pub mod renderman;
pub mod rng;
pub mod suggest;
pub mod translate;

pub use aov::{AovSet, Options};
pub use aov::{Cache, NfaMatcher};
pub use automata::error::CompileError;
pub use automata::mask::{AovMask, Class, State, MAX_AOVS};
pub use automata::mask::{LabelId, NfaState};
pub use dialect::{Dialect, DialectLpe};
pub use direct::DirectSet;
pub use matcher::PathMatcher;
pub use registry::{DialectName, UnknownDialect};
