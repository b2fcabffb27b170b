//! AOV sets that answer whole paths without an automaton: [`DirectSet`], for a set that
//! will be asked about a few paths only (`lpe-check match --batch` on a line whose
//! expression has not repeated, where compiling an [`AovSet`](crate::AovSet) would cost
//! more than all its answers).
//!
//! It keeps the expression trees, flattened (`automata::direct`), and their distinct
//! atoms, and evaluates the trees on each path, asking the dialect which atom accepts
//! which vertex ([`Dialect::accepts`]): no vertex classes, no NFA, no DFA, no unrolling
//! of counted repetition. Matching a path of `len` vertices costs up to
//! `nodes * (len + 2)` set operations on words of `len + 1` bits, where a compiled
//! [`AovSet`](crate::AovSet) steps a table once per vertex: a set that answers more than
//! a few paths belongs in an `AovSet`.
//!
//! ```
//! use lpe::renderman::{parse, Lpe};
//! use lpe::DirectSet;
//!
//! let aovs: Vec<(String, Lpe)> = vec![("far".into(), parse("C.{40}[LO]").unwrap())];
//! let set = DirectSet::compile(&aovs).unwrap();
//! assert!(set.match_path(&"C RD L".parse().unwrap()).is_empty());
//! let far = format!("C{} L", " RD".repeat(40));
//! assert!(set.match_path(&far.parse().unwrap()).contains(0));
//! ```

use crate::aov::{AovSet, Hidden, Options};
use crate::automata::direct::Program;
use crate::automata::error::CompileError;
use crate::automata::mask::AovMask;
use crate::automata::visible::Visible;
use crate::dialect::{Dialect, DialectLpe};

/// A set of AOVs of dialect `D` matched on their expression trees, path by path. Gives
/// the answers of an [`AovSet`](crate::AovSet) of the same AOVs (set algebra included),
/// without its stepping API: it reads a whole path at once. See the [module
/// docs](self).
#[derive(Clone, Debug)]
pub struct DirectSet<D: Dialect> {
    /// The distinct atoms, as the program numbers them.
    atoms: Vec<D::Atom>,
    program: Program,
    visible: Option<Visible>,
    len: usize,
}

impl<D: Dialect> DirectSet<D> {
    /// The set of `aovs`, in order: bit `i` of an answer is `aovs[i]`. Fails as an
    /// [`AovSet`](crate::AovSet) compile does on too many AOVs or operands, or on vertex
    /// classes the dialect cannot build; the size budgets of the automata do not apply,
    /// since none is built.
    pub fn compile<L>(aovs: &[(String, L)]) -> Result<DirectSet<D>, CompileError>
    where
        L: DialectLpe<Dialect = D>,
        D: Dialect<Lpe = L>,
    {
        Self::compile_lpes(aovs, None)
    }

    /// [`DirectSet::compile`], refusing as well what an [`AovSet`](crate::AovSet)
    /// compiled with `opts` refuses for its NFA's size ([`Options::nfa_budget`],
    /// counted without building anything), so that a caller who answers the first
    /// paths with this set and the rest with an `AovSet` (`lpe-check match --batch`)
    /// refuses such an expression from its first path rather than from its
    /// 256th.
    pub fn compile_within<L>(
        aovs: &[(String, L)],
        opts: &Options,
    ) -> Result<DirectSet<D>, CompileError>
    where
        L: DialectLpe<Dialect = D>,
        D: Dialect<Lpe = L>,
    {
        Self::compile_lpes(aovs, Some(opts))
    }

    fn compile_lpes(
        aovs: &[(String, D::Lpe)],
        within: Option<&Options>,
    ) -> Result<DirectSet<D>, CompileError> {
        let hidden = Hidden::of(aovs)?;
        if let Some(opts) = within {
            AovSet::<D>::check_positions(&hidden.operands, opts)?;
        }
        let (program, atoms) = Program::new(&hidden.operands);
        Ok(DirectSet {
            atoms: atoms.into_iter().cloned().collect(),
            program,
            visible: hidden.visible,
            len: aovs.len(),
        })
    }

