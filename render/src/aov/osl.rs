//! AOVs written in OSL's dialect (`--dialect osl`): parsed by `lpe::osl` with nothing
//! registered, then checked for RenderMan notions that OSL would read as something else
//! (docs/language.md §18.12). A clear error beats a silent difference:
//!
//! - prefixes (`shadows;`) and RenderMan macros (`directDiffuse`): OSL has neither (and
//!   would fail on their first letter with a less helpful message);
//! - an unquoted digit or `U` inside `<…>`: RenderMan's lobe numbers and user lobes. OSL
//!   reads each as a label of its own (`<RD2>` wants the custom label `2`, `<RU>` the
//!   scattering `U`), which no vertex of `lpe-render` carries: the AOV would stay black.
//!   Quoted (`<RD'2'>`) the label is meant and accepted.
//!
//! A leading `lpe:` is what marks a display channel's or RenderVar's source as an LPE,
//! not part of the expression: it is skipped, and positions still count from the start
//! of the source as written.

use lpe::osl::{self, Registered};
use lpe::renderman::{Limits, Prefix};

/// Why an OSL AOV was refused. Positions are byte offsets, printed as OSL prints its own
/// (`at char N`).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum OslAovError {
    /// OSL's own parse error.
    #[error("{0}")]
    Parse(osl::Error),
    #[error(
        "`{prefix}` at char {pos} is a RenderMan prefix: the OSL dialect has none (an OSL \
         AOV accumulates like a RenderMan one without prefixes); drop it, or use \
         --dialect renderman"
    )]
    Prefix { prefix: String, pos: usize },
    #[error(
        "`{name}` is a RenderMan macro: the OSL dialect has none{}",
        hint.as_ref().map_or(String::new(), |h| format!(" (in OSL: `{h}`)"))
    )]
    Macro { name: String, hint: Option<String> },
    #[error(
        "unquoted `{c}` at char {pos} inside <...> is a RenderMan lobe number: OSL has none \
         and would read it as the custom label '{c}', which no vertex carries; write \
         '{c}' (quoted) if you mean that label"
    )]
    LobeNumber { c: char, pos: usize },
    #[error(
        "unquoted `U` at char {pos} inside <...> is a RenderMan user lobe: OSL has none \
         and lpe-render's OSL vertices scatter only D, G or S; write 'U' (quoted) if you \
         mean a label"
    )]
    UserLobe { pos: usize },
}

/// Parses an OSL AOV for the renderer: nothing registered, the parser's limits.
pub fn parse(
    source: &str,
    limits: &Limits,
    macros: &lpe::renderman::macros::MacroTable,
) -> Result<osl::Lpe, OslAovError> {
    let Some(expr) = source.strip_prefix(osl::SOURCE_MARK) else {
        return parse_expr(source, limits, macros);
    };
    let shift = osl::SOURCE_MARK.len();
    let mut lpe = parse_expr(expr, limits, macros).map_err(|e| e.shifted(shift))?;
    lpe.shift_warnings(shift);
    Ok(lpe)
}

impl OslAovError {
    /// The error with its position moved `by` bytes on.
    fn shifted(self, by: usize) -> OslAovError {
        match self {
            OslAovError::Parse(e) => OslAovError::Parse(osl::Error {
                pos: e.pos + by,
                ..e
            }),
            OslAovError::Prefix { prefix, pos } => OslAovError::Prefix {
                prefix,
                pos: pos + by,
            },
            OslAovError::LobeNumber { c, pos } => OslAovError::LobeNumber { c, pos: pos + by },
            OslAovError::UserLobe { pos } => OslAovError::UserLobe { pos: pos + by },
            e @ OslAovError::Macro { .. } => e,
        }
    }
}

fn parse_expr(
    source: &str,
    limits: &Limits,
    macros: &lpe::renderman::macros::MacroTable,
) -> Result<osl::Lpe, OslAovError> {
    check_prefix(source)?;
    let lpe =
        osl::parse_with(source, &Registered::none(), limits).map_err(|e| {
            match macro_name(source, macros) {
                Some(name) => OslAovError::Macro {
                    hint: osl::BASIC
                        .iter()
                        .find(|(n, _)| *n == name)
                        .map(|(_, s)| s.to_string()),
                    name: name.to_string(),
                },
                None => OslAovError::Parse(e),
            }
        })?;
    check_renderman_lobes(source)?;
    Ok(lpe)
}

/// A RenderMan prefix (`name;`, any case) at the start, after whitespace.
fn check_prefix(source: &str) -> Result<(), OslAovError> {
    let pos = source.len() - source.trim_start().len();
    let rest = &source[pos..];
    let word_len = rest
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(rest.len());
    let (word, after) = rest.split_at(word_len);
    match after.starts_with(';') && Prefix::from_name(word).is_some() {
        true => Err(OslAovError::Prefix {
            prefix: format!("{word};"),
            pos,
        }),
        false => Ok(()),
    }
}

/// The RenderMan macro (with or without a light-group suffix) the whole source names.
fn macro_name<'a>(source: &'a str, macros: &lpe::renderman::macros::MacroTable) -> Option<&'a str> {
    let name = source.trim();
    let known = |n: &str| macros.get(n).is_some();
    if known(name) {
        return Some(name);
    }
    name.rsplit_once('_')
        .map(|(base, _)| base)
        .filter(|base| known(base))
}

