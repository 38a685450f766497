//! What the cost splitter knows of each map line before the build starts: its
//! partition for either side, and which lines are collinear (one candidate).

use std::collections::HashMap;

use glam::DVec2;

use super::build::Partition;
use super::{LineSide, Seg};
use crate::map::Map;

pub struct LineTable {
    /// Per map line, its collinear group: lines on one infinite line give one
    /// partition, so a node tries only the first seg of each group.
    group: Vec<u32>,
    pub groups: usize,
    /// Per map line, its partition for a front seg and for a back seg; the
    /// same values `Partition::of_seg` gives the build.
    parts: Vec<[Partition; 2]>,
}

impl LineTable {
    pub fn new(map: &Map) -> Self {
        let group = collinear_groups(map);
        let groups = group.iter().max().map_or(0, |&g| g as usize + 1);
        let parts = (0..map.lines.len())
            .map(|l| [LineSide::Front, LineSide::Back].map(|side| Partition::of_side(map, l, side)))
            .collect();
        LineTable { group, groups, parts }
    }

    pub fn group(&self, line: usize) -> usize {
        self.group[line] as usize
    }

    pub fn part(&self, line: usize, side: LineSide) -> &Partition {
        &self.parts[line][(side == LineSide::Back) as usize]
    }

    pub fn part_of(&self, seg: &Seg) -> &Partition {
        self.part(seg.line, seg.side)
    }
}

/// Numbers each map line's infinite line, collinear lines alike, whichever
/// way they run. Lines with integer end points (every Doom map) are keyed
/// exactly by their equation `a x + b y = c` reduced by the gcd; any other
/// line is a group of its own (no collinear candidate is then skipped, which
/// costs time, never correctness).
pub fn collinear_groups(map: &Map) -> Vec<u32> {
    let mut ids: HashMap<(i64, i64, i64), u32> = HashMap::new();
    let mut next = 0u32;
    let mut fresh = || {
        next += 1;
        next - 1
    };
    let mut group = Vec::with_capacity(map.lines.len());
    for line in &map.lines {
        let (p, q) = map.line_points(line);
        let g = match line_equation(p, q) {
            Some(key) => *ids.entry(key).or_insert_with(&mut fresh),
            None => fresh(),
        };
        group.push(g);
    }
    group
}

/// The reduced integer equation of the line through `p` and `q`, when both are
/// integral within ±2^24 (so that every product below is exact).
fn line_equation(p: DVec2, q: DVec2) -> Option<(i64, i64, i64)> {
    let limit = crate::geom::MAX_COORD;
    if [p.x, p.y, q.x, q.y].iter().any(|v| v.fract() != 0.0 || v.abs() > limit) {
        return None;
    }
    let (px, py, qx, qy) = (p.x as i64, p.y as i64, q.x as i64, q.y as i64);
    let (mut a, mut b) = (qy - py, px - qx);
    let g = gcd(a.unsigned_abs(), b.unsigned_abs()) as i64;
    if g == 0 {
        return None;
    }
    (a, b) = (a / g, b / g);
    if a < 0 || (a == 0 && b < 0) {
        (a, b) = (-a, -b);
    }
    Some((a, b, a * px + b * py))
}

fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    #[test]
    fn collinear_lines_share_an_equation_whichever_way_they_run() {
        let e = line_equation(v(0.0, 0.0), v(2.0, 4.0));
        assert_eq!(e, line_equation(v(3.0, 6.0), v(1.0, 2.0)));
        assert_eq!(e, line_equation(v(-5.0, -10.0), v(-4.0, -8.0)));
        assert_ne!(e, line_equation(v(0.0, 1.0), v(2.0, 5.0)), "parallel, not collinear");
        assert_eq!(line_equation(v(0.5, 0.0), v(1.0, 1.0)), None, "not integral: a group of its own");
    }
}
