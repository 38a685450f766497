//! A playthrough: one map after another, as a person plays a campaign.
//! Levels end at an exit; an intermission shows the level's tallies until
//! the player presses use or fire; then the next map of the [`Campaign`]
//! loads. A dead player's use restarts the map. Driven by the same
//! [`TickInput`]s as a [`SimGame`] (the intermission's presses included),
//! so a demo recorded across several maps replays exactly, headless too.

use crate::bsp::BuildOptions;
use crate::campaign::{open, Campaign, CampaignError, MapRef};
use crate::sim::game::{SimGame, SimGameError};

use super::world::Exit;
use super::{GameOptions, Stats, TickInput};

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
    #[error(transparent)]
    Sim(#[from] SimGameError),
}

/// A playthrough in progress.
pub struct Playthrough {
    pub campaign: Campaign,
    /// The map being played (or just finished).
    pub map: MapRef,
    pub game: SimGame,
    pub phase: Phase,
    /// Ticks run since the playthrough began, over every map and intermission.
    pub ticks: u64,
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
        let game = SimGame::new(opened, options)?;
        Ok(Playthrough { campaign, map, game, phase: Phase::Playing, ticks: 0, build, held: false })
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
        self.game.options()
    }

    /// The last tick held use or fire (a save keeps it: the next press is
    /// told from a held key the same way after loading).
    pub(super) fn held(&self) -> bool {
        self.held
    }

    /// A playthrough of `campaign` resumed on `map` with `game` (a loaded save).
    pub(super) fn resume(campaign: Campaign, map: MapRef, game: SimGame, ticks: u64, held: bool) -> Playthrough {
        let build = BuildOptions::default();
        Playthrough { campaign, map, game, phase: Phase::Playing, ticks, build, held }
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

    /// Loads `map` and plays it; the player keeps what Doom's
    /// `G_PlayerFinishLevel` lets through (not its keys).
    fn enter(&mut self, map: MapRef) -> Result<(), PlaythroughError> {
        let opened = open(&map, &self.build)?;
        let map = opened.map.clone();
        let game = SimGame::next_level(opened, self.options(), &self.game)?;
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
        let mut game = SimGame::new(opened, self.options())?;
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
        self.game = SimGame::new(opened, self.options())?;
        self.phase = Phase::Playing;
        Ok(())
    }
}
