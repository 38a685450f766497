//! The things in play (Doom's mobjs): every map thing the game's skill
//! shows, except markers, becomes an [`Actor`] running its actor's state
//! machine from the table ([`crate::actors`]). A tick steps the states of
//! the actors whose timer runs; an actor in a state that lasts for ever (a
//! lamp, a body) is asleep and costs nothing until something wakes it.
//! After the tick, [`Actors::draw`] hands the renderers each actor's frame
//! (its eight views) where it stands.
//!
//! What actors do (their actions: looking, chasing, attacking), moving
//! them, and what they spawn come next; so far states advance and actors
//! are drawn, and a state's action is not yet run.

use std::sync::Arc;

use glam::DVec2;

use crate::actors::{ActorFlag, ActorTable, StateId};
use crate::level::{DrawnThing, Level};
use crate::materials::Materials;
use crate::texture::TextureId;

use super::random::GameRng;

/// One thing in play.
#[derive(Clone, Debug, PartialEq)]
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
}

/// Every actor of a game.
pub struct Actors {
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
}

impl Actors {
    /// The actors of the things `level` shows (after `Level::show_skill`).
    /// Each starts part-way into its first state (Doom's P_SpawnMapThing),
    /// so that a room of monsters does not breathe in step.
    pub fn spawn_map_things(level: &Level, table: Arc<ActorTable>, fast: bool, rng: &mut GameRng) -> Actors {
        let map = &level.compiled.map;
        let mut actors = Actors { table, list: Vec::new(), awake: Vec::new(), fast, still: Vec::new() };
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
            let first = level.materials.sprites[i].map(|id| [id; 8]);
            let actor = Actor {
                kind,
                thing: Some(i),
                key: i,
                pos: t.pos,
                z,
                angle: t.angle,
                sector,
                state,
                tics: 0,
                views: first,
                bright: false,
                removed: false,
                listed: false,
            };
            actors.list.push(actor);
            let n = actors.list.len() - 1;
            actors.enter(n, state, &level.materials);
            let a = &mut actors.list[n];
            if a.tics > 0 {
                a.tics = 1 + i32::from(rng.byte()) % a.tics;
            }
        }
        actors
    }

    /// Puts actor `n` into `state`: its frame, its timer, awake or asleep.
    fn enter(&mut self, n: usize, state: StateId, materials: &Materials) {
        let s = self.table.state(state);
        let tics = if self.fast && s.fast && s.tics > 0 { (s.tics + 1) / 2 } else { s.tics };
        let actor = &mut self.list[n];
        actor.state = state;
        actor.tics = tics;
        actor.bright = s.bright;
        if let Some(views) = materials.sprite_views.get(Materials::view_index(s.sprite, s.frame)).copied().flatten() {
            actor.views = Some(views);
        }
        if tics >= 0 && !actor.listed {
            actor.listed = true;
            self.awake.push(n as u32);
        }
    }

    /// Steps every awake actor's state timer; a state whose time is up
    /// gives way to the next (several in one tick through states of 0
    /// tics, which loading has proven cannot loop).
    pub fn tick(&mut self, materials: &Materials) {
        let mut k = 0;
        while k < self.awake.len() {
            let n = self.awake[k] as usize;
            k += 1;
            let actor = &mut self.list[n];
            if actor.removed || actor.tics < 0 {
                continue;
            }
            if actor.tics > 0 {
                actor.tics -= 1;
            }
            while self.list[n].tics == 0 && !self.list[n].removed {
                match self.table.state(self.list[n].state).next {
                    Some(next) => self.enter(n, next, materials),
                    None => self.list[n].removed = true,
                }
            }
        }
        // Asleep (for ever) or gone: off the list, keeping the order.
        let list = &mut self.list;
        self.awake.retain(|&n| {
            let a = &mut list[n as usize];
            a.listed = a.tics >= 0 && !a.removed;
            a.listed
        });
    }

    /// How many actors a tick visits.
    pub fn awake(&self) -> usize {
        self.awake.len()
    }

    /// The actors as the renderers draw them: those still there, whose map
    /// thing was not picked up, with a frame the art has.
    pub fn draw(&self, level: &mut Level) {
        let mut out = std::mem::take(&mut level.things);
        out.clear();
        out.extend(self.still.iter().filter_map(|&i| level.map_thing_drawn(i)));
        for a in self.list.iter().filter(|a| !a.removed) {
            if a.thing.is_some_and(|i| !level.thing_shown[i]) {
                continue;
            }
            let Some(views) = a.views else { continue };
            out.push(DrawnThing {
                key: a.key,
                pos: a.pos,
                z: a.z,
                sector: a.sector,
                angle: a.angle,
                views,
                bright: a.bright,
            });
        }
        level.things = out;
    }
}
