//! The things in play (Doom's mobjs): every map thing the game's skill
//! shows, except markers, becomes an [`Actor`] running its actor's state
//! machine from the table ([`crate::actors`]). A tick steps the states of
//! the actors whose timer runs; an actor in a state that lasts for ever (a
//! lamp, a body) is asleep and costs nothing until something wakes it.
//! After the tick, [`Actors::draw`] updates what the renderers draw
//! (`Level::things`) for the actors that changed: those whose state was
//! entered (every change to an actor, its actions' included, follows one)
//! and those removed. A sleeping actor is not visited to draw it either.
//!
//! Entering a state runs its action (`actions.rs`: the registry's names
//! bound to Rust functions; `monsters.rs`: looking, chasing, attacking);
//! `movement.rs` is how a monster steps. An action the engine does not yet
//! implement is skipped (`actions::function` lists the ones it does).

use std::sync::Arc;

use glam::{DVec2, DVec3};

pub mod actions;
pub mod attacks;
pub mod grid;
pub mod monsters;
pub mod movement;
pub mod physics;

use crate::actors::{ActorFlag, ActorFlags, ActorTable, StateId};
use crate::level::{DrawnThing, Level};
use crate::materials::Materials;
use crate::texture::TextureId;

use super::blockmap::{Blockmap, LineQuery};
use super::events::Event;
use super::player::Player;
use super::random::GameRng;
use super::sight;
use actions::ActionFn;
use grid::{ThingGrid, UNLISTED};
use movement::NO_DIR;

/// Whom an actor is after (or, for a missile, who fired it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Target {
    #[default]
    None,
    Player,
    /// An actor, by index.
    Actor(u32),
}

/// One thing in play.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Actor {
    /// Its actor, by index into the table.
    pub kind: usize,
    /// The map thing it came from.
    pub thing: Option<usize>,
    /// What the renderers know it by (see [`DrawnThing::key`]).
    pub key: usize,
    pub pos: DVec2,
    /// Its feet (or, hanging, the bottom of its sprite).
    pub z: f64,
    /// Degrees anticlockwise from east.
    pub angle: f64,
    pub sector: usize,
    pub state: StateId,
    /// Ticks left in the state; -1 stays for ever.
    pub tics: i32,
    /// The views it shows: the last frame the art had.
    pub views: Option<[TextureId; 8]>,
    pub bright: bool,
    /// Gone (its state sequence reached `stop`).
    pub removed: bool,
    /// On the list of actors a tick visits.
    listed: bool,
    /// Waiting for a player who is out of its reach: off the tick's list
    /// until the player comes into its part of the map.
    parked: bool,
    /// Its flags now (the table's, changed by play: `Ambush` from the map,
    /// `Solid` lost in death, `Corpse` gained).
    pub flags: ActorFlags,
    pub health: i32,
    /// What it chases and attacks (Doom's `target`).
    pub target: Target,
    /// A missile's shooter, an explosion's cause: whom its damage is
    /// charged to (Doom keeps this in a missile's `target`).
    pub source: Target,
    /// A homing missile's quarry, the arch-vile's fire's victim, the
    /// corpse being raised (Doom's `tracer`).
    pub tracer: Target,
    /// Ticks it keeps chasing a monster that hurt it before it may switch
    /// to another (Doom's `threshold`).
    pub threshold: i32,
    /// Momentum, units per tick: pushes, falls, missiles' flight.
    pub vel: DVec3,
    /// A lost soul in its charge (Doom's MF_SKULLFLY).
    pub skull_fly: bool,
    /// Rising or sinking towards its target this tick (Doom's MF_INFLOAT).
    pub in_float: bool,
    /// Its cell in the grid ([`UNLISTED`]: not in it).
    cell: u32,
    /// On the list of actors physics moves.
    moving: bool,
    /// Doom's `movedir` (0..8, [`NO_DIR`]) and `movecount`: steps left before
    /// choosing a new direction.
    pub movedir: u8,
    pub movecount: i32,
    /// The tick it entered a state that lasts for ever (a corpse's last
    /// frame): skill 5 brings a monster back some time after.
    pub still_since: u64,
    /// Ticks before it may first attack (Doom's `reactiontime`).
    pub reaction_time: i32,
    /// Just attacked: the next chase step moves instead (Doom's MF_JUSTATTACKED).
    pub just_attacked: bool,
    /// Just hurt: the next missile check fires (Doom's MF_JUSTHIT).
    pub just_hit: bool,
    /// Highest floor and lowest ceiling under its box.
    pub floor: f64,
    pub ceiling: f64,
}

