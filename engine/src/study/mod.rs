//! The accuracy studies `sightline bench` runs: each measures time and
//! accuracy of one choice (visibility algorithm, ray method, BSP heuristic,
//! number type, texture sampling) against an exact answer on the same
//! frames, and returns a [`Study`]: tables, series to plot, and the
//! conclusion its numbers draw. The engine computes; the binary writes the
//! report, the CSV/JSON and the plots (it holds the plotting crate), so the
//! engine stays headless and free of presentation.

pub mod bsp;
pub mod precision;
pub mod rays;
pub mod sampling;
pub mod visibility;

use std::time::Instant;

use serde::Serialize;

/// How much work a run does: `quick` is for CI (seconds), the default for a
/// report (a few minutes in all).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Effort {
    Quick,
    Full,
}

impl Effort {
    /// Pick `quick` or `full`.
    pub fn pick<T>(self, quick: T, full: T) -> T {
        match self {
            Effort::Quick => quick,
            Effort::Full => full,
        }
    }
}

/// What every study is given.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    pub width: usize,
    pub height: usize,
    pub effort: Effort,
}

/// A cell of a table.
#[derive(Clone, Debug, Serialize, PartialEq)]
#[serde(untagged)]
pub enum Cell {
    Text(String),
    Number(f64),
}

impl From<&str> for Cell {
    fn from(s: &str) -> Cell {
        Cell::Text(s.to_string())
    }
}

impl From<String> for Cell {
    fn from(s: String) -> Cell {
        Cell::Text(s)
    }
}

impl From<f64> for Cell {
    fn from(x: f64) -> Cell {
        Cell::Number(x)
    }
}

impl From<usize> for Cell {
    fn from(x: usize) -> Cell {
        Cell::Number(x as f64)
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct Table {
    /// File stem for the CSV (`rays`, `precision`).
    pub name: String,
    pub columns: Vec<String>,
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    pub fn new(name: &str, columns: &[&str]) -> Table {
        Table { name: name.into(), columns: columns.iter().map(|c| c.to_string()).collect(), rows: Vec::new() }
    }

    pub fn push(&mut self, row: Vec<Cell>) {
        debug_assert_eq!(row.len(), self.columns.len());
        self.rows.push(row);
    }

    /// The numbers of column `name` (NaN where a cell is text).
    pub fn column(&self, name: &str) -> Vec<f64> {
        let k = self.columns.iter().position(|c| c == name).unwrap_or(usize::MAX);
        self.rows
            .iter()
            .map(|r| match r.get(k) {
                Some(Cell::Number(x)) => *x,
                _ => f64::NAN,
            })
            .collect()
    }
}

/// A line chart: named series of (x, y) points.
#[derive(Clone, Debug, Serialize)]
pub struct Plot {
    /// File stem of the image (`rays-time-error`).
    pub name: String,
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub log_x: bool,
    pub log_y: bool,
    pub series: Vec<(String, Vec<(f64, f64)>)>,
}

/// One study's results.
#[derive(Clone, Debug, Serialize)]
pub struct Study {
    pub id: String,
    pub title: String,
    /// What was measured, on what, how (a paragraph).
    pub method: String,
    pub tables: Vec<Table>,
    pub plots: Vec<Plot>,
    /// The conclusions the numbers draw, computed from them.
    pub conclusions: Vec<String>,
}

/// The median of `f()`'s wall-clock milliseconds over `runs` calls.
pub fn median_ms(runs: usize, mut f: impl FnMut()) -> f64 {
    let mut times: Vec<f64> = (0..runs.max(1))
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_exhaustive_search_is_never_beaten_on_small_rooms() {
        use crate::bsp::{build, BuildOptions, SplitterKind};
        for k in 1..=5 {
            let map = super::bsp::pillars(k, 7);
            let best = build(&map, &BuildOptions { splitter: SplitterKind::Exhaustive, seed: 0 }).unwrap();
            let cost = build(&map, &BuildOptions { splitter: SplitterKind::Cost, seed: 0 }).unwrap();
            assert!(best.stats.sides_out <= cost.stats.sides_out, "{k}: {:?} {:?}", best.stats, cost.stats);
            for seed in 0..8 {
                let random = build(&map, &BuildOptions { splitter: SplitterKind::Random, seed }).unwrap();
                assert!(best.stats.sides_out <= random.stats.sides_out);
            }
            crate::bsp::check::check_invariants(&best.map, &best.bsp).unwrap();
        }
    }
}
