//! ACS on the simulation: [`SimHost`] answers the VM's calls (`acs::Host`)
//! by acting on a [`Sim`], as ZDoom's `p_acs.cpp` and `p_lnspec.cpp` act on
//! its actors. Things are found by thing id ([`Sim::bodies_with_tid`]); id 0
//! is the script's activator. Items and weapons are ZDoom's class names
//! (`Clip`, `ClipBox`, `Pistol`, `RocketLauncher`, `Medikit`, ...) on
//! Doom's player (`Player::ammo`, `weaponowned`, health, armour).
//!
//! What ZDoom does that the calls reproduce:
//! - `GiveInventory(item, n)` gives a spawned item whose amount is `n`
//!   (ZDoom's `DoGiveInv`): `ClipBox` 6 gives 6 bullets, not six boxes,
//!   and Nightmare and the easiest skill double it as they double pickups;
//!   a weapon gives its own ammunition (`Weapon.AmmoGive`) and comes up
//!   only if the player holds none (from the next tic, as ZDoom's player
//!   brings a weapon up for an unarmed player when it next thinks).
//! - `Spawn` places the thing at the height given (0: the floor, on these
//!   maps at 0) and removes it again when it does not fit there
//!   (`P_TestMobjLocation`), returning 0; a spawned pickup is `DROPPED`.
//! - `SetActorProperty`: health (a player's too), speed (a monster's step
//!   in whole units), damage factor, render style `STYLE_None`.
//! - `Thing_Hate` with types 5 and 6 makes a monster ignore the players
//!   (the hatee's id is kept; no scenario's hatee exists).

use rand::rngs::ChaCha8Rng;
use rand::RngExt;

use crate::acs::{Activator, Host, HostCx, PrintKind};
use crate::fixed::{Angle, Fixed};
use crate::sim::interaction::{self, pickups};
use crate::sim::mobj::mf;
use crate::sim::weapons::{self, wp};
use crate::sim::{collision, specials, MobjId, Sim};

/// ZDoom's `APROP_*` numbers (`zdefs.acs`).
mod aprop {
    pub const HEALTH: i32 = 0;
    pub const SPEED: i32 = 1;
    pub const DAMAGE: i32 = 2;
    pub const RENDER_STYLE: i32 = 4;
    pub const SEE_SOUND: i32 = 5;
    pub const ATTACK_SOUND: i32 = 6;
    pub const PAIN_SOUND: i32 = 7;
    pub const DEATH_SOUND: i32 = 8;
    pub const ACTIVE_SOUND: i32 = 9;
    pub const SPAWN_HEALTH: i32 = 17;
    pub const DAMAGE_FACTOR: i32 = 24;
}

/// ZDoom's line specials the scenarios' scripts call.
mod lspec {
    pub const THING_ACTIVATE: i32 = 130;
    pub const THING_REMOVE: i32 = 132;
    pub const THING_DAMAGE: i32 = 119;
    pub const THING_CHANGE_TID: i32 = 176;
    pub const THING_HATE: i32 = 177;
    pub const THING_SET_GOAL: i32 = 229;
    pub const EXIT_NORMAL: i32 = 243;
    pub const EXIT_SECRET: i32 = 244;
    pub const HEAL_THING: i32 = 248;
}

