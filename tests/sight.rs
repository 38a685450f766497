//! Sight and shots (`play::sight`): the fast paths through the BSP give
//! exactly the brute-force oracles' answers (the same bool, the same hit to
//! the bit, the same aim) on random maps and random poses, with moved floors
//! and ceilings and both splitters' trees; the tie rules hold on a
//! hand-built map at the origin and at ±30,000; and on Freedoom's E1M1 and
//! MAP01, 10,000 random pairs of points each, before and after every door
//! and lift is opened, agree too.
//!
//! Pairs are not only random: they are chosen to pass exactly through
//! vertices, to run along lines, to start and end exactly on lines and to
//! coincide, and each run counts how often that happened and what the
//! answers were, so a run that never met a tie fails rather than passes.

// Shared with properties.rs, which uses all of it.
#[allow(dead_code)]
#[path = "random_maps.rs"]
mod random_maps;

use glam::DVec2;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use random_maps::{compile, describe, generate, map_spec};
use sightline::bsp::{build, BuildOptions, CompiledMap, LineSide, SplitterKind};
use sightline::geom::{exact_side, Side};
use sightline::map::source::{MapSource, SectorSource, ThingSource};
use sightline::map::validate::validate;
use sightline::map::PLAYER_START;
use sightline::play::sight::{
    aim_slope, aim_slope_brute, hitscan, hitscan_brute, meet, sight, sight_brute, Body, Hit, Meet, Part, Ray, Scratch,
    Struck, AIM_SLOPE, MELEE_RANGE,
};
use sightline::play::SHOT_RANGE;
use sightline_tests::freedoom_wads;

/// What a run of pairs met and answered.
#[derive(Debug, Default)]
struct Tally {
    pairs: usize,
    seen: usize,
    hidden: usize,
    /// Contacts exactly at a line's end (the segment through a vertex, or
    /// starting or ending on one), and contacts along a line.
    through_vertex: usize,
    along_line: usize,
    walls: usize,
    parts: usize,
    sky: usize,
    bodies: usize,
    misses: usize,
    aimed: usize,
}

impl Tally {
    fn add(&mut self, other: &Tally) {
        let Tally { pairs, seen, hidden, through_vertex, along_line, walls, parts, sky, bodies, misses, aimed } = other;
        self.pairs += pairs;
        self.seen += seen;
        self.hidden += hidden;
        self.through_vertex += through_vertex;
        self.along_line += along_line;
        self.walls += walls;
        self.parts += parts;
        self.sky += sky;
        self.bodies += bodies;
        self.misses += misses;
        self.aimed += aimed;
    }

    fn count_hit(&mut self, hit: &Option<Hit>) {
        match hit.map(|h| h.struck) {
            None => self.misses += 1,
            Some(Struck::Wall { part: Part::Middle, .. }) => self.walls += 1,
            Some(Struck::Wall { .. }) => self.parts += 1,
            Some(Struck::Sky { .. }) => self.sky += 1,
            Some(Struck::Body { .. }) => self.bodies += 1,
        }
    }
}

/// A random point of `map`: anywhere in (or a little beyond) its bounds, in
/// it, exactly on a vertex, exactly on a line, or a hair from a vertex.
fn point(level: &CompiledMap, r: &mut ChaCha8Rng) -> DVec2 {
    let map = &level.map;
    let (lo, hi) =
        map.vertices.iter().fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let pad = (hi - lo) * 0.05;
    let uniform = |r: &mut ChaCha8Rng| {
        DVec2::new(r.random_range(lo.x - pad.x..=hi.x + pad.x), r.random_range(lo.y - pad.y..=hi.y + pad.y))
    };
    match r.random_range(0..10) {
        0..=1 => uniform(r),
        2..=5 => (0..50).map(|_| uniform(r)).find(|&p| map.contains(p)).unwrap_or_else(|| uniform(r)),
        6 => map.vertices[r.random_range(0..map.vertices.len())],
        7 | 8 => {
            let line = &map.lines[r.random_range(0..map.lines.len())];
            let (a, b) = map.line_points(line);
            a + (b - a) * [0.25, 0.5, 0.75, 1.0 / 3.0][r.random_range(0..4)]
        }
        _ => {
            let v = map.vertices[r.random_range(0..map.vertices.len())];
            v + DVec2::new(r.random_range(-1.0..=1.0), r.random_range(-1.0..=1.0))
                * 1e-6
                * v.abs().max_element().max(1.0)
        }
    }
}

