//! Following a route (the autopilot's part of a tick between choosing a
//! goal and reaching it): where along the route the body is, what stands
//! in the way (a crushing ceiling, a busy sector a once-only line would
//! waste, a door, a lift, a step), and the input that steers, brakes or
//! waits.

use super::*;

impl Autopilot {
    /// Follows the route: the input that moves along it, opens what is in
    /// the way and does what the goal asks at its end.
    pub(super) fn follow(&mut self, game: &dyn Observe) -> TickInput {
        let now = game.ticks();
        let pos = game.player().pos;
        // Waiting for a door, on a running jump or riding a lift to fire at
        // the boss brain: no new plan now.
        let waiting = self.active.as_ref().is_some_and(|a| a.waited > 0 || a.leap.is_some()) || self.riding();
        let leaping = self.active.as_ref().is_some_and(|a| a.leap.is_some());
        if now >= self.next_replan && !waiting && !self.rechoose {
            // Now and then the route to the same goal is found again (the
            // world moves, a move was given up); only a route that no
            // longer exists sends it to choose a new goal.
            if let Some(a) = self.active.as_mut().filter(|a| a.reroutes >= MAX_REROUTES) {
                // Half a minute on one goal: count it a failure, look again.
                let goal = a.goal.clone();
                self.give_up(&goal);
                self.active = None;
            }
            if let Some(goal) = self.active.as_ref().map(|a| a.goal.clone()) {
                self.next_replan = now + REPLAN_EVERY;
                let started = std::time::Instant::now();
                let route = self.route_to(game, &goal);
                self.figures.plan_seconds += started.elapsed().as_secs_f64();
                match route {
                    Some(route) => {
                        let a = self.active.as_mut().unwrap();
                        (a.route, a.at, a.idle) = (route, 0, 0);
                        a.reroutes += 1;
                    }
                    None => self.active = None,
                }
            }
        }
        // A key picked up or health running low does not break off a leap
        // or a ride at the boss brain (the launcher put away for a fight
        // would not be up again for the shot).
        if self.active.is_none()
            || (now >= self.next_replan && !waiting)
            || (self.rechoose && !leaping && !self.riding())
        {
            self.rechoose = false;
            if now < self.settle_until && self.active.is_none() {
                return TickInput::default();
            }
            self.next_replan = now + REPLAN_EVERY;
            match self.choose(game) {
                Some(a) => {
                    let what = match &a.goal {
                        Goal::Use(l) | Goal::Cross(l) | Goal::Shoot(l) => describe(&game.level().compiled.map, *l),
                        Goal::Touch(p, _) => format!("({:.0}, {:.0})", p.x, p.y),
                        Goal::Brain(p, _) => format!("the boss brain, from ({:.0}, {:.0})", p.x, p.y),
                    };
                    self.log.push(format!(
                        "tick {now}: at ({:.0}, {:.0}) {:?} {what}, {} cells",
                        pos.x,
                        pos.y,
                        a.purpose,
                        a.route.cells.len()
                    ));
                    self.active = Some(a);
                    self.status = Status::Playing;
                    self.stuck_since = None;
                }
                None if self.rounds < MAX_ROUNDS && (self.rounds == 0 || now >= self.last_round + ROUND_GAP) => {
                    // Nothing left to try: try everything again once more
                    // (a switch pressed while its sector was busy did
                    // nothing; a move given up may work now).
                    self.rounds += 1;
                    self.last_round = now;
                    self.tried.retain(|&l, _| {
                        line_of(&game.level().compiled.map, l).3.is_some_and(|s| !s.repeat && Self::used_up(game, l))
                    });
                    self.failures.clear();
                    self.unreachable.clear();
                    self.bad.clear();
                    self.log.push(format!(
                        "tick {now}: at ({:.0}, {:.0}) nothing left: trying everything again",
                        pos.x, pos.y
                    ));
                    self.next_replan = now + 1;
                    return TickInput::default();
                }
                None => {
                    // Before giving up (and after looking again for a
                    // while: what it waits for may still come): a drop the
                    // body survives, to look again from where it lands
                    // (rounds start afresh there).
                    let since = *self.stuck_since.get_or_insert(now);
                    let drop = if now >= since + ways::WAY_DOWN_AFTER { self.way_down(game) } else { None };
                    if let Some(a) = drop {
                        self.stuck_since = None;
                        self.rounds = 0;
                        self.bad.clear();
                        self.failures.clear();
                        self.active = Some(a);
                        self.status = Status::Playing;
                        return TickInput::default();
                    }
                    self.active = None;
                    self.status = Status::Stuck {
                        at: pos,
                        why: "no exit, key or untried switch or walk line within reach".into(),
                    };
                    // Forget the moves given up on and the items not
                    // reached (a pedestal may still be coming down), and
                    // look again soon.
                    self.bad.clear();
                    self.unreachable.clear();
                    self.next_replan = now + self.look_again_in();
                    return TickInput::default();
                }
            }
        }
        let mut active = self.active.take().unwrap();
        let input = self.step(game, &mut active);
        if let Some(input) = input {
            self.active = Some(active);
            input
        } else {
            TickInput::default()
        }
    }

