//! Rollouts: the cost splitter's choice at small nodes. Greedy cost picks the
//! line with the fewest splits now; a rollout follows each of the few
//! cheapest lines through the whole subtree the greedy splitter would build
//! below it, and picks the line whose subtree splits least in total (one step
//! of lookahead, greedy after it). Most of a Doom map's splits are made in
//! nodes of fewer than 64 segs (freedoom1, greedy with split weight 128:
//! 9,000 of 11,700), where a subtree is cheap to simulate.
//!
//! The simulation cuts pieces at `v1 + (v2 - v1) * t` rather than against
//! the seg's map line as the build does; it only ranks candidates, and the
//! build re-derives every cut exactly.

use glam::DVec2;

use super::build::{Class, Partition, WorkSeg, ON_EPSILON};
use super::lines::LineTable;
use super::LineSide;

/// A seg in the simulation: its end points and its line's side.
#[derive(Clone, Copy, Debug)]
struct Piece {
    v1: DVec2,
    v2: DVec2,
    line: u32,
    side: LineSide,
}

/// Counts of one candidate over a set of pieces.
#[derive(Clone, Copy, Debug, Default)]
struct Counts {
    front: usize,
    back: usize,
    splits: usize,
}

/// Scratch for rollouts, kept across nodes so the build allocates nothing per node.
#[derive(Debug, Default)]
pub struct Rollout {
    /// The node's pieces, then every simulated subset appended after them.
    pieces: Vec<Piece>,
    /// Classes of one partition's pieces, so that each is classified once.
    classes: Vec<Class>,
    /// Subsets of `pieces` still to simulate.
    stack: Vec<(usize, usize)>,
    /// The node's candidates: (cost, splits, seg index), cheapest first.
    ranked: Vec<(usize, usize, usize)>,
    /// `seen[group] == stamp` when the group was already tried in this set.
    seen: Vec<u32>,
    stamp: u32,
}

impl Rollout {
    pub fn new(groups: usize) -> Self {
        Rollout { seen: vec![0; groups], ..Default::default() }
    }

    /// The partition for a small node: the cheapest candidate (cost
    /// `splits * weight + |front - back|`) if it splits nothing, else of the
    /// `follow` cheapest the one whose rolled-out subtree splits least (ties
    /// to the cheaper). `None` when no candidate divides (a leaf).
    pub fn pick(&mut self, lines: &LineTable, segs: &[WorkSeg], weight: usize, follow: usize) -> Option<usize> {
        self.pieces.clear();
        self.pieces.extend(segs.iter().map(|w| Piece {
            v1: w.seg.v1,
            v2: w.seg.v2,
            line: w.seg.line as u32,
            side: w.seg.side,
        }));
        self.stamp += 1;
        self.ranked.clear();
        for (c, s) in segs.iter().enumerate() {
            let g = lines.group(s.seg.line);
            if std::mem::replace(&mut self.seen[g], self.stamp) == self.stamp {
                continue;
            }
            let Some(t) = counts(&self.pieces, lines.part_of(&s.seg), |_, _| false) else {
                continue;
            };
            if t.back > 0 || t.splits > 0 {
                self.ranked.push((t.splits * weight + t.front.abs_diff(t.back), t.splits, c));
            }
        }
        self.ranked.sort_unstable();
        let &(_, splits, first) = self.ranked.first()?;
        let follow = follow.min(self.ranked.len());
        if splits == 0 || follow < 2 {
            return Some(first);
        }
        let mut best: Option<(usize, usize, usize)> = None;
        for k in 0..follow {
            let (cost, splits, c) = self.ranked[k];
            // A total equal to the best still wins if cheaper now.
            let bound = best.map_or(usize::MAX, |b| b.0 + 1);
            if splits >= bound {
                continue;
            }
            let part = *lines.part_of(&segs[c].seg);
            let total = self.splits_below(lines, &part, weight, bound);
            if best.is_none_or(|b| (total, cost) < (b.0, b.1)) {
                best = Some((total, cost, c));
            }
        }
        Some(best.map_or(first, |b| b.2))
    }

    /// Splits made by partitioning the node's pieces by `part` and then
    /// greedily below, or something at least `give_up_at` once it is reached.
    fn splits_below(&mut self, lines: &LineTable, part: &Partition, weight: usize, give_up_at: usize) -> usize {
        let n = self.pieces.len();
        let mut total = self.partition(0, n, part);
        while let Some((s, e)) = self.stack.pop() {
            if total >= give_up_at {
                break;
            }
            if let Some(best) = self.greedy(lines, s, e, weight) {
                total += self.partition(s, e, &best);
            }
        }
        self.stack.clear();
        self.pieces.truncate(n);
        total
    }

