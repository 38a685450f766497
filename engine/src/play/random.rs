//! The game's one random generator. Every random choice the simulation
//! makes (a light's flicker, a lift's first direction) comes from it, in
//! tick order, so a game is a function of its seed and its inputs. A saved
//! game keeps the generator's whole state (its seed, stream and position:
//! ChaCha's own 49-byte form), so a loaded game draws what the original would.

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

/// A copy that draws what the original would (a save takes one).
impl Clone for GameRng {
    fn clone(&self) -> GameRng {
        GameRng { rng: ChaCha8Rng::deserialize_state(&self.rng.serialize_state()) }
    }
}

impl serde::Serialize for GameRng {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_bytes(&self.rng.serialize_state())
    }
}

impl<'de> serde::Deserialize<'de> for GameRng {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<GameRng, D::Error> {
        let bytes: Vec<u8> = serde::Deserialize::deserialize(deserializer)?;
        let state: &[u8; 49] = bytes
            .as_slice()
            .try_into()
            .map_err(|_| serde::de::Error::invalid_length(bytes.len(), &"the random generator's 49 bytes of state"))?;
        Ok(GameRng { rng: ChaCha8Rng::deserialize_state(state) })
    }
}
