//! Which map to open and which follows which. A [`MapRef`] names one map: a
//! RON or compiled file, or a map in a WAD (`freedoom1.wad:E1M4`, with an
//! IWAD under a PWAD); opening a WAD map converts it in memory, as `sightline
//! import` would, and draws its art from the WAD itself. A [`Campaign`] says
//! what comes after a map ends: a WAD's episode order (Doom's and Doom II's
//! rules, secret exits included), the list of a RON campaign file, or nothing
//! after a lone map.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use serde::Deserialize;

use crate::bsp::{build, BuildOptions};
use crate::level::{open_compiled, open_level, Level, LevelError};
use crate::map::validate::validate;
use crate::map::MapError;
use crate::materials::{Materials, MissingArt};
use crate::play::world::Exit;
use crate::texture::Library;
use crate::wad::import::Report;
use crate::wad::library::WadArt;
use crate::wad::{Wad, WadError};

/// One map to open.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum MapRef {
    /// A RON map (sector or grid) or a compiled map file.
    File(PathBuf),
    /// Map `map` of the WADs `wads` read as one, later over earlier (an IWAD
    /// first, then PWADs); `None`: the first map of the last WAD that has any.
    Wad { wads: Vec<PathBuf>, map: Option<String> },
}

/// Why a map or campaign could not be opened.
#[derive(Debug, thiserror::Error)]
pub enum CampaignError {
    #[error(transparent)]
    Level(#[from] LevelError),
    #[error(transparent)]
    Wad(#[from] WadError),
    #[error("{path}: {message}")]
    Campaign { path: String, message: String },
}

impl MapRef {
    /// Map `name` of the same WADs (a Doom demo gone on to its next
    /// level); a file's map has no others and stays itself.
    pub fn in_same_wads(&self, name: &str) -> MapRef {
        match self {
            MapRef::Wad { wads, .. } => MapRef::Wad { wads: wads.clone(), map: Some(name.to_string()) },
            other => other.clone(),
        }
    }

    /// A map as a person names it on the command line: `PATH` (a RON or
    /// compiled map), `WAD` (its first map) or `WAD:MAP`. `iwad` goes under
    /// a WAD (a PWAD needs its IWAD's art). A name is a WAD when it ends in
    /// `.wad` (any case); `WAD:MAP` splits at the last colon.
    pub fn parse(text: &str, iwad: Option<&Path>) -> MapRef {
        let is_wad = |s: &str| s.to_ascii_lowercase().ends_with(".wad");
        let wads = |wad: &str| iwad.map(Path::to_path_buf).into_iter().chain([PathBuf::from(wad)]).collect();
        if is_wad(text) {
            return MapRef::Wad { wads: wads(text), map: None };
        }
        match text.rsplit_once(':') {
            Some((wad, map)) if is_wad(wad) && !map.is_empty() => {
                MapRef::Wad { wads: wads(wad), map: Some(map.to_ascii_uppercase()) }
            }
            _ => MapRef::File(PathBuf::from(text)),
        }
    }

    /// How it is written back: the path, or `WAD:MAP` (with `+` between
    /// stacked WADs, as demos store it).
    pub fn label(&self) -> String {
        match self {
            MapRef::File(path) => path.display().to_string(),
            MapRef::Wad { wads, map } => {
                let wads: Vec<String> = wads.iter().map(|w| w.display().to_string()).collect();
                match map {
                    Some(m) => format!("{}:{m}", wads.join("+")),
                    None => wads.join("+"),
                }
            }
        }
    }

    /// Reads back [`MapRef::label`].
    pub fn from_label(label: &str) -> MapRef {
        match MapRef::parse(label, None) {
            MapRef::Wad { wads, map } => {
                let all =
                    wads.iter().flat_map(|w| w.to_string_lossy().split('+').map(PathBuf::from).collect::<Vec<_>>());
                MapRef::Wad { wads: all.collect(), map }
            }
            file => file,
        }
    }

    /// The map's short name for titles and the HUD: `E1M4`, or the file name.
    pub fn short_name(&self) -> String {
        match self {
            MapRef::Wad { map: Some(m), .. } => m.clone(),
            MapRef::Wad { wads, .. } => wads.last().map(|w| w.display().to_string()).unwrap_or_default(),
            MapRef::File(p) => p.file_name().map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into()),
        }
    }
}

/// A map opened for play, and what its conversion had to say (WAD maps).
#[derive(Clone)]
pub struct Opened {
    pub level: Level,
    /// The map actually opened (a WAD's first map made explicit).
    pub map: MapRef,
    /// The importer's repairs and report, for a map read from a WAD.
    pub repairs: Vec<String>,
    pub report: Option<Report>,
    /// For a WAD map, where its sectors and linedefs went in the converted
    /// map.
    pub links: Option<crate::wad::import::Links>,
    /// For a WAD map, the WADs as one (what the game reads besides the
    /// converted map: a Doom map's lumps, a ZDoom map's scripts), so a game
    /// started again on the same map does not read them again.
    pub wad: Option<Arc<WadArt>>,
}

impl Opened {
    /// A RON level already loaded (a test's map, one made in memory),
    /// as if opened from the file `label`.
    pub fn of_level(level: Level, label: &str) -> Opened {
        let map = MapRef::File(PathBuf::from(label));
        Opened { level, map, repairs: Vec::new(), report: None, links: None, wad: None }
    }
}

/// Where a map's pictures come from, besides its own (PNGs beside a RON
/// map, a WAD map's WADs).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ArtOptions {
    /// WADs, later over earlier (an IWAD, then a PWAD), whose sprites and
    /// textures a RON map's names take after its own PNGs and before the
    /// built-in set (`--iwad`). A WAD map has its own.
    pub wads: Vec<PathBuf>,
    /// What an actor's frame no art has becomes; `None`: a stand-in with
    /// no WAD, a placeholder with one ([`Materials::resolve_in`]).
    pub missing: Option<MissingArt>,
}

