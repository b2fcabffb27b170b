//! The arguments of `lpe-check diff`, apart from the command so that `diff --external`
//! ([`super::external`]) reads them without importing the command that calls it.

use lpe_engines::differential::Run;

use crate::input::DialectArgs;

/// Arguments of `lpe-check diff`.
#[derive(clap::Args, Debug)]
#[command(mut_arg("register", |a| a.help(
    "OSL, with --external and --expr only (generated cases register their own labels): \
     user labels registered before parsing, `events=U;scatters=Y`"
)))]
pub struct Args {
    /// Number of cases (expressions or AOV sets) to generate.
    #[arg(long, default_value_t = 10_000)]
    pub cases: u64,
    /// Seed of the generator; the same seed gives the same cases.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Index of the first case (to regenerate one case of a run).
    #[arg(long, default_value_t = 0)]
    pub first: u64,
    /// Most atoms (OSL: vertex patterns) in one generated expression.
    #[arg(long, default_value_t = 10)]
    pub max_size: usize,
    /// Paths generated per case.
    #[arg(long, default_value_t = 4)]
    pub paths: usize,
    /// Engine to run: `all` (the harness needs at least two).
    #[arg(long, default_value = "all")]
    pub engine: String,
    /// Stop after this many disagreements.
    #[arg(long, default_value_t = 3)]
    pub max_failures: usize,
    /// Print every grammar production with the number of generated texts that wrote it
    /// (the summary line `grammar coverage: N of M productions` is always printed).
    #[arg(long)]
    pub coverage: bool,
    /// `--dialect renderman|osl`; `--register` (OSL, with --external --expr only: a
    /// generated case registers its own labels) for a replayed case.
    #[command(flatten)]
    pub lang: DialectArgs,
    /// An external matcher to test: a command line (split like a shell does) speaking
    /// the JSON Lines protocol of docs/protocol.md on stdin/stdout.
    #[arg(long, value_name = "CMD ARGS")]
    pub external: Option<String>,
    /// Milliseconds the external matcher has to answer one request.
    #[arg(long, default_value_t = 2000)]
    pub timeout_ms: u64,
    /// Restart the external process at most this many times after it failed; when it
    /// fails again, the run stops.
    #[arg(long, default_value_t = 20)]
    pub max_restarts: u64,
    /// With --external: replay one given AOV set (repeat for several AOVs) instead of
    /// generated cases.
    #[arg(long, requires = "external")]
    pub expr: Vec<String>,
    /// With --external: replay the conformance suite, every `*.toml` case file under DIR
    /// (e.g. tests/testdata), both dialects, instead of generated cases; prints each
    /// failed case with its file and name, exits 3 on any failure.
    #[arg(long, value_name = "DIR", requires = "external", conflicts_with_all = ["expr", "register"])]
    pub suite: Option<std::path::PathBuf>,
    /// The workspace checkout whose corpora (conformance suites, fuzz corpora) the
    /// front-end comparison also reads; default: the checkout this binary was built
    /// from, when it is still there.
    #[arg(long, value_name = "DIR")]
    pub corpus_root: Option<std::path::PathBuf>,
    /// With --external and --expr: the paths to ask about.
    #[arg(long, requires = "expr")]
    pub path: Vec<String>,
}

impl Args {
    /// The run these arguments ask for.
    pub fn run(&self) -> Run {
        Run {
            cases: self.cases,
            seed: self.seed,
            first: self.first,
            max_size: self.max_size,
            paths: self.paths,
            max_failures: self.max_failures,
        }
    }
}
