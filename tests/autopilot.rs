//! The autopilot: on small maps that each need one mechanism (a lift up, a
//! lift down by the switch on it, a switch and its remote door, a key and
//! its door, a teleporter, a one-way drop, a gap to jump at a run, a stair
//! of steps narrower than its grid, a gap as wide as the body to go round, a
//! boss brain shot at from a rising lift, a boss brain crushed by a
//! crusher a walk line starts, stepping stones narrower than the
//! body, a switch pressed from the nukage
//! below its ledge, a radiation suit before a long wade through nukage,
//! health before a shorter one it would not live through) it reaches the
//! exit through its inputs alone, and the mechanism was really used; `check` finds a map's unreachable secret and its soft lock;
//! a recorded run replays to the same state; and Freedoom's E1M1 is finished.

use glam::DVec2;
use sightline::autopilot::observe::Observe;
use sightline::autopilot::{self, check};
use sightline::campaign::MapRef;
use sightline::level::open_level;
use sightline::play::playthrough::Playthrough;
use sightline::play::{Exit, GameOptions};
use sightline_tests::{freedoom_wads, root};

/// A file under the repository root.
fn map_path(rel: &str) -> std::path::PathBuf {
    root().join(rel)
}

/// The path of test map `tests/maps/autopilot_{name}.ron`.
fn test_map(name: &str) -> std::path::PathBuf {
    map_path(&format!("tests/maps/autopilot_{name}.ron"))
}

fn map(name: &str) -> MapRef {
    MapRef::File(test_map(name))
}

/// `check`'s report on test map `name` at skill 3.
fn check_map(name: &str) -> check::Report {
    check::report(&open_level(&test_map(name), &Default::default()).unwrap(), 3)
}

/// Plays `name` without monsters until the exit (at most a minute of game
/// time), calling `watch` after every tick; panics unless it exits.
fn finish(name: &str, watch: impl FnMut(&Playthrough)) -> Playthrough {
    finish_from(name, |_| {}, watch)
}

/// [`finish`], and the player's feet never down in the pit (below -24).
fn finish_above_the_pit(name: &str) {
    let mut lowest = f64::MAX;
    finish(name, |play| lowest = lowest.min(play.game.player().z));
    assert!(lowest > -24.0, "the player fell into the pit (feet down to {lowest})");
}

/// [`finish`] with the game changed by `setup` before the bot starts.
fn finish_from(name: &str, setup: impl FnOnce(&mut Playthrough), mut watch: impl FnMut(&Playthrough)) -> Playthrough {
    let options = GameOptions { no_monsters: true, ..GameOptions::default() };
    let mut play = Playthrough::of(&map(name), options).unwrap_or_else(|e| panic!("{e}"));
    setup(&mut play);
    let (outcome, bot) = autopilot::run(&mut play, 35 * 60, |play, _| {
        watch(play);
        true
    })
    .unwrap_or_else(|e| panic!("{e}"));
    let why = format!("died: {}, stuck: {:?}, after {} ticks", outcome.died, outcome.stuck, outcome.inputs.len());
    assert_eq!(outcome.exit, Some(Exit::Normal), "{name}: did not exit ({why})\n{}", bot.log.join("\n"));
    play
}

#[test]
fn the_autopilot_rides_a_lift_up_to_the_exit() {
    let mut lowest = f64::MAX;
    let mut highest_feet = f64::MIN;
    finish("lift", |play| {
        lowest = lowest.min(play.game.level().compiled.map.sectors[1].floor);
        highest_feet = highest_feet.max(play.game.player().z);
    });
    assert_eq!(lowest, 0.0, "the lift was never called down");
    assert_eq!(highest_feet, 128.0, "the player never rode up");
}

#[test]
fn the_autopilot_rides_a_lift_down_by_the_switch_on_it() {
    let mut lowest_feet = f64::MAX;
    finish("lift_down", |play| lowest_feet = lowest_feet.min(play.game.player().z));
    assert_eq!(lowest_feet, 0.0, "the player never rode down");
}

