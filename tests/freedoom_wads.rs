//! Where Freedoom's IWADs are, for both sides of that fixture: `build.rs`,
//! which marks the Freedoom tests ignored when the WADs are missing (or fails
//! the build when CI requires them), and `freedoom.rs`, which opens them.
//! One file, compiled into both, so they cannot disagree on the path. Only
//! `std` here: the build script cannot use the rest of the crate.

use std::path::{Path, PathBuf};

/// Where Debian's `freedoom` package installs the IWADs.
pub const DEFAULT_DIR: &str = "/usr/share/games/doom";
/// Names another directory holding the IWADs; it replaces `DEFAULT_DIR`.
pub const DIR_VAR: &str = "SIGHTLINE_DOOM_DIR";
/// `1` (`.ci/run` sets it) turns missing WADs into a build error, so CI
/// never skips the Freedoom tests.
pub const REQUIRE_VAR: &str = "SIGHTLINE_REQUIRE_FREEDOOM";
/// The IWADs the tests read.
pub const WADS: [&str; 2] = ["freedoom1.wad", "freedoom2.wad"];
/// How to get them. The tests' `ignore` reasons say the same in a literal,
/// since an attribute cannot name a constant.
pub const HOW_TO_GET: &str = "apt-get install freedoom, or set SIGHTLINE_DOOM_DIR to a directory \
                              holding freedoom1.wad and freedoom2.wad";

/// The directory the IWADs are looked for in.
pub fn dir() -> PathBuf {
    std::env::var_os(DIR_VAR).map_or_else(|| PathBuf::from(DEFAULT_DIR), PathBuf::from)
}

/// Where the IWAD `name` should be (it may not exist).
pub fn path(name: &str) -> PathBuf {
    dir().join(name)
}

/// The IWADs that are not there.
pub fn missing() -> Vec<PathBuf> {
    WADS.iter().map(|w| path(w)).filter(|p| !p.is_file()).collect()
}

/// True when `REQUIRE_VAR` asks for the WADs: set to anything but empty or `0`.
pub fn required() -> bool {
    std::env::var_os(REQUIRE_VAR).is_some_and(|v| !v.is_empty() && v != "0")
}

/// What the build script watches so that installing or removing a WAD
/// decides again: each WAD that exists, and for one that does not, the
/// nearest directory above it that exists (adding a file or directory
/// changes that directory's mtime, which cargo checks). A missing path
/// cannot itself be watched: cargo counts it as changed on every build, so
/// the tests crate would be recompiled on every `cargo test` (tried). The
/// price: where `/usr/share/games` does not exist either, cargo rescans
/// `/usr/share` on each build (52,000 files here: a no-op `cargo test
/// --no-run` took 0.4 s instead of 0.16 s), and any package installed there
/// makes the tests crate recompile once.
pub fn watched() -> Vec<PathBuf> {
    let mut watched: Vec<PathBuf> = Vec::new();
    for wad in WADS.iter().map(|w| path(w)) {
        let target = if wad.exists() { wad } else { nearest_existing_ancestor(&wad) };
        if !watched.contains(&target) {
            watched.push(target);
        }
    }
    watched
}

fn nearest_existing_ancestor(path: &Path) -> PathBuf {
    // A relative SIGHTLINE_DOOM_DIR runs out of ancestors at "": cargo reads
    // relative paths from the package directory, which always exists.
    let found = path.ancestors().skip(1).find(|a| a.as_os_str().is_empty() || a.exists());
    match found {
        Some(a) if !a.as_os_str().is_empty() => a.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// A build script's whole work (`tests/build.rs`, `engine/build.rs`): with
/// both IWADs found, nothing; without them `cfg(freedoom_missing)`, under
/// which the Freedoom tests are ignored with the reason, or, when
/// [`REQUIRE_VAR`] asks for them, a failed build naming the missing files.
/// `this_file` is this module's path from the calling package, and
/// `which` names its tests in the warning.
pub fn build_script(this_file: &str, which: &str) {
    println!("cargo::rustc-check-cfg=cfg(freedoom_missing)");
    // Any rerun-if-changed replaces cargo's default of watching the whole
    // package, so the script and this module are named too.
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-changed={this_file}");
    println!("cargo::rerun-if-env-changed={DIR_VAR}");
    println!("cargo::rerun-if-env-changed={REQUIRE_VAR}");
    for path in watched() {
        println!("cargo::rerun-if-changed={}", path.display());
    }
    let missing = missing();
    if missing.is_empty() {
        return;
    }
    let list: Vec<String> = missing.iter().map(|p| p.display().to_string()).collect();
    let list = list.join(", ");
    if required() {
        eprintln!(
            "error: {REQUIRE_VAR} is set, so the Freedoom tests must run, and their WADs are missing: {list}\n\
             To get them: {HOW_TO_GET}."
        );
        std::process::exit(1);
    }
    println!("cargo::rustc-cfg=freedoom_missing");
    println!("cargo::warning=missing {list}: {which} are ignored ({HOW_TO_GET})");
}
