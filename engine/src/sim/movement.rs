//! How bodies move (`p_mobj.c`): `P_MobjThinker` (momentum, gravity, state
//! tics), `P_XYMovement` with friction and sliding, `P_ZMovement`, and the
//! spawning of missiles, puffs and blood.

use super::{MobjId, Sim};

/// `P_MobjThinker`.
pub fn mobj_thinker(sim: &mut Sim, id: MobjId) {
    let _ = (sim, id);
}

use crate::fixed::Fixed;

/// `P_SpawnPuff`: a bullet puff at `x`, `y`, `z`.
pub fn spawn_puff(sim: &mut Sim, x: Fixed, y: Fixed, z: Fixed) {
    let _ = (sim, x, y, z);
}

/// `P_SpawnBlood`.
pub fn spawn_blood(sim: &mut Sim, x: Fixed, y: Fixed, z: Fixed, damage: i32) {
    let _ = (sim, x, y, z, damage);
}

/// `P_SpawnMissile`: a missile of `kind` from `source` at `dest`.
pub fn spawn_missile(sim: &mut Sim, source: MobjId, dest: MobjId, kind: usize) -> Option<MobjId> {
    let _ = (sim, source, dest, kind);
    None
}

/// `P_SpawnPlayerMissile`: a player's missile, auto-aimed.
pub fn spawn_player_missile(sim: &mut Sim, source: MobjId, kind: usize) {
    let _ = (sim, source, kind);
}

/// `P_ExplodeMissile`.
pub fn explode_missile(sim: &mut Sim, missile: MobjId) {
    let _ = (sim, missile);
}
