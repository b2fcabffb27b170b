//! What the harness needs to know of a dialect: its expression and path types, how an
//! engine compiles a set of its expressions, how its inputs shrink.
//!
//! The comparison ([`check_in`](super::check_in)) and the minimizer
//! ([`minimize_in`](super::minimize_in)) are written once over this trait; [`RenderMan`]
//! and [`Osl`] are its two dialects.

use std::fmt;

use lpe::osl::{self, Registered};
use lpe::renderman::{Lpe, Path};

use super::shrink;
use crate::engine::{Engine, EngineError, Matcher};

/// A dialect as the harness sees it. The value itself is the context every expression
/// of a case shares (OSL's registered labels), so it is part of a counterexample.
pub trait Language: Clone + fmt::Debug + PartialEq + Eq {
    /// A parsed expression.
    type Expr: Clone + fmt::Debug + fmt::Display + PartialEq + Eq;
    /// A whole path.
    type Path: Clone + fmt::Debug + fmt::Display + PartialEq + Eq;

    /// `engine`'s matcher for `exprs`.
    fn compile<'e>(
        &self,
        engine: &'e dyn Engine,
        exprs: &[Self::Expr],
    ) -> Result<Box<dyn Matcher<Self::Path> + 'e>, EngineError>;

    /// One-step simplifications of an expression, each strictly simpler.
    fn shrink_expr(&self, e: &Self::Expr) -> Vec<Self::Expr>;

    /// One-step simplifications of a path.
    fn shrink_path(&self, p: &Self::Path) -> Vec<Self::Path>;

    /// The shared context as one line of a report (empty: nothing to say).
    fn context(&self) -> String {
        String::new()
    }
}

/// The RenderMan dialect.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderMan;

impl Language for RenderMan {
    type Expr = Lpe;
    type Path = Path;

    fn compile<'e>(
        &self,
        engine: &'e dyn Engine,
        exprs: &[Lpe],
    ) -> Result<Box<dyn Matcher + 'e>, EngineError> {
        engine.compile(exprs)
    }

    /// The expression's shrinks without prefixes ([`shrink::shrink_lpe`]), then the same
    /// expression without them (prefixes never affect matching; dropping them helps
    /// reading).
    fn shrink_expr(&self, e: &Lpe) -> Vec<Lpe> {
        let mut out = shrink::shrink_lpe(e);
        if !e.prefixes.is_empty() {
            let mut bare = e.clone();
            bare.prefixes = lpe::renderman::Prefixes::NONE;
            out.push(bare);
        }
        out
    }

    fn shrink_path(&self, p: &Path) -> Vec<Path> {
        shrink::shrink_path(p)
    }
}

/// The OSL dialect, with the user labels registered before the expressions were parsed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Osl {
    /// `events=…;scatters=…`, as `lpe-check match --register` takes it.
    pub registered: Registered,
}

impl Language for Osl {
    type Expr = osl::Lpe;
    type Path = osl::Path;

    fn compile<'e>(
        &self,
        engine: &'e dyn Engine,
        exprs: &[osl::Lpe],
    ) -> Result<Box<dyn Matcher<osl::Path> + 'e>, EngineError> {
        engine.compile_osl(exprs, &self.registered)
    }

    fn shrink_expr(&self, e: &osl::Lpe) -> Vec<osl::Lpe> {
        let basic = self.registered.basic_labels();
        shrink::shrink_set_expr(
            e,
            |x| shrink::osl::shrink_expr(x, &basic),
            osl::Lpe::from_algebra,
        )
    }

    fn shrink_path(&self, p: &osl::Path) -> Vec<osl::Path> {
        shrink::osl::shrink_path(p)
    }

    fn context(&self) -> String {
        format!("registered: {}", self.registered)
    }
}
