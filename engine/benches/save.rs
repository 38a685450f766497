//! Saved games on the simulation: how big a save is and how long saving and
//! loading take, on the default level and on Freedoom maps mid-fight. Each map is played
//! 1,050 ticks (30 s) from its start by seeded wandering inputs that fire in
//! bursts, the player unkillable, so monsters are awake, chasing and dead;
//! then, over [`ROUNDS`] rounds, each timed on its own: the save's bytes
//! made (`save_bytes`: the state gathered and encoded), the file written
//! (atomically, to a temporary directory), and the save loaded from its
//! bytes (`from_save_bytes`: the map opened afresh and checked, a game
//! started on it and the state decoded, checked and put in place), the
//! state alone put back into the running game (`SimGame::restore` of
//! `SimGame::state_bytes`: decoded and checked, no map opened); and for
//! comparison the map opened and a game started on it, as a new game does.
//! A custom loop, as the world bench's: a load is a whole map opening,
//! hundreds of milliseconds, far beyond what criterion's loop is for.
//! Prints a markdown table of medians, with the bodies in the game (the
//! simulation's live mobjs: monsters, items, missiles, the player).
//!
//! Run: `cargo bench -p sightline-engine --bench save`. Needs Freedoom's
//! WADs (Debian: freedoom), as the other Freedoom benches do.

mod common;

use std::time::Instant;

use common::{doom_dir, median, Wanted};
use sightline::campaign::MapRef;
use sightline::play::input::wander;
use sightline::play::playthrough::Playthrough;
use sightline::play::GameOptions;

const ROUNDS: usize = 15;
const PLAYED: usize = 1_050;

fn main() {
    let wanted = Wanted::from_args();
    let rounds = if wanted.quick { 1 } else { ROUNDS };
    let wad = |name: &str| doom_dir().join(name).display().to_string();
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let maps = [
        root.join("maps/outpost.ron").display().to_string(),
        format!("{}:E1M1", wad("freedoom1.wad")),
        format!("{}:E1M4", wad("freedoom1.wad")),
        format!("{}:MAP01", wad("freedoom2.wad")),
        format!("{}:MAP20", wad("freedoom2.wad")),
    ];
    let dir = std::env::temp_dir().join(format!("sightline-save-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    println!("| map | bodies | save bytes | make (ms) | write (ms) | load (ms) | restore (ms) | new game (ms) |");
    println!("|---|---|---|---|---|---|---|---|");
    for map in maps {
        let map = MapRef::parse(&map, None);
        let options = GameOptions { skill: 3, seed: 1, ..Default::default() };
        let mut play = Playthrough::of(&map, options).unwrap_or_else(|e| panic!("{e}"));
        play.game.set_health(1_000_000);
        for (i, mut input) in wander(5, PLAYED, true).into_iter().enumerate() {
            input.fire = (i / 40) % 3 == 0;
            play.tick(&input).unwrap_or_else(|e| panic!("{e}"));
        }
        let path = dir.join("bench.slsave");
        let (mut make, mut write, mut load, mut restore, mut fresh) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let state = play.game.state_bytes();
        let mut size = 0;
        for _ in 0..rounds {
            let t = Instant::now();
            let bytes = play.save_bytes().unwrap_or_else(|e| panic!("{e}"));
            make.push(t.elapsed().as_secs_f64() * 1e3);
            size = bytes.len();
            let t = Instant::now();
            play.save(&path).unwrap_or_else(|e| panic!("{e}"));
            write.push(t.elapsed().as_secs_f64() * 1e3);
            let t = Instant::now();
            let loaded = Playthrough::from_save_bytes(&bytes, "bench").unwrap_or_else(|e| panic!("{e}"));
            load.push(t.elapsed().as_secs_f64() * 1e3);
            assert!(loaded.game.state_bytes() == state);
            let t = Instant::now();
            play.game.restore(&state, "bench").unwrap_or_else(|e| panic!("{e}"));
            restore.push(t.elapsed().as_secs_f64() * 1e3);
            assert!(play.game.state_bytes() == state);
            let t = Instant::now();
            let new = Playthrough::of(&map, options).unwrap_or_else(|e| panic!("{e}"));
            fresh.push(t.elapsed().as_secs_f64() * 1e3);
            drop(new);
        }
        println!(
            "| {} | {} | {size} | {:.2} | {:.2} | {:.1} | {:.2} | {:.1} |",
            play.map.short_name(),
            play.game.sim.live_mobjs().count(),
            median(&mut make),
            median(&mut write),
            median(&mut load),
            median(&mut restore),
            median(&mut fresh)
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