/// What actions reach besides the actors: the level, the player, the
/// random generator, the events out, and scratch for lines and sight.
pub struct ActorCtx<'a> {
    pub level: &'a mut Level,
    pub player: &'a mut Player,
    pub rng: &'a mut GameRng,
    pub events: &'a mut Vec<Event>,
    pub blockmap: &'a Blockmap,
    pub query: &'a mut LineQuery,
    pub sight: &'a mut sight::Scratch,
    pub skill: u8,
    /// Monsters killed this game (for the intermission).
    pub kills: &'a mut u32,
    /// What actions ask of the world, done after the tick.
    pub requests: &'a mut Vec<attacks::Request>,
    /// The player's shots this tick, from where to where they reached
    /// (the lines they cross may have shoot specials).
    pub shots: &'a mut Vec<(DVec2, DVec2)>,
    /// The map has walk lines monsters may set off (if not, their steps
    /// are not traced).
    pub monster_walks: bool,
}

/// Every actor of a game. Saved whole (`play::save`) but for the table and
/// the action functions, which the loading game supplies, and scratch.
#[derive(Clone, serde::Serialize, serde::Deserialize)]
pub struct Actors {
    #[serde(skip, default = "no_table")]
    pub table: Arc<ActorTable>,
    pub list: Vec<Actor>,
    /// The actors whose state timer runs, in the order they began to run
    /// (Doom's thinker order): the only ones a tick visits.
    awake: Vec<u32>,
    /// Fast skill: states marked `fast` last half as long (Doom's skill 5).
    fast: bool,
    /// Map things with no actor that are drawn as they stand (a version-1
    /// map names sprites, not actors).
    still: Vec<usize>,
    /// Per action of the registry, its function (`None`: not implemented).
    #[serde(skip)]
    run: Vec<Option<ActionFn>>,
    /// The actors that block, can be shot, picked up or raised, by cell.
    pub grid: ThingGrid,
    /// The actors with momentum or off the ground (`physics.rs` moves only these).
    movers: Vec<u32>,
    /// Scratch for grid queries.
    #[serde(skip)]
    near: Vec<u32>,
    /// Per sector: the player was heard there (Doom's `soundtarget`).
    heard: Vec<bool>,
    /// Per sector, its part of the map: sectors joined by two-sided lines
    /// (directly or through others) share a part. Nothing sees, hears or
    /// shoots from one part into another.
    parts: Vec<u32>,
    /// The part the player is in (as of the last tick).
    here: u32,
    /// A door opened or shut since the parts were found: find them again.
    parts_stale: bool,
    /// Monsters waiting (`A_Look`) in a part the player is not in: they
    /// cannot see or hear it, so they are off the tick's list (may hold
    /// actors since woken; [`Actor::parked`] says).
    parked: Vec<u32>,
    /// The registry's `A_Look`.
    look: Option<crate::actors::ActionId>,
    /// Skill 5: monsters come back from the dead (Doom's `respawnmonsters`).
    pub respawn: bool,
    /// With `respawn`: the monsters that have lain still (may hold some
    /// since raised or gone; `monsters::respawn` checks).
    corpses: Vec<u32>,
    /// Per actor, its place in `Level::things` ([`NOT_DRAWN`]: none); per
    /// place, the actor there ([`NOT_DRAWN`]: a still map thing).
    slots: Vec<u32>,
    owners: Vec<u32>,
    /// Actors changed since the last [`Actors::draw`] (repeats are harmless).
    dirty: Vec<u32>,
}