#[test]
fn the_autopilot_fetches_a_radiation_suit_before_a_long_wade_through_nukage() {
    // Doom's power order (`powertype_t`), which the player read out keeps.
    let suit = sightline::sim::user::pw::IRONFEET;
    let mut suited_in_pool = false;
    let play = finish("suit", |play| {
        let p = play.game.player();
        suited_in_pool |= p.sector == 1 && p.powers[suit] > 0;
    });
    assert!(suited_in_pool, "it waded in without the suit");
    assert!(play.game.player().health > 50, "health {}", play.game.player().health);
}

#[test]
fn the_autopilot_fetches_health_before_a_wade_it_would_not_live_through() {
    let mut healed_before_pool = false;
    finish_from(
        "heal",
        |play| play.game.set_health(30),
        |play| {
            let p = play.game.player();
            healed_before_pool |= p.sector == 0 && p.health > 30;
        },
    );
    assert!(healed_before_pool, "it waded in at 30 health");
}

#[test]
fn the_autopilot_presses_a_switch_that_opens_a_remote_door() {
    let play = finish("remote_door", |_| {});
    let door = &play.game.level().compiled.map.sectors[1];
    assert!(door.ceiling - door.floor >= 56.0, "the door is shut: {door:?}");
}

#[test]
fn the_autopilot_fetches_the_key_before_its_door() {
    let play = finish("key_door", |_| {});
    let keys = &play.game.player().keys;
    assert!(keys.iter().any(|k| k.colour == sightline::map::special::KeyColour::Blue), "no blue key: {keys:?}");
}

#[test]
fn the_autopilot_takes_a_teleporter() {
    let mut jumped = false;
    let mut last: Option<DVec2> = None;
    finish("teleporter", |play| {
        let p = play.game.player().pos;
        jumped |= last.is_some_and(|q| q.distance(p) > 100.0);
        last = Some(p);
    });
    assert!(jumped, "the player never teleported");
}

/// Doom spawns no thing a single-player game leaves out, so a teleporter
/// whose only destination is for multiplayer games teleports no one
/// (freedoom2's MAP28); the bot must not count on it.
#[test]
fn a_teleporter_to_a_multiplayer_only_destination_takes_no_one() {
    let text = std::fs::read_to_string(test_map("teleporter")).unwrap();
    let only_coop = text.replace(
        r#"Thing(kind: "teleport_destination", x: 576.0, y: 128.0, angle: 0.0)"#,
        r#"Thing(kind: "teleport_destination", x: 576.0, y: 128.0, angle: 0.0, multiplayer: true)"#,
    );
    assert_ne!(text, only_coop, "the teleporter map's destination moved");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("coop_destination.ron");
    std::fs::write(&path, only_coop).unwrap();
    // Its textures, from beside the original.
    for art in ["textures", "sprites"] {
        std::os::unix::fs::symlink(map_path("tests/maps").join(art), dir.path().join(art)).unwrap();
    }
    {
        let options = GameOptions { no_monsters: true, ..GameOptions::default() };
        let mut play = Playthrough::of(&MapRef::File(path.clone()), options).unwrap_or_else(|e| panic!("{e}"));
        let start = play.game.player().pos;
        let mut farthest = 0.0f64;
        let (outcome, bot) = autopilot::run(&mut play, 35 * 20, |play, _| {
            farthest = farthest.max(play.game.player().pos.distance(start));
            true
        })
        .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(outcome.exit, None, "exited through a teleporter with no destination");
        assert!(farthest < 400.0, "the player reached {farthest} units away\n{}", bot.log.join("\n"));
    }
}

#[test]
fn the_autopilot_jumps_down_a_one_way_drop() {
    let mut feet = Vec::new();
    let play = finish("drop", |play| feet.push(play.game.player().z));
    assert_eq!(feet.first(), Some(&96.0));
    assert_eq!(play.game.player().z, 0.0);
}

#[test]
fn the_autopilot_clears_a_gap_with_a_running_jump() {
    let mut lowest = f64::MAX;
    let mut fastest = 0.0f64;
    finish("gap", |play| {
        lowest = lowest.min(play.game.player().z);
        fastest = fastest.max(play.game.player().velocity.length());
    });
    assert!(lowest > -24.0, "the player fell into the pit (feet down to {lowest})");
    assert!(fastest > 12.0, "no run: {fastest} units a tick at most");
    // `check` finds the same way across, and the pit a soft lock.
    let report = check_map("gap");
    assert!(report.exit_reachable, "{}", report.text());
    assert!(report.soft_locks.iter().all(|s| s.to_sector == 1), "{}", report.text());
    assert!(!report.soft_locks.is_empty(), "the pit: {}", report.text());
}

