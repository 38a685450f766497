//! Compile time per shipped map per splitter; prints each tree's sides_out and
//! depth beside the timings. Run: `cargo bench -p sightline-engine --bench compile`.

use std::time::Duration;

mod common;

use common::shipped_maps;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use sightline::bsp::{build, BuildOptions, SplitterKind};
use sightline::map::load_map;

fn compile(c: &mut Criterion) {
    let maps = shipped_maps();
    let mut group = c.benchmark_group("compile");
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    for path in maps {
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let map = load_map(&path).expect("shipped map loads");
        for splitter in SplitterKind::ALL {
            let options = BuildOptions { splitter, seed: 1 };
            let s = build(&map, &options).expect("compiles").stats;
            eprintln!(
                "{name:>10} {:>6}: sides_in {:>5} sides_out {:>5} splits {:>4} depth {:>3}",
                splitter.name(),
                s.sides_in,
                s.sides_out,
                s.splits,
                s.depth
            );
            group.bench_function(BenchmarkId::new(splitter.name(), &name), |b| b.iter(|| build(&map, &options)));
        }
    }
    group.finish();
}

criterion_group!(benches, compile);
criterion_main!(benches);
