//! Things the player picks up by walking over them (Doom's
//! P_TouchSpecialThing). For now the keys: cards and skulls of three
//! colours; the actors issue brings weapons, ammo, health and the rest.

use super::events::{sound, Event, Origin};
use super::player::{Key, Player, HEIGHT, RADIUS};
use crate::actors::{ActorTable, Category, KeyForm};
use crate::level::Level;

/// A thing that can be picked up, and what it gives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pickup {
    pub thing: usize,
    pub radius: f64,
    pub key: Key,
}

/// The pickups among the things shown at the start of a game.
pub fn pickups(level: &Level) -> Vec<Pickup> {
    let types = ActorTable::doom();
    let map = &level.compiled.map;
    (0..map.things.len())
        .filter(|&i| level.thing_shown[i])
        .filter_map(|i| {
            let t = types.get(&map.things[i].kind)?;
            let Category::Key(colour, form) = t.category else { return None };
            Some(Pickup { thing: i, radius: t.radius, key: Key { colour, form } })
        })
        .collect()
}

/// Picks up every pickup the player touches: their boxes overlap (Doom
/// tests squares, not circles) and the thing is within reach of the body's
/// height (from 8 under the feet to the top of the head).
pub fn touch(pickups: &mut Vec<Pickup>, level: &mut Level, player: &mut Player, events: &mut Vec<Event>) {
    if player.dead() {
        return;
    }
    let map = &level.compiled.map;
    pickups.retain(|p| {
        let thing = &map.things[p.thing];
        let reach = p.radius + RADIUS;
        let d = (thing.pos - player.pos).abs();
        let z = map.sectors[level.thing_sectors[p.thing]].floor - player.z;
        if d.x >= reach || d.y >= reach || z > HEIGHT || z < -8.0 {
            return true;
        }
        level.thing_shown[p.thing] = false;
        if !player.keys.contains(&p.key) {
            player.keys.push(p.key);
            let form = match p.key.form {
                KeyForm::Card => "keycard",
                KeyForm::Skull => "skull key",
            };
            events.push(Event::Message(format!("Picked up a {} {form}.", p.key.colour.name())));
        }
        events.push(sound("itemup", Origin::Player));
        false
    });
}
