//! The player's weapons (Doom's p_pspr.c, written anew): each weapon is an
//! actor of the table whose `Ready`, `Deselect`, `Select`, `Fire` and
//! `Flash` states run on the screen rather than in the world, on two layers
//! ([`Player::psprites`]): the weapon and its flash. Their actions
//! (`A_WeaponReady`, `A_FirePistol`, ...) are bound here, as the monsters'
//! are in `actors/actions.rs`.
//!
//! A tick: the weapon asked for by number becomes the pending one (the
//! number picks the first weapon owned in that slot, or the next after the
//! one in hand); then both layers' timers run, and states whose time is up
//! give way to the next, running their actions. `A_WeaponReady` bobs the
//! weapon, lowers it for a pending change, or fires; firing checks the
//! ammunition and, short of it, changes to the best weapon that has some.

use glam::DVec2;

use super::actors::attacks::AIM_SIDE;
use super::actors::{monsters::spread, ActorCtx, Actors, Target};
use super::player::{Player, FLASH_LAYER, WEAPON_LAYER};
use super::sight::{Ray, MELEE_RANGE};
use super::SHOT_RANGE;
use crate::actors::actions::REGISTRY;
use crate::actors::{ActorTable, Arg, Power, StateId};
use crate::play::events::{Event, Origin};
use crate::play::pickups::power_slot;

/// Where a raised weapon's origin sits (Doom's WEAPONTOP), and a lowered one's (WEAPONBOTTOM).
pub const WEAPON_TOP: f64 = 32.0;
pub const WEAPON_BOTTOM: f64 = 128.0;
/// How fast a weapon goes down and up (Doom's LOWERSPEED, RAISESPEED).
const SWAP_SPEED: f64 = 6.0;
/// The largest bob (Doom's MAXBOB, 16 units).
const MAX_BOB: f64 = 16.0;

type WeaponFn = fn(&mut Actors, usize, &[Arg], &mut ActorCtx);

/// The function of a weapon action, by name.
fn function(name: &str) -> Option<WeaponFn> {
    let f: WeaponFn = match name {
        "A_WeaponReady" => weapon_ready,
        "A_Lower" => lower,
        "A_Raise" => raise,
        "A_ReFire" => refire,
        "A_GunFlash" => gun_flash,
        "A_Light0" => |_, _, _, ctx| ctx.player.extra_light = 0,
        "A_Light1" => |_, _, _, ctx| ctx.player.extra_light = 1,
        "A_Light2" => |_, _, _, ctx| ctx.player.extra_light = 2,
        "A_Punch" => punch,
        "A_Saw" => saw,
        "A_FirePistol" => fire_pistol,
        "A_FireShotgun" => fire_shotgun,
        "A_FireShotgun2" => fire_shotgun2,
        "A_CheckReload" => |actors, _, _, ctx| {
            check_ammo(actors, ctx);
        },
        "A_OpenShotgun2" => |_, _, _, ctx| sound(ctx, "dbopn"),
        "A_LoadShotgun2" => |_, _, _, ctx| sound(ctx, "dbload"),
        "A_CloseShotgun2" => |actors, layer, args, ctx| {
            sound(ctx, "dbcls");
            refire(actors, layer, args, ctx);
        },
        "A_FireCGun" => fire_cgun,
        "A_FireMissile" => fire_missile,
        "A_FirePlasma" => fire_plasma,
        "A_BFGsound" => |_, _, _, ctx| sound(ctx, "bfg"),
        "A_FireBFG" => fire_missile,
        _ => return None,
    };
    Some(f)
}

/// The weapon actions of the registry, bound once.
fn bound() -> &'static [Option<WeaponFn>] {
    static BOUND: std::sync::OnceLock<Vec<Option<WeaponFn>>> = std::sync::OnceLock::new();
    BOUND.get_or_init(|| REGISTRY.iter().map(|a| function(a.name)).collect())
}

fn sound(ctx: &mut ActorCtx, name: &'static str) {
    ctx.events.push(Event::Sound { sound: name, origin: Origin::Player });
}

