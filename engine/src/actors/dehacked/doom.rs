//! Doom's own numbering, which patches address: states (frames), things,
//! weapons, sprites and sounds as doom.exe 1.9 has them
//! (`engine/data/doom_info.ron`, from Chocolate Doom's info.c, sounds.c
//! and d_items.c), and the `MF_` flag bits with their BEX names.

use std::sync::OnceLock;

use serde::Deserialize;

use crate::actors::{ActorFlag, AmmoKind};

const DOOM_INFO: &str = include_str!("../../../data/doom_info.ron");
pub const DOOM_INFO_PATH: &str = "engine/data/doom_info.ron";

/// states[]: S_NULL is 0, S_TECH2LAMP4 966.
pub const NUM_STATES: usize = 967;
/// mobjinfo[]: "Thing 1" is MT_PLAYER, "Thing 137" MT_MISC86.
pub const NUM_THINGS: usize = 137;
/// S_sfx[], sfx_None (0) included.
pub const NUM_SOUNDS: usize = 109;
pub const NUM_SPRITES: usize = 138;
pub const NUM_WEAPONS: usize = 9;
/// Doom's ammo types in its order (am_clip, am_shell, am_cell, am_misl):
/// not [`AmmoKind::ALL`]'s, which puts rockets before cells.
pub const AMMO: [AmmoKind; 4] = [AmmoKind::Bullets, AmmoKind::Shells, AmmoKind::Cells, AmmoKind::Rockets];
/// Doom's am_noammo, the fist's and chainsaw's "ammo type".
pub const NO_AMMO: i64 = 5;
/// clipammo[]: what one clip of each type holds (Doom's order).
pub const CLIP_AMMO: [i32; 4] = [10, 4, 20, 1];
/// maxammo[].
pub const MAX_AMMO: [i32; 4] = [200, 50, 300, 50];
/// Doom's 16.16 fixed point, in which patches give sizes and missile
/// speeds.
pub const FRACUNIT: f64 = 65536.0;
/// The bright bit of "Sprite subnumber" (FF_FULLBRIGHT).
pub const FULL_BRIGHT: i64 = 0x8000;

/// A mobjinfo's states, in DeHackEd's order, and the labels the table
/// gives them.
pub const THING_LABELS: [&str; 8] = ["Spawn", "See", "Pain", "Melee", "Missile", "Death", "XDeath", "Raise"];
/// A weaponinfo's states (upstate, downstate, readystate, atkstate,
/// flashstate) and the table's labels.
pub const WEAPON_LABELS: [&str; 5] = ["Select", "Deselect", "Ready", "Fire", "Flash"];

