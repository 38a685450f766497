//! Generalized specials on the simulation against the f64 game: a small
//! RON map built here (a room, a tagged sector in it, a walk line or a
//! switch that sets a special no vanilla number says), played by both
//! games with the same input, the tagged sector's heights compared tic by
//! tic from the tic each game set it off. The two games' bodies move by
//! different arithmetic, so the player crosses a line a tic or two apart
//! in them; the movers, once started, must then agree exactly (speeds,
//! waits and heights here are exact in 16.16). Also: every shipped map
//! converts with no special left out, and a game with generalized movers
//! saves and loads bit for bit.

use crate::autopilot::observe::Observe;
use crate::bsp::{build, BuildOptions};
use crate::campaign::{MapRef, Opened};
use crate::map::source::{LineSpecialSource, MapSource, SectorSource, SideSource, ThingSource, TriggerLineSource};
use crate::map::special::{Damage, DoorKind};
use crate::map::{parse_map, Action, Activation, SectorSpecial, Who};
use crate::play::{Game, GameOptions, TickInput};
use crate::sim::game::SimGame;
use crate::sim::{from_map, info, save, ThinkerKind, MAXPLAYERS};

/// The tagged sector: a 128-unit square in the middle of the room.
const INNER: usize = 1;

/// A sector's floor, ceiling and light as drawn, one tic's.
type Seen = (f64, f64, u8);

/// A 512x512 room (sector 0: floor 0, ceiling 256) with a tagged square
/// (sector 1, tag 1) at x 256..384, y 192..320, the player at (64, 256)
/// facing east, and a walk line across the room at x 128 carrying
/// `special` (or, with `on: Use`, the room's east wall facing the player
/// at x 112: a switch).
fn map(inner: SectorSource, special: LineSpecialSource) -> MapSource {
    let mut m = MapSource { version: 2, name: "GENTEST".into(), ..MapSource::default() };
    let sector = |floor: f64, ceiling: f64| SectorSource {
        floor,
        ceiling,
        light: 160,
        floor_texture: Some("FLOOR".into()),
        ceiling_texture: Some("CEIL".into()),
        ..SectorSource::default()
    };
    m.sectors.push(sector(0.0, 256.0));
    m.sectors.push(SectorSource { tag: 1, ..inner });
    m.add_ring(&[(0.0, 0.0), (0.0, 512.0), (512.0, 512.0), (512.0, 0.0)], 0, None);
    m.add_ring(&[(256.0, 192.0), (384.0, 192.0), (384.0, 320.0), (256.0, 320.0)], 0, Some(INNER));
    for line in &mut m.lines {
        for side in std::iter::once(&mut line.front).chain(line.back.as_mut()) {
            (side.upper, side.middle, side.lower) = (Some("BRICK".into()), None, Some("BRICK".into()));
        }
        if line.back.is_none() {
            line.front.middle = Some("BRICK".into());
        }
    }
    if special.on == Activation::Use {
        // A switch: a two-sided line in the room in front of the player,
        // facing west (south along it, its right hand is west).
        let first = m.vertices.len() as i64;
        m.vertices.extend([(112.0, 288.0), (112.0, 224.0)]);
        let side = SideSource { sector: 0, ..SideSource::default() };
        m.lines.push(crate::map::source::LineSource {
            from: first,
            to: first + 1,
            front: side.clone(),
            back: Some(side),
            special: Some(special),
            ..Default::default()
        });
    } else {
        let first = m.vertices.len() as i64;
        m.vertices.extend([(128.0, 16.0), (128.0, 496.0)]);
        m.trigger_lines.push(TriggerLineSource { from: first, to: first + 1, special });
    }
    m.things.push(ThingSource::new("player_start", 64.0, 256.0, 0.0));
    m
}

fn walk_line(action: Action) -> LineSpecialSource {
    LineSpecialSource { on: Activation::Walk, repeat: false, by: Who::Anyone, tag: 1, action }
}

fn sector(floor: f64, ceiling: f64) -> SectorSource {
    SectorSource { floor, ceiling, light: 160, ..SectorSource::default() }
}

