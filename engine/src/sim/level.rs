//! A level as Doom's game logic sees it (`r_defs.h`), loaded from a WAD's
//! map lumps exactly as stored (`p_setup.c`): vertices, sectors, sides and
//! lines in 16.16 fixed point, and the WAD's own SEGS, SSECTORS, NODES,
//! BLOCKMAP and REJECT. Demos depend on every one of them: room4doom lost
//! sync by rebuilding the blockmap (its origin came out 8 units off) and by
//! skipping a short REJECT, so nothing here is rebuilt or tidied.
//!
//! Hands the simulation plain indices: a line's sectors, a sector's lines, a
//! subsector's sector, a node's children; `validcount`-style marks live in
//! the simulation's scratch state, not here.

use crate::fixed::{Angle, Fixed, FRACBITS};
use crate::wad::level::WadMap;
use crate::wad::{Wad, WadError};

/// Doom's `MAPBLOCKSHIFT`: blockmap cells are 128 units.
pub const MAPBLOCKSHIFT: u32 = FRACBITS + 7;
/// The largest thing radius Doom allows for in block boxes (`MAXRADIUS`).
pub const MAXRADIUS: Fixed = Fixed(32 << FRACBITS);
/// A node child with this bit is a subsector (`NF_SUBSECTOR`).
pub const NF_SUBSECTOR: u16 = 0x8000;

/// Bounding box sides, Doom's `BOXTOP`.. order.
pub const BOXTOP: usize = 0;
pub const BOXBOTTOM: usize = 1;
pub const BOXLEFT: usize = 2;
pub const BOXRIGHT: usize = 3;

/// Line flags (`ML_*`).
pub mod ml {
    pub const BLOCKING: u16 = 1;
    pub const BLOCKMONSTERS: u16 = 2;
    pub const TWOSIDED: u16 = 4;
    pub const DONTPEGTOP: u16 = 8;
    pub const DONTPEGBOTTOM: u16 = 16;
    pub const SECRET: u16 = 32;
    pub const SOUNDBLOCK: u16 = 64;
    pub const DONTDRAW: u16 = 128;
    pub const MAPPED: u16 = 256;
}

/// A texture or flat, by its index in the level's name table (equal names,
/// equal ids). `NO_TEXTURE` is Doom's `-` (texture 0).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
pub struct NameId(pub u16);

pub const NO_TEXTURE: NameId = NameId(0);

#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Sector {
    pub floorheight: Fixed,
    pub ceilingheight: Fixed,
    pub floorpic: NameId,
    pub ceilingpic: NameId,
    pub lightlevel: i16,
    pub special: i16,
    pub tag: i16,
    /// 0 = untraversed, 1 and 2 = sound traversed (`P_RecursiveSound`).
    pub soundtraversed: i32,
    /// The thing that made a sound here, for monsters to wake to.
    pub soundtarget: Option<super::MobjId>,
    /// Blockmap cells the sector's lines touch, grown by `MAXRADIUS`.
    pub blockbox: [i32; 4],
    /// The middle of the sector's bounding box: where its sounds come from.
    pub soundorg: (Fixed, Fixed),
    /// The thinker moving the floor or ceiling (a door, lift, floor,
    /// crusher), so no second one starts (`specialdata`).
    pub specialdata: Option<super::ThinkerId>,
    /// The sector's lines, in Doom's order (`P_GroupLines`).
    pub lines: Vec<usize>,
}

impl Sector {
    /// A sector as a map stores it (`mapsector_t`), with what play keeps
    /// beside it empty (`P_GroupLines` fills the lines, box and sound origin).
    pub fn stored(floor: Fixed, ceiling: Fixed, pics: (NameId, NameId), light: i16, special: i16, tag: i16) -> Sector {
        Sector {
            floorheight: floor,
            ceilingheight: ceiling,
            floorpic: pics.0,
            ceilingpic: pics.1,
            lightlevel: light,
            special,
            tag,
            soundtraversed: 0,
            soundtarget: None,
            blockbox: [0; 4],
            soundorg: (Fixed::ZERO, Fixed::ZERO),
            specialdata: None,
            lines: Vec::new(),
        }
    }
}

