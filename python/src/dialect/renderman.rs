//! RenderMan's dialect from Python: `ini=` reads a `rendermn.ini` (macros and lobe
//! mappings, through lint's ini reader), `register=` is refused; a vertex tuple `("R", "D2", "floor")` is the
//! text `RD2'floor'`.

use std::path::Path;

use lpe::renderman::{Config, Parser, RenderMan};
use lpe_lint::read::ini::read_into;
use lpe_lint::read::Limits;

use super::PyDialect;

impl PyDialect for RenderMan {
    fn registration(ini: Option<&Path>, register: Option<&str>) -> Result<Parser, String> {
        if register.is_some() {
            return Err("register= is for dialect=\"osl\"".into());
        }
        let Some(path) = ini else {
            return Ok(Parser::default());
        };
        // lint's ini reader: its size limit, its errors with the file and line.
        let mut config = Config::default();
        read_into(path, &Limits::default(), &mut config).map_err(|e| format!("ini: {e}"))?;
        Ok(config.parser())
    }

    fn vertex_text(ty: &str, event: Option<&str>, label: Option<&str>) -> String {
        let label = label.map_or(String::new(), |l| format!("'{l}'"));
        format!("{ty}{}{label}", event.unwrap_or(""))
    }
}
