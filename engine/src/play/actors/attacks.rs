//! Harm: damage and death (Doom's P_DamageMobj, P_KillMobj), shots
//! (P_LineAttack), missiles (P_SpawnMissile, P_SpawnPlayerMissile),
//! explosions (P_RadiusAttack), and the monsters' attacks and special
//! behaviours that use them (imps to the boss brain).
//!
//! Damage is charged to a `source` (who fired) and pushed from an
//! `inflictor` (what hit: the missile, or the shooter for a bullet). A
//! monster hurt by another monster turns on it (infighting) unless it is
//! already busy with a grudge (`threshold`); a monster of the arch-vile's
//! kind is never turned on. An explosion hurts what it can see from where
//! it bursts, so a wall between stops it.

use glam::{DVec2, DVec3};

use super::actions::{actor as actor_arg, int};
use super::monsters::{approx_distance, face_target, player_body, spread};
use super::{ActorCtx, Actors, Target};
use crate::actors::{ActorFlag, Arg, Power, StateId};
use crate::map::special::{Action, DoorKind, FloorTarget};
use crate::play::events::{Event, Origin};
use crate::play::pickups::power_slot;
use crate::play::sight::{self, Body, Ray, Struck};

/// A monster's grudge lasts this many chase steps (Doom's BASETHRESHOLD).
const GRUDGE: i32 = 100;
/// Missiles leave a monster this far above its feet (Doom: 32).
pub const MISSILE_HEIGHT: f64 = 32.0;
/// A lost soul charges at this speed (Doom's SKULLSPEED).
const SKULL_SPEED: f64 = 20.0;
/// The mancubus spreads its fireballs by this (Doom's FATSPREAD, 90/8 degrees).
const FAT_SPREAD: f64 = 11.25;
/// A homing missile turns at most this much a step (Doom's TRACEANGLE).
const TRACE_TURN: f64 = 16.875;
/// Auto-aim tries this far either side of straight ahead (Doom's `1 << 26`).
pub const AIM_SIDE: f64 = 5.625;

/// Something an action asks of the world, done after the actors' tick
/// (the world's machinery is not the actors' to touch mid-tick).
#[derive(Clone, Debug, PartialEq)]
pub enum Request {
    /// Do `action` to the sectors tagged `tag` (a boss died).
    Tagged(Action, u16),
    /// The level ends (the boss brain died, E2M8's cyberdemon).
    Exit,
    /// An actor stepped from `from` to `to`: the walk lines it crossed
    /// that monsters may set off go off.
    Cross { actor: u32, from: DVec2, to: DVec2 },
    /// An actor blocked by a door pushes it open (Doom's P_Move trying
    /// the lines it touched with P_UseSpecialLine).
    Use { actor: u32, line: usize },
}

impl Actors {
    /// `target` takes `damage` (Doom's P_DamageMobj), pushed away from
    /// `inflictor` (an actor: a missile, a shooter), charged to `source`.
    pub fn hurt(&mut self, target: Target, damage: i32, inflictor: Option<usize>, source: Target, ctx: &mut ActorCtx) {
        let from = inflictor.filter(|&i| !self.list[i].removed).map(|i| (self.list[i].pos, self.list[i].z));
        self.hurt_from(target, damage, from, source, ctx);
    }

    /// [`Actors::hurt`] pushed away from a place (`from`: its position
    /// and height) rather than an actor: the player's shots come from the
    /// player, who is not one.
    fn hurt_from(
        &mut self,
        target: Target,
        damage: i32,
        from: Option<(DVec2, f64)>,
        source: Target,
        ctx: &mut ActorCtx,
    ) {
        match target {
            Target::None => {}
            Target::Player => self.hurt_player(damage, from, ctx),
            Target::Actor(k) => self.hurt_actor(k as usize, damage, from, source, ctx),
        }
    }

    fn hurt_player(&mut self, damage: i32, from: Option<(DVec2, f64)>, ctx: &mut ActorCtx) {
        let p = &mut *ctx.player;
        if p.dead() {
            return;
        }
        let mut damage = damage;
        if ctx.skill == 1 {
            damage /= 2;
        }
        if let Some((at, _)) = from {
            push(&mut p.velocity, at, p.pos, damage, 100);
        }
        if p.powers[power_slot(Power::Invulnerability)] > 0 && damage < 1000 {
            return;
        }
        p.hurt(damage);
        p.damage_count = (p.damage_count + damage).min(100);
        let cry = if !p.dead() {
            "plpain"
        } else if p.health < -50 {
            "pdiehi"
        } else {
            "pldeth"
        };
        ctx.events.push(Event::Sound { sound: cry, origin: Origin::Player });
    }

