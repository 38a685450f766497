//! One tick's player input, as the window samples it (or a demo replays it):
//! the only thing the simulation reads from the outside world.

use serde::{Deserialize, Serialize};

/// What the player asked for during one 1/35 s tick.
///
/// Values are clamped when used ([`TickInput::sanitized`]): a demo file or a
/// window can hand over any bit pattern without making the simulation misbehave.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct TickInput {
    /// -1 back, 0, 1 forward.
    pub forward: i8,
    /// -1 left, 0, 1 right.
    pub strafe: i8,
    /// Degrees to turn this tick, counter-clockwise positive (keys or mouse).
    pub turn: f32,
    pub run: bool,
    /// Use (open a door, press a switch) was held or pressed during this tick;
    /// it acts once per press.
    pub use_line: bool,
    /// Fire was held or pressed during this tick (until weapons come, a shot
    /// only sets off the lines it crosses); it acts once per press.
    pub fire: bool,
}

impl TickInput {
    /// `forward` and `strafe` clamped to -1..=1, a non-finite `turn` as 0.
    pub fn sanitized(&self) -> TickInput {
        TickInput {
            forward: self.forward.clamp(-1, 1),
            strafe: self.strafe.clamp(-1, 1),
            turn: if self.turn.is_finite() { self.turn } else { 0.0 },
            run: self.run,
            use_line: self.use_line,
            fire: self.fire,
        }
    }
}
