//! The boss brain (Doom II's MAP30): the level ends when it dies, and it
//! sits behind a wall, seen through a slit no shot from the floor passes.
//! A player kills it the way Doom II's players do: riding a lift up past
//! the slit's height and firing a rocket level through it as the lift goes
//! by, so that the rocket bursts on the wall behind the brain.
//!
//! This module finds where that works: for each standing place on a lift,
//! the heights at which a rocket fired level at the brain bursts near
//! enough to hurt it ([`spots`]), and, as the body rides, whether a rocket
//! fired now would ([`blast`]).

use glam::DVec2;

use crate::actors::{Arg, Category};
use crate::map::Map;
use crate::play::sight::{self, Body};
use crate::play::Game;
use crate::CompiledMap;

use super::nav::{Cell, NavGrid};
use super::plan::Mechanisms;

/// A rocket's body (Doom's: radius 11, height 8), speed per tick, and the
/// reach of its blast; a rocket leaves the launcher this high above the
/// shooter's feet.
const ROCKET_RADIUS: f64 = 11.0;
const ROCKET_HEIGHT: f64 = 8.0;
const ROCKET_SPEED: f64 = 20.0;
const BLAST: f64 = 128.0;
pub const ROCKET_Z: f64 = 32.0;
/// A shot is worth firing when its blast does at least this much.
pub const WORTH: i32 = 40;
/// The burst must be this far from the shooter (its blast reaches 128).
const SAFE: f64 = 192.0;
/// Lifts this far from the brain at most are looked at.
const LOOK: f64 = 2048.0;
/// A body's height: a lift's floor goes no nearer its ceiling.
const HEADROOM: f64 = 56.0;
/// Heights tried on a lift, this far apart.
const Z_STEP: f64 = 2.0;

/// A live boss brain.
#[derive(Clone, Copy, Debug)]
pub struct Brain {
    pub actor: u32,
    pub body: Body,
}

/// The body of a boss brain of kind `def` standing at `pos`.
pub fn body(compiled: &CompiledMap, def: &crate::actors::ActorDef, pos: DVec2, index: usize) -> Body {
    let z = compiled.map.sectors[compiled.sector_at(pos)].floor;
    Body { pos, z, height: def.height, radius: def.radius, index }
}

/// The live boss brains of `game`.
pub fn live(game: &Game) -> Vec<Brain> {
    let actors = game.actors();
    actors
        .list
        .iter()
        .enumerate()
        .filter(|(_, a)| !a.removed && a.health > 0 && actors.table.actors[a.kind].category == Category::BossBrain)
        .map(|(i, a)| {
            let def = &actors.table.actors[a.kind];
            Brain {
                actor: i as u32,
                body: Body { pos: a.pos, z: a.z, height: def.height, radius: def.radius, index: i },
            }
        })
        .collect()
}

/// One line a rocket's way crosses: how far along, and the sectors either
/// side (none for a wall).
struct Crossing {
    at: f64,
    sides: Option<(usize, usize)>,
}

/// The lines crossed by a level flight from `from` towards `to` and on
/// past it, by the rocket's centre and its two sides, nearest first.
fn crossings(map: &Map, from: DVec2, to: DVec2) -> Vec<Crossing> {
    let along = (to - from).normalize_or_zero();
    let reach = from.distance(to) + BLAST;
    let side = DVec2::new(-along.y, along.x) * ROCKET_RADIUS;
    let mut out = Vec::new();
    for l in &map.lines {
        let (a, b) = map.line_points(l);
        let sides = l.back.as_ref().map(|back| (l.front.sector, back.sector));
        for o in [DVec2::ZERO, side, -side] {
            if let Some(t) = crate::play::trace::crossing(from + o, from + o + along * reach, a, b) {
                out.push(Crossing { at: t * reach, sides });
            }
        }
    }
    out.sort_by(|x, y| x.at.total_cmp(&y.at));
    out
}

/// Where a shot is fired from: the map, and a lift's floor taken at another
/// height than it stands at now (the lift the shooter rides, when working
/// out where it would be worth firing from).
struct Shot<'a> {
    compiled: &'a CompiledMap,
    lift: Option<(usize, f64)>,
}

impl Shot<'_> {
    fn floor(&self, s: usize) -> f64 {
        match self.lift {
            Some((lift, floor)) if lift == s => floor,
            _ => self.compiled.map.sectors[s].floor,
        }
    }

    /// Does a rocket with its bottom at `z` pass the line between sectors
    /// `f` and `b`?
    fn passes(&self, (f, b): (usize, usize), z: f64) -> bool {
        let sectors = &self.compiled.map.sectors;
        self.floor(f).max(self.floor(b)) <= z && sectors[f].ceiling.min(sectors[b].ceiling) >= z + ROCKET_HEIGHT
    }
}

