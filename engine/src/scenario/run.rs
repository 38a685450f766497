//! A ViZDoom scenario played: [`Episode`] opens a `.cfg`'s WAD on the IWAD,
//! starts a game on its map at its skill, lets the first
//! `episode_start_time` tics pass without input, then takes one action a
//! tic and scores it as ViZDoom does (`docs/zdoom-facts.md`, 7):
//!
//! - each action earns the change in ACS global 0 (16.16, so divided by
//!   65536) plus `living_reward`;
//! - the episode ends on the tic the player dies (that action still
//!   counts, and `death_penalty` is subtracted once), one action after the
//!   map is left (`Exit_Normal` ends the level at the start of the next
//!   tic, as `G_ExitLevel` does), or after `episode_timeout` actions;
//! - ACS global 1 (health_gathering's shaping reward) is read out, never
//!   added.
//!
//! An action is the pressed buttons of the `.cfg`'s `available_buttons`,
//! turned into Doom's command as ZDoom's input does with "always run" off
//! (ViZDoom's default): forward and back 25, strafe 24 (50 and 40 with
//! SPEED held), a turn of 320 (of 65536) for the first five tics a turn
//! button is held, then 640 (1280 with SPEED).

use std::path::{Path, PathBuf};

use super::buffers::TicBuffers;
use super::{Button, ScenarioConfig};
use crate::bsp::BuildOptions;
use crate::campaign::{self, MapRef, Opened};
use crate::play::lmp::{buttons, Ticcmd};
use crate::play::GameOptions;
use crate::sim::game::{Setup, SimGame};

/// How an episode ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum End {
    /// The map was left (`Exit_Normal`).
    Exit,
    /// The player died.
    Death,
    /// `episode_timeout` actions were played.
    Timeout,
}

/// Tics a turn button turns slowly (ZDoom's `SLOWTURNTICS` less one: ViZDoom
/// measures the fast turn from the sixth held tic).
pub(super) const SLOW_TURN_TICS: u32 = 5;

/// One episode of a scenario.
pub struct Episode {
    pub game: SimGame,
    pub config: ScenarioConfig,
    /// Actions taken so far.
    pub actions: u32,
    /// The reward summed over the actions taken.
    pub total_reward: f64,
    end: Option<End>,
    /// Global 0 after the last action (16.16).
    reward_global: i32,
    /// The level was left on the last action: one more ends the episode.
    leaving: bool,
    /// Tics a turn button has been held.
    turn_held: u32,
    /// The counts the 1.3 rewards are paid on, after the last action.
    counts: Counts,
    /// A made scenario's own events (`scenario::made`): goals, pickups.
    made: Option<super::made::events::Tracker>,
    /// The audio and notifications buffers, fed every tic, when the
    /// `.cfg` turns either on.
    buffers: Option<Box<TicBuffers>>,
}

/// What ViZDoom 1.3's event rewards are paid on (`kill_reward` and the
/// rest): the player's counts after an action, compared with the last.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Counts {
    kills: f64,
    items: f64,
    secrets: f64,
    frags: f64,
    hits: f64,
    hits_taken: f64,
    damage: f64,
    damage_taken: f64,
    health: f64,
    armor: f64,
}

impl Counts {
    /// Player `player`'s counts.
    pub(super) fn of(game: &SimGame, player: usize) -> Counts {
        let v = |variable| super::variables::value(game, player, variable);
        use super::GameVariable as G;
        Counts {
            kills: v(G::KillCount),
            items: v(G::ItemCount),
            secrets: v(G::SecretCount),
            frags: v(G::FragCount),
            hits: v(G::HitCount),
            hits_taken: v(G::HitsTaken),
            damage: v(G::DamageCount),
            damage_taken: v(G::DamageTaken),
            health: v(G::Health),
            armor: v(G::Armor),
        }
    }

