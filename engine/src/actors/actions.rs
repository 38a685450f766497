//! The registry of actions a state may call: each one's name and the types
//! of its arguments, with Doom's values as defaults. Loading checks every
//! call in a table against this list (unknown names, too many arguments,
//! wrong types) and fills in the defaults, so that the simulation's action
//! functions, indexed by the same [`ActionId`], receive arguments they can
//! trust.
//!
//! The names are Doom's (`A_Look`, `A_Chase`, ...), the lingua franca of
//! DeHackEd, DECORATE and MBF21. Where Doom's action spawns a fixed actor
//! (the imp's fireball), the actor is an argument whose default is Doom's,
//! so that a mod can fire something else without new code.

/// An index into [`REGISTRY`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct ActionId(pub u16);

/// What an argument must be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArgKind {
    Int,
    Number,
    /// An actor name, as a string.
    Actor,
    /// A sound name, as a string.
    Sound,
    /// A label of the same actor (`See`, `See+2`).
    State,
}

impl ArgKind {
    pub fn describe(self) -> &'static str {
        match self {
            ArgKind::Int => "an integer",
            ArgKind::Number => "a number",
            ArgKind::Actor => "an actor name in quotes",
            ArgKind::Sound => "a sound name in quotes",
            ArgKind::State => "a label",
        }
    }
}

