//! Planning: what the level's special lines can do for the player (the
//! [`Mechanisms`]), the heights a search assumes ([`Plan::heights`]: manual
//! doors open, lifts lowerable), shortest routes over the navigation grid
//! ([`Search`]), and which goal to go for next ([`Plan::choose`]): the exit
//! if it can be reached, else a key, else the switch or walk line whose
//! predicted effect (`predict.rs`) opens the most of the level.

use std::cmp::Reverse;
use std::collections::{BTreeMap, BTreeSet, BinaryHeap};

use glam::DVec2;

use super::leap;
use super::nav::{Cell, Heights, LineId, NavGrid, CELL, NONE};
use super::sectors::{self, target_sectors};
use crate::geom::distance_to_segment;
use crate::level::Level;
use crate::map::special::{Action, Activation, DoorKind, KeyColour, LineSpecial};
use crate::map::Map;
use crate::play::player::{HEIGHT, MAX_STEP, RADIUS};
use crate::play::world::SpecialLine;
use crate::play::USE_RANGE;

/// Extra cost of standing in a cell whose floor hurts.
const HURT_COST: u32 = 160;
/// Extra cost of a cell on the edge of a drop (a body a little off its
/// centre falls).
const LEDGE_COST: u32 = 25;
/// Further cost of a ledge cell whose very centre is over the drop.
const OVER_DROP_COST: u32 = 100;
/// Cost of a straight and a diagonal move.
const STRAIGHT: u32 = 10;
const DIAGONAL: u32 = 14;
/// Extra cost of a wary cell: near a teleport line (within 32 units), or
/// where the body once fell off a ledge.
const WARY_COST: u32 = 60;
/// Extra cost of walking onto a lift over a line that calls it down (the
/// ride down and the wait for it to come back): some 20 cells.
const LIFT_DROP_COST: u32 = 200;
/// Extra cost of a running jump (on top of its run-up, there and back,
/// and its flight): a risk taken only when it saves a long way round.
const LEAP_COST: u32 = 300;
/// Crossing a once-only walk line while its sectors are busy (it would be
/// spent for nothing): far dearer than any way round.
const WASTE_COST: u32 = 5000;
/// A leap that comes down on a rim costs this much more: the stop there is
/// not always held, so a way with landings clear of edges wins.
const RIM_LEAP_COST: u32 = 600;
/// An item is picked up from a cell whose centre is this close along each
/// axis: the body's box touches the item's (16 + 20 in Doom, boxes, not
/// circles) even across a railing or from under a ledge; less 2 for a body
/// a little off its cell's centre.
pub const TOUCH_REACH: f64 = 34.0;
/// A use spot: the cell's centre is at most this far from the line.
const USE_REACH: f64 = USE_RANGE - 20.0;

/// A line with a special, from its [`LineId`].
pub fn line_of(map: &Map, id: LineId) -> (SpecialLine, DVec2, DVec2, Option<&LineSpecial>) {
    let walls = map.lines.len() as u32;
    if id < walls {
        let line = &map.lines[id as usize];
        let (a, b) = map.line_points(line);
        (SpecialLine::Wall(id as usize), a, b, line.special.as_ref())
    } else {
        let t = &map.trigger_lines[(id - walls) as usize];
        (SpecialLine::Trigger((id - walls) as usize), map.vertices[t.from], map.vertices[t.to], Some(&t.special))
    }
}

/// What the level's special lines offer the player, found once per map.
#[derive(Clone, Debug, Default)]
pub struct Mechanisms {
    /// Per sector: the walls that open it as a manual door (used from their
    /// front, the door behind), with the key each needs.
    pub doors: Vec<Vec<(LineId, Option<KeyColour>)>>,
    /// Per sector: the cells from which one of its manual door lines can
    /// be used (sorted; see [`Mechanisms::locate_doors`]).
    pub door_use: Vec<Vec<Cell>>,
    /// Per sector: the lines that lower it as a lift.
    pub lifts: Vec<Vec<LineId>>,
    /// Per sector: the lines that call the lift down from its top (to ride
    /// it down); a lift with none is ridden up only.
    pub lift_down: Vec<Vec<LineId>>,
    /// Per sector: every line that lowers it as a lift, and how.
    pub lift_lines: Vec<Vec<(LineId, Activation)>>,
    /// Per sector: a perpetual lift (its top is its highest neighbour's floor).
    pub perpetual: Vec<bool>,
    /// Per sector: the floor a lift comes back up to (its floor at rest, at
    /// the start and whenever it is still again; a perpetual lift's highest
    /// neighbouring floor).
    pub lift_top: Vec<f64>,
    /// Per sector: the lowest neighbouring floor when the lift's lines
    /// were last sorted.
    pub lift_low: Vec<f64>,
    /// Per sector: whether some special crushes in it (a crusher, a floor
    /// or ceiling that crushes): the bot keeps out from under it as it
    /// closes.
    pub crushers: Vec<bool>,
    /// Exit lines, and whether each is the secret exit.
    pub exits: Vec<(LineId, bool)>,
    /// Teleport lines (walked over from the front), with where they lead.
    pub teleports: BTreeMap<LineId, DVec2>,
    /// Once-only teleport lines assumed already used (by `check`'s closure,
    /// once their front is reached): crossed again they lead on over the
    /// line as well as away.
    pub used_teleports: BTreeSet<LineId>,
    /// Lines that move tagged sectors once set off: switches, walk lines and
    /// shot lines, the candidates for opening the level further.
    pub triggers: Vec<LineId>,
}

