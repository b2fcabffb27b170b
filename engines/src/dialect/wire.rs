//! A dialect's cases as text outside the process: [`WireDialect`], and the registration
//! as the external protocol carries it, [`WireRegistration`] (beside the trait that
//! returns it, so that the protocol, `external/protocol.rs`, and the dialects both import
//! this file and not each other).

use lpe::Dialect;
use serde::Serialize;

/// How a case leaves the process and comes back as text: in a report, in a request of
/// the external protocol (docs/protocol.md), in a fuzz input.
pub trait WireDialect: Dialect {
    /// The registration as one line of a report (empty: nothing to say).
    fn context(registration: &Self::Registration) -> String {
        let _ = registration;
        String::new()
    }

    /// What a `compile` request of the external protocol carries besides the AOVs;
    /// `None`: nothing.
    fn wire_registration(registration: &Self::Registration) -> Option<WireRegistration> {
        let _ = registration;
        None
    }

    /// A parse error's byte position and message, as the external protocol compares
    /// rejections.
    fn parse_error(e: &Self::ParseError) -> (usize, String);

    /// A registration written on the first line of a fuzz input, if the line is one
    /// (`None`, the default: the whole input is the expression).
    fn registration_line(line: &str) -> Option<Self::Registration> {
        let _ = line;
        None
    }

    /// Whether two parses are the same tree, as the `parse` fuzz property compares an
    /// expression with the parse of its printed text (equality unless the tree carries
    /// source positions that reprinting moves).
    fn same_tree(a: &Self::Lpe, b: &Self::Lpe) -> bool {
        a == b
    }
}

/// The user labels an OSL matcher registers before it parses a set's expressions (OSL's
/// `AccumAutomata::addEventType` and `addScatteringType`, in this order), as a `compile`
/// request carries them.
#[derive(Clone, Debug, Serialize, PartialEq, Eq, Default)]
pub struct WireRegistration {
    /// Extra event types.
    pub events: Vec<String>,
    /// Extra scattering types.
    pub scatters: Vec<String>,
}