fn level(m: &MapSource) -> crate::level::Level {
    let map = parse_map(&m.to_ron(), "gentest.ron").unwrap_or_else(|e| panic!("{e}\n{}", m.to_ron()));
    let compiled = build(&map, &BuildOptions::default()).expect("the test map compiles");
    crate::level::Level::with_builtin_textures(compiled).expect("built-in textures")
}

fn sim_game(m: &MapSource) -> SimGame {
    let opened = Opened {
        level: level(m),
        map: MapRef::File("gentest.ron".into()),
        repairs: Vec::new(),
        report: None,
        links: None,
    };
    let options = GameOptions { skill: 3, no_monsters: true, sim: true, ..GameOptions::default() };
    SimGame::new(opened, options).unwrap_or_else(|e| panic!("{e}"))
}

fn f64_game(m: &MapSource) -> Game {
    let options = GameOptions { skill: 3, no_monsters: true, ..GameOptions::default() };
    Game::with_options(level(m), options).unwrap_or_else(|e| panic!("{e}"))
}

/// The input of tic `t`: walk east for 12 tics, or press use at tic 1.
fn input(t: usize, on: Activation) -> TickInput {
    match on {
        Activation::Use => TickInput { use_line: t == 1, ..TickInput::default() },
        _ => TickInput { forward: i8::from(t < 12), ..TickInput::default() },
    }
}

/// The inner sector's (floor, ceiling, light) in each game for `tics`
/// tics, each list from the first tic it differs from how it started
/// (both games start a mover and run it in the tic that sets it off).
fn both(m: &MapSource, on: Activation, tics: usize) -> (Vec<Seen>, Vec<Seen>) {
    let (mut sim, mut f64) = (sim_game(m), f64_game(m));
    let read = |l: &crate::level::Level| {
        let s = &l.compiled.map.sectors[INNER];
        (s.floor, s.ceiling, s.light)
    };
    let (first_a, first_b) = (read(Observe::level(&sim)), read(f64.level()));
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for t in 0..tics {
        sim.tick(&input(t, on));
        f64.tick(&input(t, on));
        let (now_a, now_b) = (read(Observe::level(&sim)), read(f64.level()));
        if !a.is_empty() || now_a != first_a {
            a.push(now_a);
        }
        if !b.is_empty() || now_b != first_b {
            b.push(now_b);
        }
    }
    assert!(!a.is_empty(), "the simulation never set the special off");
    assert!(!b.is_empty(), "the f64 game never set the special off");
    let n = a.len().min(b.len());
    (a[..n].to_vec(), b[..n].to_vec())
}

/// Runs of equal values: each value and how many tics it held.
fn runs(v: &[Seen]) -> Vec<(Seen, usize)> {
    let mut out: Vec<(Seen, usize)> = Vec::new();
    for &h in v {
        match out.last_mut() {
            Some((last, n)) if *last == h => *n += 1,
            _ => out.push((h, 1)),
        }
    }
    out
}

/// Both games went through the same heights and lights in the same order
/// (so the same speeds, targets and turns), each held as long, but for
/// one tic per stop: a plane that lands exactly on its destination
/// arrives in Doom's `T_MovePlane` only on the next tic, where the f64
/// game's mover arrives at once, so the simulation's waits at the top and
/// bottom of a mover's run last a tic longer. The last run is cut short
/// by the end of the test.
fn assert_agree(m: &MapSource, on: Activation, tics: usize) -> Vec<Seen> {
    let (sim, f64) = both(m, on, tics);
    let (a, b) = (runs(&sim), runs(&f64));
    let n = a.len().min(b.len());
    assert!(n > 0 && a.len().abs_diff(b.len()) <= 1, "simulation {a:?}\nf64 game {b:?}");
    for k in 0..n {
        let last = k + 1 == n;
        let held = if last { true } else { a[k].1.abs_diff(b[k].1) <= 1 };
        assert!(a[k].0 == b[k].0 && held, "run {k}: simulation {:?}, f64 game {:?}", a[k], b[k]);
    }
    sim
}

/// It moved, and came to rest where `end` says.
fn assert_moved(heights: &[Seen], end: (f64, f64)) {
    let last = *heights.last().expect("heights");
    assert_eq!((last.0, last.1), end, "{heights:?}");
}

