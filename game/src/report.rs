//! Writing the studies of `sightline bench` out: `report.md` with every
//! table, plot and conclusion; `results.json` with everything; one CSV per
//! table; one SVG per plot (drawn with plotters).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use plotters::prelude::*;
use sightline::study::{Cell, Plot, Study, Table};

/// Writes everything into `dir`; `heading` opens report.md (how it was made).
/// `images` is the path from report.md to `dir` (empty when they sit together).
pub fn write(studies: &[Study], dir: &Path, heading: &str) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("{}: cannot create", dir.display()))?;
    for study in studies {
        for table in &study.tables {
            write_csv(table, &dir.join(format!("{}.csv", table.name)))?;
        }
        for plot in &study.plots {
            draw(plot, &dir.join(format!("{}.svg", plot.name)))?;
        }
    }
    let json = serde_json::to_string_pretty(studies)?;
    std::fs::write(dir.join("results.json"), json).context("results.json")?;
    std::fs::write(dir.join("report.md"), markdown(studies, heading, "")).context("report.md")?;
    Ok(())
}

/// The report as markdown, with images at `prefix` + name (`prefix` ends in `/`
/// or is empty).
pub fn markdown(studies: &[Study], heading: &str, prefix: &str) -> String {
    let mut md = String::new();
    md.push_str(heading);
    md.push('\n');
    for study in studies {
        let _ = writeln!(md, "\n## {}\n\n{}\n", study.title, study.method);
        if !study.conclusions.is_empty() {
            md.push_str("**Conclusions.**\n\n");
            for c in &study.conclusions {
                let _ = writeln!(md, "- {c}");
            }
            md.push('\n');
        }
        for plot in &study.plots {
            let _ = writeln!(md, "![{}]({prefix}{}.svg)\n", plot.title, plot.name);
        }
        for table in &study.tables {
            md.push_str(&markdown_table(table));
            md.push('\n');
        }
    }
    md
}

fn markdown_table(t: &Table) -> String {
    let mut s = format!("`{}.csv`\n\n| {} |\n|{}\n", t.name, t.columns.join(" | "), "---|".repeat(t.columns.len()));
    for row in &t.rows {
        let cells: Vec<String> = row.iter().map(show).collect();
        let _ = writeln!(s, "| {} |", cells.join(" | "));
    }
    s
}

/// A number as people read it: integers plainly, small and large values in
/// scientific notation, the rest to four significant digits.
fn show(c: &Cell) -> String {
    match c {
        Cell::Text(t) => t.clone(),
        Cell::Number(x) if x.fract() == 0.0 && x.abs() < 1e6 => format!("{x}"),
        Cell::Number(x) if *x != 0.0 && (x.abs() < 1e-3 || x.abs() >= 1e6) => format!("{x:.3e}"),
        Cell::Number(x) => format!("{}", (x * 1e4).round() / 1e4),
    }
}

fn write_csv(t: &Table, path: &Path) -> Result<()> {
    let mut w = csv::Writer::from_path(path).with_context(|| format!("{}: cannot write", path.display()))?;
    w.write_record(&t.columns)?;
    for row in &t.rows {
        w.write_record(row.iter().map(|c| match c {
            Cell::Text(t) => t.clone(),
            Cell::Number(x) => x.to_string(),
        }))?;
    }
    w.flush()?;
    Ok(())
}

/// A line chart. Log axes are drawn as base-10 exponents on a linear axis,
/// labelled `1e3` and so on (points at or below 0 are left out there).
fn draw(plot: &Plot, path: &Path) -> Result<()> {
    let tx = |v: f64| if plot.log_x { v.log10() } else { v };
    let ty = |v: f64| if plot.log_y { v.log10() } else { v };
    let series: Vec<(String, Vec<(f64, f64)>)> = plot
        .series
        .iter()
        .map(|(name, points)| {
            let kept = points
                .iter()
                .filter(|(x, y)| (!plot.log_x || *x > 0.0) && (!plot.log_y || *y > 0.0))
                .map(|&(x, y)| (tx(x), ty(y)))
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect();
            (name.clone(), kept)
        })
        .collect();
    let all = series.iter().flat_map(|s| s.1.iter());
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for &(x, y) in all {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    if !x0.is_finite() {
        (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
    }
    let pad = |a: f64, b: f64| {
        let d = ((b - a) * 0.05).max(1e-9);
        (a - d, b + d)
    };
    let ((x0, x1), (y0, y1)) = (pad(x0, x1), pad(y0, y1));
    let root = SVGBackend::new(path, (860, 520)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(&plot.title, ("sans-serif", 20))
        .margin(14)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(err)?;
    let label = |log: bool| move |v: &f64| if log { format!("1e{v:.1}") } else { format!("{v:.3}") };
    chart
        .configure_mesh()
        .x_desc(plot.x_label.as_str())
        .y_desc(plot.y_label.as_str())
        .x_label_formatter(&label(plot.log_x))
        .y_label_formatter(&label(plot.log_y))
        .bold_line_style(RGBColor(210, 210, 210))
        .light_line_style(RGBColor(240, 240, 240))
        .draw()
        .map_err(err)?;
    for (k, (name, points)) in series.into_iter().enumerate() {
        let colour = Palette99::pick(k).to_rgba();
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
            .map_err(err)?
            .label(name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2)));
        chart.draw_series(points.into_iter().map(|p| Circle::new(p, 3, colour.filled()))).map_err(err)?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}

fn err(e: impl std::fmt::Display) -> anyhow::Error {
    anyhow::anyhow!("drawing a plot: {e}")
}