    /// One tick along `active`; `None` when it is finished or abandoned
    /// (then a new goal is chosen next tick).
    pub(super) fn step(&mut self, game: &dyn Observe, a: &mut Active) -> Option<TickInput> {
        if let Some(input) = self.leap_step(game, a) {
            return input;
        }
        if self.on_brain_lift(game, &a.goal) {
            return self.arrive(game, a);
        }
        let now = game.ticks();
        let player = game.player();
        let pos = player.pos;
        let map = &game.level().compiled.map;
        let cells = a.route.cells.clone();
        // Where along the route the body is.
        let mut best = (f64::MAX, a.at);
        for k in a.at..(a.at + 10).min(cells.len()) {
            let d = self.nav.centre_of(cells[k]).distance(pos);
            if d < best.0 && (d < 24.0 || k == a.at) {
                best = (d, k);
            }
        }
        if best.0 > 64.0 {
            // Left behind: a body running a diagonal cuts its corners and
            // may pass every cell wider than 24; whatever cell ahead is
            // nearest will do when it is close.
            let ahead = (a.at + 1..(a.at + 16).min(cells.len()))
                .map(|k| (self.nav.centre_of(cells[k]).distance(pos), k))
                .min_by(|x, y| x.0.total_cmp(&y.0));
            if let Some(near) = ahead.filter(|&(d, _)| d < 48.0) {
                best = near;
            }
        }
        if best.1 > a.at {
            a.at = best.1;
            a.idle = 0;
            a.waited = 0;
        } else {
            a.idle += 1;
        }
        if best.0 > 96.0 {
            // Pushed or fell off the route.
            self.next_replan = now;
            return None;
        }
        // Fallen off a ledge beside the route: the body is well under every
        // floor of the route near it. The move it was on is given up for a
        // while, and the way found again from down here.
        let live = live_heights(map);
        let near = &cells[a.at..(a.at + 3).min(cells.len())];
        if player.on_ground() && near.iter().all(|&x| player.z + MAX_STEP < self.nav.span(x, &live).low) {
            // The ledge it fell from, and its neighbourhood, are kept off
            // and walked carefully from now on.
            let around =
                cells[a.at.saturating_sub(2)..(a.at + 3).min(cells.len())].iter().map(|&c| self.nav.centre_of(c));
            for p in around.chain([pos]) {
                for c in self.nav.cells_in_box(p - DVec2::splat(FALL_WARY), p + DVec2::splat(FALL_WARY)) {
                    self.wary[c as usize] = true;
                }
            }
            if let Some(&n) = cells.get(a.at + 1) {
                if let Some(d) = self.nav.direction(cells[a.at], n) {
                    self.bad.insert(cells[a.at] * 8 + d as u32, now + 35 * 30);
                }
            }
            self.next_replan = now;
            return None;
        }
        let last = cells.len() - 1;
        if a.arrived > 0 || a.at >= last || (a.at + 1 == last && self.nav.centre_of(cells[last]).distance(pos) < 20.0) {
            return self.arrive(game, a);
        }
        // The next move: can it be made now, as the level stands?
        let (c, n) = (cells[a.at], cells[a.at + 1]);
        // A ceiling coming down, or a crushing floor going up: never wait
        // under it, never step under it.
        let crushing = |cell: Cell| self.crushing(&live, cell);
        let window = a.at.saturating_sub(8)..(a.at + 10).min(cells.len());
        if self.nav.cell_at(pos).is_some_and(crushing) || crushing(c) {
            // Out from under it by the nearest cell of the route that is not.
            let out = window.filter(|&k| !crushing(cells[k]) && !a.route.teleport[k]).min_by(|&i, &j| {
                let d = |k: usize| self.nav.centre_of(cells[k]).distance(pos);
                d(i).total_cmp(&d(j))
            });
            if let Some(k) = out {
                a.idle = 0;
                return Some(self.drive_to(game, self.nav.centre_of(cells[k]), false));
            }
        } else if cells[a.at + 1..(a.at + 4).min(cells.len())].iter().any(|&x| crushing(x)) {
            a.idle = 0;
            return Some(self.hold(game));
        }
        if let Some(line) = self.waste_ahead(game, a).filter(|_| a.waited < WASTE_PATIENCE) {
            // A once-only walk line ahead whose sectors are busy: crossed
            // now it would be spent for nothing. Wait for them.
            if a.waited == 0 {
                self.log.push(format!("tick {now}: waiting for the sectors of {} to stop", describe(map, line)));
            }
            a.idle = 0;
            a.waited += 1;
            return Some(self.hold(game));
        }
        if a.route.leap[a.at + 1] > 0 {
            // A running jump from here: to the edge's centre first.
            return Some(self.drive_to(game, self.nav.centre_of(c), true));
        }
        if !a.route.teleport[a.at + 1] {
            let from = self.nav.span(c, &live);
            let to = self.nav.span(n, &live);
            if std::env::var_os("SIGHTLINE_AUTOPILOT_TRACE").is_some() {
                eprintln!(
                    "tick {now} pos {pos:?} at {} c {:?} n {:?} from {from:?} to {to:?} touched {:?} idle {}",
                    a.at,
                    self.nav.centre_of(c),
                    self.nav.centre_of(n),
                    self.nav.touched(n),
                    a.idle
                );
            }
            let climbable = self
                .nav
                .direction(c, n)
                .map_or_else(|| NavGrid::passable(from, to), |d| self.nav.climbable(c, d, from, to, &live));
            if !climbable {
                if let Some(input) = self.unblock(game, a, (n, to), &live) {
                    return Some(input);
                }
            }
        }
        if a.idle > STUCK_TICKS {
            // Give the move up for a while and plan around it.
            if let Some(d) = self.nav.direction(c, n) {
                self.bad.insert(c * 8 + d as u32, now + 35 * 30);
            }
            self.next_replan = now;
            self.give_up(&a.goal);
            if a.idle > STUCK_TICKS + 1 {
                return None;
            }
            // A door in front, maybe: press use once.
            return Some(TickInput { use_line: !self.used_last, ..Default::default() });
        }
        // Steer for a point a little way along the route, not past a
        // teleport; when progress stalls, for the very next cell, slowly.
        let soon = &cells[a.at..(a.at + 4).min(cells.len())];
        let on_ledge = soon.iter().any(|&x| self.nav.span(x, &live).ledge()) || self.coasting_off(game, a, &live);
        // A teleport line the route does not take, close by: go carefully
        // (a body that drifts over it is somewhere else).
        let teleporting = a.route.teleport[a.at..(a.at + 5).min(cells.len())].iter().any(|&t| t);
        let wary = !teleporting && soon.iter().any(|&x| self.wary[x as usize]);
        let ahead = if a.idle > STUCK_TICKS / 2 || on_ledge || wary { 1 } else { 3 };
        let mut k = a.at + 1;
        while k < last
            && k < a.at + ahead
            && !a.route.teleport[k]
            && !a.route.teleport[k + 1]
            && a.route.leap[k + 1] == 0
        {
            k += 1;
        }
        let mut target = self.nav.centre_of(cells[k]);
        if a.route.teleport[k] {
            // Step over the teleport line: past the cell before it.
            let before = cells[k - 1];
            let via =
                (0..4).find(|&d| self.nav.crossings_of(before, d).any(|(l, _)| self.mech.teleports.contains_key(&l)));
            let dir = via.map_or(DVec2::ZERO, |d| DVec2::new(DIRS[d].0 as f64, DIRS[d].1 as f64));
            target = self.nav.centre_of(before) + dir * CELL * 1.5;
        }
        Some(self.drive_to(game, target, k == last || ahead == 1 || wary))
    }