#[test]
fn a_door_with_its_own_speed_and_wait_opens_waits_and_closes_as_on_the_f64_game() {
    let door = Action::Door { kind: DoorKind::Raise, speed: 4.0, wait: 70, shut: 0, key: None };
    let m = map(sector(0.0, 0.0), walk_line(door));
    let h = assert_agree(&m, Activation::Walk, 400);
    assert!(h.iter().any(|h| h.1 == 252.0), "it opened to 4 under the room's ceiling");
    assert_moved(&h, (0.0, 0.0));
}

#[test]
fn a_close_then_open_door_waits_shut_its_own_time() {
    let door = Action::Door { kind: DoorKind::CloseThenOpen, speed: 8.0, wait: 150, shut: 90, key: None };
    let m = map(sector(0.0, 200.0), walk_line(door));
    let h = assert_agree(&m, Activation::Walk, 300);
    assert_moved(&h, (0.0, 200.0));
}

#[test]
fn a_lift_with_its_own_speed_and_wait_matches() {
    let m = map(sector(64.0, 256.0), walk_line(Action::Lift { speed: 2.0, wait: 50 }));
    let h = assert_agree(&m, Activation::Walk, 200);
    assert!(h.iter().any(|h| h.0 == 0.0), "it went down to the room's floor");
    assert_moved(&h, (64.0, 256.0));
}

#[test]
fn floors_to_each_target_match() {
    use crate::map::special::FloorTarget as T;
    for (to, offset, speed, start, end) in [
        (T::LowestNeighbourCeiling, -8.0, 3.0, 0.0, 248.0),
        (T::Current, 40.0, 0.5, 16.0, 56.0),
        (T::LowestNeighbourFloor, 0.0, 2.0, 64.0, 0.0),
        (T::HighestNeighbourFloor, 0.0, 2.0, 64.0, 0.0),
        (T::NextLowerFloor, 0.0, 2.0, 48.0, 0.0),
        (T::Ceiling, -100.0, 4.0, 0.0, 156.0),
    ] {
        let action = Action::Floor { to, offset, speed, crush: false, change: None };
        let m = map(sector(start, 256.0), walk_line(action));
        let h = assert_agree(&m, Activation::Walk, 300);
        assert_moved(&h, (end, 256.0));
    }
}

#[test]
fn a_ceiling_and_a_crusher_with_their_own_speeds_match() {
    use crate::map::special::CeilingTarget as T;
    let ceiling = Action::Ceiling { to: T::Floor, offset: 8.0, speed: 2.0, crush: false };
    let h = assert_agree(&map(sector(0.0, 200.0), walk_line(ceiling)), Activation::Walk, 200);
    assert_moved(&h, (0.0, 8.0));
    let crusher = Action::Crusher { speed: 3.0, silent: true };
    let h = assert_agree(&map(sector(0.0, 96.0), walk_line(crusher)), Activation::Walk, 150);
    assert!(h.iter().any(|h| h.1 == 8.0), "it came down to 8 over the floor");
    assert!(h.iter().filter(|h| h.1 == 96.0).count() > 1, "and went back up");
}

#[test]
fn a_repeatable_switch_lift_no_number_says_matches() {
    // Doom's use lifts are set off by players; this one by anyone.
    let special = LineSpecialSource {
        on: Activation::Use,
        repeat: true,
        by: Who::Anyone,
        tag: 1,
        action: Action::Lift { speed: 4.0, wait: 105 },
    };
    let m = map(sector(64.0, 256.0), special);
    let h = assert_agree(&m, Activation::Use, 200);
    assert_moved(&h, (64.0, 256.0));
}

#[test]
fn light_changes_match() {
    use crate::map::special::LightChange;
    for (change, light) in [(LightChange::Set(40), 40), (LightChange::BrightestNeighbour, 160)] {
        let special = LineSpecialSource { repeat: true, ..walk_line(Action::Light(change)) };
        let inner = SectorSource { light: 100, ..sector(0.0, 256.0) };
        let h = assert_agree(&map(inner, special), Activation::Walk, 20);
        assert_eq!(h.last().map(|h| h.2), Some(light));
    }
}

