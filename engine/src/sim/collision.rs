//! Moves and what they touch (`p_map.c`): `P_CheckPosition`, `P_TryMove`,
//! `P_SlideMove`, `P_TeleportMove`, `P_ThingHeightClip` and crushing
//! (`P_ChangeSector`). The hitscan half of `p_map.c` (aiming, shooting,
//! using lines, blast damage) is `hitscan.rs`, whose entry points are
//! re-exported here. What a check found is left in [`MapCheck`]
//! (`sim.tm`), as Doom leaves it in its globals, for `P_XYMovement` and
//! the monsters' `P_Move` to read.

use super::level::{BOXBOTTOM, BOXLEFT, BOXRIGHT, BOXTOP, MAPBLOCKSHIFT, MAXRADIUS};
use super::maputl::{self, Opening};
use super::mobj::{mf, point_in_subsector};
use super::{info::mt, interaction, specials, Compat, MobjId, Sim};
use crate::fixed::{Fixed, FRACUNIT};

pub use super::hitscan::{aim_line_attack, line_attack, radius_attack, use_lines};

/// `p_map.c`'s globals: what the last position check, move or trace found.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct MapCheck {
    pub thing: Option<MobjId>,
    pub flags: u32,
    pub x: Fixed,
    pub y: Fixed,
    pub bbox: [Fixed; 4],
    pub floorz: Fixed,
    pub ceilingz: Fixed,
    pub dropoffz: Fixed,
    /// The line whose opening set the ceiling (missiles hitting the sky).
    pub ceilingline: Option<usize>,
    /// Special lines crossed by the move (`spechit`).
    pub spechit: Vec<usize>,
    /// The move may go on by floating up or down (`floatok`).
    pub floatok: bool,
    /// What the last aim or shot hit (`linetarget`).
    pub linetarget: Option<MobjId>,
    /// The last aim's or shot's reach (`attackrange`): a puff spawned at
    /// melee range shows only its last frames, and `A_Tracer`'s puff reads
    /// whatever the last shot left here, as in Doom.
    pub attackrange: Fixed,
    /// `P_LineOpening`'s last answer (`opentop`, `openbottom`, ...).
    pub opening: Opening,
    /// The slopes a sight check or an aim is bounded by (`topslope`,
    /// `bottomslope`: one pair of globals shared by `p_sight.c` and
    /// `p_map.c`).
    pub topslope: Fixed,
    pub bottomslope: Fixed,
    /// `P_ChangeSector`'s `crushchange` and `nofit` (globals, because the
    /// spechit overrun can write them).
    pub crushchange: bool,
    pub nofit: bool,
}

/// Above this many special lines vanilla's `spechit[8]` overflows
/// (`MAXSPECIALCROSS_ORIGINAL`).
const MAXSPECIALCROSS_ORIGINAL: usize = 8;
/// The base address Chocolate Doom (after PrBoom-plus) gives the overrun's
/// writes (`DEFAULT_SPECHIT_MAGIC`).
const SPECHIT_MAGIC: u32 = 0x01C0_9C98;
/// The highest step a walker takes (24 units).
const STEP: Fixed = Fixed(24 * FRACUNIT);

/// Blockmap cell of a map coordinate (`(v - org) >> MAPBLOCKSHIFT`).
fn cell(v: Fixed, org: Fixed) -> i32 {
    (v - org).0 >> MAPBLOCKSHIFT
}

/// The start of `P_CheckPosition` and `P_TeleportMove`: the globals set for
/// `thing` at `x`, `y`, the floor and ceiling those of the sector there.
fn begin_check(sim: &mut Sim, thing: MobjId, x: Fixed, y: Fixed) {
    let (radius, flags) = (sim.mo(thing).radius, sim.mo(thing).flags);
    let sector = sim.level.subsectors[point_in_subsector(&sim.level, x, y)].sector;
    let (floor, ceiling) = (sim.level.sectors[sector].floorheight, sim.level.sectors[sector].ceilingheight);
    let tm = &mut sim.tm;
    tm.thing = Some(thing);
    tm.flags = flags;
    tm.x = x;
    tm.y = y;
    tm.bbox[BOXTOP] = y + radius;
    tm.bbox[BOXBOTTOM] = y - radius;
    tm.bbox[BOXRIGHT] = x + radius;
    tm.bbox[BOXLEFT] = x - radius;
    tm.ceilingline = None;
    tm.floorz = floor;
    tm.dropoffz = floor;
    tm.ceilingz = ceiling;
    maputl::next_validcount(sim);
    sim.tm.spechit.clear();
}

