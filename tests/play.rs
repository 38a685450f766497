//! Play: the simulation's promises, checked headless. Seeded random play on
//! every shipped map (the player stays in the map, never passes a wall, and
//! the step and headroom rules hold at every tick); directed cases (a wall
//! from every angle at full speed, sliding, the 24/25 step, the 56/55
//! passage, a fall, doors, a grid map's sliding doors); demos that replay bit
//! for bit; corrupt demo files.

use glam::DVec2;
use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use sightline::bsp::{build, BuildOptions};
use sightline::geom::{segment_contact, Contact};
use sightline::level::Level;
use sightline::map::special::DOOR_WAIT;
use sightline::map::{parse_map, Map};
use sightline::play::demo::{DemoError, MAGIC, VERSION};
use sightline::play::player::{HEIGHT, MAX_SPEED, MAX_STEP, RADIUS};
use sightline::play::world::doors::{DoorState, Motion};
use sightline::play::{Demo, Game, TickInput, TICRATE};
use sightline::render::shade::{ids_colour, Surface};
use sightline::render::{render_frame, Frame, RenderOptions, Renderer, Shade};
use sightline::Framebuffer;
use sightline_tests::{load, map_path, random_inputs, render, shipped_maps};

fn level_from(text: &str) -> Level {
    let map = parse_map(text, "test.ron").unwrap_or_else(|e| panic!("{e}"));
    let compiled = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    Level::with_builtin_textures(compiled).unwrap_or_else(|e| panic!("{e}"))
}

