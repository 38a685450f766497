//! The actor table in Doom's units (`info.c`'s `mobjinfo[]` and `states[]`
//! as the game logic reads them): sizes and missile speeds in fixed point,
//! flags as Doom's `MF_` bits, frames with the full-bright bit, sprites by
//! Doom's sprite numbers. Built once per game from the data-driven
//! [`ActorTable`] (so a DeHackEd patch or a modder's table plays the same
//! way), with `-fast`'s changes applied as `G_InitNew` applies them.

use std::sync::Arc;

use crate::actors::dehacked::doom_info;
use crate::actors::{ActionCall, ActorDef, ActorFlag, ActorTable, StateId};
use crate::fixed::{Fixed, FRACUNIT};

/// Doom's `FF_FULLBRIGHT`, the frame's bright bit.
pub const FF_FULLBRIGHT: i32 = 0x8000;

/// One kind of thing (`mobjinfo_t`).
#[derive(Clone, Debug)]
pub struct MobjInfo {
    pub name: String,
    pub doomednum: i32,
    pub spawnhealth: i32,
    pub reactiontime: i32,
    pub painchance: i32,
    /// Doom's raw speed: map units a step for monsters, 16.16 fixed point a
    /// tic for missiles (`MF_MISSILE`).
    pub speed: i32,
    pub radius: Fixed,
    pub height: Fixed,
    pub mass: i32,
    pub damage: i32,
    /// `MF_*` bits.
    pub flags: u32,
    pub spawnstate: Option<StateId>,
    pub seestate: Option<StateId>,
    pub painstate: Option<StateId>,
    pub meleestate: Option<StateId>,
    pub missilestate: Option<StateId>,
    pub deathstate: Option<StateId>,
    pub xdeathstate: Option<StateId>,
    pub raisestate: Option<StateId>,
    /// Sound ids ([`Info::sound`]; 0 is none).
    pub seesound: usize,
    pub attacksound: usize,
    pub painsound: usize,
    pub deathsound: usize,
    pub activesound: usize,
    /// Doom's `mobjtype_t` for this kind, when it is one of Doom's.
    pub mt: Option<usize>,
}

/// One state (`state_t`).
#[derive(Clone, Debug)]
pub struct StateInfo {
    /// Doom's sprite number (`spritenum_t`).
    pub sprite: i32,
    /// The frame, with [`FF_FULLBRIGHT`].
    pub frame: i32,
    pub tics: i32,
    pub action: Option<ActionCall>,
    /// `None` is `S_NULL`: the thing is removed.
    pub next: Option<StateId>,
}

/// A weapon (`weaponinfo_t`), by Doom's weapon number.
#[derive(Clone, Debug)]
pub struct WeaponInfo {
    /// The actor that is this weapon (its states are the weapon's).
    pub actor: usize,
    /// 0 bullets, 1 shells, 2 cells, 3 rockets (Doom's `ammotype_t`); `None`
    /// for the fist and chainsaw.
    pub ammo: Option<usize>,
    pub upstate: Option<StateId>,
    pub downstate: Option<StateId>,
    pub readystate: Option<StateId>,
    pub atkstate: Option<StateId>,
    pub flashstate: Option<StateId>,
}

/// The table the simulation reads.
#[derive(Clone, Debug)]
pub struct Info {
    pub table: Arc<ActorTable>,
    /// By actor index.
    pub things: Vec<MobjInfo>,
    /// By [`StateId`].
    pub states: Vec<StateInfo>,
    /// By Doom's weapon number; `None` where the table lacks the weapon.
    pub weapons: Vec<Option<WeaponInfo>>,
    /// The actor of each Doom `mobjtype_t` (`None` if the table lacks it).
    pub by_mt: Vec<Option<usize>>,
    /// The largest radius of any kind: how far a body's box can reach past
    /// the blockmap cell its centre is linked in (Doom's tables: the Spider
    /// Mastermind's 128).
    pub largest_radius: Fixed,
}

impl Info {
    /// Doom's tables from `table`; `fast`: `-fast` or Nightmare (halved
    /// tics on the states marked fast, missiles at their fast speeds).
    pub fn new(table: Arc<ActorTable>, fast: bool) -> Info {
        let doom = doom_info();
        let sprite_number = |s: u16| {
            let name = &table.sprites[usize::from(s)];
            doom.sprites.iter().position(|d| d == name).unwrap_or(usize::from(s)) as i32
        };
        let states = table
            .states
            .iter()
            .map(|s| StateInfo {
                sprite: sprite_number(s.sprite),
                frame: i32::from(s.frame) | if s.bright { FF_FULLBRIGHT } else { 0 },
                tics: if fast && s.fast && s.tics > 0 { s.tics >> 1 } else { s.tics },
                action: s.action.clone(),
                next: s.next,
            })
            .collect();
        let mt_of = |name: &str| doom.things.iter().position(|t| t.actor == name);
        let things: Vec<MobjInfo> =
            table.actors.iter().enumerate().map(|(i, a)| mobj_info(a, i, fast, mt_of(&a.name))).collect();
        let by_mt = doom.things.iter().map(|t| table.index(&t.actor)).collect();
        let weapons = doom
            .weapons
            .iter()
            .map(|w| {
                let actor = table.index(&w.actor)?;
                let def = &table.actors[actor];
                Some(WeaponInfo {
                    actor,
                    ammo: usize::try_from(w.ammo).ok().filter(|&a| a < 4),
                    upstate: def.label("Select"),
                    downstate: def.label("Deselect"),
                    readystate: def.label("Ready"),
                    atkstate: def.label("Fire"),
                    flashstate: def.label("Flash"),
                })
            })
            .collect();
        let largest_radius = things.iter().map(|t| t.radius).max().unwrap_or(Fixed::ZERO);
        Info { table, things, states, weapons, by_mt, largest_radius }
    }