#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Side {
    pub textureoffset: Fixed,
    pub rowoffset: Fixed,
    pub toptexture: NameId,
    pub bottomtexture: NameId,
    pub midtexture: NameId,
    pub sector: usize,
}

/// Which way a line runs (`slopetype_t`), for the box-side test.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum SlopeType {
    Horizontal,
    Vertical,
    Positive,
    Negative,
}

#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Line {
    pub v1: (Fixed, Fixed),
    pub v2: (Fixed, Fixed),
    pub dx: Fixed,
    pub dy: Fixed,
    pub flags: u16,
    pub special: i16,
    pub tag: i16,
    /// Front and back sidedefs (`sidenum`); `None` where the WAD has -1.
    pub sidenum: [Option<usize>; 2],
    pub bbox: [Fixed; 4],
    pub slopetype: SlopeType,
    pub frontsector: Option<usize>,
    pub backsector: Option<usize>,
}

impl Line {
    /// A line as `P_LoadLineDefs` makes it from its ends: the deltas, the
    /// bounding box and the slope type, with `sectors` its front and back
    /// sectors (those of its sides).
    pub fn new(
        (v1, v2): ((Fixed, Fixed), (Fixed, Fixed)),
        flags: u16,
        special: i16,
        tag: i16,
        sidenum: [Option<usize>; 2],
        sectors: [Option<usize>; 2],
    ) -> Line {
        let (dx, dy) = (v2.0 - v1.0, v2.1 - v1.1);
        let slopetype = if dx.0 == 0 {
            SlopeType::Vertical
        } else if dy.0 == 0 {
            SlopeType::Horizontal
        } else if dy.fixed_div(dx).0 > 0 {
            SlopeType::Positive
        } else {
            SlopeType::Negative
        };
        let (left, right) = if v1.0 < v2.0 { (v1.0, v2.0) } else { (v2.0, v1.0) };
        let (bottom, top) = if v1.1 < v2.1 { (v1.1, v2.1) } else { (v2.1, v1.1) };
        Line {
            v1,
            v2,
            dx,
            dy,
            flags,
            special,
            tag,
            sidenum,
            bbox: [top, bottom, left, right],
            slopetype,
            frontsector: sectors[0],
            backsector: sectors[1],
        }
    }
}

#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Seg {
    pub v1: (Fixed, Fixed),
    pub v2: (Fixed, Fixed),
    pub offset: Fixed,
    pub angle: Angle,
    pub sidedef: usize,
    pub linedef: usize,
    pub frontsector: usize,
    pub backsector: Option<usize>,
}

#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Subsector {
    pub sector: usize,
    pub numlines: usize,
    pub firstline: usize,
}

#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Node {
    pub x: Fixed,
    pub y: Fixed,
    pub dx: Fixed,
    pub dy: Fixed,
    /// Bounding boxes of the right (0) and left (1) children.
    pub bbox: [[Fixed; 4]; 2],
    /// A child with [`NF_SUBSECTOR`] set is a subsector.
    pub children: [u16; 2],
}

/// The WAD's BLOCKMAP: an origin, a grid of 128-unit cells and, for each
/// cell, a list of lines. Vanilla's lists begin with a 0 that the iterator
/// takes for line 0 ("most demos go out of sync if we don't consider
/// linedef 0", dsda-doom), so the raw words are kept and walked as Doom
/// walks them.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Blockmap {
    pub orgx: Fixed,
    pub orgy: Fixed,
    pub width: i32,
    pub height: i32,
    /// The whole lump as 16-bit words (the header, offsets, then lists).
    pub words: Vec<i16>,
}

