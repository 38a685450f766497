//! Bad input through the binary: every bad argument or file makes `sightline`
//! exit non-zero with a message naming the argument or file, never a panic, and
//! leaves the files it was pointed at exactly as they were.
//!
//! Each failure row runs in a fresh directory holding a set of fixture files
//! (see [`Scene`]); the whole directory is snapshotted before and compared
//! after, so "output not created", "existing output byte-identical", "input
//! untouched" and "no temporary file left behind" are one check.

use std::collections::BTreeMap;
use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::Command;

use sightline::bsp::{build, file, BuildOptions};
use sightline::map::parse_map;

/// Bytes of the existing output file every failing command must leave alone.
const PRECIOUS: &[u8] = b"precious bytes: not a PNG, not a map\n";

fn shipped_map(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("maps").join(name)
}

fn two_rooms() -> String {
    std::fs::read_to_string(shipped_map("two_rooms.ron")).expect("shipped map")
}

fn edit(text: &str, from: &str, to: &str) -> String {
    assert_eq!(text.matches(from).count(), 1, "edit target `{from}`");
    text.replacen(from, to, 1)
}

/// A compiled two_rooms, made through the library.
fn compiled_two_rooms() -> Vec<u8> {
    let map = parse_map(&two_rooms(), "two_rooms.ron").expect("valid");
    file::to_bytes(&build(&map, &BuildOptions::default()).expect("compiles"))
}

/// A temporary working directory with fixtures:
/// - `map.ron`: two_rooms; `bad.ron`: a missing comma on line 5, column 34;
///   `invalid.ron`: line 3 refers to vertex 99; `empty.ron`; `binary.ron`;
/// - `compiled.slbsp`: two_rooms compiled; `half.slbsp`: its first half;
/// - `dir.ron/`: a directory; `sub/`: an empty directory; `link.ron`: a
///   symbolic link to `map.ron` (on Unix);
/// - `out.png` and `out.slbsp`: existing outputs holding [`PRECIOUS`].
struct Scene {
    dir: tempfile::TempDir,
}

impl Scene {
    fn new() -> Scene {
        let dir = tempfile::tempdir().expect("temp dir");
        let text = two_rooms();
        let compiled = compiled_two_rooms();
        let header = |version: u8, map: u8| vec![version, 2, 1, map, 0, 0, 0, 0, 0, 1, 0, 0, 0];
        let with = |mut bytes: Vec<u8>, tail: &[u8]| {
            bytes.extend(tail);
            bytes
        };
        let doom2 = sightline::wad::wad_bytes(
            b"IWAD",
            &[("MAP01", &[][..]), ("THINGS", &[][..]), ("DEMO1", &with(header(109, 7), &[0x80])[..])],
        );
        let files: [(&str, Vec<u8>); 16] = [
            ("boom.lmp", with(header(202, 1), &[0x80])),
            ("mbf21.lmp", with(header(221, 1), &[0x80])),
            ("cut.lmp", with(header(109, 1), &[25, 0])),
            ("nomarker.lmp", with(header(109, 1), &[25, 0, 0, 0])),
            ("empty.lmp", Vec::new()),
            ("map05.lmp", with(header(109, 5), &[25, 0, 0, 0, 0x80])),
            ("doom2.wad", doom2),
            ("map.ron", text.clone().into()),
            ("bad.ron", edit(&text, "(0.0, 256.0), (256.0", "(0.0, 256.0) (256.0").into()),
            ("invalid.ron", edit(&text, "from: 3, to: 4", "from: 99, to: 4").into()),
            ("empty.ron", Vec::new()),
            ("binary.ron", b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR".to_vec()),
            ("half.slbsp", compiled[..compiled.len() / 2].to_vec()),
            ("compiled.slbsp", compiled),
            ("out.png", PRECIOUS.to_vec()),
            ("out.slbsp", PRECIOUS.to_vec()),
        ];
        for (name, bytes) in files {
            std::fs::write(dir.path().join(name), bytes).expect("fixture");
        }
        for sub in ["dir.ron", "sub"] {
            std::fs::create_dir(dir.path().join(sub)).expect("fixture dir");
        }
        #[cfg(unix)]
        std::os::unix::fs::symlink("map.ron", dir.path().join("link.ron")).expect("fixture link");
        Scene { dir }
    }

    fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }

