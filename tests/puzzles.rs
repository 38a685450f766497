//! Generated puzzle levels (tests/puzzle.rs) over a fixed set of seeds: on
//! every one `check` finds the exit reachable and every key, and the
//! autopilot exits it with monsters off and on (skill 2). Each map is
//! written to `target/puzzles/` for a person to look at (`sightline check
//! target/puzzles/seed_3.ron -o plan.png`).
//!
//! The default suite plays [`SEEDS`]; `puzzles_long_batch` (the long suite,
//! `--ignored`) plays [`LONG_SEEDS`].

use std::path::PathBuf;

use glam::DVec2;

use sightline::autopilot::{self, check};
use sightline::campaign::MapRef;
use sightline::level::open_level;
use sightline::play::playthrough::Playthrough;
use sightline::play::{Exit, GameOptions};
use sightline_tests::puzzle::{self, Puzzle, LINKS};
use sightline_tests::root;

/// The seeds of the default suite: every kind of link leads off at least
/// once (a seed's first link is `LINKS[seed % 8]`), a ledge every third.
const SEEDS: std::ops::Range<u64> = 0..16;
/// The long suite's seeds.
const LONG_SEEDS: std::ops::Range<u64> = 16..160;

/// Skill 2, as the issue asks.
const SKILL: u8 = 2;
/// Game time the autopilot gets on one level.
const TICKS: u64 = 35 * 60 * 3;

/// Writes `p` under `target/puzzles/`; the path.
fn write(p: &Puzzle, monsters: bool) -> PathBuf {
    let dir = root().join("target").join("puzzles");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("seed_{}{}.ron", p.seed, if monsters { "_monsters" } else { "" }));
    std::fs::write(&path, &p.ron).unwrap();
    path
}

/// `check`'s verdict on the level at `path`: `Err` says what is wrong.
fn check_level(path: &PathBuf, p: &Puzzle) -> Result<(), String> {
    let level = open_level(path, &Default::default()).map_err(|e| format!("{}: {e}", path.display()))?;
    let (report, drawing) = check::check(level, SKILL);
    let mut wrong = route_faults(&report, &drawing);
    if !report.exit_reachable {
        wrong.push("the exit is not reachable".to_string());
    }
    if report.keys.len() != p.keys.len() {
        wrong.push(format!("{} keys named, {} placed", report.keys.len(), p.keys.len()));
    }
    for k in report.keys.iter().filter(|k| !k.reachable) {
        wrong.push(format!("the {} key is not reachable", k.colour));
    }
    if wrong.is_empty() {
        Ok(())
    } else {
        Err(format!("check: {}\n{}", wrong.join("; "), report.text()))
    }
}

/// What is wrong with the route `check` draws, as the report tells it: it
/// must run without a break (a hop longer than a running jump is a
/// teleport's) from the start through every key the report calls
/// reachable to the exit, if the report calls the exit reachable.
fn route_faults(report: &check::Report, drawing: &check::Drawing) -> Vec<String> {
    let route = &drawing.route;
    let mut wrong = Vec::new();
    if route.missed > 0 {
        wrong.push(format!("the route misses {} of the closure's goals", route.missed));
    }
    for i in 1..route.points.len() {
        let hop = route.points[i - 1].distance(route.points[i]);
        if !route.teleport[i] && hop > 128.0 {
            wrong.push(format!("the route breaks off at {:?}: a hop of {hop:.0} units", route.points[i - 1]));
        }
    }
    let nearest = |x: f64, y: f64| {
        let p = DVec2::new(x, y);
        route.points.iter().map(|q| q.distance(p)).fold(f64::MAX, f64::min)
    };
    for k in report.keys.iter().filter(|k| k.reachable) {
        // A touch: the body's radius and the key's, and half a cell.
        let d = nearest(k.x, k.y);
        if d > 16.0 + 20.0 + 8.0 {
            wrong.push(format!("the route passes the {} key no nearer than {d:.0} units", k.colour));
        }
    }
    if report.exit_reachable {
        // The exit switch, used from within use range of its middle.
        let end = route.points.last().copied().unwrap_or_default();
        let to_exit = report.exits.iter().filter(|e| e.reachable).map(|e| end.distance(DVec2::new(e.x, e.y)));
        if to_exit.fold(f64::MAX, f64::min) > sightline::play::USE_RANGE + 32.0 {
            wrong.push(format!("the route ends at {end:?}, not at a reachable exit"));
        }
    }
    wrong
}

/// Plays the level at `path` with the autopilot: `Err` says how it ended
/// if not at the exit.
fn autoplay(path: &PathBuf, no_monsters: bool) -> Result<u64, String> {
    let options = GameOptions { skill: SKILL, no_monsters, ..GameOptions::default() };
    let mut play = Playthrough::of(&MapRef::File(path.clone()), options).map_err(|e| e.to_string())?;
    let (outcome, bot) = autopilot::run(&mut play, TICKS, |_, _| true).map_err(|e| e.to_string())?;
    if outcome.exit == Some(Exit::Normal) {
        return Ok(outcome.inputs.len() as u64);
    }
    let how = match (outcome.died, &outcome.stuck) {
        (true, _) => "died".to_string(),
        (false, Some((at, why))) => format!("stuck at ({:.0}, {:.0}): {why}", at.x, at.y),
        (false, None) => "out of time".to_string(),
    };
    let tail: Vec<&String> = bot.log.iter().rev().take(12).collect::<Vec<_>>().into_iter().rev().collect();
    Err(format!(
        "autopilot, monsters {}: {how}\n{}",
        if no_monsters { "off" } else { "on" },
        tail.iter().map(|s| s.as_str()).collect::<Vec<_>>().join("\n")
    ))
}