    /// Whether any count pays a reward (most scenarios pay none, and then
    /// the counts are not read at all).
    pub(super) fn paid(r: &super::Rewards) -> bool {
        let each =
            [r.kill, r.item, r.secret, r.frag, r.hit, r.hit_taken_penalty, r.damage_made, r.damage_taken_penalty];
        each.into_iter().chain([r.health, r.armor]).any(|v| v != 0.0)
    }

    /// The rewards earned from `before` to `self`: per kill, item, secret,
    /// frag and hit, per point of damage, and per point of health and
    /// armour gained (losses pay nothing).
    pub(super) fn reward_since(&self, before: &Counts, r: &super::Rewards) -> f64 {
        let gained = |now: f64, then: f64| (now - then).max(0.0);
        r.kill * (self.kills - before.kills)
            + r.item * (self.items - before.items)
            + r.secret * (self.secrets - before.secrets)
            + r.frag * (self.frags - before.frags)
            + r.hit * (self.hits - before.hits)
            - r.hit_taken_penalty * (self.hits_taken - before.hits_taken)
            + r.damage_made * (self.damage - before.damage)
            - r.damage_taken_penalty * (self.damage_taken - before.damage_taken)
            + r.health * gained(self.health, before.health)
            + r.armor * gained(self.armor, before.armor)
    }
}

/// What went wrong starting a scenario.
#[derive(Debug, thiserror::Error)]
pub enum ScenarioError {
    #[error("{cfg}: no doom_scenario_path or doom_game_path: which WAD holds the scenario's map?")]
    NoWad { cfg: String },
    #[error("{0}")]
    Open(String),
}

/// The map a scenario plays: its `.cfg`'s `doom_map` in its WAD, over
/// `iwad`, else over the `.cfg`'s `doom_game_path`, else over
/// `freedoom2.wad` where Doom ports look for it; with no scenario WAD, the
/// map is the game WAD's own.
pub fn map_of(config: &ScenarioConfig, iwad: Option<&Path>) -> Result<MapRef, ScenarioError> {
    let label = config.base_dir.display().to_string();
    let given = iwad.map(Path::to_path_buf).or_else(|| config.game_wad());
    let wad = match (config.scenario_wad(), &given) {
        (Some(wad), _) => Some(wad),
        // A map of the game's own WAD (ViZDoom's freedoom2.cfg, deathmatch
        // on freedm.wad): no scenario WAD over it.
        (None, Some(_)) => None,
        (None, None) => return Err(ScenarioError::NoWad { cfg: label }),
    };
    let iwad = given.unwrap_or_else(|| {
        let dirs = campaign::wad_dirs();
        campaign::find_wad(&PathBuf::from("freedoom2.wad"), &dirs)
    });
    Ok(MapRef::Wad { wads: std::iter::once(iwad).chain(wad).collect(), map: Some(config.doom_map.clone()) })
}

/// The reward ViZDoom would have paid so far in a game of `config` played
/// freely (the window's HUD): ACS global 0, plus the living reward for each
/// tic after the start time, less the death penalty once dead.
pub fn reward_so_far(game: &SimGame, config: &ScenarioConfig) -> f64 {
    let global = game.scripts().map_or(0, |s| s.global(0));
    let tics = game.ticks().saturating_sub(u64::from(config.episode_start_time));
    let dead = game.player().health <= 0;
    let penalty = if dead { config.rewards.death_penalty } else { 0.0 };
    f64::from(global) / 65536.0 + config.rewards.living * tics as f64 - penalty
}

/// A scenario opened once: its `.cfg` and its map converted and compiled,
/// and its one-player game set up (actors, scripts, art), so each episode
/// starts from a copy.
pub struct Scenario {
    pub config: ScenarioConfig,
    opened: Opened,
    /// The one-player game at its first tic with seed 0, copied and
    /// reseeded for each episode (`SimGame::reseeded`).
    pristine: SimGame,
    /// What the WAD's DECORATE says that the actor table cannot hold
    /// (flags, properties, actions left out), one line each with its lump
    /// and line.
    pub decorate_unread: Vec<String>,
    /// A made scenario's goals and item rewards (`scenario::made`).
    made: Option<std::sync::Arc<super::made::events::Rules>>,
}

