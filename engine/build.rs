//! Decides whether the engine's unit tests that read Freedoom's IWADs (the
//! simulation's, which take Doom's tables and maps from freedoom2.wad) can
//! run, as `tests/build.rs` does for the tests crate: without the WADs it
//! sets `cfg(freedoom_missing)`, under which those tests are `#[ignore]`d
//! with the reason; with `SIGHTLINE_REQUIRE_FREEDOOM=1` (`.ci/run`) it fails
//! the build instead. The WADs' whereabouts are `tests/freedoom_wads.rs`.

#[path = "../tests/freedoom_wads.rs"]
mod freedoom_wads;

fn main() {
    freedoom_wads::build_script("../tests/freedoom_wads.rs", "the engine's Freedoom tests");
}
