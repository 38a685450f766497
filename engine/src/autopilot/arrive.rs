//! Arriving at a goal: pressing a switch, shooting a line, walking over a
//! line, touching a thing, and what a goal that did not work is given up
//! for.

use super::*;

impl Autopilot {
    /// Faces `line` and presses use, if the body is in front of it and
    /// within reach; `None` when it is not.
    pub(super) fn use_line(&self, game: &dyn Observe, line: LineId) -> Option<TickInput> {
        let map = &game.level().compiled.map;
        let (_, a, b, special) = line_of(map, line);
        if special.is_none_or(|s| s.on != Activation::Use) {
            return None;
        }
        let pos = game.player().pos;
        let near = plan::nearest_on(pos, a, b);
        if crate::geom::front_distance(a, b, pos) <= 0.0 || near.distance(pos) > crate::play::USE_RANGE - 2.0 {
            return None;
        }
        // Aim at the part of the line in front, a little inside its ends.
        let inset = plan::nearest_on(pos, a + (b - a) * 0.2, b - (b - a) * 0.2);
        let d = inset - pos;
        if !Self::press_reaches(game, line, pos, pos + d.normalize_or_zero() * crate::play::USE_RANGE) {
            return None;
        }
        let turn = turn_to(game.player().angle, d.y.atan2(d.x).to_degrees());
        Some(TickInput { turn: turn as f32, use_line: !self.used_last, ..self.hold(game) })
    }

    /// Would a press from `from` aimed at `to` reach `line`? Doom's use
    /// stops at the first line with a live use special (another switch in
    /// front swallows the press) or at a wall with no opening.
    pub(super) fn press_reaches(game: &dyn Observe, line: LineId, from: DVec2, to: DVec2) -> bool {
        let wanted = line_of(&game.level().compiled.map, line).0;
        game.use_stop(from, to).is_none_or(|l| l == wanted)
    }