/// A default value, as it would be written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Default {
    Int(i64),
    Name(&'static str),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArgSpec {
    pub name: &'static str,
    pub kind: ArgKind,
    /// `None`: the argument must be given.
    pub default: Option<Default>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActionSpec {
    pub name: &'static str,
    pub args: &'static [ArgSpec],
    /// What it does, for `sightline actors` and the docs.
    pub doc: &'static str,
}

const fn actor(name: &'static str, default: &'static str) -> ArgSpec {
    ArgSpec { name, kind: ArgKind::Actor, default: Some(Default::Name(default)) }
}

const fn int(name: &'static str, default: i64) -> ArgSpec {
    ArgSpec { name, kind: ArgKind::Int, default: Some(Default::Int(default)) }
}

const fn sound(name: &'static str, default: &'static str) -> ArgSpec {
    ArgSpec { name, kind: ArgKind::Sound, default: Some(Default::Name(default)) }
}

const fn state(name: &'static str) -> ArgSpec {
    ArgSpec { name, kind: ArgKind::State, default: None }
}

const fn required_actor(name: &'static str) -> ArgSpec {
    ArgSpec { name, kind: ArgKind::Actor, default: None }
}

macro_rules! registry {
    ($($name:literal [$($arg:expr),*] $doc:literal;)*) => {
        /// Every action, in a fixed order ([`ActionId`] indexes it).
        pub const REGISTRY: &[ActionSpec] = &[$(ActionSpec { name: $name, args: &[$($arg),*], doc: $doc }),*];
    };
}

registry! {
    // Monsters: waking, chasing, facing.
    "A_Look" [] "Wait for a target: sight of the player (all round if awake to sound), or a sound heard.";
    "A_Chase" [] "Move towards the target; attack when in range and allowed.";
    "A_FaceTarget" [] "Turn to face the target (off by a random amount if it is a shadow).";
    "A_Pain" [] "Play the pain sound.";
    "A_Scream" [] "Play the death sound (full volume for bosses).";
    "A_XScream" [] "Play the gibbing sound.";
    "A_Fall" [] "Stop being solid: the body can be walked over.";
    "A_PlayerScream" [] "The player's death sound (the louder one below -50 health).";
    "A_Explode" [int("damage", 128), int("radius", 128)] "Splash damage around, stopped by walls.";
    "A_PlaySound" [ArgSpec { name: "sound", kind: ArgKind::Sound, default: None }] "Play a sound from the actor.";
    "A_BossDeath" [] "When every monster of this kind is dead, do the map's boss special (E1M8, MAP07, ...).";
    "A_KeenDie" [] "Fall; when every one of its kind is dead, open tag 666's doors.";
    // Attacks.
    "A_PosAttack" [] "The zombieman's hitscan: one bullet, 3 to 15 damage.";
    "A_SPosAttack" [] "The shotgun guy's hitscan: three pellets.";
    "A_CPosAttack" [] "The chaingunner's hitscan: one bullet.";
    "A_CPosRefire" [] "Keep firing while the target is in sight (sometimes stop).";
    "A_SpidRefire" [] "The spider mastermind's refire check.";
    "A_TroopAttack" [actor("missile", "imp_fireball")] "Claw in melee range, else throw a missile.";
    "A_SargAttack" [] "The demon's bite.";
    "A_HeadAttack" [actor("missile", "cacodemon_fireball")] "Bite in melee range, else spit a missile.";
    "A_BruisAttack" [actor("missile", "baron_fireball")] "Claw in melee range, else throw a missile.";
    "A_SkullAttack" [] "The lost soul's charge.";
    "A_BspiAttack" [actor("missile", "arachnotron_plasma")] "Fire a plasma missile.";
    "A_BabyMetal" [] "The arachnotron's footstep.";
    "A_CyberAttack" [actor("missile", "rocket_projectile")] "Fire a rocket.";
    "A_Hoof" [] "The cyberdemon's hoof step.";
    "A_Metal" [] "A metal footstep.";
    "A_PainAttack" [actor("spawn", "lost_soul")] "Spit a lost soul.";
    "A_PainDie" [actor("spawn", "lost_soul")] "Fall and spit three lost souls.";
    "A_SkelWhoosh" [] "The revenant's swing sound before its punch.";
    "A_SkelFist" [] "The revenant's punch.";
    "A_SkelMissile" [actor("missile", "revenant_missile")] "Fire a homing missile.";
    "A_Tracer" [actor("smoke", "missile_smoke")] "Steer a homing missile towards its target, leaving smoke.";
    "A_FatRaise" [] "The mancubus turns to its target before firing.";
    "A_FatAttack1" [actor("missile", "mancubus_fireball")] "Two fireballs, the second turned one way.";
    "A_FatAttack2" [actor("missile", "mancubus_fireball")] "Two fireballs, the second turned the other way.";
    "A_FatAttack3" [actor("missile", "mancubus_fireball")] "Two fireballs spread either side.";
    "A_VileChase" [] "Chase, and raise a corpse met on the way.";
    "A_VileStart" [] "The arch-vile's attack sound.";
    "A_VileTarget" [actor("fire", "arch_vile_fire")] "Put fire on the target.";
    "A_VileAttack" [] "Hurt the target if still in sight, blasting it up.";
    "A_StartFire" [] "The fire's first crackle; it follows the target.";
    "A_Fire" [] "Keep the fire in front of the target.";
    "A_FireCrackle" [] "Crackle and follow the target.";
    "A_BrainAwake" [] "The boss brain wakes: its spawn shooters start.";
    "A_BrainPain" [] "The boss brain's pain sound at full volume.";
    "A_BrainScream" [actor("explosion", "brain_explosion")] "Explosions across the brain as it dies.";
    "A_BrainExplode" [actor("explosion", "brain_explosion")] "More explosions while it dies.";
    "A_BrainDie" [] "The boss brain is dead: the level ends.";
    "A_BrainSpit" [actor("cube", "spawn_cube")] "Shoot a spawn cube at the next spawn spot.";
    "A_SpawnSound" [] "The cube's flying sound.";
    "A_SpawnFly" [actor("fire", "spawn_fire")] "The cube reaches its spot: fire and a random monster.";
    // The player's weapons (they run on the weapon's sprite, not the body).
    "A_WeaponReady" [] "Bob the weapon; fire or change weapons on the player's input.";
    "A_Lower" [] "Lower the weapon; then raise the next one.";
    "A_Raise" [] "Raise the weapon; ready when it is up.";
    "A_ReFire" [] "Fire again while the trigger is held.";
    "A_GunFlash" [] "Show the weapon's flash and the body's attack frame.";
    "A_Light0" [] "The weapon's light ends.";
    "A_Light1" [] "The weapon lights the room a little.";
    "A_Light2" [] "The weapon lights the room more.";
    "A_Punch" [] "The fist (ten times as hard with berserk).";
    "A_Saw" [] "The chainsaw.";
    "A_FirePistol" [] "One bullet, accurate on the first shot.";
    "A_FireShotgun" [] "Seven pellets.";
    "A_FireShotgun2" [] "Twenty pellets, spread wide.";
    "A_CheckReload" [] "Done if out of ammo.";
    "A_OpenShotgun2" [] "The super shotgun's open sound.";
    "A_LoadShotgun2" [] "Its load sound.";
    "A_CloseShotgun2" [] "Its close sound, then fire again if held.";
    "A_FireCGun" [] "One bullet; the flash follows the barrel.";
    "A_FireMissile" [actor("missile", "rocket_projectile")] "Fire a rocket.";
    "A_FirePlasma" [actor("missile", "plasma_bolt")] "Fire a plasma bolt; one of two flashes.";
    "A_BFGsound" [] "The BFG's charging sound.";
    "A_FireBFG" [actor("missile", "bfg_ball")] "Fire the BFG ball.";
    "A_BFGSpray" [actor("spray", "bfg_spray")] "Forty tracers from the shooter when the ball hits.";
    "A_FireCustomMissile" [required_actor("missile")] "Fire the named missile from the player (ZDoom's; one round of the weapon's ammunition).";
    // ZDoom's scripted marines (sim/marines.rs), and the body actions their
    // states use.
    "A_NoBlocking" [] "Stop being solid (ZDoom's name for A_Fall; nothing is dropped).";
    "A_MarineLook" [] "The chainsaw's idle sound if it wields one, then A_Look.";
    "A_MarineChase" [] "The chainsaw's idle sound if it wields one, then A_Chase.";
    "A_MarineNoise" [] "The chainsaw's idle sound if it wields one.";
    "A_M_Punch" [int("multiplier", 1)] "A punch of 2 to 20 times the multiplier (10 for berserk).";
    "A_M_Saw" [sound("fullsound", "sawful"), sound("hitsound", "sawhit"), int("damage", 2)] "The chainsaw in melee range: damage times 1 to 10, the body turned to the victim.";
    "A_M_SawRefire" [] "Back to See unless the target is alive and in melee range.";
    "A_M_Refire" [int("ignoremissile", 0), state("jumpto")] "Keep firing while the target lives and is seen (look for another most of the time), else jump.";
    "A_M_CheckAttack" [] "Face the target, or skip the attack when there is none.";
    "A_M_FirePistol" [int("accurate", 1)] "One bullet of 5 to 15 (spread unless accurate).";
    "A_M_FireCGun" [int("accurate", 1)] "One chaingun bullet of 5 to 15 (spread unless accurate).";
    "A_M_FireShotgun" [] "Seven pellets of 5 to 15.";
    "A_M_FireShotgun2" [] "Twenty pellets of 5 to 15, spread wide.";
    "A_M_FireMissile" [actor("missile", "rocket_projectile")] "Punch in melee range, else fire a rocket.";
    "A_M_FirePlasma" [actor("missile", "plasma_bolt")] "Fire a plasma bolt.";
    "A_M_BFGSound" [] "The BFG's charging sound.";
    "A_M_FireBFG" [actor("missile", "bfg_ball")] "Fire the BFG ball.";
}

/// The action of that name (case-insensitive, as DECORATE is).
pub fn find(name: &str) -> Option<ActionId> {
    REGISTRY.iter().position(|a| a.name.eq_ignore_ascii_case(name)).map(|i| ActionId(i as u16))
}

pub fn spec(id: ActionId) -> &'static ActionSpec {
    &REGISTRY[usize::from(id.0)]
}

/// A signature as it reads in an error: `A_Explode(damage: an integer = 128, ...)`.
pub fn signature(spec: &ActionSpec) -> String {
    let args: Vec<String> = spec
        .args
        .iter()
        .map(|a| {
            let default = match a.default {
                Some(Default::Int(i)) => format!(" = {i}"),
                Some(Default::Name(n)) => format!(" = \"{n}\""),
                None => String::new(),
            };
            format!("{}: {}{default}", a.name, a.kind.describe())
        })
        .collect();
    format!("{}({})", spec.name, args.join(", "))
}
