//! Ways back: with no goal left where the body stands (every round of
//! trying again spent), the drops it can survive are tried before it gives
//! up: off a raised lift or platform, off a ledge, into a pit that has a
//! way on. A drop is what `check` counts as one: a move of the search
//! (`NavGrid::climbable` over the plan's heights) that `Span::drops_to`
//! says no step climbs back, after 15 s stuck (what it waits for may still
//! come). Landing somewhere new, the bot starts its
//! rounds again from there: a switch or a line that did nothing from the
//! ledge's side may be within reach, a lift that stayed up may come down.

use super::*;

/// Drops tried in one level at most (each into a sector not dropped into
/// before).
const MAX_DROPS: usize = 8;
/// Landings looked at, nearest first, for a way on from them.
const LOOK_AT: usize = 12;
/// Ticks stuck (looking again each second) before a drop is tried: what
/// the bot waits for (a lift on its way, a floor still moving) may come,
/// and a drop is one way.
pub(super) const WAY_DOWN_AFTER: u64 = 35 * 15;

impl Autopilot {
    /// The way to the nearest drop's landing not tried yet, into a sector
    /// other than the body's, whose floor does not hurt and from which
    /// more than that sector is reached (a pit with a way out); a sector
    /// the body has not stood in before others.
    pub(super) fn way_down(&mut self, game: &dyn Observe) -> Option<Active> {
        if self.dropped.len() >= MAX_DROPS {
            return None;
        }
        let map = &game.level().compiled.map;
        let assumed = self.assume(game);
        let start = assumed.start(&self.nav, game)?;
        let world = assumed.world(&self.nav, &self.mech, (&self.hurts, &self.wary), map);
        let here = game.player().sector;
        self.search.run(&world, start, None);
        // (stood there before, cost, sector, landing cell)
        let mut landings: Vec<(bool, u32, usize, Cell)> = Vec::new();
        for &c in &self.search.reached {
            let from = self.nav.span(c, &assumed.heights);
            for d in 0..8 {
                let Some(n) = self.nav.neighbour(c, d).filter(|_| self.nav.open(c, d)) else { continue };
                let to = self.nav.span(n, &assumed.heights);
                if !from.drops_to(&to) || !self.nav.climbable(c, d, from, to, &assumed.heights) {
                    continue;
                }
                let (Some(cost), s) = (self.search.cost_to(n), self.nav.centre[n as usize]) else { continue };
                if s == nav::NONE || !self.nav.standable(n) {
                    continue;
                }
                let s = s as usize;
                if s == here || self.dropped.contains(&s) || self.hurts[s] {
                    continue;
                }
                match landings.iter_mut().find(|l| l.2 == s) {
                    Some(l) if l.1 <= cost => {}
                    Some(l) => (l.1, l.3) = (cost, n),
                    None => landings.push((self.stood_on[s] > 0, cost, s, n)),
                }
            }
        }
        landings.sort();
        for &(_, _, s, n) in landings.iter().take(LOOK_AT) {
            // A pit with a way on: from the landing, more than its own
            // sector is reached.
            self.search.run(&world, n, None);
            let nav = &self.nav;
            if self.search.reached.iter().all(|&c| nav.centre[c as usize] as usize == s) {
                continue;
            }
            let centre = self.nav.centre_of(n);
            let mut targets = Targets::default();
            targets.add(plan::cells_near(&self.nav, centre, 1.0));
            let Some(route) = self.search.run(&world, start, Some(&targets)) else { continue };
            self.dropped.insert(s);
            let now = game.ticks();
            self.log.push(format!("tick {now}: nothing left here: dropping into sector {s} to look again from there"));
            return Some(Active::new(Goal::Touch(centre, u32::MAX), Purpose::Explore, route, now));
        }
        None
    }
}
