//! The explorer page (`page.html`: HTML, CSS and JavaScript in one file, no external
//! assets) and the data each use writes into it: `serve` the language it starts in and
//! the languages to choose from (the page then asks the API), `report` every file's
//! AOVs, findings and views already answered (the page then asks nothing and opens
//! offline). The data goes into the page's one `<script id="lpe-data">` element as JSON.

use lpe::DialectName;
use lpe_profile::{Profile, ProfileError};
use serde_json::{json, Value};

/// The page, with `null` as its data.
const PAGE: &str = include_str!("page.html");

/// Where the data goes: the page holds this exactly once.
const DATA_SLOT: &str = r#"<script type="application/json" id="lpe-data">null</script>"#;

/// What the served page may load: its own inline script and style, its own server's
/// API, pictures given as `data:`; nothing from elsewhere.
pub const CONTENT_SECURITY_POLICY: &str = "default-src 'none'; script-src 'unsafe-inline'; \
     style-src 'unsafe-inline'; img-src data:; connect-src 'self'; base-uri 'none'; \
     form-action 'none'";

/// The language the page starts in: a dialect, or a renderer's profile.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Start {
    /// The dialect (a renderer's base dialect when a renderer is named).
    pub dialect: DialectName,
    /// The renderer's profile name, if one is named.
    pub renderer: Option<String>,
}

impl Start {
    /// `--dialect` and `--renderer`: an unknown renderer, or a dialect other than the
    /// renderer's, is an error.
    pub fn new(dialect: Option<DialectName>, renderer: Option<&str>) -> Result<Start, String> {
        let Some(name) = renderer else {
            return Ok(Start {
                dialect: dialect.unwrap_or_default(),
                renderer: None,
            });
        };
        let profile = lpe_profile::by_name(name).map_err(|e: ProfileError| e.to_string())?;
        match dialect {
            Some(d) if d != profile.dialect() => Err(format!(
                "--dialect {d} contradicts --renderer {name}, which reads {}'s dialect; drop --dialect",
                profile.dialect()
            )),
            _ => Ok(Start {
                dialect: profile.dialect(),
                renderer: Some(profile.name.clone()),
            }),
        }
    }

    fn json(&self) -> Value {
        json!({ "dialect": self.dialect.name(), "renderer": self.renderer })
    }
}

/// Every language the page offers: both dialects, then every shipped renderer profile.
fn languages() -> Value {
    let profiles: Vec<Value> = lpe_profile::shipped()
        .iter()
        .map(|p: &Profile| json!({ "name": p.name, "title": p.title, "dialect": p.dialect().name() }))
        .collect();
    json!({ "dialects": DialectName::ALL.iter().map(|d| d.name()).collect::<Vec<_>>(), "renderers": profiles })
}

/// The page `serve` answers `GET /` with.
pub fn serving(start: &Start) -> String {
    with_data(&json!({ "mode": "serve", "start": start.json(), "languages": languages() }))
}

/// A report page: `files` is the list of per-file entries `report` writes.
pub fn report(files: Value) -> String {
    with_data(&json!({ "mode": "report", "languages": languages(), "files": files }))
}

/// The page with `data` in its data slot. `<` is written as `\u003c`, which JSON reads
/// back as `<`, so no text in the data can close the script element.
fn with_data(data: &Value) -> String {
    let text = data.to_string().replace('<', "\\u003c");
    let slot = format!(r#"<script type="application/json" id="lpe-data">{text}</script>"#);
    PAGE.replacen(DATA_SLOT, &slot, 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The data `page` was written with, read back from its data slot.
    fn data_of(page: &str) -> Value {
        let start = page.find(r#"id="lpe-data">"#).unwrap() + r#"id="lpe-data">"#.len();
        let end = start + page[start..].find("</script>").unwrap();
        serde_json::from_str(&page[start..end]).unwrap()
    }

    /// The data reaches the page once and parses back whole, `</script>` in a name
    /// included. Fault caught: the data written unescaped (the page's script element
    /// ends inside it and the JSON read back is cut).
    #[test]
    fn data_survives_text_that_would_close_the_script() {
        assert_eq!(PAGE.matches(DATA_SLOT).count(), 1);
        let files = json!([{ "name": "a</script><script>alert(1)</script>.usda" }]);
        let data = data_of(&report(files.clone()));
        assert_eq!(data["files"], files);
        assert_eq!(data["mode"], "report");
    }

    /// The served page starts in the language `serve` was given and offers both
    /// dialects. Fault caught: `Start::json` as `null` (the page starts in its own
    /// default, whatever `--renderer` said).
    #[test]
    fn the_served_page_starts_in_the_given_language() {
        let data = data_of(&serving(&Start::new(None, Some("karma")).unwrap()));
        assert_eq!(data["mode"], "serve");
        assert_eq!(
            data["start"],
            json!({ "dialect": "osl", "renderer": "karma" })
        );
        let data = data_of(&serving(&Start::new(None, None).unwrap()));
        assert_eq!(
            data["start"],
            json!({ "dialect": "renderman", "renderer": null })
        );
        assert_eq!(data["languages"]["dialects"], json!(["renderman", "osl"]));
    }

    /// Fault caught: a contradicting `--dialect` accepted.
    #[test]
    fn the_start_language_follows_the_renderer() {
        let karma = Start::new(None, Some("karma")).unwrap();
        assert_eq!(karma.dialect, DialectName::Osl);
        assert_eq!(karma.renderer.as_deref(), Some("karma"));
        let e = Start::new(Some(DialectName::RenderMan), Some("karma")).unwrap_err();
        assert!(e.contains("contradicts --renderer karma"), "{e}");
        assert!(Start::new(None, Some("karm"))
            .unwrap_err()
            .contains("karma"));
        assert_eq!(
            Start::new(Some(DialectName::Osl), None).unwrap().dialect,
            DialectName::Osl
        );
    }
}
