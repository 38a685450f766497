//! Command-line arguments and the parsers for their small formats (sizes, poses).

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};
use sightline::bsp::SplitterKind;
use sightline::render::raycast::RayMethod;
use sightline::render::{Buffers, Renderer, Shade};

#[derive(Parser)]
#[command(
    name = "sightline",
    version,
    about = "A Doom-style 2.5D engine: play maps, replay demos, compile maps, capture frames",
    args_conflicts_with_subcommands = true
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Without a subcommand, `sightline [MAP] [OPTIONS]` is `sightline play`.
    #[command(flatten)]
    pub play: PlayArgs,
    /// A RON actor file whose actors are added to the shipped table, or
    /// replace the shipped actors of the same name, for this run (any
    /// command that loads, plays or imports a map).
    #[arg(long, global = true, value_name = "FILE")]
    pub actors: Option<PathBuf>,
}

#[derive(Subcommand)]
pub enum Command {
    /// Compile a RON map into a BSP map file.
    Compile(CompileArgs),
    /// Render one frame headless to a PNG.
    Capture(CaptureArgs),
    /// Play a map in a window (the default with no arguments).
    Play(PlayArgs),
    /// Replay a demo headless and deterministically; optionally capture frames.
    Replay(ReplayArgs),
    /// Import maps from a Doom WAD as RON maps, with their art as PNGs.
    Import(ImportArgs),
    /// Let the autopilot play a map headless until the exit or a limit, and
    /// report how it went.
    Autoplay(AutoplayArgs),
    /// Check a map for a map maker: validation, then what the player can
    /// and cannot reach (the exit, keys, secrets, items) and soft locks.
    Check(CheckArgs),
    /// Measure what accuracy costs: the study suite, written as a report with
    /// tables and plots; or `bench tour MAP` to time the renderer headless.
    Bench(BenchArgs),
}

#[derive(Args)]
pub struct ImportArgs {
    /// The WAD file (an IWAD such as freedoom1.wad, or a PWAD with its own art
    /// or with `--iwad`).
    pub wad: PathBuf,
    /// The IWAD under a PWAD whose maps use the IWAD's art (`--iwad
    /// freedoom2.wad basic.wad`).
    #[arg(long)]
    pub iwad: Option<PathBuf>,
    /// The map to import (E1M4, MAP07), or `all`.
    #[arg(long)]
    pub map: String,
    /// The directory to write `<map>.ron` and the `textures/`, `flats/` and
    /// `sprites/` folders into.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Also compile each map before writing it, to catch any map the
    /// compiler would refuse.
    #[arg(long)]
    pub check: bool,
    /// Print one JSON object per map (counts, and what could not be
    /// translated: `unsupported_specials`, `unknown_things`) on its own line.
    #[arg(long)]
    pub json: bool,
}

/// `sightline bench [MAP...] --out DIR`: the study suite; `sightline bench
/// tour MAP`: the frame-time benchmark.
#[derive(Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct BenchArgs {
    #[command(subcommand)]
    pub command: Option<BenchCommand>,
    #[command(flatten)]
    pub suite: crate::suite::SuiteArgs,
}

#[derive(Subcommand)]
pub enum BenchCommand {
    /// Time render_frame over a map's things tour (the player start, then
    /// every thing's position looking eight ways).
    Tour(BenchTourArgs),
    /// Time the autopilot: planning per map (the navigation grid and every
    /// goal choice), and ticks per second of autoplay with rendering off
    /// and on.
    Autopilot(BenchAutopilotArgs),
    /// Time `check` per map (the report, then the route it draws), with the
    /// median and worst over the maps.
    Check(BenchCheckArgs),
    /// The autopilot as an expert on ViZDoom scenarios: its answer's cost
    /// per step, and the mean reward of following it against the random
    /// policy's, as a Markdown table.
    Expert(BenchExpertArgs),
}

