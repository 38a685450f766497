//! `sightline._native`: the engine's scenarios for Python. A small core
//! that the pure-Python layers build on (`sightline.vizdoom`'s `DoomGame`,
//! the Gymnasium and PettingZoo environments):
//!
//! - [`Config`]: a ViZDoom `.cfg`'s settings, read and changed with the
//!   engine's own `.cfg` reader (so a setter and a file line are checked
//!   alike);
//! - [`Game`]: one scenario game, stepped with the interpreter lock released;
//! - [`Games`]: many games stepped together on the caller's and helper
//!   threads (the vector environment);
//! - [`multi::MultiGame`]: several agents in one game (PettingZoo).
//!
//! Every buffer reaches Python as a numpy array that owns the engine's
//! bytes (no copy after the engine writes them).

mod crew;
mod env;
mod made;
mod multi;

use numpy::ndarray::{Array, IxDyn};
use numpy::{IntoPyArray, PyArrayDyn, PyArrayMethods, PyReadonlyArray2};
use pyo3::exceptions::{PyFileNotFoundError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use sightline::scenario::{GameVariable, ScenarioConfig};

use env::{Env, Opened};

/// A scenario's settings: every `.cfg` key ViZDoom 1.3.2 reads, with
/// ViZDoom's defaults.
#[pyclass(module = "sightline._native")]
#[derive(Clone)]
pub struct Config {
    pub(crate) inner: ScenarioConfig,
}

#[pymethods]
impl Config {
    #[new]
    fn new() -> Config {
        Config { inner: ScenarioConfig::default() }
    }

    /// Applies the `.cfg` file at `path` onto these settings (ViZDoom's
    /// `load_config`); its relative paths are relative to it.
    fn load(&mut self, path: &str) -> PyResult<()> {
        let bytes =
            std::fs::read(path).map_err(|e| PyFileNotFoundError::new_err(format!("{path}: cannot read: {e}")))?;
        let label = std::path::absolute(path).map_or_else(|_| path.to_string(), |p| p.display().to_string());
        self.apply(&String::from_utf8_lossy(&bytes), &label)
    }

    /// Applies `.cfg` text onto these settings; `label` names it in errors
    /// and its directory is where its relative paths start.
    fn apply(&mut self, text: &str, label: &str) -> PyResult<()> {
        self.inner.apply(text, label).map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// The settings as a dictionary of plain values (names as ViZDoom's
    /// enums spell them).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let c = &self.inner;
        let d = PyDict::new(py);
        let path = |p: &Option<String>| p.as_deref().map(|p| c.resolve(p).display().to_string()).unwrap_or_default();
        d.set_item("vizdoom_path", path(&c.vizdoom_path))?;
        d.set_item("doom_game_path", path(&c.doom_game_path))?;
        d.set_item("doom_scenario_path", path(&c.doom_scenario_path))?;
        d.set_item("doom_config_path", path(&c.doom_config_path))?;
        d.set_item("doom_map", c.doom_map.to_ascii_lowercase())?;
        d.set_item("doom_skill", c.doom_skill)?;
        d.set_item("seed", c.seed)?;
        d.set_item("game_args", c.game_args.join(" "))?;
        d.set_item("mode", c.mode.name())?;
        d.set_item("ticrate", c.ticrate)?;
        d.set_item("episode_timeout", c.episode_timeout)?;
        d.set_item("episode_start_time", c.episode_start_time)?;
        let r = &c.rewards;
        for (k, v) in [
            ("living_reward", r.living),
            ("death_penalty", r.death_penalty),
            ("map_exit_reward", r.map_exit),
            ("kill_reward", r.kill),
            ("item_reward", r.item),
            ("secret_reward", r.secret),
            ("frag_reward", r.frag),
            ("hit_reward", r.hit),
            ("hit_taken_penalty", r.hit_taken_penalty),
            ("damage_made_reward", r.damage_made),
            ("damage_taken_penalty", r.damage_taken_penalty),
            ("health_reward", r.health),
            ("armor_reward", r.armor),
        ] {
            d.set_item(k, v)?;
        }
        d.set_item("available_buttons", c.available_buttons.iter().map(|b| b.name()).collect::<Vec<_>>())?;
        let max: Vec<(String, u32)> = c.button_max_values.iter().map(|(b, v)| (b.name(), *v)).collect();
        d.set_item("button_max_values", max)?;
        let vars: Vec<String> = c.available_game_variables.iter().map(|v| v.name()).collect();
        d.set_item("available_game_variables", vars)?;
        d.set_item("screen_width", c.screen_resolution.width)?;
        d.set_item("screen_height", c.screen_resolution.height)?;
        d.set_item("screen_format", c.screen_format.name())?;
        let f = &c.render;
        for (k, v) in [
            ("render_hud", f.hud),
            ("render_minimal_hud", f.minimal_hud),
            ("render_weapon", f.weapon),
            ("render_crosshair", f.crosshair),
            ("render_decals", f.decals),
            ("render_particles", f.particles),
            ("render_effects_sprites", f.effects_sprites),
            ("render_messages", f.messages),
            ("render_corpses", f.corpses),
            ("render_screen_flashes", f.screen_flashes),
            ("render_all_frames", f.all_frames),
        ] {
            d.set_item(k, v)?;
        }
        let o = &c.outputs;
        for (k, v) in [
            ("depth_buffer_enabled", o.depth_buffer),
            ("labels_buffer_enabled", o.labels_buffer),
            ("automap_buffer_enabled", o.automap_buffer),
            ("audio_buffer_enabled", o.audio_buffer),
            ("notifications_buffer_enabled", o.notifications_buffer),
            ("objects_info_enabled", o.objects_info),
            ("sectors_info_enabled", o.sectors_info),
            ("window_visible", c.window_visible),
            ("console_enabled", c.console_enabled),
            ("sound_enabled", c.sound_enabled),
            ("automap_rotate", c.automap.rotate),
            ("automap_render_textures", c.automap.render_textures),
            ("automap_render_objects_as_sprites", c.automap.render_objects_as_sprites),
        ] {
            d.set_item(k, v)?;
        }
        d.set_item("audio_sampling_rate", o.audio_sampling_rate.hertz())?;
        d.set_item("audio_buffer_size", o.audio_buffer_size)?;
        d.set_item("notifications_buffer_size", o.notifications_buffer_size)?;
        d.set_item("automap_mode", c.automap.mode.name())?;
        Ok(d)
    }
}

/// A game variable by ViZDoom's name (`AMMO2`), as a `ValueError` if unknown.
fn variable(name: &str) -> PyResult<GameVariable> {
    GameVariable::from_cfg(&name.to_ascii_lowercase()).ok_or_else(|| {
        PyValueError::new_err(format!("unknown game variable `{name}` (ViZDoom's names: HEALTH, AMMO2, USER1, ...)"))
    })
}

/// A numpy array owning `data`, of `shape`.
pub(crate) fn array<'py, T: numpy::Element>(
    py: Python<'py>,
    shape: &[usize],
    data: Vec<T>,
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    let a = Array::from_shape_vec(IxDyn(shape), data).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    Ok(a.into_pyarray(py))
}

