//! `sightline bench --quick --out DIR` through the binary: the visibility
//! study's figures in results.json meet the checks (front to back
//! writes each pixel exactly once; painter's writes more on the maze).
//!
//! Ignored until `sightline bench [MAP...] --out DIR` is on the command line
//! (being wired on main next to `bench tour`); tests/visibility.rs makes the
//! same checks by calling the study directly.

use std::path::Path;
use std::process::Command;

#[test]
#[ignore = "needs `sightline bench [MAP...] --out DIR` on the command line"]
fn visibility_study_overdraw() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let out = Command::new(env!("CARGO_BIN_EXE_sightline"))
        .args(["bench", "maps/maze.ron", "maps/room.ron", "--quick", "--size", "160x100", "--out"])
        .arg(dir.path())
        .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join(".."))
        .output()
        .expect("the binary runs");
    assert!(out.status.success(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(dir.path().join("results.json")).expect("results.json");
    let studies: serde_json::Value = serde_json::from_str(&text).expect("results.json is JSON");
    let study = studies
        .as_array()
        .and_then(|s| s.iter().find(|s| s["id"] == "visibility"))
        .unwrap_or_else(|| panic!("no visibility study in {text}"));
    let table = &study["tables"][0];
    let columns: Vec<&str> = table["columns"].as_array().expect("columns").iter().filter_map(|c| c.as_str()).collect();
    let col = |name: &str| columns.iter().position(|c| *c == name).unwrap_or_else(|| panic!("no column {name}"));
    let (map, renderer, overdraw) = (col("map"), col("renderer"), col("overdraw"));
    let rows = table["rows"].as_array().expect("rows");
    let value = |map_name: &str, r: &str| {
        rows.iter()
            .find(|row| row[map] == map_name && row[renderer] == r)
            .and_then(|row| row[overdraw].as_f64())
            .unwrap_or_else(|| panic!("no {map_name} {r} row"))
    };
    for m in ["maze", "room"] {
        assert_eq!(value(m, "bsp"), 1.0, "{m}: front to back writes each pixel exactly once");
    }
    assert!(value("maze", "painter") > 1.0, "painter's overdraws on the maze");
}
