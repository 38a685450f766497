//! Compile time per map per splitter: every shipped map, and one Freedoom map
//! (freedoom1's E1M5, its largest: 9,800 sides) imported from the WAD; the
//! exhaustive splitter only on maps it accepts. Prints each tree's sides_out
//! and depth beside the timings. Run:
//! `cargo bench -p sightline-engine --bench compile`. The Freedoom bench
//! needs freedoom1.wad (Debian: freedoom) in `/usr/share/games/doom` or in
//! `$SIGHTLINE_DOOM_DIR`, as tests/freedoom.rs does, and fails if it is missing.

use std::path::PathBuf;
use std::time::Duration;

mod common;

use common::shipped_maps;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use sightline::bsp::exhaustive::EXHAUSTIVE_LIMIT;
use sightline::bsp::{build, BuildOptions, SplitterKind};
use sightline::map::load_map;
use sightline::map::validate::validate;
use sightline::wad::import::{convert, Art};
use sightline::wad::Wad;
use sightline::Map;

const FREEDOOM_MAP: &str = "E1M5";

fn compile(c: &mut Criterion) {
    let mut maps: Vec<(String, Map)> = shipped_maps()
        .into_iter()
        .map(|path| {
            (path.file_stem().unwrap().to_string_lossy().to_string(), load_map(&path).expect("shipped map loads"))
        })
        .collect();
    maps.push((format!("freedoom1-{}", FREEDOOM_MAP.to_lowercase()), freedoom_map()));
    let mut group = c.benchmark_group("compile");
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    for (name, map) in &maps {
        let sides: usize = map.lines.iter().map(|l| 1 + l.back.is_some() as usize).sum();
        for splitter in SplitterKind::ALL {
            if splitter == SplitterKind::Exhaustive && sides > EXHAUSTIVE_LIMIT {
                continue;
            }
            let options = BuildOptions { splitter, seed: 1 };
            let s = build(map, &options).expect("compiles").stats;
            eprintln!(
                "{name:>16} {:>6}: sides_in {:>5} sides_out {:>5} splits {:>4} depth {:>3}",
                splitter.name(),
                s.sides_in,
                s.sides_out,
                s.splits,
                s.depth
            );
            group.bench_function(BenchmarkId::new(splitter.name(), name), |b| b.iter(|| build(map, &options)));
        }
    }
    group.finish();
}

/// Freedoom's E1M5, imported as `sightline import` does.
fn freedoom_map() -> Map {
    let dir =
        std::env::var_os("SIGHTLINE_DOOM_DIR").map_or_else(|| PathBuf::from("/usr/share/games/doom"), PathBuf::from);
    let path = dir.join("freedoom1.wad");
    let wad = Wad::open(&path).unwrap_or_else(|e| {
        panic!("{e}\nthe compile bench needs Freedoom (apt-get install freedoom) or SIGHTLINE_DOOM_DIR=dir")
    });
    let art = Art::read(&wad).unwrap_or_else(|e| panic!("{e}"));
    let raw = wad.map(FREEDOOM_MAP).unwrap_or_else(|e| panic!("{e}"));
    let converted = convert(&wad, &raw, &art).unwrap_or_else(|e| panic!("{e}"));
    validate(&converted.source).unwrap_or_else(|problems| panic!("{}: {problems:?}", path.display()))
}

criterion_group!(benches, compile);
criterion_main!(benches);
