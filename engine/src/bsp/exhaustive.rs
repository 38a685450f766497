//! The exhaustive splitter: at each node, the partition line that leads to
//! the fewest segs in the whole subtree below it, found by trying every
//! autopartition (every candidate line at every node, recursively). It gives
//! the smallest autopartition there is, the yardstick the heuristics are
//! measured against in `sightline bench`, and it takes time exponential in
//! the number of segs, so [`build`](super::build) refuses maps with more
//! than [`EXHAUSTIVE_LIMIT`] sides.
//!
//! The search remembers the best size of every set of segs it has solved
//! (sets recur: cutting by A then B often leaves the same cell as B then A),
//! and abandons a candidate once the segs it leaves, before any further
//! split, already reach the best size found.

use std::collections::HashMap;

use glam::DVec2;

use super::build::{Class, Partition, WorkSeg};
use super::split::Splitter;
use super::Seg;
use crate::geom::line_intersection;
use crate::map::Map;

/// The most input sides the exhaustive splitter accepts.
pub const EXHAUSTIVE_LIMIT: usize = 24;

/// A seg as the search sees it: its ends and line.
type Key = (u64, u64, u64, u64, usize);

pub struct ExhaustiveSplitter {
    /// Each map line's ends, where cuts are computed (as the builder does).
    lines: Vec<(DVec2, DVec2)>,
    /// Best subtree size of each set of segs solved so far.
    memo: HashMap<Vec<Key>, usize>,
}

impl ExhaustiveSplitter {
    pub fn new(map: &Map) -> Self {
        ExhaustiveSplitter { lines: map.lines.iter().map(|l| map.line_points(l)).collect(), memo: HashMap::new() }
    }

    /// The fewest segs any autopartition of `segs` ends with, and the seg
    /// whose line starts it (`None`: `segs` is already a convex leaf).
    fn solve(&mut self, segs: &[Seg]) -> (usize, Option<usize>) {
        let mut best: (usize, Option<usize>) = (usize::MAX, None);
        let mut tried: Vec<usize> = Vec::new();
        for c in 0..segs.len() {
            if tried.contains(&segs[c].line) {
                continue;
            }
            tried.push(segs[c].line);
            // The line the build will partition by: the seg's whole map line.
            let (from, to) = self.lines[segs[c].line];
            let p = match segs[c].side {
                super::LineSide::Front => Partition::new(from, to),
                super::LineSide::Back => Partition::new(to, from),
            };
            let (front, back) = self.partition(segs, &p);
            if back.is_empty() && front.len() == segs.len() {
                continue; // divides nothing
            }
            if front.len() + back.len() >= best.0 {
                continue; // cannot beat the best even with no more cuts
            }
            let size = self.size(&front) + self.size(&back);
            if size < best.0 {
                best = (size, Some(c));
                if size == segs.len() {
                    break; // no cut at all below: nothing does better
                }
            }
        }
        match best.1 {
            None => (segs.len(), None),
            Some(_) => best,
        }
    }

    fn size(&mut self, segs: &[Seg]) -> usize {
        let mut key: Vec<Key> = segs
            .iter()
            .map(|s| (s.v1.x.to_bits(), s.v1.y.to_bits(), s.v2.x.to_bits(), s.v2.y.to_bits(), s.line))
            .collect();
        key.sort_unstable();
        if let Some(&n) = self.memo.get(&key) {
            return n;
        }
        let (n, _) = self.solve(segs);
        self.memo.insert(key, n);
        n
    }

    fn partition(&self, segs: &[Seg], p: &Partition) -> (Vec<Seg>, Vec<Seg>) {
        let (mut front, mut back) = (Vec::new(), Vec::new());
        for s in segs {
            match p.classify(s) {
                Class::Front => front.push(s.clone()),
                Class::Back => back.push(s.clone()),
                Class::Split(start_in_front) => {
                    let (from, to) = self.lines[s.line];
                    let cut = line_intersection(from, to, p.a, p.b);
                    let first = Seg { v2: cut, ..s.clone() };
                    let second = Seg { v1: cut, ..s.clone() };
                    let (f, k) = if start_in_front { (first, second) } else { (second, first) };
                    front.push(f);
                    back.push(k);
                }
            }
        }
        (front, back)
    }
}

impl Splitter for ExhaustiveSplitter {
    fn pick(&mut self, _map: &Map, segs: &[WorkSeg]) -> Option<usize> {
        let plain: Vec<Seg> = segs.iter().map(|w| w.seg.clone()).collect();
        self.solve(&plain).1
    }
}
