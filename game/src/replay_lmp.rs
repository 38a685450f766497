//! `sightline replay` on Doom's own demos: a `.lmp` file (with `--iwad`) or
//! a demo lump inside a WAD (`freedoom1.wad:DEMO1`). The console player's
//! commands drive the game tic by tic; `--check-against DUMP` compares each
//! tic with a reference dump from Chocolate Doom and stops at the first tic
//! that differs, naming the fields; `--json` ends with the game's state.

use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};
use serde_json::json;
use sightline::campaign::MapRef;
use sightline::play::demo::Demo;
use sightline::play::lmp::VanillaDemo;
use sightline::play::playthrough::Playthrough;
use sightline::play::syncdump::{compare, not_compared, SyncDump};
use sightline::play::vanilla::{demo_of, input_of, open_demo, state_of};
use sightline::play::{GameOptions, TickInput};

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
    let ticks = inputs.len();
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
    println!("recorded {ticks} ticks to {}", path.display());
    Ok(())
}

/// A Doom demo as our own form (its map, options and the console player's
/// inputs), for the window to play.
pub fn as_demo(spec: &str, iwad: Option<&Path>) -> Result<Demo> {
    let source = open_demo(spec, iwad, &[])?;
    let (map, options) = source.game()?;
    let inputs = console_inputs(&source.demo).map_err(|e| anyhow!("{spec}: {e}"))?;
    Ok(Demo { inputs, skill: options.skill, seed: 0, no_monsters: options.no_monsters, ..Demo::new(map.label()) })
}

/// The commands of the player whose view the demo shows, as our inputs;
/// an error for a demo of several players.
fn console_inputs(demo: &VanillaDemo) -> Result<Vec<TickInput>> {
    let players = demo.header.players();
    if players > 1 {
        bail!("a {players}-player demo: the simulation has one player so far (ARCHITECTURE.md, \"Vanilla demos\")");
    }
    Ok((0..demo.tics()).map(|t| input_of(&demo.tic(t)[0])).collect())
}

pub fn run(args: &ReplayArgs) -> Result<()> {
    let spec = args.demo.to_string_lossy();
    let source = open_demo(&spec, args.iwad.as_deref(), &args.file)?;
    let header = &source.demo.header;
    let inputs = console_inputs(&source.demo).map_err(|e| anyhow!("{spec}: {e}"))?;
    let (map, options) = source.game()?;
    let reference = args.check_against.as_ref().map(|p| SyncDump::load(p)).transpose()?;
    let mut play = Playthrough::of(&map, options).with_context(|| format!("{}: cannot start the game", map.label()))?;
    let tics = inputs.len();
    for (t, input) in inputs.iter().enumerate() {
        play.tick(input)?;
        if let Some(dump) = &reference {
            let Some(theirs) = dump.tics.get(t) else {
                bail!("{spec}: the reference has {} tics, the demo {tics}", dump.tics.len());
            };
            let ours = state_of(&play, theirs.gametic);
            let diffs = compare(&ours, theirs);
            if !diffs.is_empty() {
                let fields: Vec<String> = diffs.iter().map(|d| format!("\n  {d}")).collect();
                bail!(
                    "{spec}: in sync for {t} of {tics} tics; out of sync at tic {} (gametic {}):{}",
                    t + 1,
                    theirs.gametic,
                    fields.concat()
                );
            }
            if t + 1 == tics {
                let left_out = not_compared(&ours, theirs);
                println!("{spec}: in sync for all {tics} tics (not compared: {})", list(&left_out));
            }
        }
    }
    if args.json {
        println!("{}", final_json(&play, tics));
    } else {
        let wad = source.wads.last().map_or_else(String::new, |w| w.display().to_string());
        println!("{spec}: {} on {wad} skill {}, {tics} tics played", map.short_name(), header.skill + 1);
        println!("{}", crate::replay::position_line(&play));
    }
    Ok(())
}

fn list(names: &[&str]) -> String {
    if names.is_empty() {
        "nothing".into()
    } else {
        names.join(", ")
    }
}

/// The game's state at the demo's end: the tics played, the player's
/// position (map units, the angle in degrees), tallies and the level's totals.
fn final_json(play: &Playthrough, tics: usize) -> serde_json::Value {
    let p = play.game.player();
    let stats = play.game.stats();
    json!({
        "tics": tics,
        "players": [{
            "x": p.pos.x, "y": p.pos.y, "z": p.z, "angle": p.angle,
            "health": p.health, "armor": p.armor,
            "kills": stats.kills.0, "items": stats.items.0, "secrets": stats.secrets.0,
        }],
        "totals": { "kills": stats.kills.1, "items": stats.items.1, "secrets": stats.secrets.1 },
    })
}