/// Calls `f` on the bodies of every cell the box could reach, grown by
/// `MAXRADIUS` (bodies are filed by their centres), x-major as Doom loops;
/// whether every call returned true.
fn things_around(sim: &mut Sim, mut f: impl FnMut(&mut Sim, MobjId) -> bool) -> bool {
    let (orgx, orgy) = (sim.level.blockmap.orgx, sim.level.blockmap.orgy);
    let b = sim.tm.bbox;
    let xl = cell(b[BOXLEFT] - MAXRADIUS, orgx);
    let xh = cell(b[BOXRIGHT] + MAXRADIUS, orgx);
    let yl = cell(b[BOXBOTTOM] - MAXRADIUS, orgy);
    let yh = cell(b[BOXTOP] + MAXRADIUS, orgy);
    for bx in xl..=xh {
        for by in yl..=yh {
            if !maputl::block_things(sim, bx, by, &mut f) {
                return false;
            }
        }
    }
    true
}

/// `P_CheckPosition`: whether `thing` fits at `x`, `y` (things and lines
/// in the way), filling [`Sim::tm`] with the floor, ceiling and drop-off
/// there and the special lines touched. Things come first (and may be
/// picked up), then lines.
pub fn check_position(sim: &mut Sim, thing: MobjId, x: Fixed, y: Fixed) -> bool {
    begin_check(sim, thing, x, y);
    if sim.tm.flags & mf::NOCLIP != 0 {
        return true;
    }
    if !things_around(sim, check_thing) {
        return false;
    }
    let (orgx, orgy) = (sim.level.blockmap.orgx, sim.level.blockmap.orgy);
    let b = sim.tm.bbox;
    let (xl, xh) = (cell(b[BOXLEFT], orgx), cell(b[BOXRIGHT], orgx));
    let (yl, yh) = (cell(b[BOXBOTTOM], orgy), cell(b[BOXTOP], orgy));
    for bx in xl..=xh {
        for by in yl..=yh {
            if !maputl::block_lines(sim, bx, by, check_line) {
                return false;
            }
        }
    }
    true
}

/// `PIT_CheckLine`: lowers the ceiling and raises the floor by each line
/// the box crosses, notes special ones; false for a line that blocks.
fn check_line(sim: &mut Sim, line: usize) -> bool {
    let ld = &sim.level.lines[line];
    if !maputl::box_touches_line(&sim.tm.bbox, ld) {
        return true;
    }
    if ld.backsector.is_none() {
        return false;
    }
    let thing = sim.tm.thing;
    let is_missile = thing.is_some_and(|t| sim.mo(t).has(mf::MISSILE));
    if !is_missile {
        if ld.flags & super::level::ml::BLOCKING != 0 {
            return false;
        }
        let is_player = thing.is_some_and(|t| sim.mo(t).player.is_some());
        if !is_player && ld.flags & super::level::ml::BLOCKMONSTERS != 0 {
            return false;
        }
    }
    let special = ld.special;
    maputl::line_opening(sim, line);
    let (o, tm) = (sim.tm.opening, &mut sim.tm);
    if o.top < tm.ceilingz {
        tm.ceilingz = o.top;
        tm.ceilingline = Some(line);
    }
    if o.bottom > tm.floorz {
        tm.floorz = o.bottom;
    }
    if o.lowfloor < tm.dropoffz {
        tm.dropoffz = o.lowfloor;
    }
    if special != 0 {
        tm.spechit.push(line);
        if tm.spechit.len() > MAXSPECIALCROSS_ORIGINAL && sim.rules.compat == Compat::Vanilla {
            spechit_overrun(sim, line);
        }
    }
    true
}

