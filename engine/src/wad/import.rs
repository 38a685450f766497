//! A WAD map to a Sightline map: [`convert`] turns the records of
//! [`super::level`] into a [`MapSource`] (the RON form), and [`write_art`]
//! writes the pictures the maps use as PNGs beside it.
//!
//! What is kept: geometry, sector heights, light and flats; side textures and
//! offsets; the pegging, two-sided and impassable flags; manual doors and the
//! tagged door triggers (walk and switch, once and repeatable, open-and-close
//! and open-and-stay); the sky per episode; the player start and the things
//! that have a sprite. What is not: other specials (lifts, floors, lights,
//! teleporters, exits), keys (keyed doors open without one), monsters' logic.
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
use super::{Wad, WadError};
use crate::map::source::{LineSource, MapSource, SectorSource, SideSource, ThingSource, TriggerSource};
use crate::map::validate::validate;
use crate::map::{Problem, TriggerOn, PLAYER_START, SKY};

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
        let index = |start, end| -> Result<HashMap<String, usize>, WadError> {
            Ok(wad.namespace(start, end)?.into_iter().map(|i| (wad.lumps[i].name.clone(), i)).collect())
        };
        // PWADs often mark their namespaces FF_START and SS_START.
        let start =
            |plain: &'static str, doubled: &'static str| if wad.find(plain).is_some() { plain } else { doubled };
        let flats = index(start("F_START", "FF_START"), "F_END")?;
        let sprites = index(start("S_START", "SS_START"), "S_END")?;
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

