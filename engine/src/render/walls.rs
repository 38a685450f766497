//! One seg's columns: the front sector's ceiling above the wall, its floor
//! below, and between them a solid wall (closing the column) or, for a
//! two-sided line, the upper and lower walls around the opening, which narrows
//! the column's clip bounds for what lies beyond.
//!
//! Each part is painted flat (ids, flat shading, untextured surfaces) or from
//! its texture, pegged as Doom pegs it; the planes go to [`super::planes`].

use glam::DVec2;

use super::bsp::onto_partition;
use super::columns::ColumnWriter;
use super::frame::{Lap, Scene, StripFrame};
use super::light::fake_contrast;
use super::plan::Plan;
use super::planes::{paint_plane, PlanePaint};
use super::shade::{ceiling_at_line, colour, plane_lights, plane_surfaces, side_offsets, wall_facing, Shade, Surface};
use super::view::NEAR;
use super::visplanes::PlaneKey;
use crate::bsp::{LineSide, Seg};
use crate::geom::cross;
use crate::level::Level;
use crate::map::{Line, Sector, Side};
use crate::materials::SideTextures;
use crate::texture::{Texture, TextureId};

/// How a wall part is painted.
#[derive(Clone, Copy)]
enum Paint<'a> {
    Solid(u32),
    /// Texel row 0 sits at map height `top`; `light` is the sector's.
    Textured {
        texture: &'a Texture,
        top: f64,
        light: u8,
    },
}

/// Everything about one seg that is fixed across its columns.
struct SegColumns<'a> {
    line: usize,
    /// The map line's `from` end, direction (`to - from`) and length, camera space.
    from: DVec2,
    dir: DVec2,
    length: f64,
    /// `cross(from, dir)`: depth at slope t is `cross_from / cross((1, t), dir)`.
    cross_from: f64,
    /// `focal / cross_from`: times `cross((1, t), dir)`, the column's scale.
    focal_per_cross: f64,
    /// Texture column at the line's start of this side, and whether the side
    /// runs against the line (a back side measures from the line's `to`).
    u_offset: f64,
    backwards: bool,
    ceiling: f64,
    floor: f64,
    /// Back sector's ceiling and floor, for a two-sided line.
    back: Option<(f64, f64)>,
    ceiling_paint: PlanePaint<'a>,
    floor_paint: PlanePaint<'a>,
    /// The front sector's ceiling or floor is sky (infinitely far, for the depth buffer).
    ceiling_sky: bool,
    floor_sky: bool,
    /// A see-through middle on a two-sided line, drawn later with the sprites.
    masked: bool,
    /// Some part samples a texture column (or the masked middle will): only
    /// then is the per-column texture coordinate worth computing.
    needs_u: bool,
    /// The solid wall of a one-sided line, or the upper and lower walls.
    middle: Paint<'a>,
    upper: Paint<'a>,
    lower: Paint<'a>,
}

/// Draws `seg` in the columns still open. `along`: the walk is below a
/// partition the eye looks along, whose near-by seg ends count as on it
/// ([`super::bsp::looks_along`]).
pub(crate) fn draw_seg(scene: &Scene, seg: &Seg, frame: &mut StripFrame, out: &mut ColumnWriter, along: Option<f64>) {
    frame.stats.walls_considered += 1;
    let (level, cam) = (scene.level, scene.cam);
    let map = &level.map;
    let line = &map.lines[seg.line];
    // Facing and depth come from the whole map line in camera space, in the
    // line's own direction: the same numbers for every piece and both sides,
    // and the same the reference computes, so edge cases resolve alike.
    // (Camera space mirrors the map, so the eye is in front when this is > 0.)
    let (from, to) = map.line_points(line);
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
    let (mut v1, mut v2) = (cam.to_camera(seg.v1), cam.to_camera(seg.v2));
    if let Some(line) = along {
        (v1, v2) = (onto_partition(v1, line), onto_partition(v2, line));
    }
    let Some((x0, x1)) = cam.project_span_in(scene.slopes, v1, v2) else {
        return;
    };
    let columns = Lap::start(scene.profile);
    let cols = seg_columns(level, seg, line, (from, dir, cross_from, cam.focal), scene.shade, &scene.plan);
    let mut drew = false;
    let mut x = x0;
    while let Some(start) = frame.occlusion.next_open(x, x1) {
        let stop = frame.occlusion.next_closed(start, x1);
        for col in start..stop {
            draw_column(scene, &cols, col, frame, out);
        }
        drew = true;
        x = stop;
    }
    frame.breakdown.walls += columns.ns();
    frame.stats.walls_drawn += u64::from(drew);
    if drew {
        frame.seen_lines[seg.line] = true;
    }
}

