//! `sightline bench tour MAP`: the frame time of one map over its things tour
//! (`sightline::tour::things_tour`: the player start, then every thing's
//! position looking eight ways). One untimed pass warms caches and the
//! allocations; then every frame of `--repeat` passes is timed on its own,
//! `render_frame` only (no PNG, no window). Then one more pass with the
//! renderer's stopwatches on gives the breakdown: the mean time per frame of
//! each part (set-up, walk, wall columns, spans, masked, copy-out). Prints a
//! short table, and with `--json` one JSON object as the last line of stdout.
//! `--buffers off,depth,labels,both` times the depth and label buffers'
//! cost: each variant a pass in turn, reported one after another.

use std::time::{Duration, Instant};

use anyhow::{bail, Result};
use sightline::bsp::BuildOptions;
use sightline::campaign::{open, MapRef};
use sightline::play::DEFAULT_SKILL;
use sightline::render::{render_frame, Breakdown, Buffers, Frame, RenderOptions, View};
use sightline::tour::things_tour;
use sightline::Framebuffer;

use crate::cli::BenchTourArgs;

/// Without `--repeat`, passes enough to time about this long.
const TARGET: Duration = Duration::from_secs(3);
/// ... but at least this many passes and at most this many frames.
const MIN_PASSES: usize = 3;
const MAX_FRAMES: usize = 200_000;

pub fn run(args: &BenchTourArgs) -> Result<()> {
    let map = MapRef::parse(&args.map, args.iwad.as_deref());
    let mut level = open(&map, &BuildOptions::default())?.level;
    // The things a game at the middle skill shows, as the player would meet them.
    level.show_skill(DEFAULT_SKILL);
    let renderer = crate::replay::choose_renderer(args.renderer, &level, &args.map)?;
    let views = things_tour(&level);
    if views.is_empty() {
        bail!("{}: no pose of the tour lies inside a sector", args.map);
    }
    let (width, height) = args.size;
    let variants: Vec<Buffers> = if args.buffers.is_empty() { vec![Buffers::default()] } else { args.buffers.clone() };
    let options = |buffers| RenderOptions { renderer, threads: args.threads, buffers, ..Default::default() };
    let mut frame = Frame::new();
    let mut fb = Framebuffer::new(width, height);
    let mut render = |view: &View, options: &RenderOptions| {
        let start = Instant::now();
        render_frame(&level, view, options, &mut frame, &mut fb);
        start.elapsed()
    };

    let mut warm_up = Duration::ZERO;
    for &buffers in &variants {
        warm_up += views.iter().map(|v| render(v, &options(buffers))).sum::<Duration>();
    }
    let passes = args.repeat.map(|n| n as usize).unwrap_or_else(|| {
        let per_pass = warm_up.as_secs_f64().max(1e-6);
        let fit = (TARGET.as_secs_f64() / per_pass).ceil() as usize;
        fit.clamp(MIN_PASSES, (MAX_FRAMES / views.len()).max(1))
    });
    // A pass of each variant in turn, so that a busy spell of the machine
    // falls on all of them alike.
    let mut times: Vec<Vec<Duration>> = variants.iter().map(|_| Vec::with_capacity(passes * views.len())).collect();
    for _ in 0..passes {
        for (&buffers, times) in variants.iter().zip(&mut times) {
            let options = options(buffers);
            times.extend(views.iter().map(|v| render(v, &options)));
        }
    }

    // The breakdown's own pass per variant: the stopwatches cost a little,
    // so its frames are not among the timed ones.
    let mut reports = Vec::new();
    for (&buffers, times) in variants.iter().zip(&mut times) {
        let profiled = RenderOptions { profile: true, ..options(buffers) };
        let mut parts = Breakdown::default();
        let profile_start = Instant::now();
        for view in &views {
            render_frame(&level, view, &profiled, &mut frame, &mut fb);
            parts += frame.breakdown;
        }
        let profiled_ms = profile_start.elapsed().as_secs_f64() * 1000.0 / views.len() as f64;
        reports.push(Report { buffers, summary: Summary::of(times), parts, profiled_ms });
    }
    let part_ms = |ns: u64| ns as f64 / 1e6 / views.len() as f64;

    let size = format!("{width}x{height}");
    println!("map       {} ({} poses x {passes} passes)", args.map, views.len());
    println!("renderer  {} at {size}, {} thread(s)", renderer.name(), args.threads);
    for report in &reports {
        let (summary, parts) = (&report.summary, &report.parts);
        if variants.len() > 1 || report.buffers.any() {
            println!("buffers   {}", report.buffers.name());
        }
        println!("frames    {}", summary.frames);
        println!("median    {:.4} ms ({:.0} fps)", summary.median_ms, summary.fps_median());
        println!("p95       {:.4} ms", summary.p95_ms);
        println!("mean      {:.4} ms", summary.mean_ms);
        println!(
            "breakdown (one profiled pass, mean per frame, {:.4} ms a frame with the stopwatches; \
             with threads, summed over them):",
            report.profiled_ms
        );
        let total = parts.total().max(1) as f64;
        for (name, ns) in parts.parts() {
            println!("  {name:<8}{:>9.4} ms {:>5.1}%", part_ms(ns), ns as f64 / total * 100.0);
        }
    }
    if args.json {
        let figures = |report: &Report| {
            let breakdown: serde_json::Map<String, serde_json::Value> =
                report.parts.parts().iter().map(|&(name, ns)| (format!("{name}_ms"), part_ms(ns).into())).collect();
            serde_json::json!({
                "buffers": report.buffers.name(),
                "frames": report.summary.frames,
                "median_ms": report.summary.median_ms,
                "p95_ms": report.summary.p95_ms,
                "mean_ms": report.summary.mean_ms,
                "fps_median": report.summary.fps_median(),
                "breakdown": breakdown,
                "profiled_mean_ms": report.profiled_ms,
            })
        };
        // The first variant's figures at the top level, as before `--buffers`.
        let mut json = figures(&reports[0]);
        if let Some(object) = json.as_object_mut() {
            object.insert("map".into(), args.map.to_string().into());
            object.insert("size".into(), size.into());
            object.insert("renderer".into(), renderer.name().into());
            object.insert("threads".into(), args.threads.into());
            object.insert("passes".into(), passes.into());
            if reports.len() > 1 {
                object.insert("variants".into(), reports.iter().map(figures).collect::<Vec<_>>().into());
            }
        }
        println!("{json}");
    }
    Ok(())
}

