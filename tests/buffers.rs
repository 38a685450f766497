//! The depth and label buffers (`RenderOptions::buffers`): the BSP walk's
//! against the brute-force reference's, on every shipped map, rooms with
//! sprites at walls and at the eye, random maps with things and see-through
//! middles from random and degenerate poses (on wall lines, on partition
//! lines looking along them, on vertices' axes); against each frame's own
//! `ids` colours; for any thread count and shading; and at no cost when off.
//!
//! The criterion, per pose and size: the `ids` frames meet the exactness
//! criterion of `assert_agree` (columns along a line through the eye exempt
//! for degenerate poses, as `assert_agree_off_eye_lines` exempts them), and
//! at every pixel where they agree the labels are equal and the depths equal
//! within a relative [`DEPTH_TOLERANCE`].
//!
//! Why a tolerance at all: both renderers compute a wall's depth with the
//! same f64 expression from the whole map line, a plane's as `rise / slope`
//! from the same row table, a sprite's as the thing's camera x, so nearly
//! every pixel agrees to the bit. Where a ray passes through a vertex
//! shared by two lines, the reference takes the crossings as one point when
//! their depths agree to 1e-9 (its `TIE`) and either line may then be the
//! one a floor or ceiling pixel was found at, whose depth bounds the
//! plane's ([`sightline::render::buffers::plane_depth`]); 1e-9 relative is
//! at most one f32 step (6e-8). 1e-6 leaves room for that and nothing more.

#[allow(dead_code)]
#[path = "random_maps.rs"]
mod random_maps;

use glam::DVec2;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use random_maps::{generate, map_spec, random_poses, Generated, WallLines};
use sightline::bsp::{BuildOptions, SplitterKind};
use sightline::geom::{exact_side, Side};
use sightline::level::Level;
use sightline::map::source::ThingSource;
use sightline::render::shade::{ids_colour, Surface, VOID};
use sightline::render::{render_frame, Buffers, Frame, RenderOptions, Renderer, Shade, View};
use sightline::Framebuffer;
use sightline_tests::{columns_along_lines_through_eye, load, map_path, shipped_maps};

/// Largest relative difference allowed between the two renderers' depths
/// at a pixel both show the same surface at (see the module's doc).
const DEPTH_TOLERANCE: f32 = 1e-6;

const BOTH: Buffers = Buffers { depth: true, labels: true };

/// Even and odd sizes: with an odd width the centre column's ray is exactly
/// the view direction, so axis-aligned poses cast exactly axis-aligned rays.
const SIZES: [(usize, usize); 2] = [(96, 60), (127, 75)];

/// A frame with its buffers.
struct Shot {
    fb: Framebuffer,
    depth: Vec<f32>,
    labels: Vec<u32>,
}

fn shot(level: &Level, view: &View, size: (usize, usize), options: RenderOptions) -> Shot {
    let mut fb = Framebuffer::new(size.0, size.1);
    let mut frame = Frame::new();
    render_frame(level, view, &options, &mut frame, &mut fb);
    Shot { fb, depth: frame.depth().to_vec(), labels: frame.labels().to_vec() }
}

fn ids_shot(level: &Level, view: &View, size: (usize, usize), renderer: Renderer) -> Shot {
    shot(level, view, size, RenderOptions { renderer, shade: Shade::Ids, buffers: BOTH, ..Default::default() })
}

/// What one comparison saw, summed over calls.
#[derive(Debug, Default)]
struct Tally {
    frames: usize,
    /// Pixels compared (the ids frames agree there).
    pixels: usize,
    /// Of those, pixels whose depths are not bit-identical, and the largest
    /// relative difference among them.
    depth_inexact: usize,
    depth_worst: f32,
    /// Pixels showing a thing, and pixels where the ids frames differ.
    labelled: usize,
    ids_differ: usize,
}

fn relative(a: f32, b: f32) -> f32 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

