//! Rendering a frame: a [`View`] of a compiled map into a [`Framebuffer`].
//!
//! [`render_frame`] is the recipe: bind the view to the screen, reset the
//! per-frame state, find the sprites in view and plan the frame, then per
//! strip of the screen (on one thread or several, see [`parallel`]) run the
//! chosen visibility pass, which writes every pixel exactly once through the
//! shared [`columns::ColumnWriter`], the strip's floors and ceilings and its
//! masked pass, and copy the strip into the framebuffer.

pub mod bsp;
pub mod buffers;
pub mod columns;
pub mod frame;
pub mod light;
pub mod occlusion;
pub mod painter;
pub mod parallel;
pub mod plan;
pub mod planes;
pub mod precision;
pub mod raycast;
pub mod rays;
pub mod reference;
pub mod shade;
pub mod sprites;
pub mod strips;
pub mod view;
pub mod visplanes;
pub mod walls;
pub mod zbuffer;

pub use buffers::Buffers;
pub use frame::{Breakdown, Frame, FrameStats, Lap};
use frame::{Scene, StripFrame};
pub use shade::Shade;
pub use view::{Camera, View};

use crate::framebuffer::Framebuffer;
use crate::level::Level;

/// The visibility algorithms `--renderer` selects.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Renderer {
    /// Front-to-back BSP walk with the column occlusion array.
    #[default]
    Bsp,
    /// Brute-force f64 ray per column against every line: the oracle.
    Reference,
    /// Grid ray-casting, one ray per column (grid maps only; other maps draw
    /// as void).
    Raycast,
    /// Painter's algorithm: the BSP walked far side first, every facing seg
    /// drawn whole over what is there (no occlusion; see [`painter`]).
    Painter,
    /// Every map line drawn, in map order, through a per-pixel depth buffer
    /// (no BSP at all; see [`zbuffer`]).
    Zbuffer,
}

impl Renderer {
    pub const ALL: [Renderer; 5] =
        [Renderer::Bsp, Renderer::Reference, Renderer::Raycast, Renderer::Painter, Renderer::Zbuffer];

    pub fn name(self) -> &'static str {
        match self {
            Renderer::Bsp => "bsp",
            Renderer::Reference => "reference",
            Renderer::Raycast => "raycast",
            Renderer::Painter => "painter",
            Renderer::Zbuffer => "zbuffer",
        }
    }

    /// Whether the opaque pass writes every pixel exactly once. Painter's and
    /// the z-buffer overwrite by design: that overdraw is what they measure.
    pub fn writes_each_pixel_once(self) -> bool {
        !matches!(self, Renderer::Painter | Renderer::Zbuffer)
    }

    /// The renderer a level is drawn with by default: the ray-caster for a
    /// grid map, the BSP renderer otherwise.
    pub fn default_for(level: &Level) -> Renderer {
        if level.grid().is_some() {
            Renderer::Raycast
        } else {
            Renderer::Bsp
        }
    }

    /// Whether this renderer fills the depth and label buffers
    /// ([`RenderOptions::buffers`]). Painter's and the z-buffer, kept for the
    /// visibility study, leave depth infinite and labels 0.
    pub fn fills_buffers(self) -> bool {
        !matches!(self, Renderer::Painter | Renderer::Zbuffer)
    }

    /// Whether this renderer can draw `level`.
    pub fn supports(self, level: &Level) -> bool {
        self != Renderer::Raycast || level.grid().is_some()
    }

    pub fn from_name(name: &str) -> Option<Renderer> {
        Self::ALL.into_iter().find(|r| r.name() == name)
    }
}

#[derive(Clone, Copy, Debug)]
pub struct RenderOptions {
    pub renderer: Renderer,
    pub shade: Shade,
    /// Keep a per-pixel write count (see [`Frame::write_counts`]).
    pub count_writes: bool,
    /// Effects to leave out even where the map asks for them.
    pub disabled: plan::Disabled,
    /// How textured floors and ceilings are drawn.
    pub floors: Floors,
    /// Texture sampling other than Doom's nearest, perspective-correct
    /// default (the sampling study; affine applies to per-column floors).
    pub sampling: columns::Sampling,
    /// How the ray-caster's rays find walls.
    pub ray: raycast::RayMethod,
    /// Threads drawing the frame's strips: 1 (or 0) draws them one after
    /// another on the calling thread; more start a pool kept in the [`Frame`]
    /// (see [`parallel`]). The frame is the same whatever the count.
    pub threads: usize,
    /// Time the frame's parts into [`Frame::breakdown`] (a few percent slower).
    pub profile: bool,
    /// Per-pixel buffers to fill besides the colour: depth and thing labels
    /// ([`Frame::depth`], [`Frame::labels`]). Off, they cost nothing per pixel.
    pub buffers: Buffers,
}