impl ArtOptions {
    /// No sprite is looked up: for a command that draws nothing.
    pub fn none() -> ArtOptions {
        ArtOptions { wads: Vec::new(), missing: Some(MissingArt::Skip) }
    }
}

/// Opens `map`: a file as [`open_level`] does; a WAD map converted in
/// memory, validated and compiled with `options`, its art read from the WAD.
pub fn open(map: &MapRef, options: &BuildOptions) -> Result<Opened, CampaignError> {
    open_with(map, options, &ArtOptions::default())
}

/// [`open`] with its pictures from `art`.
pub fn open_with(map: &MapRef, options: &BuildOptions, art: &ArtOptions) -> Result<Opened, CampaignError> {
    let resolve = |compiled: &crate::bsp::CompiledMap, library: &Library, label: &str| {
        let missing =
            art.missing.unwrap_or(if library.wad.is_some() { MissingArt::Placeholder } else { MissingArt::StandIn });
        Materials::resolve_with(&compiled.map, library, label, missing).map_err(LevelError::from)
    };
    match map {
        MapRef::File(path) if !art.wads.is_empty() || art.missing.is_some() => {
            let label = path.display().to_string();
            let compiled = open_compiled(path, options)?;
            let dirs = vec![path.parent().map(Path::to_path_buf).unwrap_or_default()];
            let wad = match &art.wads[..] {
                [] => None,
                wads => Some(Arc::new(WadArt::new(stack(wads)?)?)),
            };
            let materials = resolve(&compiled, &Library { dirs, wad }, &label)?;
            Ok(Opened::of_level(Level::new(compiled, materials), &label))
        }
        MapRef::File(path) => Ok(Opened {
            level: open_level(path, options)?,
            map: map.clone(),
            repairs: Vec::new(),
            report: None,
            links: None,
            wad: None,
        }),
        MapRef::Wad { wads, map: name } => {
            let wad = stack(wads)?;
            let name = match name {
                Some(n) => n.clone(),
                None => wad.map_names().first().cloned().ok_or_else(|| WadError::NoMap {
                    path: wad.path.clone(),
                    name: "(the first map)".into(),
                    available: "none".into(),
                })?,
            };
            let wad_art = Arc::new(WadArt::new(wad)?);
            let records = wad_art.wad.map_records(&name)?;
            let converted = crate::wad::import::convert_records(&wad_art.wad, &records, &wad_art.art)?;
            let label = format!("{}:{name}", wad_art.wad.path);
            let checked = validate(&converted.source)
                .map_err(|problems| LevelError::Map(MapError::Invalid { path: label.clone(), problems }))?;
            let compiled =
                build(&checked, options).map_err(|error| LevelError::Compile { path: label.clone(), error })?;
            let library = Library { dirs: Vec::new(), wad: Some(wad_art.clone()) };
            let materials = resolve(&compiled, &library, &label)?;
            Ok(Opened {
                level: Level::new(compiled, materials),
                map: MapRef::Wad { wads: wads.clone(), map: Some(name) },
                repairs: converted.repairs,
                report: Some(converted.report),
                links: Some(converted.links),
                wad: Some(wad_art),
            })
        }
    }
}