fn game_from(text: &str) -> Game {
    Game::new(level_from(text)).unwrap_or_else(|e| panic!("{e}"))
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

/// What one run of random play saw.
#[derive(Debug, Default)]
struct Seen {
    path: f64,
    /// Ticks ending within a unit of the body's radius from a blocking line.
    at_walls: usize,
    climbs: usize,
    falls: usize,
    /// Sectors the centre has been in.
    sectors: std::collections::BTreeSet<usize>,
}

/// Plays `inputs` on `game`, checking every rule at every tick.
fn play_checked(name: &str, game: &mut Game, inputs: &[TickInput]) -> Seen {
    let map = game.level().map.clone();
    let ends: Vec<(DVec2, DVec2)> = map.lines.iter().map(|l| map.line_points(l)).collect();
    let heights =
        |game: &Game| -> Vec<(f64, f64)> { game.level().map.sectors.iter().map(|s| (s.floor, s.ceiling)).collect() };
    let clearance_at = |p: DVec2, h: &[(f64, f64)], z: f64| {
        (0..ends.len())
            .filter(|&i| blocks(&map, h, i, z))
            .map(|i| distance_to_segment(p, ends[i].0, ends[i].1))
            .fold(f64::INFINITY, f64::min)
    };
    let mut seen = Seen::default();
    let mut before = heights(game);
    let start = game.player().clone();
    // A start closer than the radius to a wall may stay that close; once
    // clear, the body must stay clear.
    let mut clear = clearance_at(start.pos, &before, start.z) >= RADIUS - 1e-6;
    for (tick, input) in inputs.iter().enumerate() {
        let (old, z0) = (game.player().pos, game.player().z);
        game.tick(input);
        let (p, z) = (game.player().pos, game.player().z);
        let after = if game.world().thinkers.is_empty() { before.clone() } else { heights(game) };
        let at = || format!("{name}, tick {tick}: from ({}, {}) z {z0} to ({}, {}) z {z}", old.x, old.y, p.x, p.y);
        assert!(p.is_finite() && z.is_finite(), "{}", at());
        // In the map: inside a sector, or on lines that are all two-sided.
        assert!(map.contains(p), "{}: left the map", at());
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
            assert!(clearance >= RADIUS - 1e-6, "{}: {clearance} from a blocking line", at());
        }
        clear |= clearance >= RADIUS - 1e-6;
        // Steps: at most MAX_STEP per tick, measured from the feet (the
        // floor under the centre can rise more when the body already stood
        // higher, overlapping a ledge it is now walking onto).
        assert!(z - z0 <= MAX_STEP, "{}: climbed {}", at(), z - z0);
        // Standing on or above every floor under the body, fitting under
        // every ceiling over it.
        let mut under: Vec<usize> = map.sector_strictly_containing(p).into_iter().collect();
        for (i, &(a, b)) in ends.iter().enumerate() {
            if distance_to_segment(p, a, b) < RADIUS - 1e-6 {
                let line = &map.lines[i];
                under.extend(std::iter::once(line.front.sector).chain(line.back.as_ref().map(|s| s.sector)));
            }
        }
        for s in under {
            let (floor, ceiling) = after[s];
            assert!(z >= floor, "{}: feet below the floor {floor} of sector {s}", at());
            assert!(ceiling - z >= HEIGHT, "{}: only {} of headroom in sector {s}", at(), ceiling - z);
        }
        if let Some(s) = map.sector_strictly_containing(p) {
            assert!(after[s].0 - z0 <= MAX_STEP, "{}: floor rose {} in one tick", at(), after[s].0 - z0);
        }
        seen.path += old.distance(p);
        seen.at_walls += usize::from(clearance < RADIUS + 1.0);
        seen.climbs += usize::from(z > z0);
        seen.falls += usize::from(z < z0);
        seen.sectors.insert(game.player().sector);
        before = after;
    }
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
                        let mut game = Game::new(load(path)).unwrap_or_else(|e| panic!("{e}"));
                        // Random walking is not a fight: the monsters of a
                        // level that has them must not end the walk.
                        game.player_mut().health = 1_000_000_000;
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
    // bunker.ron: through every sliding door (door k is sector k + 1), so the
    // rules above held while grid doors opened and shut around the player.
    let (_, bunker) = results.iter().find(|(name, _)| name == "bunker.ron").expect("bunker.ron is shipped");
    for sector in 1..=8 {
        assert!(bunker.sectors.contains(&sector), "bunker.ron: never through door sector {sector}: {bunker:?}");
    }
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
fn run_east(game: &mut Game, ticks: usize) -> (f64, f64) {
    for _ in 0..ticks {
        game.tick(&RUN_EAST);
    }
    (game.player().pos.x, game.player().z)
}

#[test]
fn a_step_of_24_is_climbed_and_25_is_not() {
    let (x, z) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (24.0, 128.0))), 60);
    assert!(x > 512.0 + RADIUS && z == 24.0, "did not climb 24: x {x}, z {z}");
    let (x, z) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (25.0, 128.0))), 60);
    assert!(x <= 512.0 - RADIUS + 1e-6 && x > 512.0 - RADIUS - 0.1 && z == 0.0, "climbed 25: x {x}, z {z}");
    // Down is always fine.
    let (x, z) = run_east(&mut game_from(&two_rooms((25.0, 128.0), (0.0, 128.0))), 60);
    assert!(x > 512.0 + RADIUS && z == 0.0, "did not step down 25: x {x}, z {z}");
}

#[test]
fn headroom_of_56_is_enough_and_55_is_not() {
    let (x, _) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (0.0, 56.0))), 60);
    assert!(x > 512.0 + RADIUS, "could not enter a 56-unit passage: x {x}");
    let (x, _) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (0.0, 55.0))), 60);
    assert!(x <= 512.0 - RADIUS + 1e-6, "entered a 55-unit passage: x {x}");
    // A step of 8 under a ceiling 62 above the lower floor leaves 54: no.
    let (x, _) = run_east(&mut game_from(&two_rooms((0.0, 128.0), (8.0, 62.0))), 60);
    assert!(x <= 512.0 - RADIUS + 1e-6, "squeezed under 54 units: x {x}");
}