    /// Which AOVs match the whole path.
    pub fn match_path(&self, path: &D::Path) -> AovMask {
        let vertices = D::vertices(path);
        let hidden = self.program.matches(vertices.len(), |a, i| {
            D::accepts(&self.atoms[a], &vertices[i])
        });
        match &self.visible {
            Some(v) => v.mask(hidden),
            None => hidden,
        }
    }

    /// Number of AOVs.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the set has no AOVs.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Bytes held by the flattened trees and the atoms' own structs (not what the
    /// atoms hold on the heap, such as label names).
    pub fn memory_bytes(&self) -> usize {
        self.atoms.capacity() * std::mem::size_of::<D::Atom>() + self.program.memory_bytes()
    }
}

#[cfg(test)]
mod tests {
    //! Closed forms, each expected answer worked out by hand from the expression. Caught
    //! when planted: an atom that accepts nothing, the minimum reached one application
    //! early, the maximum passed by one, the stop at `T_(k+1) = T_k` below the minimum
    //! answering the empty set, a path of 64 vertices on one word, the carry between
    //! words dropped, and set algebra answered on the hidden AOVs. The early stops
    //! above the minimum (an empty set in a sequence, a set inside the union) change
    //! only how many applications a path costs, never an answer: a stop that came later
    //! would give the same sets.

    use crate::osl::{self, Osl, Registered};
    use crate::renderman::ast::Atom;
    use crate::renderman::{parse, Lpe, Path, RenderMan};

    use super::DirectSet;

    fn set(srcs: &[&str]) -> DirectSet<RenderMan> {
        let aovs: Vec<(String, Lpe)> = srcs
            .iter()
            .map(|s| (s.to_string(), parse(s).unwrap()))
            .collect();
        DirectSet::compile(&aovs).unwrap()
    }

    /// `C`, `middle` diffuse reflections, a light.
    fn bounces(middle: usize) -> Path {
        format!("C{} L", " RD".repeat(middle)).parse().unwrap()
    }

    fn answers(set: &DirectSet<RenderMan>, path: &Path) -> Vec<usize> {
        set.match_path(path).iter().collect()
    }

    /// `.{40}` reads exactly 40 vertices between `C` and `L`.
    #[test]
    fn a_counted_repetition_reads_exactly_its_count() {
        let s = set(&["C.{40}[LO]"]);
        assert_eq!(answers(&s, &bounces(39)), Vec::<usize>::new());
        assert_eq!(answers(&s, &bounces(40)), [0]);
        assert_eq!(answers(&s, &bounces(41)), Vec::<usize>::new());
    }

    /// `D{2,3}`: two or three diffuse vertices, and `{2,}` any number from two.
    #[test]
    fn a_range_unites_its_counts_and_no_others() {
        let s = set(&["CD{2,3}L", "CD{2,}L"]);
        let got: Vec<Vec<usize>> = (0..6).map(|k| answers(&s, &bounces(k))).collect();
        let want: [&[usize]; 6] = [&[], &[], &[0, 1], &[0, 1], &[1], &[1]];
        assert_eq!(got, want);
    }

    /// A count past the path's length: a body that must read a vertex leaves nothing
    /// after `len + 1` applications, and one that may read none stops growing
    /// (`T_(k+1) = T_k`) and answers that set. `(D?){256}` is any number of diffuse
    /// vertices up to 256 (the parser's largest count).
    #[test]
    fn counts_past_the_path_stop_at_its_length() {
        let s = set(&["C.{256}L", "C(D?){256}L", "C(D?){256}SL"]);
        assert_eq!(answers(&s, &bounces(0)), [1]);
        assert_eq!(answers(&s, &bounces(3)), [1]);
        let tail: Path = "C RD RD RS L".parse().unwrap();
        assert_eq!(answers(&s, &tail), [2]);
    }

    /// Unbounded repetition of bodies of one or two vertices: `((DD)|D)+` on three
    /// diffuse vertices (`|` joins single items, so `DD` is grouped), and
    /// `(<RD>(<RS>|(<RD><RS>))?)+`, whose iterations end at positions that the next ones
    /// pass over.
    #[test]
    fn unbounded_repetition_stops_when_the_union_stops_growing() {
        let s = set(&["C((DD)|D)+L", "C(<RD>(<RS>|(<RD><RS>))?)+L"]);
        assert_eq!(answers(&s, &bounces(3)), [0, 1]);
        let mixed: Path = "C RD RD RS RD RS RD L".parse().unwrap();
        assert_eq!(answers(&s, &mixed), [1]);
        let ends_wrong: Path = "C RD RS RS L".parse().unwrap();
        assert_eq!(answers(&s, &ends_wrong), Vec::<usize>::new());
    }

