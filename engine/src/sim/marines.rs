//! ZDoom's scripted marines (`engine/data/zdoom_actors.ron`, after GZDoom's
//! `scriptedmarine.zs`): the marine's look, chase and idle chainsaw noise,
//! its punch, saw, pistol, shotguns, chaingun, rockets, plasma and BFG, and
//! its refire checks, written the way `attacks.rs` writes Doom's monsters
//! (16.16 fixed point, `P_Random` for every roll, shots through
//! `collision.rs`). ZDoom rolls its own per-action generators; we roll
//! Doom's one table, so a marine fights as ZDoom's does, not tic for tic.
//!
//! Not modelled: ZDoom's `special1` reload wait after the shotguns, the
//! plasma and the BFG (`A_M_CheckAttack` then skips the attack), which
//! needs a field on the body; the BFG marine's pain immunity while it
//! charges; the railgun.

use super::monsters::{self, check_melee_range, check_missile_range, face_target, look_for_players, MISSILERANGE};
use super::{collision, movement, sight, MobjId, Sim};
use crate::actors::{actions, ActionCall, Arg};
use crate::fixed::{point_to_angle2, Angle, Fixed, ANG90};

/// `DEFMELEERANGE`: 64 units.
const MELEERANGE: Fixed = monsters::MELEERANGE;

/// Runs the marine action `name`; false when it is not one of them.
pub fn action(sim: &mut Sim, id: MobjId, name: &str, call: &ActionCall) -> bool {
    match name {
        "A_MarineNoise" => noise(sim, id),
        "A_MarineLook" => {
            noise(sim, id);
            monsters::action(sim, id, "A_Look", call);
        }
        "A_MarineChase" => {
            noise(sim, id);
            monsters::action(sim, id, "A_Chase", call);
        }
        "A_NoBlocking" => monsters::fall(sim, id),
        "A_M_Punch" => punch(sim, id, int_arg(call, 0, 1)),
        "A_M_Saw" => saw(sim, id, call),
        "A_M_SawRefire" => saw_refire(sim, id),
        "A_M_Refire" => refire(sim, id, call),
        "A_M_CheckAttack" => check_attack(sim, id),
        "A_M_FirePistol" => fire_gun(sim, id, "pistol", int_arg(call, 0, 1) != 0),
        "A_M_FireCGun" => fire_gun(sim, id, "pistol", int_arg(call, 0, 1) != 0),
        "A_M_FireShotgun" => fire_shotgun(sim, id),
        "A_M_FireShotgun2" => fire_shotgun2(sim, id),
        "A_M_FireMissile" => fire_missile(sim, id, call),
        "A_M_FirePlasma" | "A_M_FireBFG" => {
            if let (Some(target), Some(&Arg::Actor(kind))) = (sim.mo(id).target, call.args.first()) {
                face_target(sim, id);
                movement::spawn_missile(sim, id, target, kind);
            }
        }
        "A_M_BFGSound" => {
            if sim.mo(id).target.is_some() {
                face_target(sim, id);
                sim.sound_named(Some(id), "bfg");
            }
        }
        _ => return false,
    }
    true
}

/// Argument `k` as an integer, or `default`.
fn int_arg(call: &ActionCall, k: usize, default: i32) -> i32 {
    match call.args.get(k) {
        Some(Arg::Int(v)) => *v,
        _ => default,
    }
}

/// An angle plus `P_SubRandom() << shift`: `shift` 18 spreads by up to
/// 5.625 degrees either way (ZDoom's `random2() * (5.625 / 256)`).
fn spread(sim: &mut Sim, angle: Angle, shift: u32) -> Angle {
    let r = sim.rng.p_subrandom();
    Angle(angle.0.wrapping_add(r.wrapping_shl(shift) as u32))
}

/// ZDoom's `CurrentWeapon == WEAPON_Chainsaw`: a marine whose melee is the
/// chainsaw's (its first states call `A_M_Saw`) and that has no missile
/// attack.
fn wields_chainsaw(sim: &Sim, id: MobjId) -> bool {
    let info = &sim.info.things[sim.mo(id).kind];
    if info.missilestate.is_some() {
        return false;
    }
    let mut at = info.meleestate;
    for _ in 0..2 {
        let Some(state) = at.map(|s| sim.info.state(s)) else { return false };
        if state.action.as_ref().is_some_and(|c| actions::spec(c.action).name == "A_M_Saw") {
            return true;
        }
        at = state.next;
    }
    false
}

