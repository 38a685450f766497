//! `sightline replay`: a demo's inputs through the simulation, headless, as
//! fast as it runs. The same demo gives the same positions and the same
//! frames every time: the simulation is deterministic and frames are
//! rendered from the state after whole ticks (`SimGame::view(1.0)`), never from
//! wall time. A demo that exits a level goes on through the intermission
//! into the next map, as the window would.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use sightline::campaign::MapRef;
use sightline::level::{write_atomic, Level};
use sightline::play::demo::Demo;
use sightline::play::playthrough::Playthrough;
use sightline::render::{render_frame, Frame, RenderOptions, Renderer};
use sightline::Framebuffer;

use crate::cli::ReplayArgs;
use crate::play::hud;

pub fn run(args: &ReplayArgs) -> Result<()> {
    if crate::replay_lmp::is_vanilla(&args.demo.to_string_lossy()) {
        return crate::replay_lmp::run(args);
    }
    let demo = Demo::load(&args.demo)?;
    let map = match &args.map {
        Some(map) => MapRef::parse(map, args.iwad.as_deref()),
        None => demo_map(&demo.map, &args.demo),
    };
    let options = demo.options();
    let mut play = Playthrough::of(&map, options).with_context(|| format!("{}: cannot start the game", map.label()))?;
    let renderer = choose_renderer(args.renderer, play.game.level(), &map.label())?;
    let options = RenderOptions { renderer, threads: args.threads, ..Default::default() };
    let mut capture = match (args.capture_every, &args.output) {
        (Some(every), Some(dir)) => Some(Capture::new(every, dir, args.size, options)?),
        _ => None,
    };
    let last = demo.inputs.len() as u64;
    if let Some(c) = &mut capture {
        c.frame(&play, 0)?;
    }
    let mut sound = args.audio.as_ref().map(|_| {
        (
            sightline::sound::Sounds::new(),
            crate::audio::audio(&args.sound.over(&crate::config::Config::default().sound)),
            Vec::<f32>::new(),
        )
    });
    for (i, input) in demo.inputs.iter().enumerate() {
        play.tick(input)?;
        if let Some((sounds, audio, samples)) = &mut sound {
            let cues = sounds.cues(&play);
            crate::audio::warn(sounds);
            if let Err(e) = audio.render_tick(&cues, samples) {
                eprintln!("sightline: warning: music: {e}");
            }
        }
        let tick = i as u64 + 1;
        if let Some(c) = &mut capture {
            if tick.is_multiple_of(c.every) || tick == last {
                c.frame(&play, tick)?;
            }
        }
    }
    if let Some(c) = &capture {
        println!("wrote {} frames to {}", c.written, c.dir.display());
    }
    if let (Some(path), Some((_, _, samples))) = (&args.audio, &sound) {
        sightline::sound::wav::write(path, samples, sightline::sound::OUTPUT_RATE)
            .map_err(|e| anyhow::anyhow!("{}: cannot write the audio: {e}", path.display()))?;
        println!(
            "wrote {:.1} s of audio to {}",
            samples.len() as f64 / 2.0 / f64::from(sightline::sound::OUTPUT_RATE),
            path.display()
        );
    }
    println!("{}", position_line(&play));
    Ok(())
}

/// Where the game stands, in full precision (shortest round-trip form), so
/// two runs can be compared as text.
pub fn position_line(play: &Playthrough) -> String {
    let p = play.game.player();
    format!("tick {}: x {:?} y {:?} z {:?} angle {:?}", play.ticks, p.pos.x, p.pos.y, p.z, p.angle)
}

/// The renderer asked for, else the level's default; an error when it
/// cannot draw the level (the ray-caster on a sector map).
pub fn choose_renderer(asked: Option<Renderer>, level: &Level, map: &str) -> Result<Renderer> {
    let renderer = asked.unwrap_or_else(|| Renderer::default_for(level));
    if !renderer.supports(level) {
        bail!("{map}: the {} renderer draws grid maps only; this is a sector map", renderer.name());
    }
    Ok(renderer)
}

/// The map a demo names: a WAD map as written; a file as given when that
/// path exists from here, else beside the demo file.
pub fn demo_map(name: &str, demo: &Path) -> MapRef {
    match MapRef::from_label(name) {
        MapRef::File(given) => MapRef::File(beside(given, demo)),
        MapRef::Wad { wads, map } => MapRef::Wad { wads: wads.into_iter().map(|w| beside(w, demo)).collect(), map },
    }
}

fn beside(given: PathBuf, demo: &Path) -> PathBuf {
    if given.exists() || given.is_absolute() {
        return given;
    }
    let beside = demo.parent().unwrap_or(Path::new(".")).join(&given);
    if beside.exists() {
        beside
    } else {
        given
    }
}

pub struct Capture {
    pub written: usize,
    pub every: u64,
    pub dir: PathBuf,
    options: RenderOptions,
    frame: Frame,
    fb: Framebuffer,
}

impl Capture {
    pub fn new(every: u64, dir: &Path, (w, h): (usize, usize), options: RenderOptions) -> Result<Capture> {
        std::fs::create_dir_all(dir).with_context(|| format!("{}: cannot create the directory", dir.display()))?;
        Ok(Capture {
            every,
            dir: dir.to_path_buf(),
            options,
            frame: Frame::new(),
            fb: Framebuffer::new(w, h),
            written: 0,
        })
    }

    /// Renders the state after `tick` ticks to `tick-NNNNNN.png` (with the
    /// intermission over it, between levels).
    pub fn frame(&mut self, play: &Playthrough, tick: u64) -> Result<()> {
        let game = &play.game;
        render_frame(game.level(), &game.view(1.0), &self.options, &mut self.frame, &mut self.fb);
        let table = &game.sim.info.table;
        sightline::screen::draw(&mut self.fb, game.level(), table, game.player(), sightline::screen::Hud::StatusBar);
        hud::draw_phase(&mut self.fb, &play.phase);
        write_atomic(&self.dir.join(format!("tick-{tick:06}.png")), &self.fb.to_png())?;
        self.written += 1;
        Ok(())
    }
}