/// Two points: independent, through a vertex exactly (where the arithmetic
/// allows), along a line's extension, starting on a line, or the same.
fn pair(level: &CompiledMap, r: &mut ChaCha8Rng) -> (DVec2, DVec2) {
    let map = &level.map;
    match r.random_range(0..10) {
        0..=4 => (point(level, r), point(level, r)),
        5 | 6 => {
            let p = point(level, r);
            let v = map.vertices[r.random_range(0..map.vertices.len())];
            (p, v + (v - p) * [1.0, 0.5, 2.0, 0.25][r.random_range(0..4)])
        }
        7 => {
            let line = &map.lines[r.random_range(0..map.lines.len())];
            let (a, b) = map.line_points(line);
            let mut t = || [-1.5, -0.5, 0.0, 0.25, 0.5, 1.0, 1.25, 2.0][r.random_range(0..8)];
            (a + (b - a) * t(), a + (b - a) * t())
        }
        8 => {
            let p = point(level, r);
            (p, p)
        }
        9 if r.random_bool(0.5) => {
            // Ending exactly where the compiler cut a line (a seg's end off
            // the map's vertices, within rounding of a partition): where the
            // descent needs its margin.
            let seg = &level.bsp.segs[r.random_range(0..level.bsp.segs.len())];
            (point(level, r), if r.random_bool(0.5) { seg.v1 } else { seg.v2 })
        }
        _ => {
            let line = &map.lines[r.random_range(0..map.lines.len())];
            let (a, b) = map.line_points(line);
            (a + (b - a) * 0.5, point(level, r))
        }
    }
}

/// A body at `p`: feet on the floor of the sector there (or off it), of a
/// random size.
fn body(level: &CompiledMap, r: &mut ChaCha8Rng, p: DVec2, index: usize) -> Body {
    let floor = level.map.sectors[level.sector_at(p)].floor;
    let z = if r.random_bool(0.7) { floor } else { floor + r.random_range(-64.0..=64.0) };
    let height = [56.0, 16.0, 0.0, 120.0][r.random_range(0..4)];
    let radius = [16.0, 20.0, 0.0, 1.0][r.random_range(0..4)];
    Body { pos: p, z, height, radius, index }
}

/// Moves floors and ceilings at random (doors shut and open, lifts up and
/// down, sky ceilings included): heights are read live, not from the compile.
fn move_heights(level: &mut CompiledMap, r: &mut ChaCha8Rng) {
    for s in &mut level.map.sectors {
        match r.random_range(0..6) {
            0 => s.ceiling = s.floor,
            1 => s.floor += r.random_range(-64.0..=64.0),
            2 => s.ceiling += r.random_range(-64.0..=64.0),
            3 => s.ceiling_texture = Some("SKY".into()),
            _ => {}
        }
    }
}

