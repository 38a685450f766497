//! A compiled RON map (`bsp::CompiledMap`) turned into the [`Level`] the
//! simulation with Doom's arithmetic reads, so the project's own maps run in
//! the same game as Doom's: what `p_setup.c` would have loaded had a node
//! builder written the map out as a WAD. Hands the simulation a level and a
//! report of what Doom's numbers cannot say; [`sim_on_map`] starts a game on
//! it.
//!
//! What is built and how:
//! - vertices, heights and offsets in 16.16. A coordinate that is a multiple
//!   of 1/65536 converts exactly; any other is rounded to the nearest 16.16
//!   value and counted in the report. Things are stored as Doom stores them
//!   (`mapthing_t`, whole units), so their positions round to the unit.
//! - Doom's WAD format keeps coordinates in 16-bit integers and its
//!   arithmetic assumes them (`P_AproxDistance`, `FixedMul` of two
//!   coordinates, the blockmap's 16-bit offsets): a vertex, thing or height
//!   beyond ±32767 units is refused, and so is a map whose blockmap needs
//!   more than 65536 words; nothing is wrapped.
//! - specials as Doom's numbers where one says exactly the same: the
//!   reverse of `wad::specials` found by asking it for every vanilla number
//!   (1..=141 for lines, 0..=17 for sectors), so the two cannot drift
//!   apart. Any other special (its own speed or wait, a trigger or "who"
//!   no number pairs, a line teleport, a sector effect Doom's types cannot
//!   combine) becomes a generalized one: a negative number naming an entry
//!   of the level's table (`sim::generalized`), run by the same movers.
//!   Wall scrolls other than vanilla's 48 and floor conveyors go into that
//!   table too. Light transfers and translucency only change how a plane
//!   or a middle texture is drawn: the renderer reads them from the RON
//!   map it draws, whichever game runs it, so the level needs nothing.
//! - segs, subsectors and nodes from the compiled BSP in Doom's layout:
//!   nodes in post-order, so the root is the last node as `R_PointInSubsector`
//!   expects; a child with [`NF_SUBSECTOR`] is a leaf.
//! - a BLOCKMAP as Doom's node builders make it (origin at the lines' lowest
//!   x and y, 128-unit cells, each list `0, lines.., -1`), identical lists
//!   stored once as BSP 5.x and ZenNode store them, and a REJECT of zeros.

use std::collections::HashMap;
use std::fmt;
use std::sync::Arc;

use glam::DVec2;

use super::generalized::{Carry, GenLine, Generalized, SideScroll};
use super::level::{
    ml, Blockmap, Level, Line, NameId, Node, Sector, Seg, Side, Subsector, BOXBOTTOM, BOXLEFT, BOXRIGHT, BOXTOP,
    MAPBLOCKSHIFT, NF_SUBSECTOR, NO_TEXTURE,
};
use super::setup::Players;
use super::{Rules, Sim};
use crate::actors::ActorTable;
use crate::bsp::{Child, CompiledMap, LineSide};
use crate::fixed::{Angle, Fixed, FRACBITS, FRACUNIT};
use crate::geom::Aabb;
use crate::map::source::LineSpecialSource;
use crate::map::special::Scroll;
use crate::map::{LineSpecial, SectorSpecial, Side as MapSide, Who};
use crate::wad::level::WadThing;
use crate::wad::specials::{sector_special, translate, Effect};

/// The largest coordinate a WAD can store (`mapvertex_t` is two `short`s).
pub const MAX_COORD: f64 = 32767.0;
/// Blockmap offsets are 16-bit word indices (`P_BlockLinesIterator` reads
/// `blockmaplump[offset]` with `offset` a `short`, which vanilla's 64K
/// limit-removing ports reinterpret as unsigned): past this many words a
/// cell's list cannot be reached.
pub const MAX_BLOCKMAP_WORDS: usize = 65536;
/// Vanilla's line specials; Boom's start at 142.
const DOOM_LINE_SPECIALS: std::ops::RangeInclusive<u16> = 1..=141;
/// Vanilla's sector types.
const DOOM_SECTOR_TYPES: std::ops::RangeInclusive<i16> = 0..=17;
/// Doom's sky flat: the simulation asks for it by name (`skyflatnum`).
const SKY_FLAT: &str = "F_SKY1";
/// Thing option bits (`MTF_*`; 32 and 64 are Boom's, which vanilla ignores).
const MTF_EASY: u16 = 1;
const MTF_NORMAL: u16 = 2;
const MTF_HARD: u16 = 4;
const MTF_AMBUSH: u16 = 8;
const MTF_NOTSINGLE: u16 = 16;
const MTF_NOTDM: u16 = 32;
const MTF_NOTCOOP: u16 = 64;

