//! `sightline bench autopilot MAP...`: what the autopilot costs. For each
//! map, the same run (deterministic: the same ticks every time) twice: once
//! headless, once rendering every tick's frame at `--size` (no PNG); it
//! prints the navigation grid's build time, the goal choices (count, total,
//! worst), and ticks per second of each run, then the median and worst
//! planning time over the maps.

use std::time::Instant;

use anyhow::{Context, Result};
use sightline::autopilot;
use sightline::campaign::MapRef;
use sightline::play::playthrough::Playthrough;
use sightline::play::GameOptions;
use sightline::render::{render_frame, Frame, RenderOptions, Renderer};
use sightline::Framebuffer;

use crate::cli::BenchAutopilotArgs;

pub fn run(args: &BenchAutopilotArgs) -> Result<()> {
    let options = GameOptions { skill: args.skill, seed: 0, no_monsters: args.no_monsters };
    let mut planning = Vec::new();
    println!(
        "{:<28} {:>7} {:>9} {:>6} {:>9} {:>9} {:>7} {:>10} {:>10}",
        "map", "ticks", "grid ms", "plans", "plan ms", "worst ms", "exited", "tick/s off", "tick/s on"
    );
    for name in expand(&args.maps)? {
        let map = MapRef::parse(&name, None);
        let mut play = Playthrough::of(&map, options).with_context(|| format!("{name}: cannot start the game"))?;
        let started = Instant::now();
        let (outcome, bot) = autopilot::run(&mut play, args.ticks, |_, _| true)?;
        let off = started.elapsed().as_secs_f64();
        let ticks = outcome.inputs.len();
        let f = bot.figures();

        let mut again = Playthrough::of(&map, options)?;
        let render = RenderOptions {
            renderer: Renderer::default_for(again.game.level()),
            threads: args.threads,
            ..Default::default()
        };
        let mut frame = Frame::new();
        let mut fb = Framebuffer::new(args.size.0, args.size.1);
        let started = Instant::now();
        autopilot::run(&mut again, ticks as u64, |play, _| {
            render_frame(play.game.level(), &play.game.view(1.0), &render, &mut frame, &mut fb);
            true
        })?;
        let on = started.elapsed().as_secs_f64();

        let plan_ms = (f.grid_seconds + f.plan_seconds) * 1e3;
        planning.push(plan_ms);
        let short = name.rsplit('/').next().unwrap_or(&name).to_string();
        println!(
            "{:<28} {:>7} {:>9.1} {:>6} {:>9.1} {:>9.1} {:>7} {:>10.0} {:>10.0}",
            short,
            ticks,
            f.grid_seconds * 1e3,
            f.plans,
            f.plan_seconds * 1e3,
            f.worst_plan_seconds * 1e3,
            outcome.exit.is_some(),
            ticks as f64 / off,
            ticks as f64 / on
        );
        if args.json {
            let json = serde_json::json!({
                "map": name,
                "ticks": ticks,
                "grid_ms": f.grid_seconds * 1e3,
                "plans": f.plans,
                "plan_ms": f.plan_seconds * 1e3,
                "worst_plan_ms": f.worst_plan_seconds * 1e3,
                "exited": outcome.exit.is_some(),
                "ticks_per_second_render_off": ticks as f64 / off,
                "ticks_per_second_render_on": ticks as f64 / on,
                "size": format!("{}x{}", args.size.0, args.size.1),
            });
            println!("{json}");
        }
    }
    planning.sort_by(f64::total_cmp);
    if let (Some(worst), false) = (planning.last(), planning.is_empty()) {
        let median = planning[planning.len() / 2];
        println!(
            "planning (grid + goal choices) per map over {} maps: median {median:.0} ms, worst {worst:.0} ms",
            planning.len()
        );
    }
    Ok(())
}

/// `WAD:all` as every map of the WAD.
pub(super) fn expand(maps: &[String]) -> Result<Vec<String>> {
    let mut out = Vec::new();
    for m in maps {
        match m.strip_suffix(":all") {
            Some(wad) => {
                let w = sightline::wad::Wad::open(std::path::Path::new(wad))?;
                out.extend(w.map_names().into_iter().map(|n| format!("{wad}:{n}")));
            }
            None => out.push(m.clone()),
        }
    }
    Ok(out)
}
