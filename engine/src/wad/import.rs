//! A WAD map to a Sightline map: [`convert`] turns the records of
//! [`super::level`] into a version-2 [`MapSource`] (the RON form), and
//! [`write_art`] writes the pictures the maps use as PNGs beside it.
//!
//! What is kept: geometry, sector heights, light and flats; side textures and
//! offsets; the pegging, two-sided and impassable flags; every line special
//! (as the typed special [`super::specials`] translates it, invisible
//! walk-over lines becoming trigger lines), sector special and tag; Boom's
//! scrollers, light transfers, translucency and conveyors; the sky per
//! episode; every thing, named by its type, with its skill and mode flags.
//! What cannot be translated is counted and listed in [`Report`], never
//! dropped silently.
//!
//! Doom's maps break rules our validator enforces, in ways Doom never minds;
//! [`convert`] repairs what it can and says so in [`Converted::repairs`]:
//! vertices at one position are merged (node builders leave copies), lines
//! of zero length are dropped, unused vertices and sectors are left out, and
//! a ceiling below its floor is raised to it.

use std::collections::hash_map::Entry;
use std::collections::{BTreeSet, HashMap};
use std::path::Path;

use super::art::{self, Image, Palette, TextureDef};
use super::level::{flags, WadLine, WadMap};
use super::specials::{sector_special, translate, Effect};
use super::{Wad, WadError};
use crate::actors::ActorTable;
use crate::map::source::{
    LineSource, LineSpecialSource, MapSource, SectorSource, SideSource, ThingSource, TriggerLineSource,
};
use crate::map::special::{Action, Activation, Scroll, SkillBand, Who};
use crate::map::validate::validate;
use crate::map::{GameMode, Problem, SpecialAt, SKY};

/// Doom's name for the sky flat: a ceiling (or floor) showing it shows the sky.
const SKY_FLAT: &str = "F_SKY1";

/// A converted map and the art it needs.
pub struct Converted {
    pub source: MapSource,
    /// Wall textures, flats and sprites by lump name (upper case).
    pub walls: BTreeSet<String>,
    pub flats: BTreeSet<String>,
    pub sprites: BTreeSet<String>,
    /// What had to change for the map to validate, one line each.
    pub repairs: Vec<String>,
    pub report: Report,
    pub links: Links,
}

/// How the WAD's numbering maps onto the converted map's: the simulation
/// with Doom's arithmetic keeps the WAD's, and is drawn on (and steered
/// through) the converted map.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Links {
    /// The converted map's sector for each of the WAD's sectors (`None` for
    /// a sector left out).
    pub sectors: Vec<Option<usize>>,
    /// The WAD's linedefs behind each of the converted map's lines (several
    /// when lines with the same ends were merged).
    pub lines: Vec<Vec<usize>>,
    /// The WAD's linedef behind each trigger line.
    pub triggers: Vec<usize>,
}

/// What became of the map's specials and things.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Report {
    /// Line specials translated (on lines and trigger lines), and line
    /// effects (scrollers, light transfers, translucency, conveyors).
    pub specials: usize,
    /// Sectors with a special.
    pub sector_specials: usize,
    /// Specials and sector types with no translation: `linedef 12: ...`.
    pub unsupported_specials: Vec<String>,
    /// Things of a type the actor table does not know.
    pub unknown_things: Vec<String>,
    /// Specials that Doom and Boom ignore (other ports' numbers), with why.
    pub ignored: Vec<String>,
    /// Specials dropped because they name nothing in the map (a tag no
    /// sector has, a teleporter with no destination), and locks with no key.
    pub dangling: Vec<String>,
}

/// What the WAD offers for maps to use: its palette, texture definitions,
/// flats and sprites, read once for all of its maps.
pub struct Art {
    pub palette: Palette,
    pub textures: HashMap<String, TextureDef>,
    /// The first texture of TEXTURE1 (AASHITTY in Doom): Doom treats index 0
    /// as "no texture", so naming it draws nothing.
    pub null_texture: Option<String>,
    pub flats: HashMap<String, usize>,
    pub sprites: HashMap<String, usize>,
}

impl Art {
    pub fn read(wad: &Wad) -> Result<Art, WadError> {
        let palette = Palette::read(wad)?;
        let textures = art::texture_defs(wad)?;
        let null_texture = wad.find("TEXTURE1").and_then(|i| {
            let b = wad.bytes(i);
            let at = usize::try_from(super::i32_at(b, 4)).ok().filter(|_| b.len() >= 8)?;
            b.get(at..at + 8).map(super::lump_name)
        });
        let index = |start: &[&str], end: &[&str]| -> Result<HashMap<String, usize>, WadError> {
            Ok(wad.namespace(start, end)?.into_iter().map(|i| (wad.lumps[i].name.clone(), i)).collect())
        };
        // PWADs often mark their namespaces FF_START and SS_START.
        let flats = index(&["F_START", "FF_START"], &["F_END", "FF_END"])?;
        let sprites = index(&["S_START", "SS_START"], &["S_END", "SS_END"])?;
        Ok(Art { palette, textures, null_texture, flats, sprites })
    }
}