/// Converts one map. Texture, flat and sprite names are checked against
/// `art`, so every name the map uses can be written by [`write_art`].
pub fn convert(wad: &Wad, map: &WadMap, art: &Art) -> Result<Converted, WadError> {
    let mut repairs = Vec::new();
    let mut walls = BTreeSet::new();
    let mut flats = BTreeSet::new();
    let mut sprites = BTreeSet::new();

    // Vertices: only those lines use, one per position.
    let mut vertex_of_position: HashMap<(i16, i16), usize> = HashMap::new();
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
            let id = *vertex_of_position.entry(p).or_insert(next);
            if id == next {
                vertices.push((f64::from(p.0), f64::from(p.1)));
            } else {
                merged += 1;
            }
            vertex_map[v] = id;
        }
    }
    if merged > 0 {
        repairs.push(format!("merged {merged} vertices that share a position with another"));
    }

    // Lines: two-sided only with the flag and a left side (Doom's P_LoadSegs).
    let sector_of = |l: &WadLine| {
        let right = map.sides[usize::from(l.right.unwrap_or(0))].sector;
        let left = l.left.filter(|_| l.flags & flags::TWO_SIDED != 0).map(|s| map.sides[usize::from(s)].sector);
        (right, left)
    };
    // A sector all of whose lines have it on both sides has no area of its
    // own: it is Doom's self-referencing sector trick (deep water, invisible
    // bridges), which relies on how Doom's node builder assigns subsectors.
    // Its lines draw nothing here, so they go, and its area joins the sector
    // around it.
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
    let mut lines = Vec::new();
    let mut seen_ends: HashMap<(usize, usize), usize> = HashMap::new();
    for (i, l) in map.lines.iter().enumerate() {
        let (from, to) = (vertex_map[usize::from(l.v1)], vertex_map[usize::from(l.v2)]);
        if from == to {
            repairs.push(format!("dropped linedef {i}: zero length"));
            continue;
        }
        if let (r, Some(_)) = sector_of(l) {
            if only_self[usize::from(r)] {
                repairs.push(format!("dropped linedef {i}: it only borders self-referencing sector {r}"));
                continue;
            }
        }
        let duplicate = match seen_ends.entry((from.min(to), from.max(to))) {
            Entry::Occupied(first) => Some(*first.get()),
            Entry::Vacant(slot) => {
                slot.insert(lines.len());
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
                if !art.textures.contains_key(name) {
                    return Err(wad.error(
                        &format!("{}/SIDEDEFS", map.name),
                        format!("linedef {i} {which} side {part} texture {name:?} is not in TEXTURE1 or TEXTURE2"),
                    ));
                }
                walls.insert(name.to_string());
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
        let front = side(right, "right")?;
        let back = left.map(|s| side(s, "left")).transpose()?;
        let (door, trigger) = special(l, back.is_some());
        let line = LineSource {
            from: from as i64,
            to: to as i64,
            front,
            back,
            upper_unpegged: l.flags & flags::UPPER_UNPEGGED != 0,
            lower_unpegged: l.flags & flags::LOWER_UNPEGGED != 0,
            impassable: l.flags & flags::BLOCKING != 0,
            door,
            trigger,
            ..LineSource::default()
        };
        match duplicate {
            None => lines.push(line),
            Some(k) => match merge(&lines[k], &line) {
                Some(merged) => {
                    repairs.push(format!("merged linedef {i} into the line with the same end points"));
                    lines[k] = merged;
                }
                None => repairs.push(format!("dropped linedef {i}: it has the same end points as another line")),
            },
        }
    }

    drop_invisible_lines(&mut lines, &mut repairs);

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
            if !art.flats.contains_key(name) {
                return Err(wad.error(
                    &format!("{}/SECTORS", map.name),
                    format!("sector {i} {which} flat {name:?} is not between F_START and F_END"),
                ));
            }
            flats.insert(name.to_string());
            Ok(Some(name.to_string()))
        };
        let ceiling = if s.ceiling < s.floor {
            repairs.push(format!("sector {i}: raised its ceiling {} to its floor {}", s.ceiling, s.floor));
            s.floor
        } else {
            s.ceiling
        };
        sectors.push(SectorSource {
            floor: f64::from(s.floor),
            ceiling: f64::from(ceiling),
            light: i64::from(s.light.clamp(0, 255)),
            floor_texture: flat(&s.floor_flat, "floor")?,
            ceiling_texture: flat(&s.ceiling_flat, "ceiling")?,
            tag: i64::from(s.tag),
            ..SectorSource::default()
        });
    }
    for line in &mut lines {
        for side in [Some(&mut line.front), line.back.as_mut()].into_iter().flatten() {
            side.sector = sector_map[side.sector as usize] as i64;
        }
    }

    // Things: the player 1 start, and every thing with a sprite that is
    // there on Doom's middle skill (Hurt Me Plenty) in single player.
    let mut things = Vec::new();
    let mut starts = 0;
    for t in &map.things {
        let (x, y, angle) = (f64::from(t.x), f64::from(t.y), f64::from(t.angle));
        if t.kind == 1 {
            starts += 1;
            // The player start goes first: the validator takes the first.
            things.insert(0, ThingSource::new(PLAYER_START, x, y, angle));
            continue;
        }
        const MEDIUM: u16 = 0x0002;
        const MULTIPLAYER: u16 = 0x0010;
        if t.flags & MEDIUM == 0 || t.flags & MULTIPLAYER != 0 {
            continue;
        }
        let Some(sprite) = sprite_of(t.kind).and_then(|(prefix, frame)| find_sprite(art, prefix, frame)) else {
            continue;
        };
        sprites.insert(sprite.clone());
        things.push(ThingSource::new(&sprite.to_ascii_lowercase(), x, y, angle));
    }
    if starts == 0 {
        return Err(wad.error(&format!("{}/THINGS", map.name), "no player 1 start (thing type 1)"));
    }
    // Doom does not mind a start exactly on a line; our validator does (which
    // sector is it in?). Step off it by a unit, as a player would on moving.
    let on_line = |x: f64, y: f64| {
        lines.iter().any(|l| {
            let (a, b) = (vertices[l.from as usize], vertices[l.to as usize]);
            let cross = (b.0 - a.0) * (y - a.1) - (b.1 - a.1) * (x - a.0);
            cross == 0.0 && x >= a.0.min(b.0) && x <= a.0.max(b.0) && y >= a.1.min(b.1) && y <= a.1.max(b.1)
        })
    };
    let start = &mut things[0];
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

    let uses_sky =
        sectors.iter().any(|s| [&s.floor_texture, &s.ceiling_texture].iter().any(|t| t.as_deref() == Some(SKY)));
    let sky = uses_sky.then(|| sky_of(&map.name).to_string());
    if let Some(sky) = &sky {
        if !art.textures.contains_key(sky) {
            return Err(wad.missing(sky, &format!(" (the sky of {}, a texture in TEXTURE1)", map.name)));
        }
        walls.insert(sky.clone());
    }
    let mut source =
        MapSource { name: map.name.clone(), vertices, sectors, lines, things, sky, ..MapSource::default() };
    reassign_misplaced_lines(&mut source, &mut repairs);
    Ok(Converted { source, walls, flats, sprites, repairs })
}

