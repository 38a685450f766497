//! Actors in motion (Doom's P_XYMovement, P_ZMovement and the thing half
//! of P_TryMove): missiles in flight, lost souls charging, bodies pushed
//! by blasts and falling off ledges. Only actors with momentum or in the
//! air are on the list this visits ([`Actor::in_motion`]); a standing
//! monster costs nothing here.
//!
//! A move is cut into pieces no longer than [`MAX_PIECE`], so a fast
//! missile cannot pass through a thin wall or a body between ticks; each
//! piece is tried against the lines (`movement.rs`) and then the things
//! near it in the grid. What blocks a piece:
//! - a walker: a solid thing whose box overlaps (heights are not compared,
//!   as in Doom);
//! - a missile: a solid or shootable thing whose box and height overlap,
//!   other than its shooter; it hurts a shootable one by `1..8` times its
//!   damage, and explodes. A thing of the shooter's species stops it
//!   unhurt (so imps' fireballs do not start fights among imps).
//! - a charging lost soul: any solid thing, which it hurts the same way.
//!
//! A missile that meets a sky ceiling is gone without a blast.

use glam::{DVec2, DVec3};

use super::attacks::Request;
use super::movement::Opening;
use super::movement::{Ground, Mover, Refusal};
use super::{Actor, ActorCtx, Actors, Target};
use crate::actors::ActorFlag;
use crate::play::blockmap::LineQuery;
use crate::play::player::{FRICTION, GRAVITY, HEIGHT as PLAYER_HEIGHT, RADIUS as PLAYER_RADIUS, STOP_SPEED};

/// The longest piece of a move tried at once (Doom's MAXMOVE / 2).
pub const MAX_PIECE: f64 = 15.0;
/// The fastest a thing moves in the plane (Doom's MAXMOVE).
pub const MAX_MOVE: f64 = 30.0;
/// How fast a floating monster rises or sinks (Doom's FLOATSPEED).
pub const FLOAT_SPEED: f64 = 4.0;

/// Why a move stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Blocked {
    /// A line: a wall, or an opening that does not fit (its sky ceiling, if
    /// the mover is above it, makes a missile vanish).
    Line { sky: bool },
    /// An opening with room, at the wrong height for a floater.
    Float { floor: f64 },
    /// A thing.
    Thing(Target),
}

impl Actor {
    /// Has momentum, is charging, or stands above its floor with gravity:
    /// physics must visit it.
    pub fn in_motion(&self) -> bool {
        self.vel != DVec3::ZERO || self.skull_fly || (self.z > self.floor && !self.flags.has(ActorFlag::NoGravity))
    }
}

impl Actors {
    fn mover(&self, n: usize) -> Mover {
        let (a, def) = (&self.list[n], &self.table.actors[self.list[n].kind]);
        Mover {
            pos: a.pos,
            radius: def.radius,
            height: def.height,
            z: a.z,
            may_drop: a.flags.has(ActorFlag::DropOff) || a.flags.has(ActorFlag::Float),
            no_clip: a.flags.has(ActorFlag::NoClip),
            missile: a.flags.has(ActorFlag::Missile),
        }
    }

