//! OSL expression text from the grammar of docs/language.md §18: items outside `<…>`
//! (events, scatterings, registered one-character labels, `.`, quoted labels,
//! negations by slot, `[…]` lists of arbitrary items), vertex patterns `<…>` with every
//! kind of slot item (symbols, NONE, sets whose items are slot items, blacklists, quoted
//! labels, groups with `|` and nested groups, literal `|`, `-`, `&` and `]`, `*`, `+`
//! and `{` starting an item, five or more custom items),
//! postfixes (reversed ranges and leading `{0}` included), `|`, groups and set algebra.
//!
//! A registration is plain data here (the one-character events and scatterings to
//! write as shorthand); the `lpe:` mark is a source-level convenience of the command
//! line (`parse_source`), not of the dialect's grammar, and is not written.

use super::{count, label, mark_count, Config, Coverage, Writer};
use crate::generate::Choices;

/// The productions this generator writes, as `lpe-check diff --coverage` counts them.
pub const PRODUCTIONS: &[&str] = &[
    "algebra.and",
    "algebra.minus",
    "algebra.not",
    "algebra.group",
    "seq.concat",
    "seq.group",
    "seq.nested-group",
    "alt.bar",
    "alt.chain",
    "quant.star",
    "quant.plus",
    "quant.exact",
    "quant.at-least",
    "quant.range",
    "quant.reversed-range",
    "quant.zero-leading",
    "value.count.0",
    "value.count.1",
    "value.count.256",
    "item.event",
    "item.scatter",
    "item.registered-event",
    "item.registered-scatter",
    "item.dot",
    "item.label",
    "negation.event",
    "negation.scatter",
    "negation.quoted",
    "negation.mixed",
    "list",
    "list.empty",
    "list.group",
    "list.postfix",
    "list.pattern",
    "list.nested",
    "pattern.event-only",
    "pattern.two-slots",
    "pattern.customs",
    "pattern.five-customs",
    "pattern.symbol",
    "pattern.digit",
    "pattern.none",
    "pattern.dot",
    "pattern.quoted",
    "pattern.set",
    "pattern.set-quoted",
    "pattern.set-none",
    "pattern.set-dot",
    "pattern.set-blacklist",
    "pattern.set-nested",
    "pattern.set-sequence",
    "pattern.postfix-label",
    "pattern.blacklist",
    "pattern.group",
    "pattern.group-alternation",
    "pattern.group-nested",
    "pattern.group-long",
    "pattern.bar-label",
    "pattern.operator-label",
    "pattern.closer-label",
    "label.plain",
    "label.empty",
    "label.space",
    "label.punctuation",
    "label.utf8",
    "label.longest",
];

const EVENTS: [&str; 7] = ["C", "L", "B", "V", "T", "R", "O"];
const SCATTERS: [&str; 4] = ["D", "G", "S", "s"];
const LABELS: [&str; 3] = ["floor", "key", "a"];

/// What a generated text may write as registered shorthand: the registration's
/// one-character event and scattering labels.
#[derive(Clone, Debug, Default)]
pub struct Shorthand {
    /// Registered one-character events.
    pub events: Vec<String>,
    /// Registered one-character scatterings.
    pub scatters: Vec<String>,
}

impl Shorthand {
    /// The one-character labels of a registration's lists.
    pub fn of(events: &[String], scatters: &[String]) -> Shorthand {
        let one = |xs: &[String]| {
            xs.iter()
                .filter(|x| x.chars().count() == 1)
                .cloned()
                .collect()
        };
        Shorthand {
            events: one(events),
            scatters: one(scatters),
        }
    }
}

/// A fresh coverage over [`PRODUCTIONS`].
pub fn coverage() -> Coverage {
    Coverage::new(PRODUCTIONS)
}

/// A whole expression, or set algebra over expressions.
pub fn source(c: &mut impl Choices, reg: &Shorthand, cfg: &Config, cov: &mut Coverage) -> String {
    let mut g = Gen {
        w: Writer::new(cov),
        reg,
        cfg,
        group_room: false,
        nested_room: false,
    };
    if cfg.set_algebra && c.chance(12) {
        g.algebra(c, 0);
    } else {
        g.expression(c);
    }
    g.w.out
}