/// The player's start: the fist and the pistol owned, the pistol raised.
pub fn arm(actors: &Actors, player: &mut Player) {
    for name in ["fist", "pistol"] {
        if let Some(w) = actors.table.index(name) {
            if !player.weapons.contains(&w) {
                player.weapons.push(w);
            }
        }
    }
    player.ready_weapon = actors.table.index("pistol").or(player.weapons.first().copied());
    player.pending_weapon = None;
    player.psprites = Default::default();
    player.psprites[WEAPON_LAYER].sx = 1.0;
    player.psprites[WEAPON_LAYER].sy = WEAPON_BOTTOM;
    if let Some(w) = player.ready_weapon {
        player.psprites[WEAPON_LAYER].state = actors.table.actors[w].label("Select");
    }
}

/// The weapon that number key `slot` asks for: the first owned in that
/// slot, or the one after the weapon in hand if it is in that slot.
pub fn choose(actors: &Actors, player: &Player, slot: u8) -> Option<usize> {
    let owned: Vec<usize> = actors
        .table
        .actors
        .iter()
        .enumerate()
        .filter(|(i, d)| d.weapon.as_ref().is_some_and(|w| w.slot == slot) && player.weapons.contains(i))
        .map(|(i, _)| i)
        .collect();
    let at = player.ready_weapon.and_then(|r| owned.iter().position(|&w| w == r));
    match at {
        Some(k) => owned.get(k + 1).or(owned.first()).copied(),
        None => owned.first().copied(),
    }
    .filter(|&w| Some(w) != player.ready_weapon)
}

/// One tick of the weapon: a change asked for by `slot` (0: none), then
/// the layers' states.
pub fn tick(actors: &mut Actors, slot: u8, ctx: &mut ActorCtx) {
    if slot != 0 && !ctx.player.dead() {
        if let Some(w) = choose(actors, ctx.player, slot) {
            ctx.player.pending_weapon = Some(w);
        }
    }
    if ctx.player.ready_weapon.is_none() {
        return;
    }
    // A weapon whose state was never entered (the game's start) is raised.
    if ctx.player.psprites[WEAPON_LAYER].tics == 0 {
        if let Some(s) = ctx.player.psprites[WEAPON_LAYER].state {
            set_layer(actors, WEAPON_LAYER, Some(s), ctx);
        }
    }
    for layer in [WEAPON_LAYER, FLASH_LAYER] {
        let p = &mut ctx.player.psprites[layer];
        let Some(state) = p.state else { continue };
        if p.tics < 0 {
            continue;
        }
        p.tics -= 1;
        if p.tics <= 0 {
            let next = actors.table.state(state).next;
            set_layer(actors, layer, next, ctx);
        }
    }
    let p = &mut ctx.player;
    p.psprites[FLASH_LAYER].sx = p.psprites[WEAPON_LAYER].sx;
    p.psprites[FLASH_LAYER].sy = p.psprites[WEAPON_LAYER].sy;
}

/// Puts `layer` into `state` and runs its action; 0-tic states give way
/// at once (Doom's P_SetPsprite).
fn set_layer(actors: &mut Actors, layer: usize, state: Option<StateId>, ctx: &mut ActorCtx) {
    let mut at = state;
    for _ in 0..64 {
        let Some(s) = at else {
            ctx.player.psprites[layer].state = None;
            return;
        };
        let st = actors.table.state(s);
        let (tics, next, action) = (st.tics, st.next, st.action.clone());
        let p = &mut ctx.player.psprites[layer];
        p.state = Some(s);
        p.tics = tics;
        if let Some(call) = action {
            if let Some(run) = bound()[usize::from(call.action.0)] {
                run(actors, layer, &call.args, ctx);
            }
        }
        let p = &ctx.player.psprites[layer];
        if p.state != Some(s) || p.tics != 0 {
            return;
        }
        at = next;
    }
}

/// The weapon in hand's label `name`.
fn label(actors: &Actors, ctx: &ActorCtx, name: &str) -> Option<StateId> {
    actors.table.actors[ctx.player.ready_weapon?].label(name)
}

