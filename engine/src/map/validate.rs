//! Validation: every check that turns a [`MapSource`] into a [`Map`].
//!
//! Checks run in three phases, each only when the one before passed, so that a
//! later check can rely on what an earlier one established: (1) each element on
//! its own (indices in range, finite numbers); (2) geometry (zero length,
//! duplicates, crossings, closure, orientation); (3) things and the player start.

use std::collections::HashMap;

use glam::DVec2;

use super::load::Problem;
use super::source::{LineSource, LineSpecialSource, MapSource, SideSource, ThingSource};
use super::special::{Action, Activation, DoorKind, LineSpecial, SkillBand, Who};
use super::{Fog, Line, LineFlags, Map, Sector, Side, Thing, TriggerLine, TriggerOn, PLAYER_START};
use crate::geom::{cross, segment_contact, Contact, MAX_COORD};

/// At most this many crossing problems are listed; a map with more is a mess
/// the first few already describe.
const MAX_CROSSINGS_REPORTED: usize = 20;

pub fn validate(src: &MapSource) -> Result<Map, Vec<Problem>> {
    let map = check_elements(src)?;
    let mut problems = check_geometry(&map);
    if !problems.is_empty() {
        return Err(problems);
    }
    let map = match find_player_start(&map) {
        Ok(start) => Map { player_start: start, ..map },
        Err(p) => {
            problems.push(p);
            return Err(problems);
        }
    };
    let problems = super::semantics::check(&map);
    if problems.is_empty() {
        Ok(map)
    } else {
        Err(problems)
    }
}

/// Highest format version this build reads.
pub const MAX_VERSION: i64 = 2;

fn in_range(x: f64) -> bool {
    x.is_finite() && x.abs() <= MAX_COORD
}

