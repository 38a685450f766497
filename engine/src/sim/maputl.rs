//! Geometry questions over the level (`p_maputl.c`): which side of a line a
//! box is on, the opening between two sectors, the blockmap's line and
//! thing iterators, and `P_PathTraverse` with its intercepts in Doom's order.
//! Collision (`collision.rs`), the hitscan traces (`hitscan.rs`) and the
//! player's wall slide ask these; they hand back plain indices and fixed
//! values, never references into the level.

use super::level::{Line, SlopeType, BOXBOTTOM, BOXLEFT, BOXRIGHT, BOXTOP, MAPBLOCKSHIFT};
use super::{Compat, MobjId, Sim};
use crate::fixed::{intercept_vector, point_on_divline_side, point_on_line_side, Divline, Fixed, Side, FRACUNIT};
use crate::wad::level::WadThing;

/// `MAPBLOCKSIZE`: a blockmap cell's side in fixed point.
pub const MAPBLOCKSIZE: i32 = 128 * FRACUNIT;
/// `MAPBTOFRAC`: from map coordinates to a 16.16 fraction of cells.
const MAPBTOFRAC: u32 = MAPBLOCKSHIFT - 16;

/// `PT_ADDLINES`, `PT_ADDTHINGS`, `PT_EARLYOUT`: what a path traversal
/// collects.
pub const PT_ADDLINES: u32 = 1;
pub const PT_ADDTHINGS: u32 = 2;
pub const PT_EARLYOUT: u32 = 4;

/// The intercepts array's size in vanilla (`MAXINTERCEPTS_ORIGINAL`):
/// more than this overwrite the globals after it (see [`intercepts_overrun`]).
const MAXINTERCEPTS_ORIGINAL: usize = 128;

/// `P_LineOpening`'s globals: the window through a two-sided line.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Opening {
    pub top: Fixed,
    pub bottom: Fixed,
    pub range: Fixed,
    /// The lower of the two floors (for the drop-off).
    pub lowfloor: Fixed,
}

/// What an intercept is: a line or a body crossed by the trace.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hit {
    Line(usize),
    Thing(MobjId),
}

/// One crossing (`intercept_t`): how far along the trace (a 16.16 fraction
/// of its length) and what.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Intercept {
    pub frac: Fixed,
    pub hit: Hit,
}

/// `P_MakeDivline`: a map line through its first vertex.
pub fn line_divline(line: &Line) -> Divline {
    Divline { x: line.v1.0, y: line.v1.1, dx: line.dx, dy: line.dy }
}

/// `P_PointOnLineSide` on a map line: 0 front, 1 back.
pub fn point_on_map_line_side(x: Fixed, y: Fixed, line: &Line) -> usize {
    point_on_line_side(x, y, &line_divline(line)).index()
}

/// Whether a box (`BOXTOP`..`BOXRIGHT`) touches a line: their boxes
/// overlap and the line does not pass wholly on one side of it
/// (`PIT_CheckLine`'s first two tests).
pub fn box_touches_line(b: &[Fixed; 4], line: &Line) -> bool {
    let l = &line.bbox;
    !(b[BOXRIGHT] <= l[BOXLEFT] || b[BOXLEFT] >= l[BOXRIGHT] || b[BOXTOP] <= l[BOXBOTTOM] || b[BOXBOTTOM] >= l[BOXTOP])
        && box_on_line_side(b, line) == -1
}

