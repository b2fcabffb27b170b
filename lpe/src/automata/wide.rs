//! The bitset NFA stepped on its wide state ([`NfaState`], up to
//! `64 * NFA_STATE_WORDS` positions): no registry, no cache, no lock, for callers that
//! want the plain NFA (the benchmark's NFA row, a path record that can afford 32 bytes).
//! `crate::matcher` puts it behind `PathMatcher`.

use crate::automata::ir::VertexClasses;
use crate::automata::mask::{AovMask, Class, NfaState, NFA_STATE_WORDS};
use crate::automata::nfa::Nfa;
use crate::automata::visible::Visible;

/// A lazily stepped set's bitset NFA over vertex classes `C`, stepped on [`NfaState`]s. Obtained from
/// [`crate::aov::AovSet::nfa`]; answers exactly as the set.
#[derive(Debug)]
pub struct NfaMatcher<'a, C> {
    pub(crate) nfa: &'a Nfa,
    pub(crate) classes: &'a C,
    /// With set algebra, the visible masks over the NFA's hidden ones.
    pub(crate) visible: Option<&'a Visible>,
    /// No active position is dead: false when a complement then matches.
    pub(crate) empty_is_dead: bool,
}

// Written out: derived, they would ask the class table `C` to be `Copy`.
impl<C> Clone for NfaMatcher<'_, C> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<C> Copy for NfaMatcher<'_, C> {}

impl<C: VertexClasses> NfaMatcher<'_, C> {
    /// The class of a vertex.
    #[inline]
    pub fn classify(&self, v: &C::Vertex) -> Class {
        self.classes.classify(v)
    }

    /// The state before any vertex: position 0 alone.
    #[inline(always)]
    pub fn start(&self) -> NfaState {
        let mut s = [0u64; NFA_STATE_WORDS];
        s[0] = 1;
        NfaState(s)
    }

    /// The state after one more vertex. Inlined whole, so that the state stays in the
    /// caller's registers.
    #[inline(always)]
    pub fn step(&self, s: NfaState, c: Class) -> NfaState {
        NfaState(self.nfa.step_wide(s.0, c.index()))
    }

    /// The AOVs matching a path ending in `s`.
    #[inline(always)]
    pub fn matches(&self, s: NfaState) -> AovMask {
        let hidden = self.nfa.matches_wide(s.0);
        self.visible.map_or(hidden, |v| v.mask(hidden))
    }

    /// No active position, and no complement matching from there: no continuation can
    /// match.
    #[inline(always)]
    pub fn is_dead(&self, s: NfaState) -> bool {
        self.empty_is_dead && s.0 == [0; NFA_STATE_WORDS]
    }
}