struct Gen<'a, 'c> {
    w: Writer<'c>,
    reg: &'a Shorthand,
    cfg: &'a Config,
    /// Whether the current `<…>` may still take a group: one per pattern keeps the
    /// product of alternatives far below the parser's bound.
    group_room: bool,
    /// Whether the current group may still take a nested group. With one, a group of
    /// at most three `|`-joined sequences of two items stands for at most 16 vertex
    /// patterns (`|` joins the items beside it: `a b|c d|e f` is `a`, `b|c`, `d|e`,
    /// `f`; a nested group, of plain items, stands for at most 4, so the product is at
    /// most 4 * 2 * 2 * 1 or 1 * 5 * 2 * 1); with one in every item it reached 400.
    nested_room: bool,
}

impl Gen<'_, '_> {
    fn algebra(&mut self, c: &mut impl Choices, depth: usize) {
        let n = 2 + usize::from(c.chance(20));
        for i in 0..n {
            if i > 0 {
                let (name, op) = *c.pick(&[("algebra.and", "&"), ("algebra.minus", "-")]);
                self.w.cov.hit(name);
                let pad = if c.chance(70) { " " } else { "" };
                self.w.raw(pad);
                self.w.raw(op);
                self.w.raw(pad);
            }
            if c.chance(20) {
                self.w.put("algebra.not", "^");
            }
            if depth < 1 && c.chance(15) {
                self.w.put("algebra.group", "(");
                self.algebra(c, depth + 1);
                self.w.raw(")");
            } else {
                self.expression(c);
            }
        }
    }

    /// Mostly path-shaped (a camera item, a middle, an emitter item), otherwise any
    /// sequence; sometimes led by `{0}` items, which drop out.
    fn expression(&mut self, c: &mut impl Choices) {
        self.w.units = 0;
        if c.chance(4) {
            self.w.cov.hit("quant.zero-leading");
            let lead = *c.pick(&["B{0}", "D{0}", "<RD>{0,0}", "(RD){0}"]);
            self.w.raw(lead);
        }
        if c.chance(70) {
            let start = *c.pick(&["C", "<C.>", "<C_>", "<C>"]);
            self.w.raw(start);
            if c.chance(85) {
                self.sequence(c, 0);
            }
            let end = *c.pick(&["L", "O", "<L.>", "[LO]", "<L_>", "<L.'key'>"]);
            self.w.raw(end);
        } else {
            self.sequence(c, 0);
        }
    }

    fn sequence(&mut self, c: &mut impl Choices, depth: usize) {
        let n = 1 + c.below(3);
        if n > 1 {
            self.w.cov.hit("seq.concat");
        }
        for _ in 0..n {
            self.alt(c, depth);
        }
    }

    fn alt(&mut self, c: &mut impl Choices, depth: usize) {
        self.rep(c, depth);
        if c.chance(15) {
            self.w.cov.hit("alt.bar");
            let more = 1 + usize::from(c.chance(25));
            if more > 1 {
                self.w.cov.hit("alt.chain");
            }
            for _ in 0..more {
                self.w.raw("|");
                self.rep(c, depth);
            }
        }
    }

    fn rep(&mut self, c: &mut impl Choices, depth: usize) {
        let group = self.item(c, depth);
        if c.chance(25) {
            self.postfix(c, !group && depth == 0);
        }
    }

    /// `*`, `+`, `{n}` (n >= 1: `{0}` is only for leading items), `{n,}`, `{n,m}` and
    /// the reversed `{m,n}` (read as `{m}` with a warning).
    fn postfix(&mut self, c: &mut impl Choices, large: bool) {
        let w = &mut self.w;
        match c.below(6) {
            0 => w.put("quant.star", "*"),
            1 => w.put("quant.plus", "+"),
            2 => {
                let n = count(c, large).max(1);
                mark_count(w, n);
                w.put("quant.exact", &format!("{{{n}}}"))
            }
            3 => {
                let n = count(c, large);
                mark_count(w, n);
                w.put("quant.at-least", &format!("{{{n},}}"))
            }
            4 => {
                let n = count(c, false);
                let m = n.max(count(c, large)).max(1);
                mark_count(w, n);
                mark_count(w, m);
                w.put("quant.range", &format!("{{{n},{m}}}"))
            }
            _ => {
                let m = 2 + c.below(2);
                let n = c.below(m);
                w.put("quant.reversed-range", &format!("{{{m},{n}}}"))
            }
        }
    }