/// Is two-sided `line` shut: no gap between the higher floor and the lower
/// ceiling of its sides (a closed door)? Sight and sound stop there.
fn shut(map: &crate::map::Map, line: &crate::map::Line) -> bool {
    let Some(back) = &line.back else { return true };
    let (f, b) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
    f.ceiling.min(b.ceiling) <= f.floor.max(b.floor)
}

/// Each sector's part of the map: the sectors reached from it through
/// two-sided lines that are not shut, numbered by their lowest sector.
fn parts(map: &crate::map::Map) -> Vec<u32> {
    let mut part: Vec<u32> = (0..map.sectors.len() as u32).collect();
    fn root(part: &mut [u32], mut s: u32) -> u32 {
        while part[s as usize] != s {
            part[s as usize] = part[part[s as usize] as usize];
            s = part[s as usize];
        }
        s
    }
    for line in map.lines.iter().filter(|l| !shut(map, l)) {
        if let Some(back) = &line.back {
            let (a, b) = (root(&mut part, line.front.sector as u32), root(&mut part, back.sector as u32));
            part[a.max(b) as usize] = a.min(b);
        }
    }
    (0..part.len() as u32).map(|s| root(&mut part, s)).collect()
}

/// What a deserialized [`Actors`] holds until the loading game gives it its own.
fn no_table() -> Arc<ActorTable> {
    ActorTable::active().clone()
}

/// No place in `Level::things`, or no actor in a place.
const NOT_DRAWN: u32 = u32::MAX;

impl Actors {
    /// The actors of the things `level` shows (after `Level::show_skill`).
    /// Each starts part-way into its first state (Doom's P_SpawnMapThing),
    /// so that a room of monsters does not breathe in step.
    pub fn spawn_map_things(level: &Level, table: Arc<ActorTable>, fast: bool, rng: &mut GameRng) -> Actors {
        let map = &level.compiled.map;
        let run = crate::actors::actions::REGISTRY.iter().map(|a| actions::function(a.name)).collect();
        let heard = vec![false; map.sectors.len()];
        let (mut min, mut max) = (DVec2::splat(f64::MAX), DVec2::splat(f64::MIN));
        for v in &map.vertices {
            (min, max) = (min.min(*v), max.max(*v));
        }
        if min.x > max.x {
            (min, max) = (DVec2::ZERO, DVec2::ONE);
        }
        let mut actors = Actors {
            grid: ThingGrid::new(min, max),
            movers: Vec::new(),
            near: Vec::new(),
            table,
            list: Vec::new(),
            awake: Vec::new(),
            fast,
            still: Vec::new(),
            run,
            heard,
            parts: parts(map),
            here: u32::MAX,
            parts_stale: false,
            parked: Vec::new(),
            look: crate::actors::actions::find("A_Look"),
            respawn: false,
            corpses: Vec::new(),
            slots: Vec::new(),
            owners: Vec::new(),
            dirty: Vec::new(),
        };
        for (i, t) in map.things.iter().enumerate() {
            if !level.thing_shown[i] {
                continue;
            }
            let Some(kind) = actors.table.index(&t.kind).filter(|_| map.version >= 2).map(|k| actors.table.spawned(k))
            else {
                actors.still.push(i);
                continue;
            };
            let def = &actors.table.actors[kind];
            if def.category.is_marker() {
                continue;
            }
            let Some(state) = def.label("Spawn") else { continue };
            let sector = level.thing_sectors[i];
            let s = &map.sectors[sector];
            let z = if def.has(ActorFlag::SpawnCeiling) { s.ceiling - def.height } else { s.floor };
            let ambush = t.ambush || def.has(ActorFlag::Ambush);
            let mut actor = actors.new_actor(kind, t.pos, z, t.angle, (sector, s.floor, s.ceiling), i);
            actor.thing = Some(i);
            actor.views = level.materials.sprites[i].map(|id| [id; 8]);
            actor.flags.set(ActorFlag::Ambush, ambush);
            let n = actors.place(actor, state, &level.materials);
            let a = &mut actors.list[n];
            if a.tics > 0 {
                a.tics = 1 + i32::from(rng.byte()) % a.tics;
            }
        }
        actors
    }

