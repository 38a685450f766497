//! The route `check` draws, handed to its picture.
//!
//! By default it is the closure's own: the goals in the order the closure
//! reached them (keys taken, switches, walk lines and teleporters set off
//! that change the map, then the exit), joined by the search's cheapest
//! paths over the level as the closure had it at each stage. The picture
//! then draws the route the report tells, to the exit whenever the report
//! says the exit is reachable, and costs a few searches.
//!
//! The autopilot's played route ([`bot_route`], `check --bot-route`) plays
//! the whole level offline, up to 20 minutes of game time: 274 s on
//! freedoom2 MAP29 when it was the only route drawn.

use std::collections::BTreeSet;

use glam::DVec2;

use super::nav::{Cell, Heights, LineId, NavGrid};
use super::observe::Observe;
use super::plan::{self, Mechanisms, Search, Targets};
use crate::level::Level;
use crate::map::special::KeyColour;

/// What the closure set off or took in one round, and the level as that
/// round's flood saw it (the goals were met in that flood): its heights,
/// doors opened, and mechanisms (once-only teleporters used, lifts' ends).
pub(super) struct Stage {
    pub heights: Heights,
    pub opened: Vec<bool>,
    pub mech: Mechanisms,
    pub goals: Vec<Goal>,
    /// Per goal: the sectors whose heights it changed or whose door it
    /// opened (none for keys and teleporters).
    pub moved: Vec<Vec<usize>>,
}

/// A goal the closure met.
#[derive(Clone, Copy, Debug)]
pub(super) enum Goal {
    Key(KeyColour, DVec2),
    /// A switch, walk line or shot line whose special changed the map, and
    /// the key it needs.
    Line(LineId, Option<KeyColour>),
    /// A once-only teleporter, crossed.
    Teleport(LineId),
}

/// The route through a level and the places where it meets its goals.
#[derive(Clone, Debug, Default)]
pub struct Route {
    /// Points from the start.
    pub points: Vec<DVec2>,
    /// `teleport[i]`: the move into `points[i]` is a teleport (the picture
    /// draws no line across it).
    pub teleport: Vec<bool>,
    /// Where each goal was met, in order.
    pub stops: Vec<DVec2>,
    /// The route ends at an exit.
    pub exits: bool,
    /// Goals the route could not be drawn to from where it stood (a one-way
    /// drop on the way to one before it): the closure reached them from the
    /// start by another way.
    pub missed: usize,
}

/// What every search of the route reads besides the stage.
pub(super) struct Ground<'a> {
    pub nav: &'a NavGrid,
    pub level: &'a Level,
    pub meets: &'a super::check::Meets,
    pub solid: &'a BTreeSet<Cell>,
    pub hurts: &'a [bool],
}

impl Ground<'_> {
    /// The cells and line that meet `goal` with the sectors at `heights`
    /// (a press through a door's slot reaches once the door is open).
    fn targets(&self, goal: Goal, heights: &Heights) -> (Targets, Option<LineId>) {
        let map = &self.level.compiled.map;
        match goal {
            Goal::Key(_, pos) => (plan::touch_cells(self.nav, map, pos), None),
            Goal::Line(line, _) => self.meets.of(self.nav, self.level, line, heights),
            Goal::Teleport(line) => (Targets::default(), Some(line)),
        }
    }

    /// The cheapest path from `from` to any of `targets` over the level as
    /// `stage` has it, as the closure's flood searches it.
    fn search(&self, search: &mut Search, stage: &Stage, from: Cell, targets: &Targets) -> Option<plan::Route> {
        let mech = &stage.mech;
        let none = BTreeSet::new();
        let no_lines = BTreeSet::new();
        let mut shut = mech.shut_doors(&self.level.compiled.map);
        for (s, open) in stage.opened.iter().enumerate() {
            shut[s] &= !open;
        }
        let w = plan::World {
            nav: self.nav,
            map: &self.level.compiled.map,
            mech,
            heights: &stage.heights,
            blocked: self.solid,
            bad: &none,
            spent: &no_lines,
            wasted: &no_lines,
            hurts: self.hurts,
            shut: &shut,
            wary: &[],
        };
        search.run(&w, from, Some(targets))
    }
}

