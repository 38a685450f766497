//! The BSP renderer against the brute-force reference, in `ids` shading, on
//! every shipped map from ordinary and deliberately hard poses.

use rand::{RngExt, SeedableRng};
use sightline::bsp::CompiledMap;
use sightline::geom::sin_cos_degrees;
use sightline::render::View;
use sightline_tests::{assert_agree, assert_agree_on_two_sided_lines, load, shipped_maps, v};

/// Even and odd sizes: with an odd width the centre column's ray is exactly
/// the view direction, so axis-aligned views cast exactly axis-aligned rays.
const SIZES: [(usize, usize); 2] = [(320, 200), (161, 101)];

/// A pose is usable when it is inside a sector and not on a line.
fn try_view(level: &CompiledMap, x: f64, y: f64, angle: f64) -> Option<View> {
    let view = View::at_pose(level, x, y, angle, None).ok()?;
    (level.map.distance_to_nearest_line(view.pos) > 1e-3).then_some(view)
}

/// Hard poses derived from the map itself.
fn hard_poses(level: &CompiledMap) -> Vec<(String, View)> {
    let mut poses = Vec::new();
    let start = level.map.player_start().pos;
    for angle in [0.0, 90.0, 180.0, 270.0, -0.0, 45.0, 360.0 - 1e-9] {
        if let Some(view) = try_view(level, start.x, start.y, angle) {
            poses.push((format!("start facing {angle}"), view));
        }
    }
    // Exactly on partition lines (they are wall lines, so also on the
    // extension of a wall), looking along them, across them and at random.
    for node in level.bsp.nodes.iter().step_by((level.bsp.nodes.len() / 12).max(1)) {
        let d = node.b - node.a;
        let along = d.y.atan2(d.x).to_degrees();
        for t in [-3.0, -1.0, -0.25, 1.25, 2.0, 4.0] {
            let p = node.a + d * t;
            for angle in [along, along + 90.0, along + 180.0, along + 37.0] {
                if let Some(view) = try_view(level, p.x, p.y, angle) {
                    poses.push((format!("on partition {:?}->{:?} t={t} angle {angle}", node.a, node.b), view));
                }
            }
        }
    }
    // A wall 0.01 units in front of the eye, and a vertex straight ahead
    // along an axis (the centre column's ray passes exactly through it).
    for (i, line) in level.map.lines.iter().enumerate().step_by((level.map.lines.len() / 10).max(1)) {
        let (a, b) = level.map.line_points(line);
        let d = (b - a).normalize();
        let normal = v(d.y, -d.x);
        let p = (a + b) * 0.5 + normal * 0.01;
        let facing = (-normal).y.atan2((-normal).x).to_degrees();
        for angle in [facing, facing + 30.0, facing - 44.0] {
            if let Some(view) = try_view(level, p.x, p.y, angle) {
                poses.push((format!("0.01 from line {i} angle {angle}"), view));
            }
        }
        for (axis, angle) in [(v(-24.0, 0.0), 0.0), (v(24.0, 0.0), 180.0), (v(0.0, -24.0), 90.0), (v(0.0, 24.0), 270.0)]
        {
            let p = a + axis;
            if let Some(view) = try_view(level, p.x, p.y, angle) {
                poses.push((format!("vertex of line {i} dead ahead, angle {angle}"), view));
            }
        }
    }
    poses
}

/// Random poses inside the map, seeded so failures reproduce.
fn random_poses(level: &CompiledMap, count: usize, seed: u64) -> Vec<(String, View)> {
    let mut rng = rand::rngs::ChaCha8Rng::seed_from_u64(seed);
    let mut bbox = sightline::geom::Aabb::EMPTY;
    for p in &level.map.vertices {
        bbox.include(*p);
    }
    let mut poses = Vec::new();
    let mut tries = 0;
    while poses.len() < count && tries < count * 200 {
        tries += 1;
        let x = rng.random_range(bbox.min.x..=bbox.max.x);
        let y = rng.random_range(bbox.min.y..=bbox.max.y);
        let angle = rng.random_range(0.0..360.0);
        if let Some(view) = try_view(level, x, y, angle) {
            poses.push((format!("random ({x}, {y}) angle {angle}"), view));
        }
    }
    assert_eq!(poses.len(), count, "could not find {count} poses inside the map");
    poses
}

#[test]
fn bsp_matches_reference_on_every_shipped_map() {
    for path in shipped_maps() {
        let level = load(&path);
        let mut poses = hard_poses(&level);
        assert!(poses.len() >= 10, "{}: only {} hard poses found", path.display(), poses.len());
        poses.extend(random_poses(&level, 24, 7));
        for (what, view) in &poses {
            for size in SIZES {
                assert_agree(&level, view, size, &format!("{} {what} {size:?}", path.display()));
            }
        }
        eprintln!("{}: {} poses agree", path.display(), poses.len());
    }
}

#[test]
fn eye_heights_at_neighbouring_floors_and_ceilings() {
    for path in shipped_maps() {
        let level = load(&path);
        let start = level.map.player_start();
        let mut heights: Vec<f64> = level.map.sectors.iter().flat_map(|s| [s.floor, s.ceiling]).collect();
        heights.dedup();
        for z in heights {
            for angle in [0.0, 60.0, 135.0, 270.0] {
                let view = View { z, ..View::at_pose(&level, start.pos.x, start.pos.y, angle, None).unwrap() };
                assert_agree(&level, &view, (320, 200), &format!("{} eye at z={z} angle {angle}", path.display()));
            }
        }
    }
}

/// A pose exactly on a two-sided line or at a vertex where only two-sided
/// lines meet is a pose like any other: accepted, its eye at the located
/// sector's floor plus the eye height, and the BSP frame agrees with the
/// reference (see `assert_agree_on_two_sided_lines`). The doorway of
/// two_rooms, the pose issue 12 tried, agrees in every pixel all round.
#[test]
fn poses_on_two_sided_lines_and_vertices_agree() {
    let two_rooms = load(&sightline_tests::map_path("two_rooms.ron"));
    for k in 0..16 {
        let angle = 22.5 * f64::from(k);
        for angle in [angle, angle + 7.0] {
            let view = sightline_tests::view(&two_rooms, 256.0, 128.0, angle);
            for size in SIZES {
                let (diff, ..) = sightline_tests::bsp_vs_reference(&two_rooms, &view, size);
                assert_eq!(diff.pixels, 0, "two_rooms doorway (256, 128) angle {angle} {size:?}: pixels differ");
            }
        }
    }
    let mut frames = 0;
    for path in shipped_maps() {
        frames += assert_agree_on_two_sided_lines(&load(&path), &path.display().to_string(), 24, &SIZES);
    }
    eprintln!("{frames} frames from poses on two-sided lines agree");
}

#[test]
fn axis_rays_have_no_stray_components() {
    // The renderers see exact axis directions: 90 degrees is (0, 1), not (6e-17, 1).
    assert_eq!(sin_cos_degrees(90.0), (1.0, 0.0));
    assert_eq!(sin_cos_degrees(180.0), (0.0, -1.0));
}
