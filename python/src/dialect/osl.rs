//! OSL's dialect from Python: `register=` declares user labels (`events=U;scatters=Y`),
//! `ini=` is refused (its macros and lobe mappings are RenderMan's); a vertex tuple
//! `("R", "D", "floor")` is the text `R,D,floor`, `None` the NONE symbol `~`.

use std::path::Path;

use lpe::osl::{Osl, Registered};

use super::PyDialect;

impl PyDialect for Osl {
    fn registration(ini: Option<&Path>, register: Option<&str>) -> Result<Registered, String> {
        if ini.is_some() {
            return Err("ini= holds RenderMan macros; it does not apply to dialect=\"osl\"".into());
        }
        register
            .unwrap_or("-")
            .parse()
            .map_err(|e| format!("register: {e}"))
    }

    fn vertex_text(ty: &str, event: Option<&str>, label: Option<&str>) -> String {
        let symbol = |s: Option<&str>| match s {
            None => "~".to_string(),
            Some(s) if s.is_empty() || s.contains([' ', ',', '~', '\'']) => {
                format!("'{}'", s.replace('\'', "''"))
            }
            Some(s) => s.to_string(),
        };
        let mut out = format!("{},{}", symbol(Some(ty)), symbol(event));
        if let Some(l) = label {
            out.push(',');
            out.push_str(&symbol(Some(l)));
        }
        out
    }
}
