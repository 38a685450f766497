//! Play: the simulation's promises on RON maps, checked headless through
//! [`SimGame`] (Doom's fixed-point game). Seeded random play on every
//! shipped map the simulation takes (the player stays in the map, never
//! passes a wall, and the step and headroom rules hold at every tick;
//! nasty.ron, beyond Doom's 16-bit coordinates, is refused); directed cases
//! (a wall from every angle at full speed, sliding, the 24/25 step, the
//! 56/55 passage, a fall, doors, a grid map's doors); demos that replay bit
//! for bit; corrupt demo files; a map's own animations.
//!
//! Positions are read from the simulation's own bodies (`game.sim`), in map
//! units; heights from the drawn level, which the simulation writes back
//! every tic (RON sector `i` is the simulation's sector `i`).

use glam::DVec2;
use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use sightline::autopilot::observe::Observe;
use sightline::bsp::{build, BuildOptions};
use sightline::fixed::Fixed;
use sightline::geom::{segment_contact, Contact};
use sightline::level::Level;
use sightline::map::{parse_map, Map};
use sightline::play::demo::{DemoError, MAGIC, VERSION};
use sightline::play::{Demo, GameOptions, TickInput, TICRATE};
use sightline::render::{render_frame, Frame, RenderOptions};
use sightline::sim::game::SimGame;
use sightline::sim::ThinkerKind;
use sightline::Framebuffer;
use sightline_tests::sim_play::{door, stand as place, DoorState};
use sightline_tests::{load, map_path, random_inputs, shipped_maps};

/// The player's box (Doom's `mobjinfo[MT_PLAYER]`: radius 16, height 56)
/// and the highest step `P_TryMove` climbs (`tmfloorz - thing->z > 24`
/// blocks).
const RADIUS: f64 = 16.0;
const HEIGHT: f64 = 56.0;
const MAX_STEP: f64 = 24.0;
/// `MAXMOVE` (p_local.h): `P_XYMovement` clips momentum to 30 a tic on
/// each axis.
const MAXMOVE: f64 = 30.0;
/// A fixed-point unit: positions are multiples of it, so a body pressed to
/// a wall may stand that much inside the float figure.
const UNIT: f64 = 1.0 / 65536.0;

fn options() -> GameOptions {
    GameOptions::default()
}

fn level_from(text: &str) -> Level {
    let map = parse_map(text, "test.ron").unwrap_or_else(|e| panic!("{e}"));
    let compiled = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    Level::with_builtin_textures(compiled).unwrap_or_else(|e| panic!("{e}"))
}

fn game_from(text: &str) -> SimGame {
    SimGame::on_level(level_from(text), "test.ron", options()).unwrap_or_else(|e| panic!("{e}"))
}

fn game_on(name: &str) -> SimGame {
    SimGame::on_level(load(&map_path(name)), name, options()).unwrap_or_else(|e| panic!("{e}"))
}

fn body(game: &SimGame) -> &sightline::sim::Mobj {
    let console = game.sim.console;
    game.sim.mo(game.sim.players[console].as_ref().expect("a player").mo)
}

/// Where the player's body is now (the read-out `Observe::player` is as
/// of the last tic; this is the simulation's, also after [`place`]).
fn pos(game: &SimGame) -> DVec2 {
    let m = body(game);
    DVec2::new(m.x.to_f64(), m.y.to_f64())
}

fn z(game: &SimGame) -> f64 {
    body(game).z.to_f64()
}

const RUN_EAST: TickInput =
    TickInput { forward: 1, strafe: 0, turn: 0.0, run: true, use_line: false, fire: false, weapon: 0 };
const IDLE: TickInput =
    TickInput { forward: 0, strafe: 0, turn: 0.0, run: false, use_line: false, fire: false, weapon: 0 };

fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    (a + d * t).distance(p)
}

/// The rules, restated independently of the engine: does `line` stop a body
/// whose feet are at `z`, given the sector heights `h` (floor, ceiling)?
fn blocks(map: &Map, h: &[(f64, f64)], line: usize, z: f64) -> bool {
    let line = &map.lines[line];
    let Some(back) = &line.back else { return true };
    let (f, b) = (h[line.front.sector], h[back.sector]);
    let floor = f.0.max(b.0);
    line.flags.impassable || floor - z > MAX_STEP || f.1.min(b.1) - floor.max(z) < HEIGHT
}

fn heights(game: &SimGame) -> Vec<(f64, f64)> {
    Observe::level(game).compiled.map.sectors.iter().map(|s| (s.floor, s.ceiling)).collect()
}

/// Sectors whose ceiling a crusher is moving: Doom's crushers come down
/// through a body (that is what they are for), so headroom is not promised
/// under them.
fn crushing(game: &SimGame) -> Vec<usize> {
    let thinkers = game.sim.thinkers.iter().filter(|t| t.status != sightline::sim::think::Status::Removed);
    thinkers
        .filter_map(|t| if let ThinkerKind::Ceiling(c) = &t.kind { c.crush.then_some(c.sector) } else { None })
        .collect()
}

/// What one run of random play saw.
#[derive(Debug, Default)]
struct Seen {
    path: f64,
    /// Ticks ending within a unit of the body's radius from a blocking line.
    at_walls: usize,
    climbs: usize,
    falls: usize,
    teleports: usize,
    /// Sectors the centre has been in.
    sectors: std::collections::BTreeSet<usize>,
}

