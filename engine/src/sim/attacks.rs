//! Monster attacks (`p_enemy.c`): the hitscan shooters (`A_PosAttack`,
//! `A_SPosAttack`, `A_CPosAttack` and the refire checks), claws and bites
//! that hurt directly, missiles (`P_SpawnMissile` through `movement.rs`),
//! the revenant's homing missile (`A_Tracer`), the mancubus' spreads, the
//! lost soul's charge and the pain elemental's skulls. Each spends
//! `P_Random` in Doom's order; shots go to `collision.rs`, damage to
//! `interaction.rs`.

use super::info::mt;
use super::mobj::mf;
use super::monsters::{actor_arg, check_melee_range, face_target, fall, MISSILERANGE};
use super::{collision, interaction, movement, sight, MobjId, Sim};
use crate::actors::ActionCall;
use crate::fixed::{approx_distance, point_to_angle2, Angle, Fixed, ANG180, ANG270, ANG90, FRACUNIT};

/// Runs the attack action `name` (any other name does nothing).
pub fn action(sim: &mut Sim, id: MobjId, name: &str, call: &ActionCall) {
    match name {
        "A_PosAttack" => pos_attack(sim, id),
        "A_SPosAttack" => shotgun_attack(sim, id, 3),
        "A_CPosAttack" => shotgun_attack(sim, id, 1),
        "A_CPosRefire" => refire(sim, id, 40),
        "A_SpidRefire" => refire(sim, id, 10),
        "A_TroopAttack" => melee_or_missile(sim, id, call, mt::TROOPSHOT, Some(("claw", 8, 3))),
        "A_HeadAttack" => melee_or_missile(sim, id, call, mt::HEADSHOT, Some(("", 6, 10))),
        "A_BruisAttack" => bruiser_attack(sim, id, call),
        "A_SargAttack" => sarg_attack(sim, id),
        "A_BspiAttack" => missile_attack(sim, id, call, mt::ARACHPLAZ),
        "A_CyberAttack" => missile_attack(sim, id, call, mt::ROCKET),
        "A_SkelMissile" => skel_missile(sim, id, call),
        "A_Tracer" => tracer(sim, id, call),
        "A_SkelWhoosh" if sim.mo(id).target.is_some() => {
            face_target(sim, id);
            sim.sound_named(Some(id), "skeswg");
        }
        "A_SkelFist" => skel_fist(sim, id),
        "A_FatRaise" => {
            face_target(sim, id);
            sim.sound_named(Some(id), "manatk");
        }
        "A_FatAttack1" => fat_attack(sim, id, call, FatSpread::Left),
        "A_FatAttack2" => fat_attack(sim, id, call, FatSpread::Right),
        "A_FatAttack3" => fat_attack(sim, id, call, FatSpread::Both),
        "A_SkullAttack" => skull_attack(sim, id),
        "A_PainAttack" if sim.mo(id).target.is_some() => {
            face_target(sim, id);
            let angle = sim.mo(id).angle;
            pain_shoot_skull(sim, id, angle, actor_arg(sim, call, mt::SKULL));
        }
        "A_PainDie" => {
            fall(sim, id);
            let skull = actor_arg(sim, call, mt::SKULL);
            for turn in [ANG90, ANG180, ANG270] {
                let angle = sim.mo(id).angle + turn;
                pain_shoot_skull(sim, id, angle, skull);
            }
        }
        _ => {}
    }
}

/// An angle plus Doom's `P_SubRandom() << shift` spread (int arithmetic
/// that wraps as the angle's unsigned add does).
fn spread(sim: &mut Sim, angle: Angle, shift: u32) -> Angle {
    let r = sim.rng.p_subrandom();
    Angle(angle.0.wrapping_add(r.wrapping_shl(shift) as u32))
}

/// `A_PosAttack`: the zombieman's one bullet; the sound comes after the
/// aim, unlike the shotgun's.
fn pos_attack(sim: &mut Sim, id: MobjId) {
    if sim.mo(id).target.is_none() {
        return;
    }
    face_target(sim, id);
    let angle = sim.mo(id).angle;
    let slope = collision::aim_line_attack(sim, id, angle, MISSILERANGE);
    sim.sound_named(Some(id), "pistol");
    let angle = spread(sim, angle, 20);
    let damage = (sim.p_random() % 5 + 1) * 3;
    collision::line_attack(sim, id, angle, MISSILERANGE, slope, damage);
}

