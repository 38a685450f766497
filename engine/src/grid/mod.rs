//! Wolfenstein-style grid maps: a text picture of square cells read from RON
//! ([`source`], [`load`]), validated into a [`Grid`], and compiled into an
//! ordinary sector map ([`compile`]) so that the BSP renderer draws the same
//! level the grid ray-caster ([`crate::render::raycast`]) draws.
//!
//! Coordinates: cell `(i, j)` is column `i` from the west and row `j` from
//! the south, covering `x` in `[i s, (i+1) s]` and `y` in `[j s, (j+1) s]`
//! (`s` the cell size). The text's first row is the north edge, so text row
//! `r` is `j = rows - 1 - r`. Every corner coordinate is computed by
//! [`Grid::x`] and [`Grid::y`] alone, so the compiled map's vertices and the
//! ray-caster's cell edges are the same floating-point numbers.

pub mod compile;
pub mod load;
pub mod source;

use glam::DVec2;
use serde::{Deserialize, Serialize};

use crate::map::{Fog, Thing};

pub use compile::{compile, FaceLines};
pub use load::{is_grid_source, parse_grid, GridProblem};

/// A validated grid map.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Grid {
    pub name: String,
    pub cell_size: f64,
    pub columns: usize,
    pub rows: usize,
    /// `cells[j * columns + i]`.
    pub cells: Vec<Cell>,
    /// The texture names cells use; [`Cell`] indexes this list.
    pub textures: Vec<String>,
    pub floor: f64,
    pub ceiling: f64,
    pub light: u8,
    pub floor_texture: Option<String>,
    pub ceiling_texture: Option<String>,
    /// Things at cell centres, the player start among them.
    pub things: Vec<Thing>,
    pub diminishing_light: bool,
    pub fog: Option<Fog>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Cell {
    Empty,
    Wall {
        texture: u16,
    },
    /// A door: a thin panel through the cell centre, between two wall cells
    /// (its jambs) on opposite sides.
    Door {
        texture: u16,
        axis: Axis,
    },
}

/// The axis a door panel runs along.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Axis {
    /// The panel runs east-west (the passage north-south; jambs west and east).
    X,
    /// The panel runs north-south (jambs north and south).
    Y,
}

/// A side of a cell, named by the direction it faces.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Face {
    North,
    East,
    South,
    West,
}

impl Face {
    pub const ALL: [Face; 4] = [Face::North, Face::East, Face::South, Face::West];

    /// The step to the neighbouring cell this face looks at.
    pub fn step(self) -> (i64, i64) {
        match self {
            Face::North => (0, 1),
            Face::East => (1, 0),
            Face::South => (0, -1),
            Face::West => (-1, 0),
        }
    }

    /// Faces of the X kind (east and west) are hit across a vertical cell
    /// edge; Wolfenstein 3D shades them apart from the north and south faces.
    pub fn is_x(self) -> bool {
        matches!(self, Face::East | Face::West)
    }
}

/// A door panel is this share of a cell thick, centred on the cell's middle:
/// thin like Wolfenstein's, but a real slab so that the compiled map can
/// give it a sector of its own.
pub const DOOR_THICKNESS: f64 = 1.0 / 8.0;

impl Cell {
    pub fn is_walkable(self) -> bool {
        !matches!(self, Cell::Wall { .. })
    }
}

impl Grid {
    /// Western edge of column `i`.
    #[inline]
    pub fn x(&self, i: i64) -> f64 {
        i as f64 * self.cell_size
    }

    /// Southern edge of row `j`.
    #[inline]
    pub fn y(&self, j: i64) -> f64 {
        j as f64 * self.cell_size
    }

    pub fn contains(&self, i: i64, j: i64) -> bool {
        i >= 0 && j >= 0 && (i as usize) < self.columns && (j as usize) < self.rows
    }

    /// The cell at `(i, j)`; outside the grid counts as solid wall.
    #[inline]
    pub fn cell(&self, i: i64, j: i64) -> Cell {
        if self.contains(i, j) {
            self.cells[j as usize * self.columns + i as usize]
        } else {
            Cell::Wall { texture: 0 }
        }
    }

    pub fn index(&self, i: i64, j: i64) -> usize {
        j as usize * self.columns + i as usize
    }

    /// The coordinates `[low, high]` of the faces of the door panel in cell
    /// `(i, j)` across its axis (y for an [`Axis::X`] door, x for [`Axis::Y`]).
    pub fn door_slab(&self, i: i64, j: i64, axis: Axis) -> [f64; 2] {
        let (start, s) = match axis {
            Axis::X => (self.y(j), self.cell_size),
            Axis::Y => (self.x(i), self.cell_size),
        };
        [start + s * (0.5 - DOOR_THICKNESS / 2.0), start + s * (0.5 + DOOR_THICKNESS / 2.0)]
    }

    /// The cell containing `p`, a point on an edge going to the cell that
    /// `direction` (signs per axis, `-1` or `1`) leads into.
    pub fn cell_at(&self, p: DVec2, direction: (i64, i64)) -> (i64, i64) {
        (
            locate(p.x, self.cell_size, direction.0, |i| self.x(i)),
            locate(p.y, self.cell_size, direction.1, |j| self.y(j)),
        )
    }

    /// The cell centre of `(i, j)`.
    pub fn centre(&self, i: i64, j: i64) -> DVec2 {
        DVec2::new((self.x(i) + self.x(i + 1)) / 2.0, (self.y(j) + self.y(j + 1)) / 2.0)
    }
}

/// The index of the cell along one axis that holds `coord`: exact against the
/// edge function, so a coordinate equal to an edge is on that edge, and then
/// belongs to the cell on the `step` side of it.
fn locate(coord: f64, size: f64, step: i64, edge: impl Fn(i64) -> f64) -> i64 {
    // Clamped so that far-off or non-finite points cannot overflow; they are
    // outside the grid either way.
    let guess = (coord / size).floor();
    if !guess.is_finite() {
        return -2;
    }
    let mut c = guess.clamp(-2.0, 1e9) as i64;
    // The division is off by at most one cell; the edges settle it.
    for _ in 0..2 {
        if edge(c) > coord {
            c -= 1;
        } else if edge(c + 1) <= coord {
            c += 1;
        }
    }
    if step < 0 && edge(c) == coord {
        c -= 1;
    }
    c
}
