//! The world's machinery against Doom's numbers: each special on a small
//! version-2 map of its own (`tests/maps/`, made by
//! `tests/maps/generators/specials.py`, whose comments say where everything
//! is), played on the simulation with Doom's arithmetic through
//! [`SimGame::tick`] with scripted input. Heights, speeds, waits and periods
//! are Doom's (p_doors.c, p_plats.c, p_floor.c, p_ceilng.c, p_lights.c,
//! p_switch.c, p_telept.c, p_spec.c), written out as numbers in the
//! assertions.
//!
//! Counting ticks: the tick a special goes off is tick 0 of its mover, and
//! the mover already moves on it (Doom runs new thinkers in the tic that
//! made them). A mover learns it has arrived when a step would pass its
//! destination (T_MovePlane's `height + speed > dest`): one landing on it
//! exactly by whole steps stays busy one tick more at it ([`path`]).
//! A level's first tick uses nothing: Doom's G_PlayerReborn holds use down.

use std::path::PathBuf;

use glam::DVec2;
use sightline::actors::KeyForm;
use sightline::autopilot::observe::Observe;
use sightline::fixed::{DoomRandom, RNDTABLE};
use sightline::level::Level;
use sightline::map::special::{Damage, KeyColour, LightEffect, SectorSpecial, Suit};
use sightline::play::events::{Event, Origin};
use sightline::play::player::{Key, Player};
use sightline::play::world::{Exit, SpecialLine};
use sightline::play::{GameOptions, TickInput};
use sightline::sim::game::SimGame;
use sightline::sim::plats::PlatStatus;
use sightline::sim::think::Status;
use sightline::sim::ThinkerKind;
use sightline_tests::sim_play::{self, door, DoorState};
use sightline_tests::{load, root};

// ---------------------------------------------------------------------------
// Driving a game

fn fixture(name: &str) -> PathBuf {
    let p = root().join("tests").join("maps").join(format!("{name}.ron"));
    assert!(p.exists(), "missing fixture {} (tests/maps/generators/specials.py writes it)", p.display());
    p
}

fn options() -> GameOptions {
    GameOptions::default()
}

fn game(name: &str) -> SimGame {
    SimGame::on_level(load(&fixture(name)), &format!("{name}.ron"), options()).unwrap_or_else(|e| panic!("{e}"))
}

fn level(g: &SimGame) -> &Level {
    Observe::level(g)
}

/// The player as read out after the last tick.
fn player(g: &SimGame) -> &Player {
    Observe::player(g)
}

fn events(g: &SimGame) -> &[Event] {
    Observe::events(g)
}

fn leveltime(g: &SimGame) -> u64 {
    Observe::ticks(g)
}

fn console(g: &SimGame) -> &sightline::sim::Player {
    g.sim.players[g.sim.console].as_ref().expect("a player")
}

fn console_mut(g: &mut SimGame) -> &mut sightline::sim::Player {
    let n = g.sim.console;
    g.sim.players[n].as_mut().expect("a player")
}

/// Doom's `pw_ironfeet` (doomdef.h's powertype_t order).
const IRONFEET: usize = 3;

const IDLE: TickInput =
    TickInput { forward: 0, strafe: 0, turn: 0.0, run: false, use_line: false, fire: false, weapon: 0 };
const WALK: TickInput = TickInput { forward: 1, ..IDLE };
const RUN: TickInput = TickInput { forward: 1, run: true, ..IDLE };
const USE: TickInput = TickInput { use_line: true, ..IDLE };
const FIRE: TickInput = TickInput { fire: true, ..IDLE };

fn turn(degrees: f32) -> TickInput {
    TickInput { turn: degrees, ..IDLE }
}

/// One tick; returns its events.
fn tick(g: &mut SimGame, input: TickInput) -> Vec<Event> {
    g.tick(&input);
    events(g).to_vec()
}

fn idle(g: &mut SimGame, ticks: usize) {
    for _ in 0..ticks {
        g.tick(&IDLE);
    }
}

/// Presses use for one tick (use acts once per press: it must have been released).
fn press_use(g: &mut SimGame) -> Vec<Event> {
    assert!(!console(g).usedown, "use is still held from the tick before");
    tick(g, USE)
}

/// Puts the player at (x, y) facing `angle`, still, feet on the floor, use
/// released ([`sim_play::stand`]).
fn stand(g: &mut SimGame, x: f64, y: f64, angle: f64) {
    sim_play::stand(g, DVec2::new(x, y), angle);
}

/// Where the player's body is now (also right after [`stand`]).
fn pos(g: &SimGame) -> DVec2 {
    let m = g.sim.mo(console(g).mo);
    DVec2::new(m.x.to_f64(), m.y.to_f64())
}

/// Ticks `input` until `done` (checked after each tick); returns the ticks taken.
fn until(g: &mut SimGame, input: TickInput, limit: usize, done: impl Fn(&SimGame) -> bool) -> usize {
    for n in 1..=limit {
        g.tick(&input);
        if done(g) {
            return n;
        }
    }
    panic!("not done after {limit} ticks; the player is at {:?}", pos(&g));
}

fn floor(g: &SimGame, s: usize) -> f64 {
    level(g).compiled.map.sectors[s].floor
}

fn ceiling(g: &SimGame, s: usize) -> f64 {
    level(g).compiled.map.sectors[s].ceiling
}

fn light(g: &SimGame, s: usize) -> u8 {
    level(g).compiled.map.sectors[s].light
}

/// The sector tagged `tag` (the maps give each tag to one sector).
fn tagged(g: &SimGame, tag: u16) -> usize {
    let found: Vec<usize> = level(g).compiled.map.sectors_tagged(tag).collect();
    assert_eq!(found.len(), 1, "sectors tagged {tag}: {found:?}");
    found[0]
}

/// The one line whose special has this tag.
fn line_tagged(g: &SimGame, tag: u16) -> usize {
    let lines = &level(g).compiled.map.lines;
    let found: Vec<usize> =
        (0..lines.len()).filter(|&i| lines[i].special.as_ref().is_some_and(|s| s.tag == tag)).collect();
    assert_eq!(found.len(), 1, "lines with specials tagged {tag}: {found:?}");
    found[0]
}

/// Is a floor or ceiling mover (door, lift, floor, ceiling) at work on `s`?
fn moving(g: &SimGame, s: usize) -> bool {
    Observe::is_busy(g, s)
}

/// What a lift (`plat_t`) is doing; `Waiting` with its count of ticks left.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum PlatState {
    Up,
    Down,
    Waiting { count: i32 },
    Stasis,
}

fn plat(g: &SimGame, s: usize) -> Option<PlatState> {
    // A lift in stasis keeps its sector's specialdata; look it up among
    // the thinkers, as P_ActivateInStasis does among the active plats.
    let found = g.sim.thinkers.iter().filter(|t| t.status != Status::Removed).find_map(|t| match &t.kind {
        ThinkerKind::Plat(p) if p.sector == s => Some((p, t.status)),
        _ => None,
    });
    let (p, status) = found?;
    Some(match (status, p.status) {
        (Status::Stasis, _) | (_, PlatStatus::InStasis) => PlatState::Stasis,
        (_, PlatStatus::Up) => PlatState::Up,
        (_, PlatStatus::Down) => PlatState::Down,
        (_, PlatStatus::Waiting) => PlatState::Waiting { count: p.count },
    })
}

/// Live thinkers of a kind on sector `s`.
fn thinkers_on(g: &SimGame, s: usize, kind: fn(&ThinkerKind) -> Option<usize>) -> usize {
    g.sim.thinkers.iter().filter(|t| t.status != Status::Removed && kind(&t.kind) == Some(s)).count()
}

/// The name of the texture the front side of `line` shows in its middle.
fn middle(g: &SimGame, line: usize) -> String {
    let m = &level(g).materials;
    let id = m.sides[line][0].middle.expect("the line has a middle texture");
    m.textures.name(id).to_string()
}

fn sounds(events: &[Event]) -> Vec<&'static str> {
    events.iter().filter_map(|e| if let Event::Sound { sound, .. } = e { Some(*sound) } else { None }).collect()
}

fn has_sound(events: &[Event], sound: &str, origin: Origin) -> bool {
    events.iter().any(|e| matches!(e, Event::Sound { sound: s, origin: o } if *s == sound && *o == origin))
}

fn messages(events: &[Event]) -> Vec<String> {
    events.iter().filter_map(|e| if let Event::Message(m) = e { Some(m.clone()) } else { None }).collect()
}

/// The specials set off (or tried) this tick: (line, started).
fn specials_set_off(events: &[Event]) -> Vec<(SpecialLine, bool)> {
    events
        .iter()
        .filter_map(|e| if let Event::Special { line, started } = e { Some((*line, *started)) } else { None })
        .collect()
}

/// The heights a plane passes through from `from` to `to` at `speed` a
/// tick, one a tick, the last exactly `to` (Doom's T_MovePlane). A plane
/// landing on `to` by whole steps reports its arrival on the tick after,
/// at `to` again (`height + speed > dest` is false on the landing step);
/// a last step cut short arrives at once. `[to]` when it is there already
/// (the first step passes it).
fn path(from: f64, to: f64, speed: f64) -> Vec<f64> {
    if from == to {
        return vec![to];
    }
    let mut out = Vec::new();
    let mut h = from;
    while h != to {
        let step = if to > from { h + speed } else { h - speed };
        let cut = if to > from { step > to } else { step < to };
        h = if cut { to } else { step };
        out.push(h);
        if h == to && !cut {
            out.push(to);
        }
    }
    out
}