/// Vanilla's `spechit[8]` has no bounds check: the 9th to 14th entries
/// overwrite `tmbbox`, then `crushchange`, then `nofit`, which follow it in
/// doom.exe. Chocolate Doom emulates it with line addresses from a base
/// (`SpechitOverrun`, after PrBoom-plus); so do we. Later entries have no
/// emulation there either.
fn spechit_overrun(sim: &mut Sim, line: usize) {
    let addr = SPECHIT_MAGIC.wrapping_add((line as u32).wrapping_mul(0x3E)) as i32;
    let n = sim.tm.spechit.len();
    match n {
        9..=12 => sim.tm.bbox[n - 9] = Fixed(addr),
        13 => sim.tm.crushchange = addr != 0,
        14 => sim.tm.nofit = addr != 0,
        _ => {}
    }
}

/// `PIT_CheckThing`: a body in the way, a lost soul slamming into it, a
/// missile hitting it, or an item picked up; false stops the move.
fn check_thing(sim: &mut Sim, thing: MobjId) -> bool {
    let Some(tmthing) = sim.tm.thing else {
        return true;
    };
    let th = sim.mo(thing);
    if th.flags & (mf::SOLID | mf::SPECIAL | mf::SHOOTABLE) == 0 {
        return true;
    }
    let blockdist = th.radius + sim.mo(tmthing).radius;
    if (th.x - sim.tm.x).abs() >= blockdist || (th.y - sim.tm.y).abs() >= blockdist {
        return true;
    }
    if thing == tmthing {
        return true;
    }
    let tm_flags = sim.mo(tmthing).flags;
    if tm_flags & mf::SKULLFLY != 0 {
        let damage = (sim.p_random() % 8 + 1).wrapping_mul(sim.info.things[sim.mo(tmthing).kind].damage);
        interaction::damage_mobj(sim, thing, Some(tmthing), Some(tmthing), damage);
        let mo = sim.mo_mut(tmthing);
        mo.flags &= !mf::SKULLFLY;
        mo.momx = Fixed::ZERO;
        mo.momy = Fixed::ZERO;
        mo.momz = Fixed::ZERO;
        let spawn = sim.info.things[sim.mo(tmthing).kind].spawnstate;
        sim.set_mobj_state(tmthing, spawn);
        return false;
    }
    if tm_flags & mf::MISSILE != 0 {
        return missile_hits(sim, tmthing, thing);
    }
    let th = sim.mo(thing);
    if th.has(mf::SPECIAL) {
        let solid = th.has(mf::SOLID);
        if sim.tm.flags & mf::PICKUP != 0 {
            interaction::touch_special_thing(sim, thing, tmthing);
        }
        return !solid;
    }
    !th.has(mf::SOLID)
}

/// The missile half of `PIT_CheckThing`: over or under it goes on; its own
/// shooter and the shooter's species are not hurt (a player's missiles
/// hurt players); otherwise damage of 1d8 times the missile's, and stop.
fn missile_hits(sim: &mut Sim, missile: MobjId, thing: MobjId) -> bool {
    let (m, th) = (sim.mo(missile), sim.mo(thing));
    if m.z > th.z + th.height || m.z + m.height < th.z {
        return true;
    }
    if let Some(target) = m.target {
        let (tk, hk) = (sim.mt(target), sim.mt(thing));
        let same = sim.mo(target).kind == th.kind
            || (tk == Some(mt::KNIGHT) && hk == Some(mt::BRUISER))
            || (tk == Some(mt::BRUISER) && hk == Some(mt::KNIGHT));
        if same {
            if thing == target {
                return true;
            }
            // Chocolate's deh_species_infighting (a DEHACKED setting) would
            // let them; Freedoom's patch leaves it off.
            if !sim.is(thing, mt::PLAYER) {
                return false;
            }
        }
    }
    if !th.has(mf::SHOOTABLE) {
        return !th.has(mf::SOLID);
    }
    let damage = (sim.p_random() % 8 + 1).wrapping_mul(sim.info.things[sim.mo(missile).kind].damage);
    let source = sim.mo(missile).target;
    interaction::damage_mobj(sim, thing, Some(missile), source, damage);
    false
}

