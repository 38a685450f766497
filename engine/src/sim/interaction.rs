//! Things meeting things (`p_inter.c`): damage (`P_DamageMobj`) and death
//! (`P_KillMobj`) here, pickups (`P_TouchSpecialThing` and the `P_Give*`
//! helpers) in [`pickups`]. Damage comes from the shots, blasts and
//! missiles of [`super::collision`] and [`super::monsters`]; what it hands
//! on is a body's pain or death state and the monster's new target.

pub mod pickups;

use super::info::mt;
use super::mobj::{mf, ONFLOORZ};
use super::user::{cf, pw};
use super::{weapons, MobjId, PlayerState, Rules, Sim};
use crate::actors::dehacked::doom_info;
use crate::fixed::{finecosine, finesine, point_to_angle2, Fixed, ANG180, ANGLETOFINESHIFT, FRACUNIT};

/// `BASETHRESHOLD`: tics a monster keeps after the one that hurt it.
const BASETHRESHOLD: i32 = 100;

/// `P_TouchSpecialThing`: `toucher` walks onto the item `special`.
pub fn touch_special_thing(sim: &mut Sim, special: MobjId, toucher: MobjId) {
    pickups::touch_special_thing(sim, special, toucher);
}

/// The kind Doom's thing `name` (`"MT_CLIP"`) is in the table.
fn kind_named(sim: &Sim, name: &str) -> Option<usize> {
    doom_info().thing(name).and_then(|m| sim.info.actor_of(m))
}

/// `P_KillMobj`: `target` dies (by `source`'s hand, if any): it falls
/// flat, is counted, a player's weapon goes down, it enters its death (or,
/// torn apart, its gib) state with up to three tics less, and a zombie
/// drops its gun.
pub fn kill_mobj(sim: &mut Sim, source: Option<MobjId>, target: MobjId) {
    let skull = sim.is(target, mt::SKULL);
    let mo = sim.mo_mut(target);
    mo.flags &= !(mf::SHOOTABLE | mf::FLOAT | mf::SKULLFLY);
    if !skull {
        mo.flags &= !mf::NOGRAVITY;
    }
    mo.flags |= mf::CORPSE | mf::DROPOFF;
    mo.height = mo.height >> 2;
    let counted = mo.has(mf::COUNTKILL);
    let victim = mo.player;
    match source.and_then(|s| sim.mo(s).player) {
        Some(killer) => {
            if let Some(p) = sim.players[killer].as_mut() {
                if counted {
                    p.killcount += 1;
                }
                if let Some(v) = victim {
                    p.frags[v] += 1;
                }
            }
        }
        None if !sim.rules.netgame && counted => {
            // Every monster's death counts, even by another monster's hand.
            if let Some(p) = sim.players[0].as_mut() {
                p.killcount += 1;
            }
        }
        None => {}
    }
    if let Some(v) = victim {
        if let Some(p) = sim.players[v].as_mut() {
            // An environment kill counts against the victim.
            if source.is_none() {
                p.frags[v] += 1;
            }
            p.playerstate = PlayerState::Dead;
        }
        sim.zdoom.tallies[v].deaths += 1;
        sim.mo_mut(target).flags &= !mf::SOLID;
        weapons::drop_weapon(sim, v);
    }
    let info = &sim.info.things[sim.mo(target).kind];
    let (spawnhealth, death, xdeath) = (info.spawnhealth, info.deathstate, info.xdeathstate);
    let gibbed = sim.mo(target).health < -spawnhealth && xdeath.is_some();
    sim.set_mobj_state(target, if gibbed { xdeath } else { death });
    sim.fire_thing_special(target, source);
    let r = sim.p_random() & 3;
    let mo = sim.mo_mut(target);
    mo.tics -= r;
    if mo.tics < 1 {
        mo.tics = 1;
    }
    let item = match sim.mt(target) {
        Some(mt::WOLFSS) | Some(mt::POSSESSED) => "MT_CLIP",
        Some(mt::SHOTGUY) => "MT_SHOTGUN",
        Some(mt::CHAINGUY) => "MT_CHAINGUN",
        _ => return,
    };
    let Some(kind) = kind_named(sim, item) else { return };
    let (x, y) = (sim.mo(target).x, sim.mo(target).y);
    let drop = sim.spawn_mobj(x, y, ONFLOORZ, kind);
    sim.mo_mut(drop).flags |= mf::DROPPED;
}