/// `P_BoxOnLineSide`: 0 or 1 when the box is wholly on one side of the
/// (infinite) line, -1 when it crosses it. Axis-aligned lines compare the
/// box's edges with `>`/`<`, so a box edge exactly on the line counts as
/// the side the line's own test would not give it.
pub fn box_on_line_side(bbox: &[Fixed; 4], line: &Line) -> i32 {
    let (p1, p2) = match line.slopetype {
        SlopeType::Horizontal => {
            let flip = line.dx.0 < 0;
            ((bbox[BOXTOP] > line.v1.1) ^ flip, (bbox[BOXBOTTOM] > line.v1.1) ^ flip)
        }
        SlopeType::Vertical => {
            let flip = line.dy.0 < 0;
            ((bbox[BOXRIGHT] < line.v1.0) ^ flip, (bbox[BOXLEFT] < line.v1.0) ^ flip)
        }
        SlopeType::Positive => (
            point_on_map_line_side(bbox[BOXLEFT], bbox[BOXTOP], line) == 1,
            point_on_map_line_side(bbox[BOXRIGHT], bbox[BOXBOTTOM], line) == 1,
        ),
        SlopeType::Negative => (
            point_on_map_line_side(bbox[BOXRIGHT], bbox[BOXTOP], line) == 1,
            point_on_map_line_side(bbox[BOXLEFT], bbox[BOXBOTTOM], line) == 1,
        ),
    };
    if p1 == p2 {
        i32::from(p1)
    } else {
        -1
    }
}

/// `P_LineOpening`: sets `sim.tm.opening` to the window through `line`. A
/// one-sided line sets only the range (to 0) and leaves the rest as the
/// last two-sided line left them, as Doom does.
pub fn line_opening(sim: &mut Sim, line: usize) {
    let Some(ld) = sim.level.lines.get(line) else {
        sim.tm.opening.range = Fixed::ZERO;
        return;
    };
    let (Some(f), Some(b), Some(_)) = (ld.frontsector, ld.backsector, ld.sidenum[1]) else {
        sim.tm.opening.range = Fixed::ZERO;
        return;
    };
    let (front, back) = (&sim.level.sectors[f], &sim.level.sectors[b]);
    let o = &mut sim.tm.opening;
    o.top = front.ceilingheight.min(back.ceilingheight);
    if front.floorheight > back.floorheight {
        o.bottom = front.floorheight;
        o.lowfloor = back.floorheight;
    } else {
        o.bottom = back.floorheight;
        o.lowfloor = front.floorheight;
    }
    o.range = o.top - o.bottom;
}

/// `validcount++`: a new round of line marks, before each set of
/// [`block_lines`] calls (and each sight check).
pub fn next_validcount(sim: &mut Sim) {
    sim.validcount = sim.validcount.wrapping_add(1);
}

/// `P_BlockLinesIterator`: `f` on each line listed in cell (`x`, `y`) and
/// not yet marked with the current `validcount` (marking it), until it
/// returns false; whether every call returned true. Cells outside the
/// blockmap hold nothing.
pub fn block_lines(sim: &mut Sim, x: i32, y: i32, mut f: impl FnMut(&mut Sim, usize) -> bool) -> bool {
    let bm = &sim.level.blockmap;
    if x < 0 || y < 0 || x >= bm.width || y >= bm.height {
        return true;
    }
    let Some(&offset) = bm.words.get(4 + (y * bm.width + x) as usize) else {
        return true;
    };
    // The blockmap is never changed in play, so the list is read in place
    // word by word while `f` changes the rest of the world.
    let mut at = offset as u16 as usize;
    loop {
        let word = match sim.level.blockmap.words.get(at) {
            Some(&w) if w != -1 => w as u16 as usize,
            _ => return true,
        };
        at += 1;
        let Some(mark) = sim.line_valid.get_mut(word) else {
            continue;
        };
        if *mark == sim.validcount {
            continue;
        }
        *mark = sim.validcount;
        if !f(sim, word) {
            return false;
        }
    }
}