impl Blockmap {
    /// The lines of cell (`x`, `y`), as Doom's `P_BlockLinesIterator` reads
    /// them: from the cell's offset to the -1 that ends the list. Out of
    /// range cells and offsets give nothing.
    pub fn lines(&self, x: i32, y: i32) -> impl Iterator<Item = usize> + '_ {
        let cell = (x >= 0 && y >= 0 && x < self.width && y < self.height)
            .then(|| self.words.get(4 + (y * self.width + x) as usize))
            .flatten()
            .map(|&offset| offset as u16 as usize);
        let list = cell.and_then(|at| self.words.get(at..)).unwrap_or(&[]);
        list.iter().take_while(|&&w| w != -1).map(|&w| w as u16 as usize)
    }
}

/// The whole level.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Level {
    pub name: String,
    pub vertices: Vec<(Fixed, Fixed)>,
    pub sectors: Vec<Sector>,
    pub sides: Vec<Side>,
    pub lines: Vec<Line>,
    pub segs: Vec<Seg>,
    pub subsectors: Vec<Subsector>,
    pub nodes: Vec<Node>,
    pub blockmap: Blockmap,
    /// REJECT, padded as Chocolate Doom pads a short one.
    pub reject: Vec<u8>,
    /// Texture and flat names by [`NameId`] (0 is `-`).
    pub names: Vec<String>,
    /// The map's things as stored (`mapthing_t`).
    pub things: Vec<crate::wad::level::WadThing>,
    /// A RON map's specials that no vanilla number says (empty for a
    /// WAD's map): what the negative line and sector specials name, and the
    /// scrolls and conveyors ([`super::generalized`]).
    pub generalized: super::generalized::Generalized,
    /// A ZDoom map's thing ids, specials and arguments, by thing (empty
    /// for Doom's maps and RON maps).
    pub thing_fields: Vec<super::zdoom::ThingFields>,
}

#[derive(Debug, thiserror::Error)]
pub enum LevelError {
    #[error(transparent)]
    Wad(#[from] WadError),
    #[error("{path}: {lump}: {what}")]
    Lump { path: String, lump: String, what: String },
}

impl Level {
    /// Reads map `name` from `wad` as Doom's `P_SetupLevel` does.
    pub fn load(wad: &Wad, name: &str) -> Result<Level, LevelError> {
        let map = wad.map(name)?;
        let bad = |lump: &str, what: String| LevelError::Lump {
            path: wad.path.clone(),
            lump: format!("{}/{lump}", map.name),
            what,
        };
        let lump = |l: &str| -> Result<&[u8], LevelError> {
            wad.map_lump(&map.name, l)?.ok_or_else(|| bad(l, "missing (this engine needs the map's nodes)".into()))
        };
        let mut level = from_records(&map);
        level.subsectors = records(lump("SSECTORS")?, 4, |b| (u16_at(b, 0), u16_at(b, 2)))
            .map(|(n, first)| Subsector { sector: 0, numlines: n.into(), firstline: first.into() })
            .collect();
        level.nodes = records(lump("NODES")?, 28, |b| {
            let f = |at| Fixed::from_int(i16_at(b, at).into());
            Node {
                x: f(0),
                y: f(2),
                dx: f(4),
                dy: f(6),
                bbox: [[f(8), f(10), f(12), f(14)], [f(16), f(18), f(20), f(22)]],
                children: [u16_at(b, 24), u16_at(b, 26)],
            }
        })
        .collect();
        level.segs = load_segs(&level, lump("SEGS")?).map_err(|what| bad("SEGS", what))?;
        level.blockmap = load_blockmap(lump("BLOCKMAP")?).map_err(|what| bad("BLOCKMAP", what))?;
        level.check_tree().map_err(|what| bad("NODES", what))?;
        let total = level.group_lines().map_err(|what| bad("SSECTORS", what))?;
        level.reject = load_reject(lump("REJECT")?, level.sectors.len(), total);
        Ok(level)
    }

    /// Whether `a` can never see `b` by REJECT (sector indices).
    pub fn rejected(&self, a: usize, b: usize) -> bool {
        let bit = a * self.sectors.len() + b;
        self.reject.get(bit >> 3).is_some_and(|byte| byte & (1 << (bit & 7)) != 0)
    }

