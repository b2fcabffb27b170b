//! The benchmark baseline: regex-automata's dense DFA and lazy DFA over a byte encoding
//! of vertices, independent of lpe's alphabet compression.
//!
//! Encoding: two bytes per vertex, `[type and event][label]`. The first byte numbers the
//! 51 `(type, event)` combinations (C, L, O, then R and T with D1-4, S1-8, U1-12); the
//! second is 0 for no label, `1..=k` for the labels the AOVs mention (sorted), `k + 1`
//! for any other. Each atom becomes a union of `[type-event bytes][label bytes]` pairs,
//! computed by asking the reference matcher about one vertex per byte pair, so the
//! baseline shares no predicate code with lpe. Every pattern ends with an end anchor
//! and searches are anchored at the start: whole-path matching.

use lpe::renderman::ast::{Atom, Expr};
use lpe::renderman::{Event, EventKind, Lpe, Path, Vertex, VertexType};
use regex_automata::dfa::{dense, Automaton, StartKind};
use regex_automata::hybrid;
use regex_automata::nfa::thompson;
use regex_automata::util::primitives::StateID;
use regex_automata::util::start;
use regex_automata::{Anchored, MatchKind};
use regex_syntax::hir::{self, Class, ClassBytes, ClassBytesRange, Hir, Look};

use lpe::AovMask;

const TYPE_EVENTS: u8 = 51;

/// Most distinct labels the baseline's label byte numbers (0 is "no label", the last
/// value "any other label").
pub const MAX_LABELS: usize = 254;

/// Why the baseline could not be built for a set (regex-automata's large errors boxed).
#[derive(Clone, Debug, thiserror::Error)]
pub enum BaselineError {
    /// The set mentions more labels than the label byte numbers.
    #[error("{labels} labels: the baseline's label byte holds {max}")]
    TooManyLabels {
        /// Distinct labels the set mentions.
        labels: usize,
        /// [`MAX_LABELS`].
        max: usize,
    },
    /// The Thompson NFA (over [`SIZE_LIMIT`], or otherwise unbuildable).
    #[error("{0}")]
    Nfa(Box<thompson::BuildError>),
    /// The dense DFA (over [`SIZE_LIMIT`], or otherwise unbuildable).
    #[error("{0}")]
    Dense(Box<dense::BuildError>),
    /// The lazy DFA.
    #[error("{0}")]
    Lazy(Box<hybrid::BuildError>),
    /// The dense DFA has no anchored start state.
    #[error("{0}")]
    Start(regex_automata::dfa::StartError),
}

/// The byte encoding of one AOV set's vertices.
pub struct Encoding {
    labels: Vec<String>,
    other: String,
}

fn type_event_code(v: &Vertex) -> u8 {
    // The index of `e` in `Event::all()` (D1-4, S1-8, U1-12): the lobes of the kinds
    // before it, plus its own lobe.
    let event = |e: Event| {
        let before: u8 = EventKind::ALL
            .iter()
            .take_while(|&&k| k != e.kind())
            .map(|k| k.max_lobe())
            .sum();
        before + e.lobe() - 1
    };
    match (v.ty(), v.event()) {
        (VertexType::L, _) => 1,
        (VertexType::O, _) => 2,
        (VertexType::R, Some(e)) => 3 + event(e),
        (VertexType::T, Some(e)) => 27 + event(e),
        _ => 0,
    }
}

impl Encoding {
    /// The encoding for a set: at most 254 distinct labels fit the label byte.
    pub fn new(aovs: &[(String, Lpe)]) -> Result<Encoding, BaselineError> {
        let mut labels: Vec<String> = aovs.iter().flat_map(|(_, l)| l.expr.labels()).collect();
        labels.sort();
        labels.dedup();
        if labels.len() > MAX_LABELS {
            return Err(BaselineError::TooManyLabels {
                labels: labels.len(),
                max: MAX_LABELS,
            });
        }
        let mut other = "other".to_string();
        while labels.contains(&other) {
            other.push('_');
        }
        Ok(Encoding { labels, other })
    }

    fn label_code(&self, l: Option<&str>) -> u8 {
        match l {
            None => 0,
            Some(l) => match self.labels.binary_search_by(|x| x.as_str().cmp(l)) {
                Ok(i) => i as u8 + 1,
                Err(_) => self.labels.len() as u8 + 1,
            },
        }
    }

    /// Appends the two bytes of each vertex.
    pub fn encode(&self, path: &Path, out: &mut Vec<u8>) {
        self.encode_vertices(path.vertices(), out);
    }

    /// Appends the two bytes of each vertex.
    #[inline]
    pub fn encode_vertices(&self, vertices: &[Vertex], out: &mut Vec<u8>) {
        for v in vertices {
            out.push(type_event_code(v));
            out.push(self.label_code(v.label()));
        }
    }

    /// A vertex with these codes, if one exists (the camera has no label).
    fn vertex(&self, te: u8, label: u8) -> Option<Vertex> {
        let l = match label {
            0 => None,
            l if (l as usize) <= self.labels.len() => Some(self.labels[l as usize - 1].as_str()),
            _ => Some(self.other.as_str()),
        };
        let event = |i: u8| Event::all().nth(i as usize);
        Some(match te {
            0 if l.is_none() => Vertex::camera(),
            0 => return None,
            1 => Vertex::light(l),
            2 => Vertex::emissive(l),
            3..=26 => Vertex::scatter(VertexType::R, event(te - 3)?, l),
            _ => Vertex::scatter(VertexType::T, event(te - 27)?, l),
        })
    }

