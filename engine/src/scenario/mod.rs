//! ZDoom-format scenarios, as ViZDoom describes them. `cfg` reads a
//! scenario's `.cfg` text into a `config::ScenarioConfig`
//! (the scenario's WAD paths, map, buttons, game variables, rewards and
//! rendering switches, typed in `names`) for whoever runs it; `run` plays
//! episodes of it, and `expert` answers what the autopilot would press in
//! one (for imitation learning); `buffers` keeps the audio and
//! notifications of an episode's last tics, `world` lists its bodies and
//! sectors.

pub mod buffers;
mod cfg;
mod config;
pub mod expert;
pub mod host;
pub mod made;
pub mod multi;
mod names;
pub mod observe;
pub mod run;
pub mod scripts;
pub mod variables;
pub mod world;

pub use cfg::{key_names, CfgError, Problem, KEY_COUNT};
pub use config::{AutomapOptions, Outputs, RenderFlags, Rewards, ScenarioConfig};
pub use expert::Expert;
pub use multi::MultiEpisode;
pub use names::{AutomapMode, Button, GameVariable, Mode, SamplingRate, ScreenFormat, ScreenResolution, RESOLUTIONS};
pub use run::{map_of, reward_so_far, End, Episode, RandomPolicy, Scenario, ScenarioError};
pub use scripts::Scripts;

/// The actor table a ZDoom WAD plays with: `base` with the WAD's DECORATE
/// lumps applied (`decorate::apply`, on ZDoom's base classes); a WAD
/// without DECORATE plays with `base` itself. What the lumps say that the
/// table cannot hold is in the second value, one line each.
pub fn actor_table(
    wad: &crate::wad::Wad,
    base: &std::sync::Arc<crate::actors::ActorTable>,
) -> Result<(std::sync::Arc<crate::actors::ActorTable>, Vec<String>), String> {
    let mut lumps = Vec::new();
    for i in (0..wad.lumps.len()).filter(|&i| wad.lumps[i].name == "DECORATE") {
        let label = format!("{}:DECORATE", wad.path);
        let parsed = crate::decorate::parse_lump(wad.bytes(i)).map_err(|e| format!("{label}: {e}"))?;
        lumps.push((label, parsed));
    }
    if lumps.is_empty() {
        return Ok((base.clone(), Vec::new()));
    }
    let built = crate::decorate::apply(&lumps, base).map_err(|e| e.to_string())?;
    Ok((std::sync::Arc::new(built.table), built.unread))
}

/// For the tests that read ViZDoom's shipped scenarios (the `.cfg` reader's,
/// ACS's, DECORATE's): their folder, `SIGHTLINE_VIZDOOM_DIR` or where
/// `scripts/vizdoom-scenarios.sh` puts them by default (as
/// `tests/vizdoom.rs` looks), canonical so resolved paths compare equal; or
/// `None` with a note when they are absent. `SIGHTLINE_REQUIRE_VIZDOOM`
/// (`.ci/run`) turns their absence into a failure.
#[cfg(test)]
pub(crate) fn shipped_dir() -> Option<std::path::PathBuf> {
    use std::path::PathBuf;
    let dir = std::env::var_os("SIGHTLINE_VIZDOOM_DIR")
        .map_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/vizdoom/scenarios"), PathBuf::from);
    if dir.join("basic.cfg").is_file() && dir.join("basic.wad").is_file() {
        return Some(dir.canonicalize().unwrap_or(dir));
    }
    let missing = format!("{} holds no basic.cfg and basic.wad", dir.display());
    let fetch = "scripts/vizdoom-scenarios.sh fetches them, or set SIGHTLINE_VIZDOOM_DIR";
    if std::env::var_os("SIGHTLINE_REQUIRE_VIZDOOM").is_some_and(|v| !v.is_empty() && v != "0") {
        panic!("SIGHTLINE_REQUIRE_VIZDOOM is set but ViZDoom's scenario files are not here ({missing}); {fetch}");
    }
    eprintln!("skipped: ViZDoom's scenario files are not here ({missing}); {fetch}");
    None
}
