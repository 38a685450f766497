//! Generalized specials on the simulation, against the motion Doom's rules
//! make from each special's own parameters: a small RON map built here (a
//! room, a tagged sector in it, a walk line or a switch that sets a
//! special no vanilla number says) is played on [`SimGame`], and the
//! tagged sector's heights and light are read tic by tic from the tic the
//! special set them moving. What they should be is worked out here, apart
//! from the engine, by [`Motion`]: `T_MovePlane`'s steps of the special's
//! speed to a destination found by Doom's rule for its target, and its
//! waits in tics (speeds, waits and heights here are exact in 16.16, so
//! the comparison is exact). Also: damage, a combined sector special's
//! glow and secret, a line teleport and a conveyor by Doom's rules; every
//! shipped map converts with no special left out; a game with generalized
//! movers saves and loads bit for bit.

use crate::autopilot::observe::Observe;
use crate::bsp::{build, BuildOptions};
use crate::campaign::{MapRef, Opened};
use crate::map::source::{LineSpecialSource, MapSource, SectorSource, SideSource, ThingSource, TriggerLineSource};
use crate::map::special::{Damage, DoorKind};
use crate::map::{parse_map, Action, Activation, SectorSpecial, Who};
use crate::play::{GameOptions, TickInput};
use crate::sim::game::SimGame;
use crate::sim::{from_map, info, save, ThinkerKind, MAXPLAYERS};

/// The tagged sector: a 128-unit square in the middle of the room.
const INNER: usize = 1;

/// The room's floor, ceiling and light: the only neighbour the tagged
/// sector has, so every "neighbour" target below is one of these.
const ROOM_FLOOR: f64 = 0.0;
const ROOM_CEILING: f64 = 256.0;
const ROOM_LIGHT: i16 = 160;

/// A sector's floor, ceiling and light on the simulation, one tic's.
type Seen = (f64, f64, i16);

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
        light: i64::from(ROOM_LIGHT),
        floor_texture: Some("FLOOR".into()),
        ceiling_texture: Some("CEIL".into()),
        ..SectorSource::default()
    };
    m.sectors.push(sector(ROOM_FLOOR, ROOM_CEILING));
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
    SectorSource { floor, ceiling, light: i64::from(ROOM_LIGHT), ..SectorSource::default() }
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
        wad: None,
    };
    let options = GameOptions { skill: 3, no_monsters: true, ..GameOptions::default() };
    SimGame::new(opened, options).unwrap_or_else(|e| panic!("{e}"))
}

/// The input of tic `t`: walk east for 12 tics, or press use at tic 1.
fn input(t: usize, on: Activation) -> TickInput {
    match on {
        Activation::Use => TickInput { use_line: t == 1, ..TickInput::default() },
        _ => TickInput { forward: i8::from(t < 12), ..TickInput::default() },
    }
}

/// Sector `s` of the simulation as it stands.
fn seen(game: &SimGame, s: usize) -> Seen {
    let sec = &game.sim.level.sectors[s];
    (sec.floorheight.to_f64(), sec.ceilingheight.to_f64(), sec.lightlevel)
}

/// A game of `m` played `tics` tics with the input of `on`: the inner
/// sector as it started, and as it was after each tic from the first tic
/// it differed from that (a mover runs in the tic that starts it, so
/// that is its first step); and the first of those tics after which the
/// sector had no mover (its mover was done).
fn play(m: &MapSource, on: Activation, tics: usize) -> (Seen, Vec<Seen>, Option<usize>) {
    let mut game = sim_game(m);
    let first = seen(&game, INNER);
    let (mut after, mut freed) = (Vec::new(), None);
    for t in 0..tics {
        game.tick(&input(t, on));
        let now = seen(&game, INNER);
        if !after.is_empty() || now != first {
            after.push(now);
            if freed.is_none() && game.sim.level.sectors[INNER].specialdata.is_none() {
                freed = Some(after.len() - 1);
            }
        }
    }
    assert!(!after.is_empty(), "the special never set the sector off");
    (first, after, freed)
}

/// A plane's height tic by tic as Doom's movers make it, from a special's
/// parameters alone (no engine code): the heights after each tic.
#[derive(Clone, Debug)]
struct Motion {
    at: f64,
    tics: Vec<f64>,
}

impl Motion {
    fn from(height: f64) -> Motion {
        Motion { at: height, tics: Vec::new() }
    }

