//! Monster behaviour (`p_enemy.c`): waking (`A_Look`, `P_LookForPlayers`,
//! `P_NoiseAlert`), chasing (`A_Chase`, `A_FaceTarget`, the melee and
//! missile range checks) and the action dispatch for every body action.
//! Walking by directions is `chase.rs`; the attacks are `attacks.rs`, the
//! arch-vile's raising and fire `vile.rs`, the boss specials and the boss
//! brain `bosses.rs`. What they hand on: state changes, missiles, shots and
//! damage through the other mechanisms' entry points.

use super::info::mt;
use super::level::ml;
use super::mobj::mf;
use super::{attacks, bosses, chase, sight, vile, MobjId, Sim};
use crate::actors::{ActionCall, Arg};
use crate::fixed::{approx_distance, point_to_angle2, Fixed, ANG270, ANG90, FRACUNIT};

/// `MELEERANGE`: 64 units.
pub const MELEERANGE: Fixed = Fixed(64 * FRACUNIT);
/// `MISSILERANGE`: 2048 units, the hitscan attacks' reach.
pub const MISSILERANGE: Fixed = Fixed(32 * 64 * FRACUNIT);

/// The boss brain's state (`braintargets`, `braintargeton`, `easy`).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BrainState {
    pub targets: Vec<MobjId>,
    pub target_on: usize,
    pub easy: bool,
}

/// Runs body action `name` on `id`.
pub fn action(sim: &mut Sim, id: MobjId, name: &str, call: &ActionCall) {
    match name {
        "A_Look" => look(sim, id),
        "A_Chase" => chase_target(sim, id),
        "A_FaceTarget" => face_target(sim, id),
        "A_Pain" => {
            let sound = sim.info.things[sim.mo(id).kind].painsound;
            sim.sound(Some(id), sound);
        }
        "A_Scream" => scream(sim, id),
        "A_XScream" => sim.sound_named(Some(id), "slop"),
        "A_Fall" => fall(sim, id),
        "A_PlayerScream" => player_scream(sim, id),
        "A_Explode" => {
            // Doom's A_Explode is P_RadiusAttack(thingy, thingy->target, 128);
            // the table's damage argument defaults to that 128.
            let damage = match call.args.first() {
                Some(Arg::Int(d)) => *d,
                _ => 128,
            };
            let source = sim.mo(id).target;
            super::collision::radius_attack(sim, id, source, damage);
        }
        "A_PlaySound" => {
            if let Some(Arg::Sound(s)) = call.args.first() {
                sim.sound(Some(id), s + 1);
            }
        }
        "A_BFGSpray" => {
            let spray = actor_arg(sim, call, mt::EXTRABFG);
            super::weapons::bfg_spray(sim, id, spray);
        }
        "A_Hoof" => {
            sim.sound_named(Some(id), "hoof");
            chase_target(sim, id);
        }
        "A_Metal" => {
            sim.sound_named(Some(id), "metal");
            chase_target(sim, id);
        }
        "A_BabyMetal" => {
            sim.sound_named(Some(id), "bspwlk");
            chase_target(sim, id);
        }
        "A_VileChase" | "A_VileStart" | "A_VileTarget" | "A_VileAttack" | "A_StartFire" | "A_Fire"
        | "A_FireCrackle" => vile::action(sim, id, name, call),
        "A_BossDeath" | "A_KeenDie" | "A_BrainAwake" | "A_BrainPain" | "A_BrainScream" | "A_BrainExplode"
        | "A_BrainDie" | "A_BrainSpit" | "A_SpawnSound" | "A_SpawnFly" => bosses::action(sim, id, name, call),
        _ => attacks::action(sim, id, name, call),
    }
}

/// The actor an action's first argument names, else Doom's kind `mt` (the
/// imp's fireball for `A_TroopAttack`, ...).
pub(super) fn actor_arg(sim: &Sim, call: &ActionCall, mt: usize) -> usize {
    match call.args.first() {
        Some(Arg::Actor(k)) if *k < sim.info.things.len() => *k,
        _ => sim.kind_of(mt),
    }
}

/// `P_NoiseAlert`: `emitter`'s noise spreads through sound-connected
/// sectors, waking monsters to `target`.
pub fn noise_alert(sim: &mut Sim, target: MobjId, emitter: MobjId) {
    // Doom bumps validcount and compares each sector's mark with it; a mark
    // set in this call is all that test asks, so the marks are local.
    sim.validcount = sim.validcount.wrapping_add(1);
    let mut flooded = vec![false; sim.level.sectors.len()];
    let start = sim.sector_of(emitter);
    recursive_sound(sim, &mut flooded, target, start, 0);
}

