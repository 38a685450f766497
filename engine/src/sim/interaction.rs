//! Things meeting things (`p_inter.c`): pickups (`P_TouchSpecialThing`),
//! damage (`P_DamageMobj`) and death (`P_KillMobj`).

use super::{MobjId, Sim};

/// `P_DamageMobj`: `target` hurt by `damage` from `inflictor` (what hit
/// it) fired by `source` (who is to blame).
pub fn damage_mobj(sim: &mut Sim, target: MobjId, inflictor: Option<MobjId>, source: Option<MobjId>, damage: i32) {
    let _ = (sim, target, inflictor, source, damage);
}

/// `P_TouchSpecialThing`: `toucher` walks onto the item `special`.
pub fn touch_special_thing(sim: &mut Sim, special: MobjId, toucher: MobjId) {
    let _ = (sim, special, toucher);
}
