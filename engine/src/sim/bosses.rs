//! Bosses (`p_enemy.c`): the specials a boss kind's last death sets off
//! (`A_BossDeath` by game version and map, `A_KeenDie`), and the Icon of
//! Sin (`A_BrainAwake` finds the spawn spots, `A_BrainSpit` shoots cubes at
//! them in turn, `A_SpawnFly` turns a cube into a monster, the death's
//! explosions and the level's end). Floors and doors start through their
//! own modules; the level ends through `specials::exit_level`.

use super::floors::{self, FloorType};
use super::info::mt;
use super::monsters::{actor_arg, fall, look_for_players};
use super::{collision, doors, specials, GameMode, GameVersion, MobjId, Sim};
use crate::actors::ActionCall;
use crate::fixed::{Fixed, FRACUNIT};

/// Runs the boss action `name`.
pub fn action(sim: &mut Sim, id: MobjId, name: &str, call: &ActionCall) {
    match name {
        "A_BossDeath" => boss_death(sim, id),
        "A_KeenDie" => keen_die(sim, id),
        "A_BrainAwake" => brain_awake(sim),
        "A_BrainPain" => sim.sound_named(None, "bospn"),
        "A_BrainScream" => brain_scream(sim, id, call),
        "A_BrainExplode" => brain_explode(sim, id, call),
        "A_BrainDie" => specials::exit_level(sim, false),
        "A_BrainSpit" => brain_spit(sim, id, call),
        "A_SpawnSound" => {
            sim.sound_named(Some(id), "boscub");
            spawn_fly(sim, id, call);
        }
        "A_SpawnFly" => spawn_fly(sim, id, call),
        _ => {}
    }
}

/// `gameepisode` and `gamemap` from the level's lump name (`E1M8`, or
/// `MAP07` as episode 1).
fn episode_map(sim: &Sim) -> (i32, i32) {
    let name = sim.level.name.to_ascii_uppercase();
    if let Some(n) = name.strip_prefix("MAP") {
        return (1, n.parse().unwrap_or(0));
    }
    let b = name.as_bytes();
    if b.len() >= 4 && b[0] == b'E' && b[2] == b'M' {
        let episode = i32::from(b[1]) - i32::from(b'0');
        return (episode, name[3..].parse().unwrap_or(0));
    }
    (0, 0)
}

/// Whether some other body of `id`'s kind is still alive (the thinker scan
/// of `A_BossDeath` and `A_KeenDie`).
fn others_alive(sim: &Sim, id: MobjId) -> bool {
    let kind = sim.mo(id).kind;
    sim.live_mobjs().any(|m| m != id && sim.mo(m).kind == kind && sim.mo(m).health > 0)
}

/// Runs `f` with Doom's `junk` line: a line tagged `tag` that exists only
/// for the call (the movers take a line and read its tag), appended to the
/// level and taken away after.
fn with_junk_line(sim: &mut Sim, tag: i16, f: impl FnOnce(&mut Sim, usize)) {
    let Some(mut junk) = sim.level.lines.first().cloned() else { return };
    junk.tag = tag;
    junk.special = 0;
    sim.level.lines.push(junk);
    let at = sim.level.lines.len() - 1;
    f(sim, at);
    sim.level.lines.truncate(at);
}

/// `CheckBossEnd`: whether kind `kind` dying ends this map's boss fight.
/// Before The Ultimate Doom any boss on any episode's map 8 did (barons
/// only on episode 1); from it on, each episode's own boss.
fn check_boss_end(sim: &Sim, id: MobjId) -> bool {
    let (episode, map) = episode_map(sim);
    let is = |m| sim.is(id, m);
    if sim.rules.version == GameVersion::Doom19 {
        map == 8 && !(is(mt::BRUISER) && episode != 1)
    } else {
        match episode {
            1 => map == 8 && is(mt::BRUISER),
            2 => map == 8 && is(mt::CYBORG),
            3 => map == 8 && is(mt::SPIDER),
            4 => (map == 6 && is(mt::CYBORG)) || (map == 8 && is(mt::SPIDER)),
            _ => map == 8,
        }
    }
}

