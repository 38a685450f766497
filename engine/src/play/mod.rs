//! Play: what surrounds the game for a person, a test or a tool. The game
//! itself is the simulation with Doom's arithmetic ([`crate::sim`], driven
//! by [`crate::sim::game::SimGame`]); here are what a tick reads
//! ([`input`]), the player as the outside reads it ([`player`]), sounds and
//! messages out ([`events`]), a campaign of maps played in turn with
//! intermissions ([`playthrough`]), saved games ([`save`]), our own demos
//! ([`demo`]) and Doom's ([`lmp`], [`vanilla`]), the reference dumps a
//! demo is checked against ([`syncdump`], [`statdump`]) and live reload
//! ([`reload`]).

pub mod demo;
pub mod events;
pub mod input;
pub mod lmp;
pub mod player;
pub mod playthrough;
pub mod reload;
pub mod save;
pub mod statdump;
pub mod syncdump;
pub mod vanilla;
pub mod world;

pub use demo::{Demo, DemoError};
pub use input::TickInput;
pub use player::Player;
pub use world::Exit;

/// Simulation ticks per second (Doom's `TICRATE`).
pub const TICRATE: u32 = 35;
/// The skill a game has unless told otherwise: Doom's 3, "Hurt Me Plenty".
pub const DEFAULT_SKILL: u8 = 3;
/// How far ahead of the body's centre the player can use a line (Doom's `USERANGE`, 64).
pub const USE_RANGE: f64 = 64.0;

/// How a game is set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct GameOptions {
    /// 1 to 5, as Doom's: things appear by their skill flags.
    pub skill: u8,
    /// How far a RON map's game moves on in Doom's random table after the
    /// level's setup (its low byte for `P_Random`, the next for
    /// `M_Random`); a WAD's map does not, as vanilla does not.
    pub seed: u64,
    /// Monsters are not spawned (Doom's `-nomonsters`: nothing that counts
    /// as a kill, nor lost souls).
    #[serde(default)]
    pub no_monsters: bool,
}

impl Default for GameOptions {
    fn default() -> GameOptions {
        GameOptions { skill: DEFAULT_SKILL, seed: 0, no_monsters: false }
    }
}

/// The level's tallies, as the intermission shows them: found and total.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    pub kills: (u32, u32),
    pub items: (u32, u32),
    pub secrets: (u32, u32),
    /// Ticks played.
    pub ticks: u64,
}
