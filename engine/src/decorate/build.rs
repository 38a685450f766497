//! DECORATE's syntax tree onto the actor table: each lump's actors, in the
//! order written, become actors of our table (`ActorSource`s with their
//! state text written out in our syntax), layered with
//! [`ActorTable::extend_with`] on the base table and ZDoom's base classes
//! ([`zdoom::with_bases`]), so the loader's checks (labels, gotos, 0-tic
//! cycles, argument types) apply to them as to any table. The result is the
//! table the game plays (`SimGame::with_table` takes it).
//!
//! An actor is named as written, lower-cased (`CustomMedikit` is
//! `custommedikit`; [`zdoom::find`] finds it either way). A parent or a
//! replaced class is a table actor or a ZDoom class name. What has no
//! equivalent here (a flag, a property, an action, a frame keyword, an
//! `#include`) is left out and listed in [`Built::unread`] with its lump
//! and line; only an actor that cannot be built at all (an unknown parent,
//! a state the loader refuses) is an error.

use super::{Action, Actor, ActorItem, Decorate, Duration, Flow, Frame, FrameKeyword, Property, StateItem, TopLevel};
use super::{At, Value};
use crate::actors::actions::{self, ArgKind};
use crate::actors::dehacked::Strings;
use crate::actors::source::{ActorSource, SoundsSource, TableSource};
use crate::actors::WeaponDef;
use crate::actors::{zdoom, ActorDef, ActorFlag, ActorTable, ActorTableError, AmmoKind, Category, Give, Pickup};

/// The built table and what of the lumps it left out.
#[derive(Clone, Debug)]
pub struct Built {
    pub table: ActorTable,
    /// `lump:line: actor Name: what` for every flag, property, action or
    /// keyword with no equivalent here.
    pub unread: Vec<String>,
}

/// An actor that cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DecorateBuildError {
    #[error("{lump}:{line}: actor {actor}: {message}")]
    Actor { lump: String, line: usize, actor: String, message: String },
    #[error("ZDoom's base classes ({path}) do not load: {message}")]
    Bases { path: &'static str, message: String },
}

/// Builds every lump's actors (`lumps`: a name such as `"cig.wad:DECORATE"`
/// and its tree) on `base`, ZDoom's base classes added first.
pub fn apply(lumps: &[(String, Decorate)], base: &ActorTable) -> Result<Built, DecorateBuildError> {
    let mut table = zdoom::with_bases(base)
        .map_err(|e| DecorateBuildError::Bases { path: zdoom::ZDOOM_ACTORS_PATH, message: e.to_string() })?;
    let mut unread = Vec::new();
    for (lump, decorate) in lumps {
        for item in &decorate.items {
            match item {
                TopLevel::Actor(actor) => {
                    let mut builder = Builder { table: &table, lump, actor, unread: &mut unread };
                    table = builder.build()?;
                }
                TopLevel::Include { path, at } => {
                    unread.push(format!("{lump}:{}: #include \"{path}\" is not followed", at.line))
                }
                TopLevel::Const { name, at, .. } => {
                    unread.push(format!("{lump}:{}: const {name} is not read", at.line))
                }
                TopLevel::Enum { at, .. } => unread.push(format!("{lump}:{}: enum is not read", at.line)),
            }
        }
    }
    Ok(Built { table, unread })
}

/// ZDoom's flags that are ours too (ZDoom's names, upper case).
const FLAGS: &[(&str, ActorFlag)] = &[
    ("SPECIAL", ActorFlag::Special),
    ("SOLID", ActorFlag::Solid),
    ("SHOOTABLE", ActorFlag::Shootable),
    ("NOSECTOR", ActorFlag::NoSector),
    ("NOBLOCKMAP", ActorFlag::NoBlockmap),
    ("AMBUSH", ActorFlag::Ambush),
    ("SPAWNCEILING", ActorFlag::SpawnCeiling),
    ("NOGRAVITY", ActorFlag::NoGravity),
    ("DROPOFF", ActorFlag::DropOff),
    ("PICKUP", ActorFlag::Pickup),
    ("NOCLIP", ActorFlag::NoClip),
    ("SLIDESONWALLS", ActorFlag::Slide),
    ("FLOAT", ActorFlag::Float),
    ("TELEPORT", ActorFlag::Teleport),
    ("MISSILE", ActorFlag::Missile),
    ("DROPPED", ActorFlag::Dropped),
    ("SHADOW", ActorFlag::Shadow),
    ("NOBLOOD", ActorFlag::NoBlood),
    ("CORPSE", ActorFlag::Corpse),
    ("COUNTKILL", ActorFlag::CountKill),
    ("COUNTITEM", ActorFlag::CountItem),
    ("NOTDMATCH", ActorFlag::NotDeathmatch),
    ("BOSS", ActorFlag::Boss),
    ("NORADIUSDMG", ActorFlag::NoRadiusDamage),
    ("FULLVOLSOUNDS", ActorFlag::FullVolumeSounds),
];