    /// Every entry under the directory: path -> contents (None for a directory).
    fn snapshot(&self) -> BTreeMap<PathBuf, Option<Vec<u8>>> {
        fn walk(dir: &Path, root: &Path, out: &mut BTreeMap<PathBuf, Option<Vec<u8>>>) {
            for entry in std::fs::read_dir(dir).expect("read_dir") {
                let path = entry.expect("entry").path();
                let key = path.strip_prefix(root).unwrap().to_path_buf();
                if path.is_dir() {
                    out.insert(key, None);
                    walk(&path, root, out);
                } else {
                    out.insert(key, Some(std::fs::read(&path).expect("read")));
                }
            }
        }
        let mut out = BTreeMap::new();
        walk(self.dir.path(), self.dir.path(), &mut out);
        out
    }

    /// Runs `sightline args...` in the directory.
    fn run<S: AsRef<OsStr>>(&self, args: &[S]) -> Run {
        let out = Command::new(env!("CARGO_BIN_EXE_sightline"))
            .args(args)
            .current_dir(self.dir.path())
            .env("RUST_BACKTRACE", "0")
            .output()
            .expect("the binary runs");
        Run {
            success: out.status.success(),
            code: out.status.code(),
            stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
            stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        }
    }
}

struct Run {
    success: bool,
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

impl Run {
    fn ok(&self, what: &str) -> &Run {
        assert!(self.success, "{what}: exit {:?}\nstdout: {}\nstderr: {}", self.code, self.stdout, self.stderr);
        self
    }
}

/// Runs `args` in a fresh scene and checks that it fails cleanly: non-zero
/// exit (1 or clap's 2, not a signal or panic's 101), every one of `mentions`
/// in stderr, no panic, and not a byte changed on disk. Returns what is wrong.
fn check_refused(args: &[&str], mentions: &[&str]) -> Result<(), String> {
    let scene = Scene::new();
    let before = scene.snapshot();
    let run = scene.run(args);
    let mut wrong = Vec::new();
    if !matches!(run.code, Some(1 | 2)) {
        wrong.push(format!("exit code {:?}", run.code));
    }
    if run.stderr.contains("panicked") {
        wrong.push("panicked".to_string());
    }
    if run.stderr.matches("(os error").count() > 1 {
        wrong.push("the I/O cause is printed more than once".to_string());
    }
    for m in mentions.iter().filter(|m| !run.stderr.contains(*m)) {
        wrong.push(format!("stderr lacks `{m}`"));
    }
    let after = scene.snapshot();
    if after != before {
        let changed: Vec<_> = after
            .iter()
            .filter(|(k, v)| before.get(*k) != Some(v))
            .map(|(k, _)| k.display().to_string())
            .chain(before.keys().filter(|k| !after.contains_key(*k)).map(|k| k.display().to_string()))
            .collect();
        wrong.push(format!("files changed: {changed:?}"));
    }
    if wrong.is_empty() {
        Ok(())
    } else {
        Err(format!("{}\n    stderr: {}", wrong.join("; "), run.stderr.trim_end()))
    }
}

/// Checks every row, reporting all failures at once.
fn check_all_refused(rows: &[(Vec<&str>, &[&str])]) {
    let failures: Vec<String> = rows
        .iter()
        .filter_map(|(args, mentions)| {
            check_refused(args, mentions).err().map(|e| format!("sightline {}: {e}", args.join(" ")))
        })
        .collect();
    assert!(failures.is_empty(), "{} of {} rows failed:\n{}", failures.len(), rows.len(), failures.join("\n"));
}

/// The PNG signature and the IHDR size of `bytes`.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert!(bytes.len() > 24, "too short for a PNG: {} bytes", bytes.len());
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR", "first chunk is IHDR");
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    (be(16), be(20))
}

// ---------------------------------------------------------------------------
// Doom's demos

