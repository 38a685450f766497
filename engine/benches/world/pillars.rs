//! A generated map (RON, format version 2) for the cost of idle specials: a
//! room with a grid of 1,000 small pillars, each a sector of its own whose
//! floor is too high to climb (64 above the room's, the step is 24), so the
//! player walks between them and never onto one. With specials, every
//! pillar has a unique tag and a sector special that does nothing until a
//! body stands on it (damage or secret), and one face of each carries a
//! line special naming it (use, walk or shoot; a floor, a lift, a door or a
//! light change) that the bench never sets off. Without, the same geometry
//! has no tag and no special at all.

use std::fmt::Write;

/// Pillars across and down: 40 x 25 = 1,000.
pub const ACROSS: usize = 40;
pub const DOWN: usize = 25;
/// Each pillar sits in a cell of this size, [`MARGIN`] from the cell's
/// lower-left corner and 16 units wide: the gaps are 48 wide, room for the
/// 32-unit body.
const CELL: f64 = 64.0;
const MARGIN: f64 = 24.0;
const SIDE: f64 = 16.0;

/// The map's RON text; `specials`: tags, sector specials and line specials
/// on the pillars, or none.
pub fn pillars_ron(specials: bool) -> String {
    let (w, h) = (ACROSS as f64 * CELL, DOWN as f64 * CELL);
    let name = if specials { "1,000 idle tagged pillars" } else { "1,000 plain pillars" };
    let mut vertices = vec![(0.0, 0.0), (0.0, h), (w, h), (w, 0.0)];
    let mut sectors =
        vec!["Sector(floor: 0.0, ceiling: 128.0, light: 160, floor_texture: \"FLOOR\", ceiling_texture: \"CEIL\")"
            .to_string()];
    // The room's walls, clockwise seen from above (the front, on the right, is inside).
    let mut lines: Vec<String> = (0..4)
        .map(|k| format!("Line(from: {k}, to: {}, front: Side(sector: 0, middle: \"STONE\"))", (k + 1) % 4))
        .collect();
    for j in 0..DOWN {
        for i in 0..ACROSS {
            let n = j * ACROSS + i; // 0..1000
            let sector = n + 1;
            let (x, y) = (i as f64 * CELL + MARGIN, j as f64 * CELL + MARGIN);
            let v = vertices.len();
            // Counter-clockwise round the pillar: the room, outside, is on each line's right.
            vertices.extend([(x, y), (x + SIDE, y), (x + SIDE, y + SIDE), (x, y + SIDE)]);
            let mut sector_text = String::from(
                "Sector(floor: 64.0, ceiling: 128.0, light: 160, floor_texture: \"TILE\", ceiling_texture: \"CEIL\"",
            );
            if specials {
                let special = if n.is_multiple_of(2) {
                    "SectorSpecial(damage: Damage(amount: 5))"
                } else {
                    "SectorSpecial(secret: true)"
                };
                write!(sector_text, ", tag: {sector}, special: {special}").unwrap();
            }
            sector_text.push(')');
            sectors.push(sector_text);
            for k in 0..4 {
                let mut line = format!(
                    "Line(from: {}, to: {}, front: Side(sector: 0, lower: \"METAL\"), back: Some(Side(sector: {sector}))",
                    v + k,
                    v + (k + 1) % 4
                );
                if specials && k == 0 {
                    write!(line, ", special: LineSpecial({})", line_special(n, sector)).unwrap();
                }
                line.push(')');
                lines.push(line);
            }
        }
    }
    let mut out = String::new();
    writeln!(out, "Map(\n    version: 2,\n    name: \"{name}\",").unwrap();
    let vertex_text: Vec<String> = vertices.iter().map(|(x, y)| format!("({x:.1}, {y:.1})")).collect();
    writeln!(out, "    vertices: [{}],", vertex_text.join(", ")).unwrap();
    writeln!(out, "    sectors: [\n        {},\n    ],", sectors.join(",\n        ")).unwrap();
    writeln!(out, "    lines: [\n        {},\n    ],", lines.join(",\n        ")).unwrap();
    // Between four pillars, in the middle of the room.
    let start = (ACROSS as f64 / 2.0 * CELL, DOWN as f64 / 2.0 * CELL);
    writeln!(out, "    things: [Thing(kind: \"player_start\", x: {:.1}, y: {:.1}, angle: 90.0)],", start.0, start.1)
        .unwrap();
    out.push(')');
    out
}

/// The special of pillar `n`'s south face, naming its sector's tag.
fn line_special(n: usize, tag: usize) -> String {
    match n % 4 {
        0 => format!("on: Use, tag: {tag}, action: Floor(to: LowestNeighbourFloor)"),
        1 => format!("on: Walk, repeat: true, by: Anyone, tag: {tag}, action: Lift()"),
        2 => format!("on: Shoot, tag: {tag}, action: Door(kind: Open)"),
        _ => format!("on: Use, repeat: true, tag: {tag}, action: Light(Set(255))"),
    }
}
