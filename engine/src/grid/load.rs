//! Reading a grid map: text -> [`GridMapSource`] -> validated [`Grid`], with
//! every problem naming the row and column (as written in the file: row 0 is
//! the first, northern, row) and the character.

use std::collections::BTreeMap;
use std::fmt;

use glam::DVec2;

use super::source::{CellSource, GridMapSource};
use super::{Axis, Cell, Grid};
use crate::geom::MAX_COORD;
use crate::map::{Fog, MapError, Thing, PLAYER_START};

/// One thing wrong with a grid map.
#[derive(Clone, Debug, PartialEq)]
pub enum GridProblem {
    BadCellSize { value: f64 },
    NoRows,
    Ragged { row: usize, cells: usize, expected: usize },
    NotInLegend { row: usize, column: usize, c: char },
    OpenEdge { row: usize, column: usize, c: char },
    NoPlayerStart,
    SecondPlayerStart { row: usize, column: usize, first: (usize, usize) },
    BadAngle { row: usize, column: usize },
    DoorsSideBySide { row: usize, column: usize },
    TooLarge { extent: f64 },
    BadHeights { floor: f64, ceiling: f64 },
    BadLight { light: i64 },
    BadFog { distance: f64 },
    EmptyName { c: char },
    TooManyTextures,
}

impl fmt::Display for GridProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GridProblem::BadCellSize { value } => {
                write!(f, "cell_size {value:?} must be a finite number above 0")
            }
            GridProblem::NoRows => write!(f, "the map has no rows"),
            GridProblem::Ragged { row, cells, expected } => write!(
                f,
                "row {row}: has {cells} cells, but row 0 has {expected}; every row must be as long as the first"
            ),
            GridProblem::NotInLegend { row, column, c } => {
                write!(f, "row {row}, column {column}: character {c:?} is not in the legend")
            }
            GridProblem::OpenEdge { row, column, c } => write!(
                f,
                "row {row}, column {column}: {c:?} is walkable and on the border, so the map is open there; \
                 surround the map with walls"
            ),
            GridProblem::NoPlayerStart => write!(f, "the map has no PlayerStart cell"),
            GridProblem::SecondPlayerStart { row, column, first } => write!(
                f,
                "row {row}, column {column}: a second player start (the first is at row {}, column {})",
                first.0, first.1
            ),
            GridProblem::BadAngle { row, column } => {
                write!(f, "row {row}, column {column}: the player start's angle is not finite")
            }
            GridProblem::DoorsSideBySide { row, column } => write!(
                f,
                "row {row}, column {column}: two doors side by side along their panels; \
                 put a wall cell between them or make them one door"
            ),
            GridProblem::TooLarge { extent } => write!(
                f,
                "the map reaches {extent:?} map units, beyond the supported range of {MAX_COORD}; \
                 use fewer or smaller cells"
            ),
            GridProblem::BadHeights { floor, ceiling } => write!(
                f,
                "floor {floor:?} and ceiling {ceiling:?} must be finite, within the supported range, \
                 with the floor below the ceiling"
            ),
            GridProblem::BadLight { light } => write!(f, "light {light} is outside 0..=255"),
            GridProblem::BadFog { distance } => {
                write!(f, "fog: distance {distance:?} must be a finite number above 0")
            }
            GridProblem::EmptyName { c } => write!(f, "legend {c:?}: the name is empty"),
            GridProblem::TooManyTextures => write!(f, "the legend names more than 65535 textures"),
        }
    }
}

/// Does this text hold a grid map (`GridMap(...)`) rather than a sector map?
/// Decided by the first word after comments and `#![...]` attributes.
pub fn is_grid_source(text: &str) -> bool {
    let mut rest = text.trim_start_matches('\u{feff}');
    loop {
        rest = rest.trim_start();
        if let Some(r) = rest.strip_prefix("//") {
            rest = r.split_once('\n').map_or("", |(_, after)| after);
        } else if let Some(r) = rest.strip_prefix("/*") {
            rest = r.split_once("*/").map_or("", |(_, after)| after);
        } else if let Some(r) = rest.strip_prefix("#!") {
            rest = r.split_once(']').map_or("", |(_, after)| after);
        } else {
            break;
        }
    }
    rest.strip_prefix("GridMap").is_some_and(|r| r.trim_start().starts_with('('))
}

/// Parses and validates grid map text; `label` names the file in errors.
pub fn parse_grid(text: &str, label: &str) -> Result<Grid, MapError> {
    let options = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    let source: GridMapSource = options.from_str(text).map_err(|e| MapError::Syntax {
        path: label.to_string(),
        line: e.span.start.line,
        col: e.span.start.col,
        message: e.code.to_string(),
    })?;
    validate(&source).map_err(|problems| MapError::InvalidGrid { path: label.to_string(), problems })
}

