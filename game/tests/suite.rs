//! `sightline bench --quick`: the study suite CI runs, checked for sane
//! numbers, not for speed (timings are in the report, never asserted).

use std::path::Path;
use std::process::Command;

use serde_json::Value;

fn run_quick() -> (Value, String, tempfile::TempDir) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let out = tempfile::tempdir().unwrap();
    let doc = out.path().join("doc.md");
    let status = Command::new(env!("CARGO_BIN_EXE_sightline"))
        .current_dir(&root)
        .args(["bench", "--quick", "--out"])
        .arg(out.path().join("report"))
        .arg("--doc")
        .arg(&doc)
        .status()
        .unwrap();
    assert!(status.success(), "bench --quick failed");
    let dir = out.path().join("report");
    let json: Value = serde_json::from_str(&std::fs::read_to_string(dir.join("results.json")).unwrap()).unwrap();
    let report = std::fs::read_to_string(dir.join("report.md")).unwrap();
    assert_eq!(std::fs::read_to_string(&doc).unwrap().lines().next(), report.lines().next());
    (json, report, out)
}

fn study<'a>(json: &'a Value, id: &str) -> &'a Value {
    json.as_array().unwrap().iter().find(|s| s["id"] == id).unwrap_or_else(|| panic!("no study {id}"))
}

/// The rows of table `name` in `study` as maps from column to value.
fn rows(study: &Value, name: &str) -> Vec<std::collections::HashMap<String, Value>> {
    let table = study["tables"].as_array().unwrap().iter().find(|t| t["name"] == name).unwrap();
    let columns: Vec<String> =
        table["columns"].as_array().unwrap().iter().map(|c| c.as_str().unwrap().to_string()).collect();
    table["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| columns.iter().cloned().zip(r.as_array().unwrap().iter().cloned()).collect())
        .collect()
}

#[test]
fn quick_bench_reports_every_study_with_sane_numbers() {
    let (json, report, out) = run_quick();
    for id in ["visibility", "rays", "bsp", "precision", "sampling"] {
        let s = study(&json, id);
        assert!(!s["conclusions"].as_array().unwrap().is_empty(), "{id} draws no conclusion");
        for plot in s["plots"].as_array().unwrap() {
            let svg = out.path().join("report").join(format!("{}.svg", plot["name"].as_str().unwrap()));
            let text = std::fs::read_to_string(&svg).unwrap_or_else(|e| panic!("{}: {e}", svg.display()));
            assert!(text.contains("<svg") && text.contains("polyline"), "{} is not a line chart", svg.display());
            assert!(report.contains(&format!("{}.svg", plot["name"].as_str().unwrap())));
        }
    }
    // Precision: f64 relative to the eye agrees with the exact answer at
    // every distance, out to 1e7; f32 absolute does not, that far out.
    let precision = rows(study(&json, "precision"), "precision-summary");
    for r in &precision {
        let wrong = r["disagreeing columns (%)"].as_f64().unwrap();
        match r["numbers"].as_str().unwrap() {
            "f64 relative (default)" => assert_eq!(wrong, 0.0, "{r:?}"),
            "f32 absolute" if r["offset"].as_f64().unwrap() >= 1e7 => assert!(wrong > 0.0, "{r:?}"),
            _ => {}
        }
    }
    // Rays: the exact DDA is never wrong; marching with the largest step is.
    let rays = rows(study(&json, "rays"), "rays");
    assert!(rays.iter().filter(|r| r["method"] == "dda").all(|r| r["wrong share"].as_f64() == Some(0.0)));
    let coarsest = rays
        .iter()
        .filter(|r| r["method"] == "march")
        .max_by(|a, b| a["parameter (cells)"].as_f64().unwrap().total_cmp(&b["parameter (cells)"].as_f64().unwrap()))
        .expect("march rows");
    assert!(coarsest["wrong share"].as_f64().unwrap() > 0.0, "{coarsest:?}");
    // Visibility (issue 7): front to back writes each pixel exactly once on
    // every map; painter's writes some more than once on the maze; the
    // overwriting renderers still draw the reference's picture.
    let visibility = rows(study(&json, "visibility"), "visibility");
    assert!(visibility.len() >= 4 * 5, "{} rows", visibility.len());
    for r in &visibility {
        let overdraw = r["overdraw"].as_f64().unwrap();
        match r["renderer"].as_str().unwrap() {
            "bsp" => assert_eq!(overdraw, 1.0, "{r:?}"),
            "painter" if r["map"] == "maze" => assert!(overdraw > 1.0, "{r:?}"),
            "painter" | "zbuffer" => assert!(overdraw >= 1.0, "{r:?}"),
            _ => {}
        }
        if r["renderer"] != "reference" {
            assert!(r["agreement"].as_f64().unwrap() > 0.99, "{r:?}");
        }
    }
    assert!(visibility.iter().any(|r| r["map"] == "maze" && r["renderer"] == "painter"), "no maze row");
}

#[test]
fn quick_bench_bsp_and_sampling_numbers_are_sane() {
    let (json, _, _out) = run_quick();
    // The exhaustive search is never beaten on the maps it can search.
    let bsp = rows(study(&json, "bsp"), "bsp");
    let maps: std::collections::BTreeSet<String> =
        bsp.iter().filter(|r| r["splitter"] == "exhaustive").map(|r| r["map"].as_str().unwrap().to_string()).collect();
    assert!(!maps.is_empty(), "no map was searched exhaustively");
    for map in &maps {
        let out = |r: &std::collections::HashMap<String, Value>| r["sides out"].as_f64().unwrap();
        let best = bsp.iter().find(|r| r["map"] == map.as_str() && r["splitter"] == "exhaustive").map(out).unwrap();
        assert!(bsp.iter().filter(|r| r["map"] == map.as_str()).all(|r| out(r) >= best), "{map}");
    }
    // Sampling: the default differs from itself nowhere; bilinear and affine
    // change the picture.
    let sampling = rows(study(&json, "sampling"), "sampling-summary");
    let differing =
        |name: &str| sampling.iter().find(|r| r["sampling"] == name).unwrap()["pixels differing (%)"].as_f64().unwrap();
    assert_eq!(differing("nearest, spans (default)"), 0.0);
    assert!(differing("bilinear") > 1.0 && differing("affine planes") > 1.0);
}