/// The heights of a plane stopped short of its destination: [`path`]
/// without the arrival tick.
fn steps(from: f64, to: f64, speed: f64) -> Vec<f64> {
    let mut out = path(from, to, speed);
    if out.len() > 1 && out[out.len() - 2] == to {
        out.pop();
    }
    out
}

fn repeat(h: f64, n: usize) -> Vec<f64> {
    vec![h; n]
}

fn concat(parts: &[Vec<f64>]) -> Vec<f64> {
    parts.concat()
}

/// Runs `ticks` ticks of `input` (the first one already run by the caller
/// is not included) and returns `height(g)` after each.
fn record(g: &mut SimGame, input: TickInput, ticks: usize, height: impl Fn(&SimGame) -> f64) -> Vec<f64> {
    (0..ticks)
        .map(|_| {
            g.tick(&input);
            height(g)
        })
        .collect()
}

/// Sets a special off with `first` (use or fire), then idles until the
/// mover on `s` is done; returns the heights after each tick, the first
/// tick included.
fn run_mover(g: &mut SimGame, first: TickInput, s: usize, height: impl Fn(&SimGame, usize) -> f64) -> Vec<f64> {
    g.tick(&first);
    let mut out = vec![height(g, s)];
    while moving(g, s) {
        assert!(out.len() < 5000, "sector {s} never stops");
        g.tick(&IDLE);
        out.push(height(g, s));
    }
    out
}

// ---------------------------------------------------------------------------
// Lifts (tests/maps/lift.ron: lower room 0, lift A 1 (tag 1), lift B 2 (tag 2), upper room 3;
// apart, low pad 4, lift C 5 (tag 3, perpetual), high pad 6)

#[test]
fn a_lift_goes_down_waits_105_ticks_and_comes_back_up_carrying_the_player() {
    let mut g = game("lift");
    let (lift, lower) = (1, 0);
    assert_eq!((floor(&g, lift), floor(&g, lower), floor(&g, 3)), (64.0, 0.0, 64.0));
    // Walk east along y 208: the walk line at x 160 sets lift A off.
    until(&mut g, WALK, 40, |g| moving(g, lift));
    let mut heights = vec![floor(&g, lift)];
    let mut events = vec![events(&g).to_vec()];
    let mut riding = Vec::new();
    // Down at 4 a tick to the lowest neighbouring floor (the lower room's 0),
    // arriving the tick after it lands; 105 ticks there (Doom's PLATWAIT
    // 3 s, counted down from the tick after), then up at 4 to where it
    // started.
    let want = concat(&[path(64.0, 0.0, 4.0), repeat(0.0, 105), path(0.0, 64.0, 4.0), repeat(64.0, 20)]);
    // Onto the lift as soon as it is low enough, then stand still on it.
    for _ in 1..want.len() {
        let input = if player(&g).sector == lift { IDLE } else { WALK };
        events.push(tick(&mut g, input));
        heights.push(floor(&g, lift));
        riding.push((player(&g).sector == lift, player(&g).z, floor(&g, lift)));
    }
    assert_eq!(heights, want);
    // Sounds: pstart going down, pstop at the bottom, pstart going up, pstop at the top.
    let at = Origin::Sector(lift);
    // At 0 on tick 15, arrived on 16, up again on 16 + 105, at 64 on
    // 121 + 16 and arrived on the tick after.
    for (k, sound) in [(0, "pstart"), (16, "pstop"), (16 + 105, "pstart"), (16 + 105 + 17, "pstop")] {
        assert!(has_sound(&events[k], sound, at), "tick {k}: no {sound} in {:?}", events[k]);
    }
    assert_eq!(sounds(&events[17..121].concat()), Vec::<&str>::new(), "sounds while it waits");
    // Done at the top: no thinker left.
    assert_eq!(plat(&g, lift), None);
    // The player was on it all the way up, feet on its floor.
    let up = &riding[121..137];
    assert!(up.iter().all(|&(on, z, f)| on && z == f), "did not ride up: {up:?}");
    assert_eq!(player(&g).z, 64.0);
}

#[test]
fn a_lift_with_a_body_in_the_way_goes_back_down() {
    let mut g = game("lift");
    let lift = 2;
    // Lift B's switch faces the lower room at x 256.
    stand(&mut g, 200.0, 128.0, 0.0);
    let e = press_use(&mut g);
    assert!(has_sound(&e, "pstart", Origin::Sector(lift)), "{e:?}");
    assert_eq!(floor(&g, lift), 60.0);
    // Down to the south wall, then east onto the lift (its floor is 0 by then).
    tick(&mut g, turn(-90.0));
    until(&mut g, WALK, 60, |g| pos(&g).y < 40.0);
    idle(&mut g, 30);
    tick(&mut g, turn(90.0));
    until(&mut g, WALK, 60, |g| player(&g).sector == lift);
    until(&mut g, IDLE, 200, |g| plat(g, lift) == Some(PlatState::Up));
    // It rises with the player on it until the body no longer fits under its
    // ceiling (112 - 56 = 56); the step to 60 is undone and it goes back down
    // (Doom's T_PlatRaise: crushed and not a crusher -> down).
    assert_eq!(floor(&g, lift), 0.0);
    let mut heights = Vec::new();
    let mut reversed_at = None;
    for k in 0..40 {
        let e = tick(&mut g, IDLE);
        heights.push(floor(&g, lift));
        assert_eq!(player(&g).z, floor(&g, lift), "tick {k}: the player does not ride the lift");
        if reversed_at.is_none() && plat(&g, lift) == Some(PlatState::Down) {
            reversed_at = Some(k);
            assert!(has_sound(&e, "pstart", Origin::Sector(lift)), "{e:?}");
        }
    }
    // Down to 0 by tick 28, arrived on 29, then 10 of its 105 ticks waited.
    let want = concat(&[steps(0.0, 56.0, 4.0), vec![56.0], path(56.0, 0.0, 4.0), repeat(0.0, 10)]);
    assert_eq!(heights, want);
    assert_eq!(reversed_at, Some(14));
    assert_eq!(plat(&g, lift), Some(PlatState::Waiting { count: 105 - 10 }));
    // With the player gone, it goes all the way up and stops.
    stand(&mut g, 128.0, 128.0, 0.0);
    until(&mut g, IDLE, 300, |g| plat(g, lift).is_none());
    assert_eq!(floor(&g, lift), 64.0);
}

#[test]
fn a_perpetual_lift_goes_between_the_lowest_and_highest_floors_until_stopped_and_wakes_again() {
    let mut g = game("lift");
    let lift = 5;
    assert_eq!((floor(&g, 4), floor(&g, lift), floor(&g, 6)), (0.0, 32.0, 96.0));
    stand(&mut g, 40.0, 360.0, 180.0);
    press_use(&mut g);
    let mut heights = vec![floor(&g, lift)];
    heights.extend(record(&mut g, IDLE, 599, |g| floor(g, lift)));
    // Speed 1 (Doom's PLATSPEED), between the lowest (0) and the highest (96)
    // neighbouring floor, 105 ticks at each end; the first way is P_Random & 1.
    let (first, second) = if heights[0] > 32.0 { (96.0, 0.0) } else { (0.0, 96.0) };
    let cycle = |a: f64, b: f64| concat(&[path(a, b, 1.0), repeat(b, 105)]);
    let want = concat(&[cycle(32.0, first), cycle(first, second), cycle(second, first), cycle(first, second)]);
    assert_eq!(heights, want[..600]);
    // Stopped: it stays, remembering what it was doing.
    stand(&mut g, 40.0, 408.0, 180.0);
    press_use(&mut g);
    let stopped = floor(&g, lift);
    let was = plat(&g, lift);
    assert!(matches!(was, Some(PlatState::Stasis { .. })), "{was:?}");
    let held = record(&mut g, IDLE, 300, |g| floor(g, lift));
    assert!(held.iter().all(|&h| h == stopped), "moved while stopped");
    // The perpetual special again wakes it: on from where it was.
    stand(&mut g, 40.0, 360.0, 180.0);
    press_use(&mut g);
    let going = concat(&[vec![floor(&g, lift)], record(&mut g, IDLE, 200, |g| floor(g, lift))]);
    let resumed = want[600..].iter().copied().skip_while(|&h| h == stopped).take(3).collect::<Vec<_>>();
    assert_eq!(going.iter().copied().skip_while(|&h| h == stopped).take(3).collect::<Vec<_>>(), resumed);
    let lifts = thinkers_on(&g, lift, |k| if let ThinkerKind::Plat(p) = k { Some(p.sector) } else { None });
    assert_eq!(lifts, 1);
}

// ---------------------------------------------------------------------------
// Doors (tests/maps/doors.ron: hall 0, closet 1, doors 0-7 are sectors 2-9)

const DOOR_TOP: f64 = 128.0 - 4.0;

#[test]
fn a_raise_door_opens_at_2_waits_150_and_closes() {
    let mut g = game("doors");
    let d = 2;
    // The player starts below door 0's switch, facing it; a level's first
    // tick uses nothing (G_PlayerReborn holds use down).
    idle(&mut g, 1);
    let first = press_use(&mut g);
    assert!(has_sound(&first, "doropn", Origin::Sector(d)), "{first:?}");
    let mut events = vec![first];
    let mut heights = vec![ceiling(&g, d)];
    while moving(&g, d) {
        events.push(tick(&mut g, IDLE));
        heights.push(ceiling(&g, d));
    }
    let want = concat(&[path(0.0, DOOR_TOP, 2.0), repeat(DOOR_TOP, 150), path(DOOR_TOP, 0.0, 2.0)]);
    assert_eq!(heights, want);
    // At the top on tick 61, arrived on 62, closing 150 ticks later (Doom's VDOORWAIT).
    let closes = 62 + 150;
    assert!(has_sound(&events[closes], "dorcls", Origin::Sector(d)), "{:?}", events[closes]);
    assert!(events.iter().enumerate().all(|(k, e)| k == 0 || k == closes || sounds(e).is_empty()));
}

