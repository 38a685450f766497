//! Ceilings and crushers (`p_ceilng.c`): `T_MoveCeiling`, `EV_DoCeiling`, stasis.

use super::{Sim, ThinkerId};

/// The thinker's data.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ceiling {}

/// Runs the thinker one tic.
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let _ = (sim, id);
}