    /// Paths of 62 to 66 vertices, either side of the one-word width (a path of 63
    /// vertices has 64 positions, one word; 64 vertices need two), and a count that
    /// crosses the word: `C.{n}L` matches exactly the path of `n + 2` vertices.
    #[test]
    fn paths_across_the_word_boundary() {
        for middle in 60..=64 {
            let srcs: Vec<String> = (59..=65).map(|n| format!("C.{{{n}}}L")).collect();
            let refs: Vec<&str> = srcs.iter().map(String::as_str).collect();
            let s = set(&refs);
            assert_eq!(answers(&s, &bounces(middle)), [middle - 59], "{middle}");
        }
        let s = set(&["C.*L", "C<RD>+L", "C.*<RS>L"]);
        assert_eq!(answers(&s, &bounces(200)), [0, 1]);
    }

    /// Set algebra answers the visible AOVs: `C.*L - C.*DL` is the paths to a light
    /// whose last bounce is not diffuse, `^CD+L` every other path.
    #[test]
    fn set_algebra_answers_the_visible_aovs() {
        let s = set(&["C.*L - C.*DL", "^CD+L", "CD+L & C.{2}L"]);
        assert_eq!(answers(&s, &bounces(2)), [2]);
        assert_eq!(answers(&s, &"C RD RS L".parse().unwrap()), [0, 1]);
        assert_eq!(answers(&s, &"C L".parse().unwrap()), [0, 1]);
    }

    /// Labels and classes through the dialect's own acceptance: `<RD'floor'>` only on
    /// the labelled vertex, `[^D]` on any non-diffuse scattering vertex.
    #[test]
    fn atoms_accept_by_the_dialect() {
        let s = set(&["C<RD'floor'>L", "C[^D]L", "C<.D>[<L.'key'>O]"]);
        let p = |t: &str| -> Path { t.parse().unwrap() };
        assert_eq!(answers(&s, &p("C RD'floor' L")), [0]);
        assert_eq!(answers(&s, &p("C RD'floor' L'key'")), [0, 2]);
        assert_eq!(answers(&s, &p("C RD'wall' L'key'")), [2]);
        assert_eq!(answers(&s, &p("C TS L")), [1]);
    }

    /// `compile_within` refuses what the `AovSet` refuses for its NFA's size, counted
    /// as the `AovSet` counts (256 * 200 positions, past the 16 MiB default), while
    /// `compile` builds it: it unrolls nothing. Caught: the budget not checked.
    #[test]
    fn compile_within_refuses_an_nfa_over_its_budget() {
        let aovs: Vec<(String, Lpe)> = vec![("huge".into(), parse("C(.{256}){200}L").unwrap())];
        let refused = DirectSet::<RenderMan>::compile_within(&aovs, &crate::Options::default());
        assert!(
            matches!(refused, Err(crate::CompileError::NfaOverBudget { .. })),
            "{refused:?}"
        );
        assert!(crate::AovSet::compile(&aovs).is_err());
        let built = DirectSet::<RenderMan>::compile(&aovs).unwrap();
        assert!(built.match_path(&bounces(3)).is_empty());
        let fits = DirectSet::<RenderMan>::compile_within(&aovs[..0], &crate::Options::default());
        assert!(fits.is_ok_and(|s| s.is_empty()));
    }

    /// The OSL dialect: events of any length, custom labels through the registration;
    /// `<RD>` refuses a specular reflection. Caught: OSL's `accepts` answering true
    /// (`C<RD>{2}L` matches `C R,S R,D L`).
    #[test]
    fn the_osl_dialect_matches_by_event_symbols() {
        let reg = Registered::none();
        let aovs = vec![
            ("d".to_string(), osl::parse("C<RD>{2}L", &reg).unwrap()),
            ("any".to_string(), osl::parse("C.*L", &reg).unwrap()),
        ];
        let s = DirectSet::<Osl>::compile(&aovs).unwrap();
        let two: osl::Path = "C,_ R,D,_ R,D,_ L,_".parse().unwrap();
        let one: osl::Path = "C,_ R,D,_ L,_".parse().unwrap();
        assert_eq!(s.match_path(&two).iter().collect::<Vec<_>>(), [0, 1]);
        assert_eq!(s.match_path(&one).iter().collect::<Vec<_>>(), [1]);
        let specular: osl::Path = "C,_ R,S,_ R,D,_ L,_".parse().unwrap();
        assert_eq!(s.match_path(&specular).iter().collect::<Vec<_>>(), [1]);
    }

