//! Building the BSP: cut the map's sides into segs along partition lines chosen
//! by a [`Splitter`], until every set of segs bounds one convex cell (a leaf).
//!
//! The build is iterative (an explicit work stack), so a degenerate tree from a
//! bad splitter or a huge map cannot overflow the call stack.

use std::time::Instant;

use glam::DVec2;

use super::exhaustive::{ExhaustiveSplitter, EXHAUSTIVE_LIMIT};
use super::split::{CostSplitter, RandomSplitter, Splitter, SplitterKind};
use super::{Bsp, BuildStats, Child, CompiledMap, Leaf, LineSide, Node, Seg};
use crate::geom::{line_intersection, Aabb};
use crate::map::Map;

/// Points closer than this to a partition line count as on it.
///
/// Why 1e-6: front distances are computed from coordinate differences of at
/// most 2^25 units, where an f64 carries ~4e-9 of rounding; 1e-6 sits well
/// above that noise and well below the smallest feature we support (0.5-unit
/// segments, 1-unit pillars). Treating near-on points as on avoids cutting
/// slivers a billionth of a unit long off segs that merely touch a partition.
pub const ON_EPSILON: f64 = 1e-6;

#[derive(Clone, Debug, Default)]
pub struct BuildOptions {
    pub splitter: SplitterKind,
    /// Seed of the random splitter; ignored by the others.
    pub seed: u64,
}

#[derive(Debug, thiserror::Error)]
pub enum CompileError {
    #[error(
        "a convex cell near ({}, {}) borders both sector {a} and sector {b}; \
         the lines between those sectors do not separate them",
        at.x, at.y
    )]
    MixedLeaf { a: usize, b: usize, at: DVec2 },
    #[error("the exhaustive splitter takes at most {limit} sides (the search is exponential); this map has {sides}")]
    TooLargeForExhaustive { sides: usize, limit: usize },
}

/// A seg under construction and the input side it was cut from.
#[derive(Clone, Debug)]
pub struct WorkSeg {
    pub seg: Seg,
    /// Index of the input side (the random splitter's priority key).
    pub source: usize,
}

/// Where a seg falls relative to a partition line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Class {
    Front,
    Back,
    /// Cut in two; the seg's start (`v1`) is in front when the flag is true.
    Split(bool),
}

/// A partition line `a -> b` with its unit normal, so that classifying a seg
/// costs two dot products.
#[derive(Clone, Copy, Debug)]
pub struct Partition {
    pub a: DVec2,
    pub b: DVec2,
    /// Unit normal pointing to the front (the right of `a -> b`).
    normal: DVec2,
}

impl Partition {
    pub fn new(a: DVec2, b: DVec2) -> Self {
        let d = b - a;
        Partition { a, b, normal: DVec2::new(d.y, -d.x) / d.length() }
    }

    /// The whole map line of `seg`, in the seg's direction. The line's own end
    /// points, not the piece's: a piece's ends are rounded cut points, and a
    /// short piece would tilt the partition by their rounding over the map.
    pub fn of_seg(map: &Map, seg: &Seg) -> Self {
        Partition::of_side(map, seg.line, seg.side)
    }

    /// The whole line `line` in the direction of its side `side`.
    pub fn of_side(map: &Map, line: usize, side: LineSide) -> Self {
        let (from, to) = map.line_points(&map.lines[line]);
        match side {
            LineSide::Front => Partition::new(from, to),
            LineSide::Back => Partition::new(to, from),
        }
    }

    pub fn normal(&self) -> DVec2 {
        self.normal
    }

    /// Signed distance of `p`, positive in front. (Written out, not `dot`, so
    /// that `Blocks::tally` can repeat the exact arithmetic.)
    #[inline]
    pub fn distance(&self, p: DVec2) -> f64 {
        (p.x - self.a.x) * self.normal.x + (p.y - self.a.y) * self.normal.y
    }

    pub fn classify(&self, seg: &Seg) -> Class {
        self.classify_ends(seg.v1, seg.v2)
    }

    /// Where the seg `v1 -> v2` falls; points within `ON_EPSILON` count as on
    /// the line, and a seg on it goes where its own front faces.
    #[inline]
    pub fn classify_ends(&self, v1: DVec2, v2: DVec2) -> Class {
        let (d1, d2) = (self.distance(v1), self.distance(v2));
        let (on1, on2) = (d1.abs() < ON_EPSILON, d2.abs() < ON_EPSILON);
        if on1 && on2 {
            let dir = self.b - self.a;
            let facing = (v2.x - v1.x) * dir.x + (v2.y - v1.y) * dir.y > 0.0;
            return if facing { Class::Front } else { Class::Back };
        }
        if d1 > -ON_EPSILON && d2 > -ON_EPSILON {
            Class::Front
        } else if d1 < ON_EPSILON && d2 < ON_EPSILON {
            Class::Back
        } else {
            Class::Split(d1 > 0.0)
        }
    }
}

/// Cuts `seg` where the partition `a -> b` crosses it.
///
/// The cut point is intersected against the seg's whole map line, always in the
/// line's own direction, so the front and back sides of a two-sided line are
/// cut at bit-identical points and their pieces project to identical columns.
fn split(map: &Map, seg: &Seg, p: &Partition) -> (Seg, Seg) {
    let (from, to) = map.line_points(&map.lines[seg.line]);
    let cut = line_intersection(from, to, p.a, p.b);
    let first = Seg { v2: cut, ..seg.clone() };
    let second = Seg { v1: cut, offset: seg.offset + cut.distance(seg.v1), ..seg.clone() };
    (first, second)
}