#[test]
fn the_autopilot_leaps_a_pit_only_a_step_deep_onto_a_ledge() {
    // The pit is a step below the start, so walking into it is no drop;
    // its far side is a ledge, so only a run from the start clears it.
    finish_above_the_pit("lip");
    let report = check_map("lip");
    assert!(report.exit_reachable, "{}", report.text());
    assert!(report.soft_locks.is_empty(), "a step climbs out of the pit: {}", report.text());
}

#[test]
fn the_autopilot_crosses_stepping_stones_narrower_than_the_body() {
    // Every stone is narrower than a body and the margin a standing body
    // keeps from an edge, so each landing is on a rim; the chain turns a
    // corner, so no one run carries from the ledge to the exit room. The
    // bot once walked back to a run-up's start on a stone coasting, and
    // slid off its far side.
    finish_above_the_pit("stones");
    let report = check_map("stones");
    assert!(report.exit_reachable, "{}", report.text());
}

#[test]
fn the_autopilot_climbs_a_stair_of_steps_narrower_than_a_cell() {
    // Its only way to the exit is up the stair (the grid once refused it:
    // its cells are two or three steps apart).
    let play = finish("stair", |_| {});
    assert_eq!(play.game.player().z, 144.0);
}

#[test]
fn the_autopilot_goes_round_a_gap_the_body_wedges_in() {
    let gap = DVec2::new(368.0, 256.0);
    let mut nearest = f64::MAX;
    let play = finish("wedge", |play| nearest = nearest.min(play.game.player().pos.distance(gap)));
    assert!(nearest > 32.0, "the body went for the 32-unit gap (within {nearest:.1} of it)");
    // The way round is about 1,500 units: a run, not a wait at the gap.
    assert!(play.game.ticks() < 35 * 8, "{} ticks", play.game.ticks());
}

#[test]
fn the_autopilot_passes_under_a_crusher_unhurt() {
    let mut lowest = f64::MAX;
    let mut least_health = i32::MAX;
    finish("crusher", |play| {
        let corridor = &play.game.level().compiled.map.sectors[1];
        lowest = lowest.min(corridor.ceiling - corridor.floor);
        least_health = least_health.min(play.game.player().health);
    });
    assert!(lowest < 56.0, "the crusher never came down ({lowest} of room at least)");
    assert_eq!(least_health, 100, "the crusher caught the player");
}

#[test]
fn the_autopilot_presses_a_switch_from_the_nukage_below_its_ledge_at_once() {
    // The spot square in front of the switch is on a ledge 128 up; the
    // press is made from the nukage beside it, as soon as the switch is
    // within reach (lining up first, or waiting two seconds for it, kept
    // the body a hurt or two longer in the pool).
    let (a, b) = (DVec2::new(368.0, 112.0), DVec2::new(400.0, 112.0));
    let mut in_reach: Option<u64> = None;
    let mut opened: Option<u64> = None;
    let play = finish("ledge_switch", |play| {
        let (game, now) = (&play.game, play.game.ticks());
        let p = game.player().pos;
        let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
        if game.player().sector == 1 && p.distance(a + (b - a) * t) < sightline::play::USE_RANGE {
            in_reach.get_or_insert(now);
        }
        let door = &game.level().compiled.map.sectors[4];
        if door.ceiling > door.floor {
            opened.get_or_insert(now);
        }
    });
    let (reach, open) = (in_reach.expect("never within reach of the switch"), opened.expect("the door never opened"));
    assert!(open < reach + 20, "in reach at tick {reach}, pressed at {open}");
    assert!(play.game.player().health >= 30, "health {}", play.game.player().health);
}

