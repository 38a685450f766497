//! The blockmap: a uniform grid over the map whose cells list the lines that
//! pass through them (Doom's BLOCKMAP lump, built at load time). Collision asks
//! it for the lines near a small box, so a move costs the same on a 7-line map
//! and on the 2290-line maze.

use glam::DVec2;

use crate::map::Map;

/// Cell size in map units (Doom's `MAPBLOCKSIZE`, 128). A tick's move, with
/// the body round it, fits in a box of at most 94 units a side (the speed
/// limit 30 plus radius 16 plus one, each way; as Doom's player moves), so
/// a query touches at most two cells along each axis.
pub const CELL: f64 = 128.0;
/// Cells per axis are capped so a huge sparse map (coordinates up to 2^24)
/// cannot ask for a giant grid; such a map gets bigger cells instead.
const MAX_CELLS_PER_AXIS: usize = 512;

/// Lines per cell, stored flat: cell `i` owns `lines[starts[i]..starts[i + 1]]`.
#[derive(Clone, Debug)]
pub struct Blockmap {
    origin: DVec2,
    cell: f64,
    columns: usize,
    rows: usize,
    starts: Vec<u32>,
    lines: Vec<u32>,
}

impl Blockmap {
    /// The map's lines (its walls), numbered as in `map.lines`.
    pub fn new(map: &Map) -> Blockmap {
        Blockmap::of_segments(&map.vertices, map.lines.iter().map(|l| map.line_points(l)))
    }

    /// The map's trigger lines, numbered as in `map.trigger_lines`.
    pub fn of_trigger_lines(map: &Map) -> Blockmap {
        let points = map.trigger_lines.iter().map(|t| (map.vertices[t.from], map.vertices[t.to]));
        Blockmap::of_segments(&map.vertices, points)
    }

    /// Segments numbered in the order given, over a grid covering `points`
    /// (which must include every segment's ends).
    fn of_segments(points: &[DVec2], segments: impl Iterator<Item = (DVec2, DVec2)>) -> Blockmap {
        let mut min = DVec2::INFINITY;
        let mut max = DVec2::NEG_INFINITY;
        for v in points {
            min = min.min(*v);
            max = max.max(*v);
        }
        if points.is_empty() {
            (min, max) = (DVec2::ZERO, DVec2::ZERO);
        }
        let extent = (max - min).max_element().max(1.0);
        let cell = CELL.max(extent / MAX_CELLS_PER_AXIS as f64);
        // One spare cell on each axis: the last vertex may sit exactly on the far edge.
        let columns = ((max.x - min.x) / cell) as usize + 1;
        let rows = ((max.y - min.y) / cell) as usize + 1;
        let mut cells: Vec<Vec<u32>> = vec![Vec::new(); columns * rows];
        let grid = Blockmap { origin: min, cell, columns, rows, starts: Vec::new(), lines: Vec::new() };
        for (i, (a, b)) in segments.enumerate() {
            let (x0, x1, y0, y1) = grid.cell_range(a.min(b), a.max(b));
            for cy in y0..y1 {
                for cx in x0..x1 {
                    if grid.segment_touches_cell(a, b, cx, cy) {
                        cells[cy * columns + cx].push(i as u32);
                    }
                }
            }
        }
        let mut starts = Vec::with_capacity(cells.len() + 1);
        let mut lines = Vec::new();
        for c in &cells {
            starts.push(lines.len() as u32);
            lines.extend_from_slice(c);
        }
        starts.push(lines.len() as u32);
        Blockmap { starts, lines, ..grid }
    }

    /// Cells `[x0, x1) x [y0, y1)` covering the box `min..=max`, clamped to the grid.
    fn cell_range(&self, min: DVec2, max: DVec2) -> (usize, usize, usize, usize) {
        let index = |v: f64, n: usize| ((v / self.cell).floor().max(0.0) as usize).min(n - 1);
        let lo = min - self.origin;
        let hi = max - self.origin;
        let (x0, x1) = (index(lo.x, self.columns), index(hi.x, self.columns) + 1);
        let (y0, y1) = (index(lo.y, self.rows), index(hi.y, self.rows) + 1);
        (x0, x1, y0, y1)
    }

