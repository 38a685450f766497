//! Choosing partition lines: the seam where the compiler's heuristics plug in.
//!
//! A candidate is any seg of the current set; its line divides the set when at
//! least one seg lies behind it or is cut by it. When no candidate divides, the
//! set is convex and becomes a leaf.

use rand::rngs::ChaCha8Rng;
use rand::seq::SliceRandom;
use rand::SeedableRng;

use super::build::{classify, Class, WorkSeg};

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
    fn pick(&mut self, segs: &[WorkSeg]) -> Option<usize>;
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

/// Classifies every seg against `segs[candidate]`'s line, stopping early once
/// `give_up` says the tally can no longer win.
pub fn tally(segs: &[WorkSeg], candidate: usize, give_up: impl Fn(&Tally) -> bool) -> Option<Tally> {
    let part = &segs[candidate].seg;
    let mut t = Tally::default();
    for s in segs {
        match classify(part.v1, part.v2, &s.seg) {
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
    fn pick(&mut self, segs: &[WorkSeg]) -> Option<usize> {
        let mut by_priority: Vec<usize> = (0..segs.len()).collect();
        by_priority.sort_by_key(|&i| self.order[segs[i].source]);
        by_priority.into_iter().find(|&c| tally(segs, c, |t| t.divides()).is_none())
    }
}

pub struct CostSplitter {
    pub split_weight: usize,
    /// `seen[line] == stamp` when the line was already tried at this node: both
    /// sides of a line, and all pieces of one, give the same partition.
    seen: Vec<usize>,
    stamp: usize,
}

impl CostSplitter {
    pub fn new(lines: usize) -> Self {
        CostSplitter { split_weight: 8, seen: vec![usize::MAX; lines], stamp: 0 }
    }
}

impl Splitter for CostSplitter {
    fn pick(&mut self, segs: &[WorkSeg]) -> Option<usize> {
        self.stamp += 1;
        let w = self.split_weight;
        let cost = |t: &Tally| t.splits * w + t.front.abs_diff(t.back);
        let mut best: Option<(usize, usize)> = None;
        for c in 0..segs.len() {
            let line = segs[c].seg.line;
            if self.seen[line] == self.stamp {
                continue;
            }
            self.seen[line] = self.stamp;
            let bound = best.map_or(usize::MAX, |b| b.0);
            // Splits only grow, so a candidate whose splits alone exceed the best cost is out.
            let Some(t) = tally(segs, c, |t| t.splits * w > bound) else {
                continue;
            };
            if t.divides() && cost(&t) < bound {
                best = Some((cost(&t), c));
            }
        }
        best.map(|(_, c)| c)
    }
}