/// Each frame's buffers say what its own `ids` colours say: a label exactly
/// where the colour is that thing's, an infinite depth exactly where it is
/// sky or void, a finite positive depth elsewhere.
fn check_self_consistent(s: &Shot, level: &Level, what: &str) {
    let sky = ids_colour(Surface::Sky);
    let keys: Vec<usize> = level.things.iter().map(|t| t.key).collect();
    for (i, ((&c, &d), &l)) in s.fb.pixels.iter().zip(&s.depth).zip(&s.labels).enumerate() {
        let at = || format!("{what}: pixel ({}, {})", i % s.fb.width, i / s.fb.width);
        if l == 0 {
            assert!(keys.iter().all(|&k| c != ids_colour(Surface::Thing { thing: k })), "{}: a thing, no label", at());
        } else {
            let key = l as usize - 1;
            assert!(keys.contains(&key), "{}: label {l} names no thing", at());
            assert_eq!(c, ids_colour(Surface::Thing { thing: key }), "{}: label {l}, another colour", at());
        }
        if c == sky || c == VOID {
            assert_eq!(d, f32::INFINITY, "{}: sky or void at depth {d}", at());
        } else {
            assert!(d.is_finite() && d > 0.0, "{}: depth {d}", at());
        }
    }
}

/// The criterion of the module's doc for one pose at one size; `exempt`
/// columns (along a line through the eye) are left out.
fn compare(level: &Level, view: &View, size: (usize, usize), exempt: &[usize], what: &str, tally: &mut Tally) {
    let bsp = ids_shot(level, view, size, Renderer::Bsp);
    let reference = ids_shot(level, view, size, Renderer::Reference);
    let n = size.0 * size.1;
    for (s, name) in [(&bsp, "bsp"), (&reference, "reference")] {
        assert_eq!((s.depth.len(), s.labels.len()), (n, n), "{what}: {name}'s buffers");
        check_self_consistent(s, level, &format!("{what}, {name}"));
    }
    let mut differ_columns = vec![false; size.0];
    let mut counted = 0;
    for i in 0..n {
        let x = i % size.0;
        if exempt.contains(&x) {
            continue;
        }
        counted += 1;
        let at = || format!("{what}: pixel ({x}, {})", i / size.0);
        if bsp.fb.pixels[i] != reference.fb.pixels[i] {
            tally.ids_differ += 1;
            differ_columns[x] = true;
            continue;
        }
        tally.pixels += 1;
        assert_eq!(bsp.labels[i], reference.labels[i], "{}: labels", at());
        tally.labelled += usize::from(bsp.labels[i] != 0);
        let (a, b) = (bsp.depth[i], reference.depth[i]);
        if a.to_bits() != b.to_bits() {
            let r = relative(a, b);
            assert!(r <= DEPTH_TOLERANCE, "{}: depth {a} (bsp) against {b} (reference)", at());
            tally.depth_inexact += 1;
            tally.depth_worst = tally.depth_worst.max(r);
        }
    }
    let differ = differ_columns.iter().filter(|&&d| d).count();
    let adjacent = differ_columns.windows(2).any(|w| w[0] && w[1]);
    let differing = (0..n).filter(|&i| !exempt.contains(&(i % size.0)) && bsp.fb.pixels[i] != reference.fb.pixels[i]);
    let share = differing.count() as f64 / counted.max(1) as f64;
    assert!(share <= 0.001 && !adjacent, "{what}: ids frames differ in {differ} columns ({share:.5} of pixels)");
    tally.frames += 1;
}

/// Columns whose ray runs along a slanted line (or its extension, where
/// partitions lie) through the eye: only within
/// rounding, so which side of the line's vertices it passes is decided by
/// the last bits of two computations and those columns are exempt (as in
/// `assert_agree_off_eye_lines`). Along an axis-aligned line the ray runs
/// exactly along it and every column counts.
fn exempt_columns(level: &Level, view: &View, size: (usize, usize)) -> Vec<usize> {
    let slanted = level.map.lines.iter().any(|line| {
        let (a, b) = level.map.line_points(line);
        a.x != b.x
            && a.y != b.y
            && sightline::geom::front_distance(a, b, view.pos).abs()
                <= 1e-9 * a.abs().max(b.abs()).max_element().max(1.0)
    });
    if slanted {
        columns_along_lines_through_eye(level, view, size)
    } else {
        Vec::new()
    }
}

