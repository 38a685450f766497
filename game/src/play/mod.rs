//! `sightline play`: a map in a window. The engine renders into a
//! `Framebuffer` exactly as it does headless; this module adds the window
//! (winit), the GPU surface that scales the frame to it (pixels), input, and
//! the fixed-timestep loop that drives `sightline::play::Game`.
//!
//! ```text
//! keys, mouse ─▶ input::Controls ─┐            (or a demo's inputs)
//!                                 ▼
//! wall time ─▶ clock::TickClock ─▶ session::Session::run(ticks) ─▶ Game::tick
//!                    │ alpha
//!                    ▼
//!              Game::view(alpha) ─▶ render_frame ─▶ automap, hud ─▶ screen::Screen::present
//! ```

mod app;
mod attract;
mod clock;
pub(crate) mod gamepad;
pub(crate) mod hud;
pub(crate) mod input;
mod menus;
mod saves;
mod screen;
mod screenshot;
mod session;
mod sound;
mod timings;

use anyhow::{anyhow, bail, Context, Result};
use sightline::campaign::MapRef;
use sightline::play::demo::Demo;
use sightline::play::playthrough::Playthrough;
use sightline::play::GameOptions;
use winit::event_loop::{ControlFlow, EventLoop};

use crate::cli::PlayArgs;
use crate::config::{self, Config};
use app::{App, AppOptions, Changeable};
use input::{Controls, Keymap};
use screen::ScreenOptions;
use session::Session;

const NO_DISPLAY_HINT: &str = "For frames without a window use `sightline capture MAP -o frame.png` \
     (or `sightline replay DEMO --capture-every N -o DIR`).";