/// Plays `inputs` on `game`, checking every rule at every tick.
fn play_checked(name: &str, game: &mut SimGame, inputs: &[TickInput]) -> Seen {
    let map = Observe::level(game).compiled.map.clone();
    let ends: Vec<(DVec2, DVec2)> = map.lines.iter().map(|l| map.line_points(l)).collect();
    let clearance_at = |p: DVec2, h: &[(f64, f64)], z: f64| {
        (0..ends.len())
            .filter(|&i| blocks(&map, h, i, z))
            .map(|i| distance_to_segment(p, ends[i].0, ends[i].1))
            .fold(f64::INFINITY, f64::min)
    };
    // Doom's box of half-width 16 keeps every blocking line at least 16
    // from its centre (the circle of radius 16 lies inside the box); the
    // box touching a line exactly is allowed, to the fixed-point unit.
    let least = RADIUS - 2.0 * UNIT;
    let mut seen = Seen::default();
    let mut before = heights(game);
    // A start closer than the radius to a wall may stay that close; once
    // clear, the body must stay clear.
    let mut clear = clearance_at(pos(game), &before, z(game)) >= least;
    for (tick, input) in inputs.iter().enumerate() {
        // Every tick: a health bonus or a soul sphere caps health at 200,
        // and a dead body (a quarter of the height) would pass where the
        // player may not.
        game.set_health(1_000_000_000);
        let (old, z0) = (pos(game), z(game));
        game.tick(input);
        let (p, z) = (pos(game), z(game));
        let after = heights(game);
        let at = || format!("{name}, tick {tick}: from ({}, {}) z {z0} to ({}, {}) z {z}", old.x, old.y, p.x, p.y);
        assert!(p.is_finite() && z.is_finite(), "{}", at());
        // In the map: inside a sector, or on lines that are all two-sided.
        assert!(map.contains(p), "{}: left the map", at());
        // A teleporter moves the body without walking it (Doom's
        // P_TeleportMove checks no lines; the speed cap keeps a walk under
        // 2 * MAXMOVE a tic).
        if old.distance(p) > 2.0 * MAXMOVE {
            seen.teleports += 1;
            clear = clearance_at(p, &after, z) >= least;
            before = after;
            continue;
        }
        // Never across a line that blocked the body when the tick began.
        if old != p {
            for (i, &(a, b)) in ends.iter().enumerate() {
                let near = a.min(b).cmple(old.max(p) + 1.0).all() && a.max(b).cmpge(old.min(p) - 1.0).all();
                if near && blocks(&map, &before, i, z0) {
                    let contact = segment_contact(old, p, a, b);
                    assert_eq!(contact, Contact::None, "{}: crossed line {i}", at());
                }
            }
        }
        let clearance = clearance_at(p, &before, z0);
        if clear {
            assert!(clearance >= least, "{}: {clearance} from a blocking line", at());
        }
        clear |= clearance >= least;
        // Steps: at most MAX_STEP per tick, measured from the feet.
        assert!(z - z0 <= MAX_STEP, "{}: climbed {}", at(), z - z0);
        // Standing on or above every floor under the body, fitting under
        // every ceiling over it (but a crusher's).
        let crushers = crushing(game);
        let mut under: Vec<usize> = map.sector_strictly_containing(p).into_iter().collect();
        for (i, &(a, b)) in ends.iter().enumerate() {
            if distance_to_segment(p, a, b) < RADIUS - 1e-6 {
                let line = &map.lines[i];
                under.extend(std::iter::once(line.front.sector).chain(line.back.as_ref().map(|s| s.sector)));
            }
        }
        for s in under {
            let ceiling = after[s].1;
            // A floor that rose this tick did so after the body moved
            // (movers run after the bodies spawned before them): a body in
            // the air keeps its z until its next move lands it on it
            // (P_ThingHeightClip lifts only a body standing on the floor).
            let floor = before[s].0.min(after[s].0);
            assert!(z >= floor, "{}: feet below the floor {floor} of sector {s}", at());
            if !crushers.contains(&s) {
                assert!(ceiling - z >= HEIGHT, "{}: only {} of headroom in sector {s}", at(), ceiling - z);
            }
        }
        if let Some(s) = map.sector_strictly_containing(p) {
            assert!(after[s].0 - z0 <= MAX_STEP, "{}: floor rose {} in one tick", at(), after[s].0 - z0);
        }
        seen.path += old.distance(p);
        seen.at_walls += usize::from(clearance < RADIUS + 1.0);
        seen.climbs += usize::from(z > z0);
        seen.falls += usize::from(z < z0);
        seen.sectors.insert(Observe::player(game).sector);
        before = after;
    }
    assert!(Observe::player(game).health > 0, "{name}: the player died");
    seen
}

#[test]
fn random_play_keeps_every_rule_on_every_shipped_map() {
    const TICKS: usize = 100_000;
    let maps = shipped_maps();
    let results: Vec<(String, Seen)> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..2)
            .map(|w| {
                let maps = &maps;
                scope.spawn(move || {
                    let mut out = Vec::new();
                    for (k, path) in maps.iter().enumerate().filter(|(k, _)| k % 2 == w) {
                        let name = path.file_name().unwrap().to_string_lossy().to_string();
                        let level = load(path);
                        if name == "nasty.ron" {
                            // Its coordinates are beyond Doom's 16-bit map
                            // format: the simulation refuses it, by name.
                            let refused = SimGame::on_level(level, &name, options()).err().map(|e| e.to_string());
                            assert!(refused.is_some_and(|e| e.contains("beyond ±32767")), "nasty.ron was not refused");
                            continue;
                        }
                        let mut game = SimGame::on_level(level, &name, options()).unwrap_or_else(|e| panic!("{e}"));
                        let seen = play_checked(&name, &mut game, &random_inputs(1000 + k as u64, TICKS));
                        out.push((name, seen));
                    }
                    out
                })
            })
            .collect();
        workers.into_iter().flat_map(|w| w.join().unwrap()).collect()
    });
    for (name, seen) in &results {
        eprintln!("{name}: {seen:?}");
        // The run did what it was for: travelled, and spent time against walls.
        assert!(seen.path > 50_000.0, "{name}: the player hardly moved ({seen:?})");
        assert!(seen.at_walls > TICKS / 50, "{name}: the player rarely met a wall ({seen:?})");
    }
    // doors.ron (sectors numbered as maps/generators/doors.py makes them):
    // through both doors, into the pit and up its steps, round the 56-unit
    // corridor; never onto the 40-unit dais or into the 48-unit crawlspace
    // and the alcove behind it.
    let (_, doors) = results.iter().find(|(name, _)| name == "doors.ron").expect("doors.ron is shipped");
    for (sector, what) in [(3, "door 1"), (4, "door 2"), (6, "the pit"), (9, "the top pit step"), (12, "the corridor")]
    {
        assert!(doors.sectors.contains(&sector), "doors.ron: never in {what} (sector {sector}): {doors:?}");
    }
    for (sector, what) in [(11, "the dais"), (13, "the crawlspace"), (14, "the alcove")] {
        assert!(!doors.sectors.contains(&sector), "doors.ron: got into {what} (sector {sector})");
    }
    // bunker.ron: through most of its 8 grid doors (door k is sector
    // k + 1), so the rules above held while grid doors opened and shut
    // around the player. (On Doom's physics this walk misses door 1, between
    // the west and middle rooms; every_grid_door_opens_and_lets_the_player_through
    // takes the player through each.)
    let (_, bunker) = results.iter().find(|(name, _)| name == "bunker.ron").expect("bunker.ron is shipped");
    let doors_passed = (1..=8).filter(|s| bunker.sectors.contains(s)).count();
    assert!(doors_passed >= 6, "bunker.ron: through only {doors_passed} of its doors: {bunker:?}");
    let stepped = results.iter().filter(|(_, s)| s.climbs > 0 && s.falls > 0).count();
    assert!(stepped >= 3, "too few maps where the player both climbed and fell: {results:?}");
}