/// `P_BlockThingsIterator`: `f` on each body linked in cell (`x`, `y`), in
/// Doom's order (most recently linked first), until it returns false;
/// whether every call returned true.
///
/// Doom reads `mobj->bnext` after `f` returns. A body `f` unlinked keeps
/// the `bnext` it had, so the walk goes on to the body after it; one that
/// `f` relinked into the same cell sits at the head, so the walk starts
/// over from the body that was the head. Both are what the cell's order
/// after `f` gives, which is how the next body is found here.
pub fn block_things(sim: &mut Sim, x: i32, y: i32, mut f: impl FnMut(&mut Sim, MobjId) -> bool) -> bool {
    let bm = &sim.level.blockmap;
    if x < 0 || y < 0 || x >= bm.width || y >= bm.height {
        return true;
    }
    let cell = (y * bm.width + x) as usize;
    // The cell's Vec is oldest first; Doom's list is newest first.
    let mut next = sim.blocklinks.get(cell).and_then(|c| c.last().copied());
    while let Some(mo) = next {
        // What Doom's `bnext` is now: the body linked just before this one.
        let before = sim.blocklinks[cell].iter().position(|&m| m == mo).and_then(|i| i.checked_sub(1));
        let fallback = before.map(|i| sim.blocklinks[cell][i]);
        if !f(sim, mo) {
            return false;
        }
        let list = &sim.blocklinks[cell];
        next = match list.iter().position(|&m| m == mo) {
            Some(i) => i.checked_sub(1).map(|i| list[i]),
            // Unlinked by `f`: its stale `bnext` is the body that was after it.
            None => fallback,
        };
    }
    true
}

/// The trace of a path traversal (`trace`) and whether a solid line ends
/// the collection (`earlyout`).
struct Collect {
    trace: Divline,
    earlyout: bool,
    intercepts: Vec<Intercept>,
}

/// `PIT_AddLineIntercepts`: whether the collection goes on (false only for
/// an early-out on a one-sided line).
fn add_line_intercept(sim: &mut Sim, c: &mut Collect, line: usize) -> bool {
    let ld = &sim.level.lines[line];
    let t = &c.trace;
    let sixteen = 16 * FRACUNIT;
    // Doom's two routines, to "avoid precision problems": long traces test
    // the line's ends against the trace, short ones the trace's against the line.
    let (s1, s2) = if t.dx.0 > sixteen || t.dy.0 > sixteen || t.dx.0 < -sixteen || t.dy.0 < -sixteen {
        (point_on_divline_side(ld.v1.0, ld.v1.1, t), point_on_divline_side(ld.v2.0, ld.v2.1, t))
    } else {
        let dl = line_divline(ld);
        (point_on_line_side(t.x, t.y, &dl), point_on_line_side(t.x + t.dx, t.y + t.dy, &dl))
    };
    if s1 == s2 {
        return true;
    }
    let frac = intercept_vector(t, &line_divline(ld));
    if frac.0 < 0 {
        return true;
    }
    if c.earlyout && frac.0 < FRACUNIT && ld.backsector.is_none() {
        return false;
    }
    push_intercept(sim, c, Intercept { frac, hit: Hit::Line(line) });
    true
}

/// `PIT_AddThingIntercepts`: a body is crossed along the diagonal of its
/// box that runs across the trace.
fn add_thing_intercept(sim: &mut Sim, c: &mut Collect, thing: MobjId) -> bool {
    let t = &c.trace;
    let mo = sim.mo(thing);
    let tracepositive = (t.dx.0 ^ t.dy.0) > 0;
    let (x1, x2) = (mo.x - mo.radius, mo.x + mo.radius);
    let (y1, y2) =
        if tracepositive { (mo.y + mo.radius, mo.y - mo.radius) } else { (mo.y - mo.radius, mo.y + mo.radius) };
    let s1: Side = point_on_divline_side(x1, y1, t);
    let s2: Side = point_on_divline_side(x2, y2, t);
    if s1 == s2 {
        return true;
    }
    let dl = Divline { x: x1, y: y1, dx: x2 - x1, dy: y2 - y1 };
    let frac = intercept_vector(t, &dl);
    if frac.0 < 0 {
        return true;
    }
    push_intercept(sim, c, Intercept { frac, hit: Hit::Thing(thing) });
    true
}

