//! `sightline autoplay` and `sightline check` through the binary: the JSON
//! outcome has the fields the issue names, a recorded run replays to the
//! position autoplay ended at, captured frames are written, `check` reports
//! as text and JSON and draws its plan, and bad input is refused cleanly.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn repo(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(rel)
}

fn sightline(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_sightline"))
        .args(args)
        .current_dir(dir)
        .env("RUST_BACKTRACE", "0")
        .output()
        .expect("the binary runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn autoplay_reports_json_and_its_recording_replays_to_the_same_place() {
    let dir = tempfile::tempdir().unwrap();
    let map = repo("tests/maps/autopilot_key_door.ron");
    let map = map.to_str().unwrap();
    let out = sightline(
        dir.path(),
        &["autoplay", map, "--json", "--record", "run.sldemo", "--capture-every", "50", "-o", "frames"],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let json: serde_json::Value = serde_json::from_str(text(&out.stdout).trim()).expect("one JSON object");
    assert_eq!(json["exited"], true, "{json}");
    for key in ["map", "ticks", "kills", "items", "secrets"] {
        assert!(!json[key].is_null(), "no {key} in {json}");
    }
    assert!(json["kills"]["found"].is_u64() && json["kills"]["total"].is_u64(), "{json}");
    assert!(json["secrets"]["found"].is_u64() && json["secrets"]["total"].is_u64(), "{json}");
    let ticks = json["ticks"].as_u64().unwrap();
    assert!(ticks > 0);
    let frames = std::fs::read_dir(dir.path().join("frames")).unwrap().count();
    assert_eq!(frames as u64, 1 + ticks / 50 + u64::from(ticks % 50 != 0), "tick 0, every 50th and the last");

    let replay = sightline(dir.path(), &["replay", "run.sldemo"]);
    assert!(replay.status.success(), "{}", text(&replay.stderr));
    let last = text(&replay.stdout).lines().last().unwrap_or_default().to_string();
    let (x, y) = (json["position"][0].as_f64().unwrap(), json["position"][1].as_f64().unwrap());
    assert!(
        last.starts_with(&format!("tick {ticks}: x {x:?} y {y:?} ")),
        "replay ended at `{last}`, autoplay at {x:?}, {y:?}"
    );
}

#[test]
fn check_reports_as_text_and_json_and_draws_its_plan() {
    let dir = tempfile::tempdir().unwrap();
    let map = repo("tests/maps/autopilot_flawed.ron");
    let map = map.to_str().unwrap();
    let out = sightline(dir.path(), &["check", map, "-o", "plan.png", "--partitions"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let report = text(&out.stdout);
    assert!(report.contains("the exit is reachable"), "{report}");
    assert!(report.contains("secret sector 1") && report.contains("NOT reachable"), "{report}");
    assert!(report.contains("soft lock"), "{report}");
    let png = std::fs::read(dir.path().join("plan.png")).unwrap();
    assert!(png.starts_with(b"\x89PNG"));

    let out = sightline(dir.path(), &["check", map, "--json"]);
    let json: serde_json::Value = serde_json::from_str(text(&out.stdout).trim()).expect("one JSON object");
    assert_eq!(json["exit_reachable"], true);
    assert_eq!(json["secrets"][0]["reachable"], false);
    assert!(!json["soft_locks"].as_array().unwrap().is_empty(), "{json}");
}

#[test]
fn autoplay_and_check_refuse_bad_input_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("broken.ron"), "Map(version: 2, name: \"x\", vertices: [").unwrap();
    for args in [
        vec!["autoplay", "broken.ron"],
        vec!["check", "broken.ron"],
        vec!["autoplay", "missing.ron"],
        vec!["check", "nowhere.wad:E1M1"],
    ] {
        let out = sightline(dir.path(), &args);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(stderr.contains(args[1]), "{args:?}: the error does not name the file: {stderr}");
    }
    // An existing plan is not clobbered when the map cannot be read.
    std::fs::write(dir.path().join("plan.png"), b"keep").unwrap();
    let out = sightline(dir.path(), &["check", "broken.ron", "-o", "plan.png"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(std::fs::read(dir.path().join("plan.png")).unwrap(), b"keep");
}
