//! Chocolate Doom as the referee of a vanilla demo: it plays a `.lmp`
//! headless to its end and writes, with `-statdump`, the intermission
//! tallies of every level the demo completed, which come back parsed
//! ([`sightline::play::statdump`]). The same run as
//! `scripts/chocolate-statdump.sh`; the flags are explained there.
//!
//! A test that needs Chocolate asks [`present_or_skip`] first: without it
//! the test says so on stderr (uncaptured) and passes, unless
//! `SIGHTLINE_REQUIRE_CHOCOLATE=1` (`.ci/run`) turns its absence into a
//! failure, so CI never skips them.

use std::fmt;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use sightline::play::statdump::{self, LevelStats, StatdumpError};

/// `1` makes a missing Chocolate Doom fail the tests that need it.
pub const REQUIRE_VAR: &str = "SIGHTLINE_REQUIRE_CHOCOLATE";
/// Names the binary, instead of looking for it.
pub const BINARY_VAR: &str = "CHOCOLATE_DOOM";
/// Where Debian's `chocolate-doom` package puts it, often not on `PATH`.
pub const DEBIAN_BINARY: &str = "/usr/games/chocolate-doom";
pub const HOW_TO_GET: &str =
    "apt-get install chocolate-doom (it installs /usr/games/chocolate-doom), or set CHOCOLATE_DOOM to the binary";

/// How to play a demo.
#[derive(Clone, Debug)]
pub struct Options {
    /// PWADs the demo plays on, over the IWAD (Chocolate's `-file`).
    pub files: Vec<PathBuf>,
    /// The binary; `None` looks for it ([`find`]).
    pub binary: Option<PathBuf>,
    /// How long the run may take before it is killed. A `-timedemo` run
    /// with `-nodraw` plays about 40,000 tics a second here (6,467 in
    /// 0.16 s, start-up included), so this only stops a hung binary.
    pub timeout: Duration,
}

impl Default for Options {
    fn default() -> Options {
        Options { files: Vec::new(), binary: None, timeout: Duration::from_secs(300) }
    }
}

/// A demo Chocolate played to its end.
#[derive(Clone, Debug)]
pub struct Played {
    /// The levels it completed, in order (an empty statdump: none).
    pub levels: Vec<LevelStats>,
    /// Chocolate's `timed N gametics`: the tics it ran, intermissions
    /// included.
    pub gametics: u64,
}

#[derive(Debug)]
pub enum ChocolateError {
    /// No binary where it was looked for.
    Absent {
        looked: Vec<PathBuf>,
    },
    /// A path that cannot be read, or a run that could not start.
    Io {
        what: String,
        error: std::io::Error,
    },
    TimedOut {
        demo: PathBuf,
        after: Duration,
    },
    /// It stopped before the demo's end (a missing map, a bad demo): no
    /// `timed N gametics` report. `stderr` holds Chocolate's error.
    Unfinished {
        demo: PathBuf,
        status: String,
        stderr: String,
    },
    Statdump(StatdumpError),
    /// The statdump's levels and the count Chocolate printed (`None`: no
    /// count printed) differ.
    Count {
        demo: PathBuf,
        printed: Option<usize>,
        parsed: usize,
    },
}

impl fmt::Display for ChocolateError {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match self {
            ChocolateError::Absent { looked } => {
                let looked: Vec<String> = looked.iter().map(|p| p.display().to_string()).collect();
                write!(f, "chocolate-doom not found (looked for {}): {HOW_TO_GET}", looked.join(", "))
            }
            ChocolateError::Io { what, error } => write!(f, "{what}: {error}"),
            ChocolateError::TimedOut { demo, after } => {
                write!(f, "{}: chocolate-doom still ran after {after:?} and was killed", demo.display())
            }
            ChocolateError::Unfinished { demo, status, stderr } => write!(
                f,
                "{}: chocolate-doom stopped before the demo's end ({status}, no \"timed N gametics\"); its stderr:\n{stderr}",
                demo.display()
            ),
            ChocolateError::Statdump(e) => write!(f, "{e}"),
            ChocolateError::Count { demo, printed: Some(printed), parsed } => write!(
                f,
                "{}: chocolate-doom captured {printed} level(s), its statdump holds {parsed}",
                demo.display()
            ),
            ChocolateError::Count { demo, printed: None, parsed } => write!(
                f,
                "{}: chocolate-doom printed no \"Statistics captured for N level(s)\"; its statdump holds {parsed}",
                demo.display()
            ),
        }
    }
}

impl std::error::Error for ChocolateError {}

/// The binary: [`BINARY_VAR`] if set, else `chocolate-doom` on `PATH`, else
/// [`DEBIAN_BINARY`].
pub fn find() -> Result<PathBuf, ChocolateError> {
    if let Some(named) = std::env::var_os(BINARY_VAR) {
        let named = PathBuf::from(named);
        return if named.is_file() { Ok(named) } else { Err(ChocolateError::Absent { looked: vec![named] }) };
    }
    let mut looked: Vec<PathBuf> = std::env::var_os("PATH")
        .map(|path| std::env::split_paths(&path).map(|dir| dir.join("chocolate-doom")).collect())
        .unwrap_or_default();
    looked.push(PathBuf::from(DEBIAN_BINARY));
    match looked.iter().find(|p| p.is_file()) {
        Some(found) => Ok(found.clone()),
        None => Err(ChocolateError::Absent { looked }),
    }
}