/// The sky texture of map `name`, as Doom's G_InitNew picks it: SKY1..SKY4
/// by episode; in Doom II SKY1 up to MAP11, SKY2 to MAP20, SKY3 after.
pub fn sky_of(name: &str) -> &'static str {
    let n = name.as_bytes();
    if n.len() == 4 && n[0] == b'E' && n[2] == b'M' {
        return match n[1] {
            b'2' => "SKY2",
            b'3' => "SKY3",
            b'4' => "SKY4",
            _ => "SKY1",
        };
    }
    match name.strip_prefix("MAP").and_then(|k| k.parse::<u32>().ok()) {
        Some(k) if k >= 21 => "SKY3",
        Some(k) if k >= 12 => "SKY2",
        _ => "SKY1",
    }
}

/// A line as built, before the pass that turns invisible lines into
/// trigger lines: its source, and the WAD linedefs it stands for.
struct Built {
    line: LineSource,
    linedefs: Vec<usize>,
}

/// Effects of a line that act on other elements, applied once every line
/// and sector has its final number.
enum Deferred {
    LightTransfer { linedef: usize, floor: bool },
    Translucent { linedef: usize },
    Carry { linedef: usize },
    LineTeleport { linedef: usize },
}

/// Converts one map. Texture, flat and sprite names are checked against
/// `art`, so every name the map uses can be written by [`write_art`].
/// [`convert`] on a map's records in either format (`Wad::map_records`):
/// what the records could not say is reported, and a UDMF map's ZDoom
/// sector specials are put on the sectors they became.
pub fn convert_records(wad: &Wad, records: &super::udmf_records::Records, art: &Art) -> Result<Converted, WadError> {
    let mut converted = convert(wad, &records.map, art)?;
    converted.report.unsupported_specials.extend(records.unread.iter().cloned());
    for &(i, special) in &records.sector_specials {
        if let Some(j) = converted.links.sectors.get(i).copied().flatten() {
            converted.source.sectors[j].special = special;
        }
    }
    Ok(converted)
}

