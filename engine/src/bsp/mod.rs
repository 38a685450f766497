//! The compiled map: a wall-segment BSP over a validated [`Map`].
//!
//! [`build`] makes it (an autopartition: every partition line is the line of
//! one of the map's segments) with a heuristic from [`split`], which tallies
//! candidate lines over the kd-tree of [`blocks`]; [`file`] stores and loads
//! it, [`check`] verifies its invariants. The renderers walk [`Bsp`] front to
//! back.
//!
//! Invariants of a compiled map:
//! - every input side (one per side of each line) appears in `segs` exactly
//!   once as the union of its pieces;
//! - every seg lies on the side of every ancestor partition that leads to its leaf;
//! - every leaf's segs bound one convex cell, all facing into it, and all have
//!   the leaf's sector in front.

pub mod blocks;
pub mod build;
pub mod check;
pub mod exhaustive;
pub mod file;
pub mod lines;
pub mod rollout;
pub mod split;

use glam::DVec2;
use serde::{Deserialize, Serialize};

use crate::geom::{exact_side, Aabb, Side};
use crate::map::Map;

pub use build::{build, BuildOptions, CompileError};
pub use split::SplitterKind;

/// Which side of its line a seg was cut from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum LineSide {
    Front,
    Back,
}

/// A piece of one side of a line, directed so that its front sector is on its right.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Seg {
    pub v1: DVec2,
    pub v2: DVec2,
    pub line: usize,
    pub side: LineSide,
    /// Sector on the seg's right (the side the seg was cut from).
    pub front_sector: usize,
    /// Sector on its left, for a two-sided line.
    pub back_sector: Option<usize>,
    /// Distance along the side from its start (the line's `from` for a front
    /// side, its `to` for a back side) to `v1`: where textures begin.
    pub offset: f64,
}

/// Reference to a child of a node.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Child {
    Node(usize),
    Leaf(usize),
}

/// An internal node: a partition line (front is its right-hand side) and the
/// two subtrees with the bounding boxes of their segs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Node {
    pub a: DVec2,
    pub b: DVec2,
    /// `[front, back]`.
    pub children: [Child; 2],
    /// Bounding boxes of the segs under `children[0]` and `children[1]`.
    pub bbox: [Aabb; 2],
}

/// A convex cell of one sector (Doom's subsector): `segs[first..first+count]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Leaf {
    pub first: usize,
    pub count: usize,
    pub sector: usize,
    pub bbox: Aabb,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Bsp {
    pub root: Child,
    pub nodes: Vec<Node>,
    pub leaves: Vec<Leaf>,
    pub segs: Vec<Seg>,
}

/// Figures of one compile, as `sightline compile --json` prints them.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BuildStats {
    pub splitter: String,
    pub seed: u64,
    pub lines_in: usize,
    /// One per side of each line.
    pub sides_in: usize,
    /// Side pieces after splitting, counted as Doom counts segs.
    pub sides_out: usize,
    pub splits: usize,
    pub nodes: usize,
    pub leaves: usize,
    /// Internal nodes on the longest root-to-leaf path.
    pub depth: usize,
    pub build_ms: f64,
}

/// A map ready to render: the validated map and its BSP.
#[derive(Clone, Debug, PartialEq)]
pub struct CompiledMap {
    pub map: Map,
    pub bsp: Bsp,
    pub stats: BuildStats,
    /// The grid a grid map was compiled from (the ray-caster draws it).
    pub grid: Option<crate::grid::Grid>,
}

impl Bsp {
    /// The leaf whose closed cell holds `p`, by descent from the root. The
    /// tie rule of point location: **a point on a partition line belongs to
    /// its front (right-hand) side.** Sides are decided exactly (orient2d on
    /// the partition's own end points, which are the map line's vertices),
    /// so "on the line" means on it, not within rounding of it.
    pub fn leaf_at(&self, p: DVec2) -> usize {
        let mut child = self.root;
        loop {
            match child {
                Child::Leaf(i) => return i,
                Child::Node(i) => {
                    let node = &self.nodes[i];
                    let behind = exact_side(node.a, node.b, p) == Side::Back;
                    child = node.children[behind as usize];
                }
            }
        }
    }

    pub fn leaf_segs(&self, leaf: &Leaf) -> &[Seg] {
        &self.segs[leaf.first..leaf.first + leaf.count]
    }
}

impl CompiledMap {
    /// The sector `p` is in, or `None` when `p` is not in the map (in the
    /// void, in a hole, or on a one-sided line: [`Map::contains`]). Every
    /// point in the map gets exactly one sector, points on two-sided lines
    /// and vertices too: the sector of the leaf [`Bsp::leaf_at`] reaches,
    /// so a point on a partition line goes to the partition's front.
    ///
    /// Why that sector touches `p`. Descending exactly, `p` lies in the
    /// closed cell `C` of the leaf `L` reached (the intersection of the
    /// closed half-planes chosen on the way down). The open cell meets no
    /// map line but `L`'s own segs: every seg lies in its own leaf's closed
    /// cell, and open cells are disjoint. Those segs face into `L`'s sector;
    /// behind a one-sided one is void, and a two-sided one lies on a
    /// partition (its other side is a seg of the same place in another
    /// leaf), so on the edge of `C`. So no other sector reaches into the open
    /// cell, and every point of it that is in some sector is in `L`'s. `p`
    /// is in the map's interior, so points of the open cell arbitrarily near
    /// `p` are in sectors: in `L`'s, which therefore touches `p`. (Exact up
    /// to the compiler's `ON_EPSILON`: a seg end within 1e-6 of a partition
    /// counts as on it, so the argument holds wherever no vertex lies that
    /// near a partition line without being on it; the tests check the
    /// answer on every shipped map and on random ones.)
    ///
    /// O(lines) for the containment test plus the descent: for poses, starts
    /// and teleports. Hot paths that know `p` is inside use [`Self::sector_at`].
    pub fn locate(&self, p: DVec2) -> Option<usize> {
        self.map.contains(p).then(|| self.sector_at(p))
    }

    /// The sector of the leaf `p` falls in ([`Bsp::leaf_at`]), unchecked: for
    /// a point outside the map it is some sector near it. For hot paths
    /// (collision) that already know `p` is in the map; else [`Self::locate`].
    pub fn sector_at(&self, p: DVec2) -> usize {
        self.bsp.leaves[self.bsp.leaf_at(p)].sector
    }
}

#[cfg(test)]
mod tests;