#[test]
fn walking_off_a_ledge_falls_to_the_lower_floor() {
    let mut game = game_from(&two_rooms((128.0, 256.0), (0.0, 256.0)));
    let mut heights = Vec::new();
    for _ in 0..60 {
        game.tick(&RUN_EAST);
        heights.push(game.player().z);
    }
    let airborne = heights.iter().filter(|&&z| z > 0.0 && z < 128.0).count();
    // 128 units at Doom's gravity take 15 ticks; not a teleport, not a float.
    assert!((10..=20).contains(&airborne), "{airborne} ticks in the air: {heights:?}");
    assert!(heights.windows(2).all(|w| w[1] <= w[0]), "rose while falling: {heights:?}");
    let p = game.player();
    assert_eq!((p.z, p.vz, p.sector), (0.0, 0.0, 1), "did not land on the lower floor");
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
    let map = game.level().map.clone();
    let blade_x = 512.5;
    // Whole degrees and awkward fractions; aimed at the blade from both
    // sides, at its middle and near its ends, at the speed limit.
    let angles = (0..360).map(f64::from).chain((0..97).map(|k| k as f64 * 3.7137 + 0.001));
    for angle in angles {
        for target_y in [512.0, 130.0, 895.0] {
            let dir = DVec2::new(angle.to_radians().cos(), angle.to_radians().sin());
            let start = DVec2::new(blade_x, target_y) - dir * 120.0;
            let clear = map.lines.iter().all(|l| {
                let (a, b) = map.line_points(l);
                distance_to_segment(start, a, b) > RADIUS + 1.0
            });
            if !clear || map.sector_strictly_containing(start).is_none() {
                continue;
            }
            game.teleport(start, angle).unwrap();
            let mut touched = false;
            for tick in 0..40 {
                game.player_mut().velocity = dir * 1000.0;
                let old = game.player().pos;
                game.tick(&RUN_EAST);
                let p = game.player().pos;
                assert!(game.player().velocity.length() <= MAX_SPEED);
                let at = format!("angle {angle}, target y {target_y}, tick {tick}: ({}, {})", p.x, p.y);
                for l in &map.lines {
                    let (a, b) = map.line_points(l);
                    assert_eq!(segment_contact(old, p, a, b), Contact::None, "{at}: crossed a wall");
                    let d = distance_to_segment(p, a, b);
                    assert!(d >= RADIUS - 1e-6, "{at}: inside a wall");
                    touched |= d < RADIUS + 0.01;
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
    // Run north-east into the north wall at 30 degrees off it.
    game.teleport(DVec2::new(600.0, 900.0), 30.0).unwrap();
    let mut xs = Vec::new();
    for _ in 0..40 {
        game.tick(&RUN_EAST);
        xs.push(game.player().pos.x);
        let y = game.player().pos.y;
        assert!(y <= 1024.0 - RADIUS + 1e-6, "into the north wall: y {y}");
    }
    assert!((game.player().pos.y - (1024.0 - RADIUS)).abs() < 0.01, "not against the wall: {:?}", game.player().pos);
    // Against the wall the run keeps its along-wall part: 16.7 * cos 30 = 14.4 a tick.
    let per_tick = (xs[35] - xs[25]) / 10.0;
    assert!(per_tick > 12.0, "slid only {per_tick} units a tick");
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

fn door_ceiling(game: &Game) -> f64 {
    game.level().map.sectors[1].ceiling
}

/// What the door on `sector` is doing; `None` when no door is at work there
/// (it is shut, or open for good).
fn door(game: &Game, sector: usize) -> Option<DoorState> {
    game.world().door_on(sector).map(|d| d.state)
}

#[test]
fn a_door_opens_when_used_lets_the_player_through_and_closes_after_a_wait() {
    let mut game = game_from(DOOR_MAP);
    assert_eq!(door(&game, 1), None);
    // Shut: the body stops at it.
    let (x, _) = run_east(&mut game, 40);
    assert!(x <= 256.0 - RADIUS + 1e-6, "walked through a shut door: x {x}");
    assert_eq!(door_ceiling(&game), 0.0);
    // Use it from here (the door is 16 ahead, within reach).
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 1), Some(DoorState::Opening));
    // It rises at 2 a tick to the lowest neighbouring ceiling less 4 (128 - 4).
    let mut ticks = 1;
    while door(&game, 1) == Some(DoorState::Opening) {
        game.tick(&IDLE);
        ticks += 1;
        assert!(ticks < 100, "never finished opening");
    }
    assert_eq!((door_ceiling(&game), ticks), (124.0, 62));
    let (x, _) = run_east(&mut game, 30);
    assert!(x > 272.0 + RADIUS && game.player().sector == 2, "did not pass the open door: x {x}");
    // Open for 150 ticks after it finished opening, then down at 2 a tick.
    for _ in 30..150 {
        game.tick(&IDLE);
    }
    assert_eq!(door_ceiling(&game), 124.0, "closed early");
    for _ in 0..62 + 5 {
        game.tick(&IDLE);
    }
    assert_eq!((door_ceiling(&game), door(&game, 1)), (0.0, None));
    // Shut again: no way back west.
    game.teleport(DVec2::new(400.0, 128.0), 180.0).unwrap();
    for _ in 0..40 {
        game.tick(&TickInput { forward: 1, run: true, ..IDLE });
    }
    assert!(game.player().pos.x >= 272.0 + RADIUS - 1e-6, "walked back through the shut door");
    // From the far side, the other door line opens it too.
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 1), Some(DoorState::Opening));
    // Used again while it opens, it closes at once (Doom's manual doors);
    // used while it closes, it opens again.
    game.tick(&IDLE);
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 1), Some(DoorState::Closing));
    game.tick(&IDLE);
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 1), Some(DoorState::Opening));
    // Holding use does not use it again.
    for _ in 0..10 {
        game.tick(&TickInput { use_line: true, ..IDLE });
    }
    assert_eq!(door(&game, 1), Some(DoorState::Opening));
}