/// Phase 1: every element on its own. Returns a [`Map`] whose indices are safe.
fn check_elements(src: &MapSource) -> Result<Map, Vec<Problem>> {
    let mut problems = Vec::new();
    for (what, empty) in
        [("vertices", src.vertices.is_empty()), ("sectors", src.sectors.is_empty()), ("lines", src.lines.is_empty())]
    {
        if empty {
            problems.push(Problem::Missing { what });
        }
    }
    let vertices: Vec<DVec2> = src.vertices.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
    for (i, v) in vertices.iter().enumerate() {
        if !in_range(v.x) || !in_range(v.y) {
            problems.push(Problem::BadVertex { vertex: i, x: v.x, y: v.y });
        }
    }
    let sectors = src.sectors.iter().enumerate().map(|(i, s)| {
        for (which, value) in [("floor", s.floor), ("ceiling", s.ceiling)] {
            if !in_range(value) {
                problems.push(Problem::BadHeight { sector: i, which, value });
            }
        }
        if s.floor > s.ceiling {
            problems.push(Problem::FloorAboveCeiling { sector: i, floor: s.floor, ceiling: s.ceiling });
        }
        if !(0..=255).contains(&s.light) {
            problems.push(Problem::BadLight { sector: i, light: s.light });
        }
        let tag = u16::try_from(s.tag).unwrap_or_else(|_| {
            problems.push(Problem::BadTag { element: format!("sector {i}"), tag: s.tag });
            0
        });
        if let Some(d) = s.special.damage {
            if d.every == 0 || d.amount > 1000 {
                problems.push(Problem::BadSpecial {
                    element: format!("sector {i}"),
                    message: format!(
                        "damage {} every {} ticks: the amount must be 0..=1000 and every at least 1",
                        d.amount, d.every
                    ),
                });
            }
        }
        let mut light_from = |which: &str, k: Option<i64>| {
            let k = k?;
            let ok = usize::try_from(k).ok().filter(|&k| k < src.sectors.len());
            if ok.is_none() {
                problems.push(Problem::BadSpecial {
                    element: format!("sector {i}"),
                    message: format!(
                        "{which} refers to sector {k}, but the sectors are numbered 0..{}",
                        src.sectors.len()
                    ),
                });
            }
            ok
        };
        let floor_light = light_from("floor_light", s.floor_light);
        let ceiling_light = light_from("ceiling_light", s.ceiling_light);
        if let Some(c) = s.carry {
            if !(c.x.is_finite() && c.y.is_finite() && c.x.abs() <= 64.0 && c.y.abs() <= 64.0) {
                problems.push(Problem::BadSpecial {
                    element: format!("sector {i}"),
                    message: format!("carry ({:?}, {:?}) must be finite and at most 64 units a tick", c.x, c.y),
                });
            }
        }
        Sector {
            floor: s.floor,
            ceiling: s.ceiling,
            light: s.light.clamp(0, 255) as u8,
            floor_texture: s.floor_texture.clone(),
            ceiling_texture: s.ceiling_texture.clone(),
            tag,
            special: s.special,
            floor_light,
            ceiling_light,
            carry: s.carry,
        }
    });
    let sectors: Vec<Sector> = sectors.collect();
    let mut lines = Vec::with_capacity(src.lines.len());
    for (i, l) in src.lines.iter().enumerate() {
        let vertex = |end: &'static str, v: i64, problems: &mut Vec<Problem>| {
            let ok = usize::try_from(v).ok().filter(|&v| v < vertices.len());
            if ok.is_none() {
                problems.push(Problem::DanglingVertex { line: i, end, vertex: v, count: vertices.len() });
            }
            ok.unwrap_or(0)
        };
        let from = vertex("from", l.from, &mut problems);
        let to = vertex("to", l.to, &mut problems);
        let front = check_side(i, "front", &l.front, sectors.len(), &mut problems);
        let back = l.back.as_ref().map(|b| check_side(i, "back", b, sectors.len(), &mut problems));
        if l.door && back.is_none() {
            problems.push(Problem::OneSidedDoor { line: i });
        }
        let flags = LineFlags {
            upper_unpegged: l.upper_unpegged,
            lower_unpegged: l.lower_unpegged,
            impassable: l.impassable,
            block_monsters: l.block_monsters,
            block_sound: l.block_sound,
            translucent: l.translucent,
        };
        let special = line_special(i, l, &mut problems);
        lines.push(Line { from, to, front, back, flags, special });
    }
    let mut trigger_lines = Vec::with_capacity(src.trigger_lines.len());
    for (i, t) in src.trigger_lines.iter().enumerate() {
        let element = format!("trigger line {i}");
        let mut vertex = |v: i64| {
            let ok = usize::try_from(v).ok().filter(|&v| v < vertices.len());
            if ok.is_none() {
                problems.push(Problem::BadSpecial {
                    element: element.clone(),
                    message: format!("refers to vertex {v}, but the vertices are numbered 0..{}", vertices.len()),
                });
            }
            ok.unwrap_or(0)
        };
        let (from, to) = (vertex(t.from), vertex(t.to));
        if from == to && !problems.iter().any(|p| matches!(p, Problem::BadSpecial { element: e, .. } if *e == element))
        {
            problems.push(Problem::BadSpecial { element: element.clone(), message: "has zero length".into() });
        }
        let special = special_of(&element, &t.special, &mut problems);
        trigger_lines.push(TriggerLine { from, to, special });
    }
    if !(1..=MAX_VERSION).contains(&src.version) {
        problems.push(Problem::BadVersion { version: src.version });
    }
    let things = src.things.iter().map(thing_of).collect();
    if !problems.is_empty() {
        return Err(problems);
    }
    let fog = src.fog.as_ref().map(|f| Fog { colour: [f.colour.0, f.colour.1, f.colour.2], distance: f.distance });
    if let Some(f) = fog {
        if !(f.distance.is_finite() && f.distance > 0.0) {
            problems.push(Problem::BadFog { distance: f.distance });
        }
    }
    if !problems.is_empty() {
        return Err(problems);
    }
    Ok(Map {
        version: src.version as u8,
        name: src.name.clone(),
        vertices,
        sectors,
        lines,
        things,
        player_start: 0,
        diminishing_light: src.diminishing_light,
        fog,
        sky: src.sky.clone(),
        animations: src.animations.clone(),
        music: src.music.clone(),
        trigger_lines,
    })
}