#[test]
fn the_autopilot_kills_the_boss_brain_from_a_rising_lift() {
    // No exit line: the brain's death ends the level. No shot from the
    // floor passes the slit; only rockets fired from the lift as it rides
    // up past 144 to 168 do (three: 250 health, about 80 a blast).
    let mut fired_from = Vec::new();
    let mut rockets = 0;
    let named = |play: &Playthrough, name: &str| -> Vec<sightline::autopilot::observe::Seen> {
        let table = play.game.table();
        play.game.seen().iter().filter(|t| !t.removed && table.actors[t.kind].name == name).cloned().collect()
    };
    let play = finish("brain", |play| {
        let now = named(play, "rocket_projectile").len();
        if now > rockets {
            fired_from.push(play.game.player().z);
        }
        rockets = now;
    });
    // The first three leave from the rising lift. On the simulation the
    // bot then fires more from where its blast reckoning says the burst
    // reaches the brain through the slit (Doom's splash ignores height).
    let through_slit = |z: &f64| *z > 144.0 && *z <= 168.0;
    assert!(fired_from.len() >= 3, "rockets fired from floors {fired_from:?}");
    assert!(fired_from[..3].iter().all(through_slit), "rockets fired from floors {fired_from:?}");
    let table = play.game.table();
    let brain = play.game.seen().iter().find(|t| table.actors[t.kind].name == "boss_brain").cloned();
    assert!(brain.is_some_and(|b| b.health <= 0), "the brain lives");
}

#[test]
fn the_autopilot_crushes_the_boss_brain_under_a_crusher() {
    // No exit line and no launcher: the brain's closet is shut off, and
    // only the crusher a walk line starts over it kills it.
    let play = finish("brain_crusher", |_| {});
    let table = play.game.table();
    let brain = play.game.seen().iter().find(|t| table.actors[t.kind].name == "boss_brain").cloned();
    assert!(brain.is_some_and(|b| b.health <= 0), "the brain lives");
}

/// A boss brain dies under a crusher as surely as by rockets: Freedoom's
/// MAP16 has no exit line, and its four brains sit in closets no shot
/// reaches, under the crushers that twelve walk lines start. `check` calls
/// the map finishable by them, says it ends by a brain's death, and on the
/// test map calls a brain moved out from under its crusher unkillable.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn check_counts_a_crusher_over_the_boss_brain_as_its_death() {
    let report = check::report(&freedoom_level("freedoom2.wad", "MAP16"), 3);
    let text = report.text();
    assert!(report.exit_reachable && report.exit_lines == 0, "{text}");
    assert!(text.contains("no exit line; the map ends when a boss brain dies"), "{text}");
    assert_eq!(report.exits.len(), 4, "{text}");
    assert!(report.exits.iter().all(|e| e.reachable && e.what.contains("crushed by the crusher")), "{text}");

    let mut level = open_level(&test_map("brain_crusher"), &Default::default()).unwrap();
    assert!(check::report(&level, 3).exit_reachable, "{}", check::report(&level, 3).text());
    let brain = level.compiled.map.things.iter_mut().find(|t| t.kind == "boss_brain").expect("the brain");
    brain.pos = DVec2::new(448.0, 128.0);
    let report = check::report(&level, 3);
    assert!(!report.exit_reachable, "{}", report.text());
    assert!(report.exits[0].obstacle.as_deref().is_some_and(|o| o.contains("no crusher over it")), "{}", report.text());
}

#[test]
fn check_names_a_leap_with_no_way_back_a_soft_lock_by_running_jump() {
    // A move to a cell not beside the last that crosses no teleport line
    // is a running jump; it was once named a teleport.
    let report = check_map("leap_trap");
    assert!(report.exit_reachable, "{}", report.text());
    let how: Vec<(&str, usize)> = report.soft_locks.iter().map(|s| (s.how.as_str(), s.to_sector)).collect();
    assert!(how.contains(&("a running jump", 2)), "the leap into the trap room: {}", report.text());
    assert!(how.contains(&("a one-way drop", 1)), "the drop into the pit: {}", report.text());
    assert_eq!(how.len(), 2, "{}", report.text());
}

