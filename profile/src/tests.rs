//! The loader against hand-written profiles: what loads, what is refused and where, and
//! what a loaded profile registers.

use lpe::osl::{parse_source, ErrorKind, Osl};

use crate::{by_name, names, shipped, Profile, ProfileDialect, ProfileError};

const HEAD: &str = "name = \"inhouse\"\ntitle = \"In-house\"\nbase = \"osl\"\n\
                    [[sources]]\nid = \"doc\"\ntitle = \"Our manual\"\nwhere = \"wiki\"\n";

fn invalid(text: &str) -> (Option<usize>, Option<String>, String) {
    match Profile::from_text("inhouse.toml", text) {
        Err(ProfileError::Invalid {
            file,
            line,
            key,
            message,
        }) => {
            assert_eq!(file, "inhouse.toml");
            (line, key, message)
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
}

#[test]
fn every_shipped_profile_loads_under_its_file_name() {
    let loaded: Vec<&str> = shipped().iter().map(|p| p.name.as_str()).collect();
    assert_eq!(loaded, names());
    for name in [
        "renderman",
        "osl",
        "karma",
        "arnold",
        "hdprman",
        "vray",
        "moonray",
    ] {
        assert_eq!(by_name(name).unwrap().name, name);
    }
}

#[test]
fn an_unknown_renderer_lists_the_known_ones_with_the_nearest() {
    let e = by_name("karm").unwrap_err();
    let ProfileError::UnknownRenderer { nearest, known, .. } = &e else {
        panic!("{e:?}")
    };
    assert_eq!(nearest.as_deref(), Some("karma"));
    assert_eq!(known.len(), 7);
    let text = e.to_string();
    assert!(text.contains("did you mean `karma`?"), "{text}");
    assert!(text.contains("renderman, osl, karma"), "{text}");
    assert!(matches!(
        by_name("cycles").unwrap_err(),
        ProfileError::UnknownRenderer { nearest: None, .. }
    ));
}

#[test]
fn a_minimal_profile_loads_and_reads_as_its_base() {
    let p = Profile::from_text("inhouse.toml", HEAD).unwrap();
    assert_eq!(p.dialect(), lpe::DialectName::Osl);
    assert!(!p.prepends_lpe_mark());
    assert_eq!(
        p.correspondence(),
        lpe::translate::Correspondence::default()
    );
}

#[test]
fn redefining_a_letter_of_osl_is_refused_at_its_line() {
    let text = format!("{HEAD}[[events]]\nletter = \"U\"\nmeaning = \"u\"\nsource = \"doc\"\n[[events]]\nletter = \"S\"\nmeaning = \"specular\"\nsource = \"doc\"\n");
    let (line, key, message) = invalid(&text);
    assert_eq!(line, Some(13));
    assert_eq!(key.as_deref(), Some("events[1].letter"));
    assert!(
        message.contains("`S` is one of OSL's own letters"),
        "{message}"
    );
    // A scattering may not take an event's letter either, nor `x`.
    for letter in ["C", "x", "s"] {
        let text = format!(
            "{HEAD}[[scatterings]]\nletter = \"{letter}\"\nmeaning = \"m\"\nsource = \"doc\"\n"
        );
        assert_eq!(invalid(&text).1.as_deref(), Some("scatterings[0].letter"));
    }
    let twice = format!("{HEAD}[[events]]\nletter = \"U\"\nmeaning = \"u\"\nsource = \"doc\"\n[[scatterings]]\nletter = \"U\"\nmeaning = \"u\"\nsource = \"doc\"\n");
    assert!(invalid(&twice).2.contains("added twice"));
}

#[test]
fn a_rule_citing_an_unlisted_source_is_refused() {
    let text = format!("{HEAD}[[never]]\nvertex = \"<RS>\"\nwhy = \"w\"\nsource = \"blog\"\n");
    let (line, key, message) = invalid(&text);
    assert_eq!((line, key.as_deref()), (Some(11), Some("never[0].source")));
    assert!(
        message.contains("cites `blog`") && message.contains("listed: doc"),
        "{message}"
    );
}

#[test]
fn letters_and_prefixes_on_renderman_are_refused() {
    let rm = HEAD.replace("base = \"osl\"", "base = \"renderman\"");
    let events = format!("{rm}[[events]]\nletter = \"A\"\nmeaning = \"a\"\nsource = \"doc\"\n");
    assert!(invalid(&events).2.contains("registers no letters"));
    let prefixes =
        format!("{rm}[[prefixes]]\nname = \"shadow\"\nmeaning = \"a\"\nsource = \"doc\"\n");
    assert_eq!(invalid(&prefixes).1.as_deref(), Some("prefixes[0].name"));
    let translate = format!("{rm}[translate]\ncorrespondence = \"S1=G\"\nsource = \"doc\"\n");
    assert_eq!(
        invalid(&translate).1.as_deref(),
        Some("translate.correspondence")
    );
}

#[test]
fn expressions_are_checked_in_the_profiles_own_terms() {
    // `A` parses only because the profile registers it.
    let ok = format!("{HEAD}[[events]]\nletter = \"A\"\nmeaning = \"albedo\"\nsource = \"doc\"\n[[builtins]]\nname = \"albedo\"\nexpr = \"C[DSV]A\"\nsource = \"doc\"\n");
    Profile::from_text("inhouse.toml", &ok).unwrap();
    let without =
        format!("{HEAD}[[builtins]]\nname = \"albedo\"\nexpr = \"C[DSV]A\"\nsource = \"doc\"\n");
    let (line, key, message) = invalid(&without);
    assert_eq!((line, key.as_deref()), (Some(10), Some("builtins[0].expr")));
    assert!(message.contains("does not parse"), "{message}");
    let bad_vertex = format!("{HEAD}[[never]]\nvertex = \"<RS\"\nwhy = \"w\"\nsource = \"doc\"\n");
    assert_eq!(invalid(&bad_vertex).1.as_deref(), Some("never[0].vertex"));
    let bad_name = format!(
        "{HEAD}[[builtins]]\nname = \"2nd_diffuse\"\nexpr = \"C<RD>L\"\nsource = \"doc\"\n"
    );
    assert_eq!(invalid(&bad_name).1.as_deref(), Some("builtins[0].name"));
    let twice = format!("{HEAD}[[builtins]]\nname = \"d\"\nexpr = \"C<RD>L\"\nsource = \"doc\"\n[[builtins]]\nname = \"d\"\nexpr = \"C<RD>L\"\nsource = \"doc\"\n");
    assert!(invalid(&twice).2.contains("defined twice"));
}

#[test]
fn a_group_table_without_a_carrier_is_refused() {
    let text = format!("{HEAD}[groups]\nsource = \"doc\"\n");
    let (_, key, message) = invalid(&text);
    assert_eq!(key.as_deref(), Some("groups"));
    assert!(message.contains("carrier"), "{message}");
    let spaced = format!("{HEAD}[groups]\nlight = [\"my tag\"]\nsource = \"doc\"\n");
    assert_eq!(invalid(&spaced).1.as_deref(), Some("groups.light[0]"));
}

#[test]
fn malformed_toml_and_unknown_keys_name_their_line() {
    let (line, _, message) = invalid(&format!("{HEAD}[[events]\n"));
    assert_eq!(line, Some(8), "{message}");
    let (line, _, message) = invalid(&format!("{HEAD}colour = \"red\"\n"));
    assert_eq!(line, Some(8));
    assert!(message.contains("colour"), "{message}");
    let (_, key, _) = invalid(&HEAD.replace("base = \"osl\"", "base = \"cycles\""));
    assert_eq!(key.as_deref(), Some("base"));
    let missing = Profile::from_file(std::path::Path::new("/nonexistent/p.toml")).unwrap_err();
    assert!(matches!(missing, ProfileError::Read { .. }), "{missing:?}");
}

#[test]
fn a_profile_registers_its_letters_prefixes_and_builtins() {
    let text = format!(
        "{HEAD}[[events]]\nletter = \"A\"\nmeaning = \"albedo\"\nsource = \"doc\"\n\
         [[prefixes]]\nname = \"shadow\"\nmeaning = \"s\"\nsource = \"doc\"\n\
         [[builtins]]\nname = \"diffuse_direct\"\nexpr = \"C<RD>L\"\nsource = \"doc\"\n"
    );
    let p = Profile::from_text("inhouse.toml", &text).unwrap();
    let reg = <Osl as ProfileDialect>::with_profile(&p, Default::default());
    assert!(parse_source("C[DSV]A", &reg).is_ok());
    let shadow = parse_source("lpe:shadow;C<RD>L", &reg).unwrap();
    assert_eq!(shadow.prefix.as_deref(), Some("shadow"));
    assert!(shadow.to_string().starts_with("shadow;<C"), "{shadow}");
    let e = parse_source("unoccluded;C<RD>L", &reg).unwrap_err();
    assert_eq!(e.pos, 0);
    assert!(
        matches!(e.kind, ErrorKind::UnacceptedPrefix { .. }),
        "{e:?}"
    );
    let by_name = parse_source("diffuse_direct", &reg).unwrap();
    assert_eq!(by_name.expr, parse_source("C<RD>L", &reg).unwrap().expr);
    let e = parse_source("diffuse_dirct", &reg).unwrap_err();
    assert!(
        e.to_string().contains("did you mean `diffuse_direct`?"),
        "{e}"
    );
    // Plain OSL has neither.
    assert!(parse_source("C[DSV]A", &Default::default()).is_err());
}

/// A profile's name: lowercase letters, digits, `_` and `-`, never empty. Planted faults
/// (cargo-mutants), each seen failing: the emptiness test or'd with the rest (any name
/// passes); digits, `_` or `-` refused; `b == b'_'` as `!=` (any byte passes).
#[test]
fn a_profile_name_is_lowercase_letters_digits_underscores_and_hyphens() {
    let named = |name: &str| HEAD.replace("name = \"inhouse\"", &format!("name = \"{name}\""));
    let p = Profile::from_text("inhouse.toml", &named("in-house_2")).unwrap();
    assert_eq!(p.name, "in-house_2");
    for bad in ["", "In-house", "in house", "in.house"] {
        let (line, key, message) = invalid(&named(bad));
        assert_eq!((line, key.as_deref()), (None, Some("name")), "{bad:?}");
        assert!(
            message.contains(&format!("`{bad}` is not a profile name")),
            "{message}"
        );
    }
}

/// An added letter is letters and digits, never empty, and each list counts its own
/// keys. Planted faults, each seen failing: `is_empty() || !all(..)` as `&&` (the empty
/// letter and `A'` pass); one counter shared by both lists (`scatterings[2]`).
#[test]
fn an_added_letter_is_letters_and_digits_and_keyed_in_its_own_list() {
    let event =
        |l: &str| format!("[[events]]\nletter = \"{l}\"\nmeaning = \"m\"\nsource = \"doc\"\n");
    let scattering =
        |l: &str| format!("[[scatterings]]\nletter = \"{l}\"\nmeaning = \"m\"\nsource = \"doc\"\n");
    Profile::from_text("inhouse.toml", &format!("{HEAD}{}", event("A2"))).unwrap();
    for bad in ["", "A'", "a b"] {
        let (_, key, message) = invalid(&format!("{HEAD}{}", event(bad)));
        assert_eq!(key.as_deref(), Some("events[0].letter"));
        assert!(
            message.contains(&format!("`{bad}` is not a label OSL's syntax can write")),
            "{message}"
        );
    }
    let text = format!("{HEAD}{}{}{}", event("U"), scattering("Q"), scattering("S"));
    assert_eq!(invalid(&text).1.as_deref(), Some("scatterings[1].letter"));
}

/// A prefix is letters and `_`, never empty, each once. Planted faults, each seen
/// failing: `is_empty() || !all(..)` as `&&`; `b == b'_'` as `!=` (`no_shadow` refused,
/// `no-shadow` passed); the twice test as `!=` (two different prefixes refused).
#[test]
fn a_prefix_is_letters_and_underscores_each_listed_once() {
    let with = |names: &[&str]| {
        names.iter().fold(HEAD.to_string(), |t, n| {
            format!("{t}[[prefixes]]\nname = \"{n}\"\nmeaning = \"m\"\nsource = \"doc\"\n")
        })
    };
    Profile::from_text("inhouse.toml", &with(&["no_shadow", "unoccluded"])).unwrap();
    for bad in ["", "no-shadow", "shadow2"] {
        let (_, key, message) = invalid(&with(&[bad]));
        assert_eq!(key.as_deref(), Some("prefixes[0].name"));
        assert!(
            message.contains(&format!("`{bad}` is not a prefix name")),
            "{message}"
        );
    }
    let (_, key, message) = invalid(&with(&["shadow", "unoccluded", "shadow"]));
    assert_eq!(key.as_deref(), Some("prefixes[2].name"));
    assert!(message.contains("`shadow` is listed twice"), "{message}");
}

/// A RenderMan-based profile (hdPrman) reads RenderMan's dialect as the parser it is
/// given has it: an ini's macros and the limits stay. Planted fault, seen failing:
/// `with_profile` returning the default parser.
#[test]
fn a_renderman_based_profile_keeps_the_parser_it_is_given() {
    use lpe::renderman::{macros::MacroTable, Limits, Parser, RenderMan};
    let mut macros = MacroTable::builtin();
    macros.define("keyDiffuse", "C<RD><L.'key'>");
    let limits = Limits {
        max_repeat: 3,
        ..Limits::default()
    };
    let hdprman = by_name("hdprman").unwrap();
    let parser = <RenderMan as ProfileDialect>::with_profile(hdprman, Parser::new(limits, macros));
    assert!(parser.parse("keyDiffuse").is_ok());
    assert!(parser.parse("C<RD>{3}L").is_ok());
    assert!(parser.parse("C<RD>{4}L").is_err());
    assert!(lpe::renderman::parse("keyDiffuse").is_err());
}

/// What the shipped profiles say, as docs/profiles.md has it: hdPrman prepends `lpe:` and
/// Karma does not; Karma's settings are `karma:`, hdPrman's `ri:`, a profile without
/// `[detect]` has none; Karma shows every specular lobe as `G`, where the default
/// correspondence shows `S8` as `S`. Planted faults, each seen failing:
/// `prepends_lpe_mark` always false, `settings_namespace` always `None`, `Some("")` or
/// `Some("xyzzy")`, `correspondence` always the default.
#[test]
fn the_shipped_profiles_marks_namespaces_and_correspondences() {
    use lpe::translate::{Correspondence, Scattering};
    let karma = by_name("karma").unwrap();
    let hdprman = by_name("hdprman").unwrap();
    assert!(hdprman.prepends_lpe_mark());
    assert!(!karma.prepends_lpe_mark());
    assert_eq!(karma.settings_namespace(), Some("karma"));
    assert_eq!(hdprman.settings_namespace(), Some("ri"));
    let minimal = Profile::from_text("inhouse.toml", HEAD).unwrap();
    assert_eq!(minimal.settings_namespace(), None);
    assert_eq!(karma.correspondence().declaration(), "S1-S8=G");
    assert!(!karma.correspondence().shows(Scattering::Singular));
    assert_eq!(Correspondence::default().declaration(), "S1-S7=G S8=S");
}
