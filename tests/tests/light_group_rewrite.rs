//! The light-group suffix: `NAME_group` is macro `NAME` with `'group'` written into
//! EVERY `<L.>` (a light with any event and any label), wherever it stands: bare, in a
//! class, negated class, alternation, repetition, or through a macro that names another.
//! Labelled lights, `O` and `L` written without a triple are left alone.
//!
//! Expected expressions and answers are written out by hand here; nothing expected is
//! computed by the rewrite under test.

use lpe::renderman::{parse, Config, Lpe, Path};

/// User macros with several light positions each.
const INI: &str = "\
# several <L.> per macro, in every kind of place
/prman/lpe/macro/allDirect     (C<RD>[<L.>O])|(C<RS>[O<L.>])|(C<TD><L.>)
/prman/lpe/macro/nested        C((<RD>(<L.>|O))|(<TS>+(<L.>|(<RS>.*<L.>))))
/prman/lpe/macro/classes       C[^<L.>O]*[<L.'fixed'><L.>]
/prman/lpe/macro/repeated      C(<RD><L.>?)+<L.>
/prman/lpe/macro/alias         allDirect
";

/// `(body, hand-written expansion)`.
const USER: &[(&str, &str)] = &[
    (
        "allDirect_key",
        "(C<RD>[<L.'key'>O])|(C<RS>[O<L.'key'>])|(C<TD><L.'key'>)",
    ),
    (
        "nested_key",
        "C((<RD>(<L.'key'>|O))|(<TS>+(<L.'key'>|(<RS>.*<L.'key'>))))",
    ),
    ("classes_key", "C[^<L.'key'>O]*[<L.'fixed'><L.'key'>]"),
    ("repeated_key", "C(<RD><L.'key'>?)+<L.'key'>"),
    // A macro naming a macro: the group reaches the inner macro's lights.
    (
        "alias_key",
        "(C<RD>[<L.'key'>O])|(C<RS>[O<L.'key'>])|(C<TD><L.'key'>)",
    ),
    // The longest macro name before a `_` wins, so groups may contain `_`.
    (
        "allDirect_key_light",
        "(C<RD>[<L.'key_light'>O])|(C<RS>[O<L.'key_light'>])|(C<TD><L.'key_light'>)",
    ),
    // Without a suffix nothing is rewritten.
    ("allDirect", "(C<RD>[<L.>O])|(C<RS>[O<L.>])|(C<TD><L.>)"),
];

/// Every built-in with the group `g`, written out by hand.
const BUILTIN: &[(&str, &str)] = &[
    ("directDiffuse_g", "C<RD>[<L.'g'>O]"),
    ("indirectDiffuse_g", "C<RD>.+[<L.'g'>O]"),
    ("subsurface_g", "C<TD>.*[<L.'g'>O]"),
    ("directSpecular_g", "C<RS>[<L.'g'>O]"),
    ("indirectSpecular_g", "C<RS>.+[<L.'g'>O]"),
    ("transmissive_g", "C<TS>.*[<L.'g'>O]"),
    ("emissive_g", "C[<L.'g'>O]"),
    ("directDiffuseLobe_g", "CD2[<L.'g'>O]"),
    ("indirectDiffuseLobe_g", "CD2.+[<L.'g'>O]"),
    ("subsurfaceLobe_g", "CD3.*[<L.'g'>O]"),
    ("directSpecularPrimaryLobe_g", "CS2[<L.'g'>O]"),
    ("indirectSpecularPrimaryLobe_g", "CS2.+[<L.'g'>O]"),
    ("directSpecularRoughLobe_g", "CS3[<L.'g'>O]"),
    ("indirectSpecularRoughLobe_g", "CS3.+[<L.'g'>O]"),
    ("directSpecularClearcoatLobe_g", "CS4[<L.'g'>O]"),
    ("indirectSpecularClearcoatLobe_g", "CS4.+[<L.'g'>O]"),
    ("directSpecularIridescenceLobe_g", "CS5[<L.'g'>O]"),
    ("indirectSpecularIridescenceLobe_g", "CS5.+[<L.'g'>O]"),
    ("directSpecularFuzzLobe_g", "CS6[<L.'g'>O]"),
    ("indirectSpecularFuzzLobe_g", "CS6.+[<L.'g'>O]"),
    ("transmissiveSingleScatterLobe_g", "CS7.*[<L.'g'>O]"),
    ("directSpecularGlassLobe_g", "C<RS8>[<L.'g'>O]"),
    ("indirectSpecularGlassLobe_g", "C<RS8>.+[<L.'g'>O]"),
    ("transmissiveGlassLobe_g", "C<TS8>.*[<L.'g'>O]"),
    ("diffuse_g", "CD<L.'g'>"),
    ("specular_g", "CS<L.'g'>"),
    // No `<L.>`: nothing to rewrite.
    ("emission_g", "CO"),
    ("caustics_g", "CDS+[<L.'g'>O]"),
    (
        "shadowcollector_g",
        "shadows;C[<.D'collector'><.S'collector'>]<L.'g'>",
    ),
];