fn push_intercept(sim: &mut Sim, c: &mut Collect, intercept: Intercept) {
    let index = c.intercepts.len();
    c.intercepts.push(intercept);
    if sim.rules.compat == Compat::Vanilla {
        intercepts_overrun(&mut sim.tm.opening, &mut sim.starts, index, &intercept);
    }
}

/// Vanilla's `intercepts[128]` has no bounds check: entries past its end
/// overwrite the globals that follow it in doom.exe's data segment.
/// Chocolate Doom (after PrBoom-plus) emulates the writes from its 130th
/// entry on (`InterceptsOverrun`: 12 bytes an entry, `frac`, `isaline`,
/// then the pointer). Of the targets, those held here are `P_LineOpening`'s
/// four values (bytes 12..28) and `playerstarts` (bytes 176..216, as
/// 16-bit halves: a netgame's rebirth reads them). Not emulated: the
/// pointer values (heap addresses even in Chocolate, so not reproducible),
/// `bulletslope` (byte 160, the 142nd entry's `isaline`: the weapons keep
/// it as a local), and the blockmap's header (bytes 220..244: rewriting
/// the blockmap's size and origin in play would need the links rebuilt).
fn intercepts_overrun(o: &mut Opening, starts: &mut [Option<WadThing>], index: usize, intercept: &Intercept) {
    if index <= MAXINTERCEPTS_ORIGINAL {
        return;
    }
    let location = (index - MAXINTERCEPTS_ORIGINAL - 1) * 12;
    let isaline = i32::from(matches!(intercept.hit, Hit::Line(_)));
    for (at, value) in [(location, intercept.frac.0), (location + 4, isaline)] {
        match at {
            12..=15 => o.lowfloor = Fixed(value),
            16..=19 => o.bottom = Fixed(value),
            20..=23 => o.top = Fixed(value),
            24..=27 => o.range = Fixed(value),
            176..=215 => {
                let short = (at - 176) / 2;
                set_start_short(starts, short, value as u16);
                set_start_short(starts, short + 1, (value >> 16) as u16);
            }
            _ => {}
        }
    }
}

/// Writes 16-bit word `short` of `playerstarts` (five words a start: x, y,
/// angle, type, options). A start the level did not have stays absent
/// (Chocolate keeps whether a start was found apart from the words).
fn set_start_short(starts: &mut [Option<WadThing>], short: usize, value: u16) {
    let Some(Some(start)) = starts.get_mut(short / 5) else {
        return;
    };
    match short % 5 {
        0 => start.x = value as i16,
        1 => start.y = value as i16,
        2 => start.angle = value as i16,
        3 => start.kind = value,
        _ => start.flags = value,
    }
}