/// Removes the lines that draw nothing and do nothing here: the same sector
/// on both sides, no middle texture, not impassable, no door. Doom's maps use
/// them as walk-over triggers for specials we do not play, and they may cross
/// other lines (MAP20 of Freedoom 2 raises a floor with two that cut across
/// rooms) or lie in another sector than they name; Doom does not mind, our
/// validator does, and the renderer would only walk them for nothing.
fn drop_invisible_lines(lines: &mut Vec<LineSource>, repairs: &mut Vec<String>) {
    let invisible = |l: &LineSource| {
        l.back.as_ref().is_some_and(|b| b.sector == l.front.sector && b.middle.is_none())
            && l.front.middle.is_none()
            && !l.impassable
            && !l.door
            && l.trigger.is_none()
    };
    let before = lines.len();
    lines.retain(|l| !invisible(l));
    if lines.len() < before {
        repairs.push(format!(
            "dropped {} lines with the same sector on both sides that draw nothing and block nothing",
            before - lines.len()
        ));
    }
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
    Some(LineSource { from, to, front, back, door: a.door && b.door, trigger: a.trigger.clone(), ..a.clone() })
}

/// The door a line special makes, as `(door, trigger)`: the manual doors
/// (used on the line, opening its back sector) become `door`, the tagged
/// door openers a [`TriggerSource`]. Numbers from Doom's p_spec.c and
/// p_switch.c; keyed variants open without a key.
fn special(l: &WadLine, two_sided: bool) -> (bool, Option<TriggerSource>) {
    // Manual doors: DR 1, 26-28, 117 (and D1 31-34, 118, which in Doom stay
    // open; here they close again after the wait, and can be reopened).
    let manual = matches!(l.special, 1 | 26 | 27 | 28 | 31 | 32 | 33 | 34 | 117 | 118);
    if manual {
        return (two_sided, None);
    }
    // (on, once, stays open)
    let kind = match l.special {
        2 | 109 => Some((TriggerOn::Walk, true, true)),
        4 | 108 => Some((TriggerOn::Walk, true, false)),
        86 | 106 => Some((TriggerOn::Walk, false, true)),
        90 | 105 => Some((TriggerOn::Walk, false, false)),
        103 | 112 | 133 | 135 | 137 => Some((TriggerOn::Use, true, true)),
        29 | 111 => Some((TriggerOn::Use, true, false)),
        61 | 115 | 99 | 134 | 136 => Some((TriggerOn::Use, false, true)),
        63 | 114 => Some((TriggerOn::Use, false, false)),
        // Shot doors (GR 46): there are no guns; using the line opens them.
        46 => Some((TriggerOn::Use, false, true)),
        _ => None,
    };
    let trigger = kind.filter(|_| l.tag != 0).map(|(on, once, stay_open)| TriggerSource {
        tag: i64::from(l.tag),
        on,
        once,
        stay_open,
    });
    (false, trigger)
}

