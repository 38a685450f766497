//! Cheaper rays for the grid ray-caster, from the ray-casting literature, to
//! measure what exactness costs (`--ray march:K`, `--ray sphere:EPS`):
//!
//! - **Fixed-step march**: test a point every `K` map units along the ray and
//!   stop at the first inside a wall. The depth overshoots by up to `K`, and
//!   a wall corner or a door thinner than `K` can be stepped over entirely.
//! - **Sphere tracing** (Hart, 1996): step by the distance to the nearest
//!   wall, which cannot overshoot, and stop once it falls below `EPS`. Rays
//!   that graze a wall crawl along it and may run out of steps.
//!
//! Both report the face they stopped at as a [`RayHit`], so the accuracy
//! study compares them with the exact traversal face by face.

use glam::DVec2;

use super::raycast::RayHit;
use super::view::Camera;
use crate::grid::compile::{along_face, face_ends, jamb_points, NO_LINE};
use crate::grid::{Axis, Cell, Face, Grid};
use crate::level::GridLevel;

/// Most samples one ray may take before it gives up and hits nothing: with a
/// tiny step or a grazing sphere trace a ray could otherwise run for hours.
pub const MAX_SAMPLES: u64 = 1 << 20;

/// Most sphere-tracing steps per ray (the literature's usual cap is in the
/// low hundreds; grazing rays are the ones that need it).
pub const MAX_SPHERE_STEPS: u64 = 512;

/// The solid box of a cell, or of the closed part of a door panel.
fn solid_box(grid: &Grid, gl: &GridLevel, i: i64, j: i64) -> Option<[DVec2; 2]> {
    if !grid.contains(i, j) {
        return None;
    }
    let (x0, x1, y0, y1) = (grid.x(i), grid.x(i + 1), grid.y(j), grid.y(j + 1));
    match grid.cell(i, j) {
        Cell::Empty => None,
        Cell::Wall { .. } => Some([DVec2::new(x0, y0), DVec2::new(x1, y1)]),
        Cell::Door { axis, .. } => {
            let [lo, hi] = grid.door_slab(i, j, axis);
            let open = gl.open_share(grid.index(i, j));
            let slide = open * grid.cell_size;
            if open >= 1.0 {
                return None;
            }
            Some(match axis {
                Axis::X => [DVec2::new(x0, lo), DVec2::new(x1 - slide, hi)],
                Axis::Y => [DVec2::new(lo, y0), DVec2::new(hi, y1 - slide)],
            })
        }
    }
}

fn inside(b: &[DVec2; 2], p: DVec2) -> bool {
    p.x >= b[0].x && p.x <= b[1].x && p.y >= b[0].y && p.y <= b[1].y
}

/// Distance from `p` to box `b` (0 inside).
fn box_distance(b: &[DVec2; 2], p: DVec2) -> f64 {
    let dx = (b[0].x - p.x).max(p.x - b[1].x).max(0.0);
    let dy = (b[0].y - p.y).max(p.y - b[1].y).max(0.0);
    dx.hypot(dy)
}

/// The hit report for a ray stopped at `p` (depth `depth`) on `face` of the
/// solid in cell `(i, j)`, with the texture column measured from the point.
fn report(grid: &Grid, gl: &GridLevel, (i, j): (i64, i64), face: Face, p: DVec2, depth: f64) -> RayHit {
    let cell = grid.index(i, j);
    let door = matches!(grid.cell(i, j), Cell::Door { .. });
    let u = along_face(face, face_ends(grid, i, j, face).0, p);
    let mut line = gl.faces.line(cell, face);
    if let (false, Some(points)) = (door || line == NO_LINE, jamb_points(grid, i, j, face)) {
        // Pieces of a jamb, chosen by where along the face the point is.
        let along = |q: DVec2| if face.is_x() { q.y } else { q.x };
        let (a, b) = (along(points[0]), along(points[1]));
        let here = along(p);
        let passed = |v: f64| if a <= b { here >= v } else { here <= v };
        line += u32::from(passed(a)) + u32::from(passed(b));
    }
    RayHit { line: (line != NO_LINE).then_some(line as usize), cell, face, depth, u, door }
}