impl Mechanisms {
    pub fn of(level: &Level) -> Mechanisms {
        let map = &level.compiled.map;
        let sectors = map.sectors.len();
        let mut m = Mechanisms {
            doors: vec![Vec::new(); sectors],
            door_use: vec![Vec::new(); sectors],
            lifts: vec![Vec::new(); sectors],
            lift_top: map.sectors.iter().map(|s| s.floor).collect(),
            lift_low: (0..sectors).map(|s| sectors::lowest_floor_around(level, s)).collect(),
            crushers: vec![false; sectors],
            lift_down: vec![Vec::new(); sectors],
            lift_lines: vec![Vec::new(); sectors],
            perpetual: vec![false; sectors],
            ..Default::default()
        };
        let ids = 0..(map.lines.len() + map.trigger_lines.len()) as u32;
        for id in ids {
            let (line, _, _, special) = line_of(map, id);
            let Some(special) = special else { continue };
            let targets = target_sectors(level, line, special);
            if let Action::Crusher { .. } | Action::Floor { crush: true, .. } | Action::Ceiling { crush: true, .. } =
                special.action
            {
                for &s in &targets {
                    m.crushers[s] = true;
                }
            }
            if !special.by.players() {
                continue;
            }
            match &special.action {
                Action::Door { kind: DoorKind::Raise | DoorKind::Open, key, .. }
                    if special.tag == 0 && special.on == Activation::Use =>
                {
                    for &s in &targets {
                        m.doors[s].push((id, *key));
                    }
                }
                Action::Lift { .. } | Action::PerpetualLift { .. } => {
                    for &s in &targets {
                        if matches!(special.action, Action::PerpetualLift { .. }) {
                            let high = sectors::highest_floor_around(level, s).unwrap_or(m.lift_top[s]);
                            m.lift_top[s] = m.lift_top[s].max(high);
                            m.perpetual[s] = true;
                        }
                        m.lift_lines[s].push((id, special.on));
                    }
                }
                Action::Exit => m.exits.push((id, false)),
                Action::SecretExit => m.exits.push((id, true)),
                Action::Teleport if special.on == Activation::Walk => {
                    // A destination the game at this skill does not spawn
                    // (a multiplayer-only one on MAP28) teleports no one.
                    let sector_of =
                        |i: usize| level.thing_shown[i].then(|| level.compiled.locate(map.things[i].pos)).flatten();
                    if let Some(t) = crate::map::semantics::teleport_destination(map, special.tag, sector_of) {
                        m.teleports.insert(id, map.things[t].pos);
                    }
                }
                Action::Door { .. }
                | Action::Floor { .. }
                | Action::Ceiling { .. }
                | Action::Stairs { .. }
                | Action::Donut { .. }
                    if !targets.is_empty() =>
                {
                    m.triggers.push(id)
                }
                _ => {}
            }
        }
        for s in 0..sectors {
            m.sort_lift_lines(level, s);
        }
        m
    }

    /// Sorts lift `s`'s lines into those that call it from below and from
    /// the top, for its top as it is now.
    fn sort_lift_lines(&mut self, level: &Level, s: usize) {
        let floors = &level.compiled.map.sectors;
        self.sort_lift_lines_where(level, s, &|t| floors[t].floor);
    }

    /// [`Mechanisms::sort_lift_lines`] with the sectors' floors given by
    /// `floor` (the lift's own: its top and bottom, as kept).
    fn sort_lift_lines_where(&mut self, level: &Level, s: usize, floor: &dyn Fn(usize) -> f64) {
        self.lifts[s].clear();
        self.lift_down[s].clear();
        for &(id, on) in &self.lift_lines[s] {
            let (below, above) = lift_calls(level, id, on, s, (self.lift_top[s], self.lift_low[s]), floor);
            if below {
                self.lifts[s].push(id);
            }
            if above {
                self.lift_down[s].push(id);
            }
        }
    }

    /// A lift at rest is at its top: when another special has moved it
    /// (raised the floor it returns to), its top and its lines' sorting
    /// follow. `busy` says which sectors are moving now.
    pub fn settle_lifts(&mut self, level: &Level, busy: impl Fn(usize) -> bool) {
        let map = &level.compiled.map;
        for s in 0..self.lift_lines.len() {
            if self.lift_lines[s].is_empty() || self.perpetual[s] || busy(s) {
                continue;
            }
            // Its bottom moves too when a neighbour's floor does (a pool
            // lowered beside it brings a switch down there into reach).
            let floor = map.sectors[s].floor;
            let low = sectors::lowest_floor_around(level, s);
            if floor != self.lift_top[s] || low != self.lift_low[s] {
                self.lift_top[s] = floor;
                self.lift_low[s] = low;
                self.sort_lift_lines(level, s);
            }
        }
    }
}

