//! Blocks of segs: a kd-tree over one node's segs, so that a splitter tallies a
//! candidate line a block at a time and classifies single segs only in the
//! blocks the line passes through (glBSP's "superblocks", with balanced
//! median cuts instead of a fixed grid).
//!
//! A tally over blocks equals the seg-by-seg tally exactly: a block counts
//! whole only when its box is more than `2 * ON_EPSILON` clear of the line,
//! where every seg in it classifies that way whatever the rounding; every
//! other seg is classified with the arithmetic of
//! [`Partition::classify_ends`], which the build partitions with. So a line
//! that a tally says divides the set leaves neither side empty.

use glam::DVec2;

use super::build::{Partition, WorkSeg, ON_EPSILON};
use super::split::Tally;

/// Segs per leaf block. Total build ms on freedoom1's 36 maps, cost splitter
/// with split weight 8, median of 5 (one run, busy 2-core VM): 4: 330,
/// 8: 274, 16: 268, 32: 289. Small blocks cost box tests, big ones seg tests.
const LEAF_SEGS: usize = 16;

#[derive(Clone, Copy, Debug)]
struct Block {
    min: DVec2,
    max: DVec2,
    /// Its segs are `first..first + count` of the node's order.
    first: u32,
    count: u32,
    /// Index of its first child; the second follows. 0 for a leaf (the root,
    /// block 0, is nobody's child).
    children: u32,
}

/// The kd-tree of one node's segs; rebuilt per node into the same buffers.
#[derive(Debug, Default)]
pub struct Blocks {
    /// Seg end points in the node's order, one array per coordinate so that
    /// the per-seg loop runs branch-free over contiguous memory.
    x1: Vec<f64>,
    y1: Vec<f64>,
    x2: Vec<f64>,
    y2: Vec<f64>,
    blocks: Vec<Block>,
}

/// Puts `segs` in kd order: halves by count, each cut at the median of the
/// seg midpoints along the longer axis of the half's box. Any subset kept in
/// this order is still in kd order (each of its halves is a run of the whole
/// set's order, so spatially compact), which is why the build sorts once at
/// the root and keeps the order through every partition, and [`Blocks::rebuild`]
/// only cuts by count.
pub fn kd_order(segs: &mut [WorkSeg]) {
    if segs.len() <= LEAF_SEGS {
        return;
    }
    let (mut min, mut max) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
    for w in segs.iter() {
        min = min.min(w.seg.v1).min(w.seg.v2);
        max = max.max(w.seg.v1).max(w.seg.v2);
    }
    let axis = if max.x - min.x >= max.y - min.y { 0 } else { 1 };
    let mid = segs.len() / 2;
    let key = |w: &WorkSeg| (w.seg.v1 + w.seg.v2)[axis];
    segs.select_nth_unstable_by(mid, |a, b| key(a).total_cmp(&key(b)));
    let (low, high) = segs.split_at_mut(mid);
    kd_order(low);
    kd_order(high);
}

impl Blocks {
    /// Blocks over `segs` as they are ordered (see [`kd_order`]): halves by
    /// count down to `LEAF_SEGS`, so at most log2(n) + 1 levels deep.
    pub fn rebuild(&mut self, segs: &[WorkSeg]) {
        self.x1.clear();
        self.x1.extend(segs.iter().map(|w| w.seg.v1.x));
        self.y1.clear();
        self.y1.extend(segs.iter().map(|w| w.seg.v1.y));
        self.x2.clear();
        self.x2.extend(segs.iter().map(|w| w.seg.v2.x));
        self.y2.clear();
        self.y2.extend(segs.iter().map(|w| w.seg.v2.y));
        self.blocks.clear();
        self.blocks.push(Block { min: DVec2::ZERO, max: DVec2::ZERO, first: 0, count: 0, children: 0 });
        if !segs.is_empty() {
            self.build(0, 0, segs.len());
        }
    }

