//! What monsters do, as actions their states call (Doom's `p_enemy.c`
//! rules, written anew): look for the player, chase it in steps of their
//! speed around what blocks them, face it, and attack when in range and
//! in sight; pain, death cries and falling bodies.
//!
//! A monster's target is the player or, once another monster hurts it,
//! that monster (`attacks.rs`: infighting). They hear the player's shots
//! ([`Actors::noise_alert`]).

use glam::DVec2;

use super::actions::sound;
use super::attacks::Request;
use super::movement::{opposite, Ground, DIR_STEP, NO_DIR};
use super::physics::{Blocked, FLOAT_SPEED};
use super::{ActorCtx, Actors, Target};
use crate::actors::{ActorFlag, Arg};
use crate::map::special::{Action, Activation};
use crate::play::events::{Event, Origin};
use crate::play::player::{HEIGHT as PLAYER_HEIGHT, RADIUS as PLAYER_RADIUS};
use crate::play::sight::{self, Body, Ray, MELEE_RANGE};
use crate::play::SHOT_RANGE;

/// The player's index among bodies and blockers.
pub const PLAYER: usize = usize::MAX;

/// Doom's P_AproxDistance: the sum of the legs less half the shorter,
/// which monsters' decisions are tuned to.
pub fn approx_distance(d: DVec2) -> f64 {
    let (x, y) = (d.x.abs(), d.y.abs());
    x + y - x.min(y) / 2.0
}

/// `degrees` wrapped into `(-180, 180]`.
fn wrap(degrees: f64) -> f64 {
    let d = degrees.rem_euclid(360.0);
    if d > 180.0 {
        d - 360.0
    } else {
        d
    }
}

/// A random byte difference as an angle: Doom's `(P_Random() - P_Random())
/// << shift`, in degrees.
pub fn spread(ctx: &mut ActorCtx, shift: u32) -> f64 {
    let d = f64::from(ctx.rng.byte()) - f64::from(ctx.rng.byte());
    d * f64::from(1u32 << shift) * 360.0 / 4_294_967_296.0
}

impl Actors {
    pub fn body(&self, n: usize) -> Body {
        let (a, def) = (&self.list[n], &self.table.actors[self.list[n].kind]);
        Body { pos: a.pos, z: a.z, height: def.height, radius: def.radius, index: n }
    }

    pub(super) fn sound_at(&self, n: usize, sound: Option<usize>, ctx: &mut ActorCtx) {
        let Some(s) = sound else { return };
        let name = crate::actors::sounds::doom()[s].name.as_str();
        let def = &self.table.actors[self.list[n].kind];
        // Bosses are heard everywhere at full volume.
        let origin = if def.has(ActorFlag::FullVolumeSounds) {
            Origin::Player
        } else {
            Origin::Actor { index: n as u32, pos: self.list[n].pos }
        };
        ctx.events.push(Event::Sound { sound: name, origin });
    }

    /// The sound of that name (Doom's, without `DS`) from actor `n`.
    pub(super) fn sound_named(&self, n: usize, name: &str, ctx: &mut ActorCtx) {
        let s = crate::actors::sounds::doom().iter().position(|s| s.name == name);
        self.sound_at(n, s, ctx);
    }

    /// One of Doom's sound sets picked at random (`posit1`..`posit3`,
    /// `bgsit1`/`bgsit2`, `podth1`..`podth3`, `bgdth1`/`bgdth2`), else the sound.
    fn varied(&self, sound: Option<usize>, ctx: &mut ActorCtx) -> Option<usize> {
        let sounds = crate::actors::sounds::doom();
        let name = sounds.get(sound?)?.name.as_str();
        let set: &[&str] = match name {
            "posit1" | "posit2" | "posit3" => &["posit1", "posit2", "posit3"],
            "bgsit1" | "bgsit2" => &["bgsit1", "bgsit2"],
            "podth1" | "podth2" | "podth3" => &["podth1", "podth2", "podth3"],
            "bgdth1" | "bgdth2" => &["bgdth1", "bgdth2"],
            _ => return sound,
        };
        let pick = set[usize::from(ctx.rng.byte()) % set.len()];
        sounds.iter().position(|s| s.name == pick)
    }

