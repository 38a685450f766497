//! The reference renderer: the oracle every test compares against.
//!
//! Brute force in f64 and independent of the BSP path: each column's ray is
//! intersected with every line of the map, the crossings sorted by depth, and
//! each pixel's ray followed through them one by one (the z-buffer idea, per
//! ray). It shares only the view definition and the pixel writer.
//!
//! A pixel's ray at depth `d` is at height `h = z + d * slope`; at a crossing
//! with a sector `F` on the near side it sees F's ceiling if `h > F.ceiling`,
//! F's floor if `h <= F.floor`, else the line: solid if one-sided, and on a
//! two-sided line the upper wall if `h > B.ceiling`, the lower if
//! `h <= B.floor`, otherwise it passes on to the next crossing.

use glam::DVec2;

use super::columns::ColumnWriter;
use super::frame::{Frame, Hit};
use super::shade::{ceiling_at_line, colour, plane_surfaces, wall_facing, Shade, Surface};
use super::view::{Camera, NEAR};
use crate::geom::cross;
use crate::map::Map;

/// Renders `columns` (one strip) of the frame.
pub fn render(
    map: &Map,
    cam: &Camera,
    columns: std::ops::Range<usize>,
    frame: &mut Frame,
    out: &mut ColumnWriter,
    shade: Shade,
) {
    // Line ends in camera space (depth, sideways) and whether the line is
    // two-sided, once per frame.
    let ends: Vec<(DVec2, DVec2, bool)> = map
        .lines
        .iter()
        .map(|l| {
            let (a, b) = map.line_points(l);
            (cam.to_camera(a), cam.to_camera(b), l.back.is_some())
        })
        .collect();
    let eye_sector = map.sector_at(cam.eye);
    for x in columns {
        collect_hits(cam, &ends, x, &mut frame.hits);
        order_ties(map, eye_sector, &mut frame.hits);
        frame.stats.walls_considered += ends.len() as u64;
        let mut run: Option<(i32, u32)> = None;
        for y in 0..cam.height as i32 {
            let c = pixel_colour(map, cam, &frame.hits, y, shade);
            match run {
                Some((_, rc)) if rc == c => {}
                Some((start, rc)) => {
                    out.fill(x, start, y, rc);
                    run = Some((y, c));
                }
                None => run = Some((y, c)),
            }
        }
        if let Some((start, rc)) = run {
            out.fill(x, start, cam.height as i32, rc);
        }
    }
}

/// Every line column `x`'s ray crosses at depth >= NEAR, nearest first.
///
/// A ray exactly through a line's end follows the screen's half-open rule
/// ([`Camera::left_of_or_on`]): the line seen from its visible side owns its
/// left end, not its right, so two walls meeting at a vertex never both claim
/// the ray through it and never both miss it.
///
/// The back of a one-sided wall is skipped: from inside the map a ray meets
/// the solid's front faces first, and at most ties with its back at a corner.
fn collect_hits(cam: &Camera, ends: &[(DVec2, DVec2, bool)], x: usize, hits: &mut Vec<Hit>) {
    hits.clear();
    let t = cam.column_slope(x);
    let ray = DVec2::new(1.0, t);
    for (line, &(a, b, two_sided)) in ends.iter().enumerate() {
        let d = b - a;
        let den = cross(ray, d);
        // On the line, or along it: edge-on, nothing to see.
        let c = cross(a, d);
        if den == 0.0 || c == 0.0 {
            continue;
        }
        // Solve depth * ray = a + w * d.
        let depth = c / den;
        // NaN fails both tests; so does a depth behind or at infinity.
        if !depth.is_finite() || depth < NEAR {
            continue;
        }
        // Camera space mirrors the map, so the eye is on the line's front
        // (right-hand) side when cross(a, d) > 0 here.
        let from_front = c > 0.0;
        if !from_front && !two_sided {
            continue;
        }
        // Each end in front of the eye is settled by the half-open rule; an end
        // behind it (no ray on screen passes near it) by the line parameter.
        let w = cross(a, ray) / den;
        let (left, right) = if from_front { (a, b) } else { (b, a) };
        let (left_bound, right_bound) = if from_front {
            (w >= 0.0, w <= 1.0)
        } else {
            (w <= 1.0, w >= 0.0)
        };
        let left_ok = if left.x > 0.0 {
            cam.left_of_or_on(left, x)
        } else {
            left_bound
        };
        let right_ok = if right.x > 0.0 {
            !cam.left_of_or_on(right, x)
        } else {
            right_bound
        };
        let crosses = left_ok && right_ok;
        if crosses {
            hits.push(Hit {
                depth,
                line,
                from_front,
            });
        }
    }
    hits.sort_by(|p, q| p.depth.total_cmp(&q.depth).then(p.line.cmp(&q.line)));
}

/// Depths this close (relative) are one crossing point: a ray through a shared vertex.
const TIE: f64 = 1e-9;

/// Puts crossings at the same depth in the order the ray meets them. Through a
/// vertex where it enters and leaves a sector at once, the ray crosses first
/// the line whose near side is the sector it is in, then the next.
fn order_ties(map: &Map, eye_sector: Option<usize>, hits: &mut [Hit]) {
    let sides = |h: &Hit| {
        let line = &map.lines[h.line];
        let (front, back) = (line.front.sector, line.back.as_ref().map(|b| b.sector));
        if h.from_front {
            (Some(front), back)
        } else {
            (back, Some(front))
        }
    };
    let mut current = eye_sector;
    let mut i = 0;
    while i < hits.len() {
        let tied = hits[i..]
            .iter()
            .take_while(|h| h.depth - hits[i].depth <= hits[i].depth * TIE)
            .count();
        if tied > 1 {
            if let Some(k) = (i..i + tied).find(|&k| sides(&hits[k]).0 == current) {
                hits[i..=k].rotate_right(1);
            }
        }
        current = sides(&hits[i]).1;
        i += 1;
    }
}

fn pixel_colour(map: &Map, cam: &Camera, hits: &[Hit], y: i32, shade: Shade) -> u32 {
    for hit in hits {
        // Is this row's ray above `height` where it crosses the line?
        let above = |height: f64| cam.row_above(y, hit.depth, height);
        let line = &map.lines[hit.line];
        let (near, far) = if hit.from_front {
            (Some(&line.front), line.back.as_ref())
        } else {
            (line.back.as_ref(), Some(&line.front))
        };
        let (a, b) = map.line_points(line);
        let facing = wall_facing(b - a);
        let wall = Surface::Wall { line: hit.line };
        // Backs of one-sided walls never reach here (see collect_hits).
        let Some(near) = near else { continue };
        let sector = &map.sectors[near.sector];
        let far_sector = far.map(|f| &map.sectors[f.sector]);
        let light = sector.light;
        let (ceiling, floor) = plane_surfaces(near.sector, sector);
        if above(ceiling_at_line(sector, far_sector)) {
            return colour(shade, ceiling, light, 1.0);
        }
        if !above(sector.floor) {
            return colour(shade, floor, light, 1.0);
        }
        match far_sector {
            Some(back) if above(back.floor) && !above(back.ceiling) => continue,
            _ => return colour(shade, wall, light, facing),
        }
    }
    colour(shade, Surface::Void, 0, 1.0)
}