#[test]
fn a_door_never_closes_on_the_player() {
    let mut game = game_from(DOOR_MAP);
    game.teleport(DVec2::new(230.0, 128.0), 0.0).unwrap();
    game.tick(&TickInput { use_line: true, ..IDLE });
    for _ in 0..70 {
        game.tick(&IDLE);
    }
    // Step into the doorway and stand there.
    for _ in 0..3 {
        game.tick(&TickInput { forward: 1, ..IDLE });
    }
    for _ in 0..60 {
        game.tick(&IDLE);
    }
    let x = game.player().pos.x;
    assert!(x > 256.0 - RADIUS && x < 272.0 + RADIUS, "not in the doorway: x {x}");
    let mut lowest = f64::INFINITY;
    let mut reopened = 0;
    let mut last = door_ceiling(&game);
    for tick in 0..1000 {
        game.tick(&IDLE);
        let c = door_ceiling(&game);
        assert!(c - game.player().z >= HEIGHT, "tick {tick}: the door came down to {c} on the player");
        lowest = lowest.min(c);
        reopened += usize::from(c > last && last < 124.0);
        last = c;
    }
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

fn tagged(trigger: &str, switch: &str) -> Game {
    game_from(&TAGGED_MAP.replace(" TRIGGER", trigger).replace(" SWITCH", switch))
}

const RUN_WEST: TickInput = TickInput { forward: -1, ..RUN_EAST };

/// Ticks `input` until `done(x)` holds for the player's x (at most 200 ticks).
fn run_until(game: &mut Game, input: &TickInput, done: impl Fn(f64) -> bool) {
    for _ in 0..200 {
        if done(game.player().pos.x) {
            return;
        }
        game.tick(input);
    }
    panic!("never got there: x {}", game.player().pos.x);
}

#[test]
fn walking_over_a_trigger_opens_the_tagged_door_once() {
    let mut game = tagged(", trigger: Trigger(tag: 5, on: Walk, once: true)", "");
    assert_eq!(door(&game, 2), None);
    // Crossing x = 128 sets it off; the door opens, waits and closes.
    run_east(&mut game, 12);
    assert!(game.player().pos.x > 128.0);
    assert_eq!(door(&game, 2), Some(DoorState::Opening));
    for _ in 0..300 {
        game.tick(&IDLE);
    }
    assert_eq!((door(&game, 2), game.level().map.sectors[2].ceiling), (None, 0.0));
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
    assert_eq!((door(&game, 2), game.level().map.sectors[2].ceiling), (None, 124.0));
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
    game.teleport(DVec2::new(32.0, 128.0), 180.0).unwrap();
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, 2), Some(DoorState::Opening));
    // A walk trigger is not a switch.
    let mut game = tagged(", trigger: Trigger(tag: 5, on: Walk)", "");
    game.teleport(DVec2::new(100.0, 128.0), 0.0).unwrap();
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
    assert!((b.angle - 100.0).abs() < 1e-9 && (a.angle - 90.0).abs() < 1e-9 && (mid.angle - 95.0).abs() < 1e-9);
    assert_eq!(b.pos, game.player().pos);
    assert_eq!(TICRATE, 35);
}

