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

    /// The matching AOVs, in increasing order. Inlined: out of line, the iterator is
    /// returned through memory and every caller's loop waits on reloading it.
    #[inline]
    pub fn iter(&self) -> impl Iterator<Item = usize> + '_ {
        bits::ones(self.0)
    }
}

impl std::ops::BitAnd for AovMask {
    type Output = AovMask;

    /// The AOVs in both masks.
    #[inline]
    fn bitand(self, o: AovMask) -> AovMask {
        AovMask(std::array::from_fn(|w| self.0[w] & o.0[w]))
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

/// A vertex label interned once (at scene load) for one set, so that classifying a
/// vertex needs no string hashing: from [`crate::aov::AovSet::label_id`], used with
/// [`crate::aov::AovSet::classify_interned`]. Only meaningful for the set that produced
/// it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LabelId(pub(crate) u32);

/// Widest NFA state an [`NfaState`] holds: sets stepped on the bare NFA may have at most
/// `64 * NFA_STATE_WORDS` positions.
pub const NFA_STATE_WORDS: usize = 4;

/// Where a path is in a set's automaton: one `u32`, so it lives in a register in the
/// caller's loop and costs four bytes in a path record.
///
/// For a set with an eager DFA it is the DFA state's premultiplied row offset; for a set
/// stepped lazily it is the id of an NFA state in the set's state registry (ids are
/// never reused, so a state stays valid however often a [`crate::aov::Cache`] is
/// cleared). In both, `0` is the dead state. Only meaningful for the set that produced
/// it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[repr(transparent)]
pub struct State(pub(crate) u32);

impl State {
    /// The dead state, in every set.
    pub(crate) const DEAD: State = State(0);

    /// The raw id, for callers that pack states into their own records.
    #[inline]
    pub fn to_u32(self) -> u32 {
        self.0
    }

    /// A state from [`State::to_u32`]. A value that is no state of the set steps to some
    /// state, never a panic.
    #[inline]
    pub fn from_u32(id: u32) -> State {
        State(id)
    }
}

/// The active positions of a set's bitset NFA: the wide state of
/// [`crate::aov::NfaMatcher`], kept apart from [`State`] so that DFA stepping never
/// moves 32 bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct NfaState(pub(crate) [u64; NFA_STATE_WORDS]);

impl NfaState {
    /// The active NFA positions, in increasing order (position 0 is the start).
    pub fn active(&self) -> impl Iterator<Item = usize> + '_ {
        self.0.iter().enumerate().flat_map(|(w, &bits)| {
            (0..64)
                .filter(move |b| bits >> b & 1 == 1)
                .map(move |b| 64 * w + b)
        })
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

    #[test]
    fn and_keeps_the_aovs_of_both_masks_in_every_word() {
        let a: AovMask = [0, 63, 64, 130, 255].into_iter().collect();
        let b: AovMask = [63, 64, 129, 255, 7].into_iter().collect();
        assert_eq!((a & b).iter().collect::<Vec<_>>(), [63, 64, 255]);
        assert!((a & AovMask::EMPTY).is_empty());
    }
}
