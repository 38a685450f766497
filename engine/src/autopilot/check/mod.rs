//! `sightline check`: what a map maker asks of a map before anyone plays it.
//!
//! Starting from the player start with no keys, the reachable part of the
//! map is grown to a fixed point: keys that can be reached are taken, and
//! switches and walk lines that can be reached are assumed set off, their
//! sectors free to be where they were or where the special takes them
//! (optimistic: any order that helps). Then:
//!
//! - the exit, each key, each secret sector and each item is reachable or not;
//! - a key that cannot be reached, but could if its colour's doors opened
//!   freely, is behind its own door;
//! - a *soft lock* is a place the player can reach but cannot get from to an
//!   exit: the report names the one-way drops (or teleports) into such places.
//!
//! The route drawn is the closure's own (see [`super::route`]): its goals
//! in the order it reached them, joined by the search's paths; the
//! autopilot's played route is drawn on request instead.

use std::collections::{BTreeSet, HashMap};
use std::time::Instant;

use glam::DVec2;

use super::brain;
use super::nav::{Cell, Heights, LineId, NavGrid};
use super::plan::{self, line_of, Mechanisms, Search, Targets};
use super::predict;
use super::press::{self, Presses};
use super::route::{self, Goal, Ground, Route, Stage};
use crate::actors::{ActorFlag, ActorTable, Category};
use crate::level::Level;
use crate::map::special::{Activation, KeyColour};

mod picture;
mod report;

pub use picture::{Drawing, Timing};
pub use report::{KeyReport, Place, Report, SoftLock};

/// The fixed point: the heights assumed, keys held, and cells reached.
struct Closure {
    heights: Heights,
    keys: Vec<KeyColour>,
    reached: Vec<bool>,
    applied: BTreeSet<LineId>,
    /// The mechanisms, with the once-only teleporters used so far.
    mech: Mechanisms,
    /// Sectors a set-off special opens (a door, a ceiling raised): a manual
    /// door among them is no longer shut to those who cannot use it.
    opened: Vec<bool>,
    /// Each round of the fixed point: the level as its flood saw it, and
    /// what it took or set off that changed the map (the route is drawn
    /// through them).
    stages: Vec<Stage>,
}

/// The map's things that matter: keys and pickups.
struct Things {
    keys: Vec<(KeyColour, DVec2)>,
    items: Vec<(String, DVec2)>,
    solid: BTreeSet<Cell>,
}

fn things(level: &Level, nav: &NavGrid, skill: u8) -> Things {
    let map = &level.compiled.map;
    let table = ActorTable::active();
    let mut t = Things { keys: Vec::new(), items: Vec::new(), solid: BTreeSet::new() };
    for thing in map.things.iter().filter(|t| t.in_single_player(skill)) {
        let Some(def) = table.get(&thing.kind) else { continue };
        if let Some(colour) = def.key() {
            t.keys.push((colour, thing.pos));
        } else if def.has(ActorFlag::Special) {
            t.items.push((def.name.clone(), thing.pos));
        } else if def.has(ActorFlag::Solid) && !def.has(ActorFlag::CountKill) && def.category != Category::Monster {
            // Scenery stands in the way for good; a monster (a lost soul
            // counts no kill) moves or dies, and -nomonsters has none.
            let reach = def.radius + super::nav::CLEAR;
            for c in plan::cells_near(nav, thing.pos, reach * 1.42).cells() {
                let d = (nav.centre_of(c) - thing.pos).abs();
                if d.x < reach && d.y < reach {
                    t.solid.insert(c);
                }
            }
        }
    }
    t
}