    fn atom(&self, a: &Atom) -> Hir {
        let label_codes = self.labels.len() as u8 + 2;
        // Type-event bytes grouped by the exact set of label bytes the atom accepts.
        let mut groups: Vec<(Vec<u8>, Vec<u8>)> = Vec::new();
        for te in 0..TYPE_EVENTS {
            let ls: Vec<u8> = (0..label_codes)
                .filter(|&l| {
                    self.vertex(te, l)
                        .is_some_and(|v| lpe_reference::atom_matches(a, &v))
                })
                .collect();
            if ls.is_empty() {
                continue;
            }
            match groups.iter_mut().find(|(_, g)| *g == ls) {
                Some((tes, _)) => tes.push(te),
                None => groups.push((vec![te], ls)),
            }
        }
        let class = |bytes: &[u8]| {
            Hir::class(Class::Bytes(ClassBytes::new(
                bytes.iter().map(|&b| ClassBytesRange::new(b, b)),
            )))
        };
        if groups.is_empty() {
            return Hir::fail();
        }
        Hir::alternation(
            groups
                .iter()
                .map(|(tes, ls)| Hir::concat(vec![class(tes), class(ls)]))
                .collect(),
        )
    }

    fn expr(&self, e: &Expr) -> Hir {
        match e {
            Expr::Atom(a) => self.atom(a),
            Expr::Concat(es) => Hir::concat(es.iter().map(|e| self.expr(e)).collect()),
            Expr::Alt(es) => Hir::alternation(es.iter().map(|e| self.expr(e)).collect()),
            Expr::Repeat(body, r) => Hir::repetition(hir::Repetition {
                min: r.min,
                max: r.max,
                greedy: true,
                sub: Box::new(self.expr(body)),
            }),
        }
    }

    /// The whole-path pattern of one expression.
    pub fn pattern(&self, l: &Lpe) -> Hir {
        Hir::concat(vec![self.expr(&l.expr), Hir::look(Look::End)])
    }
}

/// Size limit for every regex-automata build: the same 16 MiB as the fast matcher's
/// default DFA budget.
pub const SIZE_LIMIT: usize = 16 << 20;

/// The Thompson NFA of a set (both DFAs are built from it).
pub fn nfa(enc: &Encoding, aovs: &[(String, Lpe)]) -> Result<thompson::NFA, BaselineError> {
    let hirs: Vec<Hir> = aovs.iter().map(|(_, l)| enc.pattern(l)).collect();
    thompson::Compiler::new()
        .configure(
            thompson::Config::new()
                .utf8(false)
                .nfa_size_limit(Some(SIZE_LIMIT))
                .which_captures(thompson::WhichCaptures::None),
        )
        .build_many_from_hir(&hirs)
        .map_err(|e| BaselineError::Nfa(Box::new(e)))
}

/// A dense DFA reporting every matching pattern, anchored starts only.
pub fn dense(nfa: &thompson::NFA) -> Result<dense::DFA<Vec<u32>>, BaselineError> {
    dense::Builder::new()
        .configure(
            dense::DFA::config()
                .match_kind(MatchKind::All)
                .start_kind(StartKind::Anchored)
                .dfa_size_limit(Some(SIZE_LIMIT))
                .determinize_size_limit(Some(SIZE_LIMIT)),
        )
        .build_from_nfa(nfa)
        .map_err(|e| BaselineError::Dense(Box::new(e)))
}

/// A lazy DFA reporting every matching pattern.
pub fn lazy(nfa: thompson::NFA) -> Result<hybrid::dfa::DFA, BaselineError> {
    hybrid::dfa::Builder::new()
        .configure(hybrid::dfa::DFA::config().match_kind(MatchKind::All))
        .build_from_nfa(nfa)
        .map_err(|e| BaselineError::Lazy(Box::new(e)))
}

fn anchored() -> start::Config {
    start::Config::new().anchored(Anchored::Yes)
}

/// The dense DFA's anchored start state.
pub fn dense_start(dfa: &dense::DFA<Vec<u32>>) -> Result<StateID, BaselineError> {
    dfa.start_state(&anchored()).map_err(BaselineError::Start)
}

/// Steps one encoded path with `next_state` per byte; the patterns that match.
#[inline]
pub fn dense_run(dfa: &dense::DFA<Vec<u32>>, start: StateID, bytes: &[u8]) -> AovMask {
    let mut sid = start;
    for &b in bytes {
        sid = dfa.next_state(sid, b);
    }
    sid = dfa.next_eoi_state(sid);
    let mut m = AovMask::EMPTY;
    if dfa.is_match_state(sid) {
        for i in 0..dfa.match_len(sid) {
            m.insert(dfa.match_pattern(sid, i).as_usize());
        }
    }
    m
}

/// Steps one encoded path through the lazy DFA; `None` if its cache gave up.
#[inline]
pub fn lazy_run(
    dfa: &hybrid::dfa::DFA,
    cache: &mut hybrid::dfa::Cache,
    bytes: &[u8],
) -> Option<AovMask> {
    let mut sid = dfa.start_state(cache, &anchored()).ok()?;
    for &b in bytes {
        sid = dfa.next_state(cache, sid, b).ok()?;
    }
    sid = dfa.next_eoi_state(cache, sid).ok()?;
    let mut m = AovMask::EMPTY;
    if sid.is_match() {
        for i in 0..dfa.match_len(cache, sid) {
            m.insert(dfa.match_pattern(cache, sid, i).as_usize());
        }
    }
    Some(m)
}
