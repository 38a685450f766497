//! `MultiGame`: several agents in one game (the PettingZoo environment's
//! core). Every agent's action goes into the same tic; each agent's screen
//! is drawn from its own eyes (`SimGame::look_as`), one after another.

use std::sync::Arc;

use numpy::{PyArrayDyn, PyReadonlyArray2};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use sightline::scenario::observe::{convert_into, shape, Observer};
use sightline::scenario::{variables, End, GameVariable, MultiEpisode};

use crate::env::Opened;
use crate::{array, Config};

/// One game of several agents (1 to 16).
#[pyclass(module = "sightline._native")]
pub struct MultiGame {
    opened: Arc<Opened>,
    players: usize,
    deathmatch: u8,
    episode: Option<MultiEpisode>,
    observers: Vec<Observer>,
    variables: Vec<GameVariable>,
}

impl MultiGame {
    fn episode(&mut self) -> PyResult<&mut MultiEpisode> {
        self.episode.as_mut().ok_or_else(|| PyRuntimeError::new_err("no episode is running: call new_episode first"))
    }
}

#[pymethods]
impl MultiGame {
    /// `players` agents in `config`'s scenario: deathmatch (1), altdeath
    /// (2) or co-operative (0).
    #[new]
    #[pyo3(signature = (config, players, deathmatch=1, iwad=None))]
    fn new(
        py: Python<'_>,
        config: &Config,
        players: usize,
        deathmatch: u8,
        iwad: Option<String>,
    ) -> PyResult<MultiGame> {
        if !(1..=sightline::sim::MAXPLAYERS).contains(&players) {
            let max = sightline::sim::MAXPLAYERS;
            return Err(PyValueError::new_err(format!("{players} agents: a game holds 1 to {max} players")));
        }
        if deathmatch > 2 {
            return Err(PyValueError::new_err(format!(
                "deathmatch {deathmatch}: 0 co-operative, 1 deathmatch, 2 altdeath"
            )));
        }
        let cfg = config.inner.clone();
        let opened = Arc::new(py.detach(|| Opened::open(&cfg, iwad.as_deref()))?);
        let observers = (0..players).map(|_| Observer::new(&cfg, 1)).collect();
        let variables = cfg.available_game_variables.clone();
        Ok(MultiGame { opened, players, deathmatch, episode: None, observers, variables })
    }

    fn __len__(&self) -> usize {
        self.players
    }

    /// Starts a new episode seeded by `seed`.
    fn new_episode(&mut self, py: Python<'_>, seed: u64) -> PyResult<()> {
        let (opened, players, deathmatch) = (&self.opened, self.players, self.deathmatch);
        let episode = py
            .detach(|| opened.scenario().multi_episode(seed, players, deathmatch))
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        self.episode = Some(episode);
        for o in &mut self.observers {
            o.reset();
        }
        Ok(())
    }

    /// One tic for every agent: row `n` of `actions` is agent `n`'s (one
    /// value per available button); `tics` tics hold them. Returns each
    /// agent's reward.
    #[pyo3(signature = (actions, tics=1))]
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        actions: PyReadonlyArray2<'py, f64>,
        tics: u32,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let actions = actions.as_array();
        let buttons = self.opened.scenario().config.available_buttons.len();
        if actions.nrows() != self.players || actions.ncols() != buttons {
            let (r, c, p) = (actions.nrows(), actions.ncols(), self.players);
            return Err(PyValueError::new_err(format!(
                "actions are {r}x{c}; this game takes {p}x{buttons} (one row per agent, one value per button)"
            )));
        }
        if actions.iter().any(|v| !v.is_finite()) {
            return Err(PyValueError::new_err("an action value is not a finite number"));
        }
        let rows: Vec<Vec<f64>> = actions.rows().into_iter().map(|r| r.to_vec()).collect();
        let players = self.players;
        let episode = self.episode()?;
        let rewards = py.detach(|| {
            let mut sum = vec![0.0; players];
            for _ in 0..tics.max(1) {
                if episode.end().is_some() {
                    break;
                }
                for (s, r) in sum.iter_mut().zip(episode.step(&rows)) {
                    *s += r;
                }
            }
            sum
        });
        array(py, &[rewards.len()], rewards)
    }

    /// Every agent's screen from its own eyes, stacked on a first axis.
    fn screens<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<u8>>> {
        let config = self.opened.scenario().config.clone();
        let r = config.screen_resolution;
        let one = shape(config.screen_format, usize::from(r.width), usize::from(r.height));
        let size: usize = one.iter().product();
        let players = self.players;
        let Some(episode) = self.episode.as_mut() else {
            return Err(PyRuntimeError::new_err("no episode is running: call new_episode first"));
        };
        let observers = &mut self.observers;
        let bytes = py.detach(|| -> PyResult<Vec<u8>> {
            let mut bytes = vec![0u8; size * players];
            for (n, (observer, out)) in observers.iter_mut().zip(bytes.chunks_mut(size)).enumerate() {
                episode.game.look_as(n);
                observer.render(&episode.game);
                convert_into(observer.screen(), config.screen_format, out)
                    .map_err(|e| PyValueError::new_err(e.to_string()))?;
            }
            episode.game.look_as(episode.game.sim.console);
            Ok(bytes)
        })?;
        let mut full = vec![players];
        full.extend(one);
        array(py, &full, bytes)
    }

    /// Every agent's available game variables, one row each.
    fn game_variables<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (players, vars) = (self.players, self.variables.clone());
        let episode = self.episode()?;
        let values: Vec<f64> = (0..players)
            .flat_map(|n| vars.iter().map(move |&v| (n, v)))
            .map(|(n, v)| variables::value(&episode.game, n, v))
            .collect();
        array(py, &[players, vars.len()], values)
    }

    /// Whether agent `n` is dead (it comes back on its next action).
    fn is_player_dead(&self, n: usize) -> bool {
        self.episode.as_ref().and_then(|e| e.game.sim.player(n)).is_some_and(|p| p.health <= 0)
    }

    fn is_finished(&self) -> bool {
        self.episode.as_ref().is_none_or(|e| e.end().is_some())
    }

    /// How the episode ended: "exit", "timeout", or None.
    fn end(&self) -> Option<&'static str> {
        self.episode.as_ref().and_then(MultiEpisode::end).map(|e| match e {
            End::Exit => "exit",
            End::Death => "death",
            End::Timeout => "timeout",
        })
    }

    fn total_rewards(&self) -> Vec<f64> {
        self.episode.as_ref().map_or_else(|| vec![0.0; self.players], |e| e.total_rewards.clone())
    }

    /// Actions taken this episode.
    fn actions(&self) -> u32 {
        self.episode.as_ref().map_or(0, |e| e.actions)
    }

    /// The available buttons' names, in order.
    fn buttons(&self) -> Vec<String> {
        self.opened.scenario().config.available_buttons.iter().map(|b| b.name()).collect()
    }
}
