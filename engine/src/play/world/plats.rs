//! Lifts (Doom's p_plats.c): the floor goes down to the lowest floor around
//! it, waits, and comes back up; a body in the way of the way up sends it
//! down again. Perpetual lifts go between the lowest and highest floors
//! around them for ever, until a stop special puts them in stasis; starting
//! a perpetual lift again wakes the stopped ones with its tag.

use super::mover::{move_plane, Moved, Plane};
use super::{specials, Ctx, Thinker, World};
use crate::play::events::{sound, Origin};

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum PlatState {
    Up,
    Down,
    Waiting {
        count: u32,
    },
    /// Stopped by a stop special; remembers what it was doing.
    Stasis {
        was: PlatStep,
    },
}

/// The moving states a stopped lift returns to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum PlatStep {
    Up,
    Down,
    Waiting { count: u32 },
}

#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Plat {
    pub sector: usize,
    pub low: f64,
    pub high: f64,
    pub speed: f64,
    pub wait: u32,
    pub state: PlatState,
    pub perpetual: bool,
    /// The tag of the line that started it (stop specials find it by this).
    pub tag: u16,
}

impl Plat {
    pub(super) fn think(&mut self, ctx: &mut Ctx) -> bool {
        let origin = Origin::Sector(self.sector);
        match self.state {
            PlatState::Up => match move_plane(ctx, self.sector, Plane::Floor, self.speed, self.high, false, true) {
                Moved::Crushed => {
                    self.state = PlatState::Down;
                    ctx.events.push(sound("pstart", origin));
                }
                Moved::Arrived => {
                    ctx.events.push(sound("pstop", origin));
                    if !self.perpetual {
                        return false;
                    }
                    self.state = PlatState::Waiting { count: self.wait };
                }
                Moved::Ok => {}
            },
            PlatState::Down => {
                if move_plane(ctx, self.sector, Plane::Floor, self.speed, self.low, false, false) == Moved::Arrived {
                    self.state = PlatState::Waiting { count: self.wait };
                    ctx.events.push(sound("pstop", origin));
                }
            }
            PlatState::Waiting { count } => {
                if count > 1 {
                    self.state = PlatState::Waiting { count: count - 1 };
                } else {
                    let at_bottom = ctx.level.compiled.map.sectors[self.sector].floor <= self.low;
                    self.state = if at_bottom { PlatState::Up } else { PlatState::Down };
                    ctx.events.push(sound("pstart", origin));
                }
            }
            PlatState::Stasis { .. } => {}
        }
        true
    }
}

/// Doom's down-wait-up-stay lift on each idle sector of `sectors`.
pub fn start_lift(world: &mut World, ctx: &mut Ctx, sectors: &[usize], speed: f64, wait: u32, tag: u16) -> bool {
    let mut started = false;
    for &s in sectors {
        if world.is_busy(s) {
            continue;
        }
        let floor = ctx.level.compiled.map.sectors[s].floor;
        let low = specials::lowest_floor_around(ctx.level, s);
        let plat = Plat { sector: s, low, high: floor, speed, wait, state: PlatState::Down, perpetual: false, tag };
        ctx.events.push(sound("pstart", Origin::Sector(s)));
        world.start(Thinker::Plat(plat));
        started = true;
    }
    started
}

/// Perpetual lifts: first wakes those stopped with this tag, then starts
/// one on each idle sector, going up or down at random (Doom's P_Random & 1).
pub fn start_perpetual(world: &mut World, ctx: &mut Ctx, sectors: &[usize], speed: f64, wait: u32, tag: u16) -> bool {
    let mut started = wake(world, tag);
    for &s in sectors {
        if world.is_busy(s) {
            continue;
        }
        let floor = ctx.level.compiled.map.sectors[s].floor;
        let low = specials::lowest_floor_around(ctx.level, s);
        let high = specials::highest_floor_around(ctx.level, s).map_or(floor, |h| h.max(floor));
        let state = if ctx.rng.byte() & 1 == 0 { PlatState::Up } else { PlatState::Down };
        let plat = Plat { sector: s, low, high, speed, wait, state, perpetual: true, tag };
        ctx.events.push(sound("pstart", Origin::Sector(s)));
        world.start(Thinker::Plat(plat));
        started = true;
    }
    started
}

/// Stops every moving lift started with `tag` (Doom's EV_StopPlat).
pub fn stop(world: &mut World, tag: u16) -> bool {
    let mut stopped = false;
    for t in &mut world.thinkers {
        let Thinker::Plat(p) = t else { continue };
        let was = match p.state {
            PlatState::Up => PlatStep::Up,
            PlatState::Down => PlatStep::Down,
            PlatState::Waiting { count } => PlatStep::Waiting { count },
            PlatState::Stasis { .. } => continue,
        };
        if p.tag == tag {
            p.state = PlatState::Stasis { was };
            stopped = true;
        }
    }
    stopped
}

/// Wakes the lifts stopped with `tag` (Doom's P_ActivateInStasis).
fn wake(world: &mut World, tag: u16) -> bool {
    let mut woke = false;
    for t in &mut world.thinkers {
        let Thinker::Plat(p) = t else { continue };
        if let (PlatState::Stasis { was }, true) = (p.state, p.tag == tag) {
            p.state = match was {
                PlatStep::Up => PlatState::Up,
                PlatStep::Down => PlatState::Down,
                PlatStep::Waiting { count } => PlatState::Waiting { count },
            };
            woke = true;
        }
    }
    woke
}