/// Everything asked of seed `seed`: the failures, one paragraph each.
fn play_seed(seed: u64) -> Vec<String> {
    let mut failures = Vec::new();
    for monsters in [false, true] {
        let p = puzzle::generate(seed, monsters);
        let path = write(&p, monsters);
        let at = format!("{} ({})", p.describe(), path.display());
        if let Err(e) = check_level(&path, &p) {
            failures.push(format!("{at}: {e}"));
        }
        // Without monsters on the map made without them, and with monsters
        // (and without them) on the one made with them.
        let runs: &[bool] = if monsters { &[false, true] } else { &[true] };
        for &no_monsters in runs {
            if let Err(e) = autoplay(&path, no_monsters) {
                failures.push(format!("{at}: {e}"));
            }
        }
    }
    failures
}

/// Plays `seeds` two at a time; panics with every failure.
fn play_seeds(seeds: std::ops::Range<u64>) {
    let list: Vec<u64> = seeds.collect();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let failures = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..2 {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(&seed) = list.get(i) else { break };
                let f = play_seed(seed);
                failures.lock().unwrap().extend(f);
            });
        }
    });
    let failures = failures.into_inner().unwrap();
    assert!(failures.is_empty(), "{} failures over seeds {:?}:\n\n{}", failures.len(), list, failures.join("\n\n"));
}

#[test]
fn the_default_seeds_cover_every_link_a_ledge_and_a_decoy() {
    let puzzles: Vec<Puzzle> = SEEDS.map(|s| puzzle::generate(s, true)).collect();
    for link in LINKS {
        assert!(puzzles.iter().any(|p| p.links.contains(&link)), "no seed has {link:?}");
    }
    assert!(puzzles.iter().any(|p| p.ledges > 0), "no ledge");
    assert!(puzzles.iter().any(|p| p.decoys > 0), "no decoy");
    assert!(puzzles.iter().any(|p| p.monsters > 0), "no monster");
    assert!(puzzles.iter().any(|p| !p.keys.is_empty()), "no key");
    // Deterministic from the seed.
    assert_eq!(puzzle::generate(5, true).ron, puzzles[5].ron);
}

/// `check` alone on the default seeds: the report and the route it draws
/// agree (the autopilot's part is in the test below).
#[test]
fn check_draws_the_route_its_report_tells() {
    let mut failures = Vec::new();
    for seed in SEEDS {
        for monsters in [false, true] {
            let p = puzzle::generate(seed, monsters);
            // Its own file: the test below writes `write`'s at the same time.
            let dir = root().join("target").join("puzzles");
            std::fs::create_dir_all(&dir).unwrap();
            let path = dir.join(format!("route_seed_{seed}{}.ron", if monsters { "_monsters" } else { "" }));
            std::fs::write(&path, &p.ron).unwrap();
            if let Err(e) = check_level(&path, &p) {
                failures.push(format!("{} ({}): {e}", p.describe(), path.display()));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn generated_puzzles_are_checked_and_exited() {
    play_seeds(SEEDS);
}

#[test]
#[ignore = "long suite (144 more generated puzzles): scripts/long-suites.sh runs it, as CI does"]
fn puzzles_long_batch() {
    play_seeds(LONG_SEEDS);
}

/// With nothing to do where it stands (a bare ledge, the exit out of
/// reach), the bot tries the drops it survives before it gives up: into
/// the room below with a way on, not the nearer pit with none.
#[test]
fn with_nothing_left_the_autopilot_drops_off_a_ledge_before_it_gives_up() {
    let dir = root().join("target").join("puzzles");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("ledge_over_two_pits.ron");
    std::fs::write(&path, puzzle::ledge_over_two_pits()).unwrap();
    let options = GameOptions { skill: SKILL, no_monsters: true, ..GameOptions::default() };
    let mut play = Playthrough::of(&MapRef::File(path.clone()), options).unwrap_or_else(|e| panic!("{e}"));
    let (outcome, bot) = autopilot::run(&mut play, 35 * 60 * 3, |_, _| true).unwrap();
    let log = bot.log.join("\n");
    assert_eq!(outcome.exit, None, "the exit is out of reach\n{log}");
    assert!(outcome.stuck.is_some(), "it should give up in the end\n{log}");
    let p = play.game.player();
    assert_eq!(p.z, 0.0, "still on the ledge\n{log}");
    assert!(p.pos.x > 128.0, "dropped into the pit with no way out, at {:?}\n{log}", p.pos);
    assert!(log.contains("dropping into sector 2"), "{log}");
}