    /// The first thing that stops actor `n` moving to `to` (Doom's
    /// PIT_CheckThing), with the rules in this module's notes.
    fn thing_in_way(&mut self, n: usize, to: DVec2, ctx: &ActorCtx) -> Option<Target> {
        let a = &self.list[n];
        if a.flags.has(ActorFlag::NoClip) {
            return None;
        }
        let def = &self.table.actors[a.kind];
        let (radius, z, top) = (def.radius, a.z, a.z + def.height);
        let missile = a.flags.has(ActorFlag::Missile);
        let (charging, source) = (a.skull_fly, a.source);
        let player = &ctx.player;
        let overlaps = |pos: DVec2, r: f64| (pos.x - to.x).abs() < r + radius && (pos.y - to.y).abs() < r + radius;
        let meets = |bz: f64, btop: f64| !(z > btop || top < bz);
        if !player.dead() && overlaps(player.pos, PLAYER_RADIUS) && source != Target::Player {
            let p = (player.z, player.z + PLAYER_HEIGHT);
            if !missile || meets(p.0, p.1) {
                return Some(Target::Player);
            }
        }
        let near = self.near(to - DVec2::splat(radius), to + DVec2::splat(radius));
        let mut found = None;
        for &k in &near {
            let k = k as usize;
            let b = &self.list[k];
            if k == n || b.removed {
                continue;
            }
            let bdef = &self.table.actors[b.kind];
            let solid = b.flags.has(ActorFlag::Solid);
            let shootable = b.flags.has(ActorFlag::Shootable);
            if !(solid || (missile && shootable)) || !overlaps(b.pos, bdef.radius) {
                continue;
            }
            if missile {
                if !meets(b.z, b.z + bdef.height) || source == Target::Actor(k as u32) {
                    continue;
                }
            } else if !charging && !solid {
                continue;
            }
            found = Some(Target::Actor(k as u32));
            break;
        }
        self.give_back(near);
        found
    }

    /// Moves actor `n` to `to` if the lines and things let it (Doom's
    /// P_TryMove): its place, sector, floor and ceiling follow; a walker
    /// (not floating, not a missile) steps up or down onto the new floor.
    pub fn try_move(&mut self, n: usize, to: DVec2, ctx: &mut ActorCtx) -> Result<(), Blocked> {
        let mover = self.mover(n);
        let ground = Ground { compiled: &ctx.level.compiled, blockmap: ctx.blockmap };
        let o = match ground.try_move(ctx.query, &mover, to) {
            Ok(o) => o,
            Err(Refusal::Line(_)) => return Err(Blocked::Line { sky: false }),
            Err(Refusal::Fit(o)) => {
                let map = &ctx.level.compiled.map;
                let sky = map.sectors[o.ceiling_sector].ceiling_is_sky() && mover.z + mover.height > o.ceiling;
                if self.list[n].flags.has(ActorFlag::Float) && o.ceiling - o.floor >= mover.height && !mover.missile {
                    return Err(Blocked::Float { floor: o.floor });
                }
                return Err(Blocked::Line { sky });
            }
        };
        if let Some(t) = self.thing_in_way(n, to, ctx) {
            return Err(Blocked::Thing(t));
        }
        let walker = !mover.missile && !self.list[n].flags.has(ActorFlag::Float);
        // A body that is not a missile sets off the walk lines monsters may
        // use (Doom's P_CrossSpecialLine for a thing): the game looks for
        // them after the actors' turn.
        if ctx.monster_walks && !mover.missile && !mover.no_clip {
            ctx.requests.push(Request::Cross { actor: n as u32, from: self.list[n].pos, to });
        }
        let a = &mut self.list[n];
        let on_ground = a.z <= a.floor;
        (a.sector, a.floor, a.ceiling) = (o.sector, o.floor, o.ceiling);
        if walker && (on_ground || a.z < o.floor) && a.vel.z <= 0.0 && o.floor >= a.z - 24.0 {
            a.z = o.floor;
        }
        self.set_pos(n, to);
        if self.list[n].in_motion() {
            self.wake_physics(n);
        }
        Ok(())
    }