/// True when [`REQUIRE_VAR`] asks for Chocolate: set to anything but empty or `0`.
pub fn required() -> bool {
    std::env::var_os(REQUIRE_VAR).is_some_and(|v| !v.is_empty() && v != "0")
}

/// Whether the test `test` can run: true with Chocolate found. Without it,
/// a failure when [`required`], else false after a line on stderr that
/// `cargo test` shows (it is written past the test harness's capture).
pub fn present_or_skip(test: &str) -> bool {
    match find() {
        Ok(_) => true,
        Err(e) if required() => panic!("{REQUIRE_VAR} is set and {e}"),
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "skipped {test}: {e}");
            false
        }
    }
}

/// Plays `lmp` on `iwad` to its end; see [`play_with`].
pub fn play(iwad: &Path, lmp: &Path) -> Result<Played, ChocolateError> {
    play_with(iwad, lmp, &Options::default())
}

/// Plays `lmp` on `iwad` (and `options.files`) headless to its end and
/// returns the tallies of the levels it completed.
pub fn play_with(iwad: &Path, lmp: &Path, options: &Options) -> Result<Played, ChocolateError> {
    let binary = match &options.binary {
        Some(b) if b.is_file() => b.clone(),
        Some(b) => return Err(ChocolateError::Absent { looked: vec![b.clone()] }),
        None => find()?,
    };
    // Chocolate runs in a scratch directory: absolute paths.
    let absolute =
        |p: &Path| p.canonicalize().map_err(|error| ChocolateError::Io { what: p.display().to_string(), error });
    let (iwad, demo) = (absolute(iwad)?, absolute(lmp)?);
    let files = options.files.iter().map(|f| absolute(f)).collect::<Result<Vec<_>, _>>()?;
    let scratch = Scratch::new()?;
    let io = |what: &str| {
        let what = format!("{what} ({})", scratch.0.display());
        move |error| ChocolateError::Io { what, error }
    };
    let home = scratch.0.join("home");
    std::fs::create_dir(&home).map_err(io("the scratch HOME"))?;
    let (out, err) = (scratch.0.join("stdout.txt"), scratch.0.join("stderr.txt"));
    let dump = scratch.0.join("statdump.txt");
    // Chocolate adds the demo file as a lump named after it, the last one
    // loaded, so a demo called MAP01.lmp or E1M1.lmp would be found as the
    // map's lump (and the map's lumps read past the end of the directory).
    // A copy under a name no IWAD lump has avoids that.
    let copy = scratch.0.join("sldemo.lmp");
    std::fs::copy(&demo, &copy).map_err(io("a copy of the demo"))?;

    let mut command = Command::new(&binary);
    command.arg("-iwad").arg(&iwad);
    if !files.is_empty() {
        command.arg("-file").args(&files);
    }
    command
        .arg("-timedemo")
        .arg(&copy)
        .args(["-nodraw", "-window", "-nogui", "-nosound", "-nomusic", "-statdump"])
        .arg(&dump)
        .current_dir(&scratch.0)
        .env("HOME", &home)
        .env_remove("XDG_CONFIG_HOME")
        .env_remove("XDG_DATA_HOME")
        .env("SDL_VIDEODRIVER", "dummy")
        .env("SDL_AUDIODRIVER", "dummy")
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(&out).map_err(io("stdout's file"))?)
        .stderr(std::fs::File::create(&err).map_err(io("stderr's file"))?);
    let mut child =
        command.spawn().map_err(|error| ChocolateError::Io { what: binary.display().to_string(), error })?;
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().map_err(io("waiting for chocolate-doom"))? {
            break status;
        }
        if start.elapsed() > options.timeout {
            let _ = child.kill();
            let _ = child.wait();
            return Err(ChocolateError::TimedOut { demo, after: options.timeout });
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let stdout = std::fs::read_to_string(&out).map_err(io("chocolate-doom's stdout"))?;
    let stderr = std::fs::read_to_string(&err).map_err(io("chocolate-doom's stderr"))?;

    // -timedemo ends the program at the demo's end through I_Error (exit
    // status 255), which prints this line; an earlier I_Error does not.
    let gametics = stderr.lines().find_map(|l| l.strip_prefix("timed ")?.split_once(" gametics")?.0.parse().ok());
    let Some(gametics) = gametics else {
        return Err(ChocolateError::Unfinished { demo, status: status.to_string(), stderr });
    };
    let levels = statdump::read(&dump).map_err(ChocolateError::Statdump)?;
    let printed = stdout
        .lines()
        .find_map(|l| l.strip_prefix("Statistics captured for ")?.strip_suffix(" level(s)")?.parse::<usize>().ok());
    if printed != Some(levels.len()) {
        return Err(ChocolateError::Count { demo, printed, parsed: levels.len() });
    }
    Ok(Played { levels, gametics })
}

/// A directory of its own under the system's temporary directory, removed
/// when dropped (so Chocolate's config and logs never reach the user's).
struct Scratch(PathBuf);

impl Scratch {
    fn new() -> Result<Scratch, ChocolateError> {
        static RUNS: AtomicUsize = AtomicUsize::new(0);
        let run = RUNS.fetch_add(1, Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("sightline-chocolate-{}-{run}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).map_err(|error| ChocolateError::Io { what: dir.display().to_string(), error })?;
        Ok(Scratch(dir))
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