fn thing_of(t: &ThingSource) -> Thing {
    Thing {
        kind: t.kind.clone(),
        pos: DVec2::new(t.x, t.y),
        angle: t.angle,
        skills: SkillBand::ALL.map(|b| t.skills.contains(&b)),
        ambush: t.ambush,
        multiplayer: t.multiplayer,
        not_in: t.not_in.clone(),
    }
}

/// A line's special: its `special`, or version 1's `door` or `trigger`
/// read as the special they are (at most one of the three).
fn line_special(i: usize, l: &LineSource, problems: &mut Vec<Problem>) -> Option<LineSpecial> {
    let element = format!("line {i}");
    let given = [l.door, l.trigger.is_some(), l.special.is_some()].iter().filter(|&&b| b).count();
    if given > 1 {
        problems.push(Problem::BadSpecial {
            element,
            message: "give at most one of `door`, `trigger` and `special`".into(),
        });
        return None;
    }
    if l.door {
        // Doom's DR door: used from either face, monsters too.
        return Some(LineSpecial {
            on: Activation::Use,
            repeat: true,
            by: Who::Anyone,
            tag: 0,
            action: Action::Door {
                kind: DoorKind::Raise,
                speed: super::special::DOOR_SPEED,
                wait: super::special::DOOR_WAIT,
                shut: super::special::DOOR_SHUT,
                key: None,
            },
        });
    }
    if let Some(t) = &l.trigger {
        let tag = u16::try_from(t.tag).unwrap_or_else(|_| {
            problems.push(Problem::BadTag { element: format!("line {i} trigger"), tag: t.tag });
            0
        });
        let kind = if t.stay_open { DoorKind::Open } else { DoorKind::Raise };
        return Some(LineSpecial {
            on: match t.on {
                TriggerOn::Use => Activation::Use,
                TriggerOn::Walk => Activation::Walk,
            },
            repeat: !t.once,
            by: Who::Players,
            tag,
            action: Action::Door {
                kind,
                speed: super::special::DOOR_SPEED,
                wait: super::special::DOOR_WAIT,
                shut: super::special::DOOR_SHUT,
                key: None,
            },
        });
    }
    l.special.as_ref().map(|s| special_of(&element, s, problems))
}

/// Checks a special's numbers (tag in range, speeds and heights finite and
/// sensible) and returns its validated form.
fn special_of(element: &str, s: &LineSpecialSource, problems: &mut Vec<Problem>) -> LineSpecial {
    let tag = u16::try_from(s.tag).unwrap_or_else(|_| {
        problems.push(Problem::BadTag { element: format!("{element} special"), tag: s.tag });
        0
    });
    let mut bad = |message: String| {
        problems.push(Problem::BadSpecial { element: format!("{element} {} special", s.action.name()), message })
    };
    // Speeds up to MAX_SPEED units a tick; anything faster is a typo.
    const MAX_SPEED: f64 = 1024.0;
    const MAX_WAIT: u32 = 35 * 60 * 60;
    let speed_ok = |v: f64| v.is_finite() && v > 0.0 && v <= MAX_SPEED;
    let mut speed = |v: f64| {
        if !speed_ok(v) {
            bad(format!("speed {v:?} must be above 0 and at most {MAX_SPEED} units a tick"));
        }
    };
    match &s.action {
        Action::Door { speed: v, .. }
        | Action::Lift { speed: v, .. }
        | Action::PerpetualLift { speed: v, .. }
        | Action::Crusher { speed: v, .. }
        | Action::Donut { speed: v } => speed(*v),
        Action::Floor { speed: v, offset, .. } | Action::Ceiling { speed: v, offset, .. } => {
            speed(*v);
            if !(offset.is_finite() && offset.abs() <= MAX_COORD) {
                bad(format!("offset {offset:?} is not finite within the supported range"));
            }
        }
        Action::Stairs { step, speed: v, .. } => {
            speed(*v);
            if !(step.is_finite() && *step != 0.0 && step.abs() <= 4096.0) {
                bad(format!("step {step:?} must be finite, not 0, and at most 4096"));
            }
        }
        _ => {}
    }
    let mut bad = |message: String| {
        problems.push(Problem::BadSpecial { element: format!("{element} {} special", s.action.name()), message })
    };
    match &s.action {
        Action::Door { wait, .. } | Action::Lift { wait, .. } | Action::PerpetualLift { wait, .. }
            if *wait > MAX_WAIT =>
        {
            bad(format!("wait {wait} is more than an hour ({MAX_WAIT} ticks)"))
        }
        _ => {}
    }
    LineSpecial { on: s.on, repeat: s.repeat, by: s.by, tag, action: s.action.clone() }
}

