//! The glue between AOVs and the integrator: the AOV list ([`list`]), the matcher seam
//! ([`matcher`]) and the effects plan ([`plan`]).

pub mod list;
pub mod matcher;
pub mod plan;

pub use list::{
    parse_display_channels, split_aov_arg, usd_render_vars, Aov, AovError, AovFlags, AovList,
    DisplayChannels, Partition,
};