/// Does the move from `a` to `b` cross `line`? (`b` may be a teleport's
/// landing: then some move out of `a` crosses it.)
fn crosses(nav: &NavGrid, a: Cell, b: Cell, line: LineId) -> bool {
    let dirs: Vec<usize> = match nav.direction(a, b) {
        Some(d) => vec![d],
        None => (0..8).collect(),
    };
    dirs.into_iter().any(|d| nav.crossings_of(a, d).any(|(l, _)| l == line))
}

/// Every target of `goals` as one.
fn union(goals: &[(Targets, Option<LineId>)]) -> Targets {
    let mut all = Targets::default();
    for (targets, line) in goals {
        all.add(targets.clone());
        if let Some(line) = line {
            all.add(plan::crossing_of(*line));
        }
    }
    all
}

/// The closure's route: each stage's goals, nearest first, then the exit
/// (`exit`: the targets of the exits the report calls reachable).
///
/// Switches and walk lines that change nothing the route walks on are left
/// out (the closure sets off every one it reaches: on freedoom2 MAP12 the
/// route would tour 34 of them). A line is left out only if, with it left
/// out, no cell of the route from its round on stands on a sector it moved,
/// so every search stays true without it; the check is made on the route
/// drawn without them, and any it touches is put back, until none is.
pub(super) fn closure_route(g: &Ground, stages: &[Stage], start: Cell, exit: &[(Targets, Option<LineId>)]) -> Route {
    let full = walk_goals(g, stages, start, exit, &BTreeSet::new());
    let mut dropped: BTreeSet<(usize, usize)> = BTreeSet::new();
    for (k, stage) in stages.iter().enumerate() {
        for (i, moved) in stage.moved.iter().enumerate() {
            if !moved.is_empty() && !full.touches(g.nav, full.begun[k], moved) {
                dropped.insert((k, i));
            }
        }
    }
    // Each pass puts back at least one line or returns: at most as many
    // passes as lines left out, and a few in practice.
    while !dropped.is_empty() {
        let fewer = walk_goals(g, stages, start, exit, &dropped);
        let touched: Vec<(usize, usize)> = dropped
            .iter()
            .copied()
            .filter(|&(k, i)| fewer.touches(g.nav, fewer.begun[k], &stages[k].moved[i]))
            .collect();
        if touched.is_empty() {
            if fewer.route.exits >= full.route.exits && fewer.route.missed <= full.route.missed {
                return fewer.route;
            }
            break;
        }
        for t in touched {
            dropped.remove(&t);
        }
    }
    full.route
}

/// A route as walked, with what the pruning asks of it.
struct Walked {
    route: Route,
    cells: Vec<Cell>,
    /// Per stage: the index in `cells` where its searches began.
    begun: Vec<usize>,
}

impl Walked {
    /// Does the route from `cells[from]` on stand on any of `sectors`?
    fn touches(&self, nav: &NavGrid, from: usize, sectors: &[usize]) -> bool {
        self.cells[from.min(self.cells.len())..]
            .iter()
            .any(|&c| nav.touched(c).iter().any(|&s| sectors.binary_search(&(s as usize)).is_ok()))
    }
}