#[derive(Args)]
pub struct BenchExpertArgs {
    /// Scenario `.cfg` files.
    #[arg(required = true)]
    pub scenarios: Vec<PathBuf>,
    /// Episodes per scenario and policy; episode `k` is seeded `k`.
    #[arg(long, default_value_t = 50, value_parser = clap::value_parser!(u32).range(1..))]
    pub episodes: u32,
    /// The IWAD under the scenarios' WADs.
    #[arg(long)]
    pub iwad: Option<PathBuf>,
}

#[derive(Args)]
pub struct BenchAutopilotArgs {
    /// Maps: RON files, compiled maps or `WAD:MAP`; `WAD:all` is every map
    /// of the WAD.
    #[arg(required = true)]
    pub maps: Vec<String>,
    /// Ticks of autoplay per map (it stops early at the exit).
    #[arg(long, default_value_t = 3_000)]
    pub ticks: u64,
    /// Frame size of the rendering-on run, WxH.
    #[arg(long, default_value = "320x200", value_parser = parse_size)]
    pub size: (usize, usize),
    /// Threads drawing each frame.
    #[arg(long, default_value_t = 1, value_parser = parse_threads)]
    pub threads: usize,
    /// Skill level 1 to 5.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u8).range(1..=5))]
    pub skill: u8,
    /// Play without monsters.
    #[arg(long)]
    pub no_monsters: bool,
    /// Also print one JSON object per map.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub struct BenchCheckArgs {
    /// Maps: RON files, compiled maps or `WAD:MAP`; `WAD:all` is every map
    /// of the WAD.
    #[arg(required = true)]
    pub maps: Vec<String>,
    /// Skill level 1 to 5.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u8).range(1..=5))]
    pub skill: u8,
    /// Time the autopilot's played route (`check --bot-route`) instead of
    /// the closure's.
    #[arg(long)]
    pub bot_route: bool,
    /// Also print one JSON object per map.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub struct BenchTourArgs {
    /// A RON map, a compiled map or `WAD:MAP`.
    pub map: String,
    /// The IWAD under a PWAD map.
    #[arg(long)]
    pub iwad: Option<PathBuf>,
    /// Frame size, WxH.
    #[arg(long, default_value = "320x200", value_parser = parse_size)]
    pub size: (usize, usize),
    /// bsp, reference, raycast (grid maps only), painter or zbuffer (the
    /// visibility study's overwriting renderers, no sprites or masked
    /// middles). Default: raycast for a grid map, bsp otherwise.
    #[arg(long, value_parser = parse_renderer)]
    pub renderer: Option<Renderer>,
    /// Timed passes over the tour, after one untimed warm-up pass. Default:
    /// enough for about three seconds.
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..100_000))]
    pub repeat: Option<u64>,
    /// Threads drawing each frame (its strips in parallel; the frame is the
    /// same for any count). Default: the machine's available parallelism.
    #[arg(long, default_value_t = available_threads(), value_parser = parse_threads)]
    pub threads: usize,
    /// Also print the figures as one JSON object on the last line.
    #[arg(long)]
    pub json: bool,
    /// Per-pixel buffers to fill besides the colour: off, depth, labels or
    /// both. A comma-separated list (`off,depth,labels,both`) times each in
    /// the same run, a pass of the tour each in turn, and reports each.
    #[arg(long, value_delimiter = ',', default_value = "off", value_parser = parse_buffers)]
    pub buffers: Vec<Buffers>,
}