/// Two 512x512 rooms side by side, west (A) and east (B), joined by an open
/// line at x = 512; the player starts in A facing east.
fn two_rooms(a: (f64, f64), b: (f64, f64)) -> String {
    format!(
        r#"Map(name: "two", vertices: [(0, 0), (0, 512), (512, 512), (1024, 512), (1024, 0), (512, 0)],
        sectors: [Sector(floor: {}, ceiling: {}, light: 160), Sector(floor: {}, ceiling: {}, light: 160)],
        lines: [
            Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
            Line(from: 2, to: 3, front: Side(sector: 1)), Line(from: 3, to: 4, front: Side(sector: 1)),
            Line(from: 4, to: 5, front: Side(sector: 1)), Line(from: 5, to: 0, front: Side(sector: 0)),
            Line(from: 5, to: 2, front: Side(sector: 1), back: Side(sector: 0)),
        ],
        things: [Thing(kind: "player_start", x: 256, y: 256, angle: 0)])"#,
        a.0, a.1, b.0, b.1
    )
}

/// Runs east for `ticks`; returns the final x and z.
fn run_east(game: &mut SimGame, ticks: usize) -> (f64, f64) {
    for _ in 0..ticks {
        game.tick(&RUN_EAST);
    }
    (pos(game).x, z(game))
}

/// Stopped by the line at x = `wall` coming from the west: the box's east
/// face at it or short of it, by less than a unit (P_SlideMove moves up to
/// 1/32 of a move short of the wall each tic, so pressing on closes in).
fn stopped_west_of(x: f64, wall: f64) -> bool {
    x <= wall - RADIUS && x > wall - RADIUS - 1.0
}

#[test]
fn a_step_of_24_is_climbed_and_25_is_not() {
    let (x, z) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (24.0, 128.0))), 60);
    assert!(x > 512.0 + RADIUS && z == 24.0, "did not climb 24: x {x}, z {z}");
    let (x, z) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (25.0, 128.0))), 60);
    assert!(stopped_west_of(x, 512.0) && z == 0.0, "climbed 25: x {x}, z {z}");
    // Down is always fine.
    let (x, z) = run_east(&mut game_from(&two_rooms((25.0, 128.0), (0.0, 128.0))), 60);
    assert!(x > 512.0 + RADIUS && z == 0.0, "did not step down 25: x {x}, z {z}");
}

#[test]
fn headroom_of_56_is_enough_and_55_is_not() {
    let (x, _) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (0.0, 56.0))), 60);
    assert!(x > 512.0 + RADIUS, "could not enter a 56-unit passage: x {x}");
    let (x, _) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (0.0, 55.0))), 60);
    assert!(stopped_west_of(x, 512.0), "entered a 55-unit passage: x {x}");
    // A step of 8 under a ceiling 62 above the lower floor leaves 54: no.
    let (x, _) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (8.0, 62.0))), 60);
    assert!(stopped_west_of(x, 512.0), "squeezed under 54 units: x {x}");
}

#[test]
fn walking_off_a_ledge_falls_to_the_lower_floor() {
    let mut game = game_from(&two_rooms((128.0, 256.0), (0.0, 256.0)));
    let mut heights = Vec::new();
    for _ in 0..60 {
        game.tick(&RUN_EAST);
        heights.push(z(&game));
    }
    let airborne = heights.iter().filter(|&&z| z > 0.0 && z < 128.0).count();
    // Doom's P_ZMovement: the first tic off the floor falls 2, then each
    // tic 1 faster (GRAVITY is a unit a tic): 2 + 3 + ... + 16 = 135 >= 128,
    // 15 tics; not a teleport, not a float.
    assert!((13..=16).contains(&airborne), "{airborne} ticks in the air: {heights:?}");
    assert!(heights.windows(2).all(|w| w[1] <= w[0]), "rose while falling: {heights:?}");
    let p = Observe::player(&game);
    assert_eq!((p.z, p.vz, p.sector), (0.0, 0.0, 1), "did not land on the lower floor");
    // In the air the player cannot push (P_MovePlayer thrusts only on the
    // ground) and nothing slows it (no friction off the floor): it flies on.
    assert!(p.on_ground() && p.pos.x > 512.0 + 3.0 * RADIUS, "stopped at the ledge: {:?}", p.pos);
}

/// A 1024x1024 room with a pillar one unit thick and 800 long in the middle.
const ROOM_WITH_BLADE: &str = r#"Map(name: "blade",
    vertices: [(0, 0), (0, 1024), (1024, 1024), (1024, 0), (512, 112), (513, 112), (513, 912), (512, 912)],
    sectors: [Sector(floor: 0, ceiling: 128, light: 160)],
    lines: [
        Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
        Line(from: 2, to: 3, front: Side(sector: 0)), Line(from: 3, to: 0, front: Side(sector: 0)),
        Line(from: 4, to: 5, front: Side(sector: 0)), Line(from: 5, to: 6, front: Side(sector: 0)),
        Line(from: 6, to: 7, front: Side(sector: 0)), Line(from: 7, to: 4, front: Side(sector: 0)),
    ],
    things: [Thing(kind: "player_start", x: 256, y: 512, angle: 0)])"#;