fn seg_columns<'a>(
    level: &'a Level,
    seg: &Seg,
    line: &Line,
    (from, dir, cross_from, focal): (DVec2, DVec2, f64, f64),
    shade: Shade,
    plan: &Plan,
) -> SegColumns<'a> {
    let map = &level.map;
    let front = &map.sectors[seg.front_sector];
    let back = seg.back_sector.map(|b| &map.sectors[b]);
    let (side, textures) = match seg.side {
        LineSide::Front => (&line.front, level.materials.side(seg.line, 0)),
        // A back seg exists only on two-sided lines.
        LineSide::Back => (line.side(true), level.materials.side(seg.line, 1)),
    };
    let light = front.light;
    let (ceiling_light, floor_light) = plane_lights(map, front);
    let (ceiling_surface, floor_surface) = plane_surfaces(seg.front_sector, front);
    let wall = colour(shade, Surface::Wall { line: seg.line }, light, wall_facing(seg.v2 - seg.v1));
    let ceiling = ceiling_at_line(front, back);
    let textured = shade == Shade::Textured;
    let plane = |surface, height, texture: Option<TextureId>, light: u8| match (textured, surface, texture) {
        (true, Surface::Sky, _) if plan.sky => {
            level.materials.sky.map(|t| PlanePaint::Sky(level.materials.textures.get(t)))
        }
        (true, _, Some(t)) => Some(PlanePaint::Flat { id: t, texture: level.materials.textures.get(t), height, light }),
        _ => None,
    };
    let planes = level.materials.plane(seg.front_sector);
    let ceiling_paint = plane(ceiling_surface, front.ceiling, planes.ceiling, ceiling_light)
        .unwrap_or(PlanePaint::Solid(colour(shade, ceiling_surface, ceiling_light, 1.0)));
    let floor_paint = plane(floor_surface, front.floor, planes.floor, floor_light)
        .unwrap_or(PlanePaint::Solid(colour(shade, floor_surface, floor_light, 1.0)));
    let (middle, upper, lower) = if textured {
        wall_paints(level, line, side, &textures, (front, back), (wall, seg.v2 - seg.v1))
    } else {
        (Paint::Solid(wall), Paint::Solid(wall), Paint::Solid(wall))
    };
    let masked = plan.masked && back.is_some() && textures.middle.is_some();
    SegColumns {
        line: seg.line,
        from,
        dir,
        length: dir.length(),
        cross_from,
        focal_per_cross: focal / cross_from,
        u_offset: side_offsets(side, level.time).0,
        backwards: seg.side == LineSide::Back,
        ceiling,
        floor: front.floor,
        back: back.map(|b| (b.ceiling, b.floor)),
        ceiling_paint,
        floor_paint,
        ceiling_sky: ceiling_surface == Surface::Sky,
        floor_sky: floor_surface == Surface::Sky,
        masked,
        needs_u: masked || [middle, upper, lower].iter().any(|p| matches!(p, Paint::Textured { .. })),
        middle,
        upper,
        lower,
    }
}

/// Doom's pegging: where texel row 0 of each wall part sits.
/// - middle of a one-sided wall: at the ceiling, or with `lower_unpegged`
///   its bottom row at the floor;
/// - upper: its bottom row at the back sector's ceiling (it hangs from the
///   opening), or with `upper_unpegged` at the front ceiling;
/// - lower: at the back sector's floor (it stands on the opening), or with
///   `lower_unpegged` where it would be if it started at the front ceiling.
fn wall_paints<'a>(
    level: &'a Level,
    line: &Line,
    side: &Side,
    textures: &SideTextures,
    (front, back): (&Sector, Option<&Sector>),
    (flat, direction): (u32, DVec2),
) -> (Paint<'a>, Paint<'a>, Paint<'a>) {
    let light = fake_contrast(front.light, direction);
    let paint = |id: Option<TextureId>, top: &dyn Fn(&Texture) -> f64| match id {
        Some(id) => {
            let texture = level.materials.textures.get(id);
            Paint::Textured { texture, top: top(texture) + side_offsets(side, level.time).1, light }
        }
        None => Paint::Solid(flat),
    };
    let flags = line.flags;
    let middle = paint(textures.middle, &|t| {
        if flags.lower_unpegged {
            front.floor + t.height as f64
        } else {
            front.ceiling
        }
    });
    let (back_ceiling, back_floor) = back.map_or((front.ceiling, front.floor), |b| (b.ceiling, b.floor));
    let upper = paint(textures.upper, &|t| {
        if flags.upper_unpegged {
            front.ceiling
        } else {
            back_ceiling + t.height as f64
        }
    });
    let lower = paint(textures.lower, &|_| {
        if flags.lower_unpegged {
            front.ceiling
        } else {
            back_floor
        }
    });
    (middle, upper, lower)
}