/// bunker.ron's door east of the start room: cell (7, 11) (text row 3,
/// column 7), jambs north and south, its panel running north-south through
/// x = 480 (faces at 476 and 484); the open cells (6, 11) west and (8, 11)
/// east of it. Returns its sector and its place in `GridLevel::open` (door
/// `k` is sector `k + 1`).
fn bunker_door(game: &Game) -> (usize, usize) {
    let (grid, gl) = game.level().grid().expect("bunker.ron is a grid map");
    let k = gl.faces.doors.iter().position(|&cell| cell == grid.index(7, 11));
    let k = k.expect("bunker.ron: no sliding door in cell (7, 11)");
    (k + 1, k)
}

fn slid(game: &Game, k: usize) -> f64 {
    game.level().grid.as_ref().expect("a grid level").open[k]
}

/// The door's sector: ceiling minus floor (0 shut, the grid's 64 passable).
fn door_gap(game: &Game, d: usize) -> f64 {
    let s = &game.level().map.sectors[d];
    s.ceiling - s.floor
}

/// Columns of an `ids` frame showing `colour` anywhere.
fn columns_showing(fb: &Framebuffer, colour: u32) -> Vec<usize> {
    (0..fb.width).filter(|&x| (0..fb.height).any(|y| fb.get(x, y) == colour)).collect()
}

const WEST_OF_THE_BUNKER_DOOR: DVec2 = DVec2::new(416.0, 736.0);