/// The face of box `b` that `p` (outside it or on it) is nearest to.
fn nearest_face(b: &[DVec2; 2], p: DVec2) -> Face {
    let west = b[0].x - p.x;
    let east = p.x - b[1].x;
    let south = b[0].y - p.y;
    let north = p.y - b[1].y;
    let (dx, fx) = if west > east { (west, Face::West) } else { (east, Face::East) };
    let (dy, fy) = if south > north { (south, Face::South) } else { (north, Face::North) };
    if dx >= dy {
        fx
    } else {
        fy
    }
}

/// The unit direction of a column ray and its depth per unit of length.
fn unit_ray(cam: &Camera, t: f64) -> (DVec2, f64) {
    let d = cam.forward + cam.right * t;
    let len = d.length();
    (d / len, 1.0 / len)
}

pub(crate) fn march(grid: &Grid, gl: &GridLevel, cam: &Camera, t: f64, step: f64, steps: &mut u64) -> Option<RayHit> {
    let (dir, depth_per_unit) = unit_ray(cam, t);
    let reach = grid.x(grid.columns as i64).hypot(grid.y(grid.rows as i64)) + grid.cell_size;
    let samples = ((reach / step).ceil() as u64).min(MAX_SAMPLES);
    let cell_of = |p: DVec2| grid.cell_at(p, (1, 1));
    let mut prev = cam.eye;
    let mut prev_cell = cell_of(prev);
    for k in 1..=samples {
        *steps += 1;
        let dist = k as f64 * step;
        let p = cam.eye + dir * dist;
        let (i, j) = cell_of(p);
        if !grid.contains(i, j) {
            return None;
        }
        if let Some(b) = solid_box(grid, gl, i, j).filter(|b| inside(b, p)) {
            let face = if matches!(grid.cell(i, j), Cell::Door { .. }) {
                nearest_face(&b, prev)
            } else {
                entry_face(grid, prev, p, prev_cell, (i, j))
            };
            return Some(report(grid, gl, (i, j), face, p, dist * depth_per_unit));
        }
        prev = p;
        prev_cell = (i, j);
    }
    None
}

/// The face through which the segment `prev -> p` entered cell `to` from
/// cell `from`: when both coordinates changed, the edge crossed last.
fn entry_face(grid: &Grid, prev: DVec2, p: DVec2, from: (i64, i64), to: (i64, i64)) -> Face {
    let x_face = if to.0 > from.0 { Face::West } else { Face::East };
    let y_face = if to.1 > from.1 { Face::South } else { Face::North };
    match (to.0 != from.0, to.1 != from.1) {
        (true, false) => x_face,
        (false, true) => y_face,
        (false, false) => y_face,
        (true, true) => {
            let ex = grid.x(if to.0 > from.0 { to.0 } else { to.0 + 1 });
            let ey = grid.y(if to.1 > from.1 { to.1 } else { to.1 + 1 });
            let tx = (ex - prev.x) / (p.x - prev.x);
            let ty = (ey - prev.y) / (p.y - prev.y);
            if tx > ty {
                x_face
            } else {
                y_face
            }
        }
    }
}

/// Per cell, a lower bound on the distance from any point in it to any
/// solid cell: `(k - 1) * cell_size` with `k` the Chebyshev distance in
/// cells to the nearest wall or door cell (0 for those, 1 beside one).
#[derive(Clone, Debug)]
pub struct DistanceField {
    rings: Vec<u32>,
}

impl DistanceField {
    /// Two passes of a chamfer transform over the grid: O(cells).
    pub fn new(grid: &Grid) -> DistanceField {
        let (w, h) = (grid.columns, grid.rows);
        let mut rings: Vec<u32> =
            grid.cells.iter().map(|c| if matches!(c, Cell::Empty) { u32::MAX } else { 0 }).collect();
        let at = |i: usize, j: usize| j * w + i;
        for j in 0..h {
            for i in 0..w {
                let mut best = rings[at(i, j)];
                for (di, dj) in [(-1i64, -1i64), (0, -1), (1, -1), (-1, 0)] {
                    let (ni, nj) = (i as i64 + di, j as i64 + dj);
                    if ni >= 0 && nj >= 0 && (ni as usize) < w {
                        best = best.min(rings[at(ni as usize, nj as usize)].saturating_add(1));
                    }
                }
                rings[at(i, j)] = best;
            }
        }
        for j in (0..h).rev() {
            for i in (0..w).rev() {
                let mut best = rings[at(i, j)];
                for (di, dj) in [(1i64, 1i64), (0, 1), (-1, 1), (1, 0)] {
                    let (ni, nj) = (i as i64 + di, j as i64 + dj);
                    if ni >= 0 && (ni as usize) < w && (nj as usize) < h {
                        best = best.min(rings[at(ni as usize, nj as usize)].saturating_add(1));
                    }
                }
                rings[at(i, j)] = best;
            }
        }
        DistanceField { rings }
    }

