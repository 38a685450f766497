//! Doors: the player uses a line flagged `door`, and the sector behind it
//! opens, waits and closes (Doom's vertical door, `T_VerticalDoor`). Each tick
//! the moving doors write their heights into the map, so the renderers draw
//! them and collision feels them.
//!
//! The state machine (closed, opening, open and waiting, closing, reopening
//! when the body is in the way) is shared by every kind of door; a kind only
//! says what its position moves ([`DoorKind`]). A map without door lines has
//! no [`Door`]s and pays nothing per tick.

use glam::DVec2;

use super::blockmap::LineQuery;
use super::collision::World;
use crate::geom::{exact_side, sin_cos_degrees, Side};
use crate::map::Map;

/// Units per tick a door moves (Doom's `VDOORSPEED`, 2): a 72-unit door opens
/// in 36 ticks, about a second.
pub const DOOR_SPEED: f64 = 2.0;
/// Ticks a door stays open (Doom's `VDOORWAIT`, 150): about 4.3 s.
pub const DOOR_WAIT: u32 = 150;
/// An open door stops this far under the lowest neighbouring ceiling (Doom's 4).
pub const DOOR_LIP: f64 = 4.0;
/// How far ahead of the body's centre the player can use a line (Doom's `USERANGE`, 64).
pub const USE_RANGE: f64 = 64.0;

/// What a door moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DoorKind {
    /// A sector-map door: the ceiling of its sector rises from its floor.
    /// (Grid maps' sliding doors will be a second kind here.)
    Ceiling,
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
    /// Position when shut and when open, and now (map units: for a
    /// [`DoorKind::Ceiling`] door, the ceiling's height).
    pub closed: f64,
    pub open: f64,
    pub position: f64,
}

/// Every door of a map, and which line opens which.
#[derive(Clone, Debug, Default)]
pub struct Doors {
    pub doors: Vec<Door>,
    /// `(line, door)`, sorted by line.
    by_line: Vec<(usize, usize)>,
}

impl Doors {
    /// The doors of a sector map: one per distinct back sector of its door
    /// lines. It opens to the lowest ceiling around it that is not itself a
    /// door, less [`DOOR_LIP`] (Doom's P_FindLowestCeilingSurrounding).
    pub fn new(map: &Map) -> Doors {
        let mut by_line = Vec::new();
        let mut sectors: Vec<usize> = Vec::new();
        for (i, line) in map.lines.iter().enumerate() {
            let Some(back) = line.back.as_ref().filter(|_| line.flags.door) else { continue };
            let door = sectors.iter().position(|&s| s == back.sector).unwrap_or_else(|| {
                sectors.push(back.sector);
                sectors.len() - 1
            });
            by_line.push((i, door));
        }
        let doors = sectors
            .iter()
            .map(|&sector| {
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
                }
            })
            .collect();
        Doors { doors, by_line }
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
        let d = &mut self.doors[door];
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
            let Some(back) = &line.back else { return None };
            let (f, k) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
            if f.ceiling.min(k.ceiling) <= f.floor.max(k.floor) {
                return None;
            }
        }
        None
    }

    /// Moves every door one tick and writes the heights into `map`.
    /// `in_the_way(door, position)` says whether the player's body would be
    /// caught by a door moving to `position`; a closing door then reopens
    /// (Doom's doors do the same when they meet a thing).
    pub fn tick(&mut self, map: &mut Map, mut in_the_way: impl FnMut(&Door, f64) -> bool) {
        for door in &mut self.doors {
            match door.state {
                DoorState::Closed => continue,
                DoorState::Opening => {
                    // Never down: a door the map left higher than its open height stays there.
                    door.position = (door.position + DOOR_SPEED).min(door.open.max(door.position));
                    if door.position >= door.open {
                        door.state = DoorState::Open { wait: DOOR_WAIT };
                    }
                }
                DoorState::Open { wait } => {
                    door.state = if wait > 1 { DoorState::Open { wait: wait - 1 } } else { DoorState::Closing };
                    continue;
                }
                DoorState::Closing => {
                    let next = (door.position - DOOR_SPEED).max(door.closed);
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
            door.apply(map);
        }
    }
}

impl Door {
    fn apply(&self, map: &mut Map) {
        match self.kind {
            DoorKind::Ceiling => map.sectors[self.sector].ceiling = self.position,
        }
    }
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
