//! Scenarios made without ACS: a RON map (a file, or text written by a
//! program such as `sightline.maps`) and a [`RewardSpec`], played through
//! the `.cfg` scenarios' own [`Episode`](super::Episode) machinery.
//!
//! ```text
//! MapInput ─ load ─▶ Opened (validated, compiled, art) ─┐
//! RewardSpec ─ parse, check (sectors, item kinds) ──────┼─▶ Made ─ scenario(settings) ─▶ Scenario ─ episode(seed) ─▶ Episode
//!                        configure: living, death, kill, ┘        (ScenarioConfig: buttons, variables, resolution)
//!                        secret, damage, exit, timeout ─▶ ScenarioConfig;   events::Rules ─▶ Episode's Tracker
//! ```
//!
//! The map plays under Sightline's rules, as `sightline play` plays it (a
//! one-player `SimGame` on the RON map, seeded per episode). The events
//! with a ViZDoom reward of the same meaning (a kill, a secret, a point of
//! damage taken, the exit, each tic, death, the timeout) are paid by
//! `Episode::step` from the scenario's config, which [`configure`] fills
//! from the specification; the rest (a goal sector entered, an item picked
//! up by kind, the exit ending the episode at once) by `events::Tracker`.
//! [`check`] is `sightline check` on the map, as findings.

mod check;
pub mod events;
mod spec;
#[cfg(test)]
mod tests;

use std::path::{Path, PathBuf};
use std::sync::Arc;

pub use check::{check, Finding, Severity};
pub use spec::{Pickup, Reach, RewardSpec};

use super::{Scenario, ScenarioConfig};
use crate::actors::ActorTable;
use crate::bsp::BuildOptions;
use crate::campaign::{self, CampaignError, Opened};
use crate::level::{level_from_bytes, Level, LevelError};
use crate::map::{Map, MapError};
use crate::materials::Materials;
use crate::texture::{Library, TextureError};
use crate::wad::library::WadArt;
use crate::wad::Wad;

/// Why a made scenario could not be made.
#[derive(Debug, thiserror::Error)]
pub enum MadeError {
    /// The map does not load (the message names the file or label and the
    /// element, as `sightline check` says it), or cannot be simulated.
    #[error("{0}")]
    Map(String),
    /// The reward specification is not well-formed RON or JSON.
    #[error("rewards: {0}")]
    Syntax(String),
    /// The reward specification names what is not there.
    #[error("rewards.{element}: {what}")]
    Rewards { element: String, what: String },
    /// The game could not be set up.
    #[error("{0}")]
    Open(String),
}

/// Where a made scenario's map comes from, and its art: PNGs in
/// `textures/`, `flats/` and `sprites/` of a folder, then the built-in
/// set. An actor neither has a picture of is drawn as its stand-in
/// figure; a map naming a wall or flat neither has (a Doom texture) takes
/// the IWAD's art, `freedoom2.wad` where Doom ports look, when it is there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MapInput {
    /// A RON (or compiled) map file; its art folder is its own.
    File(PathBuf),
    /// RON text, named `label` in errors, its art in `dir`; with `wad`,
    /// that WAD's pictures come after the folder and before the built-in
    /// set.
    Text { text: String, label: String, dir: Option<PathBuf>, wad: Option<PathBuf> },
}

impl MapInput {
    /// The name errors give the map.
    pub fn label(&self) -> String {
        match self {
            MapInput::File(path) => path.display().to_string(),
            MapInput::Text { label, .. } => label.clone(),
        }
    }

    /// The map validated, compiled and with its art, as play opens it.
    pub fn load(&self) -> Result<Opened, CampaignError> {
        let label = self.label();
        let read;
        let (bytes, dirs, wad) = match self {
            MapInput::File(path) => {
                let io = |error| LevelError::Map(MapError::Io { path: label.clone(), error });
                read = std::fs::read(path).map_err(io)?;
                (&read[..], vec![path.parent().map(Path::to_path_buf).unwrap_or_default()], None)
            }
            MapInput::Text { text, dir, wad, .. } => (text.as_bytes(), dir.iter().cloned().collect(), wad.as_deref()),
        };
        let compiled = level_from_bytes(bytes, &label, &BuildOptions::default())?;
        let materials = art(&compiled.map, dirs, wad, &label)?;
        Ok(Opened::of_level(Level::new(compiled, materials), &label))
    }
}