    fn hurt_actor(&mut self, n: usize, damage: i32, from: Option<(DVec2, f64)>, source: Target, ctx: &mut ActorCtx) {
        let table = self.table.clone();
        let a = &self.list[n];
        if a.removed || !a.flags.has(ActorFlag::Shootable) || a.health <= 0 {
            return;
        }
        let def = &table.actors[a.kind];
        if a.skull_fly {
            self.list[n].vel = DVec3::ZERO;
        }
        let a = &self.list[n];
        if let Some((at, z)) = from.filter(|_| !a.flags.has(ActorFlag::NoClip)) {
            let mass = def.mass.max(1);
            let mut v = DVec2::new(a.vel.x, a.vel.y);
            // Doom's quirk: a small hit from below-and-far may throw it the
            // other way, four times as hard.
            let fling = damage < 40 && damage > a.health && a.z - z > 64.0 && ctx.rng.byte() & 1 == 1;
            if fling {
                push(&mut v, a.pos, 2.0 * a.pos - at, damage * 4, mass);
            } else {
                push(&mut v, at, a.pos, damage, mass);
            }
            let a = &mut self.list[n];
            (a.vel.x, a.vel.y) = (v.x, v.y);
            if v != DVec2::ZERO {
                self.wake_physics(n);
            }
        }
        let a = &mut self.list[n];
        a.health -= damage;
        if a.health <= 0 {
            self.kill(n, ctx);
            return;
        }
        let (pain, see, spawn) = (def.label("Pain"), def.label("See"), def.label("Spawn"));
        if i32::from(ctx.rng.byte()) < def.pain_chance && !a.skull_fly && pain.is_some() {
            a.just_hit = true;
            self.set_state(n, pain, ctx);
        }
        let a = &mut self.list[n];
        a.reaction_time = 0;
        let vile = self.is_vile(n);
        let turn = match source {
            Target::None => false,
            Target::Actor(s) => s as usize != n && !self.is_vile(s as usize),
            Target::Player => true,
        };
        let a = &mut self.list[n];
        if (a.threshold == 0 || vile) && turn && !self.table.actors[a.kind].has(ActorFlag::NoThreshold) {
            a.target = source;
            a.threshold = GRUDGE;
            if Some(a.state) == spawn && see.is_some() {
                self.set_state(n, see, ctx);
            }
        } else if a.target == Target::None && turn {
            a.target = source;
        }
    }

    /// Is actor `n` one that raises the dead (and so is never a target of
    /// revenge, nor turns away from its own)?
    fn is_vile(&self, n: usize) -> bool {
        self.table.actors[self.list[n].kind].label("Heal").is_some()
    }

    /// Actor `n` dies (Doom's P_KillMobj): no longer shootable, a corpse,
    /// counted if the player or anyone killed it, its death (or gibbing)
    /// frames, and what it drops.
    pub fn kill(&mut self, n: usize, ctx: &mut ActorCtx) {
        let a = &mut self.list[n];
        let def = &self.table.actors[a.kind];
        a.flags.set(ActorFlag::Shootable, false);
        a.flags.set(ActorFlag::Float, false);
        a.flags.set(ActorFlag::Corpse, true);
        a.flags.set(ActorFlag::DropOff, true);
        a.skull_fly = false;
        // The dead fall, but for one whose death ends in nothing (Doom
        // keeps the lost soul up as it bursts).
        if !vanishes(&self.table, a.kind) {
            a.flags.set(ActorFlag::NoGravity, false);
        }
        if def.has(ActorFlag::CountKill) {
            *ctx.kills += 1;
        }
        let gib = def.label("XDeath").filter(|_| a.health < -def.health);
        let death = gib.or(def.label("Death"));
        let (pos, angle, drop) = (a.pos, a.angle, def.drop);
        self.set_state(n, death, ctx);
        let a = &mut self.list[n];
        if !a.removed && a.tics > 0 {
            // Doom's random head start, so a row of deaths falls out of step.
            a.tics = (a.tics - i32::from(ctx.rng.byte() & 3)).max(1);
        }
        if self.list[n].in_motion() {
            self.wake_physics(n);
        }
        if let Some(item) = drop {
            let z = ctx.level.compiled.map.sectors[ctx.level.compiled.sector_at(pos)].floor;
            if let Some(k) = self.spawn(item, pos, z, angle, ctx) {
                self.list[k].flags.set(ActorFlag::Dropped, true);
            }
        }
    }

    /// The shootable bodies near the line from `from` to `to` (the grid's
    /// cells over its box), the player's included unless `shooter` is it.
    pub fn bodies_along(&mut self, from: DVec2, to: DVec2, shooter: Target, ctx: &ActorCtx) -> Vec<Body> {
        let near = self.near(from.min(to), from.max(to));
        let mut out: Vec<Body> = near
            .iter()
            .map(|&k| k as usize)
            .filter(|&k| !self.list[k].removed && self.list[k].flags.has(ActorFlag::Shootable))
            .map(|k| self.body(k))
            .collect();
        self.give_back(near);
        if shooter != Target::Player && !ctx.player.dead() {
            out.push(player_body(ctx));
        }
        out
    }

    /// Auto-aim along `ray` (Doom's P_AimLineAttack): the slope to the
    /// first shootable body in the window, and whom, else level.
    pub fn aim(&mut self, ray: &Ray, ctx: &mut ActorCtx) -> (f64, Target) {
        let shooter = match ray.shooter {
            Some(s) => Target::Actor(s as u32),
            None => Target::Player,
        };
        let bodies = self.bodies_along(ray.origin, ray.end(), shooter, ctx);
        match sight::aim_slope(&ctx.level.compiled, ctx.sight, ray, &bodies) {
            Some(a) => (a.slope, self.whose(a.index)),
            None => (0.0, Target::None),
        }
    }

    fn whose(&self, index: usize) -> Target {
        if index == super::monsters::PLAYER {
            Target::Player
        } else {
            Target::Actor(index as u32)
        }
    }