pub fn run(args: &PlayArgs) -> Result<()> {
    let settings = Settings::read(args);
    let config = &settings.loaded.config;
    let vanilla = match &args.demo {
        Some(path) if crate::replay_lmp::is_vanilla(&path.to_string_lossy()) => {
            Some(crate::replay_lmp::VanillaRun::open(&path.to_string_lossy(), args.iwad.as_deref(), &args.deh)?)
        }
        _ => None,
    };
    let demo = match &args.demo {
        Some(_) if vanilla.is_some() => None,
        Some(path) => Some(Demo::load(path)?),
        None => None,
    };
    let scenario = match &args.map {
        Some(path) if crate::scenario::is_cfg(path) => Some(sightline::scenario::ScenarioConfig::load(path)?),
        _ => None,
    };
    let map = match (&args.map, &demo, &args.demo) {
        (_, _, _) if scenario.is_some() => {
            let Some(config) = &scenario else { unreachable!() };
            sightline::scenario::map_of(config, args.iwad.as_deref())?
        }
        (_, _, _) if vanilla.is_some() => vanilla
            .as_ref()
            .map(|(map, _)| map.clone())
            .unwrap_or_else(|| MapRef::File(crate::capture::default_map_path())),
        (Some(map), _, _) => MapRef::parse(map, args.iwad.as_deref()),
        (None, Some(demo), Some(demo_path)) => crate::replay::demo_map(&demo.map, demo_path),
        // Only --iwad: that WAD's game (its title first).
        (None, None, None) if args.iwad.is_some() => {
            MapRef::Wad { wads: args.iwad.iter().cloned().collect(), map: None }
        }
        _ => MapRef::File(crate::capture::default_map_path()),
    };
    let game_options = match (&demo, &scenario) {
        (Some(demo), _) => demo.options(),
        (None, Some(config)) => {
            let skill = config.doom_skill.clamp(1, 5) as u8;
            GameOptions { skill, seed: args.seed, no_monsters: args.no_monsters }
        }
        (None, None) => GameOptions { skill: args.skill, seed: args.seed, no_monsters: args.no_monsters },
    };
    let play = match &args.load {
        Some(save) => Playthrough::load(save)?,
        None => {
            // A recording keeps Doom's autoaim: a demo does not say it was off.
            let no_autoaim = scenario.as_ref().is_some_and(|c| c.no_autoaim())
                || (!config.gameplay.autoaim && args.record.is_none() && args.demo.is_none());
            let setup = sightline::sim::game::Setup { no_autoaim, ..sightline::sim::game::Setup::SINGLE };
            // A RON map's pictures may come from --iwad too.
            let art = sightline::campaign::ArtOptions {
                wads: crate::capture::art_wads(&map, args.iwad.as_deref()),
                missing: None,
            };
            let play = Playthrough::of_with(&map, game_options, setup, art)
                .with_context(|| format!("{}: cannot start the game", map.label()))?;
            crate::capture::warn(&play.game.level().materials.warnings);
            play
        }
    };
    let chosen =
        args.renderer.or_else(|| config.video.renderer.as_deref().and_then(sightline::render::Renderer::from_name));
    let renderer = crate::replay::choose_renderer(chosen, play.game.level(), &play.map.label())?;
    let keys = Keymap::of(&config.bindings());
    // No map, demo, save or scenario named: the title, with the menu open
    // (New Game starts the default level at the skill chosen).
    let title = args.title || (args.map.is_none() && args.demo.is_none() && args.load.is_none() && !args.autopilot);
    // A `.lmp` keeps turns to 1/256 of the circle: the game is fed them so.
    let lmp = args.record.as_deref().is_some_and(crate::replay_lmp::is_lmp_path);
    let mut session = match (demo, vanilla) {
        (_, Some((_, run))) => Session::vanilla(play, run),
        (Some(demo), None) => Session::demo(play, demo.inputs),
        (None, None) if args.autopilot => Session::autopilot(play, args.record.is_some(), lmp),
        (None, None) => {
            let controls = input::Settings {
                keys: keys.clone(),
                sensitivity: args.mouse_sensitivity.unwrap_or(config.controls.mouse_sensitivity),
                invert_mouse: config.controls.invert_mouse,
                always_run: config.controls.always_run,
                pad: config.pad_map(),
            };
            Session::live(play, Controls::new(controls), args.record.is_some(), lmp)
        }
    };

    check_display()?;
    if !args.no_sound {
        match sound::SoundOut::open(&args.sound.over(&config.sound)) {
            Ok(out) => {
                println!("sound: playing to the system's audio");
                session.sound = Some(out);
            }
            Err(e) => println!("sound: off: {e}; the game runs silent"),
        }
    }
    let event_loop = EventLoop::new()
        .map_err(|e| anyhow!("cannot open a window: no display could be reached ({e}).\n{NO_DISPLAY_HINT}"))?;
    event_loop.set_control_flow(ControlFlow::Poll);
    let (w, h) = args.size.map_or(config.video.size, |(w, h)| (w as u32, h as u32));
    let threads = match (args.threads, config.video.threads) {
        (Some(n), _) => n,
        (None, 0) => crate::cli::available_threads(),
        (None, n) => n,
    };
    let options = AppOptions {
        screen: ScreenOptions {
            title: app::title(&session.play),
            frame: (w, h),
            window: args.window.map(|(w, h)| (w as u32, h as u32)).or(config.video.window),
            vsync: !args.no_vsync && config.video.vsync,
            fullscreen: config.video.fullscreen,
        },
        renderer,
        threads,
        frame_limit: args.frames,
        hud: !args.no_hud && config.video.hud,
        status_bar: config.video.status_bar,
        keys,
        save_dir: args.save_dir.clone().unwrap_or_else(saves::default_dir),
        scenario,
        pads: if config.gamepad.enabled { gamepad::open_all() } else { None },
        title,
        config: config.clone(),
        new_game: (map.clone(), game_options),
    };
    let mut app = App::new(session, options);
    let at_start = app.changeable();
    println!(
        "settings: effects volume {}%, music volume {}%",
        (at_start.menu.effects_volume),
        (at_start.menu.music_volume)
    );
    let ran = event_loop.run_app(&mut app);
    settings.keep(at_start, app.changeable());
    if (args.frames.is_some() || args.stats) && app.timings.frames() > 0 {
        println!("{}", app.timings.summary());
    }
    let app_error = app.error.take();
    let mut session = app.into_session();
    let error = app_error.or(session.error.take());
    // A window that never opened leaves nothing worth a demo file.
    let recording = session.take_recording().filter(|inputs| error.is_none() || !inputs.is_empty());
    let saved = match (&args.record, recording) {
        (Some(path), Some(inputs)) => {
            let ticks = inputs.len();
            crate::replay_lmp::save_recording(path, &map, game_options, inputs)
                .map(|()| println!("recorded {ticks} ticks to {}", path.display()))
        }
        _ => Ok(()),
    };
    // What stopped the window matters more than the demo that could not be saved.
    if let Some(e) = error {
        return Err(e);
    }
    ran.map_err(|e| anyhow!("the window's event loop failed: {e}"))?;
    saved
}