impl Scenario {
    /// `config`'s WAD on `iwad`, else on the `.cfg`'s `doom_game_path`,
    /// else on `freedoom2.wad` where Doom ports look for it.
    pub fn open(config: &ScenarioConfig, iwad: Option<&Path>) -> Result<Scenario, ScenarioError> {
        let map = map_of(config, iwad)?;
        let opened = campaign::open(&map, &BuildOptions::default()).map_err(|e| ScenarioError::Open(e.to_string()))?;
        let decorate_unread = match &opened.wad {
            Some(art) => {
                super::actor_table(&art.wad, crate::actors::ActorTable::active()).map_err(ScenarioError::Open)?.1
            }
            None => Vec::new(),
        };
        let setup = Setup { no_autoaim: config.no_autoaim(), ..Setup::SINGLE };
        let pristine = Self::game(config, &opened, 0, setup)?;
        Ok(Scenario { config: config.clone(), opened, pristine, decorate_unread, made: None })
    }

    /// A scenario on a map already opened (a made scenario's RON map:
    /// `scenario::made`), whose episodes also pay `made`'s events.
    pub(super) fn on_opened(
        config: &ScenarioConfig,
        opened: Opened,
        made: Option<std::sync::Arc<super::made::events::Rules>>,
    ) -> Result<Scenario, ScenarioError> {
        let setup = Setup { no_autoaim: config.no_autoaim(), ..Setup::SINGLE };
        let pristine = Self::game(config, &opened, 0, setup)?;
        Ok(Scenario { config: config.clone(), opened, pristine, decorate_unread: Vec::new(), made })
    }

    fn game(config: &ScenarioConfig, opened: &Opened, seed: u64, setup: Setup) -> Result<SimGame, ScenarioError> {
        let skill = config.doom_skill.clamp(1, 5) as u8;
        let options = GameOptions { skill, seed, no_monsters: false };
        SimGame::netgame(opened.clone(), options, setup).map_err(|e| ScenarioError::Open(e.to_string()))
    }

    /// A new episode, its random generators seeded with `seed`, after the
    /// start time's tics played with no input: a copy of the game set up
    /// once, the same as a game set up anew with `seed`.
    pub fn episode(&self, seed: u64) -> Result<Episode, ScenarioError> {
        let Some(game) = self.pristine.reseeded(seed) else { unreachable!("the pristine game is unplayed, seed 0") };
        Ok(self.begin(game))
    }

    /// [`Scenario::episode`] with `setup` players (a multiplayer scenario:
    /// the others' commands go in through `Episode::game`'s
    /// `command_all`; [`Episode::step`] plays the first player's).
    pub fn episode_with(&self, seed: u64, setup: Setup) -> Result<Episode, ScenarioError> {
        Ok(self.begin(Self::game(&self.config, &self.opened, seed, setup)?))
    }

    /// An episode of `game`, after the start time.
    fn begin(&self, game: SimGame) -> Episode {
        let buffers = TicBuffers::new(&self.config, &self.opened, &game).map(Box::new);
        let mut episode = Episode {
            game,
            config: self.config.clone(),
            actions: 0,
            total_reward: 0.0,
            end: None,
            reward_global: 0,
            leaving: false,
            turn_held: 0,
            counts: Counts::default(),
            made: None,
            buffers,
        };
        for _ in 0..self.config.episode_start_time {
            episode.game.command(Ticcmd::default());
            episode.heard();
        }
        episode.made = self.made.as_ref().map(|rules| rules.start(&episode.game));
        episode.reward_global = episode.global(0);
        episode.counts = Counts::of(&episode.game, 0);
        episode
    }
}

impl Episode {
    /// ACS global variable `i` (16.16 where the scenario keeps a reward).
    pub fn global(&self, i: usize) -> i32 {
        self.game.scripts().map_or(0, |s| s.global(i))
    }

