//! Things the player picks up by walking over them (Doom's
//! P_TouchSpecialThing), as the actor table describes them: each pickup
//! actor's `give` list (health, armour, ammunition, weapons, keys, power-ups,
//! the backpack), its message and sound. A pickup that would give nothing
//! is left where it is, unless it is always taken (bonuses, spheres).
//! Only the items in the grid cells near the player are looked at.

use super::actors::Actors;
use super::events::{Event, Origin};
use super::player::{Key, Player, HEIGHT, RADIUS};
use crate::actors::{ActorFlag, ActorTable, AmmoKind, Give, Pickup, Power};
use crate::level::Level;

/// The gold tint a pickup adds (Doom's BONUSADD).
const BONUS_ADD: i32 = 6;

/// Ticks each power-up lasts (Doom's INVULNTICS, INVISTICS, IRONTICS,
/// INFRATICS); berserk and the map last the level.
fn power_ticks(power: Power) -> i32 {
    let seconds = match power {
        Power::Invulnerability => 30,
        Power::Invisibility | Power::IronFeet => 60,
        Power::Infrared => 120,
        Power::Strength | Power::AllMap => return 1,
    };
    seconds * 35
}

/// Index of a power in [`Player::powers`].
pub fn power_slot(power: Power) -> usize {
    power as usize
}

fn ammo_slot(kind: AmmoKind) -> usize {
    kind.index()
}

/// Gives what `pickup` gives; whether anything was taken. `dropped`: a
/// monster dropped it (half the ammunition); `skill`: Doom's skills 1 and
/// 5 double ammunition.
pub fn give(player: &mut Player, pickup: &Pickup, table: &ActorTable, dropped: bool, skill: u8) -> bool {
    let mut took = false;
    for g in &pickup.give {
        took |= match *g {
            Give::Health { amount, max } => {
                let before = player.health;
                player.health = (player.health + amount).min(max).max(player.health);
                player.health > before
            }
            Give::Armor { points, class } => {
                if player.armor >= points {
                    false
                } else {
                    (player.armor, player.armor_class) = (points, class);
                    true
                }
            }
            Give::ArmorBonus { points, max } => {
                player.armor = (player.armor + points).min(max);
                if player.armor_class == 0 {
                    player.armor_class = 1;
                }
                true
            }
            Give::Ammo(kind, amount) => {
                let k = ammo_slot(kind);
                let mut n = if dropped { (amount / 2).max(1) } else { amount };
                if skill == 1 || skill == 5 {
                    n *= 2;
                }
                let before = player.ammo[k];
                player.ammo[k] = (player.ammo[k] + n).min(player.max_ammo[k]);
                player.ammo[k] > before
            }
            Give::Weapon(ref name) => match table.index(name) {
                Some(w) if !player.weapons.contains(&w) => {
                    player.weapons.push(w);
                    true
                }
                _ => false,
            },
            // A key is always taken in a single-player game (Doom's
            // P_TouchSpecialThing), owned already or not.
            Give::Key(colour, form) => {
                let key = Key { colour, form };
                if !player.keys.contains(&key) {
                    player.keys.push(key);
                }
                true
            }
            Give::Power(power) => {
                let slot = &mut player.powers[power_slot(power)];
                *slot = (*slot).max(power_ticks(power));
                true
            }
            Give::Backpack => {
                if !player.backpack {
                    player.backpack = true;
                    for m in &mut player.max_ammo {
                        *m *= 2;
                    }
                }
                for (k, kind) in AmmoKind::ALL.iter().enumerate() {
                    // One clip of each (Doom's clipammo).
                    let clip = match kind {
                        AmmoKind::Bullets => 10,
                        AmmoKind::Shells => 4,
                        AmmoKind::Rockets => 1,
                        AmmoKind::Cells => 20,
                    };
                    player.ammo[k] = (player.ammo[k] + clip).min(player.max_ammo[k]);
                }
                true
            }
        };
    }
    took || pickup.always
}

