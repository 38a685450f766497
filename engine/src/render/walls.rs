//! One seg's columns: the front sector's ceiling above the wall, its floor
//! below, and between them a solid wall (closing the column) or, for a
//! two-sided line, the upper and lower walls around the opening, which narrows
//! the column's clip bounds for what lies beyond.
//!
//! Floors and ceilings are flat colours per sector here, filled per column in
//! the same pass; they need no separate plane stage until they are textured.

use super::columns::ColumnWriter;
use super::frame::Frame;
use super::shade::{ceiling_at_line, colour, plane_surfaces, wall_facing, Shade, Surface};
use super::view::{Camera, NEAR};
use glam::DVec2;

use crate::bsp::{LineSide, Seg};
use crate::geom::cross;
use crate::map::Map;

/// Heights and colours of one seg, fixed for all its columns, and its map
/// line in camera space for the per-column depth.
struct SegColumns {
    /// The line's direction (`to - from`), camera space.
    dir: DVec2,
    /// `cross(from, dir)`: depth at slope t is `cross_from / cross((1, t), dir)`.
    cross_from: f64,
    ceiling: f64,
    floor: f64,
    /// Back sector's ceiling and floor, for a two-sided line.
    back: Option<(f64, f64)>,
    ceiling_colour: u32,
    floor_colour: u32,
    wall_colour: u32,
}

pub fn draw_seg(
    map: &Map,
    cam: &Camera,
    seg: &Seg,
    frame: &mut Frame,
    out: &mut ColumnWriter,
    shade: Shade,
) {
    frame.stats.walls_considered += 1;
    // Facing and depth come from the whole map line in camera space, in the
    // line's own direction: the same numbers for every piece and both sides,
    // and the same the reference computes, so edge cases resolve alike.
    // (Camera space mirrors the map, so the eye is in front when this is > 0.)
    let (from, to) = map.line_points(&map.lines[seg.line]);
    let (from, dir) = (cam.to_camera(from), cam.to_camera(to) - cam.to_camera(from));
    let cross_from = cross(from, dir);
    let facing = match seg.side {
        LineSide::Front => cross_from > 0.0,
        LineSide::Back => cross_from < 0.0,
    };
    // Zero is edge-on; NaN fails both comparisons.
    if !facing || !cross_from.is_finite() {
        return;
    }
    let Some((x0, x1)) = cam.project_span(cam.to_camera(seg.v1), cam.to_camera(seg.v2)) else {
        return;
    };
    let front = &map.sectors[seg.front_sector];
    let back = seg.back_sector.map(|b| &map.sectors[b]);
    let light = front.light;
    let (ceiling_surface, floor_surface) = plane_surfaces(seg.front_sector, front);
    let cols = SegColumns {
        dir,
        cross_from,
        ceiling: ceiling_at_line(front, back),
        floor: front.floor,
        back: back.map(|b| (b.ceiling, b.floor)),
        ceiling_colour: colour(shade, ceiling_surface, light, 1.0),
        floor_colour: colour(shade, floor_surface, light, 1.0),
        wall_colour: colour(
            shade,
            Surface::Wall { line: seg.line },
            light,
            wall_facing(seg.v2 - seg.v1),
        ),
    };
    let mut drew = false;
    let mut x = x0;
    while let Some(start) = frame.occlusion.next_open(x, x1) {
        let stop = frame.occlusion.next_closed(start, x1);
        for col in start..stop {
            draw_column(cam, &cols, col, frame, out);
        }
        drew = true;
        x = stop;
    }
    frame.stats.walls_drawn += u64::from(drew);
}

#[inline]
fn draw_column(cam: &Camera, s: &SegColumns, x: usize, frame: &mut Frame, out: &mut ColumnWriter) {
    let depth = s.cross_from / cross(DVec2::new(1.0, frame.slopes[x]), s.dir);
    // Columns inside the near-clipped span are at depth >= NEAR up to rounding.
    let depth = if depth.is_finite() {
        depth.max(NEAR)
    } else {
        NEAR
    };
    let row = |height: f64| cam.first_row_at_or_below(depth, height);
    let (top, bottom) = (frame.clip_top[x], frame.clip_bottom[x]);
    let ceiling_end = row(s.ceiling).clamp(top, bottom);
    let floor_start = row(s.floor).clamp(ceiling_end, bottom);
    out.fill(x, top, ceiling_end, s.ceiling_colour);
    out.fill(x, floor_start, bottom, s.floor_colour);
    match s.back {
        None => {
            out.fill(x, ceiling_end, floor_start, s.wall_colour);
            frame.occlusion.close(x);
        }
        Some((back_ceiling, back_floor)) => {
            // The opening is below both ceilings and above both floors.
            let upper_end = row(back_ceiling).clamp(ceiling_end, floor_start);
            let lower_start = row(back_floor).clamp(upper_end, floor_start);
            out.fill(x, ceiling_end, upper_end, s.wall_colour);
            out.fill(x, lower_start, floor_start, s.wall_colour);
            if upper_end >= lower_start {
                frame.occlusion.close(x);
            } else {
                frame.clip_top[x] = upper_end;
                frame.clip_bottom[x] = lower_start;
            }
        }
    }
}
