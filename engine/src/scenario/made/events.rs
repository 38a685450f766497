//! The events of a made scenario that ViZDoom's rewards do not cover,
//! read off the simulation after each tic: a goal sector entered (the
//! player body's sector), an item picked up (by its kind), the level left.
//! [`Rules`] is the specification resolved against the map and the actor
//! table once per scenario; each episode keeps a [`Tracker`] of what it has
//! paid. The kills, secrets, damage, living reward, death and timeout are
//! the `.cfg` scenario's own rewards (`run::Episode::step`), which the
//! specification sets (`made::configure`).
//!
//! Nothing is read for an event that pays nothing: with no goal sectors
//! the body's sector is not asked, with no pickup reward no body is looked
//! at.

use std::sync::Arc;

use super::spec::RewardSpec;
use crate::actors::ActorTable;
use crate::scenario::End;
use crate::sim::game::SimGame;
use crate::sim::mobj::mf;
use crate::sim::{MobjId, Sim};

/// `BONUSADD` (`p_inter.c`): what each pickup adds to the player's gold
/// flash, which `P_PlayerThink` takes one from each tic before the bodies
/// move. The only other thing that raises it is a weapon left for the
/// others in a net game; a made scenario is played alone.
const BONUSADD: i32 = 6;

/// A made scenario's goals and item rewards, resolved once.
#[derive(Clone, Debug)]
pub struct Rules {
    /// Per sector of the map: the goal entering it is (an index into
    /// `goals`).
    goal_of: Vec<Option<usize>>,
    /// Each goal's reward and whether it ends the episode.
    goals: Vec<(f64, bool)>,
    /// Per actor kind (the table's index, as `Mobj::kind`): what picking
    /// one up pays; `None` when no pickup pays.
    pickup: Option<Vec<f64>>,
}

/// What an episode has paid so far, and what it remembers of the last tic.
#[derive(Clone, Debug)]
pub struct Tracker {
    rules: Arc<Rules>,
    /// Goals paid, by goal.
    paid: Vec<bool>,
    /// The player body's sector after the last tic.
    sector: usize,
    /// Items in the world that a pickup may take (`MF_SPECIAL` bodies).
    items: Vec<MobjId>,
    /// Bodies looked at so far (`Sim::mobjs` only grows during a level).
    bodies: usize,
    /// The player's `bonuscount` after the last tic.
    bonus: i32,
}

impl Rules {
    /// `spec` on a map of `sectors` sectors whose things come from `table`
    /// (checked: [`RewardSpec::check`]).
    pub fn new(spec: &RewardSpec, sectors: usize, table: &ActorTable) -> Rules {
        let mut goal_of = vec![None; if spec.reach.is_empty() { 0 } else { sectors }];
        let mut goals = Vec::new();
        for r in &spec.reach {
            if let Some(slot) = usize::try_from(r.sector).ok().and_then(|s| goal_of.get_mut(s)) {
                *slot = Some(goals.len());
                goals.push((r.reward, r.end));
            }
        }
        let pickup = spec.pickup.pays().then(|| table.actors.iter().map(|a| spec.pickup.of(&a.name)).collect());
        Rules { goal_of, goals, pickup }
    }

    /// A tracker for an episode of `game`, which starts now: the sector
    /// the player stands in is not entered, and the items lying about are
    /// all there to be picked up.
    pub fn start(self: &Arc<Self>, game: &SimGame) -> Tracker {
        let mut tracker = Tracker {
            rules: self.clone(),
            paid: vec![false; self.goals.len()],
            sector: player_sector(&game.sim).unwrap_or(usize::MAX),
            items: Vec::new(),
            bodies: 0,
            bonus: bonus(&game.sim),
        };
        if self.pickup.is_some() {
            tracker.look_at_new_bodies(&game.sim);
        }
        tracker
    }
}

impl Tracker {
    /// The reward for the tic just played and the end it brings, if any:
    /// the exit, or a goal that ends the episode.
    pub fn tic(&mut self, game: &SimGame) -> (f64, Option<End>) {
        let sim = &game.sim;
        let mut reward = 0.0;
        let mut end = None;
        if !self.rules.goals.is_empty() {
            if let Some(s) = player_sector(sim).filter(|&s| s != self.sector) {
                self.sector = s;
                if let Some(g) = self.rules.goal_of.get(s).copied().flatten().filter(|&g| !self.paid[g]) {
                    self.paid[g] = true;
                    let (r, ends) = self.rules.goals[g];
                    reward += r;
                    if ends {
                        end = Some(End::Exit);
                    }
                }
            }
        }
        if self.rules.pickup.is_some() {
            reward += self.pickups(sim);
        }
        if sim.exit.is_some() {
            end = Some(End::Exit);
        }
        (reward, end)
    }

    /// Which goals have been paid, in the specification's `reach` order.
    pub fn reached(&self) -> &[bool] {
        &self.paid
    }

    /// The items picked up this tic, paid by kind. An item leaves the
    /// world when it is picked up, but a dropped one also does when a
    /// ceiling crushes it; the player's gold flash tells how many were
    /// picked up (`BONUSADD` each, less the tic's fade), and those are the
    /// ones gone nearest the player.
    fn pickups(&mut self, sim: &Sim) -> f64 {
        let gone: Vec<MobjId> = self.items.iter().copied().filter(|&id| sim.mo(id).removed).collect();
        self.items.retain(|&id| !sim.mo(id).removed);
        self.look_at_new_bodies(sim);
        let now = bonus(sim);
        let picked = (now - (self.bonus - 1).max(0)).max(0) / BONUSADD;
        self.bonus = now;
        if picked == 0 || gone.is_empty() {
            return 0.0;
        }
        let Some(table) = self.rules.pickup.as_ref() else { return 0.0 };
        let mut gone = gone;
        if gone.len() > picked as usize {
            let at = player_body(sim).map(|p| (sim.mo(p).x.to_f64(), sim.mo(p).y.to_f64())).unwrap_or_default();
            let distance = |id: &MobjId| {
                let m = sim.mo(*id);
                (m.x.to_f64() - at.0).hypot(m.y.to_f64() - at.1)
            };
            gone.sort_by(|a, b| distance(a).total_cmp(&distance(b)));
            gone.truncate(picked as usize);
        }
        gone.iter().map(|&id| table.get(sim.mo(id).kind).copied().unwrap_or(0.0)).sum()
    }

    /// Adds the items spawned since the last look (a zombieman's clip).
    fn look_at_new_bodies(&mut self, sim: &Sim) {
        for (i, m) in sim.mobjs.iter().enumerate().skip(self.bodies) {
            if m.has(mf::SPECIAL) && !m.removed {
                self.items.push(MobjId(i as u32));
            }
        }
        self.bodies = sim.mobjs.len();
    }
}

fn player_body(sim: &Sim) -> Option<MobjId> {
    sim.player(sim.console).map(|p| p.mo)
}

/// The sector the player's body stands in (its centre's, as Doom links
/// it): a RON map's own numbering, which the simulation keeps.
fn player_sector(sim: &Sim) -> Option<usize> {
    player_body(sim).map(|mo| sim.sector_of(mo))
}

fn bonus(sim: &Sim) -> i32 {
    sim.player(sim.console).map_or(0, |p| p.bonuscount)
}
