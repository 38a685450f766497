//! Geometry questions over the level (`p_maputl.c`): which side of a line a
//! box is on, the opening between two sectors, the blockmap's line and
//! thing iterators, and `P_PathTraverse` with its intercepts in Doom's order.

use super::{MobjId, Sim};

/// `P_BlockThingsIterator`: `f` on each body linked in cell (`x`, `y`), in
/// Doom's order (most recently linked first), until it returns false;
/// whether every call returned true.
pub fn block_things(sim: &mut Sim, x: i32, y: i32, mut f: impl FnMut(&mut Sim, MobjId) -> bool) -> bool {
    let _ = (sim, x, y, &mut f);
    true
}