    /// Does the route, within the next moves the body could coast through,
    /// cross a live once-only walk line that is not its goal while the
    /// sectors that line moves are busy? (See [`Self::wasted`].)
    pub(super) fn waste_ahead(&self, game: &dyn Observe, a: &Active) -> Option<LineId> {
        let cells = &a.route.cells;
        let goal = match a.goal {
            Goal::Cross(l) => Some(l),
            _ => None,
        };
        let map = &game.level().compiled.map;
        let reach = game.player().velocity.length() * 10.0 + 2.0 * CELL;
        let from = self.nav.centre_of(cells[a.at]);
        (a.at..cells.len() - 1)
            .take_while(|&k| self.nav.centre_of(cells[k]).distance(from) <= reach)
            .filter_map(|k| self.nav.direction(cells[k], cells[k + 1]).map(|d| (cells[k], d)))
            .flat_map(|(c, d)| self.nav.crossings_of(c, d).map(|(l, _)| l))
            .find(|&l| Some(l) != goal && Self::would_waste(game, map, l))
    }

    /// Would the body, coasting to a stop from its speed now, pass over a
    /// drop or a teleport line the route does not take? At a run it slides
    /// about ten times its speed: a bend beside a pit must be taken at a
    /// walk.
    pub(super) fn coasting_off(&self, game: &dyn Observe, a: &Active, live: &Heights) -> bool {
        let player = game.player();
        let slide = player.velocity * 10.0;
        // Off a step down the body flies, with neither friction nor
        // thrust (Doom's P_XYMovement), for the fall's ticks: a 16-unit
        // step at a run carries it some 50 units further (E2M9, over a
        // teleport line past such a step). Measured from the floor under
        // the body to other sectors' floors (on a lift going down fast
        // the body lags its own floor: no step), and asked only of
        // teleport lines (a longer slide taken for the drops below kept
        // the bot from pushing on where it had to: MAP04, MAP06).
        let drop = (1..=4)
            .filter_map(|i| self.nav.cell_at(player.pos + slide * (i as f64 / 4.0)))
            .map(|c| self.nav.centre[c as usize])
            .filter(|&s| s != nav::NONE && s as usize != player.sector)
            .map(|s| player.floor - live.floor[s as usize])
            .fold(0.0, f64::max)
            .min(MAX_STEP);
        let flight = if drop > 0.0 && player.on_ground() { 1.0 + ((2.0 * drop).sqrt() + 1.0) / 10.0 } else { 1.0 };
        let ahead = a.at..(a.at + 16).min(a.route.cells.len());
        // Over a teleport line's front the route does not take (E2M9: a
        // run out of a teleporter's arrival, round a bend, back over the
        // line that sends it there).
        let map = &game.level().compiled.map;
        let (far, steps) = (slide * flight, (slide.length() * flight / 8.0).ceil() as usize);
        if !a.route.teleport[ahead.clone()].iter().any(|&t| t)
            && self.mech.teleports.keys().any(|&l| {
                let (_, p, q, _) = line_of(map, l);
                crate::geom::front_distance(p, q, player.pos) > 0.0
                    && (1..=steps).any(|i| {
                        let at = player.pos + far * (i as f64 / steps as f64);
                        plan::nearest_on(at, p, q).distance(at) < RADIUS + 8.0
                    })
            })
        {
            return true;
        }
        let route = &a.route.cells[ahead];
        let steps = (slide.length() / 8.0).ceil() as usize;
        (1..=steps).any(|i| {
            let p = player.pos + slide * (i as f64 / steps as f64);
            self.nav.cell_at(p).is_some_and(|c| {
                let centre = self.nav.centre[c as usize];
                centre != nav::NONE
                    && live.floor[centre as usize] < player.z - MAX_STEP
                    && !route.contains(&c)
                    && !route.iter().any(|&r| self.nav.centre_of(r).distance(p) < CELL * 0.75)
            })
        })
    }

