//! The actor table: what every thing in a game is and does, as data. Doom's
//! and Doom II's roster ships as `engine/data/actors.ron`; a modder's file
//! (`--actors FILE`) adds actors or replaces them. A map names its things by
//! actor name; the importer maps Doom's editor numbers to the same names.
//!
//! An actor is properties (health, speed, size, sounds, ...), flags by name,
//! and a state machine written the way DeHackEd and DECORATE modders know
//! it: states under labels (`Spawn:`, `See:`, `Missile:`, ...), each a
//! sprite, frame, duration, brightness and an action with typed arguments,
//! ending in `loop`, `stop`, `wait` or `goto Label+N`. Loading resolves
//! inheritance (`based_on`), replacement (`replaces`), every label, sprite,
//! sound and action, and refuses what cannot run (see `load.rs`); the
//! simulation then steps states by index and never looks a name up.
//!
//! - `source.rs`: the RON shape of a table (what a modder writes);
//! - `states.rs`: the state text of one actor, parsed into entries;
//! - `actions.rs`: the registry of actions (names and argument types);
//! - `sounds.rs`: the sound names actors may use (`engine/data/sounds.ron`);
//! - `load.rs`: resolving and checking a table into an [`ActorTable`];
//! - `zdoom.rs`: ZDoom's class names for the table's actors, and ZDoom's
//!   own base classes (`engine/data/zdoom_actors.ron`) for DECORATE.

pub mod actions;
pub mod dehacked;
mod load;
pub mod sounds;
pub mod source;
pub mod states;
#[cfg(test)]
mod tests;
pub mod zdoom;

use std::collections::HashMap;
use std::sync::{Arc, OnceLock};

use serde::Deserialize;

pub use actions::ActionId;
pub use load::ActorTableError;

use crate::map::special::KeyColour;

/// The shipped table: Doom's and Doom II's actors.
const DOOM_TABLE: &str = include_str!("../../data/actors.ron");
/// The shipped table's name in errors.
pub const DOOM_TABLE_PATH: &str = "engine/data/actors.ron";
/// Sightline's own roster (the default level's monsters), layered on
/// Doom's: new actors only, drawn by our own code.
const ROSTER: &str = include_str!("../../data/roster.ron");
pub const ROSTER_PATH: &str = "engine/data/roster.ron";
/// The shipped table's files, in layering order.
const SHIPPED: [(&str, &str); 2] = [(DOOM_TABLE, DOOM_TABLE_PATH), (ROSTER, ROSTER_PATH)];

/// What a thing is, in broad strokes (Doom's categories). It decides what a
/// map thing of this kind means before any state runs: a player start is a
/// place, not a thing; a teleport destination is where teleporters put a
/// body; a key is what the HUD shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum Category {
    /// The player's own body.
    Player,
    /// Player `n`'s start (1 is the single-player start).
    PlayerStart(u8),
    DeathmatchStart,
    /// Where teleporters in its sector put a body.
    TeleportDestination,
    Monster,
    Weapon,
    Ammo,
    Health,
    Armor,
    Powerup,
    Key(KeyColour, KeyForm),
    /// Solid scenery.
    Obstacle,
    /// Scenery that does not block.
    Decoration,
    LightSource,
    Corpse,
    BossBrain,
    BossSpawner,
    BossTarget,
    /// A missile: fired, flies, explodes.
    Projectile,
    /// Puffs, blood, fog and the like: spawned, animated, gone.
    Effect,
    /// Saved by an editor, never spawned (Doom Builder's camera, 32000).
    EditorOnly,
}

impl Category {
    /// Marks a place rather than being a thing: never drawn, never spawned
    /// as a body.
    pub fn is_marker(self) -> bool {
        matches!(
            self,
            Category::PlayerStart(_)
                | Category::DeathmatchStart
                | Category::TeleportDestination
                | Category::BossTarget
                | Category::EditorOnly
        )
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize, Deserialize)]
pub enum KeyForm {
    Card,
    Skull,
}