/// A damaging floor Doom's types cannot say (7 every 16 tics), under the
/// player: the same bites in both games, 16 tics apart (the games count
/// their tics from different starts: Doom's `leveltime` is 0 in the first
/// tic, so the simulation bites then).
#[test]
fn a_floor_with_its_own_damage_hurts_as_on_the_f64_game() {
    let mut m = map(sector(0.0, 0.0), walk_line(Action::Exit));
    let damage = Damage { amount: 7, every: 16, exit_below: 0, suit: Default::default() };
    m.sectors[0].special = SectorSpecial { damage: Some(damage), ..SectorSpecial::default() };
    let (mut sim, mut f64) = (sim_game(&m), f64_game(&m));
    let still = TickInput::default();
    let (mut bites_a, mut bites_b) = (Vec::new(), Vec::new());
    let (mut health_a, mut health_b) = (100, 100);
    for t in 0..100 {
        sim.tick(&still);
        f64.tick(&still);
        let (a, b) = (Observe::player(&sim).health, f64.player().health);
        if a != health_a {
            bites_a.push((t, health_a - a));
        }
        if b != health_b {
            bites_b.push((t, health_b - b));
        }
        (health_a, health_b) = (a, b);
    }
    assert_eq!(bites_a, (0..7).map(|k| (16 * k, 7)).collect::<Vec<_>>());
    assert!(bites_b.len() >= 6 && bites_b.iter().all(|&(_, d)| d == 7), "{bites_b:?}");
    assert!(bites_b.windows(2).all(|w| w[1].0 - w[0].0 == 16), "{bites_b:?}");
}

/// A sector special combining a glow with damage and a secret: the glow
/// runs, and the damage and the secret stay the sector's special until the
/// secret is found, then the damage alone.
#[test]
fn a_combined_sector_special_keeps_what_acts_on_the_player() {
    use crate::map::special::LightEffect;
    let mut m = map(sector(0.0, 0.0), walk_line(Action::Exit));
    let damage = Damage { amount: 5, every: 32, exit_below: 0, suit: Default::default() };
    m.sectors[0].special =
        SectorSpecial { light: Some(LightEffect::Glow), damage: Some(damage), secret: true, timer: None };
    let mut sim = sim_game(&m);
    let g = &sim.sim.level.generalized;
    let running = g.sector(sim.sim.level.sectors[0].special).copied();
    assert_eq!(running, Some(SectorSpecial { damage: Some(damage), secret: true, ..SectorSpecial::default() }));
    assert!(sim.sim.thinkers.iter().any(|t| matches!(t.kind, ThinkerKind::Light(_))), "the glow runs");
    assert_eq!(sim.sim.total_secrets, 1);
    sim.tick(&TickInput::default());
    let g = &sim.sim.level.generalized;
    assert_eq!(
        g.sector(sim.sim.level.sectors[0].special).copied(),
        Some(SectorSpecial { damage: Some(damage), ..SectorSpecial::default() })
    );
    assert_eq!(sim.sim.player(0).map(|p| p.secretcount), Some(1));
}

