//! Running jumps: a gap no step crosses, cleared by running straight at it
//! at full speed, as a player does on Freedoom's E2M4 or MAP19.
//!
//! Doom has no jump key: a running body simply keeps its speed when the
//! floor falls away under it (there is no friction or thrust in the air)
//! and falls under gravity, so it carries across a gap until it has
//! fallen more than a step below the far side. Whether a given run clears
//! a given gap is found here by playing the body's own rules tick by tick
//! along the line of cells ([`NavGrid::leap`]): thrust and friction on the
//! ground, the fall starting at twice gravity after a tick of none, a step of at most 24 and
//! [`HEIGHT`] of room at every piece of the move. A cell's span describes
//! the body at the cell's centre only, so the floor is read half a cell
//! ahead of the body (edges come early) and the far side's face is met in
//! the air with a step 4 units short.
//!
//! The follower's side ([`Autopilot::leap_step`]) walks back to the start
//! of the run-up, stops, faces along the line exactly, and runs until the
//! body is down on the far side, then brakes.

use glam::DVec2;

use super::nav::{Cell, Heights, LineId, NavGrid, Span, CELL, DIRS};
use super::plan::Route;
use super::Observe;
use super::{turn_to, Active, Autopilot};
use crate::play::player::{FRICTION, HEIGHT, MAX_STEP, RUN_THRUST};
use crate::play::TickInput;

/// The longest run-up a leap may take, in cells (448 units straight:
/// a body from a standstill is within 2% of its top speed by then).
const RUNUP_CELLS: usize = 28;
/// The farthest a leap may carry, in cells from its edge.
const FLIGHT_CELLS: usize = 28;
/// How far ahead of the body the floor is read, units: half a cell, what
/// a cell's centre may be off the body. Edges come that much early: the
/// fall starts sooner and the far side's face is met sooner.
const AHEAD: f64 = CELL / 2.0;
/// In the air the far side's face is met with this much less of a step
/// than on the ground: room for a run a little slower than the model's.
const AIR_MARGIN: f64 = 4.0;
/// A piece of a move, units: the body is checked against the floor after
/// each one, as the world's own movement is.
const PIECE: f64 = 4.0;
/// Ticks without getting closer to the run-up's start after which the
/// body is as close as it gets.
const STALLED: u32 = 35;
/// Ticks the model runs at most (run-up, flight and braking).
const MAX_TICKS: usize = 160;

/// A running jump found by [`NavGrid::leap`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Leap {
    /// The cell it comes down in (the body brakes to a stop about there).
    pub to: Cell,
    /// Cells of run-up straight behind the edge, from a standstill.
    pub runup: u8,
    /// Cells from the edge to `to`.
    pub cells: u8,
    /// It comes down on a rim (the body overhangs a drop there).
    pub rim: bool,
}

/// The move key of a leap from `c` along direction `d`, for the set of
/// moves found not to work (a step's key is `c * 8 + d`).
pub fn key(c: Cell, d: usize) -> u32 {
    debug_assert!(c < 1 << 28);
    (1 << 31) | (c * 8 + d as u32)
}

/// The direction opposite `d`.
fn back(d: usize) -> usize {
    if d < 4 {
        (d + 2) % 4
    } else {
        4 + (d - 4 + 2) % 4
    }
}

/// One step along direction `d`, units.
pub fn step_length(d: usize) -> f64 {
    if d < 4 {
        CELL
    } else {
        CELL * std::f64::consts::SQRT_2
    }
}

/// The unit vector of direction `d`.
pub fn unit(d: usize) -> DVec2 {
    DVec2::new(DIRS[d].0 as f64, DIRS[d].1 as f64).normalize()
}

/// The floors and ceilings along one line of cells, run-up first.
struct Line {
    /// Cells from the start of the longest run-up to the farthest landing.
    cells: Vec<Cell>,
    /// Per cell: the highest floor and lowest ceiling under the body there.
    floor: Vec<f64>,
    ceiling: Vec<f64>,
    /// Index of the edge cell.
    edge: usize,
    step: f64,
}

impl Line {
    /// The index of the cell nearest the point `x` units along the line
    /// from the edge's centre (the first cell for any point before it),
    /// if the line reaches that far.
    fn at(&self, x: f64) -> Option<usize> {
        let i = (self.edge as f64 + (x / self.step).round()).max(0.0);
        ((i as usize) < self.cells.len()).then_some(i as usize)
    }