fn flood(
    search: &mut Search,
    nav: &NavGrid,
    level: &Level,
    mech: &Mechanisms,
    heights: &Heights,
    solid: &BTreeSet<Cell>,
    hurts: &[bool],
    start: Cell,
    opened: &[bool],
) -> Vec<bool> {
    // Nothing given up, spent or wasted: the level as it starts.
    let none = BTreeSet::new();
    let no_lines = BTreeSet::new();
    let shut = shut_now(level, mech, opened);
    let w = plan::World {
        nav,
        map: &level.compiled.map,
        mech,
        heights,
        blocked: solid,
        bad: &none,
        spent: &no_lines,
        wasted: &no_lines,
        hurts,
        shut: &shut,
        wary: &[],
    };
    search.run(&w, start, None);
    let mut reached = vec![false; nav.cells()];
    for &c in &search.reached {
        reached[c as usize] = true;
    }
    reached
}

/// Manual doors shut to those who cannot use them: those shut in the map
/// that no special set off opens.
fn shut_now(level: &Level, mech: &Mechanisms, opened: &[bool]) -> Vec<bool> {
    let mut shut = mech.shut_doors(&level.compiled.map);
    for (s, open) in opened.iter().enumerate() {
        shut[s] &= !open;
    }
    shut
}

/// Where the level's special lines are met from, found once per check: the
/// closure asks it of every trigger in every round, and finding the cells
/// anew each time (a use line's, by sight tests; a walk line's, by a scan of
/// the whole grid) was 55% of freedoom2 MAP28's check (7.0 s of report).
pub(super) struct Meets {
    targets: HashMap<LineId, (Targets, Option<LineId>)>,
    /// Use lines: where a press reaches them from, as Doom's use does
    /// (some cells only once a shut opening on the way is open).
    presses: HashMap<LineId, Presses>,
    /// Per line: the cells with a straight move out of them across it.
    crossers: HashMap<LineId, Vec<Cell>>,
}

impl Meets {
    fn new(nav: &NavGrid, level: &Level, mech: &Mechanisms) -> Meets {
        let lines: Vec<LineId> = mech.triggers.iter().chain(mech.exits.iter().map(|(l, _)| l)).copied().collect();
        let map = &level.compiled.map;
        let used = |l: &LineId| line_of(map, *l).3.is_some_and(|s| s.on == Activation::Use);
        let presses = lines.iter().filter(|l| used(l)).map(|&l| (l, press::press_cells(nav, map, l))).collect();
        let targets = lines.iter().filter(|l| !used(l)).map(|&l| (l, goal_targets(nav, level, l))).collect();
        let mut crossers: HashMap<LineId, Vec<Cell>> = HashMap::new();
        for c in 0..nav.cells() as Cell {
            for d in 0..4 {
                for (l, _) in nav.crossings_of(c, d) {
                    let cells = crossers.entry(l).or_default();
                    if cells.last() != Some(&c) {
                        cells.push(c);
                    }
                }
            }
        }
        Meets { targets, presses, crossers }
    }

    /// The cells and line that meet `line`'s special, with the sectors at
    /// `heights`.
    pub(super) fn of(
        &self,
        nav: &NavGrid,
        level: &Level,
        line: LineId,
        heights: &Heights,
    ) -> (Targets, Option<LineId>) {
        let map = &level.compiled.map;
        if let Some(p) = self.presses.get(&line) {
            return (p.at(map, heights), None);
        }
        self.targets.get(&line).cloned().unwrap_or_else(|| goal_targets(nav, level, line))
    }

    /// Can `line`'s special be set off from the reached cells, with the
    /// sectors at `heights`?
    fn met_line(&self, level: &Level, reached: &[bool], line: LineId, heights: &Heights) -> bool {
        if let Some(p) = self.presses.get(&line) {
            return p.met(&level.compiled.map, heights, reached);
        }
        match self.targets.get(&line) {
            Some((targets, walk)) => self.met(reached, targets, *walk),
            None => false,
        }
    }

    /// Can a goal's targets be met from the reached cells?
    fn met(&self, reached: &[bool], targets: &Targets, line: Option<LineId>) -> bool {
        if targets.cells().any(|c| reached[c as usize]) {
            return true;
        }
        let Some(line) = line else { return false };
        self.crossers.get(&line).is_some_and(|cells| cells.iter().any(|&c| reached[c as usize]))
    }
}