impl Mechanisms {
    /// The lifts' ends as a plan's `heights` have them (what
    /// [`Mechanisms::settle_lifts`] does for the level as it is): another
    /// special raising a lift's floor raises its top, and a neighbour that
    /// can be lowered (a pool drained beside it) lowers where it comes down
    /// to; either can bring a switch into reach, so the lines are sorted
    /// again, each side's floor as low as it can be. A lift that now has a
    /// line calling it gets its range in `heights`. Returns whether any
    /// lift changed.
    pub fn settle_planned_lifts(&mut self, level: &Level, heights: &mut Heights) -> bool {
        let mut changed = false;
        for s in 0..self.lift_lines.len() {
            if self.lift_lines[s].is_empty() || self.perpetual[s] {
                continue;
            }
            let low = sectors::neighbours(level, s).map(|n| heights.low[n]).fold(self.lift_low[s], f64::min);
            let top = self.lift_top[s].max(heights.floor[s]);
            if low >= self.lift_low[s] && top <= self.lift_top[s] {
                continue;
            }
            self.lift_low[s] = low;
            self.lift_top[s] = top;
            let lows = heights.low.clone();
            self.sort_lift_lines_where(level, s, &|t| lows[t]);
            if !self.lifts[s].is_empty() || !self.lift_down[s].is_empty() {
                heights.low[s] = heights.low[s].min(low);
                heights.floor[s] = heights.floor[s].max(top.min(heights.ceiling[s] - 56.0));
            }
            changed = true;
        }
        changed
    }
}

/// How far from its lift a switch can be for the player to call the lift
/// and still board it: it waits 3 seconds at the bottom, in which a
/// running player covers some 1,700 units, less the turns of a real route.
const LIFT_REACH: f64 = 1024.0;

/// Where the player can call lift `lift` down with `line` from: from below
/// (to ride it up) and from the top (to ride it down). A switch works from
/// its front, within [`LIFT_REACH`] of the lift: from below when its front
/// floor is under the lift's top but not below its lowest (a switch far
/// below is for someone else), from the top when no more than a step under
/// it (a switch above drops the player onto it). A walk
/// line works from below with a side off the lift low enough to stand on (a
/// walk line only reached from the top is for coming down), and from the
/// top with a side on the lift or level with its top.
/// `(top, low)` are the lift's ends and `floor` the sectors' floors.
fn lift_calls(
    level: &Level,
    id: LineId,
    on: Activation,
    lift: usize,
    (top, low): (f64, f64),
    floor: &dyn Fn(usize) -> f64,
) -> (bool, bool) {
    let map = &level.compiled.map;
    let (sl, a, b, _) = line_of(map, id);
    let sides: Vec<(usize, bool)> = match sl {
        SpecialLine::Wall(i) => {
            let line = &map.lines[i];
            std::iter::once((line.front.sector, true)).chain(line.back.as_ref().map(|s| (s.sector, false))).collect()
        }
        SpecialLine::Trigger(_) => {
            let d = (b - a).normalize_or_zero();
            let normal = DVec2::new(d.y, -d.x) * 8.0;
            let mid = (a + b) / 2.0;
            [(mid + normal, true), (mid - normal, false)]
                .into_iter()
                .filter_map(|(p, front)| Some((level.compiled.locate(p)?, front)))
                .collect()
        }
    };
    // A switch across the level lowers the lift for someone else: it is
    // back up before the player gets there.
    let mid = (a + b) / 2.0;
    let near = level.sector_lines[lift].iter().any(|&i| {
        let (p, q) = map.line_points(&map.lines[i as usize]);
        nearest_on(mid, p, q).distance(mid) <= LIFT_REACH
    });
    let step = MAX_STEP;
    let floor = |sector: usize| if sector == lift { top } else { floor(sector) };
    let mut calls = (false, false);
    for &(sector, front) in &sides {
        match on {
            Activation::Use => {
                if front && near {
                    // A switch facing the lift is pressed standing on it:
                    // a call from the top only (the body cannot board a
                    // raised lift to press it).
                    calls.0 |= sector != lift && floor(sector) >= low - step && floor(sector) < top - step;
                    calls.1 |= floor(sector) >= top - step;
                }
            }
            _ => {
                calls.0 |= sector != lift && floor(sector) <= low + step;
                calls.1 |= sector == lift || floor(sector) >= top - step;
            }
        }
    }
    calls
}