pub fn convert(wad: &Wad, map: &WadMap, art: &Art) -> Result<Converted, WadError> {
    let mut repairs = Vec::new();
    let mut report = Report::default();
    let mut walls = BTreeSet::new();
    let mut flats = BTreeSet::new();
    let mut sprites = BTreeSet::new();

    // Vertices: only those lines use, one per position.
    // Keyed by the coordinates' bits (`+ 0.0` makes -0 the same as 0).
    let mut vertex_of_position: HashMap<(u64, u64), usize> = HashMap::new();
    let mut vertices = Vec::new();
    let mut vertex_map = vec![usize::MAX; map.vertices.len()];
    let mut merged = 0;
    for l in &map.lines {
        for v in [l.v1, l.v2] {
            let v = usize::from(v);
            if vertex_map[v] != usize::MAX {
                continue;
            }
            let p = map.vertices[v];
            let next = vertices.len();
            let id = *vertex_of_position.entry(((p.0 + 0.0).to_bits(), (p.1 + 0.0).to_bits())).or_insert(next);
            if id == next {
                vertices.push(p);
            } else {
                merged += 1;
            }
            vertex_map[v] = id;
        }
    }
    if merged > 0 {
        repairs.push(format!("merged {merged} vertices that share a position with another"));
    }

    // Line specials, translated once per linedef.
    let mut effects: Vec<Option<Effect>> = vec![None; map.lines.len()];
    let mut deferred = Vec::new();
    for (i, l) in map.lines.iter().enumerate() {
        if l.special == 0 {
            continue;
        }
        match translate(l.special, l.tag) {
            Ok(Effect::Ignored(why)) => report.ignored.push(format!("linedef {i}: special {}: {why}", l.special)),
            Ok(mut effect) => {
                report.specials += 1;
                // Monsters never use a line marked secret (Doom's
                // P_UseSpecialLine): a hidden door stays the player's.
                if let Effect::Special(s) = &mut effect {
                    if l.flags & flags::SECRET != 0 && s.on == crate::map::special::Activation::Use {
                        s.by = crate::map::special::Who::Players;
                    }
                }
                deferred.extend(match effect {
                    Effect::LightTransfer { floor } => Some(Deferred::LightTransfer { linedef: i, floor }),
                    Effect::Translucent => Some(Deferred::Translucent { linedef: i }),
                    Effect::Carry => Some(Deferred::Carry { linedef: i }),
                    Effect::LineTeleport => Some(Deferred::LineTeleport { linedef: i }),
                    _ => None,
                });
                effects[i] = Some(effect);
            }
            Err(what) => report.unsupported_specials.push(format!("linedef {i}: {what}")),
        }
    }
    let special_of = |i: usize| match &effects[i] {
        Some(Effect::Special(s)) => Some(s.clone()),
        _ => None,
    };

    // Lines: two-sided only with the flag and a left side (Doom's P_LoadSegs).
    let sector_of = |l: &WadLine| {
        let right = map.sides[usize::from(l.right.unwrap_or(0))].sector;
        let left = l.left.filter(|_| l.flags & flags::TWO_SIDED != 0).map(|s| map.sides[usize::from(s)].sector);
        (right, left)
    };
    // A sector all of whose lines have it on both sides has no area of its
    // own: it is Doom's self-referencing sector trick (deep water, invisible
    // bridges), which relies on how Doom's node builder assigns subsectors.
    // Its lines draw nothing here, so they go (their specials, if any, stay
    // as trigger lines), and its area joins the sector around it.
    let mut only_self = vec![true; map.sectors.len()];
    for l in &map.lines {
        match sector_of(l) {
            (r, Some(b)) if r == b => {}
            (r, b) => {
                only_self[usize::from(r)] = false;
                if let Some(b) = b {
                    only_self[usize::from(b)] = false;
                }
            }
        }
    }
    let mut built: Vec<Built> = Vec::new();
    let mut dropped_twins: Vec<(usize, LineSource, usize)> = Vec::new();
    let mut trigger_lines: Vec<(TriggerLineSource, usize)> = Vec::new();
    let mut seen_ends: HashMap<(usize, usize), usize> = HashMap::new();
    for (i, l) in map.lines.iter().enumerate() {
        let (from, to) = (vertex_map[usize::from(l.v1)], vertex_map[usize::from(l.v2)]);
        if from == to {
            repairs.push(format!("dropped linedef {i}: zero length"));
            if effects[i].is_some() {
                report.dangling.push(format!("linedef {i}: its special is lost with the zero-length line"));
            }
            continue;
        }
        if let (r, Some(_)) = sector_of(l) {
            if only_self[usize::from(r)] {
                match special_of(i) {
                    Some(special) => {
                        trigger_lines.push((TriggerLineSource { from: from as i64, to: to as i64, special }, i));
                        repairs.push(format!(
                            "linedef {i} borders only self-referencing sector {r}: kept as a trigger line"
                        ));
                    }
                    None => repairs.push(format!("dropped linedef {i}: it only borders self-referencing sector {r}")),
                }
                continue;
            }
        }
        let duplicate = match seen_ends.entry((from.min(to), from.max(to))) {
            Entry::Occupied(first) => Some(*first.get()),
            Entry::Vacant(slot) => {
                slot.insert(built.len());
                None
            }
        };
        let right = &map.sides[usize::from(l.right.unwrap_or(0))];
        let left = l.left.filter(|_| l.flags & flags::TWO_SIDED != 0).map(|s| &map.sides[usize::from(s)]);
        let mut side = |s: &super::level::WadSide, which: &str| -> Result<SideSource, WadError> {
            let mut texture = |name: &str, part: &str| -> Result<Option<String>, WadError> {
                if name == "-" || name.is_empty() || art.null_texture.as_deref() == Some(name) {
                    return Ok(None);
                }
                // A flat on a wall, as ZDoom allows (the art library
                // draws either kind on either surface).
                if art.textures.contains_key(name) {
                    walls.insert(name.to_string());
                } else if art.flats.contains_key(name) {
                    flats.insert(name.to_string());
                } else {
                    return Err(wad.error(
                        &format!("{}/SIDEDEFS", map.name),
                        format!("linedef {i} {which} side {part} texture {name:?} is not in TEXTURE1 or TEXTURE2 (nor a flat)"),
                    ));
                }
                Ok(Some(name.to_string()))
            };
            Ok(SideSource {
                sector: i64::from(s.sector),
                upper: texture(&s.upper, "upper")?,
                middle: texture(&s.middle, "middle")?,
                lower: texture(&s.lower, "lower")?,
                x_offset: f64::from(s.x_offset),
                y_offset: f64::from(s.y_offset),
                scroll: None,
            })
        };
        let mut front = side(right, "right")?;
        let back = left.map(|s| side(s, "left")).transpose()?;
        if let Some(Effect::Scroll(scroll)) = effects[i] {
            front.scroll = Some(scroll);
        }
        let line = LineSource {
            from: from as i64,
            to: to as i64,
            front,
            back,
            upper_unpegged: l.flags & flags::UPPER_UNPEGGED != 0,
            lower_unpegged: l.flags & flags::LOWER_UNPEGGED != 0,
            impassable: l.flags & flags::BLOCKING != 0,
            block_monsters: l.flags & flags::BLOCK_MONSTERS != 0,
            block_sound: l.flags & flags::BLOCK_SOUND != 0,
            special: special_of(i),
            ..LineSource::default()
        };
        match duplicate {
            None => built.push(Built { line, linedefs: vec![i] }),
            Some(k) => match merge(&built[k].line, &line) {
                Some(merged) => {
                    if built[k].line.special.is_some() && line.special.is_some() {
                        report.dangling.push(format!(
                            "linedef {i}: merged into a line with the same ends that has a special of its own; its special is lost"
                        ));
                    }
                    repairs.push(format!("merged linedef {i} into the line with the same end points"));
                    built[k].line = merged;
                    built[k].linedefs.push(i);
                }
                None => {
                    repairs.push(format!("dropped linedef {i}: it has the same end points as another line"));
                    dropped_twins.push((k, line, i));
                }
            },
        }
    }
    // Two one-sided lines over each other, facing opposite ways into the
    // same sector: one of them faces out of it (an editor's leftover, which
    // ZDoom never looks at). Keep the one that closes the sector's outline.
    for (k, line, i) in dropped_twins {
        if !closes_outline(&built, k, &built[k].line) && closes_outline(&built, k, &line) {
            let dropped = format!("dropped linedef {i}: it has the same end points as another line");
            repairs.retain(|r| *r != dropped);
            repairs.push(format!(
                "kept linedef {i} instead of linedef {}: it has the same end points and closes sector {}'s outline",
                built[k].linedefs[0], line.front.sector
            ));
            built[k] = Built { line, linedefs: vec![i] };
        }
    }

    // Lines that draw nothing and block nothing: trigger lines if they have
    // a special, else gone.
    let mut lines = Vec::new();
    let mut line_of_linedef: Vec<Option<usize>> = vec![None; map.lines.len()];
    let mut line_linedefs: Vec<Vec<usize>> = Vec::new();
    let mut invisible = 0;
    for b in built {
        if is_invisible(&b.line) {
            match b.line.special {
                Some(special) => {
                    let (from, to) = (b.line.from, b.line.to);
                    trigger_lines.push((TriggerLineSource { from, to, special }, b.linedefs[0]));
                }
                None => invisible += 1,
            }
            continue;
        }
        for &d in &b.linedefs {
            line_of_linedef[d] = Some(lines.len());
        }
        lines.push(b.line);
        line_linedefs.push(b.linedefs);
    }
    if invisible > 0 {
        repairs.push(format!(
            "dropped {invisible} lines with the same sector on both sides that draw nothing, block nothing and do nothing"
        ));
    }

    // Sectors: only those some side faces, renumbered.
    let mut used_sectors = vec![false; map.sectors.len()];
    for side in lines.iter().flat_map(|l| std::iter::once(&l.front).chain(&l.back)) {
        used_sectors[side.sector as usize] = true;
    }
    let mut sector_map = vec![usize::MAX; map.sectors.len()];
    let mut sectors = Vec::new();
    for (i, s) in map.sectors.iter().enumerate() {
        if !used_sectors[i] {
            repairs.push(format!("left out sector {i}: no side faces it"));
            continue;
        }
        sector_map[i] = sectors.len();
        let mut flat = |name: &str, which: &str| -> Result<Option<String>, WadError> {
            if name == SKY_FLAT {
                return Ok(Some(SKY.to_string()));
            }
            // A wall texture on a floor, as ZDoom allows.
            if art.flats.contains_key(name) {
                flats.insert(name.to_string());
            } else if art.textures.contains_key(name) {
                walls.insert(name.to_string());
            } else {
                return Err(wad.error(
                    &format!("{}/SECTORS", map.name),
                    format!("sector {i} {which} flat {name:?} is not between F_START and F_END (nor a wall texture)"),
                ));
            }
            Ok(Some(name.to_string()))
        };
        let ceiling = if s.ceiling < s.floor {
            repairs.push(format!("sector {i}: raised its ceiling {} to its floor {}", s.ceiling, s.floor));
            s.floor
        } else {
            s.ceiling
        };
        let special = match sector_special(s.special) {
            Ok(special) => special,
            Err(what) => {
                report.unsupported_specials.push(format!("sector {i}: {what}"));
                Default::default()
            }
        };
        report.sector_specials += usize::from(s.special != 0);
        sectors.push(SectorSource {
            floor: f64::from(s.floor),
            ceiling: f64::from(ceiling),
            light: i64::from(s.light.clamp(0, 255)),
            floor_texture: flat(&s.floor_flat, "floor")?,
            ceiling_texture: flat(&s.ceiling_flat, "ceiling")?,
            tag: i64::from(s.tag),
            special,
            ..SectorSource::default()
        });
    }
    for line in &mut lines {
        for side in [Some(&mut line.front), line.back.as_mut()].into_iter().flatten() {
            side.sector = sector_map[side.sector as usize] as i64;
        }
    }
    apply_deferred(map, &deferred, &line_of_linedef, &sector_map, &mut lines, &mut sectors, &mut report);

    let things = convert_things(map, art, &mut sprites, &mut report, &mut repairs)
        .map_err(|message| wad.error(&format!("{}/THINGS", map.name), message))?;
    let uses_sky =
        sectors.iter().any(|s| [&s.floor_texture, &s.ceiling_texture].iter().any(|t| t.as_deref() == Some(SKY)));
    let sky = uses_sky.then(|| sky_of(&map.name).to_string());
    if let Some(sky) = &sky {
        if !art.textures.contains_key(sky) {
            return Err(wad.missing(sky, &format!(" (the sky of {}, a texture in TEXTURE1)", map.name)));
        }
        walls.insert(sky.clone());
    }
    let (trigger_lines, mut trigger_linedefs): (Vec<_>, Vec<_>) = trigger_lines.into_iter().unzip();
    let mut source = MapSource {
        version: 2,
        name: map.name.clone(),
        vertices,
        sectors,
        lines,
        things,
        sky,
        trigger_lines,
        ..MapSource::default()
    };
    move_start_off_lines(&mut source, &mut repairs);
    reassign_misplaced_lines(&mut source, &mut repairs);
    drop_dangling_specials(&mut source, &mut trigger_linedefs, &mut report);
    let sector_map = sector_map.iter().map(|&s| (s != usize::MAX).then_some(s)).collect();
    let links = Links { sectors: sector_map, lines: line_linedefs, triggers: trigger_linedefs };
    Ok(Converted { source, walls, flats, sprites, repairs, report, links })
}