    /// The body of `target`, alive or dead, while it is in play.
    pub fn body_of(&self, target: Target, ctx: &ActorCtx) -> Option<Body> {
        match target {
            Target::None => None,
            Target::Player => Some(player_body(ctx)),
            Target::Actor(k) => (!self.list[k as usize].removed).then(|| self.body(k as usize)),
        }
    }

    /// A floater chasing rises or sinks towards its target's middle
    /// (Doom's P_ZMovement for MF_FLOAT), within its floor and ceiling.
    fn float_towards_target(&mut self, n: usize, ctx: &ActorCtx) {
        let a = &self.list[n];
        if !a.flags.has(ActorFlag::Float) || a.skull_fly || a.in_float {
            return;
        }
        let Some(t) = self.target_body(n, ctx) else { return };
        let height = self.table.actors[a.kind].height;
        let dist = approx_distance(t.pos - a.pos);
        let delta = t.z + height / 2.0 - a.z;
        let dz = if delta < 0.0 && dist < -(delta * 3.0) {
            -FLOAT_SPEED
        } else if delta > 0.0 && dist < delta * 3.0 {
            FLOAT_SPEED
        } else {
            return;
        };
        let a = &mut self.list[n];
        a.z = (a.z + dz).min(a.ceiling - height).max(a.floor);
        self.dirty.push(n as u32);
    }

    /// The body of `target` if it is alive (a live player, a shootable actor).
    pub fn live(&self, target: Target, ctx: &ActorCtx) -> Option<Body> {
        match target {
            Target::None => None,
            Target::Player => (!ctx.player.dead()).then(|| player_body(ctx)),
            Target::Actor(k) => {
                let b = &self.list[k as usize];
                (!b.removed && b.health > 0 && b.flags.has(ActorFlag::Shootable)).then(|| self.body(k as usize))
            }
        }
    }

    /// Actor `n`'s target, alive.
    pub fn target_body(&self, n: usize, ctx: &ActorCtx) -> Option<Body> {
        self.live(self.list[n].target, ctx)
    }

    /// Can actor `n` see `body`?
    pub(super) fn sees(&self, n: usize, body: &Body, ctx: &mut ActorCtx) -> bool {
        let looker = self.body(n);
        sight::sight(&ctx.level.compiled, ctx.sight, &looker, body)
    }

    /// Can actor `n` see its live target?
    pub(super) fn sees_target(&self, n: usize, ctx: &mut ActorCtx) -> bool {
        self.target_body(n, ctx).is_some_and(|t| self.sees(n, &t, ctx))
    }

    /// Doom's P_LookForPlayers: a live player in sight, in front (or all
    /// round), or behind but within melee range.
    fn look_for_player(&mut self, n: usize, all_round: bool, ctx: &mut ActorCtx) -> bool {
        if ctx.player.dead() {
            return false;
        }
        let a = &self.list[n];
        let to = ctx.player.pos - a.pos;
        if !all_round {
            let off = wrap(to.y.atan2(to.x).to_degrees() - a.angle).abs();
            if off > 90.0 && approx_distance(to) > MELEE_RANGE {
                return false;
            }
        }
        if !self.sees(n, &player_body(ctx), ctx) {
            return false;
        }
        self.list[n].target = Target::Player;
        true
    }

    /// Doom's P_CheckMeleeRange.
    pub(super) fn in_melee_range(&self, n: usize, ctx: &mut ActorCtx) -> bool {
        let Some(t) = self.target_body(n, ctx) else { return false };
        let reach = MELEE_RANGE - 20.0 + t.radius;
        approx_distance(t.pos - self.list[n].pos) < reach && self.sees(n, &t, ctx)
    }

