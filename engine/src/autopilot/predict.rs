//! What a special line does to the level's heights, foretold: the end
//! state of every mover whose result Doom fixes in advance (doors, floors
//! and ceilings to their targets, lifts, both stair builders, donuts), for
//! the planner's search and `check`'s closure, and which results cannot be
//! foretold ([`unforeseeable`]).

use super::nav::Heights;
use super::sectors::{self, target_sectors};
use crate::level::Level;
use crate::map::special::{Action, CeilingTarget, DoorKind, LineSpecial};
use crate::play::world::SpecialLine;

/// The heights after `special` (set off by `line`) has done its work, as
/// far as they can be foretold (see [`unforeseeable`]); `None` when it
/// changes nothing that can be foretold.
///
/// Doors open to their lowest neighbouring ceiling less 4 or shut on the
/// floor; floors and ceilings go to their targets; lifts range from their
/// lowest neighbouring floor to their top (a perpetual lift up to its
/// highest neighbour); stairs rise step by step through the sectors Doom's
/// `EV_BuildStairs` claims; a donut's hole sinks and its ring rises to the
/// floor beyond the ring (`EV_DoDonut`). A crusher's ceiling comes back up
/// to where it was, and changes nothing a route needs.
pub fn predict(level: &Level, heights: &Heights, line: SpecialLine, special: &LineSpecial) -> Option<Heights> {
    let mut h = heights.clone();
    let mut changed = false;
    let map = &level.compiled.map;
    match special.action {
        Action::Stairs { step, .. } => return stairs(level, special.tag, step, &mut h).then_some(h),
        Action::Donut { .. } => return donut(level, special.tag, &mut h).then_some(h),
        _ => {}
    }
    for s in target_sectors(level, line, special) {
        let sector = &map.sectors[s];
        match &special.action {
            Action::Door { kind: DoorKind::Open | DoorKind::Raise, .. } => {
                if let Some(top) = sectors::lowest_ceiling_around(level, s) {
                    if top - 4.0 > h.ceiling[s] {
                        h.ceiling[s] = top - 4.0;
                        changed = true;
                    }
                }
            }
            Action::Door { kind: DoorKind::Close, .. } => {
                if h.ceiling[s] > h.floor[s] {
                    h.ceiling[s] = h.floor[s];
                    changed = true;
                }
            }
            // Shut for 30 seconds, then open as it was.
            Action::Door { kind: DoorKind::CloseThenOpen, .. } => {}
            Action::Floor { to, offset, .. } => {
                // A move by so much goes from where the floor is by then
                // (two switches raising one floor by 32 each lift it 64).
                let dest = match to {
                    crate::map::special::FloorTarget::Current => h.floor[s] + offset,
                    _ => sectors::floor_destination(level, s, *to, *offset),
                };
                if dest != sector.floor {
                    h.floor[s] = dest;
                    h.low[s] = h.low[s].min(dest);
                    changed = true;
                }
            }
            Action::Ceiling { to, offset, .. } => {
                let target = match to {
                    CeilingTarget::Floor => sector.floor,
                    CeilingTarget::HighestNeighbourCeiling => {
                        sectors::highest_ceiling_around(level, s).unwrap_or(sector.ceiling)
                    }
                    CeilingTarget::LowestNeighbourCeiling => {
                        sectors::lowest_ceiling_around(level, s).unwrap_or(sector.ceiling)
                    }
                    CeilingTarget::Current => sector.ceiling,
                } + offset;
                if target != h.ceiling[s] {
                    h.ceiling[s] = target;
                    changed = true;
                }
            }
            Action::Lift { .. } => {
                let low = sectors::lowest_floor_around(level, s);
                if low < h.low[s] {
                    h.low[s] = low;
                    changed = true;
                }
            }
            Action::PerpetualLift { .. } => {
                let low = sectors::lowest_floor_around(level, s);
                let high = sectors::highest_floor_around(level, s).unwrap_or(sector.floor).max(h.floor[s]);
                if low < h.low[s] || high > h.floor[s] {
                    h.low[s] = h.low[s].min(low);
                    h.floor[s] = high;
                    changed = true;
                }
            }
            Action::Crusher { .. } | Action::StopCrusher | Action::StopLift => {}
            _ => return None,
        }
    }
    changed.then_some(h)
}