/// One variant's timings and breakdown.
struct Report {
    buffers: Buffers,
    summary: Summary,
    parts: Breakdown,
    profiled_ms: f64,
}

/// Order statistics of the frame times.
#[derive(Debug, PartialEq)]
struct Summary {
    frames: usize,
    median_ms: f64,
    p95_ms: f64,
    mean_ms: f64,
}

impl Summary {
    /// Sorts `times` in place. The median of an even count is the mean of
    /// the middle two; p95 is the nearest-rank value (the smallest time at or
    /// above 95% of the frames).
    fn of(times: &mut [Duration]) -> Summary {
        times.sort_unstable();
        let ms = |d: Duration| d.as_secs_f64() * 1000.0;
        let n = times.len();
        if n == 0 {
            return Summary { frames: 0, median_ms: f64::NAN, p95_ms: f64::NAN, mean_ms: f64::NAN };
        }
        let median =
            if n.is_multiple_of(2) { (ms(times[n / 2 - 1]) + ms(times[n / 2])) / 2.0 } else { ms(times[n / 2]) };
        let rank = (n * 95).div_ceil(100).max(1);
        let mean = times.iter().map(|&d| ms(d)).sum::<f64>() / n as f64;
        Summary { frames: n, median_ms: median, p95_ms: ms(times[rank - 1]), mean_ms: mean }
    }

    fn fps_median(&self) -> f64 {
        1000.0 / self.median_ms
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn order_statistics() {
        let mut times: Vec<Duration> = (1..=20).rev().map(Duration::from_millis).collect();
        let s = Summary::of(&mut times);
        assert_eq!((s.frames, s.median_ms, s.p95_ms, s.mean_ms), (20, 10.5, 19.0, 10.5));
        let mut one = [Duration::from_millis(4)];
        assert_eq!(Summary::of(&mut one).p95_ms, 4.0);
        assert!(Summary::of(&mut []).median_ms.is_nan());
    }
}
