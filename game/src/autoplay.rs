//! `sightline autoplay`: the autopilot plays a map headless, through the
//! same inputs a keyboard gives, until the exit or a tick limit, and says
//! how it went (text, or one JSON object). `--record` keeps the inputs as a
//! demo that `sightline replay` plays back to the same end.

use anyhow::{Context, Result};
use serde_json::json;
use sightline::autopilot::{self, Point};
use sightline::campaign::{ArtOptions, MapRef};
use sightline::play::playthrough::{Phase, Playthrough};
use sightline::play::{vanilla, Exit, GameOptions, Stats, TickInput, TICRATE};
use sightline::render::{RenderOptions, Renderer};
use sightline::sim::game::Setup;

use crate::cli::AutoplayArgs;
use crate::replay::Capture;

/// How a run ended, whichever game it was played on.
struct Run {
    /// The map it ended on (the last of `--levels`).
    map: MapRef,
    outcome: autopilot::Outcome,
    bot: autopilot::Autopilot,
    stats: Stats,
    health: i32,
    pos: Point,
    /// Frames written, and where.
    captured: Option<(usize, std::path::PathBuf)>,
}

pub fn run(args: &AutoplayArgs) -> Result<()> {
    if crate::scenario::is_cfg(&args.map) {
        return crate::scenario::autoplay(args);
    }
    let map = MapRef::parse(&args.map, args.iwad.as_deref());
    let options = GameOptions { skill: args.skill, seed: args.seed, no_monsters: args.no_monsters };
    let started = std::time::Instant::now();
    let run = play(args, &map, options)?;
    let seconds = started.elapsed().as_secs_f64();
    report(args, run, seconds);
    Ok(())
}

/// The autopilot on one level of a playthrough, capturing frames if asked.
fn play(args: &AutoplayArgs, map: &MapRef, options: GameOptions) -> Result<Run> {
    // A run that writes no frames looks up no sprite: a map may name any
    // actor with no art for it.
    let drawing = args.capture_every.is_some() && args.output.is_some();
    let wads = crate::capture::art_wads(map, args.iwad.as_deref());
    let art = if drawing { ArtOptions { wads, missing: None } } else { ArtOptions { wads, ..ArtOptions::none() } };
    let mut play = Playthrough::of_with(map, options, Setup::SINGLE, art)
        .with_context(|| format!("{}: cannot start the game", map.label()))?;
    if drawing {
        crate::capture::warn(&play.game.level().materials.warnings);
    }
    let first = play.map.clone();
    let mut capture = match (args.capture_every, &args.output) {
        (Some(every), Some(dir)) => {
            let renderer = Renderer::default_for(play.game.level());
            let render = RenderOptions { renderer, threads: args.threads, ..Default::default() };
            let mut c = Capture::new(every, dir, args.size, render)?;
            c.frame(&play, 0)?;
            Some(c)
        }
        _ => None,
    };
    let mut failed = None;
    let lmp = args.record.as_deref().is_some_and(crate::replay_lmp::is_lmp_path);
    let mut carry = 0.0;
    // Recording to a .lmp, the game is fed its inputs as the file keeps them.
    let mut as_kept = |input: TickInput| if lmp { vanilla::as_recorded(&input, &mut carry) } else { input };
    let mut inputs = Vec::new();
    let mut level = 1;
    let (outcome, bot) = loop {
        let before = inputs.len() as u64;
        let (outcome, bot) = autopilot::run_through(&mut play, args.max_ticks, &mut as_kept, |play, tick| {
            if let Some(c) = &mut capture {
                if (before + tick).is_multiple_of(c.every) && failed.is_none() {
                    failed = c.frame(play, before + tick).err();
                }
            }
            failed.is_none()
        })?;
        inputs.extend(outcome.inputs.iter().copied());
        if outcome.exit.is_none() || level == args.levels || failed.is_some() {
            break (outcome, bot);
        }
        println!("{}: exited after {} ticks", play.map.short_name(), outcome.inputs.len());
        // Through the intermission, pressing use every other tic as the
        // window's autopilot does; the next level loads on the tic after.
        while matches!(play.phase, Phase::Intermission { .. }) {
            let input = autopilot::press_on(inputs.len() as u64);
            play.tick(&input)?;
            inputs.push(input);
        }
        if play.phase != Phase::Playing {
            break (outcome, bot);
        }
        level += 1;
    };
    if let Some(e) = failed {
        return Err(e);
    }
    let ticks = inputs.len() as u64;
    if let Some(c) = &mut capture {
        if !ticks.is_multiple_of(c.every) {
            c.frame(&play, ticks)?;
        }
    }
    if let Some(path) = &args.record {
        // Doom completes a level at the start of the tic after the exit:
        // one more (idle) tic takes a demo's player to the intermission.
        if outcome.exit.is_some() && lmp {
            inputs.push(TickInput::default());
        }
        crate::replay_lmp::save_recording(path, &first, options, inputs)?;
    }
    let stats = match &play.phase {
        Phase::Intermission { stats, .. } | Phase::Finished { stats } => *stats,
        Phase::Playing => play.game.stats(),
    };
    let player = play.game.player();
    let captured = capture.map(|c| (c.written, c.dir.clone()));
    Ok(Run { map: play.map.clone(), outcome, bot, stats, health: player.health, pos: player.pos, captured })
}