#[test]
fn replay_refuses_bad_doom_demos() {
    check_all_refused(&[
        (vec!["replay", "boom.lmp", "--iwad", "doom2.wad"], &["boom.lmp", "demo version 202 (Boom 2.02)"]),
        (vec!["replay", "mbf21.lmp", "--iwad", "doom2.wad"], &["mbf21.lmp", "221 (MBF21)"]),
        (vec!["replay", "cut.lmp", "--iwad", "doom2.wad"], &["cut.lmp", "truncated", "tic 0 is cut short"]),
        (vec!["replay", "nomarker.lmp", "--iwad", "doom2.wad"], &["nomarker.lmp", "no end marker (0x80)"]),
        (vec!["replay", "empty.lmp", "--iwad", "doom2.wad"], &["empty.lmp", "the file is empty"]),
        (vec!["replay", "map05.lmp", "--iwad", "doom2.wad"], &["map05.lmp", "MAP05", "doom2.wad", "does not have"]),
        (vec!["replay", "map05.lmp"], &["map05.lmp", "--iwad"]),
        (vec!["replay", "doom2.wad:DEMO9"], &["doom2.wad", "no lump DEMO9"]),
        (vec!["replay", "doom2.wad:DEMO1"], &["DEMO1", "MAP07", "does not have"]),
        (vec!["replay", "missing.lmp", "--iwad", "doom2.wad"], &["missing.lmp", "cannot read"]),
    ]);
}

/// `replay --timedemo --profile` on one of Freedoom's demos: Chocolate's
/// line, then the breakdown, every part named once with a time (skipped,
/// saying why, without Freedoom; never under SIGHTLINE_REQUIRE_FREEDOOM).
#[test]
fn timedemo_profile_names_where_a_frame_goes() {
    let wad = Path::new("/usr/share/games/doom/freedoom1.wad");
    if !wad.exists() {
        assert!(std::env::var_os("SIGHTLINE_REQUIRE_FREEDOOM").is_none(), "{} is missing", wad.display());
        eprintln!("skipped: {} is not installed (apt install freedoom)", wad.display());
        return;
    }
    let scene = Scene::new();
    let demo = format!("{}:DEMO3", wad.display());
    let run = scene.run(&["replay", &demo, "--timedemo", "--profile", "--size", "64x40", "--threads", "1"]);
    run.ok("replay --timedemo --profile");
    assert!(run.stdout.starts_with("timed 1241 gametics in "), "{}", run.stdout);
    assert!(run.stdout.contains("breakdown (mean per frame"), "{}", run.stdout);
    for part in ["tic", "scene", "setup", "walk", "walls", "spans", "masked", "copy"] {
        let rows: Vec<&str> = run.stdout.lines().filter(|l| l.split_whitespace().next() == Some(part)).collect();
        assert_eq!(rows.len(), 1, "{part}: {}", run.stdout);
        assert!(rows[0].contains(" ms ") && rows[0].ends_with('%'), "{}", rows[0]);
    }
    // Without --timedemo there is nothing to profile.
    check_all_refused(&[(vec!["replay", "doom2.wad:DEMO1", "--profile"], &["--timedemo"])]);
}

#[test]
fn a_doom_demo_records_a_wad_map_only() {
    check_all_refused(&[(
        vec!["autoplay", "map.ron", "--max-ticks", "3", "--record", "out.lmp"],
        &["out.lmp", "a Doom demo records a WAD's map"],
    )]);
}

// ---------------------------------------------------------------------------
// capture

/// `capture map.ron -o out.png` with extra arguments.
macro_rules! capture {
    ($($arg:expr),* $(,)?) => {
        vec!["capture", "map.ron", "-o", "out.png", $($arg),*]
    };
}

#[test]
fn capture_refuses_bad_sizes() {
    check_all_refused(&[
        (capture!("--size", "0x10"), &["--size", "0x10", "`0`", "1..=16384"]),
        (capture!("--size", "64x0"), &["--size", "64x0", "`0`"]),
        (capture!("--size", "10"), &["--size", "`10`", "WxH"]),
        (capture!("--size", "100000x100000"), &["--size", "`100000`"]),
        (capture!("--size", "axb"), &["--size", "axb", "`a`"]),
        // A leading minus is taken for an option unless attached with `=`.
        (capture!("--size", "-5x10"), &["unexpected argument '-5'"]),
        (capture!("--size=-5x10"), &["--size", "`-5`"]),
        (capture!("--size", ""), &["--size"]),
    ]);
}