#[test]
fn check_finds_the_unreachable_secret_and_the_soft_lock() {
    let level = open_level(&test_map("flawed"), &Default::default()).unwrap();
    let (report, drawing) = check::check(level, 3);
    assert!(report.exit_reachable, "{}", report.text());
    assert_eq!(report.secrets.len(), 1);
    assert!(!report.secrets[0].reachable, "{}", report.text());
    assert!(report.items.iter().all(|i| !i.reachable), "the medikit is on the secret platform: {}", report.text());
    assert!(!report.soft_locks.is_empty(), "{}", report.text());
    for s in &report.soft_locks {
        assert_eq!((s.from_sector, s.to_sector), (0, 2), "{}", report.text());
        assert!(s.y < 0.0, "a soft lock outside the pit: {s:?}");
    }
    let text = report.text();
    assert!(text.contains("secret sector 1") && text.contains("NOT reachable") && text.contains("soft lock"), "{text}");
    // The route drawn is the closure's, from the start to the exit.
    assert!(drawing.route.points.len() > 10, "{:?}", drawing.route);
    assert!(drawing.route.exits && drawing.route.missed == 0, "{:?}", drawing.route);
    let png = drawing.draw(400, true).to_png();
    assert!(png.len() > 1000);
}

#[test]
fn check_finds_no_flaw_in_the_mechanism_maps() {
    for name in [
        "lift",
        "lift_down",
        "remote_door",
        "key_door",
        "teleporter",
        "drop",
        "stair",
        "wedge",
        "crusher",
        "ledge_switch",
        "brain",
        "brain_crusher",
        "suit",
        "heal",
    ] {
        let report = check_map(name);
        assert!(report.exit_reachable, "{name}: {}", report.text());
        assert!(report.soft_locks.is_empty(), "{name}: {}", report.text());
        assert!(report.keys.iter().all(|k| k.reachable), "{name}: {}", report.text());
    }
}

#[test]
fn check_says_a_key_behind_its_own_door_is() {
    let report = check_map("key_behind_door");
    assert!(!report.exit_reachable, "{}", report.text());
    assert_eq!(report.keys.len(), 1);
    assert!(!report.keys[0].reachable && report.keys[0].behind_own_door, "{}", report.text());
}

