//! Supplies: which health, armour, ammunition and weapons are worth a
//! detour now, and how long a one. The goal choice (`choose_inner`) asks
//! for them before the exit, keys and switches, most urgent first, and
//! searches each tier's things together, taking the nearest reached.

use glam::DVec2;

use super::plan::{Goal, Targets};
use super::{brain, Autopilot, Observe, LOW_HEALTH};
use crate::actors::{ActorFlag, Give};

/// Below this health any health the body can reach is fetched, however
/// far: one more shotgun guy's volley or imp's fireball can kill.
pub(super) const CRITICAL_HEALTH: i32 = 35;
/// Firepower (see [`firepower`]) under which ammunition is short: fetched
/// within [`LOW_COST`] ...
const SHORT_FIREPOWER: i32 = 60;
/// ... and under which the body is as good as unarmed (a fist and a few
/// bullets): ammunition or a weapon is fetched however far.
const OUT_FIREPOWER: i32 = 12;
/// Route costs (10 a cell) of the detours each tier is worth: anything
/// reachable when critical, about 120 cells when low, 80 for a weapon the
/// body lacks or better armour than it wears.
const CRITICAL_COST: u32 = 20_000;
const LOW_COST: u32 = 1200;
const NICE_COST: u32 = 800;
/// A health pickup worth a long detour gives at least this much (not a
/// health bonus's 1).
const WORTH_HEALTH: i32 = 10;

/// How badly the body needs supplies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Need {
    None,
    Low,
    Critical,
}

/// Things worth fetching, the cells they are picked up from, and the most
/// a route to them may cost.
pub(super) struct Tier {
    pub max_cost: u32,
    pub things: Vec<(u32, DVec2)>,
    pub targets: Targets,
}

/// A rough count of shots worth firing with the weapons owned: bullets,
/// shells (a shotgun blast does some four bullets' damage), rockets and
/// cells, each counted only with a weapon that fires it.
pub(super) fn firepower(game: &dyn Observe) -> i32 {
    let player = game.player();
    let table = game.table();
    let mut fires = [false; 4];
    for &w in &player.weapons {
        if let Some(k) = table.actors[w].weapon.as_ref().and_then(|d| d.ammo) {
            fires[k.index()] = true;
        }
    }
    let worth = [1, 4, 8, 1];
    (0..4).filter(|&k| fires[k]).map(|k| player.ammo[k] * worth[k]).sum()
}

/// Are monsters left alive (or a boss brain that spits more)?
fn monsters_left(game: &dyn Observe) -> bool {
    let table = game.table();
    game.seen().iter().any(|a| !a.removed && a.health > 0 && table.actors[a.kind].has(ActorFlag::CountKill))
        || !brain::live(game).is_empty()
}

/// How badly health (`health`) or ammunition is needed now.
pub(super) fn need(game: &dyn Observe) -> (Need, Need) {
    let player = game.player();
    // A boss brain spits monsters for as long as it lives (even with none
    // placed): health is worth fetching sooner.
    let endless = !brain::live(game).is_empty();
    let health = if player.health < CRITICAL_HEALTH {
        Need::Critical
    } else if player.health < if endless { 100 } else { LOW_HEALTH } {
        Need::Low
    } else {
        Need::None
    };
    let power = firepower(game);
    let ammo = if !monsters_left(game) {
        Need::None
    } else if power < OUT_FIREPOWER {
        Need::Critical
    } else if power < SHORT_FIREPOWER {
        Need::Low
    } else {
        Need::None
    };
    (health, ammo)
}

impl Autopilot {
    /// The supplies worth fetching now, most urgent first: health when
    /// critical and ammunition when as good as out, from anywhere
    /// reachable; health and ammunition when short, from nearby; and with
    /// monsters about, a weapon the body lacks or better armour than it
    /// wears, from close by.
    pub(super) fn supplies(&self, game: &dyn Observe) -> Vec<Tier> {
        let player = game.player();
        let (seen, table) = (game.seen(), game.table());
        let map = &game.level().compiled.map;
        let (health, ammo) = need(game);
        let monsters = monsters_left(game);
        let owned = |name: &str| player.weapons.iter().any(|&w| table.actors[w].name == name);
        let fires = |k: crate::actors::AmmoKind| {
            player.weapons.iter().any(|&w| table.actors[w].weapon.as_ref().is_some_and(|d| d.ammo == Some(k)))
        };
        let mut tiers: Vec<Tier> = [CRITICAL_COST, LOW_COST, NICE_COST]
            .into_iter()
            .map(|max_cost| Tier { max_cost, things: Vec::new(), targets: Targets::default() })
            .collect();
        for (i, a) in seen.iter().enumerate() {
            let def = &table.actors[a.kind];
            let goal = Goal::Touch(a.pos, i as u32);
            if a.removed || !def.has(ActorFlag::Special) || self.unreachable.contains(&(i as u32)) || self.failed(&goal)
            {
                continue;
            }
            let Some(pickup) = &def.pickup else { continue };
            // The most urgent tier any of its gifts answers (0 critical,
            // 1 low, 2 nice).
            let tier = pickup
                .give
                .iter()
                .filter_map(|g| match g {
                    Give::Health { amount, max } if player.health < *max => match health {
                        Need::Critical if *amount >= WORTH_HEALTH => Some(0),
                        Need::Critical | Need::Low => Some(1),
                        Need::None => None,
                    },
                    Give::Ammo(k, _) if fires(*k) => match ammo {
                        Need::Critical => Some(0),
                        Need::Low => Some(1),
                        Need::None => None,
                    },
                    Give::Weapon(name) if monsters && !owned(name) => Some(if ammo == Need::Critical { 0 } else { 2 }),
                    Give::Backpack if ammo > Need::None => Some(1),
                    Give::Armor { points, .. } if monsters && player.armor < *points => Some(2),
                    _ => None,
                })
                .min();
            let Some(tier) = tier else { continue };
            tiers[tier].targets.add(self.touch_targets(map, a.pos, i as u32));
            tiers[tier].things.push((i as u32, a.pos));
        }
        tiers.retain(|t| !t.things.is_empty());
        tiers
    }
}