    /// Does segment `a-b` meet cell `(cx, cy)` (closed, grown by a unit so
    /// rounding at a cell edge can only add a line, never lose one)?
    fn segment_touches_cell(&self, a: DVec2, b: DVec2, cx: usize, cy: usize) -> bool {
        let lo = self.origin + DVec2::new(cx as f64, cy as f64) * self.cell - DVec2::ONE;
        let hi = lo + DVec2::splat(self.cell + 2.0);
        // Liang-Barsky: clip the segment's parameter range to the box.
        let d = b - a;
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [(-d.x, a.x - lo.x), (d.x, hi.x - a.x), (-d.y, a.y - lo.y), (d.y, hi.y - a.y)] {
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
        t0 <= t1
    }

    /// Calls `f` with every line listed in the cells the box `min..=max`
    /// touches; a line in several cells comes once per cell (see [`LineQuery`]).
    fn for_each_in(&self, min: DVec2, max: DVec2, mut f: impl FnMut(u32)) {
        let (x0, x1, y0, y1) = self.cell_range(min, max);
        for cy in y0..y1 {
            for cx in x0..x1 {
                let i = cy * self.columns + cx;
                for &line in &self.lines[self.starts[i] as usize..self.starts[i + 1] as usize] {
                    f(line);
                }
            }
        }
    }
}

/// Reusable scratch for blockmap queries: each line once per query, in a
/// fixed order (cells row by row, lines by index within a cell), so the
/// simulation never depends on hash order. Doom's `validcount` trick: a
/// stamp per line instead of clearing a set.
#[derive(Clone, Debug, Default)]
pub struct LineQuery {
    stamp: u32,
    seen: Vec<u32>,
    pub found: Vec<u32>,
}

impl LineQuery {
    /// The lines near the box `min..=max`, in `self.found`.
    pub fn run(&mut self, blockmap: &Blockmap, line_count: usize, min: DVec2, max: DVec2) -> &[u32] {
        if self.seen.len() != line_count {
            self.seen = vec![0; line_count];
            self.stamp = 0;
        }
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.seen.fill(0);
            self.stamp = 1;
        }
        self.found.clear();
        let (seen, stamp, found) = (&mut self.seen, self.stamp, &mut self.found);
        blockmap.for_each_in(min, max, |line| {
            if seen[line as usize] != stamp {
                seen[line as usize] = stamp;
                found.push(line);
            }
        });
        &self.found
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::map::parse_map;

    #[test]
    fn every_line_near_a_box_is_found() {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../maps/pillars.ron")).unwrap();
        let map = parse_map(&text, "pillars.ron").unwrap();
        let grid = Blockmap::new(&map);
        let mut query = LineQuery::default();
        let (lo, hi) =
            map.vertices.iter().fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), v| (lo.min(*v), hi.max(*v)));
        // Boxes on a grid over the whole map: every line whose bounding box
        // meets the query box and which passes through it must be listed.
        let mut y = lo.y;
        while y < hi.y {
            let mut x = lo.x;
            while x < hi.x {
                let (min, max) = (DVec2::new(x, y), DVec2::new(x + 40.0, y + 40.0));
                let found: Vec<u32> = query.run(&grid, map.lines.len(), min, max).to_vec();
                for (i, line) in map.lines.iter().enumerate() {
                    let (a, b) = map.line_points(line);
                    let mid = (a + b) / 2.0;
                    let inside = |p: DVec2| p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
                    if inside(a) || inside(b) || inside(mid) {
                        assert!(found.contains(&(i as u32)), "line {i} missing near ({x}, {y})");
                    }
                }
                x += 37.0;
            }
            y += 37.0;
        }
    }
}