/// `A_BossDeath`: when the last of a boss kind dies with a player alive,
/// MAP07's floors (tag 666 down for the mancubi, 667 up for the
/// arachnotrons), E1M8's and E4M8's floors, E4M6's door, or else the
/// level's end.
fn boss_death(sim: &mut Sim, id: MobjId) {
    let (episode, map) = episode_map(sim);
    let commercial = sim.rules.mode == GameMode::Commercial;
    if commercial {
        if map != 7 || !(sim.is(id, mt::FATSO) || sim.is(id, mt::BABY)) {
            return;
        }
    } else if !check_boss_end(sim, id) {
        return;
    }
    // Make sure there is a player alive for victory.
    if !sim.players.iter().flatten().any(|p| p.health > 0) {
        return;
    }
    if others_alive(sim, id) {
        return;
    }
    if commercial {
        if sim.is(id, mt::FATSO) {
            boss_floor(sim, 666, FloorType::LowerFloorToLowest);
            return;
        }
        if sim.is(id, mt::BABY) {
            boss_floor(sim, 667, FloorType::RaiseToTexture);
            return;
        }
    } else {
        match (episode, map) {
            (1, _) | (4, 8) => {
                boss_floor(sim, 666, FloorType::LowerFloorToLowest);
                return;
            }
            (4, 6) => {
                with_junk_line(sim, 666, |sim, line| {
                    doors::do_door(sim, line, doors::DoorType::BlazeOpen);
                });
                return;
            }
            _ => {}
        }
    }
    specials::exit_level(sim, false);
}

/// `EV_DoFloor(&junk, how)` on the sectors tagged `tag`.
fn boss_floor(sim: &mut Sim, tag: i16, how: FloorType) {
    with_junk_line(sim, tag, |sim, line| {
        floors::do_floor(sim, line, how);
    });
}

/// `A_KeenDie`: falls; when no other of its kind lives, tag 666's doors
/// open (MAP32).
fn keen_die(sim: &mut Sim, id: MobjId) {
    fall(sim, id);
    if others_alive(sim, id) {
        return;
    }
    with_junk_line(sim, 666, |sim, line| {
        doors::do_door(sim, line, doors::DoorType::Open);
    });
}

/// `A_BrainAwake`: the spawn spots, every `MT_BOSSTARGET` in thinker order,
/// aimed at from the first. (Vanilla's array holds 32 and overflows past
/// them; no map in the demos has more.)
fn brain_awake(sim: &mut Sim) {
    let targets: Vec<MobjId> = sim.live_mobjs().filter(|&m| sim.is(m, mt::BOSSTARGET)).collect();
    sim.brain.targets = targets;
    sim.brain.target_on = 0;
    sim.sound_named(None, "bossit");
}

/// One explosion of the brain's death: a rocket (Doom spawns `MT_ROCKET`
/// and puts it in `S_BRAINEXPLODE1`, here the explosion actor's first
/// state) at `x`, `y` and 128 plus a random height, rising at random,
/// its first tics shortened at random.
fn brain_explosion(sim: &mut Sim, call: &ActionCall, x: Fixed, y: Fixed) {
    let z = Fixed(128i32.wrapping_add(sim.p_random() * 2 * FRACUNIT));
    let rocket = sim.kind_of(mt::ROCKET);
    let th = sim.spawn_mobj(x, y, z, rocket);
    let momz = sim.p_random() * 512;
    sim.mo_mut(th).momz = Fixed(momz);
    let explosion = actor_arg(sim, call, mt::ROCKET);
    let state = sim.info.things[explosion].spawnstate;
    if !sim.set_mobj_state(th, state) {
        return;
    }
    let r = sim.p_random() & 7;
    let th = sim.mo_mut(th);
    th.tics = (th.tics - r).max(1);
}