/// The ammunition `weapon` uses (its index in the player's arrays), and
/// how much a shot takes.
pub fn ammo_of(table: &ActorTable, weapon: usize) -> Option<(usize, i32)> {
    let w = table.actors.get(weapon)?.weapon.as_ref()?;
    Some((w.ammo?.index(), w.ammo_use.max(1)))
}

fn use_ammo(actors: &Actors, ctx: &mut ActorCtx) {
    if let Some((k, n)) = ctx.player.ready_weapon.and_then(|w| ammo_of(&actors.table, w)) {
        ctx.player.ammo[k] = (ctx.player.ammo[k] - n).max(0);
    }
}

/// Enough ammunition for a shot? If not, the best weapon that has some
/// becomes pending (Doom's P_CheckAmmo order: plasma, super shotgun,
/// chaingun, shotgun, pistol, chainsaw, rockets, BFG, fist) and the weapon
/// goes down.
fn check_ammo(actors: &mut Actors, ctx: &mut ActorCtx) -> bool {
    let Some(ready) = ctx.player.ready_weapon else { return false };
    let enough = |w: usize, p: &Player| ammo_of(&actors.table, w).is_none_or(|(k, n)| p.ammo[k] >= n);
    if enough(ready, ctx.player) {
        return true;
    }
    let order = [
        "plasma_rifle",
        "super_shotgun",
        "chaingun",
        "shotgun",
        "pistol",
        "chainsaw",
        "rocket_launcher",
        "bfg9000",
        "fist",
    ];
    let best = order
        .iter()
        .filter_map(|n| actors.table.index(n))
        .find(|&w| ctx.player.weapons.contains(&w) && enough(w, ctx.player));
    ctx.player.pending_weapon = best;
    let deselect = label(actors, ctx, "Deselect");
    set_layer(actors, WEAPON_LAYER, deselect, ctx);
    false
}

/// Fires the weapon in hand (Doom's P_FireWeapon): its fire states, and
/// the noise wakes the monsters that hear it.
fn fire_weapon(actors: &mut Actors, ctx: &mut ActorCtx) {
    if !check_ammo(actors, ctx) {
        return;
    }
    let fire = label(actors, ctx, "Fire");
    set_layer(actors, WEAPON_LAYER, fire, ctx);
    actors.noise_alert(ctx.level, ctx.player.sector);
}

/// A_WeaponReady: lower for a change or at death; fire on the trigger;
/// else bob with the body's speed.
fn weapon_ready(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    if ctx.player.ready_weapon.is_some_and(|w| actors.table.actors[w].name == "chainsaw")
        && ctx.player.psprites[WEAPON_LAYER].state == label(actors, ctx, "Ready")
    {
        sound(ctx, "sawidl");
    }
    if ctx.player.pending_weapon.is_some() || ctx.player.dead() {
        let deselect = label(actors, ctx, "Deselect");
        set_layer(actors, WEAPON_LAYER, deselect, ctx);
        return;
    }
    let ready = ctx.player.ready_weapon.map(|w| actors.table.actors[w].name.as_str());
    let needs_press = matches!(ready, Some("rocket_launcher" | "bfg9000"));
    if ctx.player.fire_held && (!ctx.player.attack_down || !needs_press) {
        ctx.player.attack_down = true;
        fire_weapon(actors, ctx);
        return;
    }
    ctx.player.attack_down = ctx.player.fire_held;
    bob(ctx.player, ctx.level.time);
}

/// The weapon sways with the body's speed: a figure of eight (Doom's
/// `128 * leveltime` fine angle).
pub fn bob(p: &mut Player, time: u64) {
    let amount = (p.velocity.length_squared() / 4.0).min(MAX_BOB);
    let angle = (128 * time % 8192) as f64 / 8192.0 * std::f64::consts::TAU;
    let w = &mut p.psprites[WEAPON_LAYER];
    w.sx = 1.0 + amount * angle.cos();
    w.sy = WEAPON_TOP + amount * (angle % std::f64::consts::PI).sin();
}

