//! BSP construction: the randomized autopartition (several seeds) against
//! the split-minimizing heuristic and, on small maps, the exhaustive search
//! for the smallest autopartition: build time against tree size
//! (`sides_out`), depth, and the frame time each tree gives.

use rand::{RngExt, SeedableRng};

use super::{median_ms, Cell, Plot, Settings, Study, Table};
use crate::bsp::exhaustive::EXHAUSTIVE_LIMIT;
use crate::bsp::{build, BuildOptions, CompiledMap, SplitterKind};
use crate::level::Level;
use crate::map::source::{LineSource, MapSource, SectorSource, SideSource, ThingSource};
use crate::map::validate::validate;
use crate::map::Map;
use crate::render::{render_frame, Frame, RenderOptions, Shade};
use crate::tour::tour;
use crate::Framebuffer;

pub fn run(levels: &[(String, &Level)], s: &Settings, progress: &mut dyn FnMut(&str)) -> Study {
    let mut table = Table::new(
        "bsp",
        &["map", "splitter", "seed", "sides in", "sides out", "extra (%)", "depth", "nodes", "build ms", "ms/frame"],
    );
    let mut maps: Vec<(String, Map)> =
        (1..=s.effort.pick(3, 5)).map(|k| (format!("room+{k} pillars"), pillars(k, 7))).collect();
    maps.extend(levels.iter().filter(|(_, l)| l.grid().is_none()).map(|(n, l)| (n.clone(), l.map.clone())));
    let seeds = s.effort.pick(3, 8) as u64;
    for (name, map) in &maps {
        let mut runs: Vec<BuildOptions> = vec![BuildOptions { splitter: SplitterKind::Cost, seed: 0 }];
        runs.extend((0..seeds).map(|seed| BuildOptions { splitter: SplitterKind::Random, seed }));
        let sides: usize = map.lines.iter().map(|l| 1 + usize::from(l.back.is_some())).sum();
        if sides <= EXHAUSTIVE_LIMIT {
            runs.push(BuildOptions { splitter: SplitterKind::Exhaustive, seed: 0 });
        }
        // One tour for every run, from the first compile: a pose's sector
        // (its eye height) on a two-sided line comes from the tree.
        let Ok(first) = build(map, &runs[0]) else { continue };
        let views = tour(&first, s.effort.pick(4, 16), 2);
        for options in runs {
            progress(&format!("bsp: {name} {} {}", options.splitter.name(), options.seed));
            let mut compiled: Option<CompiledMap> = None;
            let build_ms = median_ms(s.effort.pick(1, 3), || compiled = build(map, &options).ok());
            let Some(compiled) = compiled else { continue };
            let level = Level::with_builtin_textures(compiled.clone());
            let Ok(level) = level else { continue };
            let (mut frame, mut fb) = (Frame::new(), Framebuffer::new(s.width, s.height));
            let render = RenderOptions { shade: Shade::Flat, ..Default::default() };
            let ms = median_ms(s.effort.pick(3, 5), || {
                for v in &views {
                    render_frame(&level, v, &render, &mut frame, &mut fb);
                }
            }) / views.len().max(1) as f64;
            let st = &compiled.stats;
            table.push(vec![
                Cell::from(name.as_str()),
                Cell::from(options.splitter.name()),
                Cell::from(options.seed as f64),
                Cell::from(st.sides_in),
                Cell::from(st.sides_out),
                Cell::from(100.0 * (st.sides_out as f64 / st.sides_in.max(1) as f64 - 1.0)),
                Cell::from(st.depth),
                Cell::from(st.nodes),
                Cell::from(build_ms),
                Cell::from(ms),
            ]);
        }
    }
    let plots = plots(&table);
    let conclusions = conclude(&table);
    Study {
        id: "bsp".into(),
        title: "BSP construction: random autopartition, split-minimizing, exhaustive".into(),
        method: format!(
            "Each sector map given, and small generated rooms with 1 to {} square pillars at seeded places (where \
             the exhaustive search, limited to {EXHAUSTIVE_LIMIT} sides, can run), is compiled by the cost \
             heuristic (splits weighted against balance), the randomized autopartition with seeds 0..{seeds}, and \
             the exhaustive search. Extra is sides out over sides in, less one. Build time is the median of \
             repeated builds; frame time the median per frame over a tour, flat shading, {}x{}.",
            s.effort.pick(3, 5),
            s.width,
            s.height
        ),
        tables: vec![table],
        plots,
        conclusions,
    }
}

fn plots(t: &Table) -> Vec<Plot> {
    let names = t.rows.iter().map(|r| text(&r[1])).collect::<Vec<_>>();
    let (extra, build_ms, frame) = (t.column("extra (%)"), t.column("build ms"), t.column("ms/frame"));
    let mut size_vs_time = Vec::new();
    let mut frame_vs_size = Vec::new();
    for splitter in ["cost", "random", "exhaustive"] {
        let rows: Vec<usize> = (0..names.len()).filter(|&i| names[i] == splitter).collect();
        size_vs_time.push((splitter.to_string(), rows.iter().map(|&i| (build_ms[i].max(1e-4), extra[i])).collect()));
        frame_vs_size.push((splitter.to_string(), rows.iter().map(|&i| (extra[i], frame[i])).collect()));
    }
    vec![
        Plot {
            name: "bsp-build-time-vs-size".into(),
            title: "BSP: build time against extra segs (each point a map and seed)".into(),
            x_label: "build ms".into(),
            y_label: "extra segs (%)".into(),
            log_x: true,
            log_y: false,
            series: size_vs_time,
        },
        Plot {
            name: "bsp-size-vs-frame".into(),
            title: "BSP: extra segs against frame time".into(),
            x_label: "extra segs (%)".into(),
            y_label: "ms per frame".into(),
            log_x: false,
            log_y: false,
            series: frame_vs_size,
        },
    ]
}