/// Does a line draw nothing and block nothing: the same sector on both
/// sides, no middle texture, not impassable? Doom's maps use such lines as
/// walk-over triggers; they may cross other lines (MAP20 of Freedoom 2
/// raises a floor with two that cut across rooms) or lie in another sector
/// than they name. Doom does not mind; our validator does, and the renderer
/// would only walk them for nothing. With a special they become trigger lines.
fn is_invisible(l: &LineSource) -> bool {
    l.back.as_ref().is_some_and(|b| b.sector == l.front.sector && b.middle.is_none())
        && l.front.middle.is_none()
        && !l.impassable
}

/// The line effects that reach other elements: light transfers and
/// conveyors to the tagged sectors, translucency to the tagged lines, line
/// teleporters to their exit line.
fn apply_deferred(
    map: &WadMap,
    deferred: &[Deferred],
    line_of_linedef: &[Option<usize>],
    sector_map: &[usize],
    lines: &mut [LineSource],
    sectors: &mut [SectorSource],
    report: &mut Report,
) {
    let tagged_sectors = |tag: u16| -> Vec<usize> {
        (0..map.sectors.len())
            .filter(|&s| map.sectors[s].tag == tag && sector_map[s] != usize::MAX)
            .map(|s| sector_map[s])
            .collect()
    };
    let front_sector =
        |d: usize| sector_map[usize::from(map.sides[usize::from(map.lines[d].right.unwrap_or(0))].sector)];
    for effect in deferred {
        match *effect {
            Deferred::LightTransfer { linedef, floor } => {
                let from = front_sector(linedef);
                for s in tagged_sectors(map.lines[linedef].tag) {
                    let slot = if floor { &mut sectors[s].floor_light } else { &mut sectors[s].ceiling_light };
                    *slot = (from != usize::MAX).then_some(from as i64);
                }
            }
            Deferred::Carry { linedef } => {
                let l = &map.lines[linedef];
                let (a, b) = (map.vertices[usize::from(l.v1)], map.vertices[usize::from(l.v2)]);
                // Boom's carry: the line's vector / 32, times 3/32 per tick.
                let k = 3.0 / 1024.0;
                let carry = Scroll { x: (b.0 - a.0) * k, y: (b.1 - a.1) * k };
                for s in tagged_sectors(l.tag) {
                    sectors[s].carry = Some(carry);
                }
            }
            Deferred::Translucent { linedef } => {
                let tag = map.lines[linedef].tag;
                let targets: Vec<usize> = if tag == 0 {
                    vec![linedef]
                } else {
                    (0..map.lines.len()).filter(|&d| map.lines[d].tag == tag).collect()
                };
                for d in targets {
                    if let Some(k) = line_of_linedef[d] {
                        lines[k].translucent = true;
                    }
                }
            }
            Deferred::LineTeleport { linedef } => {
                let tag = map.lines[linedef].tag;
                let exit = (0..map.lines.len()).find(|&d| {
                    d != linedef
                        && tag != 0
                        && map.lines[d].tag == tag
                        && map.lines[d].left.is_some()
                        && line_of_linedef[d].is_some()
                });
                match (line_of_linedef[linedef], exit.and_then(|d| line_of_linedef[d])) {
                    (Some(k), Some(to)) => {
                        lines[k].special = Some(LineSpecialSource {
                            on: Activation::Walk,
                            repeat: true,
                            by: Who::Anyone,
                            tag: 0,
                            action: Action::LineTeleport { to },
                        });
                    }
                    _ => report
                        .dangling
                        .push(format!("linedef {linedef}: line teleporter with no exit line tagged {tag}")),
                }
            }
        }
    }
}