    /// One item outside `<…>`; true for a group or list (whose postfix stays small).
    fn item(&mut self, c: &mut impl Choices, depth: usize) -> bool {
        self.w.units += 1;
        let room = depth < self.cfg.max_depth && self.w.units < self.cfg.max_units;
        match c.below(12) {
            0 if room => {
                let name = if depth > 0 {
                    "seq.nested-group"
                } else {
                    "seq.group"
                };
                self.w.put(name, "(");
                self.sequence(c, depth + 1);
                self.w.raw(")");
                true
            }
            1 if room => {
                self.list(c, depth);
                true
            }
            2 => {
                self.negation(c);
                false
            }
            3..=5 => {
                self.pattern(c);
                false
            }
            6 => {
                self.w.put("item.dot", ".");
                false
            }
            7 => {
                self.w.cov.hit("item.label");
                label(c, &mut self.w, &LABELS);
                false
            }
            8 if !self.reg.events.is_empty() => {
                let e = c.pick(&self.reg.events).clone();
                self.w.put("item.registered-event", &e);
                false
            }
            9 if !self.reg.scatters.is_empty() => {
                let s = c.pick(&self.reg.scatters).clone();
                self.w.put("item.registered-scatter", &s);
                false
            }
            8..=9 => {
                let s = *c.pick(&SCATTERS);
                self.w.put("item.scatter", s);
                false
            }
            10 => {
                let e = *c.pick(&EVENTS);
                self.w.put("item.event", e);
                false
            }
            _ => {
                let s = *c.pick(&SCATTERS);
                self.w.put("item.scatter", s);
                false
            }
        }
    }

    /// `[^…]` outside `<…>`: known labels or quoted ones; the last decides the slot.
    fn negation(&mut self, c: &mut impl Choices) {
        self.w.raw("[^");
        let mixed = c.chance(20);
        let slot = c.below(3);
        let n = 1 + c.below(3);
        for i in 0..n {
            let last = i + 1 == n;
            let s = if last || !mixed { slot } else { (slot + 1) % 3 };
            self.known_or_quoted(c, s);
        }
        self.w.cov.hit(if mixed && n > 1 {
            "negation.mixed"
        } else {
            ["negation.event", "negation.scatter", "negation.quoted"][slot]
        });
        self.w.raw("]");
    }

    /// A label of slot `slot` (0 event, 1 scattering, 2 quoted custom) for a negation.
    fn known_or_quoted(&mut self, c: &mut impl Choices, slot: usize) {
        match slot {
            0 => {
                let e = self.event(c);
                self.w.raw(&e)
            }
            1 => {
                let s = self.scatter(c);
                self.w.raw(&s)
            }
            _ => {
                let l = format!("'{}'", c.pick(&LABELS));
                self.w.raw(&l)
            }
        }
    }

    fn event(&self, c: &mut impl Choices) -> String {
        if !self.reg.events.is_empty() && c.chance(20) {
            c.pick(&self.reg.events).clone()
        } else {
            c.pick(&EVENTS).to_string()
        }
    }

    fn scatter(&self, c: &mut impl Choices) -> String {
        if !self.reg.scatters.is_empty() && c.chance(20) {
            c.pick(&self.reg.scatters).clone()
        } else {
            c.pick(&SCATTERS).to_string()
        }
    }

    /// `[…]` outside `<…>`: an alternation of arbitrary items, postfixes included.
    fn list(&mut self, c: &mut impl Choices, depth: usize) {
        if c.chance(5) {
            self.w.put("list.empty", "[]");
            return;
        }
        self.w.put("list", "[");
        let n = 1 + c.below(3);
        for _ in 0..n {
            match c.below(6) {
                0 => {
                    self.w.put("list.group", "(");
                    self.sequence(c, depth + 1);
                    self.w.raw(")");
                }
                1 => {
                    self.w.cov.hit("list.postfix");
                    let s = *c.pick(&["C*", "D+", "G{1,2}", "R{2}"]);
                    self.w.raw(s);
                }
                2 => {
                    self.w.cov.hit("list.pattern");
                    self.pattern(c);
                }
                3 if depth + 1 < self.cfg.max_depth => {
                    self.w.cov.hit("list.nested");
                    self.list(c, depth + 1);
                }
                _ => {
                    self.item(c, depth + 1);
                }
            }
        }
        self.w.raw("]");
    }