#[test]
fn a_recorded_autopilot_run_with_monsters_replays_to_the_same_state() {
    let map = MapRef::File(map_path("maps/outpost.ron"));
    let options = GameOptions { skill: 2, seed: 5, no_monsters: false };
    let mut play = Playthrough::of(&map, options).unwrap();
    let (outcome, _) = autopilot::run(&mut play, 35 * 40, |_, _| true).unwrap();
    assert!(play.game.stats().kills.0 > 0 || outcome.exit.is_some(), "no fight in 40 s: {outcome:?}");
    let mut again = Playthrough::of(&map, options).unwrap();
    for input in &outcome.inputs {
        again.tick(input).unwrap();
    }
    assert_eq!(again.ticks, play.ticks);
    assert!(again.game.state_bytes() == play.game.state_bytes(), "the replay's state differs");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn the_autopilot_finishes_freedoom_e1m1_without_monsters() {
    let wad = freedoom_wads::path("freedoom1.wad");
    let map = MapRef::Wad { wads: vec![wad], map: Some("E1M1".into()) };
    let options = GameOptions { no_monsters: true, ..GameOptions::default() };
    let mut play = Playthrough::of(&map, options).unwrap();
    let (outcome, bot) = autopilot::run(&mut play, 35 * 60 * 20, |_, _| true).unwrap();
    assert!(outcome.exit.is_some(), "{outcome:?}\n{}", bot.log.join("\n"));
}

/// Every map of a Freedoom IWAD autoplayed without monsters on skill 3, two
/// at a time, and `check`'s report on it: the maps that exit within 20
/// minutes of game time, and a table of how each went (printed;
/// `--nocapture` shows it). The issue's targets are 30 of freedoom1's 36
/// and 26 of freedoom2's 32, which freedoom2 now meets: 26 (MAP07 needs
/// the bosses killed; MAP13, 19, 25 and 27 stall, MAP29 runs out of time;
/// MAP28 exits since a gun line is shot from where a level shot gets
/// through).
const FREEDOOM1_FLOOR: usize = 30;
const FREEDOOM2_FLOOR: usize = 26;

/// Maps on which `check` still disagrees with the bot (calls the exit it
/// reaches, or a key it takes, unreachable), each with where the bot's
/// route first leaves the cells `check` reaches
/// (`SIGHTLINE_CHECK_TRACE=1 sightline check WAD:MAP`): the model's gap
/// there is not yet found. The test fails when one of them agrees again
/// (take it off the list) as when another disagrees. None is left: the
/// last two, E3M5 (a run-up on a floor ridden up) and MAP28 (a pit a step
/// deep before a ledge), agree since the leap model takes both.
const KNOWN_GAPS: &[(&str, &str)] = &[];

/// How the bot did on one map, and what `check` says of it.
struct Played {
    map: String,
    exited: bool,
    how: String,
    /// The keys the bot held at the end.
    keys: Vec<String>,
    report: check::Report,
}

fn autoplay_wad(wad: &str) -> Vec<Played> {
    let path = freedoom_wads::path(wad);
    let names = sightline::wad::Wad::open(&path).unwrap().map_names();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(Vec::new());
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get()).min(4);
    std::thread::scope(|s| {
        for _ in 0..workers {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(name) = names.get(i) else { break };
                let map = MapRef::Wad { wads: vec![path.clone()], map: Some(name.clone()) };
                let options = GameOptions { no_monsters: true, ..GameOptions::default() };
                let mut play = Playthrough::of(&map, options).unwrap_or_else(|e| panic!("{name}: {e}"));
                let (outcome, _) = autopilot::run(&mut play, 35 * 60 * 20, |_, _| true).unwrap();
                let how = match (&outcome.exit, outcome.died, &outcome.stuck) {
                    (Some(e), _, _) => format!("{e:?} exit after {} s", outcome.inputs.len() / 35),
                    (None, true, _) => "died".to_string(),
                    (None, false, Some((at, why))) => format!("stuck at ({:.0}, {:.0}): {why}", at.x, at.y),
                    (None, false, None) => "out of time".to_string(),
                };
                let keys = play.game.player().keys.iter().map(|k| k.colour.name().to_string()).collect();
                let level = sightline::campaign::open(&map, &Default::default()).unwrap().level;
                let report = check::report(&level, options.skill);
                let map = format!("{wad}:{name}");
                let played = Played { map, exited: outcome.exit.is_some(), how, keys, report };
                results.lock().unwrap().push(played);
            });
        }
    });
    let mut results = results.into_inner().unwrap();
    results.sort_by(|a, b| a.map.cmp(&b.map));
    results
}

/// Where `check` and the bot disagree on one map (no exit the bot reaches
/// and no key it takes may be called unreachable, and every "not
/// reachable" names its obstacle); a listed gap that agrees now is wrong
/// too, so the list only shrinks.
fn disagreements(p: &Played) -> Vec<String> {
    let r = &p.report;
    let gap = KNOWN_GAPS.iter().find(|g| g.0 == p.map);
    let mut disagree = Vec::new();
    if p.exited && !r.exit_reachable {
        disagree.push(format!("{}: the bot exits it, check calls it unfinishable", p.map));
    }
    for colour in &p.keys {
        if !r.keys.iter().any(|k| &k.colour == colour && k.reachable) {
            disagree.push(format!("{}: the bot picks up the {colour} key, check calls it unreachable", p.map));
        }
    }
    let mut wrong = match gap {
        None => disagree,
        Some(_) if disagree.is_empty() => vec![format!("{}: agrees now; take it off KNOWN_GAPS", p.map)],
        Some(_) => Vec::new(),
    };
    for s in r.soft_locks.iter().filter(|s| s.from_sector == s.to_sector && s.how == "a one-way drop") {
        wrong
            .push(format!("{}: a one-way drop from sector {} into itself at ({}, {})", p.map, s.from_sector, s.x, s.y));
    }
    for k in r.keys.iter().filter(|k| !k.reachable && k.obstacle.as_deref().is_none_or(str::is_empty)) {
        wrong.push(format!("{}: the {} key is unreachable with no obstacle named", p.map, k.colour));
    }
    for e in r.exits.iter().filter(|e| !e.reachable && e.obstacle.as_deref().is_none_or(str::is_empty)) {
        wrong.push(format!("{}: the {} is unreachable with no obstacle named", p.map, e.what));
    }
    wrong
}

