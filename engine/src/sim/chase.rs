//! Walking by the eight directions (`p_enemy.c`'s `P_Move`, `P_TryWalk`,
//! `P_NewChaseDir`): a monster steps its kind's speed along its direction
//! through `P_TryMove`, opens doors it bumps into, floats towards its move's
//! floor, and when blocked picks a new direction in Doom's exact order,
//! spending `P_Random` where Doom does. `monsters.rs`'s `A_Chase` drives it.

use super::mobj::mf;
use super::{collision, switches, MobjId, Sim};
use crate::fixed::{Fixed, FRACUNIT};

/// `dirtype_t`: east, then counter-clockwise by 45 degrees; 8 is none.
pub const DI_EAST: i32 = 0;
pub const DI_NORTHEAST: i32 = 1;
pub const DI_NORTHWEST: i32 = 3;
pub const DI_WEST: i32 = 4;
pub const DI_SOUTHWEST: i32 = 5;
pub const DI_SOUTH: i32 = 6;
pub const DI_SOUTHEAST: i32 = 7;
pub const DI_NORTH: i32 = 2;
pub const DI_NODIR: i32 = 8;

/// `opposite[]`.
const OPPOSITE: [i32; 9] =
    [DI_WEST, DI_SOUTHWEST, DI_SOUTH, DI_SOUTHEAST, DI_EAST, DI_NORTHEAST, DI_NORTH, DI_NORTHWEST, DI_NODIR];
/// `diags[]`, indexed by `(dy < 0) << 1 | (dx > 0)`.
const DIAGS: [i32; 4] = [DI_NORTHWEST, DI_NORTHEAST, DI_SOUTHWEST, DI_SOUTHEAST];

/// `xspeed[]` and `yspeed[]`: a step's unit vector per direction (47000 is
/// Doom's rounding of cos 45 in 16.16).
pub const XSPEED: [Fixed; 8] =
    [Fixed(FRACUNIT), Fixed(47000), Fixed(0), Fixed(-47000), Fixed(-FRACUNIT), Fixed(-47000), Fixed(0), Fixed(47000)];
pub const YSPEED: [Fixed; 8] =
    [Fixed(0), Fixed(47000), Fixed(FRACUNIT), Fixed(47000), Fixed(0), Fixed(-47000), Fixed(-FRACUNIT), Fixed(-47000)];

/// `FLOATSPEED`: a floater's climb or descent a blocked step.
const FLOATSPEED: Fixed = Fixed(4 * FRACUNIT);

/// Where a step in direction `dir` from `(x, y)` at raw speed `speed`
/// lands (`actor->info->speed * xspeed[dir]`, an int times a fixed,
/// wrapping as Doom's int product does).
pub fn step(x: Fixed, y: Fixed, speed: i32, dir: usize) -> (Fixed, Fixed) {
    (x + XSPEED[dir] * speed, y + YSPEED[dir] * speed)
}

/// `P_Move`: one step along `movedir`. Blocked, a floater with room above
/// or below moves up or down instead; a walker that touched special lines
/// uses them (doors open for it) and counts as moved if any did something.
pub fn p_move(sim: &mut Sim, id: MobjId) -> bool {
    let actor = sim.mo(id);
    // Doom's I_Error("Weird actor->movedir!") for anything past 8.
    let Ok(dir) = usize::try_from(actor.movedir) else { return false };
    if dir >= 8 {
        return false;
    }
    let speed = sim.walk_speed(id);
    let (tryx, tryy) = step(actor.x, actor.y, speed, dir);
    if !collision::try_move(sim, id, tryx, tryy) {
        let actor = sim.mo(id);
        if actor.has(mf::FLOAT) && sim.tm.floatok {
            // Must adjust height.
            let tmfloorz = sim.tm.floorz;
            let actor = sim.mo_mut(id);
            if actor.z < tmfloorz {
                actor.z += FLOATSPEED;
            } else {
                actor.z -= FLOATSPEED;
            }
            actor.flags |= mf::INFLOAT;
            return true;
        }
        if sim.tm.spechit.is_empty() {
            return false;
        }
        sim.mo_mut(id).movedir = DI_NODIR;
        // Doom walks spechit from its last entry down (`while
        // (numspechit--)`); any line that does something makes it good.
        let lines: Vec<usize> = sim.tm.spechit.clone();
        let mut good = false;
        for &line in lines.iter().rev() {
            if switches::use_special_line(sim, id, line, 0) {
                good = true;
            }
        }
        return good;
    }
    let actor = sim.mo_mut(id);
    actor.flags &= !mf::INFLOAT;
    if !actor.has(mf::FLOAT) {
        actor.z = actor.floorz;
    }
    true
}