/// Every thing, named by its type (player 1's start first: the validator
/// takes the first), with its skill bands and mode flags; the sprite of
/// each type's first frame is added to `sprites`.
fn convert_things(
    map: &WadMap,
    art: &Art,
    sprites: &mut BTreeSet<String>,
    report: &mut Report,
    repairs: &mut Vec<String>,
) -> Result<Vec<ThingSource>, String> {
    const EASY: u16 = 0x0001;
    const MEDIUM: u16 = 0x0002;
    const HARD: u16 = 0x0004;
    const AMBUSH: u16 = 0x0008;
    const MULTIPLAYER: u16 = 0x0010;
    const NOT_DEATHMATCH: u16 = 0x0020;
    const NOT_COOP: u16 = 0x0040;
    const DEATHMATCH_START: u16 = 11;
    let types = ActorTable::active();
    let mut things = Vec::new();
    for (i, t) in map.things.iter().enumerate() {
        let Some(ty) = types.by_doomednum(t.kind) else {
            // ZDoom's things we know and do not read are named.
            let known = crate::actors::zdoom::unread_thing(t.kind).map(|n| format!(" (ZDoom's {n}, not read)"));
            report.unknown_things.push(format!(
                "thing {i}: type {}{} at ({}, {})",
                t.kind,
                known.unwrap_or_default(),
                t.x,
                t.y
            ));
            continue;
        };
        if let Some(lump) = types.first_frame(ty).and_then(|stem| find_sprite(art, &stem)) {
            sprites.insert(lump);
        }
        let bands = [(EASY, SkillBand::Easy), (MEDIUM, SkillBand::Medium), (HARD, SkillBand::Hard)];
        let mut not_in = Vec::new();
        if t.flags & NOT_DEATHMATCH != 0 {
            not_in.push(GameMode::Deathmatch);
        }
        if t.flags & NOT_COOP != 0 {
            not_in.push(GameMode::Coop);
        }
        let thing = ThingSource {
            kind: ty.name.clone(),
            x: f64::from(t.x),
            y: f64::from(t.y),
            angle: f64::from(t.angle),
            skills: bands.iter().filter(|(bit, _)| t.flags & bit != 0).map(|&(_, b)| b).collect(),
            ambush: t.flags & AMBUSH != 0,
            multiplayer: t.flags & MULTIPLAYER != 0,
            not_in,
        };
        if t.kind == 1 && !things.iter().any(|t: &ThingSource| t.kind == crate::map::PLAYER_START) {
            things.insert(0, thing);
        } else {
            things.push(thing);
        }
    }
    if !things.first().is_some_and(|t| t.kind == crate::map::PLAYER_START) {
        // A deathmatch map (ViZDoom's cig and multi_duel) may have only
        // deathmatch starts: the first one stands in, as a deathmatch
        // game would put the player there.
        let deathmatch = types.by_doomednum(DEATHMATCH_START).map(|t| t.name.clone());
        let Some(first) = things.iter().find(|t| Some(&t.kind) == deathmatch.as_ref()) else {
            return Err("no player 1 start (thing type 1) and no deathmatch start (type 11)".into());
        };
        let start = ThingSource { kind: crate::map::PLAYER_START.to_string(), ..first.clone() };
        repairs
            .push(format!("no player 1 start: the first deathmatch start, at ({}, {}), stands in", start.x, start.y));
        things.insert(0, start);
    }
    Ok(things)
}