/// Turns a grid source into a [`Grid`], or lists everything wrong with it.
pub fn validate(src: &GridMapSource) -> Result<Grid, Vec<GridProblem>> {
    let mut problems = Vec::new();
    let s = src.cell_size;
    if !(s.is_finite() && s > 0.0) {
        problems.push(GridProblem::BadCellSize { value: s });
    }
    let rows: Vec<Vec<char>> = src.rows.iter().map(|r| r.chars().collect()).collect();
    let Some(width) = rows.first().map(Vec::len).filter(|&w| w > 0) else {
        problems.push(GridProblem::NoRows);
        return Err(problems);
    };
    for (r, row) in rows.iter().enumerate() {
        if row.len() != width {
            problems.push(GridProblem::Ragged { row: r, cells: row.len(), expected: width });
        }
    }
    let extent = s * width.max(rows.len()) as f64;
    if s.is_finite() && extent > MAX_COORD {
        problems.push(GridProblem::TooLarge { extent });
    }
    let floor = src.floor.unwrap_or(0.0);
    let ceiling = src.ceiling.unwrap_or(floor + s);
    if !(floor.is_finite() && ceiling.is_finite() && floor.abs() <= MAX_COORD && ceiling.abs() <= MAX_COORD)
        || floor >= ceiling
    {
        problems.push(GridProblem::BadHeights { floor, ceiling });
    }
    let light = src.light.unwrap_or(255);
    if !(0..=255).contains(&light) {
        problems.push(GridProblem::BadLight { light });
    }
    let fog = src.fog.as_ref().map(|f| Fog { colour: [f.colour.0, f.colour.1, f.colour.2], distance: f.distance });
    if let Some(f) = fog.filter(|f| !(f.distance.is_finite() && f.distance > 0.0)) {
        problems.push(GridProblem::BadFog { distance: f.distance });
    }
    let textures = legend_textures(&src.legend, &mut problems);
    if !problems.is_empty() {
        return Err(problems);
    }

    let height = rows.len();
    let mut grid = Grid {
        name: src.name.clone(),
        cell_size: s,
        columns: width,
        rows: height,
        cells: vec![Cell::Empty; width * height],
        textures: textures.names,
        floor,
        ceiling,
        light: light as u8,
        floor_texture: src.floor_texture.clone(),
        ceiling_texture: src.ceiling_texture.clone(),
        things: Vec::new(),
        diminishing_light: src.diminishing_light,
        fog,
    };
    let mut start: Option<(usize, usize)> = None;
    let mut things = Vec::new();
    for (r, row) in rows.iter().enumerate() {
        let j = (height - 1 - r) as i64;
        for (c, ch) in row.iter().enumerate() {
            let Some(entry) = src.legend.get(ch) else {
                problems.push(GridProblem::NotInLegend { row: r, column: c, c: *ch });
                continue;
            };
            let i = c as i64;
            let pos = grid.centre(i, j);
            let cell = match entry {
                CellSource::Wall { texture } => Cell::Wall { texture: textures.index[texture.as_str()] },
                // The axis is settled below, once all neighbours are known.
                CellSource::Door { texture } => Cell::Door { texture: textures.index[texture.as_str()], axis: Axis::X },
                CellSource::Thing { kind } => {
                    things.push(Thing::new(kind, pos, 0.0));
                    Cell::Empty
                }
                CellSource::PlayerStart { angle } => {
                    if !angle.is_finite() {
                        problems.push(GridProblem::BadAngle { row: r, column: c });
                    }
                    match start {
                        Some(first) => problems.push(GridProblem::SecondPlayerStart { row: r, column: c, first }),
                        None => start = Some((r, c)),
                    }
                    things.push(Thing::new(PLAYER_START, pos, *angle));
                    Cell::Empty
                }
                CellSource::Empty => Cell::Empty,
            };
            let index = grid.index(i, j);
            grid.cells[index] = cell;
            let border = r == 0 || c == 0 || r == height - 1 || c == width - 1;
            if border && cell.is_walkable() {
                problems.push(GridProblem::OpenEdge { row: r, column: c, c: *ch });
            }
        }
    }
    if start.is_none() {
        problems.push(GridProblem::NoPlayerStart);
    }
    settle_doors(&mut grid, &mut problems);
    grid.things = things;
    if problems.is_empty() {
        Ok(grid)
    } else {
        Err(problems)
    }
}

struct LegendTextures<'a> {
    names: Vec<String>,
    index: BTreeMap<&'a str, u16>,
}