/// Why the end of `special` cannot be foretold, if it cannot: what it does
/// depends on more than the map as it stands.
pub fn unforeseeable(level: &Level, special: &LineSpecial) -> Option<&'static str> {
    let map = &level.compiled.map;
    match special.action {
        Action::Stairs { .. } | Action::Donut { .. } if special.tag == 0 => {
            Some("it has no tag (Doom would act on every untagged sector)")
        }
        Action::Donut { .. } => {
            let hole_open = map
                .sectors_tagged(special.tag)
                .all(|s| level.sector_lines[s].first().is_some_and(|&l| map.lines[l as usize].back.is_some()));
            (!hole_open).then_some("a donut hole's first line is one-sided (vanilla reads invalid memory there)")
        }
        _ => None,
    }
}

/// `EV_BuildStairs` foretold: from each tagged sector (the search for the
/// next going on from the last step built, as vanilla's does), a step
/// rises by `step` above its floor now, then the sector behind the first
/// two-sided line facing out of it with the same floor flat one step more,
/// and so on; a sector already claimed by a step is passed over but still
/// counts a step's height. Returns whether any floor moves.
fn stairs(level: &Level, tag: u16, step: f64, h: &mut Heights) -> bool {
    let map = &level.compiled.map;
    if tag == 0 {
        return false;
    }
    let n = map.sectors.len();
    let mut claimed = vec![false; n];
    let mut changed = false;
    let mut set = |h: &mut Heights, s: usize, height: f64| {
        if height != h.floor[s] {
            changed = true;
        }
        h.low[s] = h.low[s].min(height);
        h.floor[s] = height;
    };
    let mut after: Option<usize> = None;
    while let Some(first) = (after.map_or(0, |s| s + 1)..n).find(|&s| map.sectors[s].tag == tag) {
        after = Some(first);
        if claimed[first] {
            continue;
        }
        claimed[first] = true;
        let mut sec = first;
        let mut height = h.floor[first] + step;
        set(h, sec, height);
        let texture = &map.sectors[first].floor_texture;
        'steps: loop {
            for &l in &level.sector_lines[sec] {
                let line = &map.lines[l as usize];
                let Some(back) = &line.back else { continue };
                if line.front.sector != sec || &map.sectors[back.sector].floor_texture != texture {
                    continue;
                }
                height += step;
                if claimed[back.sector] {
                    continue;
                }
                claimed[back.sector] = true;
                sec = back.sector;
                after = Some(sec);
                set(h, sec, height);
                continue 'steps;
            }
            break;
        }
    }
    changed
}

/// `EV_DoDonut` foretold: for each tagged sector (the hole), the sector
/// across its first line (the ring) rises, and the hole sinks, to the floor
/// behind the first of the ring's lines whose back is not the hole. A ring
/// line with no back is passed over (vanilla reads memory there, see
/// [`unforeseeable`]). Returns whether any floor moves.
fn donut(level: &Level, tag: u16, h: &mut Heights) -> bool {
    let map = &level.compiled.map;
    let mut changed = false;
    for hole in map.sectors_tagged(tag).collect::<Vec<_>>() {
        let Some(&first) = level.sector_lines[hole].first() else { continue };
        let line = &map.lines[first as usize];
        let Some(back) = &line.back else { break };
        let ring = if line.front.sector == hole { back.sector } else { line.front.sector };
        for &l in &level.sector_lines[ring] {
            let Some(beyond) = map.lines[l as usize].back.as_ref().map(|b| b.sector) else { continue };
            if beyond == hole {
                continue;
            }
            let height = map.sectors[beyond].floor;
            for s in [ring, hole] {
                if h.floor[s] != height {
                    changed = true;
                }
                h.low[s] = h.low[s].min(height);
                h.floor[s] = height;
            }
            break;
        }
    }
    changed
}