/// `P_TryMove`: moves `thing` to `x`, `y` if it fits and may step there,
/// crossing the special lines passed.
pub fn try_move(sim: &mut Sim, thing: MobjId, x: Fixed, y: Fixed) -> bool {
    sim.tm.floatok = false;
    if !check_position(sim, thing, x, y) {
        return false;
    }
    let mo = sim.mo(thing);
    let (flags, z, height) = (mo.flags, mo.z, mo.height);
    if flags & mf::NOCLIP == 0 {
        let tm = &mut sim.tm;
        if tm.ceilingz - tm.floorz < height {
            return false;
        }
        tm.floatok = true;
        if flags & mf::TELEPORT == 0 && tm.ceilingz - z < height {
            return false;
        }
        if flags & mf::TELEPORT == 0 && tm.floorz - z > STEP {
            return false;
        }
        if flags & (mf::DROPOFF | mf::FLOAT) == 0 && tm.floorz - tm.dropoffz > STEP {
            return false;
        }
    }
    sim.unset_thing_position(thing);
    let (oldx, oldy) = (sim.mo(thing).x, sim.mo(thing).y);
    let (floorz, ceilingz) = (sim.tm.floorz, sim.tm.ceilingz);
    let mo = sim.mo_mut(thing);
    mo.floorz = floorz;
    mo.ceilingz = ceilingz;
    mo.x = x;
    mo.y = y;
    sim.set_thing_position(thing);
    if sim.mo(thing).flags & (mf::TELEPORT | mf::NOCLIP) == 0 {
        // Last touched first (`while (numspechit--)`). A crossing may
        // teleport the thing, whose P_TeleportMove empties the list: the
        // rest are then not crossed, as in Doom.
        while let Some(line) = sim.tm.spechit.pop() {
            let Some(ld) = sim.level.lines.get(line) else {
                continue;
            };
            let mo = sim.mo(thing);
            let side = maputl::point_on_map_line_side(mo.x, mo.y, ld);
            let oldside = maputl::point_on_map_line_side(oldx, oldy, ld);
            if side != oldside && ld.special != 0 {
                specials::cross_special_line(sim, line, oldside, thing);
            }
        }
    }
    true
}

/// `P_ThingHeightClip`: fits `thing` again to the floor and ceiling where
/// it stands (after a sector moved): a body on the floor rides it, a
/// floating one is pushed down only by the ceiling; whether it fits.
pub fn thing_height_clip(sim: &mut Sim, thing: MobjId) -> bool {
    let onfloor = sim.mo(thing).z == sim.mo(thing).floorz;
    let (x, y) = (sim.mo(thing).x, sim.mo(thing).y);
    check_position(sim, thing, x, y);
    let (floorz, ceilingz) = (sim.tm.floorz, sim.tm.ceilingz);
    let mo = sim.mo_mut(thing);
    mo.floorz = floorz;
    mo.ceilingz = ceilingz;
    if onfloor {
        mo.z = mo.floorz;
    } else if mo.z + mo.height > mo.ceilingz {
        mo.z = mo.ceilingz - mo.height;
    }
    mo.ceilingz - mo.floorz >= mo.height
}

/// Doom's `gamemap` from the level's name (`MAP30` is 30, `E2M8` is 8).
fn gamemap(sim: &Sim) -> i32 {
    let name = sim.level.name.to_ascii_uppercase();
    if let Some(n) = name.strip_prefix("MAP") {
        return n.parse().unwrap_or(0);
    }
    name.rsplit('M').next().and_then(|n| n.parse().ok()).unwrap_or(0)
}

