//! The profiles shipped in `data/`, compiled into the crate, and the loaders of a
//! profile's text and of a user's file.

use std::path::Path;
use std::sync::OnceLock;

use crate::check::check;
use crate::error::{line_of, ProfileError};
use crate::schema::Profile;

/// The shipped profiles' files: `renderman` and `osl` are the base dialects as their
/// own documents define them; the others are renderers.
const SHIPPED: [(&str, &str); 7] = [
    ("renderman", include_str!("../data/renderman.toml")),
    ("osl", include_str!("../data/osl.toml")),
    ("karma", include_str!("../data/karma.toml")),
    ("arnold", include_str!("../data/arnold.toml")),
    ("hdprman", include_str!("../data/hdprman.toml")),
    ("vray", include_str!("../data/vray.toml")),
    ("moonray", include_str!("../data/moonray.toml")),
];

/// Every shipped profile, loaded and checked once.
///
/// # Panics
/// When a shipped file does not load: a defect of this crate that its tests catch.
pub fn shipped() -> &'static [Profile] {
    static ALL: OnceLock<Vec<Profile>> = OnceLock::new();
    ALL.get_or_init(|| {
        SHIPPED
            .iter()
            .map(|(name, text)| {
                let file = format!("profile/data/{name}.toml");
                // A shipped profile that does not load is this crate's defect, caught by
                // `every_shipped_profile_loads`: there is no caller input to report it on.
                Profile::from_text(&file, text).unwrap_or_else(|e| panic!("{e}"))
            })
            .collect()
    })
}

/// The names of the shipped profiles.
pub fn names() -> Vec<&'static str> {
    SHIPPED.iter().map(|(n, _)| *n).collect()
}

/// The shipped profile `name`; an unknown name lists the known ones, with the nearest.
pub fn by_name(name: &str) -> Result<&'static Profile, ProfileError> {
    shipped()
        .iter()
        .find(|p| p.name == name)
        .ok_or_else(|| ProfileError::UnknownRenderer {
            name: name.to_string(),
            known: names().iter().map(|n| n.to_string()).collect(),
            // Two edits: a typo (`karm`, `arnlod`), not another renderer (`cycles`).
            nearest: lpe::suggest::close(name, names(), 2).map(str::to_string),
        })
}

impl Profile {
    /// Reads a profile from `text`; `file` names it in errors.
    pub fn from_text(file: &str, text: &str) -> Result<Profile, ProfileError> {
        let profile: Profile = toml::from_str(text).map_err(|e| ProfileError::Invalid {
            file: file.to_string(),
            line: e.span().map(|s| line_of(text, s.start)),
            key: None,
            message: e.message().trim_end().to_string(),
        })?;
        check(file, text, &profile)?;
        Ok(profile)
    }

    /// Reads the profile in `path` (`--profile FILE`).
    pub fn from_file(path: &Path) -> Result<Profile, ProfileError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ProfileError::Read {
            file: file.clone(),
            message: e.to_string(),
        })?;
        Profile::from_text(&file, &text)
    }
}