#[test]
fn buffers_are_empty_when_off_and_change_no_pixel_when_on() {
    let level = load(&map_path("hall.ron"));
    let view = View::at_start(&level).unwrap();
    for renderer in [Renderer::Bsp, Renderer::Reference] {
        let plain = RenderOptions { renderer, shade: Shade::Textured, ..Default::default() };
        let off = shot(&level, &view, (160, 100), plain);
        assert!(off.depth.is_empty() && off.labels.is_empty());
        for buffers in [Buffers { depth: true, labels: false }, Buffers { depth: false, labels: true }, BOTH] {
            let on = shot(&level, &view, (160, 100), RenderOptions { buffers, ..plain });
            assert!(on.fb.pixels == off.fb.pixels, "{} {buffers:?}: the picture changed", renderer.name());
            assert_eq!(on.depth.len(), if buffers.depth { 160 * 100 } else { 0 });
            assert_eq!(on.labels.len(), if buffers.labels { 160 * 100 } else { 0 });
        }
    }
    // A frame kept across calls drops a buffer no longer asked for.
    let mut frame = Frame::new();
    let mut fb = Framebuffer::new(64, 40);
    render_frame(&level, &view, &RenderOptions { buffers: BOTH, ..Default::default() }, &mut frame, &mut fb);
    assert_eq!(frame.depth().len(), 64 * 40);
    render_frame(&level, &view, &RenderOptions::default(), &mut frame, &mut fb);
    assert!(frame.depth().is_empty() && frame.labels().is_empty());
}

/// Depth is camera-space depth: in a square room, facing the north wall 412
/// units ahead, the centre column's wall is at 412 and a floor row where
/// the ray meets the floor; a sprite at its camera x, labelled key + 1.
#[test]
fn depth_is_along_the_view_and_labels_are_keys_plus_one() {
    let text = r#"Map(name: "square", vertices: [(0, 0), (0, 512), (512, 512), (512, 0)],
        sectors: [Sector(floor: 0, ceiling: 128, light: 160)],
        lines: [Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
                Line(from: 2, to: 3, front: Side(sector: 0)), Line(from: 3, to: 0, front: Side(sector: 0))],
        things: [Thing(kind: "player_start", x: 256, y: 100, angle: 90), Thing(kind: "barrel", x: 300, y: 300, angle: 0)])"#;
    let map = sightline::map::parse_map(text, "square.ron").unwrap();
    let level = Level::with_builtin_textures(sightline::bsp::build(&map, &BuildOptions::default()).unwrap()).unwrap();
    let view = View::at_start(&level).unwrap();
    let (w, h) = (161, 101);
    let s = ids_shot(&level, &view, (w, h), Renderer::Bsp);
    let centre = |y: usize| s.depth[y * w + w / 2];
    assert_eq!(centre(h / 2), 412.0);
    // Row y's ray is at height z + depth * slope: the bottom row meets the
    // floor 41 units below the eye.
    let cam = sightline::render::Camera::new(&view, w, h);
    let bottom = (0.0 - view.z) / cam.row_slope(h as i32 - 1);
    assert_eq!(centre(h - 1), bottom as f32);
    let barrel = level.things.iter().find(|t| t.pos == DVec2::new(300.0, 300.0)).unwrap();
    let labelled: Vec<usize> = (0..w * h).filter(|&i| s.labels[i] != 0).collect();
    assert!(!labelled.is_empty(), "the barrel shows");
    for &i in &labelled {
        assert_eq!(s.labels[i] as usize, barrel.key + 1);
        assert_eq!(s.depth[i], 200.0, "the barrel stands 200 units ahead");
    }
    check_self_consistent(&s, &level, "square room");
}

/// Every shipped map from its things tour (every pose for small tours, a
/// spread of 40 otherwise), both sizes.
#[test]
fn buffers_match_the_reference_on_every_shipped_map() {
    let mut tally = Tally::default();
    for path in shipped_maps() {
        let level = load(&path);
        let views = sightline::tour::things_tour(&level);
        let step = (views.len() / 40).max(1);
        for (k, view) in views.iter().enumerate().step_by(step) {
            for size in SIZES {
                let what = format!("{} pose {k} {size:?}", path.display());
                compare(&level, view, size, &exempt_columns(&level, view, size), &what, &mut tally);
            }
        }
    }
    eprintln!("shipped maps: {tally:?}");
    assert!(tally.labelled > 10_000, "{tally:?}");
}