/// Flags by name: Doom's `MF_` flags, and the behaviours Doom hard-codes by
/// monster type, under the names MBF21 gave them, so that a mod can give
/// them to its own actors.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Deserialize)]
pub enum ActorFlag {
    /// Picked up by touch (Doom's MF_SPECIAL).
    Special,
    /// Blocks movement.
    Solid,
    /// Can be hurt.
    Shootable,
    /// Not linked into sectors: invisible (teleport destinations).
    NoSector,
    /// Not in the blockmap: nothing collides with it.
    NoBlockmap,
    /// Deaf: wakes on sight only (a map thing's flag, allowed here too).
    Ambush,
    /// Spawned hanging from the ceiling.
    SpawnCeiling,
    NoGravity,
    /// May step off ledges higher than 24 units.
    DropOff,
    /// Picks up what it touches (the player).
    Pickup,
    /// Passes through walls and things.
    NoClip,
    /// Slides along walls (the player).
    Slide,
    /// Flies: moves up and down towards its target.
    Float,
    /// Does not set off walk lines when teleported.
    Teleport,
    /// Explodes on contact.
    Missile,
    /// Dropped by a dead monster (half ammo when picked up).
    Dropped,
    /// Drawn as the spectre's fuzz; shots at it spread.
    Shadow,
    /// Puffs, not blood, when hit.
    NoBlood,
    /// A dead body (set at death; allowed here too).
    Corpse,
    /// Counts towards the kill tally.
    CountKill,
    /// Counts towards the item tally.
    CountItem,
    /// Not spawned in deathmatch.
    NotDeathmatch,
    /// Drawn with a colour translation (player colours).
    Translation,
    /// A boss: its see and death sounds play at full volume everywhere;
    /// no splash damage (Doom's cyberdemon and spider mastermind).
    Boss,
    /// Takes no splash damage.
    NoRadiusDamage,
    /// Halves the distance in its missile decision (more eager to fire).
    RangeHalf,
    /// Fires more often at range (Doom's cyberdemon).
    HigherMissileProbability,
    /// Sees, wakes and dies at full volume.
    FullVolumeSounds,
    /// Fires only within 14 * 64 units (Doom's arch-vile).
    ShortMissileRange,
    /// Its attacks do not make victims retaliate (Doom's arch-vile).
    DamageIgnored,
    /// Retaliates at once, ignoring the threshold (Doom's arch-vile).
    NoThreshold,
    /// Melees from further away (Doom's revenant).
    LongMelee,
    /// Its death opens E1M8's tag 666 when all of its kind are dead.
    E1M8Boss,
    E2M8Boss,
    E3M8Boss,
    E4M6Boss,
    E4M8Boss,
    /// Its death lowers MAP07's tag 666 floors.
    Map07Boss1,
    /// Its death raises MAP07's tag 667 floors.
    Map07Boss2,
}

/// A set of [`ActorFlag`]s, one bit each.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct ActorFlags(u64);

impl ActorFlags {
    pub fn of(flags: &[ActorFlag]) -> ActorFlags {
        ActorFlags(flags.iter().fold(0, |bits, &f| bits | 1 << f as u32))
    }

    pub fn has(self, flag: ActorFlag) -> bool {
        self.0 & 1 << flag as u32 != 0
    }

    pub fn set(&mut self, flag: ActorFlag, on: bool) {
        if on {
            self.0 |= 1 << flag as u32;
        } else {
            self.0 &= !(1 << flag as u32);
        }
    }
}

/// Doom's four kinds of ammunition.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Deserialize)]
pub enum AmmoKind {
    Bullets,
    Shells,
    Rockets,
    Cells,
}

impl AmmoKind {
    pub const ALL: [AmmoKind; 4] = [AmmoKind::Bullets, AmmoKind::Shells, AmmoKind::Rockets, AmmoKind::Cells];

    /// Its place in [`Self::ALL`] (and in the player's ammunition arrays).
    pub fn index(self) -> usize {
        self as usize
    }
}

/// Doom's power-ups.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Deserialize)]
pub enum Power {
    Invulnerability,
    /// Berserk.
    Strength,
    Invisibility,
    /// The radiation suit.
    IronFeet,
    /// The computer area map.
    AllMap,
    /// The light amplification visor.
    Infrared,
}

