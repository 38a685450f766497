//! One tick's player input, as the window samples it (or a demo replays it):
//! the only thing the simulation reads from the outside world.

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
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
    /// Fire was held or pressed during this tick: the weapon fires, and
    /// keeps firing while it is held.
    pub fire: bool,
    /// A weapon asked for by its number key (1 to 7; 0: none): the first
    /// owned in that slot, or the next in the slot after the one in hand.
    #[serde(default)]
    pub weapon: u8,
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
            weapon: if self.weapon <= 7 { self.weapon } else { 0 },
        }
    }
}

/// Seeded input that mostly runs into things, for tests and benchmarks that
/// need a long, reproducible walk: a direction held for 1 to 140 ticks
/// (running seven times in ten), turning in bursts (now and then a mouse
/// fling), and, with `presses`, use pressed on one tick in 25. No fire.
pub fn wander(seed: u64, ticks: usize, presses: bool) -> Vec<TickInput> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut inputs = Vec::with_capacity(ticks);
    while inputs.len() < ticks {
        let hold = rng.random_range(1..=140usize);
        let forward = [1, 1, 1, 0, -1][rng.random_range(0..5usize)];
        let strafe = [0, 0, 0, 1, -1][rng.random_range(0..5usize)];
        let run = rng.random_range(0..10) < 7;
        let turn: f32 = match rng.random_range(0..10) {
            0..=5 => 0.0,
            6..=8 => rng.random_range(-8.0..8.0),
            _ => rng.random_range(-180.0..180.0),
        };
        let burst = rng.random_range(1..=hold);
        for k in 0..hold {
            let use_line = presses && rng.random_range(0..25) == 0;
            let turn = if k < burst { turn } else { 0.0 };
            inputs.push(TickInput { forward, strafe, turn, run, use_line, fire: false, weapon: 0 });
        }
    }
    inputs.truncate(ticks);
    inputs
}
