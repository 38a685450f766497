//! Property tests on random valid maps (see `random_maps.rs` for the
//! generator): the compiler keeps its invariants with either splitter, both
//! renderers write every pixel exactly once, the BSP renderer agrees with the
//! reference, and a closed map never shows the void from inside.
//!
//! On a failure proptest prints the minimal [`random_maps::MapSpec`] (enough
//! to regenerate the map) and the message names a file in the temp directory
//! holding the map's RON text.

#[path = "random_maps.rs"]
mod random_maps;

use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::path::PathBuf;

use glam::DVec2;
use proptest::prelude::*;
use proptest::test_runner::Config;
use rand::{RngExt, SeedableRng};
use random_maps::{
    compile, generate, map_spec, random_poses, usable, Generated, MapSpec, WallLines,
};
use sightline::bsp::check::check_invariants;
use sightline::bsp::SplitterKind;
use sightline::render::shade::VOID;
use sightline::render::{render_frame, Frame, RenderOptions, Renderer, Shade};
use sightline::Framebuffer;
use sightline_tests::{assert_agree, bsp_vs_reference};

/// Even and odd sizes: with an odd width the centre column's ray is exactly
/// the view direction, so axis-aligned poses cast exactly axis-aligned rays.
const SIZES: [(usize, usize); 2] = [(96, 60), (127, 75)];

/// `cases` unless `PROPTEST_CASES` asks for another number (for long runs).
fn config(cases: u32) -> Config {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(cases);
    Config {
        cases,
        // No regression files next to the tests; the seed is in the report.
        failure_persistence: None,
        max_shrink_iters: 2048,
        ..Config::default()
    }
}

/// Saves the map's RON text for a failure message and says where.
fn saved(spec: &MapSpec, g: &Generated) -> String {
    let text = g.source.to_ron();
    let mut h = DefaultHasher::new();
    text.hash(&mut h);
    let dir = std::env::temp_dir().join("sightline-failures");
    let _ = std::fs::create_dir_all(&dir);
    let path: PathBuf = dir.join(format!("random-map-{:016x}.ron", h.finish()));
    let _ = std::fs::write(&path, format!("// {spec:?}\n{text}"));
    format!("map saved to {}", path.display())
}

/// Both splitters (the random one with `seed`).
fn splitters(seed: u64) -> [(SplitterKind, u64); 2] {
    [(SplitterKind::Random, seed), (SplitterKind::Cost, 0)]
}

proptest! {
    #![proptest_config(config(400))]

    /// Both splitters compile every valid map, the result keeps the compiler's
    /// invariants, and BSP point location agrees with the map's own.
    #[test]
    fn compiles_with_invariants(spec in map_spec(), split_seed in any::<u64>(), probe_seed in any::<u64>()) {
        let g = generate(&spec);
        for (splitter, seed) in splitters(split_seed) {
            let level = compile(&spec, &g, splitter, seed);
            if let Err(e) = check_invariants(&level.map, &level.bsp) {
                prop_assert!(false, "{} (seed {seed}): {e}; {}", splitter.name(), saved(&spec, &g));
            }
            let mut r = rand::rngs::ChaCha8Rng::seed_from_u64(probe_seed);
            let (lo, hi) = level.map.vertices.iter().fold(
                (DVec2::INFINITY, DVec2::NEG_INFINITY),
                |(lo, hi), &p| (lo.min(p), hi.max(p)),
            );
            for _ in 0..32 {
                let p = DVec2::new(r.random_range(lo.x..=hi.x), r.random_range(lo.y..=hi.y));
                if !usable(&level.map, p) {
                    continue;
                }
                let expected = level.map.sector_at(p);
                prop_assert_eq!(
                    Some(level.sector_at(p)),
                    expected,
                    "{} (seed {}): BSP locates ({:?}, {:?}) in another sector; {}",
                    splitter.name(), seed, p.x, p.y, saved(&spec, &g)
                );
            }
        }
    }
}

proptest! {
    #![proptest_config(config(160))]

    /// From random poses both renderers produce a frame with every pixel
    /// written exactly once (and the stats say so).
    #[test]
    fn every_pixel_written_once(spec in map_spec(), split_seed in any::<u64>(), pose_seed in any::<u64>()) {
        let g = generate(&spec);
        let poses = random_poses(&g, 4, pose_seed, WallLines::Any);
        for (splitter, seed) in splitters(split_seed) {
            let level = compile(&spec, &g, splitter, seed);
            for (what, view) in &poses {
                for size in SIZES {
                    for (renderer, shade) in Renderer::ALL.into_iter().zip([Shade::Ids, Shade::Flat]).chain(
                        Renderer::ALL.into_iter().zip([Shade::Flat, Shade::Ids]),
                    ) {
                        let options = RenderOptions { renderer, shade, count_writes: true };
                        let mut fb = Framebuffer::new(size.0, size.1);
                        let mut frame = Frame::new();
                        let stats = render_frame(&level, view, &options, &mut frame, &mut fb);
                        let counts = frame.write_counts();
                        prop_assert_eq!(counts.len(), size.0 * size.1);
                        if let Some(i) = counts.iter().position(|&c| c != 1) {
                            let (x, y) = (i / size.1, i % size.1);
                            prop_assert!(
                                false,
                                "{} renderer ({} splitter, seed {seed}), {shade:?}, {size:?}, {what}: \
                                 pixel ({x}, {y}) written {} times ({} pixels not once); {}",
                                renderer.name(), splitter.name(), counts[i],
                                counts.iter().filter(|&&c| c != 1).count(), saved(&spec, &g)
                            );
                        }
                        prop_assert_eq!(
                            stats.pixels_written, (size.0 * size.1) as u64,
                            "{} renderer, {}: pixels_written; {}", renderer.name(), what, saved(&spec, &g)
                        );
                    }
                }
            }
        }
    }
}