    /// A vertex pattern `<…>`: 1-7 slot items.
    fn pattern(&mut self, c: &mut impl Choices) {
        if c.chance(4) {
            // A group counts once toward the five custom items (§18.4): five or more
            // custom symbols in one group keep the eater.
            let n = 5 + c.below(2);
            let symbols: String = (0..n)
                .map(|_| *c.pick(&["a", "b", "R", "D", "."]))
                .collect();
            self.w
                .put("pattern.group-long", &format!("<RD({symbols})>"));
            return;
        }
        self.w.raw("<");
        let items = match c.below(10) {
            0 => 1,
            1..=4 => 2,
            5..=8 => 3 + c.below(2),
            _ => 7,
        };
        self.w.cov.hit(match items {
            1 => "pattern.event-only",
            2 => "pattern.two-slots",
            7 => "pattern.five-customs",
            _ => "pattern.customs",
        });
        self.group_room = true;
        if c.chance(6) {
            // `*`, `+` and `{` are postfixes right after an item and an error there
            // (§18.4); only where an item starts are they a label.
            self.postfix_label(c);
        } else {
            self.slot_item(c, 0, 0);
        }
        for slot in 1..items {
            self.slot_item(c, slot, 0);
        }
        self.w.raw(">");
    }

    /// One slot item inside `<…>` (`depth`: groups around it).
    fn slot_item(&mut self, c: &mut impl Choices, slot: usize, depth: usize) {
        match c.below(14) {
            0 => self.w.put("pattern.none", "x"),
            1 => self.w.put("pattern.dot", "."),
            2 => {
                let l = format!("'{}'", c.pick(&["floor", "a b", "", "|x|", "é"]));
                self.w.put("pattern.quoted", &l)
            }
            3 => self.set(c, depth),
            4 => {
                self.w.put("pattern.blacklist", "[^");
                for _ in 0..1 + c.below(2) {
                    let s = c.below(3);
                    self.known_or_quoted(c, s);
                }
                self.w.raw("]");
            }
            5 if depth == 0 && self.group_room => {
                self.group_room = false;
                self.nested_room = true;
                self.group(c, slot, depth)
            }
            5 if depth == 1 && self.nested_room => {
                self.nested_room = false;
                self.group(c, slot, depth)
            }
            6 => {
                let d = *c.pick(&["1", "2", "7"]);
                self.w.put("pattern.digit", d)
            }
            7 if depth == 0 => {
                let l = *c.pick(&["-", "&"]);
                self.w.put("pattern.operator-label", l)
            }
            8 if depth == 0 => self.w.put("pattern.bar-label", "|"),
            9 if depth == 0 => self.w.put("pattern.closer-label", "]"),
            _ => {
                let s = match slot {
                    0 => self.event(c),
                    1 => self.scatter(c),
                    _ => c.pick(&["a", "b", "R", "D", "q"]).to_string(),
                };
                self.w.put("pattern.symbol", &s)
            }
        }
    }

    /// `*`, `+` or `{` where an item starts: the label of that character.
    fn postfix_label(&mut self, c: &mut impl Choices) {
        let l = *c.pick(&["*", "+", "{"]);
        self.w.put("pattern.postfix-label", l);
    }

    /// `[…]` inside `<…>` (`depth`: sets and groups around it): each item a slot item
    /// (§18.4), so `x` is NONE, `.` any symbol, `[^…]` a blacklist, a nested `[…]`
    /// joins in and `( … )` is a sequence of symbols, one vertex pattern of its own.
    fn set(&mut self, c: &mut impl Choices, depth: usize) {
        self.w.put("pattern.set", "[");
        for i in 0..1 + c.below(3) {
            match c.below(12) {
                0 | 1 => {
                    let l = format!("'{}'", c.pick(&LABELS));
                    self.w.put("pattern.set-quoted", &l);
                }
                2 => self.w.put("pattern.set-none", "x"),
                3 => self.w.put("pattern.set-dot", "."),
                4 => {
                    self.w.put("pattern.set-blacklist", "[^");
                    let s = c.below(3);
                    self.known_or_quoted(c, s);
                    self.w.raw("]");
                }
                5 if depth < 2 => {
                    self.w.cov.hit("pattern.set-nested");
                    self.set(c, depth + 1);
                }
                // A sequence adds a vertex pattern per way through it: one per `<…>`,
                // as for groups, keeps the product of ways below the parser's bound.
                6 if self.group_room => {
                    self.group_room = false;
                    self.w.put("pattern.set-sequence", "(");
                    for _ in 0..1 + c.below(3) {
                        let s = *c.pick(&["R", "T", "D", "S", "x", ".", "a"]);
                        self.w.raw(s);
                    }
                    self.w.raw(")");
                }
                7 if i == 0 => self.postfix_label(c),
                _ => {
                    let s = *c.pick(&["R", "T", "D", "G", "a", "1"]);
                    self.w.raw(s);
                }
            }
        }
        self.w.raw("]");
    }