#[derive(Args)]
pub struct CompileArgs {
    /// The RON map to compile.
    pub map: PathBuf,
    /// Where to write the compiled map.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Partition heuristic: random (randomized autopartition) or cost (splits and balance).
    #[arg(long, default_value = "cost", value_parser = parse_splitter)]
    pub splitter: SplitterKind,
    /// Seed of the random splitter.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Print the compile figures as one JSON object on the last line.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub struct CaptureArgs {
    /// A RON map, a compiled map, or `WAD:MAP` (a map read from a WAD).
    pub map: String,
    /// The IWAD under a PWAD map (`--iwad freedoom2.wad mymap.wad:MAP01`).
    #[arg(long)]
    pub iwad: Option<PathBuf>,
    /// X,Y,ANGLE[,Z]: where the eye is and where it looks (degrees,
    /// counter-clockwise from east). Default: the player start.
    #[arg(long, value_parser = parse_pose, allow_hyphen_values = true)]
    pub pose: Option<Pose>,
    /// Frame size, WxH.
    #[arg(long, default_value = "640x400", value_parser = parse_size)]
    pub size: (usize, usize),
    /// bsp, reference, raycast (grid maps only), painter or zbuffer (the
    /// visibility study's overwriting renderers, no sprites or masked
    /// middles). Default: raycast for a grid map, bsp otherwise.
    #[arg(long, value_parser = parse_renderer)]
    pub renderer: Option<Renderer>,
    /// How the ray-caster's rays find walls: dda (exact), march:K (a sample
    /// every K map units) or sphere:EPS (sphere tracing to within EPS).
    #[arg(long, default_value = "dda", value_parser = RayMethod::parse)]
    pub ray: RayMethod,
    /// textured (default): textures, sky, light, fog; flat: lit flat colours;
    /// ids: each wall, floor and ceiling in a colour from its index.
    #[arg(long, default_value = "textured", value_parser = parse_shade)]
    pub shade: Shade,
    /// Threads drawing each frame (its strips in parallel; the frame is the
    /// same for any count). Default: the machine's available parallelism.
    #[arg(long, default_value_t = available_threads(), value_parser = parse_threads)]
    pub threads: usize,
    /// The PNG to write.
    #[arg(short, long)]
    pub output: PathBuf,
}