#[test]
fn running_into_a_wall_from_every_angle_never_crosses_it() {
    let mut game = game_from(ROOM_WITH_BLADE);
    let map = Observe::level(&game).compiled.map.clone();
    let blade_x = 512.5;
    let console = game.sim.console;
    let mo = game.sim.players[console].as_ref().unwrap().mo;
    // Whole degrees and awkward fractions; aimed at the blade from both
    // sides, at its middle and near its ends, with momentum far past the cap.
    let angles = (0..360).map(f64::from).chain((0..97).map(|k| k as f64 * 3.7137 + 0.001));
    for angle in angles {
        for target_y in [512.0, 130.0, 895.0] {
            let dir = DVec2::new(angle.to_radians().cos(), angle.to_radians().sin());
            let start = DVec2::new(blade_x, target_y) - dir * 120.0;
            let clear = map.lines.iter().all(|l| {
                let (a, b) = map.line_points(l);
                distance_to_segment(start, a, b) > RADIUS * std::f64::consts::SQRT_2 + 1.0
            });
            if !clear || map.sector_strictly_containing(start).is_none() {
                continue;
            }
            place(&mut game, start, angle);
            let mut touched = false;
            for tick in 0..40 {
                let m = game.sim.mo_mut(mo);
                (m.momx, m.momy) = (Fixed::from_f64(dir.x * 1000.0), Fixed::from_f64(dir.y * 1000.0));
                let old = pos(&game);
                game.tick(&RUN_EAST);
                let p = pos(&game);
                let v = Observe::player(&game).velocity;
                assert!(v.x.abs() <= MAXMOVE && v.y.abs() <= MAXMOVE, "momentum {v} past MAXMOVE");
                let at = format!("angle {angle}, target y {target_y}, tick {tick}: ({}, {})", p.x, p.y);
                for l in &map.lines {
                    let (a, b) = map.line_points(l);
                    assert_eq!(segment_contact(old, p, a, b), Contact::None, "{at}: crossed a wall");
                    let d = distance_to_segment(p, a, b);
                    assert!(d >= RADIUS - 2.0 * UNIT, "{at}: inside a wall ({d})");
                    // P_SlideMove stops 1/32 of the move short of a wall:
                    // under a unit at MAXMOVE.
                    touched |= d < RADIUS + MAXMOVE / 32.0 + 0.01;
                }
            }
            // It got to a wall (it may then slide round the blade's end).
            assert!(touched, "angle {angle}, target y {target_y}: never reached a wall");
        }
    }
}

#[test]
fn sliding_along_a_wall_keeps_moving() {
    let mut game = game_from(ROOM_WITH_BLADE);
    // Run north-east into the north wall at 30 degrees off it, from far
    // enough west to slide for 60 tics above the blade's end (y 912).
    place(&mut game, DVec2::new(24.0, 900.0), 30.0);
    let mut xs = Vec::new();
    for _ in 0..80 {
        game.tick(&RUN_EAST);
        xs.push(pos(&game).x);
        let y = pos(&game).y;
        assert!(y <= 1024.0 - RADIUS, "into the north wall: y {y}");
    }
    assert!(pos(&game).y > 1024.0 - RADIUS - 1.0, "not against the wall: {:?}", pos(&game));
    // Against the wall P_SlideMove keeps the momentum's along-wall part,
    // less the share of the move it spent reaching the wall (at least the
    // 1/32 fudge, 0x800). The run's thrust along the wall (forwardmove 50 *
    // 2048 = 1.5625 a tic, times cos 30 = 1.353) against friction (0xe800,
    // 0.90625) settles at a move of 1.353 / (1 - 0.90625) = 14.43 a tic
    // with nothing lost (running's 16.67 times cos 30), and at 10.74 with a
    // 32nd lost every tic: 1.353 * k / (1 - 0.90625 * k), k = 31/32. The
    // speed lost hitting the wall is made up within 60 tics.
    let per_tick = (xs[79] - xs[69]) / 10.0;
    let before = (xs[69] - xs[59]) / 10.0;
    assert!((10.7..=14.5).contains(&per_tick), "slid {per_tick} units a tick");
    assert!(per_tick >= before - 0.01, "the slide slows: {before} then {per_tick} a tick");
}

/// Room A (west), a 16-deep door sector D (ceiling 0, shut) and room B
/// (east); both door lines face the rooms, D behind them.
const DOOR_MAP: &str = r#"Map(name: "door",
    vertices: [(0, 0), (0, 256), (256, 256), (256, 160), (256, 96), (256, 0),
               (272, 160), (272, 96), (272, 256), (528, 256), (528, 0), (272, 0)],
    sectors: [Sector(floor: 0, ceiling: 128, light: 160), Sector(floor: 0, ceiling: 0, light: 160),
              Sector(floor: 0, ceiling: 160, light: 160)],
    lines: [
        Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
        Line(from: 2, to: 3, front: Side(sector: 0)),
        Line(from: 3, to: 4, front: Side(sector: 0), back: Side(sector: 1), door: true),
        Line(from: 4, to: 5, front: Side(sector: 0)), Line(from: 5, to: 0, front: Side(sector: 0)),
        Line(from: 3, to: 6, front: Side(sector: 1)), Line(from: 7, to: 4, front: Side(sector: 1)),
        Line(from: 6, to: 8, front: Side(sector: 2)), Line(from: 8, to: 9, front: Side(sector: 2)),
        Line(from: 9, to: 10, front: Side(sector: 2)), Line(from: 10, to: 11, front: Side(sector: 2)),
        Line(from: 11, to: 7, front: Side(sector: 2)),
        Line(from: 7, to: 6, front: Side(sector: 2), back: Side(sector: 1), door: true),
    ],
    things: [Thing(kind: "player_start", x: 128, y: 128, angle: 0)])"#;

fn ceiling(game: &SimGame, sector: usize) -> f64 {
    Observe::level(game).compiled.map.sectors[sector].ceiling
}

fn door_ceiling(game: &SimGame) -> f64 {
    ceiling(game, 1)
}

