//! Lights (`p_lights.c`): flicker, flashes, strobes, glow, and light-level line specials.

use super::{Sim, ThinkerId};

/// The thinker's data.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Light {}

/// Runs the thinker one tic.
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let _ = (sim, id);
}
