//! The arch-vile (`p_enemy.c`): raising corpses met on its way
//! (`A_VileChase` with `PIT_VileCheck` over the blockmap) and its fire
//! attack (`A_VileTarget` puts a fire on the target, `A_Fire` keeps it in
//! front of the target, `A_VileAttack` hurts and blasts). Hands on state
//! changes and damage through `interaction.rs` and `collision.rs`.

use super::chase::step;
use super::info::mt;
use super::level::{MAPBLOCKSHIFT, MAXRADIUS};
use super::mobj::mf;
use super::monsters::{actor_arg, chase_target, face_target};
use super::{collision, interaction, maputl, sight, MobjId, Sim};
use crate::actors::ActionCall;
use crate::fixed::{Fixed, FRACUNIT};

/// Runs the arch-vile's action `name`.
pub fn action(sim: &mut Sim, id: MobjId, name: &str, call: &ActionCall) {
    match name {
        "A_VileChase" => vile_chase(sim, id),
        "A_VileStart" => sim.sound_named(Some(id), "vilatk"),
        "A_VileTarget" => vile_target(sim, id, call),
        "A_VileAttack" => vile_attack(sim, id),
        "A_StartFire" => {
            sim.sound_named(Some(id), "flamst");
            fire(sim, id);
        }
        "A_FireCrackle" => {
            sim.sound_named(Some(id), "flame");
            fire(sim, id);
        }
        "A_Fire" => fire(sim, id),
        _ => {}
    }
}

/// `PIT_VileCheck`: whether `thing` is a corpse at rest with a raise
/// state, touching the spot (`tryx`, `tryy`), that would fit there at four
/// times its dead height. Zeroes its momentum on the way, as Doom does,
/// even when it does not fit.
fn vile_check(sim: &mut Sim, thing: MobjId, tryx: Fixed, tryy: Fixed) -> bool {
    let t = sim.mo(thing);
    if !t.has(mf::CORPSE) || t.tics != -1 {
        return false;
    }
    let info = &sim.info.things[t.kind];
    if info.raisestate.is_none() {
        return false;
    }
    let maxdist = info.radius.0.wrapping_add(sim.info.things[sim.kind_of(mt::VILE)].radius.0);
    if (t.x - tryx).0.wrapping_abs() > maxdist || (t.y - tryy).0.wrapping_abs() > maxdist {
        return false; // not actually touching
    }
    let (x, y) = (t.x, t.y);
    let t = sim.mo_mut(thing);
    t.momx = Fixed::ZERO;
    t.momy = Fixed::ZERO;
    t.height = t.height << 2;
    let fits = collision::check_position(sim, thing, x, y);
    let t = sim.mo_mut(thing);
    t.height = t.height >> 2;
    fits
}

/// `A_VileChase`: looks in the blockmap cells around its next step for a
/// corpse to raise; raises the first found (its heal state, the corpse's
/// raise state, full height, flags and health back) or else chases.
fn vile_chase(sim: &mut Sim, id: MobjId) {
    let actor = sim.mo(id);
    if let Ok(dir @ 0..=7) = usize::try_from(actor.movedir) {
        let speed = sim.info.things[actor.kind].speed;
        let (tryx, tryy) = step(actor.x, actor.y, speed, dir);
        let bm = &sim.level.blockmap;
        let xl = (tryx - bm.orgx - MAXRADIUS * 2).0 >> MAPBLOCKSHIFT;
        let xh = (tryx - bm.orgx + MAXRADIUS * 2).0 >> MAPBLOCKSHIFT;
        let yl = (tryy - bm.orgy - MAXRADIUS * 2).0 >> MAPBLOCKSHIFT;
        let yh = (tryy - bm.orgy + MAXRADIUS * 2).0 >> MAPBLOCKSHIFT;
        for bx in xl..=xh {
            for by in yl..=yh {
                let mut corpsehit = None;
                let none = maputl::block_things(sim, bx, by, |sim, thing| {
                    if vile_check(sim, thing, tryx, tryy) {
                        corpsehit = Some(thing);
                        return false; // got one, so stop checking
                    }
                    true
                });
                if let (false, Some(corpse)) = (none, corpsehit) {
                    raise(sim, id, corpse);
                    return;
                }
            }
        }
    }
    // Return to the normal attack.
    chase_target(sim, id);
}

