//! The registry's action names bound to the Rust functions that do them.
//! The table's loader has already checked every call's arguments against
//! the names and types in [`crate::actors::actions`], so a function reads
//! its arguments by position and type without checking again.

use super::{monsters, ActorCtx, Actors};
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
        assert_eq!(bound, 13, "update the count (and ARCHITECTURE's list) when binding an action");
    }
}
