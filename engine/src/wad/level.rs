//! A map's lumps in a WAD, decoded into plain records with every index checked.
//!
//! Record layouts (bytes, little-endian) as Doom's `r_defs.h`/`doomdata.h`:
//! THINGS 10, LINEDEFS 14, SIDEDEFS 30, VERTEXES 4, SECTORS 26. The WAD's
//! SEGS, SSECTORS, NODES, REJECT and BLOCKMAP are not read here: our
//! compiler builds its own tree for the renderer, and the simulation reads
//! them as stored ([`Wad::map_lump`], `sim::level`).

use super::{i16_at, lump_name, u16_at, Wad, WadError};

/// The lumps that follow a map's marker, in Doom's order.
pub const MAP_LUMPS: [&str; 10] =
    ["THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS", "NODES", "SECTORS", "REJECT", "BLOCKMAP"];

/// A side of a line that has none (Doom's `-1` in the sidedef field).
pub const NO_SIDE: u16 = 0xFFFF;

#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct WadThing {
    pub x: i16,
    pub y: i16,
    pub angle: i16,
    pub kind: u16,
    pub flags: u16,
}

#[derive(Clone, Debug, PartialEq)]
pub struct WadLine {
    pub v1: u16,
    pub v2: u16,
    pub flags: u16,
    pub special: u16,
    pub tag: u16,
    /// Sidedef indices; `None` where the WAD says -1.
    pub right: Option<u16>,
    pub left: Option<u16>,
}

/// Linedef flag bits (Doom's `ML_*`).
pub mod flags {
    pub const BLOCKING: u16 = 0x0001;
    pub const BLOCK_MONSTERS: u16 = 0x0002;
    pub const TWO_SIDED: u16 = 0x0004;
    pub const UPPER_UNPEGGED: u16 = 0x0008;
    pub const LOWER_UNPEGGED: u16 = 0x0010;
    /// Shown as one-sided on the automap; monsters do not use it.
    pub const SECRET: u16 = 0x0020;
    pub const BLOCK_SOUND: u16 = 0x0040;
}

#[derive(Clone, Debug, PartialEq)]
pub struct WadSide {
    pub x_offset: i16,
    pub y_offset: i16,
    pub upper: String,
    pub lower: String,
    pub middle: String,
    pub sector: u16,
}

#[derive(Clone, Debug, PartialEq)]
pub struct WadSector {
    pub floor: i16,
    pub ceiling: i16,
    pub floor_flat: String,
    pub ceiling_flat: String,
    pub light: i16,
    pub special: i16,
    pub tag: u16,
}

/// One map's records, as the WAD has them.
#[derive(Clone, Debug, PartialEq)]
pub struct WadMap {
    pub name: String,
    pub things: Vec<WadThing>,
    pub lines: Vec<WadLine>,
    pub sides: Vec<WadSide>,
    /// Map units: whole numbers within 16 bits in Doom's format (VERTEXES),
    /// any value in a UDMF map.
    pub vertices: Vec<(f64, f64)>,
    pub sectors: Vec<WadSector>,
}

impl Wad {
    /// The bytes of lump `lump` (one of [`MAP_LUMPS`]) of map `name`, or
    /// `None` when the map has no such lump; an error when there is no map.
    pub fn map_lump(&self, name: &str, lump: &str) -> Result<Option<&[u8]>, WadError> {
        let upper = name.to_ascii_uppercase();
        let marker = self.lumps.iter().rposition(|l| l.name == upper).ok_or_else(|| WadError::NoMap {
            path: self.path.clone(),
            name: name.to_string(),
            available: self.map_names().join(" "),
        })?;
        let found = self.lumps[marker + 1..]
            .iter()
            .take_while(|l| MAP_LUMPS.contains(&l.name.as_str()))
            .position(|l| l.name == lump);
        Ok(found.map(|k| self.bytes(marker + 1 + k)))
    }