    /// A shot along `ray` at `slope` (Doom's P_LineAttack): hurts the first
    /// body it hits, with blood (or a puff for the bloodless); a puff where
    /// it hits a wall. Returns what it hit.
    pub fn line_attack(
        &mut self,
        shooter: Target,
        ray: &Ray,
        slope: f64,
        damage: i32,
        ctx: &mut ActorCtx,
    ) -> Option<Target> {
        let bodies = self.bodies_along(ray.origin, ray.end(), shooter, ctx);
        let hit = sight::hitscan(&ctx.level.compiled, ctx.sight, ray, slope, &bodies);
        if shooter == Target::Player {
            // The lines it crosses before what it hits may have shoot specials.
            let reach = hit.map_or(1.0, |h| h.fraction);
            ctx.shots.push((ray.origin, ray.origin + (ray.end() - ray.origin) * reach));
        }
        let hit = hit?;
        // The shot pushes its victim away from the shooter.
        let from = self.body_of(shooter, ctx).map(|b| (b.pos, b.z));
        match hit.struck {
            Struck::Body { index } => {
                let t = self.whose(index);
                let bloodless = matches!(t, Target::Actor(k) if self.list[k as usize].flags.has(ActorFlag::NoBlood));
                if let Some(p) = hit.puff {
                    let effect = if bloodless { "bullet_puff" } else { "blood" };
                    self.spawn_effect(effect, p, damage, ctx);
                }
                self.hurt_from(t, damage, from, shooter, ctx);
                Some(t)
            }
            Struck::Wall { .. } => {
                if let Some(p) = hit.puff {
                    self.spawn_effect("bullet_puff", p, 0, ctx);
                }
                None
            }
            Struck::Sky { .. } => None,
        }
    }

    /// A puff or blood at `p` (Doom's P_SpawnPuff, P_SpawnBlood): a random
    /// head start; blood shows later frames for smaller hits.
    fn spawn_effect(&mut self, name: &str, p: DVec3, damage: i32, ctx: &mut ActorCtx) {
        let Some(kind) = self.table.index(name) else { return };
        let z = p.z + (f64::from(ctx.rng.byte()) - f64::from(ctx.rng.byte())) / 64.0;
        let Some(k) = self.spawn(kind, p.truncate(), z, 0.0, ctx) else { return };
        let a = &mut self.list[k];
        a.vel.z = 1.0;
        a.tics = (a.tics - i32::from(ctx.rng.byte() & 3)).max(1);
        self.wake_physics(k);
        if name == "blood" && (9..=12).contains(&damage) {
            self.advance(k, 1, ctx);
        } else if name == "blood" && damage < 9 {
            self.advance(k, 2, ctx);
        }
    }

    /// Moves actor `k` `steps` states on along its sequence (no actions).
    fn advance(&mut self, k: usize, steps: u32, ctx: &mut ActorCtx) {
        let state = StateId(self.list[k].state.0 + steps);
        if (state.0 as usize) < self.table.states.len() {
            self.show(k, state, &ctx.level.materials);
        }
    }

    /// Fires a `kind` missile from monster `n` at its target (Doom's
    /// P_SpawnMissile): from 32 units up, at the target's feet's height by
    /// the time it gets there, off by a little at a shadow.
    pub fn monster_missile(&mut self, n: usize, kind: usize, ctx: &mut ActorCtx) -> Option<usize> {
        let t = self.body_of(self.list[n].target, ctx)?;
        let a = &self.list[n];
        let (pos, z) = (a.pos, a.z + MISSILE_HEIGHT);
        let d = t.pos - pos;
        let mut angle = d.y.atan2(d.x).to_degrees();
        let shadow = match self.list[n].target {
            Target::Actor(k) => self.list[k as usize].flags.has(ActorFlag::Shadow),
            Target::Player => ctx.player.powers[power_slot(Power::Invisibility)] > 0,
            Target::None => false,
        };
        if shadow {
            angle += spread(ctx, 20);
        }
        let speed = self.table.actors[self.table.spawned(kind)].speed(ctx.skill == 5);
        let flight = (approx_distance(d) / speed).max(1.0);
        let vz = (t.z - a.z) / flight;
        self.launch(kind, pos, z, angle, vz, Target::Actor(n as u32), ctx)
    }

    /// A missile of `kind` leaves `pos`, `z` along `angle` with vertical
    /// speed `vz`, fired by `source` (Doom's P_CheckMissileSpawn: a random
    /// head start, half a tick's flight at once, and a burst at once if
    /// that is blocked).
    pub fn launch(
        &mut self,
        kind: usize,
        pos: DVec2,
        z: f64,
        angle: f64,
        vz: f64,
        source: Target,
        ctx: &mut ActorCtx,
    ) -> Option<usize> {
        let k = self.spawn(kind, pos, z, angle.rem_euclid(360.0), ctx)?;
        let def = &self.table.actors[self.list[k].kind];
        let speed = def.speed(ctx.skill == 5);
        let see = def.sounds.see;
        let (sin, cos) = crate::geom::sin_cos_degrees(angle);
        let a = &mut self.list[k];
        a.source = source;
        a.vel = DVec3::new(cos * speed, sin * speed, vz);
        a.tics = (a.tics - i32::from(ctx.rng.byte() & 3)).max(1);
        self.sound_at(k, see, ctx);
        self.wake_physics(k);
        let ahead = self.list[k].pos + DVec2::new(cos, sin) * speed / 2.0;
        self.set_pos(k, ahead);
        if self.try_move(k, ahead, ctx).is_err() {
            self.explode_missile(k, ctx);
        }
        Some(k)
    }

    /// The player fires a `kind` missile (Doom's P_SpawnPlayerMissile):
    /// auto-aimed up or down at a body straight ahead or a little to either
    /// side, else level.
    pub fn player_missile(&mut self, kind: usize, ctx: &mut ActorCtx) -> Option<usize> {
        let p = &ctx.player;
        let (pos, z, angle) = (p.pos, p.z + MISSILE_HEIGHT, p.angle);
        let ray = Ray { origin: pos, z: p.z + crate::play::SHOT_HEIGHT, angle, range: 16.0 * 64.0, shooter: None };
        let mut aimed = self.aim(&ray, ctx);
        for side in [AIM_SIDE, -AIM_SIDE] {
            if aimed.1 == Target::None {
                aimed = self.aim(&Ray { angle: angle + side, ..ray }, ctx);
            }
        }
        let slope = if aimed.1 == Target::None { 0.0 } else { aimed.0 };
        let speed = self.table.actors[self.table.spawned(kind)].speed(ctx.skill == 5);
        self.launch(kind, pos, z, angle, speed * slope, Target::Player, ctx)
    }

