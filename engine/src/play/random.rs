//! The game's one random generator. Every random choice the simulation
//! makes (a light's flicker, a lift's first direction) comes from it, in
//! tick order, so a game is a function of its seed and its inputs.

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};

#[derive(Debug)]
pub struct GameRng {
    rng: ChaCha8Rng,
}

impl GameRng {
    pub fn new(seed: u64) -> GameRng {
        GameRng { rng: ChaCha8Rng::seed_from_u64(seed) }
    }

    /// A byte, 0..=255: what Doom's P_Random returns, so Doom's formulas
    /// (`P_Random() & 7`) carry over.
    pub fn byte(&mut self) -> u8 {
        self.rng.random::<u8>()
    }
}
