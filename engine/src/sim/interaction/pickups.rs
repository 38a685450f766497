//! Items picked up (`p_inter.c`'s first half): `P_TouchSpecialThing`,
//! which, as Doom does, tells an item by its sprite, and the gifts it
//! hands out (`P_GiveAmmo`, `P_GiveWeapon`, `P_GiveBody`, `P_GiveArmor`,
//! `P_GiveCard`, `P_GivePower`). The player's tallies change here; the
//! item leaves the world through [`Sim::remove_mobj`].

use super::doubles_ammo;
use crate::actors::dehacked::{doom_info, Strings};
use crate::actors::AmmoKind;
use crate::fixed::{Fixed, FRACUNIT};
use crate::sim::mobj::mf;
use crate::sim::user::pw;
use crate::sim::weapons::{am, wp};
use crate::sim::{GameMode, MobjId, Player, Sim, TICRATE};

/// `BONUSADD`: the gold flash of a pickup, in tics.
const BONUSADD: i32 = 6;
/// `MAXHEALTH`: what health items heal up to.
const MAXHEALTH: i32 = 100;
/// `clipammo`: a clip's worth of each ammo type.
const CLIPAMMO: [i32; 4] = [10, 4, 20, 1];
/// The powers' durations (`INVULNTICS` ...).
const INVULNTICS: i32 = 30 * TICRATE as i32;
const INVISTICS: i32 = 60 * TICRATE as i32;
const INFRATICS: i32 = 120 * TICRATE as i32;
const IRONTICS: i32 = 60 * TICRATE as i32;
/// DeHackEd's `Misc` values at doom.exe's defaults (`deh_misc.c`).
const GREEN_ARMOR_CLASS: i32 = 1;
const BLUE_ARMOR_CLASS: i32 = 2;
const MAX_HEALTH: i32 = 200;
const MAX_ARMOR: i32 = 200;
const SOULSPHERE_HEALTH: i32 = 100;
const MAX_SOULSPHERE: i32 = 200;
const MEGASPHERE_HEALTH: i32 = 200;

/// `P_GiveAmmo`: `num` clips of `ammo` (0 is half a clip), doubled on the
/// easiest and hardest skills, up to the most the player carries. False
/// when full. Ammo found with none left switches to a better weapon.
pub fn give_ammo(p: &mut Player, ammo: usize, num: i32, double: bool) -> bool {
    let Some(&clip) = CLIPAMMO.get(ammo) else { return false };
    if p.ammo[ammo] == p.maxammo[ammo] {
        return false;
    }
    let mut num = if num != 0 { num * clip } else { clip / 2 };
    if double {
        num <<= 1;
    }
    let oldammo = p.ammo[ammo];
    p.ammo[ammo] = (p.ammo[ammo] + num).min(p.maxammo[ammo]);
    if oldammo != 0 {
        // The player was low on purpose: no change.
        return true;
    }
    let (ready, owned) = (p.readyweapon, p.weaponowned);
    match ammo {
        am::CLIP if ready == wp::FIST => {
            p.pendingweapon = Some(if owned[wp::CHAINGUN] { wp::CHAINGUN } else { wp::PISTOL });
        }
        am::SHELL if (ready == wp::FIST || ready == wp::PISTOL) && owned[wp::SHOTGUN] => {
            p.pendingweapon = Some(wp::SHOTGUN);
        }
        am::CELL if (ready == wp::FIST || ready == wp::PISTOL) && owned[wp::PLASMA] => {
            p.pendingweapon = Some(wp::PLASMA);
        }
        am::MISL if ready == wp::FIST && owned[wp::MISSILE] => p.pendingweapon = Some(wp::MISSILE),
        _ => {}
    }
    true
}

