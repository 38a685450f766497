//! Moves and what they touch (`p_map.c`): `P_CheckPosition`, `P_TryMove`,
//! `P_SlideMove`, `P_TeleportMove`, hitscan aiming and shooting
//! (`P_AimLineAttack`, `P_LineAttack`), using lines (`P_UseLines`), blast
//! damage (`P_RadiusAttack`) and crushing (`P_ChangeSector`).

use super::MobjId;
use crate::fixed::Fixed;

/// `p_map.c`'s globals: what the last position check, move or trace found.
#[derive(Clone, Debug, Default, PartialEq)]
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
}

use super::Sim;
use crate::fixed::Angle;

/// `P_CheckPosition`: whether `thing` fits at `x`, `y` (things and lines
/// in the way), filling [`Sim::tm`] with the floor, ceiling and drop-off
/// there and the special lines touched.
pub fn check_position(sim: &mut Sim, thing: MobjId, x: Fixed, y: Fixed) -> bool {
    let _ = (sim, thing, x, y);
    true
}

/// `P_TryMove`: moves `thing` to `x`, `y` if it fits and may step there,
/// crossing the special lines passed.
pub fn try_move(sim: &mut Sim, thing: MobjId, x: Fixed, y: Fixed) -> bool {
    let _ = (sim, thing, x, y);
    false
}

/// `P_TeleportMove`: puts `thing` at `x`, `y`, telefragging what is there.
pub fn teleport_move(sim: &mut Sim, thing: MobjId, x: Fixed, y: Fixed) -> bool {
    let _ = (sim, thing, x, y);
    false
}

/// `P_SlideMove`: the player's move along the wall it ran into.
pub fn slide_move(sim: &mut Sim, thing: MobjId) {
    let _ = (sim, thing);
}

/// `P_AimLineAttack`: the slope to the first shootable thing along
/// `angle` within `distance`; sets `sim.tm.linetarget`.
pub fn aim_line_attack(sim: &mut Sim, shooter: MobjId, angle: Angle, distance: Fixed) -> Fixed {
    let _ = (sim, shooter, angle, distance);
    Fixed::ZERO
}

/// `P_LineAttack`: a hitscan shot along `angle` and `slope` that hurts the
/// first thing it meets by `damage`, or puffs on a wall.
pub fn line_attack(sim: &mut Sim, shooter: MobjId, angle: Angle, distance: Fixed, slope: Fixed, damage: i32) {
    let _ = (sim, shooter, angle, distance, slope, damage);
}

/// `P_UseLines`: player `player` presses use.
pub fn use_lines(sim: &mut Sim, player: usize) {
    let _ = (sim, player);
}

/// `P_RadiusAttack`: `damage` at `spot`, falling off with distance, from
/// `source`.
pub fn radius_attack(sim: &mut Sim, spot: MobjId, source: Option<MobjId>, damage: i32) {
    let _ = (sim, spot, source, damage);
}

/// `P_ChangeSector`: after a floor or ceiling moved, every thing near the
/// sector is fitted again (crushed where `crunch`); whether something no
/// longer fits.
pub fn change_sector(sim: &mut Sim, sector: usize, crunch: bool) -> bool {
    let _ = (sim, sector, crunch);
    false
}
