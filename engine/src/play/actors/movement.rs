//! How monsters walk (Doom's P_TryMove, P_Move and P_NewChaseDir, for
//! actors): in steps of their speed along one of eight directions, each step
//! taken only where the actor's box fits. A step is refused where
//! - a line the box touches is one-sided, impassable or blocks monsters;
//! - the opening under the box is lower than the actor, or its ceiling is
//!   below the actor's top (it would have to duck), or its floor is more
//!   than a 24-unit step above the feet;
//! - the box would hang over a drop of more than 24 units (unless the actor
//!   may drop off or floats);
//! - a solid actor's box overlaps it (and the player's).
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

/// A box that blocks others: a solid actor or the player.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Blocker {
    pub pos: DVec2,
    pub radius: f64,
    /// Its feet and top.
    pub z: f64,
    pub top: f64,
    /// The caller's name for it (an actor's index, or `usize::MAX` for the player).
    pub index: usize,
}

/// What the area under a box allows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Opening {
    pub sector: usize,
    /// Highest floor, lowest ceiling and lowest floor under the box.
    pub floor: f64,
    pub ceiling: f64,
    pub dropoff: f64,
}

/// A body asking to move.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mover {
    pub index: usize,
    pub radius: f64,
    pub height: f64,
    pub z: f64,
    /// May step off ledges of any height (Doom's MF_DROPOFF) or floats.
    pub may_drop: bool,
    /// Passes through bodies and lines (Doom's MF_NOCLIP).
    pub no_clip: bool,
}

/// The map as movement sees it.
pub struct Ground<'a> {
    pub compiled: &'a CompiledMap,
    pub blockmap: &'a Blockmap,
    pub blockers: &'a [Blocker],
}

impl Ground<'_> {
    /// The opening under a box of `radius` at `p`, or `None` if a line
    /// the box touches blocks it outright.
    pub fn opening(&self, query: &mut LineQuery, p: DVec2, radius: f64) -> Option<Opening> {
        let map = &self.compiled.map;
        let sector = self.compiled.sector_at(p);
        let s = &map.sectors[sector];
        let mut o = Opening { sector, floor: s.floor, ceiling: s.ceiling, dropoff: s.floor };
        let r = DVec2::splat(radius);
        let (min, max) = (p - r, p + r);
        for &i in query.run(self.blockmap, map.lines.len(), min, max) {
            let line = &map.lines[i as usize];
            let (a, b) = map.line_points(line);
            if !crosses_box(a, b, min, max) {
                continue;
            }
            let Some(back) = &line.back else { return None };
            if line.flags.impassable || line.flags.block_monsters {
                return None;
            }
            let (f, k) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
            o.floor = o.floor.max(f.floor.max(k.floor));
            o.ceiling = o.ceiling.min(f.ceiling.min(k.ceiling));
            o.dropoff = o.dropoff.min(f.floor.min(k.floor));
        }
        Some(o)
    }

    /// Where `mover` would stand at `to`, if it may step there.
    pub fn try_move(&self, query: &mut LineQuery, mover: &Mover, to: DVec2) -> Option<Opening> {
        if mover.no_clip {
            return self.opening(query, to, 0.0);
        }
        let o = self.opening(query, to, mover.radius)?;
        let fits = o.ceiling - o.floor >= mover.height
            && o.ceiling - mover.z >= mover.height
            && o.floor - mover.z <= MAX_STEP
            && (mover.may_drop || o.floor - o.dropoff <= MAX_STEP);
        let blocked = self.blockers.iter().any(|b| {
            b.index != mover.index
                && (b.pos.x - to.x).abs() < b.radius + mover.radius
                && (b.pos.y - to.y).abs() < b.radius + mover.radius
        });
        (fits && !blocked).then_some(o)
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
