//! ViZDoom's game variables read off the simulation, as ViZDoom 1.3.2's
//! `viz_game.cpp` fills its shared state after each tic: Doom's counts,
//! ViZDoom's tallies (`sim::zdoom::Tally`), the player's health, armour,
//! weapons and ammunition by ZDoom's weapon slots, the body's position and
//! momentum in map units, angles in degrees, and the scripts' globals.

use super::GameVariable;
use crate::sim::game::SimGame;
use crate::sim::{PlayerState, MAXPLAYERS};

/// Doom's weapons in ZDoom's slots (`weapontype_t` numbers): slot 1 the fist
/// and chainsaw, 3 the shotgun and super shotgun, 2 and 4 to 7 one each;
/// slots 0, 8 and 9 are empty in Doom.
const SLOTS: [&[usize]; 10] = [&[], &[0, 7], &[1], &[2, 8], &[3], &[4], &[5], &[6], &[], &[]];

/// The slot a Doom weapon sits in.
fn slot_of(weapon: usize) -> Option<usize> {
    SLOTS.iter().position(|s| s.contains(&weapon))
}

/// `variable` for player `player` (0-based) of `game`; 0 for a player not
/// in the game. Whole-number variables come out whole.
pub fn value(game: &SimGame, player: usize, variable: GameVariable) -> f64 {
    let sim = &game.sim;
    let Some(p) = sim.players.get(player).and_then(Option::as_ref) else {
        return match variable {
            GameVariable::PlayerNumber => player as f64,
            GameVariable::PlayerCount => sim.players.iter().flatten().count() as f64,
            GameVariable::User(n) => global(game, n),
            _ => 0.0,
        };
    };
    let mo = sim.mo(p.mo);
    let tally = sim.zdoom.tallies[player];
    let ammo_of = |weapon: usize| {
        let ammo = sim.info.weapons.get(weapon).and_then(Option::as_ref).and_then(|w| w.ammo);
        ammo.and_then(|a| p.ammo.get(a)).map_or(0, |&n| n)
    };
    let whole = |n: i32| f64::from(n);
    match variable {
        GameVariable::KillCount => whole(p.killcount),
        GameVariable::ItemCount => whole(p.itemcount),
        GameVariable::SecretCount => whole(p.secretcount),
        // Doom's frag count: the others fragged, less one's own deaths by
        // one's own hand or the world's.
        GameVariable::FragCount => {
            let others: i32 = (0..MAXPLAYERS).filter(|&i| i != player).map(|i| p.frags[i]).sum();
            whole(others - p.frags[player])
        }
        GameVariable::DeathCount => whole(tally.deaths),
        GameVariable::HitCount => whole(tally.hits),
        GameVariable::HitsTaken => whole(tally.hits_taken),
        GameVariable::DamageCount => whole(tally.damage),
        GameVariable::DamageTaken => whole(tally.damage_taken),
        GameVariable::Health => whole(mo.health),
        GameVariable::Armor => whole(p.armorpoints),
        GameVariable::Dead => f64::from(u8::from(p.playerstate == PlayerState::Dead || mo.health <= 0)),
        GameVariable::OnGround => f64::from(u8::from(mo.z <= mo.floorz)),
        GameVariable::AttackReady => {
            let ready = sim.info.weapons.get(p.readyweapon).and_then(Option::as_ref).and_then(|w| w.readystate);
            f64::from(u8::from(ready.is_some() && p.psprites[0].state == ready))
        }
        GameVariable::AltAttackReady => 0.0,
        GameVariable::SelectedWeapon => slot_of(p.readyweapon).map_or(-1.0, |s| s as f64),
        GameVariable::SelectedWeaponAmmo => whole(ammo_of(p.readyweapon)),
        GameVariable::Ammo(slot) => SLOTS[usize::from(slot)].first().map_or(0.0, |&w| whole(ammo_of(w))),
        GameVariable::Weapon(slot) => {
            let owned = SLOTS[usize::from(slot)].iter().filter(|&&w| p.weaponowned.get(w).copied().unwrap_or(false));
            owned.count() as f64
        }
        GameVariable::PositionX => mo.x.to_f64(),
        GameVariable::PositionY => mo.y.to_f64(),
        GameVariable::PositionZ => mo.z.to_f64(),
        GameVariable::Angle | GameVariable::CameraAngle => mo.angle.to_degrees(),
        GameVariable::Pitch | GameVariable::Roll | GameVariable::CameraPitch | GameVariable::CameraRoll => 0.0,
        GameVariable::ViewHeight => p.viewheight.to_f64(),
        GameVariable::VelocityX => mo.momx.to_f64(),
        GameVariable::VelocityY => mo.momy.to_f64(),
        GameVariable::VelocityZ => mo.momz.to_f64(),
        GameVariable::CameraPositionX => mo.x.to_f64(),
        GameVariable::CameraPositionY => mo.y.to_f64(),
        GameVariable::CameraPositionZ => p.viewz.to_f64(),
        GameVariable::CameraFov => 90.0,
        GameVariable::PlayerNumber => player as f64,
        GameVariable::PlayerCount => sim.players.iter().flatten().count() as f64,
        GameVariable::PlayerFragCount(n) => {
            let n = usize::from(n) - 1;
            match sim.players.get(n).and_then(Option::as_ref) {
                Some(q) => {
                    let others: i32 = (0..MAXPLAYERS).filter(|&i| i != n).map(|i| q.frags[i]).sum();
                    whole(others - q.frags[n])
                }
                None => 0.0,
            }
        }
        GameVariable::User(n) => global(game, n),
    }
}

/// `USERn`: the scripts' global variable n, as an integer (ViZDoom leaves
/// 16.16 values for the caller to convert).
fn global(game: &SimGame, n: u8) -> f64 {
    f64::from(game.scripts().map_or(0, |s| s.global(usize::from(n))))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_doom_weapon_has_one_slot() {
        for w in 0..9 {
            assert_eq!(SLOTS.iter().filter(|s| s.contains(&w)).count(), 1, "weapon {w}");
        }
        assert_eq!(slot_of(1), Some(2), "the pistol");
        assert_eq!(slot_of(8), Some(3), "the super shotgun");
    }
}