#[test]
fn capture_refuses_bad_poses() {
    check_all_refused(&[
        (capture!("--pose", "1,2"), &["--pose", "`1,2`", "X,Y,ANGLE"]),
        (capture!("--pose", "1,2,3,4,5"), &["--pose", "X,Y,ANGLE"]),
        (capture!("--pose", "1,2,nan"), &["--pose", "`nan`", "not finite"]),
        (capture!("--pose", "64,128,0,inf"), &["--pose", "`inf`", "not finite"]),
        (capture!("--pose", "a,b,c"), &["--pose", "`a` is not a number"]),
        (capture!("--pose", "1e999,128,0"), &["--pose", "not finite"]),
        // Outside the map, and exactly on a one-sided wall: the map names itself.
        (capture!("--pose", "-5,128,0"), &["map.ron", "bad pose", "(-5, 128)", "not inside any sector"]),
        (capture!("--pose", "1000,1000,90"), &["map.ron", "(1000, 1000)"]),
        (capture!("--pose", "0,128,0"), &["map.ron", "(0, 128)", "on a one-sided wall"]),
        (capture!("--pose", "256,0,0"), &["map.ron", "(256, 0)"]),
    ]);
}

#[test]
fn capture_refuses_bad_choices() {
    check_all_refused(&[
        (capture!("--renderer", "raytrace"), &["--renderer", "raytrace", "bsp", "reference"]),
        (capture!("--shade", "neon"), &["--shade", "neon", "ids", "flat"]),
        (capture!("--frobnicate"), &["--frobnicate"]),
        (vec!["capture", "map.ron"], &["--output"]),
        (vec!["capture", "-o", "out.png"], &["<MAP>"]),
    ]);
}

#[test]
fn capture_refuses_bad_map_files() {
    let capture = |map| vec!["capture", map, "-o", "out.png"];
    check_all_refused(&[
        (capture("missing.ron"), &["missing.ron", "cannot read"]),
        (capture("dir.ron"), &["dir.ron", "cannot read"]),
        (capture("bad.ron"), &["bad.ron:5:34", "comma"]),
        (capture("invalid.ron"), &["invalid.ron", "line 3", "vertex 99"]),
        (capture("empty.ron"), &["empty.ron", "empty"]),
        (capture("binary.ron"), &["binary.ron", "binary", "byte 8"]),
        (capture("half.slbsp"), &["half.slbsp", "corrupt or truncated"]),
    ]);
}

#[test]
fn capture_refuses_bad_outputs() {
    check_all_refused(&[
        (vec!["capture", "map.ron", "-o", "map.ron"], &["map.ron", "refusing to overwrite"]),
        (vec!["capture", "map.ron", "-o", "sub/../map.ron"], &["sub/../map.ron", "refusing to overwrite"]),
        (vec!["capture", "map.ron", "-o", "nodir/out.png"], &["nodir/out.png", "cannot write"]),
        (vec!["capture", "map.ron", "-o", "sub"], &["sub", "cannot write"]),
        (vec!["capture", "map.ron", "-o", "."], &[".: cannot write", "not a file name"]),
    ]);
}

#[test]
fn capture_writes_a_png() {
    let scene = Scene::new();
    let run = scene.run(&["capture", "map.ron", "--shade", "ids", "--size", "64x40", "-o", "new.png"]);
    run.ok("capture");
    assert!(!run.stderr.contains("panicked"), "{}", run.stderr);
    let png = std::fs::read(scene.path("new.png")).expect("the PNG was written");
    assert_eq!(png_size(&png), (64, 40));
}

/// The pose a new user tried: the doorway of two_rooms, exactly on the open
/// line between the rooms. It renders, and both renderers draw the same
/// `ids` frame from it.
#[test]
fn capture_from_a_doorway() {
    let scene = Scene::new();
    let map = shipped_map("two_rooms.ron");
    let map = map.to_str().expect("a UTF-8 path");
    let mut frames = Vec::new();
    for renderer in ["bsp", "reference"] {
        let out = format!("doorway-{renderer}.png");
        let args = ["capture", map, "--pose", "256,128,0", "--renderer", renderer, "--shade", "ids", "-o", &out];
        let run = scene.run(&args);
        run.ok(&format!("capture --pose 256,128,0 --renderer {renderer}"));
        let png = std::fs::read(scene.path(&out)).expect("the PNG was written");
        assert_eq!(png_size(&png), (640, 400));
        frames.push(png);
    }
    assert!(frames[0] == frames[1], "bsp and reference draw different frames from the doorway");
}

