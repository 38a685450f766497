//! The grid ray-caster, Wolfenstein 3D's renderer: one ray per column walks
//! the grid cell by cell (Amanatides and Woo's traversal) to the first wall
//! face or door panel, and the column is drawn from that one hit: ceiling,
//! wall, floor, every pixel once. Sprites come after, clipped by the hit's
//! depth per column (a depth buffer, kept as one clip event per column so
//! the shared masked pass in [`super::sprites`] does the clipping).
//!
//! Exactness. The traversal's one decision per step, whether the ray leaves
//! the cell through its vertical or its horizontal edge, is usually made by
//! comparing two ray parameters (`tMaxX < tMaxY`). Here it asks instead on
//! which side of the ray the cell's next corner lies, with
//! [`Camera::left_of_or_on`], the predicate that decides which column owns
//! a wall's end in the BSP renderer and the reference. A ray exactly through
//! a corner therefore meets the face the BSP renderer draws in that column:
//! the one on the ray's right, whose left end the corner is. Direction
//! components of zero (or -0.0) step towards the ray's right for the same
//! reason, and never divide.
//!
//! Cheaper rays (a fixed-step march, sphere tracing) are in [`super::rays`];
//! all three report a [`RayHit`] drawn the same way.

use glam::DVec2;

use super::columns::ColumnWriter;
use super::frame::{Scene, StripFrame};
use super::light::fake_contrast;
use super::planes::{paint_plane, PlanePaint};
use super::rays;
use super::shade::{colour, Shade, Surface, VOID};
use super::view::{Camera, NEAR};
use super::visplanes::PlaneKey;
use super::walls::WallColumn;
use crate::grid::compile::{along_face, face_ends, jamb_points, panel_ends, NO_LINE};
use crate::grid::{Axis, Cell, Face, Grid};
use crate::level::{GridLevel, Level};
use crate::texture::TextureId;

/// How rays find walls (`--ray`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum RayMethod {
    /// Exact grid traversal.
    #[default]
    Dda,
    /// Test a point every `step` map units along the ray.
    March { step: f64 },
    /// Sphere tracing against the walls' distance field; a hit is closer than `epsilon`.
    Sphere { epsilon: f64 },
}

impl RayMethod {
    /// `dda`, `march:K` or `sphere:EPS`.
    pub fn parse(s: &str) -> Result<RayMethod, String> {
        let number = |v: &str| {
            v.parse::<f64>()
                .ok()
                .filter(|k| k.is_finite() && *k > 0.0)
                .ok_or_else(|| format!("ray method `{s}`: `{v}` is not a number above 0"))
        };
        match s.split_once(':') {
            None if s == "dda" => Ok(RayMethod::Dda),
            Some(("march", k)) => Ok(RayMethod::March { step: number(k)? }),
            Some(("sphere", e)) => Ok(RayMethod::Sphere { epsilon: number(e)? }),
            _ => Err(format!("unknown ray method `{s}`; choose dda, march:K or sphere:EPS")),
        }
    }

    pub fn name(&self) -> String {
        match self {
            RayMethod::Dda => "dda".into(),
            RayMethod::March { step } => format!("march:{step}"),
            RayMethod::Sphere { epsilon } => format!("sphere:{epsilon}"),
        }
    }
}

/// What one column's ray hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayHit {
    /// The compiled line of the face hit; `None` for a face no exact ray can
    /// reach (one between two wall cells), which only approximate rays hit.
    pub line: Option<usize>,
    /// The cell whose face was hit, and which face.
    pub cell: usize,
    pub face: Face,
    /// Perpendicular distance (depth along the view direction).
    pub depth: f64,
    /// Texture column: distance along the face's line from its start.
    pub u: f64,
    /// A door panel (its texture stands on the floor) rather than a wall.
    pub door: bool,
}

/// Casts the ray of column `x` on a grid level; `steps` counts cells or samples visited.
pub fn cast(level: &Level, cam: &Camera, x: usize, method: RayMethod, steps: &mut u64) -> Option<RayHit> {
    let (grid, gl) = level.grid()?;
    cast_grid(grid, gl, cam, x, method, steps)
}

/// [`cast`] on a bare grid, which need not be a valid map (tests cast rays
/// out of open grids).
pub fn cast_grid(
    grid: &Grid,
    gl: &GridLevel,
    cam: &Camera,
    x: usize,
    method: RayMethod,
    steps: &mut u64,
) -> Option<RayHit> {
    let t = cam.column_slope(x);
    match method {
        RayMethod::Dda => dda(grid, gl, cam, x, t, steps),
        RayMethod::March { step } => rays::march(grid, gl, cam, t, step, steps),
        RayMethod::Sphere { epsilon } => rays::sphere(grid, gl, cam, t, epsilon, steps),
    }
}