fn goal_targets(nav: &NavGrid, level: &Level, line: LineId) -> (Targets, Option<LineId>) {
    let map = &level.compiled.map;
    match line_of(map, line).3.map(|s| s.on) {
        Some(Activation::Use) => (press::press_cells(nav, map, line).now, None),
        Some(Activation::Walk) => (Targets::default(), Some(line)),
        Some(Activation::Shoot) => (plan::shoot_cells(nav, map, line), None),
        _ => (Targets::default(), None),
    }
}

fn closure(
    nav: &NavGrid,
    level: &Level,
    mech: &Mechanisms,
    meets: &Meets,
    t: &Things,
    start: Cell,
    keys: Vec<KeyColour>,
    hurts: &[bool],
    search: &mut Search,
) -> Closure {
    let none = BTreeSet::new();
    let mut c = Closure {
        heights: plan::plan_heights(level, mech, &keys, &none),
        keys,
        reached: Vec::new(),
        applied: BTreeSet::new(),
        opened: vec![false; level.compiled.map.sectors.len()],
        mech: mech.clone(),
        stages: Vec::new(),
    };
    loop {
        let mut changed_teleports = false;
        c.reached = flood(search, nav, level, &c.mech, &c.heights, &t.solid, hurts, start, &c.opened);
        let mut stage = Stage {
            heights: c.heights.clone(),
            opened: c.opened.clone(),
            mech: c.mech.clone(),
            goals: Vec::new(),
            moved: Vec::new(),
        };
        // Once-only teleporters whose front is reached have been used: the
        // walk over them leads on as well (a door with a teleport line in
        // it, gone through again).
        for (&line, _) in &mech.teleports {
            let once = line_of(&level.compiled.map, line).3.is_some_and(|s| !s.repeat);
            if once && !c.mech.used_teleports.contains(&line) && meets.met(&c.reached, &Targets::default(), Some(line))
            {
                c.mech.used_teleports.insert(line);
                changed_teleports = true;
                stage.goals.push(Goal::Teleport(line));
                stage.moved.push(Vec::new());
            }
        }
        let mut changed = false;
        for &(colour, pos) in &t.keys {
            if !c.keys.contains(&colour)
                && plan::touch_cells(nav, &level.compiled.map, pos).cells().any(|x| c.reached[x as usize])
            {
                c.keys.push(colour);
                changed = true;
                stage.goals.push(Goal::Key(colour, pos));
                stage.moved.push(Vec::new());
                if std::env::var_os("SIGHTLINE_CHECK_TRACE").is_some() {
                    eprintln!("check: key {colour:?} at ({:.0}, {:.0})", pos.x, pos.y);
                }
            }
        }
        if changed {
            // Doors of the new colours open.
            let opened = plan::plan_heights(level, mech, &c.keys, &none);
            for s in 0..c.heights.ceiling.len() {
                c.heights.ceiling[s] = c.heights.ceiling[s].max(opened.ceiling[s]);
            }
        }
        for &line in &mech.triggers {
            if c.applied.contains(&line) {
                continue;
            }
            let (sl, _, _, special) = line_of(&level.compiled.map, line);
            let Some(special) = special else { continue };
            if let crate::map::special::Action::Door { key: Some(k), .. } = special.action {
                if !c.keys.contains(&k) {
                    continue;
                }
            }
            // The level as this round's flood saw it (the route's search
            // of this round meets it there too).
            if !meets.met_line(level, &c.reached, line, &stage.heights) {
                continue;
            }
            c.applied.insert(line);
            changed = true;
            let after = predict::predict(level, &c.heights, sl, special);
            // The sectors it changes.
            let mut moved = Vec::new();
            if std::env::var_os("SIGHTLINE_CHECK_TRACE").is_some() {
                let (_, a, b, _) = line_of(&level.compiled.map, line);
                eprintln!(
                    "check: line {line} ({:.0}, {:.0})-({:.0}, {:.0}) {:?} {:?} tag {}: {}",
                    a.x,
                    a.y,
                    b.x,
                    b.y,
                    special.on,
                    special.action,
                    special.tag,
                    if after.is_some() { "predicted" } else { "unknown" }
                );
            }
            if let crate::map::special::Action::Door {
                kind: crate::map::special::DoorKind::Open | crate::map::special::DoorKind::Raise,
                ..
            }
            | crate::map::special::Action::Ceiling { .. } = special.action
            {
                for s in super::sectors::target_sectors(level, sl, special) {
                    if !c.opened[s] {
                        moved.push(s);
                    }
                    c.opened[s] = true;
                }
            }
            if let Some(after) = after {
                for s in 0..after.floor.len() {
                    let (low, floor, ceiling) = (c.heights.low[s], c.heights.floor[s], c.heights.ceiling[s]);
                    c.heights.low[s] = low.min(after.floor[s]).min(after.low[s]);
                    c.heights.floor[s] = floor.max(after.floor[s]);
                    c.heights.ceiling[s] = ceiling.max(after.ceiling[s]);
                    if (low, floor, ceiling) != (c.heights.low[s], c.heights.floor[s], c.heights.ceiling[s]) {
                        moved.push(s);
                    }
                }
            }
            if !moved.is_empty() {
                let key = match special.action {
                    crate::map::special::Action::Door { key, .. } => key,
                    _ => None,
                };
                stage.goals.push(Goal::Line(line, key));
                moved.sort_unstable();
                moved.dedup();
                stage.moved.push(moved);
            }
        }
        // A lift raised, or beside a floor lowered, has new ends.
        let ends = (c.mech.lift_low.clone(), c.mech.lift_top.clone());
        changed |= c.mech.settle_planned_lifts(level, &mut c.heights);
        // The round's lines did that: each counts those lifts as moved.
        let settled: Vec<usize> =
            (0..ends.0.len()).filter(|&s| (ends.0[s], ends.1[s]) != (c.mech.lift_low[s], c.mech.lift_top[s])).collect();
        for (goal, moved) in stage.goals.iter().zip(&mut stage.moved) {
            if matches!(goal, Goal::Line(..)) && !settled.is_empty() {
                moved.extend(&settled);
                moved.sort_unstable();
                moved.dedup();
            }
        }
        c.stages.push(stage);
        if !changed && !changed_teleports {
            return c;
        }
    }
}

