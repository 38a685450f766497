//! `sightline play` and `sightline replay` through the binary, headless: the
//! replay of a scripted demo is the same twice (position line and every
//! captured PNG, byte for byte) and moves the player; the window refuses
//! cleanly without a display, naming `sightline capture`; a bad map, a bad
//! demo and a demo naming a missing map get their errors, never a panic.
//! (The window itself is tested in a real one by `.ci/window-test`.)

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use sightline::play::{Demo, TickInput};

fn shipped_map(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("maps").join(name)
}

/// Runs `sightline args...` in `dir` with no display to reach.
fn sightline(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_sightline"))
        .args(args)
        .current_dir(dir)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .env("RUST_BACKTRACE", "0")
        .output()
        .expect("the binary runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Exit status 1 with every one of `mentions` in stderr and no panic.
fn assert_refused(out: &Output, mentions: &[&str]) {
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "stderr: {stderr}");
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    for m in mentions {
        assert!(stderr.contains(m), "`{m}` not in: {stderr}");
    }
}

/// Two seconds forward, a second turning while strafing, one running back.
fn scripted_walk() -> Vec<TickInput> {
    let mut inputs = vec![TickInput { forward: 1, ..Default::default() }; 70];
    inputs.extend([TickInput { strafe: 1, turn: 3.5, ..Default::default() }; 35]);
    inputs.extend([TickInput { forward: -1, run: true, ..Default::default() }; 35]);
    inputs
}

fn write_demo(dir: &Path, map: &Path, inputs: Vec<TickInput>) -> PathBuf {
    let path = dir.join("walk.sldemo");
    Demo { inputs, ..Demo::new(map.display().to_string()) }.save(&path).expect("demo written");
    path
}

/// Every file in `dir`, sorted, with its bytes.
fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out: Vec<_> = std::fs::read_dir(dir)
        .expect("read_dir")
        .map(|e| {
            let path = e.expect("entry").path();
            (path.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read(&path).expect("read"))
        })
        .collect();
    out.sort();
    out
}

#[test]
fn replay_is_the_same_every_time_and_moves_the_player() {
    let dir = tempfile::tempdir().unwrap();
    let demo = write_demo(dir.path(), &shipped_map("pillars.ron"), scripted_walk());
    let demo = demo.to_str().unwrap();
    let mut runs = Vec::new();
    for out_dir in ["a", "b"] {
        let out = sightline(dir.path(), &["replay", demo, "--capture-every", "35", "-o", out_dir, "--size", "160x100"]);
        assert!(out.status.success(), "stderr: {}", text(&out.stderr));
        let last = text(&out.stdout).lines().last().unwrap_or_default().to_string();
        runs.push((last, files(&dir.path().join(out_dir))));
    }
    assert_eq!(runs[0], runs[1], "two replays of one demo differ");
    let (last, frames) = &runs[0];
    let names: Vec<&str> = frames.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["tick-000000.png", "tick-000035.png", "tick-000070.png", "tick-000105.png", "tick-000140.png"]);
    assert_ne!(frames[0].1, frames[4].1, "the view did not change");
    assert!(last.starts_with("tick 140: x "), "final line: {last}");

    // Without -o nothing is written and the same position is printed.
    let out = sightline(dir.path(), &["replay", demo]);
    assert_eq!(text(&out.stdout).lines().last(), Some(last.as_str()));
}

#[test]
fn no_display_is_an_error_that_points_to_capture() {
    let dir = tempfile::tempdir().unwrap();
    let map = shipped_map("room.ron");
    for args in [vec!["play", map.to_str().unwrap()], vec![map.to_str().unwrap()], vec![]] {
        let out = sightline(dir.path(), &args);
        assert_refused(&out, &["no display", "sightline capture"]);
    }
    // A display that is named but not there.
    let out = Command::new(env!("CARGO_BIN_EXE_sightline"))
        .args(["play", map.to_str().unwrap()])
        .env("DISPLAY", ":7919")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("the binary runs");
    assert_refused(&out, &["sightline capture"]);
}