impl Default for RenderOptions {
    fn default() -> RenderOptions {
        RenderOptions {
            renderer: Renderer::default(),
            shade: Shade::default(),
            count_writes: false,
            disabled: plan::Disabled::default(),
            floors: Floors::default(),
            ray: raycast::RayMethod::default(),
            threads: 1,
            sampling: columns::Sampling::default(),
            profile: false,
            buffers: Buffers::default(),
        }
    }
}

/// Textured floors and ceilings as horizontal spans (Doom's visplanes) or per
/// column; the measured figures that chose the default are in ARCHITECTURE.md.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Floors {
    #[default]
    Spans,
    Columns,
}

/// Renders one frame and returns what it cost.
pub fn render_frame(
    level: &Level,
    view: &View,
    options: &RenderOptions,
    frame: &mut Frame,
    fb: &mut Framebuffer,
) -> FrameStats {
    let setup = Lap::start(options.profile);
    let cam = Camera::new(view, fb.width, fb.height);
    let (w, h) = (cam.width, cam.height);
    let threads = options.threads.max(1);
    frame.begin(&cam, options.count_writes, options.buffers, threads);
    if !options.disabled.sprites {
        sprites::collect(level, &cam, &frame.slopes, &mut frame.sprites);
    }
    let plan = plan::Plan::new(level, frame.sprites.len(), options.disabled);
    frame.plan = plan;
    frame.strips.clear();
    frame.strips.extend(strips::strips(w, h, threads));
    let oracle = (options.renderer == Renderer::Reference)
        .then(|| reference::Reference::new(level, &cam).leaving_out(options.disabled));
    let sky_height = level.materials.sky.map(|t| level.materials.textures.get(t).height).filter(|_| plan.sky);
    frame.sky_rows.clear();
    if let Some(height) = sky_height {
        frame.sky_rows.extend(frame.row_slopes.iter().map(|&s| planes::sky_row(height, s) as u32));
    }
    let Frame { slopes, row_slopes, inv_rows, sky_rows, sprites, strips, workers, pool, counts, depth, labels, .. } =
        frame;
    let scene = Scene {
        level,
        cam: &cam,
        shade: options.shade,
        lighting: light::Lighting::for_plan(&level.map, &plan),
        plan,
        spans: options.floors == Floors::Spans,
        slopes,
        rows: view::Rows { cam: &cam, slopes: row_slopes },
        inv_rows,
        sprites,
        profile: options.profile,
        sky: planes::SkyView { angle: cam.angle_radians(), texture_height: sky_height.unwrap_or(0), rows: sky_rows },
    };
    let stream = w * h * 4 > columns::STREAM_BYTES;
    let mut setup_ns = setup.ns();
    let lines = level.map.lines.len();
    let draw = |strip: &mut StripFrame, (x0, x1)| draw_strip(&scene, options, oracle.as_ref(), strip, (x0, x1));
    let pool = if threads > 1 && strips.len() > 1 { pool.get(threads - 1) } else { None };
    let used = match pool {
        None => {
            let strip = &mut workers[0];
            strip.begin_frame(w, lines);
            for &(x0, x1) in strips.iter() {
                draw(strip, (x0, x1));
                let copy = Lap::start(options.profile);
                let rows = fb.pixels.chunks_exact_mut(w).map(|r| &mut r[x0..x1]);
                columns::present_pixels_to(&strip.canvas, h, rows, stream);
                columns::present_strip(&strip.counts, h, counts.chunks_exact_mut(w).map(|r| &mut r[x0..x1]));
                strip.buffers.present(
                    h,
                    depth.chunks_exact_mut(w).map(|r| &mut r[x0..x1]),
                    labels.chunks_exact_mut(w).map(|r| &mut r[x0..x1]),
                );
                strip.breakdown.copy += copy.ns();
            }
            1
        }
        Some(pool) => {
            let used = threads.min(strips.len());
            for strip in &mut workers[..used] {
                strip.begin_frame(w, lines);
            }
            let rows = parallel::split_rows(&mut fb.pixels, w, strips);
            let mut count_rows = parallel::split_rows(counts, w, strips).into_iter();
            let mut depth_rows = parallel::split_rows(depth, w, strips).into_iter();
            let mut label_rows = parallel::split_rows(labels, w, strips).into_iter();
            let jobs = strips
                .iter()
                .zip(rows)
                .map(|(&(x0, x1), rows)| parallel::Job {
                    x0,
                    x1,
                    rows,
                    counts: count_rows.next().unwrap_or_default(),
                    depth: depth_rows.next().unwrap_or_default(),
                    labels: label_rows.next().unwrap_or_default(),
                })
                .collect();
            parallel::run(pool, &mut workers[..used], jobs, &|strip, job| {
                draw(strip, (job.x0, job.x1));
                let copy = Lap::start(options.profile);
                columns::present_pixels_to(&strip.canvas, h, job.rows.into_iter(), stream);
                columns::present_strip(&strip.counts, h, job.counts.into_iter());
                strip.buffers.present(h, job.depth.into_iter(), job.labels.into_iter());
                strip.breakdown.copy += copy.ns();
            });
            used
        }
    };
    let gather = Lap::start(options.profile);
    frame.gather(used, lines);
    frame.stats.sprites_in_view = frame.sprites.len() as u64;
    setup_ns += gather.ns();
    frame.breakdown.setup += setup_ns;
    frame.stats
}

