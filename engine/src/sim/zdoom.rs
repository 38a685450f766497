//! What ZDoom's maps and scripts add to bodies, for ViZDoom's scenario WADs
//! (UDMF maps with ACS): a thing id (`tid`) and a thing special with its
//! five arguments from the map or from `SetThingSpecial`, and the actor
//! properties scripts set (`SetActorProperty`: speed, damage factor, an
//! invisible render style) or `Thing_Hate` sets (a monster that ignores the
//! players). Doom's maps never set any of it: every hook below is one
//! lookup in an empty map, and [`Zdoom::bodies`] stays empty.
//!
//! A thing special is ZDoom's: it runs when its body dies (`P_KillMobj`,
//! the killer as activator) or is picked up (`P_TouchSpecialThing`, the
//! player as activator). The simulation does not run scripts itself: it
//! lists the special in [`Zdoom::fired`], and the scenario that owns the
//! ACS VM (`crate::scenario::run`) runs it.

use std::collections::BTreeMap;

use super::{MobjId, Sim};
use crate::fixed::Fixed;

/// A body's ZDoom fields (`AActor::tid`, `special`, `args`, and the
/// properties scripts change).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Extra {
    pub tid: i32,
    /// A line special number (ZDoom's, Hexen-style) run when the body dies
    /// or is picked up; 0 none.
    pub special: i32,
    pub args: [i32; 5],
    /// `APROP_Speed` for a monster: its step in whole units (Doom's
    /// `mobjinfo_t::speed` for walkers), overriding its kind's.
    pub speed: Option<i32>,
    /// `APROP_DamageFactor`: damage it takes is scaled by this (16.16).
    pub damage_factor: Option<Fixed>,
    /// `APROP_RenderStyle` `STYLE_None`: not drawn.
    pub invisible: bool,
    /// `Thing_Hate` types 5 and 6: it neither looks for players nor turns on
    /// one that hurts it.
    pub ignores_players: bool,
    /// `Thing_Hate`'s hatee: the thing id it looks for instead.
    pub hates: i32,
    /// `Thing_SetGoal`: the thing it walks to, not attacking.
    pub goal: Option<MobjId>,
}

/// A map thing's ZDoom fields (UDMF's `id`, `special`, `arg0`..`arg4`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct ThingFields {
    pub tid: i32,
    pub special: i32,
    pub args: [i32; 5],
}

impl ThingFields {
    pub fn is_none(&self) -> bool {
        *self == ThingFields::default()
    }

    /// Onto the body spawned for the thing.
    pub fn put(&self, extra: &mut Extra) {
        extra.tid = self.tid;
        extra.special = self.special;
        extra.args = self.args;
    }
}

/// A thing special set off: the special and its arguments, who set it off.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Fired {
    pub special: i32,
    pub args: [i32; 5],
    pub activator: Option<MobjId>,
}

/// The ZDoom state of a level.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Zdoom {
    /// By body index; only bodies that have a ZDoom field.
    pub bodies: BTreeMap<u32, Extra>,
    /// Specials set off and not yet run, oldest first.
    pub fired: Vec<Fired>,
    /// ViZDoom's tallies, by player.
    pub tallies: [Tally; super::MAXPLAYERS],
}

/// What ViZDoom counts for a player beyond Doom's kills, items and secrets
/// (its game variables `HITCOUNT`, `HITS_TAKEN`, `DAMAGECOUNT`,
/// `DAMAGE_TAKEN`, `DEATHCOUNT`, and the rewards paid on them): hits and
/// damage as `VIZ_LogDmg` logs them, the damage a body loses in health
/// (after armour), a hit over 1,000 (a telefrag) not counted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Tally {
    /// Hits the player's attacks landed on others, and their damage.
    pub hits: i32,
    pub damage: i32,
    /// Hits the player took, and their damage.
    pub hits_taken: i32,
    pub damage_taken: i32,
    /// Times the player died.
    pub deaths: i32,
}

impl Zdoom {
    pub fn get(&self, id: MobjId) -> Option<&Extra> {
        self.bodies.get(&id.0)
    }

    /// The body's fields, made on first use.
    pub fn entry(&mut self, id: MobjId) -> &mut Extra {
        self.bodies.entry(id.0).or_default()
    }

    pub fn tid(&self, id: MobjId) -> i32 {
        self.get(id).map_or(0, |e| e.tid)
    }
}