impl Mechanisms {
    /// Finds the cells each manual door can be opened from (a door opens
    /// only from the front of one of its lines).
    /// With `keys`, only the lines those keys open count (a door whose
    /// faces want different keys opens from one side only); without, all.
    pub fn locate_doors(&mut self, nav: &NavGrid, map: &Map, keys: Option<&[KeyColour]>) {
        for s in 0..self.doors.len() {
            let mut cells = BTreeSet::new();
            for &(line, key) in &self.doors[s] {
                if key.is_none_or(|k| keys.is_none_or(|held| held.contains(&k))) {
                    cells.extend(use_cells(nav, map, line).cells);
                }
            }
            self.door_use[s] = cells.into_iter().collect();
        }
    }

    /// Sectors that are manual doors shut in `map` as it stands.
    pub fn shut_doors(&self, map: &Map) -> Vec<bool> {
        (0..self.doors.len())
            .map(|s| {
                !self.doors[s].is_empty() && map.sectors[s].ceiling - map.sectors[s].floor < crate::play::player::HEIGHT
            })
            .collect()
    }
}

/// Where a route ends and what is done there.
#[derive(Clone, Debug, PartialEq)]
pub enum Goal {
    /// Use this line (a switch, an exit switch, a lift's button).
    Use(LineId),
    /// Walk over this line.
    Cross(LineId),
    /// Shoot this line (Doom's G lines).
    Shoot(LineId),
    /// Walk onto this spot (an item, a key).
    Touch(DVec2, u32),
    /// Ride the lift under this spot and fire at the boss brain (actor)
    /// as it passes the heights a shot hurts it from.
    Brain(DVec2, u32),
}

impl Goal {
    /// A key to remember the goal by.
    pub fn key(&self) -> (u8, u32) {
        match self {
            Goal::Use(line) => (0, *line),
            Goal::Cross(line) => (1, *line),
            Goal::Touch(_, thing) => (2, *thing),
            Goal::Shoot(line) => (3, *line),
            Goal::Brain(_, actor) => (4, *actor),
        }
    }
}

/// Why a goal was chosen, for the report.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    Exit,
    Key,
    Trigger,
    Supplies,
    Lift,
    /// Off a floor that hurts, with nothing else to do.
    Safety,
    /// Health or armour seen ([`super::Options::gather`]).
    Gather,
    /// A sector not yet visited ([`super::Options::explore`]).
    Explore,
}

/// What the search needs of a goal: cells where it is met, and lines whose
/// crossing meets it.
#[derive(Clone, Default)]
pub struct Targets {
    cells: BTreeSet<Cell>,
    lines: BTreeSet<LineId>,
}

/// One route: cells from the start to a goal, and which moves are teleports.
#[derive(Clone, Debug, Default)]
pub struct Route {
    pub cells: Vec<Cell>,
    /// `teleport[i]`: the move into `cells[i]` was a teleport.
    pub teleport: Vec<bool>,
    /// `leap[i]`: the move into `cells[i]` is a running jump with this many
    /// cells of run-up (0: not a leap).
    pub leap: Vec<u8>,
    pub cost: u32,
}

/// Search buffers, kept between searches.
#[derive(Default)]
pub struct Search {
    cost: Vec<u32>,
    prev: Vec<u32>,
    tele: Vec<bool>,
    leap: Vec<u8>,
    seen: Vec<u32>,
    stamp: u32,
    heap: BinaryHeap<Reverse<(u32, Cell)>>,
    /// Cells reached by the last search, in order of cost.
    pub reached: Vec<Cell>,
}

/// Everything a search reads.
pub struct World<'a> {
    pub nav: &'a NavGrid,
    pub map: &'a Map,
    pub mech: &'a Mechanisms,
    pub heights: &'a Heights,
    /// Cells a solid thing stands on.
    pub blocked: &'a BTreeSet<Cell>,
    /// Moves found not to work (cell * 8 + dir).
    pub bad: &'a BTreeSet<u32>,
    /// Teleport and walk lines that are spent (used once, not repeatable).
    pub spent: &'a BTreeSet<LineId>,
    /// Once-only walk lines a crossing now would spend for nothing (their
    /// sectors are busy): crossed only where there is no way round.
    pub wasted: &'a BTreeSet<LineId>,
    /// Damaging sectors.
    pub hurts: &'a [bool],
    /// Manual doors shut now (the heights assume them open): they can be
    /// entered only from a cell they can be opened from.
    pub shut: &'a [bool],
    /// Per cell (or none at all): near a teleport line or where the body
    /// fell off a ledge; such cells cost more, so routes keep clear.
    pub wary: &'a [bool],
}