/// One scenario game.
#[pyclass(module = "sightline._native")]
struct Game {
    env: Env,
}

#[pymethods]
impl Game {
    /// Opens `config`'s scenario (its WAD on `iwad`, else the `.cfg`'s
    /// game WAD, else `freedoom2.wad` where Doom ports look), drawing with
    /// `threads` threads. No episode runs until `new_episode`.
    #[new]
    #[pyo3(signature = (config, iwad=None, threads=1))]
    fn new(py: Python<'_>, config: &Config, iwad: Option<String>, threads: usize) -> PyResult<Game> {
        let config = config.inner.clone();
        let opened = py.detach(|| Opened::open(&config, iwad.as_deref()))?;
        Ok(Game { env: Env::new(opened.into(), threads) })
    }

    /// Starts a new episode with its random generator seeded by `seed`.
    fn new_episode(&mut self, py: Python<'_>, seed: u64) -> PyResult<()> {
        let env = &mut self.env;
        py.detach(|| env.new_episode(seed))
    }

    /// Plays `tics` tics holding `action` (one value per available
    /// button); returns their summed reward.
    #[pyo3(signature = (action, tics=1))]
    fn step(&mut self, py: Python<'_>, action: Vec<f64>, tics: u32) -> PyResult<f64> {
        self.env.check_action(&action)?;
        let env = &mut self.env;
        py.detach(|| env.step(&action, tics))
    }