/// Sprites against a wall, at the eye, edge-on to a wall; the hall's things
/// behind its GRATE and FENCE middles.
#[test]
fn buffers_match_the_reference_with_sprites_at_walls_and_middles() {
    let text = r#"Map(name: "sprites", vertices: [(0, 0), (0, 512), (512, 512), (512, 0)],
        sectors: [Sector(floor: 0, ceiling: 128, light: 160)],
        lines: [Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
                Line(from: 2, to: 3, front: Side(sector: 0)), Line(from: 3, to: 0, front: Side(sector: 0))],
        things: [Thing(kind: "player_start", x: 256, y: 100, angle: 90), Thing(kind: "barrel", x: 256, y: 512, angle: 0),
                 Thing(kind: "lamp", x: 256, y: 100, angle: 0), Thing(kind: "column", x: 511.999999999, y: 300, angle: 0),
                 Thing(kind: "plant", x: 200, y: 300, angle: 0), Thing(kind: "barrel", x: 200, y: 300, angle: 0)])"#;
    let map = sightline::map::parse_map(text, "sprites.ron").unwrap();
    let mut tally = Tally::default();
    for splitter in SplitterKind::ALL {
        let compiled = sightline::bsp::build(&map, &BuildOptions { splitter, seed: 3 }).unwrap();
        let level = Level::with_builtin_textures(compiled).unwrap();
        for angle in [90.0, 45.0, 0.0, 270.0, 12.5, 77.0] {
            let view = View::at_pose(&level, 256.0, 100.0, angle, None).unwrap();
            for size in SIZES.into_iter().chain([(320, 200)]) {
                compare(&level, &view, size, &[], &format!("{} angle {angle} {size:?}", splitter.name()), &mut tally);
            }
        }
    }
    let hall = load(&map_path("hall.ron"));
    for (k, view) in sightline::tour::things_tour(&hall).iter().enumerate() {
        compare(&hall, view, (127, 75), &exempt_columns(&hall, view, (127, 75)), &format!("hall pose {k}"), &mut tally);
    }
    eprintln!("sprite rooms and the hall: {tally:?}");
    assert!(tally.labelled > 50_000, "{tally:?}");
}

/// Thing kinds with built-in sprites.
const KINDS: [&str; 4] = ["barrel", "lamp", "column", "plant"];

/// `g` with up to `count` things at random points of its sectors and at
/// some of its vertices, and see-through middles (GRATE, FENCE) on some of
/// its two-sided lines' sides.
fn with_things(g: &Generated, seed: u64, count: usize) -> Generated {
    let mut r = ChaCha8Rng::seed_from_u64(seed);
    let mut source = g.source.clone();
    let (lo, hi) =
        g.map.vertices.iter().fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(l, h), &p| (l.min(p), h.max(p)));
    let mut placed = 0;
    for _ in 0..count * 20 {
        if placed == count {
            break;
        }
        let p = if r.random_bool(0.2) {
            g.map.vertices[r.random_range(0..g.map.vertices.len())]
        } else {
            DVec2::new(r.random_range(lo.x..=hi.x), r.random_range(lo.y..=hi.y))
        };
        if !g.map.contains(p) {
            continue;
        }
        source.things.push(ThingSource::new(KINDS[r.random_range(0..4)], p.x, p.y, r.random_range(0.0..360.0)));
        placed += 1;
    }
    for line in source.lines.iter_mut().filter(|l| l.back.is_some()) {
        let texture = ["GRATE", "FENCE"][r.random_range(0..2)];
        match r.random_range(0..4) {
            0 => line.front.middle = Some(texture.into()),
            1 => {
                if let Some(back) = line.back.as_mut() {
                    back.middle = Some(texture.into());
                }
            }
            2 => {
                line.front.middle = Some(texture.into());
                if let Some(back) = line.back.as_mut() {
                    back.middle = Some(texture.into());
                }
            }
            _ => {}
        }
    }
    let map = sightline::map::validate::validate(&source).unwrap_or_else(|p| panic!("{p:?}\n{}", source.to_ron()));
    Generated { source, map, unit: g.unit, pillars_placed: g.pillars_placed }
}

