//! What a special will do to the converted map's sectors, as the bot
//! foresees it from the heights it sees (Doom's neighbour searches,
//! `P_FindLowestFloorSurrounding` and the rest, in map units): the
//! planner's model of lifts, doors and floors. The game itself runs them
//! in the simulation (`sim::floors` and its siblings).

use crate::level::Level;
use crate::map::special::FloorTarget;
use crate::map::LineSpecial;
use crate::play::world::SpecialLine;

/// The sectors a special acts on: those with its tag, or with none, the
/// sector behind its line.
pub fn target_sectors(level: &Level, line: SpecialLine, special: &LineSpecial) -> Vec<usize> {
    let map = &level.compiled.map;
    if special.tag != 0 {
        return map.sectors_tagged(special.tag).collect();
    }
    match line {
        SpecialLine::Wall(i) => map.lines[i].back.as_ref().map(|b| b.sector).into_iter().collect(),
        SpecialLine::Trigger(_) => Vec::new(),
    }
}

/// The sectors across the two-sided lines of `sector`, once per line, in the
/// order of its lines (Doom's `getNextSector` over `sector->lines`); a line
/// with `sector` on both sides leads nowhere (Boom's rule).
pub fn neighbours(level: &Level, sector: usize) -> impl Iterator<Item = usize> + '_ {
    let map = &level.compiled.map;
    level.sector_lines[sector].iter().filter_map(move |&i| {
        let line = &map.lines[i as usize];
        let back = line.back.as_ref()?.sector;
        match (line.front.sector == sector, back == sector) {
            (true, false) => Some(back),
            (false, true) => Some(line.front.sector),
            _ => None,
        }
    })
}

/// The lowest floor around `sector`, its own included (never above it).
pub fn lowest_floor_around(level: &Level, sector: usize) -> f64 {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].floor).fold(sectors[sector].floor, f64::min)
}

/// The highest neighbouring floor, its own not included; `None` with no neighbours.
pub fn highest_floor_around(level: &Level, sector: usize) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].floor).reduce(f64::max)
}

/// The lowest neighbouring floor above `height`, if any.
pub fn next_higher_floor(level: &Level, sector: usize, height: f64) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].floor).filter(|&f| f > height).reduce(f64::min)
}

/// The highest neighbouring floor below `height`, if any (Boom's P_FindNextLowestFloor).
pub fn next_lower_floor(level: &Level, sector: usize, height: f64) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].floor).filter(|&f| f < height).reduce(f64::max)
}

/// The lowest neighbouring ceiling, its own not included; `None` with no neighbours.
pub fn lowest_ceiling_around(level: &Level, sector: usize) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].ceiling).reduce(f64::min)
}

/// The highest neighbouring ceiling; `None` with no neighbours.
pub fn highest_ceiling_around(level: &Level, sector: usize) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].ceiling).reduce(f64::max)
}

/// The height of the shortest lower texture on either side of the
/// two-sided lines of `sector` (Doom's raise-to-texture; sides without a
/// lower texture do not count, as in Boom). `None` when there is none.
pub fn shortest_lower_texture(level: &Level, sector: usize) -> Option<f64> {
    let map = &level.compiled.map;
    let mut shortest: Option<usize> = None;
    for &i in &level.sector_lines[sector] {
        let i = i as usize;
        if map.lines[i].back.is_none() {
            continue;
        }
        for side in &level.materials.sides[i] {
            if let Some(id) = side.lower {
                let h = level.materials.textures.get(id).height;
                shortest = Some(shortest.map_or(h, |s| s.min(h)));
            }
        }
    }
    shortest.map(|h| h as f64)
}

/// Where a floor mover to `to` (plus `offset`) takes `sector`'s floor.
pub fn floor_destination(level: &Level, sector: usize, to: FloorTarget, offset: f64) -> f64 {
    let s = &level.compiled.map.sectors[sector];
    let target = match to {
        FloorTarget::LowestNeighbourFloor => lowest_floor_around(level, sector),
        FloorTarget::HighestNeighbourFloor => {
            let h = highest_floor_around(level, sector).unwrap_or(s.floor);
            // Doom's turbo lower adds its 8 only when the floor moves at all.
            if h == s.floor {
                return h;
            }
            h
        }
        FloorTarget::NextHigherFloor => next_higher_floor(level, sector, s.floor).unwrap_or(s.floor),
        FloorTarget::NextLowerFloor => next_lower_floor(level, sector, s.floor).unwrap_or(s.floor),
        FloorTarget::Ceiling => s.ceiling,
        FloorTarget::LowestNeighbourCeiling => {
            lowest_ceiling_around(level, sector).map_or(s.ceiling, |c| c.min(s.ceiling))
        }
        FloorTarget::ShortestLowerTexture => match shortest_lower_texture(level, sector) {
            Some(h) => s.floor + h,
            None => return s.floor,
        },
        FloorTarget::Current => s.floor,
    };
    target + offset
}
