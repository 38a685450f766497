//! Per-frame state, owned and cleared (not reallocated) each frame. Two
//! kinds: what the whole frame shares, read by every strip ([`Frame`]'s
//! tables and sprite list, lent out as a [`Scene`]), and what one strip's
//! walk writes ([`StripFrame`]: occlusion bits, clip bounds, visplanes, clip
//! events, the canvas). `Frame` keeps one `StripFrame` per worker thread, so
//! strips can be drawn in parallel, each by whichever worker is free.

use super::buffers::{Buffers, Canvases, FAR};
use super::light::Lighting;
use super::occlusion::Occlusion;
use super::parallel::Pool;
use super::plan::Plan;
use super::shade::Shade;
use super::sprites::VisSprite;
use super::view::{Camera, Rows};
use super::visplanes::Visplanes;
use crate::bsp::Child;
use crate::geom::Aabb;
use crate::level::Level;

/// What one frame cost, for benchmarks and the overdraw tests. With several
/// strips (and threads) these are sums over the strips.
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

impl std::ops::AddAssign for FrameStats {
    fn add_assign(&mut self, o: FrameStats) {
        self.pixels_written += o.pixels_written;
        self.nodes_visited += o.nodes_visited;
        self.subtrees_culled += o.subtrees_culled;
        self.leaves_visited += o.leaves_visited;
        self.walls_considered += o.walls_considered;
        self.walls_drawn += o.walls_drawn;
        self.masked_pixels_written += o.masked_pixels_written;
        self.sprites_in_view += o.sprites_in_view;
    }
}

/// Where a frame's time went, in nanoseconds summed over its strips (and so
/// over its threads), measured only when [`super::RenderOptions::profile`]
/// asks: a stopwatch read per seg costs a few percent of a small frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Breakdown {
    /// Binding the view, the per-frame tables, finding the sprites, planning,
    /// and adding up the workers' totals.
    pub setup: u64,
    /// The BSP walk less its segs' columns: nodes, bounding boxes, leaves,
    /// seg facing and projection, the occlusion array's open runs.
    pub walk: u64,
    /// The segs' columns: walls, per-column floors, ceilings and sky, and
    /// the clip bounds and visplane runs they leave.
    pub walls: u64,
    /// Floors and ceilings drawn as spans after the walk.
    pub spans: u64,
    /// Sprites and see-through middles.
    pub masked: u64,
    /// Copying each strip's column-major canvas into the framebuffer.
    pub copy: u64,
}

impl Breakdown {
    /// The parts in the order a frame runs them, with their names.
    pub fn parts(&self) -> [(&'static str, u64); 6] {
        [
            ("setup", self.setup),
            ("walk", self.walk),
            ("walls", self.walls),
            ("spans", self.spans),
            ("masked", self.masked),
            ("copy", self.copy),
        ]
    }

    pub fn total(&self) -> u64 {
        self.parts().iter().map(|p| p.1).sum()
    }
}

impl std::ops::AddAssign for Breakdown {
    fn add_assign(&mut self, o: Breakdown) {
        self.setup += o.setup;
        self.walk += o.walk;
        self.walls += o.walls;
        self.spans += o.spans;
        self.masked += o.masked;
        self.copy += o.copy;
    }
}

/// A stopwatch that runs only when the frame is profiled (or, in
/// `replay --profile`, the game around it).
#[derive(Clone, Copy)]
pub struct Lap(Option<std::time::Instant>);

impl Lap {
    #[inline]
    pub fn start(profile: bool) -> Lap {
        Lap(profile.then(std::time::Instant::now))
    }

