//! Where Doom's use reaches a line from, as `check` counts it: the cells
//! from which a press sets a switch off, and the openings it needs first.
//!
//! Doom's `P_UseLines` traces `USERANGE` (64 units) from the player's
//! centre along the way he faces; `PTR_UseTraverse` passes two-sided lines
//! while their opening is open (`openrange > 0`), stops at a wall with none
//! ("oof"), and stops at the first line with a special, whichever it is
//! (another switch, a walk line: vanilla uses it, or nothing happens from
//! its back). Heights play no part beyond the openings: a switch on a
//! ledge's face is pressed from the floor below, a switch at the back of a
//! door's slot from in front of the door once it is open. The player may
//! face any way, so a cell counts when some point of the line (a little
//! inside its ends, where the walls beside meet it) is within 64 of its
//! centre, on its front, with the way there clear; less what the body's
//! centre must keep further from a wall than the cell's.
//!
//! The autopilot's own targets ([`super::plan::use_cells`]) keep a margin
//! for steering (it walks to a spot and lines up); `check` asks only
//! whether a press can reach at all.

use glam::DVec2;

use super::nav::{solid, Cell, Heights, LineId, NavGrid};
use super::plan::{line_of, Targets};
use crate::geom::{crossing, distance_to_segment, front_distance};
use crate::map::Map;
use crate::play::player::RADIUS;
use crate::play::USE_RANGE;

/// The cells a press on one line reaches it from.
#[derive(Clone, Default)]
pub struct Presses {
    /// Cells from which it reaches as the map starts.
    pub now: Targets,
    /// Cells from which it reaches once each of these two-sided lines
    /// (shut as the map starts: a door's slot, a floor up to a ceiling)
    /// has an opening.
    pub once_open: Vec<(Cell, Vec<u32>)>,
}

impl Presses {
    /// The cells a press reaches the line from with the sectors at
    /// `heights` (each at its most open: ceiling as high as it goes, floor
    /// as low).
    pub fn at(&self, map: &Map, heights: &Heights) -> Targets {
        let mut t = self.now.clone();
        for (c, lines) in &self.once_open {
            if lines.iter().all(|&l| open(map, heights, l as usize)) {
                t.insert(*c);
            }
        }
        t
    }

    /// Does a press reach the line from a cell `reached` marks, with the
    /// sectors at `heights`? As [`Presses::at`], without building the set.
    pub fn met(&self, map: &Map, heights: &Heights, reached: &[bool]) -> bool {
        self.now.cells().any(|c| reached[c as usize])
            || self
                .once_open
                .iter()
                .any(|(c, lines)| reached[*c as usize] && lines.iter().all(|&l| open(map, heights, l as usize)))
    }
}

/// Does two-sided line `l` have an opening with the sectors at `heights`?
fn open(map: &Map, heights: &Heights, l: usize) -> bool {
    let line = &map.lines[l];
    let Some(back) = &line.back else { return false };
    let (f, b) = (line.front.sector, back.sector);
    heights.ceiling[f].min(heights.ceiling[b]) > heights.low[f].max(heights.low[b])
}

/// What stops a press from `p` before it gets to `q` on `target`: `None`
/// when something always does (a one-sided wall, another special line),
/// else the two-sided lines shut as the map starts that it passes
/// (`Some(empty)`: nothing stops it now).
fn stoppers(map: &Map, start: &Heights, near: &[usize], p: DVec2, q: DVec2, target: LineId) -> Option<Vec<u32>> {
    let mut shut = Vec::new();
    for &i in near {
        if i as u32 == target {
            continue;
        }
        let (_, a, b, _) = line_of(map, i as u32);
        if crossing(p, q, a, b).is_none() {
            continue;
        }
        if (i as u32) >= map.lines.len() as u32 {
            // A trigger line is a special line.
            return None;
        }
        let line = &map.lines[i];
        if line.back.is_none() || line.special.is_some() {
            return None;
        }
        if !open(map, start, i) {
            shut.push(i as u32);
        }
    }
    Some(shut)
}

/// The cells from which a press reaches `line` (see the module's words).
pub fn press_cells(nav: &NavGrid, map: &Map, line: LineId) -> Presses {
    let (_, a, b, _) = line_of(map, line);
    let reach = DVec2::splat(USE_RANGE);
    let (lo, hi) = (a.min(b) - reach, a.max(b) + reach);
    // The lines a press could pass on its way (trigger lines as their
    // `LineId`s, past the walls).
    let boxed = |p: DVec2, q: DVec2| p.max(q).cmpge(lo).all() && p.min(q).cmple(hi).all();
    let near: Vec<usize> = map
        .lines
        .iter()
        .map(|l| map.line_points(l))
        .chain(map.trigger_lines.iter().map(|t| (map.vertices[t.from], map.vertices[t.to])))
        .enumerate()
        .filter(|&(_, (p, q))| boxed(p, q))
        .map(|(i, _)| i)
        .collect();
    let along = |t: f64| a + (b - a) * t;
    // Points along the line a press may aim at, every 8 units or so.
    let n = ((a.distance(b) / 8.0).ceil() as usize).max(2);
    let points: Vec<DVec2> = (0..=n).map(|i| along(0.02 + 0.96 * i as f64 / n as f64)).collect();
    let start = Heights::of(map);
    let mut presses = Presses::default();
    for c in nav.cells_in_box(lo, hi) {
        if !nav.standable(c) {
            continue;
        }
        let p = nav.centre_of(c);
        if front_distance(a, b, p) <= 0.0 || distance_to_segment(p, a, b) > USE_RANGE {
            continue;
        }
        // A cell's centre may be closer to a wall than a body's can be
        // (a centre need only be 7.5 clear): the body stands that much
        // further off, and reaches that much less (MAP25's switches are
        // 61 units from a cell centre by a railing, 65 from the body).
        let wall = near
            .iter()
            .filter(|&&i| i < map.lines.len() && solid(&map.lines[i]))
            .map(|&i| {
                let (a, b) = map.line_points(&map.lines[i]);
                distance_to_segment(p, a, b)
            })
            .fold(f64::MAX, f64::min);
        let reach = USE_RANGE - (RADIUS - wall).max(0.0);
        let nearest = super::plan::nearest_on(p, along(0.02), along(0.98));
        let mut best: Option<Vec<u32>> = None;
        for q in std::iter::once(nearest).chain(points.iter().copied()) {
            if q.distance(p) > reach {
                continue;
            }
            let Some(shut) = stoppers(map, &start, &near, p, q, line) else { continue };
            if best.as_ref().is_none_or(|b| shut.len() < b.len()) {
                best = Some(shut);
            }
            if best.as_ref().is_some_and(Vec::is_empty) {
                break;
            }
        }
        match best {
            Some(shut) if shut.is_empty() => presses.now.insert(c),
            Some(shut) => presses.once_open.push((c, shut)),
            None => {}
        }
    }
    presses
}