#[test]
fn a_door_opens_when_used_lets_the_player_through_and_closes_after_a_wait() {
    let mut game = game_from(DOOR_MAP);
    assert_eq!(door(&game, 1), None);
    // Shut: the body stops at it.
    let (x, _) = run_east(&mut game, 40);
    assert!(stopped_west_of(x, 256.0), "walked through a shut door: x {x}");
    assert_eq!(door_ceiling(&game), 0.0);
    // Use it from here (the door is 16 ahead, within USERANGE 64).
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 1), Some(DoorState::Opening));
    // It rises at 2 a tick (VDOORSPEED) to the lowest neighbouring ceiling
    // less 4 (128 - 4): 62 tics of moving, the use tic the first (Doom runs
    // a new thinker in the tic that made it), and one more at the top:
    // T_MovePlane reports the destination only when a step would pass it
    // (`ceilingheight + speed > dest`), so a door landing on it exactly
    // learns it has arrived the tic after.
    let mut ticks = 1;
    while door(&game, 1) == Some(DoorState::Opening) {
        game.tick(&IDLE);
        ticks += 1;
        assert!(ticks < 100, "never finished opening");
    }
    assert_eq!((door_ceiling(&game), ticks), (124.0, 63));
    let (x, _) = run_east(&mut game, 30);
    assert!(x > 272.0 + RADIUS && Observe::player(&game).sector == 2, "did not pass the open door: x {x}");
    // Open for 150 tics after it finished opening (VDOORWAIT), then down at 2.
    for _ in 30..150 {
        game.tick(&IDLE);
    }
    assert_eq!(door_ceiling(&game), 124.0, "closed early");
    for _ in 0..62 + 5 {
        game.tick(&IDLE);
    }
    assert_eq!((door_ceiling(&game), door(&game, 1)), (0.0, None));
    // Shut again: no way back west.
    place(&mut game, DVec2::new(400.0, 128.0), 180.0);
    for _ in 0..40 {
        game.tick(&TickInput { forward: 1, run: true, ..IDLE });
    }
    assert!(pos(&game).x >= 272.0 + RADIUS, "walked back through the shut door");
    // From the far side, the other door line opens it too.
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 1), Some(DoorState::Opening));
    // Used again while it opens, it closes at once (Doom's EV_VerticalDoor
    // for a player); used while it closes, it opens again.
    game.tick(&IDLE);
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 1), Some(DoorState::Closing));
    game.tick(&IDLE);
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 1), Some(DoorState::Opening));
    // Holding use does not use it again (P_PlayerThink's usedown).
    for _ in 0..10 {
        game.tick(&TickInput { use_line: true, ..IDLE });
    }
    assert_eq!(door(&game, 1), Some(DoorState::Opening));
}

#[test]
fn a_door_never_closes_on_the_player() {
    let mut game = game_from(DOOR_MAP);
    place(&mut game, DVec2::new(230.0, 128.0), 0.0);
    game.tick(&TickInput { use_line: true, ..IDLE });
    for _ in 0..70 {
        game.tick(&IDLE);
    }
    // Step into the doorway and stand there.
    while pos(&game).x < 248.0 {
        game.tick(&TickInput { forward: 1, ..IDLE });
        assert!(game.sim.leveltime < 200, "never reached the doorway");
    }
    for _ in 0..60 {
        game.tick(&IDLE);
    }
    let x = pos(&game).x;
    assert!(x > 256.0 - RADIUS && x < 272.0 + RADIUS, "not in the doorway: x {x}");
    let mut lowest = f64::INFINITY;
    let mut reopened = 0;
    let mut last = door_ceiling(&game);
    for tick in 0..1000 {
        game.tick(&IDLE);
        let c = door_ceiling(&game);
        assert!(c - z(&game) >= HEIGHT, "tick {tick}: the door came down to {c} on the player");
        lowest = lowest.min(c);
        reopened += usize::from(c > last && last < 124.0);
        last = c;
    }
    // T_VerticalDoor: a normal door that meets a body goes back up.
    assert!(lowest < 124.0 && reopened > 0, "the door never tried to close (lowest {lowest})");
    // Once the player has gone, it closes.
    run_east(&mut game, 30);
    for _ in 0..400 {
        game.tick(&IDLE);
    }
    assert_eq!(door_ceiling(&game), 0.0);
}

#[test]
fn a_door_line_must_be_two_sided() {
    let text = DOOR_MAP.replace(
        "Line(from: 0, to: 1, front: Side(sector: 0))",
        "Line(from: 0, to: 1, front: Side(sector: 0), door: true)",
    );
    let err = parse_map(&text, "door.ron").unwrap_err().to_string();
    assert!(err.contains("door.ron") && err.contains("line 0") && err.contains("door"), "{err}");
}

/// Rooms A (x 0..128) and B (128..256), a door sector tagged 5 (256..272)
/// and room C beyond it. The A|B line (line 3, two-sided) carries TRIGGER;
/// the west wall (line 0) carries SWITCH. No line is a manual door.
const TAGGED_MAP: &str = r#"Map(name: "tagged",
    vertices: [(0, 0), (0, 256), (128, 256), (256, 256), (256, 160), (256, 96), (256, 0), (128, 0),
               (272, 160), (272, 96), (272, 256), (528, 256), (528, 0), (272, 0)],
    sectors: [Sector(floor: 0, ceiling: 128, light: 160), Sector(floor: 0, ceiling: 128, light: 160),
              Sector(floor: 0, ceiling: 0, light: 160, tag: 5), Sector(floor: 0, ceiling: 160, light: 160)],
    lines: [
        Line(from: 0, to: 1, front: Side(sector: 0) SWITCH), Line(from: 1, to: 2, front: Side(sector: 0)),
        Line(from: 7, to: 0, front: Side(sector: 0)),
        Line(from: 2, to: 7, front: Side(sector: 0), back: Side(sector: 1) TRIGGER),
        Line(from: 2, to: 3, front: Side(sector: 1)), Line(from: 3, to: 4, front: Side(sector: 1)),
        Line(from: 4, to: 5, front: Side(sector: 1), back: Side(sector: 2)),
        Line(from: 5, to: 6, front: Side(sector: 1)), Line(from: 6, to: 7, front: Side(sector: 1)),
        Line(from: 4, to: 8, front: Side(sector: 2)), Line(from: 9, to: 5, front: Side(sector: 2)),
        Line(from: 8, to: 10, front: Side(sector: 3)), Line(from: 10, to: 11, front: Side(sector: 3)),
        Line(from: 11, to: 12, front: Side(sector: 3)), Line(from: 12, to: 13, front: Side(sector: 3)),
        Line(from: 13, to: 9, front: Side(sector: 3)),
        Line(from: 9, to: 8, front: Side(sector: 3), back: Side(sector: 2)),
    ],
    things: [Thing(kind: "player_start", x: 64, y: 128, angle: 0)])"#;

fn tagged(trigger: &str, switch: &str) -> SimGame {
    game_from(&TAGGED_MAP.replace(" TRIGGER", trigger).replace(" SWITCH", switch))
}

const RUN_WEST: TickInput = TickInput { forward: -1, ..RUN_EAST };