fn check_side(line: usize, side: &'static str, s: &SideSource, sectors: usize, problems: &mut Vec<Problem>) -> Side {
    let sector = usize::try_from(s.sector).ok().filter(|&v| v < sectors);
    if sector.is_none() {
        problems.push(Problem::DanglingSector { line, side, sector: s.sector, count: sectors });
    }
    if !s.x_offset.is_finite() || !s.y_offset.is_finite() {
        problems.push(Problem::BadOffset { line, side });
    }
    let scroll = s.scroll.unwrap_or_default();
    if !(scroll.x.is_finite() && scroll.y.is_finite() && scroll.x.abs() <= 1024.0 && scroll.y.abs() <= 1024.0) {
        problems.push(Problem::BadSpecial {
            element: format!("line {line} {side} side"),
            message: format!("scroll ({:?}, {:?}) must be finite and at most 1024 units a tick", scroll.x, scroll.y),
        });
    }
    Side {
        sector: sector.unwrap_or(0),
        upper: s.upper.clone(),
        middle: s.middle.clone(),
        lower: s.lower.clone(),
        x_offset: s.x_offset,
        y_offset: s.y_offset,
        scroll,
    }
}

/// Phase 2: shapes. Indices are known to be in range here.
fn check_geometry(map: &Map) -> Vec<Problem> {
    let mut problems = Vec::new();
    let mut seen_pos: HashMap<(u64, u64), usize> = HashMap::new();
    for (i, v) in map.vertices.iter().enumerate() {
        // +0.0 folds -0.0 into 0.0 so the two zeros count as one position.
        let key = ((v.x + 0.0).to_bits(), (v.y + 0.0).to_bits());
        if let Some(&first) = seen_pos.get(&key) {
            problems.push(Problem::SharedPosition { vertex: i, first });
        } else {
            seen_pos.insert(key, i);
        }
    }
    let mut seen_pair: HashMap<(usize, usize), usize> = HashMap::new();
    for (i, l) in map.lines.iter().enumerate() {
        if map.vertices[l.from] == map.vertices[l.to] {
            problems.push(Problem::ZeroLength { line: i });
        }
        let key = (l.from.min(l.to), l.from.max(l.to));
        if let Some(&first) = seen_pair.get(&key) {
            problems.push(Problem::DuplicateLine { line: i, first });
        } else {
            seen_pair.insert(key, i);
        }
    }
    if !problems.is_empty() {
        return problems;
    }
    problems.extend(check_crossings(map));
    if problems.is_empty() {
        problems.extend(check_sectors(map));
    }
    if problems.is_empty() {
        problems.extend(check_sides_face_their_sectors(map));
    }
    problems
}