    /// What the autopilot would press now, as an action (one value per
    /// available button; delta buttons carry its exact turn or move): the
    /// expert for imitation learning. The autopilot is made when first
    /// asked in an episode and plays along from then on, seeing the game
    /// each time it is asked; asked twice on one tic it answers the same.
    fn expert_action(&mut self, py: Python<'_>) -> PyResult<Vec<f64>> {
        let env = &mut self.env;
        py.detach(|| env.expert_action())
    }

    /// Whether the episode has ended (or none has started).
    fn is_finished(&self) -> bool {
        self.env.finished()
    }

    fn is_player_dead(&self) -> bool {
        self.env.player_dead()
    }

    fn is_timeout_reached(&self) -> bool {
        self.env.timeout_reached()
    }

    /// How the episode ended: "exit", "death", "timeout", or None.
    fn end(&self) -> Option<&'static str> {
        self.env.end()
    }

    fn total_reward(&self) -> f64 {
        self.env.total_reward()
    }

    fn last_reward(&self) -> f64 {
        self.env.last_reward
    }

    /// Tics played this episode (the start time's included).
    fn episode_time(&self) -> u64 {
        self.env.episode_time()
    }

    /// Actions taken this episode.
    fn actions(&self) -> u32 {
        self.env.actions()
    }

    /// One game variable by ViZDoom's name.
    fn game_variable(&self, name: &str) -> PyResult<f64> {
        Ok(self.env.variable(variable(name)?))
    }

    /// The `.cfg`'s available game variables, in order.
    fn game_variables<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let values = self.env.variables();
        array(py, &[values.len()], values)
    }

    /// The screen in the `.cfg`'s format and size.
    fn screen<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<u8>>> {
        let env = &mut self.env;
        let (shape, bytes) = py.detach(|| env.screen())?;
        array(py, &shape, bytes)
    }

    /// The depth buffer (height, width; float32 map units along the view,
    /// infinite for the sky).
    fn depth<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f32>>> {
        let env = &mut self.env;
        let (shape, values) = py.detach(|| env.depth())?;
        array(py, &shape, values)
    }

    /// The labels buffer (height, width; uint8) and its objects, each a
    /// dictionary of ViZDoom's `Label` fields.
    fn labels<'py>(&mut self, py: Python<'py>) -> PyResult<(Bound<'py, PyArrayDyn<u8>>, Vec<Bound<'py, PyDict>>)> {
        let env = &mut self.env;
        let (shape, values, labels) = py.detach(|| env.labels())?;
        let objects = labels
            .into_iter()
            .map(|l| {
                let d = PyDict::new(py);
                d.set_item("object_id", l.object_id)?;
                d.set_item("object_name", l.object_name)?;
                d.set_item("value", l.value)?;
                d.set_item("x", l.x)?;
                d.set_item("y", l.y)?;
                d.set_item("width", l.width)?;
                d.set_item("height", l.height)?;
                for (k, v) in ["object_position_x", "object_position_y", "object_position_z"].iter().zip(l.position) {
                    d.set_item(*k, v)?;
                }
                d.set_item("object_angle", l.angle)?;
                for (k, v) in ["object_velocity_x", "object_velocity_y", "object_velocity_z"].iter().zip(l.velocity) {
                    d.set_item(*k, v)?;
                }
                Ok(d)
            })
            .collect::<PyResult<Vec<_>>>()?;
        Ok((array(py, &shape, values)?, objects))
    }

    /// The automap in the screen's format and size.
    fn automap<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<u8>>> {
        let env = &mut self.env;
        let (shape, bytes) = py.detach(|| env.automap())?;
        array(py, &shape, bytes)
    }

    /// The audio buffer (frames, 2; int16 stereo): the sound effects of
    /// the last `audio_buffer_size` tics at `audio_sampling_rate`, oldest
    /// first (tics x rate / 35 frames).
    fn audio<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<i16>>> {
        let (shape, samples) = self.env.audio()?;
        array(py, &shape, samples)
    }

    /// The notifications buffer: the messages the player was shown in
    /// the last `notifications_buffer_size` tics (pickups, keys, locked
    /// doors, secrets, the scripts' prints), each followed by a newline.
    fn notifications(&self) -> PyResult<String> {
        self.env.notifications()
    }

    /// Every body in the level, each a dictionary of ViZDoom's `Object`
    /// fields (`id` is the body's, as a label's `object_id`; pitch and roll
    /// are 0, the category empty).
    fn objects<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
        let objects = self.env.objects()?;
        objects
            .into_iter()
            .map(|o| {
                let d = PyDict::new(py);
                d.set_item("id", o.id)?;
                d.set_item("name", o.name)?;
                d.set_item("category", "")?;
                for (k, v) in ["position_x", "position_y", "position_z"].iter().zip(o.position) {
                    d.set_item(*k, v)?;
                }
                d.set_item("angle", o.angle)?;
                d.set_item("pitch", 0.0)?;
                d.set_item("roll", 0.0)?;
                for (k, v) in ["velocity_x", "velocity_y", "velocity_z"].iter().zip(o.velocity) {
                    d.set_item(*k, v)?;
                }
                d.set_item("sector_id", o.sector)?;
                Ok(d)
            })
            .collect()
    }

    /// Every sector, each a dictionary of ViZDoom's `Sector` fields with
    /// its `lines` as dictionaries of `Line`'s (`x1`, `y1`, `x2`, `y2`,
    /// `is_blocking`: one-sided or flagged to block).
    fn sectors<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
        let sectors = self.env.sectors()?;
        sectors
            .into_iter()
            .map(|s| {
                let d = PyDict::new(py);
                d.set_item("id", s.id)?;
                d.set_item("floor_height", s.floor)?;
                d.set_item("ceiling_height", s.ceiling)?;
                let lines = s
                    .lines
                    .iter()
                    .map(|l| {
                        let line = PyDict::new(py);
                        line.set_item("x1", l.from[0])?;
                        line.set_item("y1", l.from[1])?;
                        line.set_item("x2", l.to[0])?;
                        line.set_item("y2", l.to[1])?;
                        line.set_item("is_blocking", l.blocking)?;
                        Ok(line)
                    })
                    .collect::<PyResult<Vec<_>>>()?;
                d.set_item("lines", lines)?;
                Ok(d)
            })
            .collect()
    }

    /// The available buttons' names, in order.
    fn buttons(&self) -> Vec<String> {
        self.env.config().available_buttons.iter().map(|b| b.name()).collect()
    }
}