    /// An explosion at actor `n` (Doom's P_RadiusAttack): every shootable
    /// body within `radius` (by the larger axis distance, less its radius)
    /// that the blast can see takes `damage` less the distance, scaled
    /// to the radius; the source's own kind of missile-immune bosses
    /// (`NoRadiusDamage`) are spared.
    pub fn explode(&mut self, n: usize, damage: i32, radius: i32, source: Target, ctx: &mut ActorCtx) {
        let (spot, radius_f) = (self.body(n), f64::from(radius.max(1)));
        let reach = DVec2::splat(radius_f);
        let near = self.near(spot.pos - reach, spot.pos + reach);
        let mut victims: Vec<Target> = near.iter().map(|&k| Target::Actor(k)).collect();
        self.give_back(near);
        if !ctx.player.dead() {
            victims.push(Target::Player);
        }
        for t in victims {
            let Some(body) = self.live(t, ctx) else { continue };
            if let Target::Actor(k) = t {
                if self.table.actors[self.list[k as usize].kind].has(ActorFlag::NoRadiusDamage) {
                    continue;
                }
            }
            let d = (body.pos - spot.pos).abs();
            let dist = (d.x.max(d.y) - body.radius).max(0.0).floor();
            if dist >= radius_f {
                continue;
            }
            let blast = Body { z: spot.z, height: spot.height, ..spot };
            if sight::sight(&ctx.level.compiled, ctx.sight, &body, &blast) {
                let amount = (f64::from(damage) * (radius_f - dist) / radius_f) as i32;
                self.hurt(t, amount, Some(n), source, ctx);
            }
        }
    }
}

/// Does `kind`'s death sequence end in nothing (`stop`) rather than a body?
fn vanishes(table: &crate::actors::ActorTable, kind: usize) -> bool {
    let Some(mut s) = table.actors[kind].label("Death") else { return true };
    for _ in 0..64 {
        let state = table.state(s);
        if state.tics < 0 {
            return false;
        }
        match state.next {
            Some(next) if next != s => s = next,
            Some(_) => return false,
            None => return true,
        }
    }
    false
}

/// Adds to `velocity` the push of `damage` on a body of `mass`, away from
/// `from` towards `to` (Doom's `damage * (FRACUNIT >> 3) * 100 / mass`).
fn push(velocity: &mut DVec2, from: DVec2, to: DVec2, damage: i32, mass: i32) {
    let d = to - from;
    if d == DVec2::ZERO {
        return;
    }
    let thrust = f64::from(damage) * 12.5 / f64::from(mass.max(1));
    *velocity += d.normalize() * thrust;
}

// ---- The monsters' actions ----

fn sound(actors: &Actors, n: usize, name: &str, ctx: &mut ActorCtx) {
    actors.sound_named(n, name, ctx);
}

/// Melee if in range (`damage`, a sound), else a missile of the action's argument.
fn melee_or_missile(
    actors: &mut Actors,
    n: usize,
    args: &[Arg],
    ctx: &mut ActorCtx,
    damage: impl Fn(u8) -> i32,
    hit_sound: Option<&str>,
) {
    if actors.target_body(n, ctx).is_none() {
        return;
    }
    face_target(actors, n, &[], ctx);
    if actors.in_melee_range(n, ctx) {
        if let Some(s) = hit_sound {
            sound(actors, n, s, ctx);
        }
        let amount = damage(ctx.rng.byte());
        actors.hurt(actors.list[n].target, amount, Some(n), Target::Actor(n as u32), ctx);
        return;
    }
    if let Some(kind) = actor_arg(args, 0) {
        actors.monster_missile(n, kind, ctx);
    }
}

pub fn troop_attack(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    melee_or_missile(actors, n, args, ctx, |r| (i32::from(r) % 8 + 1) * 3, Some("claw"));
}

pub fn head_attack(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    melee_or_missile(actors, n, args, ctx, |r| (i32::from(r) % 6 + 1) * 10, None);
}

pub fn bruis_attack(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    melee_or_missile(actors, n, args, ctx, |r| (i32::from(r) % 8 + 1) * 10, Some("claw"));
}

/// A plain missile at the target (the arachnotron, the cyberdemon).
pub fn missile_attack(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    if actors.target_body(n, ctx).is_none() {
        return;
    }
    face_target(actors, n, &[], ctx);
    if let Some(kind) = actor_arg(args, 0) {
        actors.monster_missile(n, kind, ctx);
    }
}

/// The lost soul's charge: straight at the target's middle at 20 a tick.
pub fn skull_attack(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let Some(t) = actors.target_body(n, ctx) else { return };
    let attack = actors.table.actors[actors.list[n].kind].sounds.attack;
    actors.sound_at(n, attack, ctx);
    face_target(actors, n, &[], ctx);
    let a = &mut actors.list[n];
    a.skull_fly = true;
    let (sin, cos) = crate::geom::sin_cos_degrees(a.angle);
    let flight = (approx_distance(t.pos - a.pos) / SKULL_SPEED).max(1.0);
    a.vel = DVec3::new(cos * SKULL_SPEED, sin * SKULL_SPEED, (t.z + t.height / 2.0 - a.z) / flight);
    actors.wake_physics(n);
}

pub fn fat_raise(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    face_target(actors, n, &[], ctx);
    sound(actors, n, "manatk", ctx);
}

/// Turns missile `k` by `turn` degrees, keeping its speed.
fn turn_missile(actors: &mut Actors, k: usize, turn: f64) {
    let a = &mut actors.list[k];
    a.angle = (a.angle + turn).rem_euclid(360.0);
    let speed = DVec2::new(a.vel.x, a.vel.y).length();
    let (sin, cos) = crate::geom::sin_cos_degrees(a.angle);
    (a.vel.x, a.vel.y) = (cos * speed, sin * speed);
}