/// Every pair of lines whose bounding boxes overlap, tested exactly. A sweep
/// over x keeps this near-linear for real maps.
fn check_crossings(map: &Map) -> Vec<Problem> {
    let mut order: Vec<usize> = (0..map.lines.len()).collect();
    let min_x = |i: usize| {
        let (a, b) = map.line_points(&map.lines[i]);
        a.x.min(b.x)
    };
    order.sort_by(|&a, &b| min_x(a).total_cmp(&min_x(b)));
    let mut problems = Vec::new();
    for (k, &i) in order.iter().enumerate() {
        let (p0, p1) = map.line_points(&map.lines[i]);
        let (max_x, lo_y, hi_y) = (p0.x.max(p1.x), p0.y.min(p1.y), p0.y.max(p1.y));
        for &j in &order[k + 1..] {
            let (q0, q1) = map.line_points(&map.lines[j]);
            if q0.x.min(q1.x) > max_x {
                break;
            }
            if q0.y.max(q1.y) < lo_y || q0.y.min(q1.y) > hi_y {
                continue;
            }
            let (line, other) = (i.min(j), i.max(j));
            let problem = match segment_contact(p0, p1, q0, q1) {
                Contact::None => continue,
                Contact::Cross(at) => Problem::Crossing { line, other, at },
                Contact::Touch(at) => Problem::Touching { line, other, at },
                Contact::Overlap => Problem::Overlap { line, other },
            };
            problems.push(problem);
            if problems.len() >= MAX_CROSSINGS_REPORTED {
                return problems;
            }
        }
    }
    problems.sort_by_key(|p| match p {
        Problem::Crossing { line, .. } | Problem::Touching { line, .. } | Problem::Overlap { line, .. } => *line,
        _ => usize::MAX,
    });
    problems
}

/// Each side, as a directed edge with its sector on the right.
fn sector_edges(map: &Map) -> impl Iterator<Item = (usize, usize, usize)> + '_ {
    map.lines.iter().flat_map(|l| {
        let front = Some((l.front.sector, l.from, l.to));
        let back = l.back.as_ref().map(|b| (b.sector, l.to, l.from));
        front.into_iter().chain(back)
    })
}

/// Closure (at every vertex as many of a sector's edges arrive as leave) and
/// orientation (the edges wind clockwise, so the sector is on their right).
fn check_sectors(map: &Map) -> Vec<Problem> {
    let n = map.sectors.len();
    let mut degree: HashMap<(usize, usize), (usize, usize)> = HashMap::new();
    let mut area = vec![0.0f64; n];
    let mut used = vec![false; n];
    // Measure areas relative to one vertex: at a million units, absolute
    // coordinates would cancel away the small rooms' areas.
    let origin = map.vertices[0];
    for (sector, from, to) in sector_edges(map) {
        used[sector] = true;
        degree.entry((sector, from)).or_default().1 += 1;
        degree.entry((sector, to)).or_default().0 += 1;
        area[sector] += cross(map.vertices[from] - origin, map.vertices[to] - origin);
    }
    let mut problems = Vec::new();
    let mut unclosed: Vec<_> = degree.iter().filter(|(_, (i, o))| i != o).collect();
    unclosed.sort();
    let mut reported = vec![false; n];
    for (&(sector, vertex), &(into, out_of)) in unclosed {
        if !reported[sector] {
            reported[sector] = true;
            problems.push(Problem::Unclosed { sector, vertex, into, out_of });
        }
    }
    for sector in 0..n {
        if !used[sector] {
            problems.push(Problem::NoLines { sector });
        } else if !reported[sector] && area[sector] >= 0.0 {
            problems.push(Problem::InsideOut { sector });
        }
    }
    problems
}

/// Just off the middle of each line, on its front lies its front sector and
/// only that; on its back, its back sector, or no sector behind a solid wall.
/// This catches what closure and total winding cannot: a pillar wound the
/// wrong way, or a sector nested inside another with no two-sided line
/// between them (either would render as see-through walls).
fn check_sides_face_their_sectors(map: &Map) -> Vec<Problem> {
    let mut problems = Vec::new();
    let bands = Bands::of(map);
    for (i, line) in map.lines.iter().enumerate() {
        let (a, b) = map.line_points(line);
        let d = b - a;
        let normal = DVec2::new(d.y, -d.x) / d.length();
        // Far enough off the line to be decided robustly, near enough that no
        // other line (they do not cross) comes between.
        let offset = (d.length() * 1e-3).min(1e-2);
        let mid = a + d * 0.5;
        let back = line.back.as_ref().map(|s| s.sector);
        for (side, probe, expected) in
            [("front", mid + normal * offset, Some(line.front.sector)), ("back", mid - normal * offset, back)]
        {
            let found = sectors_containing(map, &bands, probe);
            if found.as_slice() != expected.as_slice() {
                problems.push(Problem::SideMismatch { line: i, side, expected, found });
                if problems.len() >= MAX_CROSSINGS_REPORTED {
                    return problems;
                }
            }
        }
    }
    problems
}