    /// Re-clips actor `n` to the opening under it after a floor or ceiling
    /// moved (Doom's P_ThingHeightClip): on its floor it rides it, else a
    /// ceiling come down pushes it down. Returns whether it fits; a corpse
    /// and a thing that cannot be shot always do (Doom squashes a corpse
    /// to gibs of no height).
    pub fn settle(&mut self, n: usize, ground: &Ground, query: &mut LineQuery) -> bool {
        let a = &self.list[n];
        if a.removed {
            return true;
        }
        let def = &self.table.actors[a.kind];
        let Ok(o): Result<Opening, usize> = ground.opening(query, a.pos, def.radius, true) else { return true };
        let yielding = a.flags.has(ActorFlag::Corpse) || !a.flags.has(ActorFlag::Shootable);
        let height = if yielding { 0.0 } else { def.height };
        let (z0, floor0, ceiling0) = (a.z, a.floor, a.ceiling);
        let a = &mut self.list[n];
        let on_floor = a.z <= a.floor;
        (a.floor, a.ceiling) = (o.floor, o.ceiling);
        if a.flags.has(ActorFlag::SpawnCeiling) && a.flags.has(ActorFlag::NoGravity) && a.z + def.height >= ceiling0 {
            a.z = o.ceiling - def.height;
        } else if on_floor {
            a.z = o.floor;
        } else if a.z + height > o.ceiling {
            a.z = (o.ceiling - height).max(o.floor);
        }
        if a.z != z0 || a.floor != floor0 || a.ceiling != ceiling0 {
            self.dirty.push(n as u32);
            if self.list[n].in_motion() {
                self.wake_physics(n);
            }
        }
        // Squeezed below no height at all (a ceiling under the floor across
        // a line its box overlaps), it still fits: only a body that can be
        // shot stops a moving plane (Doom's PIT_ChangeSector passes over
        // the others).
        yielding || o.ceiling - o.floor >= height
    }

    /// Puts actor `n` at `to` facing `angle`, standing still on the floor
    /// of the opening `o` there (a teleport).
    pub fn teleport(&mut self, n: usize, to: DVec2, angle: f64, o: Opening) {
        self.set_pos(n, to);
        let a = &mut self.list[n];
        (a.sector, a.floor, a.ceiling, a.z) = (o.sector, o.floor, o.ceiling, o.floor);
        a.angle = angle;
        a.vel = DVec3::ZERO;
    }

    /// One tick of motion for actor `n`: along its momentum in the plane,
    /// then up or down.
    pub(super) fn physics(&mut self, n: usize, ctx: &mut ActorCtx) {
        let a = &self.list[n];
        if a.vel.x != 0.0 || a.vel.y != 0.0 || a.skull_fly {
            self.move_xy(n, ctx);
        }
        let a = &self.list[n];
        if !a.removed && (a.z != a.floor || a.vel.z != 0.0) {
            self.move_z(n, ctx);
        }
    }

    fn move_xy(&mut self, n: usize, ctx: &mut ActorCtx) {
        let a = &mut self.list[n];
        let v = DVec2::new(a.vel.x, a.vel.y).clamp(DVec2::splat(-MAX_MOVE), DVec2::splat(MAX_MOVE));
        (a.vel.x, a.vel.y) = (v.x, v.y);
        let pieces = (v.abs().max_element() / MAX_PIECE).ceil().max(1.0) as usize;
        let step = v / pieces as f64;
        for _ in 0..pieces {
            let to = self.list[n].pos + step;
            match self.try_move(n, to, ctx) {
                Ok(()) => continue,
                Err(blocked) => {
                    self.blocked(n, blocked, ctx);
                    break;
                }
            }
        }
        let a = &mut self.list[n];
        if a.removed || a.flags.has(ActorFlag::Missile) || a.skull_fly || a.z > a.floor {
            return;
        }
        // Friction on the ground, and a dead stop when slow.
        a.vel.x *= FRICTION;
        a.vel.y *= FRICTION;
        if a.vel.x.abs() < STOP_SPEED && a.vel.y.abs() < STOP_SPEED {
            (a.vel.x, a.vel.y) = (0.0, 0.0);
        }
    }