/// `n` random pairs on `level`: sight both ways, a shot and an aim from the
/// first towards the second, each by both paths, which must agree exactly.
fn check_pairs(level: &CompiledMap, seed: u64, n: usize, what: &str) -> Tally {
    let map = &level.map;
    let mut r = ChaCha8Rng::seed_from_u64(seed);
    let mut scratch = Scratch::default();
    let mut tally = Tally::default();
    for k in 0..n {
        let (p, q) = pair(level, &mut r);
        let (a, b) = (body(level, &mut r, p, 0), body(level, &mut r, q, 1));
        let at = || format!("{what}, pair {k}: ({:?}, {:?}) -> ({:?}, {:?}), bodies {a:?} {b:?}", p.x, p.y, q.x, q.y);
        tally.pairs += 1;
        for c in map.lines.iter().filter_map(|l| {
            let (la, lb) = map.line_points(l);
            meet(p, q, la, lb).map(|m| (m, la, lb))
        }) {
            match c {
                (Meet::Along(..), ..) => tally.along_line += 1,
                (Meet::Point(_), la, lb) if p != q && [la, lb].iter().any(|&v| exact_side(p, q, v) == Side::On) => {
                    tally.through_vertex += 1
                }
                _ => {}
            }
        }
        for (looker, target) in [(&a, &b), (&b, &a)] {
            let fast = sight(level, &mut scratch, looker, target);
            assert_eq!(fast, sight_brute(map, looker, target), "sight: {}", at());
            if fast {
                tally.seen += 1;
            } else {
                tally.hidden += 1;
            }
        }
        let d = q - p;
        let angle = match r.random_range(0..4) {
            0 => [0.0, 90.0, 180.0, 270.0][r.random_range(0..4)],
            1 => r.random_range(0.0..360.0),
            _ => d.y.atan2(d.x).to_degrees(),
        };
        let range = [SHOT_RANGE, MELEE_RANGE, d.length()][r.random_range(0..3)];
        let z = if r.random_bool(0.7) { a.z + 40.0 } else { r.random_range(-100.0..=300.0) };
        let ray = Ray { origin: p, z, angle, range, shooter: Some(0) };
        let mut bodies = vec![a, b];
        for index in 2..r.random_range(2..6) {
            let p = point(level, &mut r);
            bodies.push(body(level, &mut r, p, index));
        }
        let aimed = aim_slope(level, &mut scratch, &ray, &bodies);
        assert_eq!(aimed, aim_slope_brute(map, &ray, &bodies), "aim {ray:?}: {}", at());
        tally.aimed += usize::from(aimed.is_some());
        let slope = match (r.random_range(0..3), aimed) {
            (0, Some(aimed)) => aimed.slope,
            (0 | 1, _) => 0.0,
            _ => r.random_range(-1.0..=1.0),
        };
        let hit = hitscan(level, &mut scratch, &ray, slope, &bodies);
        assert_eq!(hit, hitscan_brute(map, &ray, slope, &bodies), "shot {ray:?} slope {slope:?}: {}", at());
        tally.count_hit(&hit);
    }
    tally
}

fn config(cases: u32) -> Config {
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|n| n.parse().ok()).unwrap_or(cases);
    Config { cases, failure_persistence: None, max_shrink_iters: 1024, ..Config::default() }
}

proptest! {
    #![proptest_config(config(256))]

    /// Random maps compiled by both splitters, heights moved or not: the fast
    /// paths agree with the oracles on 40 pairs each.
    #[test]
    fn fast_agrees_with_brute_on_random_maps(spec in map_spec(), split_seed in any::<u64>(), seed in any::<u64>()) {
        let g = generate(&spec);
        for (splitter, s) in [(SplitterKind::Random, split_seed), (SplitterKind::Cost, 0)] {
            let mut level = compile(&spec, &g, splitter, s).compiled;
            if seed % 2 == 1 {
                move_heights(&mut level, &mut ChaCha8Rng::seed_from_u64(seed));
            }
            let what = format!("{} splitter seed {s}", splitter.name());
            let result = std::panic::catch_unwind(|| check_pairs(&level, seed, 40, &what));
            if let Err(e) = result {
                let message = e.downcast_ref::<String>().cloned().unwrap_or_default();
                prop_assert!(false, "{message}\n{}", describe(&spec, &g));
            }
        }
    }
}

/// The pairs the tests above draw do reach the ties and every kind of
/// answer: over 100 random maps, counted.
#[test]
fn random_pairs_reach_ties_and_every_answer() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let mut total = Tally::default();
    for k in 0..100u64 {
        let spec = map_spec().new_tree(&mut runner).unwrap().current();
        let g = generate(&spec);
        let mut level = compile(&spec, &g, SplitterKind::Cost, 0).compiled;
        move_heights(&mut level, &mut ChaCha8Rng::seed_from_u64(k));
        total.add(&check_pairs(&level, k, 40, &format!("map {k}")));
    }
    eprintln!("100 random maps: {total:?}");
    let t = &total;
    assert!(t.seen > t.pairs / 5 && t.hidden > t.pairs / 5, "{t:?}");
    assert!(t.through_vertex > 100 && t.along_line > 100, "{t:?}");
    assert!(t.walls > 100 && t.parts > 20 && t.sky > 20 && t.bodies > 20 && t.misses > 20 && t.aimed > 100, "{t:?}");
}