    /// At the route's end: do what the goal asks.
    pub(super) fn arrive(&mut self, game: &dyn Observe, a: &mut Active) -> Option<TickInput> {
        let now = game.ticks();
        a.arrived += 1;
        match a.goal.clone() {
            Goal::Use(line) => {
                // Stop square in front of the line's middle, face it, and
                // press (twice, a tick apart, in case the first was early).
                let (_, p, q, _) = line_of(&game.level().compiled.map, line);
                let normal = {
                    let d = (q - p).normalize_or_zero();
                    DVec2::new(d.y, -d.x)
                };
                // The middle first; after a press that did nothing, a quarter
                // of the way along, then three quarters.
                let along = [0.5, 0.25, 0.75][self.failures.get(&a.goal.key()).map_or(0, |&n| n as usize % 3)];
                let spot = p + (q - p) * along + normal * 30.0;
                let player = game.player();
                let settled = player.velocity.length() < 1.5;
                let close = player.pos.distance(spot) < 10.0;
                if a.arrived > if a.busy { 35 * 12 } else { 105 } {
                    self.tried.insert(line, now);
                    self.next_replan = now;
                    return None;
                }
                // The switch's click says the press worked; a press that
                // started nothing (its sectors busy) is made again once
                // they are still.
                let (sl, _, _, special) = line_of(&game.level().compiled.map, line);
                let pressed = |started: bool| {
                    game.events()
                        .iter()
                        .any(|e| matches!(e, Event::Special { line: l, started: s } if *l == sl && *s == started))
                };
                let worked = pressed(true);
                if pressed(false) && special.is_some_and(|s| s.repeat) {
                    (a.busy, a.presses) = (true, 0);
                    self.did_nothing.insert(line);
                }
                if worked {
                    self.did_nothing.remove(&line);
                }
                if a.busy && !worked && Self::targets_busy(game, line) {
                    return Some(self.hold(game));
                }
                if worked || (a.presses >= 2 && self.failed_once(&a.goal)) {
                    self.tried.insert(line, now);
                    self.settle_until = now + 35;
                    self.next_replan = now + 35;
                    return None;
                }
                if a.presses >= 2 {
                    // Nothing happened: try again later from another spot.
                    self.give_up(&a.goal);
                    self.next_replan = now;
                    return None;
                }
                // Where the floor hurts, no lining up: the press is made
                // as soon as it reaches (MAP29's switch is pressed from
                // the lava below its ledge, and the spot in front of it
                // is on the ledge).
                let hurry = self.on_hurting_floor(game);
                if (close && settled) || a.arrived > if hurry { 4 } else { 60 } || a.presses > 0 {
                    if let Some(input) = self.use_line(game, line) {
                        if input.use_line {
                            a.presses += 1;
                            Self::trace_press(game, line);
                        }
                        return Some(input);
                    }
                }
                if close {
                    return Some(self.hold(game));
                }
                Some(self.drive_to(game, spot, true))
            }
            Goal::Shoot(line) => {
                // Stop, face the line's middle and fire a few shots.
                let (_, p, q, _) = line_of(&game.level().compiled.map, line);
                let d = (p + q) / 2.0 - game.player().pos;
                let turn = turn_to(game.player().angle, d.y.atan2(d.x).to_degrees());
                if a.arrived > 70 {
                    self.tried.insert(line, now);
                    self.settle_until = now + 35;
                    self.next_replan = now + 35;
                    return None;
                }
                let still = game.player().velocity.length() < 1.0;
                // Only bullets set off a shot line (as in Doom): no
                // rockets, plasma or BFG.
                let weapon = weapon_for(game, Fire::Bullets);
                let player = game.player();
                let in_hand = slot_of(game, player.pending_weapon.or(player.ready_weapon));
                Some(TickInput {
                    turn: turn as f32,
                    fire: still && a.arrived % 8 < 4,
                    weapon: if in_hand == Some(weapon) { 0 } else { weapon },
                    ..self.hold(game)
                })
            }
            Goal::Cross(line) => {
                // The route ends past the line, but a body that cut a
                // corner may have passed beside a short line (the four
                // 16-unit sides of E3M7's key pad) or stopped short of it
                // (E3M9's exit pad, within the 20 units that end a route):
                // until the line is really crossed (`note_crossings`),
                // line up square in front of it, on whichever side the body
                // is, and walk across. Walk lines go off either way.
                let crossed = self.tried.get(&line).is_some_and(|&t| t >= a.started);
                if !crossed && a.arrived < 105 {
                    let (_, p, q, _) = line_of(&game.level().compiled.map, line);
                    let pos = game.player().pos;
                    let d = (q - p).normalize_or_zero();
                    let length = (q - p).length();
                    let inset = length.min(16.0) / 2.0;
                    let at = p + d * (pos - p).dot(d).clamp(inset, length - inset);
                    let here = crate::geom::front_distance(p, q, pos);
                    let over = DVec2::new(d.y, -d.x) * if here > 0.0 { -1.0 } else { 1.0 };
                    let lined_up = (pos - at).dot(d).abs() <= 3.0;
                    let target = if lined_up { at + over * 12.0 } else { at - over * 20.0 };
                    return Some(self.drive_to(game, target, true));
                }
                // The crossing is noted. A lift called down this way is
                // boarded at once (it waits three seconds at the bottom);
                // anything else is given a second to move.
                self.tried.insert(line, now);
                let settle = if a.purpose == Purpose::Lift { 0 } else { 35 };
                self.settle_until = now + settle;
                self.next_replan = now + settle;
                None
            }
            Goal::Brain(spot, actor) => self.fire_at_brain(game, a, spot, actor),
            Goal::Touch(pos, _) if a.purpose == Purpose::Safety => {
                // Off the hurting floor, or as near the safe cell as it goes.
                if !self.on_hurting_floor(game) || a.arrived > 70 {
                    self.next_replan = now;
                    return None;
                }
                Some(self.drive_to(game, pos, true))
            }
            Goal::Touch(pos, actor) => {
                let seen = game.seen();
                let Some(thing) = seen.get(actor as usize).filter(|x| !x.removed) else {
                    self.next_replan = now;
                    return None;
                };
                // A thing on a floor still moving (a pedestal coming down
                // slowly, MAP20's blue key) is waited for, a while.
                let level = game.level();
                let moving = level.compiled.locate(thing.pos).is_some_and(|s| game.is_busy(s));
                if a.arrived <= 70 || (moving && a.arrived <= MOVING_PATIENCE) {
                    return Some(self.drive_to(game, pos, false));
                }
                self.next_replan = now;
                // Given up, for good after a few tries. At a height the
                // body touches (Doom: from 8 under its feet to its top),
                // the body was not near enough (36 units off along an
                // axis is not touched, however near): that cell is not
                // tried again for it, others may be at once. Otherwise it
                // is out of reach from here (behind a wall, too high).
                self.give_up(&a.goal);
                let player = game.player();
                let mut other_cells = false;
                if (-8.0..=crate::play::player::HEIGHT).contains(&(thing.z - player.z)) {
                    let missed = self.touch_missed.entry(actor).or_default();
                    let before = missed.len();
                    missed.extend(self.nav.cell_at(player.pos));
                    missed.extend(a.route.cells.last());
                    other_cells = missed.len() > before;
                }
                if !other_cells {
                    self.unreachable.insert(actor);
                }
                None
            }
        }
    }

    /// With `SIGHTLINE_AUTOPILOT_TRACE` set: a press of `line`, where from,
    /// whether the line is still live and which of its sectors are busy.
    pub(super) fn trace_press(game: &dyn Observe, line: LineId) {
        if std::env::var_os("SIGHTLINE_AUTOPILOT_TRACE").is_none() {
            return;
        }
        let (level, player) = (game.level(), game.player());
        let (sl, _, _, special) = line_of(&level.compiled.map, line);
        let busy: Vec<(usize, bool)> = special
            .map(|sp| super::sectors::target_sectors(level, sl, sp))
            .unwrap_or_default()
            .into_iter()
            .map(|s| (s, game.is_busy(s)))
            .collect();
        eprintln!(
            "press line {line} from {:?} facing {:.1}, live {}, targets busy {busy:?}",
            player.pos,
            player.angle,
            game.special(sl).is_some()
        );
    }
}
