//! Protection before a wade: a route through floors that hurt more than the
//! body should take fetches a radiation suit (or, for a wade it would not
//! live through, health) first.

use super::*;

impl Autopilot {
    /// A route that wades through more floor that hurts than the body can
    /// take with health to spare (at a walk, two ticks a cell, and a wait at
    /// its end): fetch a radiation suit first, when one can be reached for
    /// less than the route's own cost, and the body wears none; a wade it
    /// would not live through fetches a suit or health from however far,
    /// as long as the fetch leaves the body alive and (for health) hurts
    /// less than it gives.
    pub(super) fn protection_first(&mut self, game: &dyn Observe, active: Active) -> Active {
        if matches!(active.purpose, Purpose::Supplies | Purpose::Safety) {
            return active;
        }
        let map = &game.level().compiled.map;
        let damage = |c: Cell| {
            self.nav.touched(c).iter().filter_map(|&s| map.sectors[s as usize].special.damage).map(|d| d.amount).max()
        };
        // Hurts every 32 ticks, two ticks a cell: a sixteenth of the cells'
        // damage; and at the end, where it presses and waits for what it
        // set off, about four hurts more.
        let (nav, hurts) = (&self.nav, &self.hurts);
        let hurting = |c: &&Cell| nav.touched(**c).iter().any(|&s| hurts[s as usize]);
        let wade = |cells: &[Cell]| cells.iter().filter(hurting).filter_map(|&c| damage(c)).sum::<u32>() / 16;
        let cells = &active.route.cells;
        let wait = cells.last().filter(hurting).and_then(|&c| damage(c)).unwrap_or(0) * 4;
        let dose = wade(cells) + wait;
        let health = game.player().health.max(0) as u32;
        if dose < SUIT_DOSE.min(health / 2) {
            return active;
        }
        // A wade it would not live through: health will do as well, from
        // however far.
        let lethal = dose + 5 >= health;
        let (seen, table) = (game.seen(), game.table());
        let mut targets = Targets::default();
        let mut wanted = Vec::new();
        for (i, a) in seen.iter().enumerate() {
            let helps = gives(&table.actors[a.kind]).any(|g| match *g {
                Give::Power(Power::IronFeet) => true,
                // Only health that lifts the body clear of the dose:
                // medikits stop at 100, and a wade that 100 would not live
                // through is not made safe by fetching them (it is waded as
                // it is, or with a suit).
                Give::Health { max, .. } => lethal && health < max as u32 && dose + 5 < max as u32,
                _ => false,
            });
            if helps
                && !a.removed
                && !self.unreachable.contains(&(i as u32))
                && !self.failed(&Goal::Touch(a.pos, i as u32))
            {
                targets.add(self.touch_targets(map, a.pos, i as u32));
                wanted.push((i as u32, a.pos));
            }
        }
        if wanted.is_empty() {
            return active;
        }
        let assumed = self.assume(game);
        let Some(start) = assumed.start(&self.nav, game) else { return active };
        let world = assumed.world(&self.nav, &self.mech, (&self.hurts, &self.wary), map);
        let Some(route) =
            self.search.run(&world, start, Some(&targets)).filter(|r| lethal || r.cost < active.route.cost)
        else {
            return active;
        };
        let end = self.nav.centre_of(*route.cells.last().unwrap_or(&start));
        let Some(&(i, pos)) = wanted.iter().min_by(|a, b| a.1.distance(end).total_cmp(&b.1.distance(end))) else {
            return active;
        };
        // The fetch is itself a wade: one the body would not live
        // through, or (for health) one that hurts more than the health
        // gives, is no help.
        let fetch = wade(&route.cells);
        let def = &table.actors[seen[i as usize].kind];
        let suit = gives(def).any(|g| matches!(g, Give::Power(Power::IronFeet)));
        let gain: u32 = gives(def)
            .map(|g| match *g {
                Give::Health { amount, max } => amount.min(max - health as i32).max(0) as u32,
                _ => 0,
            })
            .sum();
        if fetch + 5 >= health || (!suit && fetch >= gain) {
            return active;
        }
        let what = &def.name;
        self.log.push(format!("tick {}: the way wades through about {dose} damage: {what} first", game.ticks()));
        Active::new(Goal::Touch(pos, i), Purpose::Supplies, route, game.ticks())
    }
}