/// Draws columns `[x0, x1)` into `strip`'s canvas: the visibility pass, then
/// the strip's visplanes, then the masked pass.
fn draw_strip(
    scene: &Scene,
    options: &RenderOptions,
    oracle: Option<&reference::Reference>,
    strip: &mut StripFrame,
    (x0, x1): (usize, usize),
) {
    let h = scene.cam.height;
    strip.begin_strip(x0, x1, h, options.count_writes, options.buffers);
    // The writer borrows the canvases and counts while the pass borrows the rest.
    let mut canvas = std::mem::take(&mut strip.canvas);
    let mut counts = std::mem::take(&mut strip.counts);
    let mut buffers = std::mem::take(&mut strip.buffers);
    let counting = options.count_writes.then_some(counts.as_mut_slice());
    let mut out = columns::ColumnWriter::new(&mut canvas, x0, h, counting);
    out.sampling = options.sampling;
    if options.renderer.fills_buffers() {
        out.buffers = buffers.writer(x0, h);
    } else {
        buffers.depth.fill(buffers::FAR);
    }
    match options.renderer {
        Renderer::Bsp | Renderer::Raycast => {
            // The walk's own time is what its segs' columns did not take.
            let (walk, walls) = (Lap::start(scene.profile), strip.breakdown.walls);
            if options.renderer == Renderer::Bsp {
                bsp::render(scene, strip, &mut out);
            } else {
                raycast::render(scene, strip, &mut out, options.ray, (x0, x1));
            }
            strip.breakdown.walk += walk.ns().saturating_sub(strip.breakdown.walls - walls);
            let spans = Lap::start(scene.profile);
            let cam = scene.cam;
            strip.visplanes.draw(&mut out, cam, &scene.lighting, scene.inv_rows, &scene.level.materials.textures);
            strip.breakdown.spans += spans.ns();
            if scene.plan.masked_pass() {
                let masked = Lap::start(scene.profile);
                sprites::draw(scene, strip, &mut out, (x0, x1));
                strip.breakdown.masked += masked.ns();
            }
        }
        Renderer::Reference => {
            if let Some(oracle) = oracle {
                oracle.render(x0..x1, strip, &mut out, options.shade);
            }
        }
        Renderer::Painter => painter::render(scene, strip, &mut out, (x0, x1)),
        Renderer::Zbuffer => zbuffer::render(scene, strip, &mut out, (x0, x1)),
    }
    strip.stats.pixels_written += out.written;
    strip.stats.masked_pixels_written += out.masked_written;
    strip.canvas = canvas;
    strip.counts = counts;
    strip.buffers = buffers;
}