    /// Gives loaded actors what a save leaves out: the table and the
    /// action functions, from `fresh` (the actors of the game being loaded into).
    pub(crate) fn take_tools(&mut self, fresh: &mut Actors) {
        self.table = fresh.table.clone();
        self.run = std::mem::take(&mut fresh.run);
    }

    /// Do loaded actors fit `level` and `table` (as `fresh`, the actors a
    /// game just started there has, lays them out), with `things` drawn
    /// things? Every index an actor or a list holds must be in range. See `play::save`.
    pub(crate) fn check(&self, fresh: &Actors, level: &Level, things: usize) -> Result<(), String> {
        let map = &level.compiled.map;
        let table = &fresh.table;
        let (n, sectors, textures) = (self.list.len(), map.sectors.len(), level.materials.textures.len());
        let target = |t: &Target| !matches!(t, Target::Actor(i) if *i as usize >= n);
        let actor_fits = |a: &Actor| {
            a.kind < table.actors.len()
                && (a.state.0 as usize) < table.states.len()
                && a.sector < sectors
                && a.thing.is_none_or(|t| t < map.things.len())
                && [a.target, a.source, a.tracer].iter().all(target)
                && a.views.is_none_or(|v| v.iter().all(|id| (id.0 as usize) < textures))
                && (a.cell == UNLISTED || (a.cell as usize) < self.grid.cells())
                && a.movedir <= NO_DIR
        };
        if let Some(i) = self.list.iter().position(|a| !actor_fits(a)) {
            return Err(format!("actor {i} names a kind, state, sector, texture or actor that is not there"));
        }
        let listed = |v: &[u32]| v.iter().all(|&i| (i as usize) < n);
        let drawn = |v: &[u32], len: usize| v.iter().all(|&i| i == NOT_DRAWN || (i as usize) < len);
        let lists_fit = [&self.awake, &self.movers, &self.parked, &self.corpses, &self.dirty].iter().all(|v| listed(v))
            && self.still.iter().all(|&t| t < map.things.len())
            && self.heard.len() == sectors
            && self.parts.len() == sectors
            && self.parts.iter().all(|&p| (p as usize) < sectors)
            && self.slots.len() == n
            && drawn(&self.slots, things)
            && self.owners.len() == things
            && drawn(&self.owners, n)
            && self.look == fresh.look
            && self.grid.fits(&fresh.grid, n);
        if lists_fit {
            Ok(())
        } else {
            Err("the actors' lists, grid or per-sector marks do not fit the map".into())
        }
    }

    /// A new actor of `kind` standing at `pos`, `z` in `area` (its sector,
    /// floor and ceiling), known to the renderers as `key`.
    fn new_actor(&self, kind: usize, pos: DVec2, z: f64, angle: f64, area: (usize, f64, f64), key: usize) -> Actor {
        let def = &self.table.actors[kind];
        Actor {
            kind,
            thing: None,
            key,
            pos,
            z,
            angle,
            sector: area.0,
            state: StateId(0),
            tics: 0,
            views: None,
            bright: false,
            removed: false,
            listed: false,
            parked: false,
            flags: def.flags,
            health: def.health,
            target: Target::None,
            source: Target::None,
            tracer: Target::None,
            threshold: 0,
            vel: DVec3::ZERO,
            skull_fly: false,
            in_float: false,
            cell: UNLISTED,
            moving: false,
            movedir: NO_DIR,
            movecount: 0,
            still_since: 0,
            reaction_time: def.reaction_time,
            just_attacked: false,
            just_hit: false,
            floor: area.1,
            ceiling: area.2,
        }
    }