/// A lift's ends move with what other specials do: E2M5's lift 545 (and
/// MAP13's 68, out of the nukage to the blue key) is raised by a switch
/// elsewhere before its own switch can call it up to the key's ledge; E4M6's lift 280 comes down to the blood pool only
/// once the ledge beside it is lowered into the pool, which brings its
/// switch down there into reach.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn check_follows_lifts_whose_ends_other_specials_move() {
    for (wad, name, key) in
        [("freedoom1.wad", "E2M5", "red"), ("freedoom1.wad", "E4M6", "yellow"), ("freedoom2.wad", "MAP13", "blue")]
    {
        let report = check::report(&freedoom_level(wad, name), 3);
        // MAP13's exit wants keys beyond; the bot does not finish it either.
        assert!(report.exit_reachable || name == "MAP13", "{name}: {}", report.text());
        let k = report.keys.iter().find(|k| k.colour.eq_ignore_ascii_case(key)).expect("the key");
        assert!(k.reachable, "{name}: {}", report.text());
    }
}

/// Two of check's misreadings the Freedoom batch found: E4M8's sector
/// 183 is raised 32 by each of two switches (a move by so much goes from
/// where the floor is by then, so it ends level with the way on), and its
/// lost souls (solid, but monsters, which move and which -nomonsters has
/// none of) stood in a corridor as if scenery; MAP24's way on was "blocked"
/// by a monster at a teleporter's destination.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn check_adds_up_relative_moves_and_walks_past_monsters() {
    for (wad, name) in [("freedoom1.wad", "E4M8"), ("freedoom2.wad", "MAP24")] {
        let report = check::report(&freedoom_level(wad, name), 3);
        assert!(report.exit_reachable, "{name}: {}", report.text());
    }
}

/// Freedoom's `level` `name` of `wad`.
fn freedoom_level(wad: &str, name: &str) -> sightline::level::Level {
    let map = MapRef::Wad { wads: vec![freedoom_wads::path(wad)], map: Some(name.into()) };
    sightline::campaign::open(&map, &Default::default()).unwrap().level
}

/// The id of the line of `level` from `a` to `b`.
fn line_between(level: &sightline::level::Level, a: (f64, f64), b: (f64, f64)) -> u32 {
    let map = &level.compiled.map;
    let i = map.lines.iter().position(|l| map.line_points(l) == (DVec2::new(a.0, a.1), DVec2::new(b.0, b.1)));
    i.expect("the switch line") as u32
}

/// A switch at the back of a door's slot is pressed from in front of the
/// door once the door is open, not before: MAP22's switch lowering the
/// start's platform (sector 240) is behind a thin door (sector 229) that a
/// shot opens, and MAP21's red switch is beyond the blue switch's door
/// (sector 57), in a slot too narrow to stand in. Their presses were
/// found on the map as it starts, the slots shut.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn check_presses_a_switch_in_a_door_slot_once_the_door_is_open() {
    use sightline::autopilot::nav::{Heights, NavGrid};
    let level = freedoom_level("freedoom2.wad", "MAP22");
    let map = &level.compiled.map;
    let nav = NavGrid::new(&level.compiled);
    let presses = autopilot::press::press_cells(&nav, map, line_between(&level, (-272.0, -2256.0), (-272.0, -2224.0)));
    let mut heights = Heights::of(map);
    assert!(presses.at(map, &heights).is_empty(), "no press reaches through the shut slot");
    let door = map.sectors_tagged(15).next().unwrap();
    heights.ceiling[door] += 32.0;
    assert!(!presses.at(map, &heights).is_empty(), "the press reaches once the slot's door is open");
    let report = check::report(&level, 3);
    assert!(report.exit_reachable, "MAP22: {}", report.text());

    let report = check::report(&freedoom_level("freedoom2.wad", "MAP21"), 3);
    let yellow = report.keys.iter().find(|k| k.colour.eq_ignore_ascii_case("yellow")).expect("the key");
    assert!(yellow.reachable, "MAP21: {}", report.text());
}