#[test]
fn an_open_door_stays_open_and_a_once_only_switch_works_once() {
    let mut g = game("doors");
    let d = 3;
    stand(&mut g, 160.0, 40.0, 270.0);
    let heights = run_mover(&mut g, USE, d, ceiling);
    assert_eq!(heights, path(0.0, DOOR_TOP, 2.0));
    idle(&mut g, 300);
    assert_eq!((ceiling(&g, d), door(&g, d)), (DOOR_TOP, None));
    // S1: spent. The switch is a plain wall now.
    let e = press_use(&mut g);
    assert_eq!((specials_set_off(&e), sounds(&e)), (vec![], vec!["noway"]));
}

#[test]
fn a_close_door_closes_and_keeps_pushing_on_a_body_without_going_back_up() {
    let mut g = game("doors");
    let d = 4;
    assert_eq!(ceiling(&g, d), DOOR_TOP);
    // Stand in the doorway and use the switch on its east jamb.
    stand(&mut g, 256.0, 264.0, 0.0);
    let e = press_use(&mut g);
    assert!(has_sound(&e, "dorcls", Origin::Sector(d)), "{e:?}");
    let heights = record(&mut g, IDLE, 99, |g| ceiling(g, d));
    let heights = concat(&[vec![122.0], heights]);
    // Down at 2 until the next step would leave the body less than 56; then
    // it tries again every tick (Doom's close doors do not bounce).
    assert_eq!(heights, concat(&[steps(DOOR_TOP, 56.0, 2.0), repeat(56.0, 100 - 34)]));
    assert_eq!(door(&g, d), Some(DoorState::Closing));
    // The body leaves: it shuts.
    tick(&mut g, turn(-90.0));
    until(&mut g, WALK, 40, |g| pos(&g).y < 220.0);
    until(&mut g, IDLE, 100, |g| !moving(g, d));
    assert_eq!(ceiling(&g, d), 0.0);
}

#[test]
fn a_close_then_open_door_stays_shut_for_its_wait() {
    let mut g = game("doors");
    let d = 5;
    stand(&mut g, 352.0, 40.0, 270.0);
    let mut events = Vec::new();
    g.tick(&USE);
    events.push(Observe::events(&g).to_vec());
    let mut heights = vec![ceiling(&g, d)];
    while moving(&g, d) {
        events.push(tick(&mut g, IDLE));
        heights.push(ceiling(&g, d));
    }
    // Down, arrived on tick 62, 1050 ticks shut (Doom's 30 s of special
    // 16), back up to where it was.
    assert_eq!(heights, concat(&[path(DOOR_TOP, 0.0, 2.0), repeat(0.0, 1050), path(0.0, DOOR_TOP, 2.0)]));
    assert!(has_sound(&events[0], "dorcls", Origin::Sector(d)), "{:?}", events[0]);
    assert!(has_sound(&events[62 + 1050], "doropn", Origin::Sector(d)), "{:?}", events[62 + 1050]);
}

#[test]
fn a_blazing_door_moves_at_8_with_the_blazing_sounds() {
    let mut g = game("doors");
    let d = 6;
    stand(&mut g, 448.0, 40.0, 270.0);
    let mut events = Vec::new();
    g.tick(&USE);
    events.push(Observe::events(&g).to_vec());
    let mut heights = vec![ceiling(&g, d)];
    while moving(&g, d) {
        events.push(tick(&mut g, IDLE));
        heights.push(ceiling(&g, d));
    }
    assert_eq!(heights, concat(&[path(0.0, DOOR_TOP, 8.0), repeat(DOOR_TOP, 150), path(DOOR_TOP, 0.0, 8.0)]));
    assert_eq!(heights[..2], [8.0, 16.0]);
    assert!(has_sound(&events[0], "bdopn", Origin::Sector(d)), "{:?}", events[0]);
    assert!(has_sound(&events[15 + 150], "bdcls", Origin::Sector(d)), "{:?}", events[15 + 150]);
}

#[test]
fn a_manual_door_used_again_reverses_and_an_open_one_closes_at_once() {
    let mut g = game("doors");
    let d = 7;
    stand(&mut g, 544.0, 200.0, 90.0);
    let e = press_use(&mut g);
    assert!(has_sound(&e, "doropn", Origin::Sector(d)), "{e:?}");
    assert_eq!((door(&g, d), ceiling(&g, d)), (Some(DoorState::Opening), 2.0));
    tick(&mut g, IDLE);
    // Opening: used again, it closes (Doom's EV_VerticalDoor, a player using it).
    press_use(&mut g);
    assert_eq!((door(&g, d), ceiling(&g, d)), (Some(DoorState::Closing), 2.0));
    tick(&mut g, IDLE);
    assert_eq!(ceiling(&g, d), 0.0);
    // Shut: used, it opens.
    press_use(&mut g);
    assert_eq!((door(&g, d), ceiling(&g, d)), (Some(DoorState::Opening), 2.0));
    until(&mut g, IDLE, 100, |g| matches!(door(g, d), Some(DoorState::Open)));
    assert_eq!(ceiling(&g, d), DOOR_TOP);
    idle(&mut g, 10);
    // Open and waiting: used, it closes at once.
    press_use(&mut g);
    assert_eq!((door(&g, d), ceiling(&g, d)), (Some(DoorState::Closing), DOOR_TOP - 2.0));
    // Closing: used, it opens again.
    tick(&mut g, IDLE);
    press_use(&mut g);
    assert_eq!((door(&g, d), ceiling(&g, d)), (Some(DoorState::Opening), DOOR_TOP - 2.0));
    // The closet's door line works the same door from the other side.
    until(&mut g, IDLE, 10, |g| matches!(door(g, d), Some(DoorState::Open)));
    stand(&mut g, 544.0, 312.0, 270.0);
    press_use(&mut g);
    assert_eq!(door(&g, d), Some(DoorState::Closing));
}

#[test]
fn a_closing_door_goes_back_up_when_it_meets_the_player() {
    let mut g = game("doors");
    let d = 7;
    stand(&mut g, 544.0, 200.0, 90.0);
    press_use(&mut g);
    until(&mut g, IDLE, 100, |g| matches!(door(g, d), Some(DoorState::Open)));
    // Stand in the doorway until it comes down on the player.
    stand(&mut g, 544.0, 264.0, 90.0);
    let mut lowest = f64::INFINITY;
    let mut reversals = Vec::new();
    let mut was = door(&g, d);
    for k in 0..600 {
        let e = tick(&mut g, IDLE);
        let now = door(&g, d);
        lowest = lowest.min(ceiling(&g, d));
        assert!(ceiling(&g, d) - player(&g).z >= 56.0, "tick {k}: the door came down on the player");
        if was == Some(DoorState::Closing) && now == Some(DoorState::Opening) {
            assert!(has_sound(&e, "doropn", Origin::Sector(d)), "{e:?}");
            assert_eq!(ceiling(&g, d), 56.0);
            reversals.push(k);
        }
        was = now;
    }
    // The step to 54 undone: back up to 124 (34 ticks, arrived on the 35th),
    // 150 waiting (the last of them turning it down), down to 56 (34 ticks)
    // and the step to 54 undone again: every 35 + 150 + 35 ticks.
    assert_eq!(lowest, 56.0);
    assert!(reversals.len() >= 2, "reversed {reversals:?}");
    assert_eq!(reversals[1] - reversals[0], 35 + 150 + 35, "{reversals:?}");
}

#[test]
fn sector_timers_close_a_door_after_30_seconds_and_open_one_after_5_minutes() {
    let mut g = game("doors");
    let (closes, opens) = (8, 9);
    let mut c = Vec::new();
    let mut o = Vec::new();
    for _ in 0..5 * 60 * 35 + 63 + 150 + 63 {
        g.tick(&IDLE);
        c.push(ceiling(&g, closes));
        o.push(ceiling(&g, opens));
    }
    // Doom's P_SpawnDoorCloseIn30: open 1050 ticks (the last turning it
    // down), then down at 2.
    let want = concat(&[repeat(DOOR_TOP, 1050), path(DOOR_TOP, 0.0, 2.0)]);
    assert_eq!(c[..want.len()], want[..]);
    assert!(c[want.len()..].iter().all(|&h| h == 0.0));
    // P_SpawnDoorRaiseIn5Mins: shut 10500 ticks (the last turning it up),
    // then a normal door.
    let want = concat(&[repeat(0.0, 10500), path(0.0, DOOR_TOP, 2.0), repeat(DOOR_TOP, 150), path(DOOR_TOP, 0.0, 2.0)]);
    assert_eq!(o, want);
    assert!(!moving(&g, closes) && !moving(&g, opens));
}

// ---------------------------------------------------------------------------
// Keys and locked doors (tests/maps/locked_door.ron: hall 0, closet 1, door M 2, door S 3;
// things: 0 the start, 1 the blue card, 2 the blue skull)