    /// A mover's run to `dest` at `speed` through `T_MovePlane`: a whole
    /// step each tic while it does not pass `dest` (p_floor.c's test is
    /// `lastpos + speed > dest`, strict), then the tic that sets the
    /// plane on `dest` and reports `pastdest`. So a run of d units takes
    /// floor(d/v) + 1 tics, and when d is a multiple of v the last two
    /// are both at `dest`: the mover arrives the tic after it landed.
    fn go(mut self, dest: f64, speed: f64) -> Motion {
        assert!(speed > 0.0);
        let up = dest > self.at;
        loop {
            let next = if up { self.at + speed } else { self.at - speed };
            let past = if up { next > dest } else { next < dest };
            self.at = if past { dest } else { next };
            self.tics.push(self.at);
            if past {
                return self;
            }
        }
    }

    /// A wait of `tics` tics where it stands: a door's `topcountdown` or a
    /// plat's `count`, set to the wait on the arrival tic and counted down
    /// one a tic after it; the tic it reaches 0 turns the mover, which
    /// first moves on the tic after. So a mover rests `wait` tics after
    /// its arrival tic (and a tic more after an exact landing, above).
    fn hold(mut self, tics: usize) -> Motion {
        self.tics.extend(std::iter::repeat_n(self.at, tics));
        self
    }
}

/// Which plane of the sector a special moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Moving {
    Floor,
    Ceiling,
}

/// Runs of equal heights: each height and how many tics it held.
fn runs(v: &[f64]) -> Vec<(f64, usize)> {
    let mut out: Vec<(f64, usize)> = Vec::new();
    for &h in v {
        match out.last_mut() {
            Some((last, n)) if *last == h => *n += 1,
            _ => out.push((h, 1)),
        }
    }
    out
}

/// The sector went through `expected` tic by tic on the `moving` plane,
/// the other plane and the light as they started, and once `expected`
/// ends it stays where it ended (the mover is done). The window must hold
/// the whole of `expected`.
fn assert_motion(start: Seen, after: &[Seen], moving: Moving, expected: &Motion) {
    let e = &expected.tics;
    assert!(after.len() >= e.len(), "the test ran {} tics of the {} the motion takes", after.len(), e.len());
    let plane: Vec<f64> = after.iter().map(|s| if moving == Moving::Floor { s.0 } else { s.1 }).collect();
    let want: Vec<f64> = (0..after.len()).map(|t| e.get(t).copied().unwrap_or(expected.at)).collect();
    assert!(plane == want, "{moving:?}\nexpected {:?}\nsimulation {:?}", runs(&want), runs(&plane));
    for (t, s) in after.iter().enumerate() {
        let other = if moving == Moving::Floor { (s.1, start.1) } else { (s.0, start.0) };
        assert!(other.0 == other.1 && s.2 == start.2, "tic {t}: the other plane or the light moved: {s:?}");
    }
}

/// A mover that comes to rest is done, and leaves its sector free for
/// another, in the tic it arrives: the last of its motion, not before
/// (the tic that lands exactly on the destination does not end it) and
/// not after.
fn assert_done(freed: Option<usize>, expected: &Motion) {
    assert_eq!(freed, Some(expected.tics.len() - 1), "the tic the mover was done");
}

#[test]
fn a_door_with_its_own_speed_and_wait_opens_waits_and_closes_by_them() {
    let (speed, wait) = (4.0, 70);
    let door = Action::Door { kind: DoorKind::Raise, speed, wait, shut: 0, key: None };
    let m = map(sector(0.0, 0.0), walk_line(door));
    let (start, after, freed) = play(&m, Activation::Walk, 400);
    // A raise door opens to 4 under the lowest ceiling around it.
    let top = ROOM_CEILING - 4.0;
    let expected = Motion::from(0.0).go(top, speed).hold(wait as usize).go(0.0, speed);
    assert_motion(start, &after, Moving::Ceiling, &expected);
    assert_done(freed, &expected);
}

#[test]
fn a_close_then_open_door_waits_shut_its_own_time() {
    let (speed, shut) = (8.0, 90);
    let door = Action::Door { kind: DoorKind::CloseThenOpen, speed, wait: 150, shut, key: None };
    let m = map(sector(0.0, 200.0), walk_line(door));
    let (start, after, freed) = play(&m, Activation::Walk, 300);
    // Down to the floor, shut `shut` tics (its `wait` is a raise door's),
    // back up to where it was.
    let expected = Motion::from(200.0).go(0.0, speed).hold(shut as usize).go(200.0, speed);
    assert_motion(start, &after, Moving::Ceiling, &expected);
    assert_done(freed, &expected);
}