#[derive(Args)]
pub struct PlayArgs {
    /// A RON map, a compiled map, a campaign file, a WAD (its first map,
    /// then its episode), `WAD:MAP`, or a ViZDoom scenario's `.cfg` (its
    /// map at its skill, the reward on the HUD). With none (and no --demo,
    /// --load or --autopilot): the title with the menu over it, where New
    /// Game starts maps/outpost.ron at the skill chosen (with only --iwad:
    /// that WAD's title and attract loop). In the window Esc
    /// opens the menu (the game pauses): New Game, Options (keys, mouse,
    /// run, volumes, status bar, HUD, full screen, autoaim; kept in the
    /// settings file), Load Game and Save Game (eight named slots), Quit.
    pub map: Option<String>,
    /// The IWAD under a PWAD (`--iwad freedoom2.wad mymap.wad:MAP01`).
    /// Given with no map: that WAD's title and attract loop (TITLEPIC,
    /// CREDIT and its demos in Doom's order; a key opens the menu, whose
    /// New Game starts its episodes).
    #[arg(long)]
    pub iwad: Option<PathBuf>,
    /// Start on the title even though a map is named: a WAD's own title
    /// and attract loop (`sightline play freedoom2.wad --title`).
    #[arg(long, conflicts_with_all = ["demo", "load", "autopilot"])]
    pub title: bool,
    /// Skill level 1 to 5 (Doom's: 3 is Hurt Me Plenty); things appear by it.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u8).range(1..=5))]
    pub skill: u8,
    /// How far a RON map's game moves on in Doom's random table (a WAD's
    /// map does not, as vanilla does not).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Internal frame size, WxH; the window scales it to fit. Default: the
    /// config file's, else 640x400.
    #[arg(long, value_parser = parse_size)]
    pub size: Option<(usize, usize)>,
    /// Initial window inner size, WxH. Default: the config file's, else the
    /// frame size times the largest whole factor that fits the screen.
    #[arg(long, value_parser = parse_size)]
    pub window: Option<(usize, usize)>,
    /// Present as fast as possible instead of at the display's refresh rate.
    #[arg(long)]
    pub no_vsync: bool,
    /// Quit by itself after this many frames, printing the frame-loop timings.
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
    pub frames: Option<u64>,
    /// Print the frame-loop timings (median render and upload+present) at exit.
    #[arg(long)]
    pub stats: bool,
    /// bsp, reference, raycast (grid maps only), painter or zbuffer; R
    /// cycles them in the window. Default: the config file's, else raycast
    /// for a grid map, else bsp.
    #[arg(long, value_parser = parse_renderer)]
    pub renderer: Option<Renderer>,
    /// Threads drawing each frame (its strips in parallel; the frame is the
    /// same for any count). Default: the config file's, else the machine's
    /// available parallelism.
    #[arg(long, value_parser = parse_threads)]
    pub threads: Option<usize>,
    /// Record the inputs of every tick into this demo file (written at exit).
    #[arg(long, conflicts_with = "demo")]
    pub record: Option<PathBuf>,
    /// Play this demo's inputs instead of the keyboard and mouse; the view
    /// stays on its last tick when it ends. A Doom demo (`FILE.lmp` with
    /// --iwad, or `WAD:DEMOn`) plays on the simulation with Doom's arithmetic.
    #[arg(long)]
    pub demo: Option<PathBuf>,
    /// DeHackEd or BEX patches a Doom demo plays with (Doom's -deh),
    /// applied in order after the IWAD's own DEHACKED lump.
    #[arg(long, value_name = "FILE", requires = "demo")]
    pub deh: Vec<PathBuf>,
    /// Let the autopilot play (watch it find its way to the exit); it
    /// goes on into the next map after each intermission.
    #[arg(long, conflicts_with_all = ["demo", "load"])]
    pub autopilot: bool,
    /// Play without monsters (Doom's -nomonsters).
    #[arg(long, conflicts_with_all = ["demo", "load"])]
    pub no_monsters: bool,
    /// Start with the HUD hidden (H toggles it).
    #[arg(long)]
    pub no_hud: bool,
    /// Degrees turned per mouse count while the cursor is grabbed.
    /// Default: the config file's, else 0.15.
    #[arg(long)]
    pub mouse_sensitivity: Option<f32>,
    /// The settings file to read and write instead of
    /// $XDG_CONFIG_HOME/sightline/config.ron (~/.config/sightline/config.ron).
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// Neither read nor write the settings file: defaults and flags only.
    #[arg(long, conflicts_with = "config")]
    pub no_config: bool,
    /// Continue the game saved in this file (F6 or F2 in the window save
    /// one) instead of starting a map.
    #[arg(long, conflicts_with_all = ["map", "demo", "record", "iwad"])]
    pub load: Option<PathBuf>,
    /// Where F6 and F2 save games and F9 and F3 load them. Default:
    /// $XDG_DATA_HOME/sightline/saves (~/.local/share/sightline/saves).
    #[arg(long)]
    pub save_dir: Option<PathBuf>,
    /// No sound at all (effects or music).
    #[arg(long)]
    pub no_sound: bool,
    #[command(flatten)]
    pub sound: SoundArgs,
}

/// Sound options shared by `play` and `replay --audio`.
#[derive(Args, Clone, Debug)]
pub struct SoundArgs {
    /// No music.
    #[arg(long)]
    pub no_music: bool,
    /// The General MIDI SoundFont (.sf2) music is played with. Default: the
    /// first found of Debian's (timgm6mb-soundfont, fluid-soundfont-gm).
    #[arg(long)]
    pub soundfont: Option<PathBuf>,
    /// Effects' volume, 0 to 100. Default: the config file's (`play`), else 80.
    #[arg(long, value_parser = clap::value_parser!(u8).range(0..=100))]
    pub sfx_volume: Option<u8>,
    /// Music's volume, 0 to 100. Default: the config file's (`play`), else 60.
    #[arg(long, value_parser = clap::value_parser!(u8).range(0..=100))]
    pub music_volume: Option<u8>,
    /// Sounds played at once. Default: the config file's (`play`), else
    /// Doom's snd_channels, 8.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=64))]
    pub channels: Option<u16>,
}

