//! Choosing partition lines: the seam where the compiler's heuristics plug in.
//!
//! A candidate is any seg of the current set; its line divides the set when at
//! least one seg lies behind it or is cut by it. When no candidate divides, the
//! set is convex and becomes a leaf.

use rand::rngs::ChaCha8Rng;
use rand::seq::SliceRandom;
use rand::SeedableRng;

use super::blocks::Blocks;
use super::build::{Class, Partition, WorkSeg};
use super::lines::LineTable;
use super::rollout::Rollout;
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
    /// line, the cost model of Doom-era node builders (ZDBSP, AJBSP), with
    /// splits weighted 128; at nodes of at most 64 segs where every line
    /// splits something, follows the 4 cheapest through the greedy subtree
    /// below them and takes the one that splits least in total (a rollout).
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

/// Nodes of at most this many segs choose by rollout (see `rollout.rs`)
/// when every candidate splits something. Extra segs on freedoom1 /
/// freedoom2 and total build ms on freedoom1 (bsp_tune, median of 3, busy
/// 2-core VM), by this bound and [`ROLLOUT_CANDIDATES`]:
///
/// | below | 2 candidates | 4 | 8 |
/// |---|---|---|---|
/// | (none: greedy) | 9.41 / 10.17 %, 276 ms | | |
/// | 32 | 9.05 / 9.73, 321 | 8.81 / 9.43, 313 | 8.71 / 9.24, 345 |
/// | 64 | 8.92 / 9.58, 344 | 8.60 / 9.16, 390 | 8.44 / 8.89, 503 |
/// | 128 | 8.83 / 9.45, 442 | 8.45 / 8.98, 660 | 8.26 / 8.68, 818 |
///
/// Rolling out even when a candidate splits nothing gained 0.13 points on
/// freedoom1 (64 and 4: 8.46 %) for half again the time.
pub const ROLLOUT_BELOW: usize = 64;

/// How many candidates of least cost a rollout follows (see [`ROLLOUT_BELOW`]).
pub const ROLLOUT_CANDIDATES: usize = 4;

pub struct CostSplitter {
    pub split_weight: usize,
    lines: LineTable,
    /// `seen[group] == stamp` when the group was already tried at this node.
    seen: Vec<u32>,
    stamp: u32,
    blocks: Blocks,
    rollout: Rollout,
}

impl CostSplitter {
    pub fn new(map: &Map) -> Self {
        let lines = LineTable::new(map);
        CostSplitter {
            split_weight: SPLIT_WEIGHT,
            seen: vec![0; lines.groups],
            stamp: 0,
            blocks: Blocks::default(),
            rollout: Rollout::new(lines.groups),
            lines,
        }
    }

    /// The candidate of least cost, every candidate tried.
    fn greedy(&mut self, segs: &[WorkSeg]) -> Option<usize> {
        self.stamp += 1;
        self.blocks.rebuild(segs);
        let w = self.split_weight;
        let cost = |t: &Tally| t.splits * w + t.front.abs_diff(t.back);
        let mut best: Option<(usize, usize)> = None;
        for (c, s) in segs.iter().enumerate() {
            let g = self.lines.group(s.seg.line);
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
            let Some(t) = self.blocks.tally(self.lines.part_of(&s.seg), give_up) else {
                continue;
            };
            if t.divides() && cost(&t) < bound {
                best = Some((cost(&t), c));
            }
        }
        best.map(|(_, c)| c)
    }
}

impl Splitter for CostSplitter {
    fn pick(&mut self, _map: &Map, segs: &[WorkSeg]) -> Option<usize> {
        if segs.len() <= ROLLOUT_BELOW {
            self.rollout.pick(&self.lines, segs, self.split_weight, ROLLOUT_CANDIDATES)
        } else {
            self.greedy(segs)
        }
    }
}
