//! Ours in theirs: the autopilot plays Freedoom's first nine maps of each
//! IWAD with monsters at skill 2 on the simulation with Doom's arithmetic;
//! every map it exits is written as a vanilla demo (`.lmp`, version 109),
//! Chocolate Doom plays it headless, and its `-statdump` must give the
//! intermission we give: kills, items and secrets of their totals, and the
//! time. A demo that drifted from Doom's game by one tic would not reach
//! the exit in Chocolate at all. The table of results is printed.
//!
//! Without Chocolate these tests say so and pass, unless
//! `SIGHTLINE_REQUIRE_CHOCOLATE=1` (CI); without Freedoom's WADs they are
//! ignored, as the other Freedoom suites are.

use sightline::autopilot::{self, observe::Observe};
use sightline::bsp::BuildOptions;
use sightline::campaign::{open, MapRef};
use sightline::play::statdump::{Clock, Tally};
use sightline::play::{vanilla, GameOptions, TickInput};
use sightline::sim::game::SimGame;
use sightline_tests::chocolate;
use sightline_tests::freedoom_wads;

/// A map's run, as we tallied it and as Chocolate did.
struct Row {
    map: String,
    exited: bool,
    ours: String,
    theirs: String,
}

/// Plays `maps` of `iwad`; each exit's demo goes through Chocolate. Returns
/// the rows; panics on the first map whose tallies differ.
fn round_trip(iwad: &str, maps: &[&str]) -> Vec<Row> {
    let path = freedoom_wads::path(iwad);
    let dir = tempfile::tempdir().unwrap();
    let options = GameOptions { skill: 2, seed: 0, no_monsters: false };
    let mut rows = Vec::new();
    for &name in maps {
        let map = MapRef::Wad { wads: vec![path.clone()], map: Some(name.to_string()) };
        let opened = open(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{name}: {e}"));
        let mut game = SimGame::new(opened, options).unwrap_or_else(|e| panic!("{e}"));
        let (outcome, _) = autopilot::run_sim(&mut game, 42_000, |_, _| true);
        let stats = Observe::stats(&game);
        let ours = format!(
            "{}/{} {}/{} {}/{} {}",
            stats.kills.0,
            stats.kills.1,
            stats.items.0,
            stats.items.1,
            stats.secrets.0,
            stats.secrets.1,
            clock(Clock::from_tics(stats.ticks as i32))
        );
        if outcome.exit.is_none() {
            rows.push(Row { map: name.into(), exited: false, ours, theirs: "-".into() });
            continue;
        }
        // Doom completes the level at the start of the next tic: one idle
        // tic more takes Chocolate's player to the intermission.
        let mut inputs = outcome.inputs.clone();
        inputs.push(TickInput::default());
        let demo = vanilla::demo_of(name, options, &inputs).unwrap();
        assert_eq!(&demo.commands[..game.commands().len()], game.commands(), "{name}: the file keeps what was played");
        let lmp = dir.path().join(format!("autopilot-{name}.lmp"));
        demo.save(&lmp).unwrap();
        let played = chocolate::play(&path, &lmp).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(played.levels.len(), 1, "{name}: Chocolate finished {} levels", played.levels.len());
        let level = &played.levels[0];
        assert!(level.level.could_be(name), "{name}: Chocolate's statdump names {}", level.level);
        let p = &level.players[0];
        let tally = |t: Tally| match t {
            Tally::Counted { found, total } => format!("{found}/{total}"),
            Tally::NoneInLevel => "0/0".into(),
        };
        let theirs = format!("{} {} {} {}", tally(p.kills), tally(p.items), tally(p.secrets), clock(level.time));
        assert_eq!(ours, theirs, "{name}: our intermission (left) against Chocolate Doom's statdump (right)");
        let kills = (stats.kills.0 as i32, stats.kills.1 as i32);
        assert_eq!(p.kills, Tally::of(kills.0, kills.1), "{name}");
        rows.push(Row { map: name.into(), exited: true, ours, theirs });
    }
    eprintln!("{iwad}, skill 2, monsters: kills items secrets time, ours | Chocolate's");
    for r in &rows {
        let how = if r.exited { "exited" } else { "did not exit" };
        eprintln!("  {:6} {:13} {:24} | {}", r.map, how, r.ours, r.theirs);
    }
    rows
}

fn clock(c: Clock) -> String {
    format!("{}:{:02}", c.minutes, c.seconds)
}

/// The autopilot's exits on the simulation today (`sightline autoplay`):
/// a change that loses one shows here. freedoom1: at least 7 (E1M1, E1M2,
/// E1M3, E1M4, E1M5, E1M7, E1M9); freedoom2: MAP01, MAP03, MAP04, MAP07,
/// MAP08 (MAP05 was lost with the ways back and the stairs foretold: the
/// bot now dies there with 43 of 51 kills). Together 12 of the 18, the
/// issue's floor. (Fights in Doom's rules are chaotic: a change anywhere
/// in the bot moves which maps it survives, so a drop here is worth a
/// look, not always a bug.)
const FREEDOOM1_EXITS: usize = 7;
const FREEDOOM2_EXITS: usize = 5;

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
#[cfg_attr(
    not(freedoom_missing),
    ignore = "long suite (played again in Chocolate Doom): scripts/long-suites.sh runs it, as CI does"
)]
fn freedoom1_exits_play_to_the_same_intermission_in_chocolate_doom() {
    if !chocolate::present_or_skip("freedoom1_exits_play_to_the_same_intermission_in_chocolate_doom") {
        return;
    }
    let maps = ["E1M1", "E1M2", "E1M3", "E1M4", "E1M5", "E1M6", "E1M7", "E1M8", "E1M9"];
    let rows = round_trip("freedoom1.wad", &maps);
    let exits = rows.iter().filter(|r| r.exited).count();
    assert!(exits >= FREEDOOM1_EXITS, "the autopilot exited {exits} of freedoom1's first nine maps");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
#[cfg_attr(
    not(freedoom_missing),
    ignore = "long suite (played again in Chocolate Doom): scripts/long-suites.sh runs it, as CI does"
)]
fn freedoom2_exits_play_to_the_same_intermission_in_chocolate_doom() {
    if !chocolate::present_or_skip("freedoom2_exits_play_to_the_same_intermission_in_chocolate_doom") {
        return;
    }
    let maps = ["MAP01", "MAP02", "MAP03", "MAP04", "MAP05", "MAP06", "MAP07", "MAP08", "MAP09"];
    let rows = round_trip("freedoom2.wad", &maps);
    let exits = rows.iter().filter(|r| r.exited).count();
    assert!(exits >= FREEDOOM2_EXITS, "the autopilot exited {exits} of freedoom2's first nine maps");
}

