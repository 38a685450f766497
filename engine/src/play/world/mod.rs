//! The world's machinery: what a level does by itself once the player sets
//! it going. Doom's `p_` files, one module per mechanism:
//!
//! ```text
//! line specials (specials.rs: walk, use, shoot; once or repeat; keys)
//!    ├─ doors.rs     door thinkers (and a grid map's sliding panels)
//!    ├─ plats.rs     lifts: down, wait, up; perpetual lifts
//!    ├─ floors.rs    floors to each target, stairs, donuts
//!    ├─ ceilings.rs  ceilings and crushers
//!    ├─ lights.rs    light changes and the sector light effects
//!    ├─ teleport.rs  teleporters
//!    └─ switches.rs  switch textures, and buttons that flip back
//!            every mover ──▶ mover.rs (the one plane mover, and the bodies it carries or crushes)
//! sectors.rs    sector specials: effects spawned at load, damage, secrets
//! animation.rs  animated textures and flats, by the tick
//! ```
//!
//! Thinkers live in one `Vec`, run in the order they were made (Doom's
//! thinker list), and leave it when their work is done, so an idle sector
//! costs nothing per tick. A sector has at most one floor or ceiling mover at
//! a time (vanilla Doom's `specialdata`; a second special on a busy sector is
//! ignored, which is what maps made for vanilla Doom expect) and at most one
//! light thinker.

pub mod animation;
pub mod ceilings;
pub mod doors;
pub mod floors;
pub mod lights;
pub mod mover;
pub mod plats;
pub mod sectors;
pub mod specials;
pub mod switches;
pub mod teleport;

use super::blockmap::{Blockmap, LineQuery};
use super::events::Event;
use super::player::Player;
use super::random::GameRng;
use crate::level::Level;
use crate::map::special::KeyColour;
use crate::map::LineSpecial;

/// How the level ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Exit {
    Normal,
    Secret,
}

/// The bodies the world moves and hurts: the player and the actors.
pub struct Bodies<'a> {
    pub player: &'a mut Player,
    /// Sectors the player's circle overlaps (sorted), as of this tick's move.
    pub touched: &'a [usize],
    pub actors: &'a mut crate::play::actors::Actors,
    /// Damage the world did to actors (crushed, telefragged): actor and
    /// amount, dealt by the game after the world's turn (hurting an actor
    /// runs its state machine, which needs the actors' context).
    pub harmed: &'a mut Vec<(u32, i32)>,
    pub blockmap: &'a Blockmap,
    pub query: &'a mut LineQuery,
}

/// Everything a thinker or a special may read or change.
pub struct Ctx<'a> {
    pub level: &'a mut Level,
    pub bodies: Bodies<'a>,
    pub rng: &'a mut GameRng,
    /// Ticks since the level began (Doom's `leveltime`).
    pub time: u64,
    pub events: &'a mut Vec<Event>,
    pub exit: &'a mut Option<Exit>,
}

/// One running piece of the world.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Thinker {
    Door(doors::Door),
    Plat(plats::Plat),
    Floor(floors::FloorMove),
    Ceiling(ceilings::CeilingMove),
    Light(lights::Light),
    Button(switches::Button),
}

impl Thinker {
    /// One tick; `false` when its work is done.
    fn think(&mut self, ctx: &mut Ctx) -> bool {
        match self {
            Thinker::Door(d) => d.think(ctx),
            Thinker::Plat(p) => p.think(ctx),
            Thinker::Floor(f) => f.think(ctx),
            Thinker::Ceiling(c) => c.think(ctx),
            Thinker::Light(l) => l.think(ctx),
            Thinker::Button(b) => b.think(ctx),
        }
    }

    /// The sector whose mover slot it holds, if it is a mover.
    fn moves(&self) -> Option<usize> {
        match self {
            Thinker::Door(d) => Some(d.sector),
            Thinker::Plat(p) => Some(p.sector),
            Thinker::Floor(f) => Some(f.sector),
            Thinker::Ceiling(c) => Some(c.sector),
            Thinker::Light(_) | Thinker::Button(_) => None,
        }
    }
}

/// A line that carries a special: one of the map's walls, or one of its
/// trigger lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum SpecialLine {
    Wall(usize),
    Trigger(usize),
}

/// The level's machinery in motion.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct World {
    pub thinkers: Vec<Thinker>,
    /// Per sector: a floor or ceiling mover is at work (Doom's `specialdata`).
    busy: Vec<bool>,
    /// Per sector: a light thinker runs.
    lit: Vec<bool>,
    /// Once-only specials that have gone off: walls first, then trigger lines.
    spent: Vec<bool>,
    /// Secrets in the level, and found.
    pub secrets: (u32, u32),
}

