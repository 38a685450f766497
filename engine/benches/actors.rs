//! What actors cost per tick on the simulation with Doom's arithmetic
//! (issue 13's benchmarks, ported when the f64 game was deleted). A custom
//! loop: a tick can be timed only once from a given state, so each round
//! builds a fresh [`Sim`] (untimed), sets it up, lets 35 ticks pass
//! untimed, then times each of [`WINDOW`] `Sim::tick`s on its own. The
//! setups of a study run in turn, the order rotating each round; the table
//! gives the median of the per-round medians, so every ratio comes from one
//! run on the same machine state.
//!
//! - **horde**: a generated map (format 2) through `sim::from_map`: a hall
//!   of 100 x 100 zombiemen, 64 units apart, and the player in a room off
//!   the hall behind a shut door; then the same hall with the player in it,
//!   64 units east of the horde, where everything fights.
//! - **freedoom**: E1M1 and the largest map of the two IWADs (MAP12 of
//!   freedoom2.wad by lines), from the IWAD as Doom loads it.
//!
//! Three setups, at skill 4 (Doom's 3), the player standing still in god
//! mode: no monsters (`Rules::no_monsters`, as `-nomonsters`), the
//! monsters dormant (as the map starts them, running `A_Look`), and all
//! awake ([`wake`]: each takes the player as its target and enters its See
//! state, as `A_Look` does on sight).
//!
//! The yardstick (issue 13, `docs/actors-bench.md`) is the f64 game's
//! figures before the change to the one simulation: E1M1 with every
//! monster awake 13.9 µs a tick, and the 10,000-monster hall with the
//! player in it 2.1 ms (2,095.8 µs) a tick; the ticks must be no slower.
//! Each table prints the f64 game's median for the same setup beside the
//! simulation's, from that document (one run, 23 November 2026, the same
//! 2-core VM). Dormant monsters are not parked in the simulation, as they
//! are not in Doom: each polls `A_Look`, so "dormant" costs more than the
//! f64 game's parked monsters did; it is shown, not held to the yardstick.
//!
//! Run: `cargo bench -p sightline-engine --bench actors` (both), or with
//! `-- horde` or `-- freedoom` for one; `--test` for one short round.
//! The Freedoom study needs Freedoom's WADs (Debian: freedoom) in
//! `/usr/share/games/doom` or `$SIGHTLINE_DOOM_DIR`.

mod common;

use std::fmt::Write;
use std::time::Instant;

use common::{extent, median, open_wad, Wanted};

use sightline::actors::ActorTable;
use sightline::bsp::{build, BuildOptions};
use sightline::map::load::parse_map;
use sightline::play::lmp::Ticcmd;
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
        let table = ActorTable::active();
        let horde = |inside: bool| {
            let map = parse_map(&horde_ron(inside), "horde").unwrap_or_else(|e| panic!("{e}"));
            let compiled = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("horde: {e}"));
            let level = from_map::level_from_map(&compiled, table).unwrap_or_else(|e| panic!("{e}"));
            move |rules: Rules| from_map::sim_on_map(level.clone(), rules, solo(), table.clone())
        };
        let rules = sim_rules(GameMode::Commercial);
        study(
            "a hall of 10,000 zombiemen, the player in a room off it behind a shut door",
            &horde(false),
            rules,
            &[(Setup::NoMonsters, Some(0.2)), (Setup::Dormant, Some(0.2)), (Setup::Awake, Some(593.3))],
            rounds,
        );
        study(
            "the same hall with the player in it, 64 units east of the horde",
            &horde(true),
            rules,
            &[(Setup::NoMonsters, Some(0.3)), (Setup::Awake, Some(YARDSTICK_HALL))],
            rounds,
        );
    }
    if wanted.wants("freedoom") {
        for (file, name, before) in
            [("freedoom1.wad", "E1M1", [1.4, 1.5, YARDSTICK_E1M1]), ("freedoom2.wad", "MAP12", [1.9, 19.3, 36.2])]
        {
            let (_, wad) = open_wad(file);
            let mode = sim::demo::game_mode(&wad);
            let table = sim::demo::table_for(&wad, ActorTable::active()).unwrap_or_else(|e| panic!("{e}"));
            let make =
                |rules: Rules| Sim::new(&wad, name, rules, solo(), table.clone()).unwrap_or_else(|e| panic!("{e}"));
            let setups = [Setup::NoMonsters, Setup::Dormant, Setup::Awake];
            let with_before: Vec<(Setup, Option<f64>)> = setups.into_iter().zip(before.map(Some)).collect();
            study(&format!("{file}:{name}"), &make, sim_rules(mode), &with_before, rounds);
        }
    }
}