/// Boom's silent line teleport: the player comes out of the other line at
/// the mirrored place, turned and still moving, with no fog.
#[test]
fn a_line_teleport_moves_the_player_to_the_other_line() {
    let mut m = map(sector(0.0, 256.0), walk_line(Action::Exit));
    m.trigger_lines.clear();
    // The exit: a two-sided line at y = 448, facing north (front on its
    // right, walking west), from (480, 448) to (352, 448); no special.
    // Vertices 8 and 9 are the walk line's, (128, 16) and (128, 496).
    let first = m.vertices.len() as i64 - 2;
    m.vertices.extend([(480.0, 448.0), (352.0, 448.0)]);
    let to = m.lines.len();
    let side = SideSource { sector: 0, ..SideSource::default() };
    m.lines.push(crate::map::source::LineSource {
        from: first + 2,
        to: first + 3,
        front: side.clone(),
        back: Some(side),
        ..Default::default()
    });
    // The entry: crossed from its front (west) going east.
    m.trigger_lines.push(TriggerLineSource {
        from: first + 1,
        to: first,
        special: LineSpecialSource { repeat: true, ..walk_line(Action::LineTeleport { to }) },
    });
    let mut sim = sim_game(&m);
    let mut jumped = None;
    for t in 0..30 {
        let before = Observe::player(&sim).pos;
        sim.tick(&input(t, Activation::Walk));
        let after = Observe::player(&sim).pos;
        if after.distance(before) > 50.0 {
            jumped = Some((before, after, Observe::player(&sim).angle));
            break;
        }
    }
    let (before, after, angle) = jumped.expect("the player was teleported");
    // Crossed at y 256 of a line from y 496 to 16: 0.5 along it; out at
    // 0.5 along the exit from its far end, just north of it.
    assert!((after.x - 416.0).abs() < 17.0 && after.y > 448.0 && after.y < 466.0, "{before} -> {after}");
    // Entry faces west (the line runs north to south), exit north: the
    // body turned from east to north.
    assert!((angle.rem_euclid(360.0) - 90.0).abs() < 1.0, "facing {angle}");
    assert!(!sim.sim.thinkers.iter().any(|t| matches!(t.kind, ThinkerKind::Mobj(m) if sim.sim.is(m, info::mt::TFOG))));
}

/// A conveyor floor pushes the player standing on it east.
#[test]
fn a_carrying_floor_pushes_the_player() {
    use crate::map::special::Scroll;
    let mut m = map(sector(0.0, 256.0), walk_line(Action::Exit));
    m.trigger_lines.clear();
    m.sectors[0].carry = Some(Scroll { x: 0.5, y: 0.0 });
    let mut sim = sim_game(&m);
    let start = Observe::player(&sim).pos;
    for _ in 0..20 {
        sim.tick(&TickInput::default());
    }
    let moved = Observe::player(&sim).pos - start;
    assert!(moved.x > 20.0 && moved.y.abs() < 1e-9, "{moved}");
}

#[test]
fn every_shipped_map_converts_with_no_special_left_out() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../maps");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).expect("the maps folder") {
        let path = entry.expect("an entry").path();
        if path.extension().is_none_or(|e| e != "ron") || path.ends_with("nasty.ron") {
            continue;
        }
        let compiled = crate::level::open_compiled(&path, &BuildOptions::default()).expect("a shipped map");
        let report = from_map::level_and_report(&compiled, crate::actors::ActorTable::doom())
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
            .report;
        let dropped: Vec<_> = report
            .iter()
            .filter(|n| ["special", "scroll", "carry", "light", "number"].iter().any(|w| n.what.contains(w)))
            .collect();
        assert!(dropped.is_empty(), "{}: {dropped:?}", path.display());
        checked += 1;
    }
    assert!(checked >= 10, "only {checked} maps");
}

/// A game with generalized movers at work saved, loaded and played on
/// beside the original: the whole saved state equal every tic.
#[test]
fn a_game_with_generalized_movers_saves_and_loads_bit_for_bit() {
    let door = Action::Door { kind: DoorKind::Raise, speed: 4.0, wait: 70, shut: 0, key: None };
    let m = map(sector(0.0, 0.0), walk_line(door));
    let mut game = sim_game(&m);
    for t in 0..40 {
        game.tick(&input(t, Activation::Walk));
    }
    assert!(game.sim.thinkers.iter().any(|t| matches!(t.kind, ThinkerKind::Door(_))), "a door is at work");
    let bytes = save::to_bytes(&game.sim);
    let table = crate::actors::ActorTable::active().clone();
    let fresh = from_map::level_from_map(&level(&m).compiled, &table).expect("converts");
    let mut loaded = save::from_bytes(&bytes, "gen.sav", fresh, game.sim.info.clone()).expect("loads");
    let mut original = game.sim;
    let cmds = [None; MAXPLAYERS];
    for t in 0..200 {
        original.tick(&cmds);
        loaded.tick(&cmds);
        assert_eq!(save::to_bytes(&original), save::to_bytes(&loaded), "tic {t} after loading");
    }
}