/// The mancubus's volleys: its own turn, and the second fireball's.
fn fat_attack(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx, own: f64, second: f64, first: f64) {
    face_target(actors, n, &[], ctx);
    let a = &mut actors.list[n];
    a.angle = (a.angle + own).rem_euclid(360.0);
    let Some(kind) = actor_arg(args, 0) else { return };
    if let Some(k) = actors.monster_missile(n, kind, ctx) {
        turn_missile(actors, k, first);
    }
    if let Some(k) = actors.monster_missile(n, kind, ctx) {
        turn_missile(actors, k, second);
    }
}

pub fn fat_attack1(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    fat_attack(actors, n, args, ctx, FAT_SPREAD, FAT_SPREAD, 0.0);
}

pub fn fat_attack2(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    fat_attack(actors, n, args, ctx, -FAT_SPREAD, -2.0 * FAT_SPREAD, 0.0);
}

pub fn fat_attack3(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    fat_attack(actors, n, args, ctx, 0.0, FAT_SPREAD / 2.0, -FAT_SPREAD / 2.0);
}

pub fn skel_whoosh(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    face_target(actors, n, &[], ctx);
    sound(actors, n, "skeswg", ctx);
}

pub fn skel_fist(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    if actors.target_body(n, ctx).is_none() {
        return;
    }
    face_target(actors, n, &[], ctx);
    if actors.in_melee_range(n, ctx) {
        let damage = (i32::from(ctx.rng.byte()) % 10 + 1) * 6;
        sound(actors, n, "skepch", ctx);
        actors.hurt(actors.list[n].target, damage, Some(n), Target::Actor(n as u32), ctx);
    }
}

/// The revenant's homing missile: from 16 units higher, a step ahead, its
/// quarry the target.
pub fn skel_missile(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    if actors.target_body(n, ctx).is_none() {
        return;
    }
    face_target(actors, n, &[], ctx);
    let Some(kind) = actor_arg(args, 0) else { return };
    actors.list[n].z += 16.0;
    let k = actors.monster_missile(n, kind, ctx);
    actors.list[n].z -= 16.0;
    if let Some(k) = k {
        if !actors.list[k].removed && actors.list[k].flags.has(ActorFlag::Missile) {
            let a = &actors.list[k];
            let ahead = a.pos + DVec2::new(a.vel.x, a.vel.y);
            actors.set_pos(k, ahead);
            actors.list[k].tracer = actors.list[n].target;
        }
    }
}

/// A homing missile steers (every fourth tick, as Doom's `gametic & 3`):
/// smoke behind, a turn of at most 16.9 degrees towards its quarry, and a
/// climb or dive towards its middle.
pub fn tracer(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    if ctx.level.time & 3 != 0 {
        return;
    }
    let a = &actors.list[n];
    let (pos, z) = (a.pos, a.z);
    if let Some(kind) = actor_arg(args, 0) {
        actors.spawn_effect_kind(kind, DVec3::new(pos.x, pos.y, z), ctx);
    }
    let Some(t) = actors.live(actors.list[n].tracer, ctx) else { return };
    let a = &actors.list[n];
    let d = t.pos - a.pos;
    let want = d.y.atan2(d.x).to_degrees();
    let off = (want - a.angle + 540.0).rem_euclid(360.0) - 180.0;
    turn_missile(actors, n, off.clamp(-TRACE_TURN, TRACE_TURN));
    let a = &mut actors.list[n];
    let speed = actors.table.actors[a.kind].speed(false);
    let flight = ((t.pos - a.pos).length() / speed).max(1.0);
    let slope = (t.z + 40.0 - a.z) / flight;
    a.vel.z += if slope < a.vel.z { -1.0 / 8.0 } else { 1.0 / 8.0 };
}

impl Actors {
    /// A puff of smoke (or any effect) of `kind` at `p`, rising a little.
    fn spawn_effect_kind(&mut self, kind: usize, p: DVec3, ctx: &mut ActorCtx) {
        if let Some(k) = self.spawn(kind, p.truncate(), p.z, 0.0, ctx) {
            let a = &mut self.list[k];
            a.tics = (a.tics - i32::from(ctx.rng.byte() & 3)).max(1);
        }
    }
}

/// A_Explode: the actor bursts, charged to whoever fired or set it off.
pub fn explode(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    let source = match actors.list[n].source {
        Target::None => Target::Actor(n as u32),
        s => s,
    };
    actors.explode(n, int(args, 0), int(args, 1), source, ctx);
}

/// The spider mastermind keeps firing while its target is in sight.
pub fn spid_refire(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    face_target(actors, n, &[], ctx);
    if ctx.rng.byte() < 10 {
        return;
    }
    if !actors.sees_target(n, ctx) {
        let see = actors.table.actors[actors.list[n].kind].label("See");
        actors.set_state(n, see, ctx);
    }
}

/// A footstep, then chase (the cyberdemon's hoof, the mastermind's metal).
fn step_sound(actors: &mut Actors, n: usize, name: &str, ctx: &mut ActorCtx) {
    sound(actors, n, name, ctx);
    super::monsters::chase(actors, n, &[], ctx);
}

pub fn hoof(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    step_sound(actors, n, "hoof", ctx);
}

pub fn metal(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    step_sound(actors, n, "metal", ctx);
}

pub fn baby_metal(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    step_sound(actors, n, "bspwlk", ctx);
}

pub fn player_scream(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let name = if actors.list[n].health < -50 { "pdiehi" } else { "pldeth" };
    sound(actors, n, name, ctx);
}

