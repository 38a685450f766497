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
    /// Pixels written by the masked pass (sprites and see-through middles),
    /// on top of the opaque pass's exactly-once.
    pub masked_pixels_written: u64,
    /// Things in view (in front of the eye and on screen).
    pub sprites_in_view: u64,
}

impl FrameStats {
    /// Pixels written per screen pixel.
    pub fn overdraw(&self, width: usize, height: usize) -> f64 {
        self.pixels_written as f64 / (width * height).max(1) as f64
    }
}

/// What a column's walk left open beyond a depth: after the seg at `depth`
/// was drawn there, only rows `[top, bottom)` still show what lies behind it
/// (empty once the column closed). Sprites and masked middles farther away
/// are clipped to the window of the last event nearer than they are.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ClipEvent {
    pub depth: f64,
    pub top: i32,
    pub bottom: i32,
    /// The column's previous (nearer) event, or `NONE`.
    pub prev: u32,
}

/// A see-through middle texture to draw in one column, in depth order with
/// the sprites: the seg's line and side, where the texture column falls, and
/// the clip event its own opening left.
#[derive(Clone, Copy, Debug)]
pub(crate) struct MaskedColumn {
    pub depth: f64,
    pub line: usize,
    pub back_side: bool,
    pub u: f64,
    pub event: u32,
    /// The column's previous masked entry, or `NONE`.
    pub prev: u32,
}

/// End of a per-column list.
pub(crate) const NONE: u32 = u32::MAX;

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
    /// Inverse of each row's slope: a plane `rise` above the eye is
    /// `rise * inv_rows[y]` away along row `y`'s ray.
    pub(crate) inv_rows: Vec<f64>,
    pub(crate) stack: Vec<(Child, Option<Aabb>)>,
    pub(crate) hits: Vec<Hit>,
    /// Column-major canvas of the strip being drawn (see [`super::columns`]).
    pub(crate) canvas: Vec<u32>,
    /// Clip events of all columns, and each column's latest (deepest).
    pub(crate) events: Vec<ClipEvent>,
    pub(crate) last_event: Vec<u32>,
    /// Masked middles to draw, and each column's latest entry.
    pub(crate) masked: Vec<MaskedColumn>,
    pub(crate) last_masked: Vec<u32>,
    /// Things in view, far to near (see [`super::sprites`]).
    pub(crate) sprites: Vec<super::sprites::VisSprite>,
    /// Writes per pixel (row-major), kept only when counting was asked for.
    pub(crate) counts: Vec<u16>,
    pub stats: FrameStats,
    /// What the last frame did (see [`super::plan`]).
    pub plan: super::plan::Plan,
    /// Textured planes go to `visplanes` as spans (else painted per column).
    pub(crate) spans: bool,
    pub(crate) visplanes: super::visplanes::Visplanes,
    /// Lines that drew at least one column this frame (an automap's "seen").
    pub(crate) seen_lines: Vec<bool>,
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
        self.inv_rows.clear();
        self.inv_rows.extend((0..h as i32).map(|y| 1.0 / cam.row_slope(y)));
        self.stack.clear();
        self.hits.clear();
        self.events.clear();
        self.last_event.clear();
        self.last_event.resize(w, NONE);
        self.masked.clear();
        self.last_masked.clear();
        self.last_masked.resize(w, NONE);
        self.sprites.clear();
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
        self.visplanes.begin_strip(x0, x1);
        self.stack.clear();
    }

    /// Records that beyond `depth`, column `x` shows only rows `[top, bottom)`.
    #[inline]
    pub(crate) fn push_event(&mut self, x: usize, depth: f64, top: i32, bottom: i32) -> u32 {
        let index = self.events.len() as u32;
        self.events.push(ClipEvent { depth, top, bottom, prev: self.last_event[x] });
        self.last_event[x] = index;
        index
    }

    /// Queues a masked middle column for the masked pass.
    pub(crate) fn push_masked(&mut self, x: usize, depth: f64, line: usize, back_side: bool, u: f64, event: u32) {
        let index = self.masked.len() as u32;
        self.masked.push(MaskedColumn { depth, line, back_side, u, event, prev: self.last_masked[x] });
        self.last_masked[x] = index;
    }

    /// Rows `[top, bottom)` of column `x` through which something at `depth`
    /// can be seen: the window of the last clip event nearer than it.
    pub(crate) fn window(&self, x: usize, depth: f64, height: i32) -> (i32, i32) {
        let mut e = self.last_event[x];
        while e != NONE {
            let event = &self.events[e as usize];
            if event.depth < depth {
                return (event.top, event.bottom);
            }
            e = event.prev;
        }
        (0, height)
    }

    /// Which map lines the last frame showed, indexed like `map.lines`.
    pub fn seen_lines(&self) -> &[bool] {
        &self.seen_lines
    }

    /// Writes per pixel of the last frame rendered with counting on (row-major).
    pub fn write_counts(&self) -> &[u16] {
        &self.counts
    }
}
