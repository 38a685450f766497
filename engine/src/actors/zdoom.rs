//! ZDoom's names for the table's actors, and ZDoom's own base classes.
//!
//! DECORATE lumps, ACS scripts (`Spawn("DoomImp", ...)`) and ViZDoom's
//! configuration name actors by ZDoom's class names (`ZombieMan`,
//! `RocketAmmo`, `ScriptedMarine`); our table names them in snake case
//! (`zombieman`, `rocket`). [`find`] answers both: a table actor of that
//! name first (case-insensitive, so a DECORATE actor `CustomMedikit`,
//! stored as `custommedikit`, is found), then ZDoom's name. ZDoom's names
//! are tied to Doom's editor numbers where the actor has one (the numbers
//! are facts both engines share, so a renamed table actor is still found),
//! else to our name. The spellings are GZDoom's
//! (`wadsrc/static/zscript/actors/doom/*.zs`).
//!
//! ZDoom's classes that Doom lacks and DECORATE derives from (`Health`,
//! `Inventory`, `DoomWeapon`, `ScriptedMarine` and its weapon variants)
//! are written in our format in `engine/data/zdoom_actors.ron`;
//! [`with_bases`] layers them on a table.

use super::{ActorTable, ActorTableError};

/// ZDoom's base classes in our format (see the file's header).
const ZDOOM_ACTORS: &str = include_str!("../../data/zdoom_actors.ron");
pub const ZDOOM_ACTORS_PATH: &str = "engine/data/zdoom_actors.ron";

/// How a ZDoom class is found in our table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Ours {
    /// The actor with this editor number.
    Number(u16),
    /// The actor of this name (actors without a number: missiles, effects,
    /// the player, the fist and pistol, ZDoom's bases).
    Name(&'static str),
}

use Ours::{Name, Number};

