//! `sightline bench check MAP...`: what `sightline check MAP -o plan.png`
//! costs, map by map: loading the map (the BSP built as `check` builds
//! it), the report (the closure and every question put to it), and the
//! route drawn, then the median and worst total over the maps. One thread
//! throughout, as `check` runs.

use std::time::Instant;

use anyhow::{Context, Result};
use sightline::autopilot::check::{self, RouteFrom};
use sightline::bsp::BuildOptions;
use sightline::campaign::{open_with, ArtOptions, MapRef};

use crate::cli::BenchCheckArgs;

pub fn run(args: &BenchCheckArgs) -> Result<()> {
    let from = if args.bot_route { RouteFrom::Autopilot } else { RouteFrom::Closure };
    println!(
        "{:<28} {:>8} {:>10} {:>9} {:>9} {:>6} {:>7}",
        "map", "load s", "report s", "route s", "total s", "exit", "stops"
    );
    let mut totals = Vec::new();
    for name in super::autopilot::expand(&args.maps)? {
        let map = MapRef::parse(&name, None);
        let art = ArtOptions { wads: crate::capture::art_wads(&map, None), ..ArtOptions::none() };
        let started = Instant::now();
        let level = open_with(&map, &BuildOptions::default(), &art)
            .with_context(|| format!("{}: does not load", map.label()))?
            .level;
        let load = started.elapsed().as_secs_f64();
        let (report, drawing) = check::check_with(level, args.skill, from);
        // The picture too, as `check -o` draws it.
        let fb = drawing.draw(1400, false);
        let total = started.elapsed().as_secs_f64();
        totals.push(total);
        let t = drawing.timing;
        let short = name.rsplit('/').next().unwrap_or(&name).to_string();
        println!(
            "{:<28} {:>8.2} {:>10.2} {:>9.2} {:>9.2} {:>6} {:>7}",
            short,
            load,
            t.analyse,
            t.route,
            total,
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
    totals.sort_by(f64::total_cmp);
    if let Some(&worst) = totals.last() {
        let median = if totals.len() % 2 == 1 {
            totals[totals.len() / 2]
        } else {
            (totals[totals.len() / 2 - 1] + totals[totals.len() / 2]) / 2.0
        };
        println!("check per map over {} maps: median {median:.2} s, worst {worst:.2} s", totals.len());
    }
    Ok(())
}
