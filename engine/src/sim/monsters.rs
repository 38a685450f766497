//! Monster behaviour (`p_enemy.c`): looking, chasing, moving by directions,
//! every attack and death action, and the boss brain.

use super::{MobjId, Sim};
use crate::actors::ActionCall;

/// The boss brain's state (`braintargets`, `braintargeton`, `easy`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BrainState {
    pub targets: Vec<MobjId>,
    pub target_on: usize,
    pub easy: bool,
}

/// Runs body action `name` on `id`.
pub fn action(sim: &mut Sim, id: MobjId, name: &str, call: &ActionCall) {
    let _ = (sim, id, name, call);
}

/// `P_NoiseAlert`: `emitter`'s noise spreads through sound-connected
/// sectors, waking monsters to `target`.
pub fn noise_alert(sim: &mut Sim, target: MobjId, emitter: MobjId) {
    let _ = (sim, target, emitter);
}
