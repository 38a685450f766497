//! How bodies move (`p_mobj.c`): `P_MobjThinker` (momentum, gravity, state
//! tics, the nightmare respawn), `P_XYMovement` with friction and sliding,
//! `P_ZMovement`, and the spawning of missiles, puffs and blood. Moves go
//! through [`super::collision`]; what a missile hits is decided there and
//! in [`super::interaction`].

use super::info::mt;
use super::mobj::point_in_subsector;
use super::mobj::{mf, ONCEILINGZ, ONFLOORZ};
use super::setup::VIEWHEIGHT;
use super::{collision, GameVersion, MobjId, Sim, TICRATE};
use crate::actors::StateId;
use crate::fixed::{
    approx_distance, finecosine, finesine, point_to_angle2, Angle, Fixed, ANG45, ANGLETOFINESHIFT, FRACUNIT,
};

/// `MAXMOVE`: the most a body moves in a tic; faster momentum is clipped.
pub const MAXMOVE: Fixed = Fixed(30 * FRACUNIT);
/// `STOPSPEED`: below this a body on the floor stops.
pub const STOPSPEED: Fixed = Fixed(0x1000);
/// `FRICTION`: momentum kept each tic on the floor (0.90625).
pub const FRICTION: Fixed = Fixed(0xe800);
/// `GRAVITY`: a tic's fall speed gained.
pub const GRAVITY: Fixed = Fixed(FRACUNIT);
/// `FLOATSPEED`: how fast floating monsters rise and sink.
pub const FLOATSPEED: Fixed = Fixed(4 * FRACUNIT);
/// `MELEERANGE`: the fist's and the monsters' bite reach.
pub const MELEERANGE: Fixed = Fixed(64 * FRACUNIT);
/// `MTF_AMBUSH`: a map thing that waits deaf.
const MTF_AMBUSH: u16 = 8;

/// `P_MobjThinker`: momentum, then height, then the state's tics; a body
/// removed on the way stops there. A monster waiting in a state that
/// lasts for ever (a corpse) may come back on Nightmare.
pub fn mobj_thinker(sim: &mut Sim, id: MobjId) {
    let mo = sim.mo(id);
    if mo.momx != Fixed::ZERO || mo.momy != Fixed::ZERO || mo.has(mf::SKULLFLY) {
        xy_movement(sim, id);
        if sim.mo(id).removed {
            return;
        }
    }
    let mo = sim.mo(id);
    if mo.z != mo.floorz || mo.momz != Fixed::ZERO {
        z_movement(sim, id);
        if sim.mo(id).removed {
            return;
        }
    }
    let mo = sim.mo(id);
    if mo.tics != -1 {
        let mo = sim.mo_mut(id);
        mo.tics -= 1;
        if mo.tics == 0 {
            let next = mo.state.and_then(|s| sim.info.state(s).next);
            sim.set_mobj_state(id, next);
        }
        return;
    }
    if !mo.has(mf::COUNTKILL) || !sim.rules.respawn_monsters() {
        return;
    }
    let mo = sim.mo_mut(id);
    mo.movecount += 1;
    if mo.movecount < 12 * TICRATE as i32 || sim.leveltime & 31 != 0 {
        return;
    }
    if sim.p_random() > 4 {
        return;
    }
    nightmare_respawn(sim, id);
}

