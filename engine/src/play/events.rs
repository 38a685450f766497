//! What the simulation tells the world outside it each tick: sounds to play
//! and messages to show. The simulation never touches a device; the window,
//! the audio thread and the tests read the same events.

use glam::DVec2;

use super::world::SpecialLine;

/// Where a sound comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Origin {
    /// The listener itself (centred, full volume).
    Player,
    /// A sector's middle (doors, lifts, floors: Doom's `soundorg`).
    Sector(usize),
    /// An actor, where it stood when the sound began (a new sound from the
    /// same actor cuts off its last; the sound follows the actor).
    Actor { index: u32, pos: DVec2 },
    /// A point in the map with no one behind it (a teleport's flash).
    At(DVec2),
}

/// One thing that happened this tick.
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    /// A sound, by Doom's name without its `DS` prefix (`doropn`, `pstart`).
    Sound { sound: &'static str, origin: Origin },
    /// A line of text for the player ("Picked up a blue keycard.").
    Message(String),
    /// A line's special went off (`started`: it set something going, and a
    /// switch flips), or was tried and did nothing.
    Special { line: SpecialLine, started: bool },
}

/// Shorthand for a sound event.
pub fn sound(sound: &'static str, origin: Origin) -> Event {
    Event::Sound { sound, origin }
}
