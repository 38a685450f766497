//! Choosing the bot's next goal and the route the search finds to it
//! ([`Autopilot::choose`]): off a crushing or hurting floor first, then
//! supplies when short with monsters about, the exit, the boss brain, keys,
//! and the switches and walk lines that open the most; a lift to be called
//! first is called first.

use std::collections::BTreeSet;

use glam::DVec2;

use super::nav::{Cell, Heights, LineId};
use super::observe::Observe;
use super::plan::{self, line_of, Goal, Purpose, Route, Targets};
use super::predict;
use super::{describe, live_heights, sectors, Active, Assumed, Autopilot, MAX_LIFT_MISSES, MAX_RETAKES};
use crate::map::special::{Action, Activation, DoorKind, KeyColour};
use crate::play::player::MAX_STEP;

/// Below this much room a descending ceiling is one to keep out from under:
/// the body's height and a second or two of a crusher's travel.
const CRUSH_ROOM: f64 = 56.0 + 64.0;

impl Autopilot {
    /// Chooses the next goal and the route to it.
    pub(super) fn choose(&mut self, game: &dyn Observe) -> Option<Active> {
        let started = std::time::Instant::now();
        // A goal whose only way is by a lift that would have to be called
        // while another called lately is coming down is passed over: the
        // search is made again with that lift held where it is.
        let (mut chosen, mut calling) = (None, None);
        for _ in 0..3 {
            let Some(a) = self.choose_inner(game).map(|a| self.protection_first(game, a)) else { break };
            match self.call_lift_first(game, a) {
                Ok(a) => {
                    chosen = Some(a);
                    break;
                }
                Err((lift, call)) => {
                    self.keep_up.push(lift);
                    calling.get_or_insert((lift, call));
                }
            }
        }
        self.keep_up.clear();
        // With no other goal, the lift is called after all.
        let chosen = chosen.or_else(|| {
            let (lift, call) = calling?;
            self.log.push(format!("tick {}: lift {lift} is up on the way: calling it first", game.ticks()));
            Some(*call)
        });
        let chosen = chosen.or_else(|| self.explore_goal(game)).or_else(|| self.off_danger(game));
        let t = started.elapsed().as_secs_f64();
        self.figures.plans += 1;
        self.figures.plan_seconds += t;
        self.figures.worst_plan_seconds = self.figures.worst_plan_seconds.max(t);
        chosen
    }