/// The WADs as one, later over earlier.
pub(crate) fn stack(paths: &[PathBuf]) -> Result<Wad, WadError> {
    let dirs = wad_dirs();
    let wads = paths.iter().map(|p| Wad::open(&find_wad(p, &dirs))).collect::<Result<Vec<_>, _>>()?;
    Ok(Wad::stack(wads))
}

/// Where a WAD named without a directory is looked for when it is not in
/// the current one, as Doom ports do: `$DOOMWADDIR`, each directory of
/// `$DOOMWADPATH` (colon-separated), then where Linux packages install
/// IWADs.
pub fn wad_dirs() -> Vec<PathBuf> {
    let mut dirs: Vec<PathBuf> = std::env::var_os("DOOMWADDIR").map(PathBuf::from).into_iter().collect();
    if let Some(path) = std::env::var_os("DOOMWADPATH") {
        dirs.extend(std::env::split_paths(&path));
    }
    dirs.extend(["/usr/local/share/games/doom", "/usr/share/games/doom", "/usr/share/doom"].map(PathBuf::from));
    dirs
}

/// `wad` itself when it exists or names a directory; else the first of
/// `dirs` holding a file of that name; else `wad` (whose error then names
/// it as given).
pub fn find_wad(wad: &Path, dirs: &[PathBuf]) -> PathBuf {
    let bare = wad.parent().is_none_or(|p| p.as_os_str().is_empty());
    if wad.exists() || !bare {
        return wad.to_path_buf();
    }
    dirs.iter().map(|d| d.join(wad)).find(|p| p.is_file()).unwrap_or_else(|| wad.to_path_buf())
}

/// `Campaign(name: "...", maps: [CampaignMap(map: "a.ron"), ...])`: maps
/// in the order they are played. A map's `next` (default: the one after it
/// in the list) follows its exit; its `secret` follows its secret exit
/// (default: as `next`). Paths are relative to the campaign file.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(rename = "Campaign", deny_unknown_fields)]
pub struct CampaignFile {
    pub name: String,
    pub maps: Vec<CampaignMap>,
}

#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(rename = "CampaignMap", deny_unknown_fields)]
pub struct CampaignMap {
    pub map: String,
    #[serde(default)]
    pub next: Option<String>,
    #[serde(default)]
    pub secret: Option<String>,
}

/// What follows what.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Campaign {
    /// One map on its own: nothing follows it.
    Single(MapRef),
    /// A WAD's maps, in Doom's episode order.
    Wad { wads: Vec<PathBuf>, maps: Vec<String> },
    /// A campaign file's maps (paths resolved).
    List { name: String, maps: Vec<(PathBuf, Option<PathBuf>, Option<PathBuf>)> },
}

impl Campaign {
    /// The campaign a command-line map starts: a WAD's episodes, a campaign
    /// file's list, or the lone map.
    pub fn of(map: &MapRef) -> Result<Campaign, CampaignError> {
        match map {
            MapRef::Wad { wads, .. } => Ok(Campaign::Wad { wads: wads.clone(), maps: stack(wads)?.map_names() }),
            MapRef::File(path) if is_campaign_file(path) => Campaign::load(path),
            other => Ok(Campaign::Single(other.clone())),
        }
    }