    /// Doom's P_CheckMissileRange: in sight, then a random draw against
    /// the distance (nearer is likelier), tuned per monster by flags.
    fn wants_to_shoot(&mut self, n: usize, ctx: &mut ActorCtx) -> bool {
        let Some(t) = self.target_body(n, ctx) else { return false };
        if !self.sees(n, &t, ctx) {
            return false;
        }
        let a = &mut self.list[n];
        if std::mem::take(&mut a.just_hit) {
            return true;
        }
        if a.reaction_time > 0 {
            return false;
        }
        let def = &self.table.actors[a.kind];
        let mut dist = approx_distance(t.pos - a.pos) - 64.0;
        if def.label("Melee").is_none() {
            dist -= 128.0;
        }
        if def.has(ActorFlag::ShortMissileRange) && dist > 14.0 * 64.0 {
            return false;
        }
        if def.has(ActorFlag::LongMelee) {
            if dist < 196.0 {
                return false;
            }
            dist /= 2.0;
        }
        if def.has(ActorFlag::RangeHalf) {
            dist /= 2.0;
        }
        dist = dist.min(200.0);
        if def.has(ActorFlag::HigherMissileProbability) {
            dist = dist.min(160.0);
        }
        f64::from(ctx.rng.byte()) >= dist.floor()
    }

    /// One step along `movedir` (Doom's P_Move): taken if the box fits
    /// there; a floater at the wrong height for the opening rises or sinks
    /// towards it instead.
    fn step(&mut self, n: usize, ctx: &mut ActorCtx) -> bool {
        let a = &self.list[n];
        if a.movedir == NO_DIR {
            return false;
        }
        let def = &self.table.actors[a.kind];
        let to = a.pos + DIR_STEP[usize::from(a.movedir)] * def.speed(ctx.skill == 5);
        match self.try_move(n, to, ctx) {
            Ok(()) => {
                self.list[n].in_float = false;
                true
            }
            Err(Blocked::Float { floor }) => {
                let a = &mut self.list[n];
                a.z += if a.z < floor { FLOAT_SPEED } else { -FLOAT_SPEED };
                a.in_float = true;
                self.dirty.push(n as u32);
                true
            }
            Err(Blocked::Thing(_)) => false,
            Err(_) => self.push_doors(n, to, ctx),
        }
    }

    /// Actor `n`, stopped on its way to `to`, pushes the doors it touches
    /// there that monsters may open (Doom's P_Move using the lines in
    /// `spechit`); a door with a key stays shut to it. Returns whether it
    /// pushed one (then it keeps its direction, waiting for the door).
    fn push_doors(&mut self, n: usize, to: DVec2, ctx: &mut ActorCtx) -> bool {
        let a = &self.list[n];
        if a.flags.has(ActorFlag::Missile) || a.flags.has(ActorFlag::NoClip) {
            return false;
        }
        let radius = self.table.actors[a.kind].radius;
        let ground = Ground { compiled: &ctx.level.compiled, blockmap: ctx.blockmap };
        let map = &ctx.level.compiled.map;
        let mut pushed = false;
        for line in ground.passable_touched(ctx.query, to, radius) {
            let opens = map.lines[line].special.as_ref().is_some_and(|s| {
                s.on == Activation::Use && s.by.monsters() && matches!(s.action, Action::Door { key: None, .. })
            });
            if opens {
                ctx.requests.push(Request::Use { actor: n as u32, line });
                pushed = true;
            }
        }
        pushed
    }

    /// Sets off in `dir` for a few steps, if a first step that way works
    /// (Doom's P_TryWalk).
    fn try_walk(&mut self, n: usize, dir: u8, ctx: &mut ActorCtx) -> bool {
        self.list[n].movedir = dir;
        if !self.step(n, ctx) {
            return false;
        }
        self.list[n].movecount = i32::from(ctx.rng.byte() & 15);
        true
    }

