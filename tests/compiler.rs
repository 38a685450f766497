//! The compiler's promises on every shipped map, for every splitter and
//! several seeds: every side covered exactly once by its pieces, every piece
//! on the correct side of each ancestor, every leaf convex and of one sector;
//! plus determinism, the compiled file round trip, and what `--json` reports.

use sightline::bsp::{build, check::check_invariants, file, BuildOptions, SplitterKind};
use sightline::map::load_map;
use sightline_tests::shipped_maps;

fn all_options() -> Vec<BuildOptions> {
    let mut options = vec![BuildOptions { splitter: SplitterKind::Cost, seed: 0 }];
    options.extend((0..4).map(|seed| BuildOptions { splitter: SplitterKind::Random, seed }));
    options
}

#[test]
fn invariants_hold_on_every_shipped_map_and_splitter() {
    for path in shipped_maps() {
        let map = load_map(&path).unwrap_or_else(|e| panic!("{e}"));
        for options in all_options() {
            let compiled = build(&map, &options).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            if let Err(e) = check_invariants(&compiled.map, &compiled.bsp) {
                panic!("{} with {} seed {}: {e}", path.display(), options.splitter.name(), options.seed);
            }
            let s = &compiled.stats;
            assert_eq!(s.sides_out, compiled.bsp.segs.len());
            assert_eq!(s.sides_out, s.sides_in + s.splits, "every split adds exactly one piece");
            assert_eq!(s.leaves, s.nodes + 1, "a full binary tree");
            assert!(s.depth >= 1 || s.nodes == 0);
        }
    }
}

#[test]
fn the_checks_catch_a_broken_tree() {
    // Guard against checks that cannot fail: break each promise and watch it caught.
    let map = load_map(&sightline_tests::map_path("pillars.ron")).unwrap();
    let good = build(&map, &BuildOptions::default()).unwrap();
    assert!(check_invariants(&good.map, &good.bsp).is_ok());

    let mut missing_piece = good.bsp.clone();
    let leaf = missing_piece.leaves.iter_mut().find(|l| l.count > 1).unwrap();
    leaf.count -= 1;
    assert!(check_invariants(&good.map, &missing_piece).is_err(), "a side left uncovered");

    let mut wrong_side = good.bsp.clone();
    let node = &mut wrong_side.nodes[0];
    std::mem::swap(&mut node.a, &mut node.b);
    assert!(check_invariants(&good.map, &wrong_side).is_err(), "pieces on the wrong side of the root");

    let mut wrong_sector = good.bsp.clone();
    wrong_sector.leaves[0].sector = (wrong_sector.leaves[0].sector + 1) % good.map.sectors.len();
    assert!(check_invariants(&good.map, &wrong_sector).is_err(), "a leaf that misnames its sector");
}

#[test]
fn random_splitter_is_deterministic_per_seed() {
    let map = load_map(&sightline_tests::map_path("maze.ron")).unwrap();
    let run = |seed| build(&map, &BuildOptions { splitter: SplitterKind::Random, seed }).unwrap();
    assert_eq!(run(5).bsp, run(5).bsp);
    assert_ne!(run(5).bsp, run(6).bsp);
}

#[test]
fn compiled_file_round_trips() {
    for path in shipped_maps() {
        let compiled = build(&load_map(&path).unwrap(), &BuildOptions::default()).unwrap();
        let bytes = file::to_bytes(&compiled);
        let loaded = file::from_bytes(&bytes).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(loaded.bsp, compiled.bsp);
        assert_eq!(loaded.map, compiled.map);
    }
}

#[test]
fn cost_splitter_splits_less_than_random() {
    // The heuristic exists to split less; if it ever stops doing so, say so.
    // (The maze is axis-aligned with unit faces: neither splitter cuts it.)
    let map = load_map(&sightline_tests::map_path("pillars.ron")).unwrap();
    let cost = build(&map, &BuildOptions { splitter: SplitterKind::Cost, seed: 0 }).unwrap().stats;
    for seed in 0..4 {
        let random = build(&map, &BuildOptions { splitter: SplitterKind::Random, seed }).unwrap().stats;
        assert!(cost.splits < random.splits, "seed {seed}: cost {} splits, random {}", cost.splits, random.splits);
    }
}
