//! Sixteen players in one game (issue 41): deathmatch on ViZDoom's `cig`
//! (25 deathmatch starts) and on Debian's freedm (MAP01 has ten deathmatch
//! starts and four players' starts, MAP03 seventeen deathmatch starts), and
//! co-op on ViZDoom's `deathmatch` (one player start), every player acting
//! in the same tic: each spawns at a spot of its own, in its own colour, no
//! body leaves the map, frags and deaths are counted for players past
//! Doom's four, and a seventeenth player is refused.
//!
//! The WADs are fixtures that may be missing: without them a test says so
//! on stderr and passes, unless `SIGHTLINE_REQUIRE_VIZDOOM=1` or
//! `SIGHTLINE_REQUIRE_FREEDM=1` makes their absence a failure.

#[path = "vizdoom.rs"]
mod vizdoom;

use std::path::{Path, PathBuf};

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use sightline::scenario::{variables, Button, GameVariable, MultiEpisode, Scenario, ScenarioConfig};
use sightline::sim::collision;
use sightline::sim::info::mt;
use sightline::sim::mobj::mf;
use sightline::sim::{Compat, Sim, MAXPLAYERS};
use sightline_tests::freedoom_wads;

/// Where Debian's `freedm` package installs its WAD.
const FREEDM: &str = "/usr/share/games/doom/freedm.wad";
/// `1` makes a missing freedm.wad fail the tests that need it.
const REQUIRE_FREEDM: &str = "SIGHTLINE_REQUIRE_FREEDM";

/// freedm.wad, or `None` after saying on stderr why the test is skipped.
fn freedm_or_skip(test: &str) -> Option<PathBuf> {
    let path = PathBuf::from(FREEDM);
    if path.is_file() {
        return Some(path);
    }
    let required = std::env::var_os(REQUIRE_FREEDM).is_some_and(|v| !v.is_empty() && v != "0");
    assert!(!required, "{REQUIRE_FREEDM} is set and {FREEDM} is missing (apt-get install freedm)");
    eprintln!("skipped {test}: {FREEDM} is missing (apt-get install freedm)");
    None
}

/// The buttons the agents press (those of `sightline.pettingzoo.deathmatch_env`).
const BUTTONS: &str = "{ ATTACK USE MOVE_FORWARD MOVE_BACKWARD MOVE_LEFT MOVE_RIGHT TURN_LEFT TURN_RIGHT SPEED }";

/// Deathmatch on map `map` of freedm, as `deathmatch_env` sets it up.
fn freedm(wad: &Path, map: &str) -> Scenario {
    let text = format!(
        "doom_game_path = {}\ndoom_map = {map}\ndoom_skill = 3\navailable_buttons = {BUTTONS}\n\
         available_game_variables = {{ HEALTH FRAGCOUNT }}\n",
        wad.display()
    );
    let config = ScenarioConfig::parse(&text, "freedm deathmatch").unwrap_or_else(|e| panic!("{e}"));
    Scenario::open(&config, None).unwrap_or_else(|e| panic!("{e}"))
}

/// ViZDoom's scenario `cfg` (its own WAD) on Freedoom 2.
fn vizdoom_scenario(dir: &Path, cfg: &str) -> Scenario {
    let config = ScenarioConfig::load(dir.join(format!("{cfg}.cfg"))).unwrap_or_else(|e| panic!("{e}"));
    Scenario::open(&config, Some(&freedoom_wads::path("freedoom2.wad"))).unwrap_or_else(|e| panic!("{e}"))
}