/// Whether the blue card and the blue skull are still in play.
fn keys_in_play(g: &SimGame) -> [bool; 2] {
    let table = Observe::table(g);
    let there = |name: &str| {
        let kind = table.index(name).unwrap_or_else(|| panic!("no actor {name}"));
        Observe::seen(g).iter().any(|s| s.kind == kind && !s.removed)
    };
    [there("blue_card"), there("blue_skull")]
}

fn use_door_m(g: &mut SimGame) -> Vec<Event> {
    stand(g, 96.0, 200.0, 90.0);
    press_use(g)
}

fn use_switch_s(g: &mut SimGame) -> Vec<Event> {
    stand(g, 352.0, 40.0, 270.0);
    press_use(g)
}

#[test]
fn a_locked_door_refuses_without_its_key_and_opens_with_the_card() {
    let mut g = game("locked_door");
    let e = use_door_m(&mut g);
    assert_eq!(messages(&e), ["You need a blue key to open this door"]);
    assert!(has_sound(&e, "oof", Origin::Player), "{e:?}");
    // (The simulation reports door M's line as used and started here: Doom's
    // P_UseSpecialLine returns true for a manual door whatever
    // EV_VerticalDoor did. Nothing moves, as checked below.)
    tick(&mut g, IDLE);
    let e = use_switch_s(&mut g);
    assert_eq!(messages(&e), ["You need a blue key to activate this object"]);
    assert!(specials_set_off(&e).iter().all(|&(_, started)| !started), "{e:?}");
    idle(&mut g, 5);
    let doors = g.sim.thinkers.iter().filter(|t| t.status != Status::Removed && matches!(t.kind, ThinkerKind::Door(_)));
    assert_eq!(doors.count(), 0, "something opened");
    assert_eq!((ceiling(&g, 2), ceiling(&g, 3)), (0.0, 0.0));
    // Walk east over the blue card in the middle of the hall.
    stand(&mut g, 180.0, 128.0, 0.0);
    assert_eq!(keys_in_play(&g), [true, true]);
    let mut picked = Vec::new();
    until(&mut g, WALK, 40, |g| !player(&g).keys.is_empty());
    picked.extend(events(&g).to_vec());
    assert_eq!(messages(&picked), ["Picked up a blue keycard."]);
    assert!(has_sound(&picked, "itemup", Origin::Player));
    assert_eq!(player(&g).keys, [Key { colour: KeyColour::Blue, form: KeyForm::Card }]);
    assert_eq!(keys_in_play(&g), [false, true], "the card is still there (or the skull went)");
    idle(&mut g, 30);
    assert_eq!(player(&g).keys.len(), 1);
    // Now both open.
    let e = use_switch_s(&mut g);
    assert_eq!(messages(&e), Vec::<String>::new());
    assert_eq!((door(&g, 3), ceiling(&g, 3)), (Some(DoorState::Opening), 2.0));
    tick(&mut g, IDLE);
    use_door_m(&mut g);
    assert_eq!((door(&g, 2), ceiling(&g, 2)), (Some(DoorState::Opening), 2.0));
}

#[test]
fn a_skull_of_the_same_colour_opens_it_too() {
    let mut g = game("locked_door");
    stand(&mut g, 380.0, 64.0, 0.0);
    until(&mut g, WALK, 40, |g| !player(&g).keys.is_empty());
    assert_eq!(messages(events(&g)), ["Picked up a blue skull key."]);
    assert_eq!(player(&g).keys, [Key { colour: KeyColour::Blue, form: KeyForm::Skull }]);
    assert_eq!(keys_in_play(&g), [true, false]);
    use_door_m(&mut g);
    assert_eq!(door(&g, 2), Some(DoorState::Opening));
}

// ---------------------------------------------------------------------------
// Floors (tests/maps/floors.ron: bay k is tagged k + 1; its switch is on the corridor's
// south wall at x 64 + 96k)

fn use_bay_switch(g: &mut SimGame, k: u16) {
    stand(g, 64.0 + 96.0 * f64::from(k), 40.0, 270.0);
}

#[test]
fn floors_move_to_each_of_dooms_targets_at_their_speeds() {
    // (bay, from, to, speed)
    let cases = [
        (0, 64.0, -32.0, 1.0), // lowest neighbouring floor (own 64, corridor 0, behind -32)
        (1, 128.0, 56.0, 4.0), // turbo lower: highest neighbouring floor 48, plus 8
        (2, 48.0, 48.0, 4.0),  // turbo lower where that floor is its own: no + 8
        (3, 96.0, 32.0, 1.0),  // highest neighbouring floor (corridor 0, behind 32)
        (4, 0.0, 40.0, 1.0),   // next higher floor among 0, 40, 80
        (5, 0.0, 96.0, 1.0),   // lowest neighbouring ceiling (256, 96)
        (6, 0.0, 80.0, 1.0),   // ... capped at its own ceiling 80
        (7, 0.0, 23.0, 1.0),   // shortest lower texture: ODD (23) beside BRICK (64)
        (8, 0.0, 24.0, 1.0),   // raise by 24
        (9, 0.0, 512.0, 1.0),  // raise by 512
    ];
    let mut g = game("floors");
    for (k, from, to, speed) in cases {
        let s = tagged(&g, k + 1);
        assert_eq!(floor(&g, s), from, "bay {k}");
        use_bay_switch(&mut g, k);
        let heights = run_mover(&mut g, USE, s, floor);
        assert_eq!(heights, path(from, to, speed), "bay {k}");
        idle(&mut g, 3);
        assert_eq!(floor(&g, s), to, "bay {k}");
    }
}

#[test]
fn a_key_on_a_pedestal_does_not_hold_up_its_floor() {
    // The card's box reaches over the pedestal's edge into the hall, where
    // the opening is below nothing (floor 224, ceiling 128). Doom's
    // PIT_ChangeSector passes over a thing that cannot be shot: the floor
    // goes all the way down (it used to stop on its first step for ever).
    let mut g = game("pedestal");
    let s = tagged(&g, 1);
    assert_eq!(floor(&g, s), 224.0);
    stand(&mut g, 112.0, 40.0, 270.0);
    press_use(&mut g);
    let ticks = until(&mut g, IDLE, 400, |g| !moving(g, s));
    assert_eq!(floor(&g, s), 0.0, "stopped after {ticks} ticks");
    assert!((220..=230).contains(&ticks), "224 units at 1 a tick took {ticks}");
}

/// A sector's floor flat and special as the simulation has them (the drawn
/// level's map keeps the RON map's): the flat's name and Doom's number
/// (5: 10 damage, 7: 5 damage, 0: none).
fn sim_floor(g: &SimGame, s: usize) -> (String, i16) {
    let sector = &g.sim.level.sectors[s];
    (g.sim.level.name(sector.floorpic).to_string(), sector.special)
}

#[test]
fn a_floor_takes_the_switch_lines_front_sectors_texture_and_special_at_once() {
    let mut g = game("floors");
    let bay = tagged(&g, 11);
    let alcove = level(&g).map.lines[line_tagged(&g, 11)].front.sector;
    let damage5 = SectorSpecial {
        damage: Some(Damage { amount: 5, every: 32, exit_below: 0, suit: Default::default() }),
        ..Default::default()
    };
    assert_eq!(level(&g).map.sectors[alcove].special, damage5);
    assert_eq!(sim_floor(&g, alcove), ("GRASS".to_string(), 7));
    assert_eq!(sim_floor(&g, bay), ("FLOOR".to_string(), 0));
    // The switch is on the alcove's back wall, 56 south of here.
    stand(&mut g, 64.0 + 96.0 * 10.0, 24.0, 270.0);
    press_use(&mut g);
    // Doom's raiseFloor24AndChange takes both when it starts.
    assert_eq!((floor(&g, bay), sim_floor(&g, bay)), (1.0, ("GRASS".to_string(), 7)));
    let m = &level(&g).materials;
    assert_eq!(m.sectors[bay].floor, m.sectors[alcove].floor, "drawn with the old flat");
    until(&mut g, IDLE, 40, |g| !moving(g, bay));
    assert_eq!(floor(&g, bay), 24.0);
}

#[test]
fn a_floor_takes_the_texture_of_the_neighbour_it_arrives_at_copying_or_clearing_its_special() {
    // (bay, new texture, special after arrival: Doom's 5 is 10 damage)
    for (k, texture, special) in [(11u16, "DIRT", 5), (12, "WATER", 0)] {
        let mut g = game("floors");
        let bay = tagged(&g, k + 1);
        let before = sim_floor(&g, bay);
        assert_eq!(before.0, "FLOOR");
        use_bay_switch(&mut g, k);
        g.tick(&USE);
        let mut last = (floor(&g, bay), sim_floor(&g, bay));
        while moving(&g, bay) {
            // On the way: the old texture and special.
            assert_eq!(last.1, before, "bay {k}");
            g.tick(&IDLE);
            last = (floor(&g, bay), sim_floor(&g, bay));
        }
        // On arrival: the model's (the neighbour whose floor is -16).
        assert_eq!(last, (-16.0, (texture.to_string(), special)), "bay {k}");
        let model = (0..g.sim.level.sectors.len()).find(|&s| s != bay && sim_floor(&g, s).0 == texture).unwrap();
        let m = &level(&g).materials;
        assert_eq!(m.sectors[bay].floor, m.sectors[model].floor, "bay {k} is drawn with the old flat");
    }
}

// ---------------------------------------------------------------------------
// Ceilings and crushers (tests/maps/ceilings.ron: bay k tagged k + 1; bays 3-5 switched
// from inside, standing at x 64 + 96k, y 200)