    /// Chooses a new direction towards the player (Doom's P_NewChaseDir):
    /// straight at it (diagonally if both ways are open), else along one
    /// axis, else on as before, else any direction in a random order, and
    /// turning back only as a last resort.
    fn new_chase_dir(&mut self, n: usize, ctx: &mut ActorCtx) {
        let (old, from) = (self.list[n].movedir, self.list[n].pos);
        let back = opposite(old);
        let Some(t) = self.target_body(n, ctx) else {
            self.list[n].movedir = NO_DIR;
            return;
        };
        let delta = t.pos - from;
        let mut d = [
            if delta.x > 10.0 {
                0
            } else if delta.x < -10.0 {
                4
            } else {
                NO_DIR
            },
            if delta.y < -10.0 {
                6
            } else if delta.y > 10.0 {
                2
            } else {
                NO_DIR
            },
        ];
        // Both ways: the diagonal between them.
        if d[0] != NO_DIR && d[1] != NO_DIR {
            let diagonal = match (d[0], d[1]) {
                (0, 2) => 1,
                (4, 2) => 3,
                (4, 6) => 5,
                _ => 7,
            };
            if diagonal != back && self.try_walk(n, diagonal, ctx) {
                return;
            }
        }
        if ctx.rng.byte() > 200 || delta.y.abs() > delta.x.abs() {
            d.swap(0, 1);
        }
        for dir in &mut d {
            if *dir == back {
                *dir = NO_DIR;
            }
        }
        for dir in d {
            if dir != NO_DIR && self.try_walk(n, dir, ctx) {
                return;
            }
        }
        if old != NO_DIR && self.try_walk(n, old, ctx) {
            return;
        }
        let order: Vec<u8> = if ctx.rng.byte() & 1 == 1 { (0..8).collect() } else { (0..8).rev().collect() };
        for dir in order {
            if dir != back && self.try_walk(n, dir, ctx) {
                return;
            }
        }
        if back != NO_DIR && self.try_walk(n, back, ctx) {
            return;
        }
        self.list[n].movedir = NO_DIR;
    }

    /// Fires one bullet (Doom's P_LineAttack from a monster): aimed up or
    /// down at what it faces, turned by `angle`, hurting what it hits
    /// (its target or another in the way); a puff where it hits a wall.
    fn bullet(&mut self, n: usize, angle: f64, damage: i32, ctx: &mut ActorCtx) {
        let a = &self.list[n];
        let def = &self.table.actors[a.kind];
        let z = a.z + def.height / 2.0 + 8.0;
        let aim = Ray { origin: a.pos, z, angle: a.angle, range: SHOT_RANGE, shooter: Some(n) };
        let (slope, _) = self.aim(&aim, ctx);
        self.line_attack(Target::Actor(n as u32), &Ray { angle, ..aim }, slope, damage, ctx);
    }
}

/// The player as sight and shots see it.
pub fn player_body(ctx: &ActorCtx) -> Body {
    let p = &ctx.player;
    Body { pos: p.pos, z: p.z, height: PLAYER_HEIGHT, radius: PLAYER_RADIUS, index: PLAYER }
}

/// A_Look: wait for the player to be heard in the monster's sector (an
/// `ambush` monster must also see it) or to come into view, then cry out
/// and give chase.
pub fn look(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let a = &actors.list[n];
    let heard = actors.heard.get(a.sector).copied().unwrap_or(false) && !ctx.player.dead();
    let woken = if heard && (!a.flags.has(ActorFlag::Ambush) || actors.sees(n, &player_body(ctx), ctx)) {
        actors.list[n].target = Target::Player;
        true
    } else {
        actors.look_for_player(n, false, ctx)
    };
    if !woken {
        return;
    }
    let def = &actors.table.actors[actors.list[n].kind];
    let (see_sound, see) = (def.sounds.see, def.label("See"));
    let cry = actors.varied(see_sound, ctx);
    actors.sound_at(n, cry, ctx);
    if see.is_some() {
        actors.set_state(n, see, ctx);
    }
}

