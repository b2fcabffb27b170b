//! RenderMan expression text from the grammar of docs/language.md §3-§7: the `lpe:`
//! mark, prefixes, set algebra, macro bodies with light groups, and expressions with
//! every kind of unit, triple position, class item and quantifier, in upper and lower
//! case, with whitespace between tokens.
//!
//! Macros are the built-ins of §6.1 (the generated cases parse with the default
//! parser); user macros from `rendermn.ini` are a registration, read by the conformance
//! suite's ini cases instead.

use super::{count, label, mark_count, Config, Coverage, Writer};
use crate::generate::Choices;

/// The productions this generator writes, as `lpe-check diff --coverage` counts them.
pub const PRODUCTIONS: &[&str] = &[
    "source.lpe-mark",
    "prefix.unoccluded",
    "prefix.shadows",
    "prefix.holdouts",
    "prefix.nothruput",
    "prefix.noclamp",
    "prefix.overwrite",
    "prefix.noinfinitecheck",
    "prefix.upper-case",
    "prefix.repeated",
    "prefix.spaces",
    "algebra.and",
    "algebra.minus",
    "algebra.not",
    "algebra.group",
    "algebra.alternation-operand",
    "body.macro",
    "body.macro-upper-case",
    "body.macro-light-group",
    "body.macro-light-group-underscore",
    "seq.concat",
    "seq.group",
    "seq.nested-group",
    "alt.bar",
    "alt.chain",
    "quant.star",
    "quant.plus",
    "quant.opt",
    "quant.exact",
    "quant.at-least",
    "quant.range",
    "quant.zero",
    "value.count.0",
    "value.count.1",
    "value.count.256",
    "letter.type",
    "letter.event",
    "letter.lobe",
    "letter.user-lobe",
    "letter.lower-case",
    "value.lobe.D1",
    "value.lobe.D4",
    "value.lobe.S1",
    "value.lobe.S8",
    "value.lobe.U1",
    "value.lobe.U12",
    "dot",
    "label.plain",
    "label.empty",
    "label.space",
    "label.punctuation",
    "label.utf8",
    "label.longest",
    "triple.type-only",
    "triple.type-event",
    "triple.full",
    "triple.type.letter",
    "triple.type.dot",
    "triple.type.class",
    "triple.type.negated",
    "triple.event.letter",
    "triple.event.lobe",
    "triple.event.dot",
    "triple.event.class",
    "triple.event.negated",
    "triple.label.label",
    "triple.label.dot",
    "triple.label.class",
    "triple.label.negated",
    "class",
    "class.negated",
    "class.item.type",
    "class.item.event",
    "class.item.dot",
    "class.item.label",
    "class.item.triple",
    "space",
];

const PREFIXES: [&str; 7] = [
    "unoccluded",
    "shadows",
    "holdouts",
    "nothruput",
    "noclamp",
    "overwrite",
    "noinfinitecheck",
];

/// Built-in macros (§6.1), those with `<L.>` first (a light group changes them).
const MACROS: [&str; 10] = [
    "directDiffuse",
    "indirectDiffuse",
    "subsurface",
    "directSpecular",
    "indirectSpecular",
    "transmissive",
    "emissive",
    "caustics",
    "directDiffuseLobe",
    "emission",
];

const LABELS: [&str; 4] = ["key", "fill", "floor", "collector"];

/// A fresh coverage over [`PRODUCTIONS`].
pub fn coverage() -> Coverage {
    Coverage::new(PRODUCTIONS)
}

/// A whole AOV source: `lpe:`, prefixes, then a body or set algebra over bodies.
pub fn source(c: &mut impl Choices, cfg: &Config, cov: &mut Coverage) -> String {
    let mut w = Writer::new(cov);
    if c.chance(5) {
        let mark = *c.pick(&["lpe:", "LPE:", "lpe: "]);
        w.put("source.lpe-mark", mark);
    }
    if c.chance(15) {
        prefixes(c, &mut w);
    }
    if cfg.set_algebra && c.chance(12) {
        algebra(c, &mut w, cfg, 0);
    } else {
        body(c, &mut w, cfg);
    }
    w.out
}