/// An unquoted ASCII digit or `U` inside `<…>` (the source already parsed as OSL, so
/// quotes and brackets are balanced; a quote inside `<…>` or `[^…]` runs to the next one,
/// OSL having no escapes).
fn check_renderman_lobes(source: &str) -> Result<(), OslAovError> {
    let mut quoted = false;
    let mut in_group = false;
    for (pos, c) in source.char_indices() {
        match c {
            '\'' => quoted = !quoted,
            _ if quoted => {}
            '<' => in_group = true,
            '>' => in_group = false,
            _ if !in_group => {}
            'U' => return Err(OslAovError::UserLobe { pos }),
            c if c.is_ascii_digit() => return Err(OslAovError::LobeNumber { c, pos }),
            _ => {}
        }
    }
    Ok(())
}

/// Whether an expression can tell a labelled vertex from an unlabelled one. `lpe-render`
/// puts labels only in custom slots, and never a built-in label (the integrator refuses
/// such group names), so a pattern with no custom slot and OSL's eater accepts a vertex
/// exactly when it accepts it without its label. Every operand of set algebra counts.
pub fn names_labels(lpe: &osl::Lpe) -> bool {
    let mut any = false;
    for e in lpe.operands() {
        e.for_each_vertex(&mut |v| {
            any |= v.symbols.len() > 2 || v.eater.is_none();
        });
    }
    any
}

/// The built-in OSL label a scene label must not be: it would stop OSL's eater, so `L`
/// would no longer match a light of that group, nor `R` an object of it.
pub fn is_builtin_label(label: &str) -> bool {
    Registered::none().kind_of(label).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_default(src: &str) -> Result<osl::Lpe, OslAovError> {
        parse(
            src,
            &Limits::default(),
            &lpe::renderman::macros::MacroTable::builtin(),
        )
    }

    #[test]
    fn renderman_prefixes_are_refused_at_their_position() {
        for (src, prefix, pos) in [
            ("shadows;C<RD>L", "shadows;", 0),
            ("  Unoccluded;C<RD>L", "Unoccluded;", 2),
            ("lpe:holdouts;C<RD>L", "holdouts;", 4),
        ] {
            assert_eq!(
                parse_default(src).unwrap_err(),
                OslAovError::Prefix {
                    prefix: prefix.into(),
                    pos
                },
                "{src}"
            );
        }
        // `lpe:` marks a source as an LPE; errors count from the source as written.
        assert!(parse_default("lpe:C<RD>L").is_ok());
        assert_eq!(
            parse_default("lpe:C<RD2>L").unwrap_err(),
            OslAovError::LobeNumber { c: '2', pos: 8 }
        );
        match parse_default("lpe:CE").unwrap_err() {
            OslAovError::Parse(e) => assert_eq!(e.pos, 5),
            e => panic!("{e:?}"),
        }
        // Warnings too: the reversed range's `{` is byte 6 of the source, 2 of the LPE.
        for (src, pos) in [("lpe:C.{3,1}L", 6), ("C.{3,1}L", 2)] {
            let w = parse_default(src).unwrap().warnings;
            assert_eq!(w.iter().map(|w| w.pos).collect::<Vec<_>>(), [pos], "{src}");
        }
        // Not a prefix: OSL's own error.
        assert!(matches!(
            parse_default("shadow;C<RD>L").unwrap_err(),
            OslAovError::Parse(_)
        ));
    }

    #[test]
    fn renderman_macros_are_named_with_the_osl_spelling() {
        let e = parse_default("directDiffuse").unwrap_err();
        assert_eq!(
            e.to_string(),
            "`directDiffuse` is a RenderMan macro: the OSL dialect has none \
             (in OSL: `C<RD>[LO]`)"
        );
        let e = parse_default("caustics_key").unwrap_err();
        assert_eq!(
            e,
            OslAovError::Macro {
                name: "caustics".into(),
                hint: None
            }
        );
    }

    #[test]
    fn lobe_numbers_and_user_lobes_are_refused_unless_quoted() {
        assert_eq!(
            parse_default("C<RD2>L").unwrap_err(),
            OslAovError::LobeNumber { c: '2', pos: 4 }
        );
        assert_eq!(
            parse_default("C<R[D1]>L").unwrap_err(),
            OslAovError::LobeNumber { c: '1', pos: 5 }
        );
        assert_eq!(
            parse_default("C<RU>L").unwrap_err(),
            OslAovError::UserLobe { pos: 3 }
        );
        // Quoted, the label is meant; outside <...> digits and `U` are OSL's errors.
        assert!(parse_default("C<RD'2'>L").is_ok());
        assert!(parse_default("C<RD'U'>'U2'L").is_ok());
        assert!(matches!(
            parse_default("CU L").unwrap_err(),
            OslAovError::Parse(_)
        ));
    }

    #[test]
    fn labels_matter_only_with_custom_slots() {
        let p = |s: &str| names_labels(&parse_default(s).unwrap());
        assert!(!p("C<RD>.*[LO]"));
        assert!(!p("C[^S]*L"));
        assert!(p("C.*<L.'key'>"));
        assert!(p("C'floor'L"));
        assert!(p("C<R...[^'floor']>L"));
    }

    #[test]
    fn builtin_labels_are_known() {
        for l in ["C", "R", "T", "L", "O", "B", "V", "D", "G", "S", "s"] {
            assert!(is_builtin_label(l), "{l}");
        }
        for l in ["key", "floor", "x", "U", "E"] {
            assert!(!is_builtin_label(l), "{l}");
        }
    }

    #[test]
    fn a_label_in_any_operand_of_set_algebra_counts() {
        let l = |src: &str| parse_default(src).unwrap();
        assert!(!names_labels(&l("C.*[LO] - C<RD>.*[LO]")));
        assert!(names_labels(&l("C.*[LO] - C.*<L.'key'>")));
    }
}