/// `P_XYMovement`: the momentum spent in steps of at most half `MAXMOVE`
/// (Doom tests only the positive directions for the split), a blocked
/// player sliding along the wall, a blocked missile exploding (or vanishing
/// into the sky), then friction on the floor.
pub fn xy_movement(sim: &mut Sim, id: MobjId) {
    let mo = sim.mo(id);
    if mo.momx == Fixed::ZERO && mo.momy == Fixed::ZERO {
        if mo.has(mf::SKULLFLY) {
            // The skull slammed into something.
            let spawn = sim.info.things[mo.kind].spawnstate;
            let mo = sim.mo_mut(id);
            mo.flags &= !mf::SKULLFLY;
            mo.momx = Fixed::ZERO;
            mo.momy = Fixed::ZERO;
            mo.momz = Fixed::ZERO;
            sim.set_mobj_state(id, spawn);
        }
        return;
    }
    let player = mo.player;
    let mo = sim.mo_mut(id);
    mo.momx = clamp_move(mo.momx);
    mo.momy = clamp_move(mo.momy);
    let (mut xmove, mut ymove) = (mo.momx, mo.momy);
    let half = Fixed(MAXMOVE.0 / 2);
    loop {
        let mo = sim.mo(id);
        let (ptryx, ptryy);
        if xmove > half || ymove > half {
            ptryx = mo.x + Fixed(xmove.0 / 2);
            ptryy = mo.y + Fixed(ymove.0 / 2);
            xmove = xmove >> 1;
            ymove = ymove >> 1;
        } else {
            ptryx = mo.x + xmove;
            ptryy = mo.y + ymove;
            xmove = Fixed::ZERO;
            ymove = Fixed::ZERO;
        }
        if through_wall(sim, id, ptryx, ptryy) {
            // Gone through the wall, as in Doom and ZDoom, but out of the
            // game rather than flying on outside the map.
            sim.remove_mobj(id);
            return;
        }
        if !collision::try_move(sim, id, ptryx, ptryy) {
            if sim.mo(id).player.is_some() {
                collision::slide_move(sim, id);
            } else if sim.mo(id).has(mf::MISSILE) {
                if ceiling_is_sky(sim) {
                    // Doom's hack: a missile does not explode against the
                    // sky (sky floors are not handled).
                    sim.remove_mobj(id);
                    return;
                }
                explode_missile(sim, id);
                if sim.rules.compat == super::Compat::Sightline {
                    // Vanilla moves the exploded missile on by the rest of
                    // its split step (its momentum is gone, the step's
                    // remainder is not); under Sightline's rules it stays.
                    break;
                }
            } else {
                let mo = sim.mo_mut(id);
                mo.momx = Fixed::ZERO;
                mo.momy = Fixed::ZERO;
            }
        }
        if xmove == Fixed::ZERO && ymove == Fixed::ZERO {
            break;
        }
    }
    apply_friction(sim, id, player);
}

/// Under Sightline's rules, whether a missile too thin for its step
/// passes through a wall on it. Doom's (and ZDoom's) line checks test only
/// the box where a move ends, so a missile narrower than half its step
/// skips any line between: rocket_basic's DECORATE rocket, of radius 0,
/// goes through the wall behind its target in ViZDoom and explodes (if
/// ever) out of sight of it, which the scenario's odds depend on. Here the
/// step's path is traced, and a missile that crosses a line it could not
/// pass (one-sided, or an opening it does not fit; blocking lines do not
/// stop missiles, as in Doom) and that its box at the step's end does not
/// touch (where Doom would have let it through) leaves the game there
/// (`xy_movement`), so no body flies on outside the map. A line the end
/// box touches stops it as in Doom: it explodes against the wall.
fn through_wall(sim: &mut Sim, id: MobjId, x: Fixed, y: Fixed) -> bool {
    let mo = sim.mo(id);
    let step = (x - mo.x).abs().max((y - mo.y).abs());
    if sim.rules.compat != super::Compat::Sightline || !mo.has(mf::MISSILE) || mo.radius.0 * 2 >= step.0 {
        return false;
    }
    let (x1, y1, bottom, top, radius) = (mo.x, mo.y, mo.z, mo.z + mo.height, mo.radius);
    // Where the step ends, the box Doom's line check tests.
    let end = [y + radius, y - radius, x - radius, x + radius];
    let mut skipped = false;
    super::maputl::path_traverse(sim, x1, y1, x, y, super::maputl::PT_ADDLINES, |sim, hit, _| {
        let super::maputl::Hit::Line(line) = hit.hit else { return true };
        super::maputl::line_opening(sim, line);
        let o = sim.tm.opening;
        if o.range > Fixed::ZERO && bottom >= o.bottom && top <= o.top {
            return true; // it fits through
        }
        // A line the end box touches stops it as in Doom (it explodes there);
        // one it would have skipped stops it here.
        skipped = !super::maputl::box_touches_line(&end, &sim.level.lines[line]);
        false
    });
    skipped
}