    /// Reads map `name` (E1M4, MAP07; any case). Sidedef, vertex and sector
    /// indices are checked here, so everything after may index freely.
    pub fn map(&self, name: &str) -> Result<WadMap, WadError> {
        let upper = name.to_ascii_uppercase();
        let Some(marker) = self.map_names().iter().position(|m| *m == upper).and_then(|_| {
            // The last marker of that name, like any lump.
            self.lumps.iter().rposition(|l| l.name == upper)
        }) else {
            return Err(WadError::NoMap {
                path: self.path.clone(),
                name: name.to_string(),
                available: self.map_names().join(" "),
            });
        };
        if self.lumps.get(marker + 1).is_some_and(|l| l.name == super::udmf::TEXTMAP) {
            return Err(self.error(
                &format!("{upper}/{}", super::udmf::TEXTMAP),
                "a UDMF map, with no Doom-format records (UDMF maps can be drawn, imported and checked; the game does not play them yet)",
            ));
        }
        // A map's lumps are the run of known map lump names after its marker.
        let lump = |wanted: &str| -> Result<(&[u8], String), WadError> {
            let label = format!("{upper}/{wanted}");
            let found = self.lumps[marker + 1..]
                .iter()
                .take_while(|l| MAP_LUMPS.contains(&l.name.as_str()))
                .position(|l| l.name == wanted)
                .map(|k| self.bytes(marker + 1 + k));
            found.map(|b| (b, label.clone())).ok_or_else(|| self.missing(&label, ""))
        };
        let (bytes, label) = lump("VERTEXES")?;
        let vertices = records(self, &label, bytes, 4, |b| Ok((f64::from(i16_at(b, 0)), f64::from(i16_at(b, 2)))))?;
        let (bytes, label) = lump("SECTORS")?;
        let sectors = records(self, &label, bytes, 26, |b| {
            Ok(WadSector {
                floor: i16_at(b, 0),
                ceiling: i16_at(b, 2),
                floor_flat: lump_name(&b[4..12]),
                ceiling_flat: lump_name(&b[12..20]),
                light: i16_at(b, 20),
                special: i16_at(b, 22),
                tag: u16_at(b, 24),
            })
        })?;
        let (bytes, label) = lump("SIDEDEFS")?;
        let sides = records(self, &label, bytes, 30, |b| {
            let side = WadSide {
                x_offset: i16_at(b, 0),
                y_offset: i16_at(b, 2),
                upper: lump_name(&b[4..12]),
                lower: lump_name(&b[12..20]),
                middle: lump_name(&b[20..28]),
                sector: u16_at(b, 28),
            };
            if usize::from(side.sector) >= sectors.len() {
                return Err(format!("refers to sector {}, but there are {}", side.sector, sectors.len()));
            }
            Ok(side)
        })?;
        let (bytes, label) = lump("LINEDEFS")?;
        let lines = records(self, &label, bytes, 14, |b| {
            let side = |at| Some(u16_at(b, at)).filter(|&s| s != NO_SIDE);
            let line = WadLine {
                v1: u16_at(b, 0),
                v2: u16_at(b, 2),
                flags: u16_at(b, 4),
                special: u16_at(b, 6),
                tag: u16_at(b, 8),
                right: side(10),
                left: side(12),
            };
            for v in [line.v1, line.v2] {
                if usize::from(v) >= vertices.len() {
                    return Err(format!("refers to vertex {v}, but there are {}", vertices.len()));
                }
            }
            let Some(right) = line.right else {
                return Err("has no right sidedef (-1); every line needs one".into());
            };
            for s in [Some(right), line.left].into_iter().flatten() {
                if usize::from(s) >= sides.len() {
                    return Err(format!("refers to sidedef {s}, but there are {}", sides.len()));
                }
            }
            Ok(line)
        })?;
        let (bytes, label) = lump("THINGS")?;
        let things = records(self, &label, bytes, 10, |b| {
            Ok(WadThing {
                x: i16_at(b, 0),
                y: i16_at(b, 2),
                angle: i16_at(b, 4),
                kind: u16_at(b, 6),
                flags: u16_at(b, 8),
            })
        })?;
        Ok(WadMap { name: upper, things, lines, sides, vertices, sectors })
    }
}

/// Splits a lump into fixed-size records and decodes each; an error names
/// the lump and the record.
fn records<T>(
    wad: &Wad,
    label: &str,
    bytes: &[u8],
    size: usize,
    mut decode: impl FnMut(&[u8]) -> Result<T, String>,
) -> Result<Vec<T>, WadError> {
    if bytes.len() % size != 0 {
        return Err(wad.error(label, format!("{} bytes is not a whole number of {size}-byte records", bytes.len())));
    }
    bytes
        .chunks_exact(size)
        .enumerate()
        .map(|(k, b)| decode(b).map_err(|m| wad.error(label, format!("record {k} {m}"))))
        .collect()
}