/// A_Chase: turn towards the way it walks, attack if it can, else step.
pub fn chase(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let a = &mut actors.list[n];
    if a.reaction_time > 0 {
        a.reaction_time -= 1;
    }
    // Face the way it walks, 45 degrees a step.
    if a.movedir != NO_DIR {
        let snapped = (a.angle / 45.0).floor() * 45.0;
        let off = wrap(snapped - f64::from(a.movedir) * 45.0);
        let turned = if off > 0.0 {
            snapped - 45.0
        } else if off < 0.0 {
            snapped + 45.0
        } else {
            snapped
        };
        a.angle = turned.rem_euclid(360.0);
    }
    if a.threshold > 0 {
        a.threshold -= 1;
    }
    let def = &actors.table.actors[a.kind];
    let (spawn, melee, missile, attack_sound, active) =
        (def.label("Spawn"), def.label("Melee"), def.label("Missile"), def.sounds.attack, def.sounds.active);
    if actors.target_body(n, ctx).is_none() {
        actors.list[n].target = Target::None;
        if !actors.look_for_player(n, true, ctx) {
            actors.set_state(n, spawn, ctx);
        }
        return;
    }
    let a = &mut actors.list[n];
    let nightmare = ctx.skill == 5;
    if std::mem::take(&mut a.just_attacked) {
        if !nightmare {
            actors.new_chase_dir(n, ctx);
        }
        return;
    }
    if melee.is_some() && actors.in_melee_range(n, ctx) {
        actors.sound_at(n, attack_sound, ctx);
        actors.set_state(n, melee, ctx);
        return;
    }
    let waits = !nightmare && actors.list[n].movecount > 0;
    if missile.is_some() && !waits && actors.wants_to_shoot(n, ctx) {
        actors.set_state(n, missile, ctx);
        actors.list[n].just_attacked = true;
        return;
    }
    actors.list[n].movecount -= 1;
    if actors.list[n].movecount < 0 || !actors.step(n, ctx) {
        actors.new_chase_dir(n, ctx);
    }
    actors.float_towards_target(n, ctx);
    if active.is_some() && ctx.rng.byte() < 3 {
        actors.sound_at(n, active, ctx);
    }
}

/// A_FaceTarget: turn to the player (off by a little if it is unseen).
pub fn face_target(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let Some(t) = actors.body_of(actors.list[n].target, ctx) else { return };
    let shadow = match actors.list[n].target {
        Target::Actor(k) => actors.list[k as usize].flags.has(ActorFlag::Shadow),
        Target::Player => ctx.player.powers[crate::play::pickups::power_slot(crate::actors::Power::Invisibility)] > 0,
        Target::None => false,
    };
    let a = &mut actors.list[n];
    a.flags.set(ActorFlag::Ambush, false);
    let d = t.pos - a.pos;
    a.angle = d.y.atan2(d.x).to_degrees().rem_euclid(360.0);
    if shadow {
        let turn = spread(ctx, 21);
        let a = &mut actors.list[n];
        a.angle = (a.angle + turn).rem_euclid(360.0);
    }
    actors.dirty.push(n as u32);
}

pub fn pain(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let s = actors.table.actors[actors.list[n].kind].sounds.pain;
    actors.sound_at(n, s, ctx);
}

pub fn scream(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let s = actors.table.actors[actors.list[n].kind].sounds.death;
    let s = actors.varied(s, ctx);
    actors.sound_at(n, s, ctx);
}

pub fn xscream(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    actors.sound_named(n, "slop", ctx);
}

/// A_Fall: the body no longer blocks.
pub fn fall(actors: &mut Actors, n: usize, _: &[Arg], _: &mut ActorCtx) {
    actors.list[n].flags.set(ActorFlag::Solid, false);
}

pub fn play_sound(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    actors.sound_at(n, sound(args, 0), ctx);
}

