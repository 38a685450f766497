//! Doors (Doom's p_doors.c): a door is a sector whose ceiling rises from
//! its floor to 4 under the lowest neighbouring ceiling, waits, and comes
//! down again, reversing when a body is in the way. Kinds: raise (open,
//! wait, close), open (and stay), close (and stay), close then open (after
//! 30 s). Manual doors act on the sector behind the used line and follow
//! Doom's rules for a door already moving: a closing door reopens, an open
//! one closes at once.
//!
//! A grid map's door is the same thinker with another motion: its panel
//! slides into the jamb (Wolfenstein's WL_ACT1.C), and the doorway is
//! passable only while the panel is all the way open.

use glam::DVec2;

use super::mover::{move_plane, Moved, Plane};
use super::{specials, Ctx, Thinker, World};
use crate::grid::Grid;
use crate::level::{GridLevel, Level};
use crate::map::special::DoorKind;
use crate::play::events::{sound, Origin};
use crate::play::player::RADIUS;

/// An open door stops this far under the lowest neighbouring ceiling (Doom's 4).
pub const DOOR_LIP: f64 = 4.0;
/// Doors this fast or faster make the "blazing" sounds (Doom's 4 x VDOORSPEED).
const BLAZING: f64 = 8.0;
/// The share of its width a sliding panel moves per tick: 1/32, so it opens
/// in 32 ticks (0.91 s). Wolfenstein's panel moves `tics << 10` of its 0xffff
/// per 70 Hz tic, 64 tics end to end: the same 0.91 s, and on a 64-unit cell
/// the same 2 units per tick as Doom's door. 1/32 is exact in binary, so the
/// position lands on 0 and 1 exactly.
pub const SLIDE_SPEED: f64 = 1.0 / 32.0;

/// What a door moves.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Motion {
    /// A sector map's door: the sector's ceiling, up to `top`.
    Ceiling { top: f64 },
    /// A grid map's door: the panel slides into its jamb. `position` is the
    /// share slid open, 0..=1, written to [`GridLevel::open`].
    Slide { slide: Slide, position: f64 },
}

/// Where a sliding door is in its grid, and what it does to its sector.
///
/// The sector is passable only while the door is fully open, as in
/// Wolfenstein, where `DoorOpening` clears the tile's `actorat` only at 0xffff
/// and `CloseDoor` sets it again as closing starts: the sector's ceiling is
/// the grid's ceiling then, and on its floor otherwise. Raising it in step
/// with the slide was rejected: collision would let the body through once the
/// gap gave 56 units of headroom, which on a grid with a high ceiling is while
/// most of the panel is still in the way.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
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
    /// refuses to shut on a player in the door's tile or straddling it.
    pub fn holds(&self, pos: DVec2, radius: f64) -> bool {
        pos.clamp(self.cell[0], self.cell[1]).distance(pos) <= radius
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum DoorState {
    Opening,
    /// At the top; starts closing when `wait` runs out.
    Open {
        wait: u32,
    },
    Closing,
    /// At the bottom; starts opening when `wait` runs out (close-then-open
    /// doors, and the sector special that opens a door after 5 minutes).
    Shut {
        wait: u32,
    },
}

/// A door at work.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Door {
    pub sector: usize,
    pub kind: DoorKind,
    pub motion: Motion,
    pub state: DoorState,
    pub speed: f64,
    /// Ticks a raise door stays open.
    pub wait: u32,
    /// Ticks a close-then-open door stays shut.
    pub shut: u32,
}

impl Door {
    /// A door on `sector` of `kind`, set going.
    pub fn new(level: &Level, sector: usize, kind: DoorKind, speed: f64, (wait, shut): (u32, u32)) -> Door {
        let s = &level.compiled.map.sectors[sector];
        let motion = match level.grid().and_then(|(grid, gl)| slide_of(grid, gl, sector)) {
            Some(slide) => {
                let position = gl_open(level, slide.index);
                Motion::Slide { slide, position }
            }
            None => {
                let top = match kind {
                    // Reopens to where the ceiling was.
                    DoorKind::CloseThenOpen => s.ceiling,
                    // Never down: a door the map left higher than its open
                    // height stays there (Doom would snap it down).
                    _ => specials::lowest_ceiling_around(level, sector)
                        .map_or(s.ceiling, |c| (c - DOOR_LIP).max(s.ceiling)),
                };
                Motion::Ceiling { top }
            }
        };
        let state = match kind {
            DoorKind::Raise | DoorKind::Open => DoorState::Opening,
            DoorKind::Close | DoorKind::CloseThenOpen => DoorState::Closing,
        };
        Door { sector, kind, motion, state, speed, wait, shut }
    }

    fn blazing(&self) -> bool {
        self.speed >= BLAZING
    }