    /// What happens when a move is stopped.
    fn blocked(&mut self, n: usize, blocked: Blocked, ctx: &mut ActorCtx) {
        let a = &self.list[n];
        if a.flags.has(ActorFlag::Missile) {
            match blocked {
                Blocked::Line { sky: true } => self.remove(n),
                Blocked::Thing(t) => {
                    let damage = self.impact(n, ctx);
                    let same_species = match (self.list[n].source, t) {
                        (Target::Actor(s), Target::Actor(k)) => {
                            self.table.actors[self.list[s as usize].kind].species
                                == self.table.actors[self.list[k as usize].kind].species
                        }
                        _ => false,
                    };
                    if !same_species {
                        let source = self.list[n].source;
                        self.hurt(t, damage, Some(n), source, ctx);
                    }
                    self.explode_missile(n, ctx);
                }
                _ => self.explode_missile(n, ctx),
            }
        } else if a.skull_fly {
            if let Blocked::Thing(t) = blocked {
                let damage = self.impact(n, ctx);
                self.hurt(t, damage, Some(n), Target::Actor(n as u32), ctx);
            }
            self.end_charge(n, ctx);
        } else {
            let a = &mut self.list[n];
            (a.vel.x, a.vel.y) = (0.0, 0.0);
        }
    }

    /// A missile's or a charge's damage: `1..8` times the actor's (Doom's
    /// `((P_Random() % 8) + 1) * damage`).
    fn impact(&self, n: usize, ctx: &mut ActorCtx) -> i32 {
        (i32::from(ctx.rng.byte()) % 8 + 1) * self.table.actors[self.list[n].kind].damage
    }

    /// A lost soul's charge ends: it stops and goes back to its first state.
    fn end_charge(&mut self, n: usize, ctx: &mut ActorCtx) {
        let a = &mut self.list[n];
        a.skull_fly = false;
        a.vel = DVec3::ZERO;
        let spawn = self.table.actors[a.kind].label("Spawn");
        self.set_state(n, spawn, ctx);
    }

    fn move_z(&mut self, n: usize, ctx: &mut ActorCtx) {
        let def = &self.table.actors[self.list[n].kind];
        let height = def.height;
        let a = &mut self.list[n];
        a.z += a.vel.z;
        let missile = a.flags.has(ActorFlag::Missile);
        if a.z <= a.floor {
            if a.skull_fly {
                a.vel.z = -a.vel.z;
            }
            if a.vel.z < 0.0 {
                a.vel.z = 0.0;
            }
            a.z = a.floor;
            if missile && !a.flags.has(ActorFlag::NoClip) {
                self.explode_missile(n, ctx);
                return;
            }
        } else if !a.flags.has(ActorFlag::NoGravity) {
            a.vel.z -= if a.vel.z == 0.0 { 2.0 * GRAVITY } else { GRAVITY };
        }
        let a = &mut self.list[n];
        if a.z + height > a.ceiling {
            if a.vel.z > 0.0 {
                a.vel.z = 0.0;
            }
            a.z = (a.ceiling - height).max(a.floor);
            if a.skull_fly {
                a.vel.z = -a.vel.z;
            }
            if missile && !a.flags.has(ActorFlag::NoClip) {
                let sector = &ctx.level.compiled.map.sectors[a.sector];
                if sector.ceiling_is_sky() {
                    self.remove(n);
                } else {
                    self.explode_missile(n, ctx);
                }
                return;
            }
        }
        self.dirty.push(n as u32);
    }

    /// A missile stops and bursts (Doom's P_ExplodeMissile): its death
    /// frames (with a random head start), its death sound; it is no longer
    /// a missile.
    pub fn explode_missile(&mut self, n: usize, ctx: &mut ActorCtx) {
        let a = &mut self.list[n];
        a.vel = DVec3::ZERO;
        a.flags.set(ActorFlag::Missile, false);
        let def = &self.table.actors[a.kind];
        let (death, sound) = (def.label("Death"), def.sounds.death);
        self.set_state(n, death, ctx);
        let a = &mut self.list[n];
        if !a.removed && a.tics > 0 {
            a.tics = (a.tics - i32::from(ctx.rng.byte() & 3)).max(1);
        }
        self.sound_at(n, sound, ctx);
    }
}