fn clamp_move(m: Fixed) -> Fixed {
    if m > MAXMOVE {
        MAXMOVE
    } else if m < -MAXMOVE {
        -MAXMOVE
    } else {
        m
    }
}

/// Whether the line that set the last move's ceiling has a sky ceiling
/// behind it (`ceilingline->backsector->ceilingpic == skyflatnum`).
fn ceiling_is_sky(sim: &Sim) -> bool {
    let Some(line) = sim.tm.ceilingline.and_then(|l| sim.level.lines.get(l)) else { return false };
    let Some(back) = line.backsector.and_then(|s| sim.level.sectors.get(s)) else { return false };
    sim.level.name(back.ceilingpic).eq_ignore_ascii_case("F_SKY1")
}

/// The slowing down after a move: none for missiles, flying skulls and
/// bodies in the air; a corpse halfway off a step keeps sliding; a slow
/// body stops (a player only when its command does not move it, and its
/// running frames end); anything else loses `FRICTION`.
fn apply_friction(sim: &mut Sim, id: MobjId, player: Option<usize>) {
    let cmd = player.and_then(|n| sim.player(n)).map(|p| (p.cheats, p.cmd));
    if cmd.is_some_and(|(cheats, _)| cheats & super::user::cf::NOMOMENTUM != 0) {
        let mo = sim.mo_mut(id);
        mo.momx = Fixed::ZERO;
        mo.momy = Fixed::ZERO;
        return;
    }
    let mo = sim.mo(id);
    if mo.has(mf::MISSILE | mf::SKULLFLY) || mo.z > mo.floorz {
        return;
    }
    let quarter = Fixed(FRACUNIT / 4);
    if mo.has(mf::CORPSE)
        && (mo.momx > quarter || mo.momx < -quarter || mo.momy > quarter || mo.momy < -quarter)
        && mo.floorz != sim.level.sectors[sim.sector_of(id)].floorheight
    {
        return;
    }
    let slow = mo.momx > -STOPSPEED && mo.momx < STOPSPEED && mo.momy > -STOPSPEED && mo.momy < STOPSPEED;
    let idle = cmd.is_none_or(|(_, c)| c.forward == 0 && c.side == 0);
    if slow && idle {
        // Doom looks at the player's own body here (`player->mo`), which
        // for a voodoo doll is not the body that moved.
        if let Some(body) = player.and_then(|n| sim.player(n)).map(|p| p.mo) {
            if in_running_frames(sim, body) {
                let standing = sim.info.things[sim.mo(body).kind].spawnstate;
                sim.set_mobj_state(body, standing);
            }
        }
        let mo = sim.mo_mut(id);
        mo.momx = Fixed::ZERO;
        mo.momy = Fixed::ZERO;
    } else {
        let mo = sim.mo_mut(id);
        mo.momx = mo.momx * FRICTION;
        mo.momy = mo.momy * FRICTION;
    }
}

/// Whether the body is in one of the four running states (`S_PLAY_RUN1`
/// to `S_PLAY_RUN4`: its kind's see state and the three after it).
fn in_running_frames(sim: &Sim, id: MobjId) -> bool {
    let mo = sim.mo(id);
    match (mo.state, sim.info.things[mo.kind].seestate) {
        (Some(s), Some(run1)) => s.0.wrapping_sub(run1.0) < 4,
        _ => false,
    }
}

