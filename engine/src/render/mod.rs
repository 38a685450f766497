//! Rendering a frame: a [`View`] of a compiled map into a [`Framebuffer`].
//!
//! [`render_frame`] is the recipe: bind the view to the screen, reset the
//! per-frame state, run the chosen visibility pass, which writes every pixel
//! exactly once through the shared [`columns::ColumnWriter`].

pub mod bsp;
pub mod columns;
pub mod frame;
pub mod light;
pub mod occlusion;
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

pub use frame::{Frame, FrameStats};
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
}

impl Renderer {
    pub const ALL: [Renderer; 3] = [Renderer::Bsp, Renderer::Reference, Renderer::Raycast];

    pub fn name(self) -> &'static str {
        match self {
            Renderer::Bsp => "bsp",
            Renderer::Reference => "reference",
            Renderer::Raycast => "raycast",
        }
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

    /// Whether this renderer can draw `level`.
    pub fn supports(self, level: &Level) -> bool {
        self != Renderer::Raycast || level.grid().is_some()
    }

    pub fn from_name(name: &str) -> Option<Renderer> {
        Self::ALL.into_iter().find(|r| r.name() == name)
    }
}

#[derive(Clone, Copy, Debug, Default)]
pub struct RenderOptions {
    pub renderer: Renderer,
    pub shade: Shade,
    /// Keep a per-pixel write count (see [`Frame::write_counts`]).
    pub count_writes: bool,
    /// Effects to leave out even where the map asks for them.
    pub disabled: plan::Disabled,
    /// How textured floors and ceilings are drawn.
    pub floors: Floors,
    /// How the ray-caster's rays find walls.
    pub ray: raycast::RayMethod,
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
    let cam = Camera::new(view, fb.width, fb.height);
    frame.begin(&cam, options.count_writes);
    frame.seen_lines.clear();
    frame.seen_lines.resize(level.map.lines.len(), false);
    // The writer borrows the canvas and counts while the pass borrows the rest.
    let mut canvas = std::mem::take(&mut frame.canvas);
    let mut counts = std::mem::take(&mut frame.counts);
    let (w, h) = (cam.width, cam.height);
    if !options.disabled.sprites {
        sprites::collect(level, &cam, frame);
    }
    frame.stats.sprites_in_view = frame.sprites.len() as u64;
    let plan = plan::Plan::new(level, frame.sprites.len(), options.disabled);
    frame.plan = plan;
    frame.spans = options.floors == Floors::Spans;
    let lighting = light::Lighting::for_plan(&level.map, &plan);
    let oracle = (options.renderer == Renderer::Reference).then(|| reference::Reference::new(level, &cam));
    for (x0, x1) in strips::strips(w, h) {
        canvas.resize((x1 - x0) * h, 0);
        let counting = options.count_writes.then_some(counts.as_mut_slice());
        let mut out = columns::ColumnWriter::new(&mut canvas, x0, w, h, counting);
        frame.begin_strip(x0, x1);
        match options.renderer {
            Renderer::Bsp | Renderer::Raycast => {
                if options.renderer == Renderer::Bsp {
                    bsp::render(level, &cam, frame, &mut out, options.shade, &lighting);
                } else {
                    raycast::render(level, &cam, frame, &mut out, options.shade, &lighting, options.ray, (x0, x1));
                }
                let Frame { visplanes, inv_rows, .. } = &mut *frame;
                visplanes.draw(&mut out, &cam, &lighting, inv_rows, &level.materials.textures);
                if plan.masked_pass() {
                    sprites::draw(level, &cam, frame, &mut out, options.shade, &lighting, (x0, x1));
                }
            }
            Renderer::Reference => {
                if let Some(oracle) = &oracle {
                    oracle.render(x0..x1, frame, &mut out, options.shade);
                }
            }
        }
        frame.stats.pixels_written += out.written;
        frame.stats.masked_pixels_written += out.masked_written;
        columns::present_strip(&canvas, x0, x1, fb);
    }
    frame.canvas = canvas;
    frame.counts = counts;
    frame.stats
}