    /// Fills block `slot` with segs `lo..hi`; children first, then the box.
    fn build(&mut self, slot: usize, lo: usize, hi: usize) {
        let (mut min, mut max) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
        let mut children = 0;
        if hi - lo <= LEAF_SEGS {
            for k in lo..hi {
                min = min.min(DVec2::new(self.x1[k].min(self.x2[k]), self.y1[k].min(self.y2[k])));
                max = max.max(DVec2::new(self.x1[k].max(self.x2[k]), self.y1[k].max(self.y2[k])));
            }
        } else {
            children = self.blocks.len();
            let empty = self.blocks[slot];
            self.blocks.extend([empty, empty]);
            let mid = (lo + hi) / 2;
            self.build(children, lo, mid);
            self.build(children + 1, mid, hi);
            let (a, b) = (self.blocks[children], self.blocks[children + 1]);
            (min, max) = (a.min.min(b.min), a.max.max(b.max));
        }
        self.blocks[slot] = Block { min, max, first: lo as u32, count: (hi - lo) as u32, children: children as u32 };
    }

    /// Tallies `p` over the segs; `give_up(tally, segs not yet counted)`
    /// is asked after each block and ends the tally with `None`.
    pub fn tally(&self, p: &Partition, mut give_up: impl FnMut(&Tally, usize) -> bool) -> Option<Tally> {
        let mut t = Tally::default();
        let mut left = self.x1.len();
        if left == 0 {
            return Some(t);
        }
        let (a, n, dir) = (p.a, p.normal(), p.b - p.a);
        // Which box corner is furthest behind the line (and, opposite, furthest in front).
        let (near_x, near_y) = (n.x < 0.0, n.y < 0.0);
        // Counts halve per level, so fewer than 33 levels below a u32 count;
        // the stack holds at most one pending sibling per level.
        let mut stack = [0u32; 66];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let b = &self.blocks[stack[top] as usize];
            let (lo, hi) = (b.min, b.max);
            let back_most = DVec2::new(if near_x { hi.x } else { lo.x }, if near_y { hi.y } else { lo.y });
            let front_most = DVec2::new(if near_x { lo.x } else { hi.x }, if near_y { lo.y } else { hi.y });
            if p.distance(back_most) > 2.0 * ON_EPSILON {
                t.front += b.count as usize;
            } else if p.distance(front_most) < -2.0 * ON_EPSILON {
                t.back += b.count as usize;
            } else if b.children == 0 {
                let range = b.first as usize..(b.first + b.count) as usize;
                let (x1, y1, x2, y2) =
                    (&self.x1[range.clone()], &self.y1[range.clone()], &self.x2[range.clone()], &self.y2[range]);
                let (mut front, mut back) = (0, 0);
                for k in 0..x1.len() {
                    // `Partition::classify_ends`, branch-free; same arithmetic, same answers.
                    let d1 = (x1[k] - a.x) * n.x + (y1[k] - a.y) * n.y;
                    let d2 = (x2[k] - a.x) * n.x + (y2[k] - a.y) * n.y;
                    let in_front = (d1 > -ON_EPSILON) & (d2 > -ON_EPSILON);
                    let behind = (d1 < ON_EPSILON) & (d2 < ON_EPSILON);
                    let facing = (x2[k] - x1[k]) * dir.x + (y2[k] - y1[k]) * dir.y > 0.0;
                    let on = in_front & behind;
                    front += ((in_front & !on) | (on & facing)) as usize;
                    back += ((behind & !on) | (on & !facing)) as usize;
                }
                t.front += front;
                t.back += back;
                t.splits += x1.len() - front - back;
            } else {
                stack[top] = b.children + 1;
                stack[top + 1] = b.children;
                top += 2;
                continue;
            }
            left -= b.count as usize;
            if give_up(&t, left) {
                return None;
            }
        }
        Some(t)
    }
}
