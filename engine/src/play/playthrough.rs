//! A playthrough: one map after another, as a person plays a campaign.
//! Levels end at an exit; an intermission shows the level's tallies until
//! the player presses use or fire; then the next map of the [`Campaign`]
//! loads. A dead player's use restarts the map. Driven by the same
//! [`TickInput`]s as a [`Game`] (the intermission's presses included), so a
//! demo recorded across several maps replays exactly, headless too.

use std::borrow::Cow;

use glam::DVec2;

use crate::actors::ActorTable;
use crate::autopilot::observe::{Observe, Seen};
use crate::bsp::BuildOptions;
use crate::campaign::{open, Campaign, CampaignError, MapRef, Opened};
use crate::level::Level;
use crate::map::LineSpecial;
use crate::render::View;
use crate::sim::game::{SimGame, SimGameError};

use super::events::Event;
use super::world::{Exit, SpecialLine};
use super::{Game, GameOptions, PlayError, Player, Stats, TickInput};

/// Ticks an intermission shows before a press can end it (1 s, so a key
/// still held from the exit switch does not skip it).
pub const INTERMISSION_MIN: u32 = 35;

/// What the playthrough is showing.
#[derive(Clone, Debug, PartialEq)]
pub enum Phase {
    Playing,
    /// The level ended: its tallies, and what comes next (`None`: the
    /// campaign is over).
    Intermission {
        map: String,
        stats: Stats,
        exit: Exit,
        next: Option<MapRef>,
        ticks: u32,
    },
    /// The last map is done.
    Finished {
        stats: Stats,
    },
}