/// Each game's reward from a step, and whether its episode has ended.
type Played = (Vec<f64>, Vec<bool>);

/// Many games of one scenario, stepped together by the calling thread and
/// helper threads ([`crew`]).
#[pyclass(module = "sightline._native")]
struct Games {
    crew: crew::Crew,
    /// The screens array the last call returned, drawn into again by the
    /// next call if Python has let go of it (see [`Games::screens_array`]).
    spare: Option<Py<PyArrayDyn<u8>>>,
}

impl Games {
    /// `envs` stepped on `threads` threads (0: one per core).
    pub(crate) fn of(envs: Vec<Env>, threads: usize) -> PyResult<Games> {
        let crew = crew::Crew::new(envs, threads)
            .map_err(|e| PyRuntimeError::new_err(format!("cannot start the games' threads: {e}")))?;
        Ok(Games { crew, spare: None })
    }

    /// Checks the actions' rows, one per game, and gives each game its row;
    /// and `resets`, if given, one entry per game: a seed for a game to
    /// start a new episode with instead of playing the step, or None.
    fn set_actions(&self, actions: &PyReadonlyArray2<'_, f64>, resets: Option<Vec<Option<u64>>>) -> PyResult<()> {
        let actions = actions.as_array();
        let n = self.crew.len();
        if actions.nrows() != n {
            let rows = actions.nrows();
            return Err(PyValueError::new_err(format!("actions has {rows} rows for {n} games")));
        }
        if let Some(resets) = &resets {
            if resets.len() != n {
                return Err(PyValueError::new_err(format!("resets has {} entries for {n} games", resets.len())));
            }
        }
        for (i, (mut slot, row)) in self.crew.slots().zip(actions.rows()).enumerate() {
            slot.action.clear();
            slot.action.extend(row.iter());
            slot.env.check_action(&slot.action)?;
            slot.reset = resets.as_ref().and_then(|r| r[i]);
        }
        Ok(())
    }