    fn open_sound(&self) -> &'static str {
        if self.blazing() {
            "bdopn"
        } else {
            "doropn"
        }
    }

    fn close_sound(&self) -> &'static str {
        if self.blazing() {
            "bdcls"
        } else {
            "dorcls"
        }
    }

    pub(super) fn think(&mut self, ctx: &mut Ctx) -> bool {
        let origin = Origin::Sector(self.sector);
        match self.state {
            DoorState::Open { wait } => {
                if wait > 1 {
                    self.state = DoorState::Open { wait: wait - 1 };
                } else {
                    self.state = DoorState::Closing;
                    ctx.events.push(sound(self.close_sound(), origin));
                }
                true
            }
            DoorState::Shut { wait } => {
                if wait > 1 {
                    self.state = DoorState::Shut { wait: wait - 1 };
                } else {
                    self.state = DoorState::Opening;
                    ctx.events.push(sound(self.open_sound(), origin));
                }
                true
            }
            DoorState::Closing => match self.step(ctx, false) {
                Moved::Ok => true,
                Moved::Arrived => {
                    if self.kind == DoorKind::CloseThenOpen {
                        self.state = DoorState::Shut { wait: self.shut };
                        return true;
                    }
                    false
                }
                Moved::Crushed => {
                    // A door that only closes keeps pushing; the others go back up.
                    if self.kind != DoorKind::Close {
                        self.state = DoorState::Opening;
                        ctx.events.push(sound(self.open_sound(), origin));
                    }
                    true
                }
            },
            DoorState::Opening => match self.step(ctx, true) {
                Moved::Arrived if self.kind == DoorKind::Raise => {
                    self.state = DoorState::Open { wait: self.wait };
                    true
                }
                Moved::Arrived => false,
                _ => true,
            },
        }
    }

    /// One tick of motion, up or down.
    fn step(&mut self, ctx: &mut Ctx, up: bool) -> Moved {
        match &mut self.motion {
            Motion::Ceiling { top } => {
                let floor = ctx.level.compiled.map.sectors[self.sector].floor;
                let dest = if up { *top } else { floor };
                move_plane(ctx, self.sector, Plane::Ceiling, self.speed, dest, false, up)
            }
            Motion::Slide { slide, position } => {
                let slide = *slide;
                if !up && slide.holds(ctx.bodies.player.pos, RADIUS) {
                    return Moved::Crushed;
                }
                *position = if up { (*position + SLIDE_SPEED).min(1.0) } else { (*position - SLIDE_SPEED).max(0.0) };
                let open = *position;
                let sector = &mut ctx.level.compiled.map.sectors[self.sector];
                // Passable only when fully open (see [`Slide`]).
                sector.ceiling = if open >= 1.0 { slide.ceiling } else { sector.floor };
                ctx.bodies.actors.plane_moved(ctx.level, self.sector);
                if let Some(g) = ctx.level.grid.as_mut().and_then(|g| g.open.get_mut(slide.index)) {
                    *g = open;
                }
                if (up && open >= 1.0) || (!up && open <= 0.0) {
                    Moved::Arrived
                } else {
                    Moved::Ok
                }
            }
        }
    }
}

/// Starts doors of `kind` on `sectors`. A manual door (the sector behind
/// the used line) already at work follows Doom's EV_VerticalDoor: a
/// closing raise door goes back up, an opening or open one closes at once
/// (a grid door stays open instead: holding the key should not make it
/// flap). Tagged doors skip sectors already busy (EV_DoDoor). Returns
/// whether any door started or changed.
pub fn start(
    world: &mut World,
    ctx: &mut Ctx,
    sectors: &[usize],
    kind: DoorKind,
    speed: f64,
    waits: (u32, u32),
    manual: bool,
    closes: bool,
) -> bool {
    let mut started = false;
    for &sector in sectors {
        if manual {
            if let Some(door) = world.thinkers.iter_mut().find_map(|t| match t {
                Thinker::Door(d) if d.sector == sector => Some(d),
                _ => None,
            }) {
                if kind == DoorKind::Raise {
                    reuse(door, closes);
                    started = true;
                }
                continue;
            }
        }
        if world.is_busy(sector) {
            continue;
        }
        let door = Door::new(ctx.level, sector, kind, speed, waits);
        let origin = Origin::Sector(sector);
        let noise = match door.state {
            DoorState::Opening => door.open_sound(),
            _ => door.close_sound(),
        };
        ctx.events.push(sound(noise, origin));
        world.start(Thinker::Door(door));
        started = true;
    }
    started
}

/// Using a manual raise door that is already at work: one closing opens
/// again; an open one closes, if the user `closes` doors (the player does,
/// a monster does not).
fn reuse(door: &mut Door, closes: bool) {
    if !closes && door.state != DoorState::Closing {
        return;
    }
    door.state = match (door.state, &door.motion) {
        (DoorState::Closing, _) => DoorState::Opening,
        (DoorState::Open { .. }, Motion::Slide { .. }) => DoorState::Open { wait: door.wait },
        (_, Motion::Slide { .. }) => DoorState::Opening,
        _ => DoorState::Closing,
    };
}

/// How far the grid door `index` is open now.
fn gl_open(level: &Level, index: usize) -> f64 {
    level.grid.as_ref().and_then(|g| g.open.get(index).copied()).unwrap_or(0.0)
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