/// Which route the picture draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RouteFrom {
    /// The closure's goals in the order it reached them, joined by the
    /// search's paths: the route the report tells, in a few searches.
    #[default]
    Closure,
    /// The autopilot's, played offline with no monsters for up to 20
    /// minutes of game time: minutes on the biggest maps.
    Autopilot,
}

/// Checks `level` as played at `skill`, the closure's route drawn.
pub fn check(level: Level, skill: u8) -> (Report, Drawing) {
    check_with(level, skill, RouteFrom::Closure)
}

/// Checks `level` as played at `skill`, the route drawn from `from`.
pub fn check_with(level: Level, skill: u8, from: RouteFrom) -> (Report, Drawing) {
    let (report, mut drawing) = analyse(&level, skill, from == RouteFrom::Closure);
    // SIGHTLINE_CHECK_TRACE: the closure's steps, and where the bot's own
    // route first leaves what the closure reached (to find what the model
    // misses when the two disagree).
    let traced = std::env::var_os("SIGHTLINE_CHECK_TRACE").is_some();
    if from == RouteFrom::Autopilot || traced {
        let started = Instant::now();
        let bot = route::bot_route(level.clone(), skill);
        if traced {
            trace_divergence(&level, &drawing, &bot.points, &report);
        }
        if from == RouteFrom::Autopilot {
            drawing.route = bot;
            drawing.timing.route = started.elapsed().as_secs_f64();
        }
    }
    (report, drawing)
}

