//! A playthrough: one map after another, as a person plays a campaign.
//! Levels end at an exit; the intermission shows the level's tallies,
//! timed as Doom times it (`sim::intermission`: a press shows the tallies
//! at once, the next goes on); then the next map of the [`Campaign`]
//! loads. A dead player's use reloads the map (Doom's reborn). Driven by the
//! same [`TickInput`]s as a [`SimGame`] (the intermission's presses
//! included), tic for tic as Doom runs a demo, so a game recorded across
//! several maps replays exactly, headless too, and in Chocolate Doom.

use crate::bsp::BuildOptions;
use crate::campaign::{open_with, ArtOptions, Campaign, CampaignError, MapRef};
use crate::sim::game::{Setup, SimGame, SimGameError};
use crate::sim::intermission::Intermission;

use super::world::Exit;
use super::{GameOptions, Stats, TickInput};

/// What the playthrough is showing.
#[derive(Clone, Debug, PartialEq)]
pub enum Phase {
    Playing,
    /// The level ended: its tallies, what comes next (`None`: the
    /// campaign is over), and Doom's intermission counting them.
    Intermission {
        map: String,
        stats: Stats,
        exit: Exit,
        next: Option<MapRef>,
        wi: Box<Intermission>,
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
    /// Where each map's pictures come from.
    art: ArtOptions,
}

impl Playthrough {
    /// Starts `campaign` on `map` (its first map when `None`).
    pub fn new(campaign: Campaign, map: Option<MapRef>, options: GameOptions) -> Result<Playthrough, PlaythroughError> {
        Playthrough::set_up(campaign, map, options, Setup::SINGLE)
    }

    /// [`Playthrough::new`] with a game set up otherwise (a ViZDoom
    /// scenario's server settings); the levels after keep it.
    pub fn set_up(
        campaign: Campaign,
        map: Option<MapRef>,
        options: GameOptions,
        setup: Setup,
    ) -> Result<Playthrough, PlaythroughError> {
        Playthrough::set_up_with(campaign, map, options, setup, ArtOptions::default())
    }

    /// [`Playthrough::set_up`] with every map's pictures from `art` (a
    /// WAD's under RON maps; none for a run that draws nothing).
    pub fn set_up_with(
        campaign: Campaign,
        map: Option<MapRef>,
        options: GameOptions,
        setup: Setup,
        art: ArtOptions,
    ) -> Result<Playthrough, PlaythroughError> {
        let build = BuildOptions::default();
        let map = map.unwrap_or_else(|| campaign.first());
        let opened = open_with(&map, &build, &art)?;
        let map = opened.map.clone();
        let game = SimGame::netgame(opened, options, setup)?;
        Ok(Playthrough { campaign, map, game, phase: Phase::Playing, ticks: 0, build, art })
    }

    /// Starts on a command-line map: a WAD, `WAD:MAP`, a campaign file or a map.
    pub fn of(map: &MapRef, options: GameOptions) -> Result<Playthrough, PlaythroughError> {
        Playthrough::of_set_up(map, options, Setup::SINGLE)
    }

    /// [`Playthrough::of`] with a game set up otherwise.
    pub fn of_set_up(map: &MapRef, options: GameOptions, setup: Setup) -> Result<Playthrough, PlaythroughError> {
        Playthrough::of_with(map, options, setup, ArtOptions::default())
    }

    /// [`Playthrough::of_set_up`] with every map's pictures from `art`.
    pub fn of_with(
        map: &MapRef,
        options: GameOptions,
        setup: Setup,
        art: ArtOptions,
    ) -> Result<Playthrough, PlaythroughError> {
        let campaign = Campaign::of(map)?;
        let start = match (&campaign, map) {
            (Campaign::List { .. }, _) | (Campaign::Wad { .. }, MapRef::Wad { map: None, .. }) => None,
            _ => Some(map.clone()),
        };
        Playthrough::set_up_with(campaign, start, options, setup, art)
    }

    pub fn options(&self) -> GameOptions {
        self.game.options()
    }

    /// A playthrough of `campaign` resumed on `map` with `game` (a loaded save).
    pub(super) fn resume(campaign: Campaign, map: MapRef, game: SimGame, ticks: u64) -> Playthrough {
        let build = BuildOptions::default();
        Playthrough { campaign, map, game, phase: Phase::Playing, ticks, build, art: ArtOptions::default() }
    }

    /// One tick, in `G_Ticker`'s order: a reborn player's level reloaded,
    /// or the next level loaded when the intermission has ended; then the
    /// game's tic, or the intermission's. Loading a map can fail (a file
    /// changed or vanished); the error says which, and the playthrough
    /// stays where it was.
    pub fn tick(&mut self, input: &TickInput) -> Result<(), PlaythroughError> {
        if let Phase::Intermission { wi, next, stats, .. } = &self.phase {
            if wi.done() {
                match next.clone() {
                    Some(next) => self.enter(next)?,
                    None => self.phase = Phase::Finished { stats: *stats },
                }
            }
        } else if self.phase == Phase::Playing && self.game.reborn() {
            self.restart()?;
        }
        self.ticks += 1;
        match &mut self.phase {
            Phase::Playing => {
                self.game.tick(input);
                if let Some(exit) = self.game.exit() {
                    let stats = self.game.stats();
                    let next = self.campaign.next(&self.map, exit);
                    let map = self.map.short_name();
                    self.phase = match self.game.complete() {
                        Some(wi) => Phase::Intermission { map, stats, exit, next, wi: Box::new(wi) },
                        // Doom 1's ExM8: the episode's end, no intermission.
                        None => Phase::Finished { stats },
                    };
                }
            }
            Phase::Intermission { wi, .. } => self.game.tick_between(wi, input),
            Phase::Finished { .. } => {}
        }
        Ok(())
    }

    /// Loads `map` and plays it; the player keeps what Doom's
    /// `G_PlayerFinishLevel` lets through (not its keys or powers).
    fn enter(&mut self, map: MapRef) -> Result<(), PlaythroughError> {
        let opened = open_with(&map, &self.build, &self.art)?;
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
        let opened = open_with(&self.map, &self.build, &self.art)?;
        let mut game = SimGame::new(opened, self.options())?;
        let p = self.game.player();
        let kept = game.place_player(p.pos, p.angle);
        self.game = game;
        self.phase = Phase::Playing;
        Ok(kept)
    }

    /// The current map from its start, with a fresh player (Doom's
    /// reborn: the random index and tic count go on).
    fn restart(&mut self) -> Result<(), PlaythroughError> {
        let opened = open_with(&self.map, &self.build, &self.art)?;
        self.game = SimGame::next_level(opened, self.options(), &self.game)?;
        Ok(())
    }
}