#[test]
fn a_lift_with_its_own_speed_and_wait_goes_down_waits_and_comes_back() {
    let (speed, wait) = (2.0, 50);
    let m = map(sector(64.0, 256.0), walk_line(Action::Lift { speed, wait }));
    let (start, after, freed) = play(&m, Activation::Walk, 200);
    // Down to the lowest floor around it (or its own, if lower).
    let expected = Motion::from(64.0).go(ROOM_FLOOR, speed).hold(wait as usize).go(64.0, speed);
    assert_motion(start, &after, Moving::Floor, &expected);
    assert_done(freed, &expected);
}

#[test]
fn floors_go_to_each_target_at_their_own_speed() {
    use crate::map::special::FloorTarget as T;
    // The end is the target by Doom's rule on this map (the room is the
    // only neighbour) plus the offset.
    for (to, offset, speed, start, end) in [
        (T::LowestNeighbourCeiling, -8.0, 3.0, 0.0, ROOM_CEILING - 8.0),
        (T::Current, 40.0, 0.5, 16.0, 16.0 + 40.0),
        (T::LowestNeighbourFloor, 0.0, 2.0, 64.0, ROOM_FLOOR),
        (T::HighestNeighbourFloor, 0.0, 2.0, 64.0, ROOM_FLOOR),
        (T::NextLowerFloor, 0.0, 2.0, 48.0, ROOM_FLOOR),
        (T::Ceiling, -100.0, 4.0, 0.0, 256.0 - 100.0),
    ] {
        let action = Action::Floor { to, offset, speed, crush: false, change: None };
        let m = map(sector(start, 256.0), walk_line(action));
        let (first, after, freed) = play(&m, Activation::Walk, 300);
        let expected = Motion::from(start).go(end, speed);
        assert_motion(first, &after, Moving::Floor, &expected);
        assert_done(freed, &expected);
    }
}

#[test]
fn a_ceiling_and_a_crusher_move_at_their_own_speeds() {
    use crate::map::special::CeilingTarget as T;
    let (speed, offset) = (2.0, 8.0);
    let ceiling = Action::Ceiling { to: T::Floor, offset, speed, crush: false };
    let (start, after, freed) = play(&map(sector(0.0, 200.0), walk_line(ceiling)), Activation::Walk, 200);
    let expected = Motion::from(200.0).go(0.0 + offset, speed);
    assert_motion(start, &after, Moving::Ceiling, &expected);
    assert_done(freed, &expected);

    // A crusher goes from its ceiling down to 8 over its floor and back
    // up, turning on each arrival tic with no wait, for ever; nothing is
    // under it, so it never slows.
    let speed = 3.0;
    let crusher = Action::Crusher { speed, silent: true };
    let (start, after, freed) = play(&map(sector(0.0, 96.0), walk_line(crusher)), Activation::Walk, 150);
    assert_eq!(freed, None, "a crusher runs for ever");
    let mut expected = Motion::from(96.0);
    while expected.tics.len() < after.len() {
        expected = expected.go(8.0, speed).go(96.0, speed);
    }
    expected.tics.truncate(after.len());
    assert_motion(start, &after, Moving::Ceiling, &expected);
    // 88 units at 3 a tic: 29 steps and the arrival, each way.
    assert!(after.len() > 2 * 60, "a whole cycle and more: {} tics", after.len());
    assert_eq!(after[59].1, 96.0, "a cycle takes 60 tics");
}

#[test]
fn a_repeatable_switch_lift_no_number_says_runs_by_its_parameters() {
    // Doom's use lifts are set off by players; this one by anyone.
    let (speed, wait) = (4.0, 105);
    let special = LineSpecialSource {
        on: Activation::Use,
        repeat: true,
        by: Who::Anyone,
        tag: 1,
        action: Action::Lift { speed, wait },
    };
    let m = map(sector(64.0, 256.0), special);
    let (start, after, freed) = play(&m, Activation::Use, 200);
    let expected = Motion::from(64.0).go(ROOM_FLOOR, speed).hold(wait as usize).go(64.0, speed);
    assert_motion(start, &after, Moving::Floor, &expected);
    assert_done(freed, &expected);
}

#[test]
fn light_changes_set_the_level_at_once() {
    use crate::map::special::LightChange;
    for (change, light) in [(LightChange::Set(40), 40), (LightChange::BrightestNeighbour, ROOM_LIGHT)] {
        let special = LineSpecialSource { repeat: true, ..walk_line(Action::Light(change)) };
        let inner = SectorSource { light: 100, ..sector(0.0, 256.0) };
        let (_, after, _) = play(&map(inner, special), Activation::Walk, 20);
        // From the tic the line is crossed: the new level, nothing else
        // changed, and it holds (crossing again sets it again).
        assert!(after.iter().all(|&s| s == (0.0, 256.0, light)), "{change:?}: {after:?}");
    }
}

