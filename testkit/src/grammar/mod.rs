//! Expression *text* drawn from each dialect's grammar, production by production, with
//! a record of which productions a run wrote.
//!
//! The tree generators of [`crate::generate`] draw ASTs and print them; a construct the
//! tree cannot hold, or that the printer never writes (OSL's `(R|T)` inside `<…>`,
//! whitespace, lower-case letters, `lpe:`, prefixes, macro names), is then never read by
//! a parser under test. These generators write text directly from the grammars of
//! docs/language.md (§3-§7 for RenderMan in [`renderman`], §18 for OSL in [`osl`]): they
//! share no code or types with either front end, only the documentation, so a parser
//! that misreads a production meets it here.
//!
//! Every production a generator writes is counted in a [`Coverage`] over the dialect's
//! list of productions ([`renderman::PRODUCTIONS`], [`osl::PRODUCTIONS`]);
//! `lpe-check diff --coverage` prints the totals. The lists name what the grammars
//! allow a user to write, and the boundary values a production may be written with
//! (`value.…`, `label.empty`, `label.longest`), since a production is covered by any of
//! its values; the tests of this module check that a default-sized run writes every one
//! of them.
//!
//! The text is valid by construction: every draw respects the documented limits and
//! constraints (counts, `n <= m`, no `{0}` where it is an error, labels without `'`).
//! [`mutate`] turns a valid text into a near miss (one character deleted, doubled or
//! inserted) for the front ends' error paths.

use crate::generate::Choices;

pub mod osl;
pub mod renderman;

/// How many times each production of a dialect's grammar was written.
#[derive(Clone, Debug)]
pub struct Coverage {
    names: &'static [&'static str],
    counts: Vec<u64>,
}

impl Coverage {
    /// No production written yet, over the list `names`.
    pub fn new(names: &'static [&'static str]) -> Coverage {
        Coverage {
            names,
            counts: vec![0; names.len()],
        }
    }

    /// Records one use of `production`.
    ///
    /// # Panics
    /// If `production` is not in the list: a generator that writes a production its
    /// list does not name is a bug of this module (the tests draw thousands of texts).
    pub fn hit(&mut self, production: &str) {
        match self.names.iter().position(|n| *n == production) {
            Some(i) => self.counts[i] += 1,
            None => panic!("production `{production}` is not in the grammar's list"),
        }
    }

    /// Adds `other`'s counts (same list).
    pub fn merge(&mut self, other: &Coverage) {
        for (mine, theirs) in self.counts.iter_mut().zip(&other.counts) {
            *mine += theirs;
        }
    }

    /// Productions written at least once.
    pub fn exercised(&self) -> usize {
        self.counts.iter().filter(|&&n| n > 0).count()
    }

    /// Productions in the list.
    pub fn total(&self) -> usize {
        self.names.len()
    }

    /// The productions never written, in list order.
    pub fn missing(&self) -> Vec<&'static str> {
        self.names
            .iter()
            .zip(&self.counts)
            .filter(|(_, &n)| n == 0)
            .map(|(name, _)| *name)
            .collect()
    }

    /// Each production with its count, in list order.
    pub fn counts(&self) -> impl Iterator<Item = (&'static str, u64)> + '_ {
        self.names.iter().copied().zip(self.counts.iter().copied())
    }
}

/// Size bounds of generated text.
#[derive(Clone, Debug)]
pub struct Config {
    /// Most vertex-level units (atoms, vertex patterns) per expression, roughly: the
    /// generator stops adding units once it has written this many.
    pub max_units: usize,
    /// Deepest nesting of groups, classes and algebra groups.
    pub max_depth: usize,
    /// Whether set algebra (`&`, `-`, `^`: this toolkit's extension) may be written.
    pub set_algebra: bool,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            max_units: 10,
            max_depth: 3,
            set_algebra: true,
        }
    }
}

/// A text under construction: the text, the coverage it adds to, and the unit budget.
pub(crate) struct Writer<'a> {
    pub(crate) out: String,
    pub(crate) cov: &'a mut Coverage,
    pub(crate) units: usize,
}