/// Doom's use reaches 64 units from the body's centre whatever the heights,
/// through two-sided lines with an opening: E3M5's switch on the face of
/// the pillar in sector 175, 120 units above the lava, is pressed from the
/// lava (and raises sector 271, which is ridden up to the pillar's top).
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn check_presses_a_switch_as_far_as_doom_reaches() {
    use sightline::autopilot::nav::{Heights, NavGrid};
    let level = freedoom_level("freedoom1.wad", "E3M5");
    let map = &level.compiled.map;
    let nav = NavGrid::new(&level.compiled);
    let presses =
        autopilot::press::press_cells(&nav, map, line_between(&level, (-1488.0, -1600.0), (-1424.0, -1600.0)));
    let from_lava = presses.at(map, &Heights::of(map)).cells().any(|c| nav.centre[c as usize] == 170);
    assert!(from_lava, "the switch is pressed from the lava below");
    let report = check::report(&level, 3);
    let on_top = report.items.iter().find(|i| (i.x, i.y) == (-1416.0, -1688.0)).expect("the bullets on the pillar");
    assert!(on_top.reachable, "E3M5: {}", report.text());
}

/// A soft lock is a move the search makes, between cells it reaches:
/// E1M3's lift (sector 163) held up, and E2M2's ledges over sector 122,
/// were once named one-way drops "from sector 162 into sector 162" and
/// the like, moves into cells the search never reached. A drop into the
/// very sector it falls from cannot be, so none may be named on any map
/// the batch plays either (`disagreements`).
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn check_names_only_soft_locks_the_player_can_fall_into() {
    for name in ["E1M3", "E2M2"] {
        let report = check::report(&freedoom_level("freedoom1.wad", name), 3);
        assert!(report.exit_reachable, "{name}: {}", report.text());
        let stranded = |s: &check::SoftLock| s.from_sector == s.to_sector || s.to_sector == 122;
        assert!(report.soft_locks.iter().all(|s| s.how == "a one-way drop"), "{name}: {}", report.text());
        assert!(!report.soft_locks.iter().any(stranded), "{name}: {}", report.text());
    }
}

/// A running jump from a floor the player rides up: E3M5's sector 271,
/// raised from the lava to 72 by the switch pressed from the lava, is the
/// run-up for the leap east over a strip of lava onto sector 176 (88),
/// the bot's way to the yellow key and the exit. The run-up was once
/// walked back off the raised floor into the lava (the floor's range let
/// a walk step on at its bottom), and a run from the lava never clears it.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn check_leaps_off_a_floor_the_player_rides_up() {
    let report = check::report(&freedoom_level("freedoom1.wad", "E3M5"), 3);
    assert!(report.exit_reachable, "E3M5: {}", report.text());
    let yellow = report.keys.iter().find(|k| k.colour.eq_ignore_ascii_case("yellow")).expect("the key");
    assert!(yellow.reachable, "E3M5: {}", report.text());
}

/// The Freedoom batch: the bot's floors, and `check` agreeing with it
/// (one autoplay of each map serves both).
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
#[cfg_attr(
    not(freedoom_missing),
    ignore = "long suite (every Freedoom map): scripts/long-suites.sh runs it, as CI does"
)]
fn the_autopilot_finishes_most_of_freedoom_without_monsters_and_check_agrees() {
    let mut wrong = Vec::new();
    for (wad, floor) in [("freedoom1.wad", FREEDOOM1_FLOOR), ("freedoom2.wad", FREEDOOM2_FLOOR)] {
        let results = autoplay_wad(wad);
        for p in &results {
            let gap = KNOWN_GAPS.iter().find(|g| g.0 == p.map).map(|g| format!(" (known gap: {})", g.1));
            let verdict = if p.report.exit_reachable { "finishable" } else { "NOT finishable" };
            eprintln!("{}: {}; check: {verdict}{}", p.map, p.how, gap.unwrap_or_default());
            wrong.extend(disagreements(p));
        }
        let exited = results.iter().filter(|r| r.exited).count();
        eprintln!("{wad}: {exited} of {} maps exited", results.len());
        assert!(exited >= floor, "{wad}: only {exited} of {} maps exited (the target is {floor})", results.len());
    }
    assert!(wrong.is_empty(), "check and the autopilot disagree:\n{}", wrong.join("\n"));
}
