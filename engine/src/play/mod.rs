//! Play: the game simulation, headless. A [`Game`] owns a [`Level`] and the
//! player, and advances in fixed ticks of 1/[`TICRATE`] s from one
//! [`TickInput`] each; the window (in `game/`) accumulates real time into
//! ticks and draws [`Game::view`] between them. Nothing here reads a clock,
//! iterates a hash map or draws a random number, so the same inputs give the
//! same game, bit for bit ([`demo`] relies on it).
//!
//! One tick, in order (Doom's P_PlayerThink, P_XYMovement, P_ZMovement, then
//! the sector thinkers):
//!
//! ```text
//! input --turn, thrust--> velocity --collision::slide--> position
//!       --friction, fall (step up, gravity)--> z --use--> doors --tick--> sector heights
//!                                                                         (and grid panels)
//! ```
//!
//! Modules: [`input`] (what a tick reads), [`player`] (the body's physics and
//! constants), [`blockmap`] (lines by grid cell), [`collision`] (sweeping the
//! body's circle against lines), [`doors`] (door state machines), [`demo`]
//! (recorded inputs, saved and loaded).

pub mod blockmap;
pub mod collision;
pub mod demo;
pub mod doors;
pub mod input;
pub mod player;

use glam::DVec2;

use crate::level::Level;
use crate::render::View;
use blockmap::{Blockmap, LineQuery};
use collision::World;
use doors::{Door, DoorKind, Doors};
use player::{HEIGHT, RADIUS};

pub use demo::{Demo, DemoError};
pub use input::TickInput;
pub use player::Player;

/// Simulation ticks per second (Doom's `TICRATE`).
pub const TICRATE: u32 = 35;

#[derive(Debug, thiserror::Error, PartialEq)]
pub enum PlayError {
    #[error("{map}: ({x}, {y}) is not inside any sector (in a hole, outside the map, or on a one-sided wall)")]
    Outside { map: String, x: f64, y: f64 },
}

/// What the view interpolates between ticks.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Pose {
    pos: DVec2,
    eye: f64,
    angle: f64,
}

/// A game in progress: the level (whose door sectors move, and on a grid map
/// whose door panels slide), the player, and the tick count.
pub struct Game {
    level: Level,
    player: Player,
    doors: Doors,
    blockmap: Blockmap,
    query: LineQuery,
    /// Sectors the body overlaps (scratch for the doors).
    touched: Vec<usize>,
    /// The pose at the start of the last tick.
    previous: Pose,
    ticks: u64,
}

impl Game {
    /// A game on `level` with the player at the map's player start.
    pub fn new(level: Level) -> Result<Game, PlayError> {
        let map = &level.compiled.map;
        let start = map.player_start().clone();
        if level.compiled.locate(start.pos).is_none() {
            return Err(PlayError::Outside { map: map.name.clone(), x: start.pos.x, y: start.pos.y });
        }
        let blockmap = Blockmap::new(map);
        let doors = Doors::new(&level);
        let mut query = LineQuery::default();
        let world = World { compiled: &level.compiled, blockmap: &blockmap };
        let near = world.lines_near(&mut query, start.pos, RADIUS + 1.0);
        let area = world.area(near, start.pos);
        let player = Player::new(start.pos, start.angle, area.sector, area.floor, area.ceiling);
        let previous = pose(&player);
        Ok(Game { level, player, doors, blockmap, query, touched: Vec::new(), previous, ticks: 0 })
    }

    /// Advances the game by one tick of 1/[`TICRATE`] s.
    pub fn tick(&mut self, input: &TickInput) {
        let input = input.sanitized();
        self.previous = pose(&self.player);
        let Game { level, player, doors, blockmap, query, touched, .. } = self;
        let world = World { compiled: &level.compiled, blockmap };

        player.turn(&input);
        player.thrust(&input);
        let mut velocity = player.velocity;
        let from = player.pos;
        player.pos = world.slide(query, player.pos, player.z, &mut velocity);
        player.velocity = velocity;
        let near = world.lines_near(query, player.pos, RADIUS + 1.0);
        let area = world.area(near, player.pos);
        (player.sector, player.floor, player.ceiling) = (area.sector, area.floor, area.ceiling);
        player.friction(&input);
        player.fall();

        if doors.is_empty() {
            self.ticks += 1;
            return;
        }
        doors.walk(world, query, from, player.pos);
        if input.use_door {
            doors.use_ahead(world, query, player.pos, player.angle);
        }
        let near = world.lines_near(query, player.pos, RADIUS + 1.0);
        world.sectors_touched(near, player.pos, touched);
        let (top, pos) = (player.z + HEIGHT, player.pos);
        let touched = &*touched;
        doors.tick(level, |door, position| match &door.kind {
            DoorKind::Ceiling => touched.contains(&door.sector) && position < top,
            DoorKind::Slide(slide) => slide.holds(pos, RADIUS),
        });
        self.ticks += 1;
    }

    /// The level as it is now: door sectors at their current heights, grid
    /// door panels slid as far as they are ([`crate::level::GridLevel::open`]). Render this.
    pub fn level(&self) -> &Level {
        &self.level
    }

    /// The eye, interpolated between the start (`alpha` 0) and the end
    /// (`alpha` 1) of the last tick; `alpha` is clamped to `[0, 1]`.
    pub fn view(&self, alpha: f64) -> View {
        let now = pose(&self.player);
        let a = if alpha.is_nan() { 1.0 } else { alpha.clamp(0.0, 1.0) };
        if a == 1.0 {
            return View::new(now.pos, now.eye, now.angle);
        }
        let prev = self.previous;
        let turned = (now.angle - prev.angle + 540.0).rem_euclid(360.0) - 180.0;
        View::new(
            prev.pos + (now.pos - prev.pos) * a,
            prev.eye + (now.eye - prev.eye) * a,
            (prev.angle + turned * a).rem_euclid(360.0),
        )
    }

    pub fn player(&self) -> &Player {
        &self.player
    }

    /// The player, to change by hand (tests, tools). The next tick works
    /// from whatever it finds: speed is clamped to [`player::MAX_SPEED`],
    /// and a body left overlapping a wall can move out of it but not further in.
    pub fn player_mut(&mut self) -> &mut Player {
        &mut self.player
    }

    /// Puts the player at `pos` looking along `angle`, standing still on the
    /// floor there, as if it had started there.
    pub fn teleport(&mut self, pos: DVec2, angle: f64) -> Result<(), PlayError> {
        let map = &self.level.compiled.map;
        if !(pos.is_finite() && angle.is_finite()) || self.level.compiled.locate(pos).is_none() {
            return Err(PlayError::Outside { map: map.name.clone(), x: pos.x, y: pos.y });
        }
        let world = World { compiled: &self.level.compiled, blockmap: &self.blockmap };
        let near = world.lines_near(&mut self.query, pos, RADIUS + 1.0);
        let area = world.area(near, pos);
        self.player = Player::new(pos, angle, area.sector, area.floor, area.ceiling);
        self.previous = pose(&self.player);
        Ok(())
    }

    /// Ticks run since the start.
    pub fn ticks(&self) -> u64 {
        self.ticks
    }

    /// The map's doors and their states (empty on a map without doors).
    pub fn doors(&self) -> &[Door] {
        &self.doors.doors
    }
}

fn pose(player: &Player) -> Pose {
    Pose { pos: player.pos, eye: player.eye_z(), angle: player.angle }
}
