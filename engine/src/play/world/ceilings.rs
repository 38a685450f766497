//! Ceilings and crushers (Doom's p_ceilng.c). A ceiling special moves the
//! ceiling once to its target. A crusher goes down to 8 above the floor and
//! back up to where it started, for ever, hurting a body under it every
//! fourth tick; a slow crusher slows to an eighth of its speed while it
//! crushes, a fast one (speed 2 and up, Doom's fast crushers) does not. Stop
//! specials put crushers in stasis; starting a crusher again wakes those
//! with its tag.

use super::mover::{move_plane, Moved, Plane};
use super::{specials, Ctx, Thinker, World};
use crate::map::special::CeilingTarget;
use crate::play::events::{sound, Origin};

/// A crusher stops this far above the floor (Doom's 8).
pub const CRUSH_GAP: f64 = 8.0;
/// A slow crusher's speed while crushing, as a share of its own (Doom: CEILSPEED / 8).
const CRUSHING_SLOWDOWN: f64 = 1.0 / 8.0;
/// Crushers at least this fast never slow down (Doom's fast crushers move at 2).
const FAST: f64 = 2.0;

#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum CeilingKind {
    /// Moves once to `dest`.
    Once { dest: f64 },
    /// Goes between `bottom` and `top` for ever.
    Crusher { top: f64, bottom: f64, silent: bool },
}

#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct CeilingMove {
    pub sector: usize,
    pub kind: CeilingKind,
    /// The speed it was started with, and the speed now (a slow crusher
    /// crushing moves at an eighth of it).
    pub base_speed: f64,
    pub speed: f64,
    pub up: bool,
    pub crush: bool,
    /// Stopped by a stop special.
    pub stopped: bool,
    pub tag: u16,
}

impl CeilingMove {
    pub(super) fn think(&mut self, ctx: &mut Ctx) -> bool {
        if self.stopped {
            return true;
        }
        let origin = Origin::Sector(self.sector);
        let silent = matches!(self.kind, CeilingKind::Crusher { silent: true, .. });
        if ctx.time % 8 == 0 && !silent {
            ctx.events.push(sound("stnmov", origin));
        }
        let dest = match self.kind {
            CeilingKind::Once { dest } => dest,
            CeilingKind::Crusher { top, bottom, .. } => {
                if self.up {
                    top
                } else {
                    bottom
                }
            }
        };
        let crush = self.crush && !self.up;
        let moved = move_plane(ctx, self.sector, Plane::Ceiling, self.speed, dest, crush, self.up);
        match (moved, self.kind) {
            (Moved::Arrived, CeilingKind::Once { .. }) => return false,
            (Moved::Arrived, CeilingKind::Crusher { silent, .. }) => {
                if silent {
                    ctx.events.push(sound("pstop", origin));
                }
                self.up = !self.up;
                self.speed = self.base_speed;
            }
            (Moved::Crushed, CeilingKind::Crusher { .. }) if !self.up && self.base_speed < FAST => {
                self.speed = self.base_speed * CRUSHING_SLOWDOWN;
            }
            _ => {}
        }
        true
    }
}

/// A one-time ceiling move on each idle sector of `sectors`.
pub fn start(
    world: &mut World,
    ctx: &mut Ctx,
    sectors: &[usize],
    to: CeilingTarget,
    offset: f64,
    speed: f64,
    crush: bool,
) -> bool {
    let mut started = false;
    for &s in sectors {
        if world.is_busy(s) {
            continue;
        }
        let sector = &ctx.level.compiled.map.sectors[s];
        let (floor, ceiling) = (sector.floor, sector.ceiling);
        let target = match to {
            CeilingTarget::Floor => floor,
            CeilingTarget::HighestNeighbourCeiling => specials::highest_ceiling_around(ctx.level, s).unwrap_or(ceiling),
            CeilingTarget::LowestNeighbourCeiling => specials::lowest_ceiling_around(ctx.level, s).unwrap_or(ceiling),
            CeilingTarget::Current => ceiling,
        };
        let dest = target + offset;
        let kind = CeilingKind::Once { dest };
        let mover = CeilingMove {
            sector: s,
            kind,
            base_speed: speed,
            speed,
            up: dest > ceiling,
            crush,
            stopped: false,
            tag: 0,
        };
        world.start(Thinker::Ceiling(mover));
        started = true;
    }
    started
}

/// Crushers: first wakes the stopped ones with this tag, then starts one on
/// each idle sector, from its ceiling now down to 8 above its floor.
pub fn start_crusher(world: &mut World, ctx: &mut Ctx, sectors: &[usize], speed: f64, silent: bool, tag: u16) -> bool {
    let mut started = false;
    for t in &mut world.thinkers {
        if let Thinker::Ceiling(c) = t {
            if c.stopped && c.tag == tag && matches!(c.kind, CeilingKind::Crusher { .. }) {
                c.stopped = false;
                started = true;
            }
        }
    }
    for &s in sectors {
        if world.is_busy(s) {
            continue;
        }
        let sector = &ctx.level.compiled.map.sectors[s];
        let kind = CeilingKind::Crusher { top: sector.ceiling, bottom: sector.floor + CRUSH_GAP, silent };
        let mover =
            CeilingMove { sector: s, kind, base_speed: speed, speed, up: false, crush: true, stopped: false, tag };
        world.start(Thinker::Ceiling(mover));
        started = true;
    }
    started
}

/// Stops every running crusher started with `tag` (Doom's EV_CeilingCrushStop).
pub fn stop(world: &mut World, tag: u16) -> bool {
    let mut stopped = false;
    for t in &mut world.thinkers {
        if let Thinker::Ceiling(c) = t {
            if !c.stopped && c.tag == tag && matches!(c.kind, CeilingKind::Crusher { .. }) {
                c.stopped = true;
                stopped = true;
            }
        }
    }
    stopped
}
