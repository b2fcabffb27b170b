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

#[cfg(test)]
mod tests {
    use lpe::osl::{Osl, Registered};
    use lpe::renderman::RenderMan;
    use lpe::Dialect;
    use lpe_engines::external::{Answer, AovSource};

    use super::*;

    /// A disagreement on `exprs` and `path` under `registration`, as the harness reports
    /// one.
    fn finding<D: Dialect>(
        registration: D::Registration,
        exprs: &[&str],
        path: &str,
    ) -> Disagreement<D> {
        let aovs: Vec<AovSource> = exprs
            .iter()
            .enumerate()
            .map(|(i, e)| AovSource {
                name: format!("a{i}"),
                expr: e.to_string(),
            })
            .collect();
        Disagreement {
            case: Some(7),
            original: (aovs.clone(), path.into()),
            aovs,
            path: path.into(),
            registration,
            external: Answer::Matches(vec![false; exprs.len()]),
            engines: vec![("reference", Some(Answer::Matches(vec![true; exprs.len()])))],
            note: None,
        }
    }

    #[test]
    fn a_renderman_replay_names_no_dialect_and_quotes_each_word() {
        let d = finding::<RenderMan>(Default::default(), &["C<RD>L", "C D{1,2} L"], "C RD L");
        assert_eq!(
            replay("python3 m.py --plant-bug", &d),
            "lpe-check diff --external 'python3 m.py --plant-bug' --expr 'C<RD>L' \
             --expr 'C D{1,2} L' --path 'C RD L'"
        );
    }

    /// OSL's replay names the dialect and, when labels were registered, gives them back
    /// as `--register` reads them; with nothing registered it says nothing of it.
    #[test]
    fn an_osl_replay_names_the_dialect_and_gives_the_registration_back() {
        let registered: Registered = "events=U;scatters=Y".parse().unwrap();
        let d = finding::<Osl>(registered.clone(), &["CDY+U"], "C,_ R,D,Y L,_");
        let line = replay("m", &d);
        assert_eq!(
            line,
            "lpe-check diff --external m --dialect osl --register 'events=U;scatters=Y' \
             --expr CDY+U --path 'C,_ R,D,Y L,_'"
        );
        let words = shell_words::split(&line).unwrap();
        let at = words.iter().position(|w| w == "--register").unwrap();
        let back = Osl::registration(None, Some(&words[at + 1])).unwrap();
        assert_eq!(back, registered);
        let none = finding::<Osl>(Registered::none(), &["CL"], "C,_ L,_");
        assert_eq!(
            replay("m", &none),
            "lpe-check diff --external m --dialect osl --expr CL --path 'C,_ L,_'"
        );
    }
}
