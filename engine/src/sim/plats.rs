//! Lifts and platforms (`p_plats.c`): `T_PlatRaise`, `EV_DoPlat`, stasis.

use super::{Sim, ThinkerId};

/// The thinker's data.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Plat {}

/// Runs the thinker one tic.
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let _ = (sim, id);
}