/// The raising itself: the vile faces the corpse (its target kept), enters
/// Doom's `S_VILE_HEAL1` (the vile kind's `Heal` label), and the corpse
/// comes back as it spawned.
fn raise(sim: &mut Sim, id: MobjId, corpse: MobjId) {
    let temp = sim.mo(id).target;
    sim.mo_mut(id).target = Some(corpse);
    face_target(sim, id);
    sim.mo_mut(id).target = temp;
    let vile = sim.kind_of(mt::VILE);
    let heal = sim.info.table.actors.get(vile).and_then(|a| a.label("Heal"));
    if heal.is_some() {
        sim.set_mobj_state(id, heal);
    }
    sim.sound_named(Some(corpse), "slop");
    let info = &sim.info.things[sim.mo(corpse).kind];
    let (raisestate, flags, health) = (info.raisestate, info.flags, info.spawnhealth);
    sim.set_mobj_state(corpse, raisestate);
    let c = sim.mo_mut(corpse);
    c.height = c.height << 2;
    c.flags = flags;
    c.health = health;
    c.target = None;
}

/// `A_VileTarget`: a fire spawned at the target (at the target's x for
/// both x and y: Doom's typo, kept since `A_Fire` moves it at once and the
/// spawn's subsector and floor are what demos saw), linked to both.
fn vile_target(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    let Some(target) = sim.mo(id).target else { return };
    face_target(sim, id);
    let (tx, tz) = (sim.mo(target).x, sim.mo(target).z);
    let kind = actor_arg(sim, call, mt::FIRE);
    let fog = sim.spawn_mobj(tx, tx, tz, kind);
    sim.mo_mut(id).tracer = Some(fog);
    let f = sim.mo_mut(fog);
    f.target = Some(id);
    f.tracer = Some(target);
    fire(sim, fog);
}

/// `A_Fire`: the fire stays 24 units in front of its tracer while the vile
/// (its target) sees it. Doom checks sight from a dummy when the fire has
/// no vile (`P_SubstNullMobj`); such a fire stays put here.
fn fire(sim: &mut Sim, id: MobjId) {
    let Some(dest) = sim.mo(id).tracer else { return };
    let Some(target) = sim.mo(id).target else { return };
    if !sight::check_sight(sim, target, dest) {
        return; // don't move it if the vile lost sight
    }
    let d = sim.mo(dest);
    let (x, y, z) = (d.x + Fixed(24 * FRACUNIT) * d.angle.cos(), d.y + Fixed(24 * FRACUNIT) * d.angle.sin(), d.z);
    sim.unset_thing_position(id);
    let f = sim.mo_mut(id);
    f.x = x;
    f.y = y;
    f.z = z;
    sim.set_thing_position(id);
}

/// `A_VileAttack`: if the target is still in sight, 20 damage, a blast
/// upwards of 1000/mass units a tic, and the fire, moved between the two
/// (not relinked, as Doom), explodes for 70.
fn vile_attack(sim: &mut Sim, id: MobjId) {
    let Some(target) = sim.mo(id).target else { return };
    face_target(sim, id);
    if !sight::check_sight(sim, id, target) {
        return;
    }
    sim.sound_named(Some(id), "barexp");
    interaction::damage_mobj(sim, target, Some(id), Some(id), 20);
    // A plain int division; Doom would fault on a massless target.
    let mass = sim.info.things[sim.mo(target).kind].mass;
    if let Some(momz) = (1000 * FRACUNIT).checked_div(mass) {
        sim.mo_mut(target).momz = Fixed(momz);
    }
    let angle = sim.mo(id).angle;
    let Some(fire) = sim.mo(id).tracer else { return };
    let (tx, ty) = (sim.mo(target).x, sim.mo(target).y);
    let f = sim.mo_mut(fire);
    f.x = tx - Fixed(24 * FRACUNIT) * angle.cos();
    f.y = ty - Fixed(24 * FRACUNIT) * angle.sin();
    collision::radius_attack(sim, fire, Some(id), 70);
}