fn stand_in_bay(g: &mut SimGame, k: u16, angle: f64) {
    stand(g, 64.0 + 96.0 * f64::from(k), 200.0, angle);
}

#[test]
fn ceilings_move_to_the_floor_the_floor_plus_8_and_the_highest_neighbouring_ceiling() {
    let mut g = game("ceilings");
    for (k, from, to) in [(0, 128.0, 0.0), (1, 128.0, 8.0), (2, 96.0, 224.0)] {
        let s = tagged(&g, k + 1);
        assert_eq!(ceiling(&g, s), from);
        use_bay_switch(&mut g, k);
        assert_eq!(run_mover(&mut g, USE, s, ceiling), path(from, to, 1.0), "bay {k}");
    }
}

/// Plays a crusher with the player under it: the ceiling and the health
/// after each tick, with the tick's `leveltime`.
fn crush(g: &mut SimGame, s: usize, ticks: usize) -> Vec<(u64, f64, i32)> {
    let mut out = Vec::new();
    for k in 0..ticks {
        let time = leveltime(&g);
        g.tick(if k == 0 { &USE } else { &IDLE });
        out.push((time, ceiling(g, s), player(&g).health));
        assert_eq!(player(&g).z, 0.0);
    }
    out
}

/// Checks that the player lost 10 health exactly on the ticks where Doom's
/// PIT_ChangeSector hurts: `leveltime % 4 == 0`, on the way down (`down`,
/// whose last tick is the one the crusher learns it is at the bottom), with
/// the ceiling less than 56 above the floor. On that last tick it hurts
/// twice: T_MovePlane sets the ceiling to its destination and calls
/// P_ChangeSector, finds the body does not fit, puts the ceiling back (at
/// the same height) and calls it again. Returns the number of hurts (a
/// dead player is hurt no more).
fn check_crush_damage(run: &[(u64, f64, i32)], start_health: i32, down: std::ops::RangeInclusive<usize>) -> usize {
    let mut health = start_health;
    let mut hurts = 0;
    for (k, &(time, ceiling, h)) in run.iter().enumerate() {
        let hurt = down.contains(&k) && ceiling < 56.0 && time % 4 == 0;
        let bites = if k == *down.end() { 2 } else { 1 };
        let want = if hurt { (health - 10 * bites).max(0) } else { health };
        assert_eq!(h, want, "tick {k} (leveltime {time}, ceiling {ceiling})");
        hurts += usize::from(h < health);
        health = h;
    }
    hurts
}

#[test]
fn a_slow_crusher_slows_to_an_eighth_while_crushing_hurts_every_4th_tick_and_reverses_at_floor_plus_8() {
    let mut g = game("ceilings");
    let s = tagged(&g, 4);
    // Enough health to live through it, so the body stays in the way.
    g.set_health(100_000);
    stand_in_bay(&mut g, 3, 90.0);
    // 1 a tick while the body fits (128 -> 56), the step to 55 kept (it
    // crushes), then an eighth (Doom's CEILSPEED / 8) down to floor + 8,
    // then back up at full speed to 128 and down again.
    let want = concat(&[
        steps(128.0, 56.0, 1.0),
        vec![55.0],
        path(55.0, 8.0, 0.125),
        path(8.0, 128.0, 1.0),
        steps(128.0, 88.0, 1.0),
    ]);
    let run = crush(&mut g, s, want.len());
    let heights: Vec<f64> = run.iter().map(|r| r.1).collect();
    assert_eq!(heights, want);
    // Crushing from the step to 55 (tick 72) to the tick it learns it is at
    // 8 (449: T_MovePlane crushes on that tick too).
    let hurts = check_crush_damage(&run, 100_000, 72..=72 + 377);
    assert!((94..=95).contains(&hurts), "{hurts} hurts in 378 ticks");
}

#[test]
fn a_fast_crusher_does_not_slow_down_and_the_player_lives_through_one_pass() {
    let mut g = game("ceilings");
    let s = tagged(&g, 5);
    stand_in_bay(&mut g, 4, 90.0);
    let want = concat(&[path(128.0, 8.0, 2.0), path(8.0, 128.0, 2.0)]);
    let run = crush(&mut g, s, want.len());
    let heights: Vec<f64> = run.iter().map(|r| r.1).collect();
    assert_eq!(heights, want);
    // 25 ticks crushing (54 down to 8, and the tick it learns it is there):
    // leveltime 36 to 60, seven multiples of 4, the last hurting twice.
    assert_eq!(check_crush_damage(&run, 100, 36..=60), 7);
    assert_eq!(player(&g).health, 20);
}

#[test]
fn a_crusher_kills_and_goes_on_over_the_body() {
    let mut g = game("ceilings");
    let s = tagged(&g, 4);
    stand_in_bay(&mut g, 3, 90.0);
    let run = crush(&mut g, s, 72 + 1 + 377 + 121);
    let hurts = check_crush_damage(&run, 100, 72..=72 + 377);
    assert_eq!(hurts, 10, "ten hurts of 10 from 100");
    assert!(player(&g).dead());
    // It did not stop over the body: down to 8 and back up.
    let heights: Vec<f64> = run.iter().map(|r| r.1).collect();
    assert_eq!(heights[72 + 377], 8.0);
    assert_eq!(heights.last(), Some(&128.0));
}

#[test]
fn a_dead_body_does_not_hold_up_a_ceiling() {
    // Doom's PIT_ChangeSector turns a corpse into gibs with no height: it
    // never stops a plane.
    let mut g = game("ceilings");
    let s = tagged(&g, 6);
    stand_in_bay(&mut g, 5, 90.0);
    press_use(&mut g);
    let mo = console(&g).mo;
    sightline::sim::interaction::damage_mobj(&mut g.sim, mo, None, None, 1000);
    assert!(console(&g).health <= 0 && g.sim.mo(mo).health <= 0, "not dead");
    until(&mut g, IDLE, 200, |g| !moving(g, s));
    assert_eq!(ceiling(&g, s), 0.0);
}

#[test]
fn a_stopped_crusher_stays_put_and_a_crusher_special_starts_it_again() {
    let mut g = game("ceilings");
    let s = tagged(&g, 4);
    stand_in_bay(&mut g, 3, 90.0);
    press_use(&mut g);
    idle(&mut g, 29);
    assert_eq!(ceiling(&g, s), 98.0);
    // Face the east wall and use its stop switch.
    tick(&mut g, turn(-90.0));
    assert_eq!(ceiling(&g, s), 97.0);
    press_use(&mut g);
    let stopped = ceiling(&g, s);
    assert_eq!(stopped, 97.0);
    let held = record(&mut g, IDLE, 200, |g| ceiling(g, s));
    assert!(held.iter().all(|&c| c == stopped), "moved while stopped: {held:?}");
    // The west wall's crusher special wakes it: on down from where it stopped.
    tick(&mut g, turn(180.0));
    // Doom's EV_DoCeiling wakes the crushers in stasis on the tag
    // (P_ActivateInStasisCeiling), then finds the sector busy and starts
    // nothing new: the switch does not flip, but the crusher goes on.
    let e = press_use(&mut g);
    assert!(!specials_set_off(&e).is_empty(), "the switch was not reached: {e:?}");
    let first = ceiling(&g, s);
    let on = record(&mut g, IDLE, 5, |g| ceiling(g, s));
    assert_eq!(concat(&[vec![first], on]), steps(stopped, stopped - 6.0, 1.0));
    let crushers = thinkers_on(&g, s, |k| if let ThinkerKind::Ceiling(c) = k { Some(c.sector) } else { None });
    assert_eq!(crushers, 1);
}

// ---------------------------------------------------------------------------
// Stairs (tests/maps/stairs.ron: hall 0, A1-A4 1-4, X1 5, X2 6, B1-B3 7-9)

#[test]
fn stairs_build_one_step_higher_each_through_front_facing_lines_of_the_same_texture() {
    let mut g = game("stairs");
    stand(&mut g, 64.0, 40.0, 270.0);
    g.tick(&USE);
    let mut ticks = 1;
    while [1, 2, 3, 4].iter().any(|&s| moving(&g, s)) {
        // Each step rises at 0.25 a tick to 8 more than the one before.
        for (n, s) in (1..=4).enumerate() {
            let want = (0.25 * ticks as f64).min(8.0 * (n + 1) as f64);
            assert_eq!(floor(&g, s), want, "step A{} after {ticks} ticks", n + 1);
        }
        g.tick(&IDLE);
        ticks += 1;
    }
    // A4 reaches 32 on tick 128 and learns it has arrived on 129.
    assert_eq!(ticks, 129);
    let heights: Vec<f64> = (0..=6).map(|s| floor(&g, s)).collect();
    // The hall (TILE), X1 (its line faces X1) and X2 (DIRT) stay at 0.
    assert_eq!(heights, [0.0, 8.0, 16.0, 24.0, 32.0, 0.0, 0.0]);
}

#[test]
fn turbo_stairs_build_16_a_step_at_4() {
    let mut g = game("stairs");
    stand(&mut g, 384.0, 40.0, 270.0);
    let b3 = run_mover(&mut g, USE, 9, floor);
    assert_eq!(b3, path(0.0, 48.0, 4.0));
    assert_eq!([floor(&g, 7), floor(&g, 8), floor(&g, 9)], [16.0, 32.0, 48.0]);
    assert_eq!(floor(&g, 4), 0.0, "staircase A moved");
}

// ---------------------------------------------------------------------------
// Donut (tests/maps/donut.ron: outside 0, ring 1, pillar 2)