/// `A_SPosAttack` (three pellets) and `A_CPosAttack` (one): the sound,
/// the aim, then each pellet's spread and damage.
fn shotgun_attack(sim: &mut Sim, id: MobjId, pellets: usize) {
    if sim.mo(id).target.is_none() {
        return;
    }
    sim.sound_named(Some(id), "shotgn");
    face_target(sim, id);
    let bangle = sim.mo(id).angle;
    let slope = collision::aim_line_attack(sim, id, bangle, MISSILERANGE);
    for _ in 0..pellets {
        let angle = spread(sim, bangle, 20);
        let damage = (sim.p_random() % 5 + 1) * 3;
        collision::line_attack(sim, id, angle, MISSILERANGE, slope, damage);
    }
}

/// `A_CPosRefire` and `A_SpidRefire`: keep firing unless a `P_Random` below
/// `keep` says so, or the target is dead or out of sight.
fn refire(sim: &mut Sim, id: MobjId, keep: i32) {
    face_target(sim, id);
    if sim.p_random() < keep {
        return;
    }
    let go_on = match sim.mo(id).target {
        Some(t) => sim.mo(t).health > 0 && sight::check_sight(sim, id, t),
        None => false,
    };
    if !go_on {
        let see = sim.info.things[sim.mo(id).kind].seestate;
        sim.set_mobj_state(id, see);
    }
}

/// The imp's and cacodemon's attack: in melee range a hit of
/// `(P_Random() % sides + 1) * times` (with `sound`, if any), else a
/// missile of the action's kind (Doom's `missile` by default).
fn melee_or_missile(sim: &mut Sim, id: MobjId, call: &ActionCall, missile: usize, melee: Option<(&str, i32, i32)>) {
    let Some(target) = sim.mo(id).target else { return };
    face_target(sim, id);
    if let Some((sound, sides, times)) = melee {
        if check_melee_range(sim, id) {
            if !sound.is_empty() {
                sim.sound_named(Some(id), sound);
            }
            let damage = (sim.p_random() % sides + 1) * times;
            interaction::damage_mobj(sim, target, Some(id), Some(id), damage);
            return;
        }
    }
    let kind = actor_arg(sim, call, missile);
    movement::spawn_missile(sim, id, target, kind);
}

/// `A_BruisAttack`: as the imp's, but without turning to the target first.
fn bruiser_attack(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    let Some(target) = sim.mo(id).target else { return };
    if check_melee_range(sim, id) {
        sim.sound_named(Some(id), "claw");
        let damage = (sim.p_random() % 8 + 1) * 10;
        interaction::damage_mobj(sim, target, Some(id), Some(id), damage);
        return;
    }
    let kind = actor_arg(sim, call, mt::BRUISERSHOT);
    movement::spawn_missile(sim, id, target, kind);
}

/// `A_SargAttack`: the demon's bite, only in melee range (Doom 1.5 on; 1.2
/// fired a short hitscan instead).
fn sarg_attack(sim: &mut Sim, id: MobjId) {
    let Some(target) = sim.mo(id).target else { return };
    face_target(sim, id);
    if !check_melee_range(sim, id) {
        return;
    }
    let damage = (sim.p_random() % 10 + 1) * 4;
    interaction::damage_mobj(sim, target, Some(id), Some(id), damage);
}

/// `A_BspiAttack`, `A_CyberAttack`: face and fire.
fn missile_attack(sim: &mut Sim, id: MobjId, call: &ActionCall, missile: usize) {
    let Some(target) = sim.mo(id).target else { return };
    face_target(sim, id);
    let kind = actor_arg(sim, call, missile);
    movement::spawn_missile(sim, id, target, kind);
}

/// `A_SkelFist`: the revenant's punch, `(P_Random() % 10 + 1) * 6`.
fn skel_fist(sim: &mut Sim, id: MobjId) {
    let Some(target) = sim.mo(id).target else { return };
    face_target(sim, id);
    if check_melee_range(sim, id) {
        let damage = (sim.p_random() % 10 + 1) * 6;
        sim.sound_named(Some(id), "skepch");
        interaction::damage_mobj(sim, target, Some(id), Some(id), damage);
    }
}

