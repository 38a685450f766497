//! Where the window keeps saved games: a directory (`--save-dir`, by default
//! `$XDG_DATA_HOME/sightline/saves`, else `~/.local/share/sightline/saves`)
//! holding `quick.slsave` (F6 and F9) and `slot1.slsave` to `slot9.slsave`
//! (F2 or F3, then a digit). The files are `sightline::play::save`'s.

use std::path::{Path, PathBuf};

/// A slot: the quick one or a numbered one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slot {
    Quick,
    Numbered(u8),
}

impl Slot {
    pub fn file_name(self) -> String {
        match self {
            Slot::Quick => "quick.slsave".into(),
            Slot::Numbered(n) => format!("slot{n}.slsave"),
        }
    }

    pub fn describe(self) -> String {
        match self {
            Slot::Quick => "the quick slot".into(),
            Slot::Numbered(n) => format!("slot {n}"),
        }
    }
}

/// The directory saves go to when none is given.
pub fn default_dir() -> PathBuf {
    let var = |name: &str| std::env::var_os(name).filter(|v| !v.is_empty()).map(PathBuf::from);
    let data = var("XDG_DATA_HOME").or_else(|| var("HOME").map(|h| h.join(".local").join("share")));
    match data {
        Some(data) => data.join("sightline").join("saves"),
        None => PathBuf::from("saves"),
    }
}

/// The file of `slot` in `dir`.
pub fn path(dir: &Path, slot: Slot) -> PathBuf {
    dir.join(slot.file_name())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slots_have_fixed_file_names() {
        assert_eq!(path(Path::new("/s"), Slot::Quick), Path::new("/s/quick.slsave"));
        assert_eq!(path(Path::new("/s"), Slot::Numbered(3)), Path::new("/s/slot3.slsave"));
        assert!(default_dir().ends_with("saves"));
    }
}