impl Search {
    /// Cheapest route from `start` to any of `targets` (or, with none, a
    /// flood of everything reachable: see [`Search::reached`]). Returns the
    /// route to the first target met.
    pub fn run(&mut self, w: &World, start: Cell, targets: Option<&Targets>) -> Option<Route> {
        let cells = w.nav.cells();
        if self.cost.len() != cells {
            self.cost = vec![0; cells];
            self.prev = vec![NONE; cells];
            self.tele = vec![false; cells];
            self.leap = vec![0; cells];
            self.seen = vec![0; cells];
            self.stamp = 0;
        }
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.seen.fill(0);
            self.stamp = 1;
        }
        self.heap.clear();
        self.reached.clear();
        let stamp = self.stamp;
        self.seen[start as usize] = stamp;
        self.cost[start as usize] = 0;
        self.prev[start as usize] = NONE;
        self.tele[start as usize] = false;
        self.leap[start as usize] = 0;
        self.heap.push(Reverse((0, start)));
        while let Some(Reverse((cost, c))) = self.heap.pop() {
            if cost > self.cost[c as usize] {
                continue;
            }
            self.reached.push(c);
            if let Some(t) = targets {
                if t.cells.contains(&c) {
                    return Some(self.route(c));
                }
            }
            let from = w.nav.span(c, w.heights);
            // Directions in which the next cell is a full step down or more: a
            // running jump may clear a gap there or a cell on.
            let mut drops = 0u8;
            for d in 0..8 {
                if !w.nav.open(c, d) || w.bad.contains(&(c * 8 + d as u32)) {
                    continue;
                }
                let Some(n) = w.nav.neighbour(c, d) else { continue };
                if w.blocked.contains(&n) {
                    continue;
                }
                let here = w.nav.touched(c);
                let mut to = w.nav.span(n, w.heights);
                // A lift ridden up only: from its top (every sector under
                // the body the lift or level with its top) it stays up.
                let up_only = |s: usize| {
                    let top = w.heights.floor[s];
                    !w.mech.lifts[s].is_empty()
                        && w.mech.lift_down[s].is_empty()
                        && w.heights.low[s] < top
                        && here.iter().all(|&t| t as usize == s || w.heights.floor[t as usize] >= top - MAX_STEP)
                };
                // A lift called from its top only (its switch on the lift
                // itself): from below it stays up.
                let down_only = |s: usize| {
                    let top = w.heights.floor[s];
                    w.mech.lifts[s].is_empty()
                        && !w.mech.lift_down[s].is_empty()
                        && w.heights.low[s] < top
                        && here.iter().all(|&t| t as usize != s && w.heights.floor[t as usize] < top - MAX_STEP)
                };
                let fixed = |s: usize| up_only(s) || down_only(s);
                if w.nav.touched(n).iter().any(|&s| fixed(s as usize)) {
                    to = w.nav.span_where(n, w.heights, |s| fixed(s).then_some(w.heights.floor[s]));
                }
                if from.leaps_off(&to) {
                    drops |= 1 << d;
                }
                if !w.nav.climbable(c, d, from, to, w.heights) {
                    continue;
                }
                let door_shut = w.nav.touched(n).iter().any(|&s| {
                    w.shut[s as usize] && !here.contains(&s) && w.mech.door_use[s as usize].binary_search(&c).is_err()
                });
                if door_shut {
                    continue;
                }
                let mut next = n;
                let mut teleported = false;
                let mut met = false;
                let mut lift_drop = false;
                let mut waste = false;
                for (line, front) in w.nav.crossings_of(c, d) {
                    if targets.is_some_and(|t| t.lines.contains(&line)) {
                        met = true;
                    } else {
                        waste |= w.wasted.contains(&line);
                    }
                    let (_, _, _, special) = line_of(w.map, line);
                    let Some(special) = special else { continue };
                    if special.on != Activation::Walk || w.spent.contains(&line) || !special.by.players() {
                        continue;
                    }
                    // Walking onto a lift over a line that calls it down:
                    // the floor goes from under the body, which rides down
                    // and waits for it to come back up. Walking round is
                    // better where there is a way round.
                    let onto = w.nav.centre[n as usize];
                    lift_drop |= onto != NONE && w.mech.lift_down[onto as usize].contains(&line);
                    if let (Some(&dest), true) = (w.mech.teleports.get(&line), front) {
                        if let Some(t) = w.nav.standable_near(dest, 2) {
                            next = t;
                            teleported = true;
                        }
                    }
                }
                // A once-only teleporter used before: the walk goes on over
                // the line too.
                if teleported && w.nav.crossings_of(c, d).any(|(l, _)| w.mech.used_teleports.contains(&l)) {
                    self.relax(c, n, cost + if d < 4 { STRAIGHT } else { DIAGONAL }, false, 0);
                }
                let centre = w.nav.centre[next as usize];
                let mut step = if d < 4 { STRAIGHT } else { DIAGONAL } + u32::from(w.nav.narrow[next as usize]);
                if to.ledge() {
                    step += LEDGE_COST;
                    // Its centre over the drop: the body keeps its footing
                    // only while it is pushed no further out.
                    if centre != NONE && w.heights.floor[centre as usize] < to.high - MAX_STEP {
                        step += OVER_DROP_COST;
                    }
                }
                if centre != NONE && w.hurts[centre as usize] {
                    step += HURT_COST;
                }
                if w.wary.get(next as usize).copied().unwrap_or(false) {
                    step += WARY_COST;
                }
                if lift_drop {
                    step += LIFT_DROP_COST;
                }
                if waste {
                    step += WASTE_COST;
                }
                if self.relax(c, next, cost + step, teleported, 0) && met {
                    return Some(self.route(next));
                }
            }
            for d in (0..8).filter(|&d| drops & (1 << d) != 0) {
                if w.bad.contains(&leap::key(c, d)) {
                    continue;
                }
                let Some(jump) = leap_from(w.nav, w.mech, w.heights, c, d) else { continue };
                if w.blocked.contains(&jump.to) {
                    continue;
                }
                let runup = u32::from(jump.runup) * 2 + u32::from(jump.cells);
                let step = if d < 4 { STRAIGHT } else { DIAGONAL };
                let rim = if jump.rim { RIM_LEAP_COST } else { 0 };
                self.relax(c, jump.to, cost + LEAP_COST + rim + runup * step, false, jump.runup);
            }
        }
        None
    }

    /// Reaching `next` from `c` at `total`: kept if cheaper than known.
    fn relax(&mut self, c: Cell, next: Cell, total: u32, teleported: bool, leap: u8) -> bool {
        let n = next as usize;
        if self.seen[n] == self.stamp && total >= self.cost[n] {
            return false;
        }
        self.seen[n] = self.stamp;
        self.cost[n] = total;
        self.prev[n] = c;
        self.tele[n] = teleported;
        self.leap[n] = leap;
        self.heap.push(Reverse((total, next)));
        true
    }

    fn route(&self, end: Cell) -> Route {
        let mut cells = vec![end];
        let mut c = end;
        while self.prev[c as usize] != NONE {
            c = self.prev[c as usize];
            cells.push(c);
        }
        cells.reverse();
        // `tele[c]` and `leap[c]` mark the move into c.
        let teleport = cells.iter().map(|&c| self.tele[c as usize]).collect();
        let leap = cells.iter().map(|&c| self.leap[c as usize]).collect();
        Route { cells, teleport, leap, cost: self.cost[end as usize] }
    }

    /// Was `c` reached by the last search?
    pub fn was_reached(&self, c: Cell) -> bool {
        self.seen[c as usize] == self.stamp
    }

    /// The cost of reaching `c` in the last search.
    pub fn cost_to(&self, c: Cell) -> Option<u32> {
        self.was_reached(c).then(|| self.cost[c as usize])
    }
}