#[derive(Debug, thiserror::Error)]
pub enum FromMapError {
    #[error(
        "{map}: {element} is at {value}, beyond ±{limit} units: Doom's map format stores 16-bit \
         coordinates and its 16.16 arithmetic assumes them"
    )]
    OutOfRange { map: String, element: String, value: f64, limit: f64 },
    #[error(
        "{map}: its blockmap needs {words} words ({width}x{height} cells of 128 units), more than the \
         {limit} that Doom's 16-bit blockmap offsets reach"
    )]
    Blockmap { map: String, words: usize, width: i64, height: i64, limit: usize },
    #[error("{map}: {element}: {what}")]
    Unsupported { map: String, element: String, what: String },
}

/// Something of the map that Doom's numbers do not carry: a special left
/// 0, a thing left out, an approximation.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Note {
    /// "line 17", "sector 3", "thing 9".
    pub element: String,
    pub what: String,
}

impl fmt::Display for Note {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.element, self.what)
    }
}

/// A level and what its conversion could not say in Doom's numbers.
#[derive(Clone, Debug)]
pub struct FromMap {
    pub level: Level,
    pub report: Vec<Note>,
}

/// The simulation's level of `compiled` (see the module's docs); the report
/// is dropped. [`level_and_report`] keeps it.
pub fn level_from_map(compiled: &CompiledMap, table: &ActorTable) -> Result<Level, FromMapError> {
    level_and_report(compiled, table).map(|converted| converted.level)
}

/// The simulation's level of `compiled` and the report of what Doom's
/// numbers do not carry.
pub fn level_and_report(compiled: &CompiledMap, table: &ActorTable) -> Result<FromMap, FromMapError> {
    let mut c = Convert::new(compiled);
    if compiled.grid.is_some() {
        // A grid map compiles to sectors like any other; nothing to refuse,
        // but its walls were never written as Doom lines, so say so.
        c.note("map", "a grid map: its cells became sectors and lines".into());
    }
    let vertices = c.vertices()?;
    let sectors = c.sectors()?;
    let (sides, lines) = c.sides_and_lines(&vertices)?;
    let things = c.things(table)?;
    let segs = c.segs(&lines)?;
    let subsectors = c.subsectors()?;
    let nodes = c.nodes()?;
    let blockmap = build_blockmap(&c.name, &lines)?;
    c.report_rounding();
    let generalized = std::mem::take(&mut c.generalized);
    let mut level = Level {
        name: c.name.clone(),
        vertices,
        sectors,
        sides,
        lines,
        segs,
        subsectors,
        nodes,
        blockmap,
        reject: Vec::new(),
        names: c.names,
        things,
        generalized,
        thing_fields: Vec::new(),
    };
    // Every line here has a front side (the map's lines always do).
    level.group_lines().map_err(|what| FromMapError::Unsupported {
        map: level.name.clone(),
        element: "lines".into(),
        what,
    })?;
    // Nothing rejected: every sight check is traced (correct, only slower).
    level.reject = vec![0; (level.sectors.len() * level.sectors.len()).div_ceil(8)];
    Ok(FromMap { level, report: c.report })
}

/// A UDMF map as a level: the geometry of its compiled conversion (our own
/// tree and blockmap: ZNODES are not read), and its things as the map
/// stores them (`records`, one for each of `udmf`'s things, in order) with
/// their ZDoom thing ids, specials and arguments. A map with only
/// deathmatch starts (ViZDoom's `cig`, `multi_duel`) gets player 1's
/// start at the first of them, as the importer gives its converted map.
pub fn level_from_udmf(
    compiled: &CompiledMap,
    table: &ActorTable,
    udmf: &crate::wad::udmf::UdmfMap,
    records: &crate::wad::level::WadMap,
) -> Result<Level, FromMapError> {
    let mut level = level_from_map(compiled, table)?;
    level.things = records.things.clone();
    level.thing_fields = udmf
        .things
        .iter()
        .map(|t| {
            let int = |v: i64| v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32;
            super::zdoom::ThingFields { tid: int(t.id), special: int(t.special), args: t.args.map(int) }
        })
        .collect();
    if !level.things.iter().any(|t| t.kind == 1) {
        if let Some(dm) = level.things.iter().find(|t| t.kind == 11).cloned() {
            level.things.push(WadThing { kind: 1, ..dm });
        }
    }
    Ok(level)
}