fn config() -> Config {
    Config::from_ini(INI).unwrap()
}

fn expand(config: &Config, body: &str) -> Lpe {
    config
        .parser()
        .parse(body)
        .unwrap_or_else(|e| panic!("{body}: {e}"))
}

#[test]
fn user_macros_with_several_lights_get_the_group_everywhere() {
    let config = config();
    for (body, by_hand) in USER {
        let got = expand(&config, body);
        let want = parse(by_hand).unwrap();
        assert_eq!(got, want, "{body}: got `{got}`, want `{by_hand}`");
    }
}

#[test]
fn every_builtin_gets_the_group() {
    // Every built-in is listed: a new built-in needs its hand-written expansion here.
    let listed: Vec<String> = BUILTIN
        .iter()
        .map(|(b, _)| b.trim_end_matches("_g").to_ascii_lowercase())
        .collect();
    for name in lpe::renderman::macros::MacroTable::builtin().names() {
        assert!(
            listed.contains(&name.to_ascii_lowercase()),
            "built-in `{name}` has no hand-written expansion"
        );
    }
    for (body, by_hand) in BUILTIN {
        let got = parse(body).unwrap_or_else(|e| panic!("{body}: {e}"));
        let want = parse(by_hand).unwrap();
        assert_eq!(got, want, "{body}: got `{got}`, want `{by_hand}`");
    }
}

/// `(body, path, matches?)`, decided by hand: each light position of each macro gets a
/// path that reaches it with the group's light (matches) and with another group's light
/// or no group (does not), so a rewrite that skips any one position fails here.
const ANSWERS: &[(&str, &str, bool)] = &[
    // allDirect: three light positions.
    ("allDirect_key", "C RD1 L'key'", true),
    ("allDirect_key", "C RD1 L'fill'", false),
    ("allDirect_key", "C RD1 L", false),
    ("allDirect_key", "C RD1 O'fill'", true),
    ("allDirect_key", "C RS2 L'key'", true),
    ("allDirect_key", "C RS2 L'fill'", false),
    ("allDirect_key", "C RS2 O", true),
    ("allDirect_key", "C TD1 L'key'", true),
    ("allDirect_key", "C TD1 L'fill'", false),
    ("allDirect_key", "C TD1 O", false),
    // nested: three light positions inside alternations and a repetition.
    ("nested_key", "C RD3 L'key'", true),
    ("nested_key", "C RD3 L'fill'", false),
    ("nested_key", "C RD3 O'x'", true),
    ("nested_key", "C TS1 TS2 L'key'", true),
    ("nested_key", "C TS1 TS2 L'fill'", false),
    ("nested_key", "C TS1 RS1 RD1 L'key'", true),
    ("nested_key", "C TS1 RS1 RD1 L'fill'", false),
    ("nested_key", "C TS1 RS1 L'key'", true),
    ("nested_key", "C TS1 RS1 L", false),
    // classes: the negated class is rewritten too; the labelled light stays as it is.
    ("classes_key", "C RD1 L'key'", true),
    ("classes_key", "C RD1 L'fixed'", true),
    ("classes_key", "C RD1 L'fill'", false),
    ("classes_key", "C L'key'", true),
    // repeated: an optional light inside a repetition, then a final light. The inner
    // one cannot be followed by anything a path has, so only the final light decides.
    ("repeated_key", "C RD1 RD2 L'key'", true),
    ("repeated_key", "C RD1 RD2 L'fill'", false),
    ("repeated_key", "C RD1 L", false),
    // Through an alias.
    ("alias_key", "C TD1 L'key'", true),
    ("alias_key", "C TD1 L'fill'", false),
    ("alias_key", "C RS1 O", true),
    // Groups with `_`.
    ("allDirect_key_light", "C TD1 L'key_light'", true),
    ("allDirect_key_light", "C TD1 L'key'", false),
    // Built-ins.
    ("caustics_key", "C RD1 RS1 L'key'", true),
    ("caustics_key", "C RD1 RS1 L'fill'", false),
    ("caustics_key", "C RD1 RS1 O", true),
    ("shadowcollector_key", "C RD1'collector' L'key'", true),
    ("shadowcollector_key", "C RD1'collector' L'fill'", false),
    ("diffuse_key", "C TD2 L'key'", true),
    ("diffuse_key", "C TD2 L'fill'", false),
    ("diffuse_key", "C TD2 O", false),
];

#[test]
fn rewritten_macros_match_the_hand_decided_paths() {
    let config = config();
    for &(body, path, want) in ANSWERS {
        let lpe = expand(&config, body);
        let p: Path = path.parse().unwrap();
        assert_eq!(
            lpe_reference::is_match(&lpe, &p),
            want,
            "reference: `{body}` (`{lpe}`) on `{p}`"
        );
        let set = lpe::AovSet::compile(&[(body.to_string(), lpe.clone())]).unwrap();
        assert_eq!(
            set.match_path(&p).contains(0),
            want,
            "compiled: `{body}` (`{lpe}`) on `{p}`"
        );
    }
}