/// The game pcodes (their stack forms' numbers, `acs::pcodes`).
mod op {
    pub const PLAYERCOUNT: u16 = 90;
    pub const GAMETYPE: u16 = 91;
    pub const GAMESKILL: u16 = 92;
    pub const TIMER: u16 = 93;
    pub const SINGLEPLAYER: u16 = 135;
    pub const CLEARINVENTORY: u16 = 142;
    pub const GIVEINVENTORY: u16 = 143;
    pub const TAKEINVENTORY: u16 = 145;
    pub const CHECKINVENTORY: u16 = 147;
    pub const SPAWN: u16 = 149;
    pub const SPAWNSPOT: u16 = 151;
    pub const SETTHINGSPECIAL: u16 = 180;
    pub const GETACTORX: u16 = 196;
    pub const GETACTORY: u16 = 197;
    pub const GETACTORZ: u16 = 198;
    pub const CHECKWEAPON: u16 = 223;
    pub const SETWEAPON: u16 = 224;
    pub const SETACTORPROPERTY: u16 = 245;
    pub const GETACTORPROPERTY: u16 = 246;
    pub const PLAYERNUMBER: u16 = 247;
    pub const ACTIVATORTID: u16 = 248;
    pub const GETACTORANGLE: u16 = 260;
    pub const SETACTORANGLE: u16 = 276;
    pub const SETACTORPOSITION: u16 = 283;
}

/// `ACSF_PlaySound`.
const PLAY_SOUND: u16 = 61;
/// The extended functions the game serves.
pub const SUPPORTED_FUNCTIONS: [u16; 1] = [PLAY_SOUND];

/// Doom's weapons by ZDoom's class names, with `Weapon.AmmoGive`.
const WEAPONS: [(&str, usize, i32); 9] = [
    ("Fist", wp::FIST, 0),
    ("Pistol", wp::PISTOL, 20),
    ("Shotgun", wp::SHOTGUN, 8),
    ("Chaingun", wp::CHAINGUN, 20),
    ("RocketLauncher", wp::MISSILE, 2),
    ("PlasmaRifle", wp::PLASMA, 40),
    ("BFG9000", wp::BFG, 40),
    ("Chainsaw", wp::CHAINSAW, 0),
    ("SuperShotgun", wp::SUPERSHOTGUN, 8),
];

/// Doom's ammunition by ZDoom's class names (the big ones count as their
/// parent when given with an amount, as ZDoom's `AAmmo::HandlePickup`).
const AMMO: [(&str, usize); 8] = [
    ("Clip", 0),
    ("ClipBox", 0),
    ("Shell", 1),
    ("ShellBox", 1),
    ("Cell", 2),
    ("CellPack", 2),
    ("RocketAmmo", 3),
    ("RocketBox", 3),
];

/// Doom's weapon of ZDoom class `item`, and its `Weapon.AmmoGive`.
fn doom_weapon(item: &str) -> Option<(usize, i32)> {
    WEAPONS.iter().find(|(name, ..)| name.eq_ignore_ascii_case(item)).map(|&(_, w, give)| (w, give))
}

/// Doom's ammunition type of ZDoom class `item` (a box counts as its kind).
fn ammo_named(item: &str) -> Option<usize> {
    AMMO.iter().find(|(name, _)| name.eq_ignore_ascii_case(item)).map(|&(_, a)| a)
}

/// ZDoom's ammunition factor for the skill (`SKILLP_AmmoFactor`): double
/// on the easiest skill and on Nightmare.
fn ammo_factor(sim: &Sim) -> i32 {
    if sim.rules.skill == 0 || sim.rules.skill == crate::sim::Rules::NIGHTMARE {
        2
    } else {
        1
    }
}

/// The VM's view of one game: the simulation, the scripts' own random
/// generator (ZDoom's `pr_acs`), and what scripts printed.
pub struct SimHost<'a> {
    pub sim: &'a mut Sim,
    pub rng: &'a mut ChaCha8Rng,
    /// Printed and logged text, oldest first.
    pub printed: &'a mut Vec<String>,
    /// Calls the simulation does not carry out, named once each.
    pub unsupported: &'a mut Vec<String>,
}