/// The inventory properties of one actor, gathered before they become a
/// pickup or a weapon.
#[derive(Default)]
struct Item {
    amount: Option<i32>,
    max_amount: Option<i32>,
    message: Option<String>,
    sound: Option<String>,
    always: Option<bool>,
    ammo_use: Option<i32>,
    ammo_give: Option<i32>,
    ammo_type: Option<AmmoKind>,
    slot: Option<u8>,
    /// Where the first inventory property was, for the note when the actor
    /// is no item.
    at: Option<At>,
}

struct Builder<'a> {
    table: &'a ActorTable,
    lump: &'a str,
    actor: &'a Actor,
    unread: &'a mut Vec<String>,
}

impl Builder<'_> {
    fn fail(&self, line: usize, message: String) -> DecorateBuildError {
        DecorateBuildError::Actor { lump: self.lump.to_string(), line, actor: self.actor.name.clone(), message }
    }

    fn note(&mut self, at: At, what: String) {
        self.unread.push(format!("{}:{}: actor {}: {what}", self.lump, at.line, self.actor.name));
    }

    /// A class name as a table actor's index.
    fn class(&self, what: &str, class: &str) -> Result<usize, DecorateBuildError> {
        zdoom::find(self.table, class)
            .ok_or_else(|| self.fail(self.actor.at.line, format!("unknown {what} class {class}")))
    }

    fn build(&mut self) -> Result<ActorTable, DecorateBuildError> {
        let actor = self.actor;
        let line = actor.at.line;
        let name = actor.name.to_ascii_lowercase();
        if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
            return Err(self.fail(line, "a name of letters, digits and _ is all our table holds".into()));
        }
        let parent = actor.parent.as_deref().map(|p| self.class("parent", p)).transpose()?;
        let replaces = actor.replaces.as_deref().map(|r| self.class("replaced", r)).transpose()?;
        let doomednum = match actor.doomednum {
            None | Some(-1) => None,
            Some(n) => Some(
                u16::try_from(n)
                    .ok()
                    .filter(|&n| n > 0)
                    .ok_or_else(|| self.fail(line, format!("editor number {n} is not within 1..=65535")))?,
            ),
        };
        if actor.native {
            self.note(actor.at, "`native` is ignored".into());
        }
        let parent_def = parent.map(|p| &self.table.actors[p]);
        let mut source = ActorSource {
            name: name.clone(),
            based_on: parent_def.map(|p| p.name.clone()),
            replaces: replaces.map(|r| self.table.actors[r].name.clone()),
            doomednum,
            ..ActorSource::default()
        };
        let mut item = Item::default();
        for body in &actor.body {
            match body {
                ActorItem::Flag { name, set, at } => self.flag(&mut source, &mut item, name, *set, *at),
                ActorItem::Property(p) => self.property(&mut source, &mut item, p),
                ActorItem::States(_) => {}
                ActorItem::Unknown { text, at } => self.note(*at, format!("`{text}` is not read")),
            }
        }
        let (states, sprites, lines) = self.states_text();
        if !states.is_empty() {
            source.states = Some(states);
        }
        self.item(&mut source, item, parent_def);
        let file = TableSource { sprites, actors: vec![source] };
        self.table.extend_with(vec![(file, self.lump.to_string())]).map_err(|e| match e {
            ActorTableError::State { label, line: text_line, text, message, .. } => {
                let at = lines.get(text_line.wrapping_sub(1)).copied().unwrap_or(line);
                self.fail(at, format!("state {label} (`{text}`): {message}"))
            }
            ActorTableError::Actor { message, .. } => self.fail(line, message),
            other => self.fail(line, other.to_string()),
        })
    }

    fn flag(&mut self, source: &mut ActorSource, item: &mut Item, name: &str, set: bool, at: At) {
        let upper = name.to_ascii_uppercase();
        if let Some(&(_, flag)) = FLAGS.iter().find(|(n, _)| *n == upper) {
            if set {
                source.add_flags.push(flag);
            } else {
                source.remove_flags.push(flag);
            }
            return;
        }
        match upper.as_str() {
            "INVENTORY.ALWAYSPICKUP" => item.always = Some(set),
            "ISMONSTER" if set => source.category = Some(Category::Monster),
            _ => self.note(at, format!("flag {}{name} has no equivalent here", if set { '+' } else { '-' })),
        }
    }

    fn property(&mut self, source: &mut ActorSource, item: &mut Item, p: &Property) {
        let key = p.name.to_ascii_lowercase();
        let int = match p.values.as_slice() {
            [Value::Int(v)] => i32::try_from(*v).ok(),
            _ => None,
        };
        let number = match p.values.as_slice() {
            [Value::Int(v)] => Some(*v as f64),
            [Value::Float(v)] => Some(*v),
            _ => None,
        };
        let text = match p.values.as_slice() {
            [Value::Str(s) | Value::Name(s)] => Some(s.clone()),
            _ => None,
        };
        let mut bad = false;
        let mut set_int = |slot: &mut Option<i32>| match int {
            Some(v) => *slot = Some(v),
            None => bad = true,
        };
        match key.as_str() {
            "health" => set_int(&mut source.health),
            "mass" => set_int(&mut source.mass),
            "painchance" => set_int(&mut source.pain_chance),
            "reactiontime" => set_int(&mut source.reaction_time),
            "damage" => set_int(&mut source.damage),
            "inventory.amount" => set_int(&mut item.amount),
            "inventory.maxamount" => set_int(&mut item.max_amount),
            "weapon.ammouse" | "weapon.ammouse1" => set_int(&mut item.ammo_use),
            "weapon.ammogive" | "weapon.ammogive1" => set_int(&mut item.ammo_give),
            "radius" | "height" | "speed" | "fastspeed" => {
                let slot = match key.as_str() {
                    "radius" => &mut source.radius,
                    "height" => &mut source.height,
                    "speed" => &mut source.speed,
                    _ => &mut source.fast_speed,
                };
                match number {
                    Some(v) => *slot = Some(v),
                    None => bad = true,
                }
            }
            "seesound" | "attacksound" | "painsound" | "deathsound" | "activesound" => {
                let ours = text.as_deref().and_then(|t| zdoom::sound(self.table, t));
                let Some(index) = ours else {
                    let heard = text.unwrap_or_else(|| "?".into());
                    return self.note(p.at, format!("{}: no sound of ours is {heard:?}", p.name));
                };
                let ours = Some(self.table.sounds[index].clone());
                if source.sounds.is_none() {
                    source.sounds = Some(self.inherited_sounds(source));
                }
                let sounds = source.sounds.get_or_insert_with(SoundsSource::default);
                match key.as_str() {
                    "seesound" => sounds.see = ours,
                    "attacksound" => sounds.attack = ours,
                    "painsound" => sounds.pain = ours,
                    "deathsound" => sounds.death = ours,
                    _ => sounds.active = ours,
                }
            }
            "monster" => {
                source.add_flags.extend([ActorFlag::Solid, ActorFlag::Shootable, ActorFlag::CountKill]);
                source.category = Some(Category::Monster);
            }
            // ZDoom's Projectile is also NOTELEPORT, IMPACT and PCROSS
            // (line activation by missiles), which we do not have.
            "projectile" => {
                source.add_flags.extend([
                    ActorFlag::NoBlockmap,
                    ActorFlag::NoGravity,
                    ActorFlag::DropOff,
                    ActorFlag::Missile,
                ]);
                source.category = Some(Category::Projectile);
            }
            "inventory.pickupmessage" => match text {
                Some(t) => item.message = Some(language(&t)),
                None => bad = true,
            },
            "inventory.pickupsound" => match text.as_deref().and_then(|t| zdoom::sound(self.table, t)) {
                Some(i) => item.sound = Some(self.table.sounds[i].clone()),
                None => return self.note(p.at, format!("{}: no sound of ours is {text:?}", p.name)),
            },
            "weapon.ammotype" | "weapon.ammotype1" => {
                let kind = text
                    .as_deref()
                    .and_then(|t| zdoom::find(self.table, t))
                    .and_then(|i| ammo_of(&self.table.actors[i]));
                match kind {
                    Some(k) => item.ammo_type = Some(k),
                    None => return self.note(p.at, format!("{}: {text:?} is none of Doom's four ammunitions", p.name)),
                }
            }
            "weapon.slotnumber" => match int.and_then(|v| u8::try_from(v).ok()) {
                Some(v) => item.slot = Some(v),
                None => bad = true,
            },
            _ => return self.note(p.at, format!("property {} has no equivalent here", p.name)),
        }
        if key.starts_with("inventory.") || key.starts_with("weapon.") {
            item.at.get_or_insert(p.at);
        }
        if bad {
            let values: Vec<String> = p.values.iter().map(describe).collect();
            self.note(p.at, format!("property {} {}: not a value we can read", p.name, values.join(", ")));
        }
    }

    /// The parent's sounds, as names, for a child that changes one of them.
    fn inherited_sounds(&self, source: &ActorSource) -> SoundsSource {
        let Some(def) = source.based_on.as_deref().and_then(|p| self.table.get(p)) else {
            return SoundsSource::default();
        };
        let name = |s: Option<usize>| s.map(|i| self.table.sounds[i].clone());
        SoundsSource {
            see: name(def.sounds.see),
            attack: name(def.sounds.attack),
            pain: name(def.sounds.pain),
            death: name(def.sounds.death),
            active: name(def.sounds.active),
        }
    }

    /// The pickup or weapon the inventory properties make, by what the
    /// parent is: a Health gives health, a weapon is a weapon.
    fn item(&mut self, source: &mut ActorSource, item: Item, parent: Option<&ActorDef>) {
        let category = parent.map(|p| p.category);
        let given = item.at.is_some() || item.always.is_some();
        match category {
            Some(Category::Health) => {
                let mut pickup = parent.and_then(|p| p.pickup.clone()).unwrap_or_else(|| Pickup {
                    give: Vec::new(),
                    message: String::new(),
                    sound: "itemup".into(),
                    always: false,
                });
                let (old_amount, old_max) = pickup
                    .give
                    .iter()
                    .find_map(|g| match g {
                        Give::Health { amount, max } => Some((*amount, *max)),
                        _ => None,
                    })
                    .unwrap_or((1, 100));
                // ZDoom's MaxAmount 0 means the player's maximum, 100.
                let max = item.max_amount.filter(|&m| m > 0).unwrap_or(if item.max_amount == Some(0) {
                    100
                } else {
                    old_max
                });
                let health = health_give(item.amount.unwrap_or(old_amount), max);
                pickup.give.retain(|g| !matches!(g, Give::Health { .. }));
                pickup.give.insert(0, health);
                if let Some(m) = item.message {
                    pickup.message = m;
                }
                if let Some(s) = item.sound {
                    pickup.sound = s;
                }
                if let Some(a) = item.always {
                    pickup.always = a;
                }
                source.pickup = Some(pickup);
            }
            Some(Category::Weapon) => {
                let old = parent.and_then(|p| p.weapon.clone());
                let ammo = item.ammo_type.or(old.as_ref().and_then(|w| w.ammo));
                // Doom's slots by ammunition, when ZDoom's SlotNumber is not given.
                let slot = item.slot.or(old.as_ref().map(|w| w.slot)).unwrap_or(match ammo {
                    Some(AmmoKind::Shells) => 3,
                    Some(AmmoKind::Bullets) => 4,
                    Some(AmmoKind::Rockets) => 5,
                    Some(AmmoKind::Cells) => 6,
                    None => 1,
                });
                let ammo_use = item.ammo_use.or(old.as_ref().map(|w| w.ammo_use)).unwrap_or(0);
                source.weapon = Some(WeaponDef { slot, ammo, ammo_use });
                let mut give = vec![Give::Weapon(source.name.clone())];
                if let (Some(kind), Some(rounds)) = (ammo, item.ammo_give) {
                    give.push(Give::Ammo(kind, rounds));
                }
                let old_pickup = parent.and_then(|p| p.pickup.clone());
                source.pickup = Some(Pickup {
                    give,
                    message: item.message.or(old_pickup.as_ref().map(|p| p.message.clone())).unwrap_or_default(),
                    sound: item.sound.unwrap_or_else(|| "wpnup".into()),
                    always: item.always.unwrap_or(false),
                });
            }
            _ if given => {
                let at = item.at.unwrap_or(self.actor.at);
                self.note(at, "inventory properties on an actor that is no Health or weapon are not read".into());
            }
            _ => {}
        }
    }

    /// The actor's `States` written in our syntax, the sprites it uses, and
    /// for each line of that text the DECORATE line it came from.
    fn states_text(&mut self) -> (String, Vec<String>, Vec<usize>) {
        let (mut text, mut sprites, mut lines) = (String::new(), Vec::new(), Vec::new());
        let mut previous: Option<(String, char)> = None;
        let items: Vec<&StateItem> = self.actor.states().collect();
        for item in items {
            let (line, at) = match item {
                StateItem::Label { name, at } => (format!("{name}:"), *at),
                StateItem::Flow { flow, at } => (self.flow(flow, *at), *at),
                StateItem::Frame(frame) => match self.frame(frame, &mut previous) {
                    Some((line, sprite)) => {
                        if !sprites.contains(&sprite) {
                            sprites.push(sprite);
                        }
                        (line, frame.at)
                    }
                    None => continue,
                },
            };
            text.push_str(&line);
            text.push('\n');
            lines.push(at.line);
        }
        (text, sprites, lines)
    }

    fn flow(&mut self, flow: &Flow, at: At) -> String {
        match flow {
            Flow::Loop => "loop".into(),
            Flow::Stop => "stop".into(),
            Flow::Wait => "wait".into(),
            Flow::Fail => {
                self.note(at, "`fail` (for custom inventory) is read as `stop`".into());
                "stop".into()
            }
            Flow::Goto { scope, label, offset } => {
                let scope = match scope.as_deref() {
                    None => String::new(),
                    Some(s) if s.eq_ignore_ascii_case("super") => "Super::".into(),
                    Some(s) => {
                        self.note(at, format!("goto {s}::{label}: a class scope other than Super is read as Super"));
                        "Super::".into()
                    }
                };
                match offset {
                    0 => format!("goto {scope}{label}"),
                    n => format!("goto {scope}{label}+{n}"),
                }
            }
        }
    }

    /// One frame line in our syntax and its sprite; `None` (noted) when it
    /// cannot be written.
    fn frame(&mut self, frame: &Frame, previous: &mut Option<(String, char)>) -> Option<(String, String)> {
        let at = frame.at;
        // `####` and `#` keep the previous frame's sprite and letter.
        let sprite = match (frame.sprite.as_str(), previous.as_ref()) {
            ("####" | "----", Some((s, _))) => s.clone(),
            (s, _) if s.len() == 4 && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') => {
                s.to_ascii_uppercase()
            }
            (s, _) => {
                self.note(at, format!("sprite {s:?} cannot be written: the frame is left out"));
                return None;
            }
        };
        let mut letters = String::new();
        for c in frame.frames.chars() {
            let c = match (c, previous.as_ref()) {
                ('#', Some((_, p))) => *p,
                (c, _) => c.to_ascii_uppercase(),
            };
            if !matches!(c, 'A'..='Z' | '[' | '\\' | ']') {
                self.note(at, format!("frame letter {c:?} cannot be written: the frame is left out"));
                return None;
            }
            letters.push(c);
        }
        *previous = Some((sprite.clone(), letters.chars().last().unwrap_or('A')));
        let tics = match &frame.duration {
            Duration::Tics(t) => *t,
            Duration::Random(low, high) => {
                self.note(at, format!("random({low}, {high}) tics are read as their minimum"));
                low.to_string().parse().unwrap_or(1)
            }
        };
        let mut line = format!("{sprite} {letters} {tics}");
        for keyword in &frame.keywords {
            match keyword {
                FrameKeyword::Bright => line.push_str(" bright"),
                FrameKeyword::Fast => line.push_str(" fast"),
                other => self.note(at, format!("frame keyword {other:?} is not read")),
            }
        }
        if let Some((x, y)) = &frame.offset {
            self.note(at, format!("Offset({x}, {y}) is not read"));
        }
        if let Some(action) = &frame.action {
            if let Some(call) = self.action(action, at) {
                line.push(' ');
                line.push_str(&call);
            }
        }
        Some((line, sprite))
    }

    /// An action call in our syntax, its arguments translated (class names
    /// to our actors, ZDoom's sounds to ours); `None` (noted) when the
    /// action is not ours or an argument cannot be read.
    fn action(&mut self, action: &Action, at: At) -> Option<String> {
        let Some(id) = actions::find(&action.name) else {
            self.note(at, format!("action {} is not ours: the state runs without it", action.name));
            return None;
        };
        let spec = actions::spec(id);
        if action.args.len() > spec.args.len() {
            let extra: Vec<String> = action.args[spec.args.len()..].iter().map(|e| e.to_string()).collect();
            self.note(
                at,
                format!("{}: arguments past {} are not read ({})", spec.name, spec.args.len(), extra.join(", ")),
            );
        }
        let mut args = Vec::new();
        for (expr, arg) in action.args.iter().zip(spec.args) {
            let word = match expr.tokens.as_slice() {
                [one] => one.clone(),
                // A negative number is two tokens.
                [minus, n] if minus == "-" => format!("-{n}"),
                _ => {
                    self.note(
                        at,
                        format!("{}: argument {} `{expr}` is an expression we do not evaluate", spec.name, arg.name),
                    );
                    return None;
                }
            };
            let quoted = word.strip_prefix('"').and_then(|w| w.strip_suffix('"')).map(str::to_string);
            let written = match arg.kind {
                ArgKind::Actor => {
                    let class = quoted.unwrap_or_else(|| word.clone());
                    match zdoom::find(self.table, &class) {
                        Some(i) => format!("\"{}\"", self.table.actors[i].name),
                        None => {
                            self.note(at, format!("{}: no actor {class:?}", spec.name));
                            return None;
                        }
                    }
                }
                ArgKind::Sound => {
                    let name = quoted.unwrap_or_else(|| word.clone());
                    match zdoom::sound(self.table, &name) {
                        Some(i) => format!("\"{}\"", self.table.sounds[i]),
                        None => {
                            self.note(at, format!("{}: no sound of ours is {name:?}", spec.name));
                            return None;
                        }
                    }
                }
                ArgKind::State => quoted.unwrap_or(word),
                ArgKind::Int | ArgKind::Number => match word.to_ascii_lowercase().as_str() {
                    "true" => "1".into(),
                    "false" => "0".into(),
                    _ if word.parse::<f64>().is_ok() => word,
                    _ => {
                        self.note(at, format!("{}: argument {} `{word}` is not a number", spec.name, arg.name));
                        return None;
                    }
                },
            };
            args.push(written);
        }
        Some(if args.is_empty() { spec.name.to_string() } else { format!("{}({})", spec.name, args.join(", ")) })
    }
}

