//! Sector rendering: frame time per showcase map, horizontal spans against
//! per-column floors, and each effect on against off, including effects a
//! map does not use (they must cost nothing). Textured shading, one thread,
//! a fixed tour of 16 poses per iteration.
//! Run: `cargo bench -p sightline-engine --bench sectors`.

use std::path::PathBuf;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkGroup, Criterion, Throughput};
use sightline::bsp::BuildOptions;
use sightline::level::{open_level, Level};
use sightline::render::plan::Disabled;
use sightline::render::{render_frame, Floors, Frame, RenderOptions, View};
use sightline::tour::tour;
use sightline::Framebuffer;

const SHOWCASE: [&str; 3] = ["stairs", "courtyard", "hall"];

fn level(name: &str) -> Level {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("../maps/{name}.ron"));
    open_level(&path, &BuildOptions::default()).expect("shipped map loads")
}

fn bench_tour(
    group: &mut BenchmarkGroup<criterion::measurement::WallTime>,
    id: String,
    level: &Level,
    views: &[View],
    (w, h): (usize, usize),
    options: RenderOptions,
) {
    let mut fb = Framebuffer::new(w, h);
    let mut frame = Frame::new();
    group.bench_function(id, |b| {
        b.iter(|| {
            for v in views {
                render_frame(level, v, &options, &mut frame, &mut fb);
            }
        })
    });
}

fn configure<'a>(c: &'a mut Criterion, name: &str) -> BenchmarkGroup<'a, criterion::measurement::WallTime> {
    let mut group = c.benchmark_group(name);
    group.sample_size(10).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
    group.throughput(Throughput::Elements(16));
    group
}

fn frames(c: &mut Criterion) {
    let mut group = configure(c, "showcase");
    for name in SHOWCASE {
        let level = level(name);
        let views = tour(&level, 8, 1);
        for size in [(320, 200), (1920, 1080)] {
            bench_tour(&mut group, format!("{name}/{}x{}", size.0, size.1), &level, &views, size, Default::default());
        }
    }
    group.finish();
}

fn floors(c: &mut Criterion) {
    let mut group = configure(c, "floors");
    for name in ["hall", "courtyard"] {
        let level = level(name);
        let views = tour(&level, 8, 1);
        for (label, floors) in [("spans", Floors::Spans), ("columns", Floors::Columns)] {
            let options = RenderOptions { floors, ..Default::default() };
            bench_tour(&mut group, format!("{name}/{label}"), &level, &views, (1920, 1080), options);
        }
    }
    group.finish();
}

fn effects(c: &mut Criterion) {
    let mut group = configure(c, "effects");
    let off = |f: fn(&mut Disabled)| {
        let mut d = Disabled::default();
        f(&mut d);
        d
    };
    let switches: [(&str, Disabled); 5] = [
        ("sky", off(|d| d.sky = true)),
        ("sprites", off(|d| d.sprites = true)),
        ("masked", off(|d| d.masked = true)),
        ("diminishing", off(|d| d.diminishing = true)),
        ("fog", off(|d| d.fog = true)),
    ];
    for name in ["room", "hall", "courtyard"] {
        let level = level(name);
        let views = tour(&level, 8, 1);
        bench_tour(&mut group, format!("{name}/all-available"), &level, &views, (640, 400), Default::default());
        for (effect, disabled) in switches {
            let options = RenderOptions { disabled, ..Default::default() };
            bench_tour(&mut group, format!("{name}/without-{effect}"), &level, &views, (640, 400), options);
        }
        // Once more at the end: the first run of a group tends to be slower.
        bench_tour(&mut group, format!("{name}/all-available-again"), &level, &views, (640, 400), Default::default());
    }
    group.finish();
}

criterion_group!(benches, frames, floors, effects);
criterion_main!(benches);
