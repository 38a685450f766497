//! Freedoom's eight vanilla demos on the simulation with Doom's arithmetic,
//! each tic compared with Chocolate Doom's dump of the same demo
//! (`tests/fixtures/demo-dumps/`, made by `scripts/chocolate-demo-dumps.sh`):
//! the `P_Random` index, the player, a hash of every body and of every
//! sector must agree after every one of the 22,637 tics. A run prints how
//! far each got and, on a desync, the first tic and the fields that differ.

use std::path::Path;

use sightline::actors::ActorTable;
use sightline::play::lmp::VanillaDemo;
use sightline::play::syncdump::SyncDump;
use sightline::sim::demo;
use sightline::wad::Wad;
use sightline_tests::freedoom_wads;

/// (IWAD, lump, the tics it holds).
const DEMOS: [(&str, &str, usize); 8] = [
    ("freedoom1", "DEMO1", 1531),
    ("freedoom1", "DEMO2", 2763),
    ("freedoom1", "DEMO3", 1241),
    ("freedoom1", "DEMO4", 6467),
    ("freedoom2", "DEMO1", 1415),
    ("freedoom2", "DEMO2", 4785),
    ("freedoom2", "DEMO3", 2593),
    ("freedoom2", "DEMO4", 1842),
];

fn run(iwad: &str, lump: &str) -> demo::SyncReport {
    let wad = Wad::open(&freedoom_wads::path(&format!("{iwad}.wad"))).expect("the IWAD opens");
    let index = wad.find(lump).expect("the IWAD has the demo");
    let demo = VanillaDemo::from_bytes(wad.bytes(index), &format!("{iwad}.wad:{lump}")).expect("the demo reads");
    let dump_path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("fixtures/demo-dumps/{iwad}-{lump}.txt"));
    let dump = SyncDump::load(&dump_path).expect("the dump reads");
    let table = demo::table_for(&wad, ActorTable::doom()).expect("the IWAD's DEHACKED applies");
    let sim = demo::start(&wad, &demo, table).expect("the demo's game starts");
    demo::check(&mut demo::DemoGame::new(std::sync::Arc::new(wad), sim), &demo, &dump)
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "Freedoom's IWADs are missing: apt-get install freedoom")]
fn freedoom_demos_stay_in_sync() {
    let mut short = Vec::new();
    for (iwad, lump, tics) in DEMOS {
        let report = run(iwad, lump);
        match &report.first_difference {
            None => println!("{iwad} {lump}: in sync for all {} tics", report.tics),
            Some((tic, diffs)) => {
                let fields: Vec<String> = diffs.iter().take(6).map(ToString::to_string).collect();
                println!(
                    "{iwad} {lump}: in sync {} of {} tics; tic {tic}: {}",
                    report.in_sync,
                    report.tics,
                    fields.join("; ")
                );
            }
        }
        if report.in_sync != tics || report.tics != tics {
            short.push(format!("{iwad} {lump}: {} of {} tics in sync, {tics} expected", report.in_sync, report.tics));
        }
    }
    assert!(short.is_empty(), "{}", short.join("\n"));
}

/// Games across an intermission, on the level tics Chocolate Doom dumped.
/// `freedoom1-autopilot-e1m1-e1m2`: the autopilot at skill 2, E1M1 to its
/// exit, the intermission pressed through, E1M2 until it dies (recorded by
/// `sightline autoplay --levels 3 --record`). `freedoom1-coop-e1m1-e1m2`: a
/// co-op game of two, the first player's commands the autopilot's E1M1 run
/// without monsters, the second idle, then the netgame's intermission
/// (fire held by one, use by the other, the episode map left to time out)
/// and 100 tics of E1M2. Each line's gametic counts the intermission's
/// tics, so a tic too many or too few there shows on E1M2's first tic; the
/// players, the random index and every body carried into E1M2 are compared
/// from there on.
#[test]
#[cfg_attr(freedoom_missing, ignore = "Freedoom's IWADs are missing: apt-get install freedoom")]
fn demos_across_an_intermission_stay_in_sync() {
    let fixtures = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/demo-dumps");
    for (name, tics, lines) in [("freedoom1-autopilot-e1m1-e1m2", 8447, 8431), ("freedoom1-coop-e1m1-e1m2", 1993, 1697)]
    {
        let wad = Wad::open(&freedoom_wads::path("freedoom1.wad")).expect("the IWAD opens");
        let bytes = std::fs::read(fixtures.join(format!("{name}.lmp"))).expect("the demo is there");
        let demo = VanillaDemo::from_bytes(&bytes, name).expect("the demo reads");
        let dump = SyncDump::load(&fixtures.join(format!("{name}.txt"))).expect("the dump reads");
        let table = demo::table_for(&wad, ActorTable::doom()).expect("DEHACKED applies");
        let sim = demo::start(&wad, &demo, table).expect("starts");
        let mut game = demo::DemoGame::new(std::sync::Arc::new(wad), sim);
        let report = demo::check(&mut game, &demo, &dump);
        if let Some((tic, diffs)) = &report.first_difference {
            let fields: Vec<String> = diffs.iter().take(6).map(ToString::to_string).collect();
            panic!("{name}: in sync {} of {} tics; tic {tic}: {}", report.in_sync, report.tics, fields.join("; "));
        }
        // Both levels were played, and the intermission between them.
        assert_eq!((game.sim.level.name.as_str(), report.tics, dump.tics.len()), ("E1M2", tics, lines), "{name}");
    }
}

