//! Point location: every point of the map has exactly one sector, points
//! exactly on two-sided lines and on vertices where only such lines meet
//! included, and it is the sector of the BSP leaf the descent reaches (a
//! point on a partition goes to its front). Points on one-sided lines, in
//! holes and outside are not in the map. Checked on every shipped map and on
//! random maps (`random_maps.rs`), with and without proptest's shrinking.

// Shared with properties.rs, which uses all of it.
#[allow(dead_code)]
#[path = "random_maps.rs"]
mod random_maps;

use glam::DVec2;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use random_maps::{compile, generate, map_spec, MapSpec};
use sightline::bsp::{CompiledMap, SplitterKind};
use sightline::geom::{exact_side, on_segment, Side};
use sightline::map::Map;
use sightline_tests::{assert_agree_on_two_sided_lines, load, shipped_maps};

/// The sectors on either side of every line through `p` (exactly), and
/// whether any of those lines is one-sided.
fn touching(map: &Map, p: DVec2) -> (Vec<usize>, bool) {
    let (mut sectors, mut one_sided) = (Vec::new(), false);
    for line in &map.lines {
        let (a, b) = map.line_points(line);
        if on_segment(a, b, p) {
            sectors.push(line.front.sector);
            match &line.back {
                Some(back) => sectors.push(back.sector),
                None => one_sided = true,
            }
        }
    }
    sectors.sort_unstable();
    sectors.dedup();
    (sectors, one_sided)
}

/// How many points of each kind a check saw.
#[derive(Debug, Default)]
struct Seen {
    inside: usize,
    on_two_sided: usize,
    /// Vertices where only two-sided lines meet (counted in `on_two_sided` too).
    two_sided_vertices: usize,
    on_one_sided: usize,
    outside: usize,
}

/// The promise for one point `p`, whatever it is. Returns what kind it was.
fn check_point(level: &CompiledMap, p: DVec2, what: &str, seen: &mut Seen) {
    let map = &level.map;
    let located = level.locate(p);
    let leaf_sector = level.bsp.leaves[level.bsp.leaf_at(p)].sector;
    let at = || format!("{what}: ({:?}, {:?})", p.x, p.y);
    let (sectors, one_sided) = touching(map, p);
    if sectors.is_empty() {
        // On no line: the crossing-number oracle decides.
        let expected = map.sector_strictly_containing(p);
        assert_eq!(located, expected, "{}: located in {located:?}, strictly inside {expected:?}", at());
        assert_eq!(map.contains(p), expected.is_some(), "{}", at());
        if expected.is_some() {
            seen.inside += 1;
        } else {
            seen.outside += 1;
        }
    } else if one_sided {
        assert_eq!(located, None, "{}: on a one-sided line, yet located in a sector", at());
        assert!(!map.contains(p), "{}", at());
        seen.on_one_sided += 1;
    } else {
        let Some(s) = located else { panic!("{}: on two-sided lines only (sectors {sectors:?}), not located", at()) };
        assert!(sectors.contains(&s), "{}: located in sector {s}, which does not touch it ({sectors:?})", at());
        assert_eq!(s, leaf_sector, "{}: not the sector of the leaf the descent reaches", at());
        seen.on_two_sided += 1;
    }
}

/// Points exactly on the segment `a-b` at the fractions `k / 16`, and, when
/// `beyond`, on its line outside it: only those that are exactly on the line
/// (with arbitrary f64 ends the rounded point often is not).
fn exact_points(a: DVec2, b: DVec2, beyond: bool) -> Vec<DVec2> {
    let mut ts: Vec<f64> = (1..16).map(|k| f64::from(k) / 16.0).collect();
    if beyond {
        ts.extend([-3.0, -1.0, -0.5, 1.5, 2.0, 4.0]);
    }
    ts.into_iter().map(|t| a + (b - a) * t).filter(|&p| exact_side(a, b, p) == Side::On).collect()
}