/// `P_TryWalk`: a step, then a new count of steps (`P_Random() & 15`)
/// before the next choice.
fn try_walk(sim: &mut Sim, id: MobjId) -> bool {
    if !p_move(sim, id) {
        return false;
    }
    let count = sim.p_random() & 15;
    sim.mo_mut(id).movecount = count;
    true
}

/// Tries direction `dir`: sets it and walks.
fn try_dir(sim: &mut Sim, id: MobjId, dir: i32) -> bool {
    sim.mo_mut(id).movedir = dir;
    try_walk(sim, id)
}

/// `P_NewChaseDir`: the diagonal towards the target, then the two straight
/// directions (swapped by `P_Random() > 200` or when the target is more
/// north-south than east-west), the old direction, every direction in a
/// random sense, and last turning round; never straight back unless
/// nothing else moves.
pub fn new_chase_dir(sim: &mut Sim, id: MobjId) {
    // Doom's I_Error("P_NewChaseDir: called with no target").
    let Some(target) = sim.mo(id).target else { return };
    let olddir = sim.mo(id).movedir;
    let turnaround = OPPOSITE.get(olddir as usize).copied().unwrap_or(DI_NODIR);
    let deltax = (sim.mo(target).x - sim.mo(id).x).0;
    let deltay = (sim.mo(target).y - sim.mo(id).y).0;
    let ten = 10 * FRACUNIT;
    let mut d1 = if deltax > ten {
        DI_EAST
    } else if deltax < -ten {
        DI_WEST
    } else {
        DI_NODIR
    };
    let mut d2 = if deltay < -ten {
        DI_SOUTH
    } else if deltay > ten {
        DI_NORTH
    } else {
        DI_NODIR
    };
    // Try the direct route.
    if d1 != DI_NODIR && d2 != DI_NODIR {
        let diag = DIAGS[(usize::from(deltay < 0) << 1) + usize::from(deltax > 0)];
        sim.mo_mut(id).movedir = diag;
        if diag != turnaround && try_walk(sim, id) {
            return;
        }
    }
    // Try the other directions; C's abs wraps at INT_MIN as wrapping_abs.
    if sim.p_random() > 200 || deltay.wrapping_abs() > deltax.wrapping_abs() {
        std::mem::swap(&mut d1, &mut d2);
    }
    if d1 == turnaround {
        d1 = DI_NODIR;
    }
    if d2 == turnaround {
        d2 = DI_NODIR;
    }
    if d1 != DI_NODIR && try_dir(sim, id, d1) {
        return; // either moved forward or attacked
    }
    if d2 != DI_NODIR && try_dir(sim, id, d2) {
        return;
    }
    // No direct path to the player: another direction.
    if olddir != DI_NODIR && try_dir(sim, id, olddir) {
        return;
    }
    // Randomly determine the sense of the search.
    let order: [i32; 8] = if sim.p_random() & 1 != 0 { [0, 1, 2, 3, 4, 5, 6, 7] } else { [7, 6, 5, 4, 3, 2, 1, 0] };
    for tdir in order {
        if tdir != turnaround && try_dir(sim, id, tdir) {
            return;
        }
    }
    if turnaround != DI_NODIR && try_dir(sim, id, turnaround) {
        return;
    }
    sim.mo_mut(id).movedir = DI_NODIR; // can not move
}
