//! The command line that replays a disagreement of `diff --external`, written from the
//! finding's structured data (its set, path and registration): the one place that knows
//! how `lpe-check` spells a replay, so the engines' report stays free of it.

use lpe::DialectName;
use lpe_engines::external::Disagreement;

use crate::dialect::CliDialect;

/// `lpe-check diff --external COMMAND [--dialect D] [registration] --expr E... --path P`,
/// quoted as a shell reads it: the minimized case of `d` asked again of `command`.
pub fn replay<D: CliDialect>(command: &str, d: &Disagreement<D>) -> String {
    let mut words = vec![
        "lpe-check".to_string(),
        "diff".into(),
        "--external".into(),
        command.to_string(),
    ];
    // `--dialect`'s default goes without saying.
    if D::NAME != DialectName::default().name() {
        words.extend(["--dialect".into(), D::NAME.to_string()]);
    }
    words.extend(D::registration_args(&d.registration));
    for e in d.exprs() {
        words.extend(["--expr".into(), e]);
    }
    words.extend(["--path".into(), d.path.clone()]);
    shell_words::join(words)
}