    /// Brings a new actor of `kind` (or what replaces it) into play at
    /// `pos`, `z`, in its first state (Doom's P_SpawnMobj: the state's
    /// action does not run). Returns its index, or `None` if the actor has
    /// no `Spawn` label.
    pub fn spawn(&mut self, kind: usize, pos: DVec2, z: f64, angle: f64, ctx: &mut ActorCtx) -> Option<usize> {
        let kind = self.table.spawned(kind);
        let state = self.table.actors[kind].label("Spawn")?;
        let compiled = &ctx.level.compiled;
        let sector = compiled.sector_at(pos);
        let s = &compiled.map.sectors[sector];
        // Keys past the map's things, never reused: the list only grows.
        let key = compiled.map.things.len() + self.list.len();
        let actor = self.new_actor(kind, pos, z, angle, (sector, s.floor, s.ceiling), key);
        Some(self.place(actor, state, &ctx.level.materials))
    }

    /// Adds an actor to the list (and the grid) in its first state, whose action does not run (Doom's P_SpawnMobj).
    /// Returns its index.
    fn place(&mut self, actor: Actor, state: StateId, materials: &Materials) -> usize {
        let n = self.list.len();
        self.list.push(actor);
        self.slots.push(NOT_DRAWN);
        self.link(n);
        self.show(n, state, materials);
        n
    }

    /// Lists actor `n` in the grid, unless it stays out of it (`NoBlockmap`).
    fn link(&mut self, n: usize) {
        let a = &self.list[n];
        if a.removed || a.flags.has(ActorFlag::NoBlockmap) || a.cell != UNLISTED {
            return;
        }
        let cell = self.grid.cell(a.pos);
        self.grid.insert(n as u32, cell, self.table.actors[a.kind].radius);
        self.list[n].cell = cell;
    }

    fn unlink(&mut self, n: usize) {
        let cell = std::mem::replace(&mut self.list[n].cell, UNLISTED);
        if cell != UNLISTED {
            self.grid.remove(n as u32, cell);
        }
    }

    /// Moves actor `n` to `pos` (its grid cell follows) and redraws it.
    pub fn set_pos(&mut self, n: usize, pos: DVec2) {
        let a = &mut self.list[n];
        a.pos = pos;
        self.dirty.push(n as u32);
        if a.cell != UNLISTED && self.grid.cell(pos) != a.cell {
            self.unlink(n);
            self.link(n);
        }
    }

    /// Puts actor `n` on the list physics moves (it has momentum, or may fall).
    pub fn wake_physics(&mut self, n: usize) {
        let a = &mut self.list[n];
        if !a.moving && !a.removed {
            a.moving = true;
            self.movers.push(n as u32);
        }
    }

    /// The actors listed in the grid near the box `min..max` (scratch,
    /// handed back with [`Actors::give_back`]).
    pub fn near(&mut self, min: DVec2, max: DVec2) -> Vec<u32> {
        let mut out = std::mem::take(&mut self.near);
        out.clear();
        self.grid.near(min, max, &mut out);
        out
    }

    pub fn give_back(&mut self, scratch: Vec<u32>) {
        self.near = scratch;
    }

    /// The actors (but `except`) with `flag` whose box overlaps a box of
    /// `radius` at `at` (Doom's P_TeleportMove and P_CheckPosition at a
    /// spot: who stands there).
    pub fn overlapping(&mut self, at: DVec2, radius: f64, flag: ActorFlag, except: Option<u32>) -> Vec<u32> {
        let r = DVec2::splat(radius);
        let near = self.near(at - r, at + r);
        let found = near
            .iter()
            .copied()
            .filter(|&k| {
                let b = &self.list[k as usize];
                let br = self.table.actors[b.kind].radius;
                Some(k) != except
                    && !b.removed
                    && b.flags.has(flag)
                    && (b.pos.x - at.x).abs() < br + radius
                    && (b.pos.y - at.y).abs() < br + radius
            })
            .collect();
        self.give_back(near);
        found
    }