    /// Nanoseconds since the start (0 when not profiling).
    #[inline]
    pub fn ns(self) -> u64 {
        self.0.map_or(0, |t| t.elapsed().as_nanos() as u64)
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

/// What every strip of one frame reads and none writes: set up once per
/// frame by `render_frame`, shared by all workers.
#[derive(Clone, Copy)]
pub(crate) struct Scene<'a> {
    pub level: &'a Level,
    pub cam: &'a Camera,
    pub shade: Shade,
    pub lighting: Lighting,
    /// What the frame does (see [`super::plan`]).
    pub plan: Plan,
    /// Textured planes go to the visplanes as spans (else painted per column).
    pub spans: bool,
    /// Slope of each column's ray.
    pub slopes: &'a [f64],
    /// Each row's slope, for the row predicates.
    pub rows: Rows<'a>,
    /// Inverse of each row's slope: a plane `rise` above the eye is
    /// `rise * inv_rows[y]` away along row `y`'s ray.
    pub inv_rows: &'a [f64],
    /// Things in view, far to near (see [`super::sprites`]).
    pub sprites: &'a [VisSprite],
    /// Time the frame's parts (see [`Breakdown`]).
    pub profile: bool,
    /// The sky's per-frame table (see [`super::planes::SkyView`]).
    pub sky: super::planes::SkyView<'a>,
}

/// The frame as the caller keeps it: the shared tables, the totals of the
/// last frame, and the per-worker strip states and threads.
#[derive(Debug, Default)]
pub struct Frame {
    /// Slope of each column's ray, slope of each row's and its inverse (see [`Scene`]).
    pub(crate) slopes: Vec<f64>,
    pub(crate) row_slopes: Vec<f64>,
    pub(crate) inv_rows: Vec<f64>,
    /// Each row's sky texel row, when the frame has a sky.
    pub(crate) sky_rows: Vec<u32>,
    /// Things in view, far to near.
    pub(crate) sprites: Vec<VisSprite>,
    /// The strips `[x0, x1)` of this frame.
    pub(crate) strips: Vec<(usize, usize)>,
    /// One strip state per worker; `workers[0]` is the calling thread's.
    pub(crate) workers: Vec<StripFrame>,
    /// The threads besides the caller's, kept across frames (see [`super::parallel`]).
    pub(crate) pool: Pool,
    /// Writes per pixel (row-major), kept only when counting was asked for.
    pub(crate) counts: Vec<u16>,
    /// Depth and labels per pixel (row-major), kept only when asked for
    /// (see [`super::buffers`]).
    pub(crate) depth: Vec<f32>,
    pub(crate) labels: Vec<u32>,
    pub stats: FrameStats,
    /// Where the last frame's time went, when it was profiled.
    pub breakdown: Breakdown,
    /// What the last frame did (see [`super::plan`]).
    pub plan: Plan,
    /// Lines that drew at least one column this frame (an automap's "seen").
    pub(crate) seen_lines: Vec<bool>,
}

impl Frame {
    pub fn new() -> Frame {
        Frame::default()
    }

    /// Resets the shared state for a new frame of `cam`'s size, and readies
    /// `workers` strip states.
    pub(crate) fn begin(&mut self, cam: &Camera, count_writes: bool, buffers: Buffers, workers: usize) {
        let (w, h) = (cam.width, cam.height);
        self.slopes.clear();
        self.slopes.extend((0..w).map(|x| cam.column_slope(x)));
        self.row_slopes.clear();
        self.row_slopes.extend(cam.row_slopes());
        self.inv_rows.clear();
        self.inv_rows.extend(self.row_slopes.iter().map(|s| 1.0 / s));
        self.sprites.clear();
        self.counts.clear();
        if count_writes {
            self.counts.resize(w * h, 0);
        }
        // Every pixel is written by the strips' copies; no clearing needed.
        self.depth.resize(if buffers.depth { w * h } else { 0 }, FAR);
        self.labels.resize(if buffers.labels { w * h } else { 0 }, 0);
        self.stats = FrameStats::default();
        self.breakdown = Breakdown::default();
        if self.workers.len() < workers {
            self.workers.resize_with(workers, StripFrame::default);
        }
    }

    /// Adds up what the first `workers` strip states did this frame.
    pub(crate) fn gather(&mut self, workers: usize, lines: usize) {
        self.seen_lines.clear();
        self.seen_lines.resize(lines, false);
        for worker in &self.workers[..workers] {
            self.stats += worker.stats;
            self.breakdown += worker.breakdown;
            for (seen, &s) in self.seen_lines.iter_mut().zip(&worker.seen_lines) {
                *seen |= s;
            }
        }
    }

    /// Which map lines the last frame showed, indexed like `map.lines`.
    pub fn seen_lines(&self) -> &[bool] {
        &self.seen_lines
    }

    /// Writes per pixel of the last frame rendered with counting on (row-major).
    pub fn write_counts(&self) -> &[u16] {
        &self.counts
    }

    /// Camera-space depth of each pixel of the last frame, row-major
    /// (`width * height`), in map units; `f32::INFINITY` for sky and void.
    /// Empty unless the last frame was rendered with
    /// [`super::RenderOptions::buffers`]`.depth` on. The BSP walk, the
    /// ray-caster and the reference fill it; painter's and the z-buffer
    /// (the visibility study) leave it infinite.
    pub fn depth(&self) -> &[f32] {
        &self.depth
    }