/// `A_SkelMissile`: a homing missile spawned 16 units higher, moved one
/// tic ahead at once (without relinking, as Doom), homing on the target.
fn skel_missile(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    let Some(target) = sim.mo(id).target else { return };
    face_target(sim, id);
    let kind = actor_arg(sim, call, mt::TRACER);
    sim.mo_mut(id).z += Fixed(16 * FRACUNIT); // so the missile spawns higher
    let missile = movement::spawn_missile(sim, id, target, kind);
    sim.mo_mut(id).z -= Fixed(16 * FRACUNIT);
    if let Some(mo) = missile {
        let mo = sim.mo_mut(mo);
        mo.x += mo.momx;
        mo.y += mo.momy;
        mo.tracer = Some(target);
    }
}

/// `TRACEANGLE`: how far a homing missile turns in one of its steps.
const TRACEANGLE: u32 = 0xc00_0000;

/// `A_Tracer`: every fourth game tic (`gametic & 3`, so demos depend on the
/// tic count) a puff and a smoke trail, then a turn towards the tracer's
/// target and a climb or dive of 1/8 unit a tic towards its chest.
fn tracer(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    if sim.gametic & 3 != 0 {
        return;
    }
    let (x, y, z, momx, momy) = {
        let a = sim.mo(id);
        (a.x, a.y, a.z, a.momx, a.momy)
    };
    movement::spawn_puff(sim, x, y, z);
    let smoke = actor_arg(sim, call, mt::SMOKE);
    let th = sim.spawn_mobj(x - momx, y - momy, z, smoke);
    let r = sim.p_random() & 3;
    let th = sim.mo_mut(th);
    th.momz = Fixed(FRACUNIT);
    th.tics = (th.tics - r).max(1);
    // Adjust the direction.
    let Some(dest) = sim.mo(id).tracer else { return };
    if sim.mo(dest).health <= 0 {
        return;
    }
    let (dx, dy, dz) = (sim.mo(dest).x, sim.mo(dest).y, sim.mo(dest).z);
    let speed = sim.info.things[sim.mo(id).kind].speed;
    let actor = sim.mo_mut(id);
    let exact = point_to_angle2(actor.x, actor.y, dx, dy);
    if exact != actor.angle {
        if exact.0.wrapping_sub(actor.angle.0) > 0x8000_0000 {
            actor.angle.0 = actor.angle.0.wrapping_sub(TRACEANGLE);
            if exact.0.wrapping_sub(actor.angle.0) < 0x8000_0000 {
                actor.angle = exact;
            }
        } else {
            actor.angle.0 = actor.angle.0.wrapping_add(TRACEANGLE);
            if exact.0.wrapping_sub(actor.angle.0) > 0x8000_0000 {
                actor.angle = exact;
            }
        }
    }
    actor.momx = Fixed(speed) * actor.angle.cos();
    actor.momy = Fixed(speed) * actor.angle.sin();
    // Change the slope: plain int divisions, as Doom's `dist / speed`.
    let dist = approx_distance(dx - actor.x, dy - actor.y).0.checked_div(speed).unwrap_or(0).max(1);
    let slope = (dz + Fixed(40 * FRACUNIT) - actor.z).0.wrapping_div(dist);
    if slope < actor.momz.0 {
        actor.momz -= Fixed(FRACUNIT / 8);
    } else {
        actor.momz += Fixed(FRACUNIT / 8);
    }
}

/// Which way `A_FatAttack1..3` turn their two fireballs.
#[derive(Clone, Copy)]
enum FatSpread {
    Left,
    Right,
    Both,
}

/// `FATSPREAD`: 11.25 degrees.
const FATSPREAD: u32 = 0x4000_0000 / 8;

/// A missile's angle turned by `turn` (wrapping), its momentum set anew
/// along it at its kind's speed.
fn turn_missile(sim: &mut Sim, mo: Option<MobjId>, turn: u32) {
    let Some(mo) = mo else { return };
    let speed = Fixed(sim.info.things[sim.mo(mo).kind].speed);
    let m = sim.mo_mut(mo);
    m.angle.0 = m.angle.0.wrapping_add(turn);
    m.momx = speed * m.angle.cos();
    m.momy = speed * m.angle.sin();
}