#[test]
fn a_grid_door_slides_open_when_used_and_the_ray_caster_draws_it_sliding() {
    let mut game = Game::new(load(&map_path("bunker.ron"))).unwrap_or_else(|e| panic!("{e}"));
    let (grid, gl) = game.level().grid().expect("bunker.ron is a grid map");
    assert!(gl.faces.doors.len() >= 7, "bunker.ron has {} doors", gl.faces.doors.len());
    let grid_ceiling = grid.ceiling;
    let (d, k) = bunker_door(&game);
    let panel = gl.faces.line(gl.faces.doors[k], sightline::grid::Face::West) as usize;
    let panel_colour = ids_colour(Surface::Wall { line: panel });
    // Shut: the body stops at its face.
    game.teleport(WEST_OF_THE_BUNKER_DOOR, 0.0).unwrap();
    let (x, _) = run_east(&mut game, 30);
    assert!(x <= 476.0 - RADIUS + 1e-6, "walked through a shut door: x {x}");
    game.teleport(WEST_OF_THE_BUNKER_DOOR, 0.0).unwrap();
    let view = game.view(1.0);
    let frame = |game: &Game, renderer| render(game.level(), &view, (160, 100), renderer, Shade::Ids);
    let (shut, shut_bsp) = (frame(&game, Renderer::Raycast), frame(&game, Renderer::Bsp));
    let door_columns = columns_showing(&shut, panel_colour);
    assert!(door_columns.len() > 60, "the panel fills only columns {door_columns:?}");

    // Used from 60 units away, it slides 1/32 of its width a tick, from the
    // use tick on.
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!((door(&game, d), slid(&game, k)), (Some(DoorState::Opening), 1.0 / 32.0));
    // A grid door is a sliding door: door k is sector k + 1, and it opens to the grid's ceiling.
    let motion = game.world().door_on(d).map(|door| door.motion);
    assert!(matches!(motion, Some(Motion::Slide { slide, .. }) if slide.index == k && slide.ceiling == grid_ceiling));
    for _ in 1..16 {
        game.tick(&IDLE);
    }
    assert_eq!(slid(&game, k), 0.5);
    assert_eq!(door_gap(&game, d), 0.0, "passable while half open");
    // Half open: the ray-caster sees through part of the doorway, and only there.
    let half = frame(&game, Renderer::Raycast);
    let changed: Vec<usize> =
        (0..half.width).filter(|&x| (0..half.height).any(|y| half.get(x, y) != shut.get(x, y))).collect();
    assert!(changed.len() > 20, "half open, only columns {changed:?} changed");
    assert!(changed.iter().all(|x| door_columns.contains(x)), "columns {changed:?} changed, door {door_columns:?}");
    let still = columns_showing(&half, panel_colour);
    assert!(!still.is_empty() && still.len() < door_columns.len(), "half the panel: columns {still:?}");

    // Fully open after 32 ticks (0.91 s): passable, and no panel drawn.
    let mut ticks = 16;
    while door(&game, d) == Some(DoorState::Opening) {
        game.tick(&IDLE);
        ticks += 1;
        assert!(ticks < 100, "never finished opening");
    }
    assert_eq!((slid(&game, k), ticks, door_gap(&game, d)), (1.0, 32, 64.0));
    assert!(columns_showing(&frame(&game, Renderer::Raycast), panel_colour).is_empty());
    // The BSP renderer draws it as a raised Doom door: open, so it sees past it too.
    assert!(frame(&game, Renderer::Bsp).pixels != shut_bsp.pixels, "the BSP frame still shows the door shut");

    // Walk through into the cell east of the door.
    let (x, _) = run_east(&mut game, 20);
    assert!(x > 512.0 + RADIUS, "did not pass the open door: x {x}");
    ticks += 20;
    // It waits DOOR_WAIT ticks from when it finished opening, then slides shut
    // in 32 more, shutting its sector as it starts.
    while ticks < 32 + DOOR_WAIT as usize {
        game.tick(&IDLE);
        ticks += 1;
        assert_eq!((slid(&game, k), door_gap(&game, d)), (1.0, 64.0), "tick {ticks}: closed early");
    }
    assert_eq!(door(&game, d), Some(DoorState::Closing));
    game.tick(&IDLE);
    assert_eq!((slid(&game, k), door_gap(&game, d)), (31.0 / 32.0, 0.0));
    for _ in 1..32 {
        game.tick(&IDLE);
    }
    assert_eq!((door(&game, d), slid(&game, k)), (None, 0.0));
    assert!(frame(&game, Renderer::Raycast).pixels == shut.pixels, "shut again, but drawn differently");
    // Shut again: no way back west.
    game.tick(&TickInput { forward: 1, run: true, turn: 180.0, ..IDLE });
    for _ in 0..30 {
        game.tick(&TickInput { forward: 1, run: true, ..IDLE });
    }
    assert!(game.player().pos.x >= 484.0 + RADIUS - 1e-6, "walked back through the shut door");
    // From the east, the other face opens it.
    game.tick(&TickInput { use_line: true, ..IDLE });
    assert_eq!(door(&game, d), Some(DoorState::Opening));
}