/// A running jump from `c` along direction `d`, as the search and `check`
/// both take one: never over a teleport line (the body would be elsewhere).
pub fn leap_from(nav: &NavGrid, mech: &Mechanisms, heights: &Heights, c: Cell, d: usize) -> Option<leap::Leap> {
    nav.leap(c, d, heights, |l| mech.teleports.contains_key(&l))
}

/// The cells from which `line` can be used: on its front, the centre within
/// use range, nothing solid between.
pub fn use_cells(nav: &NavGrid, map: &Map, line: LineId) -> Targets {
    let mut near = use_cells_within(nav, map, line, USE_REACH);
    // Cells with no room for the body as the level stands (a switch at the
    // back of a low slot) do not count as near.
    let now = Heights::of(map);
    let roomy = |c: Cell| {
        let span = nav.span(c, &now);
        span.ceiling - span.high >= HEIGHT
    };
    if near.cells().any(roomy) {
        // A switch on a ledge's top, facing the floor below: the near
        // cells are all on the ledge or over its edge, and the press also
        // reaches from the floor below, a step or more down from every
        // near floor one can stand on away from an edge.
        let floors: Vec<f64> =
            near.cells().filter(|&c| roomy(c) && !nav.span(c, &now).ledge()).map(|c| nav.span(c, &now).high).collect();
        let below: Vec<Cell> = use_cells_within(nav, map, line, USE_RANGE - 6.0)
            .cells()
            .filter(|&c| {
                let span = nav.span(c, &now);
                roomy(c) && !span.ledge() && floors.iter().all(|&f| (f - span.high).abs() > MAX_STEP)
            })
            .collect();
        near.cells.extend(below);
        return near;
    }
    // A switch on a ledge's face, across a step or at the back of a slot:
    // every cell that close has its body over the ledge or under the low
    // ceiling. The press reaches further than the margin kept for
    // steering (`use_line` presses within the use range).
    let mut far = use_cells_within(nav, map, line, USE_RANGE - 6.0);
    far.add(near);
    far
}

/// [`use_cells`] within `reach` of the line.
fn use_cells_within(nav: &NavGrid, map: &Map, line: LineId, reach: f64) -> Targets {
    let (_, a, b, _) = line_of(map, line);
    let mut t = Targets::default();
    for c in nav.cells_in_box(a.min(b) - DVec2::splat(reach), a.max(b) + DVec2::splat(reach)) {
        if !nav.standable(c) {
            continue;
        }
        let p = nav.centre_of(c);
        if crate::geom::front_distance(a, b, p) <= 0.0 || distance_to_segment(p, a, b) > reach {
            continue;
        }
        // Aimed at the line's inner part (its ends are where niche walls
        // meet it): the point across from the cell, or the middle.
        let along = |t: f64| a + (b - a) * t;
        let reachable = [nearest_on(p, along(0.2), along(0.8)), along(0.5)]
            .into_iter()
            .any(|q| q.distance(p) <= reach && clear_between(map, p, q, line));
        if reachable {
            t.cells.insert(c);
        }
    }
    t
}