/// Without a display server winit fails with a terse message; say what to
/// do instead. (Only where X11 or Wayland is the way to a display.)
fn check_display() -> Result<()> {
    if cfg!(all(unix, not(target_os = "macos"), not(target_os = "android"), not(target_os = "ios"))) {
        let set = |var: &str| std::env::var_os(var).is_some_and(|v| !v.is_empty());
        if !set("DISPLAY") && !set("WAYLAND_DISPLAY") && !set("WAYLAND_SOCKET") {
            bail!("no display to open a window on (neither DISPLAY nor WAYLAND_DISPLAY is set).\n{NO_DISPLAY_HINT}");
        }
    }
    Ok(())
}

/// The settings file this run reads and writes, and what it held.
struct Settings {
    path: Option<std::path::PathBuf>,
    loaded: config::Loaded,
}

impl Settings {
    /// Reads the settings file (`--config`, else the default one; none
    /// with `--no-config`), printing its warnings.
    fn read(args: &PlayArgs) -> Settings {
        let path = if args.no_config { None } else { args.config.clone().or_else(config::default_path) };
        let loaded = match &path {
            Some(path) => config::load(path),
            None => config::Loaded { config: Config::default(), warnings: Vec::new(), needs_backup: false },
        };
        if let Some(path) = path.as_ref().filter(|p| p.is_file()) {
            println!("settings: {}", path.display());
        }
        for w in &loaded.warnings {
            eprintln!("sightline: warning: {w}");
        }
        Settings { path, loaded }
    }

    /// Writes back what the player changed in the game (from `before` to
    /// `after`), if anything; the settings the flags overrode for this run
    /// keep the file's values.
    fn keep(&self, before: Changeable, after: Changeable) {
        let Some(path) = &self.path else { return };
        let mut config = self.loaded.config.clone();
        let v = &mut config.video;
        if before.status_bar != after.status_bar {
            v.status_bar = after.status_bar;
        }
        if before.hud != after.hud {
            v.hud = after.hud;
        }
        if before.fullscreen != after.fullscreen {
            v.fullscreen = after.fullscreen;
        }
        if before.menu != after.menu {
            menus::controls_into(&after.menu, &mut config);
        }
        if let (Some(was), Some(now)) = (before.volumes, after.volumes) {
            let percent = |v: f32| (v * 100.0).round().clamp(0.0, 100.0) as u8;
            if was.0 != now.0 {
                config.sound.effects_volume = percent(now.0);
            }
            if was.1 != now.1 {
                config.sound.music_volume = percent(now.1);
            }
        }
        if config == self.loaded.config {
            return;
        }
        match config.save(path, self.loaded.needs_backup) {
            Ok(()) => println!("settings saved to {}", path.display()),
            Err(e) => eprintln!("sightline: warning: the settings were not saved: {e:#}"),
        }
    }
}