/// Ticks `input` until `done(x)` holds for the player's x (at most 200 ticks).
fn run_until(game: &mut SimGame, input: &TickInput, done: impl Fn(f64) -> bool) {
    for _ in 0..200 {
        if done(pos(game).x) {
            return;
        }
        game.tick(input);
    }
    panic!("never got there: x {}", pos(game).x);
}

#[test]
fn walking_over_a_trigger_opens_the_tagged_door_once() {
    let mut game = tagged(", trigger: Trigger(tag: 5, on: Walk, once: true)", "");
    assert_eq!(door(&game, 2), None);
    // Crossing x = 128 sets it off; the door opens, waits and closes
    // (62 up, 150 open, 62 down).
    run_east(&mut game, 12);
    assert!(pos(&game).x > 128.0);
    assert_eq!(door(&game, 2), Some(DoorState::Opening));
    for _ in 0..300 {
        game.tick(&IDLE);
    }
    assert_eq!((door(&game, 2), ceiling(&game, 2)), (None, 0.0));
    // Once only: back over the line and across again does nothing.
    run_until(&mut game, &RUN_WEST, |x| x < 100.0);
    run_until(&mut game, &RUN_EAST, |x| x > 160.0);
    assert_eq!(door(&game, 2), None);
}

#[test]
fn a_repeatable_trigger_works_from_either_side_and_a_stay_open_door_stays() {
    let mut game = tagged(", trigger: Trigger(tag: 5, on: Walk, stay_open: true)", "");
    run_east(&mut game, 8);
    for _ in 0..400 {
        game.tick(&IDLE);
    }
    assert_eq!((door(&game, 2), ceiling(&game, 2)), (None, 124.0));
    let mut game = tagged(", trigger: Trigger(tag: 5, on: Walk)", "");
    run_east(&mut game, 8);
    for _ in 0..300 {
        game.tick(&IDLE);
    }
    assert_eq!(door(&game, 2), None);
    run_until(&mut game, &RUN_WEST, |x| x < 100.0);
    assert_eq!(door(&game, 2), Some(DoorState::Opening), "crossing back sets it off again");
}

#[test]
fn a_switch_opens_the_tagged_door_and_a_walk_trigger_ignores_use() {
    let mut game = tagged("", ", trigger: Trigger(tag: 5, on: Use, once: true, stay_open: true)");
    // Face the west wall (the switch) from 32 units: use it.
    place(&mut game, DVec2::new(32.0, 128.0), 180.0);
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 2), Some(DoorState::Opening));
    // A walk trigger is not a switch.
    let mut game = tagged(", trigger: Trigger(tag: 5, on: Walk)", "");
    place(&mut game, DVec2::new(100.0, 128.0), 0.0);
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 2), None);
}

#[test]
fn a_trigger_tag_out_of_range_is_refused() {
    let text = TAGGED_MAP.replace(" TRIGGER", ", trigger: Trigger(tag: 70000, on: Walk)").replace(" SWITCH", "");
    let err = parse_map(&text, "t.ron").unwrap_err().to_string();
    assert!(err.contains("line 3 trigger: tag 70000 is outside 0..=65535"), "{err}");
}

#[test]
fn the_view_interpolates_between_ticks() {
    let mut game = game_from(&two_rooms((0.0, 128.0), (0.0, 128.0)));
    for _ in 0..10 {
        game.tick(&TickInput { turn: 10.0, ..RUN_EAST });
    }
    let (a, b) = (game.view(0.0), game.view(1.0));
    let mid = game.view(0.5);
    assert!((mid.pos - (a.pos + b.pos) / 2.0).length() < 1e-9);
    assert!((mid.angle - (a.angle + b.angle) / 2.0).abs() < 1e-9);
    // A 1.9 demo's command turns by whole 1/256ths of the circle (1.40625
    // degrees), the rest carried: 90 degrees is 64 of them, 100 rounds
    // down to 71 (99.84375).
    assert_eq!((a.angle, b.angle), (90.0, 71.0 * 360.0 / 256.0));
    assert!(a.pos.x < b.pos.x, "the view did not move");
    assert_eq!(b.pos, pos(&game));
    assert_eq!(TICRATE, 35);
}

/// bunker.ron's door east of the start room: cell (7, 11) (text row 3,
/// column 7), jambs north and south, its panel running north-south through
/// x = 480 (faces at 476 and 484); the open cells (6, 11) west and (8, 11)
/// east of it. Returns its sector (door `k` of the grid level is sector
/// `k + 1`).
fn bunker_door(game: &SimGame) -> usize {
    let (grid, gl) = Observe::level(game).grid().expect("bunker.ron is a grid map");
    assert!(gl.faces.doors.len() >= 7, "bunker.ron has {} doors", gl.faces.doors.len());
    let k = gl.faces.doors.iter().position(|&cell| cell == grid.index(7, 11));
    k.expect("bunker.ron: no door in cell (7, 11)") + 1
}

/// The door's sector: ceiling minus floor (0 shut).
fn door_gap(game: &SimGame, d: usize) -> f64 {
    let s = &Observe::level(game).compiled.map.sectors[d];
    s.ceiling - s.floor
}

const WEST_OF_THE_BUNKER_DOOR: DVec2 = DVec2::new(416.0, 736.0);

/// Ticks idle until no mover is at work on `d` (at most `limit` ticks);
/// returns the ticks taken.
fn settle(game: &mut SimGame, d: usize, limit: usize) -> usize {
    let mut n = 0;
    while Observe::is_busy(game, d) {
        game.tick(&IDLE);
        n += 1;
        assert!(n < limit, "the door on sector {d} still moving after {limit} ticks");
    }
    n
}