fn prefixes(c: &mut impl Choices, w: &mut Writer<'_>) {
    let n = 1 + c.below(2);
    let mut last = None;
    for _ in 0..n {
        let i = if last.is_some() && c.chance(15) {
            w.cov.hit("prefix.repeated");
            last.unwrap_or(0)
        } else {
            c.below(PREFIXES.len())
        };
        last = Some(i);
        let name = PREFIXES[i];
        w.cov.hit(&format!("prefix.{name}"));
        if c.chance(15) {
            w.put("prefix.upper-case", &name.to_uppercase());
        } else {
            w.raw(name);
        }
        if c.chance(15) {
            w.put("prefix.spaces", " ; ");
        } else {
            w.raw(";");
        }
    }
}

/// Set algebra: operands joined by `&`/`-`, some complemented or grouped.
fn algebra(c: &mut impl Choices, w: &mut Writer<'_>, cfg: &Config, depth: usize) {
    let n = 2 + usize::from(c.chance(20));
    for i in 0..n {
        if i > 0 {
            let (name, op) = *c.pick(&[("algebra.and", "&"), ("algebra.minus", "-")]);
            w.cov.hit(name);
            w.raw(if c.chance(70) { " " } else { "" });
            w.raw(op);
            w.raw(if c.chance(70) { " " } else { "" });
        }
        operand(c, w, cfg, depth);
    }
}

fn operand(c: &mut impl Choices, w: &mut Writer<'_>, cfg: &Config, depth: usize) {
    if c.chance(20) {
        w.put("algebra.not", "^");
    }
    if depth < 1 && c.chance(15) {
        w.put("algebra.group", "(");
        algebra(c, w, cfg, depth + 1);
        w.raw(")");
    } else if c.chance(10) {
        // A union of whole expressions as one operand: `((A)|(B))`.
        w.put("algebra.alternation-operand", "((");
        expression(c, w, cfg);
        w.raw(")|(");
        expression(c, w, cfg);
        w.raw("))");
    } else {
        body(c, w, cfg);
    }
}

/// A macro reference (8%) or an expression.
fn body(c: &mut impl Choices, w: &mut Writer<'_>, cfg: &Config) {
    if c.chance(8) {
        let name = *c.pick(&MACROS);
        if c.chance(20) {
            w.put("body.macro-upper-case", &name.to_uppercase());
        } else {
            w.put("body.macro", name);
        }
        if c.chance(35) {
            if c.chance(30) {
                w.put("body.macro-light-group-underscore", "_key_fill");
            } else {
                let g = format!("_{}", c.pick(&LABELS));
                w.put("body.macro-light-group", &g);
            }
        }
    } else {
        expression(c, w, cfg);
    }
}

/// An expression: mostly path-shaped (a camera unit, a middle, an emitter unit) so
/// that generated paths can match, otherwise any sequence.
fn expression(c: &mut impl Choices, w: &mut Writer<'_>, cfg: &Config) {
    w.units = 0;
    if c.chance(70) {
        let start = *c.pick(&["C", "c", "<C>", "<C.>", "<C.'cam'>"]);
        if start.starts_with('<') {
            w.cov.hit("triple.type.letter");
            w.cov.hit(if start.len() == 3 {
                "triple.type-only"
            } else if start.len() == 4 {
                "triple.type-event"
            } else {
                "triple.full"
            });
        } else {
            w.cov.hit("letter.type");
        }
        w.raw(start);
        if c.chance(85) {
            space(c, w);
            sequence(c, w, cfg, 0);
        }
        space(c, w);
        let end = *c.pick(&["L", "O", "<L.>", "[<L.>O]", "<L.'key'>", "[LO]", "l"]);
        w.raw(end);
    } else {
        sequence(c, w, cfg, 0);
    }
}

