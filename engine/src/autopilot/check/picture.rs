//! The plan picture `check -o` draws: the map from above, what can be
//! reached, and the route.

use glam::DVec2;

use super::super::nav::{solid, Cell, NavGrid, CELL, NONE};
use super::super::route::Route;
use crate::framebuffer::{rgb, Framebuffer};
use crate::level::Level;

/// Seconds spent: the report (the closure and every question put to it),
/// then the route.
#[derive(Clone, Copy, Debug, Default)]
pub struct Timing {
    pub analyse: f64,
    pub route: f64,
}

/// What the plan picture shows.
pub struct Drawing {
    pub(super) nav: NavGrid,
    pub(super) reached: Vec<bool>,
    finish: Vec<bool>,
    /// The route drawn (see [`super::RouteFrom`]).
    pub route: Route,
    /// What the check cost.
    pub timing: Timing,
    /// The map's lines with their colours, and the BSP's partitions (each
    /// clipped to its node's box).
    lines: Vec<(DVec2, DVec2, u32)>,
    partitions: Vec<(DVec2, DVec2)>,
}

impl Drawing {
    pub(super) fn new(level: &Level, nav: NavGrid, reached: Vec<bool>, finish: Vec<bool>) -> Drawing {
        let map = &level.compiled.map;
        let mut lines = Vec::new();
        for l in &map.lines {
            let (a, b) = map.line_points(l);
            let colour = if l.special.is_some() {
                rgb(90, 140, 255)
            } else if solid(l) {
                rgb(235, 235, 235)
            } else {
                rgb(120, 120, 120)
            };
            lines.push((a, b, colour));
        }
        for t in &map.trigger_lines {
            lines.push((map.vertices[t.from], map.vertices[t.to], rgb(90, 140, 255)));
        }
        let partitions = level
            .compiled
            .bsp
            .nodes
            .iter()
            .filter_map(|node| {
                let bbox = node.bbox[0].union(node.bbox[1]);
                clip_line(node.a, node.b, bbox.min, bbox.max)
            })
            .collect();
        Drawing { nav, reached, finish, route: Route::default(), timing: Timing::default(), lines, partitions }
    }

    /// The map from above, `size` pixels on its longer side: reachable
    /// floor dark green, unreachable floor dark red, soft-lock floor orange,
    /// walls white, two-sided lines grey, special lines blue, the route
    /// yellow from the white square of the start, a yellow square where it
    /// meets each goal and a larger one at the exit, and with `partitions`
    /// the BSP's partition lines cyan.
    pub fn draw(&self, size: usize, partitions: bool) -> Framebuffer {
        let nav = &self.nav;
        let extent = DVec2::new(nav.width as f64, nav.height as f64) * CELL;
        let scale = size as f64 / extent.x.max(extent.y);
        let (w, h) = (((extent.x * scale) as usize).max(1) + 8, ((extent.y * scale) as usize).max(1) + 8);
        let mut fb = Framebuffer::new(w, h);
        let to_px = |p: DVec2| {
            let q = (p - nav.origin) * scale;
            DVec2::new(q.x + 4.0, h as f64 - 4.0 - q.y)
        };
        let any_finish = self.finish.iter().any(|&f| f);
        for c in 0..nav.cells() as Cell {
            if nav.centre[c as usize] == NONE || !nav.standable(c) {
                continue;
            }
            let reached = self.reached.get(c as usize).copied().unwrap_or(false);
            let finish = self.finish.get(c as usize).copied().unwrap_or(false);
            let colour = match (reached, finish) {
                (true, false) if any_finish => rgb(170, 90, 0),
                (true, _) => rgb(20, 70, 30),
                (false, _) => rgb(110, 20, 20),
            };
            let p = to_px(nav.centre_of(c) - DVec2::splat(CELL / 2.0));
            let q = to_px(nav.centre_of(c) + DVec2::splat(CELL / 2.0));
            fill(&mut fb, p, q, colour);
        }
        if partitions {
            for &(a, b) in &self.partitions {
                line(&mut fb, to_px(a), to_px(b), rgb(0, 150, 170));
            }
        }
        for &(a, b, colour) in &self.lines {
            line(&mut fb, to_px(a), to_px(b), colour);
        }
        let points = &self.route.points;
        for i in 1..points.len() {
            if !self.route.teleport.get(i).copied().unwrap_or(false) {
                line(&mut fb, to_px(points[i - 1]), to_px(points[i]), rgb(255, 220, 0));
            }
        }
        // Where the route meets each goal a small yellow square, at the
        // exit a larger one; the start is white.
        let stops = self.route.stops.len();
        for (i, &p) in self.route.stops.iter().enumerate() {
            let r = DVec2::splat(if self.route.exits && i + 1 == stops { 6.0 } else { 3.0 });
            fill(&mut fb, to_px(p) - r, to_px(p) + r, rgb(255, 220, 0));
        }
        if let Some(&p) = self.route.points.first() {
            let r = DVec2::splat(5.0);
            fill(&mut fb, to_px(p) - r, to_px(p) + r, rgb(255, 255, 255));
        }
        fb
    }
}

fn fill(fb: &mut Framebuffer, p: DVec2, q: DVec2, colour: u32) {
    let (x0, x1) = (p.x.min(q.x).floor().max(0.0) as usize, p.x.max(q.x).ceil().max(0.0) as usize);
    let (y0, y1) = (p.y.min(q.y).floor().max(0.0) as usize, p.y.max(q.y).ceil().max(0.0) as usize);
    for y in y0..y1.min(fb.height) {
        for x in x0..x1.min(fb.width) {
            fb.pixels[y * fb.width + x] = colour;
        }
    }
}

fn line(fb: &mut Framebuffer, a: DVec2, b: DVec2, colour: u32) {
    let n = (b - a).abs().max_element().ceil().max(1.0) as usize;
    for i in 0..=n {
        let p = a + (b - a) * (i as f64 / n as f64);
        if p.x >= 0.0 && p.y >= 0.0 && (p.x as usize) < fb.width && (p.y as usize) < fb.height {
            fb.pixels[p.y as usize * fb.width + p.x as usize] = colour;
        }
    }
}

/// The part of the infinite line through `a` and `b` inside the box.
fn clip_line(a: DVec2, b: DVec2, min: DVec2, max: DVec2) -> Option<(DVec2, DVec2)> {
    let d = b - a;
    let (mut t0, mut t1) = (f64::MIN, f64::MAX);
    for axis in 0..2 {
        let (o, v, lo, hi) = if axis == 0 { (a.x, d.x, min.x, max.x) } else { (a.y, d.y, min.y, max.y) };
        if v.abs() < 1e-12 {
            if o < lo || o > hi {
                return None;
            }
            continue;
        }
        let (u0, u1) = ((lo - o) / v, (hi - o) / v);
        t0 = t0.max(u0.min(u1));
        t1 = t1.min(u0.max(u1));
    }
    (t0 <= t1).then(|| (a + d * t0, a + d * t1))
}
