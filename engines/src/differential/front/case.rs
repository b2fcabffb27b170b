//! What the front-end comparison needs of a dialect ([`FrontEnds`]: the reference front
//! end on text, its printer, where its corpora are) and what it compares ([`FrontCase`]:
//! a text under a registration, with where it came from).

use lpe::Dialect;

use crate::differential::Generate;

/// What the front-end comparison needs of a dialect beyond its engines and generators:
/// the reference front end on source text, its printer, and where its corpora are.
pub trait FrontEnds: Generate {
    /// The reference front end on source text under `registration` (as plain data):
    /// its tree, or the error's byte position and message.
    fn reference_parse(
        text: &str,
        registration: &Self::Registration,
    ) -> Result<Self::ReferenceTree, (usize, String)>;

    /// The reference's tree as text lpe's parser reads back to the same meaning.
    fn reference_print(tree: &Self::ReferenceTree) -> String;

    /// The registration of a conformance-suite case of this dialect (`None`: the case is
    /// another dialect's, or its `ini` does not load).
    fn suite_registration(case: &lpe_testkit::suite::Loaded) -> Option<Self::Registration>;

    /// The fuzz targets whose corpora hold this dialect's expression text (a first line
    /// may be a registration, [`crate::WireDialect::registration_line`]).
    const FUZZ_TARGETS: &'static [&'static str];

    /// The hand-written constructs: (registration, text) pairs exercising every
    /// production of the dialect's grammar ([`super::constructs`]).
    fn constructs() -> Vec<(Self::Registration, String)>;
}

/// One expression to compare: its text, registration and where it came from.
#[derive(Clone, Debug)]
pub struct FrontCase<D: Dialect> {
    /// The source text.
    pub text: String,
    /// What it is parsed under.
    pub registration: D::Registration,
    /// Where it came from (a suite file and case, a corpus file, `generated case N`).
    pub origin: String,
}
