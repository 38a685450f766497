//! Decides whether the engine's unit tests that read Freedoom's IWADs (the
//! simulation's, which take Doom's tables and maps from freedoom2.wad) can
//! run, as `tests/build.rs` does for the tests crate: without the WADs it
//! sets `cfg(freedoom_missing)`, under which those tests are `#[ignore]`d
//! with the reason; with `SIGHTLINE_REQUIRE_FREEDOOM=1` (`.ci/run`) it fails
//! the build instead. The WADs' whereabouts are `tests/freedoom_wads.rs`.

#[path = "../tests/freedoom_wads.rs"]
mod freedoom_wads;

fn main() {
    println!("cargo::rustc-check-cfg=cfg(freedoom_missing)");
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-changed=../tests/freedoom_wads.rs");
    println!("cargo::rerun-if-env-changed={}", freedoom_wads::DIR_VAR);
    println!("cargo::rerun-if-env-changed={}", freedoom_wads::REQUIRE_VAR);
    for path in freedoom_wads::watched() {
        println!("cargo::rerun-if-changed={}", path.display());
    }
    let missing = freedoom_wads::missing();
    if missing.is_empty() {
        return;
    }
    let list: Vec<String> = missing.iter().map(|p| p.display().to_string()).collect();
    let list = list.join(", ");
    if freedoom_wads::required() {
        eprintln!(
            "error: {} is set, so the Freedoom tests must run, and their WADs are missing: {list}\nTo get them: {}.",
            freedoom_wads::REQUIRE_VAR,
            freedoom_wads::HOW_TO_GET
        );
        std::process::exit(1);
    }
    println!("cargo::rustc-cfg=freedoom_missing");
    println!("cargo::warning=missing {list}: the engine's Freedoom tests are ignored ({})", freedoom_wads::HOW_TO_GET);
}