/// `P_RecursiveSound`: floods `sector` and its neighbours through open
/// two-sided lines; a second `ML_SOUNDBLOCK` line stops the flood. A
/// sector reached again with fewer blocks is flooded again (Doom's
/// `soundtraversed <= soundblocks+1` test), so the marks end at the least.
fn recursive_sound(sim: &mut Sim, flooded: &mut [bool], target: MobjId, sector: usize, soundblocks: i32) {
    let Some(sec) = sim.level.sectors.get_mut(sector) else { return };
    if flooded[sector] && sec.soundtraversed <= soundblocks + 1 {
        return;
    }
    flooded[sector] = true;
    sec.soundtraversed = soundblocks + 1;
    sec.soundtarget = Some(target);
    for i in 0..sim.level.sectors[sector].lines.len() {
        let check = &sim.level.lines[sim.level.sectors[sector].lines[i]];
        if check.flags & ml::TWOSIDED == 0 {
            continue;
        }
        // P_LineOpening: a line without a back side is closed.
        let (Some(front), Some(back), Some(side0), Some(side1)) =
            (check.frontsector, check.backsector, check.sidenum[0], check.sidenum[1])
        else {
            continue;
        };
        let (f, b) = (&sim.level.sectors[front], &sim.level.sectors[back]);
        let opentop = f.ceilingheight.min(b.ceilingheight);
        let openbottom = f.floorheight.max(b.floorheight);
        if (opentop - openbottom).0 <= 0 {
            continue; // a closed door
        }
        let sides = &sim.level.sides;
        let other = match (sides.get(side0), sides.get(side1)) {
            (Some(s0), Some(s1)) => {
                if s0.sector == sector {
                    s1.sector
                } else {
                    s0.sector
                }
            }
            _ => continue,
        };
        if check.flags & ml::SOUNDBLOCK != 0 {
            if soundblocks == 0 {
                recursive_sound(sim, flooded, target, other, 1);
            }
        } else {
            recursive_sound(sim, flooded, target, other, soundblocks);
        }
    }
}

/// `P_CheckMeleeRange`: the target within reach (64 units less 20 plus
/// the target kind's radius, Doom 1.5 and later) and in sight.
pub fn check_melee_range(sim: &mut Sim, id: MobjId) -> bool {
    let Some(t) = sim.mo(id).target else { return false };
    let (pl, actor) = (sim.mo(t), sim.mo(id));
    let dist = approx_distance(pl.x - actor.x, pl.y - actor.y);
    let range = MELEERANGE - Fixed(20 * FRACUNIT) + sim.info.things[pl.kind].radius;
    if dist >= range {
        return false;
    }
    sight::check_sight(sim, id, t)
}

/// `P_CheckMissileRange`: in sight, and then a `P_Random` against the
/// distance, shortened for the kinds Doom favours.
pub fn check_missile_range(sim: &mut Sim, id: MobjId) -> bool {
    let Some(t) = sim.mo(id).target else { return false };
    if !sight::check_sight(sim, id, t) {
        return false;
    }
    let actor = sim.mo_mut(id);
    if actor.has(mf::JUSTHIT) {
        // The target just hit it: fight back.
        actor.flags &= !mf::JUSTHIT;
        return true;
    }
    if actor.reactiontime != 0 {
        return false;
    }
    let (actor, target) = (sim.mo(id), sim.mo(t));
    let mut dist = approx_distance(actor.x - target.x, actor.y - target.y) - Fixed(64 * FRACUNIT);
    if sim.info.things[actor.kind].meleestate.is_none() {
        dist -= Fixed(128 * FRACUNIT); // no melee attack, so fire more
    }
    let mut dist = dist.0 >> 16;
    if sim.is(id, mt::VILE) && dist > 14 * 64 {
        return false;
    }
    if sim.is(id, mt::UNDEAD) {
        if dist < 196 {
            return false; // close enough for the fist
        }
        dist >>= 1;
    }
    if sim.is(id, mt::CYBORG) || sim.is(id, mt::SPIDER) || sim.is(id, mt::SKULL) {
        dist >>= 1;
    }
    dist = dist.min(200);
    if sim.is(id, mt::CYBORG) && dist > 160 {
        dist = 160;
    }
    sim.p_random() >= dist
}