/// [`check`]'s report alone: what can be reached, without the route.
pub fn report(level: &Level, skill: u8) -> Report {
    analyse(level, skill, false).0
}

/// The report, the picture, and with `route` the closure's route on it.
fn analyse(level: &Level, skill: u8, route: bool) -> (Report, Drawing) {
    let started = Instant::now();
    let map = &level.compiled.map;
    let nav = NavGrid::new(&level.compiled);
    let mut mech = Mechanisms::of(level);
    mech.locate_doors(&nav, map, None);
    let t = things(level, &nav, skill);
    let hurts: Vec<bool> = map.sectors.iter().map(|s| s.special.damage.is_some()).collect();
    let mut search = Search::default();
    let start_pos = map.player_start().pos;
    let standable_cells = (0..nav.cells() as Cell).filter(|&c| nav.standable(c)).count();
    let Some(start) = nav.standable_near(start_pos, 3) else {
        let report = Report {
            map: map.name.clone(),
            exit_reachable: false,
            has_exit: !mech.exits.is_empty(),
            exit_lines: mech.exits.len(),
            exits: Vec::new(),
            keys: Vec::new(),
            secrets: Vec::new(),
            items: Vec::new(),
            soft_locks: Vec::new(),
            unforeseen: Vec::new(),
            triggers_used: 0,
            reachable_cells: 0,
            standable_cells,
        };
        let mut drawing = Drawing::new(level, nav, Vec::new(), Vec::new());
        drawing.timing.analyse = started.elapsed().as_secs_f64();
        return (report, drawing);
    };
    let meets = Meets::new(&nav, level, &mech);
    let c = closure(&nav, level, &mech, &meets, &t, start, Vec::new(), &hurts, &mut search);
    let shut = shut_now(level, &mech, &c.opened);
    let why = super::obstacle::Reach {
        nav: &nav,
        level,
        mech: &c.mech,
        heights: &c.heights,
        keys: &c.keys,
        reached: &c.reached,
        shut: &shut,
        solid: &t.solid,
        applied: &c.applied,
    };
    let place = |what: String, p: DVec2, reachable: bool| Place { what, x: p.x, y: p.y, reachable, obstacle: None };
    let near_reached = |reached: &[bool], p: DVec2| {
        plan::touch_cells(&nav, &level.compiled.map, p).cells().any(|x| reached[x as usize])
    };

    let mut exits = Vec::new();
    // Per exit, the ways to meet it.
    let mut exit_targets: Vec<Vec<(Targets, Option<LineId>)>> = Vec::new();
    for &(line, secret) in &mech.exits {
        let (targets, walk) = meets.of(&nav, level, line, &c.heights);
        let (_, a, b, _) = line_of(map, line);
        let ok = meets.met(&c.reached, &targets, walk);
        let mut exit = place(if secret { "secret exit".into() } else { "exit".into() }, (a + b) / 2.0, ok);
        if !ok {
            exit.obstacle = Some(why.first_obstacle(&targets, walk));
        }
        exits.push(exit);
        exit_targets.push(vec![(targets, walk)]);
    }
    // The boss brain's death ends the level too: crushed under a crusher
    // the player starts, or hurt by a rocket fired from a lift the player
    // reaches (whether a launcher can be had is not asked).
    let table = ActorTable::active();
    let rocket = brain::table_rocket(table);
    for (i, thing) in map.things.iter().enumerate().filter(|(_, t)| t.in_single_player(skill)) {
        let Some(def) = table.get(&thing.kind).filter(|d| d.category == Category::BossBrain) else { continue };
        let body = brain::body(&level.compiled, def, thing.pos, i);
        let (crushers, shot) = brain::ways(&nav, level, &mech, rocket.as_ref(), &body, &c.heights.floor);
        let mut ways: Vec<(Targets, Option<LineId>)> =
            crushers.iter().map(|&l| meets.of(&nav, level, l, &c.heights)).collect();
        let crushed = crushers.iter().zip(&ways).find(|(_, (t, w))| meets.met(&c.reached, t, *w)).map(|(&l, _)| l);
        let hit = shot.cells().any(|x| c.reached[x as usize]);
        // How it dies: the way met, else the first way there is (a
        // crusher before rockets).
        let how = match crushed.or(crushers.first().copied()) {
            Some(l) if crushed.is_some() || !hit => format!("; {}", brain::crushed_by(map, l)),
            _ if !shot.is_empty() => "; by a rocket from a lift".into(),
            _ => String::new(),
        };
        let ok = crushed.is_some() || hit;
        let mut exit = place(format!("boss brain (its death ends the map{how})"), thing.pos, ok);
        if !ok {
            exit.obstacle = Some(match ways.first() {
                Some((targets, walk)) => why.first_obstacle(targets, *walk),
                None if !shot.is_empty() => why.first_obstacle(&shot, None),
                None => "no crusher over it, and no lift near it from which a rocket hurts it".into(),
            });
        }
        if !shot.is_empty() {
            ways.push((shot, None));
        }
        exits.push(exit);
        exit_targets.push(ways);
    }
    let exit_reachable = exits.iter().any(|e| e.reachable);
    let has_exit = !exits.is_empty();
    let mut keys = Vec::new();
    for &(colour, pos) in &t.keys {
        let reachable = near_reached(&c.reached, pos);
        let behind_own_door = !reachable && {
            let with = closure(&nav, level, &mech, &meets, &t, start, vec![colour], &hurts, &mut search);
            near_reached(&with.reached, pos)
        };
        let obstacle =
            (!reachable).then(|| why.first_obstacle(&plan::touch_cells(&nav, &level.compiled.map, pos), None));
        keys.push(KeyReport {
            colour: colour.name().to_string(),
            x: pos.x,
            y: pos.y,
            reachable,
            behind_own_door,
            obstacle,
        });
    }
    let mut secrets = Vec::new();
    for (s, sector) in map.sectors.iter().enumerate() {
        if !sector.special.secret {
            continue;
        }
        let cells: Vec<Cell> = (0..nav.cells() as Cell).filter(|&x| nav.centre[x as usize] == s as u32).collect();
        let reachable = cells.iter().any(|&x| c.reached[x as usize])
            || (0..nav.cells() as Cell).any(|x| c.reached[x as usize] && nav.touched(x).contains(&(s as u32)));
        let centre = (level.sector_boxes[s].min + level.sector_boxes[s].max) / 2.0;
        secrets.push(place(format!("secret sector {s}"), centre, reachable));
    }
    let items = t.items.iter().map(|(name, pos)| place(name.clone(), *pos, near_reached(&c.reached, *pos))).collect();

    // Where the exit can be reached from: a backward flood over the moves
    // the forward one found.
    let mut finish = vec![false; nav.cells()];
    let mut soft_locks = Vec::new();
    if exit_reachable {
        let edges = forward_edges(&nav, level, &c.mech, &c.heights, &t.solid, &c.reached);
        let mut into: Vec<Vec<Cell>> = vec![Vec::new(); nav.cells()];
        for &(a, b, _) in &edges {
            into[b as usize].push(a);
        }
        let mut stack: Vec<Cell> = Vec::new();
        for (targets, walk) in exit_targets.iter().flatten() {
            for x in targets.cells() {
                if c.reached[x as usize] && !finish[x as usize] {
                    finish[x as usize] = true;
                    stack.push(x);
                }
            }
            if let Some(line) = walk {
                for (a, _, crossed) in &edges {
                    let a = *a;
                    if crossed.contains(line) && !finish[a as usize] {
                        finish[a as usize] = true;
                        stack.push(a);
                    }
                }
            }
        }
        while let Some(b) = stack.pop() {
            for &a in &into[b as usize] {
                if !finish[a as usize] {
                    finish[a as usize] = true;
                    stack.push(a);
                }
            }
        }
        let mut seen = BTreeSet::new();
        for &(a, b, ref crossed) in &edges {
            if finish[a as usize] && !finish[b as usize] {
                // From the highest floor under the body before the move
                // (the ledge), into the sector under it after.
                let sa = nav
                    .touched(a)
                    .iter()
                    .map(|&s| s as usize)
                    .max_by(|&x, &y| c.heights.floor[x].total_cmp(&c.heights.floor[y]))
                    .unwrap_or(0);
                let sb = nav.centre[b as usize] as usize;
                if seen.insert((sa, sb)) {
                    let adjacent = nav.direction(a, b).is_some();
                    let p = nav.centre_of(b);
                    // A move to a cell not beside it crosses a teleport
                    // line, or is a running jump (which crosses none).
                    let how = match (adjacent, crossed.is_empty()) {
                        (true, _) => "a one-way drop",
                        (false, true) => "a running jump",
                        (false, false) => "a teleport",
                    };
                    soft_locks.push(SoftLock { from_sector: sa, to_sector: sb, x: p.x, y: p.y, how: how.into() });
                }
            }
        }
    }
    let reachable_cells = c.reached.iter().filter(|&&r| r).count();
    let unforeseen = c
        .applied
        .iter()
        .filter_map(|&line| {
            let (_, a, b, special) = line_of(map, line);
            let why = predict::unforeseeable(level, special?)?;
            let m = (a + b) / 2.0;
            Some(format!("line {line} at ({:.0}, {:.0}): {why}", m.x, m.y))
        })
        .collect();
    let report = Report {
        map: map.name.clone(),
        exit_reachable,
        has_exit,
        exit_lines: mech.exits.len(),
        exits,
        keys,
        secrets,
        items,
        soft_locks,
        unforeseen,
        triggers_used: c.applied.len(),
        reachable_cells,
        standable_cells,
    };
    let analysed = Instant::now();
    let route = if route {
        // To the exits the report calls reachable, a secret one only if no
        // other is.
        let reachable: Vec<usize> = (0..report.exits.len()).filter(|&i| report.exits[i].reachable).collect();
        let normal: Vec<usize> = reachable.iter().copied().filter(|&i| report.exits[i].what != "secret exit").collect();
        let ends = if normal.is_empty() { reachable } else { normal };
        let exit: Vec<(Targets, Option<LineId>)> = ends.iter().flat_map(|&i| exit_targets[i].clone()).collect();
        let ground = Ground { nav: &nav, level, meets: &meets, solid: &t.solid, hurts: &hurts };
        route::closure_route(&ground, &c.stages, start, &exit)
    } else {
        Route::default()
    };
    let mut drawing = Drawing::new(level, nav, c.reached, finish);
    drawing.route = route;
    drawing.timing = Timing { analyse: (analysed - started).as_secs_f64(), route: analysed.elapsed().as_secs_f64() };
    (report, drawing)
}