    /// A distance from `p` to the nearest solid that never exceeds the true
    /// one and is exact within a cell of a solid, with the nearest solid
    /// cell when that is what bounds it.
    fn distance(&self, grid: &Grid, gl: &GridLevel, (i, j): (i64, i64), p: DVec2) -> (f64, Option<(i64, i64)>) {
        let ring = self.rings[grid.index(i, j)];
        if ring >= 2 {
            return (f64::from(ring - 1) * grid.cell_size, None);
        }
        // Solids two or more cells away are at least a cell away.
        let mut best = (grid.cell_size, None);
        for dj in -1..=1 {
            for di in -1..=1 {
                if let Some(b) = solid_box(grid, gl, i + di, j + dj) {
                    let d = box_distance(&b, p);
                    if d < best.0 {
                        best = (d, Some((i + di, j + dj)));
                    }
                }
            }
        }
        best
    }
}

pub(crate) fn sphere(
    grid: &Grid,
    gl: &GridLevel,
    cam: &Camera,
    t: f64,
    epsilon: f64,
    steps: &mut u64,
) -> Option<RayHit> {
    let field = gl.field.get_or_init(|| DistanceField::new(grid));
    let (dir, depth_per_unit) = unit_ray(cam, t);
    let mut dist = 0.0;
    for _ in 0..MAX_SPHERE_STEPS {
        *steps += 1;
        let p = cam.eye + dir * dist;
        let cell = grid.cell_at(p, (1, 1));
        if !grid.contains(cell.0, cell.1) {
            return None;
        }
        let (d, nearest) = field.distance(grid, gl, cell, p);
        if d < epsilon {
            let (i, j) = nearest.unwrap_or(cell);
            let b = solid_box(grid, gl, i, j)?;
            return Some(report(grid, gl, (i, j), nearest_face(&b, p), p, dist * depth_per_unit));
        }
        dist += d;
    }
    None
}

/// How a ray method compares with the exact traversal over some frames.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RayAccuracy {
    pub columns: u64,
    /// Columns whose ray hit a different face than the exact one, or nothing.
    pub wrong: u64,
    /// Mean and largest difference in wall depth (map units) over the
    /// columns that hit something.
    pub mean_error: f64,
    pub max_error: f64,
    /// Cells or samples visited per column.
    pub steps_per_column: f64,
}

impl RayAccuracy {
    pub fn wrong_share(&self) -> f64 {
        self.wrong as f64 / self.columns.max(1) as f64
    }
}

/// Casts every column of every view with `method` and with the exact DDA and
/// compares them (screen `width` columns; the height does not matter).
pub fn accuracy(
    level: &crate::level::Level,
    views: &[super::View],
    width: usize,
    method: super::raycast::RayMethod,
) -> RayAccuracy {
    use super::raycast::{cast, RayMethod};
    let mut a = RayAccuracy::default();
    let (mut error_sum, mut hits, mut steps, mut exact_steps) = (0.0, 0u64, 0u64, 0u64);
    for view in views {
        let cam = Camera::new(view, width, 1);
        for x in 0..width {
            a.columns += 1;
            let exact = cast(level, &cam, x, RayMethod::Dda, &mut exact_steps);
            let approx = cast(level, &cam, x, method, &mut steps);
            if let (Some(e), Some(c)) = (exact, approx) {
                let error = (e.depth - c.depth).abs();
                error_sum += error;
                a.max_error = a.max_error.max(error);
                hits += 1;
            }
            let same = matches!((exact, approx), (Some(e), Some(c)) if e.line.is_some() && e.line == c.line);
            a.wrong += u64::from(!same);
        }
    }
    a.mean_error = error_sum / hits.max(1) as f64;
    a.steps_per_column = steps as f64 / a.columns.max(1) as f64;
    a
}
