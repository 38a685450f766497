//! Traces through the map's lines (Doom's P_PathTraverse and its users):
//! which lines a body's centre crossed in a move (walk triggers), and which
//! lines a straight trace meets in order (use, shots). Walls and trigger
//! lines alike; each list in a fixed order, so play stays deterministic.

use glam::DVec2;

use super::blockmap::{Blockmap, LineQuery};
use super::world::SpecialLine;
use crate::geom::{exact_side, Side};
use crate::map::Map;

/// A line a trace or move crossed: where along it (0 at the start, 1 at the
/// end) and from which side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    pub line: SpecialLine,
    pub t: f64,
    /// The trace started on the line's front side (a point on the line
    /// counts as in front, the tie rule of the BSP).
    pub from_front: bool,
}

/// The map's lines, walls and trigger lines, with a blockmap of each.
pub struct Lines<'a> {
    pub map: &'a Map,
    pub walls: &'a Blockmap,
    pub triggers: &'a Blockmap,
}

/// Scratch for [`Lines`] queries.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    pub walls: LineQuery,
    pub triggers: LineQuery,
}

impl Lines<'_> {
    /// Every line the segment `from -> to` crosses or touches, nearest
    /// first (ties by wall before trigger line, then by index).
    pub fn along(&self, scratch: &mut Scratch, from: DVec2, to: DVec2) -> Vec<Crossing> {
        let (lo, hi) = (from.min(to), from.max(to));
        let mut out = Vec::new();
        let walls = scratch.walls.run(self.walls, self.map.lines.len(), lo, hi);
        for &i in walls {
            let (a, b) = self.map.line_points(&self.map.lines[i as usize]);
            if let Some(t) = crossing(from, to, a, b) {
                out.push(Crossing { line: SpecialLine::Wall(i as usize), t, from_front: in_front(a, b, from) });
            }
        }
        let triggers = scratch.triggers.run(self.triggers, self.map.trigger_lines.len(), lo, hi);
        for &i in triggers {
            let t = &self.map.trigger_lines[i as usize];
            let (a, b) = (self.map.vertices[t.from], self.map.vertices[t.to]);
            if let Some(t) = crossing(from, to, a, b) {
                out.push(Crossing { line: SpecialLine::Trigger(i as usize), t, from_front: in_front(a, b, from) });
            }
        }
        out.sort_by(|x, y| x.t.total_cmp(&y.t).then(x.line.cmp(&y.line)));
        out
    }

    /// The lines a body's centre crossed moving `from -> to`: it was on one
    /// side before and on the other after (Doom's P_CrossSpecialLine test),
    /// and its path meets the line itself, not only its extension. Only
    /// lines with a special are listed.
    pub fn crossed(&self, scratch: &mut Scratch, from: DVec2, to: DVec2) -> Vec<Crossing> {
        if from == to {
            return Vec::new();
        }
        let mut out = self.along(scratch, from, to);
        out.retain(|c| {
            let (a, b) = self.points(c.line);
            self.has_special(c.line) && in_front(a, b, from) != in_front(a, b, to)
        });
        out
    }

    fn has_special(&self, line: SpecialLine) -> bool {
        match line {
            SpecialLine::Wall(i) => self.map.lines[i].special.is_some(),
            SpecialLine::Trigger(_) => true,
        }
    }

    pub fn points(&self, line: SpecialLine) -> (DVec2, DVec2) {
        match line {
            SpecialLine::Wall(i) => self.map.line_points(&self.map.lines[i]),
            SpecialLine::Trigger(i) => {
                let t = &self.map.trigger_lines[i];
                (self.map.vertices[t.from], self.map.vertices[t.to])
            }
        }
    }
}

/// Is `p` on the front of `a -> b`, a point on the line counting as front?
fn in_front(a: DVec2, b: DVec2, p: DVec2) -> bool {
    exact_side(a, b, p) != Side::Back
}

/// Where segment `p-q` crosses segment `a-b`, as a fraction of `p-q`;
/// touching counts.
pub fn crossing(p: DVec2, q: DVec2, a: DVec2, b: DVec2) -> Option<f64> {
    let r = q - p;
    let s = b - a;
    let denom = crate::geom::cross(r, s);
    if denom == 0.0 {
        return None;
    }
    let t = crate::geom::cross(a - p, s) / denom;
    let u = crate::geom::cross(a - p, r) / denom;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then_some(t)
}
