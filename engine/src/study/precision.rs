//! Precision: the BSP walk's visibility decisions in f64 and f32, on map
//! coordinates as they are or relative to the eye, with the whole map moved
//! from the origin out to 10,000,000 units: where each stops agreeing with
//! the exact answer, and what each costs (see [`crate::render::precision`]).

use glam::DVec2;

use super::{median_ms, Cell, Plot, Settings, Study, Table};
use crate::bsp::{build, BuildOptions, CompiledMap};
use crate::geom::MAX_COORD;
use crate::level::Level;
use crate::render::precision::{agreeing, exact_walls, walls, Numbers};
use crate::tour::tour;

const OFFSETS: [f64; 6] = [0.0, 1e3, 1e4, 1e5, 1e6, 1e7];

pub fn run(levels: &[(String, &Level)], s: &Settings, progress: &mut dyn FnMut(&str)) -> Study {
    let mut table = Table::new("precision", &["map", "numbers", "offset", "agreeing columns", "ms/frame"]);
    let offsets: &[f64] = s.effort.pick(&[0.0, 1e5, 1e7], &OFFSETS);
    // numbers -> offset -> (agreeing, columns, ms sum, maps)
    let mut totals = vec![vec![(0usize, 0usize, 0.0f64, 0usize); offsets.len()]; Numbers::ALL.len()];
    for (name, level) in levels {
        for (k, &offset) in offsets.iter().enumerate() {
            progress(&format!("precision: {name} at {offset:e}"));
            let Some(compiled) = moved(&level.compiled, offset) else { continue };
            let views = tour(&compiled, s.effort.pick(8, 32), 5);
            let exact: Vec<_> = views.iter().map(|v| exact_walls(&compiled, v, s.width)).collect();
            for (n, &numbers) in Numbers::ALL.iter().enumerate() {
                let got: Vec<_> = views.iter().map(|v| walls(&compiled, v, s.width, numbers)).collect();
                let agree: usize = got.iter().zip(&exact).map(|(g, e)| agreeing(g, e)).sum();
                let columns = views.len() * s.width;
                let ms = median_ms(s.effort.pick(3, 5), || {
                    for v in &views {
                        std::hint::black_box(walls(&compiled, v, s.width, numbers));
                    }
                }) / views.len().max(1) as f64;
                table.push(vec![
                    Cell::from(name.as_str()),
                    Cell::from(numbers.name()),
                    Cell::from(offset),
                    Cell::from(agree as f64 / columns.max(1) as f64),
                    Cell::from(ms),
                ]);
                let t = &mut totals[n][k];
                *t = (t.0 + agree, t.1 + columns, t.2 + ms, t.3 + 1);
            }
        }
    }
    let mut summary =
        Table::new("precision-summary", &["numbers", "offset", "disagreeing columns (%)", "ms/frame (mean over maps)"]);
    let mut series = Vec::new();
    for (n, numbers) in Numbers::ALL.iter().enumerate() {
        let mut points = Vec::new();
        for (k, &offset) in offsets.iter().enumerate() {
            let (agree, columns, ms, maps) = totals[n][k];
            let wrong = 100.0 * (1.0 - agree as f64 / columns.max(1) as f64);
            summary.push(vec![
                Cell::from(numbers.name()),
                Cell::from(offset),
                Cell::from(wrong),
                Cell::from(ms / maps.max(1) as f64),
            ]);
            // Log axes cannot show 0: plot the origin at 1 unit and exact as 1e-4 %.
            points.push((offset.max(1.0), wrong.max(1e-4)));
        }
        series.push((numbers.name().to_string(), points));
    }
    let conclusions = conclude(&summary, offsets);
    Study {
        id: "precision".into(),
        title: "Precision: f64 against f32, absolute against eye-relative".into(),
        method: format!(
            "Each map is moved by (D, D) for D in {offsets:?} and recompiled. From a tour of {} poses, the BSP walk \
             (partition sides, back faces, projected wall ends, column occlusion) is carried out in each number type, \
             and each column's nearest solid wall is compared with a brute-force f64 ray per column (ties at vertices \
             accept either wall). Absolute modes convert map coordinates to the type as they are; relative modes \
             subtract the eye in f64 first, as the renderer does. Time is the walk alone, {} columns.",
            s.effort.pick(16, 40),
            s.width
        ),
        tables: vec![summary, table],
        plots: vec![Plot {
            name: "precision-offset-vs-wrong".into(),
            title: "Precision: columns that disagree with the exact answer".into(),
            x_label: "distance of the map from the origin (units)".into(),
            y_label: "disagreeing columns (%, 1e-4 = none)".into(),
            log_x: true,
            log_y: true,
            series,
        }],
        conclusions,
    }
}

/// `compiled`'s map moved by (offset, offset) and compiled again; `None` when
/// that would leave the supported range.
fn moved(compiled: &CompiledMap, offset: f64) -> Option<CompiledMap> {
    let mut map = compiled.map.clone();
    let shift = DVec2::splat(offset);
    for v in &mut map.vertices {
        *v += shift;
    }
    for t in &mut map.things {
        t.pos += shift;
    }
    if map.vertices.iter().any(|v| v.abs().max_element() > MAX_COORD) {
        return None;
    }
    build(&map, &BuildOptions::default()).ok()
}

fn conclude(summary: &Table, offsets: &[f64]) -> Vec<String> {
    let wrong = summary.column("disagreeing columns (%)");
    let ms = summary.column("ms/frame (mean over maps)");
    let n = offsets.len();
    let mut out = Vec::new();
    for (k, numbers) in Numbers::ALL.iter().enumerate() {
        let rows = k * n..(k + 1) * n;
        let first_wrong = rows.clone().find(|&r| wrong[r] > 0.0).map(|r| offsets[r - k * n]);
        let mean_ms = rows.clone().map(|r| ms[r]).sum::<f64>() / n as f64;
        out.push(match first_wrong {
            None => format!(
                "{}: exact at every distance tried, up to {:e} units ({mean_ms:.4} ms per frame).",
                numbers.name(),
                offsets[n - 1]
            ),
            Some(d) => format!(
                "{}: first disagrees {}, {:.3}% of columns at {:e} units ({mean_ms:.4} ms per frame).",
                numbers.name(),
                if d == 0.0 {
                    "already at the origin (poses at fractional positions round)".to_string()
                } else {
                    format!("{d:e} units out")
                },
                wrong[rows.end - 1],
                offsets[n - 1]
            ),
        });
    }
    out.push(
        "The engine renders in f64 relative to the eye: exact here out to the largest distance tried, and the format's \
         limit of 2^24 units keeps every coordinate difference an exact f64."
            .into(),
    );
    out
}
