//! Collision: moving the body's circle through the map along its velocity,
//! stopping at walls and sliding along them. Hands the new position (and the
//! velocity with its into-the-wall part removed) back to the tick.
//!
//! A line *blocks* the body when it is one-sided, flagged `impassable`, or
//! two-sided with a step up of more than [`MAX_STEP`] from the feet or with
//! less than [`HEIGHT`] of headroom ([`blocks`]). The body is swept
//! continuously against blocking lines: for each, the earliest time its
//! circle would touch the segment (its interior, or a round end), so no speed
//! can carry it through a wall. The move is cut into pieces no longer than
//! [`PIECE`] (half the radius) so that each piece also checks the whole area
//! under the body ([`fits`]): the highest floor and lowest ceiling of every
//! sector the circle overlaps, as Doom's P_CheckPosition does.
//!
//! Steps are measured from the feet's height at the start of the tick, as in
//! Doom (P_TryMove compares against `thing->z`, which only P_ZMovement
//! changes, once per tick): the body climbs at most [`MAX_STEP`] per tick, so
//! a staircase is climbed one step per tick at most.

use glam::DVec2;

use super::blockmap::{Blockmap, LineQuery};
use super::player::{HEIGHT, MAX_STEP, RADIUS};
use crate::bsp::CompiledMap;
use crate::map::{Line, Map};

/// Longest piece of a move, checked on its own. Shorter than the radius as
/// the issue asks; with the continuous sweep this is about the area check
/// and its step-up, not about tunnelling.
pub const PIECE: f64 = RADIUS / 2.0;
/// After a hit the body stops this far (along its path) short of the contact,
/// so the next sweep does not start in contact because of rounding.
const SKIN: f64 = 1.0 / 1024.0;
/// At most this many walls are slid along in one tick (a corner takes two).
const MAX_HITS: usize = 4;

/// The map, its BSP (to find the sector under a point) and the blockmap.
#[derive(Clone, Copy)]
pub struct World<'a> {
    pub compiled: &'a CompiledMap,
    pub blockmap: &'a Blockmap,
}

/// What the body's circle covers at a position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Area {
    /// The sector under the centre.
    pub sector: usize,
    /// Highest floor and lowest ceiling over every sector the circle overlaps.
    pub floor: f64,
    pub ceiling: f64,
}

/// Does `line` block a body whose feet are at `z`?
pub fn blocks(map: &Map, line: &Line, z: f64) -> bool {
    let Some(back) = &line.back else { return true };
    if line.flags.impassable {
        return true;
    }
    let (front, back) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
    let floor = front.floor.max(back.floor);
    let ceiling = front.ceiling.min(back.ceiling);
    floor - z > MAX_STEP || ceiling - floor.max(z) < HEIGHT
}

/// Distance from `p` to the segment `a-b`.
pub fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    (a + d * t).distance(p)
}

impl World<'_> {
    fn map(&self) -> &Map {
        &self.compiled.map
    }

    /// The lines that can matter to a body within `reach` of `p`.
    pub fn lines_near<'q>(&self, query: &'q mut LineQuery, p: DVec2, reach: f64) -> &'q [u32] {
        let r = DVec2::splat(reach);
        query.run(self.blockmap, self.map().lines.len(), p - r, p + r)
    }

    /// The area under a circle at `p`, from `near` (which must hold every line within
    /// [`RADIUS`] of `p`).
    pub fn area(&self, near: &[u32], p: DVec2) -> Area {
        let map = self.map();
        let sector = self.compiled.sector_at(p);
        let (mut floor, mut ceiling) = (map.sectors[sector].floor, map.sectors[sector].ceiling);
        for &i in near {
            let line = &map.lines[i as usize];
            let (a, b) = map.line_points(line);
            if distance_to_segment(p, a, b) < RADIUS {
                for side in std::iter::once(&line.front).chain(&line.back) {
                    floor = floor.max(map.sectors[side.sector].floor);
                    ceiling = ceiling.min(map.sectors[side.sector].ceiling);
                }
            }
        }
        Area { sector, floor, ceiling }
    }

    /// Every sector the circle at `p` overlaps, into `out` (sorted, no
    /// repeats); `centre` is the sector under `p` (the caller's from
    /// [`Self::area`]: locating it again would descend the BSP twice a tick).
    pub fn sectors_touched(&self, near: &[u32], p: DVec2, centre: usize, out: &mut Vec<usize>) {
        let map = self.map();
        out.clear();
        out.push(centre);
        for &i in near {
            let line = &map.lines[i as usize];
            let (a, b) = map.line_points(line);
            if distance_to_segment(p, a, b) < RADIUS {
                out.extend(std::iter::once(&line.front).chain(&line.back).map(|s| s.sector));
            }
        }
        out.sort_unstable();
        out.dedup();
    }

    /// Can the body stand at `p` with its feet at `z`: no step up over
    /// [`MAX_STEP`] anywhere under it, and [`HEIGHT`] of room once it has
    /// stepped up.
    fn fits(&self, area: &Area, z: f64) -> bool {
        area.floor - z <= MAX_STEP && area.ceiling - area.floor.max(z) >= HEIGHT
    }

    /// Moves the body from `pos` along `velocity` (this tick's displacement)
    /// with its feet at `z`, sliding along whatever blocks it. Returns the
    /// new position; `velocity` loses the part of it that pushed into walls.
    ///
    /// The body ends where it could stand: swept against every blocking
    /// line, and each piece of the path accepted only where the area under
    /// it fits ([`Self::fits`]); a piece that does not fit ends the move.
    pub fn slide(&self, query: &mut LineQuery, pos: DVec2, z: f64, velocity: &mut DVec2) -> DVec2 {
        // The path is never longer than the velocity, so one query covers it.
        let near = self.lines_near(query, pos, velocity.length() + RADIUS + 1.0);
        let mut pos = pos;
        let mut remaining = *velocity;
        let mut hits = 0;
        // Pieces plus hits bound the loop: MAX_SPEED / PIECE + MAX_HITS + 1 < 16.
        for _ in 0..16 {
            let len = remaining.length();
            if len < 1e-9 {
                break;
            }
            let piece = if len > PIECE { remaining * (PIECE / len) } else { remaining };
            let hit = self.first_hit(near, pos, piece, z);
            let t = hit.map_or(1.0, |h| (h.t - SKIN / piece.length()).max(0.0));
            if t > 0.0 {
                let next = pos + piece * t;
                if !self.fits(&self.area(near, next), z) {
                    *velocity = DVec2::ZERO;
                    break;
                }
                pos = next;
            }
            remaining -= piece * t;
            if let Some(h) = hit {
                hits += 1;
                remaining = clip(remaining, h.normal);
                *velocity = clip(*velocity, h.normal);
                if hits >= MAX_HITS {
                    break;
                }
            }
        }
        pos
    }

    /// The earliest contact of the circle moving from `p` by `d` with a line
    /// that blocks feet at `z`.
    fn first_hit(&self, near: &[u32], p: DVec2, d: DVec2, z: f64) -> Option<Hit> {
        let map = self.map();
        let mut best: Option<Hit> = None;
        for &i in near {
            let line = &map.lines[i as usize];
            if !blocks(map, line, z) {
                continue;
            }
            let (a, b) = map.line_points(line);
            if let Some(h) = sweep_segment(p, d, a, b) {
                if best.is_none_or(|b: Hit| h.t < b.t) {
                    best = Some(h);
                }
            }
        }
        best
    }
}