/// The pain elemental spits a lost soul along `angle` (Doom's
/// A_PainShootSkull): not if the level already has more than 20; the soul
/// starts just clear of it and charges at once, or dies if it is stuck.
fn shoot_skull(actors: &mut Actors, n: usize, angle: f64, kind: usize, ctx: &mut ActorCtx) {
    let kind = actors.table.spawned(kind);
    let souls = actors.list.iter().filter(|a| !a.removed && a.kind == kind && a.health > 0).count();
    if souls > 20 {
        return;
    }
    let a = &actors.list[n];
    let (r1, r2) = (actors.table.actors[a.kind].radius, actors.table.actors[kind].radius);
    let prestep = 4.0 + 3.0 * (r1 + r2) / 2.0;
    let (sin, cos) = crate::geom::sin_cos_degrees(angle);
    let pos = a.pos + DVec2::new(cos, sin) * prestep;
    let (z, target) = (a.z + 8.0, a.target);
    let Some(k) = actors.spawn(kind, pos, z, angle, ctx) else { return };
    if actors.try_move(k, pos, ctx).is_err() {
        actors.hurt(Target::Actor(k as u32), 10000, Some(n), Target::Actor(n as u32), ctx);
        return;
    }
    actors.list[k].target = target;
    skull_attack(actors, k, &[], ctx);
}

pub fn pain_attack(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    if actors.target_body(n, ctx).is_none() {
        return;
    }
    face_target(actors, n, &[], ctx);
    if let Some(kind) = actor_arg(args, 0) {
        let angle = actors.list[n].angle;
        shoot_skull(actors, n, angle, kind, ctx);
    }
}

pub fn pain_die(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    super::monsters::fall(actors, n, &[], ctx);
    if let Some(kind) = actor_arg(args, 0) {
        let angle = actors.list[n].angle;
        for turn in [90.0, 180.0, 270.0] {
            shoot_skull(actors, n, angle + turn, kind, ctx);
        }
    }
}

/// The BFG's ball bursts: forty tracers from whoever fired it, spread over
/// 90 degrees about the ball's flight; each body they find takes fifteen
/// rolls of 1 to 8, with a flash on it.
pub fn bfg_spray(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    let source = actors.list[n].source;
    let (origin, z, shooter) = match source {
        Target::Player => (ctx.player.pos, ctx.player.z + crate::play::SHOT_HEIGHT, None),
        Target::Actor(s) if !actors.list[s as usize].removed => {
            let a = &actors.list[s as usize];
            (a.pos, a.z + actors.table.actors[a.kind].height / 2.0 + 8.0, Some(s as usize))
        }
        _ => return,
    };
    let base = actors.list[n].angle - 45.0;
    for i in 0..40 {
        let angle = base + 90.0 / 40.0 * f64::from(i);
        let ray = Ray { origin, z, angle, range: 16.0 * 64.0, shooter };
        let (_, t) = actors.aim(&ray, ctx);
        let Some(body) = actors.live(t, ctx) else { continue };
        if let Some(kind) = actor_arg(args, 0) {
            actors.spawn(kind, body.pos, body.z + body.height / 4.0, 0.0, ctx);
        }
        let damage: i32 = (0..15).map(|_| i32::from(ctx.rng.byte() & 7) + 1).sum();
        let inflictor = match source {
            Target::Actor(s) => Some(s as usize),
            _ => None,
        };
        actors.hurt(t, damage, inflictor, source, ctx);
    }
}

// ---- The arch-vile ----

/// Chase, but first look a step ahead for a corpse to raise: one in its
/// last frame, with raise frames, that fits where it lies.
pub fn vile_chase(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    let table = actors.table.clone();
    let a = &actors.list[n];
    if a.movedir != super::movement::NO_DIR {
        let def = &table.actors[a.kind];
        let ahead = a.pos + super::movement::DIR_STEP[usize::from(a.movedir)] * def.speed;
        let reach = DVec2::splat(def.radius + 64.0);
        let near = actors.near(ahead - reach, ahead + reach);
        let corpse = near.iter().map(|&k| k as usize).find(|&k| {
            let c = &actors.list[k];
            let cdef = &table.actors[c.kind];
            let d = (c.pos - ahead).abs();
            k != n
                && !c.removed
                && c.flags.has(ActorFlag::Corpse)
                && c.tics == -1
                && cdef.label("Raise").is_some()
                && d.x.max(d.y) <= cdef.radius + def.radius
                && actors.fits_standing(k, ctx)
        });
        actors.give_back(near);
        if let Some(k) = corpse {
            let old = actors.list[n].target;
            actors.list[n].target = Target::Actor(k as u32);
            face_target(actors, n, &[], ctx);
            actors.list[n].target = old;
            let heal = actors.table.actors[actors.list[n].kind].label("Heal");
            actors.set_state(n, heal, ctx);
            sound(actors, k, "slop", ctx);
            actors.raise(k, ctx);
            return;
        }
    }
    super::monsters::chase(actors, n, args, ctx);
}

impl Actors {
    /// Would corpse `k` fit standing up where it lies?
    fn fits_standing(&mut self, k: usize, ctx: &mut ActorCtx) -> bool {
        let was = self.list[k].flags;
        self.list[k].flags.set(ActorFlag::Solid, true);
        let pos = self.list[k].pos;
        let ok = self.try_move(k, pos, ctx).is_ok();
        self.list[k].flags = was;
        ok
    }

    /// Corpse `k` rises (Doom's arch-vile raise): its table's flags and
    /// health back, no target, its raise frames.
    fn raise(&mut self, k: usize, ctx: &mut ActorCtx) {
        let table = self.table.clone();
        let def = &table.actors[self.list[k].kind];
        let raise = def.label("Raise");
        let a = &mut self.list[k];
        a.flags = def.flags;
        a.health = def.health;
        a.target = Target::None;
        a.threshold = 0;
        self.set_state(k, raise, ctx);
        if def.has(ActorFlag::CountKill) {
            *ctx.kills = ctx.kills.saturating_sub(1);
        }
    }
}

