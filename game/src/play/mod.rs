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
mod clock;
pub(crate) mod hud;
mod input;
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
use app::{App, AppOptions};
use input::Controls;
use screen::ScreenOptions;
use session::Session;

const NO_DISPLAY_HINT: &str = "For frames without a window use `sightline capture MAP -o frame.png` \
     (or `sightline replay DEMO --capture-every N -o DIR`).";

pub fn run(args: &PlayArgs) -> Result<()> {
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
            let no_autoaim = scenario.as_ref().is_some_and(|c| c.no_autoaim());
            let setup = sightline::sim::game::Setup { no_autoaim, ..sightline::sim::game::Setup::SINGLE };
            Playthrough::of_set_up(&map, game_options, setup)
                .with_context(|| format!("{}: cannot start the game", map.label()))?
        }
    };
    let renderer = crate::replay::choose_renderer(args.renderer, play.game.level(), &play.map.label())?;
    // A `.lmp` keeps turns to 1/256 of the circle: the game is fed them so.
    let lmp = args.record.as_deref().is_some_and(crate::replay_lmp::is_lmp_path);
    let mut session = match (demo, vanilla) {
        (_, Some((_, run))) => Session::vanilla(play, run),
        (Some(demo), None) => Session::demo(play, demo.inputs),
        (None, None) if args.autopilot => Session::autopilot(play, args.record.is_some(), lmp),
        (None, None) => Session::live(play, Controls::new(args.mouse_sensitivity), args.record.is_some(), lmp),
    };

    check_display()?;
    if !args.no_sound {
        match sound::SoundOut::open(&args.sound) {
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
    let (w, h) = args.size;
    let options = AppOptions {
        screen: ScreenOptions {
            title: app::title(&session.play),
            frame: (w as u32, h as u32),
            window: args.window.map(|(w, h)| (w as u32, h as u32)),
            vsync: !args.no_vsync,
        },
        renderer,
        threads: args.threads,
        frame_limit: args.frames,
        hud: !args.no_hud,
        save_dir: args.save_dir.clone().unwrap_or_else(saves::default_dir),
        scenario,
    };
    let mut app = App::new(session, options);
    let ran = event_loop.run_app(&mut app);
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