fn compile(g: &Generated, splitter: SplitterKind, seed: u64) -> Level {
    let compiled = sightline::bsp::build(&g.map, &BuildOptions { splitter, seed })
        .unwrap_or_else(|e| panic!("{e}\n{}", g.source.to_ron()));
    Level::with_builtin_textures(compiled).unwrap_or_else(|e| panic!("{e}"))
}

/// Poses exactly on the compiled tree's partition lines (the rounded points
/// at sixteenths along each partition that are exactly on it, and its map
/// vertices), looking along the partition both ways and across it; only
/// those in the map.
fn partition_poses(level: &Level, max: usize) -> Vec<(String, View)> {
    let mut poses = Vec::new();
    for (i, node) in level.bsp.nodes.iter().enumerate() {
        let (a, b) = (node.a, node.b);
        let d = b - a;
        let along = d.y.atan2(d.x).to_degrees();
        let points = (0..=16).map(|k| a + d * (f64::from(k) / 16.0)).filter(|&p| exact_side(a, b, p) == Side::On);
        for p in points.filter(|&p| level.locate(p).is_some()) {
            for angle in [along, along + 180.0, along + 90.0] {
                let view = View::at_pose(level, p.x, p.y, angle, None).unwrap();
                poses.push((format!("on node {i}'s partition at ({:?}, {:?}) angle {angle}", p.x, p.y), view));
            }
        }
    }
    let step = (poses.len() / max.max(1)).max(1);
    poses.into_iter().step_by(step).collect()
}

fn config(cases: u32) -> Config {
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|n| n.parse().ok()).unwrap_or(cases);
    Config { cases, failure_persistence: None, max_shrink_iters: 512, ..Config::default() }
}

/// The random-map check: random poses (uniform, on vertices' axes looking
/// at them, a hair beside wall extensions, near walls, eye heights at and
/// outside the sectors' floors and ceilings), poses exactly on wall lines,
/// and poses exactly on partition lines looking along them, from both
/// splitters' trees.
fn check_random_map(g: &Generated, split_seed: u64, pose_seed: u64, tally: &mut Tally) {
    let mut poses = random_poses(g, 4, pose_seed, WallLines::Avoid);
    poses.extend(random_poses(g, 2, pose_seed ^ 1, WallLines::Only));
    for (splitter, seed) in [(SplitterKind::Random, split_seed), (SplitterKind::Cost, 0)] {
        let level = compile(g, splitter, seed);
        let mut all = poses.clone();
        all.extend(partition_poses(&level, 4));
        for (what, view) in &all {
            for size in SIZES {
                let exempt = exempt_columns(&level, view, size);
                let what = format!("{} seed {seed}, {what} {size:?}", splitter.name());
                compare(&level, view, size, &exempt, &what, tally);
            }
        }
    }
}

proptest! {
    #![proptest_config(config(150))]

    /// Random maps with things and middles ([`check_random_map`]).
    #[test]
    fn buffers_match_the_reference_on_random_maps(
        spec in map_spec(),
        things_seed in any::<u64>(),
        split_seed in any::<u64>(),
        pose_seed in any::<u64>(),
    ) {
        let g = with_things(&generate(&spec), things_seed, 6);
        let result = std::panic::catch_unwind(|| check_random_map(&g, split_seed, pose_seed, &mut Tally::default()));
        if let Err(e) = result {
            let message = e.downcast_ref::<String>().cloned().unwrap_or_default();
            prop_assert!(false, "{message}\nspec {spec:?}\n{}", g.source.to_ron());
        }
    }
}

/// The same check on 100 fixed random maps, to show what it covers: things
/// in view, poses on partitions, and how exactly the depths agree.
#[test]
fn random_maps_show_things_through_middles_and_from_partitions() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let mut tally = Tally::default();
    let mut on_partitions = 0;
    for k in 0..100u64 {
        let spec = map_spec().new_tree(&mut runner).unwrap().current();
        let g = with_things(&generate(&spec), k, 6);
        on_partitions += partition_poses(&compile(&g, SplitterKind::Cost, 0), 4).len();
        check_random_map(&g, k, k, &mut tally);
    }
    eprintln!("100 random maps: {tally:?}, {on_partitions} poses on partitions (cost splitter)");
    assert!(tally.labelled > 20_000 && on_partitions > 200, "{tally:?}, {on_partitions}");
}

