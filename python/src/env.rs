//! One scenario game as Python drives it: the engine's [`Episode`] and an
//! [`Observer`] of it, with the checks a call from Python needs (an action
//! of the wrong length, a step before any episode) turned into Python
//! exceptions. Frames are drawn when asked for, once per state.

use std::sync::Arc;

use pyo3::exceptions::{PyFileNotFoundError, PyRuntimeError, PyValueError};
use pyo3::PyResult;
use sightline::scenario::observe::{convert, convert_into, shape, Observer};
use sightline::scenario::{variables, world, Episode, Expert, GameVariable, Scenario, ScenarioConfig};

/// A scenario opened once, shared by every game of it.
pub struct Opened {
    scenario: Scenario,
}

impl Opened {
    /// A scenario opened otherwise (a made scenario: `made.rs`).
    pub fn of(scenario: Scenario) -> Opened {
        Opened { scenario }
    }

    /// Opens `config`'s scenario, its files checked first so that a
    /// missing one is a `FileNotFoundError` naming it.
    pub fn open(config: &ScenarioConfig, iwad: Option<&str>) -> PyResult<Opened> {
        let given = iwad.map(std::path::PathBuf::from).or_else(|| config.game_wad());
        let wad = config.scenario_wad();
        if wad.is_none() && given.is_none() {
            return Err(PyValueError::new_err(
                "no map: set doom_scenario_path (a scenario WAD) or doom_game_path (a WAD whose own map to play)",
            ));
        }
        for path in [wad, given.clone()].into_iter().flatten() {
            if !path.is_file() {
                return Err(PyFileNotFoundError::new_err(format!("{}: no such file", path.display())));
            }
        }
        let scenario = Scenario::open(config, given.as_deref()).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        Ok(Opened { scenario })
    }

    pub fn scenario(&self) -> &Scenario {
        &self.scenario
    }
}

/// A body seen in the labels buffer (ViZDoom's `Label`).
pub struct Label {
    pub object_id: u32,
    pub object_name: String,
    pub value: u8,
    pub x: usize,
    pub y: usize,
    pub width: usize,
    pub height: usize,
    pub position: [f64; 3],
    pub angle: f64,
    pub velocity: [f64; 3],
}

/// A game of an opened scenario.
pub struct Env {
    opened: Arc<Opened>,
    episode: Option<Episode>,
    observer: Observer,
    /// The available game variables, in order.
    variables: Vec<GameVariable>,
    /// The last step's reward.
    pub last_reward: f64,
    /// The screen drawn is the current state's.
    drawn: bool,
    /// The autopilot playing along, made when first asked for its action
    /// in an episode (so a game never asked pays nothing).
    expert: Option<Expert>,
}

impl Env {
    pub fn new(opened: Arc<Opened>, threads: usize) -> Env {
        let config = &opened.scenario.config;
        let observer = Observer::new(config, threads);
        let variables = config.available_game_variables.clone();
        Env { opened, episode: None, observer, variables, last_reward: 0.0, drawn: false, expert: None }
    }

    pub fn config(&self) -> &ScenarioConfig {
        &self.opened.scenario.config
    }

    pub fn new_episode(&mut self, seed: u64) -> PyResult<()> {
        let episode = self.opened.scenario.episode(seed).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        self.episode = Some(episode);
        self.expert = None;
        self.observer.reset();
        self.last_reward = 0.0;
        self.drawn = false;
        Ok(())
    }

    fn episode(&self) -> PyResult<&Episode> {
        self.episode.as_ref().ok_or_else(|| PyRuntimeError::new_err("no episode is running: call new_episode first"))
    }

    /// An action must give one value per available button, each finite.
    pub fn check_action(&self, action: &[f64]) -> PyResult<()> {
        let buttons = &self.config().available_buttons;
        if action.len() != buttons.len() {
            let names: Vec<String> = buttons.iter().map(|b| b.name()).collect();
            return Err(PyValueError::new_err(format!(
                "an action has one value per available button: {} given for {} ({})",
                action.len(),
                buttons.len(),
                names.join(", ")
            )));
        }
        if let Some(i) = action.iter().position(|v| !v.is_finite()) {
            return Err(PyValueError::new_err(format!("action value {i} ({}) is not a finite number", action[i])));
        }
        Ok(())
    }

    /// `tics` tics holding `action` (checked), delta buttons held to
    /// their `button_max_value`.
    pub fn step(&mut self, action: &[f64], tics: u32) -> PyResult<f64> {
        self.episode()?;
        let config = &self.opened.scenario.config;
        let limited: Vec<f64> = action
            .iter()
            .zip(&config.available_buttons)
            .map(|(&v, b)| match config.button_max_values.get(b) {
                Some(&max) if max > 0 && b.is_delta() => v.clamp(-f64::from(max), f64::from(max)),
                _ => v,
            })
            .collect();
        let Some(episode) = self.episode.as_mut() else { unreachable!("checked above") };
        self.last_reward = episode.step_tics(&limited, tics);
        self.drawn = false;
        Ok(self.last_reward)
    }