/// `A_MarineNoise`: the chainsaw idling.
fn noise(sim: &mut Sim, id: MobjId) {
    if wields_chainsaw(sim, id) {
        sim.sound_named(Some(id), "sawidl");
    }
}

/// `A_M_Punch`: `(1d10 * 2) * multiplier` at melee range, facing whatever
/// it hit.
fn punch(sim: &mut Sim, id: MobjId, multiplier: i32) {
    if sim.mo(id).target.is_none() {
        return;
    }
    let damage = ((sim.p_random() % 10 + 1) << 1) * multiplier;
    face_target(sim, id);
    let angle = spread(sim, sim.mo(id).angle, 18);
    let slope = collision::aim_line_attack(sim, id, angle, MELEERANGE);
    collision::line_attack(sim, id, angle, MELEERANGE, slope, damage);
    if let Some(t) = sim.tm.linetarget {
        sim.sound_named(Some(id), "punch");
        let (m, t) = (sim.mo(id), sim.mo(t));
        let to = point_to_angle2(m.x, m.y, t.x, t.y);
        sim.mo_mut(id).angle = to;
    }
}

/// `A_M_Saw`: in melee range, `damage * 1d10` one unit past melee range
/// (as the player's saw, so the puff shows), then the hit sound and a turn
/// of at most 4.5 degrees towards the victim; else the saw's full sound.
/// ZDoom rolls a spread and then cuts along the body's own angle; the roll
/// is spent here too.
fn saw(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    if sim.mo(id).target.is_none() {
        return;
    }
    let sound = |k: usize| match call.args.get(k) {
        Some(Arg::Sound(s)) => s + 1,
        _ => 0,
    };
    let (full, hit) = (sound(0), sound(1));
    let damage = match int_arg(call, 2, 2) {
        0 => 2,
        d => d,
    };
    face_target(sim, id);
    if !check_melee_range(sim, id) {
        sim.sound(Some(id), full);
        return;
    }
    let damage = damage * (sim.p_random() % 10 + 1);
    let _unused = spread(sim, sim.mo(id).angle, 18);
    let angle = sim.mo(id).angle;
    let range = MELEERANGE + Fixed(1);
    let slope = collision::aim_line_attack(sim, id, angle, range);
    collision::line_attack(sim, id, angle, range, slope, damage);
    let Some(t) = sim.tm.linetarget else {
        sim.sound(Some(id), full);
        return;
    };
    sim.sound(Some(id), hit);
    let (m, t) = (sim.mo(id), sim.mo(t));
    let to = point_to_angle2(m.x, m.y, t.x, t.y);
    let step = Angle(ANG90.0 / 20);
    let snap = Angle(ANG90.0 / 21);
    let m = sim.mo_mut(id);
    // The difference as a signed angle, as ZDoom's deltaangle.
    let diff = (to - m.angle).0 as i32;
    if diff < 0 {
        if diff < -(step.0 as i32) {
            m.angle = to + snap;
        } else {
            m.angle -= step;
        }
    } else if diff > step.0 as i32 {
        m.angle = to - snap;
    } else {
        m.angle += step;
    }
}

/// `A_M_SawRefire`: back to See unless the target lives within reach.
fn saw_refire(sim: &mut Sim, id: MobjId) {
    let alive = sim.mo(id).target.is_some_and(|t| sim.mo(t).health > 0);
    if !alive || !check_melee_range(sim, id) {
        let see = sim.info.things[sim.mo(id).kind].seestate;
        sim.set_mobj_state(id, see);
    }
}

