//! Doors: the player uses a line flagged `door`, and the sector behind it
//! opens, waits and closes. Each tick the moving doors write their state into
//! the level, so the renderers draw them and collision feels them.
//!
//! The state machine (closed, opening, open and waiting, closing, reopening
//! when the body is in the way) is shared by every kind of door; a kind only
//! says what its position moves ([`DoorKind`]): a sector map's door raises its
//! ceiling (Doom's `T_VerticalDoor`), a grid map's door slides its panel
//! sideways (Wolfenstein's `DoorOpening` and `DoorClosing`, WL_ACT1.C). A map
//! without door lines has no [`Door`]s and pays nothing per tick.

use glam::DVec2;

use super::blockmap::LineQuery;
use super::collision::World;
use crate::geom::{exact_side, sin_cos_degrees, Side};
use crate::grid::Grid;
use crate::level::{GridLevel, Level};
use crate::map::{Map, Trigger, TriggerOn};

/// Units per tick a door moves (Doom's `VDOORSPEED`, 2): a 72-unit door opens
/// in 36 ticks, about a second.
pub const DOOR_SPEED: f64 = 2.0;
/// Ticks a door stays open (Doom's `VDOORWAIT`, 150): about 4.3 s. Wolfenstein's
/// `OPENTICS` is the same time: 300 of its 70 Hz tics.
pub const DOOR_WAIT: u32 = 150;
/// An open door stops this far under the lowest neighbouring ceiling (Doom's 4).
pub const DOOR_LIP: f64 = 4.0;
/// How far ahead of the body's centre the player can use a line (Doom's `USERANGE`, 64).
pub const USE_RANGE: f64 = 64.0;
/// The share of its width a sliding panel moves per tick: 1/32, so it opens
/// in 32 ticks (0.91 s). Wolfenstein's panel moves `tics << 10` of its 0xffff
/// per 70 Hz tic, 64 tics end to end: the same 0.91 s, and on a 64-unit cell
/// the same 2 units per tick as [`DOOR_SPEED`]. 1/32 is exact in binary, so
/// the position lands on 0 and 1 exactly.
pub const SLIDE_SPEED: f64 = 1.0 / 32.0;

/// What a door moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DoorKind {
    /// A sector-map door: the ceiling of its sector rises from its floor.
    Ceiling,
    /// A grid map's door: the panel slides into its jamb. The position is the
    /// share slid open, 0..=1, written to [`GridLevel::open`] for the
    /// ray-caster.
    Slide(Slide),
}

/// Where a sliding door is in its grid, and what it does to its sector.
///
/// The sector is passable only while the door is fully open, as in
/// Wolfenstein, where `DoorOpening` clears the tile's `actorat` only at 0xffff
/// and `CloseDoor` sets it again as closing starts: the sector's ceiling is
/// the grid's ceiling then, and on its floor otherwise. Raising it in step
/// with the slide was rejected: collision would let the body through once the
/// gap gave 56 units of headroom, which on a grid with a high ceiling is while
/// most of the panel is still in the way. So the BSP renderers, which have no
/// sliding panel, draw a grid door shut until it is fully open and open from
/// then until it starts closing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slide {
    /// The door's place in [`crate::grid::FaceLines::doors`] and [`GridLevel::open`].
    pub index: usize,
    /// The door's cell: its south-west and north-east corners.
    pub cell: [DVec2; 2],
    /// The sector's ceiling while the door is fully open (the grid's ceiling).
    pub ceiling: f64,
}