impl World {
    /// The machinery of `level`: its sector effects running (lights, door
    /// timers), its switch textures and animations known, nothing moving.
    pub fn new(level: &mut Level, rng: &mut GameRng) -> World {
        let map = &level.compiled.map;
        let sectors = map.sectors.len();
        let mut world = World {
            thinkers: Vec::new(),
            busy: vec![false; sectors],
            lit: vec![false; sectors],
            spent: vec![false; map.lines.len() + map.trigger_lines.len()],
            secrets: (map.sectors.iter().filter(|s| s.special.secret).count() as u32, 0),
        };
        sectors::spawn_effects(&mut world, level, rng);
        world
    }

    pub fn is_busy(&self, sector: usize) -> bool {
        self.busy[sector]
    }

    /// Adds a mover for `sector` (which must be idle) and marks it busy.
    fn start(&mut self, thinker: Thinker) {
        if let Some(s) = thinker.moves() {
            self.busy[s] = true;
        }
        self.thinkers.push(thinker);
    }

    /// Adds a light thinker for `sector`, unless one runs there already.
    fn start_light(&mut self, sector: usize, light: lights::Light) -> bool {
        if std::mem::replace(&mut self.lit[sector], true) {
            return false;
        }
        self.thinkers.push(Thinker::Light(light));
        true
    }

    /// Runs every thinker one tick, in order, and drops those that are done.
    pub fn tick(&mut self, ctx: &mut Ctx) {
        let busy = &mut self.busy;
        self.thinkers.retain_mut(|t| {
            let keep = t.think(ctx);
            if !keep {
                if let Some(s) = t.moves() {
                    busy[s] = false;
                }
            }
            keep
        });
        animation::tick(ctx.level, ctx.time);
    }

    /// The special of `line`, if it has one that has not been used up.
    pub fn special(&self, level: &Level, line: SpecialLine) -> Option<LineSpecial> {
        let map = &level.compiled.map;
        let (special, slot) = match line {
            SpecialLine::Wall(i) => (map.lines[i].special.as_ref(), i),
            SpecialLine::Trigger(i) => (Some(&map.trigger_lines[i].special), map.lines.len() + i),
        };
        special.filter(|_| !self.spent[slot]).cloned()
    }

    fn spend(&mut self, level: &Level, line: SpecialLine) {
        let slot = match line {
            SpecialLine::Wall(i) => i,
            SpecialLine::Trigger(i) => level.compiled.map.lines.len() + i,
        };
        self.spent[slot] = true;
    }

    /// Does a loaded world fit `level` (every sector, line and texture its
    /// thinkers name is the level's)? See `play::save`.
    pub(crate) fn check(&self, level: &Level) -> Result<(), String> {
        let map = &level.compiled.map;
        let (sectors, lines) = (map.sectors.len(), map.lines.len());
        let doors = level.grid.as_ref().map_or(0, |g| g.open.len());
        if self.busy.len() != sectors
            || self.lit.len() != sectors
            || self.spent.len() != lines + map.trigger_lines.len()
        {
            return Err("the world's per-sector and per-line marks do not fit the map".into());
        }
        let fits = |t: &Thinker| match t {
            Thinker::Door(d) => match d.motion {
                doors::Motion::Slide { slide, .. } => d.sector < sectors && slide.index < doors,
                doors::Motion::Ceiling { .. } => d.sector < sectors,
            },
            Thinker::Plat(p) => p.sector < sectors,
            Thinker::Floor(f) => f.sector < sectors && f.arrival.is_none_or(|r| r.from < sectors),
            Thinker::Ceiling(c) => c.sector < sectors,
            Thinker::Light(l) => l.sector < sectors,
            Thinker::Button(b) => {
                b.line < lines && (b.original.0 as usize) < level.materials.textures.len() && b.count > 0
            }
        };
        match self.thinkers.iter().position(|t| !fits(t)) {
            Some(i) => Err(format!("the world's thinker {i} names a sector, line or texture the map does not have")),
            None => Ok(()),
        }
    }

    /// The door thinker on `sector`, if one is at work there.
    pub fn door_on(&self, sector: usize) -> Option<&doors::Door> {
        self.thinkers.iter().find_map(|t| match t {
            Thinker::Door(d) if d.sector == sector => Some(d),
            _ => None,
        })
    }
}

/// A message for the player (Doom's `player->message`).
pub(crate) fn say(ctx: &mut Ctx, text: impl Into<String>) {
    ctx.events.push(Event::Message(text.into()));
}

/// Does the player hold a key of `colour` (card or skull)?
pub(crate) fn has_key(player: &Player, colour: KeyColour) -> bool {
    player.keys.iter().any(|k| k.colour == colour)
}