#[test]
fn a_donut_lowers_the_pillar_and_raises_the_ring_to_the_outside_floor_taking_its_texture() {
    let mut g = game("donut");
    let (outside, ring, pillar) = (0, 1, 2);
    assert!(level(&g).map.sectors[ring].special.damage.is_some());
    let ring_before = sim_floor(&g, ring);
    assert_eq!(ring_before.0, "WATER");
    assert_ne!(ring_before.1, 0, "the ring's damage is not a special in the simulation");
    // The player starts facing the pillar; a level's first tick uses nothing.
    idle(&mut g, 1);
    g.tick(&USE);
    let mut rings = vec![floor(&g, ring)];
    let mut pillars = vec![floor(&g, pillar)];
    while moving(&g, ring) || moving(&g, pillar) {
        if moving(&g, ring) {
            assert_eq!(sim_floor(&g, ring), ring_before);
        }
        g.tick(&IDLE);
        rings.push(floor(&g, ring));
        pillars.push(floor(&g, pillar));
    }
    // Both at 0.5 a tick (Doom's FLOORSPEED / 2) to the outside's floor, 0.
    assert_eq!(rings[..65], path(-32.0, 0.0, 0.5)[..]);
    assert_eq!(pillars, path(64.0, 0.0, 0.5));
    // On arrival the ring takes the outside's flat and special (none).
    assert_eq!(sim_floor(&g, ring), ("GRASS".to_string(), 0));
    assert_eq!(sim_floor(&g, pillar).0, "TILE");
    let m = &level(&g).materials;
    assert_eq!(m.sectors[ring].floor, m.sectors[outside].floor);
}

// ---------------------------------------------------------------------------
// Lights (tests/maps/lights.ron: hall 0 (light 96); cells 0-6 are sectors 1-7, light
// 224; cell 7 is sector 9; light special targets: tags 1-4)

fn lights_over(g: &mut SimGame, s: usize, ticks: usize) -> Vec<u8> {
    (0..ticks)
        .map(|_| {
            g.tick(&IDLE);
            light(g, s)
        })
        .collect()
}

#[test]
fn synchronised_strobes_are_dark_15_or_35_ticks_and_bright_5_from_the_first_tick() {
    let mut g = game("lights");
    let effect = |g: &SimGame, s: usize| level(&g).map.sectors[s].special.light;
    assert_eq!((effect(&g, 4), effect(&g, 5)), (Some(LightEffect::StrobeFastSync), Some(LightEffect::StrobeSlowSync)));
    let levels: Vec<(u8, u8, u8)> = (0..400)
        .map(|_| {
            g.tick(&IDLE);
            (light(&g, 4), light(&g, 5), light(&g, 9))
        })
        .collect();
    for (t, &(fast, slow, black)) in levels.iter().enumerate() {
        // Doom's FASTDARK 15, SLOWDARK 35, STROBEBRIGHT 5; dark is the
        // darkest neighbour (the hall's 96), or 0 when none is darker.
        assert_eq!(fast, if t % 20 < 15 { 96 } else { 224 }, "fast, tick {t}");
        assert_eq!(slow, if t % 40 < 35 { 96 } else { 224 }, "slow, tick {t}");
        assert_eq!(black, if t % 40 < 35 { 0 } else { 160 }, "no darker neighbour, tick {t}");
    }
}

/// The first tick a level differs from `from`, and the runs of equal levels after it.
fn runs(levels: &[u8], from: u8) -> (usize, Vec<(u8, usize)>) {
    let first = levels.iter().position(|&l| l != from).expect("it never changed");
    let mut out: Vec<(u8, usize)> = Vec::new();
    for &l in &levels[first..] {
        match out.last_mut() {
            Some((level, n)) if *level == l => *n += 1,
            _ => out.push((l, 1)),
        }
    }
    (first, out)
}

#[test]
fn unsynchronised_strobes_start_within_8_ticks_then_keep_the_period() {
    let mut g = game("lights");
    let levels: Vec<(u8, u8)> = (0..400)
        .map(|_| {
            g.tick(&IDLE);
            (light(&g, 2), light(&g, 3))
        })
        .collect();
    for (which, dark, pick) in [("fast", 15, 0), ("slow", 35, 1)] {
        let l: Vec<u8> = levels.iter().map(|p| if pick == 0 { p.0 } else { p.1 }).collect();
        let (first, runs) = runs(&l, 224);
        // The first change after (P_Random & 7) + 1 ticks.
        assert!(first < 8, "{which}: first change at tick {first}");
        let complete = &runs[..runs.len() - 1];
        for (k, &(level, n)) in complete.iter().enumerate() {
            let want = if k % 2 == 0 { (96, dark) } else { (224, 5) };
            assert_eq!((level, n), want, "{which}: run {k} of {runs:?}");
        }
    }
}

#[test]
fn a_glow_swings_8_a_tick_between_the_darkest_neighbour_and_its_level() {
    let mut g = game("lights");
    let levels = lights_over(&mut g, 6, 120);
    // Doom's T_Glow: down 8 a tick from 224; a step reaching 96 (the
    // hall's) is undone and it turns, and so at 224 going up: it swings
    // between 104 and 216 with a period of 30 ticks.
    let want: Vec<u8> = (0..120)
        .map(|t| match t % 30 {
            i @ 0..=14 => 216 - 8 * i as u8,
            15 => 104,
            i => 104 + 8 * (i - 15) as u8,
        })
        .collect();
    assert_eq!(levels, want);
}

#[test]
fn a_flicker_changes_every_4_ticks_by_multiples_of_16_under_its_level() {
    let mut g = game("lights");
    let levels = lights_over(&mut g, 7, 400);
    for t in 1..levels.len() {
        if t % 4 != 3 {
            assert_eq!(levels[t], levels[t - 1], "changed at tick {t}");
        }
        assert!([224, 208, 192, 176].contains(&levels[t]), "tick {t}: {}", levels[t]);
    }
    let distinct: std::collections::BTreeSet<u8> = levels.iter().copied().collect();
    assert!(distinct.len() >= 3, "only {distinct:?}");
}

#[test]
fn a_random_blink_is_dark_1_to_8_ticks_and_bright_1_or_65() {
    let mut g = game("lights");
    let levels = lights_over(&mut g, 1, 3000);
    let (first, runs) = runs(&levels, 224);
    // Starts bright for (P_Random & 64) + 1 ticks: 1 or 65.
    assert!(first == 0 || first == 64, "first change at tick {first}");
    let complete = &runs[..runs.len() - 1];
    assert!(complete.len() > 20, "{runs:?}");
    for &(level, n) in complete {
        match level {
            96 => assert!((1..=8).contains(&n), "dark for {n}"),
            224 => assert!(n == 1 || n == 65, "bright for {n}"),
            other => panic!("level {other}"),
        }
    }
    assert!(complete.iter().any(|&(l, n)| l == 224 && n == 65) && complete.iter().any(|&(l, n)| l == 224 && n == 1));
}

#[test]
fn light_specials_set_the_brightest_or_dimmest_neighbour_a_level_or_a_strobe() {
    let mut g = game("lights");
    let (t1, t2, t3, t4) = (tagged(&g, 1), tagged(&g, 2), tagged(&g, 3), tagged(&g, 4));
    assert_eq!([light(&g, t1), light(&g, t2), light(&g, t3), light(&g, t4)], [128, 128, 128, 192]);
    let switch = |g: &mut SimGame, x: f64| {
        stand(g, x, 40.0, 270.0);
        press_use(g);
        tick(g, IDLE);
    };
    switch(&mut g, 832.0);
    assert_eq!(light(&g, t1), 200, "brightest neighbour (behind it, 200; the hall 96)");
    switch(&mut g, 928.0);
    assert_eq!(light(&g, t2), 96, "dimmest neighbour (the hall)");
    switch(&mut g, 1008.0);
    assert_eq!(light(&g, t3), 35);
    switch(&mut g, 1040.0);
    assert_eq!(light(&g, t3), 255);
    // A strobe: between the darkest neighbour and its level, 35 dark, 5 bright.
    stand(&mut g, 1120.0, 40.0, 270.0);
    press_use(&mut g);
    let levels = lights_over(&mut g, t4, 200);
    let (first, runs) = runs(&levels, 192);
    assert!(first < 8, "first change at {first}");
    for (k, &(level, n)) in runs[..runs.len() - 1].iter().enumerate() {
        assert_eq!((level, n), if k % 2 == 0 { (96, 35) } else { (192, 5) }, "{runs:?}");
    }
}

// ---------------------------------------------------------------------------
// Damage and secrets (tests/maps/sector_specials.ron: room 0, nukage 1 (floor -8), secret 2,
// exit floor 3)

#[test]
fn damage_hurts_every_32_ticks_only_with_the_feet_on_the_floor() {
    let mut g = game("sector_specials");
    let pool = 1;
    // The centre over the pool, the body still on the room's floor beside it.
    stand(&mut g, 264.0, 128.0, 0.0);
    idle(&mut g, 1);
    assert_eq!((player(&g).sector, player(&g).z), (pool, 0.0));
    idle(&mut g, 99);
    assert_eq!(player(&g).health, 100, "hurt with its feet above the pool's floor");
    // Into the pool.
    until(&mut g, WALK, 20, |g| player(&g).z == -8.0);
    idle(&mut g, 10);
    let mut health = player(&g).health;
    let mut hurts = Vec::new();
    for _ in 0..200 {
        let time = leveltime(&g);
        g.tick(&IDLE);
        let h = player(&g).health;
        if h != health {
            assert_eq!((health - h, time % 32), (10, 0), "hurt at leveltime {time}");
            hurts.push(time);
        }
        health = h;
    }
    assert!((6..=7).contains(&hurts.len()), "{hurts:?}");
}

