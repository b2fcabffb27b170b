//! The RenderMan-dialect front end: source text to [`crate::renderman::ast::Lpe`].
//!
//! ```text
//! source := ('lpe:')? (prefix ';')* body
//! body   := macro-name ('_' lightgroup)?  |  expression
//! ```
//!
//! A body that is exactly a macro name, or a macro name, `_` and a light group (the
//! longest prefix before a `_` that names a macro wins, so groups may contain `_`), is
//! that macro with `group` written into every `<L.>`. Anything else is parsed as an
//! expression. An identifier-like body that names no macro and holds a character no
//! expression can (`directDifuse`, `CDL_key`) is an "unknown macro" error listing the
//! nearest names; one made of event letters and digits (`CDL`, `C2L`, `CD5L`) is taken
//! as the expression it looks like and gets that expression's error, if any.
//!
//! Set algebra over whole bodies (`A - B`, `A & B`, `^A`, docs/language.md) is found by
//! the dialect-independent [`crate::algebra`] layer after the prefixes; each operand is
//! then a body as above (a macro operand may itself hold set algebra).
//!
//! The front end is the only dialect-specific part: OSL's dialect ([`crate::osl`], with
//! `G`, `V`, `B` and an open alphabet) is another module, whose own tree compiles into the
//! same automata.

mod error;
mod lexer;
mod parser;

pub use crate::limits::Limits;

pub use crate::suggest::edit_distance;
use crate::suggest::nearest;
pub use error::{Error, ErrorKind};

use crate::algebra::{self, AlgebraError, ParseError};
use crate::renderman::ast::{Atom, EventPos, Item, LabelPos, Lpe, Triple, TypePos};
use crate::renderman::macros::MacroTable;
use crate::renderman::path::VertexType;
use crate::renderman::prefix::{Prefix, Prefixes};

/// A configured parser: limits plus the macro table.
#[derive(Clone, Debug, Default)]
pub struct Parser {
    limits: Limits,
    macros: MacroTable,
}

/// Parses with the built-in macros and default limits.
///
/// ```
/// let lpe = lpe::renderman::parse("lpe:unoccluded;C<RD>[<L.>O]").unwrap();
/// assert!(lpe.prefixes.contains(lpe::renderman::Prefix::Unoccluded));
/// assert_eq!(lpe.to_string(), "unoccluded;C<RD>[<L.>O]");
/// ```
pub fn parse(source: &str) -> Result<Lpe, Error> {
    // One parser for every call: building the built-in macro table was half the heap
    // blocks of parsing a short expression.
    static DEFAULT: std::sync::OnceLock<Parser> = std::sync::OnceLock::new();
    DEFAULT.get_or_init(Parser::default).parse(source)
}

