//! Switches (`p_switch.c`): the switch textures' pairs, a pressed switch's
//! texture and its return, and what a used line does (`P_UseSpecialLine`).

use super::{MobjId, Sim};

/// `P_UseSpecialLine`: `thing` used line `line` from side `side`; whether
/// the line did anything.
pub fn use_special_line(sim: &mut Sim, thing: MobjId, line: usize, side: usize) -> bool {
    let _ = (sim, thing, line, side);
    false
}