/// One thing a pickup gives.
#[derive(Clone, Debug, PartialEq, Deserialize)]
pub enum Give {
    /// Health up to `max`.
    Health {
        amount: i32,
        max: i32,
    },
    /// Armour of a class (1 green, 2 blue) when it is better than what is worn.
    Armor {
        points: i32,
        class: u8,
    },
    /// Armour points up to `max`, class 1 when none is worn.
    ArmorBonus {
        points: i32,
        max: i32,
    },
    Ammo(AmmoKind, i32),
    /// The weapon actor of that name.
    Weapon(String),
    Key(KeyColour, KeyForm),
    Power(Power),
    /// Doubles the ammo limits and gives a clip of each kind.
    Backpack,
}

/// What touching a pickup does (Doom's P_TouchSpecialThing, as data).
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pickup {
    pub give: Vec<Give>,
    pub message: String,
    /// A sound name from the sound list.
    pub sound: String,
    /// Picked up even when it gives nothing (bonuses, spheres, power-ups).
    #[serde(default)]
    pub always: bool,
}

/// A weapon the player can hold: its slot (the number key), its ammunition,
/// and the labels `Ready`, `Select`, `Deselect`, `Fire` (and `Flash`).
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WeaponDef {
    pub slot: u8,
    #[serde(default)]
    pub ammo: Option<AmmoKind>,
    #[serde(default)]
    pub ammo_use: i32,
}

/// An actor's sounds by role, as indices into the sound list.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sounds {
    pub see: Option<usize>,
    pub attack: Option<usize>,
    pub pain: Option<usize>,
    pub death: Option<usize>,
    pub active: Option<usize>,
}

/// An index into [`ActorTable::states`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
pub struct StateId(pub u32);

/// An action's argument, checked against the action's signature.
#[derive(Clone, Debug, PartialEq)]
pub enum Arg {
    Int(i32),
    Number(f64),
    /// An actor, by index into the table.
    Actor(usize),
    /// A sound, by index into the sound list.
    Sound(usize),
    /// A state of the same actor.
    State(StateId),
}

/// A state's action and its arguments (defaults filled in).
#[derive(Clone, Debug, PartialEq)]
pub struct ActionCall {
    pub action: ActionId,
    pub args: Vec<Arg>,
}

/// One state of a state machine.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// An index into [`ActorTable::sprites`].
    pub sprite: u16,
    /// The frame: 0 is `A`.
    pub frame: u8,
    /// Ticks it lasts; -1 stays for ever.
    pub tics: i32,
    /// Drawn at full brightness.
    pub bright: bool,
    /// Halved on fast monsters (skill 5, `-fast`).
    pub fast: bool,
    pub action: Option<ActionCall>,
    /// What follows; `None` removes the actor (`stop`).
    pub next: Option<StateId>,
}

/// The labels every engine path knows; an actor may define others too.
pub const LABELS: [&str; 13] = [
    "Spawn", "See", "Melee", "Missile", "Pain", "Death", "XDeath", "Raise", "Ready", "Select", "Deselect", "Fire",
    "Flash",
];

/// One actor, resolved: inheritance applied, names turned into indices.
#[derive(Clone, Debug, PartialEq)]
pub struct ActorDef {
    pub name: String,
    /// Doom's editor number, which WADs store.
    pub doomednum: Option<u16>,
    pub category: Category,
    pub health: i32,
    pub reaction_time: i32,
    /// Out of 256: the chance a hit makes it flinch.
    pub pain_chance: i32,
    /// Map units a step for monsters (Doom moves them in steps), a tick for
    /// missiles.
    pub speed: f64,
    /// A missile's speed on fast skills, when it differs.
    pub fast_speed: Option<f64>,
    pub radius: f64,
    pub height: f64,
    pub mass: i32,
    /// A missile's damage factor (damage is 1d8 times it).
    pub damage: i32,
    pub sounds: Sounds,
    pub flags: ActorFlags,
    /// Actors of one species do not hurt each other with missiles (Doom's
    /// barons and hell knights); an index into the table, itself by default.
    pub species: usize,
    /// Dropped at death.
    pub drop: Option<usize>,
    pub pickup: Option<Pickup>,
    pub weapon: Option<WeaponDef>,
    /// Labels to states, in the order written.
    pub labels: Vec<(String, StateId)>,
    /// The actor that spawns in its place, if another replaces it.
    pub replaced_by: Option<usize>,
}

