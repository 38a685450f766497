//! The player's own thinking (`p_user.c`): `P_PlayerThink`, moving by the
//! command (`P_MovePlayer`, `P_Thrust`), the view's height and bob
//! (`P_CalcHeight`), and dying (`P_DeathThink`).

use super::Sim;

/// `P_PlayerThink` for player `n`.
pub fn player_think(sim: &mut Sim, n: usize) {
    let _ = (sim, n);
}