impl SoundArgs {
    /// `base`'s settings with these flags over them.
    pub fn over(&self, base: &crate::config::Sound) -> crate::config::Sound {
        crate::config::Sound {
            effects_volume: self.sfx_volume.unwrap_or(base.effects_volume),
            music_volume: self.music_volume.unwrap_or(base.music_volume),
            channels: self.channels.unwrap_or(base.channels),
            soundfont: self.soundfont.clone().or_else(|| base.soundfont.clone()),
            music: base.music && !self.no_music,
        }
    }
}

#[derive(Args)]
pub struct ReplayArgs {
    /// The demo to replay: one of ours (`.sldemo`), Doom's (`.lmp`, played
    /// on --iwad) or a demo lump inside a WAD (`freedoom1.wad:DEMO1`).
    pub demo: PathBuf,
    /// Replay on this map (a path or `WAD:MAP`) instead of the one the demo names.
    #[arg(long)]
    pub map: Option<String>,
    /// The IWAD under a PWAD given with --map, or that a Doom demo plays on.
    #[arg(long)]
    pub iwad: Option<PathBuf>,
    /// PWADs a Doom demo plays on, over the IWAD (Doom's -file).
    #[arg(long, num_args = 1..)]
    pub file: Vec<PathBuf>,
    /// DeHackEd or BEX patches a Doom demo plays with (Doom's -deh),
    /// applied in order after the IWAD's own DEHACKED lump.
    #[arg(long, value_name = "FILE")]
    pub deh: Vec<PathBuf>,
    /// Compare every tic of a Doom demo with a reference dump (see
    /// tests/fixtures/demo-dumps/README.md); name the first tic that differs.
    #[arg(long)]
    pub check_against: Option<PathBuf>,
    /// End with the game's state as one JSON object (Doom demos).
    #[arg(long)]
    pub json: bool,
    /// Run every tic of a Doom demo and render a frame per tic (none kept,
    /// none shown); print Chocolate Doom's "timed N gametics in M
    /// realtics" and the CPU and wall time per frame.
    #[arg(long, conflicts_with_all = ["capture_every", "check_against"])]
    pub timedemo: bool,
    /// With --timedemo: also print where a frame's time went (the tic, the
    /// scene's update from the game, and the renderer's parts as `sightline
    /// bench tour` names them), from stopwatches that cost a little.
    #[arg(long, requires = "timedemo")]
    pub profile: bool,
    /// The Doom executable a Doom demo plays as: 1.9, ultimate or final.
    /// Default: as Chocolate Doom picks it from the IWAD (freedoom1.wad
    /// plays as The Ultimate Doom, freedoom2.wad as Doom II 1.9).
    #[arg(long, value_parser = sightline::sim::demo::parse_game_version)]
    pub gameversion: Option<sightline::sim::GameVersion>,
    /// Write a PNG of every Nth tick (tick 0, N, 2N, ... and the last) into
    /// the directory given with -o.
    #[arg(long, requires = "output", value_parser = clap::value_parser!(u64).range(1..))]
    pub capture_every: Option<u64>,
    /// Directory for the captured frames (created if missing).
    #[arg(short, long, requires = "capture_every")]
    pub output: Option<PathBuf>,
    /// Size of the captured frames, WxH.
    #[arg(long, default_value = "640x400", value_parser = parse_size)]
    pub size: (usize, usize),
    /// bsp, reference, raycast (grid maps only), painter or zbuffer (the
    /// visibility study's overwriting renderers, no sprites or masked
    /// middles). Default: raycast for a grid map, else bsp.
    #[arg(long, value_parser = parse_renderer)]
    pub renderer: Option<Renderer>,
    /// Threads drawing each frame (its strips in parallel; the frame is the
    /// same for any count). Default: the machine's available parallelism.
    #[arg(long, default_value_t = available_threads(), value_parser = parse_threads)]
    pub threads: usize,
    /// Render the run's sound and music into this WAV file (16-bit stereo,
    /// 44,100 Hz, 1,260 frames a tick): the same demo gives the same bytes.
    #[arg(long)]
    pub audio: Option<PathBuf>,
    #[command(flatten)]
    pub sound: SoundArgs,
}