#[test]
fn bad_maps_and_demos_get_their_errors() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.ron"), "Map(name: \"x\", vertices: [(0.0, 0.0)").unwrap();
    // The map's error comes before any window is tried.
    assert_refused(&sightline(dir.path(), &["play", "bad.ron"]), &["bad.ron"]);
    assert_refused(&sightline(dir.path(), &["play", "missing.ron"]), &["missing.ron"]);

    std::fs::write(dir.path().join("junk.sldemo"), b"not a demo").unwrap();
    assert_refused(&sightline(dir.path(), &["replay", "junk.sldemo"]), &["junk.sldemo"]);
    assert_refused(&sightline(dir.path(), &["play", "--demo", "junk.sldemo"]), &["junk.sldemo"]);
    assert_refused(&sightline(dir.path(), &["replay", "none.sldemo"]), &["none.sldemo"]);

    let demo = write_demo(dir.path(), Path::new("gone.ron"), scripted_walk());
    assert_refused(&sightline(dir.path(), &["replay", demo.to_str().unwrap()]), &["gone.ron"]);
    // ... unless told which map to use.
    let room = shipped_map("room.ron");
    let out = sightline(dir.path(), &["replay", demo.to_str().unwrap(), "--map", room.to_str().unwrap()]);
    assert!(out.status.success(), "stderr: {}", text(&out.stderr));

    // The ray-caster on a sector map.
    let out = sightline(
        dir.path(),
        &["replay", demo.to_str().unwrap(), "--map", room.to_str().unwrap(), "--renderer", "raycast"],
    );
    assert_refused(&out, &["raycast", "grid"]);
    // Recording and playing a demo at once makes no sense.
    let out = sightline(dir.path(), &["play", "--demo", "a", "--record", "b"]);
    assert_eq!(out.status.code(), Some(2), "stderr: {}", text(&out.stderr));
}

/// `--actors FILE` reaches map checking and play: a map naming an actor
/// only the user's file defines loads with it and is refused without it; a
/// broken file is an error naming it.
#[test]
fn a_user_actor_file_is_used_by_commands_that_play() {
    let dir = tempfile::tempdir().unwrap();
    let user = shipped_map("../tests/actors/user.ron");
    let room = std::fs::read_to_string(shipped_map("../tests/maps/monsters.ron")).unwrap();
    // The monsters' room with a sturdy zombieman by the player start.
    let start = room.find("Thing(kind: \"player_start\"").expect("monsters.ron has a player start");
    let mut map = room.clone();
    map.insert_str(start, "Thing(kind: \"sturdy_zombieman\", x: 200.0, y: 256.0),\n        ");
    std::fs::write(dir.path().join("sturdy.ron"), &map).unwrap();
    let demo = write_demo(dir.path(), &dir.path().join("sturdy.ron"), scripted_walk());
    let replay = |extra: &[&str]| {
        let mut args = vec!["replay", demo.to_str().unwrap()];
        args.extend_from_slice(extra);
        sightline(dir.path(), &args)
    };
    assert_refused(&replay(&[]), &["sturdy_zombieman"]);
    let out = replay(&["--actors", user.to_str().unwrap()]);
    assert!(out.status.success(), "stderr: {}", text(&out.stderr));
    std::fs::write(dir.path().join("broken.ron"), "Actors(actors: [Actor(name: \"a\", based_on: \"impp\")])").unwrap();
    let broken = dir.path().join("broken.ron");
    assert_refused(&replay(&["--actors", broken.to_str().unwrap()]), &["broken.ron", "impp"]);
}