/// Every vertex; points exactly along every line; points exactly on every
/// partition line, in the map and out of it; `random` uniform points over the
/// map's box and a margin round it; the box's outside corners.
fn check_map(level: &CompiledMap, what: &str, random: usize, seed: u64) -> Seen {
    let map = &level.map;
    let mut seen = Seen::default();
    for (i, &v) in map.vertices.iter().enumerate() {
        let before = seen.on_two_sided;
        check_point(level, v, &format!("{what} vertex {i}"), &mut seen);
        seen.two_sided_vertices += seen.on_two_sided - before;
    }
    for (i, line) in map.lines.iter().enumerate() {
        let (a, b) = map.line_points(line);
        for p in exact_points(a, b, false) {
            check_point(level, p, &format!("{what} line {i}"), &mut seen);
        }
    }
    for (i, node) in level.bsp.nodes.iter().enumerate() {
        for p in exact_points(node.a, node.b, true) {
            check_point(level, p, &format!("{what} partition of node {i}"), &mut seen);
        }
    }
    let (lo, hi) =
        map.vertices.iter().fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let margin = (hi - lo) * 0.1 + 1.0;
    let mut r = ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..random {
        let p = DVec2::new(
            r.random_range(lo.x - margin.x..=hi.x + margin.x),
            r.random_range(lo.y - margin.y..=hi.y + margin.y),
        );
        check_point(level, p, &format!("{what} random point"), &mut seen);
    }
    for corner in [lo - margin, hi + margin, DVec2::new(lo.x - margin.x, hi.y + margin.y)] {
        check_point(level, corner, &format!("{what} outside corner"), &mut seen);
        assert_eq!(level.locate(corner), None, "{what}: ({corner}) is outside the map");
    }
    seen
}

#[test]
fn every_point_of_every_shipped_map_has_one_sector() {
    let mut two_sided_maps = 0;
    for path in shipped_maps() {
        let level = load(&path);
        let seen = check_map(&level, &path.display().to_string(), 4000, 12);
        eprintln!("{}: {seen:?}", path.display());
        assert!(seen.inside > 500 && seen.on_one_sided > 0 && seen.outside > 0, "{}: {seen:?}", path.display());
        let has_two_sided = level.map.lines.iter().any(|l| l.back.is_some());
        assert_eq!(seen.on_two_sided > 0, has_two_sided, "{}: {seen:?}", path.display());
        two_sided_maps += usize::from(has_two_sided);
    }
    assert!(two_sided_maps >= 8, "only {two_sided_maps} shipped maps have two-sided lines");
}

/// The doorway of `two_rooms.ron`, the pose a new user tried: (256, 128) is
/// on line 6, between the west room (sector 0) and the east room (sector 1).
#[test]
fn the_two_rooms_doorway_is_in_one_room() {
    let level = load(&sightline_tests::map_path("two_rooms.ron"));
    let p = DVec2::new(256.0, 128.0);
    assert_eq!(level.map.sector_strictly_containing(p), None, "on the line, so in neither strictly");
    assert!(level.map.contains(p));
    let sector = level.locate(p).expect("the doorway is in the map");
    assert!(sector == 0 || sector == 1);
    // Its ends, where the line meets the one-sided outer walls, are not.
    for end in [DVec2::new(256.0, 0.0), DVec2::new(256.0, 256.0)] {
        assert_eq!(level.locate(end), None, "({end}) is on the outer wall");
    }
    let view = sightline::View::at_pose(&level, p.x, p.y, 0.0, None).expect("a pose in the doorway");
    assert_eq!(view.z, level.map.sectors[sector].floor + sightline::render::view::EYE_HEIGHT);
}

/// The random maps do what the property tests below need: pillar sectors
/// give vertices where only two-sided lines meet.
#[test]
fn random_maps_have_two_sided_lines_and_vertices() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let mut total = Seen::default();
    for k in 0..100 {
        let spec = map_spec().new_tree(&mut runner).unwrap().current();
        let g = generate(&spec);
        let level = compile(&spec, &g, SplitterKind::Cost, 0);
        let seen = check_map(&level, &format!("map {k}"), 50, k);
        total.on_two_sided += seen.on_two_sided;
        total.two_sided_vertices += seen.two_sided_vertices;
    }
    eprintln!("100 random maps: {total:?}");
    assert!(total.two_sided_vertices > 100 && total.on_two_sided > 1000, "{total:?}");
}

fn config(cases: u32) -> Config {
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|n| n.parse().ok()).unwrap_or(cases);
    Config { cases, failure_persistence: None, max_shrink_iters: 1024, ..Config::default() }
}

fn map_text(spec: &MapSpec, g: &random_maps::Generated) -> String {
    random_maps::describe(spec, g)
}

