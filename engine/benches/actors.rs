//! What actors cost per tick (issue 13's benchmarks). A custom loop, as the
//! world bench's: a tick can be timed only once from a given state (`Game`
//! is not `Clone`), so each round starts a fresh game (untimed), sets it up,
//! lets 35 ticks pass untimed, then times each of [`WINDOW`] ticks on its
//! own. The setups of a study run in turn, the order rotating each round;
//! the table gives the median of the per-round medians, so every ratio
//! comes from one run on the same machine state.
//!
//! - **horde**: a generated map (format 2): a hall of 100 x 100 zombiemen,
//!   64 units apart, and the player in a room off the hall behind a shut
//!   door.
//!   Three setups: no monsters (the same things turned into markers, which
//!   do not spawn), the monsters dormant (as the map starts them: waiting
//!   for the player, whom they cannot see or hear through the shut door:
//!   parked), and all awake
//!   (`Game::wake_monsters`: each chases the player and tries to shoot).
//! - **freedoom**: E1M1 and the largest map of the two IWADs (MAP12 of
//!   freedoom2.wad by lines), skill 4, the player standing at the start,
//!   too tough to die: no monsters, dormant, and all awake.
//! - **before and after** (each map above): the f64 game (`Game`) against
//!   the simulation with Doom's arithmetic (`sim::Sim`, the horde through
//!   `sim::from_map`), dormant and awake, interleaved within each round.
//!
//! Run: `cargo bench -p sightline-engine --bench actors` (both), or with
//! `-- horde` or `-- freedoom` for one; `--test` for one short round.
//! The Freedoom study needs Freedoom's WADs (Debian: freedoom) in
//! `/usr/share/games/doom` or `$SIGHTLINE_DOOM_DIR`.

mod common;

use std::fmt::Write;
use std::time::Instant;

use common::{extent, median, open_wad, wad_library, Wanted};

use sightline::actors::{ActorFlag, ActorTable};
use sightline::bsp::{build, BuildOptions};
use sightline::campaign::{open, MapRef};
use sightline::level::Level;
use sightline::map::load::parse_map;
use sightline::materials::Materials;
use sightline::play::{Game, GameOptions, TickInput};
use sightline::sim::{self, from_map, GameMode, Rules, Sim};

/// Ticks timed per round.
const WINDOW: usize = 105;
/// Untimed ticks before the window (the awake monsters spread out).
const SETTLE: usize = 35;
const ROUNDS: usize = 7;
/// Zombiemen across and down the hall, and their spacing.
const HORDE: usize = 100;
const SPACING: f64 = 64.0;