impl Sim {
    /// Logs `damage` about to come off `target`'s health, by `source`
    /// (ViZDoom's `VIZ_LogDmg`): a player hit counts as taken, else a hit
    /// by a player counts as that player's.
    pub fn log_damage(&mut self, target: MobjId, source: Option<MobjId>, damage: i32) {
        if !(0..=1000).contains(&damage) {
            return;
        }
        if let Some(n) = self.mo(target).player {
            let t = &mut self.zdoom.tallies[n];
            t.hits_taken += 1;
            t.damage_taken += damage;
        } else if let Some(n) = source.and_then(|s| self.mo(s).player) {
            let t = &mut self.zdoom.tallies[n];
            t.hits += 1;
            t.damage += damage;
        }
    }

    /// The live bodies with thing id `tid`, oldest first (0 matches none:
    /// ACS means the activator by it, which the caller resolves).
    pub fn bodies_with_tid(&self, tid: i32) -> Vec<MobjId> {
        if tid == 0 {
            return Vec::new();
        }
        let ids = self.zdoom.bodies.iter().filter(|(_, e)| e.tid == tid).map(|(&i, _)| MobjId(i));
        ids.filter(|&id| !self.mo(id).removed).collect()
    }

    /// A walker's step: its own speed if a script set one.
    pub fn walk_speed(&self, id: MobjId) -> i32 {
        match self.zdoom.get(id).and_then(|e| e.speed) {
            Some(speed) => speed,
            None => self.info.things[self.mo(id).kind].speed,
        }
    }

    /// Damage scaled by the target's damage factor (ZDoom rounds the
    /// product down).
    pub fn scaled_damage(&self, target: MobjId, damage: i32) -> i32 {
        match self.zdoom.get(target).and_then(|e| e.damage_factor) {
            Some(factor) => (Fixed::from_int(damage) * factor).0 >> 16,
            None => damage,
        }
    }

    /// Whether a monster ignores the players (`Thing_Hate` 5, 6).
    pub fn ignores_players(&self, id: MobjId) -> bool {
        self.zdoom.get(id).is_some_and(|e| e.ignores_players)
    }

    /// Whether the body is drawn.
    pub fn invisible(&self, id: MobjId) -> bool {
        self.zdoom.get(id).is_some_and(|e| e.invisible)
    }

    /// ZDoom's `A_Chase` for a monster a script sent to a goal
    /// (`Thing_SetGoal`): it walks to the goal without attacking, and
    /// within melee range of it goes on to the next patrol point (the one
    /// whose thing id is the goal's first argument), or stops having a
    /// goal. Returns whether the monster is walking to a goal this tic.
    /// (ZDoom's wait at a point, its second argument, is not kept: the
    /// scenarios' points have none.)
    pub fn walk_to_goal(&mut self, id: MobjId) -> bool {
        let Some(goal) = self.zdoom.get(id).and_then(|e| e.goal) else { return false };
        if self.mo(goal).removed {
            self.zdoom.entry(id).goal = None;
            return false;
        }
        let (mo, g) = (self.mo(id), self.mo(goal));
        let near = crate::fixed::approx_distance(g.x - mo.x, g.y - mo.y) < super::monsters::MELEERANGE;
        let mut goal = Some(goal);
        if near {
            let next = self.zdoom.get(goal.unwrap_or(id)).map_or(0, |e| e.args[0]);
            goal = self.bodies_with_tid(next).first().copied();
            self.zdoom.entry(id).goal = goal;
        }
        let Some(goal) = goal else {
            self.mo_mut(id).target = None;
            return false;
        };
        self.mo_mut(id).target = Some(goal);
        let actor = self.mo_mut(id);
        actor.movecount -= 1;
        if actor.movecount < 0 || !super::chase::p_move(self, id) {
            super::chase::new_chase_dir(self, id);
        }
        true
    }

    /// A body with a thing special died or was taken: the special is set
    /// off (once: ZDoom clears it as it runs).
    pub fn fire_thing_special(&mut self, id: MobjId, activator: Option<MobjId>) {
        let Some(extra) = self.zdoom.bodies.get_mut(&id.0) else { return };
        if extra.special == 0 {
            return;
        }
        let fired = Fired { special: extra.special, args: extra.args, activator };
        extra.special = 0;
        self.zdoom.fired.push(fired);
    }
}
