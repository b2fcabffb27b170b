//! The glue between AOVs and the integrator: the AOV list ([`list`]) in either dialect
//! (the OSL one's renderer-specific checks in [`osl`]), the matcher seam ([`matcher`]),
//! the renderer's vertices as each dialect sees them ([`vertex`]) and the effects plan
//! ([`plan`]).

pub mod list;
pub mod matcher;
pub mod osl;
pub mod plan;
pub mod vertex;

pub use list::{
    parse_display_channels, split_aov_arg, usd_render_vars, Aov, AovError, AovExpr, AovFlags,
    AovList, DisplayChannels, Partition,
};