#[derive(Debug, thiserror::Error)]
pub enum PlaythroughError {
    #[error(transparent)]
    Open(#[from] CampaignError),
    #[error("{map}: {error}")]
    Start { map: String, error: PlayError },
    #[error(transparent)]
    Sim(#[from] SimGameError),
}

/// The game a level is played on: the f64 game, or the simulation with
/// Doom's arithmetic ([`GameOptions::sim`]). Both answer what the window,
/// the sound and the autopilot ask ([`Observe`], [`Played::view`],
/// [`Played::tick`]).
pub enum Played {
    Float(Box<Game>),
    Sim(Box<SimGame>),
}

impl Played {
    pub fn tick(&mut self, input: &TickInput) {
        match self {
            Played::Float(g) => g.tick(input),
            Played::Sim(g) => g.tick(input),
        }
    }

    /// The eye between the last tick's start (`alpha` 0) and end (1).
    pub fn view(&self, alpha: f64) -> View {
        match self {
            Played::Float(g) => g.view(alpha),
            Played::Sim(g) => g.view(alpha),
        }
    }

    pub fn level(&self) -> &Level {
        Observe::level(self)
    }

    /// The level to draw into (a Doom demo played elsewhere is drawn here).
    pub fn level_mut(&mut self) -> &mut Level {
        match self {
            Played::Float(g) => g.level_mut(),
            Played::Sim(g) => g.level_mut(),
        }
    }

    pub fn player(&self) -> &Player {
        Observe::player(self)
    }

    /// The player, to change by hand (tests, tools, what a screen shows).
    /// On the simulation this is what it shows only: the next tick reads
    /// the player afresh.
    pub fn player_mut(&mut self) -> &mut Player {
        match self {
            Played::Float(g) => g.player_mut(),
            Played::Sim(g) => g.player_mut(),
        }
    }

    pub fn ticks(&self) -> u64 {
        Observe::ticks(self)
    }

    pub fn stats(&self) -> Stats {
        Observe::stats(self)
    }

    pub fn events(&self) -> &[Event] {
        Observe::events(self)
    }

    pub fn exit(&self) -> Option<Exit> {
        Observe::exit(self)
    }

    pub fn options(&self) -> GameOptions {
        match self {
            Played::Float(g) => g.options(),
            Played::Sim(g) => g.options(),
        }
    }

    /// The game's whole state as bytes: equal bytes, equal games (what a
    /// save holds after its header).
    pub fn state_bytes(&self) -> Vec<u8> {
        match self {
            Played::Float(g) => g.state_bytes(),
            Played::Sim(g) => g.state_bytes(),
        }
    }

    /// The f64 game, when that is what plays (tests and tools that reach
    /// into its machinery).
    pub fn float(&self) -> Option<&Game> {
        match self {
            Played::Float(g) => Some(g),
            Played::Sim(_) => None,
        }
    }

    pub fn float_mut(&mut self) -> Option<&mut Game> {
        match self {
            Played::Float(g) => Some(g),
            Played::Sim(_) => None,
        }
    }

    /// Sets the player's health (tests and tools).
    pub fn set_health(&mut self, health: i32) {
        match self {
            Played::Float(g) => g.player_mut().health = health,
            Played::Sim(g) => g.set_health(health),
        }
    }

    /// Puts the player at `pos` facing `angle`, standing still; `false`
    /// when it does not fit there (tests and tools).
    pub fn put_player(&mut self, pos: DVec2, angle: f64) -> bool {
        self.place_player(pos, angle)
    }

    /// The simulation with Doom's arithmetic, when that is what plays.
    pub fn sim(&self) -> Option<&SimGame> {
        match self {
            Played::Float(_) => None,
            Played::Sim(g) => Some(g),
        }
    }

    pub fn sim_mut(&mut self) -> Option<&mut SimGame> {
        match self {
            Played::Float(_) => None,
            Played::Sim(g) => Some(g),
        }
    }

    /// Puts the player at `pos` facing `angle`, standing still (a map
    /// reloaded under a map maker keeps their pose); `false` when it does
    /// not fit there.
    fn place_player(&mut self, pos: DVec2, angle: f64) -> bool {
        match self {
            Played::Float(g) => g.place_player(pos, angle),
            Played::Sim(g) => g.place_player(pos, angle),
        }
    }
}

impl Played {
    /// The game behind, read as the autopilot reads a game.
    fn inner(&self) -> &dyn Observe {
        match self {
            Played::Float(g) => &**g,
            Played::Sim(g) => &**g,
        }
    }
}

impl Observe for Played {
    fn level(&self) -> &Level {
        self.inner().level()
    }

    fn ticks(&self) -> u64 {
        self.inner().ticks()
    }

    fn player(&self) -> &Player {
        self.inner().player()
    }

    fn seen(&self) -> Cow<'_, [Seen]> {
        self.inner().seen()
    }

    fn table(&self) -> &ActorTable {
        self.inner().table()
    }

    fn exit(&self) -> Option<Exit> {
        self.inner().exit()
    }

    fn events(&self) -> &[Event] {
        self.inner().events()
    }

    fn stats(&self) -> Stats {
        self.inner().stats()
    }

    fn is_busy(&self, sector: usize) -> bool {
        self.inner().is_busy(sector)
    }

    fn turn_step(&self) -> f64 {
        self.inner().turn_step()
    }

    fn special(&self, line: SpecialLine) -> Option<LineSpecial> {
        self.inner().special(line)
    }

    fn use_stop(&self, from: DVec2, to: DVec2) -> Option<SpecialLine> {
        self.inner().use_stop(from, to)
    }
}

/// A playthrough in progress.
pub struct Playthrough {
    pub campaign: Campaign,
    /// The map being played (or just finished).
    pub map: MapRef,
    pub game: Played,
    pub phase: Phase,
    /// Ticks run since the playthrough began, over every map and intermission.
    pub ticks: u64,
    options: GameOptions,
    build: BuildOptions,
    /// The last tick's use or fire, to act on presses only.
    held: bool,
}

impl Playthrough {
    /// Starts `campaign` on `map` (its first map when `None`).
    pub fn new(campaign: Campaign, map: Option<MapRef>, options: GameOptions) -> Result<Playthrough, PlaythroughError> {
        let build = BuildOptions::default();
        let map = map.unwrap_or_else(|| campaign.first());
        let opened = open(&map, &build)?;
        let map = opened.map.clone();
        let game = start(opened, options)?;
        Ok(Playthrough { campaign, map, game, phase: Phase::Playing, ticks: 0, options, build, held: false })
    }