    pub fn state(&self, id: StateId) -> &StateInfo {
        &self.states[id.0 as usize]
    }

    /// The actor index of Doom's `mobjtype_t` `mt` (see [`mt`]).
    pub fn actor_of(&self, mt: usize) -> Option<usize> {
        self.by_mt.get(mt).copied().flatten()
    }

    /// The kind spawned for a map thing's editor number.
    pub fn by_doomednum(&self, number: i32) -> Option<usize> {
        self.things.iter().position(|t| t.doomednum == number && number > 0)
    }

    /// A sound's id by its Doom name (`"pistol"`): 0 when unknown.
    pub fn sound(&self, name: &str) -> usize {
        self.table.sounds.iter().position(|s| s.eq_ignore_ascii_case(name)).map_or(0, |i| i + 1)
    }
}

/// The editor number a map thing of actor `kind` (`def`) is stored under:
/// Doom's, or, for an actor Doom's editors never numbered (Sightline's
/// roster: a RON map's sentries and stalkers), one counted down from the
/// top of the 16-bit range, where no Doom map's things are (vanilla's
/// `mapthing_t` type is a signed short: these read as negative).
pub fn editor_number(def: &ActorDef, kind: usize) -> Option<u16> {
    def.doomednum.or_else(|| u16::try_from(65535usize.checked_sub(kind)?).ok().filter(|&n| n > 32767))
}

/// Doom's `MF_` bits of a table actor's flags.
fn mf_bits(def: &ActorDef) -> u32 {
    let mut bits = 0;
    for &(bit, name, flag) in crate::actors::dehacked::MF_BITS.iter() {
        // TRANSLATION1/2 share the table's one flag; a kind gets the first.
        if name == "TRANSLATION2" || name == "TRANSLATION" {
            continue;
        }
        if flag.is_some_and(|f| def.has(f)) {
            bits |= bit;
        }
    }
    bits
}

fn mobj_info(def: &ActorDef, kind: usize, fast: bool, mt: Option<usize>) -> MobjInfo {
    let fixed = |v: f64| Fixed((v * f64::from(FRACUNIT)).round() as i32);
    let speed = def.speed(fast);
    let sound = |s: Option<usize>| s.map_or(0, |i| i + 1);
    MobjInfo {
        name: def.name.clone(),
        doomednum: editor_number(def, kind).map_or(-1, i32::from),
        spawnhealth: def.health,
        reactiontime: def.reaction_time,
        painchance: def.pain_chance,
        speed: if def.has(ActorFlag::Missile) { fixed(speed).0 } else { speed.round() as i32 },
        radius: fixed(def.radius),
        height: fixed(def.height),
        mass: def.mass,
        damage: def.damage,
        flags: mf_bits(def),
        spawnstate: def.label("Spawn"),
        seestate: def.label("See"),
        painstate: def.label("Pain"),
        meleestate: def.label("Melee"),
        missilestate: def.label("Missile"),
        deathstate: def.label("Death"),
        xdeathstate: def.label("XDeath"),
        raisestate: def.label("Raise"),
        seesound: sound(def.sounds.see),
        attacksound: sound(def.sounds.attack),
        painsound: sound(def.sounds.pain),
        deathsound: sound(def.sounds.death),
        activesound: sound(def.sounds.active),
        mt,
    }
}

/// Doom's `mobjtype_t` numbers (`info.h`), for the behaviours Doom ties to
/// a kind rather than to a flag.
pub mod mt {
    pub const PLAYER: usize = 0;
    pub const POSSESSED: usize = 1;
    pub const SHOTGUY: usize = 2;
    pub const VILE: usize = 3;
    pub const FIRE: usize = 4;
    pub const UNDEAD: usize = 5;
    pub const TRACER: usize = 6;
    pub const SMOKE: usize = 7;
    pub const FATSO: usize = 8;
    pub const FATSHOT: usize = 9;
    pub const CHAINGUY: usize = 10;
    pub const TROOP: usize = 11;
    pub const SERGEANT: usize = 12;
    pub const SHADOWS: usize = 13;
    pub const HEAD: usize = 14;
    pub const BRUISER: usize = 15;
    pub const BRUISERSHOT: usize = 16;
    pub const KNIGHT: usize = 17;
    pub const SKULL: usize = 18;
    pub const SPIDER: usize = 19;
    pub const BABY: usize = 20;
    pub const CYBORG: usize = 21;
    pub const PAIN: usize = 22;
    pub const WOLFSS: usize = 23;
    pub const KEEN: usize = 24;
    pub const BOSSBRAIN: usize = 25;
    pub const BOSSSPIT: usize = 26;
    pub const BOSSTARGET: usize = 27;
    pub const SPAWNSHOT: usize = 28;
    pub const SPAWNFIRE: usize = 29;
    pub const BARREL: usize = 30;
    pub const TROOPSHOT: usize = 31;
    pub const HEADSHOT: usize = 32;
    pub const ROCKET: usize = 33;
    pub const PLASMA: usize = 34;
    pub const BFG: usize = 35;
    pub const ARACHPLAZ: usize = 36;
    pub const PUFF: usize = 37;
    pub const BLOOD: usize = 38;
    pub const TFOG: usize = 39;
    pub const IFOG: usize = 40;
    pub const TELEPORTMAN: usize = 41;
    pub const EXTRABFG: usize = 42;
    pub const INV: usize = 56;
    pub const INS: usize = 58;
}