    /// The floor and ceiling under a body `x` along: the cell's half a
    /// cell ahead of it.
    fn under(&self, x: f64) -> Option<(f64, f64)> {
        let i = self.at(x + AHEAD)?;
        Some((self.floor[i], self.ceiling[i]))
    }
}

/// Where a run from a standstill `runup` cells behind the edge comes to a
/// stop, if it crosses the gap: `(stop, landing)`, units along the line.
fn run(line: &Line, runup: usize) -> Option<(f64, f64)> {
    let mut x = -(runup as f64) * line.step;
    let mut z = line.floor[line.edge - runup];
    let (mut v, mut vz) = (0.0f64, 0.0f64);
    // The lowest floor passed over in the air, and where it came down.
    let mut pit = f64::MAX;
    let mut landed: Option<(f64, f64)> = None;
    for _ in 0..MAX_TICKS {
        let (floor, _) = line.under(x)?;
        let ground = z <= floor;
        if ground {
            // Thrust ahead until down on the far side, then back to brake.
            v = if landed.is_none() { v + RUN_THRUST } else { (v - RUN_THRUST).max(0.0) };
        }
        let mut left = v;
        while left > 1e-9 {
            let piece = left.min(PIECE);
            let (high, ceiling) = line.under(x + piece)?;
            let step = if ground { MAX_STEP } else { MAX_STEP - AIR_MARGIN };
            if high - z > step || ceiling - high.max(z) < HEIGHT {
                // A wall: before the landing the leap fails; after it the
                // body has simply stopped.
                landed?;
                v = 0.0;
                break;
            }
            x += piece;
            left -= piece;
        }
        let (low, _) = line.under(x)?;
        if low > z {
            z = low;
            vz = 0.0;
        } else if z > low {
            // The fall so far, then gravity (the world's own order).
            z += vz;
            if x >= 0.0 {
                pit = pit.min(low);
            }
            if z <= low {
                z = low;
                vz = 0.0;
            } else {
                vz = if vz == 0.0 { -2.0 } else { vz - 1.0 };
            }
        }
        let ground = z <= low;
        match landed {
            None if ground && pit < f64::MAX && x > 0.0 => {
                // Down: across the gap only if well above its bottom.
                if z <= pit + MAX_STEP {
                    return None;
                }
                landed = Some((z, x));
            }
            Some((at, _)) if z < at - MAX_STEP => return None,
            _ => {}
        }
        if ground {
            v *= FRICTION;
        }
        if let Some((_, at)) = landed {
            if v < 0.5 {
                return Some((x, at));
            }
        }
    }
    None
}