    /// An alternation with more of its sequence after it: `C((<RD><RD>)|<RS>)<RD>L`
    /// reads the alternation, then `<RD>` from where it ended. On `C RD RD L` neither
    /// alternative leaves a diffuse vertex before the light, so it does not match; it
    /// matches with a third diffuse vertex or a specular one first. Caught: the
    /// alternation's loop running the node after its last alternative as one more
    /// (`<=` for `<` on its end: `<RD>` read from where the alternation starts lets
    /// `C RD RD L` match).
    #[test]
    fn an_alternation_ends_at_its_last_alternative() {
        let s = set(&["C((<RD><RD>)|<RS>)<RD>L"]);
        let p = |t: &str| -> Path { t.parse().unwrap() };
        assert_eq!(answers(&s, &p("C RD RD L")), Vec::<usize>::new());
        assert_eq!(answers(&s, &p("C RD RD RD L")), [0]);
        assert_eq!(answers(&s, &p("C RS RD L")), [0]);
        assert_eq!(answers(&s, &p("C RS L")), Vec::<usize>::new());
    }

    /// An empty sequence inside a tree (`osl::Expr::Empty`, which the OSL parser leaves
    /// only as a whole expression, built here by hand as a caller of the public tree
    /// may): `C () <RD> L` reads `C`, nothing, a diffuse reflection and a light.
    /// Caught: the empty node's subtree ending at its own index (the sequence runs it
    /// forever) or at the index before it (`C` read again at the second vertex: no
    /// match).
    #[test]
    fn an_empty_sequence_inside_a_tree_reads_nothing() {
        let reg = Registered::none();
        let mut lpe = osl::parse("C<RD>L", &reg).unwrap();
        let osl::Expr::Concat(parts) = &mut lpe.expr else {
            panic!("C<RD>L parses as a sequence: {:?}", lpe.expr)
        };
        parts.insert(1, osl::Expr::Empty);
        let s = DirectSet::<Osl>::compile(&[("gap".to_string(), lpe)]).unwrap();
        let rd: osl::Path = "C,_ R,D,_ L,_".parse().unwrap();
        let rs: osl::Path = "C,_ R,S,_ L,_".parse().unwrap();
        assert_eq!(s.match_path(&rd).iter().collect::<Vec<_>>(), [0]);
        assert!(s.match_path(&rs).is_empty());
    }

    /// `len` counts the AOVs given (an AOV of set algebra is one, whatever its
    /// operands), `is_empty` tells a set of none. Caught: `len` as 0 or 1, `is_empty`
    /// as true.
    #[test]
    fn the_set_counts_its_aovs_not_their_operands() {
        let s = set(&["C.*L - C.*DL", "CDL", "CSL"]);
        assert_eq!(s.len(), 3);
        assert!(!s.is_empty());
        let none = set(&[]);
        assert_eq!(none.len(), 0);
        assert!(none.is_empty());
    }

    /// The bytes held: the three distinct atoms of `C<RD>L` and `C<RD><RD>L` (`C`,
    /// `<RD>`, `L`), collected into a vector of exactly three, each the size of an
    /// [`Atom`], plus the flattened trees' own count. Caught: the sum's `+` as `-` or
    /// `*`, the atoms' `*` as `+` or `/`, the whole as 0 or 1.
    #[test]
    fn memory_counts_the_atoms_and_the_trees() {
        let s = set(&["C<RD>L", "C<RD><RD>L"]);
        assert_eq!((s.atoms.len(), s.atoms.capacity()), (3, 3));
        let trees = s.program.memory_bytes();
        assert!(trees > 0);
        assert_eq!(s.memory_bytes(), 3 * std::mem::size_of::<Atom>() + trees);
    }
}