/// A contact: the fraction of the move before it, and the unit normal from
/// the wall towards the body.
#[derive(Clone, Copy, Debug)]
struct Hit {
    t: f64,
    normal: DVec2,
}

/// Removes the part of `v` that pushes against a wall with normal `n`.
fn clip(v: DVec2, n: DVec2) -> DVec2 {
    v - n * v.dot(n).min(0.0)
}

/// When, for `t` in `[0, 1]`, the circle of [`RADIUS`] at `p + t d` first
/// touches segment `a-b`, approaching it. A circle already overlapping the
/// segment and moving towards it touches at `t = 0`; one moving away or
/// along it never does, so a body can always leave a wall.
fn sweep_segment(p: DVec2, d: DVec2, a: DVec2, b: DVec2) -> Option<Hit> {
    let mut best = None;
    let e = b - a;
    let len = e.length();
    let u = e / len;
    let right = DVec2::new(u.y, -u.x);
    let s0 = (p - a).dot(right);
    if s0 != 0.0 {
        let n = if s0 > 0.0 { right } else { -right };
        let approach = -d.dot(n);
        if approach > 0.0 {
            let t = ((s0.abs() - RADIUS) / approach).max(0.0);
            if t <= 1.0 {
                let along = (p + d * t - a).dot(u);
                if (0.0..=len).contains(&along) {
                    best = Some(Hit { t, normal: n });
                }
            }
        }
    }
    for end in [a, b] {
        if let Some(h) = sweep_point(p, d, end) {
            if best.is_none_or(|b: Hit| h.t < b.t) {
                best = Some(h);
            }
        }
    }
    best
}

/// When the circle at `p + t d` first touches the point `v`, approaching it.
fn sweep_point(p: DVec2, d: DVec2, v: DVec2) -> Option<Hit> {
    let m = p - v;
    let half_b = m.dot(d);
    if half_b >= 0.0 {
        return None; // moving away from the point, or past it
    }
    let a = d.length_squared();
    let c = m.length_squared() - RADIUS * RADIUS;
    if c <= 0.0 {
        let normal = m.try_normalize().unwrap_or(-d / a.sqrt());
        return Some(Hit { t: 0.0, normal });
    }
    let disc = half_b * half_b - a * c;
    if disc < 0.0 {
        return None;
    }
    let t = (-half_b - disc.sqrt()) / a;
    if t > 1.0 {
        return None;
    }
    let t = t.max(0.0);
    let normal = (p + d * t - v).try_normalize().unwrap_or(-d / a.sqrt());
    Some(Hit { t, normal })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sweep_meets_a_wall_at_the_radius() {
        let (a, b) = (DVec2::new(100.0, -50.0), DVec2::new(100.0, 50.0));
        let h = sweep_segment(DVec2::new(0.0, 0.0), DVec2::new(200.0, 0.0), a, b).unwrap();
        assert!((h.t - (100.0 - RADIUS) / 200.0).abs() < 1e-12, "{h:?}");
        assert_eq!(h.normal, DVec2::new(-1.0, 0.0));
        // Moving away, or along, never hits; overlapping and approaching hits at once.
        assert!(sweep_segment(DVec2::new(90.0, 0.0), DVec2::new(-5.0, 0.0), a, b).is_none());
        assert!(sweep_segment(DVec2::new(90.0, 0.0), DVec2::new(0.0, 5.0), a, b).is_none());
        assert_eq!(sweep_segment(DVec2::new(90.0, 0.0), DVec2::new(5.0, 0.0), a, b).unwrap().t, 0.0);
        // The round end: passing 10 units beyond the end still touches it.
        let h = sweep_segment(DVec2::new(0.0, 60.0), DVec2::new(200.0, 0.0), a, b).unwrap();
        let hit_at = DVec2::new(0.0, 60.0) + DVec2::new(200.0, 0.0) * h.t;
        assert!((hit_at.distance(b) - RADIUS).abs() < 1e-9);
    }
}