/// `P_LookForPlayers`: the next players in turn from `lastlook` (at most
/// two of them, as Doom's `c++ == 2` stops it), the first alive and in
/// sight and, unless `allaround`, in front or within melee range becomes
/// the target. The turn goes round the game's [`Sim::slots`]: Doom's
/// `& 3` in a game of four slots.
pub fn look_for_players(sim: &mut Sim, id: MobjId, allaround: bool) -> bool {
    if sim.players.iter().all(Option::is_none) || sim.ignores_players(id) {
        return false; // Doom would loop for ever
    }
    let slots = sim.slots() as i32;
    let mut c = 0;
    let stop = (sim.mo(id).lastlook - 1).rem_euclid(slots);
    loop {
        let look = sim.mo(id).lastlook;
        if let Some(player) = sim.player(look.rem_euclid(slots) as usize) {
            let (health, pmo) = (player.health, player.mo);
            c += 1;
            if c == 3 || look == stop {
                return false; // done looking
            }
            if health > 0 && sight::check_sight(sim, id, pmo) {
                if !allaround {
                    let (actor, p) = (sim.mo(id), sim.mo(pmo));
                    let an = point_to_angle2(actor.x, actor.y, p.x, p.y) - actor.angle;
                    if an.0 > ANG90.0 && an.0 < ANG270.0 {
                        let dist = approx_distance(p.x - actor.x, p.y - actor.y);
                        // Behind its back, unless really close.
                        if dist > MELEERANGE {
                            sim.mo_mut(id).lastlook = (look + 1).rem_euclid(slots);
                            continue;
                        }
                    }
                }
                sim.mo_mut(id).target = Some(pmo);
                return true;
            }
        }
        sim.mo_mut(id).lastlook = (look + 1).rem_euclid(slots);
    }
}

/// `A_Look`: wakes to a sound heard in its sector (an ambusher only once
/// the sound's maker is in sight) or to a player seen in front; then the
/// see sound and the see state.
fn look(sim: &mut Sim, id: MobjId) {
    sim.mo_mut(id).threshold = 0; // any shot will wake it
    let heard = sim.level.sectors[sim.sector_of(id)].soundtarget;
    // A monster that ignores the players (ZDoom's Thing_Hate) does not
    // hear them either.
    let heard = heard.filter(|&t| !(sim.mo(t).player.is_some() && sim.ignores_players(id)));
    let mut seen = false;
    if let Some(targ) = heard.filter(|&t| sim.mo(t).has(mf::SHOOTABLE)) {
        sim.mo_mut(id).target = Some(targ);
        seen = !sim.mo(id).has(mf::AMBUSH) || sight::check_sight(sim, id, targ);
    }
    if !seen && !look_for_players(sim, id, false) {
        return;
    }
    let info = &sim.info.things[sim.mo(id).kind];
    let (seesound, seestate) = (info.seesound, info.seestate);
    if seesound != 0 {
        let sound = varied_sound(sim, seesound, &["posit1", "posit2", "posit3"], &["bgsit1", "bgsit2"]);
        play_boss_loud(sim, id, sound);
    }
    sim.set_mobj_state(id, seestate);
}

/// Doom's sounds chosen at random among their kin: a sound of `three`
/// gives one of the three (`P_Random() % 3`), of `two` one of the two.
fn varied_sound(sim: &mut Sim, sound: usize, three: &[&str; 3], two: &[&str; 2]) -> usize {
    let is = |names: &[&str], sim: &Sim| names.iter().any(|n| sim.info.sound(n) == sound);
    if is(three, sim) {
        let r = sim.p_random() % 3;
        sim.info.sound(three[r as usize])
    } else if is(two, sim) {
        let r = sim.p_random() % 2;
        sim.info.sound(two[r as usize])
    } else {
        sound
    }
}

/// The spider mastermind's and cyberdemon's sounds play at full volume
/// (from no origin), everyone else's from the body.
fn play_boss_loud(sim: &mut Sim, id: MobjId, sound: usize) {
    if sim.is(id, mt::SPIDER) || sim.is(id, mt::CYBORG) {
        sim.sound(None, sound);
    } else {
        sim.sound(Some(id), sound);
    }
}

