//! Floors (Doom's p_floor.c and EV_DoDonut): a floor moves once to a
//! target (a neighbour's floor or ceiling, the next floor up, its lowest
//! lower texture, or by a distance), maybe taking a new texture and special;
//! stairs raise a chain of sectors a step higher each; a donut lowers a
//! pillar and raises the ring around it to the floor outside.

use super::mover::{move_plane, Moved, Plane};
use super::{specials, Ctx, Thinker, World};
use crate::level::Level;
use crate::map::special::{Change, ChangeFrom, FloorTarget, SpecialChange};
use crate::map::SectorSpecial;
use crate::play::events::{sound, Origin};

/// A floor special's parameters (from [`crate::map::Action::Floor`]).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Floor {
    pub to: FloorTarget,
    pub offset: f64,
    pub speed: f64,
    pub crush: bool,
    pub change: Option<Change>,
}

/// A new floor texture (and maybe special) taken from another sector.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Retexture {
    /// The sector whose floor texture is copied.
    pub from: usize,
    /// The special to set, `None` to keep the current one.
    pub special: Option<SectorSpecial>,
}

/// A floor at work.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FloorMove {
    pub sector: usize,
    pub dest: f64,
    pub speed: f64,
    pub up: bool,
    pub crush: bool,
    /// Applied on arrival.
    pub arrival: Option<Retexture>,
}

impl FloorMove {
    pub(super) fn think(&mut self, ctx: &mut Ctx) -> bool {
        let moved = move_plane(ctx, self.sector, Plane::Floor, self.speed, self.dest, self.crush, self.up);
        let origin = Origin::Sector(self.sector);
        if ctx.time % 8 == 0 {
            ctx.events.push(sound("stnmov", origin));
        }
        if moved != Moved::Arrived {
            return true;
        }
        if let Some(r) = self.arrival {
            retexture(ctx.level, self.sector, r);
        }
        ctx.events.push(sound("pstop", origin));
        false
    }
}

/// Gives `sector` the floor texture of `r.from` (and its special, if asked).
pub fn retexture(level: &mut Level, sector: usize, r: Retexture) {
    let texture = level.compiled.map.sectors[r.from].floor_texture.clone();
    level.compiled.map.sectors[sector].floor_texture = texture;
    level.materials.sectors[sector].floor = level.materials.sectors[r.from].floor;
    if let Some(special) = r.special {
        level.compiled.map.sectors[sector].special = special;
    }
}

/// The special a change gives, from its model sector.
fn new_special(level: &Level, model: usize, change: SpecialChange) -> Option<SectorSpecial> {
    match change {
        SpecialChange::Keep => None,
        SpecialChange::Copy => Some(level.compiled.map.sectors[model].special),
        SpecialChange::Clear => Some(SectorSpecial::default()),
    }
}

/// Where `floor` takes `sector`'s floor.
pub fn destination(level: &Level, sector: usize, floor: &Floor) -> f64 {
    let s = &level.compiled.map.sectors[sector];
    let target = match floor.to {
        FloorTarget::LowestNeighbourFloor => specials::lowest_floor_around(level, sector),
        FloorTarget::HighestNeighbourFloor => {
            let h = specials::highest_floor_around(level, sector).unwrap_or(s.floor);
            // Doom's turbo lower adds its 8 only when the floor moves at all.
            if h == s.floor {
                return h;
            }
            h
        }
        FloorTarget::NextHigherFloor => specials::next_higher_floor(level, sector, s.floor).unwrap_or(s.floor),
        FloorTarget::NextLowerFloor => specials::next_lower_floor(level, sector, s.floor).unwrap_or(s.floor),
        FloorTarget::Ceiling => s.ceiling,
        FloorTarget::LowestNeighbourCeiling => {
            specials::lowest_ceiling_around(level, sector).map_or(s.ceiling, |c| c.min(s.ceiling))
        }
        FloorTarget::ShortestLowerTexture => match specials::shortest_lower_texture(level, sector) {
            Some(h) => s.floor + h,
            None => return s.floor,
        },
        FloorTarget::Current => s.floor,
    };
    target + floor.offset
}

