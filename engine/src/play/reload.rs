//! Live reload: a RON map being played is watched, and when its file
//! changes (a map maker saved it in an editor) the playthrough reloads it,
//! keeping the player's pose when that is still inside the map. A file with
//! errors is reported (file, line, element, as loading reports them) and
//! the last good level goes on. The file is polled (its modification time
//! and size), which also follows editors that save by writing a new file
//! and renaming it over the old.

use std::path::PathBuf;
use std::time::SystemTime;

use crate::campaign::MapRef;

use super::playthrough::Playthrough;

/// What a poll found.
#[derive(Debug, PartialEq)]
pub enum Reload {
    /// The file is as it was.
    Unchanged,
    /// The map was read again; `kept_pose`: the player stands where it did.
    Reloaded { kept_pose: bool },
    /// The changed file has errors; the old level goes on.
    Broken(String),
}

/// Watches the file of the map being played.
pub struct Watch {
    path: PathBuf,
    stamp: Option<(SystemTime, u64)>,
}

fn stamp(path: &std::path::Path) -> Option<(SystemTime, u64)> {
    let meta = std::fs::metadata(path).ok()?;
    Some((meta.modified().ok()?, meta.len()))
}

impl Watch {
    /// A watch on `map` if it is a RON map file (not a WAD, a compiled map
    /// or a campaign file).
    pub fn new(map: &MapRef) -> Option<Watch> {
        let MapRef::File(path) = map else { return None };
        let ron = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("ron"));
        let campaign = std::fs::read_to_string(path).is_ok_and(|t| t.trim_start().starts_with("Campaign"));
        (ron && !campaign).then(|| Watch { path: path.clone(), stamp: stamp(path) })
    }

    pub fn path(&self) -> &std::path::Path {
        &self.path
    }

    /// Looks at the file; if it changed since the last look, reloads
    /// `play` from it (when `play` is still on that map).
    pub fn poll(&mut self, play: &mut Playthrough) -> Reload {
        let now = stamp(&self.path);
        if now == self.stamp || now.is_none() {
            // Unchanged, or gone for a moment mid-save: look again later.
            return Reload::Unchanged;
        }
        self.stamp = now;
        if play.map != MapRef::File(self.path.clone()) {
            return Reload::Unchanged;
        }
        match play.reload() {
            Ok(kept_pose) => Reload::Reloaded { kept_pose },
            Err(e) => Reload::Broken(e.to_string()),
        }
    }
}