/// Doom's `MF_` bits, their BEX names (Boom's), and the flag the table
/// has for each. JUSTHIT, JUSTATTACKED, INFLOAT and SKULLFLY are states
/// the simulation sets on a body, not properties of a kind; Boom's and
/// MBF's bits above TRANSLATION have no flag here.
pub const MF_BITS: [(u32, &str, Option<ActorFlag>); 33] = [
    (0x1, "SPECIAL", Some(ActorFlag::Special)),
    (0x2, "SOLID", Some(ActorFlag::Solid)),
    (0x4, "SHOOTABLE", Some(ActorFlag::Shootable)),
    (0x8, "NOSECTOR", Some(ActorFlag::NoSector)),
    (0x10, "NOBLOCKMAP", Some(ActorFlag::NoBlockmap)),
    (0x20, "AMBUSH", Some(ActorFlag::Ambush)),
    (0x40, "JUSTHIT", None),
    (0x80, "JUSTATTACKED", None),
    (0x100, "SPAWNCEILING", Some(ActorFlag::SpawnCeiling)),
    (0x200, "NOGRAVITY", Some(ActorFlag::NoGravity)),
    (0x400, "DROPOFF", Some(ActorFlag::DropOff)),
    (0x800, "PICKUP", Some(ActorFlag::Pickup)),
    (0x1000, "NOCLIP", Some(ActorFlag::NoClip)),
    (0x2000, "SLIDE", Some(ActorFlag::Slide)),
    (0x4000, "FLOAT", Some(ActorFlag::Float)),
    (0x8000, "TELEPORT", Some(ActorFlag::Teleport)),
    (0x10000, "MISSILE", Some(ActorFlag::Missile)),
    (0x20000, "DROPPED", Some(ActorFlag::Dropped)),
    (0x40000, "SHADOW", Some(ActorFlag::Shadow)),
    (0x80000, "NOBLOOD", Some(ActorFlag::NoBlood)),
    (0x100000, "CORPSE", Some(ActorFlag::Corpse)),
    (0x200000, "INFLOAT", None),
    (0x400000, "COUNTKILL", Some(ActorFlag::CountKill)),
    (0x800000, "COUNTITEM", Some(ActorFlag::CountItem)),
    (0x1000000, "SKULLFLY", None),
    (0x2000000, "NOTDMATCH", Some(ActorFlag::NotDeathmatch)),
    // Two bits: a translation table 1 to 3. The table has one flag for
    // "translated"; which of the three is not kept.
    (0x4000000, "TRANSLATION1", Some(ActorFlag::Translation)),
    (0x8000000, "TRANSLATION2", Some(ActorFlag::Translation)),
    (0x4000000, "TRANSLATION", Some(ActorFlag::Translation)),
    (0x10000000, "TOUCHY", None),
    (0x20000000, "BOUNCES", None),
    (0x40000000, "FRIEND", None),
    (0x80000000, "TRANSLUCENT", None),
];

/// The bit of a BEX flag name (`SOLID`, `COUNTKILL`, ...).
pub fn flag_bit(name: &str) -> Option<u32> {
    MF_BITS.iter().find(|(_, n, _)| n.eq_ignore_ascii_case(name)).map(|&(bit, _, _)| bit)
}

#[derive(Clone, Debug, PartialEq)]
pub struct DoomState {
    /// info.h's name (`S_POSS_ATK2`).
    pub name: String,
    /// Index into [`DoomInfo::sprites`].
    pub sprite: usize,
    /// The frame, with [`FULL_BRIGHT`] for full brightness.
    pub frame: i64,
    pub tics: i32,
    /// The action's name (`A_PosAttack`).
    pub action: Option<String>,
    /// The state after it; 0 (S_NULL) removes the thing.
    pub next: usize,
}

#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(rename = "Thing", deny_unknown_fields)]
struct ThingSource {
    mt: String,
    actor: String,
    doomednum: i32,
    health: i32,
    reaction_time: i32,
    pain_chance: i32,
    speed: i32,
    radius: i32,
    height: i32,
    mass: i32,
    damage: i32,
    flags: u32,
    sounds: (String, String, String, String, String),
    states: (String, String, String, String, String, String, String, String),
}

/// One mobjinfo entry.
#[derive(Clone, Debug, PartialEq)]
pub struct DoomThing {
    /// info.h's name (`MT_POSSESSED`).
    pub mt: String,
    /// The table's actor that is it.
    pub actor: String,
    /// -1 for things no map places.
    pub doomednum: i32,
    pub health: i32,
    pub reaction_time: i32,
    pub pain_chance: i32,
    /// Map units a step, or 16.16 map units a tick for missiles.
    pub speed: i32,
    /// 16.16.
    pub radius: i32,
    pub height: i32,
    pub mass: i32,
    pub damage: i32,
    pub flags: u32,
    /// see, attack, pain, death, active: S_sfx indices, 0 for none.
    pub sounds: [usize; 5],
    /// In [`THING_LABELS`]' order; 0 for none.
    pub states: [usize; 8],
}

#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(rename = "Weapon", deny_unknown_fields)]
struct WeaponSource {
    name: String,
    actor: String,
    ammo: i64,
    up: String,
    down: String,
    ready: String,
    attack: String,
    flash: String,
}

/// One weaponinfo entry.
#[derive(Clone, Debug, PartialEq)]
pub struct DoomWeapon {
    pub name: String,
    pub actor: String,
    /// Doom's ammo type ([`AMMO`]'s index, or [`NO_AMMO`]).
    pub ammo: i64,
    /// In [`WEAPON_LABELS`]' order.
    pub states: [usize; 5],
}

