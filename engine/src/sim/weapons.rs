//! The player's weapons (`p_pspr.c`): the weapon and flash sprites'
//! states, raising and lowering, firing, and every weapon action.

use super::Sim;
use crate::actors::ActionCall;

/// Runs weapon action `name` for player `player`'s sprite `psp`.
pub fn action(sim: &mut Sim, player: usize, psp: usize, name: &str, call: &ActionCall) {
    let _ = (sim, player, psp, name, call);
}

/// `P_SetupPsprites`: a new body's weapon comes up.
pub fn setup_psprites(sim: &mut Sim, player: usize) {
    let _ = (sim, player);
}

/// `P_DropWeapon`: player `player`'s weapon goes down (death, a change).
pub fn drop_weapon(sim: &mut Sim, player: usize) {
    let _ = (sim, player);
}

/// `P_MovePsprites`: the weapon sprites' tics.
pub fn move_psprites(sim: &mut Sim, player: usize) {
    let _ = (sim, player);
}