/// Every move of the forward search from the reached cells to reached
/// cells: from, to, and the walk lines it crosses. A move the search did
/// not make (onto a lift it holds up, say) is left out: a cell the search
/// never reached is no place a player could be stranded.
fn forward_edges(
    nav: &NavGrid,
    level: &Level,
    mech: &Mechanisms,
    heights: &Heights,
    solid: &BTreeSet<Cell>,
    reached: &[bool],
) -> Vec<(Cell, Cell, Vec<LineId>)> {
    let map = &level.compiled.map;
    let mut edges = Vec::new();
    for a in 0..nav.cells() as Cell {
        if !reached[a as usize] {
            continue;
        }
        let from = nav.span(a, heights);
        for d in 0..8 {
            if !nav.open(a, d) {
                continue;
            }
            let Some(b) = nav.neighbour(a, d) else { continue };
            let to = nav.span(b, heights);
            if from.leaps_off(&to) {
                // A running jump across the gap, as the search takes one.
                if let Some(leap) = plan::leap_from(nav, mech, heights, a, d)
                    .filter(|l| !solid.contains(&l.to) && reached[l.to as usize])
                {
                    edges.push((a, leap.to, Vec::new()));
                }
            }
            if solid.contains(&b) || !nav.climbable(a, d, from, to, heights) {
                continue;
            }
            let mut to = b;
            let mut crossed = Vec::new();
            for (line, front) in nav.crossings_of(a, d) {
                crossed.push(line);
                let walk = line_of(map, line).3.is_some_and(|s| s.on == Activation::Walk);
                if let (true, true, Some(&dest)) = (walk, front, mech.teleports.get(&line)) {
                    if let Some(t) = nav.standable_near(dest, 2) {
                        to = t;
                    }
                }
            }
            if to != b && reached[b as usize] && crossed.iter().any(|l| mech.used_teleports.contains(l)) {
                edges.push((a, b, crossed.clone()));
            }
            if reached[to as usize] {
                edges.push((a, to, crossed));
            }
        }
    }
    edges
}