proptest! {
    #![proptest_config(config(300))]

    /// Random maps, both splitters: vertices (a pillar sector's ring has
    /// vertices where only two-sided lines meet), exact points along lines
    /// and partitions, random points.
    #[test]
    fn every_point_of_random_maps_has_one_sector(spec in map_spec(), split_seed in any::<u64>(), probe_seed in any::<u64>()) {
        let g = generate(&spec);
        for (splitter, seed) in [(SplitterKind::Random, split_seed), (SplitterKind::Cost, 0)] {
            let level = compile(&spec, &g, splitter, seed);
            let what = format!("{} splitter seed {seed}", splitter.name());
            let result = std::panic::catch_unwind(|| check_map(&level, &what, 200, probe_seed));
            if let Err(e) = result {
                let message = e.downcast_ref::<String>().cloned().unwrap_or_default();
                prop_assert!(false, "{message}\n{}", map_text(&spec, &g));
            }
        }
    }

    /// Random points near the map's vertices and lines, snapped to a grid
    /// fine enough to land exactly on vertices and on axis-aligned or
    /// 45-degree lines now and then, and exact vertices themselves.
    #[test]
    fn random_points_near_lines_and_vertices(
        spec in map_spec(),
        picks in proptest::collection::vec((any::<prop::sample::Index>(), 0u8..4, -8i32..=8, -8i32..=8), 1..64),
    ) {
        let g = generate(&spec);
        let level = compile(&spec, &g, SplitterKind::Cost, 0);
        let map = &level.map;
        for (index, kind, dx, dy) in picks {
            let line = &map.lines[index.index(map.lines.len())];
            let (a, b) = map.line_points(line);
            // An exact vertex, or a point on a grid of 1/64 of the line's
            // longer extent round an end, the middle or a quarter of a line.
            let p = match kind {
                0 => a,
                1 => (a + b) * 0.5,
                2 => a + (b - a) * 0.25,
                _ => map.vertices[index.index(map.vertices.len())],
            } + if kind == 3 { DVec2::ZERO } else { DVec2::new(f64::from(dx), f64::from(dy)) * ((b - a).abs().max_element() / 64.0) };
            let result = std::panic::catch_unwind(|| check_point(&level, p, "random point", &mut Seen::default()));
            if let Err(e) = result {
                let message = e.downcast_ref::<String>().cloned().unwrap_or_default();
                prop_assert!(false, "{message}\n{}", map_text(&spec, &g));
            }
        }
    }
}

proptest! {
    #![proptest_config(config(100))]

    /// Poses on random maps' two-sided lines and at their pillar sectors'
    /// corners, with both splitters: accepted, and the renderers agree.
    #[test]
    fn poses_on_two_sided_lines_of_random_maps_agree(spec in map_spec(), split_seed in any::<u64>()) {
        let g = generate(&spec);
        for (splitter, seed) in [(SplitterKind::Random, split_seed), (SplitterKind::Cost, 0)] {
            let level = compile(&spec, &g, splitter, seed);
            let what = format!("{} splitter seed {seed}", splitter.name());
            let sizes = [(96, 60), (127, 75)];
            let result = std::panic::catch_unwind(|| assert_agree_on_two_sided_lines(&level, &what, 6, &sizes));
            if let Err(e) = result {
                let message = e.downcast_ref::<String>().cloned().unwrap_or_default();
                prop_assert!(false, "{message}\n{}", map_text(&spec, &g));
            }
        }
    }
}

/// Two rooms, west (sector 0) and east (sector 1), joined by the two-sided
/// line x = 0; in each room a low-ceilinged triangle (sectors 2 and 3)
/// whose apex lies on y = 0, 50 units from the doorway, both its other
/// corners to the left of a ray from the doorway out along y = 0. That ray
/// meets the apex's two lines at one point (entering the triangle and
/// leaving it at once), listed so that the one it crosses first has the
/// higher index.
const DOORWAY_AND_WEDGES: &str = r#"Map(name: "doorway and wedges",
    vertices: [(-200, -100), (-200, 100), (0, 100), (200, 100), (200, -100), (0, -100),
               (-50, 0), (-60, 30), (-90, 10), (50, 0), (60, -30), (90, -10)],
    sectors: [Sector(floor: 0, ceiling: 128, light: 160), Sector(floor: 0, ceiling: 128, light: 160),
              Sector(floor: 0, ceiling: 64, light: 160), Sector(floor: 0, ceiling: 64, light: 160)],
    lines: [
        Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
        Line(from: 5, to: 0, front: Side(sector: 0)),
        Line(from: 2, to: 3, front: Side(sector: 1)), Line(from: 3, to: 4, front: Side(sector: 1)),
        Line(from: 4, to: 5, front: Side(sector: 1)),
        Line(from: 5, to: 2, front: Side(sector: 1), back: Side(sector: 0)),
        Line(from: 6, to: 8, front: Side(sector: 2), back: Side(sector: 0)),
        Line(from: 8, to: 7, front: Side(sector: 2), back: Side(sector: 0)),
        Line(from: 7, to: 6, front: Side(sector: 2), back: Side(sector: 0)),
        Line(from: 9, to: 11, front: Side(sector: 3), back: Side(sector: 1)),
        Line(from: 11, to: 10, front: Side(sector: 3), back: Side(sector: 1)),
        Line(from: 10, to: 9, front: Side(sector: 3), back: Side(sector: 1)),
    ],
    things: [Thing(kind: "player_start", x: -150, y: 0, angle: 0)])"#;