fn report(args: &AutoplayArgs, run: Run, seconds: f64) {
    let Run { map, outcome, bot, stats, health, pos, captured } = run;
    if std::env::var_os("SIGHTLINE_AUTOPILOT_LOG").is_some() {
        for line in &bot.log {
            eprintln!("{line}");
        }
    }
    let ticks = outcome.inputs.len() as u64;
    let figures = bot.figures();
    let reason = match (&outcome.exit, outcome.died, &outcome.stuck) {
        (Some(_), _, _) => None,
        (None, true, _) => Some("died".to_string()),
        (None, false, Some((_, why))) => Some(format!("stuck: {why}")),
        (None, false, None) => Some(format!("out of time after {} ticks", args.max_ticks)),
    };
    if args.json {
        let pair = |p: (u32, u32)| json!({ "found": p.0, "total": p.1 });
        let value = json!({
            "map": map.label(),
            "skill": args.skill,
            "monsters": !args.no_monsters,
            "exited": outcome.exit.is_some(),
            "exit": outcome.exit.map(|e| if e == Exit::Secret { "secret" } else { "normal" }),
            "ticks": ticks,
            "game_seconds": ticks as f64 / f64::from(TICRATE),
            "kills": pair(stats.kills),
            "items": pair(stats.items),
            "secrets": pair(stats.secrets),
            "level_tics": stats.ticks,
            "health": health,
            "why_not": reason,
            "position": [pos.x, pos.y],
            "planning": {
                "grid_ms": figures.grid_seconds * 1e3,
                "plans": figures.plans,
                "plan_ms_total": figures.plan_seconds * 1e3,
                "plan_ms_worst": figures.worst_plan_seconds * 1e3,
            },
            "wall_seconds": seconds,
        });
        println!("{value}");
        return;
    }
    let (k, i, s) = (stats.kills, stats.items, stats.secrets);
    match outcome.exit {
        Some(e) => println!(
            "{}: exited ({}) after {ticks} ticks ({:.0} s of game time)",
            map.label(),
            if e == Exit::Secret { "secret exit" } else { "normal exit" },
            ticks as f64 / f64::from(TICRATE)
        ),
        None => {
            println!("{}: did not exit: {} (at {:.0}, {:.0})", map.label(), reason.unwrap_or_default(), pos.x, pos.y)
        }
    }
    println!("kills {}/{}, items {}/{}, secrets {}/{}, health {health}", k.0, k.1, i.0, i.1, s.0, s.1);
    println!(
        "planning: grid {:.0} ms, {} plans, {:.0} ms in all, worst {:.0} ms; {:.1} s of wall time",
        figures.grid_seconds * 1e3,
        figures.plans,
        figures.plan_seconds * 1e3,
        figures.worst_plan_seconds * 1e3,
        seconds
    );
    if let Some((written, dir)) = captured {
        println!("wrote {written} frames to {}", dir.display());
    }
}
