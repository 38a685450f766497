//! Teleporters (`p_telept.c`): `EV_Teleport` puts a thing on the first
//! teleport destination (in thinker order) standing in a sector the line
//! tags, with a fog at each end.

use super::info::mt;
use super::maputl::point_on_map_line_side;
use super::mobj::mf;
use super::think::{Status, ThinkerKind};
use super::{collision, GameVersion, MobjId, Sim};
use crate::fixed::{finecosine, finesine, point_to_angle2, Fixed, ANG180};

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

/// How far, in 1/65536 units, a line teleport may nudge a body off the
/// exit line to put it on the line's front side (rounding can leave the
/// interpolated point a hair behind it; Boom allows the same 10 steps).
const NUDGES: i32 = 10;

/// A silent line teleport (Boom's 244, Sightline's `LineTeleport`):
/// `thing` crossed `line` from its front and comes out of line `to` at the
/// same place along it (measured from its far end, so lines facing each
/// other mirror), on its front side, turned by the angle between the lines
/// plus a half turn, its momentum turned alike and its height above the
/// floor kept: no fog, no sound, no freeze. Missiles and crossings from
/// the back stay, and so does a thing whose exit is blocked (a player
/// telefrags, as at any teleporter). Whether it moved.
pub fn line_teleport(sim: &mut Sim, line: usize, to: usize, side: usize, thing: MobjId) -> bool {
    if sim.mo(thing).has(mf::MISSILE) || side == 1 || line == to {
        return false;
    }
    let (Some(src), Some(dst)) = (sim.level.lines.get(line), sim.level.lines.get(to)) else { return false };
    let (src, dst) = (src.clone(), dst.clone());
    let mo = sim.mo(thing);
    // Where along the source the thing crossed, 0 at its first vertex, in
    // the axis the line runs furthest along.
    let along = if src.dx.abs() > src.dy.abs() {
        (mo.x - src.v1.0).fixed_div(src.dx)
    } else {
        (mo.y - src.v1.1).fixed_div(src.dy)
    };
    let turn = ANG180 + point_to_angle2(Fixed::ZERO, Fixed::ZERO, dst.dx, dst.dy)
        - point_to_angle2(Fixed::ZERO, Fixed::ZERO, src.dx, src.dy);
    let (mut x, mut y) = (dst.v2.0 - along * dst.dx, dst.v2.1 - along * dst.dy);
    for _ in 0..NUDGES {
        if point_on_map_line_side(x, y, &dst) == 0 {
            break;
        }
        // Towards the front: the right of the line's direction.
        if dst.dx.abs() > dst.dy.abs() {
            y -= Fixed(dst.dx.0.signum());
        } else {
            x += Fixed(dst.dy.0.signum());
        }
    }
    let above = mo.z - mo.floorz;
    if !collision::teleport_move(sim, thing, x, y) {
        return false;
    }
    let (sin, cos) = (turn.sin(), turn.cos());
    let mo = sim.mo_mut(thing);
    mo.z = mo.floorz + above;
    mo.angle += turn;
    let (mx, my) = (mo.momx, mo.momy);
    mo.momx = mx * cos - my * sin;
    mo.momy = my * cos + mx * sin;
    let (z, player) = (mo.z, mo.player);
    if let Some(p) = player.and_then(|n| sim.players[n].as_mut()) {
        p.viewz = z + p.viewheight;
    }
    true
}
