//! Teleporters (`p_telept.c`): `EV_Teleport` puts a thing on the first
//! teleport destination (in thinker order) standing in a sector the line
//! tags, with a fog at each end.

use super::info::mt;
use super::mobj::mf;
use super::think::{Status, ThinkerKind};
use super::{collision, GameVersion, MobjId, Sim};
use crate::fixed::{finecosine, finesine, Fixed};

/// `EV_Teleport`: `thing` crossed teleport line `line` from `side`.
/// Missiles and things crossing from the back stay; a destination that
/// is blocked (`P_TeleportMove` fails) ends the search. The player is
/// held still 18 tics. Whether the thing moved.
pub fn teleport(sim: &mut Sim, line: usize, side: usize, thing: MobjId) -> bool {
    if sim.mo(thing).has(mf::MISSILE) || side == 1 {
        return false;
    }
    let tag = sim.level.lines[line].tag;
    for s in 0..sim.level.sectors.len() {
        if sim.level.sectors[s].tag != tag {
            continue;
        }
        if let Some(dest) = destination_in(sim, s) {
            return teleport_to(sim, thing, dest);
        }
    }
    false
}

/// The first teleport destination, in thinker order, in sector `s`.
fn destination_in(sim: &Sim, s: usize) -> Option<MobjId> {
    sim.thinkers.iter().find_map(|t| match (&t.kind, t.status) {
        (ThinkerKind::Mobj(m), Status::Active) if sim.is(*m, mt::TELEPORTMAN) && sim.sector_of(*m) == s => Some(*m),
        _ => None,
    })
}

fn teleport_to(sim: &mut Sim, thing: MobjId, dest: MobjId) -> bool {
    let (oldx, oldy, oldz) = (sim.mo(thing).x, sim.mo(thing).y, sim.mo(thing).z);
    let (dx, dy, dangle) = (sim.mo(dest).x, sim.mo(dest).y, sim.mo(dest).angle);
    if !collision::teleport_move(sim, thing, dx, dy) {
        return false;
    }
    // The first Final Doom executable leaves z where it was.
    if sim.rules.version != GameVersion::Final {
        let floorz = sim.mo(thing).floorz;
        sim.mo_mut(thing).z = floorz;
    }
    let z = sim.mo(thing).z;
    let player = sim.mo(thing).player;
    if let Some(p) = player.and_then(|n| sim.players[n].as_mut()) {
        p.viewz = z + p.viewheight;
    }
    let fog_kind = sim.kind_of(mt::TFOG);
    let fog = sim.spawn_mobj(oldx, oldy, oldz, fog_kind);
    sim.sound_named(Some(fog), "telept");
    let an = dangle.fine_index();
    let fog = sim.spawn_mobj(dx + finecosine(an) * 20, dy + finesine(an) * 20, z, fog_kind);
    sim.sound_named(Some(fog), "telept");
    let mo = sim.mo_mut(thing);
    if player.is_some() {
        mo.reactiontime = 18;
    }
    mo.angle = dangle;
    mo.momx = Fixed::ZERO;
    mo.momy = Fixed::ZERO;
    mo.momz = Fixed::ZERO;
    true
}