/// `A_FatAttack1` (the body turns left by `FATSPREAD`, the second ball a
/// further spread left), `A_FatAttack2` (right, the second ball two spreads
/// right) and `A_FatAttack3` (two balls, half a spread either side).
/// Doom fires at a dummy at the origin when there is no target
/// (`P_SubstNullMobj`); a body with no target fires nothing here.
fn fat_attack(sim: &mut Sim, id: MobjId, call: &ActionCall, how: FatSpread) {
    face_target(sim, id);
    let Some(target) = sim.mo(id).target else { return };
    let kind = actor_arg(sim, call, mt::FATSHOT);
    match how {
        FatSpread::Left | FatSpread::Right => {
            let (body, second) = match how {
                FatSpread::Left => (FATSPREAD, FATSPREAD),
                _ => (FATSPREAD.wrapping_neg(), (FATSPREAD * 2).wrapping_neg()),
            };
            let actor = sim.mo_mut(id);
            actor.angle.0 = actor.angle.0.wrapping_add(body);
            movement::spawn_missile(sim, id, target, kind);
            let mo = movement::spawn_missile(sim, id, target, kind);
            turn_missile(sim, mo, second);
        }
        FatSpread::Both => {
            let mo = movement::spawn_missile(sim, id, target, kind);
            turn_missile(sim, mo, (FATSPREAD / 2).wrapping_neg());
            let mo = movement::spawn_missile(sim, id, target, kind);
            turn_missile(sim, mo, FATSPREAD / 2);
        }
    }
}

/// `SKULLSPEED`: a lost soul's charge, 20 units a tic.
const SKULLSPEED: Fixed = Fixed(20 * FRACUNIT);

/// `A_SkullAttack`: the lost soul flies at its target like a missile,
/// aimed at the target's middle.
pub fn skull_attack(sim: &mut Sim, id: MobjId) {
    let Some(dest) = sim.mo(id).target else { return };
    sim.mo_mut(id).flags |= mf::SKULLFLY;
    let sound = sim.info.things[sim.mo(id).kind].attacksound;
    sim.sound(Some(id), sound);
    face_target(sim, id);
    let (dx, dy, dz, dh) = {
        let d = sim.mo(dest);
        (d.x, d.y, d.z, d.height)
    };
    let actor = sim.mo_mut(id);
    actor.momx = SKULLSPEED * actor.angle.cos();
    actor.momy = SKULLSPEED * actor.angle.sin();
    // Plain int divisions, as Doom's.
    let dist = (approx_distance(dx - actor.x, dy - actor.y).0 / SKULLSPEED.0).max(1);
    actor.momz = Fixed((dz + (dh >> 1) - actor.z).0.wrapping_div(dist));
}

/// `A_PainShootSkull`: unless more than 20 lost souls are about, one
/// spawned just in front along `angle` and launched at the target; one
/// that does not fit there is killed at once.
fn pain_shoot_skull(sim: &mut Sim, id: MobjId, angle: Angle, skull: usize) {
    let count = sim.live_mobjs().filter(|&m| sim.mo(m).kind == skull).count();
    if count > 20 {
        return;
    }
    let radius = sim.info.things[sim.mo(id).kind].radius.0;
    let skull_radius = sim.info.things[skull].radius.0;
    // 4 + 1.5 times the two radii: Doom's int arithmetic, divided after
    // the product.
    let prestep = Fixed(4 * FRACUNIT + 3i32.wrapping_mul(radius.wrapping_add(skull_radius)) / 2);
    let actor = sim.mo(id);
    let x = actor.x + prestep * angle.cos();
    let y = actor.y + prestep * angle.sin();
    let z = actor.z + Fixed(8 * FRACUNIT);
    let target = actor.target;
    let newmobj = sim.spawn_mobj(x, y, z, skull);
    let (nx, ny) = (sim.mo(newmobj).x, sim.mo(newmobj).y);
    if !collision::try_move(sim, newmobj, nx, ny) {
        // Kill it immediately.
        interaction::damage_mobj(sim, newmobj, Some(id), Some(id), 10000);
        return;
    }
    sim.mo_mut(newmobj).target = target;
    skull_attack(sim, newmobj);
}