    /// Plays `tics` tics in every game (drawing each screen into its part
    /// of `out` too, if it is not empty): the rewards and whether each
    /// episode has ended.
    fn play(&self, py: Python<'_>, tics: u32, out: &mut [u8]) -> PyResult<Played> {
        let crew = &self.crew;
        let screen = !out.is_empty();
        py.detach(|| crew.run(crew::Task::Step { tics, screen }, out));
        let (mut rewards, mut done) = (Vec::with_capacity(crew.len()), Vec::with_capacity(crew.len()));
        for mut slot in crew.slots() {
            std::mem::replace(&mut slot.result, Ok(()))?;
            rewards.push(slot.reward);
            done.push(slot.env.finished());
        }
        Ok((rewards, done))
    }

    /// An array for every game's screen, stacked on a first axis: the
    /// games' threads draw straight into it. It is the array the last call
    /// returned when nothing outside holds that any more (the usual loop
    /// copies each step's screens and drops them): no one can see it
    /// change, and the call saves allocating and zeroing a new one (at
    /// 640x480, four games' 3.7 MB on the caller's thread, while the games'
    /// threads waited).
    fn screens_array<'py>(&mut self, py: Python<'py>) -> Bound<'py, PyArrayDyn<u8>> {
        if let Some(spare) = self.spare.take() {
            let spare = spare.into_bound(py);
            if spare.get_refcnt() == 1 {
                return spare;
            }
        }
        let mut shape = vec![self.crew.len()];
        shape.extend(self.crew.slot(0).env.screen_shape());
        PyArrayDyn::zeros(py, IxDyn(&shape), false)
    }

    /// Runs `task` (one that draws) on every game into a screens array,
    /// which it returns and keeps as the next call's spare.
    fn draw<'py>(
        &mut self,
        py: Python<'py>,
        task: impl FnOnce(&Games, Python<'_>, &mut [u8]) -> PyResult<Played>,
    ) -> PyResult<(Played, Bound<'py, PyArrayDyn<u8>>)> {
        let screens = self.screens_array(py);
        let played = {
            let mut bytes = screens.try_readwrite().map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
            let bytes = bytes.as_slice_mut().map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
            task(self, py, bytes)?
        };
        self.spare = Some(screens.clone().unbind());
        Ok((played, screens))
    }
}

#[pymethods]
impl Games {
    /// `count` games of `config`'s scenario, stepped on `threads` threads
    /// (0: one per core).
    #[new]
    #[pyo3(signature = (config, count, iwad=None, threads=0))]
    fn new(py: Python<'_>, config: &Config, count: usize, iwad: Option<String>, threads: usize) -> PyResult<Games> {
        if count == 0 {
            return Err(PyValueError::new_err("a vector of games needs at least one game"));
        }
        let config = config.inner.clone();
        let opened = std::sync::Arc::new(py.detach(|| Opened::open(&config, iwad.as_deref()))?);
        Games::of((0..count).map(|_| Env::new(opened.clone(), 1)).collect(), threads)
    }

    fn __len__(&self) -> usize {
        self.crew.len()
    }

