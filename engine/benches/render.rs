//! Frame time per shipped map over a fixed tour, bsp against reference, at
//! 320x200 and 1920x1080. Run: `cargo bench -p sightline-engine --bench render`.

use std::time::Duration;

mod common;

use common::shipped_maps;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use sightline::bsp::BuildOptions;
use sightline::level::open_level;
use sightline::render::{render_frame, Frame, RenderOptions, Renderer, Shade};
use sightline::tour::tour;
use sightline::Framebuffer;

fn frames(c: &mut Criterion) {
    for path in shipped_maps() {
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let level = open_level(&path, &BuildOptions::default()).expect("shipped map loads");
        let views = tour(&level, 8, 1);
        let mut group = c.benchmark_group(format!("frame/{name}"));
        group.sample_size(10).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
        group.throughput(Throughput::Elements(views.len() as u64));
        for (w, h) in [(320, 200), (1920, 1080)] {
            for renderer in Renderer::ALL.into_iter().filter(|r| r.supports(&level)) {
                let options = RenderOptions { renderer, shade: Shade::Flat, count_writes: false, ..Default::default() };
                let mut fb = Framebuffer::new(w, h);
                let mut frame = Frame::new();
                let id = BenchmarkId::new(renderer.name(), format!("{w}x{h}"));
                group.bench_function(id, |b| {
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
}

criterion_group!(benches, frames);
criterion_main!(benches);