/// `A_BrainScream`: a row of explosions every 8 units from 196 left to 320
/// right of the brain, 320 units in front of it (south), and the death
/// cry.
fn brain_scream(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    let (mx, my) = (sim.mo(id).x, sim.mo(id).y);
    let y = my - Fixed(320 * FRACUNIT);
    let end = i64::from(mx.0) + i64::from(320 * FRACUNIT);
    let mut x = i64::from(mx.0) - i64::from(196 * FRACUNIT);
    while x < end {
        brain_explosion(sim, call, Fixed(x as i32), y);
        x += i64::from(8 * FRACUNIT);
    }
    sim.sound_named(None, "bosdth");
}

/// `A_BrainExplode`: one more explosion, up to 255 * 2048 / 65536 units
/// either side of the body.
fn brain_explode(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    let r = sim.rng.p_subrandom();
    let (mx, my) = (sim.mo(id).x, sim.mo(id).y);
    brain_explosion(sim, call, Fixed(mx.0.wrapping_add(r.wrapping_mul(2048))), my);
}

/// `A_BrainSpit`: every other call on the easy skills, a cube at the next
/// spawn spot, flying for as many of its state's tics as it takes to get
/// there north-south (plain int divisions, as Doom's).
fn brain_spit(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    sim.brain.easy = !sim.brain.easy;
    if sim.rules.skill <= 1 && !sim.brain.easy {
        return;
    }
    // Vanilla crashes with no spots (Chocolate's I_Error); nothing here.
    let n = sim.brain.targets.len();
    let Some(&targ) = sim.brain.targets.get(sim.brain.target_on) else { return };
    sim.brain.target_on = (sim.brain.target_on + 1) % n;
    let kind = actor_arg(sim, call, mt::SPAWNSHOT);
    if let Some(cube) = super::movement::spawn_missile(sim, id, targ, kind) {
        let tics = sim.mo(cube).state.map_or(0, |s| sim.info.state(s).tics);
        let flight = (sim.mo(targ).y - sim.mo(id).y).0.checked_div(sim.mo(cube).momy.0).unwrap_or(0);
        let c = sim.mo_mut(cube);
        c.target = Some(targ);
        c.reactiontime = flight.checked_div(tics).unwrap_or(0);
    }
    sim.sound_named(None, "bospit");
}

/// `A_SpawnFly`: when its flight time is up, the cube becomes fire and a
/// monster at its spot (by `P_Random`'s table of odds), which looks round
/// for players at once and telefrags what stands there; the cube goes.
fn spawn_fly(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    let m = sim.mo_mut(id);
    m.reactiontime -= 1;
    if m.reactiontime != 0 {
        return; // still flying
    }
    // P_SubstNullMobj: a cube without a target spawns at the origin.
    let (x, y, z) = sim.mo(id).target.map_or((Fixed::ZERO, Fixed::ZERO, Fixed::ZERO), |t| {
        let t = sim.mo(t);
        (t.x, t.y, t.z)
    });
    let fire = actor_arg(sim, call, mt::SPAWNFIRE);
    let fog = sim.spawn_mobj(x, y, z, fire);
    sim.sound_named(Some(fog), "telept");
    // The probabilities fall off down the list.
    let r = sim.p_random();
    let kind = match r {
        0..50 => mt::TROOP,
        50..90 => mt::SERGEANT,
        90..120 => mt::SHADOWS,
        120..130 => mt::PAIN,
        130..160 => mt::HEAD,
        160..162 => mt::VILE,
        162..172 => mt::UNDEAD,
        172..192 => mt::BABY,
        192..222 => mt::FATSO,
        222..246 => mt::KNIGHT,
        _ => mt::BRUISER,
    };
    let kind = sim.kind_of(kind);
    let newmobj = sim.spawn_mobj(x, y, z, kind);
    if look_for_players(sim, newmobj, true) {
        let see = sim.info.things[kind].seestate;
        sim.set_mobj_state(newmobj, see);
    }
    // Telefrag anything in this spot.
    let (nx, ny) = (sim.mo(newmobj).x, sim.mo(newmobj).y);
    collision::teleport_move(sim, newmobj, nx, ny);
    sim.remove_mobj(id);
}