fn main() {
    let wanted = Wanted::from_args();
    let rounds = if wanted.quick { 1 } else { ROUNDS };
    if wanted.wants("horde") {
        let horde = |inside: bool| {
            let map = parse_map(&horde_ron(inside), "horde").unwrap_or_else(|e| panic!("{e}"));
            let compiled = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("horde: {e}"));
            move || Level::with_builtin_textures(compiled.clone()).unwrap_or_else(|e| panic!("{e}"))
        };
        study(
            "a hall of 10,000 zombiemen, the player in a room off it behind a shut door",
            &horde(false),
            &SETUPS,
            rounds,
        );
        let fighting = [Setup::NoMonsters, Setup::Awake];
        study("the same hall with the player in it, 64 units east of the horde", &horde(true), &fighting, rounds);
        for inside in [false, true] {
            let map = parse_map(&horde_ron(inside), "horde").unwrap_or_else(|e| panic!("{e}"));
            let compiled = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("horde: {e}"));
            let doom = from_map::level_from_map(&compiled, ActorTable::active()).unwrap_or_else(|e| panic!("{e}"));
            let place = if inside { "the player in the hall" } else { "the player behind the shut door" };
            versus(
                &format!("the horde hall, {place}"),
                &|| Level::with_builtin_textures(compiled.clone()).unwrap_or_else(|e| panic!("{e}")),
                || {
                    sim::from_map::sim_on_map(
                        doom.clone(),
                        sim_rules(GameMode::Commercial),
                        solo(),
                        ActorTable::active().clone(),
                    )
                },
                rounds,
            );
        }
    }
    if wanted.wants("freedoom") {
        for (file, name) in [("freedoom1.wad", "E1M1"), ("freedoom2.wad", "MAP12")] {
            let (path, wad) = open_wad(file);
            let library = wad_library(wad);
            let label = format!("{}:{name}", path.display());
            let opened = open(&MapRef::parse(&label, None), &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
            let compiled = opened.level.compiled;
            // A fresh level as `open` makes it, without compiling again.
            let level = || {
                let materials =
                    Materials::resolve_in(&compiled.map, &library, &label).unwrap_or_else(|e| panic!("{e}"));
                Level::new(compiled.clone(), materials)
            };
            study(&format!("{file}:{name}"), &level, &SETUPS, rounds);
            let doom_wad = sightline::wad::Wad::open(&path).unwrap_or_else(|e| panic!("{e}"));
            let mode = sim::demo::game_mode(&doom_wad);
            let table = sim::demo::table_for(&doom_wad, ActorTable::active()).unwrap_or_else(|e| panic!("{e}"));
            let make =
                || Sim::new(&doom_wad, name, sim_rules(mode), solo(), table.clone()).unwrap_or_else(|e| panic!("{e}"));
            versus(&format!("{file}:{name}"), &level, make, rounds);
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Setup {
    NoMonsters,
    Dormant,
    Awake,
}

const SETUPS: [Setup; 3] = [Setup::NoMonsters, Setup::Dormant, Setup::Awake];

/// A fresh game on `level` at skill 4 for `setup`, with the player unable
/// to die and (awake) every monster after it.
fn game(mut level: Level, setup: Setup) -> Game {
    if setup == Setup::NoMonsters {
        let table = ActorTable::active();
        for t in &mut level.compiled.map.things {
            if table.get(&t.kind).is_some_and(|a| a.has(ActorFlag::CountKill)) {
                t.kind = "deathmatch_start".into();
            }
        }
    }
    let mut game = Game::with_options(level, GameOptions { skill: 4, seed: 1, ..Default::default() })
        .unwrap_or_else(|e| panic!("{e}"));
    game.player_mut().health = 1_000_000;
    if setup == Setup::Awake {
        game.wake_monsters();
    }
    game
}

/// Times the three setups on `level`, `rounds` times each in rotating
/// order, and prints a markdown table.
fn study(what: &str, level: &impl Fn() -> Level, setups: &[Setup], rounds: usize) {
    let mut medians: Vec<Vec<f64>> = vec![Vec::new(); setups.len()];
    let mut census = vec![(0usize, 0usize, 0usize); setups.len()];
    let still = TickInput::default();
    for round in 0..rounds {
        for k in 0..setups.len() {
            let which = (k + round) % setups.len();
            let mut game = game(level(), setups[which]);
            for _ in 0..SETTLE {
                game.tick(&still);
            }
            let mut times = Vec::with_capacity(WINDOW);
            for _ in 0..WINDOW {
                let start = Instant::now();
                game.tick(&still);
                times.push(start.elapsed().as_secs_f64() * 1e6);
            }
            medians[which].push(median(&mut times));
            let alive = game.actors().list.iter().filter(|a| a.health > 0 && a.flags.has(ActorFlag::CountKill)).count();
            census[which] = (alive, game.actors().awake(), game.actors().parked());
        }
    }
    let m: Vec<f64> = medians.iter_mut().map(|v| median(v)).collect();
    let spread = |v: &[f64]| {
        let (lo, hi) = extent(v);
        format!("{lo:.1}..{hi:.1}")
    };
    println!("\n## {what}: skill 4, {rounds} rounds of {WINDOW} ticks, median of the per-round medians\n");
    println!("| setup | µs per tick | ticks per second | monsters alive at the end | actors a tick visits | parked |");
    println!("|---|---:|---:|---:|---:|---:|");
    for (k, setup) in setups.iter().enumerate() {
        let name = match setup {
            Setup::NoMonsters => "no monsters",
            Setup::Dormant => "monsters dormant",
            Setup::Awake => "monsters awake",
        };
        let (monsters, visited, parked) = census[k];
        println!("| {name} | {:.1} | {:.0} | {monsters} | {visited} | {parked} |", m[k], 1e6 / m[k]);
    }
    if setups.len() < 3 {
        println!(
            "\nawake / none = {:.1}; per-round medians: none {}, awake {}",
            m[1] / m[0],
            spread(&medians[0]),
            spread(&medians[1])
        );
        return;
    }
    println!(
        "\ndormant / none = {:.3}; awake / none = {:.1}; per-round medians: none {}, dormant {}, awake {}",
        m[1] / m[0],
        m[2] / m[0],
        spread(&medians[0]),
        spread(&medians[1]),
        spread(&medians[2])
    );
}

/// The horde map's RON text: the hall (sector 0) with its zombiemen facing
/// east, towards the player's room (sector 2), which opens off the hall's
/// east wall through a shut door (sector 1, 16 deep, a manual door anyone
/// may open); or (`inside`) the player in the hall, 64 units east of the
/// last column.
fn horde_ron(inside: bool) -> String {
    let side = HORDE as f64 * SPACING + SPACING;
    let (mid, door, room) = (side / 2.0, 16.0, 256.0);
    let (dx, rx) = (side + door, side + door + room);
    let mut text = String::from("Map(\n    version: 2,\n    name: \"Horde\",\n    vertices: [\n");
    let vertices = [
        (0.0, 0.0),             // 0: the hall, clockwise from the south-west
        (0.0, side),            // 1
        (side, side),           // 2
        (side, mid + 32.0),     // 3: the door's north-west corner
        (side, mid - 32.0),     // 4: its south-west corner
        (side, 0.0),            // 5
        (dx, mid + 32.0),       // 6: the door's north-east corner
        (dx, mid - 32.0),       // 7: its south-east corner
        (dx, mid + room / 2.0), // 8: the room
        (rx, mid + room / 2.0), // 9
        (rx, mid - room / 2.0), // 10
        (dx, mid - room / 2.0), // 11
    ];
    for (x, y) in vertices {
        writeln!(text, "        ({x:.1}, {y:.1}),").unwrap();
    }
    text.push_str("    ],\n    sectors: [\n");
    for ceiling in [128.0, 0.0, 128.0] {
        writeln!(
            text,
            "        Sector(floor: 0.0, ceiling: {ceiling:.1}, light: 160, floor_texture: \"FLOOR\", ceiling_texture: \"CEIL\"),"
        )
        .unwrap();
    }
    text.push_str("    ],\n    lines: [\n");
    let door_line = "special: LineSpecial(on: Use, repeat: true, by: Anyone, action: Door(kind: Raise))";
    // The inside is on each line's right.
    for (from, to, front, back) in [
        (0, 1, 0, None),
        (1, 2, 0, None),
        (2, 3, 0, None),
        (3, 4, 0, Some(1)),
        (4, 5, 0, None),
        (5, 0, 0, None),
        (3, 6, 1, None),
        (7, 4, 1, None),
        (7, 6, 2, Some(1)),
        (6, 8, 2, None),
        (8, 9, 2, None),
        (9, 10, 2, None),
        (10, 11, 2, None),
        (11, 7, 2, None),
    ] {
        match back {
            None => writeln!(
                text,
                "        Line(from: {from}, to: {to}, front: Side(sector: {front}, middle: \"STONE\")),"
            ),
            Some(b) => writeln!(
                text,
                "        Line(from: {from}, to: {to}, front: Side(sector: {front}, upper: \"DOOR\"), back: Some(Side(sector: {b}, upper: \"DOOR\")), {door_line}),"
            ),
        }
        .unwrap();
    }
    text.push_str("    ],\n    things: [\n");
    let start = if inside { (side - SPACING / 2.0, mid) } else { (rx - room / 2.0, mid) };
    writeln!(text, "        Thing(kind: \"player_start\", x: {:.1}, y: {:.1}, angle: 180.0),", start.0, start.1)
        .unwrap();
    for j in 0..HORDE {
        for i in 0..HORDE {
            let (x, y) = ((i + 1) as f64 * SPACING, (j + 1) as f64 * SPACING);
            writeln!(text, "        Thing(kind: \"zombieman\", x: {x:.1}, y: {y:.1}, angle: 0.0),").unwrap();
        }
    }
    text.push_str("    ],\n)\n");
    text
}

/// Doom's rules at skill 4 (Doom's number 3), as a demo of `mode` plays.
fn sim_rules(mode: GameMode) -> Rules {
    Rules::single(3, sim::demo::game_version(mode), mode)
}

fn solo() -> sim::setup::Players {
    sim::setup::Players { in_game: [true, false, false, false], console: 0 }
}

/// `sim` with every monster after the player, as `Game::wake_monsters`
/// wakes the f64 game's (each takes the player as its target and enters
/// its See state, as A_Look does on sight), and the player in god mode.
fn wake(sim: &mut Sim) {
    let Some(player) = sim.player(0).map(|p| p.mo) else { return };
    if let Some(p) = sim.players[0].as_mut() {
        p.cheats |= 2; // CF_GODMODE
    }
    let monsters: Vec<_> = sim.live_mobjs().filter(|&id| sim.mo(id).has(sim::mobj::mf::COUNTKILL)).collect();
    for id in monsters {
        sim.mo_mut(id).target = Some(player);
        let see = sim.info.things[sim.mo(id).kind].seestate;
        sim.set_mobj_state(id, see);
    }
}

/// The same map's ticks in the f64 game (`Game`, today's) and in the
/// simulation with Doom's arithmetic (`Sim`), monsters dormant and awake,
/// interleaved within each round; the median of the per-round medians.
fn versus(what: &str, level: &impl Fn() -> Level, make: impl Fn() -> Sim, rounds: usize) {
    let names = ["f64 game, dormant", "f64 game, awake", "Doom arithmetic, dormant", "Doom arithmetic, awake"];
    let mut medians: Vec<Vec<f64>> = vec![Vec::new(); names.len()];
    let still = TickInput::default();
    let idle = [Some(sightline::play::lmp::Ticcmd::default()), None, None, None];
    for round in 0..rounds {
        for k in 0..names.len() {
            let which = (k + round) % names.len();
            let mut times = Vec::with_capacity(WINDOW);
            if which < 2 {
                let mut g = game(level(), if which == 0 { Setup::Dormant } else { Setup::Awake });
                for _ in 0..SETTLE {
                    g.tick(&still);
                }
                for _ in 0..WINDOW {
                    let start = Instant::now();
                    g.tick(&still);
                    times.push(start.elapsed().as_secs_f64() * 1e6);
                }
            } else {
                let mut s = make();
                if which == 3 {
                    wake(&mut s);
                }
                for _ in 0..SETTLE {
                    s.tick(&idle);
                }
                for _ in 0..WINDOW {
                    let start = Instant::now();
                    s.tick(&idle);
                    times.push(start.elapsed().as_secs_f64() * 1e6);
                }
            }
            medians[which].push(median(&mut times));
        }
    }
    let m: Vec<f64> = medians.iter_mut().map(|v| median(v)).collect();
    println!(
        "\n## {what}, before and after: skill 4, {rounds} rounds of {WINDOW} ticks, median of the per-round medians\n"
    );
    println!("| game | µs per tick | per-round medians |");
    println!("|---|---:|---|");
    for (k, name) in names.iter().enumerate() {
        let (lo, hi) = extent(&medians[k]);
        println!("| {name} | {:.1} | {lo:.1}..{hi:.1} |", m[k]);
    }
    println!("\nDoom arithmetic / f64: dormant {:.2}x, awake {:.2}x", m[2] / m[0], m[3] / m[1]);
}