fn space(c: &mut impl Choices, w: &mut Writer<'_>) {
    if c.chance(4) {
        let s = *c.pick(&[" ", "  ", "\t", "\n"]);
        w.put("space", s);
    }
}

/// `alt alt*`.
fn sequence(c: &mut impl Choices, w: &mut Writer<'_>, cfg: &Config, depth: usize) {
    let n = 1 + c.below(3);
    if n > 1 {
        w.cov.hit("seq.concat");
    }
    for i in 0..n {
        if i > 0 {
            space(c, w);
        }
        alt(c, w, cfg, depth);
    }
}

/// `rep ('|' rep)*`.
fn alt(c: &mut impl Choices, w: &mut Writer<'_>, cfg: &Config, depth: usize) {
    rep(c, w, cfg, depth);
    if c.chance(15) {
        w.cov.hit("alt.bar");
        let more = 1 + usize::from(c.chance(25));
        if more > 1 {
            w.cov.hit("alt.chain");
        }
        for _ in 0..more {
            space(c, w);
            w.raw("|");
            space(c, w);
            rep(c, w, cfg, depth);
        }
    }
}

/// `unit quantifier?`.
fn rep(c: &mut impl Choices, w: &mut Writer<'_>, cfg: &Config, depth: usize) {
    let group = unit(c, w, cfg, depth);
    if c.chance(30) {
        quantifier(c, w, !group && depth == 0);
    }
}

fn quantifier(c: &mut impl Choices, w: &mut Writer<'_>, large: bool) {
    match c.below(7) {
        0 => w.put("quant.star", "*"),
        1 => w.put("quant.plus", "+"),
        2 => w.put("quant.opt", "?"),
        3 => {
            let n = count(c, large);
            mark_count(w, n);
            w.put("quant.exact", &format!("{{{n}}}"))
        }
        4 => {
            let n = count(c, large);
            mark_count(w, n);
            w.put("quant.at-least", &format!("{{{n},}}"))
        }
        5 => {
            let n = count(c, false);
            let m = n.max(count(c, large));
            mark_count(w, n);
            mark_count(w, m);
            w.put("quant.range", &format!("{{{n},{m}}}"))
        }
        _ => {
            let z = *c.pick(&["{0}", "{0,0}"]);
            w.put("quant.zero", z)
        }
    }
}

/// One unit; true for a group (whose quantifier stays small).
fn unit(c: &mut impl Choices, w: &mut Writer<'_>, cfg: &Config, depth: usize) -> bool {
    w.units += 1;
    let budget_left = w.units < cfg.max_units;
    match c.below(10) {
        0 | 1 if depth < cfg.max_depth && budget_left => {
            w.put(
                if depth > 0 {
                    "seq.nested-group"
                } else {
                    "seq.group"
                },
                "(",
            );
            space(c, w);
            sequence(c, w, cfg, depth + 1);
            space(c, w);
            w.raw(")");
            true
        }
        2 => {
            class(c, w);
            false
        }
        3 | 4 => {
            triple(c, w);
            false
        }
        5 => {
            label(c, w, &LABELS);
            false
        }
        6 => {
            w.put("dot", ".");
            false
        }
        _ => {
            letter(c, w, true);
            false
        }
    }
}

/// A type letter, an event letter, or an event with a lobe; sometimes lower case.
fn letter(c: &mut impl Choices, w: &mut Writer<'_>, types: bool) {
    let text = if types && c.chance(40) {
        w.cov.hit("letter.type");
        c.pick(&["C", "R", "T", "L", "O"]).to_string()
    } else {
        event(c, w, "letter.event", "letter.lobe", "letter.user-lobe")
    };
    if c.chance(15) {
        w.put("letter.lower-case", &text.to_lowercase());
    } else {
        w.raw(&text);
    }
}