fn is_ident(s: &str) -> bool {
    let mut cs = s.chars();
    cs.next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && cs.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

fn skip_ws(s: &str, mut i: usize) -> usize {
    let b = s.as_bytes();
    while i < b.len() && b[i].is_ascii_whitespace() {
        i += 1;
    }
    i
}

impl Parser {
    /// A parser with these limits and macros.
    pub fn new(limits: Limits, macros: MacroTable) -> Parser {
        Parser { limits, macros }
    }

    /// The limits in force.
    pub fn limits(&self) -> &Limits {
        &self.limits
    }

    /// The macro table in use.
    pub fn macros(&self) -> &MacroTable {
        &self.macros
    }

    /// Parses one expression source.
    pub fn parse(&self, source: &str) -> Result<Lpe, Error> {
        self.parse_at_depth(source, 0)
    }

    fn parse_at_depth(&self, source: &str, depth: usize) -> Result<Lpe, Error> {
        let mut i = skip_ws(source, 0);
        if source
            .get(i..i + 4)
            .is_some_and(|s| s.eq_ignore_ascii_case("lpe:"))
        {
            i = skip_ws(source, i + 4);
        }
        let mut prefixes = Prefixes::NONE;
        // Prefixes: identifiers each followed by `;`.
        loop {
            let b = source.as_bytes();
            let mut j = i;
            while j < b.len() && (b[j].is_ascii_alphanumeric() || b[j] == b'_') {
                j += 1;
            }
            let k = skip_ws(source, j);
            if k >= b.len() || b[k] != b';' {
                break;
            }
            let name = &source[i..j];
            match Prefix::from_name(name) {
                Some(p) => prefixes.insert(p),
                None => {
                    let what = if name.is_empty() {
                        "empty prefix before `;`".to_string()
                    } else {
                        format!("unknown prefix `{name}`")
                    };
                    let names = Prefix::ALL.map(Prefix::name);
                    let near = nearest(name, names, 1);
                    return Err(Error::new(ErrorKind::UnknownPrefix, i..k + 1, what, source)
                        .with_help(format!(
                            "did you mean `{}`? prefixes are {}",
                            near[0],
                            names.join(", ")
                        )));
                }
            }
            i = skip_ws(source, k + 1);
        }
        let body_end = source.trim_end().len().max(i);
        let body = &source[i..body_end];
        if body.is_empty() {
            return Err(Error::new(
                ErrorKind::Empty,
                i..source.len(),
                "empty expression",
                source,
            ));
        }
        if algebra::has_algebra(source, i..body_end) {
            return self.parse_algebra(source, i..body_end, prefixes, depth);
        }
        let lpe = self.parse_operand(source, i..body_end, depth)?;
        Ok(Lpe::from_algebra(prefixes.union(lpe.prefixes), lpe.tree()))
    }

    /// A body with set algebra: prefixes brought in by macro operands apply to the whole
    /// expression, like the ones written before it.
    fn parse_algebra(
        &self,
        source: &str,
        body: std::ops::Range<usize>,
        mut prefixes: Prefixes,
        depth: usize,
    ) -> Result<Lpe, Error> {
        let mut operands = 0;
        let tree = algebra::parse(source, body, self.limits.max_depth, &mut |span| {
            if span.is_empty() {
                return Err(Error::new(
                    ErrorKind::Empty,
                    span,
                    "empty expression",
                    source,
                ));
            }
            let lpe = self.parse_operand(source, span.clone(), depth)?;
            prefixes = prefixes.union(lpe.prefixes);
            // Macro operands graft whole trees: count their operands too, so nested
            // macros cannot multiply an expression past the limit.
            operands += lpe.operands().len();
            if operands > algebra::MAX_OPERANDS {
                return Err(Error::new(
                    ErrorKind::Limit,
                    span,
                    format!(
                        "more than {} set-algebra operands once macros are expanded (each \
                         is a hidden AOV)",
                        algebra::MAX_OPERANDS
                    ),
                    source,
                ));
            }
            Ok(lpe.tree())
        })
        .map_err(|e| match e {
            ParseError::Operand(e) => e,
            ParseError::Algebra(e) => {
                let kind = match e {
                    AlgebraError::MissingOperand { .. } => ErrorKind::Empty,
                    AlgebraError::TooDeep { .. } | AlgebraError::TooManyOperands { .. } => {
                        ErrorKind::Limit
                    }
                    _ => ErrorKind::Syntax,
                };
                Error::new(kind, e.span(), e.to_string(), source).with_help(e.help())
            }
        })?;
        Ok(Lpe::from_algebra(prefixes, tree))
    }

    /// One operand, `source[span]`: a macro (whose definition may itself hold set
    /// algebra and prefixes) or an expression.
    fn parse_operand(
        &self,
        source: &str,
        span: std::ops::Range<usize>,
        depth: usize,
    ) -> Result<Lpe, Error> {
        let (i, body_end) = (span.start, span.end);
        let body = &source[span];
        if is_ident(body) {
            if let Some(lpe) = self.expand_macro(source, i..body_end, depth)? {
                return Ok(lpe);
            }
        }
        // An identifier-like body that does not even tokenize (`directDifuse`, `CDL_key`)
        // was meant as a macro name; one that tokenizes (`C2L`, `CD5L`) was meant as an
        // expression and gets the expression's error.
        let tokens = match lexer::tokenize(source, i..body_end) {
            Ok(t) => t,
            Err(e) if is_ident(body) && e.kind() == ErrorKind::Syntax => {
                let near = nearest(body, self.macros.names(), 3);
                let list = near
                    .iter()
                    .map(|n| format!("`{n}`"))
                    .collect::<Vec<_>>()
                    .join(", ");
                return Err(Error::new(
                    ErrorKind::UnknownMacro,
                    i..body_end,
                    format!("unknown macro `{body}` (and not a valid expression)"),
                    source,
                )
                .with_help(format!("nearest macros: {list}")));
            }
            Err(e) => return Err(e),
        };
        let expr = parser::ExprParser::new(source, tokens, &self.limits).parse(i..body_end)?;
        Ok(Lpe::new(Prefixes::NONE, expr))
    }

    /// `NAME` or `NAME_group`, if the body names a macro.
    fn expand_macro(
        &self,
        source: &str,
        span: std::ops::Range<usize>,
        depth: usize,
    ) -> Result<Option<Lpe>, Error> {
        let body = &source[span.clone()];
        let mut found = self.macros.get(body).map(|s| (body, s, None));
        if found.is_none() {
            // Longest macro name before a `_`: scan `_` positions right to left.
            for (u, _) in body
                .match_indices('_')
                .collect::<Vec<_>>()
                .into_iter()
                .rev()
            {
                if let Some(s) = self.macros.get(&body[..u]) {
                    let group = &body[u + 1..];
                    found = Some((&body[..u], s, Some(group)));
                    break;
                }
            }
        }
        let Some((name, macro_source, group)) = found else {
            return Ok(None);
        };
        if group == Some("") {
            return Err(Error::new(
                ErrorKind::Syntax,
                span,
                format!("`{body}`: empty light group after `_`"),
                source,
            ));
        }
        if depth >= self.limits.max_macro_depth {
            return Err(Error::new(
                ErrorKind::Limit,
                span,
                format!(
                    "macro `{name}` nests deeper than the limit of {} (a macro that names itself?)",
                    self.limits.max_macro_depth
                ),
                source,
            ));
        }
        let mut lpe = self
            .parse_at_depth(macro_source, depth + 1)
            .map_err(|inner| {
                Error::new(
                    inner.kind(),
                    span.clone(),
                    format!(
                        "macro `{name}` = `{macro_source}` is invalid: {}",
                        inner.one_line()
                    ),
                    source,
                )
            })?;
        if let Some(group) = group {
            set_light_group(&mut lpe, group);
        }
        Ok(Some(lpe))
    }
}

/// Writes `group` into every `<L.>` (a light triple with any event and any label).
pub fn set_light_group(lpe: &mut Lpe, group: &str) {
    let rewrite = |item: &mut Item| {
        if let Item::Triple(Triple {
            ty: TypePos::One(VertexType::L),
            event: EventPos::Any,
            label: label @ LabelPos::Any,
        }) = item
        {
            *label = LabelPos::One(group.to_string());
        }
    };
    lpe.operands_mut(&mut |e| {
        e.for_each_atom_mut(&mut |a| match a {
            Atom::Item(i) => rewrite(i),
            Atom::Class { items, .. } => items.iter_mut().for_each(rewrite),
        })
    });
}

#[cfg(test)]
mod tests;
