//! Floors (`p_floor.c`): the shared mover `T_MovePlane`, `T_MoveFloor`, `EV_DoFloor`, stairs (`EV_BuildStairs`) and donuts.

use super::{Sim, ThinkerId};

/// The thinker's data.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FloorMove {}

/// Runs the thinker one tic.
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let _ = (sim, id);
}