/// Netgames against Chocolate Doom: four players of seeded random commands
/// (`scripts/random-demo.py`), co-op on freedoom1's E1M1 at skill 5 (12
/// deaths, each a player's use and a rebirth at a start) and deathmatch on
/// freedoom2's MAP07 (34 deaths, each rebirth at a random deathmatch start,
/// frags), 3,000 tics each, every player compared every tic.
#[test]
#[cfg_attr(freedoom_missing, ignore = "Freedoom's IWADs are missing: apt-get install freedoom")]
fn four_player_coop_and_deathmatch_stay_in_sync() {
    let fixtures = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/demo-dumps");
    for (iwad, name) in [("freedoom1", "freedoom1-random-coop4"), ("freedoom2", "freedoom2-random-dm4")] {
        let wad = Wad::open(&freedoom_wads::path(&format!("{iwad}.wad"))).expect("the IWAD opens");
        let bytes = std::fs::read(fixtures.join(format!("{name}.lmp"))).expect("the demo is there");
        let demo = VanillaDemo::from_bytes(&bytes, name).expect("the demo reads");
        assert_eq!(demo.header.players(), 4, "{name}");
        let dump = SyncDump::load(&fixtures.join(format!("{name}.txt"))).expect("the dump reads");
        let table = demo::table_for(&wad, ActorTable::doom()).expect("DEHACKED applies");
        let sim = demo::start(&wad, &demo, table).expect("starts");
        let report = demo::check(&mut demo::DemoGame::new(std::sync::Arc::new(wad), sim), &demo, &dump);
        if let Some((tic, diffs)) = &report.first_difference {
            let fields: Vec<String> = diffs.iter().take(6).map(ToString::to_string).collect();
            panic!("{name}: in sync {} of {} tics; tic {tic}: {}", report.in_sync, report.tics, fields.join("; "));
        }
        assert_eq!(report.in_sync, 3000, "{name}");
    }
}

/// The tic (from 1) whose `P_Random` draws first read entry `index`,
/// from the dump's cursor after each tic (the cursor before tic 1 is the
/// one level set-up left, which `demo::start` reproduces).
fn first_draw(start: u8, dump: &SyncDump, index: u8) -> Option<usize> {
    let mut before = start;
    for (t, tic) in dump.tics.iter().enumerate() {
        let after = tic.rnd?;
        let draws = after.wrapping_sub(before);
        if (1..=draws).any(|k| before.wrapping_add(k) == index) {
            return Some(t + 1);
        }
        before = after;
    }
    None
}

/// One wrong number in Doom's random table (every bit of one entry
/// flipped) puts the game out of sync, never before the tic that first
/// reads it, and for most draws on that very tic: the check catches a single
/// bad draw and names where.
#[test]
#[cfg_attr(freedoom_missing, ignore = "Freedoom's IWADs are missing: apt-get install freedoom")]
fn a_changed_random_entry_is_caught_where_it_is_read() {
    // MAP26's flickering lights show a changed draw in the same tic's
    // light levels; a draw that feeds only hidden state (a monster's
    // movecount, a light's countdown) shows later, when it moves something.
    let wad = std::sync::Arc::new(Wad::open(&freedoom_wads::path("freedoom2.wad")).expect("the IWAD opens"));
    let demo = VanillaDemo::from_bytes(wad.bytes(wad.find("DEMO4").expect("DEMO4")), "DEMO4").expect("reads");
    let dump_path = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/demo-dumps/freedoom2-DEMO4.txt");
    let dump = SyncDump::load(&dump_path).expect("the dump reads");
    let table = demo::table_for(&wad, ActorTable::doom()).expect("DEHACKED applies");
    let start = demo::start(&wad, &demo, table.clone()).expect("starts").rng.p_index();
    let mut checked = 0;
    // Entries first read during play, not during level set-up.
    for index in (0..=255u8).filter(|&i| i.wrapping_sub(start) > 0 && i.wrapping_sub(start) < 40) {
        let Some(expected) = first_draw(start, &dump, index) else { continue };
        let mut sim = demo::start(&wad, &demo, table.clone()).expect("starts");
        // Every bit flipped, so a draw taken modulo or masked changes too.
        let changed = !sightline::fixed::RNDTABLE[usize::from(index)];
        sim.rng = sim.rng.with_altered_entry(index, changed);
        let report = demo::check(&mut demo::DemoGame::new(wad.clone(), sim), &demo, &dump);
        let (tic, diffs) = report.first_difference.expect("a changed random number must show");
        assert!(tic >= expected, "entry {index}: a difference at tic {tic}, before its first draw at tic {expected}");
        if tic == expected {
            checked += 1;
        } else {
            println!("entry {index}: first read at tic {expected}, shows at tic {tic}: {}", diffs[0]);
        }
    }
    assert!(checked >= 10, "only {checked} changed entries showed on the tic that reads them");
}