/// The route through `stages`' goals but those `dropped` (stage, goal),
/// then to the exit.
fn walk_goals(
    g: &Ground,
    stages: &[Stage],
    start: Cell,
    exit: &[(Targets, Option<LineId>)],
    dropped: &BTreeSet<(usize, usize)>,
) -> Walked {
    let nav = g.nav;
    let mut search = Search::default();
    let mut cells = vec![start];
    let mut route = Route { teleport: vec![false], ..Route::default() };
    let mut at = start;
    // Appends `path` (from `at`) and moves there.
    let walk = |path: &plan::Route, cells: &mut Vec<Cell>, route: &mut Route, at: &mut Cell| {
        cells.extend(path.cells.iter().skip(1));
        route.teleport.extend(path.teleport.iter().skip(1));
        if let Some(&end) = path.cells.last() {
            *at = end;
            route.stops.push(nav.centre_of(end));
        }
    };
    let mut begun = Vec::new();
    let Some(last) = stages.last() else { return Walked { route, cells, begun } };
    let mut held: Vec<KeyColour> = Vec::new();
    for (k, stage) in stages.iter().enumerate() {
        begun.push(cells.len() - 1);
        let mut left: Vec<(Goal, Targets, Option<LineId>)> = stage
            .goals
            .iter()
            .enumerate()
            .filter(|&(i, _)| !dropped.contains(&(k, i)))
            .map(|(_, &goal)| {
                let (targets, line) = g.targets(goal, &stage.heights);
                (goal, targets, line)
            })
            .collect();
        while !left.is_empty() {
            // A keyed door's switch waits for its key, taken in this round.
            let ready = |goal: &Goal| !matches!(goal, Goal::Line(_, Some(k)) if !held.contains(k));
            let mut open: Vec<(Targets, Option<LineId>)> =
                left.iter().filter(|(goal, ..)| ready(goal)).map(|(_, t, l)| (t.clone(), *l)).collect();
            if open.is_empty() {
                open = left.iter().map(|(_, t, l)| (t.clone(), *l)).collect();
            }
            let all = union(&open);
            // From where the route stands; failing that (a one-way drop
            // since), over the level as the closure ends it.
            let path = g.search(&mut search, stage, at, &all).or_else(|| g.search(&mut search, last, at, &all));
            let Some(path) = path else {
                if std::env::var_os("SIGHTLINE_CHECK_TRACE").is_some() {
                    let p = nav.centre_of(at);
                    let goals: Vec<Goal> = left.iter().map(|(goal, ..)| *goal).collect();
                    eprintln!("check: route from ({:.0}, {:.0}) cannot reach {goals:?}", p.x, p.y);
                }
                route.missed += left.len();
                break;
            };
            let before = left.len();
            // Every goal the path meets is done, on the way or at its end.
            left.retain(|(goal, targets, line)| {
                let on_cell = path.cells.iter().any(|&c| targets.contains_cell(c));
                let on_line = line.is_some_and(|l| path.cells.windows(2).any(|p| crosses(nav, p[0], p[1], l)));
                if let (Goal::Key(colour, _), true) = (goal, on_cell) {
                    held.push(*colour);
                }
                !(on_cell || on_line)
            });
            walk(&path, &mut cells, &mut route, &mut at);
            if left.len() == before {
                // A search ends only on a goal met; kept from looping all
                // the same.
                if std::env::var_os("SIGHTLINE_CHECK_TRACE").is_some() {
                    let goals: Vec<Goal> = left.iter().map(|(goal, ..)| *goal).collect();
                    eprintln!("check: route met none of {goals:?} at its end");
                }
                route.missed += left.len();
                break;
            }
        }
    }
    if !exit.is_empty() {
        let all = union(exit);
        match g.search(&mut search, last, at, &all) {
            Some(path) => {
                walk(&path, &mut cells, &mut route, &mut at);
                route.exits = true;
            }
            None => {
                if std::env::var_os("SIGHTLINE_CHECK_TRACE").is_some() {
                    let p = nav.centre_of(at);
                    eprintln!("check: route from ({:.0}, {:.0}) cannot reach the exit", p.x, p.y);
                }
                route.missed += 1
            }
        }
    }
    route.points = cells.iter().map(|&c| nav.centre_of(c)).collect();
    Walked { route, cells, begun }
}

/// The autopilot's route through the level, played offline: a game with no
/// monsters, played until the exit or 20 minutes, its path kept.
pub(super) fn bot_route(level: Level, skill: u8) -> Route {
    let options = crate::play::GameOptions { skill, seed: 0, no_monsters: true };
    let label = level.compiled.map.name.clone();
    let Ok(mut game) = crate::sim::game::SimGame::on_level(level, &label, options) else { return Route::default() };
    let mut path = vec![Observe::player(&game).pos];
    // Played as `autoplay` plays: a bot stuck for a while may find its way
    // again (it gives up after a minute), so the route is not cut at the
    // first stop.
    super::run_sim(&mut game, 42_000, |game, _| {
        let p = Observe::player(game).pos;
        if path.last().is_none_or(|q| q.distance(p) >= 8.0) {
            path.push(p);
        }
        true
    });
    // A hop longer than a tick's run is a teleport.
    let teleport = (0..path.len()).map(|i| i > 0 && path[i - 1].distance(path[i]) >= 64.0).collect();
    Route { points: path, teleport, ..Route::default() }
}