/// The damage a rocket fired level from `from`, its bottom at `z`, at the
/// brain does to it (0 when it bursts too far away, out of the brain's
/// sight, or near the shooter), given the way's crossings.
fn damage(shot: &Shot, scratch: &mut sight::Scratch, from: DVec2, z: f64, brain: &Body, ways: &[Crossing]) -> i32 {
    let along = (brain.pos - from).normalize_or_zero();
    let stop = ways.iter().find(|c| !c.sides.is_some_and(|s| shot.passes(s, z))).map_or(f64::INFINITY, |c| c.at);
    // A direct hit: the rocket meets the brain's box before anything else.
    let to_brain = from.distance(brain.pos);
    let level_with = z < brain.z + brain.height && z + ROCKET_HEIGHT > brain.z;
    if level_with && to_brain - brain.radius - ROCKET_RADIUS < stop {
        return BLAST as i32;
    }
    if !stop.is_finite() || stop < SAFE {
        return 0;
    }
    // It bursts where it last stood before the wall: up to a tick's flight
    // short of it. The nearer of the two ends counts.
    let mut worst = i32::MAX;
    for back in [ROCKET_RADIUS, ROCKET_RADIUS + ROCKET_SPEED] {
        let burst = from + along * (stop - back);
        let d = (brain.pos - burst).abs();
        let dist = (d.x.max(d.y) - brain.radius).max(0.0).floor();
        if dist >= BLAST {
            return 0;
        }
        let spot = Body { pos: burst, z, height: ROCKET_HEIGHT, radius: ROCKET_RADIUS, index: usize::MAX };
        if !sight::sight(shot.compiled, scratch, brain, &spot) {
            return 0;
        }
        worst = worst.min((BLAST - dist) as i32);
    }
    worst
}

/// The damage a rocket fired now from `from`, its bottom at `z`, would do
/// to `brain`.
pub fn blast(compiled: &CompiledMap, scratch: &mut sight::Scratch, from: DVec2, z: f64, brain: &Body) -> i32 {
    let ways = crossings(&compiled.map, from, brain.pos);
    damage(&Shot { compiled, lift: None }, scratch, from, z, brain, &ways)
}

/// A place to fire from: a cell wholly on a lift, and the lowest and
/// highest floor heights of the lift from which a rocket fired level hurts
/// the brain by [`WORTH`] at least.
#[derive(Clone, Copy, Debug)]
pub struct Spot {
    pub cell: Cell,
    pub lift: usize,
    pub low: f64,
    pub high: f64,
}

/// Where to fire at `brain` from, with the sectors' floors at `floors`
/// (the level's own, or those a plan assumes): every cell wholly on a lift
/// (not a perpetual one) within reach of it, with the heights the lift
/// passes through (its lowest neighbouring floor to its top) that make a
/// shot worth firing. The widest window first.
pub fn spots(nav: &NavGrid, compiled: &CompiledMap, mech: &Mechanisms, brain: &Body, floors: &[f64]) -> Vec<Spot> {
    let map = &compiled.map;
    let mut scratch = sight::Scratch::default();
    let reach = DVec2::splat(LOOK);
    let mut out = Vec::new();
    for cell in nav.cells_in_box(brain.pos - reach, brain.pos + reach) {
        let &[lift] = nav.touched(cell) else { continue };
        let lift = lift as usize;
        if mech.lift_lines[lift].is_empty() || mech.perpetual[lift] || !nav.standable(cell) {
            continue;
        }
        // Raised above its top at rest (something else moves its floor up,
        // as MAP30's switch raises its lift 512): it may go as high as its
        // ceiling lets a body stand.
        let raised = floors[lift] > mech.lift_top[lift];
        let top = if raised { map.sectors[lift].ceiling - HEADROOM } else { mech.lift_top[lift] };
        let bottom = mech.lift_low[lift];
        let from = nav.centre_of(cell);
        let ways = crossings(map, from, brain.pos);
        let mut window: Option<(f64, f64)> = None;
        let mut best: Option<(f64, f64)> = None;
        let mut floor = bottom;
        while floor <= top {
            let shot = Shot { compiled, lift: Some((lift, floor)) };
            if damage(&shot, &mut scratch, from, floor + ROCKET_Z, brain, &ways) >= WORTH {
                window = Some(window.map_or((floor, floor), |w| (w.0, floor)));
            } else {
                window = None;
            }
            if let Some(w) = window.filter(|w| best.is_none_or(|b| w.1 - w.0 > b.1 - b.0)) {
                best = Some(w);
            }
            floor += Z_STEP;
        }
        if let Some((low, high)) = best {
            out.push(Spot { cell, lift, low, high });
        }
    }
    out.sort_by(|a, b| (b.high - b.low).total_cmp(&(a.high - a.low)).then(a.cell.cmp(&b.cell)));
    out
}

/// The rocket launcher's weapon slot (as the fight's choice of weapon has
/// it).
pub const LAUNCHER_SLOT: u8 = 5;

/// Whether `game`'s player has the rocket launcher with a rocket for a
/// shot, and the ticks from the trigger to the rocket leaving (its `Fire`
/// states before the first that launches an actor: Doom's 8).
pub fn launcher(game: &Game) -> Option<u32> {
    let player = game.player();
    let table = &game.actors().table;
    player.weapons.iter().find_map(|&w| {
        let def = table.actors[w].weapon.as_ref().filter(|d| d.slot == LAUNCHER_SLOT)?;
        let ammo = def.ammo.is_none_or(|k| player.ammo[k.index()] >= def.ammo_use.max(1));
        let mut state = table.actors[w].label("Fire")?;
        let mut lead = 0u32;
        for _ in 0..16 {
            let s = table.state(state);
            if s.action.as_ref().is_some_and(|a| a.args.iter().any(|g| matches!(g, Arg::Actor(_)))) {
                return ammo.then_some(lead);
            }
            lead += s.tics.max(0) as u32;
            state = s.next?;
        }
        None
    })
}