/// `P_GiveWeapon`: weapon `weapon` and its ammo (one clip dropped, two
/// found). In co-op and plain deathmatch a placed weapon stays for the
/// others, and gives nothing to one who has it.
pub fn give_weapon(sim: &mut Sim, n: usize, weapon: usize, dropped: bool) -> bool {
    let ammo = sim.info.weapons.get(weapon).and_then(Option::as_ref).and_then(|w| w.ammo);
    let (netgame, deathmatch, double) = (sim.rules.netgame, sim.rules.deathmatch, doubles_ammo(&sim.rules));
    let console = n == sim.console;
    let Some(p) = sim.players[n].as_mut() else { return false };
    if weapon >= p.weaponowned.len() {
        return false;
    }
    if netgame && deathmatch != 2 && !dropped {
        if p.weaponowned[weapon] {
            return false;
        }
        p.bonuscount += BONUSADD;
        p.weaponowned[weapon] = true;
        if let Some(a) = ammo {
            give_ammo(p, a, if deathmatch != 0 { 5 } else { 2 }, double);
        }
        p.pendingweapon = Some(weapon);
        if console {
            sim.sound_named(None, "wpnup");
        }
        return false;
    }
    let gaveammo = ammo.is_some_and(|a| give_ammo(p, a, if dropped { 1 } else { 2 }, double));
    let gaveweapon = !p.weaponowned[weapon];
    if gaveweapon {
        p.weaponowned[weapon] = true;
        p.pendingweapon = Some(weapon);
    }
    gaveweapon || gaveammo
}

/// `P_GiveBody`: `num` health up to 100; false when already there.
pub fn give_body(sim: &mut Sim, n: usize, num: i32) -> bool {
    let Some(p) = sim.players[n].as_mut() else { return false };
    if p.health >= MAXHEALTH {
        return false;
    }
    p.health = p.health.saturating_add(num).min(MAXHEALTH);
    let (mo, health) = (p.mo, p.health);
    sim.mo_mut(mo).health = health;
    true
}

/// `P_GiveArmor`: armor of class `armortype` (100 points a class); false
/// when the player has as much already.
pub fn give_armor(p: &mut Player, armortype: i32) -> bool {
    let hits = armortype * 100;
    if p.armorpoints >= hits {
        return false;
    }
    p.armortype = armortype;
    p.armorpoints = hits;
    true
}

/// `P_GiveCard`.
pub fn give_card(p: &mut Player, card: usize) {
    if p.cards[card] {
        return;
    }
    p.bonuscount = BONUSADD;
    p.cards[card] = true;
}

/// `P_GivePower`: timed powers restart; berserk heals to 100; the others
/// are given once.
pub fn give_power(sim: &mut Sim, n: usize, power: usize) -> bool {
    if power == pw::STRENGTH {
        give_body(sim, n, 100);
    }
    let Some(p) = sim.players[n].as_mut() else { return false };
    let tics = match power {
        pw::INVULNERABILITY => INVULNTICS,
        pw::INVISIBILITY => INVISTICS,
        pw::INFRARED => INFRATICS,
        pw::IRONFEET => IRONTICS,
        pw::STRENGTH => 1,
        _ if p.powers[power] != 0 => return false,
        _ => 1,
    };
    p.powers[power] = tics;
    if power == pw::INVISIBILITY {
        let mo = p.mo;
        sim.mo_mut(mo).flags |= mf::SHADOW;
    }
    true
}

