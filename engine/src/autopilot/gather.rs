//! Gathering and exploring, for play whose aim is not the exit (ViZDoom's
//! scenarios: health_gathering's medikits, my_way_home's armour,
//! deadly_corridor's vest at the corridor's end): items the body has seen
//! and would gain from are fetched, the nearest by the route first; with
//! none known, the body goes to the nearest sector it has not stood in,
//! looking about on the way. Everything here is off by default
//! ([`Options`]), so a level played for its exit is played as before.

use std::collections::BTreeSet;

use glam::DVec2;

use super::nav::Cell;
use super::plan::{self, Goal, Purpose, Targets};
use super::sight::{self, Body};
use super::{gives, Active, Assumed, Autopilot, Observe};
use crate::actors::{ActorDef, Give};

/// What the autopilot plays for besides the exit. All off by default: the
/// Freedoom figures (`tests/autopilot.rs`) are the default's.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// Fetch, before anything else, health the body can take (below its
    /// pickup's maximum) and armour better than it wears, once seen.
    pub gather: bool,
    /// With nothing else to do, go to the nearest sector not yet stood in
    /// (and so come to see what there is to gather).
    pub explore: bool,
    /// Lead a moving enemy with a missile: aim where it will be when the
    /// missile gets there, from the way it moved over its last ticks in
    /// sight (a walking monster has no momentum to read: it steps).
    pub lead: bool,
}

impl Options {
    /// For ViZDoom's scenarios, which are about fights, pickups and
    /// finding things rather than exits: everything on.
    pub const SCENARIO: Options = Options { gather: true, explore: true, lead: true };
}

/// Ticks of a target's track kept to estimate its velocity: a walking
/// monster steps every few ticks (a cacodemon's chase states last 3), so
/// an average over several steps.
const TRACK_TICKS: u64 = 24;
/// The least span of a track whose pace is trusted for a lead.
const MIN_TRACK_TICKS: u64 = 6;
/// Ticks between looks about for pickups.
const LOOK_EVERY: u64 = 4;
/// Two steps whose ways' cosine is below this (30 degrees apart) are a
/// turn.
const TURNED: f64 = 0.866;

/// What the body has found out by looking about, for [`Options`].
#[derive(Clone, Debug, Default)]
pub(super) struct Finds {
    /// Pickups (health, armour) seen, by index, whether wanted then or not.
    seen: BTreeSet<u32>,
    /// Per sector: the body's centre has been in it.
    visited: Vec<bool>,
    /// The enemy tracked for leading, and where it was at each tick.
    track: Option<(usize, Vec<(u64, DVec2)>)>,
}

/// Does `def` give anything gathering is about (health or armour)?
fn gatherable(def: &ActorDef) -> bool {
    gives(def).any(|g| matches!(g, Give::Health { amount, .. } | Give::Armor { points: amount, .. } if *amount > 0))
}

/// Would the body gain from picking up `def` now?
fn wanted(def: &ActorDef, health: i32, armor: i32) -> bool {
    gives(def).any(|g| match *g {
        Give::Health { amount, max } => amount > 0 && health < max,
        Give::Armor { points, .. } => points > armor,
        _ => false,
    })
}

impl Autopilot {
    /// Looks about: the pickups now in sight join those seen, and the
    /// sector the body is in counts as visited. Asks for a new goal when
    /// something worth fetching comes into sight while the body has
    /// nothing better to do (exploring, or standing with no goal), or
    /// when the sector an exploration headed for has been reached.
    pub(super) fn look_about(&mut self, game: &dyn Observe) {
        if !(self.options.gather || self.options.explore) {
            return;
        }
        let player = game.player();
        let sectors = game.level().compiled.map.sectors.len();
        self.finds.visited.resize(sectors, false);
        let arrived = player.sector < sectors && !self.finds.visited[player.sector];
        if let Some(v) = self.finds.visited.get_mut(player.sector) {
            *v = true;
        }
        let (seen, table) = (game.seen(), game.table());
        let compiled = &game.level().compiled;
        let looker = Body { pos: player.pos, z: player.z, height: 56.0, radius: 16.0, index: usize::MAX };
        let mut new_want = false;
        // Looking about every few ticks is enough to find things: a
        // body at a run covers half a cell meanwhile (health_gathering
        // _supreme's 80-odd items cost 15 µs a tick in sight checks
        // when every tick looked).
        let looking = game.ticks().is_multiple_of(LOOK_EVERY);
        for (i, a) in seen.iter().enumerate().filter(|_| looking) {
            let def = &table.actors[a.kind];
            if a.removed || self.finds.seen.contains(&(i as u32)) || !gatherable(def) {
                continue;
            }
            let target = Body { pos: a.pos, z: a.z, height: def.height.max(1.0), radius: def.radius, index: i };
            if sight::sight(compiled, &mut self.sight, &looker, &target) {
                self.finds.seen.insert(i as u32);
                new_want |= self.options.gather && wanted(def, player.health, player.armor);
            }
        }
        let idle = self.active.as_ref().is_none_or(|a| a.purpose == Purpose::Explore);
        let explored = arrived && self.active.as_ref().is_some_and(|a| a.purpose == Purpose::Explore);
        if (new_want && idle) || explored {
            self.rechoose = true;
            self.next_replan = self.next_replan.min(game.ticks());
        }
    }

    /// Ticks until a bot with nothing to do looks for a goal again: a
    /// second, or five when it looks about ([`Options`]), since a pickup
    /// coming into sight then asks at once ([`Self::look_about`]). Each
    /// look floods the grid (3 ms on defend_the_center's 7,500 cells);
    /// every second, that was 140 µs a tic on average.
    pub(super) fn look_again_in(&self) -> u64 {
        if self.options.gather || self.options.explore {
            35 * 5
        } else {
            35
        }
    }