    /// `key + 1` of the thing whose sprite shows at each pixel of the last
    /// frame, 0 where none does, row-major (`width * height`). Empty unless
    /// the last frame was rendered with [`super::RenderOptions::buffers`]`.labels`
    /// on. Painter's and the z-buffer, which draw no sprites, leave it 0.
    pub fn labels(&self) -> &[u32] {
        &self.labels
    }
}

/// One worker's state, for the strip it is drawing: the walk's occlusion
/// bits and clip bounds, the strip's visplanes, clip events and masked
/// middles, its canvas, and what its strips cost.
#[derive(Debug, Default)]
pub(crate) struct StripFrame {
    pub(crate) occlusion: Occlusion,
    /// First open row of each column (whole-screen width, so columns keep
    /// their screen index; only the strip's columns are reset and used).
    pub(crate) clip_top: Vec<i32>,
    /// One past the last open row of each column.
    pub(crate) clip_bottom: Vec<i32>,
    /// The walk's stack: a subtree, its box, and whether it lies below a
    /// partition the eye looks along: that line's sideways offset in camera
    /// space (see `bsp::looks_along`).
    pub(crate) stack: Vec<(Child, Option<Aabb>, Option<f64>)>,
    pub(crate) hits: Vec<Hit>,
    /// Column-major canvas of the strip being drawn (see [`super::columns`]),
    /// and its write counts when counting.
    pub(crate) canvas: Vec<u32>,
    pub(crate) counts: Vec<u16>,
    /// Clip events of the strip's columns, and each column's latest (deepest).
    pub(crate) events: Vec<ClipEvent>,
    pub(crate) last_event: Vec<u32>,
    /// Masked middles to draw, and each column's latest entry.
    pub(crate) masked: Vec<MaskedColumn>,
    pub(crate) last_masked: Vec<u32>,
    /// Each column's sky texel column once a sky piece of it has found it
    /// (`NONE` before): a column's sky is the same whichever seg's ceiling
    /// shows it, and finding it takes an `atan` and a float remainder.
    pub(crate) sky_columns: Vec<u32>,
    /// The masked pass's scratch: the texel row of each screen row of the
    /// sprite being drawn.
    pub(crate) sprite_rows: Vec<u32>,
    pub(crate) visplanes: Visplanes,
    /// What this worker's strips cost, and the lines they showed.
    pub(crate) stats: FrameStats,
    pub(crate) breakdown: Breakdown,
    pub(crate) seen_lines: Vec<bool>,
    /// Depth buffer and scratch canvas of the z-buffer renderer (study only).
    pub(crate) zbuffer: super::zbuffer::Buffers,
    /// The strip's depth and label canvases, when the frame asks for them.
    pub(crate) buffers: Canvases,
}

impl StripFrame {
    /// Forgets the last frame: no strips drawn yet, no lines seen.
    pub(crate) fn begin_frame(&mut self, width: usize, lines: usize) {
        self.stats = FrameStats::default();
        self.breakdown = Breakdown::default();
        self.seen_lines.clear();
        self.seen_lines.resize(lines, false);
        for v in [&mut self.clip_top, &mut self.clip_bottom] {
            if v.len() != width {
                v.clear();
                v.resize(width, 0);
            }
        }
        for v in [&mut self.last_event, &mut self.last_masked, &mut self.sky_columns] {
            if v.len() != width {
                v.clear();
                v.resize(width, NONE);
            }
        }
    }

    /// Readies columns `[x0, x1)` of a `height`-row screen for a walk that
    /// sees only them.
    pub(crate) fn begin_strip(&mut self, x0: usize, x1: usize, height: usize, count_writes: bool, buffers: Buffers) {
        let width = self.clip_top.len();
        self.occlusion.reset_to_strip(width, x0, x1);
        self.clip_top[x0..x1].fill(0);
        self.clip_bottom[x0..x1].fill(height as i32);
        self.last_event[x0..x1].fill(NONE);
        self.last_masked[x0..x1].fill(NONE);
        self.sky_columns[x0..x1].fill(NONE);
        self.events.clear();
        self.masked.clear();
        self.visplanes.begin_strip(x0, x1);
        self.stack.clear();
        self.hits.clear();
        self.canvas.resize((x1 - x0) * height, 0);
        self.counts.clear();
        if count_writes {
            self.counts.resize((x1 - x0) * height, 0);
        }
        self.buffers.begin_strip(buffers, (x1 - x0) * height);
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
}