    /// Every node child and subsector range points inside the level.
    fn check_tree(&self) -> Result<(), String> {
        for (i, node) in self.nodes.iter().enumerate() {
            for child in node.children {
                let (index, len, what) = if child & NF_SUBSECTOR != 0 {
                    (usize::from(child & !NF_SUBSECTOR), self.subsectors.len(), "subsector")
                } else {
                    (usize::from(child), self.nodes.len(), "node")
                };
                if index >= len {
                    return Err(format!("node {i} has {what} {index} for a child, but there are {len}"));
                }
            }
        }
        for (i, ss) in self.subsectors.iter().enumerate() {
            if ss.numlines == 0 || ss.firstline + ss.numlines > self.segs.len() {
                return Err(format!(
                    "subsector {i} has segs {}..{}, of {}",
                    ss.firstline,
                    ss.firstline + ss.numlines,
                    self.segs.len()
                ));
            }
        }
        if self.nodes.is_empty() && self.subsectors.len() != 1 {
            return Err("no nodes, and not exactly one subsector".into());
        }
        Ok(())
    }

    /// `P_GroupLines`: each subsector's sector, each sector's lines, block
    /// box and sound origin. Returns `totallines` (REJECT's padding uses it).
    pub(crate) fn group_lines(&mut self) -> Result<usize, String> {
        for ss in &mut self.subsectors {
            ss.sector = self.sides[self.segs[ss.firstline].sidedef].sector;
        }
        let mut total = 0;
        for (i, line) in self.lines.iter().enumerate() {
            let front = line.frontsector.ok_or_else(|| format!("line {i} has no front sector"))?;
            self.sectors[front].lines.push(i);
            total += 1;
            if let Some(back) = line.backsector.filter(|&b| b != front) {
                self.sectors[back].lines.push(i);
                total += 1;
            }
        }
        let bm = &self.blockmap;
        for sector in &mut self.sectors {
            let mut bbox = clear_box();
            for &l in &sector.lines {
                let line = &self.lines[l];
                add_to_box(&mut bbox, line.v1);
                add_to_box(&mut bbox, line.v2);
            }
            sector.soundorg =
                (Fixed((bbox[BOXRIGHT] + bbox[BOXLEFT]).0 / 2), Fixed((bbox[BOXTOP] + bbox[BOXBOTTOM]).0 / 2));
            let block = |v: Fixed, org: Fixed| (v - org).0 >> MAPBLOCKSHIFT;
            sector.blockbox[BOXTOP] = block(bbox[BOXTOP] + MAXRADIUS, bm.orgy).min(bm.height - 1);
            sector.blockbox[BOXBOTTOM] = block(bbox[BOXBOTTOM] - MAXRADIUS, bm.orgy).max(0);
            sector.blockbox[BOXRIGHT] = block(bbox[BOXRIGHT] + MAXRADIUS, bm.orgx).min(bm.width - 1);
            sector.blockbox[BOXLEFT] = block(bbox[BOXLEFT] - MAXRADIUS, bm.orgx).max(0);
        }
        Ok(total)
    }

    /// The name of texture or flat `id`.
    pub fn name(&self, id: NameId) -> &str {
        self.names.get(usize::from(id.0)).map_or("-", String::as_str)
    }

