//! Scenarios made in Python (`sightline.make_scenario`, `sightline.check`):
//! [`MadeScenario`] holds a RON map opened once and its reward
//! specification (`sightline::scenario::made`), and makes the same
//! [`Game`] and [`Games`] a `.cfg` scenario gives, so `DoomGame`, the
//! Gymnasium environments and the vector environment play it unchanged.
//! A bad map or specification is a `ValueError` naming the element.

use std::path::PathBuf;
use std::sync::Arc;

use pyo3::exceptions::{PyFileNotFoundError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use sightline::scenario::made::{self, Made, MadeError, MapInput, RewardSpec};

use crate::env::{Env, Opened};
use crate::{Config, Game, Games};

fn py_error(e: MadeError) -> PyErr {
    match e {
        MadeError::Open(_) => PyRuntimeError::new_err(e.to_string()),
        _ => PyValueError::new_err(e.to_string()),
    }
}

/// The map given as exactly one of `text` (RON, named `label` in errors,
/// its art in `art`: a folder or a WAD) and `path`; a path that is no
/// file is a `FileNotFoundError`.
fn map_input(
    text: Option<String>,
    path: Option<String>,
    label: Option<String>,
    art: Option<String>,
) -> PyResult<MapInput> {
    match (text, path) {
        (Some(text), None) => {
            let label = label.unwrap_or_else(|| "<map>".to_string());
            // `art`: a folder of PNGs, or a WAD (by its extension).
            let art = art.map(PathBuf::from);
            let is_wad = art.as_ref().and_then(|a| a.extension()).is_some_and(|e| e.eq_ignore_ascii_case("wad"));
            let (dir, wad) = if is_wad { (None, art) } else { (art, None) };
            Ok(MapInput::Text { text, label, dir, wad })
        }
        (None, Some(path)) => {
            if !std::path::Path::new(&path).is_file() {
                return Err(PyFileNotFoundError::new_err(format!("{path}: no such map file")));
            }
            Ok(MapInput::File(PathBuf::from(path)))
        }
        _ => Err(PyValueError::new_err("give a map as exactly one of text and path")),
    }
}

/// Findings as `(severity, message)` pairs.
fn findings(list: Vec<made::Finding>) -> Vec<(String, String)> {
    list.into_iter().map(|f| (f.severity.name().to_string(), f.message)).collect()
}

/// A scenario made from a RON map and a reward specification.
#[pyclass(module = "sightline._native", frozen)]
pub struct MadeScenario {
    made: Arc<Made>,
}

#[pymethods]
impl MadeScenario {
    /// Opens the map (RON `text`, or the file at `path`) and checks the
    /// reward specification `rewards` (RON or JSON text) against it.
    #[new]
    #[pyo3(signature = (rewards, text=None, path=None, label=None, art=None))]
    fn new(
        py: Python<'_>,
        rewards: &str,
        text: Option<String>,
        path: Option<String>,
        label: Option<String>,
        art: Option<String>,
    ) -> PyResult<MadeScenario> {
        let map = map_input(text, path, label, art)?;
        let spec = RewardSpec::parse(rewards).map_err(py_error)?;
        let made = py.detach(|| Made::open(&map, spec)).map_err(py_error)?;
        Ok(MadeScenario { made: Arc::new(made) })
    }

    /// One game of the scenario with `config`'s settings (buttons, game
    /// variables, screen), the specification's rewards over its own.
    #[pyo3(signature = (config, threads=1))]
    fn game(&self, py: Python<'_>, config: &Config, threads: usize) -> PyResult<Game> {
        let settings = config.inner.clone();
        let scenario = py.detach(|| self.made.scenario(&settings)).map_err(py_error)?;
        Ok(Game { env: Env::new(Arc::new(Opened::of(scenario)), threads) })
    }

    /// `count` games of the scenario stepped together on `threads`
    /// threads (0: one per core), as `Games` gives for a `.cfg`.
    #[pyo3(signature = (config, count, threads=0))]
    fn games(&self, py: Python<'_>, config: &Config, count: usize, threads: usize) -> PyResult<Games> {
        if count == 0 {
            return Err(PyValueError::new_err("a vector of games needs at least one game"));
        }
        let settings = config.inner.clone();
        let scenario = py.detach(|| self.made.scenario(&settings)).map_err(py_error)?;
        let opened = Arc::new(Opened::of(scenario));
        Games::of((0..count).map(|_| Env::new(opened.clone(), 1)).collect(), threads)
    }

    /// Writes the specification's rewards and timeout into `config`
    /// (`living_reward`, `death_penalty`, `kill_reward`, `secret_reward`,
    /// `damage_taken_penalty`, `map_exit_reward`, `episode_timeout`), as
    /// a game of the scenario will play them.
    fn configure(&self, mut config: PyRefMut<'_, Config>) {
        made::configure(&self.made.spec, &mut config.inner);
    }

    /// What `sightline check` says of the map at `skill`, and what in the
    /// rewards can never pay: `(severity, message)` pairs, severity
    /// "error", "warning" or "note".
    #[pyo3(signature = (skill=3))]
    fn check(&self, py: Python<'_>, skill: u8) -> Vec<(String, String)> {
        findings(py.detach(|| self.made.check(skill)))
    }

    /// The reward specification as RON.
    fn rewards(&self) -> String {
        self.made.spec.to_ron()
    }

    /// The map's sector count.
    fn sectors(&self) -> usize {
        self.made.opened.level.compiled.map.sectors.len()
    }
}

/// What `sightline check` says of a map (RON `text` or the file at
/// `path`) at `skill`, with a reward specification's own findings when
/// `rewards` is given: `(severity, message)` pairs; a map that does not
/// load gives its errors, each validation problem on its own.
#[pyfunction]
#[pyo3(signature = (text=None, path=None, label=None, art=None, rewards=None, skill=3))]
fn check_map(
    py: Python<'_>,
    text: Option<String>,
    path: Option<String>,
    label: Option<String>,
    art: Option<String>,
    rewards: Option<&str>,
    skill: u8,
) -> PyResult<Vec<(String, String)>> {
    let map = map_input(text, path, label, art)?;
    let spec = rewards.map(RewardSpec::parse).transpose().map_err(py_error)?;
    Ok(findings(py.detach(|| made::check(&map, spec.as_ref(), skill))))
}

/// Adds the made scenarios' class and function to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<MadeScenario>()?;
    m.add_function(wrap_pyfunction!(check_map, m)?)?;
    Ok(())
}