/// `P_PathTraverse`: traces from (`x1`, `y1`) to (`x2`, `y2`) through the
/// blockmap, collecting the lines and/or bodies crossed (`flags`), then
/// calls `trav` on them nearest first (`P_TraverseIntercepts`) with the
/// trace, up to the trace's end; whether `trav` returned true for all.
pub fn path_traverse(
    sim: &mut Sim,
    x1: Fixed,
    y1: Fixed,
    x2: Fixed,
    y2: Fixed,
    flags: u32,
    mut trav: impl FnMut(&mut Sim, &Intercept, &Divline) -> bool,
) -> bool {
    next_validcount(sim);
    let (orgx, orgy) = (sim.level.blockmap.orgx, sim.level.blockmap.orgy);
    let (mut x1, mut y1) = (x1, y1);
    // Don't start exactly on a cell's edge.
    if (x1 - orgx).0 & (MAPBLOCKSIZE - 1) == 0 {
        x1 += Fixed::ONE;
    }
    if (y1 - orgy).0 & (MAPBLOCKSIZE - 1) == 0 {
        y1 += Fixed::ONE;
    }
    let mut c = Collect {
        trace: Divline { x: x1, y: y1, dx: x2 - x1, dy: y2 - y1 },
        earlyout: flags & PT_EARLYOUT != 0,
        intercepts: Vec::new(),
    };
    let (x1, y1, x2, y2) = (x1 - orgx, y1 - orgy, x2 - orgx, y2 - orgy);
    let (xt1, yt1) = (x1.0 >> MAPBLOCKSHIFT, y1.0 >> MAPBLOCKSHIFT);
    let (xt2, yt2) = (x2.0 >> MAPBLOCKSHIFT, y2.0 >> MAPBLOCKSHIFT);
    let frac_in_cell = |v: Fixed| (v.0 >> MAPBTOFRAC) & (FRACUNIT - 1);
    let (mapxstep, partial, ystep) = if xt2 > xt1 {
        (1, FRACUNIT - frac_in_cell(x1), (y2 - y1) / (x2 - x1).abs())
    } else if xt2 < xt1 {
        (-1, frac_in_cell(x1), (y2 - y1) / (x2 - x1).abs())
    } else {
        (0, FRACUNIT, Fixed(256 * FRACUNIT))
    };
    let mut yintercept = Fixed(y1.0 >> MAPBTOFRAC) + Fixed(partial) * ystep;
    let (mapystep, partial, xstep) = if yt2 > yt1 {
        (1, FRACUNIT - frac_in_cell(y1), (x2 - x1) / (y2 - y1).abs())
    } else if yt2 < yt1 {
        (-1, frac_in_cell(y1), (x2 - x1) / (y2 - y1).abs())
    } else {
        (0, FRACUNIT, Fixed(256 * FRACUNIT))
    };
    let mut xintercept = Fixed(x1.0 >> MAPBTOFRAC) + Fixed(partial) * xstep;
    let (mut mapx, mut mapy) = (xt1, yt1);
    let around = (sim.rules.compat == Compat::Sightline).then(|| cells_a_box_reaches(sim));
    let mut crossed = Vec::new();
    // At most 64 cells: the count stops a rounding error from missing the end.
    for _ in 0..64 {
        if flags & PT_ADDLINES != 0 && !block_lines(sim, mapx, mapy, |sim, line| add_line_intercept(sim, &mut c, line))
        {
            return false;
        }
        if flags & PT_ADDTHINGS != 0 {
            if around.is_some() {
                crossed.push((mapx, mapy));
            } else if !block_things(sim, mapx, mapy, |sim, thing| add_thing_intercept(sim, &mut c, thing)) {
                return false;
            }
        }
        if mapx == xt2 && mapy == yt2 {
            break;
        }
        if yintercept.0 >> 16 == mapy {
            yintercept += ystep;
            mapx = mapx.wrapping_add(mapxstep);
        } else if xintercept.0 >> 16 == mapx {
            xintercept += xstep;
            mapy = mapy.wrapping_add(mapystep);
        }
    }
    if let Some(reach) = around {
        add_things_around(sim, &mut c, &crossed, reach);
    }
    traverse_intercepts(sim, &mut c.intercepts, &c.trace, Fixed::ONE, &mut trav)
}

/// How many cells past the one its centre is linked in a body's box can
/// reach: the largest radius in cells, rounded up (1 for Doom's kinds,
/// whose largest radius is 128, a cell's side), and never more than the
/// blockmap is wide or high.
fn cells_a_box_reaches(sim: &Sim) -> i32 {
    let radius = i64::from(sim.info.largest_radius.0.max(0));
    let cells = (radius + i64::from(MAPBLOCKSIZE) - 1) >> MAPBLOCKSHIFT;
    let bm = &sim.level.blockmap;
    cells.min(i64::from(bm.width.max(bm.height))) as i32
}