impl SimHost<'_> {
    /// The body an activator names.
    fn activator_body(&self, activator: Activator) -> Option<MobjId> {
        match activator {
            Activator::Thing(i) => {
                let id = MobjId(u32::try_from(i).ok()?);
                ((id.0 as usize) < self.sim.mobjs.len()).then_some(id)
            }
            Activator::World => None,
        }
    }

    /// The bodies `tid` names: the activator for 0.
    fn things(&self, tid: i32, activator: Activator) -> Vec<MobjId> {
        if tid == 0 {
            return self.activator_body(activator).into_iter().collect();
        }
        self.sim.bodies_with_tid(tid)
    }

    /// The first body `tid` names.
    fn thing(&self, tid: i32, activator: Activator) -> Option<MobjId> {
        self.things(tid, activator).into_iter().next()
    }

    /// The player whose body the activator is.
    fn player_of(&self, activator: Activator) -> Option<usize> {
        self.activator_body(activator).and_then(|b| self.sim.mo(b).player)
    }

    fn unsupported(&mut self, what: String) {
        if !self.unsupported.contains(&what) {
            self.unsupported.push(what);
        }
    }

    fn give(&mut self, n: usize, item: &str, amount: i32) {
        let amount = amount.max(1);
        if let Some((w, ammo_give)) = doom_weapon(item) {
            self.give_weapon(n, w, ammo_give);
            return;
        }
        if let Some(a) = ammo_named(item) {
            let factor = ammo_factor(self.sim);
            if let Some(p) = self.sim.players[n].as_mut() {
                p.ammo[a] = p.ammo[a].saturating_add(amount.saturating_mul(factor)).min(p.maxammo[a]);
            }
            return;
        }
        let health = match item.to_ascii_lowercase().as_str() {
            "stimpack" => Some(10i32),
            "medikit" => Some(25),
            _ => None,
        };
        if let Some(h) = health {
            pickups::give_body(self.sim, n, h.saturating_mul(amount));
            return;
        }
        if let Some((w, ammo_give)) = self.custom_weapon(item) {
            self.give_weapon(n, w, ammo_give);
            return;
        }
        self.unsupported(format!("GiveInventory(\"{item}\") (not an item this game knows)"));
    }

    /// Weapon `w` with `ammo_give` of its ammunition (times the skill's
    /// factor); it comes up only for an unarmed player, from the next tic
    /// on (`Scripts::tick`).
    fn give_weapon(&mut self, n: usize, w: usize, ammo_give: i32) {
        let ammo = self.sim.info.weapons.get(w).and_then(Option::as_ref).and_then(|i| i.ammo);
        let factor = ammo_factor(self.sim);
        let Some(p) = self.sim.players[n].as_mut() else { return };
        if let Some(a) = ammo {
            p.ammo[a] = p.ammo[a].saturating_add(ammo_give.saturating_mul(factor)).min(p.maxammo[a]);
        }
        if !p.weaponowned[w] {
            p.weaponowned[w] = true;
            if p.psprites[0].state.is_none() {
                p.pendingweapon = Some(w);
            }
        }
    }

    /// A DECORATE weapon (`CustomRocketLauncher`): the player holds Doom's
    /// nine weapons, so it takes the place of Doom's weapon with the same
    /// ammunition (the rocket launcher for rockets, the pistol for
    /// bullets, ...) in this game's weapon table, its states and actions
    /// its own. Returns that weapon's number and the ammunition its pickup
    /// gives.
    fn custom_weapon(&mut self, item: &str) -> Option<(usize, i32)> {
        let table = self.sim.info.table.clone();
        let kind = crate::actors::zdoom::find(&table, item)?;
        let def = &table.actors[kind];
        let weapon = def.weapon.as_ref()?;
        let w = match weapon.ammo {
            Some(crate::actors::AmmoKind::Bullets) => wp::PISTOL,
            Some(crate::actors::AmmoKind::Shells) => wp::SHOTGUN,
            Some(crate::actors::AmmoKind::Rockets) => wp::MISSILE,
            Some(crate::actors::AmmoKind::Cells) => wp::PLASMA,
            None => wp::FIST,
        };
        let ammo_give = def.pickup.iter().flat_map(|p| p.give.iter()).find_map(|g| match g {
            crate::actors::Give::Ammo(_, n) => Some(*n),
            _ => None,
        });
        let info = std::sync::Arc::make_mut(&mut self.sim.info);
        let slot = info.weapons.get_mut(w)?;
        let ammo = slot.as_ref().and_then(|s| s.ammo);
        *slot = Some(crate::sim::info::WeaponInfo {
            actor: kind,
            ammo,
            upstate: def.label("Select"),
            downstate: def.label("Deselect"),
            readystate: def.label("Ready"),
            atkstate: def.label("Fire"),
            flashstate: def.label("Flash"),
        });
        Some((w, ammo_give.unwrap_or(0)))
    }

    fn take(&mut self, n: usize, item: &str, amount: i32) {
        let Some(p) = self.sim.players[n].as_mut() else { return };
        if let Some((w, _)) = doom_weapon(item) {
            p.weaponowned[w] = false;
            return;
        }
        if let Some(a) = ammo_named(item) {
            p.ammo[a] = p.ammo[a].saturating_sub(amount.max(0)).max(0);
            return;
        }
        self.unsupported(format!("TakeInventory(\"{item}\")"));
    }

    fn count(&self, n: usize, item: &str) -> i32 {
        let Some(p) = self.sim.player(n) else { return 0 };
        if let Some((w, _)) = doom_weapon(item) {
            return i32::from(p.weaponowned[w]);
        }
        if let Some(a) = ammo_named(item) {
            return p.ammo[a];
        }
        if item.eq_ignore_ascii_case("Health") {
            return p.health;
        }
        0
    }

    /// `ClearInventory`: weapons and ammunition gone, the weapon lowered
    /// out of sight (ZDoom leaves the player unarmed until given one).
    fn clear(&mut self, n: usize) {
        let Some(p) = self.sim.players[n].as_mut() else { return };
        p.weaponowned = [false; crate::sim::NUMWEAPONS];
        p.ammo = [0; crate::sim::NUMAMMO];
        p.backpack = false;
        p.pendingweapon = None;
        weapons::set_psprite(self.sim, n, 0, None);
        weapons::set_psprite(self.sim, n, 1, None);
    }

    /// ACS `Spawn`: the thing at (x, y, z), or nothing where it does not fit.
    fn spawn(&mut self, class: &str, x: i32, y: i32, z: i32, tid: i32, angle: i32) -> i32 {
        let Some(kind) = crate::actors::zdoom::find(&self.sim.info.table, class) else {
            self.unsupported(format!("Spawn(\"{class}\") (no such actor)"));
            return 0;
        };
        let id = self.sim.spawn_mobj(Fixed(x), Fixed(y), Fixed(z), kind);
        if !self.fits(id) {
            self.sim.remove_mobj(id);
            return 0;
        }
        let mo = self.sim.mo_mut(id);
        mo.angle = Angle((angle as u32) << 24);
        if mo.has(mf::SPECIAL) {
            mo.flags |= mf::DROPPED;
        }
        self.sim.count_in_totals(id);
        self.sim.zdoom.entry(id).tid = tid;
        1
    }

    /// `P_TestMobjLocation`: nothing solid in the way, and between the
    /// floor and the ceiling there.
    fn fits(&mut self, id: MobjId) -> bool {
        let flags = self.sim.mo(id).flags;
        self.sim.mo_mut(id).flags &= !mf::PICKUP;
        let (x, y) = (self.sim.mo(id).x, self.sim.mo(id).y);
        let ok = collision::check_position(self.sim, id, x, y);
        self.sim.mo_mut(id).flags = flags;
        let mo = self.sim.mo(id);
        ok && mo.z >= self.sim.tm.floorz && mo.z + mo.height <= self.sim.tm.ceilingz
    }

    /// `SetActorPosition`: moves the thing if it fits there.
    fn set_position(&mut self, id: MobjId, x: i32, y: i32, z: i32) -> bool {
        let (ox, oy, oz) = (self.sim.mo(id).x, self.sim.mo(id).y, self.sim.mo(id).z);
        self.sim.unset_thing_position(id);
        let mo = self.sim.mo_mut(id);
        (mo.x, mo.y, mo.z) = (Fixed(x), Fixed(y), Fixed(z));
        self.sim.set_thing_position(id);
        if self.fits(id) {
            let (floor, ceiling) = (self.sim.tm.floorz, self.sim.tm.ceilingz);
            let mo = self.sim.mo_mut(id);
            mo.floorz = floor;
            mo.ceilingz = ceiling;
            if mo.z < floor {
                mo.z = floor;
            }
            if let Some(n) = mo.player {
                let viewheight = self.sim.player(n).map_or(Fixed::ZERO, |p| p.viewheight);
                let z = self.sim.mo(id).z;
                if let Some(p) = self.sim.players[n].as_mut() {
                    p.viewz = z + viewheight;
                }
            }
            return true;
        }
        self.sim.unset_thing_position(id);
        let mo = self.sim.mo_mut(id);
        (mo.x, mo.y, mo.z) = (ox, oy, oz);
        self.sim.set_thing_position(id);
        false
    }

    fn set_property(&mut self, id: MobjId, property: i32, value: i32) {
        match property {
            aprop::HEALTH => {
                self.sim.mo_mut(id).health = value;
                if let Some(n) = self.sim.mo(id).player {
                    if let Some(p) = self.sim.players[n].as_mut() {
                        p.health = value;
                    }
                }
            }
            aprop::SPEED => self.sim.zdoom.entry(id).speed = Some(value >> 16),
            aprop::DAMAGE_FACTOR => self.sim.zdoom.entry(id).damage_factor = Some(Fixed(value)),
            aprop::RENDER_STYLE => self.sim.zdoom.entry(id).invisible = value == 0,
            _ => self.unsupported(format!("SetActorProperty property {property}")),
        }
    }

    fn get_property(&mut self, id: MobjId, property: i32, cx: &mut HostCx) -> i32 {
        let mo = self.sim.mo(id);
        let info = &self.sim.info.things[mo.kind];
        let sound = |s: usize| self.sim.info.table.sounds.get(s.wrapping_sub(1)).cloned().unwrap_or_default();
        match property {
            aprop::HEALTH => mo.health,
            aprop::SPEED => self.sim.walk_speed(id) << 16,
            aprop::DAMAGE => info.damage,
            aprop::SPAWN_HEALTH => info.spawnhealth,
            aprop::SEE_SOUND => cx.strings.add(&sound(info.seesound)),
            aprop::ATTACK_SOUND => cx.strings.add(&sound(info.attacksound)),
            aprop::PAIN_SOUND => cx.strings.add(&sound(info.painsound)),
            aprop::DEATH_SOUND => cx.strings.add(&sound(info.deathsound)),
            aprop::ACTIVE_SOUND => cx.strings.add(&sound(info.activesound)),
            aprop::DAMAGE_FACTOR => self.sim.zdoom.get(id).and_then(|e| e.damage_factor).map_or(1 << 16, |f| f.0),
            _ => {
                self.unsupported(format!("GetActorProperty property {property}"));
                0
            }
        }
    }

    fn text(cx: &HostCx, id: i32) -> String {
        cx.strings.get(id).unwrap_or_default().to_string()
    }
}

