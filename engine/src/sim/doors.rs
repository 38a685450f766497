//! Doors (`p_doors.c`): `T_VerticalDoor` and `EV_DoDoor`, `EV_VerticalDoor` (doors opened by use, keys checked).

use super::{Sim, ThinkerId};

/// The thinker's data.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Door {}

/// Runs the thinker one tic.
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let _ = (sim, id);
}
