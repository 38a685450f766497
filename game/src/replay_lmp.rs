//! `sightline replay` on Doom's own demos: a `.lmp` file (with `--iwad`) or
//! a demo lump inside a WAD (`freedoom1.wad:DEMO1`), played headless on the
//! simulation with Doom's arithmetic (`sightline::sim`). `--check-against
//! DUMP` compares each tic with a reference dump from Chocolate Doom and
//! stops at the first tic that differs, naming the fields (the tool for
//! bisecting a desync); `--json` ends with the game's state. Recording
//! (`--record x.lmp`) and the window's `--demo` are here too.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};
use serde_json::json;
use sightline::actors::ActorTable;
use sightline::bsp::BuildOptions;
use sightline::campaign::MapRef;
use sightline::level::write_atomic;
use sightline::play::demo::Demo;
use sightline::play::lmp::VanillaDemo;
use sightline::play::syncdump::SyncDump;
use sightline::play::vanilla::{demo_of, open_demo};
use sightline::play::{GameOptions, TickInput};
use sightline::render::{render_frame, Breakdown, Frame, Lap, RenderOptions};
use sightline::sim::demo::{DemoGame, SyncCheck};
use sightline::sim::{self, Sim};
use sightline::Framebuffer;

use crate::cli::ReplayArgs;

/// Whether `args.demo` names a vanilla demo: a `WAD:LUMP`, or a file that is
/// not one of our own demos.
pub fn is_vanilla(spec: &str) -> bool {
    let wad_lump = spec.rsplit_once(':').is_some_and(|(w, _)| w.to_ascii_lowercase().ends_with(".wad"));
    wad_lump || !std::fs::read(spec).is_ok_and(|b| b.starts_with(sightline::play::demo::MAGIC))
}

/// Whether a recording to `path` is a Doom demo (it ends in `.lmp`).
pub fn is_lmp_path(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("lmp"))
}

/// Writes a recorded game: a Doom demo to a `.lmp` path (a WAD map's, its
/// inputs already rounded as the file keeps them), else one of ours.
pub fn save_recording(path: &Path, map: &MapRef, options: GameOptions, inputs: Vec<TickInput>) -> Result<()> {
    if is_lmp_path(path) {
        let name = match map {
            MapRef::Wad { map: Some(name), .. } => name.clone(),
            other => bail!("{}: a Doom demo records a WAD's map, not {}", path.display(), other.label()),
        };
        let demo = demo_of(&name, options, &inputs).map_err(|e| anyhow!("{}: {e}", path.display()))?;
        demo.save(path)?;
    } else {
        // The map as given, so a demo recorded in the repository replays there.
        let demo = Demo {
            inputs,
            skill: options.skill,
            seed: options.seed,
            no_monsters: options.no_monsters,
            ..Demo::new(map.label())
        };
        demo.save(path)?;
    }
    Ok(())
}

/// A Doom demo played on the simulation with Doom's arithmetic, for the
/// window: the game (across levels), the demo, where the next tic is, and
/// how the game is drawn on the converted map the window renders.
pub struct VanillaRun {
    pub game: DemoGame,
    pub demo: VanillaDemo,
    pub next: usize,
    pub scene: sim::draw::Scene,
    /// The map the window shows (the game may have gone on to the next).
    pub shown: MapRef,
}

impl VanillaRun {
    /// Opens `spec` on `iwad`; the map to show is returned beside it.
    pub fn open(spec: &str, iwad: Option<&Path>, deh: &[PathBuf]) -> Result<(MapRef, VanillaRun)> {
        let source = open_demo(spec, iwad, &[])?;
        let (map, _) = source.game()?;
        let wad = source.wad()?;
        let table = sim::demo::table_with_patches(&wad, ActorTable::active(), deh).map_err(|e| anyhow!("{e}"))?;
        let sim = sim::demo::start(&wad, &source.demo, table).map_err(|e| anyhow!("{spec}: {e}"))?;
        let game = DemoGame::new(std::sync::Arc::new(wad), sim);
        let opened = sightline::campaign::open(&map, &BuildOptions::default())?;
        let scene = sim::draw::Scene::new(opened.links.unwrap_or_default());
        Ok((map.clone(), VanillaRun { game, demo: source.demo, next: 0, scene, shown: map }))
    }

    /// Runs the next tic, if the demo has one (`Ok(false)` when it has run
    /// out); a next map the WAD lacks is an error.
    pub fn tick(&mut self) -> Result<bool> {
        if self.next >= self.demo.tics() {
            return Ok(false);
        }
        self.game.tick(&sim::demo::commands(&self.demo, self.next)).map_err(|e| anyhow!("{e}"))?;
        self.next += 1;
        Ok(true)
    }