/// Doom does not mind a start exactly on a line; our validator does (which
/// sector is it in?). Step off it by a unit, as a player would on moving.
fn move_start_off_lines(source: &mut MapSource, repairs: &mut Vec<String>) {
    let (vertices, lines) = (&source.vertices, &source.lines);
    let on_line = |x: f64, y: f64| {
        lines.iter().any(|l| {
            let (a, b) = (vertices[l.from as usize], vertices[l.to as usize]);
            let cross = (b.0 - a.0) * (y - a.1) - (b.1 - a.1) * (x - a.0);
            cross == 0.0 && x >= a.0.min(b.0) && x <= a.0.max(b.0) && y >= a.1.min(b.1) && y <= a.1.max(b.1)
        })
    };
    let start = &mut source.things[0];
    if on_line(start.x, start.y) {
        let (x, y) = (start.x, start.y);
        if let Some((dx, dy)) =
            [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)].into_iter().find(|(dx, dy)| !on_line(x + dx, y + dy))
        {
            start.x += dx;
            start.y += dy;
            repairs.push(format!("moved the player start off the line it stood on, from ({x}, {y})"));
        }
    }
}

/// Specials that name nothing the map has (a tag no sector has, a
/// teleporter with no destination, a manual special on a one-sided line)
/// are dropped, and a lock whose key no thing gives is taken off: Doom
/// would do nothing, or crash, or never open. Each is listed.
/// `trigger_linedefs` (each trigger line's linedef) loses what the trigger
/// lines lose.
fn drop_dangling_specials(source: &mut MapSource, trigger_linedefs: &mut Vec<usize>, report: &mut Report) {
    for _ in 0..2 {
        let Err(problems) = validate(source) else { return };
        let mut changed = false;
        for p in problems {
            let (at, why) = match &p {
                Problem::TagMatchesNothing { at, .. }
                | Problem::NoBackSector { at, .. }
                | Problem::NoTeleportDestination { at, .. }
                | Problem::BadTeleportLine { at, .. } => (*at, "dropped"),
                Problem::MissingKey { at, .. } => (*at, "unlocked"),
                _ => continue,
            };
            let special = match at {
                SpecialAt::Line(i) => source.lines.get_mut(i).and_then(|l| l.special.as_mut()),
                SpecialAt::TriggerLine(i) => source.trigger_lines.get_mut(i).map(|t| &mut t.special),
            };
            let Some(special) = special else { continue };
            if why == "unlocked" {
                if let Action::Door { key, .. } = &mut special.action {
                    *key = None;
                }
            } else {
                special.action = Action::Exit;
                special.on = Activation::Shoot;
            }
            report.dangling.push(format!("{p} ({why})"));
            changed = true;
        }
        // Dropped specials were marked above; remove them now that the
        // problems' line numbers no longer matter.
        for l in &mut source.lines {
            if l.special.as_ref().is_some_and(is_marked) {
                l.special = None;
            }
        }
        let kept: Vec<bool> = source.trigger_lines.iter().map(|t| !is_marked(&t.special)).collect();
        let (mut a, mut b) = (kept.iter(), kept.iter());
        source.trigger_lines.retain(|_| a.next() == Some(&true));
        trigger_linedefs.retain(|_| b.next() == Some(&true));
        if !changed {
            return;
        }
    }
}