/// A game across an intermission, recorded as the window records one: the
/// autopilot exits freedoom1's E1M1 (monsters off), the intermission is
/// pressed through at irregular times (a press while the tallies count, use
/// held, a press on the finished tallies, one on the episode's map), the
/// autopilot exits E1M2 too, and Chocolate Doom plays the one demo through
/// both levels: its statdump gives both our intermissions. A tic's
/// difference in how long our intermission lasted would start E1M2 out of
/// step, and the bot's inputs would not reach its exit in Chocolate.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn a_game_recorded_across_an_intermission_plays_on_in_chocolate_doom() {
    use sightline::play::playthrough::{Phase, Playthrough};
    if !chocolate::present_or_skip("a_game_recorded_across_an_intermission_plays_on_in_chocolate_doom") {
        return;
    }
    let path = freedoom_wads::path("freedoom1.wad");
    let options = GameOptions { skill: 3, seed: 0, no_monsters: true };
    let map = MapRef::Wad { wads: vec![path.clone()], map: Some("E1M1".into()) };
    let mut play = Playthrough::of(&map, options).unwrap_or_else(|e| panic!("{e}"));
    let mut carry = 0.0;
    let mut inputs = Vec::new();
    let mut ours = Vec::new();
    for level in ["E1M1", "E1M2"] {
        assert_eq!(play.map.short_name(), level);
        let (outcome, _) =
            autopilot::run_through(&mut play, 42_000, |i| vanilla::as_recorded(&i, &mut carry), |_, _| true).unwrap();
        assert!(outcome.exit.is_some(), "{level}: the autopilot did not exit");
        inputs.extend(outcome.inputs);
        let Phase::Intermission { stats, .. } = &play.phase else { panic!("{level}: no intermission") };
        ours.push(*stats);
        // Through the intermission: idle while the tallies count, a press
        // (fire), fire held, use pressed, idle on the episode's map, use.
        let press = |k: usize| TickInput {
            fire: (40..46).contains(&k),
            use_line: k == 50 || k == 51 || k == 95,
            ..TickInput::default()
        };
        let mut k = 0;
        while play.phase != Phase::Playing {
            let input = press(k);
            play.tick(&input).unwrap();
            inputs.push(input);
            k += 1;
            assert!(k < 2000, "{level}: the intermission did not end");
        }
        // The tic that loaded E1M2 was played there too; the bot goes on
        // from the next.
        assert_eq!(k, 96 + 10 + 1, "{level}: Doom 1's intermission, pressed through");
        if level == "E1M2" {
            break;
        }
    }
    let demo = vanilla::demo_of("E1M1", options, &inputs).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let lmp = dir.path().join("two-levels.lmp");
    demo.save(&lmp).unwrap();
    let played = chocolate::play(&path, &lmp).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(played.levels.len(), 2, "Chocolate finished {} levels", played.levels.len());
    for (level, stats) in played.levels.iter().zip(&ours) {
        let p = &level.players[0];
        let tally = |(found, total): (u32, u32)| Tally::of(found as i32, total as i32);
        let theirs = (p.kills, p.items, p.secrets, level.time);
        let mine = (tally(stats.kills), tally(stats.items), tally(stats.secrets), Clock::from_tics(stats.ticks as i32));
        assert_eq!(mine, theirs, "{}: our intermission (left) against Chocolate Doom's statdump", level.level);
    }
}