/// The bites of a damaging floor by Doom's rule: `amount` in each tic
/// whose `leveltime` is a multiple of `every`; `leveltime` is 0 in the
/// first tic, so the first bite comes then.
fn bites(amount: i32, every: usize, tics: usize) -> Vec<(usize, i32)> {
    (0..tics).filter(|t| t % every == 0).map(|t| (t, amount)).collect()
}

/// Damaging floors Doom's types cannot say (7 every 16 tics, 3 every 10),
/// under the player standing still: each bite its amount, the bites
/// `every` tics apart, as many in 100 tics as the period gives.
#[test]
fn a_floor_with_its_own_damage_hurts_by_its_amount_and_period() {
    let tics = 100;
    for (amount, every) in [(7, 16), (3, 10)] {
        let mut m = map(sector(0.0, 0.0), walk_line(Action::Exit));
        let damage = Damage { amount, every, exit_below: 0, suit: Default::default() };
        m.sectors[0].special = SectorSpecial { damage: Some(damage), ..SectorSpecial::default() };
        let mut game = sim_game(&m);
        let mut seen = Vec::new();
        let mut health = 100;
        for t in 0..tics {
            game.tick(&TickInput::default());
            let now = game.sim.player(0).expect("the player").health;
            if now != health {
                seen.push((t, health - now));
            }
            health = now;
        }
        let every = every as usize;
        let expected = bites(amount as i32, every, tics);
        assert_eq!(expected.len(), tics.div_ceil(every));
        assert_eq!(seen, expected, "{amount} every {every}");
    }
}

/// `T_Glow` from p_lights.c, apart from the engine: from the sector's
/// own level `max` down by 8 a tic towards the dimmest neighbour's `min`,
/// turning back one step short of either end. The levels after each tic.
fn glow(max: i16, min: i16, tics: usize) -> Vec<i16> {
    let (mut level, mut down) = (max, true);
    let mut out = Vec::new();
    for _ in 0..tics {
        level = if down { level - 8 } else { level + 8 };
        if down && level <= min {
            (level, down) = (level + 8, false);
        } else if !down && level >= max {
            (level, down) = (level - 8, true);
        }
        out.push(level);
    }
    out
}

/// A sector special combining a glow with damage and a secret: the glow
/// runs (between the sector's own light and its dimmest neighbour's by
/// Doom's rule), and the damage and the secret stay the sector's special
/// until the secret is found, then the damage alone.
#[test]
fn a_combined_sector_special_keeps_what_acts_on_the_player() {
    use crate::map::special::LightEffect;
    let dim: i16 = 96;
    let mut m = map(SectorSource { light: i64::from(dim), ..sector(0.0, 0.0) }, walk_line(Action::Exit));
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
    let mut lights = vec![seen(&sim, 0).2];
    for _ in 1..40 {
        sim.tick(&TickInput::default());
        lights.push(seen(&sim, 0).2);
    }
    assert_eq!(lights, glow(ROOM_LIGHT, dim, 40));
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

/// A conveyor (Boom's carrying floor: `push` units of momentum a tic)
/// under the player standing still pushes the body along it by Doom's
/// rules: each tic the body moves by its momentum (`P_XYMovement`), keeps
/// `FRICTION` (0xe800/0x10000 = 0.90625) of it on the floor, and the
/// conveyor, which runs after the thinkers as Boom's scrollers do, adds
/// its push. So its speed tends to push·f/(1−f), 4.83 units a tic for
/// 0.5, and it goes nowhere across the push.
#[test]
fn a_carrying_floor_pushes_the_player() {
    use crate::map::special::Scroll;
    let push = 0.5;
    let mut m = map(sector(0.0, 256.0), walk_line(Action::Exit));
    m.trigger_lines.clear();
    m.sectors[0].carry = Some(Scroll { x: push, y: 0.0 });
    let mut sim = sim_game(&m);
    let start = Observe::player(&sim).pos;
    let friction = f64::from(0xe800) / f64::from(0x10000);
    let (mut x, mut momentum) = (0.0, 0.0);
    for t in 0..20 {
        sim.tick(&TickInput::default());
        x += momentum;
        momentum = momentum * friction + push;
        let moved = Observe::player(&sim).pos - start;
        // FixedMul truncates: a few 2^-16 a tic.
        assert!((moved.x - x).abs() < 1e-3 && moved.y == 0.0, "tic {t}: moved {moved}, by Doom's rules {x}");
    }
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