    /// The map the game has gone on to, when it is not the one shown.
    pub fn moved_to(&self) -> Option<MapRef> {
        moved_to(&self.shown, &self.game.sim.level.name)
    }

    /// Shows `map` from now on (the window has opened it), drawn through
    /// `links`.
    pub fn show(&mut self, map: MapRef, links: sightline::wad::import::Links) {
        self.scene = sim::draw::Scene::new(links);
        self.shown = map;
    }
}

pub fn run(args: &ReplayArgs) -> Result<()> {
    let spec = args.demo.to_string_lossy();
    if args.audio.is_some() {
        bail!("{spec}: the sound of a Doom demo is not rendered yet: the simulation with Doom's arithmetic sends no sound to the mixer");
    }
    let source = open_demo(&spec, args.iwad.as_deref(), &args.file)?;
    let (map, _) = source.game()?;
    let wad = source.wad()?;
    let table = sim::demo::table_with_patches(&wad, ActorTable::active(), &args.deh).map_err(|e| anyhow!("{e}"))?;
    let sim = sim::demo::start_as(&wad, &source.demo, table, args.gameversion).map_err(|e| anyhow!("{spec}: {e}"))?;
    let mut game = DemoGame::new(std::sync::Arc::new(wad), sim);
    let reference = args.check_against.as_ref().map(|p| SyncDump::load(p)).transpose()?;
    let mut sync = reference.as_ref().map(SyncCheck::new);
    let mut frames = match (args.capture_every, args.timedemo) {
        (None, false) => None,
        _ => Some(Frames::open(&map, args)?),
    };
    let tics = source.demo.tics();
    let started = (std::time::Instant::now(), cpu_time::ProcessTime::now());
    if let Some(f) = &mut frames {
        f.tic(&game, 0, tics == 0)?;
    }
    let mut tic_ns = 0;
    for t in 0..tics {
        let tic_lap = Lap::start(args.profile);
        game.tick(&sim::demo::commands(&source.demo, t)).map_err(|e| anyhow!("{spec}: at tic {}: {e}", t + 1))?;
        tic_ns += tic_lap.ns();
        let diffs = match sync.as_mut().map(|s| s.tic(&game)) {
            None => Vec::new(),
            Some(Some(diffs)) => diffs,
            // The reference holds the level tics alone.
            Some(None) => bail!("{spec}: the reference ends before the demo's tic {} (a level tic)", t + 1),
        };
        if !diffs.is_empty() {
            let fields: Vec<String> = diffs.iter().map(|d| format!("\n  {d}")).collect();
            bail!("{spec}: in sync for {t} of {tics} tics; out of sync at tic {}:{}", t + 1, fields.concat());
        }
        if let Some(f) = &mut frames {
            f.tic(&game, t as u64 + 1, t + 1 == tics)?;
        }
    }
    if let Some(path) = &args.check_against {
        println!("{spec}: in sync for all {tics} tics with {}", path.display());
    }
    if let Some(f) = &frames {
        if args.timedemo {
            // Chocolate Doom's line: gametics over realtics (1/35 s each).
            let (wall, cpu) = (started.0.elapsed(), started.1.elapsed());
            let realtics = (wall.as_secs_f64() * 35.0).round().max(1.0) as u64;
            let frames = f.rendered.max(1) as f64;
            println!(
                "timed {tics} gametics in {realtics} realtics ({:.1} fps); {:.3} ms CPU, {:.3} ms wall per frame",
                tics as f64 * 35.0 / realtics as f64,
                cpu.as_secs_f64() * 1000.0 / frames,
                wall.as_secs_f64() * 1000.0 / frames
            );
            if args.profile {
                f.print_profile(tic_ns, tics);
            }
        }
        if f.written > 0 {
            println!("wrote {} frames to {}", f.written, f.dir.display());
        }
    }
    if args.json {
        println!("{}", final_json(&game.sim, tics));
    } else if !args.timedemo {
        let h = &source.demo.header;
        println!("{spec}: {} skill {}, {tics} tics played", game.sim.level.name, h.skill + 1);
    }
    Ok(())
}

/// Frames of the simulation: every `--capture-every`th tic and the last
/// written as PNGs,
/// or (`--timedemo`) every tic rendered and not kept.
struct Frames {
    /// The map drawn (the demo's level, or the one it went on to).
    map: MapRef,
    level: sightline::level::Level,
    scene: sim::draw::Scene,
    options: RenderOptions,
    frame: Frame,
    fb: Framebuffer,
    every: Option<u64>,
    dir: PathBuf,
    rendered: usize,
    written: usize,
    /// With `--profile`: the scene's updates from the game, and the
    /// renderer's parts, summed over the frames.
    scene_ns: u64,
    parts: Breakdown,
}