    /// A route that boards a lift from below while the lift is up, with no
    /// call of it on the way: call it first, from a switch reachable now
    /// (one up on a ledge beside it, say) rather than at its foot, where
    /// the switch may be out of reach (and the foot a nukage pit). A call
    /// made in the last 20 seconds stands while the lift has not been down
    /// and back up since; a lift that came back up before the body got on
    /// was missed and is called again, [`MAX_LIFT_MISSES`] times at most,
    /// after which the route's own unblocking takes over. `Err` (the lift,
    /// and the way to call it): another goal should be looked for first,
    /// another lift called lately being on its way down.
    fn call_lift_first(&mut self, game: &dyn Observe, active: Active) -> Result<Active, (usize, Box<Active>)> {
        if active.purpose == Purpose::Lift {
            return Ok(active);
        }
        let map = &game.level().compiled.map;
        let live = live_heights(map);
        let now = game.ticks();
        let cells = &active.route.cells;
        let player = game.player();
        for i in 1..cells.len() {
            if active.route.teleport[i] {
                continue;
            }
            let mut from = self.nav.span(cells[i - 1], &live);
            if i == 1 && player.on_ground() && self.mech.lifts.get(player.sector).is_some_and(|l| l.is_empty()) {
                // The body stands where it stands: a start cell whose
                // circle overlaps the lift's top (Doom keeps the body
                // itself 16 units off the lift's raised edge, in the
                // corner below it) does not put the body up there. (On a
                // lift itself, it rides where the lift takes it.)
                from.high = from.high.min(player.z);
            }
            let up = self.nav.touched(cells[i]).iter().map(|&s| s as usize).find(|&s| {
                !self.mech.lifts[s].is_empty() && live.floor[s] > from.high + MAX_STEP && !self.mech.perpetual[s]
            });
            let Some(lift) = up else { continue };
            // A once-only switch used already calls nothing.
            let lines: Vec<LineId> =
                self.mech.lifts[lift].iter().copied().filter(|&l| !Self::used_up(game, l)).collect();
            if lines.is_empty() {
                continue;
            }
            let on_the_way = lines.iter().any(|&l| {
                let t = plan::targets_of(&self.nav, map, &Goal::Use(l));
                cells[..i].iter().any(|&c| t.contains_cell(c))
                    || cells[..i].windows(2).any(|w| {
                        self.nav.direction(w[0], w[1]).is_some_and(|d| self.nav.crossings_of(w[0], d).any(|x| x.0 == l))
                    })
            });
            // A call made lately still stands, unless the lift has been
            // down and come back up since (missed: call it again, a few
            // times at most).
            let called = lines.iter().filter_map(|l| self.tried.get(l)).max().copied();
            let missed = called.is_some_and(|t| self.floor_moved[lift] > t && self.floor_moved[lift] + 1 < now);
            let misses = self.lift_misses.get(&lift).copied().unwrap_or(0);
            if on_the_way || called.is_some_and(|t| now < t + 35 * 20 && (!missed || misses >= MAX_LIFT_MISSES)) {
                return Ok(active);
            }
            if missed {
                *self.lift_misses.entry(lift).or_insert(0) += 1;
            }
            // Another lift called lately, not yet stood on, is down or on
            // its way, and the goal has no way without this one: another
            // goal is looked for first (one the lift coming down serves).
            // Two pads each lowered by a switch at the other's far end
            // (MAP21's) would otherwise have the body call one, then the
            // other, for ever.
            let called_other = (0..self.mech.lifts.len()).any(|other| {
                other != lift
                    && live.floor[other] < self.mech.lift_top[other]
                    && self.mech.lifts[other]
                        .iter()
                        .filter_map(|l| self.tried.get(l))
                        .any(|&t| now < t + 35 * 20 && self.floor_moved[other] + 1 >= t && self.stood_on[other] < t)
            });
            // The lift held where it stands (up), as it is until called.
            let up = |h: &mut Heights| (h.low[lift], h.floor[lift]) = (live.floor[lift], live.floor[lift]);
            let instead = called_other && self.route_with(game, &active.goal, up).is_none();
            for line in lines {
                let goal = match line_of(map, line).3.map(|s| s.on) {
                    Some(Activation::Use) => Goal::Use(line),
                    Some(Activation::Walk) => Goal::Cross(line),
                    _ => continue,
                };
                // The way to its switch cannot cross it.
                let Some(route) = self.route_with(game, &goal, up) else { continue };
                // Not pressed from by the lift itself (the way there may
                // run beside it: MAP20's switch is in a slot over the lava
                // the lift stands in).
                let pressed_from = route.cells.last().map_or(&[][..], |&c| self.nav.touched(c));
                if !pressed_from.contains(&(lift as u32)) {
                    let calling = Active::new(goal, Purpose::Lift, route, now);
                    if instead {
                        return Err((lift, Box::new(calling)));
                    }
                    self.log.push(format!("tick {now}: lift {lift} is up on the way: calling it first"));
                    return Ok(calling);
                }
            }
            return Ok(active);
        }
        Ok(active)
    }

    /// Does a ceiling come down on `cell`, or a crushing floor go up under
    /// it, with less than [`CRUSH_ROOM`] left?
    pub(super) fn crushing(&self, live: &Heights, cell: Cell) -> bool {
        self.nav.touched(cell).iter().any(|&s| {
            let s = s as usize;
            let room = live.ceiling[s] - live.floor[s];
            let closing = live.ceiling[s] < self.last.ceiling[s]
                || (self.mech.crushers[s] && room < self.last.ceiling[s] - self.last.floor[s]);
            closing && room < CRUSH_ROOM
        })
    }

    /// Is the body's sector one whose floor hurts?
    pub(super) fn on_hurting_floor(&self, game: &dyn Observe) -> bool {
        self.hurts.get(game.player().sector).copied().unwrap_or(false)
    }

