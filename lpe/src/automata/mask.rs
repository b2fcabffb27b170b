//! The ids every automaton layer shares: vertex [`Class`]es, matcher [`State`]s and
//! [`AovMask`]s. A leaf: the alphabet, the NFA, the DFA and the [`crate::aov`] facade all
//! speak these types, so none of them needs another to name them.

use crate::bits;

/// Most AOVs one set holds (the width of [`AovMask`]).
pub const MAX_AOVS: usize = 256;
const MASK_WORDS: usize = MAX_AOVS / 64;

/// Which AOVs of a set match: bit `i` is the set's `i`-th AOV.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct AovMask([u64; MASK_WORDS]);

impl AovMask {
    /// No AOV.
    pub const EMPTY: AovMask = AovMask([0; MASK_WORDS]);

    /// Whether AOV `i` matches (false for `i >= MAX_AOVS`).
    #[inline]
    pub fn contains(&self, i: usize) -> bool {
        i < MAX_AOVS && bits::get(&self.0, i)
    }

    /// Adds AOV `i` (ignored for `i >= MAX_AOVS`).
    pub fn insert(&mut self, i: usize) {
        if i < MAX_AOVS {
            bits::set(&mut self.0, i);
        }
    }

    /// No AOV matches.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.0.iter().all(|&w| w == 0)
    }

    /// How many AOVs match.
    #[inline]
    pub fn count(&self) -> usize {
        self.0.iter().map(|w| w.count_ones() as usize).sum()
    }

    /// The matching AOVs, in increasing order.
    pub fn iter(&self) -> impl Iterator<Item = usize> + '_ {
        bits::ones(self.0)
    }
}

impl FromIterator<usize> for AovMask {
    /// The mask of these AOV indices (indices `>= MAX_AOVS` are ignored).
    fn from_iter<I: IntoIterator<Item = usize>>(iter: I) -> AovMask {
        let mut m = AovMask::EMPTY;
        iter.into_iter().for_each(|i| m.insert(i));
        m
    }
}

/// An equivalence class of vertices: no compiled atom tells two vertices of one class
/// apart. Obtained from [`crate::aov::AovSet::classify`]; only meaningful for the set
/// that produced it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Class(pub(crate) u32);

impl Class {
    /// The class number, `0..class_count`.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// Widest NFA state a [`State`] holds inline: sets stepped on the NFA (their DFA is over
/// budget) may have at most `64 * NFA_STATE_WORDS` positions.
pub const NFA_STATE_WORDS: usize = 4;

/// Where a path is in the automaton: a DFA state id, or the active NFA positions. Small,
/// `Copy`, and only meaningful for the set that produced it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct State(pub(crate) [u64; NFA_STATE_WORDS]);

impl State {
    /// The state holding DFA state `id` (or the NFA positions of the one word `id`).
    #[inline]
    pub(crate) fn id(id: u32) -> State {
        let mut s = [0u64; NFA_STATE_WORDS];
        s[0] = u64::from(id);
        State(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mask_holds_more_than_64_aovs() {
        let mut m = AovMask::EMPTY;
        m.insert(3);
        m.insert(200);
        m.insert(MAX_AOVS);
        assert!(m.contains(200) && m.contains(3) && !m.contains(4));
        assert_eq!(m.iter().collect::<Vec<_>>(), [3, 200]);
        assert_eq!(m.count(), 2);
    }
}