/// The reference orders crossings tied at one point from the sector the ray
/// is in. From an eye in a doorway that is not one sector for the frame:
/// rays west start in the west room, rays east in the east room, whichever
/// sector point location gives the eye. Both renderers agree in every
/// pixel (the odd width puts the centre column's ray exactly through the
/// apex), from each splitter's tree.
#[test]
fn rays_from_a_doorway_start_in_the_room_they_enter() {
    let map = sightline::map::parse_map(DOORWAY_AND_WEDGES, "wedges.ron").unwrap_or_else(|e| panic!("{e}"));
    for (splitter, seed) in [(SplitterKind::Cost, 0), (SplitterKind::Random, 1), (SplitterKind::Random, 2)] {
        let compiled = sightline::bsp::build(&map, &sightline::bsp::BuildOptions { splitter, seed }).unwrap();
        let level = sightline::level::Level::with_builtin_textures(compiled).unwrap();
        assert!(level.locate(DVec2::ZERO).is_some());
        for angle in [0.0, 180.0, 90.0, 270.0, 10.0, 190.0] {
            let view = sightline::View::at_pose(&level, 0.0, 0.0, angle, None).unwrap();
            for size in [(161, 101), (160, 100)] {
                let (diff, ..) = sightline_tests::bsp_vs_reference(&level, &view, size);
                let what = format!("{} seed {seed}, angle {angle}, {size:?}", splitter.name());
                assert_eq!(diff.pixels, 0, "{what}: bsp and reference differ in {} pixels", diff.pixels);
            }
        }
    }
}

/// The case `poses_on_two_sided_lines_of_random_maps_agree` found (the map is
/// `tests/maps/eye_on_partition.ron`): the eye at vertex 15, the south-west
/// corner of an axis-aligned platform, looking east along the platform's
/// south face (line 15), whose line is the partition of node 1 in the
/// random splitter's tree for this seed. Line 8, a face of another platform
/// 171 units ahead, is cut by that partition 1.8e-15 south of it, so its
/// south piece missed column 63, whose ray runs along the line; the near
/// (south) subtree drew the far side of that platform there (line 11 from
/// inside it, cut exactly on the line), and 65 of the column's 75 pixels
/// showed that platform's ceiling and floor, not line 8's face and the
/// room's. Before the fix this failed; `render::bsp::looks_along` says why.
#[test]
fn regression_eye_on_partition_of_a_random_map() {
    let path = sightline_tests::root().join("tests/maps/eye_on_partition.ron");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let map = sightline::map::parse_map(&text, "eye_on_partition.ron").unwrap_or_else(|e| panic!("{e}"));
    let options = sightline::bsp::BuildOptions { splitter: SplitterKind::Random, seed: 162_236_210_168_585_868 };
    let level = sightline::level::Level::with_builtin_textures(sightline::bsp::build(&map, &options).unwrap()).unwrap();
    let p = level.map.vertices[15];
    assert_eq!(p, DVec2::new(-142.472_218_957_953_94, 0.335_868_730_799_857_6));
    let node = &level.bsp.nodes[1];
    assert!(node.a == p && node.b.y == p.y, "node 1's partition is line 15's line, through the eye");
    let view = sightline::View::at_pose(&level, p.x, p.y, 360.0, None).unwrap();
    for size in [(127, 75), (96, 60)] {
        let (diff, ..) = sightline_tests::bsp_vs_reference(&level, &view, size);
        assert_eq!(diff.pixels, 0, "{size:?}: bsp and reference differ in {} pixels", diff.pixels);
    }
}