pub fn vile_start(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    sound(actors, n, "vilatk", ctx);
}

/// Fire appears on the target; it follows the target while the vile sees it.
pub fn vile_target(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    let Some(t) = actors.target_body(n, ctx) else { return };
    face_target(actors, n, &[], ctx);
    let Some(kind) = actor_arg(args, 0) else { return };
    let Some(k) = actors.spawn(kind, t.pos, t.z, 0.0, ctx) else { return };
    actors.list[k].source = Target::Actor(n as u32);
    actors.list[k].tracer = actors.list[n].target;
    actors.list[n].tracer = Target::Actor(k as u32);
    fire(actors, k, &[], ctx);
}

/// The blast: 20 damage to the target if still seen, flung up, and the
/// fire before it bursts for 70 around.
pub fn vile_attack(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let Some(t) = actors.target_body(n, ctx) else { return };
    face_target(actors, n, &[], ctx);
    if !actors.sees(n, &t, ctx) {
        return;
    }
    sound(actors, n, "barexp", ctx);
    let target = actors.list[n].target;
    actors.hurt(target, 20, Some(n), Target::Actor(n as u32), ctx);
    match target {
        Target::Player => ctx.player.vz = 1000.0 / 100.0,
        Target::Actor(k) => {
            let mass = f64::from(actors.table.actors[actors.list[k as usize].kind].mass.max(1));
            actors.list[k as usize].vel.z = 1000.0 / mass;
            actors.wake_physics(k as usize);
        }
        Target::None => {}
    }
    let Target::Actor(f) = actors.list[n].tracer else { return };
    let f = f as usize;
    if actors.list[f].removed {
        return;
    }
    let (sin, cos) = crate::geom::sin_cos_degrees(actors.list[n].angle);
    let at = t.pos - DVec2::new(cos, sin) * 24.0;
    actors.set_pos(f, at);
    actors.explode(f, 70, 70, Target::Actor(n as u32), ctx);
}

/// The fire keeps in front of its victim while the arch-vile sees it.
pub fn fire(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let Some(dest) = actors.body_of(actors.list[n].tracer, ctx) else { return };
    let Target::Actor(vile) = actors.list[n].source else { return };
    if actors.list[vile as usize].removed || !actors.sees(vile as usize, &dest, ctx) {
        return;
    }
    let angle = match actors.list[n].tracer {
        Target::Player => ctx.player.angle,
        Target::Actor(k) => actors.list[k as usize].angle,
        Target::None => 0.0,
    };
    let (sin, cos) = crate::geom::sin_cos_degrees(angle);
    actors.set_pos(n, dest.pos + DVec2::new(cos, sin) * 24.0);
    actors.list[n].z = dest.z;
}

pub fn start_fire(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    sound(actors, n, "flamst", ctx);
    fire(actors, n, args, ctx);
}

pub fn fire_crackle(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    sound(actors, n, "flame", ctx);
    fire(actors, n, args, ctx);
}

// ---- Bosses ----

/// When the last of a boss's kind on the maps that need it dies, the
/// level's boss special happens (Doom's A_BossDeath): E1M8's barons lower
/// tag 666's floors; E2M8's cyberdemon and E3M8's mastermind end the
/// level; E4M6's cyberdemon opens tag 666's doors fast; E4M8's mastermind
/// lowers 666's floors; MAP07's mancubi lower 666's floors and its
/// arachnotrons raise 667's to the shortest lower texture. The actor's
/// flags say which map it counts on.
pub fn boss_death(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let def = &actors.table.actors[actors.list[n].kind];
    let map = ctx.level.compiled.map.name.to_ascii_uppercase();
    let map = map.rsplit(['/', ':']).next().unwrap_or("").to_string();
    let lower =
        Action::Floor { to: FloorTarget::LowestNeighbourFloor, offset: 0.0, speed: 1.0, crush: false, change: None };
    let request = match map.as_str() {
        "E1M8" if def.has(ActorFlag::E1M8Boss) => Request::Tagged(lower, 666),
        "E2M8" if def.has(ActorFlag::E2M8Boss) => Request::Exit,
        "E3M8" if def.has(ActorFlag::E3M8Boss) => Request::Exit,
        "E4M6" if def.has(ActorFlag::E4M6Boss) => Request::Tagged(blaze_open(), 666),
        "E4M8" if def.has(ActorFlag::E4M8Boss) => Request::Tagged(lower, 666),
        "MAP07" if def.has(ActorFlag::Map07Boss1) => Request::Tagged(lower, 666),
        "MAP07" if def.has(ActorFlag::Map07Boss2) => Request::Tagged(
            Action::Floor {
                to: FloorTarget::ShortestLowerTexture,
                offset: 0.0,
                speed: 1.0,
                crush: false,
                change: None,
            },
            667,
        ),
        _ => return,
    };
    if ctx.player.dead() || actors.others_alive(n) {
        return;
    }
    ctx.requests.push(request);
}

fn blaze_open() -> Action {
    Action::Door { kind: DoorKind::Open, speed: 8.0, wait: 150, shut: 35 * 30, key: None }
}

impl Actors {
    /// Is any other actor of `n`'s kind still alive?
    fn others_alive(&self, n: usize) -> bool {
        let kind = self.list[n].kind;
        self.list.iter().enumerate().any(|(k, a)| k != n && a.kind == kind && !a.removed && a.health > 0)
    }
}

