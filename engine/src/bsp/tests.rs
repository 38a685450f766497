//! The compiler's own tests: tallies over blocks agree with the seg-by-seg
//! tally, the cost splitter is deterministic, and every Freedoom map compiles
//! to a tree that `check` accepts with the cost and random splitters.

use glam::DVec2;
use proptest::prelude::*;

use super::blocks::{kd_order, Blocks};
use super::build::{Partition, WorkSeg};
use super::check::check_invariants;
use super::split::{tally, Tally};
use super::{build, BuildOptions, LineSide, Seg, SplitterKind};

fn work_seg(v1: DVec2, v2: DVec2, source: usize) -> WorkSeg {
    let seg = Seg { v1, v2, line: 0, side: LineSide::Front, front_sector: 0, back_sector: None, offset: 0.0 };
    WorkSeg { seg, source }
}

/// Segs on a small integer grid, so that many are collinear with a
/// partition, touch it, or end on it; a few end at half units.
fn segs() -> impl Strategy<Value = Vec<WorkSeg>> {
    let point = (-24i32..24, -24i32..24, 0..8u8).prop_map(|(x, y, half)| {
        let h = if half == 0 { 0.5 } else { 0.0 };
        DVec2::new(x as f64 + h, y as f64)
    });
    prop::collection::vec((point.clone(), point), 1..300).prop_map(|ends| {
        let ends = ends.into_iter().filter(|(a, b)| a != b);
        ends.enumerate().map(|(i, (a, b))| work_seg(a, b, i)).collect()
    })
}

fn same(a: &Tally, b: &Tally) -> bool {
    (a.front, a.back, a.splits) == (b.front, b.back, b.splits)
}

proptest! {
    /// Every line of every seg, through blocks and seg by seg: the same counts.
    #[test]
    fn block_tallies_are_exact(mut segs in segs(), bound in 0usize..400) {
        prop_assume!(!segs.is_empty());
        kd_order(&mut segs);
        let mut blocks = Blocks::default();
        blocks.rebuild(&segs);
        for s in &segs {
            let p = Partition::new(s.seg.v1, s.seg.v2);
            let flat = tally(&segs, &p, |_| false).unwrap();
            let whole = blocks.tally(&p, |_, _| false).unwrap();
            prop_assert!(same(&flat, &whole), "{flat:?} != {whole:?}");
            // A tally that did not give up is complete.
            let give_up = |t: &Tally, left: usize| t.splits * 8 + t.front.abs_diff(t.back).saturating_sub(left) >= bound;
            if let Some(t) = blocks.tally(&p, give_up) {
                prop_assert!(same(&flat, &t));
            }
        }
    }
}

fn shipped(name: &str) -> crate::map::Map {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../maps").join(name);
    crate::map::load_map(&path).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn cost_splitter_is_deterministic() {
    let map = shipped("nasty.ron");
    let options = BuildOptions { splitter: SplitterKind::Cost, seed: 0 };
    assert_eq!(build(&map, &options).unwrap().bsp, build(&map, &options).unwrap().bsp);
}

/// Every map of Freedoom's two IWADs, imported and compiled with each
/// heuristic splitter, passes `check` (tests/freedoom.rs renders and plays
/// them; this holds the trees to every invariant). The WADs are a fixture:
/// Debian's freedoom package, or `SIGHTLINE_DOOM_DIR`.
#[test]
fn freedoom_maps_compile_to_valid_trees() {
    use crate::wad::import::{convert, Art};
    use crate::wad::Wad;
    let dir = std::env::var_os("SIGHTLINE_DOOM_DIR")
        .map_or_else(|| std::path::PathBuf::from("/usr/share/games/doom"), std::path::PathBuf::from);
    for file in ["freedoom1.wad", "freedoom2.wad"] {
        let path = dir.join(file);
        let wad = Wad::open(&path)
            .unwrap_or_else(|e| panic!("{e}: install Freedoom (apt-get install freedoom) or set SIGHTLINE_DOOM_DIR"));
        let art = Art::read(&wad).unwrap_or_else(|e| panic!("{e}"));
        for name in wad.map_names() {
            let raw = wad.map(&name).unwrap_or_else(|e| panic!("{e}"));
            let converted = convert(&wad, &raw, &art).unwrap_or_else(|e| panic!("{e}"));
            let map = crate::map::validate::validate(&converted.source)
                .unwrap_or_else(|problems| panic!("{file} {name}: {problems:?}"));
            for options in [
                BuildOptions { splitter: SplitterKind::Cost, seed: 0 },
                BuildOptions { splitter: SplitterKind::Random, seed: 1 },
            ] {
                let compiled = build(&map, &options).unwrap_or_else(|e| panic!("{file} {name}: {e}"));
                if let Err(e) = check_invariants(&compiled.map, &compiled.bsp) {
                    panic!("{file} {name} with {}: {e}", options.splitter.name());
                }
            }
        }
    }
}