/// Sightline's rules (ZDoom's): a trace meets every body whose box it
/// crosses. Doom links a body in the one cell its centre is in and looks
/// only in the cells the trace crosses, so a shot through the edge of a box
/// that reaches into the next cell misses (on ViZDoom's `basic`, a player
/// 2.6 units off the cacodemon's centre, across a cell edge from it, shot
/// past it). ZDoom links a body in every cell its box overlaps
/// (`AActor::LinkToWorld`'s block nodes) and takes each body once per
/// trace. Here the cells within `reach` of those `crossed` are searched,
/// each once, which finds the same bodies; Doom's test, the box's diagonal
/// across the trace (`add_thing_intercept`), spans as much across the trace
/// as the box does, so it keeps exactly those whose box the trace crosses.
/// Rejected: linking bodies in every cell they overlap, as ZDoom does. Every
/// collision check walks the cells of a box grown by `MAXRADIUS` and would
/// then meet a body once per cell, and the links are part of the saves.
fn add_things_around(sim: &mut Sim, c: &mut Collect, crossed: &[(i32, i32)], reach: i32) {
    let mut cells: Vec<(i32, i32)> = crossed
        .iter()
        .flat_map(|&(x, y)| (-reach..=reach).flat_map(move |dy| (-reach..=reach).map(move |dx| (y + dy, x + dx))))
        .collect();
    cells.sort_unstable();
    cells.dedup();
    for (y, x) in cells {
        block_things(sim, x, y, |sim, thing| add_thing_intercept(sim, c, thing));
    }
}