    /// The cheapest partition of pieces `s..e`, every candidate tried.
    fn greedy(&mut self, lines: &LineTable, s: usize, e: usize, weight: usize) -> Option<Partition> {
        self.stamp += 1;
        let mut best: Option<(usize, Partition)> = None;
        for k in s..e {
            let p = self.pieces[k];
            let g = lines.group(p.line as usize);
            if std::mem::replace(&mut self.seen[g], self.stamp) == self.stamp {
                continue;
            }
            let part = lines.part(p.line as usize, p.side);
            let bound = best.map_or(usize::MAX, |b| b.0);
            let give_up =
                |t: &Counts, left: usize| t.splits * weight + t.front.abs_diff(t.back).saturating_sub(left) >= bound;
            let Some(t) = counts(&self.pieces[s..e], part, give_up) else {
                continue;
            };
            let cost = t.splits * weight + t.front.abs_diff(t.back);
            if (t.back > 0 || t.splits > 0) && cost < bound {
                best = Some((cost, *part));
            }
        }
        best.map(|b| b.1)
    }

    /// Appends the front pieces of `s..e` and then the back ones, pushes both
    /// subsets for simulation, and returns the number of cuts.
    fn partition(&mut self, s: usize, e: usize, part: &Partition) -> usize {
        self.classes.clear();
        self.classes.extend(self.pieces[s..e].iter().map(|p| part.classify_ends(p.v1, p.v2)));
        let mut cuts = 0;
        let front = self.pieces.len();
        for (k, class) in (s..e).zip(0..) {
            let p = self.pieces[k];
            match self.classes[class] {
                Class::Front => self.pieces.push(p),
                Class::Back => {}
                Class::Split(start_in_front) => {
                    cuts += 1;
                    let cut = cut_point(part, p);
                    self.pieces.push(if start_in_front { Piece { v2: cut, ..p } } else { Piece { v1: cut, ..p } });
                }
            }
        }
        let back = self.pieces.len();
        for (k, class) in (s..e).zip(0..) {
            let p = self.pieces[k];
            match self.classes[class] {
                Class::Front => {}
                Class::Back => self.pieces.push(p),
                Class::Split(start_in_front) => {
                    let cut = cut_point(part, p);
                    self.pieces.push(if start_in_front { Piece { v1: cut, ..p } } else { Piece { v2: cut, ..p } });
                }
            }
        }
        // A single seg is convex already.
        for (from, to) in [(front, back), (back, self.pieces.len())] {
            if to - from > 1 {
                self.stack.push((from, to));
            }
        }
        cuts
    }
}

fn cut_point(part: &Partition, p: Piece) -> DVec2 {
    let (d1, d2) = (part.distance(p.v1), part.distance(p.v2));
    p.v1 + (p.v2 - p.v1) * (d1 / (d1 - d2))
}

/// Classifies every piece against `part`, or `None` once `give_up(counts,
/// pieces left)` says so (asked every 8 pieces).
fn counts(pieces: &[Piece], part: &Partition, give_up: impl Fn(&Counts, usize) -> bool) -> Option<Counts> {
    let (a, n, dir) = (part.a, part.normal(), part.b - part.a);
    let mut t = Counts::default();
    let mut left = pieces.len();
    for chunk in pieces.chunks(8) {
        for p in chunk {
            // `Partition::classify_ends`, branch-free, as in `Blocks::tally`.
            let d1 = (p.v1.x - a.x) * n.x + (p.v1.y - a.y) * n.y;
            let d2 = (p.v2.x - a.x) * n.x + (p.v2.y - a.y) * n.y;
            let in_front = (d1 > -ON_EPSILON) & (d2 > -ON_EPSILON);
            let behind = (d1 < ON_EPSILON) & (d2 < ON_EPSILON);
            let facing = (p.v2.x - p.v1.x) * dir.x + (p.v2.y - p.v1.y) * dir.y > 0.0;
            let on = in_front & behind;
            t.front += ((in_front & !on) | (on & facing)) as usize;
            t.back += ((behind & !on) | (on & !facing)) as usize;
            t.splits += (!in_front & !behind) as usize;
        }
        left -= chunk.len();
        if give_up(&t, left) {
            return None;
        }
    }
    Some(t)
}