/// `D S U` with an optional lobe in range (D 1-4, S 1-8, U 1-12); the smallest and the
/// largest lobe of each kind are recorded as values (`value.lobe.D1` … `value.lobe.U12`),
/// since `letter.lobe` is covered by any lobe.
fn event(c: &mut impl Choices, w: &mut Writer<'_>, bare: &str, lobe: &str, user: &str) -> String {
    let (kind, max) = *c.pick(&[('D', 4), ('S', 8), ('U', 12)]);
    if kind == 'U' {
        w.cov.hit(user);
    }
    if c.chance(40) {
        w.cov.hit(lobe);
        let n = 1 + c.below(max);
        if n == 1 || n == max {
            w.cov.hit(&format!("value.lobe.{kind}{n}"));
        }
        format!("{kind}{n}")
    } else {
        w.cov.hit(bare);
        kind.to_string()
    }
}

/// `<type event label>`, with omitted trailing positions.
fn triple(c: &mut impl Choices, w: &mut Writer<'_>) {
    w.raw("<");
    let positions = 1 + c.below(3);
    w.cov
        .hit(["triple.type-only", "triple.type-event", "triple.full"][positions - 1]);
    match c.below(5) {
        0 => w.put("triple.type.dot", "."),
        1 => position_class(c, w, "triple.type.class", "triple.type.negated", |c, w| {
            let t = *c.pick(&["R", "T", "C", "L", "O"]);
            w.raw(t)
        }),
        _ => {
            let t = *c.pick(&["R", "T", "R", "T", "C", "L", "O", "r", "t"]);
            w.put("triple.type.letter", t)
        }
    }
    if positions >= 2 {
        triple_space(c, w);
        match c.below(5) {
            0 => w.put("triple.event.dot", "."),
            1 => position_class(
                c,
                w,
                "triple.event.class",
                "triple.event.negated",
                |c, w| {
                    let e = event(
                        c,
                        w,
                        "triple.event.letter",
                        "triple.event.lobe",
                        "letter.user-lobe",
                    );
                    w.raw(&e)
                },
            ),
            _ => {
                let e = event(
                    c,
                    w,
                    "triple.event.letter",
                    "triple.event.lobe",
                    "letter.user-lobe",
                );
                w.raw(&e)
            }
        }
    }
    if positions == 3 {
        triple_space(c, w);
        match c.below(4) {
            0 => w.put("triple.label.dot", "."),
            1 => position_class(
                c,
                w,
                "triple.label.class",
                "triple.label.negated",
                |c, w| label(c, w, &LABELS),
            ),
            _ => {
                w.cov.hit("triple.label.label");
                label(c, w, &LABELS)
            }
        }
    }
    w.raw(">");
}

fn triple_space(c: &mut impl Choices, w: &mut Writer<'_>) {
    if c.chance(10) {
        w.put("space", " ");
    }
}