/// The simulation never panics: every Freedoom map with its monsters, the
/// player fed random commands (seeded) for 1,000 tics.
#[test]
#[cfg_attr(freedoom_missing, ignore = "Freedoom's IWADs are missing: apt-get install freedoom")]
fn random_commands_on_every_map_never_panic() {
    use sightline::play::lmp::{DemoHeader, Ticcmd};
    for iwad in ["freedoom1", "freedoom2"] {
        let wad = Wad::open(&freedoom_wads::path(&format!("{iwad}.wad"))).expect("the IWAD opens");
        let table = demo::table_for(&wad, ActorTable::doom()).expect("DEHACKED applies");
        for name in wad.map_names() {
            let (episode, map) = match name.strip_prefix("MAP") {
                Some(n) => (1, n.parse().expect("MAPnn")),
                None => (name[1..2].parse().expect("ExMy"), name[3..4].parse().expect("ExMy")),
            };
            let demo = VanillaDemo::new(DemoHeader::single(3, episode, map));
            let mut sim = demo::start(&wad, &demo, table.clone()).unwrap_or_else(|e| panic!("{iwad} {name}: {e}"));
            let mut seed = 0x2545_f491_u32 ^ u32::from(map) << 8 ^ u32::from(episode);
            for _ in 0..1000 {
                seed ^= seed << 13;
                seed ^= seed >> 17;
                seed ^= seed << 5;
                let b = seed.to_le_bytes();
                let cmd = Ticcmd {
                    forward: (b[0] as i8).clamp(-50, 50),
                    side: (b[1] as i8).clamp(-40, 40),
                    turn: i16::from(b[2] as i8) << 6,
                    buttons: b[3] & 0x3f,
                };
                let mut cmds = [None; sightline::sim::MAXPLAYERS];
                cmds[0] = Some(cmd);
                sim.tick(&cmds);
            }
        }
    }
}

/// A vanilla demo may carry four players: each is a body of its own,
/// driven by its own commands, in co-op and in deathmatch (at the
/// deathmatch starts, with every key).
#[test]
#[cfg_attr(freedoom_missing, ignore = "Freedoom's IWADs are missing: apt-get install freedoom")]
fn four_players_each_move_by_their_own_commands() {
    use sightline::play::lmp::{DemoHeader, Ticcmd};
    let wad = Wad::open(&freedoom_wads::path("freedoom2.wad")).expect("the IWAD opens");
    let table = demo::table_for(&wad, ActorTable::doom()).expect("DEHACKED applies");
    for deathmatch in [0, 2] {
        let mut header = DemoHeader::single(2, 1, 1);
        header.in_game = [true; 4];
        header.deathmatch = deathmatch;
        let mut demo = VanillaDemo::new(header);
        // Player k runs forward and turns its own way.
        for _ in 0..70 {
            for k in 0..4i16 {
                demo.commands.push(Ticcmd { forward: 50, side: 0, turn: (k - 2) * 256, buttons: 0 });
            }
        }
        let bytes = demo.to_bytes();
        let demo = VanillaDemo::from_bytes(&bytes, "four.lmp").expect("reads back");
        assert_eq!(demo.tics(), 70);
        let mut sim = demo::start(&wad, &demo, table.clone()).expect("starts");
        let start: Vec<_> = sim.players.iter().map(|p| p.as_ref().map(|p| (sim.mo(p.mo).x, sim.mo(p.mo).y))).collect();
        let bodies: Vec<_> = sim.players.iter().flatten().map(|p| p.mo).collect();
        assert_eq!(bodies.len(), 4, "deathmatch {deathmatch}: four bodies");
        for t in 0..demo.tics() {
            sim.tick(&demo::commands(&demo, t));
        }
        for (k, p) in sim.players.iter().enumerate().take(4) {
            let p = p.as_ref().expect("in the game");
            let now = (sim.mo(p.mo).x, sim.mo(p.mo).y);
            assert_ne!(Some(now), start[k], "deathmatch {deathmatch}: player {k} did not move");
            assert_eq!(sim.mo(p.mo).player, Some(k));
            if deathmatch != 0 {
                assert!(p.cards.iter().all(|&c| c), "deathmatch gives every key");
            }
        }
        let angles: std::collections::HashSet<u32> = bodies.iter().map(|&b| sim.mo(b).angle.0).collect();
        assert!(angles.len() > 1, "each turned by its own command");
    }
}