    /// What the autopilot would press now: one value per available
    /// button (`scenario::expert`); all zero once the episode is over.
    pub fn expert_action(&mut self) -> PyResult<Vec<f64>> {
        let Some(episode) = self.episode.as_ref() else {
            return Err(PyRuntimeError::new_err("no episode is running: call new_episode first"));
        };
        Ok(self.expert.get_or_insert_with(|| Expert::new(episode)).action(episode))
    }

    pub fn finished(&self) -> bool {
        self.episode.as_ref().is_none_or(|e| e.end().is_some())
    }

    pub fn player_dead(&self) -> bool {
        self.episode.as_ref().is_some_and(|e| e.game.player().health <= 0)
    }

    pub fn timeout_reached(&self) -> bool {
        self.episode.as_ref().is_some_and(|e| e.end() == Some(sightline::scenario::End::Timeout))
    }

    pub fn end(&self) -> Option<&'static str> {
        self.episode.as_ref().and_then(Episode::end).map(|end| match end {
            sightline::scenario::End::Exit => "exit",
            sightline::scenario::End::Death => "death",
            sightline::scenario::End::Timeout => "timeout",
        })
    }

    pub fn total_reward(&self) -> f64 {
        self.episode.as_ref().map_or(0.0, |e| e.total_reward)
    }

    pub fn episode_time(&self) -> u64 {
        self.episode.as_ref().map_or(0, |e| e.game.ticks())
    }

    pub fn actions(&self) -> u32 {
        self.episode.as_ref().map_or(0, |e| e.actions)
    }

    pub fn variable(&self, v: GameVariable) -> f64 {
        self.episode.as_ref().map_or(0.0, |e| variables::value(&e.game, 0, v))
    }

    pub fn variables(&self) -> Vec<f64> {
        self.variables.iter().map(|&v| self.variable(v)).collect()
    }

    /// Draws the current state if it is not drawn yet.
    fn draw(&mut self) -> PyResult<()> {
        if !self.drawn {
            let Some(episode) = self.episode.as_ref() else {
                return Err(PyRuntimeError::new_err("no episode is running: call new_episode first"));
            };
            self.observer.render(&episode.game);
            self.drawn = true;
        }
        Ok(())
    }

    /// The screen in the `.cfg`'s format: its array shape and bytes.
    pub fn screen(&mut self) -> PyResult<(Vec<usize>, Vec<u8>)> {
        self.draw()?;
        let fb = self.observer.screen();
        self.formatted(fb)
    }

    /// The screen's array shape in the `.cfg`'s format.
    pub fn screen_shape(&self) -> Vec<usize> {
        let r = self.config().screen_resolution;
        shape(self.config().screen_format, usize::from(r.width), usize::from(r.height))
    }

    /// The screen in the `.cfg`'s format, into `out` (of its size).
    pub fn screen_into(&mut self, out: &mut [u8]) -> PyResult<()> {
        self.draw()?;
        let format = self.config().screen_format;
        convert_into(self.observer.screen(), format, out).map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// [`Env::screen_into`], drawn by `observer` rather than the game's
    /// own: the vector environment's threads each keep one and draw every
    /// game they play with it, so a frame's scratch memory is one per
    /// thread, not one per game (four games' at 640x480 did not stay in
    /// the caches: each game's step took 1.4 times as long as one game's
    /// alone). A game whose own observer has drawn this state already, or
    /// whose automap remembers what it has seen, draws with its own.
    pub fn screen_into_using(&mut self, observer: &mut Observer, out: &mut [u8]) -> PyResult<()> {
        if self.drawn || self.config().outputs.automap_buffer {
            return self.screen_into(out);
        }
        observer.render(&self.episode()?.game);
        let format = self.config().screen_format;
        convert_into(observer.screen(), format, out).map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// The depth buffer: each pixel's depth along the view in map units
    /// (f32, infinite for the sky), rows first.
    pub fn depth(&mut self) -> PyResult<(Vec<usize>, Vec<f32>)> {
        if !self.config().outputs.depth_buffer {
            return Err(PyRuntimeError::new_err("the depth buffer is off: set_depth_buffer_enabled(True) first"));
        }
        self.draw()?;
        let fb = self.observer.screen();
        Ok((vec![fb.height, fb.width], self.observer.frame().depth().to_vec()))
    }

    /// The labels buffer and its objects: each visible body gets a value
    /// 1 to 255 by its id's order (0: no body; past 254 bodies the rest
    /// share 255), and each object its box in the frame.
    pub fn labels(&mut self) -> PyResult<(Vec<usize>, Vec<u8>, Vec<Label>)> {
        if !self.config().outputs.labels_buffer {
            return Err(PyRuntimeError::new_err("the labels buffer is off: set_labels_buffer_enabled(True) first"));
        }
        self.draw()?;
        let Some(episode) = self.episode.as_ref() else { unreachable!("drawn above") };
        let sim = &episode.game.sim;
        let (w, h) = (self.observer.screen().width, self.observer.screen().height);
        let keys = self.observer.frame().labels();
        let mut seen: Vec<u32> = keys.iter().copied().filter(|&k| k != 0).collect();
        seen.sort_unstable();
        seen.dedup();
        let value_of = |k: u32| seen.binary_search(&k).map_or(0, |i| (i + 1).min(255) as u8);
        let mut boxes: Vec<(usize, usize, usize, usize)> = vec![(usize::MAX, usize::MAX, 0, 0); seen.len()];
        let mut buffer = vec![0u8; keys.len()];
        for (i, &k) in keys.iter().enumerate() {
            if k == 0 {
                continue;
            }
            buffer[i] = value_of(k);
            let Ok(j) = seen.binary_search(&k) else { continue };
            let (x, y) = (i % w, i / w);
            let b = &mut boxes[j];
            *b = (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y));
        }
        let labels = seen
            .iter()
            .zip(&boxes)
            .filter_map(|(&k, &(x0, y0, x1, y1))| {
                let id = sightline::sim::MobjId(k - 1);
                let m = sim.mobjs.get(id.0 as usize)?;
                Some(Label {
                    object_id: id.0,
                    object_name: sim.info.things.get(m.kind).map_or_else(String::new, |t| t.name.clone()),
                    value: value_of(k),
                    x: x0,
                    y: y0,
                    width: x1 + 1 - x0,
                    height: y1 + 1 - y0,
                    position: [m.x.to_f64(), m.y.to_f64(), m.z.to_f64()],
                    angle: m.angle.to_degrees(),
                    velocity: [m.momx.to_f64(), m.momy.to_f64(), m.momz.to_f64()],
                })
            })
            .collect();
        Ok((vec![h, w], buffer, labels))
    }

    /// The automap in the screen's format.
    pub fn automap(&mut self) -> PyResult<(Vec<usize>, Vec<u8>)> {
        if !self.config().outputs.automap_buffer {
            return Err(PyRuntimeError::new_err("the automap buffer is off: set_automap_buffer_enabled(True) first"));
        }
        self.draw()?;
        let Some(fb) = self.observer.automap() else { unreachable!("drawn with the automap on") };
        self.formatted(fb)
    }

    /// The audio buffer: (frames, 2) int16, the sound effects of the
    /// last `audio_buffer_size` tics at the `.cfg`'s rate, oldest first.
    pub fn audio(&self) -> PyResult<(Vec<usize>, Vec<i16>)> {
        let buffer = self.episode()?.buffers().and_then(|b| b.audio());
        let Some(audio) = buffer else {
            return Err(PyRuntimeError::new_err("the audio buffer is off: set_audio_buffer_enabled(True) first"));
        };
        Ok((vec![audio.frames(), 2], audio.samples()))
    }

    /// The notifications buffer: the messages of the last
    /// `notifications_buffer_size` tics, each followed by a newline.
    pub fn notifications(&self) -> PyResult<String> {
        let buffer = self.episode()?.buffers().and_then(|b| b.notifications());
        let Some(notifications) = buffer else {
            return Err(PyRuntimeError::new_err(
                "the notifications buffer is off: set_notifications_buffer_enabled(True) first",
            ));
        };
        Ok(notifications.text())
    }

    /// Every body in the level (ViZDoom's `objects`).
    pub fn objects(&self) -> PyResult<Vec<world::Object>> {
        if !self.config().outputs.objects_info {
            return Err(PyRuntimeError::new_err("objects info is off: set_objects_info_enabled(True) first"));
        }
        Ok(world::objects(&self.episode()?.game))
    }

    /// Every sector with its heights and lines (ViZDoom's `sectors`).
    pub fn sectors(&self) -> PyResult<Vec<world::Sector>> {
        if !self.config().outputs.sectors_info {
            return Err(PyRuntimeError::new_err("sectors info is off: set_sectors_info_enabled(True) first"));
        }
        Ok(world::sectors(&self.episode()?.game))
    }

    fn formatted(&self, fb: &sightline::Framebuffer) -> PyResult<(Vec<usize>, Vec<u8>)> {
        let format = self.config().screen_format;
        let mut bytes = Vec::new();
        convert(fb, format, &mut bytes).map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok((shape(format, fb.width, fb.height), bytes))
    }
}
