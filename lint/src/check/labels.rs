//! Who must carry a group label an AOV names: what the label checks compare with the
//! groups a stage declares. Each dialect finds the labels of its expressions
//! ([`super::dialect::LintDialect::labels`]).

/// Who must carry a label for the AOV to see it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Carrier {
    /// A light (`<L.'key'>`): its light group.
    Light,
    /// Geometry: a scattering vertex (`'floor'`, `<R.'floor'>`) or an emissive object
    /// (`<O.'lamp'>`): its object group (lpegroup / lpetag).
    Object,
}