    /// Starts on a command-line map: a WAD, `WAD:MAP`, a campaign file or a map.
    pub fn of(map: &MapRef, options: GameOptions) -> Result<Playthrough, PlaythroughError> {
        let campaign = Campaign::of(map)?;
        let start = match (&campaign, map) {
            (Campaign::List { .. }, _) | (Campaign::Wad { .. }, MapRef::Wad { map: None, .. }) => None,
            _ => Some(map.clone()),
        };
        Playthrough::new(campaign, start, options)
    }

    pub fn options(&self) -> GameOptions {
        self.options
    }

    /// The last tick held use or fire (a save keeps it: the next press is
    /// told from a held key the same way after loading).
    pub(super) fn held(&self) -> bool {
        self.held
    }

    /// A playthrough of `campaign` resumed on `map` with `game` (a loaded save).
    pub(super) fn resume(campaign: Campaign, map: MapRef, game: Played, ticks: u64, held: bool) -> Playthrough {
        let options = game.options();
        let build = BuildOptions::default();
        Playthrough { campaign, map, game, phase: Phase::Playing, ticks, options, build, held }
    }

    /// One tick: the game's, or the intermission's. Loading the next map can
    /// fail (a file changed or vanished); the error says which, and the
    /// playthrough stays in its intermission.
    pub fn tick(&mut self, input: &TickInput) -> Result<(), PlaythroughError> {
        self.ticks += 1;
        let pressed = (input.use_line || input.fire) && !self.held;
        self.held = input.use_line || input.fire;
        match &mut self.phase {
            Phase::Playing => {
                if self.game.player().dead() && pressed {
                    return self.restart();
                }
                self.game.tick(input);
                if let Some(exit) = self.game.exit() {
                    let next = self.campaign.next(&self.map, exit);
                    let map = self.map.short_name();
                    self.phase = Phase::Intermission { map, stats: self.game.stats(), exit, next, ticks: 0 };
                    // The press that ended the level does not end the intermission.
                    self.held = true;
                }
            }
            Phase::Intermission { ticks, next, stats, .. } => {
                *ticks += 1;
                if pressed && *ticks >= INTERMISSION_MIN {
                    match next.clone() {
                        Some(next) => self.enter(next)?,
                        None => self.phase = Phase::Finished { stats: *stats },
                    }
                }
            }
            Phase::Finished { .. } => {}
        }
        Ok(())
    }

    /// Loads `map` and plays it; the player keeps its health (not its keys,
    /// as in Doom).
    fn enter(&mut self, map: MapRef) -> Result<(), PlaythroughError> {
        let opened = open(&map, &self.build)?;
        let map = opened.map.clone();
        let game = match &self.game {
            Played::Sim(from) => Played::Sim(Box::new(SimGame::next_level(opened, self.options, from)?)),
            Played::Float(from) => {
                let health = from.player().health;
                let mut game = start(opened, self.options)?;
                game.player_mut().health = health.max(1);
                game
            }
        };
        self.map = map;
        self.game = game;
        self.phase = Phase::Playing;
        Ok(())
    }

    /// The current map read again from its file (a map maker saved it): a
    /// new game on it, the player kept where it stood if that is still
    /// inside the map (`Ok(true)`), else at the start (`Ok(false)`). On an
    /// error the playthrough is untouched.
    pub fn reload(&mut self) -> Result<bool, PlaythroughError> {
        let opened = open(&self.map, &self.build)?;
        let mut game = start(opened, self.options)?;
        let p = self.game.player();
        let kept = game.place_player(p.pos, p.angle);
        self.game = game;
        self.phase = Phase::Playing;
        Ok(kept)
    }

    /// The current map from its start, with a fresh player (Doom's reborn).
    fn restart(&mut self) -> Result<(), PlaythroughError> {
        let map = self.map.clone();
        let opened = open(&map, &self.build)?;
        self.game = start(opened, self.options)?;
        self.phase = Phase::Playing;
        Ok(())
    }
}

/// A new game on `opened`, on the game `options` choose.
fn start(opened: Opened, options: GameOptions) -> Result<Played, PlaythroughError> {
    if options.sim {
        return Ok(Played::Sim(Box::new(SimGame::new(opened, options)?)));
    }
    let map = opened.map.label();
    let game = Game::with_options(opened.level, options).map_err(|error| PlaythroughError::Start { map, error })?;
    Ok(Played::Float(Box::new(game)))
}
