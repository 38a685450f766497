//! Choosing partition lines: the seam where the compiler's heuristics plug in.
//!
//! A candidate is any seg of the current set; its line divides the set when at
//! least one seg lies behind it or is cut by it. When no candidate divides, the
//! set is convex and becomes a leaf.

use std::collections::HashMap;

use rand::rngs::ChaCha8Rng;
use rand::seq::SliceRandom;
use rand::SeedableRng;

use super::blocks::Blocks;
use super::build::{Class, Partition, WorkSeg};
use super::LineSide;
use crate::map::Map;

/// The splitters `sightline compile --splitter NAME` offers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SplitterKind {
    /// The randomized autopartition (Paterson and Yao's RANDAUTO, as in de Berg
    /// et al.): a random order of the input sides, and at each node the first
    /// side in that order whose line divides the node's segs. Expected size
    /// O(n log n). Unlike RANDAUTO we skip lines that divide nothing rather
    /// than cut off empty cells, which changes no split.
    Random,
    /// Minimizes `splits * split_weight + |front - back|` over every candidate
    /// line, the cost model of Doom-era node builders (ZDBSP, AJBSP).
    #[default]
    Cost,
    /// The smallest autopartition, by trying them all (small maps only: see
    /// [`super::exhaustive`]).
    Exhaustive,
}

impl SplitterKind {
    pub const ALL: [SplitterKind; 3] = [SplitterKind::Random, SplitterKind::Cost, SplitterKind::Exhaustive];