    /// The audio and notifications buffers, when the `.cfg` turns either on.
    pub fn buffers(&self) -> Option<&TicBuffers> {
        self.buffers.as_deref()
    }

    /// Feeds the tic just played to the buffers.
    fn heard(&mut self) {
        if let Some(b) = &mut self.buffers {
            b.tic(&self.game);
        }
    }

    /// How the episode ended, once it has.
    pub fn end(&self) -> Option<End> {
        self.end
    }

    /// Tics a turn button has been held up to now (the next tic's turn
    /// step depends on it: `command`).
    pub fn turn_held(&self) -> u32 {
        self.turn_held
    }

    /// A made scenario's goals paid so far, in its `reach` order (empty
    /// for a `.cfg` scenario).
    pub fn reached(&self) -> &[bool] {
        self.made.as_ref().map_or(&[], |m| m.reached())
    }

    /// One action: `pressed[i]` for the `.cfg`'s `available_buttons[i]`
    /// (delta buttons take their value: degrees for turns, units for
    /// moves). Returns the action's reward (0 once the episode is over).
    pub fn step(&mut self, pressed: &[f64]) -> f64 {
        if self.end.is_some() {
            return 0.0;
        }
        let rewards = self.config.rewards;
        let mut reward = rewards.living;
        self.actions += 1;
        if self.leaving {
            self.end = Some(End::Exit);
        } else {
            let cmd = self.command(pressed);
            self.game.command(cmd);
            self.heard();
            let global = self.global(0);
            reward += f64::from(global.wrapping_sub(self.reward_global)) / 65536.0;
            self.reward_global = global;
            if Counts::paid(&rewards) {
                let counts = Counts::of(&self.game, 0);
                reward += counts.reward_since(&self.counts, &rewards);
                self.counts = counts;
            }
            if self.game.player().health <= 0 {
                reward -= rewards.death_penalty;
                self.end = Some(End::Death);
            } else if self.game.sim.exit.is_some() {
                reward += rewards.map_exit;
                self.leaving = true;
            }
            if let Some((paid, end)) = self.made.as_mut().map(|m| m.tic(&self.game)) {
                reward += paid;
                self.end = self.end.or(end);
            }
        }
        if self.end.is_none() && self.config.episode_timeout > 0 && self.actions >= self.config.episode_timeout {
            self.end = Some(End::Timeout);
        }
        self.total_reward += reward;
        reward
    }

    /// [`Episode::step`] `tics` times with the same buttons, as ViZDoom's
    /// `make_action(action, tics)`: the rewards summed, stopping early when
    /// the episode ends.
    pub fn step_tics(&mut self, pressed: &[f64], tics: u32) -> f64 {
        let mut reward = 0.0;
        for _ in 0..tics.max(1) {
            if self.end.is_some() {
                break;
            }
            reward += self.step(pressed);
        }
        reward
    }

    /// Doom's command for the pressed buttons.
    fn command(&mut self, pressed: &[f64]) -> Ticcmd {
        command(&self.config, pressed, &mut self.turn_held)
    }
}

