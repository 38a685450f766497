//! Several agents in one game: a multiplayer scenario (multi_duel,
//! deathmatch, cig, or any deathmatch map) with each player driven by its
//! own action every tic, all in the same tic of one simulation, and each
//! scored as ViZDoom scores a player: the change in ACS global 0 (the same
//! for all), the living reward, the 1.3 event rewards on that player's own
//! counts (frags, hits, damage, ...), and the death penalty for each death.
//!
//! A dead player comes back as in a ViZDoom netgame after
//! `respawn_player`: its next command presses USE, which Doom's
//! `P_DeathThink` takes as the wish to be reborn, and the game brings it
//! back at a deathmatch start (`SimGame::command_all`). The episode ends
//! when the level is left or after `episode_timeout` actions; a death does
//! not end it.

use super::run::{command, Counts, End};
use super::{Scenario, ScenarioConfig, ScenarioError};
use crate::play::lmp::{buttons, Ticcmd};
use crate::sim::game::{Setup, SimGame};
use crate::sim::MAXPLAYERS;

/// One episode of a game with several agents.
pub struct MultiEpisode {
    pub game: SimGame,
    pub config: ScenarioConfig,
    players: usize,
    pub actions: u32,
    /// Each player's reward summed over the actions taken.
    pub total_rewards: Vec<f64>,
    end: Option<End>,
    reward_global: i32,
    counts: Vec<Counts>,
    deaths: Vec<i32>,
    turn_held: Vec<u32>,
}

impl Scenario {
    /// A game of `players` agents (1 to [`MAXPLAYERS`], sixteen),
    /// deathmatch (`deathmatch` 1, or 2 for altdeath) or co-operative (0),
    /// seeded with `seed`. Players the map has no start for spawn where
    /// `sim::starts` puts them.
    pub fn multi_episode(&self, seed: u64, players: usize, deathmatch: u8) -> Result<MultiEpisode, ScenarioError> {
        if !(1..=MAXPLAYERS).contains(&players) {
            return Err(ScenarioError::Open(format!("{players} agents: a game holds 1 to {MAXPLAYERS} players")));
        }
        let setup = Setup { players, deathmatch, no_autoaim: self.config.no_autoaim() };
        let episode = self.episode_with(seed, setup)?;
        let game = episode.game;
        let global = game.scripts().map_or(0, |s| s.global(0));
        let counts = (0..players).map(|n| Counts::of(&game, n)).collect();
        let deaths = (0..players).map(|n| game.sim.zdoom.tallies[n].deaths).collect();
        Ok(MultiEpisode {
            game,
            config: self.config.clone(),
            players,
            actions: 0,
            total_rewards: vec![0.0; players],
            end: None,
            reward_global: global,
            counts,
            deaths,
            turn_held: vec![0; players],
        })
    }
}

impl MultiEpisode {
    pub fn players(&self) -> usize {
        self.players
    }

    /// How the episode ended, once it has.
    pub fn end(&self) -> Option<End> {
        self.end
    }

    /// One tic: `actions[n]` for player `n` (one value per available
    /// button). Returns each player's reward (all 0 once the episode is
    /// over).
    pub fn step(&mut self, actions: &[Vec<f64>]) -> Vec<f64> {
        let mut rewards = vec![0.0; self.players];
        if self.end.is_some() {
            return rewards;
        }
        let mut cmds: [Option<Ticcmd>; MAXPLAYERS] = [None; MAXPLAYERS];
        for (n, cmd) in cmds.iter_mut().enumerate().take(self.players) {
            let pressed = actions.get(n).map_or(&[][..], Vec::as_slice);
            let mut c = command(&self.config, pressed, &mut self.turn_held[n]);
            if self.game.sim.player(n).is_some_and(|p| p.health <= 0) {
                c.buttons |= buttons::USE;
            }
            *cmd = Some(c);
        }
        self.game.command_all(&cmds);
        self.actions += 1;
        let global = self.game.scripts().map_or(0, |s| s.global(0));
        let shared = f64::from(global.wrapping_sub(self.reward_global)) / 65536.0;
        self.reward_global = global;
        let r = self.config.rewards;
        for (n, reward) in rewards.iter_mut().enumerate() {
            let counts = Counts::of(&self.game, n);
            let deaths = self.game.sim.zdoom.tallies[n].deaths;
            *reward = shared + r.living + counts.reward_since(&self.counts[n], &r)
                - r.death_penalty * f64::from(deaths - self.deaths[n]);
            self.counts[n] = counts;
            self.deaths[n] = deaths;
        }
        if self.game.sim.exit.is_some() {
            for reward in &mut rewards {
                *reward += r.map_exit;
            }
            self.end = Some(End::Exit);
        } else if self.config.episode_timeout > 0 && self.actions >= self.config.episode_timeout {
            self.end = Some(End::Timeout);
        }
        for (total, reward) in self.total_rewards.iter_mut().zip(&rewards) {
            *total += reward;
        }
        rewards
    }
}

#[cfg(test)]
mod tests {
    use super::super::RandomPolicy;
    use super::*;

    /// Two agents in multi_duel: both act in the same tics, both see their
    /// own view, frags and deaths are each player's, and a dead agent
    /// comes back.
    #[test]
    fn two_agents_duel_in_one_game() {
        let Some(dir) = super::super::shipped_dir() else { return };
        let config = ScenarioConfig::load(dir.join("multi_duel.cfg")).unwrap();
        let scenario = Scenario::open(&config, None).unwrap();
        let mut episode = scenario.multi_episode(3, 2, 1).unwrap();
        let mut policies = [RandomPolicy::new(1), RandomPolicy::new(2)];
        let buttons = config.available_buttons.len();
        let mut died = [false; 2];
        let mut reborn = [false; 2];
        for _ in 0..3000 {
            let actions: Vec<Vec<f64>> = policies.iter_mut().map(|p| p.action(buttons)).collect();
            episode.step(&actions);
            for n in 0..2 {
                let health = episode.game.sim.player(n).map_or(0, |p| p.health);
                reborn[n] |= died[n] && health > 0;
                died[n] |= health <= 0;
            }
        }
        let views: Vec<_> = (0..2)
            .map(|n| {
                assert!(episode.game.look_as(n));
                episode.game.view(1.0)
            })
            .collect();
        assert_ne!(views[0].pos, views[1].pos, "each agent sees from its own body");
        assert!(!episode.game.look_as(2), "no third player");
        let frags: Vec<f64> = (0..2)
            .map(|n| super::super::variables::value(&episode.game, n, super::super::GameVariable::FragCount))
            .collect();
        let deaths: Vec<i32> = (0..2).map(|n| episode.game.sim.zdoom.tallies[n].deaths).collect();
        assert!(deaths.iter().sum::<i32>() > 0, "3,000 tics of random shooting in a duel kill someone: {deaths:?}");
        for n in 0..2 {
            if died[n] {
                assert!(reborn[n], "player {n} died and was not reborn");
            }
        }
        assert!(frags.iter().all(|f| f.is_finite()));
    }
}