/// The direction a ray steps along each axis: its sign, and for a zero
/// component the side of the ray's right, which owns exact ties.
pub(crate) fn ray_steps(d: DVec2) -> (i64, i64) {
    let sx = if d.x > 0.0 || (d.x == 0.0 && d.y > 0.0) { 1 } else { -1 };
    let sy = if d.y > 0.0 || (d.y == 0.0 && d.x < 0.0) { 1 } else { -1 };
    (sx, sy)
}

/// Does column `x`'s ray, heading `(sx, sy)`, meet the vertical line through
/// `corner` before the horizontal one? A corner left of the ray (or on it)
/// means the ray passes on its right, through the edge on the right.
fn crosses_x(cam: &Camera, x: usize, corner: DVec2, (sx, sy): (i64, i64)) -> bool {
    let left = cam.left_of_or_on(cam.to_camera(corner), x);
    // Heading north-east or south-west, the vertical edge is the right one.
    left == (sx * sy > 0)
}

fn dda(grid: &Grid, gl: &GridLevel, cam: &Camera, x: usize, t: f64, steps: &mut u64) -> Option<RayHit> {
    let d = cam.forward + cam.right * t;
    let heading = ray_steps(d);
    let (sx, sy) = heading;
    let (mut i, mut j) = grid.cell_at(cam.eye, heading);
    let mut entered = None;
    // Each step moves one cell on, so this many steps leave any grid.
    for _ in 0..=grid.columns + grid.rows + 1 {
        if !grid.contains(i, j) {
            return None;
        }
        match grid.cell(i, j) {
            // Entered is None only when the eye is inside the wall: nothing to see.
            Cell::Wall { .. } => return entered.map(|face| wall_hit(grid, gl, cam, x, d, (i, j), face)),
            Cell::Door { axis, .. } => {
                if let Some(hit) = door_hit(grid, gl, cam, x, d, (i, j), axis, entered) {
                    return Some(hit);
                }
            }
            Cell::Empty => {}
        }
        let corner = DVec2::new(grid.x(if sx > 0 { i + 1 } else { i }), grid.y(if sy > 0 { j + 1 } else { j }));
        *steps += 1;
        if crosses_x(cam, x, corner, heading) {
            i += sx;
            entered = Some(if sx > 0 { Face::West } else { Face::East });
        } else {
            j += sy;
            entered = Some(if sy > 0 { Face::South } else { Face::North });
        }
    }
    None
}

/// The hit on `face` of the wall cell `(i, j)`.
fn wall_hit(grid: &Grid, gl: &GridLevel, cam: &Camera, x: usize, d: DVec2, (i, j): (i64, i64), face: Face) -> RayHit {
    let (depth, u) = face_hit(cam, d, face, face_ends(grid, i, j, face).0);
    let cell = grid.index(i, j);
    let mut line = gl.faces.line(cell, face);
    if let Some(points) = jamb_points(grid, i, j, face) {
        // A jamb is three lines, left to right on screen; the ray is in the
        // piece after each inner point on or left of it, as the BSP decides.
        line += points.iter().filter(|p| cam.left_of_or_on(cam.to_camera(**p), x)).count() as u32;
    }
    RayHit { line: (line != NO_LINE).then_some(line as usize), cell, face, depth, u, door: false }
}