/// Ticks idle `ticks` times and returns each hurt the body took.
fn hurts_over(g: &mut SimGame, ticks: u32) -> Vec<i32> {
    let mut health = console(g).health;
    let mut hurts = Vec::new();
    for _ in 0..ticks {
        g.tick(&IDLE);
        let h = player(&g).health;
        if h != health {
            hurts.push(health - h);
        }
        health = h;
    }
    hurts
}

#[test]
fn a_radiation_suit_shields_from_nukage_leaks_on_20_floors_and_not_on_the_exit_floor() {
    // The 10-damage pool: no hurt while the suit lasts, hurts again after.
    let mut g = game("sector_specials");
    stand(&mut g, 264.0, 128.0, 0.0);
    until(&mut g, WALK, 20, |g| player(&g).z == -8.0);
    console_mut(&mut g).powers[IRONFEET] = 300;
    assert_eq!(hurts_over(&mut g, 290), Vec::<i32>::new(), "hurt through the suit");
    assert!(!hurts_over(&mut g, 100).is_empty(), "no hurt after the suit ran out");
    // The same pool as a 20 floor (Doom's 4 and 16): through the suit 5
    // times in 256, so a few hurts of 20 in a long wait, far fewer than bare.
    let text = std::fs::read_to_string(fixture("sector_specials")).unwrap();
    let leaky = text.replace("Damage(amount: 10)", "Damage(amount: 20, suit: Leaks)");
    assert_ne!(leaky, text);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("leaky_pool.ron");
    std::fs::write(&path, leaky).unwrap();
    let mut g = SimGame::on_level(load(&path), "leaky_pool.ron", options()).unwrap_or_else(|e| panic!("{e}"));
    let damage = level(&g).map.sectors[1].special.damage;
    assert_eq!(damage, Some(Damage { amount: 20, every: 32, exit_below: 0, suit: Suit::Leaks }));
    stand(&mut g, 264.0, 128.0, 0.0);
    until(&mut g, WALK, 20, |g| player(&g).z == -8.0);
    console_mut(&mut g).powers[IRONFEET] = 1_000_000;
    g.set_health(100_000);
    // P_PlayerInSpecialSector draws P_Random every tick on it (the first
    // draw of the tick: nothing else here draws), and hurts through the
    // suit on a biting tick (leveltime % 32 == 0) when it is below 5. The
    // cursor set before each biting tick so that it reads every entry of
    // Doom's table once: it hurts exactly on the entries below 5.
    let mut hurt_on = Vec::new();
    for k in 0..=255u8 {
        while leveltime(&g) % 32 != 0 {
            idle(&mut g, 1);
        }
        g.sim.rng = DoomRandom::from_indices(k.wrapping_sub(1), 0);
        let before = console(&g).health;
        idle(&mut g, 1);
        match before - console(&g).health {
            0 => {}
            20 => hurt_on.push(k),
            other => panic!("hurt {other} through the suit"),
        }
    }
    let low: Vec<u8> = (0..=255u8).filter(|&k| RNDTABLE[usize::from(k)] < 5).collect();
    assert!(!low.is_empty());
    assert_eq!(hurt_on, low, "hurt through the suit on these entries of the table");
    // The exit floor (Doom's 11) hurts whatever the player wears.
    let mut g = game("sector_specials");
    stand(&mut g, 896.0, 128.0, 0.0);
    console_mut(&mut g).powers[IRONFEET] = 1000;
    let hurts = hurts_over(&mut g, 64);
    assert_eq!(hurts, [20, 20]);
}

#[test]
fn a_secret_is_counted_once_when_entered() {
    let mut g = game("sector_specials");
    assert_eq!(Observe::stats(&g).secrets, (0, 1));
    let mut said = Vec::new();
    until(&mut g, RUN, 100, |g| player(&g).sector == 2 && player(&g).z == 0.0);
    said.extend(messages(events(&g)));
    // P_PlayerInSpecialSector runs in P_PlayerThink, before the body moves:
    // the tick after it is in the sector, on its floor.
    assert_eq!(Observe::stats(&g).secrets, (0, 1), "counted before the player was in it");
    said.extend(messages(&tick(&mut g, IDLE)));
    assert_eq!(Observe::stats(&g).secrets, (1, 1));
    // Vanilla Doom says nothing of it; a RON map plays by Sightline's
    // rules, which say so as Boom does, once.
    assert_eq!(said, ["A secret is revealed!"]);
    // Doom clears the sector's special (9) once counted.
    assert_eq!(g.sim.level.sectors[2].special, 0);
    idle(&mut g, 40);
    assert_eq!(Observe::stats(&g).secrets, (1, 1));
}

#[test]
fn an_exit_floor_hurts_and_ends_the_level_at_10_health() {
    // Doom's sector type 11 (E1M8's): 20 every 32 ticks; at 10 health or
    // less the level ends. P_DamageMobj's "end of game hell hack" keeps the
    // player alive on it: damage that would kill leaves 1 health.
    let mut g = game("sector_specials");
    stand(&mut g, 896.0, 128.0, 0.0);
    let mut healths = Vec::new();
    while g.exit().is_none() {
        let time = leveltime(&g);
        g.tick(&IDLE);
        if time % 32 == 0 {
            healths.push(player(&g).health);
        }
        assert!(leveltime(&g) < 1000, "never ended");
    }
    assert_eq!(healths, [80, 60, 40, 20, 1]);
    assert_eq!(g.exit(), Some(Exit::Normal));
}

// ---------------------------------------------------------------------------
// Teleporters (tests/maps/teleport.ron: A 0, B 1 (tag 7, floor 32), C1 2, C2 3, D1 4, D2 5;
// the destination at (768, 200) facing 100 degrees)

#[test]
fn a_teleporter_puts_the_player_at_the_destination_facing_its_angle_still_and_held_18_ticks() {
    let mut g = game("teleport");
    let n = until(&mut g, RUN, 60, |g| player(&g).sector == 1);
    let e = events(&g).to_vec();
    let p = player(&g).clone();
    // Doom spawns a map thing facing its angle rounded down to 45 degrees: 100 -> 90.
    assert_eq!((p.pos, p.angle, p.velocity, p.z, p.freeze), (DVec2::new(768.0, 200.0), 90.0, DVec2::ZERO, 32.0, 18));
    assert_eq!(sounds(&e), ["telept", "telept"]);
    assert!(n > 5, "teleported after {n} ticks");
    // Held for 18 ticks (Doom's reactiontime), whatever the input.
    for k in 0..18 {
        g.tick(&RUN);
        assert_eq!(pos(&g), p.pos, "moved {k} ticks after teleporting");
    }
    g.tick(&RUN);
    assert!(pos(&g).y > 200.0, "still held after 18 ticks");
}

#[test]
fn a_teleporter_crossed_from_its_back_does_nothing() {
    let mut g = game("teleport");
    stand(&mut g, 384.0, 128.0, 180.0);
    let line = &level(&g).map.trigger_lines[0];
    let x = level(&g).map.vertices[line.from].x;
    assert!(x > 200.0 && x < 384.0, "the teleporter line is not between start and end");
    let mut sounded = Vec::new();
    while pos(&g).x > 200.0 {
        sounded.extend(sounds(&tick(&mut g, RUN)));
        assert!(leveltime(&g) < 100, "never got across");
    }
    // Across it from its back (Doom's EV_Teleport refuses side 1): no
    // teleport, no fog, no hold.
    assert_eq!((player(&g).sector, player(&g).freeze, sounded), (0, 0, vec![]));
}

#[test]
fn a_line_teleporter_keeps_the_speed_turned_by_the_angle_between_the_lines() {
    let mut g = game("teleport");
    stand(&mut g, 128.0, 560.0, 0.0);
    until(&mut g, RUN, 40, |g| player(&g).sector == 5);
    let p = player(&g).clone();
    // Along the source line (from (256, 640) down to (256, 384)) y 560 is
    // 0.3125 of the way; the exit runs from (896, 512) to (640, 512),
    // measured from its far end: x 640 + 0.3125 * 256 = 720 (less a little:
    // Doom's finesine[0] is 25/65536, so running "east" drifts north a
    // hair), nudged a fixed-point unit at a time until in front of it.
    // Turned by the angle between the lines plus a half turn: east becomes
    // north (Boom's EV_SilentLineTeleport, special 244).
    assert!((p.pos.x - 720.0).abs() < 0.1 && p.pos.y > 512.0 && p.pos.y < 512.0 + 1.0 / 64.0, "at {}", p.pos);
    // To the binary angle (360 / 2^32 degrees).
    assert!((p.angle - 90.0).abs() < 1e-6, "angle {}", p.angle);
    assert_eq!((p.z, p.freeze), (0.0, 0));
    // (The run's hair of drift north, turned, is a hair west.)
    assert!(p.velocity.x.abs() < 1e-3 && p.velocity.y > 10.0, "velocity {:?}", p.velocity);
    assert_eq!(sounds(events(&g)), Vec::<&str>::new(), "a silent teleport");
    g.tick(&IDLE);
    assert!(pos(&g).y > p.pos.y + 5.0, "the speed was not kept");
}

// ---------------------------------------------------------------------------
// Switches and once-only lines (tests/maps/switches.ron: room 0, alcoves 1-4 (tags 1-4))

