//! Sector specials (Doom's P_SpawnSpecials and P_PlayerInSpecialSector):
//! the light effects and door timers that start with the level, and what a
//! sector does to the player standing on its floor: damage every 32 ticks,
//! a secret counted the first time. A radiation suit shields from damage
//! as the floor's [`Suit`] says.

use super::doors::{Door, DoorState};
use super::lights::Light;
use super::{say, Ctx, Exit, Thinker, World};
use crate::actors::Power;
use crate::level::Level;
use crate::map::special::{DoorKind, DoorTimer, Suit, DOOR_SHUT, DOOR_SPEED, DOOR_WAIT, SUIT_LEAK};
use crate::play::pickups::power_slot;
use crate::play::random::GameRng;

/// Ticks before a sector's timed door acts (Doom: 30 s and 5 minutes).
pub const CLOSE_IN: u32 = 30 * 35;
pub const RAISE_IN: u32 = 5 * 60 * 35;

/// Starts the effects every sector's special calls for, in sector order.
pub fn spawn_effects(world: &mut World, level: &mut Level, rng: &mut GameRng) {
    for s in 0..level.compiled.map.sectors.len() {
        let special = level.compiled.map.sectors[s].special;
        if let Some(effect) = special.light {
            let light = Light::new(level, rng, s, effect);
            world.start_light(s, light);
        }
        let Some(timer) = special.timer else { continue };
        let mut door = Door::new(level, s, DoorKind::Raise, DOOR_SPEED, (DOOR_WAIT, DOOR_SHUT));
        door.state = match timer {
            // An open door that closes after 30 s, and stays closed.
            DoorTimer::CloseIn30s => DoorState::Open { wait: CLOSE_IN },
            DoorTimer::RaiseIn5Min => DoorState::Shut { wait: RAISE_IN },
        };
        world.start(Thinker::Door(door));
    }
}

/// What the sector under the player does to it this tick: only while its
/// feet are on that sector's floor, as in Doom.
pub fn player_in_sector(world: &mut World, ctx: &mut Ctx) {
    let player = &mut *ctx.bodies.player;
    let sector = player.sector;
    let s = &mut ctx.level.compiled.map.sectors[sector];
    if player.z != s.floor || player.dead() {
        return;
    }
    if let Some(damage) = s.special.damage {
        let suited = player.powers[power_slot(Power::IronFeet)] > 0;
        // A suit's leak draws its random byte only when a hurt is due.
        let due = ctx.time % u64::from(damage.every) == 0;
        let hurts = !suited
            || match damage.suit {
                Suit::Shields => false,
                Suit::Leaks => due && ctx.rng.byte() < SUIT_LEAK,
                Suit::Useless => true,
            };
        if due && hurts {
            player.hurt(damage.amount as i32);
            if damage.exit_below > 0 && player.health <= damage.exit_below as i32 {
                *ctx.exit = Some(Exit::Normal);
            }
        }
    }
    if s.special.secret {
        s.special.secret = false;
        world.secrets.1 += 1;
        say(ctx, "A secret is revealed!");
    }
}