    /// The input that heads for `target`.
    pub(super) fn drive_to(&self, game: &dyn Observe, target: DVec2, gently: bool) -> TickInput {
        let player = game.player();
        let d = target - player.pos;
        let turn = turn_to(player.angle, d.y.atan2(d.x).to_degrees());
        // Heading for a narrow landing far below: off the edge at a creep
        // (about a unit a tick). A falling body keeps its speed, and from
        // high up even a walk carries it past (round MAP30's lift, 512
        // below its top, the floor at its foot is at most 72 wide, the main
        // floor 256 below it). Narrow: where a walking body would come
        // down, the floor falls away again.
        let sectors = &game.level().compiled.map.sectors;
        let floor_at = |p: DVec2| {
            let c = self.nav.cell_at(p)?;
            self.nav.touched(c).iter().map(|&s| sectors[s as usize].floor).max_by(|a, b| a.total_cmp(b))
        };
        let long = floor_at(target).filter(|&f| player.z - f > LONG_DROP);
        // Falling `h` takes sqrt(2h) ticks (gravity is a unit a tick per
        // tick), in which a walking body goes some 8 units a tick.
        let past = long.and_then(|f| floor_at(target + d.normalize_or_zero() * WALK * (2.0 * (player.z - f)).sqrt()));
        if player.on_ground() && long.is_some_and(|f| past.is_some_and(|p| p < f - MAX_STEP)) {
            self.creeping.store(true, std::sync::atomic::Ordering::Relaxed);
            if player.velocity.length() > CREEP {
                return self.hold(game);
            }
            return TickInput { forward: 1, turn: turn as f32, ..Default::default() };
        }
        let speed = player.velocity.length();
        let slow = gently;
        // Coast when close: friction carries the body about ten times its speed.
        let push = !slow || speed * 6.0 < d.length();
        TickInput { forward: i8::from(push), turn: turn as f32, run: !slow, ..Default::default() }
    }