/// The sprite and frame a thing type shows (Doom's mobjinfo spawn states,
/// info.c). `None` for things with no picture (starts, teleport
/// destinations) or types we do not know.
pub fn sprite_of(kind: u16) -> Option<(&'static str, u8)> {
    let a = b'A';
    Some(match kind {
        // Monsters.
        3004 => ("POSS", a),
        9 => ("SPOS", a),
        65 => ("CPOS", a),
        3001 => ("TROO", a),
        3002 | 58 => ("SARG", a),
        3006 => ("SKUL", a),
        3005 => ("HEAD", a),
        3003 => ("BOSS", a),
        69 => ("BOS2", a),
        16 => ("CYBR", a),
        7 => ("SPID", a),
        64 => ("VILE", a),
        66 => ("SKEL", a),
        67 => ("FATT", a),
        68 => ("BSPI", a),
        71 => ("PAIN", a),
        84 => ("SSWV", a),
        72 => ("KEEN", a),
        88 => ("BBRN", a),
        // Weapons, ammunition, health, armour, power-ups, keys.
        2001 => ("SHOT", a),
        82 => ("SGN2", a),
        2002 => ("MGUN", a),
        2003 => ("LAUN", a),
        2004 => ("PLAS", a),
        2005 => ("CSAW", a),
        2006 => ("BFUG", a),
        2007 => ("CLIP", a),
        2048 => ("AMMO", a),
        2008 => ("SHEL", a),
        2049 => ("SBOX", a),
        2010 => ("ROCK", a),
        2046 => ("BROK", a),
        2047 => ("CELL", a),
        17 => ("CELP", a),
        8 => ("BPAK", a),
        2011 => ("STIM", a),
        2012 => ("MEDI", a),
        2014 => ("BON1", a),
        2015 => ("BON2", a),
        2018 => ("ARM1", a),
        2019 => ("ARM2", a),
        83 => ("MEGA", a),
        2013 => ("SOUL", a),
        2022 => ("PINV", a),
        2023 => ("PSTR", a),
        2024 => ("PINS", a),
        2025 => ("SUIT", a),
        2026 => ("PMAP", a),
        2045 => ("PVIS", a),
        5 => ("BKEY", a),
        6 => ("YKEY", a),
        13 => ("RKEY", a),
        38 => ("RSKU", a),
        39 => ("YSKU", a),
        40 => ("BSKU", a),
        // Obstacles and decoration.
        2035 => ("BAR1", a),
        70 => ("FCAN", a),
        2028 => ("COLU", a),
        30 => ("COL1", a),
        31 => ("COL2", a),
        32 => ("COL3", a),
        33 => ("COL4", a),
        36 => ("COL5", a),
        37 => ("COL6", a),
        41 => ("CEYE", a),
        42 => ("FSKU", a),
        43 => ("TRE1", a),
        54 => ("TRE2", a),
        44 => ("TBLU", a),
        45 => ("TGRN", a),
        46 => ("TRED", a),
        55 => ("SMBT", a),
        56 => ("SMGT", a),
        57 => ("SMRT", a),
        47 => ("SMIT", a),
        48 => ("ELEC", a),
        34 => ("CAND", a),
        35 => ("CBRA", a),
        85 => ("TLMP", a),
        86 => ("TLP2", a),
        49 | 63 => ("GOR1", a),
        50 | 59 => ("GOR2", a),
        51 | 61 => ("GOR3", a),
        52 | 60 => ("GOR4", a),
        53 | 62 => ("GOR5", a),
        73 => ("HDB1", a),
        74 => ("HDB2", a),
        75 => ("HDB3", a),
        76 => ("HDB4", a),
        77 => ("HDB5", a),
        78 => ("HDB6", a),
        24 => ("POL5", a),
        25 => ("POL1", a),
        26 => ("POL6", a),
        27 => ("POL4", a),
        28 => ("POL2", a),
        29 => ("POL3", a),
        79 => ("POB1", a),
        80 => ("POB2", a),
        81 => ("BRS1", a),
        // Corpses: the last frame of a death.
        10 | 12 => ("PLAY", b'W'),
        15 => ("PLAY", b'N'),
        18 => ("POSS", b'L'),
        19 => ("SPOS", b'L'),
        20 => ("TROO", b'M'),
        21 => ("SARG", b'N'),
        22 => ("HEAD", b'L'),
        _ => return None,
    })
}

/// The lump of a sprite frame seen from the front: rotation 0 (the same from
/// every side) or 1 (facing the viewer), alone or as the first half of a
/// mirrored pair (`POSSA2A8` holds rotations 2 and 8, so not 1).
fn find_sprite(art: &Art, prefix: &str, frame: u8) -> Option<String> {
    let frame = char::from(frame);
    ["0", "1"].iter().find_map(|rot| {
        let exact = format!("{prefix}{frame}{rot}");
        if art.sprites.contains_key(&exact) {
            return Some(exact);
        }
        art.sprites.keys().find(|k| k.starts_with(&exact) && k.len() == 8).cloned()
    })
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
        let image = art::picture(wad.bytes(art.sprites[name]), &art.palette).map_err(|m| wad.error(name, m))?;
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
