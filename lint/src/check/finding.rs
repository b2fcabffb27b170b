//! One lint finding: what, where, and the text to point at.

use crate::Location;

/// What a finding reports. The JSON `kind` is [`Kind::name`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Kind {
    /// The expression does not parse.
    ParseError,
    /// The AOV can match no path (it renders black whatever the scene).
    Empty,
    /// The AOV matches exactly the paths an earlier AOV matches.
    Equivalent,
    /// A light-group label no light of the stage carries.
    UnknownLightGroup,
    /// An object-group label no object of the stage carries.
    UnknownObjectGroup,
    /// A numbered lobe no lobe mapping feeds.
    UnfedLobe,
    /// A partition member that names no AOV of its file.
    UnknownMember,
    /// Two partition members match a common path.
    Overlap,
    /// A universe path no partition member matches.
    Gap,
    /// A partition member matches a path outside the universe.
    Outside,
    /// A stage that does not declare its dialect holds an expression that parses in
    /// RenderMan's and OSL's and means different things in each.
    AmbiguousDialect,
    /// An equivalence or partition question the analysis could not decide within its
    /// budget: neither a finding nor a clean bill, so it is reported, never silent.
    Undecided,
    /// Every path the AOV matches passes a vertex the run's renderer never produces
    /// (its profile's `never` rules): it renders black in that renderer.
    NeverProduced,
    /// A USD `sourceName` written with `lpe:` for a renderer that prepends the mark
    /// itself (hdPrman), which then reads `lpe:lpe:…`.
    DoubledLpeMark,
}

impl Kind {
    /// Snake-case name, stable across releases (the JSON schema in docs/lint.md).
    pub fn name(self) -> &'static str {
        match self {
            Kind::ParseError => "parse_error",
            Kind::Empty => "empty",
            Kind::Equivalent => "equivalent",
            Kind::UnknownLightGroup => "unknown_light_group",
            Kind::UnknownObjectGroup => "unknown_object_group",
            Kind::UnfedLobe => "unfed_lobe",
            Kind::UnknownMember => "unknown_member",
            Kind::Overlap => "overlap",
            Kind::Gap => "gap",
            Kind::Outside => "outside",
            Kind::AmbiguousDialect => "ambiguous_dialect",
            Kind::Undecided => "undecided",
            Kind::NeverProduced => "never_produced",
            Kind::DoubledLpeMark => "doubled_lpe_mark",
        }
    }
}

/// A finding about one AOV (or one partition).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Finding {
    /// What.
    pub kind: Kind,
    /// The file, as given.
    pub file: String,
    /// The AOV (or the partition's name for partition findings).
    pub subject: String,
    /// Where the AOV or partition is declared.
    pub location: Location,
    /// One line, no position.
    pub message: String,
    /// The expression text and the byte span in it to put a caret under.
    pub caret: Option<(String, std::ops::Range<usize>)>,
    /// A suggested fix.
    pub help: Option<String>,
    /// The other AOV of an equivalence or overlap.
    pub other: Option<String>,
    /// A shortest witness path, re-checked with the reference matcher.
    pub witness: Option<String>,
    /// For a gap: an AOV expression matching exactly the missing paths, when one could
    /// be written and checked.
    pub remainder: Option<String>,
}

impl Finding {
    /// A finding with no caret, help, witness or remainder.
    pub fn new(
        kind: Kind,
        file: &str,
        subject: &str,
        location: &Location,
        message: String,
    ) -> Finding {
        Finding {
            kind,
            file: file.to_string(),
            subject: subject.to_string(),
            location: location.clone(),
            message,
            caret: None,
            help: None,
            other: None,
            witness: None,
            remainder: None,
        }
    }

    /// The caret under the first `needle` in `source`, if it occurs.
    pub fn with_caret_on(mut self, source: &str, needle: &str) -> Finding {
        if let Some(i) = source.find(needle) {
            self.caret = Some((source.to_string(), i..i + needle.len()));
        }
        self
    }
}
