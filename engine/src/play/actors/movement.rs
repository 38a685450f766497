//! How monsters walk (Doom's P_TryMove, P_Move and P_NewChaseDir, for
//! actors): in steps of their speed along one of eight directions, each step
//! taken only where the actor's box fits. A step is refused where
//! - a line the box touches is one-sided, impassable or blocks monsters;
//! - the opening under the box is lower than the actor, or its ceiling is
//!   below the actor's top (it would have to duck), or its floor is more
//!   than a 24-unit step above the feet;
//! - the box would hang over a drop of more than 24 units (unless the actor
//!   may drop off or floats);
//! - the centre's way there crosses a one-sided line (beyond Doom, which
//!   checks only where a step ends);
//! - a solid actor's box overlaps it, or the player's (`physics.rs`
//!   asks the grid of actors).
//!
//! Boxes are squares of side `2 radius`, axis aligned, as Doom's; a line
//! touches a box when it crosses its interior (a line along an edge does
//! not), which is Doom's P_BoxOnLineSide rule for a box that straddles it.

use glam::DVec2;

use super::super::blockmap::{Blockmap, LineQuery};
use super::super::player::MAX_STEP;
use crate::bsp::CompiledMap;
use crate::geom::{exact_side, Side};

/// Doom's eight directions and "none" (`dirtype_t`): east, north-east,
/// north, ... anticlockwise; 8 is no direction.
pub const NO_DIR: u8 = 8;
/// Doom's diagonal step share: `47000 / 65536`, a little over `sqrt(1/2)`.
const DIAGONAL: f64 = 47000.0 / 65536.0;
/// A direction's step for a speed of 1.
pub const DIR_STEP: [DVec2; 8] = [
    DVec2::new(1.0, 0.0),
    DVec2::new(DIAGONAL, DIAGONAL),
    DVec2::new(0.0, 1.0),
    DVec2::new(-DIAGONAL, DIAGONAL),
    DVec2::new(-1.0, 0.0),
    DVec2::new(-DIAGONAL, -DIAGONAL),
    DVec2::new(0.0, -1.0),
    DVec2::new(DIAGONAL, -DIAGONAL),
];

/// The direction opposite `dir`.
pub fn opposite(dir: u8) -> u8 {
    if dir == NO_DIR {
        NO_DIR
    } else {
        (dir + 4) % 8
    }
}

/// What the area under a box allows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Opening {
    pub sector: usize,
    /// Highest floor, lowest ceiling and lowest floor under the box.
    pub floor: f64,
    pub ceiling: f64,
    pub dropoff: f64,
    /// The sector whose ceiling is the lowest (a missile that hits it is
    /// gone without a blast if it is sky: Doom's `ceilingline`).
    pub ceiling_sector: usize,
}

/// A body asking to move.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mover {
    /// Where its centre stands now.
    pub pos: DVec2,
    pub radius: f64,
    pub height: f64,
    pub z: f64,
    /// May step off ledges of any height (Doom's MF_DROPOFF) or floats.
    pub may_drop: bool,
    /// Passes through bodies and lines (Doom's MF_NOCLIP).
    pub no_clip: bool,
    /// A missile: lines that block walkers (impassable, monster-blocking)
    /// let it through; it must fit the opening at its own height.
    pub missile: bool,
}

/// Why a move was refused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refusal {
    /// A line the box touches is a wall to it.
    Line(usize),
    /// The opening there does not fit (too low, a step too high, a drop).
    Fit(Opening),
}

/// The map's lines as movement sees them.
pub struct Ground<'a> {
    pub compiled: &'a CompiledMap,
    pub blockmap: &'a Blockmap,
}