#[derive(Deserialize)]
#[serde(rename = "DoomInfo", deny_unknown_fields)]
struct InfoSource {
    sprites: Vec<String>,
    sounds: Vec<String>,
    states: Vec<(String, String, i64, i32, String, String)>,
    things: Vec<ThingSource>,
    weapons: Vec<WeaponSource>,
}

/// Doom's tables, names resolved to indices.
#[derive(Debug)]
pub struct DoomInfo {
    pub sprites: Vec<String>,
    /// S_sfx names; index 0 is sfx_None's empty name.
    pub sounds: Vec<String>,
    pub states: Vec<DoomState>,
    pub things: Vec<DoomThing>,
    pub weapons: Vec<DoomWeapon>,
}

impl DoomInfo {
    /// The frame of a state name.
    pub fn state(&self, name: &str) -> Option<usize> {
        self.states.iter().position(|s| s.name == name)
    }

    /// The mobjinfo index of a thing name (`MT_MISC2`).
    pub fn thing(&self, mt: &str) -> Option<usize> {
        self.things.iter().position(|t| t.mt == mt)
    }
}

/// Doom's tables, as shipped (checked by the tests, so a broken file fails
/// them, not a player's game).
pub fn doom_info() -> &'static DoomInfo {
    static INFO: OnceLock<DoomInfo> = OnceLock::new();
    INFO.get_or_init(|| load().unwrap_or_else(|e| panic!("{DOOM_INFO_PATH} is broken: {e}")))
}

fn load() -> Result<DoomInfo, String> {
    let source: InfoSource = ron::from_str(DOOM_INFO).map_err(|e| e.to_string())?;
    let names: Vec<&str> = source.states.iter().map(|s| s.0.as_str()).collect();
    let state = |name: &str| names.iter().position(|n| *n == name).ok_or(format!("no state {name}"));
    let mut sounds = vec![String::new()];
    sounds.extend(source.sounds.iter().cloned());
    let sound = |name: &str| match name {
        "" => Ok(0),
        n => sounds.iter().position(|s| s == n).ok_or(format!("no sound {n}")),
    };
    let mut states = Vec::new();
    for (name, sprite, frame, tics, action, next) in &source.states {
        states.push(DoomState {
            name: name.clone(),
            sprite: source.sprites.iter().position(|s| s == sprite).ok_or(format!("no sprite {sprite}"))?,
            frame: *frame,
            tics: *tics,
            action: Some(action.clone()).filter(|a| !a.is_empty()),
            next: state(next)?,
        });
    }
    let mut things = Vec::new();
    for t in &source.things {
        let s = &t.states;
        let n = &t.sounds;
        things.push(DoomThing {
            mt: t.mt.clone(),
            actor: t.actor.clone(),
            doomednum: t.doomednum,
            health: t.health,
            reaction_time: t.reaction_time,
            pain_chance: t.pain_chance,
            speed: t.speed,
            radius: t.radius,
            height: t.height,
            mass: t.mass,
            damage: t.damage,
            flags: t.flags,
            sounds: [sound(&n.0)?, sound(&n.1)?, sound(&n.2)?, sound(&n.3)?, sound(&n.4)?],
            states: [
                state(&s.0)?,
                state(&s.1)?,
                state(&s.2)?,
                state(&s.3)?,
                state(&s.4)?,
                state(&s.5)?,
                state(&s.6)?,
                state(&s.7)?,
            ],
        });
    }
    let mut weapons = Vec::new();
    for w in &source.weapons {
        weapons.push(DoomWeapon {
            name: w.name.clone(),
            actor: w.actor.clone(),
            ammo: w.ammo,
            states: [state(&w.up)?, state(&w.down)?, state(&w.ready)?, state(&w.attack)?, state(&w.flash)?],
        });
    }
    Ok(DoomInfo { sprites: source.sprites, sounds, states, things, weapons })
}