/// `A_M_Refire(ignoremissile, jumpto)`: with its target dead or gone, a
/// marine that shoots looks for another most of the time (160 in 256) and
/// keeps firing if one is in range; otherwise, or when the target is out of
/// sight (or out of reach for a melee-only marine), or on a 4-in-256 whim,
/// it jumps.
fn refire(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    let ignore_missile = int_arg(call, 0, 0) != 0;
    let jump = match call.args.get(1) {
        Some(&Arg::State(s)) => Some(s),
        _ => None,
    };
    let go = |sim: &mut Sim| {
        sim.set_mobj_state(id, jump);
    };
    let has_missile = sim.info.things[sim.mo(id).kind].missilestate.is_some();
    let target = sim.mo(id).target.filter(|&t| sim.mo(t).health > 0);
    let Some(target) = target else {
        if has_missile && sim.p_random() < 160 && look_for_players(sim, id, true) && check_missile_range(sim, id) {
            return;
        }
        return go(sim);
    };
    let out_of_reach = (ignore_missile || !has_missile) && !check_melee_range(sim, id);
    if out_of_reach || !sight::check_sight(sim, id, target) || sim.p_random() < 4 {
        go(sim);
    }
}

/// `A_M_CheckAttack`: face the target, or skip the attack without one.
fn check_attack(sim: &mut Sim, id: MobjId) {
    if sim.mo(id).target.is_some() {
        face_target(sim, id);
        return;
    }
    let skip = sim.info.table.actors[sim.mo(id).kind].label("SkipAttack");
    if skip.is_some() {
        sim.set_mobj_state(id, skip);
    }
}

/// ZDoom's `GunShot2`: one bullet of `5 * 1d3`, spread unless accurate.
fn gun_shot(sim: &mut Sim, id: MobjId, accurate: bool, slope: Fixed) {
    let damage = 5 * (sim.p_random() % 3 + 1);
    let mut angle = sim.mo(id).angle;
    if !accurate {
        angle = spread(sim, angle, 18);
    }
    collision::line_attack(sim, id, angle, MISSILERANGE, slope, damage);
}

/// `A_M_FirePistol` and `A_M_FireCGun` (Doom's chaingun sounds as its pistol).
fn fire_gun(sim: &mut Sim, id: MobjId, sound: &str, accurate: bool) {
    if sim.mo(id).target.is_none() {
        return;
    }
    sim.sound_named(Some(id), sound);
    face_target(sim, id);
    let angle = sim.mo(id).angle;
    let slope = collision::aim_line_attack(sim, id, angle, MISSILERANGE);
    gun_shot(sim, id, accurate, slope);
}

/// `A_M_FireShotgun`: seven pellets.
fn fire_shotgun(sim: &mut Sim, id: MobjId) {
    if sim.mo(id).target.is_none() {
        return;
    }
    sim.sound_named(Some(id), "shotgn");
    face_target(sim, id);
    let angle = sim.mo(id).angle;
    let slope = collision::aim_line_attack(sim, id, angle, MISSILERANGE);
    for _ in 0..7 {
        gun_shot(sim, id, false, slope);
    }
}

/// `A_M_FireShotgun2`: twenty pellets, twice the spread and a vertical
/// one (Doom's super shotgun's `P_SubRandom() << 5` on the slope).
fn fire_shotgun2(sim: &mut Sim, id: MobjId) {
    if sim.mo(id).target.is_none() {
        return;
    }
    sim.sound_named(Some(id), "dshtgn");
    face_target(sim, id);
    let bangle = sim.mo(id).angle;
    let slope = collision::aim_line_attack(sim, id, bangle, MISSILERANGE);
    for _ in 0..20 {
        let damage = 5 * (sim.p_random() % 3 + 1);
        let angle = spread(sim, bangle, 19);
        let dz = sim.rng.p_subrandom().wrapping_shl(5);
        collision::line_attack(sim, id, angle, MISSILERANGE, Fixed(slope.0.wrapping_add(dz)), damage);
    }
}

/// `A_M_FireMissile`: a punch when the target is within reach (ZDoom's
/// comment: the marine would otherwise blow himself up), else a rocket.
fn fire_missile(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    let Some(target) = sim.mo(id).target else { return };
    if check_melee_range(sim, id) {
        punch(sim, id, 1);
        return;
    }
    face_target(sim, id);
    if let Some(&Arg::Actor(kind)) = call.args.first() {
        movement::spawn_missile(sim, id, target, kind);
    }
}