/// The hit on the door panel in cell `(i, j)`, if the ray meets its closed
/// part before leaving the cell; `entered` is the cell edge the ray came in
/// through (`None` when the eye is in this cell).
#[allow(clippy::too_many_arguments)]
fn door_hit(
    grid: &Grid,
    gl: &GridLevel,
    cam: &Camera,
    x: usize,
    d: DVec2,
    (i, j): (i64, i64),
    axis: Axis,
    entered: Option<Face>,
) -> Option<RayHit> {
    let (sx, sy) = ray_steps(d);
    let [lo, hi] = grid.door_slab(i, j, axis);
    let cell = grid.index(i, j);
    // Coordinates across the panel (y for an east-west panel) and along it.
    let (eye_across, d_across, s_across) = match axis {
        Axis::X => (cam.eye.y, d.y, sy),
        Axis::Y => (cam.eye.x, d.x, sx),
    };
    let (low_face, high_face) = match axis {
        Axis::X => (Face::South, Face::North),
        Axis::Y => (Face::West, Face::East),
    };
    // Where the ray is, across the panel, when it enters the cell.
    let approach = match entered {
        None if eye_across < lo => Across::Below,
        None if eye_across > hi => Across::Above,
        None => Across::Inside,
        Some(face) if face.is_x() != (axis == Axis::X) => {
            if s_across > 0 {
                Across::Below
            } else {
                Across::Above
            }
        }
        // Through the panel's end: past it, short of it, or into its end face.
        Some(face) => match through_end(grid, cam, x, d, (i, j), axis, face) {
            Across::Inside => return Some(end_hit(grid, gl, cam, d, (i, j), face, cell)),
            across => across,
        },
    };
    let (plane, face) = match (approach, s_across > 0) {
        _ if d_across == 0.0 => return None,
        (Across::Below, true) => (lo, low_face),
        (Across::Above, false) => (hi, high_face),
        // Inside the slab (only when it is open) the far face is seen from behind.
        (Across::Inside, true) => (hi, high_face),
        (Across::Inside, false) => (lo, low_face),
        _ => return None,
    };
    // Does the ray reach the panel's plane before the cell's side edge?
    let reaches = match axis {
        Axis::X => !crosses_x(cam, x, DVec2::new(grid.x(if sx > 0 { i + 1 } else { i }), plane), (sx, sy)),
        Axis::Y => crosses_x(cam, x, DVec2::new(plane, grid.y(if sy > 0 { j + 1 } else { j })), (sx, sy)),
    };
    if !reaches {
        return None;
    }
    let depth = (plane - eye_across) / d_across;
    let hit = cam.eye + d * depth;
    // The panel slides towards lower coordinates; `slide` of it is gone.
    let slide = gl.open_share(cell) * grid.cell_size;
    let (along, low) = match axis {
        Axis::X => (hit.x, grid.x(i)),
        Axis::Y => (hit.y, grid.y(j)),
    };
    // (A closed panel spans the cell: the corner test above already decided.)
    if slide > 0.0 && along - low >= grid.cell_size - slide {
        return None;
    }
    let high = low + grid.cell_size;
    let u = match face {
        Face::South | Face::East => along - low + slide,
        Face::North | Face::West => high - slide - along,
    };
    let line = gl.faces.line(cell, face);
    Some(RayHit { line: (line != NO_LINE).then_some(line as usize), cell, face, depth, u, door: true })
}

/// Where a ray is across a door panel's slab.
#[derive(Clone, Copy, PartialEq)]
enum Across {
    Below,
    Inside,
    Above,
}

/// For a ray entering door cell `(i, j)` through the edge `face` that the
/// panel ends on: is it below, into or above the panel's end? Decided by
/// which side of the ray the end face's two corners lie.
fn through_end(grid: &Grid, cam: &Camera, x: usize, d: DVec2, (i, j): (i64, i64), axis: Axis, face: Face) -> Across {
    let (_, (a, b)) = panel_ends(grid, i, j, axis)[usize::from(matches!(face, Face::East | Face::North))];
    let (left_a, left_b) = (cam.left_of_or_on(cam.to_camera(a), x), cam.left_of_or_on(cam.to_camera(b), x));
    if left_a != left_b {
        return Across::Inside;
    }
    // The left of a ray heading along +x is +y; along +y it is -x.
    let (sx, sy) = ray_steps(d);
    let left_is_up = match axis {
        Axis::X => sx > 0,
        Axis::Y => sy < 0,
    };
    // Both corners on the upper side: the ray passes below the panel's end.
    if left_a == left_is_up {
        Across::Below
    } else {
        Across::Above
    }
}

/// The hit on the end face of a door panel (a door with no wall beside it).
fn end_hit(grid: &Grid, gl: &GridLevel, cam: &Camera, d: DVec2, (i, j): (i64, i64), face: Face, cell: usize) -> RayHit {
    let axis = if face.is_x() { Axis::X } else { Axis::Y };
    let (from, _) = panel_ends(grid, i, j, axis)[usize::from(matches!(face, Face::East | Face::North))].1;
    let (depth, u) = face_hit(cam, d, face, from);
    let line = gl.faces.line(cell, face);
    RayHit { line: (line != NO_LINE).then_some(line as usize), cell, face, depth, u, door: true }
}

/// Where ray `d` meets the line of `face` that starts at `from`: its
/// perpendicular distance (Wolfenstein's, no fish-eye) and how far along the
/// face it is.
fn face_hit(cam: &Camera, d: DVec2, face: Face, from: DVec2) -> (f64, f64) {
    let depth = if face.is_x() { (from.x - cam.eye.x) / d.x } else { (from.y - cam.eye.y) / d.y };
    (depth, along_face(face, from, cam.eye + d * depth))
}

/// What a frame's columns share: the planes' paints and the sector's light.
struct Setup<'a> {
    ceiling: f64,
    floor: f64,
    ceiling_paint: PlanePaint<'a>,
    floor_paint: PlanePaint<'a>,
    light: u8,
}