impl Host for SimHost<'_> {
    fn random(&mut self, min: i32, max: i32) -> i32 {
        self.rng.random_range(min..=max)
    }

    fn line_special(&mut self, special: i32, args: [i32; 5], cx: &mut HostCx) -> i32 {
        let activator = cx.activator;
        match special {
            lspec::EXIT_NORMAL | lspec::EXIT_SECRET => {
                specials::exit_level(self.sim, special == lspec::EXIT_SECRET);
                1
            }
            lspec::THING_REMOVE => {
                for id in self.things(args[0], activator) {
                    if self.sim.mo(id).player.is_none() {
                        self.sim.remove_mobj(id);
                    }
                }
                1
            }
            lspec::THING_DAMAGE => {
                for id in self.things(args[0], activator) {
                    interaction::damage_mobj(self.sim, id, None, None, args[1]);
                }
                1
            }
            lspec::HEAL_THING => {
                if let Some(n) = self.player_of(activator) {
                    pickups::give_body(self.sim, n, args[0]);
                }
                1
            }
            lspec::THING_CHANGE_TID => {
                for id in self.things(args[0], activator) {
                    self.sim.zdoom.entry(id).tid = args[1];
                }
                1
            }
            lspec::THING_HATE => {
                for id in self.things(args[0], activator) {
                    let extra = self.sim.zdoom.entry(id);
                    extra.hates = args[1];
                    if args[2] == 5 || args[2] == 6 {
                        extra.ignores_players = true;
                    }
                    let target = self.sim.mo(id).target;
                    if args[1] != 0 && target.is_some_and(|t| self.sim.zdoom.tid(t) != args[1]) {
                        self.sim.mo_mut(id).target = None;
                    }
                }
                1
            }
            lspec::THING_SET_GOAL => {
                let goal = self.sim.bodies_with_tid(args[1]).into_iter().next();
                for id in self.things(args[0], activator) {
                    self.sim.zdoom.entry(id).goal = goal;
                    if let Some(g) = goal {
                        self.sim.mo_mut(id).target = Some(g);
                        let see = self.sim.info.things[self.sim.mo(id).kind].seestate;
                        self.sim.set_mobj_state(id, see);
                    }
                }
                1
            }
            lspec::THING_ACTIVATE => 1,
            _ => {
                self.unsupported(format!("line special {special}"));
                0
            }
        }
    }

    fn game(&mut self, pcode: u16, args: &[i32], cx: &mut HostCx) -> i32 {
        let arg = |i: usize| args.get(i).copied().unwrap_or(0);
        let activator = cx.activator;
        let player = self.player_of(activator);
        match pcode {
            op::PLAYERCOUNT => self.sim.players.iter().flatten().filter(|p| p.health > 0).count() as i32,
            op::GAMETYPE => i32::from(self.sim.rules.deathmatch != 0) * 2,
            op::GAMESKILL => i32::from(self.sim.rules.skill),
            op::TIMER => self.sim.leveltime as i32,
            op::SINGLEPLAYER => i32::from(!self.sim.rules.netgame),
            op::CLEARINVENTORY => {
                if let Some(n) = player {
                    self.clear(n);
                }
                0
            }
            op::GIVEINVENTORY | op::TAKEINVENTORY => {
                let item = Self::text(cx, arg(0));
                if let Some(n) = player {
                    if pcode == op::GIVEINVENTORY {
                        self.give(n, &item, arg(1));
                    } else {
                        self.take(n, &item, arg(1));
                    }
                }
                0
            }
            op::CHECKINVENTORY => player.map_or(0, |n| self.count(n, &Self::text(cx, arg(0)))),
            op::SPAWN => {
                let class = Self::text(cx, arg(0));
                self.spawn(&class, arg(1), arg(2), arg(3), arg(4), arg(5))
            }
            op::SPAWNSPOT => {
                let class = Self::text(cx, arg(0));
                let spots = self.sim.bodies_with_tid(arg(1));
                let mut made = 0;
                for spot in spots {
                    let (x, y, z) = (self.sim.mo(spot).x, self.sim.mo(spot).y, self.sim.mo(spot).z);
                    made += self.spawn(&class, x.0, y.0, z.0, arg(2), arg(3));
                }
                made
            }
            op::SETTHINGSPECIAL => {
                for id in self.things(arg(0), activator) {
                    let extra = self.sim.zdoom.entry(id);
                    extra.special = arg(1);
                    extra.args = [arg(2), arg(3), arg(4), arg(5), arg(6)];
                }
                0
            }
            op::GETACTORX | op::GETACTORY | op::GETACTORZ => self.thing(arg(0), activator).map_or(0, |id| {
                let mo = self.sim.mo(id);
                match pcode {
                    op::GETACTORX => mo.x.0,
                    op::GETACTORY => mo.y.0,
                    _ => mo.z.0,
                }
            }),
            op::GETACTORANGLE => self.thing(arg(0), activator).map_or(0, |id| (self.sim.mo(id).angle.0 >> 16) as i32),
            op::SETACTORANGLE => {
                for id in self.things(arg(0), activator) {
                    self.sim.mo_mut(id).angle = Angle((arg(1) as u32) << 16);
                }
                0
            }
            op::SETACTORPOSITION => {
                self.thing(arg(0), activator).map_or(0, |id| i32::from(self.set_position(id, arg(1), arg(2), arg(3))))
            }
            op::SETACTORPROPERTY => {
                for id in self.things(arg(0), activator) {
                    self.set_property(id, arg(1), arg(2));
                }
                0
            }
            op::GETACTORPROPERTY => match self.thing(arg(0), activator) {
                Some(id) => self.get_property(id, arg(1), cx),
                None => 0,
            },
            op::CHECKWEAPON => {
                let name = Self::text(cx, arg(0));
                let ready = player.and_then(|n| self.sim.player(n)).map(|p| p.readyweapon);
                let named = doom_weapon(&name).map(|(w, _)| w);
                i32::from(ready.is_some() && ready == named)
            }
            op::SETWEAPON => {
                let name = Self::text(cx, arg(0));
                let named = doom_weapon(&name).map(|(w, _)| w);
                match (player, named) {
                    (Some(n), Some(w)) => {
                        let Some(p) = self.sim.players[n].as_mut() else { return 0 };
                        if !p.weaponowned[w] {
                            return 0;
                        }
                        if p.readyweapon != w || p.psprites[0].state.is_none() {
                            p.pendingweapon = Some(w);
                        }
                        1
                    }
                    _ => 0,
                }
            }
            op::PLAYERNUMBER => player.map_or(-1, |n| n as i32),
            op::ACTIVATORTID => self.activator_body(activator).map_or(0, |id| self.sim.zdoom.tid(id)),
            _ => {
                let name = crate::acs::pcodes::name(pcode);
                self.unsupported(format!("{name} (pcode {pcode})"));
                0
            }
        }
    }

    fn supports_function(&self, id: u16) -> bool {
        SUPPORTED_FUNCTIONS.contains(&id)
    }

    fn function(&mut self, id: u16, args: &[i32], cx: &mut HostCx) -> i32 {
        if id == PLAY_SOUND {
            // PlaySound(tid, sound, ...): Doom's sound of that name.
            let name = Self::text(cx, args.get(1).copied().unwrap_or(0));
            let origin = self.thing(args.first().copied().unwrap_or(0), cx.activator);
            let short = name.rsplit('/').next().unwrap_or(&name).to_string();
            let sound = self.sim.info.sound(&name).max(self.sim.info.sound(&short));
            self.sim.sound(origin, sound);
        }
        0
    }

    fn print(&mut self, _kind: PrintKind, text: &str, _activator: Activator) {
        self.printed.push(text.to_string());
    }

    fn sectors_busy(&mut self, tag: i32) -> bool {
        let level = &self.sim.level;
        level.sectors.iter().any(|s| i32::from(s.tag) == tag && s.specialdata.is_some())
    }

    fn polyobj_busy(&mut self, _po: i32) -> bool {
        false
    }

    fn has_lock(&mut self, _lock: i32, _activator: Activator) -> bool {
        false
    }
}
