//! `sightline bench check MAP...`: what `sightline check MAP -o plan.png`
//! costs, map by map: loading the map (the BSP built as `check` builds
//! it), the report (the closure and every question put to it), and the
//! route drawn, then the median and worst total over the maps. One thread
//! throughout, as `check` runs. Beside the wall-clock total, the CPU time
//! of the thread (Linux's `/proc/thread-self/schedstat`): on a machine
//! shared with other work the wall clock counts the waits for a core too.

use std::time::Instant;

use anyhow::{Context, Result};
use sightline::autopilot::check::{self, RouteFrom};
use sightline::bsp::BuildOptions;
use sightline::campaign::{open_with, ArtOptions, MapRef};

use crate::cli::BenchCheckArgs;

pub fn run(args: &BenchCheckArgs) -> Result<()> {
    let from = if args.bot_route { RouteFrom::Autopilot } else { RouteFrom::Closure };
    println!(
        "{:<28} {:>8} {:>10} {:>9} {:>9} {:>7} {:>6} {:>7}",
        "map", "load s", "report s", "route s", "total s", "cpu s", "exit", "stops"
    );
    let mut totals = Vec::new();
    let mut cpus = Vec::new();
    for name in super::autopilot::expand(&args.maps)? {
        let map = MapRef::parse(&name, None);
        let art = ArtOptions { wads: crate::capture::art_wads(&map, None), ..ArtOptions::none() };
        let started = Instant::now();
        let cpu_started = cpu_seconds();
        let level = open_with(&map, &BuildOptions::default(), &art)
            .with_context(|| format!("{}: does not load", map.label()))?
            .level;
        let load = started.elapsed().as_secs_f64();
        let (report, drawing) = check::check_with(level, args.skill, from);
        // The picture too, as `check -o` draws it.
        let fb = drawing.draw(1400, false);
        let total = started.elapsed().as_secs_f64();
        let cpu = cpu_seconds().zip(cpu_started).map(|(b, a)| b - a);
        totals.push(total);
        cpus.extend(cpu);
        let t = drawing.timing;
        let short = name.rsplit('/').next().unwrap_or(&name).to_string();
        println!(
            "{:<28} {:>8.2} {:>10.2} {:>9.2} {:>9.2} {:>7} {:>6} {:>7}",
            short,
            load,
            t.analyse,
            t.route,
            total,
            cpu.map_or("-".to_string(), |c| format!("{c:.2}")),
            report.exit_reachable,
            drawing.route.stops.len()
        );
        if args.json {
            let json = serde_json::json!({
                "map": name,
                "load_s": load,
                "report_s": t.analyse,
                "route_s": t.route,
                "total_s": total,
                "cpu_s": cpu,
                "exit_reachable": report.exit_reachable,
                "route": if args.bot_route { "autopilot" } else { "closure" },
                "route_points": drawing.route.points.len(),
                "route_stops": drawing.route.stops.len(),
                "route_missed": drawing.route.missed,
                "plan_pixels": fb.width * fb.height,
            });
            println!("{json}");
        }
    }
    if let Some((median, worst)) = median_worst(&mut totals) {
        println!("check per map over {} maps: median {median:.2} s, worst {worst:.2} s", totals.len());
    }
    if let Some((median, worst)) = median_worst(&mut cpus) {
        println!("CPU time per map over {} maps: median {median:.2} s, worst {worst:.2} s", cpus.len());
    }
    Ok(())
}

fn median_worst(v: &mut [f64]) -> Option<(f64, f64)> {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    let median = match n {
        0 => return None,
        _ if n % 2 == 1 => v[n / 2],
        _ => (v[n / 2 - 1] + v[n / 2]) / 2.0,
    };
    Some((median, v[n - 1]))
}

/// This thread's CPU time so far, where Linux tells it.
fn cpu_seconds() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = text.split_whitespace().next()?.parse().ok()?;
    Some(ns / 1e9)
}