/// The conversion's state: the name table being filled and the report.
struct Convert<'a> {
    compiled: &'a CompiledMap,
    name: String,
    names: Vec<String>,
    report: Vec<Note>,
    /// Coordinates that were not multiples of 1/65536 (or, for things, of a
    /// unit) and were rounded.
    rounded: usize,
    /// The specials no vanilla number says, and the scrolls and conveyors.
    generalized: Generalized,
}

impl<'a> Convert<'a> {
    fn new(compiled: &'a CompiledMap) -> Convert<'a> {
        Convert {
            compiled,
            name: compiled.map.name.clone(),
            names: vec!["-".into()],
            report: Vec::new(),
            rounded: 0,
            generalized: Generalized::default(),
        }
    }

    fn note(&mut self, element: &str, what: String) {
        self.report.push(Note { element: element.to_string(), what });
    }

    fn report_rounding(&mut self) {
        if self.rounded > 0 {
            let what = format!(
                "{} coordinates were not exact in 16.16 (or, for things, whole units) and were rounded",
                self.rounded
            );
            self.note("map", what);
        }
    }

    fn out_of_range(&self, element: String, value: f64) -> FromMapError {
        FromMapError::OutOfRange { map: self.name.clone(), element, value, limit: MAX_COORD }
    }

    /// A map coordinate or height in 16.16, refused beyond ±32767 units.
    fn fixed(&mut self, units: f64, element: impl FnOnce() -> String) -> Result<Fixed, FromMapError> {
        if units.is_nan() || units.abs() > MAX_COORD {
            return Err(self.out_of_range(element(), units));
        }
        // Scaling by a power of two is exact in f64, so this is exact when
        // `units` is a multiple of 1/65536 and the nearest value otherwise.
        let scaled = units * f64::from(FRACUNIT);
        if scaled.fract() != 0.0 {
            self.rounded += 1;
        }
        Ok(Fixed(scaled.round() as i32))
    }

    /// The id of a texture or flat (`None` is Doom's `-`); the map's sky is
    /// Doom's `F_SKY1`.
    fn name_id(&mut self, name: Option<&str>) -> NameId {
        let Some(name) = name.filter(|n| !n.is_empty() && *n != "-") else {
            return NO_TEXTURE;
        };
        let upper = name.to_ascii_uppercase();
        let upper = if upper == crate::map::SKY { SKY_FLAT.to_string() } else { upper };
        match self.names.iter().position(|n| *n == upper) {
            Some(i) => NameId(i as u16),
            None => {
                self.names.push(upper);
                NameId((self.names.len() - 1) as u16)
            }
        }
    }

    fn vertices(&mut self) -> Result<Vec<(Fixed, Fixed)>, FromMapError> {
        let compiled = self.compiled;
        compiled
            .map
            .vertices
            .iter()
            .enumerate()
            .map(|(i, v)| Ok((self.fixed(v.x, || format!("vertex {i}"))?, self.fixed(v.y, || format!("vertex {i}"))?)))
            .collect()
    }

    fn sectors(&mut self) -> Result<Vec<Sector>, FromMapError> {
        let compiled = self.compiled;
        let map = &compiled.map;
        let mut out = Vec::with_capacity(map.sectors.len());
        for (i, s) in map.sectors.iter().enumerate() {
            let element = format!("sector {i}");
            let special = match doom_sector_type(&s.special) {
                Ok(n) => n,
                Err(_) => self.generalized.sector_number(s.special).ok_or_else(|| self.full(&element))?,
            };
            if let Some(c) = s.carry {
                let (dx, dy) =
                    (self.fixed(c.x, || format!("{element}'s carry"))?, self.fixed(c.y, || element.clone())?);
                self.generalized.carries.push(Carry { sector: i, dx, dy });
            }
            let floor = self.fixed(s.floor, || format!("{element}'s floor"))?;
            let ceiling = self.fixed(s.ceiling, || format!("{element}'s ceiling"))?;
            let pics = (self.name_id(s.floor_texture.as_deref()), self.name_id(s.ceiling_texture.as_deref()));
            out.push(Sector::stored(floor, ceiling, pics, i16::from(s.light), special, s.tag as i16));
        }
        Ok(out)
    }

    fn side(&mut self, side: &MapSide, element: &str) -> Result<Side, FromMapError> {
        Ok(Side {
            textureoffset: self.fixed(side.x_offset, || format!("{element}'s x offset"))?,
            rowoffset: self.fixed(side.y_offset, || format!("{element}'s y offset"))?,
            toptexture: self.name_id(side.upper.as_deref()),
            bottomtexture: self.name_id(side.lower.as_deref()),
            midtexture: self.name_id(side.middle.as_deref()),
            sector: side.sector,
        })
    }

    /// Sides in line order (front, then back), then the lines: the map's,
    /// then its trigger lines. A trigger line becomes what Doom's editors
    /// make of a walk-over line inside a room: two-sided, both sides in the
    /// sector its middle is in, no textures.
    fn sides_and_lines(&mut self, vertices: &[(Fixed, Fixed)]) -> Result<(Vec<Side>, Vec<Line>), FromMapError> {
        let compiled = self.compiled;
        let map = &compiled.map;
        let mut sides = Vec::with_capacity(map.lines.len() * 2);
        let mut lines = Vec::with_capacity(map.lines.len() + map.trigger_lines.len());
        for (i, l) in map.lines.iter().enumerate() {
            let element = format!("line {i}");
            let front = sides.len();
            sides.push(self.side(&l.front, &format!("{element}'s front"))?);
            let back = match &l.back {
                Some(b) => {
                    sides.push(self.side(b, &format!("{element}'s back"))?);
                    Some(sides.len() - 1)
                }
                None => None,
            };
            let mut flags = 0;
            // A one-sided line blocks in Doom whatever its flags say; Doom's
            // editors set ML_BLOCKING on it all the same.
            if l.flags.impassable || back.is_none() {
                flags |= ml::BLOCKING;
            }
            if back.is_some() {
                flags |= ml::TWOSIDED;
            }
            for (set, bit) in [
                (l.flags.block_monsters, ml::BLOCKMONSTERS),
                (l.flags.block_sound, ml::SOUNDBLOCK),
                (l.flags.upper_unpegged, ml::DONTPEGTOP),
                (l.flags.lower_unpegged, ml::DONTPEGBOTTOM),
            ] {
                if set {
                    flags |= bit;
                }
            }
            let (mut special, tag) = match &l.special {
                Some(s) => (self.line_number(&element, s)?, s.tag as i16),
                None => (0, 0),
            };
            special = self.scrolls(
                &element,
                special,
                [Some((front, l.front.scroll)), back.zip(l.back.as_ref().map(|b| b.scroll))],
            )?;
            let (v1, v2) = (vertices[l.from], vertices[l.to]);
            let sidenum = [Some(front), back];
            let sectors = sidenum.map(|s| s.map(|s| sides[s].sector));
            lines.push(Line::new((v1, v2), flags, special, tag, sidenum, sectors));
        }
        for (k, t) in map.trigger_lines.iter().enumerate() {
            let element = format!("trigger line {k}");
            let (a, b) = (map.vertices[t.from], map.vertices[t.to]);
            let Some(sector) = self.compiled.locate((a + b) / 2.0) else {
                return Err(FromMapError::Unsupported {
                    map: self.name.clone(),
                    element,
                    what: "its middle is not in the map, so it has no sector for its sides".into(),
                });
            };
            let blank = Side {
                textureoffset: Fixed::ZERO,
                rowoffset: Fixed::ZERO,
                toptexture: NO_TEXTURE,
                bottomtexture: NO_TEXTURE,
                midtexture: NO_TEXTURE,
                sector,
            };
            sides.push(blank.clone());
            sides.push(blank);
            let sidenum = [Some(sides.len() - 2), Some(sides.len() - 1)];
            let special = self.line_number(&element, &t.special)?;
            let (v1, v2) = (vertices[t.from], vertices[t.to]);
            let sectors = sidenum.map(|s| s.map(|s| sides[s].sector));
            lines.push(Line::new((v1, v2), ml::TWOSIDED, special, t.special.tag as i16, sidenum, sectors));
        }
        Ok((sides, lines))
    }

    /// The line special number of `special`: Doom's when one says exactly
    /// the same, else a generalized one.
    fn line_number(&mut self, element: &str, special: &LineSpecial) -> Result<i16, FromMapError> {
        if let Ok((number, None)) = doom_line_special(special) {
            return Ok(number as i16);
        }
        let mut rounded = 0;
        let mut out_of_range = None;
        let g = GenLine::of(special, |v| {
            if v.is_nan() || v.abs() > MAX_COORD {
                out_of_range = Some(v);
            }
            let scaled = v * f64::from(FRACUNIT);
            rounded += usize::from(scaled.fract() != 0.0);
            Fixed(scaled.round() as i32)
        });
        if let Some(v) = out_of_range {
            return Err(self.out_of_range(format!("{element}'s special"), v));
        }
        self.rounded += rounded;
        self.generalized.line_number(g).ok_or_else(|| self.full(element))
    }

    fn full(&self, element: &str) -> FromMapError {
        FromMapError::Unsupported {
            map: self.name.clone(),
            element: element.to_string(),
            what: "more distinct generalized specials than the 32768 negative special numbers".into(),
        }
    }

    /// The sides' scrolls: a front side scrolling one unit a tic towards
    /// its start, on a line with no other special, is Doom's 48; any other
    /// scroll is a generalized one (Doom scrolls only front sides, by one).
    fn scrolls(
        &mut self,
        element: &str,
        special: i16,
        sides: [Option<(usize, Scroll)>; 2],
    ) -> Result<i16, FromMapError> {
        let mut special = special;
        for (k, (side, scroll)) in sides.into_iter().flatten().enumerate() {
            if scroll == Scroll::default() {
                continue;
            }
            if k == 0 && special == 0 && scroll == (Scroll { x: 1.0, y: 0.0 }) {
                special = 48;
                continue;
            }
            let dx = self.fixed(scroll.x, || format!("{element}'s scroll"))?;
            let dy = self.fixed(scroll.y, || format!("{element}'s scroll"))?;
            self.generalized.scrolls.push(SideScroll { side, dx, dy });
        }
        Ok(special)
    }

    fn things(&mut self, table: &ActorTable) -> Result<Vec<WadThing>, FromMapError> {
        let compiled = self.compiled;
        let map = &compiled.map;
        let mut out = Vec::with_capacity(map.things.len());
        for (i, t) in map.things.iter().enumerate() {
            let element = format!("thing {i}");
            // A kind the table does not know is a decoration the renderer
            // draws by name (`statue`, `column`): nothing the game runs.
            let Some(index) = table.index(&t.kind) else {
                self.note(&element, format!("`{}` is not an actor of the table; left out", t.kind));
                continue;
            };
            let Some(kind) = super::info::editor_number(&table.actors[index], index) else {
                self.note(&element, format!("actor `{}` has no editor number and none is free; left out", t.kind));
                continue;
            };
            let x = self.thing_coord(t.pos.x, &element)?;
            let y = self.thing_coord(t.pos.y, &element)?;
            // Degrees counter-clockwise from east, as Doom's; Doom then
            // rounds down to a multiple of 45 when it spawns the thing.
            let angle = (t.angle.rem_euclid(360.0).round() as i32 % 360) as i16;
            let mut flags = 0;
            for (on, bit) in t.skills.iter().zip([MTF_EASY, MTF_NORMAL, MTF_HARD]) {
                if *on {
                    flags |= bit;
                }
            }
            if t.ambush {
                flags |= MTF_AMBUSH;
            }
            if t.multiplayer {
                flags |= MTF_NOTSINGLE;
            }
            for mode in &t.not_in {
                flags |= match mode {
                    crate::map::GameMode::Deathmatch => MTF_NOTDM,
                    crate::map::GameMode::Coop => MTF_NOTCOOP,
                };
            }
            out.push(WadThing { x, y, angle, kind, flags });
        }
        Ok(out)
    }

    fn thing_coord(&mut self, units: f64, element: &str) -> Result<i16, FromMapError> {
        if units.is_nan() || units.abs() > MAX_COORD {
            return Err(self.out_of_range(element.to_string(), units));
        }
        if units.fract() != 0.0 {
            self.rounded += 1;
        }
        Ok(units.round() as i16)
    }

    /// `P_LoadSegs`' result: each compiled seg with its line, side, offset
    /// along the side and angle (in the WAD's precision, a 16-bit binary
    /// angle). Split points keep their 16.16 position, where a WAD would
    /// have rounded them to a whole-unit vertex.
    fn segs(&mut self, lines: &[Line]) -> Result<Vec<Seg>, FromMapError> {
        let compiled = self.compiled;
        let bsp = &compiled.bsp;
        let mut out = Vec::with_capacity(bsp.segs.len());
        for (i, s) in bsp.segs.iter().enumerate() {
            let element = || format!("seg {i}");
            let v1 = (self.fixed(s.v1.x, element)?, self.fixed(s.v1.y, element)?);
            let v2 = (self.fixed(s.v2.x, element)?, self.fixed(s.v2.y, element)?);
            let side = usize::from(s.side == LineSide::Back);
            let line = &lines[s.line];
            let Some(sidedef) = line.sidenum[side] else {
                return Err(FromMapError::Unsupported {
                    map: self.name.clone(),
                    element: element(),
                    what: format!("it is the back of line {}, which has none", s.line),
                });
            };
            out.push(Seg {
                v1,
                v2,
                offset: Fixed::from_f64(s.offset),
                angle: seg_angle(v1, v2),
                sidedef,
                linedef: s.line,
                frontsector: s.front_sector,
                backsector: s.back_sector,
            });
        }
        Ok(out)
    }

    fn subsectors(&self) -> Result<Vec<Subsector>, FromMapError> {
        let leaves = &self.compiled.bsp.leaves;
        if leaves.len() > usize::from(NF_SUBSECTOR) {
            return Err(self.too_many("subsectors", leaves.len()));
        }
        for (i, leaf) in leaves.iter().enumerate() {
            if leaf.count == 0 {
                return Err(FromMapError::Unsupported {
                    map: self.name.clone(),
                    element: format!("leaf {i}"),
                    what: "it has no segs, and Doom finds a subsector's sector by its first".into(),
                });
            }
        }
        Ok(leaves
            .iter()
            .map(|leaf| Subsector { sector: leaf.sector, numlines: leaf.count, firstline: leaf.first })
            .collect())
    }

    fn too_many(&self, what: &str, count: usize) -> FromMapError {
        FromMapError::Unsupported {
            map: self.name.clone(),
            element: what.into(),
            what: format!("{count} of them; a node child is 15 bits (NF_SUBSECTOR is the 16th)"),
        }
    }

    /// The tree in post-order: children before parents, the root last.
    fn nodes(&mut self) -> Result<Vec<Node>, FromMapError> {
        let compiled = self.compiled;
        let bsp = &compiled.bsp;
        if bsp.nodes.len() >= usize::from(NF_SUBSECTOR) {
            return Err(self.too_many("nodes", bsp.nodes.len()));
        }
        match bsp.root {
            Child::Leaf(_) => return Ok(Vec::new()),
            Child::Node(_) => {}
        }
        let mut out = Vec::with_capacity(bsp.nodes.len());
        // An explicit stack: (node, children's numbers once known).
        let mut stack: Vec<(usize, Vec<u16>)> = vec![(root_index(bsp.root), Vec::new())];
        let mut fractional = 0;
        while let Some((n, done)) = stack.last_mut() {
            let node = &bsp.nodes[*n];
            if done.len() == 2 {
                let children = [done[0], done[1]];
                let n = *n;
                stack.pop();
                let (a, b) = (node.a, node.b);
                let x = self.fixed(a.x, || format!("node {n}"))?;
                let y = self.fixed(a.y, || format!("node {n}"))?;
                let dx = self.fixed(b.x, || format!("node {n}"))? - x;
                let dy = self.fixed(b.y, || format!("node {n}"))? - y;
                if dx.0 & (FRACUNIT - 1) != 0 || dy.0 & (FRACUNIT - 1) != 0 {
                    fractional += 1;
                }
                out.push(Node { x, y, dx, dy, bbox: [doom_box(node.bbox[0]), doom_box(node.bbox[1])], children });
                let number = (out.len() - 1) as u16;
                match stack.last_mut() {
                    Some((_, parent)) => parent.push(number),
                    None => break,
                }
                continue;
            }
            match node.children[done.len()] {
                Child::Leaf(leaf) => done.push(NF_SUBSECTOR | leaf as u16),
                Child::Node(child) => stack.push((child, Vec::new())),
            }
        }
        if fractional > 0 {
            let what = format!(
                "{fractional} partition lines run between vertices that are not whole units; Doom's side \
                 test drops the fraction of a partition's dx and dy, so points near them may fall on the wrong side"
            );
            self.note("nodes", what);
        }
        Ok(out)
    }
}

fn root_index(root: Child) -> usize {
    match root {
        Child::Node(i) | Child::Leaf(i) => i,
    }
}

/// A bounding box in Doom's order, rounded outwards to 16.16.
fn doom_box(b: Aabb) -> [Fixed; 4] {
    let down = |v: f64| Fixed((v * f64::from(FRACUNIT)).floor() as i32);
    let up = |v: f64| Fixed((v * f64::from(FRACUNIT)).ceil() as i32);
    let mut out = [Fixed::ZERO; 4];
    out[BOXTOP] = up(b.max.y);
    out[BOXBOTTOM] = down(b.min.y);
    out[BOXLEFT] = down(b.min.x);
    out[BOXRIGHT] = up(b.max.x);
    out
}

/// The binary angle of `v1 -> v2`, to the 16 bits a WAD's seg keeps (as
/// node builders compute it: from the floating-point direction).
fn seg_angle(v1: (Fixed, Fixed), v2: (Fixed, Fixed)) -> Angle {
    let (dx, dy) = (f64::from((v2.0 - v1.0).0), f64::from((v2.1 - v1.1).0));
    let turns = dy.atan2(dx) / std::f64::consts::TAU;
    let sixteen = (turns.rem_euclid(1.0) * 65536.0).round() as u32 & 0xffff;
    Angle(sixteen << FRACBITS)
}

/// Doom's sector type for a typed special: the vanilla type that
/// `wad::specials` reads as this very special. `Err` says why there is none.
pub fn doom_sector_type(special: &SectorSpecial) -> Result<i16, String> {
    if special.is_none() {
        return Ok(0);
    }
    DOOM_SECTOR_TYPES
        .into_iter()
        .find(|&n| sector_special(n).is_ok_and(|s| s == *special))
        .ok_or_else(|| format!("its special {special:?} has no vanilla sector type; left 0"))
}

/// Doom's line special for a typed one, and a note when the number only
/// approximates it (who can set it off differs). The number is the vanilla
/// one that `wad::specials` reads as this special with the line's tag;
/// with tag 0 a special that moves sectors must be a manual (D) one, since
/// a tagged number with tag 0 moves every untagged sector in Doom.
pub fn doom_line_special(special: &LineSpecial) -> Result<(u16, Option<String>), String> {
    let tag = special.tag;
    let wanted = |by: Who| {
        Effect::Special(LineSpecialSource {
            on: special.on,
            repeat: special.repeat,
            by,
            tag: i64::from(tag),
            action: special.action.clone(),
        })
    };
    // Manual specials act on the sector behind the line and so translate
    // with tag 0 whatever tag they are given.
    let manual = |n: u16| matches!(translate(n, 1), Ok(Effect::Special(s)) if s.tag == 0);
    let mut candidates: Vec<u16> = DOOM_LINE_SPECIALS.filter(|&n| manual(n)).collect();
    candidates.extend(DOOM_LINE_SPECIALS.filter(|&n| !manual(n)));
    let usable = |n: u16| tag != 0 || !special.action.moves_sectors() || manual(n);
    for by in [special.by, Who::Players, Who::Anyone, Who::Monsters] {
        let want = wanted(by);
        if let Some(&n) = candidates.iter().find(|&&n| usable(n) && translate(n, tag).is_ok_and(|e| e == want)) {
            let note = (by != special.by).then(|| {
                format!("Doom's special {n} is set off by {by:?}, the map's by {:?}; kept as {n}", special.by)
            });
            return Ok((n, note));
        }
    }
    Err(format!(
        "its special ({:?} {}, by {:?}, tag {tag}: {:?}) has no vanilla number; left 0",
        special.on,
        if special.repeat { "repeatable" } else { "once" },
        special.by,
        special.action
    ))
}

/// Doom's blockmap cell of a 16.16 coordinate, relative to the origin.
const BLOCK: i64 = 1 << MAPBLOCKSHIFT;

/// The BLOCKMAP of `lines` (see the module's docs). A line is listed in
/// every cell whose closed square its segment touches, boundaries included:
/// listing a line in one more cell costs a test, missing one lets bodies
/// through it.
pub fn build_blockmap(map: &str, lines: &[Line]) -> Result<Blockmap, FromMapError> {
    let unsupported =
        |what: String| FromMapError::Unsupported { map: map.to_string(), element: "blockmap".into(), what };
    if lines.len() >= 0xffff {
        return Err(unsupported(format!("{} lines; a list word is 16 bits and 0xffff ends it", lines.len())));
    }
    let points = || lines.iter().flat_map(|l| [l.v1, l.v2]);
    let (Some(min_x), Some(min_y)) = (points().map(|p| p.0 .0).min(), points().map(|p| p.1 .0).min()) else {
        return Err(unsupported("no lines".into()));
    };
    let max_x = points().map(|p| p.0 .0).max().unwrap_or(min_x);
    let max_y = points().map(|p| p.1 .0).max().unwrap_or(min_y);
    // The origin on a whole unit, as the header stores it.
    let org = (i64::from(min_x) >> FRACBITS << FRACBITS, i64::from(min_y) >> FRACBITS << FRACBITS);
    let width = ((i64::from(max_x) - org.0) >> MAPBLOCKSHIFT) + 1;
    let height = ((i64::from(max_y) - org.1) >> MAPBLOCKSHIFT) + 1;
    let cells = (width * height) as usize;
    if 4 + cells + 2 > MAX_BLOCKMAP_WORDS {
        let words = 4 + 3 * cells;
        return Err(FromMapError::Blockmap { map: map.into(), words, width, height, limit: MAX_BLOCKMAP_WORDS });
    }
    let mut lists: Vec<Vec<i16>> = vec![vec![0]; cells];
    for (i, line) in lines.iter().enumerate() {
        for (cx, cy) in cells_touched(line, org, width, height) {
            lists[(cy * width + cx) as usize].push(i as u16 as i16);
        }
    }
    let mut words: Vec<i16> = vec![(org.0 >> FRACBITS) as i16, (org.1 >> FRACBITS) as i16, width as i16, height as i16];
    words.resize(4 + cells, 0);
    let mut stored: HashMap<Vec<i16>, usize> = HashMap::new();
    for (cell, mut list) in lists.into_iter().enumerate() {
        list.push(-1);
        let at = match stored.get(&list) {
            Some(&at) => at,
            None => {
                let at = words.len();
                words.extend_from_slice(&list);
                stored.insert(list, at);
                at
            }
        };
        words[4 + cell] = at as u16 as i16;
    }
    if words.len() > MAX_BLOCKMAP_WORDS {
        let words = words.len();
        return Err(FromMapError::Blockmap { map: map.into(), words, width, height, limit: MAX_BLOCKMAP_WORDS });
    }
    Ok(Blockmap {
        orgx: Fixed(org.0 as i32),
        orgy: Fixed(org.1 as i32),
        width: width as i32,
        height: height as i32,
        words,
    })
}

/// The cells whose closed squares `line` touches: those its bounding box
/// reaches that have corners on both sides of its line, or on it (the
/// separating-axis test of a segment and a box, exact in 16.16 integers).
fn cells_touched(line: &Line, org: (i64, i64), width: i64, height: i64) -> Vec<(i64, i64)> {
    let (x1, y1) = (i64::from(line.v1.0 .0), i64::from(line.v1.1 .0));
    let (x2, y2) = (i64::from(line.v2.0 .0), i64::from(line.v2.1 .0));
    // Cell k's closed square is [k, k+1] blocks: a point touches cells
    // ceil(p) - 1 ..= floor(p).
    let range = |a: i64, b: i64, org: i64, n: i64| {
        let (lo, hi) = (a.min(b) - org, a.max(b) - org);
        (((lo + BLOCK - 1).div_euclid(BLOCK) - 1).max(0), hi.div_euclid(BLOCK).min(n - 1))
    };
    let (xl, xh) = range(x1, x2, org.0, width);
    let (yl, yh) = range(y1, y2, org.1, height);
    let side = |px: i64, py: i64| {
        let cross = i128::from(x2 - x1) * i128::from(py - y1) - i128::from(y2 - y1) * i128::from(px - x1);
        cross.signum()
    };
    let mut out = Vec::new();
    for cy in yl..=yh {
        for cx in xl..=xh {
            let (x0, y0) = (org.0 + cx * BLOCK, org.1 + cy * BLOCK);
            let corners = [side(x0, y0), side(x0 + BLOCK, y0), side(x0, y0 + BLOCK), side(x0 + BLOCK, y0 + BLOCK)];
            if corners.iter().any(|&s| s >= 0) && corners.iter().any(|&s| s <= 0) {
                out.push((cx, cy));
            }
        }
    }
    out
}

/// A game on a RON map's level ([`Sim::on_level`]; a RON map has no WAD
/// texture heights, so raise-to-texture floors stay put).
pub fn sim_on_map(level: Level, rules: Rules, players: Players, table: Arc<ActorTable>) -> Sim {
    Sim::on_level(level, rules, players, table, |_| {})
}

/// A point in 16.16 from map units, for the tests and tools that compare
/// the two point locations.
pub fn fixed_point(p: DVec2) -> (Fixed, Fixed) {
    (Fixed::from_f64(p.x), Fixed::from_f64(p.y))
}

#[cfg(test)]
#[path = "from_map_tests.rs"]
mod tests;
