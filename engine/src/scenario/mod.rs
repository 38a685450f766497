//! ZDoom-format scenarios, as ViZDoom describes them. For now the reader of
//! a scenario's `.cfg`: `cfg` reads the text into a `config::ScenarioConfig`
//! (the scenario's WAD paths, map, buttons, game variables, rewards and
//! rendering switches, typed in `names`) for whoever runs it. Nothing here
//! loads the WAD or starts a game yet.

mod cfg;
mod config;
mod names;

pub use cfg::{key_names, CfgError, Problem, KEY_COUNT};
pub use config::{AutomapOptions, Outputs, RenderFlags, Rewards, ScenarioConfig};
pub use names::{AutomapMode, Button, GameVariable, Mode, SamplingRate, ScreenFormat, ScreenResolution, RESOLUTIONS};