/// The input sides of `map` as segs, front side then back side of each line.
fn initial_segs(map: &Map) -> Vec<WorkSeg> {
    let mut segs = Vec::with_capacity(map.lines.len() * 2);
    for (i, line) in map.lines.iter().enumerate() {
        let (from, to) = map.line_points(line);
        let back_sector = line.back.as_ref().map(|b| b.sector);
        let front = Seg {
            v1: from,
            v2: to,
            line: i,
            side: LineSide::Front,
            front_sector: line.front.sector,
            back_sector,
            offset: 0.0,
        };
        segs.push(WorkSeg { seg: front, source: segs.len() });
        if let Some(back) = &line.back {
            let seg = Seg {
                v1: to,
                v2: from,
                line: i,
                side: LineSide::Back,
                front_sector: back.sector,
                back_sector: Some(line.front.sector),
                offset: 0.0,
            };
            segs.push(WorkSeg { seg, source: segs.len() });
        }
    }
    segs
}

fn bbox_of(segs: &[WorkSeg]) -> Aabb {
    let mut bbox = Aabb::EMPTY;
    for s in segs {
        bbox.include(s.seg.v1);
        bbox.include(s.seg.v2);
    }
    bbox
}

/// Where a finished subtree is attached.
#[derive(Clone, Copy)]
enum Slot {
    Root,
    Child(usize, usize),
}

struct Work {
    segs: Vec<WorkSeg>,
    slot: Slot,
    depth: usize,
}

/// Compiles `map` into a BSP with the chosen splitter.
pub fn build(map: &Map, options: &BuildOptions) -> Result<CompiledMap, CompileError> {
    let started = Instant::now();
    let mut segs = initial_segs(map);
    let sides_in = segs.len();
    // Partitioning keeps the order, so every node's segs stay in kd order.
    super::blocks::kd_order(&mut segs);
    let mut splitter: Box<dyn Splitter> = match options.splitter {
        SplitterKind::Random => Box::new(RandomSplitter::new(sides_in, options.seed)),
        SplitterKind::Cost => Box::new(CostSplitter::new(map)),
        SplitterKind::Exhaustive if sides_in > EXHAUSTIVE_LIMIT => {
            return Err(CompileError::TooLargeForExhaustive { sides: sides_in, limit: EXHAUSTIVE_LIMIT })
        }
        SplitterKind::Exhaustive => Box::new(ExhaustiveSplitter::new(map)),
    };
    let mut bsp = Bsp { root: Child::Leaf(0), nodes: Vec::new(), leaves: Vec::new(), segs: Vec::new() };
    let (mut splits, mut depth) = (0, 0);
    let mut stack = vec![Work { segs, slot: Slot::Root, depth: 0 }];
    while let Some(work) = stack.pop() {
        let child = match splitter.pick(map, &work.segs) {
            None => {
                depth = depth.max(work.depth);
                Child::Leaf(make_leaf(&mut bsp, work.segs)?)
            }
            Some(c) => {
                let p = Partition::of_seg(map, &work.segs[c].seg);
                let (front, back, cuts) = partition(map, work.segs, &p);
                splits += cuts;
                let index = bsp.nodes.len();
                let bbox = [bbox_of(&front), bbox_of(&back)];
                bsp.nodes.push(Node { a: p.a, b: p.b, children: [Child::Leaf(0); 2], bbox });
                for (k, segs) in [(1, back), (0, front)] {
                    stack.push(Work { segs, slot: Slot::Child(index, k), depth: work.depth + 1 });
                }
                Child::Node(index)
            }
        };
        match work.slot {
            Slot::Root => bsp.root = child,
            Slot::Child(node, k) => bsp.nodes[node].children[k] = child,
        }
    }
    let stats = BuildStats {
        splitter: options.splitter.name().to_string(),
        seed: options.seed,
        lines_in: map.lines.len(),
        sides_in,
        sides_out: bsp.segs.len(),
        splits,
        nodes: bsp.nodes.len(),
        leaves: bsp.leaves.len(),
        depth,
        build_ms: started.elapsed().as_secs_f64() * 1e3,
    };
    Ok(CompiledMap { map: map.clone(), bsp, stats, grid: None })
}

/// Splits a set of segs by `p`; returns front, back and the number of cuts.
fn partition(map: &Map, segs: Vec<WorkSeg>, p: &Partition) -> (Vec<WorkSeg>, Vec<WorkSeg>, usize) {
    let (mut front, mut back, mut cuts) = (Vec::new(), Vec::new(), 0);
    for w in segs {
        match p.classify(&w.seg) {
            Class::Front => front.push(w),
            Class::Back => back.push(w),
            Class::Split(start_in_front) => {
                cuts += 1;
                let (first, second) = split(map, &w.seg, p);
                let (f, k) = if start_in_front { (first, second) } else { (second, first) };
                front.push(WorkSeg { seg: f, source: w.source });
                back.push(WorkSeg { seg: k, source: w.source });
            }
        }
    }
    (front, back, cuts)
}

fn make_leaf(bsp: &mut Bsp, segs: Vec<WorkSeg>) -> Result<usize, CompileError> {
    let sector = segs[0].seg.front_sector;
    if let Some(other) = segs.iter().find(|s| s.seg.front_sector != sector) {
        return Err(CompileError::MixedLeaf { a: sector, b: other.seg.front_sector, at: other.seg.v1 });
    }
    let leaf = Leaf { first: bsp.segs.len(), count: segs.len(), sector, bbox: bbox_of(&segs) };
    bsp.segs.extend(segs.into_iter().map(|w| w.seg));
    bsp.leaves.push(leaf);
    Ok(bsp.leaves.len() - 1)
}