/// What touching an item did: `None` left it there; otherwise the message
/// and whether the power-up sound plays.
type Taken = Option<(&'static str, Sound)>;

#[derive(Clone, Copy, PartialEq, Eq)]
enum Sound {
    ItemUp,
    GetPow,
    WpnUp,
}

/// `P_TouchSpecialThing`: `toucher` walks onto the item `special`. Within
/// reach (its feet no more than 8 units above the item, the item no higher
/// than its head) a live player takes what the item's sprite says, and
/// the item goes; keys stay for the others in a net game.
pub fn touch_special_thing(sim: &mut Sim, special: MobjId, toucher: MobjId) {
    let (s, t) = (sim.mo(special), sim.mo(toucher));
    let delta = s.z - t.z;
    if delta > t.height || delta < Fixed(-8 * FRACUNIT) {
        return;
    }
    // A sliding corpse touches things too.
    let Some(n) = t.player.filter(|_| t.health > 0) else { return };
    let sprite = usize::try_from(s.sprite).ok().and_then(|i| doom_info().sprites.get(i));
    let Some(sprite) = sprite.map(String::as_str) else { return };
    let dropped = s.has(mf::DROPPED);
    let kind = s.kind;
    let taken = match sprite {
        _ if sim.info.things[kind].mt.is_none() && sim.info.table.actors[kind].pickup.is_some() => {
            take_as_table_says(sim, n, kind)
        }
        "BKEY" | "YKEY" | "RKEY" | "BSKU" | "YSKU" | "RSKU" => {
            take_key(sim, n, sprite);
            if sim.rules.netgame {
                return;
            }
            Some(("", Sound::ItemUp))
        }
        _ => take(sim, n, sprite, dropped),
    };
    let Some((message, sound)) = taken else { return };
    let counted = sim.mo(special).has(mf::COUNTITEM);
    if let Some(p) = sim.players[n].as_mut() {
        if !message.is_empty() {
            p.message = Strings::original(message).map(str::to_string);
        }
        if counted {
            p.itemcount += 1;
        }
    }
    sim.fire_thing_special(special, Some(toucher));
    sim.remove_mobj(special);
    if let Some(p) = sim.players[n].as_mut() {
        p.bonuscount += BONUSADD;
    }
    if n == sim.console {
        let name = match sound {
            Sound::ItemUp => "itemup",
            Sound::GetPow => "getpow",
            Sound::WpnUp => "wpnup",
        };
        sim.sound_named(None, name);
    }
}

/// An actor Doom never had (a DECORATE item): what its pickup data
/// gives, its message shown as written. Only health and ammunition are
/// given this way; any other gift leaves the item where it is.
fn take_as_table_says(sim: &mut Sim, n: usize, kind: usize) -> Taken {
    let table = sim.info.table.clone();
    let pickup = table.actors[kind].pickup.as_ref()?;
    let double = doubles_ammo(&sim.rules);
    let p = sim.players[n].as_mut()?;
    let mut gave = false;
    for give in &pickup.give {
        match *give {
            crate::actors::Give::Health { amount, max } => {
                if p.health < max {
                    p.health = (p.health + amount).min(max);
                    gave = true;
                }
            }
            crate::actors::Give::Ammo(kind, count) => {
                let ammo = match kind {
                    AmmoKind::Bullets => am::CLIP,
                    AmmoKind::Shells => am::SHELL,
                    AmmoKind::Cells => am::CELL,
                    AmmoKind::Rockets => am::MISL,
                };
                let count = if double { count * 2 } else { count };
                if p.ammo[ammo] < p.maxammo[ammo] {
                    p.ammo[ammo] = (p.ammo[ammo] + count).min(p.maxammo[ammo]);
                    gave = true;
                }
            }
            _ => return None,
        }
    }
    if !gave && !pickup.always {
        return None;
    }
    let (mo, health) = (p.mo, p.health);
    p.message = Some(pickup.message.clone()).filter(|m| !m.is_empty());
    sim.mo_mut(mo).health = health;
    Some(("", Sound::ItemUp))
}

/// A key: its message the first time, then the card.
fn take_key(sim: &mut Sim, n: usize, sprite: &str) {
    let (card, message) = match sprite {
        "BKEY" => (0, "GOTBLUECARD"),
        "YKEY" => (1, "GOTYELWCARD"),
        "RKEY" => (2, "GOTREDCARD"),
        "BSKU" => (3, "GOTBLUESKUL"),
        "YSKU" => (4, "GOTYELWSKUL"),
        _ => (5, "GOTREDSKULL"),
    };
    let Some(p) = sim.players[n].as_mut() else { return };
    if !p.cards[card] {
        p.message = Strings::original(message).map(str::to_string);
    }
    give_card(p, card);
}

/// Every other item, by sprite (Doom's switch; an unknown one is left
/// where it lies, where Doom stops with an error).
fn take(sim: &mut Sim, n: usize, sprite: &str, dropped: bool) -> Taken {
    let commercial = sim.rules.mode == GameMode::Commercial;
    let double = doubles_ammo(&sim.rules);
    let ammo = |sim: &mut Sim, ammo: usize, num: i32, message: &'static str| -> Taken {
        let p = sim.players[n].as_mut()?;
        give_ammo(p, ammo, num, double).then_some((message, Sound::ItemUp))
    };
    let power = |sim: &mut Sim, power: usize, message: &'static str| -> Taken {
        give_power(sim, n, power).then_some((message, Sound::GetPow))
    };
    let weapon = |sim: &mut Sim, weapon: usize, dropped: bool, message: &'static str| -> Taken {
        give_weapon(sim, n, weapon, dropped).then_some((message, Sound::WpnUp))
    };
    match sprite {
        "ARM1" => give_armor(sim.players[n].as_mut()?, GREEN_ARMOR_CLASS).then_some(("GOTARMOR", Sound::ItemUp)),
        "ARM2" => give_armor(sim.players[n].as_mut()?, BLUE_ARMOR_CLASS).then_some(("GOTMEGA", Sound::ItemUp)),
        "BON1" => {
            let p = sim.players[n].as_mut()?;
            // Health bonuses go past 100.
            p.health = (p.health + 1).min(MAX_HEALTH);
            let (mo, health) = (p.mo, p.health);
            sim.mo_mut(mo).health = health;
            Some(("GOTHTHBONUS", Sound::ItemUp))
        }
        "BON2" => {
            let p = sim.players[n].as_mut()?;
            p.armorpoints = (p.armorpoints + 1).min(MAX_ARMOR);
            // A helmet is always class 1, whatever the green armor's class.
            if p.armortype == 0 {
                p.armortype = 1;
            }
            Some(("GOTARMBONUS", Sound::ItemUp))
        }
        "SOUL" => {
            let p = sim.players[n].as_mut()?;
            p.health = (p.health + SOULSPHERE_HEALTH).min(MAX_SOULSPHERE);
            let (mo, health) = (p.mo, p.health);
            sim.mo_mut(mo).health = health;
            Some(("GOTSUPER", Sound::GetPow))
        }
        "MEGA" => {
            if !commercial {
                return None;
            }
            let p = sim.players[n].as_mut()?;
            p.health = MEGASPHERE_HEALTH;
            give_armor(p, 2);
            let (mo, health) = (p.mo, p.health);
            sim.mo_mut(mo).health = health;
            Some(("GOTMSPHERE", Sound::GetPow))
        }
        "STIM" => give_body(sim, n, 10).then_some(("GOTSTIM", Sound::ItemUp)),
        "MEDI" => {
            if !give_body(sim, n, 25) {
                return None;
            }
            // Doom tests the health after healing: "really need" shows
            // only when it is still under 25.
            let low = sim.player(n).is_some_and(|p| p.health < 25);
            Some((if low { "GOTMEDINEED" } else { "GOTMEDIKIT" }, Sound::ItemUp))
        }
        "PINV" => power(sim, pw::INVULNERABILITY, "GOTINVUL"),
        "PSTR" => {
            let taken = power(sim, pw::STRENGTH, "GOTBERSERK")?;
            let p = sim.players[n].as_mut()?;
            if p.readyweapon != wp::FIST {
                p.pendingweapon = Some(wp::FIST);
            }
            Some(taken)
        }
        "PINS" => power(sim, pw::INVISIBILITY, "GOTINVIS"),
        "SUIT" => power(sim, pw::IRONFEET, "GOTSUIT"),
        "PMAP" => power(sim, pw::ALLMAP, "GOTMAP"),
        "PVIS" => power(sim, pw::INFRARED, "GOTVISOR"),
        "CLIP" => ammo(sim, am::CLIP, if dropped { 0 } else { 1 }, "GOTCLIP"),
        "AMMO" => ammo(sim, am::CLIP, 5, "GOTCLIPBOX"),
        "ROCK" => ammo(sim, am::MISL, 1, "GOTROCKET"),
        "BROK" => ammo(sim, am::MISL, 5, "GOTROCKBOX"),
        "CELL" => ammo(sim, am::CELL, 1, "GOTCELL"),
        "CELP" => ammo(sim, am::CELL, 5, "GOTCELLBOX"),
        "SHEL" => ammo(sim, am::SHELL, 1, "GOTSHELLS"),
        "SBOX" => ammo(sim, am::SHELL, 5, "GOTSHELLBOX"),
        "BPAK" => {
            let p = sim.players[n].as_mut()?;
            if !p.backpack {
                for max in &mut p.maxammo {
                    *max *= 2;
                }
                p.backpack = true;
            }
            for a in 0..4 {
                give_ammo(p, a, 1, double);
            }
            Some(("GOTBACKPACK", Sound::ItemUp))
        }
        "BFUG" => weapon(sim, wp::BFG, false, "GOTBFG9000"),
        "MGUN" => weapon(sim, wp::CHAINGUN, dropped, "GOTCHAINGUN"),
        "CSAW" => weapon(sim, wp::CHAINSAW, false, "GOTCHAINSAW"),
        "LAUN" => weapon(sim, wp::MISSILE, false, "GOTLAUNCHER"),
        "PLAS" => weapon(sim, wp::PLASMA, false, "GOTPLASMA"),
        "SHOT" => weapon(sim, wp::SHOTGUN, dropped, "GOTSHOTGUN"),
        "SGN2" => weapon(sim, wp::SUPERSHOTGUN, dropped, "GOTSHOTGUN2"),
        _ => None,
    }
}