#[derive(Args)]
pub struct AutoplayArgs {
    /// A RON map, a compiled map, `WAD:MAP`, or a ViZDoom scenario's
    /// `.cfg` (played by `--policy` for `--episodes` episodes).
    pub map: String,
    /// The IWAD under a PWAD map.
    #[arg(long)]
    pub iwad: Option<PathBuf>,
    /// Skill level 1 to 5.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u8).range(1..=5))]
    pub skill: u8,
    /// How far a RON map's game moves on in Doom's random table (a WAD's
    /// map does not, as vanilla does not).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Play without monsters (Doom's -nomonsters).
    #[arg(long)]
    pub no_monsters: bool,
    /// Give up after this many ticks (35 a second; default 20 minutes).
    #[arg(long, default_value_t = 42_000)]
    pub max_ticks: u64,
    /// Play on through this many levels of the campaign, pressing through
    /// each intermission (`--record` keeps them all in one demo).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    pub levels: u32,
    /// Record the run as a demo (`sightline replay` plays it back).
    #[arg(long)]
    pub record: Option<PathBuf>,
    /// Write a PNG of every Nth tick into the directory given with -o.
    #[arg(long, requires = "output", value_parser = clap::value_parser!(u64).range(1..))]
    pub capture_every: Option<u64>,
    /// Directory for the captured frames (created if missing).
    #[arg(short, long, requires = "capture_every")]
    pub output: Option<PathBuf>,
    /// Size of the captured frames, WxH.
    #[arg(long, default_value = "640x400", value_parser = parse_size)]
    pub size: (usize, usize),
    /// Threads drawing each captured frame.
    #[arg(long, default_value_t = available_threads(), value_parser = parse_threads)]
    pub threads: usize,
    /// Print the outcome as one JSON object.
    #[arg(long)]
    pub json: bool,
    /// A scenario `.cfg`: episodes to play.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    pub episodes: u32,
    /// A scenario `.cfg`: who presses the buttons. `random`: each tic one of
    /// the `.cfg`'s buttons, or none, uniformly, from a generator seeded
    /// with `--seed`; `idle`: nothing is pressed; `expert`: what the
    /// autopilot would press (`scenario::expert`).
    #[arg(long, value_enum, default_value_t = Policy::Random)]
    pub policy: Policy,
}

/// Who plays a scenario in `sightline autoplay SCENARIO.cfg`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Policy {
    Random,
    Idle,
    Expert,
}

#[derive(Args)]
pub struct CheckArgs {
    /// A RON map, a compiled map or `WAD:MAP`.
    pub map: String,
    /// The IWAD under a PWAD map.
    #[arg(long)]
    pub iwad: Option<PathBuf>,
    /// Skill level 1 to 5 (which things are in the map).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u8).range(1..=5))]
    pub skill: u8,
    /// Print the report as one JSON object.
    #[arg(long)]
    pub json: bool,
    /// Draw the map from above into this PNG: what cannot be reached, where
    /// the player can get stuck, and the route to the exit.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Also draw the BSP's partition lines on the plan.
    #[arg(long, requires = "output")]
    pub partitions: bool,
    /// The plan's longer side, pixels.
    #[arg(long, default_value_t = 1400, value_parser = clap::value_parser!(u32).range(64..=16_384))]
    pub plan_size: u32,
    /// Draw the autopilot's own route, played offline with no monsters for
    /// up to 20 minutes of game time, instead of the report's route. Slow:
    /// minutes on the biggest maps (274 s on freedoom2 MAP29).
    #[arg(long, requires = "output")]
    pub bot_route: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub x: f64,
    pub y: f64,
    pub angle: f64,
    pub z: Option<f64>,
}

