//! How an AOV accumulates: the prefixes of its expression, decoded (a leaf: the dialects
//! produce flags, the film reads them).

/// How an AOV accumulates: its prefixes, decoded (docs/language.md §7; the integrator
/// documents each one where it applies it). A dialect without prefixes gives every AOV
/// the default, a plain one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AovFlags {
    pub unoccluded: bool,
    pub shadows: bool,
    pub nothruput: bool,
    pub noclamp: bool,
    pub overwrite: bool,
    pub noinfinitecheck: bool,
    pub holdouts: bool,
}

impl AovFlags {
    /// No prefix that changes what a contribution adds (weights, throughput, clamp,
    /// holdouts): such an AOV receives exactly beauty's contribution. `overwrite` and
    /// `noinfinitecheck` act when a sample is committed, not per contribution.
    pub fn values_like_beauty(&self) -> bool {
        !(self.unoccluded || self.shadows || self.nothruput || self.noclamp || self.holdouts)
    }
}