/// Where the autopilot's route first leaves what the closure reached, with
/// the heights under the last reached and first unreached points.
fn trace_divergence(level: &Level, d: &Drawing, route: &[DVec2], report: &Report) {
    let nav = &d.nav;
    let map = &level.compiled.map;
    let unreached = report
        .keys
        .iter()
        .filter(|k| !k.reachable)
        .map(|k| (format!("{} key", k.colour), DVec2::new(k.x, k.y)))
        .chain(report.exits.iter().filter(|e| !e.reachable).map(|e| (e.what.clone(), DVec2::new(e.x, e.y))));
    for (what, p) in unreached {
        let Some(q) = route.iter().copied().min_by(|a, b| a.distance(p).total_cmp(&b.distance(p))) else { continue };
        let c = nav.cell_at(q);
        eprintln!(
            "check: {what} at ({:.0}, {:.0}): the route comes within {:.0} at ({:.0}, {:.0}), cell reached {:?}, touching {:?}",
            p.x,
            p.y,
            q.distance(p),
            q.x,
            q.y,
            c.map(|c| d.reached[c as usize]),
            c.map(|c| nav.touched(c).to_vec())
        );
    }
    let near = |c: Cell| (0..8).filter_map(|k| nav.neighbour(c, k)).chain([c]).any(|n| d.reached[n as usize]);
    let mut last = None;
    for (i, &p) in route.iter().enumerate() {
        let Some(c) = nav.cell_at(p) else { continue };
        if near(c) {
            last = Some((p, c));
            continue;
        }
        // The way the bot came (a leap, a ride, a press from below).
        let came: Vec<String> =
            route[i.saturating_sub(16)..i].iter().map(|q| format!("({:.0}, {:.0})", q.x, q.y)).collect();
        eprintln!("check: the bot's route before it leaves: {}", came.join(" "));
        let show = |c: Cell| {
            nav.touched(c)
                .iter()
                .map(|&s| {
                    let x = &map.sectors[s as usize];
                    format!("{s}(f {} c {} tag {})", x.floor, x.ceiling, x.tag)
                })
                .collect::<Vec<_>>()
                .join(" ")
        };
        if let Some((q, lc)) = last {
            eprintln!("check: route leaves the reached cells at ({:.0}, {:.0}) [{}]", q.x, q.y, show(lc));
        }
        eprintln!("check: first unreached route point ({:.0}, {:.0}) [{}]", p.x, p.y, show(c));
        return;
    }
    eprintln!("check: the whole route is in the reached cells");
}