/// The distinct texture names the legend uses, numbered in legend order.
fn legend_textures<'a>(legend: &'a BTreeMap<char, CellSource>, problems: &mut Vec<GridProblem>) -> LegendTextures<'a> {
    let mut out = LegendTextures { names: Vec::new(), index: BTreeMap::new() };
    for (c, entry) in legend {
        let name = match entry {
            CellSource::Wall { texture } | CellSource::Door { texture } => texture.as_str(),
            CellSource::Thing { kind } if kind.trim().is_empty() => {
                problems.push(GridProblem::EmptyName { c: *c });
                continue;
            }
            _ => continue,
        };
        if name.trim().is_empty() {
            problems.push(GridProblem::EmptyName { c: *c });
            continue;
        }
        if !out.index.contains_key(name) {
            let Ok(n) = u16::try_from(out.names.len()) else {
                problems.push(GridProblem::TooManyTextures);
                break;
            };
            out.index.insert(name, n);
            out.names.push(name.to_string());
        }
    }
    out
}

/// Gives each door its axis: its panel runs between the wall cells on a pair
/// of opposite sides (its jambs, as in Wolfenstein); with walls north and
/// south only, it runs north-south; otherwise east-west.
fn settle_doors(grid: &mut Grid, problems: &mut Vec<GridProblem>) {
    for j in 0..grid.rows as i64 {
        for i in 0..grid.columns as i64 {
            let Cell::Door { texture, .. } = grid.cell(i, j) else { continue };
            let axis = door_axis(grid, i, j);
            let index = grid.index(i, j);
            grid.cells[index] = Cell::Door { texture, axis };
        }
    }
    // Two panels meeting end to end would share their end lines.
    for j in 0..grid.rows as i64 {
        for i in 0..grid.columns as i64 {
            if door_beside(grid, i, j) {
                problems.push(GridProblem::DoorsSideBySide { row: grid.rows - 1 - j as usize, column: i as usize });
            }
        }
    }
}

/// Does the door in cell `(i, j)` have another door next along its panel?
fn door_beside(grid: &Grid, i: i64, j: i64) -> bool {
    match grid.cell(i, j) {
        Cell::Door { axis: Axis::X, .. } => matches!(grid.cell(i + 1, j), Cell::Door { axis: Axis::X, .. }),
        Cell::Door { axis: Axis::Y, .. } => matches!(grid.cell(i, j + 1), Cell::Door { axis: Axis::Y, .. }),
        _ => false,
    }
}

fn door_axis(grid: &Grid, i: i64, j: i64) -> Axis {
    let wall = |di: i64, dj: i64| matches!(grid.cell(i + di, j + dj), Cell::Wall { .. });
    if wall(0, -1) && wall(0, 1) && !(wall(-1, 0) && wall(1, 0)) {
        Axis::Y
    } else {
        Axis::X
    }
}

/// Checks a grid read back from a compiled file: the invariants [`validate`] established.
pub fn check(grid: &Grid) -> Result<(), String> {
    let s = grid.cell_size;
    if !(s.is_finite() && s > 0.0) || grid.columns == 0 || grid.rows == 0 {
        return Err("bad size".into());
    }
    if grid.cells.len() != grid.columns.checked_mul(grid.rows).ok_or("bad size")? {
        return Err("cell count does not match its size".into());
    }
    if s * grid.columns.max(grid.rows) as f64 > MAX_COORD {
        return Err("too large".into());
    }
    for j in 0..grid.rows as i64 {
        for i in 0..grid.columns as i64 {
            let cell = grid.cell(i, j);
            let border = i == 0 || j == 0 || i as usize == grid.columns - 1 || j as usize == grid.rows - 1;
            if border && cell.is_walkable() {
                return Err(format!("cell ({i}, {j}) is open on the border"));
            }
            match cell {
                Cell::Wall { texture } | Cell::Door { texture, .. } if usize::from(texture) >= grid.textures.len() => {
                    return Err(format!("cell ({i}, {j}) names texture {texture}, which does not exist"));
                }
                Cell::Door { axis, .. } if axis != door_axis(grid, i, j) || door_beside(grid, i, j) => {
                    return Err(format!("door ({i}, {j}) has the wrong axis or a door beside it"));
                }
                _ => {}
            }
        }
    }
    let inside =
        |p: DVec2| p.x > 0.0 && p.y > 0.0 && p.x < grid.x(grid.columns as i64) && p.y < grid.y(grid.rows as i64);
    if grid.things.iter().any(|t| !inside(t.pos) || !t.angle.is_finite()) {
        return Err("a thing is outside the grid".into());
    }
    Ok(())
}
