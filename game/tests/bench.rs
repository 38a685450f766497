//! `sightline bench tour` through the binary: it runs from the repository
//! root on a shipped map and its last line of stdout is one JSON object with
//! the figures a script reads; without `--json` there is no JSON line.

use std::path::Path;
use std::process::{Command, Output};

fn sightline(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_sightline"))
        .args(args)
        .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join(".."))
        .env("RUST_BACKTRACE", "0")
        .output()
        .expect("the binary runs")
}

fn stdout_of(out: &Output) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "exit {:?}, stderr: {stderr}", out.status.code());
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn bench_tour_ends_with_a_json_line() {
    let out = sightline(&["bench", "tour", "maps/pillars.ron", "--size", "64x40", "--repeat", "1", "--json"]);
    let stdout = stdout_of(&out);
    let last = stdout.lines().last().expect("some output");
    let json: serde_json::Value = serde_json::from_str(last).unwrap_or_else(|e| panic!("{e}: {last}"));
    // pillars.ron has 8 things, the player start among them: 1 + 8 * 8 poses.
    assert_eq!(json["frames"], 65, "{json}");
    assert_eq!(json["size"], "64x40");
    assert_eq!(json["renderer"], "bsp");
    assert_eq!(json["map"], "maps/pillars.ron");
    for key in ["median_ms", "p95_ms", "mean_ms", "fps_median"] {
        let v = json[key].as_f64().unwrap_or_else(|| panic!("{key} missing: {json}"));
        assert!(v.is_finite() && v > 0.0, "{key} = {v}");
    }
    assert!(json["p95_ms"].as_f64() >= json["median_ms"].as_f64());
    // The breakdown: every part, none negative, the walls and the copy there.
    let parts = ["setup", "walk", "walls", "spans", "masked", "copy"];
    for part in parts {
        let v = json["breakdown"][format!("{part}_ms")].as_f64().unwrap_or_else(|| panic!("{part} missing: {json}"));
        assert!(v.is_finite() && v >= 0.0, "{part} = {v}");
    }
    assert!(json["breakdown"]["walls_ms"].as_f64() > Some(0.0), "{json}");
    assert!(json["breakdown"]["copy_ms"].as_f64() > Some(0.0), "{json}");
    assert!(json["profiled_mean_ms"].as_f64() > Some(0.0), "{json}");
}

#[test]
fn bench_tour_without_json_prints_only_the_table() {
    let out = sightline(&["bench", "tour", "maps/room.ron", "--size", "32x20", "--repeat", "1"]);
    let stdout = stdout_of(&out);
    assert!(stdout.contains("median"), "{stdout}");
    assert!(stdout.contains("breakdown") && stdout.contains("walls"), "{stdout}");
    assert!(!stdout.contains('{'), "{stdout}");
}

#[test]
fn bench_tour_refuses_a_missing_map() {
    let out = sightline(&["bench", "tour", "maps/no-such-map.ron", "--repeat", "1"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no-such-map.ron"));
}

/// `--buffers` with a list times every variant in one run: the JSON's top
/// level is the first one's, and `variants` holds each, named.
#[test]
fn bench_tour_times_each_buffers_variant() {
    let args = ["bench", "tour", "maps/pillars.ron", "--size", "64x40", "--repeat", "1", "--json"];
    let out = sightline(&[&args[..], &["--buffers", "off,depth,labels,both"]].concat());
    let stdout = stdout_of(&out);
    let json: serde_json::Value = serde_json::from_str(stdout.lines().last().unwrap_or_default()).unwrap();
    assert_eq!(json["buffers"], "off", "{json}");
    let variants = json["variants"].as_array().unwrap_or_else(|| panic!("no variants: {json}"));
    let names: Vec<_> = variants.iter().map(|v| v["buffers"].as_str().unwrap_or_default()).collect();
    assert_eq!(names, ["off", "depth", "labels", "both"]);
    for v in variants {
        assert_eq!(v["frames"], 65, "{v}");
        assert!(v["median_ms"].as_f64() > Some(0.0), "{v}");
    }
    let bad = sightline(&["bench", "tour", "maps/room.ron", "--buffers", "colour"]);
    assert_eq!(bad.status.code(), Some(2));
}