/// The yardstick (µs a tick): the f64 game's E1M1 with every monster
/// awake, and its 10,000-monster hall with the player in it
/// (`docs/actors-bench.md`).
const YARDSTICK_E1M1: f64 = 13.9;
const YARDSTICK_HALL: f64 = 2095.8;

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Setup {
    NoMonsters,
    Dormant,
    Awake,
}

impl Setup {
    fn name(self) -> &'static str {
        match self {
            Setup::NoMonsters => "no monsters",
            Setup::Dormant => "monsters dormant",
            Setup::Awake => "monsters awake",
        }
    }
}

/// A fresh simulation from `make` for `setup`: monsters left out
/// (`-nomonsters`), as spawned, or all woken, the player in god mode.
fn fresh(make: &impl Fn(Rules) -> Sim, rules: Rules, setup: Setup) -> Sim {
    let mut s = make(Rules { no_monsters: setup == Setup::NoMonsters, ..rules });
    if let Some(p) = s.players[0].as_mut() {
        p.cheats |= 2; // CF_GODMODE
    }
    if setup == Setup::Awake {
        wake(&mut s);
    }
    s
}

/// Times `setups` on the simulations `make` builds, `rounds` times each in
/// rotating order, and prints a markdown table beside the f64 game's
/// figure for each setup (`before`, µs a tick, when there is one).
fn study(what: &str, make: &impl Fn(Rules) -> Sim, rules: Rules, setups: &[(Setup, Option<f64>)], rounds: usize) {
    let mut medians: Vec<Vec<f64>> = vec![Vec::new(); setups.len()];
    let mut census = vec![(0usize, 0usize); setups.len()];
    let idle = [Some(Ticcmd::default()), None, None, None];
    for round in 0..rounds {
        for k in 0..setups.len() {
            let which = (k + round) % setups.len();
            let mut s = fresh(make, rules, setups[which].0);
            for _ in 0..SETTLE {
                s.tick(&idle);
            }
            let mut times = Vec::with_capacity(WINDOW);
            for _ in 0..WINDOW {
                let start = Instant::now();
                s.tick(&idle);
                times.push(start.elapsed().as_secs_f64() * 1e6);
            }
            medians[which].push(median(&mut times));
            let alive =
                s.live_mobjs().filter(|&id| s.mo(id).has(sim::mobj::mf::COUNTKILL) && s.mo(id).health > 0).count();
            census[which] = (alive, s.live_mobjs().count());
        }
    }
    let m: Vec<f64> = medians.iter_mut().map(|v| median(v)).collect();
    println!("\n## {what}: skill 4, {rounds} rounds of {WINDOW} ticks, median of the per-round medians\n");
    println!("| setup | µs per tick | ticks per second | per-round medians | f64 game before (µs) | now / before | monsters alive at the end | bodies a tick runs |");
    println!("|---|---:|---:|---|---:|---:|---:|---:|");
    for (k, (setup, before)) in setups.iter().enumerate() {
        let (lo, hi) = extent(&medians[k]);
        let (alive, bodies) = census[k];
        let (b, ratio) = match before {
            Some(b) => (format!("{b:.1}"), format!("{:.2}", m[k] / b)),
            None => ("-".into(), "-".into()),
        };
        println!(
            "| {} | {:.1} | {:.0} | {lo:.1}..{hi:.1} | {b} | {ratio} | {alive} | {bodies} |",
            setup.name(),
            m[k],
            1e6 / m[k]
        );
    }
    let ratios: Vec<String> =
        (1..setups.len()).map(|k| format!("{} / none = {:.1}", setups[k].0.name(), m[k] / m[0])).collect();
    println!("\n{}", ratios.join("; "));
    for (k, (setup, before)) in setups.iter().enumerate() {
        if let Some(b) = before.filter(|&b| b == YARDSTICK_E1M1 || b == YARDSTICK_HALL) {
            let verdict = if m[k] <= b { "no slower than" } else { "SLOWER than" };
            println!("yardstick: {} {:.1} µs a tick, {verdict} the f64 game's {b:.1}", setup.name(), m[k]);
        }
    }
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

/// `sim` with every monster after the player (each takes the player as
/// its target and enters its See state, as `A_Look` does on sight), and
/// the player in god mode.
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