impl Frames {
    fn open(map: &MapRef, args: &ReplayArgs) -> Result<Frames> {
        let opened = sightline::campaign::open(map, &BuildOptions::default())?;
        let links = opened.links.unwrap_or_default();
        let renderer = crate::replay::choose_renderer(args.renderer, &opened.level, &map.label())?;
        let dir = args.output.clone().unwrap_or_default();
        if args.capture_every.is_some() {
            std::fs::create_dir_all(&dir).with_context(|| format!("{}: cannot create the directory", dir.display()))?;
        }
        Ok(Frames {
            map: map.clone(),
            level: opened.level,
            scene: sim::draw::Scene::new(links),
            options: RenderOptions { renderer, threads: args.threads, profile: args.profile, ..Default::default() },
            frame: Frame::new(),
            fb: Framebuffer::new(args.size.0, args.size.1),
            every: if args.timedemo { None } else { args.capture_every },
            dir,
            rendered: 0,
            written: 0,
            scene_ns: 0,
            parts: Breakdown::default(),
        })
    }

    /// Renders the state after `tic` tics, and writes it when it is one to
    /// keep (every `--capture-every`th, and the `last`).
    fn tic(&mut self, game: &DemoGame, tic: u64, last: bool) -> Result<()> {
        let keep = self.every.is_some_and(|every| tic.is_multiple_of(every) || last);
        if (self.every.is_some() && !keep) || !game.on_level() {
            return Ok(());
        }
        let game = &game.sim;
        if let Some(next) = moved_to(&self.map, &game.level.name) {
            // The demo went on to the next level: draw that one.
            let opened = sightline::campaign::open(&next, &BuildOptions::default())?;
            (self.map, self.level) = (next, opened.level);
            self.scene = sim::draw::Scene::new(opened.links.unwrap_or_default());
        }
        let Some(view) = self.scene.view(game) else { return Ok(()) };
        let scene_lap = Lap::start(self.options.profile);
        self.scene.draw(game, &mut self.level);
        self.scene_ns += scene_lap.ns();
        render_frame(&self.level, &view, &self.options, &mut self.frame, &mut self.fb);
        self.parts += self.frame.breakdown;
        self.rendered += 1;
        if keep {
            write_atomic(&self.dir.join(format!("tick-{tic:06}.png")), &self.fb.to_png())?;
            self.written += 1;
        }
        Ok(())
    }

    /// `--profile`'s lines: the mean per frame of the tic, the scene's
    /// update and each part of the renderer (with threads, summed over them).
    fn print_profile(&self, tic_ns: u64, tics: usize) {
        let frames = self.rendered.max(1) as f64;
        let ms = |ns: f64| ns / 1e6 / frames;
        let mut rows = vec![("tic", tic_ns as f64 * frames / tics.max(1) as f64), ("scene", self.scene_ns as f64)];
        rows.extend(self.parts.parts().iter().map(|&(name, ns)| (name, ns as f64)));
        let total: f64 = rows.iter().map(|r| r.1).sum::<f64>().max(1.0);
        println!("breakdown (mean per frame; the tic's time is per tic):");
        for (name, ns) in rows {
            println!("  {name:<8}{:>9.4} ms {:>5.1}%", ms(ns), ns / total * 100.0);
        }
    }
}

/// The WAD map a demo's game is on, `level`, when it is not `shown`.
fn moved_to(shown: &MapRef, level: &str) -> Option<MapRef> {
    let MapRef::Wad { map: Some(name), .. } = shown else { return None };
    (!name.eq_ignore_ascii_case(level)).then(|| shown.in_same_wads(level))
}

/// The game's state at the demo's end: the tics played, each player's
/// position (map units: the fixed-point values divided out; the angle in
/// degrees), health, armour and tallies, and the level's totals.
fn final_json(game: &Sim, tics: usize) -> serde_json::Value {
    let players: Vec<serde_json::Value> = game
        .players
        .iter()
        .enumerate()
        .filter_map(|(n, p)| p.as_ref().map(|p| (n, p)))
        .map(|(n, p)| {
            let mo = game.mo(p.mo);
            json!({
                "player": n,
                "x": mo.x.to_f64(), "y": mo.y.to_f64(), "z": mo.z.to_f64(), "angle": mo.angle.to_degrees(),
                "health": p.health, "armor": p.armorpoints,
                "kills": p.killcount, "items": p.itemcount, "secrets": p.secretcount,
            })
        })
        .collect();
    json!({
        "tics": tics,
        "players": players,
        "totals": { "kills": game.total_kills, "items": game.total_items, "secrets": game.total_secrets },
    })
}