impl ActorDef {
    /// Its speed, or its fast speed (skill 5, `-fast`) if it has one.
    pub fn speed(&self, fast: bool) -> f64 {
        match (fast, self.fast_speed) {
            (true, Some(s)) => s,
            _ => self.speed,
        }
    }

    pub fn has(&self, flag: ActorFlag) -> bool {
        self.flags.has(flag)
    }

    /// The state a label names.
    pub fn label(&self, name: &str) -> Option<StateId> {
        self.labels.iter().find(|(l, _)| l.eq_ignore_ascii_case(name)).map(|&(_, s)| s)
    }

    /// The key it gives, if it is a key.
    pub fn key(&self) -> Option<KeyColour> {
        match self.category {
            Category::Key(colour, _) => Some(colour),
            _ => None,
        }
    }
}

/// A resolved, checked actor table.
#[derive(Clone, Debug)]
pub struct ActorTable {
    pub actors: Vec<ActorDef>,
    pub states: Vec<State>,
    /// Sprite names (four characters), indexed by [`State::sprite`].
    pub sprites: Vec<String>,
    /// Sound names, indexed by the sound fields.
    pub sounds: Vec<String>,
    by_name: HashMap<String, usize>,
    by_number: HashMap<u16, usize>,
}

static ACTIVE: OnceLock<Arc<ActorTable>> = OnceLock::new();