/// A_Lower: down; at the bottom the pending weapon comes up (a dead
/// player's weapon stays down).
fn lower(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let dead = ctx.player.dead();
    let w = &mut ctx.player.psprites[WEAPON_LAYER];
    w.sy += SWAP_SPEED;
    if w.sy < WEAPON_BOTTOM {
        return;
    }
    if dead {
        w.sy = WEAPON_BOTTOM;
        return;
    }
    if let Some(p) = ctx.player.pending_weapon.take() {
        ctx.player.ready_weapon = Some(p);
    }
    let w = &mut ctx.player.psprites[WEAPON_LAYER];
    w.sy = WEAPON_BOTTOM;
    if ctx.player.ready_weapon.is_some_and(|w| actors.table.actors[w].name == "chainsaw") {
        sound(ctx, "sawup");
    }
    let select = label(actors, ctx, "Select");
    set_layer(actors, WEAPON_LAYER, select, ctx);
}

/// A_Raise: up; at the top, ready.
fn raise(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let w = &mut ctx.player.psprites[WEAPON_LAYER];
    w.sy -= SWAP_SPEED;
    if w.sy > WEAPON_TOP {
        return;
    }
    w.sy = WEAPON_TOP;
    let ready = label(actors, ctx, "Ready");
    set_layer(actors, WEAPON_LAYER, ready, ctx);
}

/// A_ReFire: fire again while the trigger is held (not while changing or dead).
fn refire(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let p = &mut ctx.player;
    if p.fire_held && p.pending_weapon.is_none() && !p.dead() {
        p.refire += 1;
        fire_weapon(actors, ctx);
    } else {
        p.refire = 0;
        check_ammo(actors, ctx);
    }
}

fn gun_flash(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let flash = label(actors, ctx, "Flash");
    set_layer(actors, FLASH_LAYER, flash, ctx);
}

/// The slope auto-aim gives a shot along the player's view (Doom's
/// P_BulletSlope: straight ahead, then a little to either side).
fn bullet_slope(actors: &mut Actors, range: f64, ctx: &mut ActorCtx) -> (f64, Target) {
    let p = &ctx.player;
    let ray = Ray { origin: p.pos, z: p.z + super::SHOT_HEIGHT, angle: p.angle, range, shooter: None };
    let mut aimed = actors.aim(&ray, ctx);
    for side in [AIM_SIDE, -AIM_SIDE] {
        if aimed.1 == Target::None {
            aimed = actors.aim(&Ray { angle: ray.angle + side, ..ray }, ctx);
        }
    }
    aimed
}

/// One bullet (Doom's P_GunShot): 5, 10 or 15, spread unless accurate.
fn gun_shot(actors: &mut Actors, slope: f64, accurate: bool, ctx: &mut ActorCtx) {
    let damage = 5 * (i32::from(ctx.rng.byte()) % 3 + 1);
    let mut angle = ctx.player.angle;
    if !accurate {
        angle += spread(ctx, 18);
    }
    shot(actors, angle, SHOT_RANGE, slope, damage, ctx);
}

fn shot(actors: &mut Actors, angle: f64, range: f64, slope: f64, damage: i32, ctx: &mut ActorCtx) -> Option<Target> {
    let p = &ctx.player;
    let ray = Ray { origin: p.pos, z: p.z + super::SHOT_HEIGHT, angle, range, shooter: None };
    actors.line_attack(Target::Player, &ray, slope, damage, ctx)
}

/// How far a gun's bullets look for something to aim at (Doom's 16 * 64).
const BULLET_AIM: f64 = 16.0 * 64.0;

/// What every gun does as it fires: its sound, one round used, its flash,
/// and the slope its bullets take (auto-aimed).
fn open_fire(actors: &mut Actors, noise: &'static str, ctx: &mut ActorCtx) -> f64 {
    sound(ctx, noise);
    use_ammo(actors, ctx);
    gun_flash(actors, FLASH_LAYER, &[], ctx);
    bullet_slope(actors, BULLET_AIM, ctx).0
}

fn fire_pistol(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let slope = open_fire(actors, "pistol", ctx);
    let accurate = ctx.player.refire == 0;
    gun_shot(actors, slope, accurate, ctx);
}

