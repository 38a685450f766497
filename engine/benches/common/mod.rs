//! What the benchmarks share: the shipped maps.

use std::path::PathBuf;

/// Every shipped `.ron` map, sorted.
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
