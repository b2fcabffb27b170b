//! The bitset NFA stepped on its wide state ([`NfaState`], up to
//! `64 * NFA_STATE_WORDS` positions): no registry, no cache, no lock, for callers that
//! want the plain NFA (the benchmark's NFA row, a path record that can afford 32 bytes).
//! `crate::matcher` puts it behind `PathMatcher`.

use crate::automata::alphabet::Alphabet;
use crate::automata::mask::{AovMask, Class, NfaState, NFA_STATE_WORDS};
use crate::automata::nfa::Nfa;
use crate::automata::visible::Visible;
use crate::path::Vertex;

/// A lazily stepped set's bitset NFA, stepped on [`NfaState`]s. Obtained from
/// [`crate::aov::AovSet::nfa`]; answers exactly as the set.
#[derive(Clone, Copy, Debug)]
pub struct NfaMatcher<'a> {
    pub(crate) nfa: &'a Nfa,
    pub(crate) alphabet: &'a Alphabet,
    /// With set algebra, the visible masks over the NFA's hidden ones.
    pub(crate) visible: Option<&'a Visible>,
    /// No active position is dead: false when a complement then matches.
    pub(crate) empty_is_dead: bool,
}

impl NfaMatcher<'_> {
    /// The class of a vertex.
    #[inline]
    pub fn classify(&self, v: &Vertex) -> Class {
        self.alphabet.classify(v)
    }

    /// The state before any vertex: position 0 alone.
    #[inline]
    pub fn start(&self) -> NfaState {
        let mut s = [0u64; NFA_STATE_WORDS];
        s[0] = 1;
        NfaState(s)
    }

    /// The state after one more vertex.
    #[inline]
    pub fn step(&self, s: NfaState, c: Class) -> NfaState {
        let w = self.nfa.words();
        let mut next = [0u64; NFA_STATE_WORDS];
        self.nfa.step(&s.0[..w], c.index(), &mut next[..w]);
        NfaState(next)
    }

    /// The AOVs matching a path ending in `s`.
    #[inline]
    pub fn matches(&self, s: NfaState) -> AovMask {
        let hidden = self.nfa.matches(&s.0[..self.nfa.words()]);
        self.visible.map_or(hidden, |v| v.mask(hidden))
    }

    /// No active position, and no complement matching from there: no continuation can
    /// match.
    #[inline]
    pub fn is_dead(&self, s: NfaState) -> bool {
        self.empty_is_dead && s.0 == [0; NFA_STATE_WORDS]
    }
}
