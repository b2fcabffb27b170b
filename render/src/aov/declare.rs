//! AOVs as a dialect declares them before they are parsed: names and sources, and the
//! partitions of beauty they are known to form (a leaf: the dialects write these, the
//! AOV list reads them).

/// AOVs whose sum should equal beauty, by construction of a default set.
#[derive(Clone, Debug)]
pub struct Partition {
    pub name: String,
    /// Indices into the list's AOVs.
    pub members: Vec<usize>,
    /// Whether the members partition *every* light-transport path, or only this scene's
    /// (the per-lobe set covers just the lobes the scene's materials map into it).
    pub universal: bool,
}

/// A dialect's default AOVs for a scene, still as text.
#[derive(Clone, Debug, Default)]
pub struct Declared {
    /// `(name, source)`, in layer order.
    pub aovs: Vec<(String, String)>,
    /// Partitions over indices into `aovs`.
    pub partitions: Vec<Partition>,
    /// Why a partition was not declared (e.g. lobes outside the per-lobe set).
    pub notes: Vec<String>,
}

impl Declared {
    /// Appends one AOV; returns its index.
    pub fn push(&mut self, name: impl Into<String>, source: impl Into<String>) -> usize {
        self.aovs.push((name.into(), source.into()));
        self.aovs.len() - 1
    }

    /// Appends `aovs` as one partition named `name`.
    pub fn push_partition(
        &mut self,
        name: &str,
        aovs: impl IntoIterator<Item = (String, String)>,
        universal: bool,
    ) -> Vec<usize> {
        let members: Vec<usize> = aovs.into_iter().map(|(n, s)| self.push(n, s)).collect();
        self.partitions.push(Partition {
            name: name.into(),
            members: members.clone(),
            universal,
        });
        members
    }
}