    /// With nothing to do while standing where the floor hurts or a crusher
    /// closes: the way to the nearest floor that does not hurt, out from
    /// under every crusher.
    fn off_danger(&mut self, game: &dyn Observe) -> Option<Active> {
        let player = game.player();
        let live = live_heights(&game.level().compiled.map);
        let crushed = self.nav.cell_at(player.pos).is_some_and(|c| self.crushing(&live, c));
        if !self.on_hurting_floor(game) && !crushed {
            return None;
        }
        let assumed = self.assume(game);
        let start = assumed.start(&self.nav, game)?;
        let world = assumed.world(&self.nav, &self.mech, (&self.hurts, &self.wary), &game.level().compiled.map);
        self.search.run(&world, start, None);
        let safe = self.search.reached.iter().copied().find(|&c| {
            self.nav.touched(c).iter().all(|&s| !self.hurts[s as usize] && !self.mech.crushers[s as usize])
                && !self.nav.span(c, &assumed.heights).ledge()
        })?;
        let mut targets = Targets::default();
        targets.add(plan::cells_near(&self.nav, self.nav.centre_of(safe), 1.0));
        let route = self.search.run(&world, start, Some(&targets))?;
        Some(Active::new(Goal::Touch(self.nav.centre_of(safe), u32::MAX), Purpose::Safety, route, game.ticks()))
    }

