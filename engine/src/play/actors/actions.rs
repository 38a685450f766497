//! The registry's action names bound to the Rust functions that do them.
//! The table's loader has already checked every call's arguments against
//! the names and types in [`crate::actors::actions`], so a function reads
//! its arguments by position and type without checking again.

use super::{attacks, monsters, ActorCtx, Actors};
use crate::actors::Arg;

/// An action: the actors, which one acts, its arguments, the world.
pub type ActionFn = fn(&mut Actors, usize, &[Arg], &mut ActorCtx);

/// The function that does the action of that name, if the engine has it.
pub fn function(name: &str) -> Option<ActionFn> {
    let f: ActionFn = match name {
        "A_Look" => monsters::look,
        "A_Chase" => monsters::chase,
        "A_FaceTarget" => monsters::face_target,
        "A_Pain" => monsters::pain,
        "A_Scream" => monsters::scream,
        "A_XScream" => monsters::xscream,
        "A_Fall" => monsters::fall,
        "A_PlaySound" => monsters::play_sound,
        "A_PosAttack" => monsters::pos_attack,
        "A_SPosAttack" => monsters::spos_attack,
        "A_CPosAttack" => monsters::cpos_attack,
        "A_CPosRefire" => monsters::cpos_refire,
        "A_SargAttack" => monsters::sarg_attack,
        "A_TroopAttack" => attacks::troop_attack,
        "A_HeadAttack" => attacks::head_attack,
        "A_BruisAttack" => attacks::bruis_attack,
        "A_BspiAttack" | "A_CyberAttack" => attacks::missile_attack,
        "A_SkullAttack" => attacks::skull_attack,
        "A_FatRaise" => attacks::fat_raise,
        "A_FatAttack1" => attacks::fat_attack1,
        "A_FatAttack2" => attacks::fat_attack2,
        "A_FatAttack3" => attacks::fat_attack3,
        "A_SkelWhoosh" => attacks::skel_whoosh,
        "A_SkelFist" => attacks::skel_fist,
        "A_SkelMissile" => attacks::skel_missile,
        "A_Tracer" => attacks::tracer,
        "A_Explode" => attacks::explode,
        "A_SpidRefire" => attacks::spid_refire,
        "A_Hoof" => attacks::hoof,
        "A_Metal" => attacks::metal,
        "A_BabyMetal" => attacks::baby_metal,
        "A_PlayerScream" => attacks::player_scream,
        "A_PainAttack" => attacks::pain_attack,
        "A_PainDie" => attacks::pain_die,
        "A_VileChase" => attacks::vile_chase,
        "A_VileStart" => attacks::vile_start,
        "A_VileTarget" => attacks::vile_target,
        "A_VileAttack" => attacks::vile_attack,
        "A_StartFire" => attacks::start_fire,
        "A_Fire" => attacks::fire,
        "A_FireCrackle" => attacks::fire_crackle,
        "A_BossDeath" => attacks::boss_death,
        "A_KeenDie" => attacks::keen_die,
        "A_BrainAwake" => attacks::brain_awake,
        "A_BrainPain" => attacks::brain_pain,
        "A_BrainScream" => attacks::brain_scream,
        "A_BrainExplode" => attacks::brain_explode,
        "A_BrainDie" => attacks::brain_die,
        "A_BrainSpit" => attacks::brain_spit,
        "A_SpawnSound" => attacks::spawn_sound,
        "A_SpawnFly" => attacks::spawn_fly,
        "A_BFGSpray" => attacks::bfg_spray,
        _ => return None,
    };
    Some(f)
}

/// An integer argument (checked at load).
pub fn int(args: &[Arg], k: usize) -> i32 {
    match args.get(k) {
        Some(Arg::Int(v)) => *v,
        _ => 0,
    }
}

/// An actor argument (checked at load).
pub fn actor(args: &[Arg], k: usize) -> Option<usize> {
    match args.get(k) {
        Some(Arg::Actor(a)) => Some(*a),
        _ => None,
    }
}

/// A sound argument (checked at load).
pub fn sound(args: &[Arg], k: usize) -> Option<usize> {
    match args.get(k) {
        Some(Arg::Sound(s)) => Some(*s),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::actors::actions::REGISTRY;

    #[test]
    fn every_bound_name_is_in_the_registry() {
        for name in ["A_Look", "A_Chase", "A_PosAttack", "A_Fall"] {
            assert!(function(name).is_some());
        }
        let bound = REGISTRY.iter().filter(|a| function(a.name).is_some()).count();
        assert_eq!(bound, 53, "update the count (and ARCHITECTURE's list) when binding an action");
        // With the weapons' (`play/weapons.rs`), every action of the registry does something.
        let weapons = [
            "A_WeaponReady",
            "A_Lower",
            "A_Raise",
            "A_ReFire",
            "A_GunFlash",
            "A_Light0",
            "A_Light1",
            "A_Light2",
            "A_Punch",
            "A_Saw",
            "A_FirePistol",
            "A_FireShotgun",
            "A_FireShotgun2",
            "A_CheckReload",
            "A_OpenShotgun2",
            "A_LoadShotgun2",
            "A_CloseShotgun2",
            "A_FireCGun",
            "A_FireMissile",
            "A_FirePlasma",
            "A_BFGsound",
            "A_FireBFG",
        ];
        let unbound: Vec<&str> =
            REGISTRY.iter().map(|a| a.name).filter(|n| function(n).is_none() && !weapons.contains(n)).collect();
        assert_eq!(unbound, Vec::<&str>::new());
    }
}