/// Random presses, several buttons at once: mostly forward, turning and
/// firing, so that sixteen players meet and shoot each other. Never USE,
/// which could press an exit switch (a dead player presses it to come
/// back); now and then anything else.
fn random_actions(rng: &mut ChaCha8Rng, players: usize, buttons: &[Button]) -> Vec<Vec<f64>> {
    let odds = |b: &Button| match b.name().as_str() {
        "ATTACK" => 0.4,
        "USE" => 0.0,
        "MOVE_FORWARD" => 0.6,
        "MOVE_BACKWARD" => 0.1,
        "MOVE_LEFT" | "MOVE_RIGHT" => 0.2,
        "TURN_LEFT" | "TURN_RIGHT" => 0.25,
        "SPEED" => 0.5,
        _ => 0.05,
    };
    let press = |rng: &mut ChaCha8Rng, b: &Button| f64::from(u8::from(rng.random_bool(odds(b))));
    (0..players).map(|_| buttons.iter().map(|b| press(rng, b)).collect()).collect()
}

/// Where each player's body stands, checking that it is that player's.
fn spots(sim: &Sim, players: usize) -> Vec<(i32, i32)> {
    (0..players)
        .map(|n| {
            let p = sim.player(n).unwrap_or_else(|| panic!("player {n} is in the game"));
            let mo = sim.mo(p.mo);
            assert_eq!(mo.player, Some(n), "player {n}'s body is its own");
            (mo.x.0, mo.y.0)
        })
        .collect()
}

/// Every player stands at a spot of its own, in its own colour (Doom's
/// translation bits hold the player's number less one).
fn check_spawned(sim: &Sim, players: usize, what: &str) {
    let at = spots(sim, players);
    for i in 0..players {
        for j in 0..i {
            assert_ne!(at[i], at[j], "{what}: players {j} and {i} spawned at the same spot");
        }
        let colour = (sim.mo(sim.player(i).unwrap().mo).flags & mf::TRANSLATION) >> mf::TRANSSHIFT;
        assert_eq!(colour as usize, i, "{what}: player {i}'s colour");
    }
}

/// No two players' bodies overlap (Doom's bodies collide as boxes: two
/// overlapping players could never move apart).
fn check_apart(sim: &Sim, players: usize, what: &str) {
    let bodies: Vec<_> = (0..players).map(|n| sim.mo(sim.player(n).unwrap().mo)).collect();
    for i in 0..players {
        for j in 0..i {
            let (a, b) = (bodies[i], bodies[j]);
            let apart = (a.x - b.x).abs() >= a.radius + b.radius || (a.y - b.y).abs() >= a.radius + b.radius;
            assert!(apart, "{what}: players {j} and {i} overlap at {:?} and {:?}", (b.x, b.y), (a.x, a.y));
        }
    }
}

/// Every body stands within the map's bounds. Under vanilla's rules (a
/// Doom-format map such as freedm's) a teleport fog may not: Doom puts the
/// fog of a spot facing west or south-west thousands of units away (its
/// negative fine angle reads `finetangent`), and Chocolate Doom keeps that.
fn check_bodies(sim: &Sim, what: &str) {
    let (mut lo, mut hi) = ((i32::MAX, i32::MAX), (i32::MIN, i32::MIN));
    for &(x, y) in &sim.level.vertices {
        lo = (lo.0.min(x.0), lo.1.min(y.0));
        hi = (hi.0.max(x.0), hi.1.max(y.0));
    }
    let vanilla = sim.rules.compat == Compat::Vanilla;
    for id in sim.live_mobjs() {
        let mo = sim.mo(id);
        if vanilla && sim.is(id, mt::TFOG) {
            continue;
        }
        let inside = (lo.0..=hi.0).contains(&mo.x.0) && (lo.1..=hi.1).contains(&mo.y.0);
        let name = &sim.info.table.actors[mo.kind].name;
        assert!(inside, "{what}: body {} ({name}) outside the map at ({}, {})", id.0, mo.x.to_f64(), mo.y.to_f64());
    }
}

/// What a run of random play saw: each player's frags of others and deaths.
struct Tally {
    frags: Vec<i32>,
    deaths: Vec<i32>,
}

