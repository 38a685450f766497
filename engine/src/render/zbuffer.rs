//! The z-buffer renderer, for the visibility study: every map line, in the
//! map's order and without the BSP, drawn from the side facing the eye, each
//! pixel kept only where it is nearer than what the per-pixel depth buffer
//! holds.
//!
//! A line's column is painted as the BSP renderer paints a seg's (through
//! the same [`draw_seg`], into a scratch canvas, with the whole column open):
//! the near sector's ceiling, the wall parts, its floor; an opening paints
//! nothing. Every painted pixel of the column, planes included, takes the
//! line's depth in that column: a floor or ceiling pixel belongs to the
//! sector the ray crosses just before reaching the line, so the nearest line
//! painting a pixel is the one the ray meets first there, the same one the
//! front-to-back walk draws. (Giving plane pixels their own distance along
//! the ray would be wrong: a low ceiling behind a wall is nearer, as an
//! infinite plane, than the high ceiling in front of it.)
//!
//! Left out, as in [`super::painter`]: the masked pass and visplane spans.

use glam::DVec2;

use super::columns::ColumnWriter;
use super::frame::{Scene, StripFrame};
use super::painter::{clear, open_whole_columns, without_deferred};
use super::view::{Camera, NEAR};
use super::walls::draw_seg;
use crate::bsp::{LineSide, Seg};
use crate::geom::cross;
use crate::map::Map;

/// The strip's depth buffer and the scratch canvas a line is painted into
/// before its depth test, column-major like the strip's canvas.
#[derive(Debug, Default)]
pub(crate) struct Buffers {
    depth: Vec<f64>,
    fragments: Vec<u32>,
}

impl Buffers {
    /// Depth-tests rows `[y0, y1)` of column `x` (at `base` in the buffers)
    /// against `depth`, writing the fragments that pass, in runs.
    fn test(&mut self, out: &mut ColumnWriter, x: usize, base: usize, (y0, y1): (i32, i32), depth: f64) {
        let mut y = y0;
        while y < y1 {
            // Skip rows something nearer (or as near: first drawn wins) holds.
            while y < y1 && self.depth[base + y as usize] <= depth {
                y += 1;
            }
            let start = y;
            while y < y1 && self.depth[base + y as usize] > depth {
                self.depth[base + y as usize] = depth;
                y += 1;
            }
            let fragments = &self.fragments;
            out.fill_with(x, start, y, |row| fragments[base + row as usize]);
        }
    }
}

/// Draws the strip `[x0, x1)`: every line, each pixel depth-tested.
pub(crate) fn render(scene: &Scene, frame: &mut StripFrame, out: &mut ColumnWriter, strip: (usize, usize)) {
    let scene = &without_deferred(scene);
    clear(scene, out, strip);
    let (map, cam) = (&scene.level.map, scene.cam);
    let h = cam.height;
    let mut buffers = std::mem::take(&mut frame.zbuffer);
    let n = (strip.1 - strip.0) * h;
    buffers.depth.clear();
    buffers.depth.resize(n, f64::INFINITY);
    buffers.fragments.resize(n, 0);
    for index in 0..map.lines.len() {
        let Some((seg, from, dir)) = facing_seg(map, index, cam) else {
            frame.stats.walls_considered += 1;
            continue;
        };
        let Some((a, b)) = open_whole_columns(scene, &seg, frame, strip) else {
            frame.stats.walls_considered += 1;
            continue;
        };
        let drawn = frame.stats.walls_drawn;
        draw_seg(scene, &seg, frame, &mut ColumnWriter::new(&mut buffers.fragments, strip.0, h, None), None);
        if frame.stats.walls_drawn == drawn {
            // draw_seg turned it away (it decides facing as facing_seg does).
            continue;
        }
        let cross_from = cross(from, dir);
        for x in a..b {
            // The depth draw_seg computed for this column (same expression).
            let depth = cross_from / cross(DVec2::new(1.0, scene.slopes[x]), dir);
            let depth = if depth.is_finite() { depth.max(NEAR) } else { NEAR };
            // What draw_seg left open is the opening it did not paint.
            let (top, bottom) = if frame.occlusion.any_open(x, x + 1) {
                (frame.clip_top[x], frame.clip_bottom[x])
            } else {
                (h as i32, h as i32)
            };
            let base = (x - strip.0) * h;
            buffers.test(out, x, base, (0, top), depth);
            buffers.test(out, x, base, (bottom.max(top), h as i32), depth);
        }
    }
    frame.zbuffer = buffers;
}

/// `map.lines[index]` as a seg from the side that faces the eye, with the
/// line's `from` end and direction in camera space (the numbers draw_seg
/// computes its depths from); `None` edge-on or from behind a solid wall.
fn facing_seg(map: &Map, index: usize, cam: &Camera) -> Option<(Seg, DVec2, DVec2)> {
    let line = &map.lines[index];
    let (a, b) = map.line_points(line);
    let (from, dir) = (cam.to_camera(a), cam.to_camera(b) - cam.to_camera(a));
    let c = cross(from, dir);
    let (front, back) = (line.front.sector, line.back.as_ref().map(|s| s.sector));
    let seg = if c > 0.0 {
        Seg { v1: a, v2: b, line: index, side: LineSide::Front, front_sector: front, back_sector: back, offset: 0.0 }
    } else if c < 0.0 {
        let back = back?;
        Seg {
            v1: b,
            v2: a,
            line: index,
            side: LineSide::Back,
            front_sector: back,
            back_sector: Some(front),
            offset: 0.0,
        }
    } else {
        // Edge-on, or NaN.
        return None;
    };
    Some((seg, from, dir))
}
