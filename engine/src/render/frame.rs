//! Per-frame state, owned in one struct and cleared (not reallocated) each
//! frame: the occlusion bits, the per-column clip bounds, scratch lists, and
//! the frame's statistics.

use super::occlusion::Occlusion;
use super::view::Camera;
use crate::bsp::Child;
use crate::geom::Aabb;

/// What one frame cost, for benchmarks and the overdraw tests.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameStats {
    pub pixels_written: u64,
    pub nodes_visited: u64,
    /// Subtrees skipped because their box projects only onto closed columns.
    pub subtrees_culled: u64,
    pub leaves_visited: u64,
    /// Segs (BSP) or lines (reference) looked at.
    pub walls_considered: u64,
    /// Segs or lines that wrote at least one column.
    pub walls_drawn: u64,
}

impl FrameStats {
    /// Pixels written per screen pixel.
    pub fn overdraw(&self, width: usize, height: usize) -> f64 {
        self.pixels_written as f64 / (width * height).max(1) as f64
    }
}

/// One ray's crossing of a line, for the reference renderer.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Hit {
    pub depth: f64,
    pub line: usize,
    /// The viewer is on the line's front side.
    pub from_front: bool,
}

#[derive(Debug, Default)]
pub struct Frame {
    pub(crate) occlusion: Occlusion,
    /// First open row of each column.
    pub(crate) clip_top: Vec<i32>,
    /// One past the last open row of each column.
    pub(crate) clip_bottom: Vec<i32>,
    /// Slope of each column's ray.
    pub(crate) slopes: Vec<f64>,
    pub(crate) stack: Vec<(Child, Option<Aabb>)>,
    pub(crate) hits: Vec<Hit>,
    /// Column-major canvas of the strip being drawn (see [`super::columns`]).
    pub(crate) canvas: Vec<u32>,
    /// Writes per pixel (row-major), kept only when counting was asked for.
    pub(crate) counts: Vec<u16>,
    pub stats: FrameStats,
}

impl Frame {
    pub fn new() -> Frame {
        Frame::default()
    }

    /// Resets everything for a new frame of `cam`'s size.
    pub(crate) fn begin(&mut self, cam: &Camera, count_writes: bool) {
        let (w, h) = (cam.width, cam.height);
        self.occlusion.reset(w);
        self.clip_top.clear();
        self.clip_top.resize(w, 0);
        self.clip_bottom.clear();
        self.clip_bottom.resize(w, h as i32);
        self.slopes.clear();
        self.slopes.extend((0..w).map(|x| cam.column_slope(x)));
        self.stack.clear();
        self.hits.clear();
        self.counts.clear();
        if count_writes {
            self.counts.resize(w * h, 0);
        }
        self.stats = FrameStats::default();
    }

    /// Restricts the next pass to columns `[x0, x1)`; clip bounds there are
    /// already reset by [`Frame::begin`] and untouched by other strips.
    pub(crate) fn begin_strip(&mut self, x0: usize, x1: usize) {
        self.occlusion.reset_to_strip(self.clip_top.len(), x0, x1);
        self.stack.clear();
    }

    /// Writes per pixel of the last frame rendered with counting on (row-major).
    pub fn write_counts(&self) -> &[u16] {
        &self.counts
    }
}
