//! The world's machinery, per tick (issue 12's benchmarks), on the
//! simulation with Doom's arithmetic: each tick is `SimGame::tick`, the
//! game's whole tic (the player's command, every thinker, the specials,
//! then the level read out for the renderer), as the window runs it.
//!
//! - **idle**: a tick in a generated room of 1,000 pillar sectors, each with
//!   a unique tag, an idle sector special and a line special naming it that
//!   is never set off, against the same geometry with none, the player
//!   walking about (the same seeded inputs on both; a RON map plays by
//!   Sightline's rules, its specials as Boom's generalized ones,
//!   `sim::from_map`). Criterion times one
//!   tick per iteration (`idle-tags/none`, `idle-tags/1000-tagged`,
//!   `idle-tags/none-again`); a
//!   second, interleaved loop (none, tagged, tagged, none, ...) gives the
//!   medians and their ratio from one run.
//! - **freedoom**: ticks per second on every map of freedoom1.wad and
//!   freedoom2.wad (68 maps) with everything the player can set off
//!   running. Each round starts a fresh game at skill 3 on the map (opened
//!   once from the WAD, its level rebuilt and the simulation loaded from
//!   the WAD untimed), sets off every special
//!   through the player's inputs (`world/setoff.rs`, untimed), puts the
//!   player back at the start and times each of [`WINDOW`] ticks on its
//!   own: walking (seeded random inputs), standing still, and standing still
//!   in a game where nothing was set off (the lights and timers a level
//!   starts with still run), the three in rotating order. A custom loop, not
//!   criterion: a tick can be timed only once from a given state, so every
//!   window needs an untimed fresh game and setup
//!   worth hundreds of ticks, which criterion's loop cannot keep out of its
//!   budget; and its warm-up, analysis and reports for 68 maps would take far
//!   longer than the ticks. Prints a markdown table: median µs per tick over
//!   all rounds, ticks per second, the sector thinkers running (the
//!   simulation's doors, lifts, floors, ceilings and lights, and the
//!   pressed buttons waiting to pop back) at the start and end of the
//!   window, and what could not be set off.
//!
//! Run: `cargo bench -p sightline-engine --bench world` (both), or with
//! `-- idle` or `-- freedoom` for one; `SIGHTLINE_WORLD_MAPS=MAP20,E1M4`
//! keeps only those maps. Needs Freedoom's WADs (Debian:
//! freedoom) in `/usr/share/games/doom` or `$SIGHTLINE_DOOM_DIR`, and fails
//! if they are missing, as the compile bench does.

mod common;
#[path = "world/pillars.rs"]
mod pillars;
#[path = "world/setoff.rs"]
mod setoff;

use std::time::{Duration, Instant};

use common::{extent, median, open_wad, wad_library, Wanted};
use criterion::Criterion;
use sightline::bsp::{build, BuildOptions, CompiledMap};
use sightline::campaign::{open, MapRef, Opened};
use sightline::level::Level;
use sightline::map::load::parse_map;
use sightline::materials::Materials;
use sightline::play::input::wander;
use sightline::play::{GameOptions, TickInput};
use sightline::sim::game::SimGame;
use sightline::sim::think::Status;
use sightline::sim::ThinkerKind;

/// Ticks timed per round on a Freedoom map: 3 s of play, while what was
/// set off still runs (a door is done about 214 ticks after it opens).
const WINDOW: usize = 105;
/// Rounds per Freedoom map and setup (each starts a fresh game and sets
/// everything off again).
const ROUNDS: usize = 20;
/// Ticks per round of the interleaved idle study, and rounds of it.
const IDLE_TICKS: usize = 2_000;
const IDLE_ROUNDS: usize = 10;
/// The player's health while timing: never dying keeps every round's walk
/// the same length of movement, whatever the nukage it crosses.
const HEALTH: i32 = 1_000_000;

fn main() {
    let wanted = Wanted::from_args();
    let mut c = Criterion::default().configure_from_args();
    if wanted.wants("idle-tags") {
        idle(&mut c, wanted.quick);
    }
    c.final_summary();
    if wanted.wants("freedoom") {
        freedoom(wanted.quick);
    }
}

/// Seeded random walking without use or fire (pressing use could set off
/// an exit).
fn walking(seed: u64, ticks: usize) -> Vec<TickInput> {
    wander(seed, ticks, false)
}

/// The median of `times`, in µs.
fn median_us(times: &[Duration]) -> f64 {
    median(&mut times.iter().map(|d| d.as_secs_f64() * 1e6).collect::<Vec<_>>())
}