    pub fn name(self) -> &'static str {
        match self {
            SplitterKind::Random => "random",
            SplitterKind::Cost => "cost",
            SplitterKind::Exhaustive => "exhaustive",
        }
    }

    pub fn from_name(name: &str) -> Option<SplitterKind> {
        Self::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// Picks the partition for one node; `None` means the set is convex.
pub trait Splitter {
    /// The seg whose line (`Partition::of_seg`) partitions `segs`.
    fn pick(&mut self, map: &Map, segs: &[WorkSeg]) -> Option<usize>;
}

/// Counts of a candidate partition over a set of segs.
#[derive(Clone, Copy, Debug, Default)]
pub struct Tally {
    pub front: usize,
    pub back: usize,
    pub splits: usize,
}

impl Tally {
    pub fn divides(&self) -> bool {
        self.back > 0 || self.splits > 0
    }
}

/// Classifies every seg against `p`, stopping early once `give_up` says the
/// tally can no longer win.
pub fn tally(segs: &[WorkSeg], p: &Partition, give_up: impl Fn(&Tally) -> bool) -> Option<Tally> {
    let mut t = Tally::default();
    for s in segs {
        match p.classify(&s.seg) {
            Class::Front => t.front += 1,
            Class::Back => t.back += 1,
            Class::Split(..) => t.splits += 1,
        }
        if give_up(&t) {
            return None;
        }
    }
    Some(t)
}

pub struct RandomSplitter {
    order: Vec<usize>,
}

impl RandomSplitter {
    /// `priority` of input side `i` is its rank in a permutation seeded by `seed`;
    /// ChaCha8 keeps the tree the same for a seed on every platform and version.
    pub fn new(sides: usize, seed: u64) -> Self {
        let mut rank: Vec<usize> = (0..sides).collect();
        rank.shuffle(&mut ChaCha8Rng::seed_from_u64(seed));
        RandomSplitter { order: rank }
    }

    pub fn priority(&self, side: usize) -> usize {
        self.order[side]
    }
}

impl Splitter for RandomSplitter {
    fn pick(&mut self, map: &Map, segs: &[WorkSeg]) -> Option<usize> {
        let mut by_priority: Vec<usize> = (0..segs.len()).collect();
        by_priority.sort_by_key(|&i| self.order[segs[i].source]);
        by_priority.into_iter().find(|&c| tally(segs, &Partition::of_seg(map, &segs[c].seg), |t| t.divides()).is_none())
    }
}

/// What one split costs against one seg of imbalance. Doom-era builders use
/// 8 (ZDBSP) to 11 (glBSP); weighing splits far more makes fewer segs on
/// Doom maps, whose trees can be lopsided at no cost to the renderer.
/// Extra segs over freedoom1 / freedoom2 with every candidate tried (the
/// measurements of the commit that set this): 8: 13.3 / 14.2 %, 32: 10.0 /
/// 10.8, 64: 9.5 / 10.3, 96: 9.4 / 10.2, 128: 9.4 / 10.1, 192: 9.3 / 10.1,
/// 256: 9.4 / 10.2, 512: 9.5 / 10.3; splits alone, ties by balance: 9.8 on
/// freedoom1, and slower (deeper trees).
pub const SPLIT_WEIGHT: usize = 128;

pub struct CostSplitter {
    pub split_weight: usize,
    /// Per map line, its collinear group: lines on one infinite line give one
    /// partition, so only the first seg of each group is tried at a node.
    group: Vec<u32>,
    /// `seen[group] == stamp` when the group was already tried at this node.
    seen: Vec<u32>,
    stamp: u32,
    /// Per map line, its partition for a front seg and for a back seg.
    parts: Vec<[Partition; 2]>,
    blocks: Blocks,
}

impl CostSplitter {
    pub fn new(map: &Map) -> Self {
        let group = collinear_groups(map);
        let groups = group.iter().max().map_or(0, |&g| g as usize + 1);
        let parts = (0..map.lines.len())
            .map(|l| [LineSide::Front, LineSide::Back].map(|side| Partition::of_side(map, l, side)))
            .collect();
        CostSplitter {
            split_weight: SPLIT_WEIGHT,
            group,
            seen: vec![0; groups],
            stamp: 0,
            parts,
            blocks: Blocks::default(),
        }
    }
}

impl Splitter for CostSplitter {
    fn pick(&mut self, _map: &Map, segs: &[WorkSeg]) -> Option<usize> {
        self.stamp += 1;
        self.blocks.rebuild(segs);
        let w = self.split_weight;
        let cost = |t: &Tally| t.splits * w + t.front.abs_diff(t.back);
        let mut best: Option<(usize, usize)> = None;
        for (c, s) in segs.iter().enumerate() {
            let g = self.group[s.seg.line] as usize;
            if self.seen[g] == self.stamp {
                continue;
            }
            self.seen[g] = self.stamp;
            let bound = best.map_or(usize::MAX, |b| b.0);
            // Splits only grow, and the imbalance can shrink by at most the
            // segs not yet counted: once that lower bound reaches the best
            // cost, the candidate cannot win.
            let give_up =
                |t: &Tally, left: usize| t.splits * w + t.front.abs_diff(t.back).saturating_sub(left) >= bound;
            let part = &self.parts[s.seg.line][(s.seg.side == LineSide::Back) as usize];
            let Some(t) = self.blocks.tally(part, give_up) else {
                continue;
            };
            if t.divides() && cost(&t) < bound {
                best = Some((cost(&t), c));
            }
        }
        best.map(|(_, c)| c)
    }
}

/// Numbers each map line's infinite line, collinear lines alike, whichever
/// way they run. Lines with integer end points (every Doom map) are keyed
/// exactly by their equation `a x + b y = c` reduced by the gcd; any other
/// line is a group of its own (no collinear candidate is then skipped, which
/// costs time, never correctness).
pub fn collinear_groups(map: &Map) -> Vec<u32> {
    let mut ids: HashMap<(i64, i64, i64), u32> = HashMap::new();
    let mut next = 0u32;
    let mut fresh = || {
        next += 1;
        next - 1
    };
    let mut group = Vec::with_capacity(map.lines.len());
    for line in &map.lines {
        let (p, q) = map.line_points(line);
        let g = match line_equation(p, q) {
            Some(key) => *ids.entry(key).or_insert_with(&mut fresh),
            None => fresh(),
        };
        group.push(g);
    }
    group
}

/// The reduced integer equation of the line through `p` and `q`, when both are
/// integral within ±2^24 (so that every product below is exact).
fn line_equation(p: glam::DVec2, q: glam::DVec2) -> Option<(i64, i64, i64)> {
    let limit = crate::geom::MAX_COORD;
    if [p.x, p.y, q.x, q.y].iter().any(|v| v.fract() != 0.0 || v.abs() > limit) {
        return None;
    }
    let (px, py, qx, qy) = (p.x as i64, p.y as i64, q.x as i64, q.y as i64);
    let (mut a, mut b) = (qy - py, px - qx);
    let g = gcd(a.unsigned_abs(), b.unsigned_abs()) as i64;
    if g == 0 {
        return None;
    }
    (a, b) = (a / g, b / g);
    if a < 0 || (a == 0 && b < 0) {
        (a, b) = (-a, -b);
    }
    Some((a, b, a * px + b * py))
}

fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}