/// A class in one triple position: `[a b]` or `[^a b]`, items drawn by `item`.
fn position_class<C: Choices>(
    c: &mut C,
    w: &mut Writer<'_>,
    class: &str,
    negated: &str,
    item: impl Fn(&mut C, &mut Writer<'_>),
) {
    w.raw("[");
    if c.chance(40) {
        w.put(negated, "^");
    } else {
        w.cov.hit(class);
    }
    let n = 1 + c.below(3);
    for i in 0..n {
        if i > 0 && c.chance(30) {
            w.put("space", " ");
        }
        item(c, w);
    }
    w.raw("]");
}

/// A top-level class `[…]` / `[^…]` of letters, lobes, `.`, labels and triples.
fn class(c: &mut impl Choices, w: &mut Writer<'_>) {
    w.raw("[");
    if c.chance(35) {
        w.put("class.negated", "^");
    } else {
        w.cov.hit("class");
    }
    let n = 1 + c.below(4);
    for i in 0..n {
        if i > 0 && c.chance(25) {
            w.put("space", " ");
        }
        match c.below(6) {
            0 => {
                w.cov.hit("class.item.type");
                let t = *c.pick(&["C", "R", "T", "L", "O"]);
                w.raw(t)
            }
            1 | 2 => {
                w.cov.hit("class.item.event");
                let e = event(c, w, "letter.event", "letter.lobe", "letter.user-lobe");
                w.raw(&e)
            }
            3 => w.put("class.item.dot", "."),
            4 => {
                w.cov.hit("class.item.label");
                label(c, w, &LABELS)
            }
            _ => {
                w.cov.hit("class.item.triple");
                triple(c, w)
            }
        }
    }
    w.raw("]");
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeSet;

    use lpe::rng::SplitMix64;

    use super::*;

    /// Every text parses with lpe's RenderMan parser (the grammar is the documented
    /// one, so a rejection is a bug on one side: it names the text), and a default-sized
    /// run of 10 000 texts writes every production and every boundary value (the
    /// smallest and largest lobe of each kind, counts 0, 1 and 256, the empty and the
    /// longest label).
    ///
    /// Faults planted, each seen to fail this test and reverted: lobes drawn as
    /// `1 + c.below(max - 1)` (never the largest) and `count` never 0
    /// (`1 + c.below(3)`), both of which the production list alone passed (each
    /// production covered by its other values); `count` never 256 (caught before too,
    /// by `quant.max-count`); the longest label never written.
    #[test]
    fn texts_parse_and_reach_every_production() {
        let cfg = Config::default();
        super::super::assert_texts_parse_and_cover(
            coverage(),
            10_000,
            |_, rng, cov| source(rng, &cfg, cov),
            |_, text| {
                lpe::renderman::parse(text)
                    .map(drop)
                    .map_err(|e| e.to_string())
            },
        );
    }

    /// The lobes `text` writes at the ends of their ranges (`D1 D4 S1 S8 U1 U12`), read
    /// from the text outside quoted labels, ignoring case (`d4` is `D4`).
    fn extreme_lobes(text: &str) -> BTreeSet<String> {
        let chars: Vec<char> = text.to_uppercase().chars().collect();
        let mut out = BTreeSet::new();
        let mut quoted = false;
        for (i, &ch) in chars.iter().enumerate() {
            if ch == '\'' {
                quoted = !quoted;
            }
            let max = match ch {
                'D' => "4",
                'S' => "8",
                'U' => "12",
                _ => continue,
            };
            let digits: String = chars[i + 1..]
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .collect();
            if !quoted && (digits == "1" || digits == max) {
                out.insert(format!("{ch}{digits}"));
            }
        }
        out
    }

    /// A lobe value is recorded for a text exactly when the text writes that lobe, so
    /// full coverage means each boundary lobe was written, not only drawn.
    ///
    /// Fault planted in `event`, seen to fail this test and reverted (the coverage test
    /// above passes it): the largest lobe of the kind recorded for every lobe drawn.
    #[test]
    fn lobe_values_are_recorded_exactly_when_written() {
        let cfg = Config::default();
        let mut rng = SplitMix64::new(9);
        let mut written = 0;
        for _ in 0..3000 {
            let mut cov = coverage();
            let text = source(&mut rng, &cfg, &mut cov);
            let recorded: BTreeSet<String> = cov
                .counts()
                .filter(|(_, n)| *n > 0)
                .filter_map(|(p, _)| p.strip_prefix("value.lobe."))
                .map(str::to_string)
                .collect();
            let lobes = extreme_lobes(&text);
            assert_eq!(recorded, lobes, "`{text}`");
            written += lobes.len();
        }
        assert!(written > 300, "{written}: few boundary lobes were written");
    }

    #[test]
    fn without_set_algebra_no_operator_is_written() {
        let cfg = Config {
            set_algebra: false,
            ..Config::default()
        };
        let mut cov = coverage();
        let mut rng = SplitMix64::new(8);
        for _ in 0..3000 {
            source(&mut rng, &cfg, &mut cov);
        }
        for p in [
            "algebra.and",
            "algebra.minus",
            "algebra.not",
            "algebra.group",
        ] {
            assert_eq!(cov.counts().find(|(n, _)| *n == p).unwrap().1, 0, "{p}");
        }
    }
}