    fn choose_inner(&mut self, game: &dyn Observe) -> Option<Active> {
        let level = game.level();
        let map = &level.compiled.map;
        let keys = Self::keys_held(game);
        let assumed = self.assume(game);
        if let Some(a) = self.gather_goal(game, &assumed) {
            return Some(a);
        }
        let Assumed { heights, spent, .. } = &assumed;
        let start = assumed.start(&self.nav, game)?;
        let world = assumed.world(&self.nav, &self.mech, (&self.hurts, &self.wary), map);
        let nav = &self.nav;
        let active = |goal, purpose, route| Active::new(goal, purpose, route, game.ticks());

        // Supplies first when they are short and monsters are about.
        for tier in self.supplies(game) {
            let Some(route) = self.search.run(&world, start, Some(&tier.targets)) else { continue };
            if route.cost >= tier.max_cost {
                continue;
            }
            let end = nav.centre_of(*route.cells.last().unwrap_or(&start));
            let nearest = tier.things.iter().min_by(|a, b| a.1.distance(end).total_cmp(&b.1.distance(end)));
            if let Some(&(i, pos)) = nearest {
                return Some(active(Goal::Touch(pos, i), Purpose::Supplies, route));
            }
        }
        // The exit: the normal one if it can be reached, else the secret one.
        for secret in [false, true] {
            let mut best: Option<(Route, Goal)> = None;
            for &(line, is_secret) in &self.mech.exits {
                if is_secret != secret {
                    continue;
                }
                let (_, _, _, special) = line_of(map, line);
                let goal = match special.map(|s| s.on) {
                    Some(Activation::Use) => Goal::Use(line),
                    Some(Activation::Walk) => Goal::Cross(line),
                    _ => continue,
                };
                if self.failed(&goal) {
                    continue;
                }
                let targets = plan::targets_of(nav, map, &goal);
                if let Some(route) = self.search.run(&world, start, Some(&targets)) {
                    if best.as_ref().is_none_or(|b| route.cost < b.0.cost) {
                        best = Some((route, goal));
                    }
                }
            }
            if let Some((route, goal)) = best {
                return Some(active(goal, Purpose::Exit, route));
            }
        }
        // No exit line within reach: the boss brain's death ends the level.
        if let Some(a) = self.brain_goal(game) {
            return Some(a);
        }
        let world = assumed.world(&self.nav, &self.mech, (&self.hurts, &self.wary), map);
        let nav = &self.nav;
        // Keys not yet held.
        let mut targets = Targets::default();
        let mut wanted = Vec::new();
        for (i, a) in game.seen().iter().enumerate() {
            let def = &game.table().actors[a.kind];
            let Some(colour) = def.key() else { continue };
            if a.removed
                || keys.contains(&colour)
                || self.unreachable.contains(&(i as u32))
                || self.failed(&Goal::Touch(a.pos, i as u32))
            {
                continue;
            }
            targets.add(self.touch_targets(map, a.pos, i as u32));
            wanted.push((i as u32, a.pos));
        }
        if !targets.is_empty() {
            if let Some(route) = self.search.run(&world, start, Some(&targets)) {
                let end = nav.centre_of(*route.cells.last().unwrap());
                let (i, pos) = *wanted.iter().min_by(|a, b| a.1.distance(end).total_cmp(&b.1.distance(end))).unwrap();
                return Some(active(Goal::Touch(pos, i), Purpose::Key, route));
            }
        }
        // Switches and walk lines: what could each open? (A level with
        // none, as most of ViZDoom's scenarios, needs no flood to say so.)
        if self.mech.triggers.is_empty() {
            return None;
        }
        self.search.run(&world, start, None);
        let base = self.search.reached.len();
        // With nothing untried left, a repeatable line tried before (a
        // door's switch seen from inside the closet it shut) is taken
        // again, when it is foretold to open something.
        let mut candidates = self.trigger_candidates(game, spent, &keys, false);
        let confined = candidates.is_empty();
        if confined {
            candidates = self.trigger_candidates(game, spent, &keys, true);
        }
        candidates.sort_by_key(|c| (c.0, c.1));
        if std::env::var_os("SIGHTLINE_AUTOPILOT_TRACE").is_some() {
            eprintln!(
                "choose: start {start}, reached {base}, {} candidates, {} triggers, tried {}",
                candidates.len(),
                self.mech.triggers.len(),
                self.tried.len()
            );
        }
        let mut unknown: Option<(u32, LineId, Goal)> = None;
        let mut best: Option<(usize, u32, LineId, Goal)> = None;
        let mut harmful = BTreeSet::new();
        for (cost, line, goal) in candidates.iter().take(16).cloned() {
            let (sl, _, _, special) = line_of(map, line);
            let Some(special) = special else { continue };
            let Some(after) = predict::predict(level, heights, sl, special) else {
                if unknown.is_none() {
                    unknown = Some((cost, line, goal));
                }
                continue;
            };
            let world = plan::World { heights: &after, ..world };
            let exit_opens = self.mech.exits.iter().any(|&(l, _)| {
                let g = match line_of(map, l).3.map(|s| s.on) {
                    Some(Activation::Use) => Goal::Use(l),
                    _ => Goal::Cross(l),
                };
                let t = plan::targets_of(nav, map, &g);
                self.search.run(&world, start, Some(&t)).is_some()
            });
            if exit_opens {
                best = Some((usize::MAX, cost, line, goal));
                break;
            }
            // A key coming within reach is worth more than any floor space.
            let key_opens = !targets.is_empty() && self.search.run(&world, start, Some(&targets)).is_some();
            self.search.run(&world, start, None);
            let reached = self.search.reached.len();
            let gain = reached.saturating_sub(base) + if key_opens { 1_000_000 } else { 0 };
            if std::env::var_os("SIGHTLINE_AUTOPILOT_TRACE").is_some() {
                eprintln!("  candidate {} cost {cost}: reaches {reached} (gain {gain})", describe(map, line));
            }
            if gain > 8 && best.as_ref().is_none_or(|b| gain > b.0 * 2 || (gain * 2 > b.0 && cost < b.1)) {
                best = Some((gain, cost, line, goal));
            } else if !key_opens && reached + 8 < base && !special.repeat {
                // A once-only line that shuts part of the level off (a
                // floor raised across a way on): last of all.
                harmful.insert(line);
            } else if unknown.is_none() {
                unknown = Some((cost, line, goal));
            }
        }
        // The pick first, then the rest by distance, the harmful last.
        let pick = best.map(|b| (b.2, b.3)).or(unknown.filter(|_| !confined).map(|u| (u.1, u.2)));
        let world = plan::World { heights, ..world };
        candidates.sort_by_key(|c| harmful.contains(&c.1));
        if confined {
            candidates.clear();
        }
        for (line, goal) in pick.into_iter().chain(candidates.into_iter().map(|c| (c.1, c.2))) {
            let targets = plan::targets_of(nav, map, &goal);
            if let Some(route) = self.search.run(&world, start, Some(&targets)) {
                if confined {
                    *self.retaken.entry(line).or_insert(0) += 1;
                }
                return Some(active(goal, Purpose::Trigger, route));
            }
        }
        None
    }