/// `P_TeleportMove`: puts `thing` at `x`, `y`, telefragging what is there
/// (`PIT_StompThing`); a monster may telefrag only on MAP30.
pub fn teleport_move(sim: &mut Sim, thing: MobjId, x: Fixed, y: Fixed) -> bool {
    begin_check(sim, thing, x, y);
    let boss_level = gamemap(sim) == 30;
    let stomp = |sim: &mut Sim, th: MobjId| -> bool {
        let Some(tmthing) = sim.tm.thing else {
            return true;
        };
        let t = sim.mo(th);
        if !t.has(mf::SHOOTABLE) {
            return true;
        }
        let blockdist = t.radius + sim.mo(tmthing).radius;
        if (t.x - sim.tm.x).abs() >= blockdist || (t.y - sim.tm.y).abs() >= blockdist {
            return true;
        }
        if th == tmthing {
            return true;
        }
        if sim.mo(tmthing).player.is_none() && !boss_level {
            return false;
        }
        interaction::damage_mobj(sim, th, Some(tmthing), Some(tmthing), 10000);
        true
    };
    if !things_around(sim, stomp) {
        return false;
    }
    sim.unset_thing_position(thing);
    let (floorz, ceilingz) = (sim.tm.floorz, sim.tm.ceilingz);
    let mo = sim.mo_mut(thing);
    mo.floorz = floorz;
    mo.ceilingz = ceilingz;
    mo.x = x;
    mo.y = y;
    sim.set_thing_position(thing);
    true
}

/// `P_SlideMove`: the player's move along the wall it ran into.
pub fn slide_move(sim: &mut Sim, thing: MobjId) {
    super::slide::slide_move(sim, thing);
}

/// `P_ChangeSector`: after a floor or ceiling moved, every thing near the
/// sector is fitted again (crushed where `crunch`); whether something no
/// longer fits.
pub fn change_sector(sim: &mut Sim, sector: usize, crunch: bool) -> bool {
    sim.tm.nofit = false;
    sim.tm.crushchange = crunch;
    let Some(bb) = sim.level.sectors.get(sector).map(|s| s.blockbox) else {
        return false;
    };
    for x in bb[BOXLEFT]..=bb[BOXRIGHT] {
        for y in bb[BOXBOTTOM]..=bb[BOXTOP] {
            maputl::block_things(sim, x, y, change_thing);
        }
    }
    sim.tm.nofit
}

/// Doom's `MT_MISC71`, whose spawn state is `S_GIBS`.
const MT_GIBS: usize = 121;

/// `PIT_ChangeSector`: a body that no longer fits is gibbed if dead,
/// removed if a dropped item, otherwise hurt every fourth tic when
/// crushing, spraying blood.
fn change_thing(sim: &mut Sim, thing: MobjId) -> bool {
    if thing_height_clip(sim, thing) {
        return true;
    }
    if sim.mo(thing).health <= 0 {
        let gibs = sim.info.actor_of(MT_GIBS).and_then(|a| sim.info.things[a].spawnstate);
        sim.set_mobj_state(thing, gibs);
        // Doom 1.2 and earlier left the gibs solid; every version here is later.
        let mo = sim.mo_mut(thing);
        mo.flags &= !mf::SOLID;
        mo.height = Fixed::ZERO;
        mo.radius = Fixed::ZERO;
        return true;
    }
    if sim.mo(thing).has(mf::DROPPED) {
        sim.remove_mobj(thing);
        return true;
    }
    if !sim.mo(thing).has(mf::SHOOTABLE) {
        return true;
    }
    sim.tm.nofit = true;
    if sim.tm.crushchange && sim.leveltime & 3 == 0 {
        interaction::damage_mobj(sim, thing, None, None, 10);
        let mo = sim.mo(thing);
        let (x, y, z) = (mo.x, mo.y, mo.z + Fixed(mo.height.0 / 2));
        let blood = sim.kind_of(mt::BLOOD);
        let spray = sim.spawn_mobj(x, y, z, blood);
        let momx = Fixed(sim.rng.p_subrandom() << 12);
        let momy = Fixed(sim.rng.p_subrandom() << 12);
        let mo = sim.mo_mut(spray);
        mo.momx = momx;
        mo.momy = momy;
    }
    true
}

/// `BODYQUESIZE`: corpses kept in a netgame before the oldest goes.
const BODYQUESIZE: usize = 32;