    /// Reads a campaign file; every map it names must exist.
    pub fn load(path: &Path) -> Result<Campaign, CampaignError> {
        let label = path.display().to_string();
        let bad = |message: String| CampaignError::Campaign { path: label.clone(), message };
        let text = std::fs::read_to_string(path).map_err(|e| bad(format!("cannot read: {e}")))?;
        let file: CampaignFile = ron::Options::default()
            .with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
            .from_str(&text)
            .map_err(|e| bad(format!("{}:{}: {}", e.span.start.line, e.span.start.col, e.code)))?;
        if file.maps.is_empty() {
            return Err(bad("the campaign lists no maps".into()));
        }
        let dir = path.parent().unwrap_or(Path::new(""));
        let resolve = |name: &str, what: String| -> Result<PathBuf, CampaignError> {
            let p = dir.join(name);
            if p.is_file() {
                Ok(p)
            } else {
                Err(bad(format!("{what}: {} does not exist", p.display())))
            }
        };
        let mut maps = Vec::with_capacity(file.maps.len());
        for (i, m) in file.maps.iter().enumerate() {
            let map = resolve(&m.map, format!("map {i}"))?;
            let next = m.next.as_deref().map(|n| resolve(n, format!("map {i} next"))).transpose()?;
            let secret = m.secret.as_deref().map(|n| resolve(n, format!("map {i} secret"))).transpose()?;
            maps.push((map, next, secret));
        }
        Ok(Campaign::List { name: file.name, maps })
    }

    /// The map the campaign starts on, unless the command line named one.
    pub fn first(&self) -> MapRef {
        match self {
            Campaign::Single(m) => m.clone(),
            Campaign::Wad { wads, maps } => MapRef::Wad { wads: wads.clone(), map: maps.first().cloned() },
            Campaign::List { maps, .. } => MapRef::File(maps[0].0.clone()),
        }
    }

    /// The map after `current` ends by `exit`, or `None` when the campaign
    /// (or the episode) is over.
    pub fn next(&self, current: &MapRef, exit: Exit) -> Option<MapRef> {
        match (self, current) {
            (Campaign::Single(_), _) => None,
            (Campaign::Wad { wads, maps }, MapRef::Wad { map: Some(name), .. }) => {
                let next = next_doom_map(name, exit, |m| maps.iter().any(|n| n == m))?;
                Some(MapRef::Wad { wads: wads.clone(), map: Some(next) })
            }
            (Campaign::List { maps, .. }, MapRef::File(path)) => {
                let k = maps.iter().position(|(p, ..)| p == path)?;
                let (_, next, secret) = &maps[k];
                let following = maps.get(k + 1).map(|m| m.0.clone());
                let to = match exit {
                    Exit::Secret => secret.clone().or_else(|| next.clone()).or(following),
                    Exit::Normal => next.clone().or(following),
                };
                to.map(MapRef::File)
            }
            _ => None,
        }
    }
}

/// Is `path` a campaign file (its text starts with `Campaign(`, after
/// comments)? Read cheaply: only the start of the file.
pub fn is_campaign_file(path: &Path) -> bool {
    let Ok(text) = std::fs::read(path) else { return false };
    let text = String::from_utf8_lossy(&text[..text.len().min(4096)]);
    let mut rest = text.trim_start_matches('\u{feff}');
    loop {
        rest = rest.trim_start();
        if let Some(after) = rest.strip_prefix("//") {
            rest = after.split_once('\n').map_or("", |(_, r)| r);
        } else if let Some(after) = rest.strip_prefix("/*") {
            rest = after.split_once("*/").map_or("", |(_, r)| r);
        } else {
            return rest.starts_with("Campaign");
        }
    }
}

/// Doom's order (G_DoCompleted and G_WorldDone): in Doom, ExMy goes to
/// ExM(y+1), ExM8 ends the episode, a secret exit goes to ExM9, and ExM9
/// returns to E1M4, E2M6, E3M7 or E4M3 (the map after each episode's secret
/// exit; E5 on follows E4). In Doom II, MAPnn goes to MAPnn+1 and MAP30 ends
/// the game, MAP15's secret exit goes to MAP31, MAP31's to MAP32, and MAP31
/// and MAP32 return to MAP16. A map the WAD lacks ends the campaign; a
/// secret exit with nowhere secret to go is a normal one.
pub fn next_doom_map(current: &str, exit: Exit, exists: impl Fn(&str) -> bool) -> Option<String> {
    let next = match doom_map_number(current)? {
        (Some(e), m) => match (m, exit) {
            (9, _) => format!("E{e}M{}", [4, 6, 7, 3].get(e.wrapping_sub(1) as usize).copied().unwrap_or(3)),
            (_, Exit::Secret) if exists(&format!("E{e}M9")) => format!("E{e}M9"),
            (8, _) => return None,
            (m, _) => format!("E{e}M{}", m + 1),
        },
        (None, n) => match (n, exit) {
            (15, Exit::Secret) if exists("MAP31") => "MAP31".into(),
            (31, Exit::Secret) if exists("MAP32") => "MAP32".into(),
            (31 | 32, _) => "MAP16".into(),
            (30, _) => return None,
            (n, _) => format!("MAP{:02}", n + 1),
        },
    };
    exists(&next).then_some(next)
}

