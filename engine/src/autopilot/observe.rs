//! What the autopilot reads of a game: the level as it stands, the player,
//! the things in play, the tallies, and which sectors are moving and which
//! specials are spent, in map units and degrees. The simulation with
//! Doom's arithmetic answers it ([`crate::sim::game::SimGame`]), so a game
//! the autopilot plays can be recorded as a vanilla demo.

use std::borrow::Cow;

use glam::DVec2;

use crate::actors::ActorTable;
use crate::level::Level;
use crate::map::LineSpecial;
use crate::play::events::Event;
use crate::play::world::{Exit, SpecialLine};
use crate::play::{Player, Stats};

/// A thing in play as the autopilot sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seen {
    /// Its actor, by index into [`Observe::table`].
    pub kind: usize,
    pub pos: DVec2,
    pub z: f64,
    /// Momentum in the plane, units per tick.
    pub vel: DVec2,
    pub health: i32,
    /// Gone from play.
    pub removed: bool,
    pub solid: bool,
    pub shootable: bool,
    pub missile: bool,
    /// A missile the player fired.
    pub by_player: bool,
}

/// A game as the autopilot reads it. Things keep their index for the
/// level's life (a goal names a thing by it).
pub trait Observe {
    /// The level as it stands now (heights, textures, things drawn).
    fn level(&self) -> &Level;
    fn ticks(&self) -> u64;
    fn player(&self) -> &Player;
    /// Every thing spawned this level, by index, removed ones included.
    fn seen(&self) -> Cow<'_, [Seen]>;
    fn table(&self) -> &ActorTable;
    fn exit(&self) -> Option<Exit>;
    /// What happened on the last tick.
    fn events(&self) -> &[Event];
    fn stats(&self) -> Stats;
    /// A mover is at work on the converted map's sector `sector`.
    fn is_busy(&self, sector: usize) -> bool;
    /// The smallest turn the game's commands carry, in degrees (a 1.9
    /// demo's 1/256 of the circle on the simulation), or 0 for any angle.
    fn turn_step(&self) -> f64 {
        0.0
    }
    /// `line`'s special, unless it was used up.
    fn special(&self, line: SpecialLine) -> Option<LineSpecial>;
    /// Where a use from `from` towards `to` stops: the first line with a
    /// live use special, or a wall with no opening; `None` when nothing does.
    fn use_stop(&self, from: DVec2, to: DVec2) -> Option<SpecialLine>;
}