    /// The id of a texture or flat name, if the level uses it.
    pub fn name_id(&self, name: &str) -> Option<NameId> {
        self.names.iter().position(|n| n.eq_ignore_ascii_case(name)).map(|i| NameId(i as u16))
    }
}

/// `M_ClearBox`.
pub fn clear_box() -> [Fixed; 4] {
    [Fixed::MIN, Fixed::MAX, Fixed::MAX, Fixed::MIN]
}

/// `M_AddToBox`: note Doom's `else if`, which a point can make matter only
/// in a box that was just cleared.
pub fn add_to_box(b: &mut [Fixed; 4], (x, y): (Fixed, Fixed)) {
    if x < b[BOXLEFT] {
        b[BOXLEFT] = x;
    } else if x > b[BOXRIGHT] {
        b[BOXRIGHT] = x;
    }
    if y < b[BOXBOTTOM] {
        b[BOXBOTTOM] = y;
    } else if y > b[BOXTOP] {
        b[BOXTOP] = y;
    }
}

/// Vertices, sectors, sides and lines from the decoded records
/// (`P_LoadVertexes`, `P_LoadSectors`, `P_LoadSideDefs`, `P_LoadLineDefs`).
fn from_records(map: &WadMap) -> Level {
    let mut names = vec!["-".to_string()];
    let mut id = |name: &str| {
        let upper = name.to_ascii_uppercase();
        if upper == "-" || upper.is_empty() {
            return NO_TEXTURE;
        }
        match names.iter().position(|n| *n == upper) {
            Some(i) => NameId(i as u16),
            None => {
                names.push(upper);
                NameId((names.len() - 1) as u16)
            }
        }
    };
    let fixed = |v: i16| Fixed::from_int(v.into());
    // Whole 16-bit numbers in Doom's format: exact.
    let vertices: Vec<(Fixed, Fixed)> =
        map.vertices.iter().map(|&(x, y)| (Fixed::from_f64(x), Fixed::from_f64(y))).collect();
    let sectors = map
        .sectors
        .iter()
        .map(|s| {
            let pics = (id(&s.floor_flat), id(&s.ceiling_flat));
            Sector::stored(fixed(s.floor), fixed(s.ceiling), pics, s.light, s.special, s.tag as i16)
        })
        .collect();
    let sides: Vec<Side> = map
        .sides
        .iter()
        .map(|s| Side {
            textureoffset: fixed(s.x_offset),
            rowoffset: fixed(s.y_offset),
            toptexture: id(&s.upper),
            bottomtexture: id(&s.lower),
            midtexture: id(&s.middle),
            sector: s.sector.into(),
        })
        .collect();
    let lines = map
        .lines
        .iter()
        .map(|l| {
            let ends = (vertices[usize::from(l.v1)], vertices[usize::from(l.v2)]);
            let sidenum = [l.right.map(usize::from), l.left.map(usize::from)];
            let sectors = sidenum.map(|s| s.map(|s| sides[s].sector));
            Line::new(ends, l.flags, l.special as i16, l.tag as i16, sidenum, sectors)
        })
        .collect();
    Level {
        name: map.name.clone(),
        vertices,
        sectors,
        sides,
        lines,
        segs: Vec::new(),
        subsectors: Vec::new(),
        nodes: Vec::new(),
        blockmap: Blockmap { orgx: Fixed::ZERO, orgy: Fixed::ZERO, width: 0, height: 0, words: Vec::new() },
        reject: Vec::new(),
        names,
        things: map.things.clone(),
        generalized: Default::default(),
        thing_fields: Vec::new(),
    }
}

/// `P_LoadSegs`. A two-sided line without a second side ("glass hack"
/// windows) gets no back sector here, where Chocolate points at sector 0's
/// memory; no Freedoom map has one.
fn load_segs(level: &Level, bytes: &[u8]) -> Result<Vec<Seg>, String> {
    let raw: Vec<[u16; 6]> = records(bytes, 12, |b| [0, 2, 4, 6, 8, 10].map(|at| u16_at(b, at))).collect();
    raw.iter()
        .enumerate()
        .map(|(i, &[v1, v2, angle, linedef, side, offset])| {
            let vertex = |v: u16| {
                level
                    .vertices
                    .get(usize::from(v))
                    .copied()
                    .ok_or_else(|| format!("seg {i} has vertex {v}, of {}", level.vertices.len()))
            };
            let line = level.lines.get(usize::from(linedef)).ok_or_else(|| format!("seg {i} has linedef {linedef}"))?;
            let side = usize::from(side & 1);
            let sidedef = line.sidenum[side].ok_or_else(|| format!("seg {i}: linedef {linedef} has no side {side}"))?;
            let backsector = if line.flags & ml::TWOSIDED != 0 {
                line.sidenum[side ^ 1].map(|s| level.sides[s].sector)
            } else {
                None
            };
            Ok(Seg {
                v1: vertex(v1)?,
                v2: vertex(v2)?,
                offset: Fixed::from_int(i32::from(offset as i16)),
                angle: Angle(u32::from(angle) << FRACBITS),
                sidedef,
                linedef: linedef.into(),
                frontsector: level.sides[sidedef].sector,
                backsector,
            })
        })
        .collect()
}

fn load_blockmap(bytes: &[u8]) -> Result<Blockmap, String> {
    let words: Vec<i16> = records(bytes, 2, |b| i16_at(b, 0)).collect();
    let [x, y, w, h] = match words.get(..4) {
        Some(&[x, y, w, h]) => [x, y, w, h],
        _ => return Err(format!("{} bytes, too short for the header", bytes.len())),
    };
    let (width, height) = (i32::from(w), i32::from(h));
    if width <= 0 || height <= 0 || words.len() < 4 + (width * height) as usize {
        return Err(format!("a {width}x{height} grid does not fit {} words", words.len()));
    }
    Ok(Blockmap { orgx: Fixed::from_int(x.into()), orgy: Fixed::from_int(y.into()), width, height, words })
}

/// `P_LoadReject` with Chocolate Doom's `PadRejectArray`: a short lump is
/// followed by what vanilla read past its end, the zone block header after
/// it (its size, a pointer, `PU_LEVEL` and the zone id), then zeros.
fn load_reject(bytes: &[u8], sectors: usize, total_lines: usize) -> Vec<u8> {
    let wanted = (sectors * sectors).div_ceil(8);
    let mut reject = bytes.to_vec();
    if reject.len() < wanted {
        let pad: [u32; 4] = [((total_lines as u32 * 4 + 3) & !3) + 24, 0, 50, 0x1d_4a11];
        let pad_bytes = pad.iter().flat_map(|w| w.to_le_bytes());
        let missing = wanted - reject.len();
        reject.extend(pad_bytes.take(missing));
        reject.resize(wanted, 0);
    }
    reject
}

fn records<'a, T>(bytes: &'a [u8], size: usize, decode: impl FnMut(&[u8]) -> T + 'a) -> impl Iterator<Item = T> + 'a {
    bytes.chunks_exact(size).map(decode)
}

fn u16_at(b: &[u8], at: usize) -> u16 {
    u16::from_le_bytes([b[at], b[at + 1]])
}

fn i16_at(b: &[u8], at: usize) -> i16 {
    i16::from_le_bytes([b[at], b[at + 1]])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_reject_is_padded_as_chocolate_pads_it() {
        let r = load_reject(&[0xff], 5, 10);
        assert_eq!(r.len(), 4);
        assert_eq!(r, [0xff, 64, 0, 0]);
        let r = load_reject(&[], 12, 3);
        assert_eq!(&r[..12], &[36, 0, 0, 0, 0, 0, 0, 0, 50, 0, 0, 0]);
        assert_eq!(&r[12..16], &[0x11, 0x4a, 0x1d, 0]);
        assert!(r[16..].iter().all(|&b| b == 0));
    }

    #[test]
    fn block_lists_start_with_doom_s_zero() {
        // A 2x1 map: cell 0 lists line 0 (the leading 0) then 3; cell 1 only the 0.
        let words = vec![0, 0, 2, 1, 6, 9, 0, 3, -1, 0, -1];
        let bm = Blockmap { orgx: Fixed::ZERO, orgy: Fixed::ZERO, width: 2, height: 1, words };
        assert_eq!(bm.lines(0, 0).collect::<Vec<_>>(), [0, 3]);
        assert_eq!(bm.lines(1, 0).collect::<Vec<_>>(), [0]);
        assert_eq!(bm.lines(2, 0).count(), 0);
        assert_eq!(bm.lines(-1, 0).count(), 0);
    }
}