/// `P_DamageMobj`: `target` hurt by `damage` from `inflictor` (what hit
/// it) fired by `source` (who is to blame): pushed away from the
/// inflictor, a player's armor and god mode applied, then death, or pain
/// by chance, and a monster turns on its attacker.
pub fn damage_mobj(sim: &mut Sim, target: MobjId, inflictor: Option<MobjId>, source: Option<MobjId>, damage: i32) {
    let mut damage = damage;
    let mo = sim.mo(target);
    if !mo.has(mf::SHOOTABLE) || mo.health <= 0 {
        return;
    }
    if mo.has(mf::SKULLFLY) {
        let mo = sim.mo_mut(target);
        mo.momx = Fixed::ZERO;
        mo.momy = Fixed::ZERO;
        mo.momz = Fixed::ZERO;
    }
    let player = sim.mo(target).player;
    if player.is_some() && sim.rules.skill == 0 {
        // Half damage in trainer mode.
        damage >>= 1;
    }
    let scaled = sim.scaled_damage(target, damage);
    if scaled <= 0 && damage > 0 {
        return; // a damage factor of 0 (ZDoom: no pain, no thrust)
    }
    damage = scaled;
    if let Some(inflictor) = inflictor {
        thrust_away(sim, target, inflictor, source, damage);
    }
    if let Some(n) = player {
        if !damage_player(sim, n, target, source, &mut damage) {
            return;
        }
    }
    sim.log_damage(target, source, damage);
    let mo = sim.mo_mut(target);
    mo.health = mo.health.wrapping_sub(damage);
    if mo.health <= 0 {
        kill_mobj(sim, source, target);
        return;
    }
    let info = &sim.info.things[sim.mo(target).kind];
    let (painchance, painstate, spawnstate, seestate) =
        (info.painchance, info.painstate, info.spawnstate, info.seestate);
    if sim.p_random() < painchance && !sim.mo(target).has(mf::SKULLFLY) {
        // Fight back!
        sim.mo_mut(target).flags |= mf::JUSTHIT;
        sim.set_mobj_state(target, painstate);
    }
    sim.mo_mut(target).reactiontime = 0;
    let Some(source) = source else { return };
    if sim.mo(source).player.is_some() && sim.ignores_players(target) {
        return;
    }
    let vile_target = sim.is(target, mt::VILE);
    // Every version we play is 1.5 or later, where a monster does not
    // turn on itself; an arch-vile is never chased, and always chases.
    if (sim.mo(target).threshold == 0 || vile_target) && source != target && !sim.is(source, mt::VILE) {
        let mo = sim.mo_mut(target);
        mo.target = Some(source);
        mo.threshold = BASETHRESHOLD;
        if mo.state.is_some() && mo.state == spawnstate && seestate.is_some() {
            sim.set_mobj_state(target, seestate);
        }
    }
}

/// The push a hit gives, away from the inflictor (none for a thing that
/// does not clip, nor from a player's chainsaw, which would push its
/// victim out of reach). A killing blow of under 40 from well below
/// sometimes throws the body forwards four times as hard (one `P_Random`).
fn thrust_away(sim: &mut Sim, target: MobjId, inflictor: MobjId, source: Option<MobjId>, damage: i32) {
    if sim.mo(target).has(mf::NOCLIP) {
        return;
    }
    let sawing = source
        .and_then(|s| sim.mo(s).player)
        .and_then(|n| sim.player(n))
        .is_some_and(|p| p.readyweapon == weapons::wp::CHAINSAW);
    if sawing {
        return;
    }
    let (t, i) = (sim.mo(target), sim.mo(inflictor));
    let mut ang = point_to_angle2(i.x, i.y, t.x, t.y);
    let mass = sim.info.things[t.kind].mass;
    // int arithmetic as Doom's, wrapping for a telefrag's 10000; a kind
    // of mass 0 (a modder's) would divide by zero in Doom: no push.
    let mut thrust = damage.wrapping_mul(FRACUNIT >> 3).wrapping_mul(100).checked_div(mass).unwrap_or(0);
    if damage < 40 && damage > t.health && (t.z - i.z) > Fixed::from_int(64) && (sim.p_random() & 1) != 0 {
        ang += ANG180;
        thrust = thrust.wrapping_mul(4);
    }
    let fine = (ang.0 >> ANGLETOFINESHIFT) as usize;
    let mo = sim.mo_mut(target);
    mo.momx += Fixed(thrust) * finecosine(fine);
    mo.momy += Fixed(thrust) * finesine(fine);
}

/// The player's side of a hit: the end-of-game sector keeps player `n`
/// alive, god mode and invulnerability stop it (false: no damage at all),
/// armor takes its share, and the rest is the player's health and red
/// flash.
fn damage_player(sim: &mut Sim, n: usize, target: MobjId, source: Option<MobjId>, damage: &mut i32) -> bool {
    let health = sim.mo(target).health;
    // Sector special 11 (E1M8's exit floor) never kills.
    if sim.level.sectors[sim.sector_of(target)].special == 11 && *damage >= health {
        *damage = health - 1;
    }
    let Some(p) = sim.players[n].as_mut() else { return true };
    if *damage < 1000 && (p.cheats & cf::GODMODE != 0 || p.powers[pw::INVULNERABILITY] != 0) {
        return false;
    }
    if p.armortype != 0 {
        let mut saved = if p.armortype == 1 { *damage / 3 } else { *damage / 2 };
        if p.armorpoints <= saved {
            // The armor is used up.
            saved = p.armorpoints;
            p.armortype = 0;
        }
        p.armorpoints -= saved;
        *damage -= saved;
    }
    p.health = p.health.wrapping_sub(*damage);
    if p.health < 0 {
        p.health = 0;
    }
    p.attacker = source;
    p.damagecount = p.damagecount.wrapping_add(*damage);
    if p.damagecount > 100 {
        // A telefrag does 10000.
        p.damagecount = 100;
    }
    true
}

/// Whether a skill doubles the ammo picked up (`sk_baby`, `sk_nightmare`).
fn doubles_ammo(rules: &Rules) -> bool {
    rules.skill == 0 || rules.skill == Rules::NIGHTMARE
}
