//! What the benchmarks share: the shipped maps, Freedoom's WADs, which
//! studies to run, medians.

use std::path::PathBuf;

/// Every shipped `.ron` map, sorted.
#[allow(dead_code)]
pub fn shipped_maps() -> Vec<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../maps");
    let mut maps: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("maps directory")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .collect();
    maps.sort();
    maps
}

/// Which studies to run: Criterion's filter (its first positional
/// argument) and `--test` (one short round), honoured by the custom loops
/// too.
#[allow(dead_code)]
pub struct Wanted {
    filter: Option<String>,
    pub quick: bool,
}

#[allow(dead_code)]
impl Wanted {
    pub fn from_args() -> Wanted {
        let args: Vec<String> = std::env::args().skip(1).collect();
        let filter = args.iter().find(|a| !a.starts_with('-')).cloned();
        Wanted { filter, quick: args.iter().any(|a| a == "--test") }
    }

    /// Whether the study `name` runs: no filter, or one that is part of the
    /// name or contains it.
    pub fn wants(&self, name: &str) -> bool {
        self.filter.as_deref().is_none_or(|f| name.contains(f) || f.contains(name))
    }
}

/// Where Freedoom's WADs are (as the tests look): `$SIGHTLINE_DOOM_DIR`,
/// else Debian's directory.
#[allow(dead_code)]
pub fn doom_dir() -> PathBuf {
    std::env::var_os("SIGHTLINE_DOOM_DIR").map_or_else(|| PathBuf::from("/usr/share/games/doom"), PathBuf::from)
}

/// Opens the IWAD `file` of [`doom_dir`], or says how to get it.
#[allow(dead_code)]
pub fn open_wad(file: &str) -> (PathBuf, sightline::wad::Wad) {
    let path = doom_dir().join(file);
    let wad = sightline::wad::Wad::open(&path).unwrap_or_else(|e| {
        panic!("{e}\nthis bench needs Freedoom (apt-get install freedoom) or SIGHTLINE_DOOM_DIR=dir")
    });
    (path, wad)
}

/// `wad`'s art as a texture library, for `Materials::resolve_in`.
#[allow(dead_code)]
pub fn wad_library(wad: sightline::wad::Wad) -> sightline::texture::Library {
    use sightline::wad::{library::WadArt, Wad};
    let art = WadArt::new(Wad::stack(vec![wad])).unwrap_or_else(|e| panic!("{e}"));
    sightline::texture::Library { dirs: Vec::new(), wad: Some(std::sync::Arc::new(art)) }
}

/// The median of `values` (sorted in place).
#[allow(dead_code)]
pub fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n.is_multiple_of(2) {
        (values[n / 2 - 1] + values[n / 2]) / 2.0
    } else {
        values[n / 2]
    }
}

/// The smallest and largest of `values`.
#[allow(dead_code)]
pub fn extent(values: &[f64]) -> (f64, f64) {
    values.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &x| (lo.min(x), hi.max(x)))
}