    /// Takes actor `n` out of play (its state sequence ended, or it was
    /// picked up).
    pub fn remove(&mut self, n: usize) {
        self.unlink(n);
        self.list[n].removed = true;
        self.dirty.push(n as u32);
    }

    /// Puts actor `n` into `state`: its frame, its timer, awake or asleep
    /// (Doom's P_SetMobjState without the action).
    fn show(&mut self, n: usize, state: StateId, materials: &Materials) {
        let s = self.table.state(state);
        let tics = if self.fast && s.fast && s.tics > 0 { (s.tics + 1) / 2 } else { s.tics };
        self.dirty.push(n as u32);
        let actor = &mut self.list[n];
        actor.state = state;
        actor.tics = tics;
        actor.bright = s.bright;
        if let Some(views) = materials.sprite_views.get(Materials::view_index(s.sprite, s.frame)).copied().flatten() {
            actor.views = Some(views);
        }
        if tics >= 0 && !actor.listed {
            actor.listed = true;
            actor.parked = false;
            self.awake.push(n as u32);
        }
    }

    /// Puts actor `n` into `state` and runs its action; states of 0 tics
    /// give way at once to the next, whose actions run too (Doom's
    /// P_SetMobjState; loading has proven such states cannot loop). `None`
    /// removes the actor.
    pub fn set_state(&mut self, n: usize, state: Option<StateId>, ctx: &mut ActorCtx) {
        let mut at = state;
        loop {
            let Some(state) = at else {
                self.remove(n);
                return;
            };
            self.show(n, state, &ctx.level.materials);
            if let Some(call) = &self.table.state(state).action {
                if let Some(run) = self.run[usize::from(call.action.0)] {
                    let args = call.args.clone();
                    run(self, n, &args, ctx);
                }
            }
            let a = &self.list[n];
            // The action may have moved it on (or removed it) already.
            if a.removed || a.state != state || a.tics != 0 {
                return;
            }
            at = self.table.state(state).next;
        }
    }

    /// Moves the actors that have momentum or are in the air
    /// (`physics.rs`), then steps every awake actor's state timer; a state
    /// whose time is up gives way to the next, whose action runs.
    pub fn tick(&mut self, ctx: &mut ActorCtx) {
        if self.respawn && ctx.level.time % 32 == 0 {
            self.respawn_monsters(ctx);
        }
        let stale = std::mem::take(&mut self.parts_stale);
        if stale {
            self.parts = parts(&ctx.level.compiled.map);
        }
        let here = self.parts.get(ctx.player.sector).copied().unwrap_or(u32::MAX);
        if here != self.here || stale {
            self.here = here;
            self.unpark();
        }
        let mut k = 0;
        while k < self.movers.len() {
            let n = self.movers[k] as usize;
            k += 1;
            if !self.list[n].removed {
                self.physics(n, ctx);
            }
        }
        let list = &mut self.list;
        self.movers.retain(|&n| {
            let a = &mut list[n as usize];
            a.moving = !a.removed && a.in_motion();
            a.moving
        });
        let mut k = 0;
        while k < self.awake.len() {
            let n = self.awake[k] as usize;
            k += 1;
            let actor = &mut self.list[n];
            if actor.removed || actor.tics < 0 {
                continue;
            }
            actor.tics -= 1;
            if actor.tics <= 0 {
                let next = self.table.state(actor.state).next;
                self.set_state(n, next, ctx);
            }
        }
        // Asleep (for ever), gone or parked: off the list, keeping the order.
        let Actors { list, table, parts, parked, look, here, respawn, corpses, .. } = self;
        let now = ctx.level.time;
        self.awake.retain(|&n| {
            let a = &mut list[n as usize];
            a.listed = a.tics >= 0 && !a.removed;
            if a.tics < 0 && !a.removed {
                a.still_since = now;
                if *respawn && a.flags.has(ActorFlag::CountKill) {
                    corpses.push(n);
                }
            }
            let looking = table.state(a.state).action.as_ref().is_some_and(|c| Some(c.action) == *look);
            if a.listed && looking && parts.get(a.sector).is_some_and(|p| p != here) {
                (a.listed, a.parked) = (false, true);
                parked.push(n);
            }
            a.listed
        });
    }