/// The map's lines in horizontal bands, each line in every band its span in
/// y meets: a crossing-number probe at `y` counts only lines with
/// `min.y <= y < max.y`, all in `y`'s band. Testing every line for every
/// probe was lines² work: 42% of `sightline check` on freedoom2 MAP12
/// (about 1.6 s of 4 s), on every load of a big map.
struct Bands {
    y0: f64,
    /// Bands per map unit.
    scale: f64,
    lines: Vec<Vec<usize>>,
}

impl Bands {
    fn of(map: &Map) -> Bands {
        let n = (map.lines.len() as f64).sqrt().ceil().max(1.0) as usize;
        let ys = || map.lines.iter().flat_map(|l| [map.vertices[l.from].y, map.vertices[l.to].y]);
        let (y0, y1) = (ys().fold(f64::MAX, f64::min), ys().fold(f64::MIN, f64::max));
        let scale = if y1 > y0 { n as f64 / (y1 - y0) } else { 0.0 };
        let mut bands = Bands { y0, scale, lines: vec![Vec::new(); n] };
        for (i, line) in map.lines.iter().enumerate() {
            let (a, b) = map.line_points(line);
            for band in bands.band(a.y.min(b.y))..=bands.band(a.y.max(b.y)) {
                bands.lines[band].push(i);
            }
        }
        bands
    }

    /// The band of `y`, clamped to the map's (no line spans a `y` outside).
    fn band(&self, y: f64) -> usize {
        let k = ((y - self.y0) * self.scale).floor();
        if k > 0.0 {
            (k as usize).min(self.lines.len() - 1)
        } else {
            0
        }
    }
}

/// Every sector whose boundary encloses `p` (crossing number, half-open in y).
fn sectors_containing(map: &Map, bands: &Bands, p: DVec2) -> Vec<usize> {
    let mut odd = vec![false; map.sectors.len()];
    for &i in &bands.lines[bands.band(p.y)] {
        let line = &map.lines[i];
        let (a, b) = map.line_points(line);
        if (a.y > p.y) != (b.y > p.y) && a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) > p.x {
            odd[line.front.sector] ^= true;
            if let Some(back) = &line.back {
                odd[back.sector] ^= true;
            }
        }
    }
    odd.iter().enumerate().filter(|(_, &o)| o).map(|(s, _)| s).collect()
}