/// `P_ZMovement`: a player stepping up squats its view, the body moves by
/// `momz`, floating monsters drift towards their target's height, and the
/// floor and ceiling stop it (landing hard squats a player; missiles
/// explode; a charging lost soul bounces, by the game version's rule).
pub fn z_movement(sim: &mut Sim, id: MobjId) {
    let mo = sim.mo(id);
    if let Some(n) = mo.player {
        if mo.z < mo.floorz {
            let step = mo.floorz - mo.z;
            if let Some(p) = sim.players[n].as_mut() {
                p.viewheight -= step;
                p.deltaviewheight = (VIEWHEIGHT - p.viewheight) >> 3;
            }
        }
    }
    let mo = sim.mo_mut(id);
    mo.z += mo.momz;
    let mo = sim.mo(id);
    if mo.has(mf::FLOAT) && !mo.has(mf::SKULLFLY) && !mo.has(mf::INFLOAT) {
        if let Some(t) = mo.target {
            let target = sim.mo(t);
            let dist = approx_distance(mo.x - target.x, mo.y - target.y);
            let delta = (target.z + (mo.height >> 1)) - mo.z;
            if delta < Fixed::ZERO && dist < -(delta * 3) {
                sim.mo_mut(id).z -= FLOATSPEED;
            } else if delta > Fixed::ZERO && dist < delta * 3 {
                sim.mo_mut(id).z += FLOATSPEED;
            }
        }
    }
    // Ultimate and Final Doom bounce a charging skull off the floor before
    // the landing; Doom 1.9 (and Doom II's) after it, where a rising floor
    // reverses a charge's climb as well.
    let bounce_first = sim.rules.version != GameVersion::Doom19;
    let mo = sim.mo(id);
    if mo.z <= mo.floorz {
        if bounce_first && mo.has(mf::SKULLFLY) {
            let mo = sim.mo_mut(id);
            mo.momz = -mo.momz;
        }
        let mo = sim.mo(id);
        if mo.momz < Fixed::ZERO {
            if let Some(n) = mo.player {
                if mo.momz < -(GRAVITY * 8) {
                    // Squat down after hitting the ground hard.
                    let squat = mo.momz >> 3;
                    if let Some(p) = sim.players[n].as_mut() {
                        p.deltaviewheight = squat;
                    }
                    sim.sound_named(Some(id), "oof");
                }
            }
            sim.mo_mut(id).momz = Fixed::ZERO;
        }
        let mo = sim.mo_mut(id);
        mo.z = mo.floorz;
        if !bounce_first && mo.has(mf::SKULLFLY) {
            mo.momz = -mo.momz;
        }
        if mo.has(mf::MISSILE) && !mo.has(mf::NOCLIP) {
            explode_missile(sim, id);
            return;
        }
    } else if !mo.has(mf::NOGRAVITY) {
        let mo = sim.mo_mut(id);
        if mo.momz == Fixed::ZERO {
            mo.momz = -(GRAVITY * 2);
        } else {
            mo.momz -= GRAVITY;
        }
    }
    let mo = sim.mo_mut(id);
    if mo.z + mo.height > mo.ceilingz {
        if mo.momz > Fixed::ZERO {
            mo.momz = Fixed::ZERO;
        }
        mo.z = mo.ceilingz - mo.height;
        if mo.has(mf::SKULLFLY) {
            mo.momz = -mo.momz;
        }
        if mo.has(mf::MISSILE) && !mo.has(mf::NOCLIP) {
            explode_missile(sim, id);
        }
    }
}

/// `P_NightmareRespawn`: a dead monster comes back at its map spot if it
/// fits there, with teleport fog at both places.
pub fn nightmare_respawn(sim: &mut Sim, id: MobjId) {
    let spot = sim.mo(id).spawnpoint.clone();
    let x = Fixed::from_int(spot.x.into());
    let y = Fixed::from_int(spot.y.into());
    if !collision::check_position(sim, id, x, y) {
        return;
    }
    let fog = sim.kind_of(mt::TFOG);
    let (ox, oy) = (sim.mo(id).x, sim.mo(id).y);
    let old_floor = sim.level.sectors[sim.sector_of(id)].floorheight;
    let f = sim.spawn_mobj(ox, oy, old_floor, fog);
    sim.sound_named(Some(f), "telept");
    let ss = point_in_subsector(&sim.level, x, y);
    let new_floor = sim.level.sectors[sim.level.subsectors[ss].sector].floorheight;
    let f = sim.spawn_mobj(x, y, new_floor, fog);
    sim.sound_named(Some(f), "telept");
    let kind = sim.mo(id).kind;
    let z = if sim.info.things[kind].flags & mf::SPAWNCEILING != 0 { ONCEILINGZ } else { ONFLOORZ };
    let mo = sim.spawn_mobj(x, y, z, kind);
    let m = sim.mo_mut(mo);
    m.angle = Angle(ANG45.0.wrapping_mul((i32::from(spot.angle) / 45) as u32));
    if spot.flags & MTF_AMBUSH != 0 {
        m.flags |= mf::AMBUSH;
    }
    m.reactiontime = 18;
    m.spawnpoint = spot;
    sim.remove_mobj(id);
}