/// ZDoom's class names and where each is in our table. Lookups ignore
/// case; the spelling is what ViZDoom 1.3.2 names its objects
/// (`Zombieman`, where ZDoom's DECORATE wrote `ZombieMan`), for
/// `scenario::world`.
const CLASSES: &[(&str, Ours)] = &[
    // The player, monsters and the boss brain's parts.
    ("DoomPlayer", Name("player")),
    ("Zombieman", Number(3004)),
    ("ShotgunGuy", Number(9)),
    ("ChaingunGuy", Number(65)),
    ("DoomImp", Number(3001)),
    ("Demon", Number(3002)),
    ("Spectre", Number(58)),
    ("Cacodemon", Number(3005)),
    ("LostSoul", Number(3006)),
    ("BaronOfHell", Number(3003)),
    ("HellKnight", Number(69)),
    ("Arachnotron", Number(68)),
    ("Revenant", Number(66)),
    ("Fatso", Number(67)),
    ("PainElemental", Number(71)),
    ("Archvile", Number(64)),
    ("Cyberdemon", Number(16)),
    ("SpiderMastermind", Number(7)),
    ("WolfensteinSS", Number(84)),
    ("CommanderKeen", Number(72)),
    ("BossBrain", Number(88)),
    ("BossEye", Number(89)),
    ("BossTarget", Number(87)),
    ("ExplosiveBarrel", Number(2035)),
    // Ammunition.
    ("Clip", Number(2007)),
    ("ClipBox", Number(2048)),
    ("Shell", Number(2008)),
    ("ShellBox", Number(2049)),
    ("RocketAmmo", Number(2010)),
    ("RocketBox", Number(2046)),
    ("Cell", Number(2047)),
    ("CellPack", Number(17)),
    ("Backpack", Number(8)),
    // Health, armour, power-ups, keys.
    ("Stimpack", Number(2011)),
    ("Medikit", Number(2012)),
    ("HealthBonus", Number(2014)),
    ("ArmorBonus", Number(2015)),
    ("GreenArmor", Number(2018)),
    ("BlueArmor", Number(2019)),
    ("Soulsphere", Number(2013)),
    ("Megasphere", Number(83)),
    ("InvulnerabilitySphere", Number(2022)),
    ("Berserk", Number(2023)),
    ("BlurSphere", Number(2024)),
    ("RadSuit", Number(2025)),
    ("Allmap", Number(2026)),
    ("Infrared", Number(2045)),
    ("BlueCard", Number(5)),
    ("YellowCard", Number(6)),
    ("RedCard", Number(13)),
    ("BlueSkull", Number(40)),
    ("YellowSkull", Number(39)),
    ("RedSkull", Number(38)),
    // Weapons.
    ("Fist", Name("fist")),
    ("Pistol", Name("pistol")),
    ("Chainsaw", Number(2005)),
    ("Shotgun", Number(2001)),
    ("SuperShotgun", Number(82)),
    ("Chaingun", Number(2002)),
    ("RocketLauncher", Number(2003)),
    ("PlasmaRifle", Number(2004)),
    ("BFG9000", Number(2006)),
    // Missiles and effects.
    ("Rocket", Name("rocket_projectile")),
    ("PlasmaBall", Name("plasma_bolt")),
    ("BFGBall", Name("bfg_ball")),
    ("BFGExtra", Name("bfg_spray")),
    ("DoomImpBall", Name("imp_fireball")),
    ("CacodemonBall", Name("cacodemon_fireball")),
    ("BaronBall", Name("baron_fireball")),
    ("ArachnotronPlasma", Name("arachnotron_plasma")),
    ("RevenantTracer", Name("revenant_missile")),
    ("RevenantTracerSmoke", Name("missile_smoke")),
    ("FatShot", Name("mancubus_fireball")),
    ("ArchvileFire", Name("arch_vile_fire")),
    ("SpawnShot", Name("spawn_cube")),
    ("SpawnFire", Name("spawn_fire")),
    ("BulletPuff", Name("bullet_puff")),
    ("Blood", Name("blood")),
    ("TeleportFog", Name("teleport_fog")),
    ("ItemFog", Name("item_fog")),
    ("TeleportDest", Number(14)),
    // ZDoom's map markers (engine/data/actors.ron).
    ("MapSpot", Number(9001)),
    ("PatrolPoint", Number(9024)),
    // Decorations.
    ("TechLamp", Number(85)),
    ("TechLamp2", Number(86)),
    ("Column", Number(2028)),
    ("TallGreenColumn", Number(30)),
    ("ShortGreenColumn", Number(31)),
    ("TallRedColumn", Number(32)),
    ("ShortRedColumn", Number(33)),
    ("SkullColumn", Number(37)),
    ("HeartColumn", Number(36)),
    ("EvilEye", Number(41)),
    ("FloatingSkull", Number(42)),
    ("TorchTree", Number(43)),
    ("BlueTorch", Number(44)),
    ("GreenTorch", Number(45)),
    ("RedTorch", Number(46)),
    ("ShortBlueTorch", Number(55)),
    ("ShortGreenTorch", Number(56)),
    ("ShortRedTorch", Number(57)),
    ("Stalagtite", Number(47)),
    ("TechPillar", Number(48)),
    ("Candlestick", Number(34)),
    ("Candelabra", Number(35)),
    ("BloodyTwitch", Number(49)),
    ("Meat2", Number(50)),
    ("Meat3", Number(51)),
    ("Meat4", Number(52)),
    ("Meat5", Number(53)),
    ("NonsolidMeat2", Number(59)),
    ("NonsolidMeat4", Number(60)),
    ("NonsolidMeat3", Number(61)),
    ("NonsolidMeat5", Number(62)),
    ("NonsolidTwitch", Number(63)),
    ("DeadCacodemon", Number(22)),
    ("DeadMarine", Number(15)),
    ("DeadZombieMan", Number(18)),
    ("DeadDemon", Number(21)),
    ("DeadLostSoul", Number(23)),
    ("DeadDoomImp", Number(20)),
    ("DeadShotgunGuy", Number(19)),
    ("GibbedMarine", Number(10)),
    ("GibbedMarineExtra", Number(12)),
    ("HeadsOnAStick", Number(28)),
    ("Gibs", Number(24)),
    ("HeadOnAStick", Number(27)),
    ("HeadCandles", Number(29)),
    ("DeadStick", Number(25)),
    ("LiveStick", Number(26)),
    ("BigTree", Number(54)),
    ("BurningBarrel", Number(70)),
    ("HangNoGuts", Number(73)),
    ("HangBNoBrain", Number(74)),
    ("HangTLookingDown", Number(75)),
    ("HangTSkull", Number(76)),
    ("HangTLookingUp", Number(77)),
    ("HangTNoBrain", Number(78)),
    ("ColonGibs", Number(79)),
    ("SmallBloodPool", Number(80)),
    ("BrainStem", Number(81)),
    // ZDoom's own classes (engine/data/zdoom_actors.ron).
    ("Inventory", Name("inventory")),
    ("Health", Name("health_item")),
    ("DoomWeapon", Name("doom_weapon")),
    ("Weapon", Name("doom_weapon")),
    ("ScriptedMarine", Name("scripted_marine")),
    ("MarineFist", Name("marine_fist")),
    ("MarineBerserk", Name("marine_berserk")),
    ("MarineChainsaw", Name("marine_chainsaw")),
    ("MarinePistol", Name("marine_pistol")),
    ("MarineShotgun", Name("marine_shotgun")),
    ("MarineSSG", Name("marine_ssg")),
    ("MarineChaingun", Name("marine_chaingun")),
    ("MarineRocket", Name("marine_rocket")),
    ("MarinePlasma", Name("marine_plasma")),
    ("MarineBFG", Name("marine_bfg")),
];