    /// Puts the parked monsters of the player's part back on the tick's
    /// list, in the order they were parked.
    fn unpark(&mut self) {
        let Actors { list, parts, parked, awake, here, .. } = self;
        parked.retain(|&n| {
            let a = &mut list[n as usize];
            if !a.parked || a.removed {
                return false;
            }
            if parts.get(a.sector) != Some(here) {
                return true;
            }
            (a.parked, a.listed) = (false, true);
            awake.push(n);
            false
        });
    }

    /// A plane of `sector` moved: if a line of it opened or shut (a door),
    /// the parts of the map are found again before the next tick's actors.
    pub fn plane_moved(&mut self, level: &Level, sector: usize) {
        if self.parts_stale {
            return;
        }
        let map = &level.compiled.map;
        for &i in &level.sector_lines[sector] {
            let line = &map.lines[i as usize];
            let Some(back) = &line.back else { continue };
            let joined = self.parts.get(line.front.sector) == self.parts.get(back.sector);
            if joined == shut(map, line) {
                self.parts_stale = true;
                return;
            }
        }
    }

    /// Monsters parked: waiting in a part of the map the player is not in.
    pub fn parked(&self) -> usize {
        self.parked.iter().filter(|&&n| self.list[n as usize].parked).count()
    }

    /// How many actors a tick visits.
    pub fn awake(&self) -> usize {
        self.awake.len()
    }

    /// Draws every actor afresh into `level.things` (with the map things
    /// that have no actor): at the start of a game.
    pub fn draw_all(&mut self, level: &mut Level) {
        level.things = self.still.iter().filter_map(|&i| level.map_thing_drawn(i)).collect();
        self.owners = vec![NOT_DRAWN; level.things.len()];
        self.slots.fill(NOT_DRAWN);
        self.dirty = (0..self.list.len() as u32).collect();
        self.draw(level);
    }

    /// Brings `level.things` up to date with the actors changed since the
    /// last call: an actor still there with a frame the art has is drawn
    /// where it stands; one gone leaves its place to the last entry.
    pub fn draw(&mut self, level: &mut Level) {
        for n in std::mem::take(&mut self.dirty) {
            let a = &self.list[n as usize];
            let drawn = a.views.filter(|_| !a.removed).map(|views| DrawnThing {
                key: a.key,
                pos: a.pos,
                z: a.z,
                sector: a.sector,
                angle: a.angle,
                views,
                bright: a.bright,
                fuzz: a.flags.has(ActorFlag::Shadow),
            });
            let slot = self.slots[n as usize];
            match (slot, drawn) {
                (NOT_DRAWN, Some(d)) => {
                    self.slots[n as usize] = level.things.len() as u32;
                    self.owners.push(n);
                    level.things.push(d);
                }
                (NOT_DRAWN, None) => {}
                (s, Some(d)) => level.things[s as usize] = d,
                (s, None) => {
                    level.things.swap_remove(s as usize);
                    self.owners.swap_remove(s as usize);
                    if let Some(&moved) = self.owners.get(s as usize) {
                        if moved != NOT_DRAWN {
                            self.slots[moved as usize] = s;
                        }
                    }
                    self.slots[n as usize] = NOT_DRAWN;
                }
            }
        }
    }
}