// A grid map's sliding doors are Doom doors on the simulation (how they
// are drawn is changing): these check only that one opens for the player,
// lets the player through, closes, and never closes on the player.
#[test]
fn a_grid_door_opens_when_used_lets_the_player_through_and_closes() {
    let mut game = game_on("bunker.ron");
    let d = bunker_door(&game);
    assert_eq!(door_gap(&game, d), 0.0, "the door starts open");
    // Shut: the body stops at its face.
    place(&mut game, WEST_OF_THE_BUNKER_DOOR, 0.0);
    let (x, _) = run_east(&mut game, 30);
    assert!(stopped_west_of(x, 476.0), "walked through a shut door: x {x}");
    place(&mut game, WEST_OF_THE_BUNKER_DOOR, 0.0);
    // Used from 60 units away it starts at once and opens to let a body by.
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert!(Observe::is_busy(&game, d) && door_gap(&game, d) > 0.0, "the door did not start");
    let mut ticks = 1;
    while door_gap(&game, d) < HEIGHT {
        game.tick(&IDLE);
        ticks += 1;
        assert!(ticks < 200, "never opened far enough to pass");
    }
    // Walk through into the cell east of the door.
    let (x, _) = run_east(&mut game, 20);
    assert!(x > 512.0 + RADIUS, "did not pass the open door: x {x}");
    // It closes by itself, all the way.
    settle(&mut game, d, 1000);
    assert_eq!(door_gap(&game, d), 0.0, "stopped open");
    // Shut again: no way back west.
    game.tick(&TickInput { forward: 1, run: true, turn: 180.0, ..IDLE });
    for _ in 0..30 {
        game.tick(&TickInput { forward: 1, run: true, ..IDLE });
    }
    assert!(pos(&game).x >= 484.0 + RADIUS, "walked back through the shut door");
    // From the east, the other face opens it.
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert!(Observe::is_busy(&game, d) && door_gap(&game, d) > 0.0, "the east face did not open it");
}

#[test]
fn every_grid_door_opens_and_lets_the_player_through() {
    let doors = {
        let game = game_on("bunker.ron");
        let (_, gl) = Observe::level(&game).grid().expect("bunker.ron is a grid map");
        gl.faces.doors.clone()
    };
    assert_eq!(doors.len(), 8, "bunker.ron's doors");
    for (k, &cell) in doors.iter().enumerate() {
        let mut game = game_on("bunker.ron");
        let (grid, _) = Observe::level(&game).grid().unwrap();
        let (i, j) = ((cell % grid.columns) as i64, (cell / grid.columns) as i64);
        let centre = |i: i64, j: i64| DVec2::new(grid.x(i) + grid.cell_size / 2.0, grid.y(j) + grid.cell_size / 2.0);
        // The door's passage: the two open cells on either side of it.
        let (step, angle) = [((1, 0), 0.0), ((0, 1), 90.0), ((-1, 0), 180.0), ((0, -1), 270.0)]
            .into_iter()
            .find(|&((di, dj), _)| grid.cell(i - di, j - dj).is_walkable() && grid.cell(i + di, j + dj).is_walkable())
            .unwrap_or_else(|| panic!("door {k} at ({i}, {j}) has no passage"));
        let (from, to) = (centre(i - step.0, j - step.1), centre(i + step.0, j + step.1));
        let d = k + 1;
        place(&mut game, from, angle);
        // From the cell before it, 60 from its panel: used, it opens high
        // enough to pass.
        game.tick(&TickInput { use_line: true, ..IDLE });
        for _ in 0..200 {
            if door_gap(&game, d) >= HEIGHT {
                break;
            }
            game.tick(&IDLE);
        }
        assert!(door_gap(&game, d) >= HEIGHT, "door {k} at ({i}, {j}) did not open");
        for _ in 0..60 {
            if pos(&game).distance(to) < 16.0 {
                break;
            }
            game.tick(&RUN_EAST);
        }
        assert!(pos(&game).distance(to) < 16.0, "door {k} at ({i}, {j}): stuck at {} on the way to {to}", pos(&game));
    }
}

#[test]
fn a_grid_door_never_closes_on_the_player() {
    let mut game = game_on("bunker.ron");
    let d = bunker_door(&game);
    place(&mut game, WEST_OF_THE_BUNKER_DOOR, 0.0);
    game.tick(&TickInput { use_line: true, ..IDLE });
    // Open: as high as it goes.
    let mut top = 0.0;
    while door_gap(&game, d) > top || door_gap(&game, d) < HEIGHT {
        top = door_gap(&game, d);
        game.tick(&IDLE);
        assert!(game.sim.leveltime < 200, "never opened");
    }
    // Walk into the doorway, under the door, and stop there.
    while pos(&game).x < 472.0 {
        game.tick(&TickInput { forward: 1, ..IDLE });
    }
    let console = game.sim.console;
    let mo = game.sim.players[console].as_ref().unwrap().mo;
    (game.sim.mo_mut(mo).momx, game.sim.mo_mut(mo).momy) = (Fixed(0), Fixed(0));
    for _ in 0..30 {
        game.tick(&IDLE);
    }
    let x = pos(&game).x;
    assert!(x > 476.0 - RADIUS && x < 484.0 + RADIUS, "not in the doorway: x {x}");
    let (mut lowest, mut reopened, mut last) = (f64::INFINITY, 0, door_gap(&game, d));
    for tick in 0..1000 {
        game.tick(&IDLE);
        let gap = door_gap(&game, d);
        assert!(gap >= HEIGHT, "tick {tick}: the door came down to {gap} on the player");
        lowest = lowest.min(gap);
        reopened += usize::from(gap > last);
        last = gap;
    }
    assert!(lowest < top && reopened > 0, "the door never tried to close (lowest {lowest})");
    // Once the player has gone, it closes.
    place(&mut game, DVec2::new(352.0, 736.0), 0.0);
    for _ in 0..1000 {
        game.tick(&IDLE);
        if door_gap(&game, d) == 0.0 && !Observe::is_busy(&game, d) {
            return;
        }
    }
    panic!("the door did not close once the player had gone: gap {}", door_gap(&game, d));
}

/// Every tick's pose, bit for bit.
fn trace(game: &mut SimGame, inputs: &[TickInput], frames: &mut Vec<Framebuffer>) -> Vec<[u64; 4]> {
    let mut frame = Frame::new();
    inputs
        .iter()
        .enumerate()
        .map(|(tick, input)| {
            game.tick(input);
            if tick % 400 == 0 {
                let mut fb = Framebuffer::new(160, 100);
                render_frame(Observe::level(game), &game.view(0.5), &RenderOptions::default(), &mut frame, &mut fb);
                frames.push(fb);
            }
            let p = Observe::player(game);
            [p.pos.x.to_bits(), p.pos.y.to_bits(), p.z.to_bits(), p.angle.to_bits()]
        })
        .collect()
}