    /// The switches and walk lines worth setting off now, with the cost of
    /// the way to each (after a flood from the start): those not tried
    /// yet, and of those tried, a once-only walk line the level kept live
    /// (its sectors were busy then) and a switch whose last press started
    /// nothing, once their sectors are still. `confined` (nothing else
    /// left): any repeatable line tried before, [`MAX_RETAKES`] times. No
    /// line whose sectors are moving now is worth anything until they stop.
    fn trigger_candidates(
        &self,
        game: &dyn Observe,
        spent: &BTreeSet<LineId>,
        keys: &[KeyColour],
        confined: bool,
    ) -> Vec<(u32, LineId, Goal)> {
        let (nav, map) = (&self.nav, &game.level().compiled.map);
        let mut candidates = Vec::new();
        for &line in &self.mech.triggers {
            if spent.contains(&line) {
                continue;
            }
            let Some(special) = line_of(map, line).3 else { continue };
            if let Some(&when) = self.tried.get(&line) {
                let since = game.ticks().saturating_sub(when);
                let again = if special.on == Activation::Walk && !special.repeat {
                    self.crossed.get(&line).is_some_and(|&n| n < 2) && since > 35 * 5
                } else {
                    since > 35 * 2
                        && (self.did_nothing.contains(&line)
                            || confined && special.repeat && self.retaken.get(&line).is_none_or(|&n| n < MAX_RETAKES))
                };
                if !again {
                    continue;
                }
            }
            // A sector already moving takes no new special: the line would
            // do nothing now (and walking over a rising crusher's sibling
            // line to set it off is how a body gets crushed).
            if Self::targets_busy(game, line) {
                continue;
            }
            match special.action {
                Action::Door { key: Some(k), .. } if !keys.contains(&k) => continue,
                // A line that only shuts doors opens nothing: it is never a
                // goal (MAP21's, round the pit outside the start, shut the
                // start room, and the blue door in it, until the yellow key).
                Action::Door { kind: DoorKind::Close, .. } => continue,
                _ => {}
            }
            let goal = match special.on {
                Activation::Use => Goal::Use(line),
                Activation::Walk => Goal::Cross(line),
                Activation::Shoot => Goal::Shoot(line),
            };
            if self.failed(&goal) {
                continue;
            }
            let cost = match &goal {
                Goal::Use(_) | Goal::Shoot(_) => {
                    plan::targets_of(nav, map, &goal).cells().filter_map(|c| self.search.cost_to(c)).min()
                }
                _ => self.crossing_cost(line),
            };
            if let Some(cost) = cost {
                candidates.push((cost, line, goal));
            }
        }
        candidates
    }

    /// Is any sector `line`'s special moves busy now?
    pub(super) fn targets_busy(game: &dyn Observe, line: LineId) -> bool {
        let level = game.level();
        let (sl, _, _, special) = line_of(&level.compiled.map, line);
        special.is_some_and(|sp| sectors::target_sectors(level, sl, sp).into_iter().any(|s| game.is_busy(s)))
    }

    /// The cheapest reached cell from which a move crosses `line` (after a
    /// flood).
    fn crossing_cost(&self, line: LineId) -> Option<u32> {
        let mut best: Option<u32> = None;
        for &c in &self.search.reached {
            for d in 0..4 {
                let across = self.nav.neighbour(c, d).is_some_and(|n| self.search.was_reached(n));
                if across && self.nav.crossings_of(c, d).any(|(l, _)| l == line) {
                    let cost = self.search.cost_to(c).unwrap_or(u32::MAX);
                    best = Some(best.map_or(cost, |b| b.min(cost)));
                }
            }
        }
        best
    }

    /// The cells thing `i` at `p` is picked up from (`plan::touch_cells`),
    /// less those it was found not to be (`touch_missed`).
    pub(super) fn touch_targets(&self, map: &crate::map::Map, p: DVec2, i: u32) -> plan::Targets {
        let mut t = plan::touch_cells(&self.nav, map, p);
        if let Some(missed) = self.touch_missed.get(&i) {
            t.remove_cells(missed);
        }
        t
    }

    /// A route to `goal` from here, with the heights a plan assumes.
    pub(super) fn route_to(&mut self, game: &dyn Observe, goal: &Goal) -> Option<Route> {
        self.route_with(game, goal, |_| {})
    }

    /// [`Self::route_to`] with the assumed heights changed by `adjust`.
    pub(super) fn route_with(
        &mut self,
        game: &dyn Observe,
        goal: &Goal,
        adjust: impl FnOnce(&mut Heights),
    ) -> Option<Route> {
        let level = game.level();
        let map = &level.compiled.map;
        let mut assumed = self.assume(game);
        adjust(&mut assumed.heights);
        let start = assumed.start(&self.nav, game)?;
        let world = assumed.world(&self.nav, &self.mech, (&self.hurts, &self.wary), map);
        let targets = match goal {
            Goal::Touch(p, thing) => self.touch_targets(map, *p, *thing),
            _ => plan::targets_of(&self.nav, map, goal),
        };
        self.search.run(&world, start, Some(&targets))
    }
}