/// The engine's tie map moved by `o`: a 1024x512 sky-ceilinged room
/// (floor 0, ceiling 256) with a solid pillar at [256, 320]x[192, 256]
/// (lines 4-7), a platform (floor 24) at [640, 704]x[192, 256] (lines
/// 8-11) and a low alcove (ceiling 128, sky) at [832, 896]x[320, 384]
/// (lines 12-15).
fn tie_map(o: DVec2) -> CompiledMap {
    let at = |x: f64, y: f64| (x + o.x, y + o.y);
    let square = |x0, y0, x1, y1| [at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y1)];
    let sector = |floor: f64, ceiling: f64| SectorSource {
        floor,
        ceiling,
        light: 160,
        ceiling_texture: Some("SKY".into()),
        ..SectorSource::default()
    };
    let start = at(64.0, 64.0);
    let mut source = MapSource {
        name: "ties".into(),
        sectors: vec![sector(0.0, 256.0), sector(24.0, 256.0), sector(0.0, 128.0)],
        things: vec![ThingSource::new(PLAYER_START, start.0, start.1, 0.0)],
        ..MapSource::default()
    };
    source.add_ring(&[at(0.0, 0.0), at(0.0, 512.0), at(1024.0, 512.0), at(1024.0, 0.0)], 0, None);
    source.add_ring(&square(256.0, 192.0, 320.0, 256.0), 0, None);
    source.add_ring(&square(640.0, 192.0, 704.0, 256.0), 0, Some(1));
    source.add_ring(&square(832.0, 320.0, 896.0, 384.0), 0, Some(2));
    let map = validate(&source).unwrap_or_else(|p| panic!("{p:?}"));
    build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