/// The state `offset` states after `kind`'s spawn state (Doom's
/// `S_PUFF3`, `S_BLOOD2` are numbered from their kind's first); a table
/// too short for it keeps the spawn state.
fn spawn_state_plus(sim: &Sim, kind: usize, offset: u32) -> Option<StateId> {
    let first = sim.info.things[kind].spawnstate?;
    let later = first.0.checked_add(offset).filter(|&s| (s as usize) < sim.info.states.len());
    Some(later.map_or(first, StateId))
}

/// Takes up to three from a new effect's first tics (at least one stays),
/// spending one `P_Random`.
fn shorten_tics(sim: &mut Sim, id: MobjId) {
    let r = sim.p_random() & 3;
    let mo = sim.mo_mut(id);
    mo.tics -= r;
    if mo.tics < 1 {
        mo.tics = 1;
    }
}

/// `P_SpawnPuff`: a bullet puff at `x`, `y`, `z` (height jittered),
/// rising; at melee range (the last aim's or shot's `attackrange`) only its
/// last frames.
pub fn spawn_puff(sim: &mut Sim, x: Fixed, y: Fixed, z: Fixed) {
    let range = sim.tm.attackrange;
    spawn_puff_ranged(sim, x, y, z, range);
}

/// `P_SpawnPuff` with the shot's range (`attackrange`): a melee hit
/// (`MELEERANGE`) shows only the puff's last frames, so a punch does not
/// spark on the wall.
pub fn spawn_puff_ranged(sim: &mut Sim, x: Fixed, y: Fixed, z: Fixed, attackrange: Fixed) {
    let z = z + Fixed(sim.rng.p_subrandom() << 10);
    let kind = sim.kind_of(mt::PUFF);
    let th = sim.spawn_mobj(x, y, z, kind);
    sim.mo_mut(th).momz = Fixed::ONE;
    shorten_tics(sim, th);
    if attackrange == MELEERANGE {
        let puff3 = spawn_state_plus(sim, kind, 2);
        sim.set_mobj_state(th, puff3);
    }
}

/// `P_SpawnBlood`: blood at `x`, `y`, `z`, smaller for smaller hits.
pub fn spawn_blood(sim: &mut Sim, x: Fixed, y: Fixed, z: Fixed, damage: i32) {
    let z = z + Fixed(sim.rng.p_subrandom() << 10);
    let kind = sim.kind_of(mt::BLOOD);
    let th = sim.spawn_mobj(x, y, z, kind);
    sim.mo_mut(th).momz = Fixed(FRACUNIT * 2);
    shorten_tics(sim, th);
    let offset = match damage {
        9..=12 => 1,
        ..=8 => 2,
        _ => return,
    };
    let smaller = spawn_state_plus(sim, kind, offset);
    sim.set_mobj_state(th, smaller);
}

/// `P_CheckMissileSpawn`: a new missile steps half a tic forward (so an
/// angle can be found if it explodes at once) and explodes if it does not
/// fit there.
pub fn check_missile_spawn(sim: &mut Sim, th: MobjId) {
    shorten_tics(sim, th);
    let mo = sim.mo(th);
    if through_wall(sim, th, mo.x + (mo.momx >> 1), mo.y + (mo.momy >> 1)) {
        sim.remove_mobj(th);
        return;
    }
    let mo = sim.mo_mut(th);
    mo.x += mo.momx >> 1;
    mo.y += mo.momy >> 1;
    mo.z += mo.momz >> 1;
    let (x, y) = (mo.x, mo.y);
    if !collision::try_move(sim, th, x, y) {
        explode_missile(sim, th);
    }
}