#[test]
fn a_grid_door_never_closes_on_the_player() {
    let mut game = Game::new(load(&map_path("bunker.ron"))).unwrap_or_else(|e| panic!("{e}"));
    let (d, k) = bunker_door(&game);
    game.teleport(WEST_OF_THE_BUNKER_DOOR, 0.0).unwrap();
    game.tick(&TickInput { use_line: true, ..IDLE });
    for _ in 0..40 {
        game.tick(&IDLE);
    }
    // Walk into the doorway, onto the slab, and stop there.
    while game.player().pos.x < 472.0 {
        game.tick(&TickInput { forward: 1, ..IDLE });
    }
    game.player_mut().velocity = DVec2::ZERO;
    for _ in 0..30 {
        game.tick(&IDLE);
    }
    let x = game.player().pos.x;
    assert!(x > 476.0 - RADIUS && x < 484.0 + RADIUS, "not in the doorway: x {x}");
    let mut tried = 0;
    for tick in 0..1000 {
        game.tick(&IDLE);
        assert_eq!((slid(&game, k), door_gap(&game, d)), (1.0, 64.0), "tick {tick}: the door moved on the player");
        tried += usize::from(door(&game, d) == Some(DoorState::Closing));
    }
    assert!(tried >= 5, "the door tried to close only {tried} times in 1000 ticks");

    // Back out of the cell (its west edge is x = 448) and let it start closing...
    game.teleport(DVec2::new(428.0, 736.0), 0.0).unwrap();
    while slid(&game, k) == 1.0 {
        game.tick(&IDLE);
    }
    assert_eq!(door_gap(&game, d), 0.0, "still passable while closing");
    // ...then step into the cell: it reopens, never shuts.
    let mut least = slid(&game, k);
    for _ in 0..3 {
        game.tick(&TickInput { forward: 1, run: true, ..IDLE });
        least = least.min(slid(&game, k));
    }
    assert!(game.player().pos.x > 448.0 - RADIUS, "did not reach the cell: {:?}", game.player().pos);
    for _ in 0..100 {
        game.tick(&IDLE);
        least = least.min(slid(&game, k));
    }
    assert!(least > 0.8, "the panel came down to {least} with the player in its cell");
    assert_eq!((slid(&game, k), door_gap(&game, d)), (1.0, 64.0), "did not reopen");
    // Once the player has gone, it closes.
    game.teleport(DVec2::new(352.0, 736.0), 0.0).unwrap();
    for _ in 0..DOOR_WAIT + 40 {
        game.tick(&IDLE);
    }
    assert_eq!((door(&game, d), slid(&game, k), door_gap(&game, d)), (None, 0.0, 0.0));
}

/// Every tick's pose, bit for bit.
fn trace(game: &mut Game, inputs: &[TickInput], frames: &mut Vec<Framebuffer>) -> Vec<[u64; 4]> {
    let mut frame = Frame::new();
    inputs
        .iter()
        .enumerate()
        .map(|(tick, input)| {
            game.tick(input);
            if tick % 400 == 0 {
                let mut fb = Framebuffer::new(160, 100);
                render_frame(game.level(), &game.view(0.5), &RenderOptions::default(), &mut frame, &mut fb);
                frames.push(fb);
            }
            let p = game.player();
            [p.pos.x.to_bits(), p.pos.y.to_bits(), p.z.to_bits(), p.angle.to_bits()]
        })
        .collect()
}

#[test]
fn a_demo_replays_to_the_same_positions_and_frames() {
    let path = map_path("doors.ron");
    let inputs = random_inputs(7, 6000);
    let mut live_frames = Vec::new();
    let live = trace(&mut Game::new(load(&path)).unwrap(), &inputs, &mut live_frames);
    let demo = Demo { inputs, ..Demo::new("maps/doors.ron") };
    let file = std::env::temp_dir().join(format!("sightline-play-{}.demo", std::process::id()));
    demo.save(&file).unwrap();
    let loaded = Demo::load(&file).unwrap();
    let _ = std::fs::remove_file(&file);
    assert_eq!(loaded, demo);
    for run in 0..2 {
        let mut frames = Vec::new();
        let replay = trace(&mut Game::new(load(&path)).unwrap(), &loaded.inputs, &mut frames);
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
    let shown = |game: &Game| {
        let m = &game.level().materials;
        m.textures.name(m.side(0, 0).middle.expect("a middle texture")).to_string()
    };
    let mut game = Game::new(level).unwrap();
    let mut seen = Vec::new();
    for _ in 0..7 {
        seen.push(shown(&game));
        game.tick(&IDLE);
    }
    // Tick t shows frame (t / tics) of the cycle, t counted before the tick
    // (Doom's leveltime): frames change on ticks 2, 4, ...
    assert_eq!(seen, ["BRICK", "BRICK", "BRICK", "STONE", "STONE", "WOOD", "WOOD"]);
    std::fs::write(dir.path().join("anims.ron"), anims.replace("tics: 2", "tics: 0")).unwrap();
    let err = sightline::level::open_level(&path, &BuildOptions::default()).unwrap_err().to_string();
    assert!(
        err.contains("m.ron: the animations file:") && err.contains("anims.ron: texture animation 0: tics"),
        "{err}"
    );
}