/// The tie rules, at the origin and with the map's corners at ±30,000:
/// the same answers everywhere, by both paths.
#[test]
fn tie_rules_hold_at_the_origin_and_at_30000() {
    let offsets = [DVec2::ZERO, DVec2::new(30_000.0 - 1024.0, 30_000.0 - 512.0), DVec2::splat(-30_000.0)];
    for o in offsets {
        let level = tie_map(o);
        let mut scratch = Scratch::default();
        let b =
            |x: f64, y: f64, z: f64, height: f64| Body { pos: DVec2::new(x, y) + o, z, height, radius: 16.0, index: 1 };
        let mut sees = |level: &CompiledMap, a: Body, t: Body| {
            let fast = sight(level, &mut scratch, &a, &t);
            assert_eq!(fast, sight_brute(&level.map, &a, &t), "offset {o}: {a:?} -> {t:?}");
            fast
        };
        let cases = [
            // (what, looker, target, seen)
            ("through the pillar", b(64.0, 224.0, 0.0, 56.0), b(448.0, 224.0, 0.0, 56.0), false),
            ("over the platform", b(576.0, 224.0, 0.0, 56.0), b(768.0, 224.0, 0.0, 56.0), true),
            ("exactly through the pillar's corner", b(192.0, 256.0, 0.0, 56.0), b(320.0, 128.0, 0.0, 56.0), false),
            ("a unit beside the corner", b(192.0, 255.0, 0.0, 56.0), b(320.0, 127.0, 0.0, 56.0), true),
            ("exactly through the platform's corner", b(576.0, 256.0, 0.0, 56.0), b(704.0, 128.0, 0.0, 56.0), true),
            ("along the pillar's face", b(128.0, 192.0, 0.0, 56.0), b(448.0, 192.0, 0.0, 56.0), false),
            ("along the platform's edge", b(576.0, 192.0, 0.0, 56.0), b(768.0, 192.0, 0.0, 56.0), true),
            ("from the platform's edge", b(672.0, 192.0, 0.0, 56.0), b(672.0, 64.0, 0.0, 56.0), true),
            ("from the edge, eye under the lip", b(672.0, 192.0, -40.0, 56.0), b(672.0, 64.0, 0.0, 56.0), false),
            ("to the pillar's face", b(64.0, 224.0, 0.0, 56.0), b(256.0, 224.0, 0.0, 56.0), false),
            ("to the platform's edge", b(576.0, 224.0, 0.0, 56.0), b(640.0, 224.0, 0.0, 56.0), true),
            ("to the edge, under the lip", b(576.0, 224.0, 0.0, 56.0), b(640.0, 224.0, 0.0, 20.0), false),
            ("the same point", b(128.0, 128.0, 0.0, 56.0), b(128.0, 128.0, 0.0, 56.0), true),
        ];
        for (what, looker, target, expected) in cases {
            assert_eq!(sees(&level, looker, target), expected, "{what} at offset {o}");
        }
        // Live heights: the platform's lip raised above the line of sight
        // through its corner and along its edge.
        let mut raised = level.clone();
        raised.map.sectors[1].floor = 50.0;
        assert!(!sees(&raised, b(576.0, 256.0, 0.0, 56.0), b(704.0, 128.0, 0.0, 56.0)), "offset {o}");
        assert!(!sees(&raised, b(576.0, 192.0, 0.0, 56.0), b(768.0, 192.0, 0.0, 56.0)), "offset {o}");

        let mut shoot = |level: &CompiledMap, x: f64, y: f64, z: f64, angle: f64, slope: f64, bodies: &[Body]| {
            let ray = Ray { origin: DVec2::new(x, y) + o, z, angle, range: SHOT_RANGE, shooter: Some(0) };
            let fast = hitscan(level, &mut scratch, &ray, slope, bodies);
            assert_eq!(fast, hitscan_brute(&level.map, &ray, slope, bodies), "offset {o}: {ray:?}");
            fast.unwrap_or_else(|| panic!("offset {o}: {ray:?} hit nothing"))
        };
        let wall = |line, part| Struck::Wall { line, side: LineSide::Front, part };
        let shots = [
            // (what, origin, z, angle, slope, struck, point hit)
            ("along the pillar's face", (128.0, 192.0), 32.0, 0.0, 0.0, wall(4, Part::Middle), (256.0, 192.0)),
            ("from the pillar's face", (256.0, 224.0), 32.0, 180.0, 0.0, wall(7, Part::Middle), (256.0, 224.0)),
            ("along the edge, over the lip", (576.0, 192.0), 32.0, 0.0, 0.0, wall(2, Part::Middle), (1024.0, 192.0)),
            ("along the edge, under the lip", (576.0, 192.0), 10.0, 0.0, 0.0, wall(8, Part::Lower), (640.0, 192.0)),
            ("from the platform's edge", (672.0, 192.0), 32.0, 270.0, 0.0, wall(3, Part::Middle), (672.0, 0.0)),
            ("the alcove above its sky", (800.0, 352.0), 200.0, 0.0, 0.0, Struck::Sky { line: 15 }, (832.0, 352.0)),
        ];
        for (what, (x, y), z, angle, slope, struck, (hx, hy)) in shots {
            let hit = shoot(&level, x, y, z, angle, slope, &[]);
            assert_eq!(hit.struck, struck, "{what} at offset {o}");
            let expected = DVec2::new(hx, hy) + o;
            assert!(hit.point.truncate().distance(expected) < 1e-9, "{what} at offset {o}: {hit:?}");
        }
        // A body in front of the east wall, and one flush with it (the wall wins the tie).
        let body = |x: f64, index| Body { pos: DVec2::new(x, 64.0) + o, z: 0.0, height: 56.0, radius: 16.0, index };
        let hit = shoot(&level, 960.0, 64.0, 32.0, 0.0, 0.0, &[body(1008.0, 1)]);
        assert_eq!(hit.struck, Struck::Body { index: 1 }, "offset {o}");
        let hit = shoot(&level, 960.0, 64.0, 32.0, 0.0, 0.0, &[body(1040.0, 2)]);
        assert_eq!(hit.struck, wall(2, Part::Middle), "offset {o}");

        let aim = |level: &CompiledMap, x: f64, y: f64, bodies: &[Body]| {
            let ray = Ray { origin: DVec2::new(x, y) + o, z: 32.0, angle: 0.0, range: 1024.0, shooter: Some(0) };
            let fast = aim_slope(level, &mut Scratch::default(), &ray, bodies);
            assert_eq!(fast, aim_slope_brute(&level.map, &ray, bodies), "offset {o}: {ray:?}");
            fast
        };
        let at = |x: f64, y: f64, z: f64, height: f64, index| Body { index, ..b(x, y, z, height) };
        let aimed = aim(&level, 400.0, 384.0, &[at(512.0, 384.0, 0.0, 56.0, 3)]).expect("in view");
        assert!((aimed.slope + 4.0 / 96.0).abs() < 1e-12 && aimed.index == 3, "offset {o}: {aimed:?}");
        let tall = aim(&level, 400.0, 384.0, &[at(512.0, 384.0, 0.0, 400.0, 3)]).expect("in view");
        assert!((tall.slope - (AIM_SLOPE - 32.0 / 96.0) / 2.0).abs() < 1e-12, "offset {o}: {tall:?}");
        assert_eq!(aim(&level, 64.0, 224.0, &[at(448.0, 224.0, 0.0, 56.0, 1)]), None, "offset {o}");
    }
}