/// A special [`drop_dangling_specials`] marked for removal (an exit set off
/// by a shot: no translation makes one).
fn is_marked(s: &LineSpecialSource) -> bool {
    s.action == Action::Exit && s.on == Activation::Shoot
}

/// A line with one sector on both sides lying inside another sector (a
/// mapper's slip Doom forgives: MAP20 of Freedoom 2 has a grate line naming
/// the sector of a pillar next to it) is given the sector it lies in, as the
/// validator finds it. Anything else the validator says is left for it to
/// report.
fn reassign_misplaced_lines(source: &mut MapSource, repairs: &mut Vec<String>) {
    // Each round fixes every such line the validator names; a fix cannot
    // create a new mismatch elsewhere, but two rounds cost nothing to allow.
    for _ in 0..2 {
        let Err(problems) = validate(source) else { return };
        let mut fixed = false;
        for p in problems {
            let Problem::SideMismatch { line, found, .. } = p else { continue };
            let ([sector], Some(l)) = (found.as_slice(), source.lines.get_mut(line)) else { continue };
            let sector = *sector as i64;
            let Some(back) = l.back.as_mut().filter(|b| b.sector == l.front.sector && b.sector != sector) else {
                continue;
            };
            repairs
                .push(format!("line {line}: named sector {} on both sides but lies in sector {sector}", back.sector));
            back.sector = sector;
            l.front.sector = sector;
            fixed = true;
        }
        if !fixed {
            return;
        }
    }
}

/// Two lines with the same end points as one. Each side is an edge of its
/// sector's boundary, directed with the sector on its right; a sector with
/// edges both ways along the line is on both sides, so those cancel. What is
/// left, at most one edge each way, is the line. `None` when more is left
/// (then no single line says the same).
/// Does `line`, standing in `built[k]`'s place, leave each sector it borders
/// with as many outline edges leaving each of its ends as arriving there?
fn closes_outline(built: &[Built], k: usize, line: &LineSource) -> bool {
    // The directed outline edges of a line: the front side's sector runs
    // from -> to, the back side's to -> from.
    let edges = |l: &LineSource| {
        let back = l.back.as_ref().map(|b| (b.sector, l.to, l.from));
        [Some((l.front.sector, l.from, l.to)), back].into_iter().flatten()
    };
    edges(line).all(|(sector, _, _)| {
        [line.from, line.to].iter().all(|&v| {
            let mut balance = 0i64;
            let others = built.iter().enumerate().filter(|&(j, _)| j != k).map(|(_, b)| &b.line);
            for (s, from, to) in others.chain([line]).flat_map(edges) {
                if s == sector {
                    balance += i64::from(to == v) - i64::from(from == v);
                }
            }
            balance == 0
        })
    })
}

fn merge(a: &LineSource, b: &LineSource) -> Option<LineSource> {
    // (side, runs from the lower-numbered end to the higher)
    let mut edges: Vec<(SideSource, bool)> = Vec::new();
    for l in [a, b] {
        let forward = l.from < l.to;
        edges.push((l.front.clone(), forward));
        if let Some(back) = &l.back {
            edges.push((back.clone(), !forward));
        }
    }
    let mut k = 0;
    while k < edges.len() {
        let twin = (k + 1..edges.len()).find(|&j| edges[j].0.sector == edges[k].0.sector && edges[j].1 != edges[k].1);
        match twin {
            Some(j) => {
                edges.remove(j);
                edges.remove(k);
            }
            None => k += 1,
        }
    }
    let forward: Vec<_> = edges.iter().filter(|e| e.1).map(|e| e.0.clone()).collect();
    let backward: Vec<_> = edges.iter().filter(|e| !e.1).map(|e| e.0.clone()).collect();
    let (lo, hi) = (a.from.min(a.to), a.from.max(a.to));
    let (from, to, front, back) = match (forward.as_slice(), backward.as_slice()) {
        ([f], []) => (lo, hi, f.clone(), None),
        ([f], [b]) => (lo, hi, f.clone(), Some(b.clone())),
        ([], [b]) => (hi, lo, b.clone(), None),
        _ => return None,
    };
    Some(LineSource { from, to, front, back, special: a.special.clone().or_else(|| b.special.clone()), ..a.clone() })
}

