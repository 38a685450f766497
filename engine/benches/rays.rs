//! What accuracy costs the ray-caster: the exact DDA against the fixed-step
//! march and sphere tracing at several step sizes and tolerances, and against
//! the BSP renderer, on one grid map at 320x200 and 1920x1080. Before timing,
//! each method's accuracy against the DDA over the same tour is printed
//! (wrong-face share, mean and maximum depth error).
//!
//! Run: `cargo bench -p sightline-engine --bench rays`.

use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use sightline::bsp::BuildOptions;
use sightline::level::open_level;
use sightline::render::raycast::RayMethod;
use sightline::render::rays::accuracy;
use sightline::render::{render_frame, Frame, RenderOptions, Renderer, Shade};
use sightline::tour::tour;
use sightline::Framebuffer;

/// The methods measured, with the cell size `s` of the map.
pub fn methods(s: f64) -> Vec<RayMethod> {
    let mut m = vec![RayMethod::Dda];
    m.extend([0.01, 0.05, 0.25, 1.0].map(|k| RayMethod::March { step: k * s }));
    m.extend([1e-4, 1e-2, 0.1, 0.5].map(|e| RayMethod::Sphere { epsilon: e * s }));
    m
}

fn rays(c: &mut Criterion) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../maps/gridmaze.ron");
    let level = open_level(&path, &BuildOptions::default()).expect("shipped map loads");
    let s = level.grid().expect("a grid map").0.cell_size;
    let views = tour(&level, 8, 1);
    let mut group = c.benchmark_group("rays/gridmaze");
    group.sample_size(10).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
    group.throughput(Throughput::Elements(views.len() as u64));
    for (w, h) in [(320, 200), (1920, 1080)] {
        println!(
            "accuracy at {w}x{h} over {} views: method, wrong share, mean error, max error, steps/column",
            views.len()
        );
        for method in methods(s) {
            let a = accuracy(&level, &views, w, method);
            println!(
                "  {:<14} {:.4} {:.4} {:.4} {:.1}",
                method.name(),
                a.wrong_share(),
                a.mean_error,
                a.max_error,
                a.steps_per_column
            );
        }
        let runs = methods(s).into_iter().map(|m| (Renderer::Raycast, m)).chain([(Renderer::Bsp, RayMethod::Dda)]);
        for (renderer, ray) in runs {
            let options = RenderOptions { renderer, shade: Shade::Flat, ray, ..Default::default() };
            let mut fb = Framebuffer::new(w, h);
            let mut frame = Frame::new();
            let name = if renderer == Renderer::Bsp { "bsp".to_string() } else { ray.name() };
            group.bench_function(BenchmarkId::new(name, format!("{w}x{h}")), |b| {
                b.iter(|| {
                    for v in &views {
                        render_frame(&level, v, &options, &mut frame, &mut fb);
                    }
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, rays);
criterion_main!(benches);