/// Doom's command for `pressed` (one value per `config`'s available
/// button); `turn_held` counts the tics a turn button has been held.
pub(super) fn command(config: &ScenarioConfig, pressed: &[f64], turn_held: &mut u32) -> Ticcmd {
    let held = |b: Button| {
        let i = config.available_buttons.iter().position(|&x| x == b);
        i.and_then(|i| pressed.get(i)).copied().unwrap_or(0.0)
    };
    let on = |b: Button| held(b) != 0.0;
    let speed = on(Button::Speed);
    let (walk, strafe) = if speed { (50.0, 40.0) } else { (25.0, 24.0) };
    let mut forward = 0.0;
    let mut side = 0.0;
    forward += if on(Button::MoveForward) { walk } else { 0.0 };
    forward -= if on(Button::MoveBackward) { walk } else { 0.0 };
    side += if on(Button::MoveRight) { strafe } else { 0.0 };
    side -= if on(Button::MoveLeft) { strafe } else { 0.0 };
    forward += held(Button::MoveForwardBackwardDelta);
    side += held(Button::MoveLeftRightDelta);
    let turning = on(Button::TurnLeft) != on(Button::TurnRight);
    *turn_held = if turning { *turn_held + 1 } else { 0 };
    let rate = if speed {
        1280.0
    } else if *turn_held <= SLOW_TURN_TICS {
        320.0
    } else {
        640.0
    };
    let mut turn = 0.0;
    turn += if on(Button::TurnLeft) { rate } else { 0.0 };
    turn -= if on(Button::TurnRight) { rate } else { 0.0 };
    // Delta turns are degrees, positive to the right.
    turn -= (held(Button::TurnLeftRightDelta) * 32768.0 / 180.0).floor();
    let mut bits = 0;
    if on(Button::Attack) {
        bits |= buttons::ATTACK;
    }
    if on(Button::Use) {
        bits |= buttons::USE;
    }
    let clamp8 = |v: f64| v.clamp(-127.0, 127.0) as i8;
    Ticcmd { forward: clamp8(forward), side: clamp8(side), turn: turn.clamp(-32768.0, 32767.0) as i16, buttons: bits }
}

/// The comparison's random policy (`scripts/vizdoom-compare.py` plays the
/// same in ViZDoom): each tic one of the `.cfg`'s buttons pressed alone, or
/// none, each with the same chance, from a generator seeded apart from the
/// game's.
pub struct RandomPolicy {
    rng: rand::rngs::ChaCha8Rng,
}

impl RandomPolicy {
    pub fn new(seed: u64) -> RandomPolicy {
        use rand::SeedableRng;
        RandomPolicy { rng: rand::rngs::ChaCha8Rng::seed_from_u64(seed) }
    }

    /// The next action for `buttons` buttons.
    pub fn action(&mut self, buttons: usize) -> Vec<f64> {
        use rand::RngExt;
        let mut pressed = vec![0.0; buttons];
        let pick = self.rng.random_range(0..=buttons);
        if let Some(b) = pressed.get_mut(pick) {
            *b = 1.0;
        }
        pressed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What two games must agree on: every body's place and health, the
    /// generators' cursors, the scripts' reward.
    fn fingerprint(e: &Episode) -> (Vec<(i32, i32, i32, i32)>, u8, u8, i32) {
        let sim = &e.game.sim;
        let bodies = sim.mobjs.iter().map(|m| (m.x.0, m.y.0, m.z.0, m.health)).collect();
        (bodies, sim.rng.p_index(), sim.rng.m_index(), e.global(0))
    }

    /// A copied, reseeded game plays as one set up anew with the seed,
    /// with scripts (ACS random numbers) and monsters (Doom's table).
    #[test]
    fn a_reseeded_copy_plays_as_a_game_set_up_with_its_seed() {
        let Some(dir) = super::super::shipped_dir() else { return };
        for name in ["defend_the_center.cfg", "predict_position.cfg", "health_gathering.cfg"] {
            let config = ScenarioConfig::load(dir.join(name)).unwrap();
            let scenario = Scenario::open(&config, None).unwrap();
            let setup = Setup { no_autoaim: config.no_autoaim(), ..Setup::SINGLE };
            for seed in [1, 77, 4096] {
                let mut copied = scenario.episode(seed).unwrap();
                let mut fresh = scenario.episode_with(seed, setup).unwrap();
                let mut policy = RandomPolicy::new(seed);
                for tic in 0..300 {
                    let action = policy.action(config.available_buttons.len());
                    copied.step(&action);
                    fresh.step(&action);
                    assert_eq!(fingerprint(&copied), fingerprint(&fresh), "{name} seed {seed} tic {tic}");
                }
                assert_eq!(copied.total_reward, fresh.total_reward, "{name} seed {seed}");
            }
        }
    }
}