/// Picks up every pickup actor the player touches: their boxes overlap
/// (Doom tests squares, not circles) and the thing is within reach of the
/// body's height (from 8 under the feet to the top of the head). Returns
/// how many counted as items.
pub fn touch(actors: &mut Actors, level: &mut Level, player: &mut Player, events: &mut Vec<Event>, skill: u8) -> u32 {
    if player.dead() {
        return 0;
    }
    let mut items = 0;
    let table = actors.table.clone();
    let reach = glam::DVec2::splat(RADIUS);
    let near = actors.near(player.pos - reach, player.pos + reach);
    for &n in &near {
        let n = n as usize;
        let a = &actors.list[n];
        if a.removed {
            continue;
        }
        let def = &table.actors[a.kind];
        let Some(pickup) = def.pickup.as_ref().filter(|_| a.flags.has(ActorFlag::Special)) else { continue };
        let reach = def.radius + RADIUS;
        let d = (a.pos - player.pos).abs();
        let z = a.z - player.z;
        if d.x >= reach || d.y >= reach || z > HEIGHT || z < -8.0 {
            continue;
        }
        if !give(player, pickup, &table, a.flags.has(ActorFlag::Dropped), skill) {
            continue;
        }
        items += u32::from(def.has(ActorFlag::CountItem));
        if let Some(i) = actors.list[n].thing {
            level.thing_shown[i] = false;
        }
        actors.remove(n);
        player.bonus_count = (player.bonus_count + BONUS_ADD).min(100);
        events.push(Event::Message(pickup.message.clone()));
        if let Some(s) = crate::actors::sounds::doom().iter().find(|s| s.name == pickup.sound) {
            events.push(Event::Sound { sound: s.name.as_str(), origin: Origin::Player });
        }
    }
    actors.give_back(near);
    items
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    fn player() -> Player {
        Player::new(DVec2::ZERO, 0.0, 0, 0.0, 128.0)
    }

    fn pickup(name: &str) -> &'static Pickup {
        ActorTable::doom().get(name).and_then(|a| a.pickup.as_ref()).unwrap_or_else(|| panic!("{name}"))
    }

    fn take(p: &mut Player, name: &str) -> bool {
        give(p, pickup(name), ActorTable::doom(), false, 3)
    }

    #[test]
    fn armour_absorbs_a_third_or_a_half_and_no_more_than_it_has() {
        let mut p = player();
        assert!(take(&mut p, "green_armor"));
        p.hurt(30);
        assert_eq!((p.health, p.armor, p.armor_class), (80, 90, 1));
        let mut p = player();
        assert!(take(&mut p, "blue_armor"));
        p.hurt(30);
        assert_eq!((p.health, p.armor, p.armor_class), (85, 185, 2));
        // Rounding down, as Doom's integer division: 10 / 3 saves 3.
        p.armor_class = 1;
        p.hurt(10);
        assert_eq!((p.health, p.armor), (78, 182));
        // Five points left save five of a third of 30, then the armour is gone.
        p.armor = 5;
        p.hurt(30);
        assert_eq!((p.health, p.armor, p.armor_class), (53, 0, 0));
        p.hurt(9);
        assert_eq!(p.health, 44);
    }

    #[test]
    fn pickups_give_what_doom_s_do_and_stay_when_they_would_give_nothing() {
        let mut p = player();
        assert!(!take(&mut p, "medikit"), "full health: the medikit stays");
        p.health = 95;
        assert!(take(&mut p, "stimpack"));
        assert_eq!(p.health, 100);
        assert!(take(&mut p, "health_bonus"), "a bonus is always taken");
        assert_eq!(p.health, 101);
        assert!(take(&mut p, "soul_sphere"));
        assert_eq!(p.health, 200);
        assert!(take(&mut p, "blue_armor"));
        assert!(!take(&mut p, "green_armor"), "worse than what is worn");
        assert!(take(&mut p, "armor_bonus"));
        assert_eq!((p.armor, p.armor_class), (200, 2));
        assert!(take(&mut p, "clip"));
        assert_eq!(p.ammo[0], 60);
        assert!(give(&mut p, pickup("clip"), ActorTable::doom(), true, 3));
        assert_eq!(p.ammo[0], 65, "a dropped clip holds half");
        assert!(give(&mut p, pickup("shotgun_shells"), ActorTable::doom(), false, 5));
        assert_eq!(p.ammo[1], 8, "skill 5 doubles ammunition");
        assert!(take(&mut p, "backpack"));
        assert_eq!((p.max_ammo, p.ammo), ([400, 100, 100, 600], [75, 12, 1, 20]));
        assert!(take(&mut p, "shotgun"));
        assert!(p.weapons.contains(&ActorTable::doom().index("shotgun").unwrap()));
        assert_eq!(p.ammo[1], 20);
        assert!(take(&mut p, "radiation_suit"));
        assert_eq!(p.powers[power_slot(Power::IronFeet)], 60 * 35);
        assert!(take(&mut p, "blue_card") && take(&mut p, "blue_card"), "keys are always taken");
        assert_eq!(p.keys.len(), 1);
    }
}
