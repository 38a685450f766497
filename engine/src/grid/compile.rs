//! Grid map -> sector map: one one-sided line per exposed cell face (so that
//! `ids` shading colours a grid wall by its face in both renderers), and per
//! door a thin sector of its own, closed (ceiling on the floor), bounded by
//! the panel's two faces (flagged `door`, so that play can open it) and the
//! jamb pieces beside it.
//!
//! The open cells form sector 0; door `k` (in cell order) is sector `k + 1`.
//! [`FaceLines`] records which line each face became, so the ray-caster
//! reports the same line for the same face.

use std::collections::HashMap;

use glam::DVec2;

use super::{Axis, Cell, Face, Grid};
use crate::map::source::{FogSource, LineSource, MapSource, SectorSource, SideSource, ThingSource};

/// No line: the face is not exposed.
pub const NO_LINE: u32 = u32::MAX;

/// Which compiled line each cell face became.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FaceLines {
    /// `faces[cell * 4 + face as usize]` (faces in [`Face::ALL`] order): the
    /// line of an exposed wall face, or of a door panel's face; a jamb face
    /// beside a door is split in three consecutive lines and holds the first.
    pub faces: Vec<u32>,
    /// The sector of each door, by cell index (0 where there is no door).
    pub door_sectors: Vec<u32>,
    /// Door cells in sector order.
    pub doors: Vec<usize>,
}

impl FaceLines {
    #[inline]
    pub fn line(&self, cell: usize, face: Face) -> u32 {
        self.faces[cell * 4 + face as usize]
    }
}

/// The ends of a face of cell `(i, j)`, directed so that the cell it faces
/// is on the right (the front side of the line).
pub fn face_ends(grid: &Grid, i: i64, j: i64, face: Face) -> (DVec2, DVec2) {
    let (x0, x1, y0, y1) = (grid.x(i), grid.x(i + 1), grid.y(j), grid.y(j + 1));
    let p = DVec2::new;
    match face {
        Face::North => (p(x1, y1), p(x0, y1)),
        Face::East => (p(x1, y0), p(x1, y1)),
        Face::South => (p(x0, y0), p(x1, y0)),
        Face::West => (p(x0, y1), p(x0, y0)),
    }
}

/// How far `p` (on the face's line) lies along a face that starts at
/// `from`: the texture column, as the compiled line measures it.
pub fn along_face(face: Face, from: DVec2, p: DVec2) -> f64 {
    match face {
        Face::North => from.x - p.x,
        Face::East => p.y - from.y,
        Face::South => p.x - from.x,
        Face::West => from.y - p.y,
    }
}

/// The door whose jamb this face is (the face looks into a door cell whose
/// panel ends against it), with its cell.
pub fn jamb_of(grid: &Grid, i: i64, j: i64, face: Face) -> Option<(i64, i64, Axis)> {
    let (di, dj) = face.step();
    match grid.cell(i + di, j + dj) {
        Cell::Door { axis: Axis::X, .. } if face.is_x() => Some((i + di, j + dj, Axis::X)),
        Cell::Door { axis: Axis::Y, .. } if !face.is_x() => Some((i + di, j + dj, Axis::Y)),
        _ => None,
    }
}

/// A jamb face's two inner points (where the door slab meets it), in the
/// face's line order.
pub fn jamb_points(grid: &Grid, i: i64, j: i64, face: Face) -> Option<[DVec2; 2]> {
    let (di, dj, axis) = jamb_of(grid, i, j, face)?;
    let [lo, hi] = grid.door_slab(di, dj, axis);
    let (from, _) = face_ends(grid, i, j, face);
    let points = match axis {
        Axis::X => [DVec2::new(from.x, lo), DVec2::new(from.x, hi)],
        Axis::Y => [DVec2::new(lo, from.y), DVec2::new(hi, from.y)],
    };
    // Line order runs from `from`: reverse when `from` is at the high end.
    let ascending = match face {
        Face::East | Face::South => true,
        Face::West | Face::North => false,
    };
    Some(if ascending { points } else { [points[1], points[0]] })
}

/// The two faces of the door panel in cell `(i, j)`, as (face direction, ends).
pub fn panel_faces(grid: &Grid, i: i64, j: i64, axis: Axis) -> [(Face, (DVec2, DVec2)); 2] {
    let [lo, hi] = grid.door_slab(i, j, axis);
    let (x0, x1, y0, y1) = (grid.x(i), grid.x(i + 1), grid.y(j), grid.y(j + 1));
    let p = DVec2::new;
    match axis {
        Axis::X => [(Face::South, (p(x0, lo), p(x1, lo))), (Face::North, (p(x1, hi), p(x0, hi)))],
        Axis::Y => [(Face::West, (p(lo, y1), p(lo, y0))), (Face::East, (p(hi, y0), p(hi, y1)))],
    }
}

/// The two end faces of the door panel in cell `(i, j)`, where it meets the
/// cell's edges (a jamb's pieces when a wall is there, else lines of their own).
pub fn panel_ends(grid: &Grid, i: i64, j: i64, axis: Axis) -> [(Face, (DVec2, DVec2)); 2] {
    let [lo, hi] = grid.door_slab(i, j, axis);
    let (x0, x1, y0, y1) = (grid.x(i), grid.x(i + 1), grid.y(j), grid.y(j + 1));
    let p = DVec2::new;
    match axis {
        Axis::X => [(Face::West, (p(x0, hi), p(x0, lo))), (Face::East, (p(x1, lo), p(x1, hi)))],
        Axis::Y => [(Face::South, (p(lo, y0), p(hi, y0))), (Face::North, (p(hi, y1), p(lo, y1)))],
    }
}

