//! Where a state's action goes: actions on bodies (`actionf_p1`, most of
//! them in `monsters.rs`) and actions on a player's weapon sprite
//! (`actionf_p2`, in `weapons.rs`); ZDoom's marines' actions are
//! `marines.rs`. The actor table names actions
//! ([`crate::actors::actions`]); each module matches the names it
//! implements.

use super::{marines, monsters, weapons, MobjId, Sim};
use crate::actors::{actions, ActionCall};

/// Runs a body's state action.
pub fn call_mobj(sim: &mut Sim, id: MobjId, call: &ActionCall) {
    let name = actions::spec(call.action).name;
    if !marines::action(sim, id, name, call) {
        monsters::action(sim, id, name, call);
    }
}

/// Runs a weapon sprite's state action for player `player`'s sprite `psp`
/// (0 the weapon, 1 its flash).
pub fn call_weapon(sim: &mut Sim, player: usize, psp: usize, call: &ActionCall) {
    let name = actions::spec(call.action).name;
    weapons::action(sim, player, psp, name, call);
}