    /// The nearest (by route) pickup seen that the body would gain from.
    pub(super) fn gather_goal(&mut self, game: &dyn Observe, assumed: &Assumed) -> Option<Active> {
        if !self.options.gather {
            return None;
        }
        let player = game.player();
        let (seen, table) = (game.seen(), game.table());
        let map = &game.level().compiled.map;
        let mut targets = Targets::default();
        let mut things = Vec::new();
        for &i in &self.finds.seen {
            let Some(a) = seen.get(i as usize) else { continue };
            let goal = Goal::Touch(a.pos, i);
            if a.removed
                || !wanted(&table.actors[a.kind], player.health, player.armor)
                || self.unreachable.contains(&i)
                || self.failed(&goal)
            {
                continue;
            }
            targets.add(self.touch_targets(map, a.pos, i));
            things.push((i, a.pos));
        }
        if things.is_empty() {
            return None;
        }
        let start = assumed.start(&self.nav, game)?;
        let world = assumed.world(&self.nav, &self.mech, (&self.hurts, &self.wary), map);
        let route = self.search.run(&world, start, Some(&targets))?;
        let end = self.nav.centre_of(*route.cells.last().unwrap_or(&start));
        let &(i, pos) = things.iter().min_by(|a, b| a.1.distance(end).total_cmp(&b.1.distance(end)))?;
        Some(Active::new(Goal::Touch(pos, i), Purpose::Gather, route, game.ticks()))
    }

    /// The way to the nearest sector the body has not stood in (by the
    /// route, the sector under a reachable cell's centre). When every
    /// sector within reach has been visited, they are all forgotten but
    /// the one the body is in and the rounds start again: what was missed
    /// (out of sight behind a pillar) may be seen the next time round.
    pub(super) fn explore_goal(&mut self, game: &dyn Observe) -> Option<Active> {
        if !self.options.explore {
            return None;
        }
        let assumed = self.assume(game);
        let start = assumed.start(&self.nav, game)?;
        let map = &game.level().compiled.map;
        let world = assumed.world(&self.nav, &self.mech, (&self.hurts, &self.wary), map);
        self.search.run(&world, start, None);
        let here = game.player().sector;
        let visited = &mut self.finds.visited;
        visited.resize(map.sectors.len(), false);
        let nav = &self.nav;
        let fresh = |c: &Cell, visited: &[bool]| {
            let s = nav.centre[*c as usize] as usize;
            s < visited.len() && !visited[s]
        };
        let mut target = self.search.reached.iter().copied().find(|c| fresh(c, visited));
        if target.is_none() {
            visited.iter_mut().enumerate().for_each(|(s, v)| *v = s == here);
            target = self.search.reached.iter().copied().find(|c| fresh(c, visited));
        }
        let target = self.nav.centre_of(target?);
        let route = self.search.run(&world, start, Some(&plan::cells_near(&self.nav, target, 1.0)))?;
        Some(Active::new(Goal::Touch(target, u32::MAX), Purpose::Explore, route, game.ticks()))
    }

    /// Where to aim at the enemy `index` (a body of `def`'s size, now at
    /// `pos`, feet at `z`) so that a missile fired now meets it: the
    /// trigger's ticks before the launch, then the flight, at the velocity
    /// its track shows. `pos` itself without [`Options::lead`] or with a
    /// weapon other than the launcher. The second value says whether the
    /// guess can be trusted: a track of a few steps, and a way from the
    /// enemy to the point clear of walls (a patrol turns back at its end,
    /// so a point past a wall is not where it will be: predict_position's
    /// cacodemon walks between two points near the walls).
    pub(super) fn lead(&mut self, game: &dyn Observe, body: Body, weapon: u8) -> (DVec2, bool) {
        let (index, pos) = (body.index, body.pos);
        if !self.options.lead {
            return (pos, true);
        }
        let now = game.ticks();
        if self.finds.track.as_ref().is_none_or(|(i, _)| *i != index) {
            self.finds.track = Some((index, Vec::new()));
        }
        let Some((_, track)) = self.finds.track.as_mut() else { return (pos, true) };
        track.retain(|&(t, _)| t + TRACK_TICKS >= now && t < now);
        // A walking monster steps every few ticks: only the ticks it moved
        // on (and the first) mark its pace. It walks one of eight ways
        // (Doom's `movedir`): a step another way starts the track afresh.
        if track.last().is_none_or(|&(_, p)| p != pos) {
            if let [.., (_, a), (t, b)] = track[..] {
                if (b - a).normalize_or_zero().dot((pos - b).normalize_or_zero()) < TURNED {
                    track.clear();
                    track.push((t, b));
                }
            }
            track.push((now, pos));
        }
        let rocket = super::brain::launcher(game).filter(|_| weapon == super::brain::LAUNCHER_SLOT);
        let Some(rocket) = rocket.filter(|r| r.speed > 0.0) else { return (pos, true) };
        let (Some(&(t0, p0)), Some(&(t1, p1))) = (track.first(), track.last()) else { return (pos, false) };
        let still = now - t1 > TRACK_TICKS / 3;
        let vel = if still || t1 == t0 { DVec2::ZERO } else { (p1 - p0) / (t1 - t0) as f64 };
        let known = still || t1 - t0 >= MIN_TRACK_TICKS;
        let me = game.player().pos;
        // Twice round: the flight to where it will be, then to there.
        let mut at = pos;
        for _ in 0..2 {
            let t = f64::from(rocket.lead) + at.distance(me) / rocket.speed;
            at = pos + vel * t;
        }
        let there = Body { pos: at, ..body };
        let open = at == pos || sight::sight(&game.level().compiled, &mut self.sight, &body, &there);
        (at, known && open)
    }
}