/// `P_TraverseIntercepts`: repeatedly the nearest intercept not yet taken
/// (the first of equal ones in collection order), until one lies beyond
/// `maxfrac` or `trav` says stop. A taken one's fraction becomes
/// `INT_MAX`, as Doom marks it.
fn traverse_intercepts<T>(
    ctx: &mut T,
    intercepts: &mut [Intercept],
    trace: &Divline,
    maxfrac: Fixed,
    trav: &mut impl FnMut(&mut T, &Intercept, &Divline) -> bool,
) -> bool {
    for _ in 0..intercepts.len() {
        let mut dist = Fixed::MAX;
        let mut nearest = None;
        for (i, scan) in intercepts.iter().enumerate() {
            if scan.frac < dist {
                dist = scan.frac;
                nearest = Some(i);
            }
        }
        if dist > maxfrac {
            return true;
        }
        // Every fraction is INT_MAX only when all are taken; Doom would
        // then call `trav` on a stale pointer, which maxfrac < INT_MAX rules out.
        let Some(i) = nearest else {
            return true;
        };
        let this = intercepts[i];
        if !trav(ctx, &this, trace) {
            return false;
        }
        intercepts[i].frac = Fixed::MAX;
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn u(n: i32) -> Fixed {
        Fixed::from_int(n)
    }

    fn line(v1: (i32, i32), v2: (i32, i32)) -> Line {
        Line::new(((u(v1.0), u(v1.1)), (u(v2.0), u(v2.1))), 0, 0, 0, [Some(0), None], [Some(0), None])
    }

    fn bbox(x: i32, y: i32, r: i32) -> [Fixed; 4] {
        [u(y + r), u(y - r), u(x - r), u(x + r)]
    }

    #[test]
    fn a_box_is_on_one_side_or_crosses() {
        // A wall going north at x = 100: its front (0) is the east.
        let wall = line((100, 0), (100, 200));
        assert_eq!(box_on_line_side(&bbox(150, 50, 16), &wall), 0);
        assert_eq!(box_on_line_side(&bbox(50, 50, 16), &wall), 1);
        assert_eq!(box_on_line_side(&bbox(90, 50, 16), &wall), -1);
        // Touching the line from the east: right edge 116 is not < 100, left
        // 100 is not < 100 either, so still wholly in front.
        assert_eq!(box_on_line_side(&bbox(116, 50, 16), &wall), 0);
        // A diagonal wall from (0,0) to (100,100), front to the south-east.
        let diag = line((0, 0), (100, 100));
        assert_eq!(box_on_line_side(&bbox(80, 20, 10), &diag), 0);
        assert_eq!(box_on_line_side(&bbox(20, 80, 10), &diag), 1);
        assert_eq!(box_on_line_side(&bbox(50, 50, 10), &diag), -1);
        // A wall going west: the flip makes the north its front.
        let west = line((200, 0), (0, 0));
        assert_eq!(box_on_line_side(&bbox(50, 50, 10), &west), 0);
        assert_eq!(box_on_line_side(&bbox(50, -50, 10), &west), 1);
    }

    #[test]
    fn nearest_intercepts_come_first_and_ties_keep_their_order() {
        let mut list = vec![
            Intercept { frac: Fixed(30000), hit: Hit::Line(1) },
            Intercept { frac: Fixed(10000), hit: Hit::Line(2) },
            Intercept { frac: Fixed(10000), hit: Hit::Thing(MobjId(3)) },
            Intercept { frac: Fixed(70000), hit: Hit::Line(4) },
        ];
        let mut seen = Vec::new();
        let all = traverse_intercepts(&mut seen, &mut list, &Divline::default(), Fixed::ONE, &mut |seen, i, _| {
            seen.push(i.hit);
            true
        });
        // 70000 is beyond the trace's end (65536): not visited, but all in range were.
        assert!(all);
        assert_eq!(seen, [Hit::Line(2), Hit::Thing(MobjId(3)), Hit::Line(1)]);
        // A traverser that stops at the first line leaves the rest unvisited.
        let mut list =
            vec![Intercept { frac: Fixed(500), hit: Hit::Line(7) }, Intercept { frac: Fixed(100), hit: Hit::Line(8) }];
        let mut seen = Vec::new();
        let all = traverse_intercepts(&mut seen, &mut list, &Divline::default(), Fixed::ONE, &mut |seen, i, _| {
            seen.push(i.hit);
            false
        });
        assert!(!all);
        assert_eq!(seen, [Hit::Line(8)]);
    }

    #[test]
    fn intercepts_past_the_129th_overwrite_the_opening() {
        let mut o = Opening { top: u(1), bottom: u(2), range: u(3), lowfloor: u(4) };
        let line = Intercept { frac: Fixed(777), hit: Hit::Line(9) };
        // Up to index 129 (byte 0: nothing held here is written).
        intercepts_overrun(&mut o, &mut [], 128, &line);
        intercepts_overrun(&mut o, &mut [], 129, &line);
        assert_eq!(o, Opening { top: u(1), bottom: u(2), range: u(3), lowfloor: u(4) });
        // Index 130 writes bytes 12..24: lowfloor the frac, openbottom isaline.
        intercepts_overrun(&mut o, &mut [], 130, &line);
        assert_eq!((o.lowfloor, o.bottom), (Fixed(777), Fixed(1)));
        // Index 131: openrange the frac (a thing's), byte 28 is nothing.
        intercepts_overrun(&mut o, &mut [], 131, &Intercept { frac: Fixed(555), hit: Hit::Thing(MobjId(0)) });
        assert_eq!((o.range, o.top), (Fixed(555), u(1)));
        // Index 144 writes bytes 180..188: start 0's angle and type get the
        // frac's halves, its options and start 1's x isaline's (absent
        // start 1: nothing).
        let start = WadThing { x: 10, y: 20, angle: 90, kind: 1, flags: 7 };
        let mut starts = [Some(start.clone()), None, None, None];
        let far = Intercept { frac: Fixed(0x0003_8000), hit: Hit::Line(0) };
        intercepts_overrun(&mut o, &mut starts, 144, &far);
        assert_eq!(starts[0], Some(WadThing { angle: -0x8000, kind: 3, flags: 1, ..start }));
        assert_eq!(starts[1], None);
    }
}