/// An existing output is replaced whole, through a temporary file that is gone
/// afterwards; the reference renderer and an explicit pose work too.
/// Odd but legal poses and sizes render without complaint through both renderers.
#[test]
fn capture_survives_extreme_poses_and_sizes() {
    let scene = Scene::new();
    let poses = [
        "64,128,0,1e300",
        "64,128,0,-1e300",
        "64,128,1e300",
        "64,128,-90,128",
        "64,128,0,0",
        "0.000001,0.000001,45",
        "255.9999999999,128,0",
        "511.99999999999,255.9999999999,200,1e15",
    ];
    let sizes = ["1x1", "1x300", "300x1", "16384x1"];
    let runs = poses.iter().map(|p| (*p, "48x30")).chain(sizes.iter().map(|s| ("64,128,0", *s)));
    for (pose, size) in runs {
        for renderer in ["bsp", "reference"] {
            let args = ["capture", "map.ron", "-o", "x.png", "--renderer", renderer, "--size", size];
            let run = scene.run(&[&args[..], &[&format!("--pose={pose}")]].concat());
            run.ok(&format!("--pose={pose} --size {size} --renderer {renderer}"));
            let (w, h) = size.split_once('x').unwrap();
            let png = std::fs::read(scene.path("x.png")).unwrap();
            assert_eq!(png_size(&png), (w.parse().unwrap(), h.parse().unwrap()));
        }
    }
}

#[test]
fn capture_replaces_an_existing_output() {
    let scene = Scene::new();
    let before = scene.snapshot();
    scene
        .run(&[
            "capture",
            "map.ron",
            "--renderer",
            "reference",
            "--pose",
            "64,128,45,60",
            "--size",
            "33x17",
            "-o",
            "out.png",
        ])
        .ok("capture over out.png");
    let png = std::fs::read(scene.path("out.png")).unwrap();
    assert_eq!(png_size(&png), (33, 17));
    let after = scene.snapshot();
    let changed: Vec<_> = after.keys().filter(|k| before.get(*k) != after.get(*k)).collect();
    assert_eq!(changed, [Path::new("out.png")], "only out.png changes");
}

// ---------------------------------------------------------------------------
// compile

#[test]
fn compile_refuses_to_overwrite_its_input() {
    check_all_refused(&[
        (vec!["compile", "map.ron", "-o", "map.ron"], &["map.ron", "refusing to overwrite the input map"]),
        (vec!["compile", "map.ron", "-o", "./sub/../map.ron"], &["./sub/../map.ron", "refusing"]),
        #[cfg(unix)]
        (vec!["compile", "map.ron", "-o", "link.ron"], &["link.ron", "refusing"]),
        #[cfg(unix)]
        (vec!["compile", "link.ron", "-o", "map.ron"], &["map.ron", "refusing"]),
    ]);
}

/// A map that cannot be compiled leaves the existing output as it was.
#[test]
fn compile_of_a_bad_map_leaves_the_output_alone() {
    let compile = |map| vec!["compile", map, "-o", "out.slbsp"];
    check_all_refused(&[
        (compile("bad.ron"), &["bad.ron:5:34", "comma"]),
        (compile("invalid.ron"), &["invalid.ron", "line 3", "`from` refers to vertex 99"]),
        (compile("empty.ron"), &["empty.ron", "empty"]),
        (compile("binary.ron"), &["binary.ron", "byte 8"]),
        (compile("missing.ron"), &["missing.ron", "cannot read"]),
        (compile("dir.ron"), &["dir.ron", "cannot read"]),
        (compile("compiled.slbsp"), &["compiled.slbsp", "already a compiled map"]),
        (compile("missing.wad:E1M1"), &["missing.wad:E1M1", "sightline import"]),
    ]);
}