/// Ticks `game` through `inputs`, timing each tick on its own.
fn time_ticks(game: &mut SimGame, inputs: &[TickInput], times: &mut Vec<Duration>) {
    for input in inputs {
        let start = Instant::now();
        game.tick(input);
        times.push(start.elapsed());
    }
}

/// A fresh game on the pillar room, with (`specials`) or without its
/// tags and specials.
fn pillar_game(specials: bool) -> SimGame {
    let label = if specials { "pillars-tagged" } else { "pillars-plain" };
    SimGame::on_level(pillar_level(specials), label, GameOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

fn pillar_level(specials: bool) -> Level {
    let label = if specials { "pillars-tagged" } else { "pillars-plain" };
    let map = parse_map(&pillars::pillars_ron(specials), label).unwrap_or_else(|e| panic!("{e}"));
    let specials_found = (
        map.sectors.iter().filter(|s| s.tag != 0 && !s.special.is_none()).count(),
        map.lines.iter().filter(|l| l.special.is_some()).count(),
    );
    let wanted = if specials { (pillars::ACROSS * pillars::DOWN, pillars::ACROSS * pillars::DOWN) } else { (0, 0) };
    assert_eq!(specials_found, wanted, "{label}: tagged sectors with a special, and lines with a special");
    let compiled = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{label}: {e}"));
    Level::with_builtin_textures(compiled).unwrap_or_else(|e| panic!("{e}"))
}

fn idle(c: &mut Criterion, quick: bool) {
    let inputs = walking(7, 10_000);
    let mut group = c.benchmark_group("idle-tags");
    group.sample_size(50).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
    // "none" once more at the end: the first run of a group tends to be
    // slower (the sectors bench sees the same).
    for (name, specials) in [("none", false), ("1000-tagged", true), ("none-again", false)] {
        let mut game = pillar_game(specials);
        let mut k = 0;
        group.bench_function(name, |b| {
            b.iter(|| {
                game.tick(&inputs[k % inputs.len()]);
                k += 1;
            })
        });
    }
    group.finish();

    // Interleaved, from a fresh game each round: none, tagged, tagged, none, ...
    let (ticks, rounds) = if quick { (35, 2) } else { (IDLE_TICKS, IDLE_ROUNDS) };
    let levels = [false, true];
    let mut medians: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
    let mut ends = [None, None];
    for round in 0..rounds {
        let order = if round.is_multiple_of(2) { [0, 1] } else { [1, 0] };
        for which in order {
            let mut game = pillar_game(levels[which]);
            let mut times = Vec::with_capacity(ticks);
            time_ticks(&mut game, &inputs[..ticks], &mut times);
            medians[which].push(median_us(&times));
            assert_eq!(sector_thinkers(&game), 0, "an idle map has no sector thinker running");
            ends[which] = Some(game.player().pos);
        }
    }
    assert_eq!(ends[0], ends[1], "the same inputs walk the same way through the same geometry");
    let none = median(&mut medians[0]);
    let tagged = median(&mut medians[1]);
    println!("\n## Idle specials: {rounds} interleaved rounds of {ticks} ticks, median of the per-round medians\n");
    println!("| map | µs per tick | ticks per second |");
    println!("|---|---:|---:|");
    println!("| 1,000 pillars, no tags or specials | {none:.3} | {:.0} |", 1e6 / none);
    println!("| 1,000 pillars, tagged, sector and line specials | {tagged:.3} | {:.0} |", 1e6 / tagged);
    println!("\ntagged / none = {:.3}", tagged / none);
    let spread = |m: &[f64]| {
        let (lo, hi) = extent(m);
        format!("{lo:.3}..{hi:.3}")
    };
    println!("per-round medians: none {}, tagged {}\n", spread(&medians[0]), spread(&medians[1]));
}

/// The sector thinkers running, by kind: doors, plats (lifts), floors,
/// ceilings (and crushers), lights; and the pressed buttons waiting to pop
/// back (Doom keeps them in `buttonlist`, not as thinkers). A plat or
/// crusher in stasis is not running; bodies are not counted.
fn census(game: &SimGame) -> [usize; 6] {
    let mut n = [0; 6];
    for t in game.sim.thinkers.iter().filter(|t| t.status == Status::Active) {
        let k = match t.kind {
            ThinkerKind::Mobj(_) => continue,
            ThinkerKind::Door(_) => 0,
            ThinkerKind::Plat(_) => 1,
            ThinkerKind::Floor(_) => 2,
            ThinkerKind::Ceiling(_) => 3,
            ThinkerKind::Light(_) => 4,
        };
        n[k] += 1;
    }
    n[5] = game.sim.spec.buttons.iter().filter(|b| b.timer != 0).count();
    n
}

/// All of [`census`]: the level's machinery at work.
fn sector_thinkers(game: &SimGame) -> usize {
    census(game).iter().sum()
}

/// How a Freedoom map is timed: with everything set off or nothing, the
/// player walking or standing still.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Setup {
    /// Everything set off, the player walking: the headline figure.
    Walking,
    /// Everything set off, the player standing at the start: mostly the
    /// thinkers' cost.
    Idle,
    /// Nothing set off (only the lights and timers a level starts with),
    /// the player standing at the start: the baseline for [`Setup::Idle`].
    PlainIdle,
}

const SETUPS: [Setup; 3] = [Setup::Walking, Setup::Idle, Setup::PlainIdle];

/// One Freedoom map's figures.
struct Row {
    map: String,
    lines: usize,
    sectors: usize,
    set: setoff::SetOff,
    /// Median µs per tick, per [`SETUPS`].
    us: [f64; 3],
    /// Thinkers running by kind when the walking window starts, and how many at its end.
    start: [usize; 6],
    end: usize,
    /// Thinkers at the start of the plain window.
    plain_thinkers: usize,
    /// Per setup, the tick of the window at which the level ended (an exit
    /// line crossed); later ticks are not timed.
    exited_at: [Option<usize>; 3],
}

fn freedoom(quick: bool) {
    let (window, rounds) = if quick { (35, 1) } else { (WINDOW, ROUNDS) };
    let walk = walking(7, window);
    let still = vec![TickInput::default(); window];
    let mut rows = Vec::new();
    let started = Instant::now();
    for file in ["freedoom1.wad", "freedoom2.wad"] {
        let (path, wad) = open_wad(file);
        let mut names = wad.map_names();
        let library = wad_library(wad);
        if let Ok(only) = std::env::var("SIGHTLINE_WORLD_MAPS") {
            names.retain(|n| only.split(',').any(|o| o.eq_ignore_ascii_case(n)));
        }
        if quick {
            names.truncate(1);
        }
        for name in names {
            let label = format!("{}:{name}", path.display());
            let opened = open(&MapRef::parse(&label, None), &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
            let compiled = opened.level.compiled.clone();
            // A fresh level as `open` makes it, without compiling again; the
            // simulation reads the WAD's own lumps.
            let fresh = || -> SimGame {
                let materials =
                    Materials::resolve_in(&compiled.map, &library, &label).unwrap_or_else(|e| panic!("{e}"));
                let again = Opened {
                    level: Level::new(compiled.clone(), materials),
                    map: opened.map.clone(),
                    repairs: Vec::new(),
                    report: None,
                    links: opened.links.clone(),
                    wad: opened.wad.clone(),
                };
                SimGame::new(again, GameOptions { skill: 3, ..Default::default() })
                    .unwrap_or_else(|e| panic!("{label}: {e}"))
            };
            let row = time_map(&name, &compiled, fresh, [&walk, &still, &still], rounds);
            eprintln!(
                "{file} {name}: {:.2} µs/tick walking, {:.2} idle, {:.2} plain idle, {} thinkers ({:.0} s so far)",
                row.us[0],
                row.us[1],
                row.us[2],
                row.start.iter().sum::<usize>(),
                started.elapsed().as_secs_f64()
            );
            rows.push(row);
        }
    }
    print_freedoom(&rows, window, rounds);
}

/// Times `rounds` windows of each setup, in turn (the order rotating each
/// round), each on a fresh game: set everything off (or not), put the
/// player back at the start, time every tick until the window ends or the
/// level does.
fn time_map(
    name: &str,
    compiled: &CompiledMap,
    fresh: impl Fn() -> SimGame,
    inputs: [&[TickInput]; 3],
    rounds: usize,
) -> Row {
    let mut times: [Vec<Duration>; 3] = Default::default();
    let mut row = Row {
        map: name.to_string(),
        lines: compiled.map.lines.len(),
        sectors: compiled.map.sectors.len(),
        set: Default::default(),
        us: [0.0; 3],
        start: [0; 6],
        end: 0,
        plain_thinkers: 0,
        exited_at: [None; 3],
    };
    for round in 0..rounds {
        for k in 0..SETUPS.len() {
            let which = (k + round) % SETUPS.len();
            let setup = SETUPS[which];
            let mut game = fresh();
            let set = match setup {
                Setup::Walking | Setup::Idle => setoff::set_off_everything(&mut game),
                Setup::PlainIdle => setoff::SetOff::default(),
            };
            let start = compiled.map.player_start();
            assert!(game.place_player(start.pos, start.angle), "{name}: the player start has no room");
            game.set_health(HEALTH);
            let census_start = census(&game);
            for (tick, input) in inputs[which].iter().enumerate() {
                let t = Instant::now();
                game.tick(input);
                times[which].push(t.elapsed());
                if game.exit().is_some() {
                    row.exited_at[which] = Some(tick);
                    break;
                }
            }
            match setup {
                Setup::Walking => (row.set, row.start, row.end) = (set, census_start, sector_thinkers(&game)),
                Setup::Idle => {}
                Setup::PlainIdle => row.plain_thinkers = census_start.iter().sum(),
            }
        }
    }
    for (us, t) in row.us.iter_mut().zip(&times) {
        *us = median_us(t);
    }
    row
}

/// The cost of timing an empty interval (`Instant::now` and `elapsed`),
/// included in every per-tick figure: the median of 100,000.
fn timer_overhead() -> f64 {
    let times: Vec<Duration> = (0..100_000).map(|_| Instant::now().elapsed()).collect();
    median_us(&times)
}

fn print_freedoom(rows: &[Row], window: usize, rounds: usize) {
    println!("\n## Freedoom: every map with everything set off ({rounds} rounds of {window} ticks, median per tick)\n");
    println!(
        "| map | lines | sectors | set off: went off / tried (use, walk, shoot) | skipped: sectors already moving | setup ticks | thinkers at the start: all (doors, lifts, floors, ceilings, lights, buttons) | at the end | walking: µs per tick | walking: ticks per second | idle: µs per tick | nothing set off, idle: thinkers | nothing set off, idle: µs per tick | idle / nothing set off |"
    );
    println!("|---|---:|---:|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|");
    for r in rows {
        let [u, w, s] = r.set.fired;
        let [tu, tw, ts] = r.set.tried;
        let t = r.start;
        let exited: String = SETUPS
            .iter()
            .zip(r.exited_at)
            .filter_map(|(setup, at)| at.map(|k| format!(" (the level ends at tick {k}, {setup:?})")))
            .collect();
        println!(
            "| {}{exited} | {} | {} | {}/{} ({u}/{tu}, {w}/{tw}, {s}/{ts}) | {} | {} | {} ({}, {}, {}, {}, {}, {}) | {} | {:.2} | {:.0} | {:.2} | {} | {:.2} | {:.2} |",
            r.map,
            r.lines,
            r.sectors,
            r.set.fired_total(),
            r.set.tried_total(),
            r.set.busy,
            r.set.ticks,
            t.iter().sum::<usize>(),
            t[0],
            t[1],
            t[2],
            t[3],
            t[4],
            t[5],
            r.end,
            r.us[0],
            1e6 / r.us[0],
            r.us[1],
            r.plain_thinkers,
            r.us[2],
            r.us[1] / r.us[2],
        );
    }
    let column = |f: &dyn Fn(&Row) -> f64| -> Vec<f64> { rows.iter().map(f).collect() };
    let mut walk = column(&|r| r.us[0]);
    let (lo, hi) = extent(&walk);
    let walk_median = median(&mut walk);
    let mut idle = column(&|r| r.us[1]);
    let mut ratio = column(&|r| r.us[1] / r.us[2]);
    let (rlo, rhi) = extent(&ratio);
    println!(
        "\n{} maps. Walking with everything set off: median over maps {walk_median:.2} µs per tick ({:.0} ticks per second), range {lo:.2}..{hi:.2}. Idle: median {:.2} µs; idle / nothing set off: median {:.2}, range {rlo:.2}..{rhi:.2}.",
        rows.len(),
        1e6 / walk_median,
        median(&mut idle),
        median(&mut ratio),
    );
    println!("Timing an empty interval costs {:.3} µs (median), included in every figure above.", timer_overhead());
    let failed: usize = rows.iter().map(|r| r.set.failed.len()).sum();
    let tried: usize = rows.iter().map(|r| r.set.tried_total()).sum();
    println!("\nSpecials tried that did not go off on either pass ({failed} of {tried}):\n");
    for r in rows.iter().filter(|r| !r.set.failed.is_empty()) {
        let failed: Vec<String> =
            r.set.failed.iter().map(|f| format!("{:?} {:?} {} ({:?})", f.line, f.on, f.action, f.why)).collect();
        println!("- {}: {}", r.map, failed.join(", "));
    }
}