struct Builder {
    vertices: Vec<(f64, f64)>,
    index: HashMap<(u64, u64), i64>,
    lines: Vec<LineSource>,
}

impl Builder {
    fn vertex(&mut self, p: DVec2) -> i64 {
        let key = (p.x.to_bits(), p.y.to_bits());
        let next = self.vertices.len() as i64;
        *self.index.entry(key).or_insert_with(|| {
            self.vertices.push((p.x, p.y));
            next
        })
    }

    fn line(&mut self, (a, b): (DVec2, DVec2), front: SideSource, back: Option<SideSource>) -> u32 {
        self.line_with((a, b), front, back, false)
    }

    fn line_with(&mut self, (a, b): (DVec2, DVec2), front: SideSource, back: Option<SideSource>, door: bool) -> u32 {
        let (from, to) = (self.vertex(a), self.vertex(b));
        let n = self.lines.len() as u32;
        self.lines.push(LineSource { from, to, front, back, door, ..LineSource::default() });
        n
    }
}

fn side(sector: usize) -> SideSource {
    SideSource { sector: sector as i64, ..SideSource::default() }
}

/// The sector map a grid stands for, and where each face went.
pub fn compile(grid: &Grid) -> (MapSource, FaceLines) {
    let cells = grid.cells.len();
    let mut faces = FaceLines { faces: vec![NO_LINE; cells * 4], door_sectors: vec![0; cells], doors: Vec::new() };
    for (index, cell) in grid.cells.iter().enumerate() {
        if matches!(cell, Cell::Door { .. }) {
            faces.doors.push(index);
            faces.door_sectors[index] = faces.doors.len() as u32;
        }
    }
    let mut b = Builder { vertices: Vec::new(), index: HashMap::new(), lines: Vec::new() };
    for j in 0..grid.rows as i64 {
        for i in 0..grid.columns as i64 {
            let index = grid.index(i, j);
            match grid.cell(i, j) {
                Cell::Wall { texture } => {
                    let name = &grid.textures[usize::from(texture)];
                    for face in Face::ALL {
                        let (di, dj) = face.step();
                        if !grid.cell(i + di, j + dj).is_walkable() {
                            continue;
                        }
                        let middle = |sector: usize, x_offset: f64| SideSource {
                            middle: Some(name.clone()),
                            x_offset,
                            ..side(sector)
                        };
                        let (from, to) = face_ends(grid, i, j, face);
                        let first = match jamb_of(grid, i, j, face).zip(jamb_points(grid, i, j, face)) {
                            None => b.line((from, to), middle(0, 0.0), None),
                            Some(((di, dj, _), [p, q])) => {
                                let door = faces.door_sectors[grid.index(di, dj)] as usize;
                                // Texture offsets keep the face's texture running on across the pieces.
                                let first = b.line((from, p), middle(0, 0.0), None);
                                b.line((p, q), middle(door, from.distance(p)), None);
                                b.line((q, to), middle(0, from.distance(q)), None);
                                first
                            }
                        };
                        faces.faces[index * 4 + face as usize] = first;
                    }
                }
                Cell::Door { texture, axis } => {
                    let door = faces.door_sectors[index] as usize;
                    let name = &grid.textures[usize::from(texture)];
                    let ends = panel_ends(grid, i, j, axis).into_iter().filter(|(face, _)| {
                        let (di, dj) = face.step();
                        grid.cell(i + di, j + dj).is_walkable()
                    });
                    // The panel's two broad faces are `door` lines: using one opens the
                    // door sector behind it, as on a sector map, and `play::world::doors` makes
                    // it slide because the level has a grid. (Flagging them here rather
                    // than finding grid doors apart keeps one path for "use", and the
                    // compiled map alone stays playable: without its grid, its doors
                    // rise like Doom's.) Panel ends without a jamb are not for using,
                    // as Wolfenstein's doors are used from the front only.
                    let broad = panel_faces(grid, i, j, axis).into_iter().map(|f| (f, true));
                    for ((face, ends), is_door) in broad.chain(ends.map(|f| (f, false))) {
                        let front = SideSource { upper: Some(name.clone()), ..side(0) };
                        faces.faces[index * 4 + face as usize] = b.line_with(ends, front, Some(side(door)), is_door);
                    }
                }
                Cell::Empty => {}
            }
        }
    }
    let sector = |ceiling: f64| SectorSource {
        floor: grid.floor,
        ceiling,
        light: i64::from(grid.light),
        floor_texture: grid.floor_texture.clone(),
        ceiling_texture: grid.ceiling_texture.clone(),
        ..SectorSource::default()
    };
    let mut sectors = vec![sector(grid.ceiling)];
    // A closed door: its ceiling rests on its floor.
    sectors.extend(faces.doors.iter().map(|_| sector(grid.floor)));
    let source = MapSource {
        name: grid.name.clone(),
        vertices: b.vertices,
        sectors,
        lines: b.lines,
        things: grid.things.iter().map(|t| ThingSource::new(&t.kind, t.pos.x, t.pos.y, t.angle)).collect(),
        diminishing_light: grid.diminishing_light,
        fog: grid.fog.map(|f| FogSource { colour: (f.colour[0], f.colour[1], f.colour[2]), distance: f.distance }),
        ..MapSource::default()
    };
    (source, faces)
}
