//! Decides whether the Freedoom suites (`freedoom.rs`) can run. With both
//! IWADs found it does nothing. Without them it sets `cfg(freedoom_missing)`,
//! under which those tests are `#[ignore]`d with a reason naming
//! `apt-get install freedoom`, so `cargo test` on a fresh machine passes and
//! lists them as ignored; with `SIGHTLINE_REQUIRE_FREEDOOM=1` (`.ci/run`) it
//! fails the build instead, naming the missing files.

#[path = "freedoom_wads.rs"]
mod freedoom_wads;

fn main() {
    println!("cargo::rustc-check-cfg=cfg(freedoom_missing)");
    // Any rerun-if-changed replaces cargo's default of watching the whole
    // package, so the script and its module are named too.
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-changed=freedoom_wads.rs");
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
            "error: {} is set, so the Freedoom tests must run, and their WADs are missing: {list}\n\
             To get them: {}.",
            freedoom_wads::REQUIRE_VAR,
            freedoom_wads::HOW_TO_GET
        );
        std::process::exit(1);
    }
    println!("cargo::rustc-cfg=freedoom_missing");
    println!("cargo::warning=missing {list}: the Freedoom tests are ignored ({})", freedoom_wads::HOW_TO_GET);
}