    /// `( … )` inside `<…>`: alternatives of slot-item sequences, nested groups too.
    fn group(&mut self, c: &mut impl Choices, slot: usize, depth: usize) {
        self.w.put(
            if depth > 0 {
                "pattern.group-nested"
            } else {
                "pattern.group"
            },
            "(",
        );
        let alternatives = if c.chance(50) { 1 } else { 2 + c.below(2) };
        if alternatives > 1 {
            self.w.cov.hit("pattern.group-alternation");
        }
        for a in 0..alternatives {
            if a > 0 {
                self.w.raw("|");
            }
            for i in 0..1 + c.below(2) {
                self.slot_item(c, slot + i, depth + 1);
            }
        }
        self.w.raw(")");
    }
}

#[cfg(test)]
mod tests {
    use lpe::osl::Registered;

    use super::*;

    /// Every text parses with lpe's OSL parser under its registration (a rejection is
    /// a bug on one side and names the text), and 10 000 texts, half of them under a
    /// registration, write every production and every boundary value (counts 0, 1 and
    /// 256, the empty and the longest label).
    ///
    /// Faults planted in `grammar/mod.rs`, each seen to fail this test and reverted:
    /// `count` never 0; `count` never 256; the longest label never written. In this
    /// file: `*`, `+` or `{` written as any item of a `[…]` inside `<…>`, not only the
    /// first (`<[R*]>` is a postfix where the parser refuses one: rejected).
    #[test]
    fn texts_parse_and_reach_every_production() {
        let cfg = Config::default();
        let registered = Registered {
            events: vec!["U".into()],
            scatters: vec!["Y".into()],
            ..Registered::default()
        };
        let reg = |i: usize| {
            if i.is_multiple_of(2) {
                Registered::none()
            } else {
                registered.clone()
            }
        };
        super::super::assert_texts_parse_and_cover(
            coverage(),
            10_000,
            |i, rng, cov| {
                let r = reg(i);
                source(rng, &Shorthand::of(&r.events, &r.scatters), &cfg, cov)
            },
            |i, text| {
                lpe::osl::parse(text, &reg(i))
                    .map(drop)
                    .map_err(|e| e.message())
            },
        );
    }

    /// Groups nest in groups as often as a source can make them: the slot-item choice
    /// (`below(14)`) answers "group" 3 times in 5, and every group spells 2 or 3
    /// alternatives of 2 items each. The products of alternatives stay within the
    /// parser's bound, 256 vertex patterns per `<…>`.
    ///
    /// Fault it catches: a nested group allowed in every item of a group (as it was:
    /// `<.((GD|GD|GD)(DD|DD|DD)|([11])b|(GD|GD|GD)(D.|..|..))..>` spells 400, found by
    /// the `osl_differential` fuzz target as a documented text the parser rejects).
    #[test]
    fn group_heavy_texts_stay_within_the_parsers_bound() {
        struct GroupHeavy(lpe::rng::SplitMix64);
        impl Choices for GroupHeavy {
            fn below(&mut self, n: usize) -> usize {
                match n {
                    14 if self.0.below(5) < 3 => 5,
                    // `chance(50)` false: 2 or 3 alternatives; 2 items each.
                    100 => 50 + self.0.below(50),
                    2 => 1,
                    _ => self.0.below(n),
                }
            }
        }
        let cfg = Config::default();
        let reg = Registered::none();
        let mut source_of = GroupHeavy(lpe::rng::SplitMix64::new(11));
        let mut cov = coverage();
        for i in 0..20_000 {
            let text = source(&mut source_of, &Shorthand::of(&[], &[]), &cfg, &mut cov);
            if let Err(e) = lpe::osl::parse(&text, &reg) {
                panic!("text {i} `{text}` does not parse: {}", e.message());
            }
        }
    }
}