/// Starts `floor` on each idle sector of `sectors`. `trigger`: the front
/// sector of the line that set it off (the model of a trigger change).
pub fn start(world: &mut World, ctx: &mut Ctx, sectors: &[usize], floor: &Floor, trigger: Option<usize>) -> bool {
    let mut started = false;
    for &s in sectors {
        if world.is_busy(s) {
            continue;
        }
        let dest = destination(ctx.level, s, floor);
        let now = ctx.level.compiled.map.sectors[s].floor;
        let mut arrival = None;
        match floor.change {
            Some(Change { from: ChangeFrom::Trigger, special }) => {
                if let Some(model) = trigger {
                    let special = new_special(ctx.level, model, special);
                    retexture(ctx.level, s, Retexture { from: model, special });
                }
            }
            Some(Change { from: ChangeFrom::Neighbour, special }) => {
                let model =
                    specials::neighbours(ctx.level, s).find(|&n| ctx.level.compiled.map.sectors[n].floor == dest);
                arrival = model.map(|m| Retexture { from: m, special: new_special(ctx.level, m, special) });
            }
            None => {}
        }
        let up = dest > now;
        let mover = FloorMove { sector: s, dest, speed: floor.speed, up, crush: floor.crush, arrival };
        world.start(Thinker::Floor(mover));
        started = true;
    }
    started
}

/// Doom's EV_BuildStairs: each idle tagged sector rises by `step`; from it,
/// the stairs go on through its two-sided lines that have it in front and a
/// sector of the same floor texture behind, one step higher each. As in
/// vanilla Doom, a busy sector in the way is skipped but still counts a step,
/// and the search for the next tagged sector resumes after the last step's
/// sector number.
pub fn stairs(world: &mut World, ctx: &mut Ctx, tag: u16, step: f64, speed: f64, crush: bool) -> bool {
    let mut started = false;
    let count = ctx.level.compiled.map.sectors.len();
    let mut next = 0;
    while let Some(first) = (next..count).find(|&s| ctx.level.compiled.map.sectors[s].tag == tag && tag != 0) {
        next = first + 1;
        if world.is_busy(first) {
            continue;
        }
        let map = &ctx.level.compiled.map;
        let texture = map.sectors[first].floor_texture.clone();
        let mut height = map.sectors[first].floor + step;
        world.start(Thinker::Floor(FloorMove {
            sector: first,
            dest: height,
            speed,
            up: step > 0.0,
            crush,
            arrival: None,
        }));
        started = true;
        let mut current = first;
        loop {
            let map = &ctx.level.compiled.map;
            let mut found = None;
            for &i in &ctx.level.sector_lines[current] {
                let line = &map.lines[i as usize];
                let Some(back) = &line.back else { continue };
                if line.front.sector != current || map.sectors[back.sector].floor_texture != texture {
                    continue;
                }
                height += step;
                if world.is_busy(back.sector) {
                    continue;
                }
                found = Some(back.sector);
                break;
            }
            let Some(s) = found else { break };
            world.start(Thinker::Floor(FloorMove {
                sector: s,
                dest: height,
                speed,
                up: step > 0.0,
                crush,
                arrival: None,
            }));
            current = s;
        }
        next = next.max(current + 1);
    }
    started
}

/// Doom's EV_DoDonut: for each idle tagged sector (the pillar), the ring is
/// the sector across the pillar's first line, and the outside the first
/// sector behind one of the ring's lines that is not the pillar. The ring
/// rises to the outside's floor taking its texture (and no special); the
/// pillar lowers to it.
pub fn donut(world: &mut World, ctx: &mut Ctx, sectors: &[usize], speed: f64) -> bool {
    let mut started = false;
    for &pillar in sectors {
        let map = &ctx.level.compiled.map;
        let Some(&first) = ctx.level.sector_lines[pillar].first() else { continue };
        let line = &map.lines[first as usize];
        let Some(back) = &line.back else { continue };
        let ring = if line.front.sector == pillar { back.sector } else { line.front.sector };
        if ring == pillar || world.is_busy(pillar) || world.is_busy(ring) {
            continue;
        }
        let outside = ctx.level.sector_lines[ring].iter().find_map(|&i| {
            let b = map.lines[i as usize].back.as_ref()?.sector;
            (b != pillar).then_some(b)
        });
        let Some(outside) = outside else { continue };
        let height = map.sectors[outside].floor;
        let ring_up = height > map.sectors[ring].floor;
        let pillar_up = height > map.sectors[pillar].floor;
        let arrival = Some(Retexture { from: outside, special: Some(SectorSpecial::default()) });
        world.start(Thinker::Floor(FloorMove {
            sector: ring,
            dest: height,
            speed,
            up: ring_up,
            crush: false,
            arrival,
        }));
        world.start(Thinker::Floor(FloorMove {
            sector: pillar,
            dest: height,
            speed,
            up: pillar_up,
            crush: false,
            arrival: None,
        }));
        started = true;
    }
    started
}