#[test]
fn a_button_flips_its_texture_and_flips_back_after_35_ticks() {
    let mut g = game("switches");
    let line = line_tagged(&g, 1);
    assert_eq!(middle(&g, line), "SW1COMM");
    // The player starts facing it; a level's first tick uses nothing.
    idle(&mut g, 1);
    let e = press_use(&mut g);
    assert_eq!(specials_set_off(&e), [(SpecialLine::Wall(line), true)]);
    assert!(has_sound(&e, "swtchn", Origin::Sector(0)), "{e:?}");
    assert_eq!(middle(&g, line), "SW2COMM");
    // Doom's BUTTONTIME: 35 ticks counted from the tick it was pressed.
    let mut shown = Vec::new();
    let mut back = None;
    for k in 1..40 {
        let e = tick(&mut g, IDLE);
        shown.push(middle(&g, line));
        if has_sound(&e, "swtchn", Origin::Sector(0)) {
            back = Some(k);
        }
    }
    assert_eq!(back, Some(34));
    assert!(shown[..33].iter().all(|t| t == "SW2COMM") && shown[33..].iter().all(|t| t == "SW1COMM"), "{shown:?}");
    assert_eq!(floor(&g, 1), 8.0);
    // Repeatable: again.
    let e = press_use(&mut g);
    assert_eq!(specials_set_off(&e), [(SpecialLine::Wall(line), true)]);
    assert_eq!(middle(&g, line), "SW2COMM");
    idle(&mut g, 10);
    assert_eq!(floor(&g, 1), 16.0);
}

#[test]
fn a_once_only_switch_stays_flipped_and_works_once() {
    let mut g = game("switches");
    let line = line_tagged(&g, 2);
    stand(&mut g, 192.0, 40.0, 270.0);
    let e = press_use(&mut g);
    assert_eq!(specials_set_off(&e), [(SpecialLine::Wall(line), true)]);
    idle(&mut g, 100);
    assert_eq!((middle(&g, line), floor(&g, 2)), ("SW2COMM".to_string(), 8.0));
    let e = press_use(&mut g);
    assert_eq!((specials_set_off(&e), sounds(&e)), (vec![], vec!["noway"]));
    idle(&mut g, 20);
    assert_eq!((middle(&g, line), floor(&g, 2)), ("SW2COMM".to_string(), 8.0));
}

#[test]
fn a_once_only_walk_line_works_once_and_a_repeatable_one_every_time() {
    let mut g = game("switches");
    stand(&mut g, 250.0, 96.0, 0.0);
    // Walk lines go off unseen (the simulation reports used lines only):
    // what they did shows in the floors of alcoves 3 (W1) and 4 (WR), each
    // raised 8 by a crossing.
    let walk = |g: &mut SimGame, past: fn(f64) -> bool| {
        while !past(pos(&g).x) {
            tick(g, WALK);
            assert!(leveltime(&g) < 400, "never got there");
        }
    };
    // East over the W1 line (x 300, trigger line 0), then the WR line (x 400).
    walk(&mut g, |x| x > 440.0);
    idle(&mut g, 40);
    assert_eq!((floor(&g, 3), floor(&g, 4)), (8.0, 8.0));
    // Back west over both: only the repeatable one goes off.
    tick(&mut g, turn(180.0));
    walk(&mut g, |x| x < 260.0);
    idle(&mut g, 20);
    assert_eq!((floor(&g, 3), floor(&g, 4)), (8.0, 16.0));
    // And east again.
    tick(&mut g, turn(180.0));
    walk(&mut g, |x| x > 440.0);
    idle(&mut g, 20);
    assert_eq!((floor(&g, 3), floor(&g, 4)), (8.0, 24.0));
}

// ---------------------------------------------------------------------------
// Shoot lines (tests/maps/shoot.ron: A 0, B 1, R1 2 (tag 1), R2 3 (tag 2))

/// Fires the pistol once: waits for it to be ready, holds fire until the
/// shot, and returns that tick's events.
fn shoot(g: &mut SimGame) -> Vec<Event> {
    let ready = Observe::table(g).get("pistol").and_then(|p| p.label("Ready"));
    for _ in 0..60 {
        if player(&g).psprites[0].state == ready {
            break;
        }
        tick(g, IDLE);
    }
    let bullets = player(&g).ammo[0];
    for _ in 0..20 {
        let e = tick(g, FIRE);
        if player(&g).ammo[0] < bullets {
            return e;
        }
    }
    panic!("the pistol did not fire");
}

#[test]
fn a_shot_sets_off_a_shoot_line_through_an_opening_but_not_through_a_wall() {
    let mut g = game("shoot");
    let g1 = line_tagged(&g, 1);
    // A shot line goes off unseen (the simulation reports used lines
    // only): its switch texture and its floor show it.
    // Facing east across A and the open line into B, at G1 on B's far wall.
    assert_eq!(middle(&g, g1), "SW1COMM");
    shoot(&mut g);
    assert_eq!(middle(&g, g1), "SW2COMM");
    idle(&mut g, 10);
    assert_eq!(floor(&g, 2), 8.0);
    // Once only.
    shoot(&mut g);
    idle(&mut g, 10);
    assert_eq!(floor(&g, 2), 8.0);
    // G2 with the pillar between: the shot stops at the pillar.
    stand(&mut g, 128.0, 64.0, 90.0);
    shoot(&mut g);
    idle(&mut g, 10);
    assert_eq!(floor(&g, 3), 0.0);
    // Using it does nothing either: it is a shoot line. (Vanilla's
    // PTR_UseTraverse stops at any line with a special, silently.)
    stand(&mut g, 128.0, 232.0, 90.0);
    let e = press_use(&mut g);
    assert!(specials_set_off(&e).iter().all(|&(_, started)| !started), "{e:?}");
    idle(&mut g, 10);
    assert_eq!(floor(&g, 3), 0.0, "set off by use");
    // Shot from in front of it: it goes off.
    shoot(&mut g);
    idle(&mut g, 10);
    assert_eq!(floor(&g, 3), 8.0);
}

// ---------------------------------------------------------------------------
// Exits (tests/maps/exit.ron: room 0, secret closet 1)

#[test]
fn the_exit_ends_the_level_and_the_stats_count_the_secret_found_before() {
    let mut g = game("exit");
    assert_eq!(Observe::stats(&g).secrets, (0, 1));
    until(&mut g, WALK, 60, |g| player(&g).sector == 1);
    // Counted the tick after (P_PlayerInSpecialSector runs before the move).
    tick(&mut g, WALK);
    assert_eq!(Observe::stats(&g).secrets, (1, 1));
    tick(&mut g, turn(180.0));
    until(&mut g, WALK, 100, |g| pos(&g).x < 48.0);
    idle(&mut g, 30);
    assert_eq!(g.exit(), None);
    let e = press_use(&mut g);
    assert_eq!(g.exit(), Some(Exit::Normal));
    // Vanilla's P_ChangeSwitchTexture clears a once-only line's special
    // before it asks whether it is the exit (11) for swtchx: the exit
    // switch clicks like any other.
    assert!(has_sound(&e, "swtchn", Origin::Sector(0)), "{e:?}");
    let stats = Observe::stats(&g);
    assert_eq!((stats.secrets, stats.ticks), ((1, 1), leveltime(&g)));
    // Later ticks do nothing.
    let (at, time) = (pos(&g), leveltime(&g));
    for _ in 0..20 {
        assert_eq!(tick(&mut g, RUN), vec![]);
    }
    assert_eq!((pos(&g), leveltime(&g), Observe::stats(&g), g.exit()), (at, time, stats, Some(Exit::Normal)));
}

#[test]
fn the_secret_exit_ends_the_level_as_a_secret_exit() {
    let mut g = game("exit");
    stand(&mut g, 100.0, 32.0, 0.0);
    until(&mut g, WALK, 20, |g| g.exit().is_some());
    assert_eq!(g.exit(), Some(Exit::Secret));
    assert_eq!(Observe::stats(&g).secrets, (0, 1));
}

// ---------------------------------------------------------------------------
// Once defects, now fixed and kept

/// Doom's close-then-open door (16, 76) stays shut 1050 ticks: `shut`, whose
/// default is that, apart from a raise door's `wait` (150).
#[test]
fn a_close_then_open_door_stays_shut_dooms_30_seconds_by_default() {
    use sightline::map::special::Action;
    let text = "Map(name: \"t\", vertices: [], sectors: [], lines: [], trigger_lines: [TriggerLine(from: 0, to: 1, \
                special: LineSpecial(on: Walk, tag: 1, action: Door(kind: CloseThenOpen)))])";
    let source = sightline::map::load::parse_source(text.as_bytes(), "t.ron").unwrap_or_else(|e| panic!("{e}"));
    let action = &source.trigger_lines[0].special.action;
    assert!(matches!(action, Action::Door { wait: 150, shut: 1050, .. }), "{action:?}");
}

#[test]
fn the_player_can_use_a_switch_while_held_after_a_teleport() {
    // Doom's P_PlayerThink skips P_MovePlayer while reactiontime counts down,
    // but P_UseLines (and the weapon) run every tic all the same.
    let mut g = game("teleport");
    until(&mut g, RUN, 60, |g| player(&g).sector == 1);
    assert_eq!((player(&g).freeze, light(&g, 1)), (18, 176));
    // Facing north, 56 from room B's light switch.
    let e = press_use(&mut g);
    assert_eq!(light(&g, 1), 255, "{e:?}");
}