/// Depth and labels are the same whatever the thread count, frame size
/// and shading (the hall: sprites, middles, sky; E1M4-like sizes).
#[test]
fn buffers_are_the_same_for_any_thread_count_and_shading() {
    let level = load(&map_path("hall.ron"));
    let views = sightline::tour::things_tour(&level);
    for size in [(320, 200), (321, 200), (7, 5), (64, 40), (1920, 1080)] {
        for view in views.iter().step_by(if size.0 > 1000 { 40 } else { 8 }) {
            let base = RenderOptions { buffers: BOTH, ..Default::default() };
            let one = shot(&level, view, size, base);
            for (threads, shade) in
                [(2, Shade::Textured), (3, Shade::Textured), (4, Shade::Textured), (1, Shade::Ids), (2, Shade::Flat)]
            {
                let other = shot(&level, view, size, RenderOptions { threads, shade, ..base });
                let what = format!("{size:?} {threads} threads {shade:?} from {view:?}");
                assert!(one.labels == other.labels, "{what}: labels differ");
                let same = one.depth.iter().zip(&other.depth).all(|(a, b)| a.to_bits() == b.to_bits());
                assert!(same, "{what}: depths differ");
            }
        }
    }
}

/// Grid maps drawn by the ray-caster fill the buffers too, as the BSP walk
/// does (the two agree in `ids`; depth within the tolerance where they do).
#[test]
fn the_ray_caster_fills_the_buffers_as_the_walk_does() {
    let mut compared = 0;
    for path in shipped_maps() {
        let level = load(&path);
        if level.grid().is_none() {
            continue;
        }
        for view in sightline::tour::things_tour(&level).iter().step_by(3) {
            let (bsp, ray) = (
                ids_shot(&level, view, (127, 75), Renderer::Bsp),
                ids_shot(&level, view, (127, 75), Renderer::Raycast),
            );
            check_self_consistent(&ray, &level, &format!("{} raycast", path.display()));
            for i in 0..127 * 75 {
                if bsp.fb.pixels[i] == ray.fb.pixels[i] {
                    assert_eq!(bsp.labels[i], ray.labels[i], "{}: labels at {i}", path.display());
                    let r = relative(bsp.depth[i], ray.depth[i]);
                    assert!(r <= 1e-5, "{}: depth {} against {} at {i}", path.display(), bsp.depth[i], ray.depth[i]);
                    compared += 1;
                }
            }
        }
    }
    assert!(compared > 100_000, "{compared} pixels compared");
}

/// The eye exactly at the height a sprite stands on, so the horizon row's
/// centre is exactly on the sprite's bottom edge: the row belongs below it
/// (`Camera::row_above`), in both renderers. The reference once took the
/// bottom as `top - height`, which rounds off a floor like this one's and
/// gave the sprite the horizon row (found by the random-map check from a
/// pose beside a column standing on a raised pillar).
#[test]
fn a_sprite_whose_bottom_is_at_the_eye_leaves_the_horizon_row_alone() {
    let floor = 91.86244171092729_f64;
    let text = format!(
        r#"Map(name: "ledge", vertices: [(0, 0), (0, 512), (512, 512), (512, 0)],
        sectors: [Sector(floor: {floor:?}, ceiling: 300, light: 160)],
        lines: [Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
                Line(from: 2, to: 3, front: Side(sector: 0)), Line(from: 3, to: 0, front: Side(sector: 0))],
        things: [Thing(kind: "player_start", x: 256, y: 100, angle: 90), Thing(kind: "column", x: 256, y: 140, angle: 0)])"#
    );
    let map = sightline::map::parse_map(&text, "ledge.ron").unwrap();
    let level = Level::with_builtin_textures(sightline::bsp::build(&map, &BuildOptions::default()).unwrap()).unwrap();
    let column = level.things.iter().find(|t| t.pos == DVec2::new(256.0, 140.0)).unwrap();
    let height = level.materials.textures.get(column.texture_seen_from(DVec2::new(256.0, 100.0))).height as f64;
    assert_ne!(floor + height - height, floor, "the case needs a floor that the sum and difference round off");
    // An odd height: row 37's centre is the horizon, exactly at the eye.
    let size = (127, 75);
    let view = View::new(DVec2::new(256.0, 100.0), floor, 90.0);
    let bsp = ids_shot(&level, &view, size, Renderer::Bsp);
    let reference = ids_shot(&level, &view, size, Renderer::Reference);
    let thing = ids_colour(Surface::Thing { thing: column.key });
    let horizon = &bsp.fb.pixels[37 * size.0..38 * size.0];
    assert!(bsp.fb.pixels[36 * size.0..37 * size.0].contains(&thing), "the column shows above the horizon");
    assert!(!horizon.contains(&thing), "the horizon row is below the column's bottom");
    assert!(bsp.fb.pixels == reference.fb.pixels, "the renderers agree on every pixel");
    compare(&level, &view, size, &[], "eye at a sprite's floor", &mut Tally::default());
}