/// A 60,000-unit room from -30,000 to 30,000 with a pillar in the middle:
/// lines of sight across it, grazing the pillar's corners exactly, and
/// random pairs, by both paths.
#[test]
fn huge_room_at_30000() {
    let mut source = MapSource {
        name: "huge".into(),
        sectors: vec![SectorSource { floor: 0.0, ceiling: 512.0, light: 160, ..SectorSource::default() }],
        things: vec![ThingSource::new(PLAYER_START, -29_000.0, -29_000.0, 0.0)],
        ..MapSource::default()
    };
    let r = 30_000.0;
    source.add_ring(&[(-r, -r), (-r, r), (r, r), (r, -r)], 0, None);
    source.add_ring(&[(-64.0, -64.0), (64.0, -64.0), (64.0, 64.0), (-64.0, 64.0)], 0, None);
    let map = validate(&source).unwrap_or_else(|p| panic!("{p:?}"));
    let level = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let b = |x: f64, y: f64| Body { pos: DVec2::new(x, y), z: 0.0, height: 56.0, radius: 16.0, index: 1 };
    let mut scratch = Scratch::default();
    let mut sees = |a: Body, t: Body| {
        let fast = sight(&level, &mut scratch, &a, &t);
        assert_eq!(fast, sight_brute(&level.map, &a, &t), "{a:?} -> {t:?}");
        fast
    };
    // Corner to corner: through the pillar. Along x + y = 128, which touches
    // the pillar only at its corner (64, 64): blocked; a unit off it: seen.
    assert!(!sees(b(-29_999.0, -29_999.0), b(29_999.0, 29_999.0)));
    assert!(!sees(b(-29_000.0, 29_128.0), b(29_128.0, -29_000.0)));
    assert!(sees(b(-29_000.0, 29_129.0), b(29_129.0, -29_000.0)));
    assert!(sees(b(-29_999.0, 29_999.0), b(29_999.0, 29_999.0)));
    let tally = check_pairs(&level, 30_000, 2_000, "huge room");
    assert!(tally.seen > 100 && tally.hidden > 100, "{tally:?}");
}

/// Opens `WAD:MAP` as `sightline play` does.
fn open(wad: &str, name: &str) -> CompiledMap {
    use sightline::campaign::{open, MapRef};
    let path = freedoom_wads::path(wad);
    assert!(path.is_file(), "missing fixture {}: {}", path.display(), freedoom_wads::HOW_TO_GET);
    let text = format!("{}:{name}", path.display());
    open(&MapRef::parse(&text, None), &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}")).level.compiled
}

/// Freedoom's E1M1 and MAP01: 10,000 random pairs each (half with the map's
/// heights as shipped, half with every shut door and raised lift opened),
/// the fast paths agreeing with the oracles on every one.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn freedoom_pairs_agree() {
    for (wad, name) in [("freedoom1.wad", "E1M1"), ("freedoom2.wad", "MAP01")] {
        let mut level = open(wad, name);
        let mut tally = check_pairs(&level, 1, 5_000, name);
        for s in &mut level.map.sectors {
            if s.ceiling <= s.floor + 8.0 {
                s.ceiling = s.floor + 72.0;
            }
        }
        tally.add(&check_pairs(&level, 2, 5_000, &format!("{name}, doors open")));
        eprintln!("{name}: {tally:?}");
        let t = &tally;
        assert!(t.seen > t.pairs / 10 && t.hidden > t.pairs / 10, "{name}: {t:?}");
        assert!(t.through_vertex > 100 && t.along_line > 100, "{name}: {t:?}");
        assert!(t.walls > 100 && t.parts > 100 && t.sky > 0 && t.bodies > 100 && t.aimed > 100, "{name}: {t:?}");
    }
}