#[inline]
fn draw_column(scene: &Scene, s: &SegColumns, x: usize, frame: &mut StripFrame, out: &mut ColumnWriter) {
    let t = scene.slopes[x];
    let across = cross(DVec2::new(1.0, t), s.dir);
    let depth = s.cross_from / across;
    // `scale` (focal / depth) only starts the row searches, which end on the
    // same rows from any start: a multiply, off the division's critical
    // path, where a second division held up every row search.
    let (depth, scale) = if depth.is_finite() && depth >= NEAR {
        (depth, across * s.focal_per_cross)
    } else {
        // Columns inside the near-clipped span are at depth >= NEAR up to rounding.
        let depth = if depth.is_finite() { depth.max(NEAR) } else { NEAR };
        (depth, scene.cam.focal / depth)
    };
    let row = |height: f64| scene.rows.first_at_or_below(depth, scale, height);
    let (top, bottom) = (frame.clip_top[x], frame.clip_bottom[x]);
    let ceiling_end = row(s.ceiling).clamp(top, bottom);
    let floor_start = row(s.floor).clamp(ceiling_end, bottom);
    for (rows, paint) in [((top, ceiling_end), s.ceiling_paint), ((floor_start, bottom), s.floor_paint)] {
        match paint {
            PlanePaint::Flat { id, height, light, .. } if scene.spans => {
                frame.visplanes.add(PlaneKey { texture: id, height, light }, x, rows.0, rows.1);
            }
            _ => paint_plane(out, scene, x, rows, t, paint, &mut frame.sky_columns[x]),
        }
    }
    let u = if s.needs_u { texture_u(s, depth, t) } else { 0.0 };
    let wall = WallColumn { scene, x, depth, u };
    // Clip events only matter to the masked pass; a frame without one skips them.
    let track = scene.plan.masked_pass();
    if out.buffers.on() {
        let (z, inv_rows) = (scene.cam.z, scene.inv_rows);
        out.buffers.plane(x, (top, ceiling_end), (!s.ceiling_sky).then_some(s.ceiling - z), inv_rows, depth);
        out.buffers.plane(x, (floor_start, bottom), (!s.floor_sky).then_some(s.floor - z), inv_rows, depth);
    }
    match s.back {
        None => {
            wall.paint(out, (ceiling_end, floor_start), s.middle);
            out.buffers.flat(x, (ceiling_end, floor_start), depth);
            frame.occlusion.close(x);
            if track {
                frame.push_event(x, depth, 0, 0);
            }
        }
        Some((back_ceiling, back_floor)) => {
            // The opening is below both ceilings and above both floors.
            let upper_end = row(back_ceiling).clamp(ceiling_end, floor_start);
            let lower_start = row(back_floor).clamp(upper_end, floor_start);
            wall.paint(out, (ceiling_end, upper_end), s.upper);
            wall.paint(out, (lower_start, floor_start), s.lower);
            out.buffers.flat(x, (ceiling_end, upper_end), depth);
            out.buffers.flat(x, (lower_start, floor_start), depth);
            if upper_end >= lower_start {
                frame.occlusion.close(x);
            } else {
                frame.clip_top[x] = upper_end;
                frame.clip_bottom[x] = lower_start;
            }
            if track {
                let event = frame.push_event(x, depth, upper_end, lower_start.max(upper_end));
                if s.masked && upper_end < lower_start {
                    frame.push_masked(x, depth, s.line, s.backwards, wall.u, event);
                }
            }
        }
    }
}

/// Distance along the side from its start to where column slope `t` meets
/// it, plus the side's texture offset: the texture column.
#[inline]
fn texture_u(s: &SegColumns, depth: f64, t: f64) -> f64 {
    let hit = DVec2::new(depth, depth * t);
    let along = (hit - s.from).dot(s.dir) / s.length;
    s.u_offset + if s.backwards { s.length - along } else { along }
}

/// One screen column of a wall at `depth`, showing texture column `u`
/// (before wrapping), for painting its parts.
pub(crate) struct WallColumn<'a> {
    pub scene: &'a Scene<'a>,
    pub x: usize,
    pub depth: f64,
    pub u: f64,
}

impl WallColumn<'_> {
    fn paint(&self, out: &mut ColumnWriter, rows: (i32, i32), paint: Paint) {
        match paint {
            Paint::Solid(c) => out.fill(self.x, rows.0, rows.1, c),
            Paint::Textured { texture, top, light } => self.textured(out, rows, texture, top, light),
        }
    }

    /// Paints rows `rows` from `texture`, whose texel row 0 is at height
    /// `top`, lit by `light`.
    #[inline]
    pub(crate) fn textured(&self, out: &mut ColumnWriter, rows: (i32, i32), texture: &Texture, top: f64, light: u8) {
        if rows.1 <= rows.0 {
            return;
        }
        let (scene, depth) = (self.scene, self.depth);
        let u = texture.wrap_column(crate::geom::floor_i64(self.u));
        // Row y's ray is at height z + depth * slope(y) on the wall.
        let height = scene.cam.z + depth * scene.rows.slopes[rows.0 as usize];
        let dv = depth / scene.cam.focal;
        let tint = scene.lighting.tint(light, depth);
        if out.sampling.bilinear {
            let exact_u = self.u;
            out.fill_with(self.x, rows.0, rows.1, |y| {
                let v = top - height + f64::from(y - rows.0) * dv;
                tint.apply(texture.bilinear(exact_u, v))
            });
            return;
        }
        out.textured(self.x, rows, texture.column(u), top - height, dv, tint);
    }
}