/// Phase 3: things. The last player start in the map is the one used, as
/// in Doom (each start spawns the player in turn and the last keeps it; an
/// earlier one is a "voodoo doll": freedoom2's MAP20 has one on a
/// conveyor). With none in the map, the first is reported outside.
fn find_player_start(map: &Map) -> Result<usize, Problem> {
    for (i, t) in map.things.iter().enumerate() {
        if !in_range(t.pos.x) || !in_range(t.pos.y) || !t.angle.is_finite() {
            return Err(Problem::BadThing { thing: i });
        }
    }
    let mut starts = map.things.iter().enumerate().filter(|(_, t)| t.kind == PLAYER_START).map(|(i, _)| i);
    let first = starts.next().ok_or(Problem::NoPlayerStart)?;
    let start = starts.filter(|&i| map.contains(map.things[i].pos)).last().unwrap_or(first);
    let p = map.things[start].pos;
    // In the map, a point on a two-sided line included; which sector it is
    // in is for the BSP to say, once compiled (CompiledMap::locate).
    if map.contains(p) {
        Ok(start)
    } else {
        Err(Problem::StartOutside { thing: start, x: p.x, y: p.y })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::map::parse_map;

    /// A 256-unit room (clockwise) with a square loop inside it, given as
    /// vertex order and the loop's line sides.
    fn room_with_inner_loop(inner: &str, inner_sector: &str, extra_sectors: &str) -> String {
        format!(
            r#"Map(name: "t",
            vertices: [(0.0, 0.0), (0.0, 256.0), (256.0, 256.0), (256.0, 0.0),
                       (100.0, 100.0), (100.0, 150.0), (150.0, 150.0), (150.0, 100.0)],
            sectors: [Sector(floor: 0.0, ceiling: 128.0, light: 160), {extra_sectors}],
            lines: [
                Line(from: 0, to: 1, front: Side(sector: 0)), Line(from: 1, to: 2, front: Side(sector: 0)),
                Line(from: 2, to: 3, front: Side(sector: 0)), Line(from: 3, to: 0, front: Side(sector: 0)),
                {inner}
            ],
            things: [Thing(kind: "player_start", x: 50.0, y: 50.0, angle: 0.0)])"#
        )
        .replace("SECTOR", inner_sector)
    }

    fn loop_lines(order: [usize; 4], side: &str) -> String {
        (0..4).map(|k| format!("Line(from: {}, to: {}, front: {side}),", order[k], order[(k + 1) % 4])).collect()
    }

    fn problems(text: &str) -> Vec<Problem> {
        parse_map(text, "t.ron").err().map(|e| e.problems().to_vec()).unwrap_or_default()
    }

    #[test]
    fn the_last_player_start_in_the_map_is_the_player() {
        let things = |list: &str| {
            room_with_inner_loop("", "", "").replace(
                r#"things: [Thing(kind: "player_start", x: 50.0, y: 50.0, angle: 0.0)]"#,
                &format!("things: [{list}]"),
            )
        };
        let start = |text: String| parse_map(&text, "t.ron").unwrap_or_else(|e| panic!("{e}")).player_start().pos;
        let first = r#"Thing(kind: "player_start", x: 50.0, y: 50.0, angle: 0.0)"#;
        let last = r#"Thing(kind: "player_start", x: 200.0, y: 200.0, angle: 90.0)"#;
        let outside = r#"Thing(kind: "player_start", x: 900.0, y: 900.0, angle: 90.0)"#;
        assert_eq!(start(things(&format!("{first}, {last}"))), glam::DVec2::new(200.0, 200.0));
        assert_eq!(start(things(&format!("{first}, {last}, {outside}"))), glam::DVec2::new(200.0, 200.0));
    }

    #[test]
    fn pillar_wound_either_way() {
        // Counter-clockwise (room on the right of each pillar edge): valid.
        let good = room_with_inner_loop(&loop_lines([4, 7, 6, 5], "Side(sector: 0)"), "", "");
        assert_eq!(problems(&good), vec![]);
        // Clockwise: closure and the sector's total winding both still pass.
        let bad = room_with_inner_loop(&loop_lines([4, 5, 6, 7], "Side(sector: 0)"), "", "");
        let p = problems(&bad);
        assert!(matches!(p[0], Problem::SideMismatch { line: 4.., .. }), "{p:?}");
        assert!(p[0].to_string().contains("winding"), "{}", p[0]);
    }

    #[test]
    fn nested_sector_needs_a_two_sided_boundary() {
        // A closed sector 1 inside sector 0 whose walls face only into itself.
        let nested = room_with_inner_loop(
            &loop_lines([4, 5, 6, 7], "Side(sector: 1)"),
            "",
            "Sector(floor: 0.0, ceiling: 128.0, light: 160)",
        );
        let p = problems(&nested);
        assert!(p.iter().any(|p| matches!(p, Problem::SideMismatch { side: "back", expected: None, .. })), "{p:?}");
        // The same loop as two-sided lines between the sectors is valid.
        let portal = room_with_inner_loop(
            &loop_lines([4, 5, 6, 7], "Side(sector: 1), back: Some(Side(sector: 0))"),
            "",
            "Sector(floor: 16.0, ceiling: 128.0, light: 160)",
        );
        assert_eq!(problems(&portal), vec![]);
    }

    #[test]
    fn misspelt_field_is_an_error() {
        let text = room_with_inner_loop("", "", "").replace("light: 160)", "light: 160, flor_texture: \"X\")");
        let err = parse_map(&text, "t.ron").unwrap_err().to_string();
        assert!(err.contains("flor_texture") && err.starts_with("t.ron:"), "{err}");
    }
}