/// What a Health pickup of `amount` up to `max` gives, as our table says
/// it. ZDoom's `P_GiveBody` reads a negative amount as a percentage of the
/// maximum to raise health to ("A negative value sets you up with a
/// percentage of your full health", Strife's rule): Amount -25 with
/// MaxAmount 100 lifts a player below 25 to 25 and does nothing above, so
/// health_gathering_supreme's "Poison" never hurts (its author's comment,
/// "this doesn't work of course", is right). Raising to 25 is the same as
/// giving 25 up to 25, which is how it is written here.
fn health_give(amount: i32, max: i32) -> Give {
    if amount < 0 {
        let floor = max.saturating_mul(amount.saturating_neg()) / 100;
        Give::Health { amount: floor, max: floor }
    } else {
        Give::Health { amount, max }
    }
}

/// The ammunition an ammo actor gives, if it is one of Doom's four.
fn ammo_of(def: &ActorDef) -> Option<AmmoKind> {
    def.pickup.as_ref()?.give.iter().find_map(|g| match g {
        Give::Ammo(kind, _) => Some(*kind),
        _ => None,
    })
}

/// A pickup message: `$NAME` is a LANGUAGE string, Doom's English text when
/// doom.exe has it.
fn language(text: &str) -> String {
    match text.strip_prefix('$') {
        Some(name) => Strings::original(name).map_or_else(|| text.to_string(), str::to_string),
        None => text.to_string(),
    }
}

fn describe(value: &Value) -> String {
    match value {
        Value::Int(v) => v.to_string(),
        Value::Float(v) => v.to_string(),
        Value::Str(s) => format!("{s:?}"),
        Value::Name(s) => s.clone(),
        Value::Expr(e) => format!("({e})"),
    }
}