/// Cells within `reach` of `p` along each axis (a square, as Doom's
/// touching boxes are).
pub fn cells_near(nav: &NavGrid, p: DVec2, reach: f64) -> Targets {
    let mut t = Targets::default();
    let r = (reach / CELL).ceil() as i32 + 1;
    let Some(centre) = nav.cell_at(p) else { return t };
    let (cx, cy) = ((centre as usize % nav.width) as i32, (centre as usize / nav.width) as i32);
    for dy in -r..=r {
        for dx in -r..=r {
            let (x, y) = (cx + dx, cy + dy);
            if x < 0 || y < 0 || x as usize >= nav.width || y as usize >= nav.height {
                continue;
            }
            let c = (y as usize * nav.width + x as usize) as Cell;
            if nav.standable(c) && (nav.centre_of(c) - p).abs().max_element() <= reach {
                t.cells.insert(c);
            }
        }
    }
    t
}

/// The cells from which an item at `p` can be picked up: those within
/// [`TOUCH_REACH`] (a square, as Doom's boxes touch), and those a little
/// further from which a walk straight at it stops against a step or ledge
/// (a two-sided line it cannot climb) with the item then in reach: a key on
/// a pedestal is taken by walking into the pedestal.
pub fn touch_cells(nav: &NavGrid, map: &Map, p: DVec2) -> Targets {
    let mut t = cells_near(nav, p, TOUCH_REACH);
    let far = cells_near(nav, p, TOUCH_REACH + CELL);
    for c in far.cells() {
        if t.contains_cell(c) {
            continue;
        }
        let from = nav.centre_of(c);
        // The lines on the way, nearest first: the first that stops the
        // body must be a step or ledge (two-sided), with the item in reach
        // of the body standing against it.
        let mut crossed: Vec<(f64, &crate::map::Line)> = map
            .lines
            .iter()
            .filter_map(|l| {
                let (a, b) = map.line_points(l);
                crate::geom::crossing(from, p, a, b).map(|f| (f, l))
            })
            .collect();
        crossed.sort_by(|x, y| x.0.total_cmp(&y.0));
        for (_, line) in crossed {
            let Some(back) = &line.back else { break };
            if line.flags.impassable {
                break;
            }
            let (a, b) = map.line_points(line);
            let (near, beyond) = if crate::geom::front_distance(a, b, from) >= 0.0 {
                (&map.sectors[line.front.sector], &map.sectors[back.sector])
            } else {
                (&map.sectors[back.sector], &map.sectors[line.front.sector])
            };
            if beyond.floor <= near.floor + MAX_STEP && beyond.ceiling - beyond.floor.max(near.floor) >= HEIGHT {
                continue;
            }
            // Where the body's circle first meets the line (its ends too:
            // a pedestal's corner stops a slanting walk early). Doom's
            // touch wants the item no higher than the body is tall.
            let (len, dir) = ((p - from).length(), (p - from).normalize_or_zero());
            let mut stop = from;
            let mut s = 0.0;
            while s <= len && distance_to_segment(from + dir * s, a, b) > RADIUS {
                stop = from + dir * s;
                s += 1.0;
            }
            if (stop - p).abs().max_element() <= TOUCH_REACH && beyond.floor <= near.floor + HEIGHT {
                t.cells.insert(c);
            }
            break;
        }
    }
    t
}

/// Targets met by crossing `line`.
pub fn crossing_of(line: LineId) -> Targets {
    Targets { cells: BTreeSet::new(), lines: [line].into() }
}

impl Targets {
    pub fn is_empty(&self) -> bool {
        self.cells.is_empty() && self.lines.is_empty()
    }

    pub fn add(&mut self, other: Targets) {
        self.cells.extend(other.cells);
        self.lines.extend(other.lines);
    }

    /// Drops `cells` from the targets.
    pub fn remove_cells(&mut self, cells: &BTreeSet<Cell>) {
        self.cells.retain(|c| !cells.contains(c));
    }

    pub fn insert(&mut self, c: Cell) {
        self.cells.insert(c);
    }

    pub fn contains_cell(&self, c: Cell) -> bool {
        self.cells.contains(&c)
    }

    pub fn cells(&self) -> impl Iterator<Item = Cell> + '_ {
        self.cells.iter().copied()
    }
}

/// The targets of a goal.
pub fn targets_of(nav: &NavGrid, map: &Map, goal: &Goal) -> Targets {
    match goal {
        Goal::Use(line) => use_cells(nav, map, *line),
        Goal::Cross(line) => crossing_of(*line),
        Goal::Touch(p, _) => touch_cells(nav, map, *p),
        Goal::Shoot(line) => {
            let mut t = shoot_cells(nav, map, *line);
            t.cells.retain(|&c| shot_passes(nav, map, c, *line));
            t
        }
        Goal::Brain(p, _) => cells_near(nav, *p, 1.0),
    }
}