/// A thing standing on a pillar's corner, seen from straight down the
/// axis through it: the centre column's ray touches the pillar only at that
/// corner, entering and leaving at once, and the two lines' depths there,
/// each from its whole line, differ from the thing's depth in the last bit
/// (found by the random-map check). Depths within `TIE` are one, and a
/// sprite against a wall is in front of it, in both renderers: the walk
/// once let the nearer-by-a-bit line clip the sprite's top.
#[test]
fn a_sprite_on_a_corner_the_ray_touches_is_in_front_of_both_lines() {
    let text = r#"Map(name: "corner", vertices: [(-600, -100), (-600, 400), (-200, 400), (-200, -100),
            (-392.9375, 133.625), (-390.25, 139.125), (-393.5625, 143.75), (-398.5, 143.375), (-400.75, 139.5625), (-399.0625, 134.8125)],
        sectors: [Sector(floor: 125, ceiling: 140.85998268425843, light: 97), Sector(floor: 125, ceiling: 131.09556528254598, light: 13)],
        lines: [Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
                Line(from: 2, to: 3, front: Side(sector: 0)), Line(from: 3, to: 0, front: Side(sector: 0)),
                Line(from: 4, to: 5, front: Side(sector: 0, middle: Some("GRATE")), back: Some(Side(sector: 1))),
                Line(from: 5, to: 6, front: Side(sector: 0), back: Some(Side(sector: 1, middle: Some("FENCE")))),
                Line(from: 6, to: 7, front: Side(sector: 0), back: Some(Side(sector: 1))),
                Line(from: 7, to: 8, front: Side(sector: 0), back: Some(Side(sector: 1))),
                Line(from: 8, to: 9, front: Side(sector: 0, middle: Some("GRATE")), back: Some(Side(sector: 1, middle: Some("GRATE")))),
                Line(from: 9, to: 4, front: Side(sector: 0), back: Some(Side(sector: 1, middle: Some("GRATE"))))],
        things: [Thing(kind: "player_start", x: -500, y: 0, angle: 90), Thing(kind: "column", x: -400.75, y: 139.5625, angle: 0)])"#;
    let map = sightline::map::parse_map(text, "corner.ron").unwrap();
    let column = DVec2::new(-400.75, 139.5625);
    let view = View::new(DVec2::new(-400.75, 110.16725965237217), 125.0, 90.0);
    let size = (127, 75);
    for (splitter, seed) in [(SplitterKind::Random, 0), (SplitterKind::Random, 1), (SplitterKind::Cost, 0)] {
        let compiled = sightline::bsp::build(&map, &BuildOptions { splitter, seed }).unwrap();
        let level = Level::with_builtin_textures(compiled).unwrap();
        let cam = sightline::render::Camera::new(&view, size.0, size.1);
        let depth = |line: usize| {
            let (a, b) = level.map.line_points(&level.map.lines[line]);
            let (from, dir) = (cam.to_camera(a), cam.to_camera(b) - cam.to_camera(a));
            sightline::geom::cross(from, dir) / sightline::geom::cross(DVec2::new(1.0, cam.column_slope(63)), dir)
        };
        let thing = cam.to_camera(column).x;
        assert!(depth(7) < thing && depth(8) == thing, "the case needs one line's depth a bit short of the thing's");
        let what = format!("{} seed {seed}", splitter.name());
        let bsp = ids_shot(&level, &view, size, Renderer::Bsp);
        let reference = ids_shot(&level, &view, size, Renderer::Reference);
        let key = level.things.iter().find(|t| t.pos == column).unwrap().key;
        let centre: Vec<u32> = (0..size.1).map(|y| bsp.fb.pixels[y * size.0 + 63]).collect();
        // Down to the horizon: the eye is at the column's floor.
        let shows = centre[..37].iter().all(|&c| c == ids_colour(Surface::Thing { thing: key }));
        assert!(shows, "{what}: the column fills the centre column above the horizon");
        assert!(bsp.fb.pixels == reference.fb.pixels, "{what}: the renderers agree on every pixel");
        compare(&level, &view, size, &[], &what, &mut Tally::default());
    }
}