/// `A_Chase`: turns towards its direction, attacks when it may, else walks
/// on towards the target (choosing a new direction when the count runs out
/// or the way is blocked), now and then making its active sound.
pub fn chase_target(sim: &mut Sim, id: MobjId) {
    let actor = sim.mo_mut(id);
    if actor.reactiontime != 0 {
        actor.reactiontime -= 1;
    }
    if sim.mo(id).threshold != 0 {
        // Doom 1.2 and earlier only counted down; every version we play is
        // later.
        let target_gone = sim.mo(id).target.is_none_or(|t| sim.mo(t).health <= 0);
        let actor = sim.mo_mut(id);
        if target_gone {
            actor.threshold = 0;
        } else {
            actor.threshold -= 1;
        }
    }
    let actor = sim.mo_mut(id);
    if (0..8).contains(&actor.movedir) {
        // Turn 45 degrees a tic towards the direction of movement.
        actor.angle.0 &= 7 << 29;
        let delta = actor.angle.0.wrapping_sub((actor.movedir as u32) << 29) as i32;
        if delta > 0 {
            actor.angle.0 = actor.angle.0.wrapping_sub(ANG90.0 / 2);
        } else if delta < 0 {
            actor.angle.0 = actor.angle.0.wrapping_add(ANG90.0 / 2);
        }
    }
    if sim.walk_to_goal(id) {
        return; // a ZDoom script's goal: walking there, not fighting
    }
    let target = sim.mo(id).target.filter(|&t| sim.mo(t).has(mf::SHOOTABLE));
    let Some(target) = target else {
        // Look for a new target.
        if look_for_players(sim, id, true) {
            return;
        }
        let spawn = sim.info.things[sim.mo(id).kind].spawnstate;
        sim.set_mobj_state(id, spawn);
        return;
    };
    let fast = sim.rules.fast_monsters();
    if sim.mo(id).has(mf::JUSTATTACKED) {
        // Do not attack twice in a row.
        sim.mo_mut(id).flags &= !mf::JUSTATTACKED;
        if !fast {
            chase::new_chase_dir(sim, id);
        }
        return;
    }
    let info = &sim.info.things[sim.mo(id).kind];
    let (melee, missile, attacksound, activesound) =
        (info.meleestate, info.missilestate, info.attacksound, info.activesound);
    if melee.is_some() && check_melee_range(sim, id) {
        sim.sound(Some(id), attacksound);
        sim.set_mobj_state(id, melee);
        return;
    }
    if missile.is_some() && (fast || sim.mo(id).movecount == 0) && check_missile_range(sim, id) {
        sim.set_mobj_state(id, missile);
        sim.mo_mut(id).flags |= mf::JUSTATTACKED;
        return;
    }
    // Possibly choose another target.
    if sim.rules.netgame
        && sim.mo(id).threshold == 0
        && !sight::check_sight(sim, id, target)
        && look_for_players(sim, id, true)
    {
        return;
    }
    // Chase towards the player.
    let actor = sim.mo_mut(id);
    actor.movecount -= 1;
    if actor.movecount < 0 || !chase::p_move(sim, id) {
        chase::new_chase_dir(sim, id);
    }
    if activesound != 0 && sim.p_random() < 3 {
        sim.sound(Some(id), activesound);
    }
}

/// `A_FaceTarget`: turns to the target (off by up to about 22 degrees
/// either way when it is a shadow) and ends an ambush.
pub fn face_target(sim: &mut Sim, id: MobjId) {
    let Some(t) = sim.mo(id).target else { return };
    let (tx, ty, shadow) = (sim.mo(t).x, sim.mo(t).y, sim.mo(t).has(mf::SHADOW));
    let actor = sim.mo_mut(id);
    actor.flags &= !mf::AMBUSH;
    actor.angle = point_to_angle2(actor.x, actor.y, tx, ty);
    if shadow {
        let r = sim.rng.p_subrandom();
        let actor = sim.mo_mut(id);
        actor.angle.0 = actor.angle.0.wrapping_add(r.wrapping_shl(21) as u32);
    }
}

/// `A_Fall`: a body on the ground can be walked over.
pub fn fall(sim: &mut Sim, id: MobjId) {
    sim.mo_mut(id).flags &= !mf::SOLID;
}

/// `A_Scream`: the death sound (one of the kin at random), full volume for
/// the two big bosses.
fn scream(sim: &mut Sim, id: MobjId) {
    let deathsound = sim.info.things[sim.mo(id).kind].deathsound;
    if deathsound == 0 {
        return;
    }
    let sound = varied_sound(sim, deathsound, &["podth1", "podth2", "podth3"], &["bgdth1", "bgdth2"]);
    play_boss_loud(sim, id, sound);
}

/// `A_PlayerScream`: the louder death below -50 health, in Doom II only.
fn player_scream(sim: &mut Sim, id: MobjId) {
    let high = sim.rules.mode == super::GameMode::Commercial && sim.mo(id).health < -50;
    sim.sound_named(Some(id), if high { "pdiehi" } else { "pldeth" });
}

#[cfg(test)]
mod tests;
