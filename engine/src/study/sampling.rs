//! Sampling: nearest against bilinear texture filtering, and
//! perspective-correct against affine texture coordinates on floors and
//! ceilings: frame time against how far each picture is from Doom's default
//! (nearest texels, perspective-correct), the same frames for all.

use super::{median_ms, Cell, Plot, Settings, Study, Table};
use crate::level::Level;
use crate::render::columns::Sampling;
use crate::render::{render_frame, Floors, Frame, RenderOptions};
use crate::tour::tour;
use crate::Framebuffer;

struct Variant {
    name: &'static str,
    floors: Floors,
    sampling: Sampling,
}

const VARIANTS: [Variant; 4] = [
    Variant {
        name: "nearest, spans (default)",
        floors: Floors::Spans,
        sampling: Sampling { bilinear: false, affine_planes: false },
    },
    Variant {
        name: "nearest, per-column planes",
        floors: Floors::Columns,
        sampling: Sampling { bilinear: false, affine_planes: false },
    },
    Variant { name: "bilinear", floors: Floors::Spans, sampling: Sampling { bilinear: true, affine_planes: false } },
    Variant {
        name: "affine planes",
        floors: Floors::Columns,
        sampling: Sampling { bilinear: false, affine_planes: true },
    },
];

pub fn run(levels: &[(String, &Level)], s: &Settings, progress: &mut dyn FnMut(&str)) -> Study {
    let mut table = Table::new(
        "sampling",
        &["map", "sampling", "ms/frame", "pixels differing from default (%)", "mean channel difference (0-255)"],
    );
    // variant -> (ms sum, differing sum, mean diff sum, maps)
    let mut totals = [(0.0f64, 0.0f64, 0.0f64, 0usize); VARIANTS.len()];
    for (name, level) in levels {
        let views = tour(level, s.effort.pick(4, 16), 3);
        let mut baseline: Vec<Vec<u32>> = Vec::new();
        for (k, variant) in VARIANTS.iter().enumerate() {
            progress(&format!("sampling: {name} {}", variant.name));
            let options = RenderOptions { floors: variant.floors, sampling: variant.sampling, ..Default::default() };
            let (mut frame, mut fb) = (Frame::new(), Framebuffer::new(s.width, s.height));
            let frames: Vec<Vec<u32>> = views
                .iter()
                .map(|v| {
                    render_frame(level, v, &options, &mut frame, &mut fb);
                    fb.pixels.clone()
                })
                .collect();
            let ms = median_ms(s.effort.pick(3, 5), || {
                for v in &views {
                    render_frame(level, v, &options, &mut frame, &mut fb);
                }
            }) / views.len().max(1) as f64;
            if k == 0 {
                baseline = frames.clone();
            }
            let (differing, mean) = difference(&baseline, &frames);
            table.push(vec![
                Cell::from(name.as_str()),
                Cell::from(variant.name),
                Cell::from(ms),
                Cell::from(differing * 100.0),
                Cell::from(mean),
            ]);
            let t = &mut totals[k];
            *t = (t.0 + ms, t.1 + differing * 100.0, t.2 + mean, t.3 + 1);
        }
    }
    let mut summary = Table::new(
        "sampling-summary",
        &["sampling", "ms/frame (mean over maps)", "pixels differing (%)", "mean channel difference"],
    );
    let mut series = Vec::new();
    for (k, variant) in VARIANTS.iter().enumerate() {
        let (ms, differing, mean, maps) = totals[k];
        let n = maps.max(1) as f64;
        summary.push(vec![
            Cell::from(variant.name),
            Cell::from(ms / n),
            Cell::from(differing / n),
            Cell::from(mean / n),
        ]);
        series.push((variant.name.to_string(), vec![(ms / n, mean / n)]));
    }
    let conclusions = conclude(&summary);
    Study {
        id: "sampling".into(),
        title: "Sampling: nearest against bilinear, perspective-correct against affine".into(),
        method: format!(
            "Every map given, a tour of {} poses, textured, one thread, {}x{}. Each variant's frames are compared \
             pixel by pixel with the default's (nearest texels; floors and ceilings as horizontal spans, which are \
             perspective-correct because a row of a floor is at one depth). Per-column planes are also \
             perspective-correct (a divide per pixel); affine planes interpolate texture coordinates linearly \
             between the exact ends of each column's run, as renderers without a divide per pixel did; bilinear \
             blends the four nearest texels on walls and flats.",
            s.effort.pick(12, 24),
            s.width,
            s.height
        ),
        tables: vec![summary, table],
        plots: vec![Plot {
            name: "sampling-time-vs-difference".into(),
            title: "Sampling: frame time against difference from the default".into(),
            x_label: "ms per frame (mean over maps)".into(),
            y_label: "mean channel difference (0-255)".into(),
            log_x: false,
            log_y: false,
            series,
        }],
        conclusions,
    }
}

/// Share of pixels that differ, and the mean absolute channel difference
/// (RGB, 0-255) over all pixels.
fn difference(a: &[Vec<u32>], b: &[Vec<u32>]) -> (f64, f64) {
    let (mut differing, mut sum, mut total) = (0u64, 0u64, 0u64);
    for (fa, fb) in a.iter().zip(b) {
        for (&p, &q) in fa.iter().zip(fb) {
            total += 1;
            if p != q {
                differing += 1;
                let (p, q) = (p.to_le_bytes(), q.to_le_bytes());
                sum += (0..3).map(|k| u64::from(p[k].abs_diff(q[k]))).sum::<u64>();
            }
        }
    }
    let total = total.max(1) as f64;
    (differing as f64 / total, sum as f64 / (3.0 * total))
}

fn conclude(summary: &Table) -> Vec<String> {
    let (ms, differing, mean) = (
        summary.column("ms/frame (mean over maps)"),
        summary.column("pixels differing (%)"),
        summary.column("mean channel difference"),
    );
    vec![
        format!(
            "Bilinear filtering costs {:.1}x the default's time ({:.3} against {:.3} ms) and changes {:.1}% of pixels by \
             {:.2} levels on average: smoother close up, the same picture from afar.",
            ms[2] / ms[0],
            ms[2],
            ms[0],
            differing[2],
            mean[2]
        ),
        format!(
            "Per-column planes are {:.1}x the spans' time for a picture that differs in {:.2}% of pixels (rounding at \
             texel edges): spans are the faster way to the same perspective-correct floors.",
            ms[1] / ms[0],
            differing[1]
        ),
        format!(
            "Affine planes change {:.1}% of pixels by {:.2} levels on average (floors swim where a column's run spans \
             a wide range of depths) and take {:.3} ms against {:.3} ms for exact per-column planes: {}",
            differing[3],
            mean[3],
            ms[3],
            ms[1],
            if ms[3] < 0.9 * ms[1] {
                "a real saving, paid for in a visibly wrong floor."
            } else {
                "no real saving, since a divide per pixel is cheap next to the memory traffic."
            }
        ),
    ]
}