/// A shot line is shot from a cell this close to its middle.
const SHOOT_REACH: f64 = 384.0;

/// The cells from which a shot at the middle of `line` reaches it (nothing
/// that stops a use stops it first: a one-sided wall or a closed opening).
pub fn shoot_cells(nav: &NavGrid, map: &Map, line: LineId) -> Targets {
    let (_, a, b, _) = line_of(map, line);
    let mid = (a + b) / 2.0;
    let mut t = Targets::default();
    for c in cells_near(nav, mid, SHOOT_REACH).cells() {
        let p = nav.centre_of(c);
        if p.distance(mid) > 48.0 && clear_between(map, p, mid, line) {
            t.cells.insert(c);
        }
    }
    t
}

/// The point of segment `a-b` nearest `p`.
pub fn nearest_on(p: DVec2, a: DVec2, b: DVec2) -> DVec2 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    a + d * t
}

/// Can a use reach from `p` to `q` on `line`: does the segment cross no
/// wall that stops a use (one-sided, or two-sided with no opening: Doom's
/// P_UseTraverse; an impassable flag does not stop it)?
pub fn clear_between(map: &Map, p: DVec2, q: DVec2, line: LineId) -> bool {
    clear_through(map, p, q, line, |bottom, top| top > bottom)
}

/// Does the segment from `p` to `q` on `line` cross only two-sided lines
/// whose opening (its bottom and top) `passes` lets through? `line` itself
/// does not count, and the segment stops a hair short of it.
fn clear_through(map: &Map, p: DVec2, q: DVec2, line: LineId, passes: impl Fn(f64, f64) -> bool) -> bool {
    let q = p + (q - p) * 0.98;
    map.lines.iter().enumerate().all(|(i, l)| {
        if i as u32 == line {
            return true;
        }
        if let Some(back) = &l.back {
            let (f, b) = (&map.sectors[l.front.sector], &map.sectors[back.sector]);
            if passes(f.floor.max(b.floor), f.ceiling.min(b.ceiling)) {
                return true;
            }
        }
        let (a, b) = map.line_points(l);
        crate::geom::crossing(p, q, a, b).is_none()
    })
}

/// A bullet leaves this high above the shooter's feet: half the player's
/// height and 8 more (Doom's `P_LineAttack` from `P_GunShot`).
const SHOT_HEIGHT: f64 = HEIGHT / 2.0 + 8.0;

/// Does a level shot fired from cell `c` (with nothing to aim at, Doom's
/// autoaim leaves the slope at 0) get through every two-sided line on its
/// way to the middle of `line`, the levels as they stand? Doom's
/// `PTR_ShootTraverse` stops a shot at a step up whose top is above the
/// shot's height, or at a ceiling coming down below it: a gun line behind
/// a step (MAP28's door behind a 16-unit step, shot at from the floor 24
/// below) is shot at from the step, not from below it. The shot line
/// itself is set off whatever its opening (`P_ShootSpecialLine` comes
/// first). The body stands on the highest floor under its circle; a cell
/// over a step is tried from its lowest floor as well, since the body may
/// stand either side.
fn shot_passes(nav: &NavGrid, map: &Map, c: Cell, line: LineId) -> bool {
    let floors = || nav.touched(c).iter().map(|&s| map.sectors[s as usize].floor);
    let (Some(low), Some(high)) = (floors().min_by(f64::total_cmp), floors().max_by(f64::total_cmp)) else {
        return false;
    };
    let (_, a, b, _) = line_of(map, line);
    let from = nav.centre_of(c);
    std::iter::once(low).chain((high != low).then_some(high)).all(|floor| {
        let z = floor + SHOT_HEIGHT;
        clear_through(map, from, (a + b) / 2.0, line, |bottom, top| bottom <= z && top >= z)
    })
}

/// The heights a plan assumes: the level now, with every manual door the
/// player can open open, and every lift it can call able to come down.
pub fn plan_heights(level: &Level, mech: &Mechanisms, keys: &[KeyColour], spent: &BTreeSet<LineId>) -> Heights {
    let map = &level.compiled.map;
    let mut h = Heights::of(map);
    for (s, doors) in mech.doors.iter().enumerate() {
        if doors.iter().any(|(_, key)| key.is_none_or(|k| keys.contains(&k))) {
            if let Some(top) = sectors::lowest_ceiling_around(level, s) {
                h.ceiling[s] = h.ceiling[s].max(top - 4.0);
            }
        }
    }
    for (s, lifts) in mech.lifts.iter().enumerate() {
        if lifts.iter().chain(&mech.lift_down[s]).any(|l| !spent.contains(l)) {
            h.low[s] = h.low[s].min(sectors::lowest_floor_around(level, s));
            h.floor[s] = h.floor[s].max(mech.lift_top[s].min(h.ceiling[s] - 56.0));
        }
    }
    h
}