impl<'a> Writer<'a> {
    pub(crate) fn new(cov: &'a mut Coverage) -> Writer<'a> {
        Writer {
            out: String::new(),
            cov,
            units: 0,
        }
    }

    /// Appends `text` as production `production`.
    pub(crate) fn put(&mut self, production: &str, text: &str) {
        self.cov.hit(production);
        self.out.push_str(text);
    }

    /// Appends `text` with no production of its own (punctuation of an enclosing one).
    pub(crate) fn raw(&mut self, text: &str) {
        self.out.push_str(text);
    }
}

/// Bytes of the longest label written: as long as the longest of
/// [`crate::labels`], well past the 16 bytes RenderMan's label key holds in place.
/// Neither dialect limits a label's length; renderers write long light-group names.
pub const LONGEST_LABEL: usize = 40;

/// A quoted label: plain, with a space, with characters that are operators or
/// punctuation elsewhere, UTF-8, empty (the shortest), or [`LONGEST_LABEL`] bytes long
/// (the longest). Never holds `'` (no escapes in either dialect).
pub(crate) fn label(c: &mut impl Choices, w: &mut Writer<'_>, plain: &[&str]) {
    match c.below(6) {
        0 => w.put("label.empty", "''"),
        // The longest, 1 in 30: a boundary the plain labels below never reach.
        4 if c.chance(20) => {
            let l = format!("'{}'", "k".repeat(LONGEST_LABEL));
            w.put("label.longest", &l)
        }
        1 => w.put("label.space", "'a b'"),
        2 => {
            let l = *c.pick(&["'a|b'", "'x-y'", "'p&q'", "'^n'", "'<R>'", "'[D]'", "'(c)'"]);
            w.put("label.punctuation", l)
        }
        3 => w.put("label.utf8", "'é'"),
        _ => {
            let l = format!("'{}'", c.pick(plain));
            w.put("label.plain", &l)
        }
    }
}

/// A count for `{…}`: mostly small, sometimes the documented maximum (256), where it
/// cannot multiply (the caller says whether it may be large).
pub(crate) fn count(c: &mut impl Choices, large: bool) -> u32 {
    if large && c.chance(3) {
        256
    } else {
        c.below(4) as u32
    }
}

/// Records the boundary values of a count written in `{…}`: 0, 1 and the documented
/// limit (256). The quantifier's production counts it whatever its value; these say
/// whether a run wrote each boundary (docs/language.md §10).
pub(crate) fn mark_count(w: &mut Writer<'_>, n: u32) {
    match n {
        0 => w.cov.hit("value.count.0"),
        1 => w.cov.hit("value.count.1"),
        256 => w.cov.hit("value.count.256"),
        _ => {}
    }
}

/// One-character edits that turn a valid text into a near miss: delete, double, or
/// insert a character that means something in some position of one of the grammars.
pub fn mutate(c: &mut impl Choices, text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let at = c.below(chars.len() + 1);
    let mut out: Vec<char> = chars.clone();
    match c.below(3) {
        0 if at < chars.len() => {
            out.remove(at);
        }
        1 if at < chars.len() => out.insert(at, chars[at]),
        _ => {
            let ch = *c.pick(&[
                '<', '>', '[', ']', '(', ')', '{', '}', ',', '|', '*', '+', '?', '^', '\'', '.',
                ' ', '&', '-', ';', '_', '1', 'x', 'D', 'L',
            ]);
            out.insert(at, ch);
        }
    }
    out.into_iter().collect()
}

/// The generators' shared test: `n` texts from `text` (given the text's index, the
/// source of choices and the coverage) all parse (`parse` returns the error), and
/// together they write every production of `cov`'s list.
#[cfg(test)]
pub(crate) fn assert_texts_parse_and_cover(
    mut cov: Coverage,
    n: usize,
    mut text: impl FnMut(usize, &mut lpe::rng::SplitMix64, &mut Coverage) -> String,
    parse: impl Fn(usize, &str) -> Result<(), String>,
) {
    let mut rng = lpe::rng::SplitMix64::new(7);
    for i in 0..n {
        let t = text(i, &mut rng, &mut cov);
        if let Err(e) = parse(i, &t) {
            panic!("text {i} `{t}` does not parse: {e}");
        }
    }
    assert_eq!(cov.missing(), Vec::<&str>::new());
}

#[cfg(test)]
mod tests {
    use super::*;

    const NAMES: &[&str] = &["a", "b", "c"];

    #[test]
    fn coverage_counts_and_lists_what_is_missing() {
        let mut cov = Coverage::new(NAMES);
        assert_eq!((cov.exercised(), cov.total()), (0, 3));
        cov.hit("b");
        cov.hit("b");
        let mut other = Coverage::new(NAMES);
        other.hit("c");
        cov.merge(&other);
        assert_eq!(cov.exercised(), 2);
        assert_eq!(cov.missing(), vec!["a"]);
        assert_eq!(
            cov.counts().collect::<Vec<_>>(),
            vec![("a", 0), ("b", 2), ("c", 1)]
        );
    }

    #[test]
    #[should_panic(expected = "`z` is not in the grammar's list")]
    fn a_production_outside_the_list_is_a_bug() {
        Coverage::new(NAMES).hit("z");
    }

    /// Whether `long` is `short` with one character inserted somewhere.
    fn one_inserted(long: &str, short: &str) -> bool {
        let l: Vec<char> = long.chars().collect();
        (0..l.len()).any(|i| {
            let mut without = l.clone();
            without.remove(i);
            without.into_iter().collect::<String>() == short
        })
    }

    /// Each near miss is one character deleted, doubled or inserted, anywhere (the end
    /// included), and a fixed seed's 700 draws take each kind often: the deletions and
    /// the doublings each about 1 in 3 (a pool character next to its twin counts as a
    /// doubling too, rarely).
    #[test]
    fn mutations_delete_double_or_insert_one_character() {
        let text = "C<RD>L";
        let mut rng = lpe::rng::SplitMix64::new(3);
        let (mut deleted, mut doubled, mut inserted, mut at_end) = (0, 0, 0, 0);
        for _ in 0..700 {
            let m = mutate(&mut rng, text);
            if one_inserted(text, &m) {
                deleted += 1;
                continue;
            }
            assert!(one_inserted(&m, text), "`{m}` is not one edit of `{text}`");
            let c: Vec<char> = m.chars().collect();
            if c.windows(2).any(|w| w[0] == w[1]) {
                doubled += 1;
            } else {
                inserted += 1;
            }
            // Past the end (not a doubling of the last `L`, which reads the same).
            if m.starts_with(text) && !m.ends_with("LL") {
                at_end += 1;
            }
        }
        assert!(
            deleted > 150 && doubled > 150 && inserted > 100,
            "{deleted} {doubled} {inserted}"
        );
        assert!(at_end > 20, "{at_end}");
    }
}