#[test]
fn play_load_continues_a_saved_game_or_names_the_bad_save() {
    use sightline::campaign::MapRef;
    use sightline::play::playthrough::Playthrough;
    use sightline::play::GameOptions;

    let dir = tempfile::tempdir().unwrap();
    let mut play = Playthrough::of(&MapRef::File(shipped_map("room.ron")), GameOptions::default()).unwrap();
    for input in scripted_walk() {
        play.tick(&input).unwrap();
    }
    let save = dir.path().join("room.slsave");
    play.save(&save).unwrap();
    // A good save loads, and only then is the window tried (there is no display here).
    let out = sightline(dir.path(), &["play", "--load", "room.slsave"]);
    assert_refused(&out, &["no display"]);
    // A bad or missing save is refused before any window, naming the file.
    std::fs::write(dir.path().join("junk.slsave"), b"not a save").unwrap();
    assert_refused(
        &sightline(dir.path(), &["play", "--load", "junk.slsave"]),
        &["junk.slsave", "not a Sightline saved game"],
    );
    let mut cut = std::fs::read(&save).unwrap();
    cut.truncate(cut.len() / 2);
    std::fs::write(dir.path().join("cut.slsave"), cut).unwrap();
    assert_refused(&sightline(dir.path(), &["play", "--load", "cut.slsave"]), &["cut.slsave", "truncated"]);
    assert_refused(&sightline(dir.path(), &["play", "--load", "gone.slsave"]), &["gone.slsave"]);
    // A save continues a game: it does not go with a map, a demo or a recording.
    let room = shipped_map("room.ron");
    for other in [vec![room.to_str().unwrap()], vec!["--demo", "a.sldemo"], vec!["--record", "b.sldemo"]] {
        let mut args = vec!["play", "--load", "room.slsave"];
        args.extend(other);
        let out = sightline(dir.path(), &args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", text(&out.stderr));
        assert!(text(&out.stderr).contains("cannot be used with"), "{}", text(&out.stderr));
    }
}

#[test]
fn replay_audio_writes_the_same_wav_every_time_with_sound_where_the_game_made_it() {
    let dir = tempfile::tempdir().unwrap();
    // Fire the pistol now and then while walking about the default level.
    let mut inputs = scripted_walk();
    for (i, input) in inputs.iter_mut().enumerate() {
        input.fire = i % 40 < 3;
    }
    let demo = write_demo(dir.path(), &shipped_map("outpost.ron"), inputs);
    let demo = demo.to_str().unwrap();
    let wav = |name: &str| {
        let out = sightline(dir.path(), &["replay", demo, "--audio", name, "--no-music"]);
        assert!(out.status.success(), "stderr: {}", text(&out.stderr));
        assert!(text(&out.stdout).contains(&format!("of audio to {name}")), "{}", text(&out.stdout));
        std::fs::read(dir.path().join(name)).unwrap()
    };
    let (a, b) = (wav("a.wav"), wav("b.wav"));
    assert!(a == b, "two renders of one demo differ");
    // 16-bit stereo at 44,100 Hz, 1,260 frames a tick: 140 ticks.
    assert_eq!(&a[..4], b"RIFF");
    assert_eq!(&a[8..16], b"WAVEfmt ");
    assert_eq!(u32::from_le_bytes(a[24..28].try_into().unwrap()), 44_100);
    assert_eq!(a.len(), 44 + 140 * 1260 * 4);
    let samples: Vec<i16> = a[44..].chunks_exact(2).map(|b| i16::from_le_bytes([b[0], b[1]])).collect();
    let loud = |tick: usize| samples[tick * 2520..(tick + 1) * 2520].iter().any(|&v| v.unsigned_abs() > 1000);
    // The first shot (pressed on tick 1; the pistol fires a few ticks into its attack) is heard.
    assert!((1..12).any(loud), "the first shot is not heard");
    // A file that cannot be written is an error naming it.
    let out = sightline(dir.path(), &["replay", demo, "--audio", "no/such/dir/x.wav", "--no-music"]);
    assert_refused(&out, &["x.wav"]);
}