#[test]
fn a_demo_replays_to_the_same_positions_and_frames() {
    let path = map_path("doors.ron");
    let inputs = random_inputs(7, 6000);
    let start = || SimGame::on_level(load(&path), "doors.ron", options()).unwrap_or_else(|e| panic!("{e}"));
    let mut live_frames = Vec::new();
    let live = trace(&mut start(), &inputs, &mut live_frames);
    let demo = Demo { inputs, ..Demo::new("maps/doors.ron") };
    let file = std::env::temp_dir().join(format!("sightline-play-{}.demo", std::process::id()));
    demo.save(&file).unwrap();
    let loaded = Demo::load(&file).unwrap();
    let _ = std::fs::remove_file(&file);
    assert_eq!(loaded, demo);
    for run in 0..2 {
        let mut frames = Vec::new();
        let replay = trace(&mut start(), &loaded.inputs, &mut frames);
        let first = live.iter().zip(&replay).position(|(a, b)| a != b);
        assert_eq!(first, None, "replay {run} diverged at that tick");
        assert_eq!(frames.len(), live_frames.len());
        for (k, (a, b)) in frames.iter().zip(&live_frames).enumerate() {
            assert!(a.pixels == b.pixels, "replay {run}: frame {k} differs");
        }
    }
    // The demo went somewhere (a replay of nothing would pass trivially).
    let moved = live.iter().map(|t| (t[0], t[1])).collect::<std::collections::BTreeSet<_>>().len();
    assert!(moved > 3000, "only {moved} distinct positions");
}
#[test]
fn corrupt_demo_files_are_errors() {
    let demo = Demo { inputs: random_inputs(3, 200), ..Demo::new("maps/doors.ron") };
    let bytes = demo.to_bytes();
    assert_eq!(Demo::from_bytes(&bytes, "ok.demo").unwrap(), demo);
    for len in 0..bytes.len() {
        let err = Demo::from_bytes(&bytes[..len], "cut.demo").unwrap_err();
        assert!(err.to_string().starts_with("cut.demo: "), "{err}");
    }
    let mut magic = bytes.clone();
    magic[0] = b'X';
    assert!(matches!(Demo::from_bytes(&magic, "m"), Err(DemoError::Magic { .. })));
    let mut version = bytes.clone();
    version[MAGIC.len()] = VERSION + 1;
    let err = Demo::from_bytes(&version, "v.demo").unwrap_err();
    assert!(matches!(err, DemoError::Version { found, .. } if found == VERSION + 1), "{err}");
    // Absurd lengths: the map name and the tick count.
    let body = MAGIC.len() + 5;
    let mut long_name = bytes.clone();
    long_name[body..body + 4].copy_from_slice(&u32::MAX.to_le_bytes());
    assert!(matches!(Demo::from_bytes(&long_name, "n"), Err(DemoError::MapTooLong { .. })));
    // The skill (a byte after the name, then the 8-byte seed) must be 1 to 5.
    let skill = body + 4 + demo.map.len();
    let mut bad_skill = bytes.clone();
    bad_skill[skill] = 9;
    // With its checksum made right, so the skill itself is what is refused.
    let crc = crc32fast::hash(&bad_skill[body..]).to_le_bytes();
    bad_skill[body - 4..body].copy_from_slice(&crc);
    let err = Demo::from_bytes(&bad_skill, "s.demo").unwrap_err();
    assert!(err.to_string().contains("skill 9"), "{err}");
    let count = skill + 9;
    let mut many = bytes.clone();
    many[count..count + 4].copy_from_slice(&u32::MAX.to_le_bytes());
    let err = Demo::from_bytes(&many, "t.demo").unwrap_err();
    assert!(matches!(err, DemoError::Truncated { .. }), "{err}");
    // A flipped bit, and trailing bytes.
    let mut flipped = bytes.clone();
    flipped[count + 10] ^= 4;
    assert!(matches!(Demo::from_bytes(&flipped, "f"), Err(DemoError::Corrupt { .. })));
    let mut trailing = bytes.clone();
    trailing.push(0);
    assert!(matches!(Demo::from_bytes(&trailing, "x"), Err(DemoError::Corrupt { .. })));
    // Noise after a good header.
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..2000 {
        let len = rng.random_range(0..200usize);
        let noise: Vec<u8> = (0..len).map(|_| rng.random::<u8>()).collect();
        let _ = Demo::from_bytes(&[MAGIC, &[VERSION], &noise].concat(), "noise");
    }
    // Through the file system, errors name the file.
    let missing = std::env::temp_dir().join("sightline-no-such.demo");
    let err = Demo::load(&missing).unwrap_err();
    assert!(matches!(err, DemoError::Read { .. }) && err.to_string().contains("sightline-no-such.demo"), "{err}");
}

/// A map may name its own animations file: its textures animate by it (a
/// modder's list, not the shipped one), and a broken one is an error naming
/// the file and what is wrong.
#[test]
fn a_map_names_its_own_animations() {
    let dir = tempfile::tempdir().unwrap();
    let anims =
        r#"Animations(flats: [], textures: [Animation(frames: ["BRICK", "STONE", "WOOD"], tics: 2)], switches: [])"#;
    std::fs::write(dir.path().join("anims.ron"), anims).unwrap();
    let text = two_rooms((0.0, 128.0), (0.0, 128.0))
        .replace("Map(name:", "Map(animations: \"anims.ron\", name:")
        .replacen("Side(sector: 0)", "Side(sector: 0, middle: \"BRICK\")", 1);
    let path = dir.path().join("m.ron");
    std::fs::write(&path, &text).unwrap();
    let level = sightline::level::open_level(&path, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let mut game = SimGame::on_level(level, "m.ron", GameOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let shown = |game: &SimGame| {
        let m = &Observe::level(game).materials;
        m.textures.name(m.side(0, 0).middle.expect("a middle texture")).to_string()
    };
    let mut seen = Vec::new();
    for _ in 0..7 {
        seen.push(shown(&game));
        game.tick(&IDLE);
    }
    // Doom's P_UpdateSpecials shows frame (leveltime / tics) of the cycle
    // and runs before the tic's leveltime++: frames change after ticks 3, 5.
    assert_eq!(seen, ["BRICK", "BRICK", "BRICK", "STONE", "STONE", "WOOD", "WOOD"]);
    std::fs::write(dir.path().join("anims.ron"), anims.replace("tics: 2", "tics: 0")).unwrap();
    let err = sightline::level::open_level(&path, &BuildOptions::default()).unwrap_err().to_string();
    assert!(
        err.contains("m.ron: the animations file:") && err.contains("anims.ron: texture animation 0: tics"),
        "{err}"
    );
}