#[test]
fn compile_refuses_bad_arguments() {
    check_all_refused(&[
        (
            vec!["compile", "map.ron", "-o", "out.slbsp", "--splitter", "nonsense"],
            &["--splitter", "unknown splitter `nonsense`", "random", "cost"],
        ),
        (vec!["compile", "map.ron", "-o", "out.slbsp", "--seed", "abc"], &["--seed", "abc"]),
        (vec!["compile", "map.ron", "-o", "out.slbsp", "--seed=-1"], &["--seed", "'-1'"]),
        (vec!["compile", "map.ron"], &["--output"]),
        (vec!["compile", "map.ron", "-o", "nodir/out.slbsp"], &["nodir/out.slbsp", "cannot write"]),
        (vec!["compile", "map.ron", "-o", "sub"], &["sub", "cannot write"]),
        (vec!["frobnicate"], &["frobnicate"]),
    ]);
}

#[test]
fn compile_json_is_one_object_on_the_last_line_and_the_file_loads() {
    let scene = Scene::new();
    for splitter in ["cost", "random"] {
        let out = format!("two_rooms.{splitter}.slbsp");
        let run = scene.run(&["compile", "map.ron", "-o", &out, "--json", "--splitter", splitter, "--seed", "3"]);
        run.ok("compile --json");
        let last = run.stdout.lines().last().expect("some stdout");
        let stats: serde_json::Value =
            serde_json::from_str(last).unwrap_or_else(|e| panic!("last stdout line is not JSON ({e}): {last}"));
        let obj = stats.as_object().expect("a JSON object");
        for key in ["lines_in", "sides_in", "sides_out", "splits", "nodes", "leaves", "depth"] {
            assert!(obj.get(key).is_some_and(|v| v.is_u64()), "`{key}` missing or not a count: {last}");
        }
        assert!(obj.get("build_ms").is_some_and(|v| v.as_f64().is_some_and(|ms| ms >= 0.0)), "{last}");
        assert_eq!(obj["lines_in"], 7, "{last}");
        assert_eq!(obj["sides_in"], 8, "{last}");
        assert!(obj["sides_out"].as_u64() >= obj["sides_in"].as_u64(), "{last}");
        assert_eq!(obj["leaves"].as_u64(), obj["nodes"].as_u64().map(|n| n + 1), "a binary tree: {last}");

        let compiled = std::fs::read(scene.path(&out)).expect("compiled file written");
        assert!(compiled.starts_with(file::MAGIC), "compiled file header");
        let png = format!("{out}.png");
        scene
            .run(&["capture", &out, "--shade", "ids", "--size", "64x40", "-o", &png])
            .ok("capture of the compiled file");
        assert_eq!(png_size(&std::fs::read(scene.path(&png)).unwrap()), (64, 40));
    }
}

/// The compiled file renders exactly as its source does.
#[test]
fn a_compiled_map_captures_like_its_source() {
    let scene = Scene::new();
    scene.run(&["compile", "map.ron", "-o", "map.slbsp"]).ok("compile");
    for (input, png) in [("map.ron", "a.png"), ("map.slbsp", "b.png")] {
        scene.run(&["capture", input, "--size", "80x50", "--pose", "100,100,30", "-o", png]).ok("capture");
    }
    let (a, b) = (std::fs::read(scene.path("a.png")).unwrap(), std::fs::read(scene.path("b.png")).unwrap());
    assert!(a == b, "capture of the compiled map differs from the source's");
}

#[test]
fn compile_without_json_prints_a_summary() {
    let scene = Scene::new();
    let run = scene.run(&["compile", "map.ron", "-o", "out.slbsp"]);
    run.ok("compile");
    let line = run.stdout.trim_end();
    for part in ["map.ron", "7 lines", "8 sides", "-> out.slbsp"] {
        assert!(line.contains(part), "summary lacks `{part}`: {line}");
    }
}

// ---------------------------------------------------------------------------
// Known bugs, reported; each passes once fixed.

#[test]

fn bug_compiling_a_compiled_map_says_so() {
    check_all_refused(&[(
        vec!["compile", "compiled.slbsp", "-o", "out.slbsp"],
        &["compiled.slbsp", "already a compiled map"],
    )]);
}