/// A hitscan attack: face the player, the weapon's sound (named in the
/// action, as Doom's are: the shotgun guy's table has no attack sound),
/// then `bullets` shots each turned by Doom's spread and doing 3 to 15
/// damage.
fn volley(actors: &mut Actors, n: usize, ctx: &mut ActorCtx, sound: &str, bullets: usize) {
    if actors.target_body(n, ctx).is_none() {
        return;
    }
    face_target(actors, n, &[], ctx);
    actors.sound_named(n, sound, ctx);
    for _ in 0..bullets {
        let angle = actors.list[n].angle + spread(ctx, 20);
        let damage = (i32::from(ctx.rng.byte()) % 5 + 1) * 3;
        actors.bullet(n, angle, damage, ctx);
    }
}

/// The zombieman: one bullet.
pub fn pos_attack(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    volley(actors, n, ctx, "pistol", 1);
}

/// The shotgun guy: three pellets.
pub fn spos_attack(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    volley(actors, n, ctx, "shotgn", 3);
}

/// The chaingunner: one bullet a shot (with the shotgun's sound, as Doom's).
pub fn cpos_attack(actors: &mut Actors, n: usize, _: &[Arg], ctx: &mut ActorCtx) {
    volley(actors, n, ctx, "shotgn", 1);
}

/// Keeps firing while the player is in sight (stopping now and then).
pub fn cpos_refire(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    face_target(actors, n, args, ctx);
    if ctx.rng.byte() < 40 {
        return;
    }
    if !actors.sees_target(n, ctx) {
        let see = actors.table.actors[actors.list[n].kind].label("See");
        actors.set_state(n, see, ctx);
    }
}

/// The demon's bite: 4 to 40 damage in melee range.
pub fn sarg_attack(actors: &mut Actors, n: usize, args: &[Arg], ctx: &mut ActorCtx) {
    if actors.target_body(n, ctx).is_none() {
        return;
    }
    face_target(actors, n, args, ctx);
    if actors.in_melee_range(n, ctx) {
        let damage = (i32::from(ctx.rng.byte()) % 10 + 1) * 4;
        actors.hurt(actors.list[n].target, damage, Some(n), Target::Actor(n as u32), ctx);
    }
}

/// Ticks a monster lies still before skill 5 may bring it back (Doom's
/// 12 seconds), and the chance each 32nd tick after that (Doom's
/// `P_Random() <= 4`: 5 in 256).
pub const RESPAWN_AFTER: u64 = 12 * 35;

impl Actors {
    /// Skill 5, every 32nd tick (Doom's P_NightmareRespawn): each monster
    /// that has lain still (a counted monster in a state that lasts for
    /// ever) for [`RESPAWN_AFTER`] ticks comes back, with a chance of 5 in
    /// 256, where its map thing stood, if nothing solid stands there: a
    /// new actor of its kind with the map's ambush flag, held 18 ticks,
    /// and a teleport fog where the body lay and where it appears.
    pub(super) fn respawn_monsters(&mut self, ctx: &mut ActorCtx) {
        let now = ctx.level.time;
        let mut corpses = std::mem::take(&mut self.corpses);
        corpses.retain(|&n| {
            let a = &self.list[n as usize];
            if a.removed || a.tics >= 0 {
                return false; // raised, or gone
            }
            if now < a.still_since + RESPAWN_AFTER || ctx.rng.byte() > 4 {
                return true;
            }
            !self.bring_back(n as usize, ctx)
        });
        corpses.append(&mut self.corpses);
        self.corpses = corpses;
    }

