//! A profile made into a dialect's registration ([`ProfileDialect`]): for an OSL-based
//! renderer, its letters registered as OSL's `addEventType`/`addScatteringType` would,
//! its prefixes and its built-in names; a RenderMan-based renderer reads RenderMan's
//! dialect as it is.

use lpe::osl::{Osl, Registered};
use lpe::renderman::RenderMan;

use crate::schema::Profile;

/// A dialect whose registration a profile can give.
pub trait ProfileDialect: lpe::Dialect {
    /// The registration `profile` gives on top of `base` (what `--ini` or `--register`
    /// gave): the profile's letters, prefixes and built-ins are added after its.
    fn with_profile(profile: &Profile, base: Self::Registration) -> Self::Registration;
}

impl ProfileDialect for Osl {
    fn with_profile(profile: &Profile, base: Registered) -> Registered {
        registered_with(profile, base, true)
    }
}

impl ProfileDialect for RenderMan {
    /// hdPrman reads RenderMan's dialect unchanged: its differences are in how a
    /// `sourceName` reaches prman and where groups come from, which lint reads from the
    /// profile itself.
    fn with_profile(_profile: &Profile, base: lpe::renderman::Parser) -> lpe::renderman::Parser {
        base
    }
}

/// OSL's registration from `profile` on top of `base`, with its built-in names when
/// `with_builtins` (the checks parse the built-ins themselves without them).
pub(crate) fn registered_with(
    profile: &Profile,
    base: Registered,
    with_builtins: bool,
) -> Registered {
    let mut r = base;
    r.events
        .extend(profile.events.iter().map(|e| e.letter.get_ref().clone()));
    r.scatters.extend(
        profile
            .scatterings
            .iter()
            .map(|e| e.letter.get_ref().clone()),
    );
    let mut prefixes = r.prefixes.take().unwrap_or_default();
    prefixes.extend(profile.prefixes.iter().map(|p| p.name.get_ref().clone()));
    r.prefixes = Some(prefixes);
    if with_builtins {
        r.builtins.extend(
            profile
                .builtins
                .iter()
                .map(|b| (b.name.get_ref().clone(), b.expr.get_ref().clone())),
        );
    }
    r
}
