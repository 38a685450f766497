//! ViZDoom's scenarios as a fixture: the WADs and `.cfg` files the `vizdoom`
//! package (1.3.2) ships in its `scenarios` folder, which
//! `scripts/vizdoom-scenarios.sh` unpacks from the wheel on PyPI.
//!
//! A test that needs them asks [`scenarios_or_skip`] first: without them the
//! test says so on stderr (uncaptured) and passes, unless
//! `SIGHTLINE_REQUIRE_VIZDOOM=1` (`.ci/run`) turns their absence into a
//! failure, so CI never skips them.

use std::path::PathBuf;

/// Names the folder holding the scenarios (basic.wad, basic.cfg, ...).
pub const DIR_VAR: &str = "SIGHTLINE_VIZDOOM_DIR";
/// `1` makes missing scenarios fail the tests that need them.
pub const REQUIRE_VAR: &str = "SIGHTLINE_REQUIRE_VIZDOOM";
pub const HOW_TO_GET: &str =
    "scripts/vizdoom-scenarios.sh unpacks them into target/vizdoom/scenarios, or set SIGHTLINE_VIZDOOM_DIR";
/// The scenario WADs the package ships.
pub const WADS: [&str; 18] = [
    "basic",
    "basic_audio",
    "basic_notifications",
    "simpler_basic",
    "rocket_basic",
    "defend_the_center",
    "defend_the_line",
    "health_gathering",
    "health_gathering_supreme",
    "my_way_home",
    "deadly_corridor",
    "predict_position",
    "take_cover",
    "deathmatch",
    "multi_deathmatch",
    "multi_duel",
    "cig",
    "cig_with_unknown",
];

/// The folder the scenarios are looked for in: `SIGHTLINE_VIZDOOM_DIR`, or
/// the script's default under the workspace's `target`.
pub fn dir() -> PathBuf {
    std::env::var_os(DIR_VAR)
        .map_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/vizdoom/scenarios"), PathBuf::from)
}

/// The folder, when every scenario WAD is in it; otherwise `None` after
/// saying why on stderr, or a panic when CI requires them.
pub fn scenarios_or_skip(test: &str) -> Option<PathBuf> {
    let dir = dir();
    let missing: Vec<&str> = WADS.iter().copied().filter(|w| !dir.join(format!("{w}.wad")).is_file()).collect();
    if missing.is_empty() {
        return Some(dir);
    }
    let why = format!("{}: missing {}.wad ({HOW_TO_GET})", dir.display(), missing.join(".wad, "));
    let required = std::env::var_os(REQUIRE_VAR).is_some_and(|v| !v.is_empty() && v != "0");
    assert!(!required, "{REQUIRE_VAR} is set and ViZDoom's scenarios are missing: {why}");
    eprintln!("skipped {test}: {why}");
    None
}
