//! Decides whether the Freedoom suites (`freedoom.rs`) can run. With both
//! IWADs found it does nothing. Without them it sets `cfg(freedoom_missing)`,
//! under which those tests are `#[ignore]`d with a reason naming
//! `apt-get install freedoom`, so `cargo test` on a fresh machine passes and
//! lists them as ignored; with `SIGHTLINE_REQUIRE_FREEDOOM=1` (`.ci/run`) it
//! fails the build instead, naming the missing files.

#[path = "freedoom_wads.rs"]
mod freedoom_wads;

fn main() {
    freedoom_wads::build_script("freedoom_wads.rs", "the Freedoom tests");
}