/// The front view of a sprite frame `stem` (`TROOA`), by the name
/// [`crate::materials`] looks for: rotation 0 (the same from every side) or
/// 1 (facing the viewer), whichever the WAD has.
pub fn find_sprite(art: &Art, stem: &str) -> Option<String> {
    ["0", "1"].iter().map(|rot| format!("{stem}{rot}")).find(|name| sprite_lump(art, name).is_some())
}

/// The lump that holds front view `name` (`TROOA1`): the lump of that name,
/// or a mirrored pair that starts with it (`TROOA1A5` would hold rotations 1
/// and 5).
pub fn sprite_lump(art: &Art, name: &str) -> Option<usize> {
    art.sprites.get(name).copied().or_else(|| {
        let mut pairs: Vec<_> = art.sprites.iter().filter(|(k, _)| k.starts_with(name) && k.len() == 8).collect();
        pairs.sort();
        pairs.first().map(|(_, &i)| i)
    })
}

/// The lump that shows sprite view `name` (`TROOA8`: frame A from
/// direction 8), and whether it must be mirrored: the lump of that name, the
/// first half of a pair (`TROOA8A2` shows 8 as drawn), or
/// the second half of a pair (`TROOA2A8` shows 8 mirrored), as Doom reads
/// sprite names.
pub fn sprite_view(art: &Art, name: &str) -> Option<(usize, bool)> {
    if let Some(lump) = sprite_lump(art, name) {
        return Some((lump, false));
    }
    let (stem, view) = (name.get(..4)?, name.get(4..6)?);
    let mut pairs: Vec<_> =
        art.sprites.iter().filter(|(k, _)| k.len() == 8 && k.starts_with(stem) && &k[6..8] == view).collect();
    pairs.sort();
    pairs.first().map(|(_, &i)| (i, true))
}

/// Writes the PNGs `converted` maps need under `dir`: wall textures in
/// `textures/`, flats in `flats/`, sprites in `sprites/`. A sprite is padded
/// so that Doom's origin (its offsets) lands at the middle of its bottom edge,
/// where our renderer stands a sprite on the floor; rows below the origin
/// (feet that Doom sinks into the floor) are cut. Returns the files written.
pub fn write_art<'a>(
    wad: &Wad,
    art: &Art,
    maps: impl IntoIterator<Item = &'a Converted>,
    dir: &Path,
) -> Result<usize, WadError> {
    let (mut walls, mut flats, mut sprites) = (BTreeSet::new(), BTreeSet::new(), BTreeSet::new());
    for c in maps {
        walls.extend(c.walls.iter().cloned());
        flats.extend(c.flats.iter().cloned());
        sprites.extend(c.sprites.iter().cloned());
    }
    let mut written = 0;
    for name in &walls {
        let def = &art.textures[name];
        let image = art::compose(wad, def, &art.palette)?;
        save(&dir.join("textures"), name, &image)?;
        written += 1;
    }
    for name in &flats {
        let image = art::flat(wad.bytes(art.flats[name]), &art.palette).map_err(|m| wad.error(name, m))?;
        save(&dir.join("flats"), name, &image)?;
        written += 1;
    }
    for name in &sprites {
        let lump = sprite_lump(art, name).ok_or_else(|| wad.missing(name, " (a sprite)"))?;
        let image = art::picture(wad.bytes(lump), &art.palette).map_err(|m| wad.error(name, m))?;
        save(&dir.join("sprites"), name, &stand_on_origin(&image))?;
        written += 1;
    }
    Ok(written)
}

/// Re-frames a sprite so its origin is the middle of the bottom edge (at
/// most 4096 by 4096: an origin far outside the picture crops it).
pub(crate) fn stand_on_origin(image: &Image) -> Image {
    let (w, h) = (image.width as i32, image.height as i32);
    let half = image.left.max(w - image.left).clamp(1, 2048);
    let height = if image.top > 0 { image.top.min(4096) } else { h };
    let (width, dx) = (2 * half, half - image.left);
    let mut out = Image {
        width: width as usize,
        height: height as usize,
        rgba: vec![[0; 4]; (width * height) as usize],
        left: half,
        top: height,
    };
    for y in 0..h.min(height) {
        for x in 0..w {
            let (ox, oy) = (x + dx, y);
            if (0..width).contains(&ox) {
                out.rgba[(oy * width + ox) as usize] = image.rgba[(y * w + x) as usize];
            }
        }
    }
    out
}

fn save(dir: &Path, name: &str, image: &Image) -> Result<(), WadError> {
    let write_error = |e: String| WadError::Io {
        path: dir.join(format!("{name}.png")).display().to_string(),
        error: std::io::Error::other(e),
    };
    std::fs::create_dir_all(dir).map_err(|e| write_error(e.to_string()))?;
    let mut bytes = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut bytes, image.width as u32, image.height as u32);
        encoder.set_color(png::ColorType::Rgba);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header().map_err(|e| write_error(e.to_string()))?;
        let flat: Vec<u8> = image.rgba.iter().flatten().copied().collect();
        writer.write_image_data(&flat).map_err(|e| write_error(e.to_string()))?;
    }
    std::fs::write(dir.join(format!("{name}.png")), bytes).map_err(|e| write_error(e.to_string()))
}