/// The eye a hair (4 ulps) beside a pillar's face, on the line of the
/// pillar's side looking exactly along the face: the centre column's ray
/// runs between the face's line (a partition) and the rounded points where
/// the partition cuts the walls beyond. The walk once let a cut point
/// rounded past the ray leave the near piece of the platform's face short
/// of it, so walls behind took the column (found by the random-map check
/// from a pose on a partition). Every compile of the map agrees with the
/// reference, every pixel.
#[test]
fn a_ray_a_hair_beside_a_partition_meets_the_near_pieces() {
    let text = r#"Map(name: "hair", vertices: [(-200, -400), (-200, 400), (200, 400), (200, -400),
            (44.03793402360988, 60.269261657181985), (4.9445746772164405, 60.269261657181985),
            (4.9445746772164405, 21.175902310788548), (44.03793402360988, 21.175902310788548),
            (51.66691978109927, -123.21958833056928), (-31.963513396153445, -123.21958833056928),
            (-31.963513396153445, -206.850021507822), (51.66691978109927, -206.850021507822)],
        sectors: [Sector(floor: -60, ceiling: 191, light: 188), Sector(floor: 0.632306380798255, ceiling: 98, light: 247)],
        lines: [Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
                Line(from: 2, to: 3, front: Side(sector: 0)), Line(from: 3, to: 0, front: Side(sector: 0)),
                Line(from: 4, to: 5, front: Side(sector: 0)), Line(from: 5, to: 6, front: Side(sector: 0)),
                Line(from: 6, to: 7, front: Side(sector: 0)), Line(from: 7, to: 4, front: Side(sector: 0)),
                Line(from: 8, to: 9, front: Side(sector: 0), back: Some(Side(sector: 1))),
                Line(from: 9, to: 10, front: Side(sector: 0), back: Some(Side(sector: 1))),
                Line(from: 10, to: 11, front: Side(sector: 0), back: Some(Side(sector: 1))),
                Line(from: 11, to: 8, front: Side(sector: 0), back: Some(Side(sector: 1)))],
        things: [Thing(kind: "player_start", x: 0, y: 300, angle: 270)])"#;
    let map = sightline::map::parse_map(text, "hair.ron").unwrap();
    let eye = DVec2::new(4.944574677216437, 60.269261657181985);
    assert!(eye.x < map.vertices[5].x, "the eye is beside the face's line, not on it");
    let size = (127, 75);
    let mut cases = vec![(SplitterKind::Cost, 0)];
    cases.extend((0..24).map(|seed| (SplitterKind::Random, seed)));
    for (splitter, seed) in cases {
        let compiled = sightline::bsp::build(&map, &BuildOptions { splitter, seed }).unwrap();
        let level = Level::with_builtin_textures(compiled).unwrap();
        let view = View::at_pose(&level, eye.x, eye.y, 270.0, None).unwrap();
        let what = format!("{} seed {seed}", splitter.name());
        let bsp = ids_shot(&level, &view, size, Renderer::Bsp);
        let reference = ids_shot(&level, &view, size, Renderer::Reference);
        let differ =
            (0..size.1).filter(|&y| bsp.fb.pixels[y * size.0 + 63] != reference.fb.pixels[y * size.0 + 63]).count();
        assert!(
            bsp.fb.pixels == reference.fb.pixels,
            "{what}: the renderers differ ({differ} pixels of the centre column)"
        );
    }
}