/// Commander Keen: falls, and when every Keen is dead tag 666's doors open.
pub fn keen_die(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    super::monsters::fall(actors, n, &[], ctx);
    if !actors.others_alive(n) {
        let open = Action::Door { kind: DoorKind::Open, speed: 2.0, wait: 150, shut: 35 * 30, key: None };
        ctx.requests.push(Request::Tagged(open, 666));
    }
}

pub fn brain_awake(_: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    ctx.events.push(Event::Sound { sound: "bossit", origin: Origin::Player });
}

pub fn brain_pain(_: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    ctx.events.push(Event::Sound { sound: "bospn", origin: Origin::Player });
}

/// Explosions along the brain's wall as it dies.
pub fn brain_scream(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    let Some(kind) = actor_arg(args, 0) else { return };
    let pos = actors.list[n].pos;
    let mut x = pos.x - 196.0;
    while x < pos.x + 320.0 {
        let y = pos.y - 320.0;
        let z = 128.0 + f64::from(ctx.rng.byte()) * 2.0;
        if let Some(k) = actors.spawn(kind, DVec2::new(x, y), z, 0.0, ctx) {
            let a = &mut actors.list[k];
            a.vel.z = f64::from(ctx.rng.byte()) / 512.0;
            a.tics = (a.tics - i32::from(ctx.rng.byte() & 7)).max(1);
            actors.wake_physics(k);
        }
        x += 8.0;
    }
    ctx.events.push(Event::Sound { sound: "bosdth", origin: Origin::Player });
}

pub fn brain_explode(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    let Some(kind) = actor_arg(args, 0) else { return };
    let a = &actors.list[n];
    let x = a.pos.x + (f64::from(ctx.rng.byte()) - f64::from(ctx.rng.byte())) / 32.0;
    let (y, z) = (a.pos.y, 128.0 + f64::from(ctx.rng.byte()) * 2.0);
    if let Some(k) = actors.spawn(kind, DVec2::new(x, y), z, 0.0, ctx) {
        let a = &mut actors.list[k];
        a.vel.z = f64::from(ctx.rng.byte()) / 512.0;
        a.tics = (a.tics - i32::from(ctx.rng.byte() & 7)).max(1);
        actors.wake_physics(k);
    }
}

pub fn brain_die(_: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    ctx.requests.push(Request::Exit);
}

/// The boss shooter sends a cube to the next spawn spot (a map thing) in turn.
pub fn brain_spit(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    let map = &ctx.level.compiled.map;
    let spots: Vec<usize> = (0..map.things.len()).filter(|&i| map.things[i].kind == "boss_spawn_spot").collect();
    if spots.is_empty() {
        return;
    }
    // Skills 1 and 2 spit every other time (Doom's `easy` toggle).
    actors.list[n].threshold ^= 1;
    if ctx.skill <= 2 && actors.list[n].threshold == 0 {
        return;
    }
    let spot = spots[actors.list[n].movecount.rem_euclid(spots.len() as i32) as usize];
    actors.list[n].movecount = actors.list[n].movecount.wrapping_add(1);
    let Some(kind) = actor_arg(args, 0) else { return };
    let to = ctx.level.compiled.map.things[spot].pos;
    let a = &actors.list[n];
    let (pos, z) = (a.pos, a.z + MISSILE_HEIGHT);
    let d = to - pos;
    let Some(c) = actors.launch(kind, pos, z, d.y.atan2(d.x).to_degrees(), 0.0, Target::Actor(n as u32), ctx) else {
        return;
    };
    let a = &actors.list[c];
    let speed = DVec2::new(a.vel.x, a.vel.y).length().max(1.0);
    let tics = actors.table.state(a.state).tics.max(1);
    let flight = (d.length() / speed).ceil();
    let a = &mut actors.list[c];
    a.movecount = spot as i32;
    a.reaction_time = (flight / f64::from(tics)) as i32;
    ctx.events.push(Event::Sound { sound: "bospit", origin: Origin::Player });
}

pub fn spawn_sound(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    sound(actors, n, "boscub", ctx);
    spawn_fly(actors, n, args, ctx);
}

/// The cube flies until its time is up, then fire and a monster (Doom's
/// odds: imps most often, a cyberdemon least) appear at its spot, killing
/// what stands there.
pub fn spawn_fly(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    actors.list[n].reaction_time -= 1;
    if actors.list[n].reaction_time > 0 {
        return;
    }
    let map = &ctx.level.compiled.map;
    let Some(thing) = usize::try_from(actors.list[n].movecount).ok().and_then(|i| map.things.get(i)) else {
        actors.remove(n);
        return;
    };
    let pos = thing.pos;
    let z = map.sectors[ctx.level.compiled.sector_at(pos)].floor;
    if let Some(kind) = actor_arg(args, 0) {
        if let Some(f) = actors.spawn(kind, pos, z, 0.0, ctx) {
            sound(actors, f, "telept", ctx);
        }
    }
    let r = ctx.rng.byte();
    let name = match r {
        0..=49 => "imp",
        50..=89 => "demon",
        90..=119 => "spectre",
        120..=129 => "pain_elemental",
        130..=159 => "cacodemon",
        160..=161 => "arch_vile",
        162..=171 => "revenant",
        172..=191 => "arachnotron",
        192..=221 => "mancubus",
        222..=245 => "hell_knight",
        _ => "baron_of_hell",
    };
    if let Some(kind) = actors.table.index(name) {
        if let Some(m) = actors.spawn(kind, pos, z, 0.0, ctx) {
            let see = actors.table.actors[actors.list[m].kind].label("See");
            // It looks round for the player at once.
            if !ctx.player.dead() {
                actors.list[m].target = Target::Player;
                actors.set_state(m, see, ctx);
            }
        }
    }
    actors.remove(n);
}
