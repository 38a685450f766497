//! Renders a map's tour repeatedly, for profilers:
//! `cargo run --release -p sightline-engine --example profile_frame -- MAP WxH RENDERER SECONDS`.
use std::time::{Duration, Instant};

use sightline::bsp::BuildOptions;
use sightline::level::open_level;
use sightline::render::{render_frame, Frame, RenderOptions, Renderer};
use sightline::tour::tour;
use sightline::Framebuffer;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() < 5 {
        eprintln!("usage: profile_frame MAP WxH bsp|reference SECONDS");
        std::process::exit(2);
    }
    let level = open_level(std::path::Path::new(&args[1]), &BuildOptions::default()).unwrap_or_else(|e| {
        eprintln!("{e}");
        std::process::exit(1)
    });
    let (w, h) = args[2]
        .split_once('x')
        .map(|(w, h)| (w.parse().unwrap_or(640), h.parse().unwrap_or(400)))
        .unwrap_or((640, 400));
    let renderer = Renderer::from_name(&args[3]).unwrap_or_default();
    let seconds: f64 = args[4].parse().unwrap_or(5.0);
    let views = tour(&level, 8, 1);
    let options = RenderOptions { renderer, ..Default::default() };
    let (mut fb, mut frame) = (Framebuffer::new(w, h), Frame::new());
    let start = Instant::now();
    let mut frames = 0u64;
    while start.elapsed() < Duration::from_secs_f64(seconds) {
        for v in &views {
            render_frame(&level, v, &options, &mut frame, &mut fb);
            frames += 1;
        }
    }
    println!("{frames} frames, {:.3} ms per frame", start.elapsed().as_secs_f64() * 1e3 / frames as f64);
}