impl ActorTable {
    /// The shipped table: Doom's and Doom II's actors, and Sightline's own
    /// roster on top (checked by the tests, so this cannot fail in a release).
    pub fn doom() -> &'static Arc<ActorTable> {
        static TABLE: OnceLock<Arc<ActorTable>> = OnceLock::new();
        TABLE.get_or_init(|| {
            let table =
                ActorTable::parse(&SHIPPED).unwrap_or_else(|e| panic!("the shipped actor table is broken: {e}"));
            Arc::new(table)
        })
    }

    /// The table this process plays with: the one [`ActorTable::install`]ed
    /// (a user's `--actors` file on the shipped table), else the shipped
    /// one. Map validation, materials, games and the status bar read it.
    pub fn active() -> &'static Arc<ActorTable> {
        ACTIVE.get_or_init(|| ActorTable::doom().clone())
    }

    /// Makes `table` the [`ActorTable::active`] one for the rest of the
    /// process. It must come before anything reads the active table (a
    /// program does it first thing); afterwards it is refused.
    pub fn install(table: ActorTable) -> Result<(), ActorTableError> {
        ACTIVE.set(Arc::new(table)).map_err(|_| ActorTableError::AlreadyActive)
    }

    /// The shipped table with a user's file on top: its actors are added,
    /// or replace the shipped ones of the same name.
    pub fn with_file(path: &std::path::Path) -> Result<ActorTable, ActorTableError> {
        let label = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| ActorTableError::Io { path: label.clone(), message: e.to_string() })?;
        ActorTable::parse(&[SHIPPED[0], SHIPPED[1], (&text, &label)])
    }

    /// Parses, layers (later files add or replace actors) and checks tables.
    pub fn parse(files: &[(&str, &str)]) -> Result<ActorTable, ActorTableError> {
        load::load(files)
    }

    /// Actor files (RON, our format) layered on this resolved table: the
    /// table's actors keep their indices; the files' actors may be
    /// `based_on` them or replace them.
    // Errors are made once, when a table is refused (as in `load.rs`).
    #[allow(clippy::result_large_err)]
    pub fn extend(&self, files: &[(&str, &str)]) -> Result<ActorTable, ActorTableError> {
        let parsed = files
            .iter()
            .map(|&(text, path)| Ok((load::parse_source(text, path)?, path.to_string())))
            .collect::<Result<Vec<_>, ActorTableError>>()?;
        load::extend(self, parsed)
    }

    /// As [`ActorTable::extend`], with the sources already built (the
    /// DECORATE builder writes them).
    #[allow(clippy::result_large_err)]
    pub fn extend_with(&self, files: Vec<(source::TableSource, String)>) -> Result<ActorTable, ActorTableError> {
        load::extend(self, files)
    }

    pub fn index(&self, name: &str) -> Option<usize> {
        self.by_name.get(name).copied()
    }

    pub fn get(&self, name: &str) -> Option<&ActorDef> {
        self.index(name).map(|i| &self.actors[i])
    }

    pub fn by_doomednum(&self, number: u16) -> Option<&ActorDef> {
        self.by_number.get(&number).map(|&i| &self.actors[i])
    }

    /// The actor that spawns for `index`: itself, or the actor that
    /// replaces it (replacements are checked for cycles when loading).
    pub fn spawned(&self, mut index: usize) -> usize {
        while let Some(by) = self.actors[index].replaced_by {
            index = by;
        }
        index
    }

    pub fn state(&self, id: StateId) -> &State {
        &self.states[id.0 as usize]
    }

    /// The sprite lump stem of an actor's first spawn frame (`BKEYA`), if it
    /// is drawn. Markers are not: a start is where a player appears, not a
    /// thing; nor are things that are never linked into a sector.
    pub fn first_frame(&self, actor: &ActorDef) -> Option<String> {
        if actor.category.is_marker() || actor.has(ActorFlag::NoSector) {
            return None;
        }
        let state = self.state(actor.label("Spawn")?);
        Some(format!("{}{}", self.sprites[usize::from(state.sprite)], char::from(b'A' + state.frame)))
    }

    /// The states an actor can be in: every state its labels lead to.
    pub fn states_of(&self, actor: &ActorDef) -> Vec<StateId> {
        let mut seen: Vec<StateId> = Vec::new();
        for &(_, start) in &actor.labels {
            let mut at = Some(start);
            while let Some(id) = at.filter(|id| !seen.contains(id)) {
                seen.push(id);
                at = self.state(id).next;
            }
        }
        seen.sort();
        seen
    }

    /// `roots` and every actor they can bring into play: what spawns in
    /// their place, what they drop, and what their actions spawn (missiles,
    /// fire, lost souls...), sorted.
    pub fn closure(&self, roots: impl IntoIterator<Item = usize>) -> Vec<usize> {
        let mut seen = vec![false; self.actors.len()];
        let mut todo: Vec<usize> = roots.into_iter().collect();
        while let Some(i) = todo.pop() {
            if std::mem::replace(&mut seen[i], true) {
                continue;
            }
            let a = &self.actors[i];
            todo.extend(a.replaced_by.iter().chain(&a.drop));
            for id in self.states_of(a) {
                let args = self.state(id).action.iter().flat_map(|c| &c.args);
                todo.extend(args.filter_map(|arg| match arg {
                    Arg::Actor(n) => Some(*n),
                    _ => None,
                }));
            }
        }
        (0..seen.len()).filter(|&i| seen[i]).collect()
    }

    /// The known actor name nearest to `name` (by edit distance), for "did
    /// you mean".
    pub fn nearest(&self, name: &str) -> Option<&str> {
        nearest(name, self.actors.iter().map(|a| a.name.as_str()))
    }
}

/// The candidate nearest to `name` by edit distance, if it is near enough
/// to be a misspelling.
pub fn nearest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .map(|c| (edit_distance(&name.to_ascii_lowercase(), &c.to_ascii_lowercase()), c))
        .filter(|&(d, _)| d <= name.len().max(3) / 2)
        .min()
        .map(|(_, c)| c)
}

/// Levenshtein distance over bytes (names are ASCII).
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, &ca) in a.iter().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (diagonal + usize::from(ca != cb)).min(row[j] + 1).min(row[j + 1] + 1);
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}