/// `tics` tics of random play for all `players` of `episode`, checking
/// the bodies now and then and that a dead player comes back.
fn play(episode: &mut MultiEpisode, players: usize, tics: u32, seed: u64, what: &str) -> Tally {
    let buttons = episode.config.available_buttons.clone();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut dead_since = vec![None; players];
    for tic in 0..tics {
        episode.step(&random_actions(&mut rng, players, &buttons));
        // No one presses USE (the dead press it to come back): an exit
        // switch would end the game.
        assert_eq!(episode.end(), None, "{what}: the episode ended at tic {tic}");
        for (n, since) in dead_since.iter_mut().enumerate() {
            let alive = episode.game.sim.player(n).is_some_and(|p| p.health > 0);
            match (alive, *since) {
                (false, None) => *since = Some(tic),
                (true, Some(_)) => *since = None,
                (false, Some(t)) => assert!(tic - t < 200, "{what}: player {n} dead since tic {t}, not reborn"),
                (true, None) => {}
            }
        }
        if tic % 100 == 0 {
            check_bodies(&episode.game.sim, &format!("{what}, tic {tic}"));
            spots(&episode.game.sim, players);
        }
    }
    check_bodies(&episode.game.sim, what);
    let sim = &episode.game.sim;
    let frags = (0..players)
        .map(|n| {
            let p = sim.player(n).unwrap();
            p.frags.iter().enumerate().filter(|&(v, _)| v != n).map(|(_, f)| f).sum()
        })
        .collect();
    let deaths = (0..players).map(|n| sim.zdoom.tallies[n].deaths).collect();
    Tally { frags, deaths }
}

/// Sixteen players on `scenario` in deathmatch for `tics` tics: spawned
/// apart, in the map throughout, and some player past Doom's four both
/// fragged and died.
fn sixteen_in_deathmatch(scenario: &Scenario, tics: u32, what: &str) {
    let mut episode = scenario.multi_episode(5, MAXPLAYERS, 1).unwrap_or_else(|e| panic!("{what}: {e}"));
    check_spawned(&episode.game.sim, MAXPLAYERS, what);
    check_bodies(&episode.game.sim, what);
    let tally = play(&mut episode, MAXPLAYERS, tics, 11, what);
    eprintln!("{what}: frags {:?} deaths {:?}", tally.frags, tally.deaths);
    let (frags, deaths) = (&tally.frags[4..], &tally.deaths[4..]);
    assert!(frags.iter().any(|&f| f > 0), "{what}: no frag for players 5 to 16 in {tics} tics: {:?}", tally.frags);
    assert!(deaths.iter().any(|&d| d > 0), "{what}: no death of players 5 to 16 in {tics} tics: {:?}", tally.deaths);
    // The game variable an agent reads counts them too.
    let counted: Vec<f64> =
        (0..MAXPLAYERS).map(|n| variables::value(&episode.game, n, GameVariable::FragCount)).collect();
    assert!(counted[4..].iter().any(|&f| f != 0.0), "{what}: FRAGCOUNT {counted:?}");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn sixteen_players_play_deathmatch_on_vizdoom_cig() {
    let Some(dir) = vizdoom::scenarios_or_skip("sixteen_players_play_deathmatch_on_vizdoom_cig") else { return };
    sixteen_in_deathmatch(&vizdoom_scenario(&dir, "cig"), 4000, "cig.wad MAP01, 16 players");
}

#[test]
fn sixteen_players_play_deathmatch_on_freedm() {
    let Some(wad) = freedm_or_skip("sixteen_players_play_deathmatch_on_freedm") else { return };
    // MAP01: 10 deathmatch starts and 4 players' starts for 16 players;
    // MAP03: 17 deathmatch starts, all kept in a game past four players.
    for map in ["MAP01", "MAP03"] {
        sixteen_in_deathmatch(&freedm(&wad, map), 10000, &format!("freedm.wad {map}, 16 players"));
    }
}

/// A game past four players keeps every deathmatch start (vanilla keeps
/// ten, and a game of four still does: Doom's demos depend on it).
#[test]
fn a_game_past_four_players_keeps_every_deathmatch_start() {
    let Some(wad) = freedm_or_skip("a_game_past_four_players_keeps_every_deathmatch_start") else { return };
    let scenario = freedm(&wad, "MAP03");
    for (players, kept, slots) in [(2, 10, 4), (4, 10, 4), (5, 17, 16), (16, 17, 16)] {
        let episode = scenario.multi_episode(1, players, 1).unwrap();
        let sim = &episode.game.sim;
        assert_eq!((sim.deathmatch_starts.len(), sim.slots()), (kept, slots), "{players} players");
    }
}

/// Co-op on ViZDoom's `deathmatch` map, whose only start is player 1's
/// (three of them: the last is the player's, the others voodoo dolls): the
/// other fifteen players find room beside it, not inside each other or a
/// wall, and can all walk.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn sixteen_players_without_starts_spawn_beside_player_1s() {
    let Some(dir) = vizdoom::scenarios_or_skip("sixteen_players_without_starts_spawn_beside_player_1s") else {
        return;
    };
    let scenario = vizdoom_scenario(&dir, "deathmatch");
    for deathmatch in [0, 1] {
        let what = format!("deathmatch.wad MAP01, 16 players, deathmatch {deathmatch}");
        let mut episode = scenario.multi_episode(2, MAXPLAYERS, deathmatch).unwrap();
        check_spawned(&episode.game.sim, MAXPLAYERS, &what);
        check_apart(&episode.game.sim, MAXPLAYERS, &what);
        check_bodies(&episode.game.sim, &what);
        let before = spots(&episode.game.sim, MAXPLAYERS);
        play(&mut episode, MAXPLAYERS, 300, 3, &what);
        let after = spots(&episode.game.sim, MAXPLAYERS);
        let moved = before.iter().zip(&after).filter(|(a, b)| a != b).count();
        assert!(moved >= 12, "{what}: only {moved} of 16 players moved in 300 tics");
    }
}

