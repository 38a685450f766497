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

use crate::geom::Aabb;
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
    /// The leaf whose cell contains `p` (points on a partition go to its front).
    pub fn leaf_at(&self, p: DVec2) -> usize {
        let mut child = self.root;
        loop {
            match child {
                Child::Leaf(i) => return i,
                Child::Node(i) => {
                    let node = &self.nodes[i];
                    let behind = crate::geom::front_distance(node.a, node.b, p) < 0.0;
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
    /// The sector under `p` by BSP point location.
    pub fn sector_at(&self, p: DVec2) -> usize {
        self.bsp.leaves[self.bsp.leaf_at(p)].sector
    }
}

#[cfg(test)]
mod tests;