/// A Doom map's numbers from its name (any case): `(Some(episode), map)`
/// for ExMy, `(None, map)` for MAPnn, `None` for any other name.
pub fn doom_map_number(name: &str) -> Option<(Option<u32>, u32)> {
    let name = name.to_ascii_uppercase();
    let b = name.as_bytes();
    if b.len() == 4 && b[0] == b'E' && b[2] == b'M' && b[1].is_ascii_digit() && b[3].is_ascii_digit() {
        return Some((Some(u32::from(b[1] - b'0')), u32::from(b[3] - b'0')));
    }
    Some((None, name.strip_prefix("MAP")?.parse().ok()?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bare_wad_name_is_looked_for_in_the_wad_directories() {
        let dir = tempfile::tempdir().unwrap();
        let (empty, full) = (dir.path().join("empty"), dir.path().join("full"));
        std::fs::create_dir_all(&empty).unwrap();
        std::fs::create_dir_all(&full).unwrap();
        std::fs::write(full.join("only-here.wad"), b"IWAD").unwrap();
        let dirs = [empty.clone(), full.clone()];
        let find = |name: &str| find_wad(Path::new(name), &dirs);
        assert_eq!(find("only-here.wad"), full.join("only-here.wad"));
        // Not found anywhere, or named with a directory: as given.
        assert_eq!(find("nowhere.wad"), PathBuf::from("nowhere.wad"));
        let with_dir = empty.join("only-here.wad");
        assert_eq!(find_wad(&with_dir, &dirs), with_dir);
    }

    #[test]
    fn doom_order() {
        let all = |_: &str| true;
        let next = |m: &str, e| next_doom_map(m, e, all);
        assert_eq!(next("E1M1", Exit::Normal).as_deref(), Some("E1M2"));
        assert_eq!(next("E1M3", Exit::Secret).as_deref(), Some("E1M9"));
        assert_eq!(next("E1M9", Exit::Normal).as_deref(), Some("E1M4"));
        assert_eq!(next("E2M9", Exit::Normal).as_deref(), Some("E2M6"));
        assert_eq!(next("E3M9", Exit::Secret).as_deref(), Some("E3M7"));
        assert_eq!(next("E4M9", Exit::Normal).as_deref(), Some("E4M3"));
        assert_eq!(next("E1M8", Exit::Normal), None);
        assert_eq!(next("MAP01", Exit::Normal).as_deref(), Some("MAP02"));
        assert_eq!(next("MAP15", Exit::Secret).as_deref(), Some("MAP31"));
        assert_eq!(next("MAP31", Exit::Secret).as_deref(), Some("MAP32"));
        assert_eq!(next("MAP31", Exit::Normal).as_deref(), Some("MAP16"));
        assert_eq!(next("MAP32", Exit::Normal).as_deref(), Some("MAP16"));
        assert_eq!(next("MAP30", Exit::Normal), None);
        // A secret exit with no secret map is a normal exit; a missing next map ends it.
        assert_eq!(next_doom_map("MAP15", Exit::Secret, |m| m != "MAP31").as_deref(), Some("MAP16"));
        assert_eq!(next_doom_map("MAP07", Exit::Normal, |m| m != "MAP08"), None);
    }

    #[test]
    fn map_refs_parse_and_print() {
        assert_eq!(MapRef::parse("maps/a.ron", None), MapRef::File("maps/a.ron".into()));
        let wad = MapRef::parse("freedoom1.wad:e1m4", None);
        assert_eq!(wad, MapRef::Wad { wads: vec!["freedoom1.wad".into()], map: Some("E1M4".into()) });
        assert_eq!(wad.label(), "freedoom1.wad:E1M4");
        let pwad = MapRef::parse("my.WAD:MAP01", Some(Path::new("freedoom2.wad")));
        assert_eq!(pwad.label(), "freedoom2.wad+my.WAD:MAP01");
        assert_eq!(MapRef::from_label(&pwad.label()), pwad);
        assert_eq!(MapRef::parse("doom2.wad", None), MapRef::Wad { wads: vec!["doom2.wad".into()], map: None });
    }
}