/// Player 10 telefrags player 12: the frag is player 10's, its count and
/// FRAGCOUNT say so, player 12's death is counted, and player 12 comes back
/// elsewhere when it presses USE.
#[test]
fn player_10_fragging_player_12_counts_for_both() {
    let Some(wad) = freedm_or_skip("player_10_fragging_player_12_counts_for_both") else { return };
    let scenario = freedm(&wad, "MAP03");
    let mut episode = scenario.multi_episode(4, MAXPLAYERS, 1).unwrap();
    let (killer, victim) = (9, 11);
    let sim = &mut episode.game.sim;
    let (body, target) = (sim.player(killer).unwrap().mo, sim.player(victim).unwrap().mo);
    let at = (sim.mo(target).x, sim.mo(target).y);
    assert!(collision::teleport_move(sim, body, at.0, at.1), "the telefrag");
    assert!(sim.player(victim).unwrap().health <= 0, "player 12 died");
    assert_eq!(sim.player(killer).unwrap().frags[victim], 1);
    assert_eq!(variables::value(&episode.game, killer, GameVariable::FragCount), 1.0);
    let buttons = episode.config.available_buttons.len();
    let idle = vec![vec![0.0; buttons]; MAXPLAYERS];
    for _ in 0..70 {
        episode.step(&idle);
    }
    let sim = &episode.game.sim;
    assert_eq!(sim.zdoom.tallies[victim].deaths, 1);
    let reborn = sim.player(victim).unwrap();
    assert!(reborn.health > 0 && reborn.mo != target, "player 12 came back");
    let now = (sim.mo(reborn.mo).x, sim.mo(reborn.mo).y);
    assert_ne!(now, at, "at another spot");
    check_bodies(sim, "after the telefrag");
}

#[test]
fn a_seventeenth_player_is_refused() {
    let Some(wad) = freedm_or_skip("a_seventeenth_player_is_refused") else { return };
    let scenario = freedm(&wad, "MAP01");
    let Err(e) = scenario.multi_episode(0, MAXPLAYERS + 1, 1) else { panic!("17 players made a game") };
    assert!(e.to_string().contains("a game holds 1 to 16 players"), "{e}");
    assert!(scenario.multi_episode(0, 0, 1).is_err());
}