    /// Starts a new episode in game `i` seeded by `seed`.
    fn new_episode(&mut self, py: Python<'_>, i: usize, seed: u64) -> PyResult<()> {
        let count = self.crew.len();
        if i >= count {
            return Err(PyValueError::new_err(format!("no game {i} of {count}")));
        }
        let crew = &self.crew;
        py.detach(|| crew.slot(i).env.new_episode(seed))
    }

    /// Plays `tics` tics in every game, game `i` holding row `i` of
    /// `actions`; returns each game's reward and whether its episode has
    /// ended. `resets` (one entry per game, a seed or None) starts game
    /// `i` on a new episode seeded by `resets[i]` instead of playing its
    /// step (its reward is 0): Gymnasium's autoreset on the games' threads.
    #[pyo3(signature = (actions, tics=1, resets=None))]
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        actions: PyReadonlyArray2<'py, f64>,
        tics: u32,
        resets: Option<Vec<Option<u64>>>,
    ) -> PyResult<(Bound<'py, PyArrayDyn<f64>>, Bound<'py, PyArrayDyn<bool>>)> {
        self.set_actions(&actions, resets)?;
        let (rewards, done) = self.play(py, tics, &mut [])?;
        Ok((array(py, &[rewards.len()], rewards)?, array(py, &[done.len()], done)?))
    }

    /// [`Games::step`] and [`Games::screens`] in one pass over the games'
    /// threads (each game plays its tics and draws its screen in one
    /// task): the rewards, whether each episode has ended, the screens.
    #[pyo3(signature = (actions, tics=1, resets=None))]
    #[allow(clippy::type_complexity)]
    fn step_screens<'py>(
        &mut self,
        py: Python<'py>,
        actions: PyReadonlyArray2<'py, f64>,
        tics: u32,
        resets: Option<Vec<Option<u64>>>,
    ) -> PyResult<(Bound<'py, PyArrayDyn<f64>>, Bound<'py, PyArrayDyn<bool>>, Bound<'py, PyArrayDyn<u8>>)> {
        self.set_actions(&actions, resets)?;
        let ((rewards, done), screens) = self.draw(py, |games, py, bytes| games.play(py, tics, bytes))?;
        Ok((array(py, &[rewards.len()], rewards)?, array(py, &[done.len()], done)?, screens))
    }

    /// Every game's screen, stacked on a first axis (each game draws into
    /// its part of one array, on the games' threads).
    fn screens<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<u8>>> {
        let (_, screens) = self.draw(py, |games, py, bytes| {
            let crew = &games.crew;
            py.detach(|| crew.run(crew::Task::Screen, bytes));
            for mut slot in crew.slots() {
                std::mem::replace(&mut slot.result, Ok(()))?;
            }
            Ok((Vec::new(), Vec::new()))
        })?;
        Ok(screens)
    }

    /// Every game's available game variables, one row each.
    fn game_variables<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let rows: Vec<Vec<f64>> = self.crew.slots().map(|s| s.env.variables()).collect();
        let width = rows[0].len();
        array(py, &[rows.len(), width], rows.concat())
    }

    /// Every game's expert action (`Game.expert_action`), one row each,
    /// answered on the games' threads.
    fn expert_actions<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let crew = &self.crew;
        py.detach(|| crew.run(crew::Task::Expert, &mut []));
        let width = self.crew.slot(0).env.config().available_buttons.len();
        let mut rows = Vec::with_capacity(width * self.crew.len());
        for mut slot in self.crew.slots() {
            std::mem::replace(&mut slot.result, Ok(()))?;
            rows.extend_from_slice(&slot.expert);
        }
        array(py, &[self.crew.len(), width], rows)
    }

    /// Every game's total reward this episode.
    fn total_rewards(&self) -> Vec<f64> {
        self.crew.slots().map(|s| s.env.total_reward()).collect()
    }

    /// How each game's episode ended ("exit", "death", "timeout") or None.
    fn ends(&self) -> Vec<Option<&'static str>> {
        self.crew.slots().map(|s| s.env.end()).collect()
    }
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Config>()?;
    m.add_class::<Game>()?;
    m.add_class::<Games>()?;
    m.add_class::<multi::MultiGame>()?;
    made::register(m)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
