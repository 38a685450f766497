//! The compiler's own tests: tallies over blocks agree with the seg-by-seg
//! tally, and the cost splitter is deterministic. (That every Freedoom map
//! compiles to a tree `check` accepts is in tests/freedoom.rs, beside the
//! other tests that need the WADs and the build script that skips them.)

use glam::DVec2;
use proptest::prelude::*;

use super::blocks::{kd_order, Blocks};
use super::build::{Partition, WorkSeg};
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
