//! Actors by grid cell (Doom's blocklinks): every actor that can block,
//! be shot, be picked up or be raised (all but `NoBlockmap` ones) is listed
//! in the 128-unit cell under its centre, so that a step, a missile, a
//! shot or an explosion asks only the cells near it, and a tick's cost
//! does not grow with the number of actors elsewhere on the map.

use glam::DVec2;

/// A cell's side in map units (Doom's MAPBLOCKUNITS).
pub const CELL: f64 = 128.0;

/// No cell: the actor is not listed.
pub const UNLISTED: u32 = u32::MAX;

#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct ThingGrid {
    origin: DVec2,
    cols: usize,
    rows: usize,
    cells: Vec<Vec<u32>>,
    /// The widest radius listed so far: a query reaches this far past its box.
    reach: f64,
}

impl ThingGrid {
    /// A grid over the box `min..max` (positions outside clamp to the edge cells).
    pub fn new(min: DVec2, max: DVec2) -> ThingGrid {
        let span = ((max - min) / CELL).ceil().max(DVec2::ONE);
        let cols = (span.x as usize).clamp(1, 4096);
        let rows = (span.y as usize).clamp(1, 4096);
        ThingGrid { origin: min, cols, rows, cells: vec![Vec::new(); cols * rows], reach: 0.0 }
    }

    fn col_row(&self, p: DVec2) -> (usize, usize) {
        let c = ((p - self.origin) / CELL).floor();
        let clamp = |v: f64, n: usize| if v.is_nan() || v < 0.0 { 0 } else { (v as usize).min(n - 1) };
        (clamp(c.x, self.cols), clamp(c.y, self.rows))
    }

    /// The cell under `p`.
    pub fn cell(&self, p: DVec2) -> u32 {
        let (c, r) = self.col_row(p);
        (r * self.cols + c) as u32
    }

    /// How many cells it has.
    pub fn cells(&self) -> usize {
        self.cells.len()
    }

    /// Is a loaded grid laid out as `fresh` (the same map's) and does it
    /// list only actors below `actors`?
    pub fn fits(&self, fresh: &ThingGrid, actors: usize) -> bool {
        (self.origin, self.cols, self.rows) == (fresh.origin, fresh.cols, fresh.rows)
            && self.cells.len() == fresh.cells.len()
            && self.cells.iter().flatten().all(|&n| (n as usize) < actors)
    }

    /// Lists actor `n` (of `radius`) in `cell`.
    pub fn insert(&mut self, n: u32, cell: u32, radius: f64) {
        self.cells[cell as usize].push(n);
        self.reach = self.reach.max(radius);
    }

    pub fn remove(&mut self, n: u32, cell: u32) {
        let list = &mut self.cells[cell as usize];
        if let Some(k) = list.iter().position(|&m| m == n) {
            list.swap_remove(k);
        }
    }

    /// Appends to `out` every actor listed in a cell that a box of
    /// `min..max`, grown by the widest radius listed, overlaps. Cells are
    /// visited row by row and an actor is listed once, so the order is
    /// fixed by the game's history (the simulation stays deterministic).
    pub fn near(&self, min: DVec2, max: DVec2, out: &mut Vec<u32>) {
        let grow = DVec2::splat(self.reach);
        let (c0, r0) = self.col_row(min - grow);
        let (c1, r1) = self.col_row(max + grow);
        for r in r0..=r1 {
            for c in c0..=c1 {
                out.extend_from_slice(&self.cells[r * self.cols + c]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_actor_is_found_from_a_neighbouring_cell_and_lost_when_removed() {
        let mut g = ThingGrid::new(DVec2::ZERO, DVec2::splat(1024.0));
        let cell = g.cell(DVec2::new(130.0, 130.0));
        g.insert(7, cell, 20.0);
        let mut out = Vec::new();
        // A box just left of the cell, within the radius of it.
        g.near(DVec2::new(100.0, 130.0), DVec2::new(110.0, 131.0), &mut out);
        assert_eq!(out, [7]);
        out.clear();
        g.near(DVec2::new(900.0, 900.0), DVec2::new(901.0, 901.0), &mut out);
        assert!(out.is_empty());
        g.remove(7, cell);
        g.near(DVec2::ZERO, DVec2::splat(1024.0), &mut out);
        assert!(out.is_empty());
        // Far outside, NaN: clamped, no panic.
        let _ = g.cell(DVec2::new(f64::NAN, -1e300));
    }
}