    /// Brings monster `n` back at its map thing's spot; `false` if it has
    /// none or the spot is taken.
    fn bring_back(&mut self, n: usize, ctx: &mut ActorCtx) -> bool {
        let a = &self.list[n];
        let Some(i) = a.thing else { return false };
        let (kind, body, z_body) = (a.kind, a.pos, a.z);
        let thing = &ctx.level.compiled.map.things[i];
        let (spot, angle, ambush) = (thing.pos, (thing.angle / 45.0).trunc() * 45.0, thing.ambush);
        let def = &self.table.actors[kind];
        let (radius, height, ceiling) = (def.radius, def.height, def.has(ActorFlag::SpawnCeiling));
        let ground = Ground { compiled: &ctx.level.compiled, blockmap: ctx.blockmap };
        let Ok(o) = ground.opening(ctx.query, spot, radius, false) else { return false };
        if o.ceiling - o.floor < height {
            return false;
        }
        let taken = !self.overlapping(spot, radius, ActorFlag::Solid, None).is_empty();
        let p = &ctx.player;
        let on_player =
            (p.pos.x - spot.x).abs() < PLAYER_RADIUS + radius && (p.pos.y - spot.y).abs() < PLAYER_RADIUS + radius;
        if taken || (on_player && !p.dead()) {
            return false;
        }
        let z = if ceiling { o.ceiling - height } else { o.floor };
        let Some(k) = self.spawn(kind, spot, z, angle, ctx) else { return false };
        let b = &mut self.list[k];
        b.thing = Some(i);
        b.reaction_time = 18;
        if ambush {
            b.flags.set(ActorFlag::Ambush, true);
        }
        if let Some(fog) = self.table.index("teleport_fog") {
            self.spawn(fog, body, z_body, 0.0, ctx);
            self.spawn(fog, spot, o.floor, 0.0, ctx);
        }
        ctx.events.push(Event::Sound { sound: "telept", origin: Origin::At(body) });
        ctx.events.push(Event::Sound { sound: "telept", origin: Origin::At(spot) });
        self.remove(n);
        true
    }

    /// Wakes every monster that is waiting for the player (in a state
    /// whose action is `A_Look`): it takes the player as its target and
    /// goes to its `See` state, as if it had seen it (for benchmarks and
    /// stress tests: every monster of a map awake at once).
    pub fn wake_all(&mut self, ctx: &mut ActorCtx) {
        let Some(look) = crate::actors::actions::find("A_Look") else { return };
        for n in 0..self.list.len() {
            let a = &self.list[n];
            let waiting = self.table.state(a.state).action.as_ref().is_some_and(|c| c.action == look);
            let see = self.table.actors[a.kind].label("See");
            if a.removed || !waiting || see.is_none() {
                continue;
            }
            self.list[n].target = Target::Player;
            self.set_state(n, see, ctx);
        }
    }

    /// The player made a noise in `sector` (a shot: Doom's P_NoiseAlert):
    /// it floods through every open two-sided line, and crosses at most one
    /// line that blocks sound; every sector it reaches remembers, for the
    /// rest of the level, that the player was heard there.
    pub fn noise_alert(&mut self, level: &crate::level::Level, sector: usize) {
        let map = &level.compiled.map;
        self.heard.resize(map.sectors.len(), false);
        // Per sector, the fewest sound-blocking lines crossed to reach it
        // (Doom visits a sector again only with fewer).
        let mut best = vec![u8::MAX; map.sectors.len()];
        let mut todo = vec![(sector, 0u8)];
        while let Some((s, blocks)) = todo.pop() {
            if best[s] <= blocks {
                continue;
            }
            best[s] = blocks;
            self.heard[s] = true;
            for &i in &level.sector_lines[s] {
                let line = &map.lines[i as usize];
                let Some(back) = &line.back else { continue };
                let other = if line.front.sector == s { back.sector } else { line.front.sector };
                let (f, b) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
                if f.ceiling.min(b.ceiling) <= f.floor.max(b.floor) {
                    continue; // a closed door
                }
                match (line.flags.block_sound, blocks) {
                    (false, _) => todo.push((other, blocks)),
                    (true, 0) => todo.push((other, 1)),
                    (true, _) => {}
                }
            }
        }
    }
}