/// ZDoom's map things we know and do not read: a map placing them plays
/// without them (the importer lists them as unknown things, named).
pub const UNREAD_THINGS: &[(u16, &str)] = &[
    (9027, "RedParticleFountain"),
    (9028, "GreenParticleFountain"),
    (9029, "BlueParticleFountain"),
    (9030, "YellowParticleFountain"),
    (9031, "PurpleParticleFountain"),
    (9032, "BlackParticleFountain"),
    (9033, "WhiteParticleFountain"),
    (9110, "MarineRailgun"),
];

/// The actor a class name means: the table actor of exactly that name (our
/// names are lower-case), else the actor ZDoom's class of that name is
/// (case-insensitive), else a table actor of that name in any case (a
/// DECORATE actor, `CustomMedikit` for `custommedikit`). ZDoom's names come
/// before the case-insensitive match for one clash: ZDoom's `Rocket` is the
/// missile, our `rocket` the ammunition; every other ZDoom name that is also
/// one of ours, in some case, means the same actor.
pub fn find(table: &ActorTable, class: &str) -> Option<usize> {
    if let Some(i) = table.index(class) {
        return Some(i);
    }
    let zdoom = CLASSES.iter().find(|(name, _)| name.eq_ignore_ascii_case(class)).and_then(|&(_, ours)| match ours {
        Number(n) => table.by_doomednum(n).and_then(|def| table.index(&def.name)),
        Name(name) => table.index(name),
    });
    zdoom.or_else(|| table.actors.iter().position(|a| a.name.eq_ignore_ascii_case(class)))
}

/// ZDoom's class name for a table actor, if it has one.
pub fn class_name(table: &ActorTable, index: usize) -> Option<&'static str> {
    let def = table.actors.get(index)?;
    CLASSES.iter().find_map(|&(class, ours)| {
        let hit = match ours {
            Number(n) => def.doomednum == Some(n),
            Name(name) => def.name == name,
        };
        hit.then_some(class)
    })
}

/// The name of a ZDoom map thing we know but do not read.
pub fn unread_thing(number: u16) -> Option<&'static str> {
    UNREAD_THINGS.iter().find(|&&(n, _)| n == number).map(|&(_, name)| name)
}

/// ZDoom's logical sound names (its Doom SNDINFO) for Doom's sounds, as
/// DECORATE's `SeeSound "weapons/rocklf"` names them. `*` names are the
/// player's sounds.
const SOUNDS: &[(&str, &str)] = &[
    ("weapons/pistol", "pistol"),
    ("weapons/shotgf", "shotgn"),
    ("weapons/sshotf", "dshtgn"),
    ("weapons/sshoto", "dbopn"),
    ("weapons/sshotl", "dbload"),
    ("weapons/sshotc", "dbcls"),
    ("weapons/chngun", "pistol"),
    ("weapons/rocklf", "rlaunc"),
    ("weapons/rocklx", "barexp"),
    ("weapons/plasmaf", "plasma"),
    ("weapons/plasmax", "firxpl"),
    ("weapons/bfgf", "bfg"),
    ("weapons/bfgx", "rxplod"),
    ("weapons/sawup", "sawup"),
    ("weapons/sawidle", "sawidl"),
    ("weapons/sawfull", "sawful"),
    ("weapons/sawhit", "sawhit"),
    ("misc/w_pkup", "wpnup"),
    ("misc/i_pkup", "itemup"),
    ("misc/k_pkup", "itemup"),
    ("misc/p_pkup", "getpow"),
    ("misc/health_pkup", "itemup"),
    ("misc/armor_pkup", "itemup"),
    ("misc/ammo_pkup", "itemup"),
    ("*death", "pldeth"),
    ("*xdeath", "pdiehi"),
    ("*gibbed", "slop"),
    ("*pain100", "plpain"),
    ("*pain75", "plpain"),
    ("*pain50", "plpain"),
    ("*pain25", "plpain"),
    ("*fist", "punch"),
];

/// Our sound for a ZDoom sound name: its SNDINFO name, or one of ours
/// as written (`rlaunc`), or a lump name (`DSRLAUNC`).
pub fn sound(table: &ActorTable, name: &str) -> Option<usize> {
    let ours = SOUNDS.iter().find(|(z, _)| z.eq_ignore_ascii_case(name)).map(|&(_, o)| o);
    let candidates =
        [ours, Some(name), name.get(2..).filter(|_| name.len() > 2 && name[..2].eq_ignore_ascii_case("ds"))];
    candidates.into_iter().flatten().find_map(|n| table.sounds.iter().position(|s| s.eq_ignore_ascii_case(n)))
}

/// `base` with ZDoom's base classes layered on it.
// Errors are made once, when a table is refused (as in `load.rs`).
#[allow(clippy::result_large_err)]
pub fn with_bases(base: &ActorTable) -> Result<ActorTable, ActorTableError> {
    base.extend(&[(ZDOOM_ACTORS, ZDOOM_ACTORS_PATH)])
}