/// The exactness criterion on `poses`, with both splitters.
fn check_agreement(spec: &MapSpec, g: &Generated, split_seed: u64, poses: &[(String, sightline::View)]) {
    for (splitter, seed) in splitters(split_seed) {
        let level = compile(spec, g, splitter, seed);
        for (what, view) in poses {
            for size in SIZES {
                let (diff, ..) = bsp_vs_reference(&level, view, size);
                if diff.equal_share() < 0.999 || diff.widest_column_run > 1 {
                    // Saves the frames and fails with the figures.
                    let where_ = saved(spec, g);
                    assert_agree(
                        &level,
                        view,
                        size,
                        &format!("{} splitter seed {seed} {what} {size:?}; {where_}", splitter.name()),
                    );
                }
            }
        }
    }
}

/// No `ids` pixel is the void colour, for either renderer.
fn check_no_void(
    spec: &MapSpec,
    g: &Generated,
    split_seed: u64,
    poses: &[(String, sightline::View)],
) -> Result<(), TestCaseError> {
    let level = compile(spec, g, SplitterKind::Random, split_seed);
    for (what, view) in poses {
        for size in SIZES {
            for renderer in Renderer::ALL {
                let fb = sightline_tests::render(&level, view, size, renderer, Shade::Ids);
                if let Some(i) = fb.pixels.iter().position(|&c| c == VOID) {
                    prop_assert!(
                        false,
                        "{} renderer (random splitter seed {split_seed}), {size:?}, {what}: \
                         pixel ({}, {}) is void ({} void pixels); {}",
                        renderer.name(), i % size.0, i / size.0,
                        fb.pixels.iter().filter(|&&c| c == VOID).count(), saved(spec, g)
                    );
                }
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(200))]

    /// The BSP renderer agrees with the brute-force reference (the exactness
    /// criterion of `assert_agree`) from random and hard poses: exactly
    /// through vertices along the axes, a hair beside partition lines, next
    /// to walls, at sector heights. Poses exactly on a wall's line are left to
    /// the ignored test below.
    #[test]
    fn bsp_agrees_with_reference(spec in map_spec(), split_seed in any::<u64>(), pose_seed in any::<u64>()) {
        let g = generate(&spec);
        let poses = random_poses(&g, 4, pose_seed, WallLines::Avoid);
        check_agreement(&spec, &g, split_seed, &poses);
    }

    /// Every generated map is closed (one-sided outer walls), so from inside
    /// no ray escapes: no pixel of an `ids` frame is the void colour.
    #[test]
    fn closed_map_shows_no_void(spec in map_spec(), split_seed in any::<u64>(), pose_seed in any::<u64>()) {
        let g = generate(&spec);
        let poses = random_poses(&g, 4, pose_seed, WallLines::Avoid);
        check_no_void(&spec, &g, split_seed, &poses)?;
    }
}

// Known bugs: poses exactly on the line of a wall (an extension of a wall,
// which is also a partition line), looking along it. With an odd width the
// centre column's ray runs exactly along the line, and the BSP renderer gets
// that one column wrong (see the regression tests at the end for the causes).
proptest! {
    #![proptest_config(config(200))]

    #[test]
    #[ignore = "bug: eye exactly on a partition/wall line: BSP renderer shows a farther wall, or the void, in the column whose ray runs along the line (see regression_* tests)"]
    fn bsp_agrees_with_reference_on_wall_lines(spec in map_spec(), split_seed in any::<u64>(), pose_seed in any::<u64>()) {
        let g = generate(&spec);
        let poses = random_poses(&g, 4, pose_seed, WallLines::Only);
        check_agreement(&spec, &g, split_seed, &poses);
    }

    #[test]
    #[ignore = "bug: eye exactly on a wall line: BSP back-face test (map space) disagrees with its camera-space projection, leaving the column along the line unclaimed: void in a closed map (see regression_void_along_wall_line)"]
    fn closed_map_shows_no_void_on_wall_lines(spec in map_spec(), split_seed in any::<u64>(), pose_seed in any::<u64>()) {
        let g = generate(&spec);
        let poses = random_poses(&g, 4, pose_seed, WallLines::Only);
        check_no_void(&spec, &g, split_seed, &poses)?;
    }
}

/// The generator itself: every spec gives a valid map (checked inside
/// `generate`), pillars mostly fit, and the pose sampler finds its poses.
#[test]
fn generator_makes_varied_valid_maps() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let (mut pillars_asked, mut pillars_placed, mut sectors, mut lines) = (0, 0, 0, 0);
    for _ in 0..500 {
        let spec = map_spec().new_tree(&mut runner).unwrap().current();
        let g = generate(&spec);
        pillars_asked += spec.pillars.len();
        pillars_placed += g.pillars_placed;
        sectors += g.map.sectors.len();
        lines += g.map.lines.len();
        assert_eq!(random_poses(&g, 8, 1, WallLines::Any).len(), 8);
        assert_eq!(random_poses(&g, 8, 2, WallLines::Avoid).len(), 8);
    }
    eprintln!(
        "500 maps: {pillars_placed} of {pillars_asked} pillars placed, {sectors} sectors, {lines} lines"
    );
    assert!(
        pillars_placed * 10 >= pillars_asked * 8,
        "too many pillars did not fit"
    );
}