fn text(c: &Cell) -> String {
    match c {
        Cell::Text(t) => t.clone(),
        Cell::Number(x) => x.to_string(),
    }
}

fn conclude(t: &Table) -> Vec<String> {
    let maps: Vec<String> = t.rows.iter().map(|r| text(&r[0])).collect();
    let names: Vec<String> = t.rows.iter().map(|r| text(&r[1])).collect();
    let (extra, build_ms, frame, depth) =
        (t.column("extra (%)"), t.column("build ms"), t.column("ms/frame"), t.column("depth"));
    let mean = |f: &dyn Fn(usize) -> bool, v: &[f64]| {
        let rows: Vec<usize> = (0..v.len()).filter(|&i| f(i)).collect();
        rows.iter().map(|&i| v[i]).sum::<f64>() / rows.len().max(1) as f64
    };
    let mut out = Vec::new();
    let exhaustive_maps: Vec<&String> =
        maps.iter().zip(&names).filter(|(_, n)| *n == "exhaustive").map(|(m, _)| m).collect();
    if !exhaustive_maps.is_empty() {
        let on_small = |splitter: &str| mean(&|i| names[i] == splitter && exhaustive_maps.contains(&&maps[i]), &extra);
        out.push(format!(
            "On the maps small enough to search exhaustively, the smallest autopartition has {:.1}% extra segs; the cost \
             heuristic {:.1}%, the random autopartition {:.1}% (mean over seeds), and the search took {:.2} ms against \
             the heuristic's {:.3} ms.",
            on_small("exhaustive"),
            on_small("cost"),
            on_small("random"),
            mean(&|i| names[i] == "exhaustive", &build_ms),
            mean(&|i| names[i] == "cost" && exhaustive_maps.contains(&&maps[i]), &build_ms),
        ));
    }
    let big = |i: usize| !exhaustive_maps.contains(&&maps[i]);
    out.push(format!(
        "On the other maps: cost {:.1}% extra, depth {:.1}, {:.3} ms per frame; random {:.1}% extra, depth {:.1}, \
         {:.3} ms per frame. Fewer segs and a shallower tree make frames {}.",
        mean(&|i| names[i] == "cost" && big(i), &extra),
        mean(&|i| names[i] == "cost" && big(i), &depth),
        mean(&|i| names[i] == "cost" && big(i), &frame),
        mean(&|i| names[i] == "random" && big(i), &extra),
        mean(&|i| names[i] == "random" && big(i), &depth),
        mean(&|i| names[i] == "random" && big(i), &frame),
        if mean(&|i| names[i] == "cost" && big(i), &frame) <= mean(&|i| names[i] == "random" && big(i), &frame) {
            "faster here"
        } else {
            "no faster here (the walk's cost is dominated by what is drawn, not by the tree)"
        }
    ));
    out
}

/// A 512-unit square room with `k` 48-unit square pillars placed at seeded
/// spots of a 4x4 grid of slots, so they never touch.
pub(crate) fn pillars(k: usize, seed: u64) -> Map {
    let mut rng = rand::rngs::ChaCha8Rng::seed_from_u64(seed + k as u64);
    let mut vertices = vec![(0.0, 0.0), (0.0, 512.0), (512.0, 512.0), (512.0, 0.0)];
    let side = |sector| SideSource { sector, ..Default::default() };
    let line = |from: usize, to: usize| LineSource {
        from: from as i64,
        to: to as i64,
        front: side(0),
        ..LineSource::default()
    };
    let mut lines: Vec<LineSource> = (0..4).map(|i| line(i, (i + 1) % 4)).collect();
    let mut slots: Vec<usize> = (0..16).filter(|&s| s != 0).collect();
    for _ in 0..k.min(15) {
        let slot = slots.remove(rng.random_range(0..slots.len()));
        let (cx, cy) = (64.0 + 128.0 * (slot % 4) as f64, 64.0 + 128.0 * (slot / 4) as f64);
        // Jitter so partitions through pillar edges cut other pillars.
        let (cx, cy) = (cx + rng.random_range(-24.0..24.0f64).round(), cy + rng.random_range(-24.0..24.0f64).round());
        let n = vertices.len();
        // Counter-clockwise: a hole in the room.
        vertices.extend([
            (cx - 24.0, cy - 24.0),
            (cx + 24.0, cy - 24.0),
            (cx + 24.0, cy + 24.0),
            (cx - 24.0, cy + 24.0),
        ]);
        lines.extend((0..4).map(|i| line(n + i, n + (i + 1) % 4)));
    }
    let source = MapSource {
        name: format!("room with {k} pillars"),
        vertices,
        sectors: vec![SectorSource { floor: 0.0, ceiling: 128.0, light: 192, ..SectorSource::default() }],
        lines,
        things: vec![ThingSource::new(crate::map::PLAYER_START, 8.0, 8.0, 45.0)],
        ..MapSource::default()
    };
    // Built from fixed shapes in free slots: valid by construction.
    validate(&source).unwrap_or_else(|p| unreachable!("generated room is invalid: {p:?}"))
}