fn fire_shotgun(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let slope = open_fire(actors, "shotgn", ctx);
    for _ in 0..7 {
        gun_shot(actors, slope, false, ctx);
    }
}

/// The super shotgun: twenty pellets spread in both directions.
fn fire_shotgun2(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let slope = open_fire(actors, "dshtgn", ctx);
    for _ in 0..20 {
        let damage = 5 * (i32::from(ctx.rng.byte()) % 3 + 1);
        let angle = ctx.player.angle + spread(ctx, 19);
        let tilt = (f64::from(ctx.rng.byte()) - f64::from(ctx.rng.byte())) / 2048.0;
        shot(actors, angle, SHOT_RANGE, slope + tilt, damage, ctx);
    }
}

/// The chaingun: its flash follows the barrel (the second fire frame shows
/// the second flash).
fn fire_cgun(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    if !check_ammo(actors, ctx) {
        return;
    }
    sound(ctx, "pistol");
    use_ammo(actors, ctx);
    let (fire, flash) = (label(actors, ctx, "Fire"), label(actors, ctx, "Flash"));
    let at = ctx.player.psprites[WEAPON_LAYER].state;
    let offset = match (fire, at) {
        (Some(f), Some(s)) if s.0 >= f.0 && s.0 - f.0 < 2 => s.0 - f.0,
        _ => 0,
    };
    set_layer(actors, FLASH_LAYER, flash.map(|f| StateId(f.0 + offset)), ctx);
    let (slope, _) = bullet_slope(actors, BULLET_AIM, ctx);
    let accurate = ctx.player.refire == 0;
    gun_shot(actors, slope, accurate, ctx);
}

/// The fist: 2 to 20, ten times that with berserk; turns the player to
/// what it hits.
fn punch(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let mut damage = (i32::from(ctx.rng.byte()) % 10 + 1) * 2;
    if ctx.player.powers[power_slot(Power::Strength)] > 0 {
        damage *= 10;
    }
    let angle = ctx.player.angle + spread(ctx, 18);
    melee(actors, angle, damage, "punch", None, ctx);
}

/// The chainsaw: 2 to 20, and it pulls the player round to its victim.
fn saw(actors: &mut Actors, _: usize, _: &[Arg], ctx: &mut ActorCtx) {
    let damage = 2 * (i32::from(ctx.rng.byte()) % 10 + 1);
    let angle = ctx.player.angle + spread(ctx, 18);
    melee(actors, angle, damage, "sawhit", Some("sawful"), ctx);
}

fn melee(
    actors: &mut Actors,
    angle: f64,
    damage: i32,
    hit: &'static str,
    miss: Option<&'static str>,
    ctx: &mut ActorCtx,
) {
    let p = &ctx.player;
    let range = MELEE_RANGE + 1.0;
    let ray = Ray { origin: p.pos, z: p.z + super::SHOT_HEIGHT, angle, range, shooter: None };
    let (slope, _) = actors.aim(&ray, ctx);
    match shot(actors, angle, range, slope, damage, ctx) {
        Some(t) => {
            sound(ctx, hit);
            if let Some(b) = actors.body_of(t, ctx) {
                let d: DVec2 = b.pos - ctx.player.pos;
                ctx.player.angle = d.y.atan2(d.x).to_degrees().rem_euclid(360.0);
            }
        }
        None => {
            if let Some(m) = miss {
                sound(ctx, m);
            }
        }
    }
}

fn fire_missile(actors: &mut Actors, _: usize, args: &[Arg], ctx: &mut ActorCtx) {
    use_ammo(actors, ctx);
    if let Some(kind) = super::actors::actions::actor(args, 0) {
        actors.player_missile(kind, ctx);
    }
}

/// The plasma rifle: one of its two flashes at random.
fn fire_plasma(actors: &mut Actors, layer: usize, args: &[Arg], ctx: &mut ActorCtx) {
    let flash = label(actors, ctx, "Flash").map(|f| StateId(f.0 + u32::from(ctx.rng.byte() & 1)));
    set_layer(actors, FLASH_LAYER, flash, ctx);
    fire_missile(actors, layer, args, ctx);
}