impl Ground<'_> {
    /// The opening under a box of `radius` at `p`, or the line that blocks
    /// it outright (one-sided; impassable or blocking monsters, unless
    /// `missile`).
    pub fn opening(&self, query: &mut LineQuery, p: DVec2, radius: f64, missile: bool) -> Result<Opening, usize> {
        let map = &self.compiled.map;
        let sector = self.compiled.sector_at(p);
        let s = &map.sectors[sector];
        let mut o = Opening { sector, floor: s.floor, ceiling: s.ceiling, dropoff: s.floor, ceiling_sector: sector };
        let r = DVec2::splat(radius);
        let (min, max) = (p - r, p + r);
        for &i in query.run(self.blockmap, map.lines.len(), min, max) {
            let line = &map.lines[i as usize];
            let (a, b) = map.line_points(line);
            if !crosses_box(a, b, min, max) {
                continue;
            }
            let Some(back) = &line.back else { return Err(i as usize) };
            if !missile && (line.flags.impassable || line.flags.block_monsters) {
                return Err(i as usize);
            }
            let (f, k) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
            o.floor = o.floor.max(f.floor.max(k.floor));
            let low = if f.ceiling <= k.ceiling { line.front.sector } else { back.sector };
            if map.sectors[low].ceiling < o.ceiling {
                (o.ceiling, o.ceiling_sector) = (map.sectors[low].ceiling, low);
            }
            o.dropoff = o.dropoff.min(f.floor.min(k.floor));
        }
        Ok(o)
    }

    /// The lines a box of `radius` at `p` touches that it could pass
    /// (two-sided, not blocking walkers): those a monster stopped there
    /// may push, in the blockmap's order.
    pub fn passable_touched<'q>(
        &self,
        query: &'q mut LineQuery,
        p: DVec2,
        radius: f64,
    ) -> impl Iterator<Item = usize> + 'q
    where
        Self: 'q,
    {
        let map = &self.compiled.map;
        let r = DVec2::splat(radius);
        let (min, max) = (p - r, p + r);
        query.run(self.blockmap, map.lines.len(), min, max).iter().map(|&i| i as usize).filter(move |&i| {
            let line = &map.lines[i];
            let (a, b) = map.line_points(line);
            line.back.is_some() && !line.flags.impassable && !line.flags.block_monsters && crosses_box(a, b, min, max)
        })
    }

    /// The first one-sided line the centre's path `from-to` meets (touching
    /// counts). Doom checks only where a move ends, so a fast missile can
    /// pass a wall's corner between two pieces of its move and fly out of
    /// the map; here the path between is checked too.
    fn wall_across(&self, query: &mut LineQuery, from: DVec2, to: DVec2) -> Option<usize> {
        let map = &self.compiled.map;
        let lines = query.run(self.blockmap, map.lines.len(), from.min(to), from.max(to));
        lines.iter().map(|&i| i as usize).find(|&i| {
            let line = &map.lines[i];
            let (a, b) = map.line_points(line);
            line.back.is_none() && crate::play::trace::crossing(from, to, a, b).is_some()
        })
    }

    /// Where `mover` would stand at `to`, if the lines let it (Doom's
    /// P_TryMove without the things: the caller checks those), and its
    /// centre's way there crosses no one-sided line ([`Ground::wall_across`]).
    pub fn try_move(&self, query: &mut LineQuery, mover: &Mover, to: DVec2) -> Result<Opening, Refusal> {
        if mover.no_clip {
            return self.opening(query, to, 0.0, true).map_err(Refusal::Line);
        }
        let o = self.opening(query, to, mover.radius, mover.missile).map_err(Refusal::Line)?;
        let fits = o.ceiling - o.floor >= mover.height
            && o.ceiling - mover.z >= mover.height
            && o.floor - mover.z <= MAX_STEP
            && (mover.missile || mover.may_drop || o.floor - o.dropoff <= MAX_STEP);
        if !fits {
            return Err(Refusal::Fit(o));
        }
        match self.wall_across(query, mover.pos, to) {
            Some(line) => Err(Refusal::Line(line)),
            None => Ok(o),
        }
    }
}

/// Does segment `a-b` pass through the interior of the box `[min, max]`?
/// Exact for the axis-aligned box: the segment's own box must overlap the
/// interior, and the box's corners must not all lie on one side of the
/// line (a corner on the line counts as neither side).
pub fn crosses_box(a: DVec2, b: DVec2, min: DVec2, max: DVec2) -> bool {
    if a.x.max(b.x) <= min.x || a.x.min(b.x) >= max.x || a.y.max(b.y) <= min.y || a.y.min(b.y) >= max.y {
        return false;
    }
    let corners = [min, DVec2::new(max.x, min.y), max, DVec2::new(min.x, max.y)];
    let sides = corners.map(|c| exact_side(a, b, c));
    sides.contains(&Side::Front) && sides.contains(&Side::Back)
}