/// `map`'s art from `dirs` and the built-in set, or with `wad` between
/// them; with no `wad`, the IWAD's when something is missing.
fn art(map: &Map, dirs: Vec<PathBuf>, wad: Option<&Path>, label: &str) -> Result<Materials, CampaignError> {
    let with_wad = |wad: &Path, dirs: Vec<PathBuf>| -> Result<Materials, CampaignError> {
        let wad = Wad::open(&campaign::find_wad(wad, &campaign::wad_dirs()))?;
        let library = Library { dirs, wad: Some(Arc::new(WadArt::new(wad)?)) };
        Ok(Materials::resolve_in(map, &library, label).map_err(LevelError::from)?)
    };
    if let Some(wad) = wad {
        return with_wad(wad, dirs);
    }
    match Materials::resolve(map, &dirs, label) {
        Err(e) if matches!(e.error, TextureError::Missing { .. }) => match default_iwad() {
            Some(iwad) => with_wad(&iwad, dirs),
            None => Err(LevelError::from(e).into()),
        },
        other => Ok(other.map_err(LevelError::from)?),
    }
}

/// `freedoom2.wad` where Doom ports look for it, if it is there.
fn default_iwad() -> Option<PathBuf> {
    Some(campaign::find_wad(Path::new("freedoom2.wad"), &campaign::wad_dirs())).filter(|p| p.is_file())
}

/// A made scenario: its map opened once and its rewards checked against
/// it. [`Made::scenario`] makes the playable [`Scenario`] for given
/// settings (buttons, game variables, resolution, skill).
#[derive(Clone)]
pub struct Made {
    pub opened: Opened,
    pub spec: RewardSpec,
    rules: Arc<events::Rules>,
}

impl Made {
    /// Opens `map` and checks `spec` against it: an error names the map's
    /// element or the specification's (`rewards.reach[0].sector`).
    pub fn open(map: &MapInput, spec: RewardSpec) -> Result<Made, MadeError> {
        let opened = map.load().map_err(|e| MadeError::Map(e.to_string()))?;
        let table = ActorTable::active();
        // What the simulation refuses (a coordinate past Doom's 16 bits)
        // is the map's fault: say so now rather than when a game starts.
        crate::sim::from_map::level_from_map(&opened.level.compiled, table)
            .map_err(|e| MadeError::Map(e.to_string()))?;
        let sectors = opened.level.compiled.map.sectors.len();
        spec.check(sectors, table)?;
        let rules = Arc::new(events::Rules::new(&spec, sectors, table));
        Ok(Made { opened, spec, rules })
    }

    /// The scenario played with `settings` (a `.cfg`'s keys: buttons,
    /// variables, screen, skill, ...), the specification's rewards and
    /// timeout written over its own ([`configure`]).
    pub fn scenario(&self, settings: &ScenarioConfig) -> Result<Scenario, MadeError> {
        let mut config = settings.clone();
        configure(&self.spec, &mut config);
        Scenario::on_opened(&config, self.opened.clone(), Some(self.rules.clone()))
            .map_err(|e| MadeError::Open(e.to_string()))
    }

    /// [`check`] on this scenario's map and rewards.
    pub fn check(&self, skill: u8) -> Vec<Finding> {
        check::check_opened(&self.opened, Some(&self.spec), skill)
    }
}

/// Writes the events `spec` shares with ViZDoom's rewards into `config`,
/// where `Episode::step` pays them: `living_reward`, `death_penalty` (the
/// negation of `death`), `kill_reward`, `secret_reward`,
/// `damage_taken_penalty` (the negation of `damage_taken`),
/// `map_exit_reward` and `episode_timeout`. The specification wins over
/// what the settings said; ViZDoom's other rewards (`hit_reward`, ...)
/// are left as they were and add to it.
pub fn configure(spec: &RewardSpec, config: &mut ScenarioConfig) {
    let r = &mut config.rewards;
    r.living = spec.living;
    r.death_penalty = -spec.death;
    r.kill = spec.kill;
    r.secret = spec.secret;
    r.damage_taken_penalty = -spec.damage_taken;
    r.map_exit = spec.exit;
    config.episode_timeout = spec.timeout_tics();
}