impl NavGrid {
    /// A running jump from `c` along direction `d` (where the next cell is
    /// a drop no step climbs back): the shortest run-up straight behind `c`
    /// that carries the body over the gap to a floor well above the gap's
    /// bottom, and the cell it stops in. The line must be open cell to cell
    /// (no solid wall across it) and cross no line `refuse` names (a
    /// teleport: the body would be elsewhere); the run-up must be walkable
    /// both ways, on floors at their highest.
    pub fn leap(&self, c: Cell, d: usize, heights: &Heights, refuse: impl Fn(LineId) -> bool) -> Option<Leap> {
        let mut behind = vec![c];
        let b = back(d);
        // The run is made on the floors as they stand at their highest
        // (the line's floors): a lift's range, which lets a walk step on at
        // its bottom, is no run-up at its top.
        let level = |s: Span| Span { low: s.high, ..s };
        while behind.len() <= RUNUP_CELLS {
            let last = *behind.last().unwrap();
            let Some(n) = self.neighbour(last, b).filter(|_| self.open(last, b)) else { break };
            let (p, q) = (level(self.span(last, heights)), level(self.span(n, heights)));
            if !NavGrid::passable(p, q)
                || !NavGrid::passable(q, p)
                || self.crossings_of(last, b).any(|(l, _)| refuse(l))
            {
                break;
            }
            behind.push(n);
        }
        if behind.len() < 3 {
            return None;
        }
        let mut cells: Vec<Cell> = behind.iter().rev().copied().collect();
        let edge = cells.len() - 1;
        while cells.len() <= edge + FLIGHT_CELLS {
            let last = *cells.last().unwrap();
            let Some(n) = self.neighbour(last, d).filter(|_| self.open(last, d)) else { break };
            if self.crossings_of(last, d).any(|(l, _)| refuse(l)) {
                break;
            }
            cells.push(n);
        }
        let spans: Vec<_> = cells.iter().map(|&x| self.span(x, heights)).collect();
        let line = Line {
            floor: spans.iter().map(|s| s.high).collect(),
            ceiling: spans.iter().map(|s| s.ceiling).collect(),
            cells,
            edge,
            step: step_length(d),
        };
        // A run-up of `r` cells: where it stops, if it gets across to a
        // cell on the landing's level and, unless `rims`, not on the edge
        // of a drop (a corner that only grazes a high floor is slid off).
        let attempt = |r: usize, rims: bool| {
            let (stop, landing) = run(&line, r)?;
            let landing_floor = line.under(landing)?.0;
            let i = line.at(stop)?;
            [i, i - 1].into_iter().find_map(|i| {
                let ok = i > edge
                    && (i - edge) as f64 * line.step >= landing - CELL
                    && self.standable(line.cells[i])
                    && (rims || !self.span(line.cells[i], heights).ledge())
                    && (line.floor[i] - landing_floor).abs() <= MAX_STEP;
                ok.then(|| Leap { to: line.cells[i], runup: r as u8, cells: (i - edge) as u8, rim: rims })
            })
        };
        // The longest run-up first: with it failing, none works.
        let longest = edge;
        let shortest = |rims: bool| {
            let best = attempt(longest, rims)?;
            let (mut lo, mut hi) = (1, longest);
            while lo < hi {
                let mid = (lo + hi) / 2;
                if attempt(mid, rims).is_some() {
                    hi = mid;
                } else {
                    lo = mid + 1;
                }
            }
            // A cell more than the least, for a start a little off.
            attempt((lo + 1).min(longest), rims).or_else(|| attempt(lo, rims)).or(Some(best))
        };
        // A landing clear of edges first; where there is none, one on a
        // rim: a chain of stepping stones narrower than the body (MAP21's
        // way to its red key) has nothing else.
        shortest(false).or_else(|| shortest(true))
    }
}

/// A leap under way: where its run-up starts and which way it runs.
#[derive(Clone, Copy, Debug)]
pub struct Run {
    /// The route index of the edge cell.
    edge: usize,
    start: DVec2,
    dir: DVec2,
    angle: f64,
    /// Running (else still walking back to `start`).
    running: bool,
    /// Down on the far side, braking.
    landed: bool,
    /// Left the ground since the run began.
    airborne: bool,
    /// Ticks in this phase.
    ticks: u32,
    /// The closest the body has come to `start`, and ticks since it came
    /// closer.
    closest: f64,
    stalled: u32,
    /// The edge's floor.
    floor: f64,
    key: u32,
    /// Down with a drop close ahead (braked at a run's thrust).
    drop_ahead: bool,
}

impl Run {
    /// Is the body running at the gap (the fight must not turn it)?
    pub fn running(&self) -> bool {
        self.running && !self.landed
    }
}

/// The leap that makes the move into `route.cells[i]`, if one does: its
/// direction.
fn leap_dir(nav: &NavGrid, route: &Route, i: usize) -> Option<usize> {
    if route.leap.get(i).is_none_or(|&r| r == 0) {
        return None;
    }
    let (from, to) = (nav.centre_of(route.cells[i - 1]), nav.centre_of(route.cells[i]));
    let v = to - from;
    (0..8).max_by(|&a, &b| unit(a).dot(v).total_cmp(&unit(b).dot(v)))
}