/// Largest frame side we accept, and largest pixel count: 64 Mpx, which with
/// the canvas and the PNG rows stays well under a gigabyte.
const MAX_SIDE: usize = 16_384;
const MAX_PIXELS: usize = 8_192 * 8_192;

pub fn parse_size(s: &str) -> Result<(usize, usize), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(|| format!("size `{s}` is not WxH, e.g. 640x400"))?;
    let side = |v: &str| {
        v.trim()
            .parse::<usize>()
            .ok()
            .filter(|n| (1..=MAX_SIDE).contains(n))
            .ok_or_else(|| format!("size `{s}`: `{v}` is not a whole number of pixels in 1..={MAX_SIDE}"))
    };
    let (w, h) = (side(w)?, side(h)?);
    if w * h > MAX_PIXELS {
        return Err(format!("size `{s}` has more than {MAX_PIXELS} pixels"));
    }
    Ok((w, h))
}

pub fn parse_pose(s: &str) -> Result<Pose, String> {
    let parts: Vec<&str> = s.split(',').collect();
    if !(3..=4).contains(&parts.len()) {
        return Err(format!("pose `{s}` is not X,Y,ANGLE or X,Y,ANGLE,Z"));
    }
    let mut values = Vec::with_capacity(4);
    for p in &parts {
        let v: f64 = p.trim().parse().map_err(|_| format!("pose `{s}`: `{p}` is not a number"))?;
        if !v.is_finite() {
            return Err(format!("pose `{s}`: `{p}` is not finite"));
        }
        values.push(v);
    }
    Ok(Pose { x: values[0], y: values[1], angle: values[2], z: values.get(3).copied() })
}

/// Most threads a frame may be drawn with.
pub const MAX_THREADS: usize = 256;

/// The machine's available parallelism (1 when it cannot be told).
pub fn available_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get()).min(MAX_THREADS)
}

fn parse_threads(s: &str) -> Result<usize, String> {
    s.trim()
        .parse::<usize>()
        .ok()
        .filter(|n| (1..=MAX_THREADS).contains(n))
        .ok_or_else(|| format!("threads `{s}` is not a whole number in 1..={MAX_THREADS}"))
}

fn parse_splitter(s: &str) -> Result<SplitterKind, String> {
    SplitterKind::from_name(s).ok_or_else(|| {
        let names: Vec<_> = SplitterKind::ALL.iter().map(|k| k.name()).collect();
        format!("unknown splitter `{s}`; choose one of {}", names.join(", "))
    })
}

pub fn parse_renderer(s: &str) -> Result<Renderer, String> {
    Renderer::from_name(s).ok_or_else(|| {
        let names: Vec<_> = Renderer::ALL.iter().map(|r| r.name()).collect();
        format!("unknown renderer `{s}`; choose one of {}", names.join(", "))
    })
}

fn parse_buffers(s: &str) -> Result<Buffers, String> {
    Buffers::from_name(s.trim()).ok_or_else(|| format!("unknown buffers `{s}`; choose off, depth, labels or both"))
}

fn parse_shade(s: &str) -> Result<Shade, String> {
    Shade::from_name(s).ok_or_else(|| format!("unknown shade `{s}`; choose textured, flat or ids"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_and_poses() {
        assert_eq!(parse_size("320x200"), Ok((320, 200)));
        assert!(parse_size("0x200").is_err());
        assert!(parse_size("320").is_err());
        assert!(parse_size("99999x2").is_err());
        assert_eq!(parse_pose("1,2,90").map(|p| p.z), Ok(None));
        assert_eq!(parse_pose("1,-2,90,50").map(|p| (p.y, p.z)), Ok((-2.0, Some(50.0))));
        assert!(parse_pose("1,2").is_err());
        assert!(parse_pose("1,2,nan").is_err());
        assert_eq!(parse_threads("3"), Ok(3));
        assert!(parse_threads("0").is_err() && parse_threads("two").is_err());
        assert!(available_threads() >= 1);
    }
}