/// `G_CheckSpot` (`g_game.c`): whether player `n` may spawn at the map
/// thing `spot`. `body` is the player's current body, `None` at the
/// level's first spawn, when (as in Doom) only an earlier player standing
/// exactly there blocks the spot. Otherwise the body must fit there
/// (`P_CheckPosition`); then it joins the body queue (the oldest of 32
/// corpses is removed) and a teleport fog appears 20 units ahead of the
/// spot, with Chocolate's emulation of vanilla's negative fine angles
/// (a spot facing west or south-west reads `finetangent`, putting the fog
/// thousands of units away) under vanilla's rules, and truly ahead under
/// Sightline's.
///
/// `sim.bodyque` holds every body queued this level, so its length is
/// Doom's `bodyqueslot`.
pub fn check_spot(sim: &mut Sim, n: usize, body: Option<MobjId>, spot: &crate::wad::level::WadThing) -> bool {
    let (x, y) = (Fixed::from_int(spot.x.into()), Fixed::from_int(spot.y.into()));
    let Some(mo) = body else {
        // Vanilla looks at the players before `n`: when deathmatch places
        // the players in turn they are the ones with bodies yet. A player
        // placed after the map's starts (`sim::starts`) may come before
        // some who have one, so every other player's own body is looked at.
        let stands_there = |i: usize| {
            let Some(p) = sim.player(i) else { return false };
            sim.mobjs.get(p.mo.0 as usize).is_some_and(|m| m.player == Some(i) && m.x == x && m.y == y)
        };
        return !(0..super::MAXPLAYERS).filter(|&i| i != n).any(stands_there);
    };
    if !check_position(sim, mo, x, y) {
        return false;
    }
    let slot = sim.bodyque.len();
    if slot >= BODYQUESIZE {
        sim.remove_mobj(sim.bodyque[slot - BODYQUESIZE]);
    }
    sim.bodyque.push(mo);
    let sector = sim.level.subsectors[point_in_subsector(&sim.level, x, y)].sector;
    let floor = sim.level.sectors[sector].floorheight;
    let (xa, ya) = match sim.rules.compat {
        super::Compat::Vanilla => spawn_fog_offset(i32::from(spot.angle)),
        // The fog 20 units ahead of the spot, whichever way it faces.
        super::Compat::Sightline => {
            let fine = (super::setup::thing_angle(spot).0 >> crate::fixed::ANGLETOFINESHIFT) as usize;
            (crate::fixed::finecosine(fine).0, crate::fixed::finesine(fine).0)
        }
    };
    let fog = sim.kind_of(mt::TFOG);
    let fog = sim.spawn_mobj(x + Fixed(xa.wrapping_mul(20)), y + Fixed(ya.wrapping_mul(20)), floor, fog);
    // No sound on the first frame (Doom's `viewz != 1` test).
    if sim.player(sim.console).is_some_and(|p| p.viewz != Fixed(1)) {
        sim.sound_named(Some(fog), "telept");
    }
    true
}

/// The fog's direction for a spot's angle: vanilla's `an` is
/// `ANG45 * (angle / 45) >> ANGLETOFINESHIFT` in a signed int, negative
/// from 180 degrees on, so its table reads fall before `finecosine` and
/// `finesine`, into `finetangent` (Chocolate's table of the cases, after
/// PrBoom-plus). An angle that is not a multiple of 45 from 0 to 360 is an
/// error in Chocolate; here it gives no offset.
fn spawn_fog_offset(angle: i32) -> (i32, i32) {
    use crate::fixed::{finecosine, finesine, finetangent, tantoangle};
    let an = 1024i32.wrapping_mul(angle / 45);
    match an {
        4096 => (finetangent(2048).0, finetangent(0).0),
        5120 => (finetangent(3072).0, finetangent(1024).0),
        6144 => (finesine(0).0, finetangent(2048).0),
        7168 => (finesine(1024).0, finetangent(3072).0),
        0 | 1024 | 2048 | 3072 => (finecosine(an as usize).0, finesine(an as usize).0),
        8192 => (tantoangle(0).0 as i32, finesine(8192).0),
        _ => (0, 0),
    }
}

#[cfg(test)]
#[path = "collision_tests.rs"]
mod tests;