/// The missile's start: spawned 32 units up from `source`, its see sound,
/// `source` as its owner, and its angle.
fn launch(sim: &mut Sim, source: MobjId, kind: usize, angle: Angle) -> MobjId {
    let s = sim.mo(source);
    let th = sim.spawn_mobj(s.x, s.y, s.z + Fixed::from_int(32), kind);
    let seesound = sim.info.things[kind].seesound;
    sim.sound(Some(th), seesound);
    let mo = sim.mo_mut(th);
    mo.target = Some(source);
    mo.angle = angle;
    th
}

/// `P_SpawnMissile`: a missile of `kind` from `source` at `dest` (off by a
/// random turn if `dest` is a shadow), climbing to reach its height.
pub fn spawn_missile(sim: &mut Sim, source: MobjId, dest: MobjId, kind: usize) -> Option<MobjId> {
    let (s, d) = (sim.mo(source), sim.mo(dest));
    let (sx, sy, sz, dx, dy, dz) = (s.x, s.y, s.z, d.x, d.y, d.z);
    let shadow = d.has(mf::SHADOW);
    let th = launch(sim, source, kind, Angle::ZERO);
    // The spawn spent its P_Random before the shadow's turn.
    let mut an = point_to_angle2(sx, sy, dx, dy);
    if shadow {
        an += Angle((sim.rng.p_subrandom() << 20) as u32);
    }
    let speed = sim.info.things[kind].speed;
    let fine = (an.0 >> ANGLETOFINESHIFT) as usize;
    let mo = sim.mo_mut(th);
    mo.angle = an;
    mo.momx = Fixed(speed) * finecosine(fine);
    mo.momy = Fixed(speed) * finesine(fine);
    // C's int division; a kind of speed 0 (only a modder's) flies level.
    let dist = approx_distance(dx - sx, dy - sy).0.checked_div(speed).unwrap_or(0).max(1);
    mo.momz = Fixed((dz - sz).0 / dist);
    check_missile_spawn(sim, th);
    Some(th)
}

/// `P_SpawnPlayerMissile`: a player's missile, aimed at a monster straight
/// ahead or a little to either side (`P_AimLineAttack` three times), else
/// level and straight.
pub fn spawn_player_missile(sim: &mut Sim, source: MobjId, kind: usize) {
    let range = Fixed(16 * 64 * FRACUNIT);
    let mut an = sim.mo(source).angle;
    let mut slope = Fixed::ZERO;
    if !sim.rules.no_autoaim {
        slope = collision::aim_line_attack(sim, source, an, range);
    }
    if !sim.rules.no_autoaim && sim.tm.linetarget.is_none() {
        an += Angle(1 << 26);
        slope = collision::aim_line_attack(sim, source, an, range);
        if sim.tm.linetarget.is_none() {
            an -= Angle(2 << 26);
            slope = collision::aim_line_attack(sim, source, an, range);
        }
        if sim.tm.linetarget.is_none() {
            an = sim.mo(source).angle;
            slope = Fixed::ZERO;
        }
    }
    let th = launch(sim, source, kind, an);
    let speed = Fixed(sim.info.things[kind].speed);
    let fine = (an.0 >> ANGLETOFINESHIFT) as usize;
    let mo = sim.mo_mut(th);
    mo.momx = speed * finecosine(fine);
    mo.momy = speed * finesine(fine);
    mo.momz = speed * slope;
    check_missile_spawn(sim, th);
}

/// `P_ExplodeMissile`: the missile stops, enters its death state with up
/// to three tics less (one `P_Random`), and stops being a missile.
pub fn explode_missile(sim: &mut Sim, missile: MobjId) {
    let mo = sim.mo_mut(missile);
    mo.momx = Fixed::ZERO;
    mo.momy = Fixed::ZERO;
    mo.momz = Fixed::ZERO;
    let kind = mo.kind;
    let death = sim.info.things[kind].deathstate;
    sim.set_mobj_state(missile, death);
    // Doom goes on with the freed body if the death state removed it.
    shorten_tics(sim, missile);
    sim.mo_mut(missile).flags &= !mf::MISSILE;
    let sound = sim.info.things[kind].deathsound;
    sim.sound(Some(missile), sound);
}