impl Autopilot {
    /// One tick of a leap on the route: `None` when the next move is not
    /// a leap (or the body is not at its edge yet), else the input, or
    /// `Some(None)` when the leap failed or was abandoned (plan again).
    pub(super) fn leap_step(&mut self, game: &dyn Observe, a: &mut Active) -> Option<Option<TickInput>> {
        let player = game.player();
        let now = game.ticks();
        if a.leap.is_none() {
            let i = a.at + 1;
            let d = leap_dir(&self.nav, &a.route, i)?;
            let edge = a.route.cells[a.at];
            if self.nav.centre_of(edge).distance(player.pos) > 24.0 {
                return None;
            }
            let dir = unit(d);
            let runup = f64::from(a.route.leap[i]) * step_length(d);
            let floor = self.nav.span(edge, &super::live_heights(&game.level().compiled.map)).high;
            a.leap = Some(Run {
                edge: a.at,
                start: self.nav.centre_of(edge) - dir * runup,
                dir,
                angle: dir.y.atan2(dir.x).to_degrees(),
                running: false,
                landed: false,
                airborne: false,
                ticks: 0,
                closest: f64::MAX,
                stalled: 0,
                floor,
                key: key(edge, d),
                drop_ahead: false,
            });
            self.log.push(format!(
                "tick {now}: a running jump from {:?} with {runup:.0} units of run-up",
                self.nav.centre_of(edge)
            ));
        }
        let mut run = a.leap.unwrap();
        run.ticks += 1;
        a.idle = 0;
        if run.landed {
            // Brake before going on: at a run the body would coast some
            // ten times its speed. Near a drop ahead, at a run's thrust, as
            // the model does: a walk's braking takes twice the way, off the
            // far side of a stepping stone.
            if player.velocity.length() > 2.0 && run.ticks < 35 {
                a.leap = Some(run);
                return Some(Some(TickInput { run: run.drop_ahead, ..self.hold(game) }));
            }
            a.leap = None;
            return None;
        }
        let fail = |bot: &mut Autopilot, a: &mut Active, why: &str| {
            bot.log.push(format!("tick {now}: the running jump failed: {why}"));
            bot.bad.insert(run.key, now + 35 * 60);
            a.leap = None;
            bot.next_replan = now;
            Some(None)
        };
        if !run.running {
            // Back to the start of the run-up, stopped there, facing along.
            // A start the body cannot quite reach (a wall beside or behind
            // it) will do from within a cell of it, close to the line: the
            // run-up has a cell to spare.
            let off = run.start - player.pos;
            if off.length() < run.closest - 0.5 {
                (run.closest, run.stalled) = (off.length(), 0);
            } else {
                run.stalled += 1;
            }
            let there = off.length() <= 3.0
                || (run.stalled > STALLED && off.perp_dot(run.dir).abs() <= 12.0 && -off.dot(run.dir) <= CELL);
            if run.ticks > 35 * 15 || (run.stalled > STALLED && !there) {
                return fail(self, a, "the run-up's start was not reached");
            }
            if !there {
                a.leap = Some(run);
                // Braked to a stop at the start, at a run's thrust, once
                // within the way that takes (and a tick's travel): a body
                // left to coast goes on some ten times its speed, off the
                // far side of a stepping stone.
                let v = player.velocity.length();
                if v > 1.0 && off.length() < v * v / (2.0 * RUN_THRUST) + v {
                    return Some(Some(TickInput { run: true, ..self.hold(game) }));
                }
                return Some(Some(self.drive_to(game, run.start, true)));
            }
            if player.velocity.length() > 0.3 {
                a.leap = Some(run);
                return Some(Some(self.hold(game)));
            }
            run.running = true;
            run.ticks = 0;
        }
        let input =
            TickInput { forward: 1, run: true, turn: turn_to(player.angle, run.angle) as f32, ..Default::default() };
        run.airborne |= !player.on_ground();
        let along = (player.pos - run.start).dot(run.dir);
        let land = self.nav.centre_of(a.route.cells[run.edge + 1]);
        let land_along = (land - run.start).dot(run.dir);
        if run.airborne && player.on_ground() {
            if player.z + MAX_STEP
                < run.floor.min(
                    self.nav.span(a.route.cells[run.edge + 1], &super::live_heights(&game.level().compiled.map)).high,
                )
            {
                return fail(self, a, "fell short");
            }
            if along >= land_along - 2.0 * CELL {
                // Across: brake, then on along the route.
                self.log.push(format!("tick {now}: across, at {:?}", player.pos));
                (run.landed, run.ticks) = (true, 0);
                a.at = run.edge + 1;
                // A landing with a drop within a run's coast ahead (a
                // stepping stone) is braked at a run's thrust.
                let live = super::live_heights(&game.level().compiled.map);
                run.drop_ahead = (1..=4).any(|k| {
                    let p = player.pos + run.dir * (f64::from(k) * CELL);
                    self.nav.cell_at(p).is_none_or(|c| {
                        let span = self.nav.span(c, &live);
                        span.ledge() || span.high < player.z - MAX_STEP
                    })
                });
                a.leap = Some(run);
                return Some(Some(TickInput { run: run.drop_ahead, ..self.hold(game) }));
            }
        }
        if run.ticks > 35 * 6 || (run.ticks > 10 && player.on_ground() && player.velocity.length() < 1.0) {
            return fail(self, a, "no way across");
        }
        a.leap = Some(run);
        Some(Some(input))
    }
}