    /// The next move, to cell `next` whose span is `to` as the level
    /// stands, is blocked: open the door, call the lift, or wait for what
    /// is moving.
    pub(super) fn unblock(
        &mut self,
        game: &dyn Observe,
        a: &mut Active,
        (next, to): (Cell, Span),
        live: &Heights,
    ) -> Option<TickInput> {
        let level = game.level();
        let map = &level.compiled.map;
        let player = game.player();
        let keys = Self::keys_held(game);
        a.waited += 1;
        // Waiting on a floor that hurts is short.
        let hurting = self.on_hurting_floor(game);
        let patience = if hurting { 35 * 2 } else { 35 * 12 };
        if a.waited > patience || a.still > STILL_TICKS {
            a.idle = STUCK_TICKS + 1;
            a.waited = 0;
            a.still = 0;
            return None;
        }
        a.idle = 0;
        // The way on is higher than the body can step (a lift it rides has
        // gone down under it, or not come up yet).
        let way_up = to.low > player.z + MAX_STEP;
        let mut around = self.nav.touched(next).to_vec();
        around.extend_from_slice(self.nav.touched(a.route.cells[a.at]));
        for s in around {
            let s = s as usize;
            let moving = live.floor[s] != self.last.floor[s] || live.ceiling[s] != self.last.ceiling[s];
            if moving {
                return Some(self.hold(game));
            }
            // A manual door that is shut: use it.
            let shut = live.ceiling[s] - live.floor[s] < 56.0;
            if shut {
                let mut closest: Option<(f64, DVec2)> = None;
                for &(line, key) in &self.mech.doors[s] {
                    if key.is_some_and(|k| !keys.contains(&k)) {
                        continue;
                    }
                    if let Some(input) = self.use_line(game, line) {
                        return Some(input);
                    }
                    let (_, a, b, _) = line_of(map, line);
                    let q = plan::nearest_on(player.pos, a, b);
                    if crate::geom::front_distance(a, b, player.pos) > 0.0
                        && closest.is_none_or(|(d, _)| q.distance(player.pos) < d)
                    {
                        closest = Some((q.distance(player.pos), q));
                    }
                }
                // Out of reach, or another switch in front swallows the
                // press: walk up to the door's face, then press.
                if let Some((_, q)) = closest.filter(|&(d, _)| d > RADIUS + 2.0) {
                    return Some(self.drive_to(game, q, true));
                }
            }
            // A lift that is up: call it, from below, or from on it when
            // the way on is lower.
            let below = live.floor[s] > player.z + 24.0;
            let on = (player.z - live.floor[s]).abs() < 1.0
                && self.nav.touched(a.route.cells[a.at]).contains(&(s as u32))
                && !(self.mech.lifts[s].is_empty() && self.mech.lift_down[s].is_empty());
            if on && way_up && game.is_busy(s) {
                // Riding it: it comes back up by itself.
                return Some(self.hold(game));
            }
            let lines = match (below, on) {
                (true, _) => self.mech.lifts[s].clone(),
                (false, true) if !way_up => self.mech.lift_down[s].clone(),
                _ => Vec::new(),
            };
            if !lines.is_empty() {
                let spent = self.spent(game);
                for &line in &lines {
                    if spent.contains(&line) {
                        continue;
                    }
                    if let Some(input) = self.use_line(game, line) {
                        return Some(input);
                    }
                }
                // Not in reach: go and set it off, then come back.
                for line in lines.into_iter().filter(|l| !spent.contains(l)) {
                    let goal = match line_of(map, line).3.map(|s| s.on) {
                        Some(Activation::Use) => Goal::Use(line),
                        Some(Activation::Walk) => Goal::Cross(line),
                        _ => continue,
                    };
                    if a.purpose == Purpose::Lift {
                        // Already on a detour to call a lift: do not nest.
                        break;
                    }
                    if let Some(route) = self.route_to(game, &goal) {
                        self.give_up(&a.goal);
                        *a = Active::new(goal, Purpose::Lift, route, game.ticks());
                        return Some(self.hold(game));
                    }
                }
            }
        }
        // Something else (a remote door, a floor on its way): wait a while.
        a.still += 1;
        Some(self.hold(game))
    }

    /// Stand still (braking).
    pub(super) fn hold(&self, game: &dyn Observe) -> TickInput {
        let v = game.player().velocity;
        if v.length() > 2.0 {
            // Thrust against the motion.
            let angle = game.player().angle;
            let back = (-v).y.atan2(-v.x).to_degrees();
            let rel = (back - angle).to_radians();
            let (s, c) = rel.sin_cos();
            return TickInput {
                forward: if c > 0.5 {
                    1
                } else if c < -0.5 {
                    -1
                } else {
                    0
                },
                strafe: if s > 0.5 {
                    -1
                } else if s < -0.5 {
                    1
                } else {
                    0
                },
                ..Default::default()
            };
        }
        TickInput::default()
    }
}