impl Slide {
    /// Does a body of radius `radius` at `pos` overlap (or touch) the door's
    /// cell? Such a body holds the door open, as Wolfenstein's `CloseDoor`
    /// refuses to shut on a player in the door's tile or straddling it. The
    /// whole cell, not only the slab, so that a body stepping into the
    /// doorway stops a closing panel before it reaches the slab.
    pub fn holds(&self, pos: DVec2, radius: f64) -> bool {
        pos.clamp(self.cell[0], self.cell[1]).distance(pos) <= radius
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DoorState {
    /// At rest where the map put it (normally shut).
    Closed,
    Opening,
    /// Fully open; starts closing when `wait` reaches 0.
    Open {
        wait: u32,
    },
    Closing,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Door {
    /// The door sector: the back sector of its door lines.
    pub sector: usize,
    pub kind: DoorKind,
    pub state: DoorState,
    /// Position when shut and when open, and now: for a [`DoorKind::Ceiling`]
    /// door the ceiling's height (map units), for a [`DoorKind::Slide`] door
    /// the share of the panel slid away (0 shut, 1 open).
    pub closed: f64,
    pub open: f64,
    pub position: f64,
    /// Once open, stays open (the last opener was a "stay open" trigger).
    pub stays_open: bool,
}

/// Every door of a map, and which line opens which.
#[derive(Clone, Debug, Default)]
pub struct Doors {
    pub doors: Vec<Door>,
    /// `(line, door)`, sorted by line.
    by_line: Vec<(usize, usize)>,
    /// Lines with a [`Trigger`], sorted by line.
    triggers: Vec<TriggerLine>,
}

/// A trigger line and the doors of the sectors its tag names.
#[derive(Clone, Debug)]
struct TriggerLine {
    line: usize,
    trigger: Trigger,
    doors: Vec<usize>,
    /// A once-only trigger that has gone off.
    spent: bool,
}

impl Doors {
    /// The doors of a level: one per distinct back sector of its door lines.
    /// On a grid level a door sector is a grid door, and slides; otherwise it
    /// opens to the lowest ceiling around it that is not itself a door, less
    /// [`DOOR_LIP`] (Doom's P_FindLowestCeilingSurrounding).
    pub fn new(level: &Level) -> Doors {
        let map = &level.compiled.map;
        let mut by_line = Vec::new();
        let mut sectors: Vec<usize> = Vec::new();
        let mut door_of = |sector: usize| {
            sectors.iter().position(|&s| s == sector).unwrap_or_else(|| {
                sectors.push(sector);
                sectors.len() - 1
            })
        };
        for (i, line) in map.lines.iter().enumerate() {
            let Some(back) = line.back.as_ref().filter(|_| line.flags.door) else { continue };
            by_line.push((i, door_of(back.sector)));
        }
        // Tagged doors: every sector a trigger's tag names (Doom's
        // P_FindSectorFromLineTag; tag 0 names none).
        let mut triggers = Vec::new();
        for (i, line) in map.lines.iter().enumerate() {
            let Some(trigger) = line.trigger.filter(|t| t.tag != 0) else { continue };
            let doors =
                (0..map.sectors.len()).filter(|&s| map.sectors[s].tag == trigger.tag).map(&mut door_of).collect();
            triggers.push(TriggerLine { line: i, trigger, doors, spent: false });
        }
        let doors = sectors
            .iter()
            .map(|&sector| match level.grid().and_then(|(grid, gl)| slide_of(grid, gl, sector)) {
                Some(slide) => Door {
                    sector,
                    kind: DoorKind::Slide(slide),
                    state: DoorState::Closed,
                    closed: 0.0,
                    open: 1.0,
                    // The compiled map's doors are shut, whatever `open` says.
                    position: 0.0,
                    stays_open: false,
                },
                None => {
                    let s = &map.sectors[sector];
                    let neighbours = neighbour_ceilings(map, sector, &sectors);
                    let top = neighbours.unwrap_or(s.ceiling) - DOOR_LIP;
                    Door {
                        sector,
                        kind: DoorKind::Ceiling,
                        state: DoorState::Closed,
                        closed: s.floor,
                        open: top.max(s.floor),
                        position: s.ceiling,
                        stays_open: false,
                    }
                }
            })
            .collect();
        Doors { doors, by_line, triggers }
    }

    pub fn is_empty(&self) -> bool {
        self.doors.is_empty()
    }

    /// The door a line opens, if it is a door line.
    pub fn door_of_line(&self, line: usize) -> Option<usize> {
        self.by_line.binary_search_by_key(&line, |&(l, _)| l).ok().map(|k| self.by_line[k].1)
    }

    /// Opens a door (or keeps an open one open, or reopens a closing one).
    ///
    /// Unlike Doom, using an open door does not shut it: the window may
    /// report use for every tick the key is held, and holding it should not
    /// make the door flap.
    pub fn activate(&mut self, door: usize) {
        self.open_door(door, false);
    }

    fn open_door(&mut self, door: usize, stay: bool) {
        let d = &mut self.doors[door];
        d.stays_open = stay;
        d.state = match d.state {
            DoorState::Open { .. } => DoorState::Open { wait: DOOR_WAIT },
            _ => DoorState::Opening,
        };
    }

    /// Uses the first line straight ahead of a body at `pos` looking along
    /// `angle`, within [`USE_RANGE`]: a door line seen from its front opens
    /// its door; a closed line (solid, or no gap between floor and ceiling)
    /// stops the search; an open one is looked through (Doom's PTR_UseTraverse).
    /// Returns the door opened.
    pub fn use_ahead(&mut self, world: World, query: &mut LineQuery, pos: DVec2, angle: f64) -> Option<usize> {
        let map = &world.compiled.map;
        let (sin, cos) = sin_cos_degrees(angle);
        let end = pos + DVec2::new(cos, sin) * USE_RANGE;
        let near = query.run(world.blockmap, map.lines.len(), pos.min(end), pos.max(end));
        let mut crossed: Vec<(f64, usize)> = near
            .iter()
            .filter_map(|&i| {
                let (a, b) = map.line_points(&map.lines[i as usize]);
                crossing(pos, end, a, b).map(|t| (t, i as usize))
            })
            .collect();
        // Ties (a ray through a vertex) go to the lower line index: deterministic.
        crossed.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        for (_, i) in crossed {
            let line = &map.lines[i];
            let (a, b) = map.line_points(line);
            if let Some(door) = self.door_of_line(i) {
                if exact_side(a, b, pos) == Side::Front {
                    self.activate(door);
                    return Some(door);
                }
            }
            if exact_side(a, b, pos) == Side::Front {
                if let Some(first) = self.fire(i, TriggerOn::Use) {
                    return Some(first);
                }
            }
            let Some(back) = &line.back else { return None };
            let (f, k) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
            if f.ceiling.min(k.ceiling) <= f.floor.max(k.floor) {
                return None;
            }
        }
        None
    }

    /// Sets off the trigger on `line` if it goes off `on` that and is not
    /// spent; returns the first door it opened.
    fn fire(&mut self, line: usize, on: TriggerOn) -> Option<usize> {
        let k = self.triggers.binary_search_by_key(&line, |t| t.line).ok()?;
        let t = &mut self.triggers[k];
        if t.trigger.on != on || t.spent {
            return None;
        }
        t.spent = t.trigger.once;
        let (doors, stay) = (t.doors.clone(), t.trigger.stay_open);
        for &door in &doors {
            self.open_door(door, stay);
        }
        doors.first().copied()
    }

    /// Sets off the walk-over triggers whose lines the body's centre crossed
    /// moving from `from` to `to` (Doom's P_CrossSpecialLine: the centre
    /// changes sides, either way).
    pub fn walk(&mut self, world: World, query: &mut LineQuery, from: DVec2, to: DVec2) {
        if self.triggers.iter().all(|t| t.trigger.on != TriggerOn::Walk) || from == to {
            return;
        }
        let map = &world.compiled.map;
        let near = query.run(world.blockmap, map.lines.len(), from.min(to), from.max(to));
        let mut crossed: Vec<usize> = near
            .iter()
            .map(|&i| i as usize)
            .filter(|&i| {
                let (a, b) = map.line_points(&map.lines[i]);
                let (s, e) = (exact_side(a, b, from), exact_side(a, b, to));
                s != e && s != Side::On && e != Side::On && crossing(from, to, a, b).is_some()
            })
            .collect();
        crossed.sort_unstable();
        for i in crossed {
            self.fire(i, TriggerOn::Walk);
        }
    }

    /// Moves every door one tick and writes its state into `level`.
    /// `in_the_way(door, position)` says whether the player's body would be
    /// caught by a door moving to `position`; a closing door then reopens
    /// (Doom's doors do the same when they meet a thing, Wolfenstein's when
    /// the player steps into the doorway).
    pub fn tick(&mut self, level: &mut Level, mut in_the_way: impl FnMut(&Door, f64) -> bool) {
        for door in &mut self.doors {
            let speed = door.speed();
            match door.state {
                DoorState::Closed => continue,
                DoorState::Opening => {
                    // Never down: a door the map left higher than its open height stays there.
                    door.position = (door.position + speed).min(door.open.max(door.position));
                    if door.position >= door.open {
                        door.state = DoorState::Open { wait: DOOR_WAIT };
                    }
                }
                DoorState::Open { .. } if door.stays_open => continue,
                DoorState::Open { wait } => {
                    door.state = if wait > 1 { DoorState::Open { wait: wait - 1 } } else { DoorState::Closing };
                    continue;
                }
                DoorState::Closing => {
                    let next = (door.position - speed).max(door.closed);
                    if in_the_way(door, next) {
                        door.state = DoorState::Opening;
                        continue;
                    }
                    door.position = next;
                    if next <= door.closed {
                        door.state = DoorState::Closed;
                    }
                }
            }
            door.apply(level);
        }
    }
}

impl Door {
    fn speed(&self) -> f64 {
        match self.kind {
            DoorKind::Ceiling => DOOR_SPEED,
            DoorKind::Slide(_) => SLIDE_SPEED,
        }
    }

    fn apply(&self, level: &mut Level) {
        let sector = &mut level.compiled.map.sectors[self.sector];
        match self.kind {
            DoorKind::Ceiling => sector.ceiling = self.position,
            DoorKind::Slide(slide) => {
                // Passable only when fully open (see [`Slide`]).
                sector.ceiling = if self.position >= self.open { slide.ceiling } else { sector.floor };
                if let Some(open) = level.grid.as_mut().and_then(|g| g.open.get_mut(slide.index)) {
                    *open = self.position;
                }
            }
        }
    }
}

/// The sliding door whose sector is `sector`, if it is a grid door: door `k`
/// of [`crate::grid::FaceLines::doors`] is sector `k + 1` (as `grid::compile`
/// numbers them; checked against `door_sectors` rather than assumed).
fn slide_of(grid: &Grid, gl: &GridLevel, sector: usize) -> Option<Slide> {
    let index = sector.checked_sub(1)?;
    let &cell = gl.faces.doors.get(index)?;
    if gl.faces.door_sectors.get(cell).map(|&s| s as usize) != Some(sector) || gl.open.len() <= index {
        return None;
    }
    let (i, j) = ((cell % grid.columns) as i64, (cell / grid.columns) as i64);
    let corners = [DVec2::new(grid.x(i), grid.y(j)), DVec2::new(grid.x(i + 1), grid.y(j + 1))];
    Some(Slide { index, cell: corners, ceiling: grid.ceiling })
}

/// The lowest ceiling of the sectors sharing a line with `sector`, leaving
/// out door sectors (a shut door next to another would otherwise give it no
/// room to open); `None` when every neighbour is a door.
fn neighbour_ceilings(map: &Map, sector: usize, doors: &[usize]) -> Option<f64> {
    let mut lowest: Option<f64> = None;
    for line in &map.lines {
        let Some(back) = &line.back else { continue };
        let other = match (line.front.sector == sector, back.sector == sector) {
            (true, false) => back.sector,
            (false, true) => line.front.sector,
            _ => continue,
        };
        if !doors.contains(&other) {
            let c = map.sectors[other].ceiling;
            lowest = Some(lowest.map_or(c, |l| l.min(c)));
        }
    }
    lowest
}

/// Where segment `p-q` crosses segment `a-b`, as a fraction of `p-q`;
/// touching counts.
fn crossing(p: DVec2, q: DVec2, a: DVec2, b: DVec2) -> Option<f64> {
    let r = q - p;
    let s = b - a;
    let denom = crate::geom::cross(r, s);
    if denom == 0.0 {
        return None;
    }
    let t = crate::geom::cross(a - p, s) / denom;
    let u = crate::geom::cross(a - p, r) / denom;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then_some(t)
}
