//! RenderMan's dialect from Python: `ini=` reads a `rendermn.ini` (macros and lobe
//! mappings), `register=` is refused; a vertex tuple `("R", "D2", "floor")` is the
//! text `RD2'floor'`.

use std::path::Path;

use lpe::renderman::{Config, Parser, RenderMan};

use super::PyDialect;

impl PyDialect for RenderMan {
    fn registration(ini: Option<&Path>, register: Option<&str>) -> Result<Parser, String> {
        if register.is_some() {
            return Err("register= is for dialect=\"osl\"".into());
        }
        let Some(path) = ini else {
            return Ok(Parser::default());
        };
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        Config::from_ini(&text)
            .map(|c| c.parser())
            .map_err(|e| format!("{}: {e}", path.display()))
    }

    fn vertex_text(ty: &str, event: Option<&str>, label: Option<&str>) -> String {
        let label = label.map_or(String::new(), |l| format!("'{l}'"));
        format!("{ty}{}{label}", event.unwrap_or(""))
    }
}