/// Draws columns `[x0, x1)` of a grid level.
#[allow(clippy::too_many_arguments)]
pub(crate) fn render(
    scene: &Scene,
    frame: &mut StripFrame,
    out: &mut ColumnWriter,
    method: RayMethod,
    (x0, x1): (usize, usize),
) {
    let (level, cam, shade) = (scene.level, scene.cam, scene.shade);
    let h = cam.height as i32;
    if level.grid().is_none() {
        for x in x0..x1 {
            out.fill(x, 0, h, VOID);
            out.buffers.far(x, (0, h));
        }
        return;
    }
    // The open cells are sector 0; its planes are every column's planes.
    let sector = &level.map.sectors[0];
    let textures = level.materials.plane(0);
    let plane = |surface, height, texture: Option<TextureId>| match (shade, texture) {
        (Shade::Textured, Some(id)) => {
            PlanePaint::Flat { id, texture: level.materials.textures.get(id), height, light: sector.light }
        }
        _ => PlanePaint::Solid(colour(shade, surface, sector.light, 1.0)),
    };
    let setup = Setup {
        ceiling: sector.ceiling,
        floor: sector.floor,
        ceiling_paint: plane(Surface::Ceiling { sector: 0 }, sector.ceiling, textures.ceiling),
        floor_paint: plane(Surface::Floor { sector: 0 }, sector.floor, textures.floor),
        light: sector.light,
    };
    let mut steps = 0;
    for x in x0..x1 {
        let hit = cast(level, cam, x, method, &mut steps);
        frame.stats.walls_considered += 1;
        match hit {
            Some(hit) => draw_column(scene, &setup, &hit, x, frame, out),
            None => {
                out.fill(x, 0, h, VOID);
                out.buffers.far(x, (0, h));
            }
        }
    }
    frame.stats.nodes_visited += steps;
}

fn draw_column(scene: &Scene, setup: &Setup, hit: &RayHit, x: usize, frame: &mut StripFrame, out: &mut ColumnWriter) {
    let (level, cam, shade) = (scene.level, scene.cam, scene.shade);
    let h = cam.height as i32;
    let depth = if hit.depth.is_finite() { hit.depth.max(NEAR) } else { NEAR };
    let scale = cam.focal / depth;
    let ceiling_end = scene.rows.first_at_or_below(depth, scale, setup.ceiling);
    let floor_start = scene.rows.first_at_or_below(depth, scale, setup.floor).max(ceiling_end);
    let t = scene.slopes[x];
    for (rows, paint) in [((0, ceiling_end), setup.ceiling_paint), ((floor_start, h), setup.floor_paint)] {
        match paint {
            PlanePaint::Flat { id, height, light, .. } if scene.spans => {
                frame.visplanes.add(PlaneKey { texture: id, height, light }, x, rows.0, rows.1);
            }
            _ => paint_plane(out, scene, x, rows, t, paint, &mut frame.sky_columns[x]),
        }
    }
    let rows = (ceiling_end, floor_start);
    if out.buffers.on() {
        let (z, inv_rows, sector) = (cam.z, scene.inv_rows, &level.map.sectors[0]);
        let ceiling = (!sector.ceiling_is_sky()).then_some(setup.ceiling - z);
        let floor = (!sector.floor_is_sky()).then_some(setup.floor - z);
        out.buffers.plane(x, (0, ceiling_end), ceiling, inv_rows, depth);
        out.buffers.plane(x, (floor_start, h), floor, inv_rows, depth);
        out.buffers.flat(x, rows, depth);
    }
    let surface = Surface::Wall { line: hit.line.unwrap_or(usize::MAX) };
    // Wolfenstein shades east and west faces apart from north and south ones.
    let facing = if hit.face.is_x() { 1.0 } else { 0.8 };
    let texture = hit.line.filter(|_| shade == Shade::Textured).and_then(|line| {
        let side = level.materials.side(line, 0);
        if hit.door {
            side.upper
        } else {
            side.middle
        }
    });
    match texture {
        Some(id) => {
            let texture = level.materials.textures.get(id);
            // Pegged as the compiled map pegs them: walls hang from the
            // ceiling, a door's texture stands on the floor.
            let top = if hit.door { setup.floor + texture.height as f64 } else { setup.ceiling };
            let run = if hit.face.is_x() { DVec2::Y } else { DVec2::X };
            let light = fake_contrast(setup.light, run);
            WallColumn { scene, x, depth, u: hit.u }.textured(out, rows, texture, top, light);
        }
        None => out.fill(x, rows.0, rows.1, colour(shade, surface, setup.light, facing)),
    }
    if let Some(line) = hit.line {
        frame.seen_lines[line] = true;
    }
    if scene.plan.masked_pass() {
        frame.push_event(x, depth, 0, 0);
    }
}
