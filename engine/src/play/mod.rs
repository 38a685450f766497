//! Play: the game simulation, headless. A [`Game`] owns a [`Level`], the
//! player and the world's machinery, and advances in fixed ticks of
//! 1/[`TICRATE`] s from one [`TickInput`] each; the window (in `game/`)
//! accumulates real time into ticks and draws [`Game::view`] between them.
//! Nothing here reads a clock or iterates a hash map, and every random
//! choice comes from the game's one seeded generator ([`random`]), so the
//! same seed and inputs give the same game, bit for bit ([`demo`] relies on
//! it).
//!
//! One tick, in order (Doom's P_PlayerThink, the player's P_MobjThinker,
//! then the other thinkers and P_UpdateSpecials):
//!
//! ```text
//! input --turn, thrust--> velocity --collision::slide--> position --walk triggers (trace)
//!       --friction, fall--> z --use, fire (trace)--> line specials
//!       --sector under the feet (damage, secret)--> pickups --world thinkers--> sector heights,
//!         light, switch textures --animation--> texture frames --actors (states, actions)-->
//!         monsters look, chase and attack --draw--> Level::things
//! ```
//!
//! Modules: [`actors`] (the things in play and their state machines),
//! [`sight`] (sight and shots, fast and brute force), [`input`] (what a tick reads), [`player`] (the body's physics and
//! constants), [`blockmap`] (lines by grid cell), [`collision`] (sweeping the
//! body's circle against lines), [`trace`] (what a move, a use or a shot
//! crosses), [`world`] (the level's machinery: specials and thinkers),
//! [`pickups`] (what walking over an item gives), [`events`] (sounds and messages out), [`random`],
//! [`demo`] (recorded inputs, saved and loaded), [`save`] (saved games).

pub mod actors;
pub mod blockmap;
pub mod collision;
pub mod demo;
pub mod events;
pub mod input;
pub mod lmp;
pub mod pickups;
pub mod player;
pub mod playthrough;
pub mod random;
pub mod reload;
pub mod save;
pub mod sight;
pub mod statdump;
pub mod syncdump;
pub mod trace;
pub mod vanilla;
pub mod weapons;
pub mod world;

use std::sync::Arc;

use glam::DVec2;

use crate::actors::{ActorFlag, ActorTable};
use crate::geom::sin_cos_degrees;
use crate::level::Level;
use crate::map::special::Activation;
use crate::render::View;
use blockmap::{Blockmap, LineQuery};
use collision::World as Collision;
use events::{sound, Event, Origin};
use player::{HEIGHT, RADIUS};
use random::GameRng;
use trace::{Lines, Scratch};
use world::specials::{activate, Activator};
use world::{Bodies, Ctx, SpecialLine, World};

pub use demo::{Demo, DemoError};
pub use input::TickInput;
pub use player::Player;
pub use world::Exit;

/// Simulation ticks per second (Doom's `TICRATE`).
pub const TICRATE: u32 = 35;
/// The skill a game has unless told otherwise: Doom's 3, "Hurt Me Plenty".
pub const DEFAULT_SKILL: u8 = 3;
/// How far ahead of the body's centre the player can use a line (Doom's `USERANGE`, 64).
pub const USE_RANGE: f64 = 64.0;
/// How far a shot reaches (Doom's `MISSILERANGE`, 2048).
pub const SHOT_RANGE: f64 = 2048.0;
/// A shot leaves the body this far above the feet (Doom: half the height plus 8).
pub const SHOT_HEIGHT: f64 = HEIGHT / 2.0 + 8.0;

#[derive(Debug, thiserror::Error, PartialEq)]
pub enum PlayError {
    #[error("{map}: ({x}, {y}) is not inside any sector (in a hole, outside the map, or on a one-sided wall)")]
    Outside { map: String, x: f64, y: f64 },
    #[error("skill {0} is not 1 to 5")]
    Skill(u8),
}

/// How a game is set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct GameOptions {
    /// 1 to 5, as Doom's: things appear by their skill flags.
    pub skill: u8,
    /// The seed of the game's random generator.
    pub seed: u64,
    /// Monsters are not spawned (Doom's `-nomonsters`: nothing that counts
    /// as a kill, nor lost souls).
    #[serde(default)]
    pub no_monsters: bool,
    /// Played on the simulation with Doom's arithmetic ([`crate::sim`]),
    /// not this module's f64 game.
    #[serde(default)]
    pub sim: bool,
}

impl Default for GameOptions {
    fn default() -> GameOptions {
        GameOptions { skill: DEFAULT_SKILL, seed: 0, no_monsters: false, sim: true }
    }
}

/// The level's tallies, as the intermission shows them: found and total.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    pub kills: (u32, u32),
    pub items: (u32, u32),
    pub secrets: (u32, u32),
    /// Ticks played.
    pub ticks: u64,
}

/// What the view interpolates between ticks.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
struct Pose {
    pos: DVec2,
    eye: f64,
    angle: f64,
}

/// A game in progress on one level.
pub struct Game {
    level: Level,
    player: Player,
    world: World,
    blockmap: Blockmap,
    triggers: Blockmap,
    query: LineQuery,
    scratch: Scratch,
    /// Sectors the body overlaps (scratch).
    touched: Vec<usize>,
    actors: actors::Actors,
    sight: sight::Scratch,
    /// What the actors asked of the world this tick, and the player's shots.
    requests: Vec<actors::attacks::Request>,
    shots: Vec<(DVec2, DVec2)>,
    /// Damage the world's movers and teleports did to actors, dealt after
    /// the world's turn.
    harmed: Vec<(u32, i32)>,
    /// The map has walk lines monsters may set off.
    monster_walks: bool,
    /// Monsters killed and items picked up so far.
    kills: u32,
    items: u32,
    rng: GameRng,
    events: Vec<Event>,
    exit: Option<Exit>,
    options: GameOptions,
    /// Monsters and items to count at the intermission (what the actors
    /// issue will let the player kill and pick up).
    totals: (u32, u32),
    /// The pose at the start of the last tick.
    previous: Pose,
    ticks: u64,
    /// The map's fingerprint as opened, before play (a save names the map by it).
    fingerprint: u32,
}

impl Game {
    /// A game on `level` at the default skill, with the player at the map's player start.
    pub fn new(level: Level) -> Result<Game, PlayError> {
        Game::with_options(level, GameOptions::default())
    }

    /// A game with the [`ActorTable::active`] actors.
    pub fn with_options(level: Level, options: GameOptions) -> Result<Game, PlayError> {
        Game::with_table(level, options, ActorTable::active().clone())
    }

    /// A game whose things are `table`'s actors (a user's table: the level's
    /// things must be its kinds, and its art must have been loaded for it).
    pub fn with_table(mut level: Level, options: GameOptions, table: Arc<ActorTable>) -> Result<Game, PlayError> {
        if !(1..=5).contains(&options.skill) {
            return Err(PlayError::Skill(options.skill));
        }
        let map = &level.compiled.map;
        let start = map.player_start().clone();
        if level.compiled.locate(start.pos).is_none() {
            return Err(PlayError::Outside { map: map.name.clone(), x: start.pos.x, y: start.pos.y });
        }
        let fingerprint = save::map_fingerprint(&level);
        let types = &table;
        let monster =
            |kind: &str| types.get(kind).is_some_and(|ty| ty.has(ActorFlag::CountKill) || ty.name == "lost_soul");
        let mut totals = (0, 0);
        for t in map.things.iter().filter(|t| t.in_single_player(options.skill) && map.version >= 2) {
            if options.no_monsters && monster(&t.kind) {
                continue;
            }
            if let Some(ty) = types.get(&t.kind) {
                totals.0 += u32::from(ty.has(ActorFlag::CountKill));
                totals.1 += u32::from(ty.has(ActorFlag::CountItem));
            }
        }
        level.show_skill(options.skill);
        if options.no_monsters {
            let things = &level.compiled.map.things;
            for (shown, t) in level.thing_shown.iter_mut().zip(things) {
                *shown &= !monster(&t.kind);
            }
            level.draw_map_things();
        }
        level.time = 0;
        let blockmap = Blockmap::new(&level.compiled.map);
        let triggers = Blockmap::of_trigger_lines(&level.compiled.map);
        let mut rng = GameRng::new(options.seed);
        let world = World::new(&mut level, &mut rng);
        let fast = options.skill == 5;
        let mut actors = actors::Actors::spawn_map_things(&level, table.clone(), fast, &mut rng);
        actors.respawn = options.skill == 5;
        actors.draw_all(&mut level);
        let mut query = LineQuery::default();
        let collision = Collision { compiled: &level.compiled, blockmap: &blockmap };
        let near = collision.lines_near(&mut query, start.pos, RADIUS + 1.0);
        let area = collision.area(near, start.pos);
        let mut player = Player::new(start.pos, start.angle, area.sector, area.floor, area.ceiling);
        weapons::arm(&actors, &mut player);
        let previous = pose(&player);
        let monster_walk = |s: &crate::map::LineSpecial| s.on == Activation::Walk && s.by.monsters();
        let map = &level.compiled.map;
        let monster_walks = map.lines.iter().filter_map(|l| l.special.as_ref()).any(monster_walk)
            || map.trigger_lines.iter().any(|t| monster_walk(&t.special));
        Ok(Game {
            level,
            player,
            world,
            blockmap,
            triggers,
            query,
            scratch: Scratch::default(),
            touched: Vec::new(),
            actors,
            sight: sight::Scratch::default(),
            requests: Vec::new(),
            shots: Vec::new(),
            harmed: Vec::new(),
            monster_walks,
            kills: 0,
            items: 0,
            rng,
            events: Vec::new(),
            exit: None,
            options,
            totals,
            previous,
            ticks: 0,
            fingerprint,
        })
    }

    /// Advances the game by one tick of 1/[`TICRATE`] s. After the level
    /// has ended ([`Game::exit`]) ticks do nothing.
    pub fn tick(&mut self, input: &TickInput) {
        self.events.clear();
        if self.exit.is_some() {
            return;
        }
        let input = input.sanitized();
        self.previous = pose(&self.player);
        let from = self.player.pos;
        self.move_player(&input);
        let to = self.player.pos;
        self.walk_triggers(from, to);
        let use_pressed = input.use_line && !self.player.use_held;
        (self.player.use_held, self.player.fire_held) = (input.use_line, input.fire);
        // Held after a teleport the body cannot move or turn, but it can
        // still use and fire (Doom's reactiontime stops P_MovePlayer only).
        if !self.player.dead() && use_pressed {
            self.use_lines();
        }
        self.player.tick_powers();
        let (actors, mut ctx) = self.actor_ctx();
        weapons::tick(actors, input.weapon, &mut ctx);
        self.shoot_lines();
        if self.player.pos != to {
            // A teleport: do not draw the way between.
            self.previous = pose(&self.player);
        }
        self.run_world();
        self.ticks += 1;
        self.level.time = self.ticks;
    }

    /// Turn, thrust, move, friction, fall (or, dead, sink).
    fn move_player(&mut self, input: &TickInput) {
        let Game { level, player, blockmap, query, .. } = self;
        let collision = Collision { compiled: &level.compiled, blockmap };
        if player.dead() {
            player.sink();
        } else if player.freeze > 0 {
            player.freeze -= 1;
        } else {
            player.turn(input);
            player.thrust(input);
        }
        let mut velocity = player.velocity;
        player.pos = collision.slide(query, player.pos, player.z, &mut velocity);
        player.velocity = velocity;
        let near = collision.lines_near(query, player.pos, RADIUS + 1.0);
        let area = collision.area(near, player.pos);
        (player.sector, player.floor, player.ceiling) = (area.sector, area.floor, area.ceiling);
        let idle = if player.dead() || player.freeze > 0 { &TickInput::default() } else { input };
        player.friction(idle);
        player.fall();
    }

    /// A context for the world's specials and thinkers.
    fn ctx(&mut self) -> (&mut World, Ctx<'_>) {
        let Game { level, player, world, blockmap, query, touched, actors, harmed, rng, events, exit, ticks, .. } =
            self;
        let bodies = Bodies { player, touched, actors, harmed, blockmap, query };
        (world, Ctx { level, bodies, rng, time: *ticks, events, exit })
    }

    /// The actors, and a context for their actions.
    fn actor_ctx(&mut self) -> (&mut actors::Actors, actors::ActorCtx<'_>) {
        let Game {
            level,
            player,
            actors,
            blockmap,
            query,
            sight,
            rng,
            events,
            options,
            kills,
            requests,
            shots,
            monster_walks,
            ..
        } = self;
        let skill = options.skill;
        let monster_walks = *monster_walks;
        let ctx = actors::ActorCtx {
            level,
            player,
            rng,
            events,
            blockmap,
            query,
            sight,
            skill,
            kills,
            requests,
            shots,
            monster_walks,
        };
        (actors, ctx)
    }

    /// The lines with walk specials the body's centre crossed.
    fn walk_triggers(&mut self, from: DVec2, to: DVec2) {
        if !self.player.dead() {
            self.cross_lines(from, to, Activator::Player);
        }
    }

    /// Sets off, for `who`, the walk specials of the lines a step from
    /// `from` to `to` crossed, in order, until one takes an actor out of
    /// play.
    fn cross_lines(&mut self, from: DVec2, to: DVec2, who: Activator) {
        let lines = Lines { map: &self.level.compiled.map, walls: &self.blockmap, triggers: &self.triggers };
        for c in lines.crossed(&mut self.scratch, from, to) {
            if let Activator::Monster(n) = who {
                if self.actors.list[n as usize].removed {
                    break;
                }
            }
            let (world, mut ctx) = self.ctx();
            activate(world, &mut ctx, c.line, Activation::Walk, who, c.from_front);
        }
    }

    /// Uses the first line ahead, within [`USE_RANGE`], that has a use
    /// special (Doom's P_UseLines): from its front it goes off; a wall with
    /// no opening stops the search first ("no way" sound). Unlike vanilla
    /// Doom, lines with other specials (walk lines) do not stop it.
    fn use_lines(&mut self) {
        let (sin, cos) = sin_cos_degrees(self.player.angle);
        let from = self.player.pos;
        let to = from + DVec2::new(cos, sin) * USE_RANGE;
        let mut scratch = std::mem::take(&mut self.scratch);
        let stop = self.use_stop(&mut scratch, from, to);
        self.scratch = scratch;
        let Some(c) = stop else { return };
        if self.world.special(&self.level, c.line).is_some_and(|s| s.on == Activation::Use) {
            if c.from_front {
                let (world, mut ctx) = self.ctx();
                activate(world, &mut ctx, c.line, Activation::Use, Activator::Player, true);
            }
        } else {
            self.events.push(sound("noway", Origin::Player));
        }
    }

    /// Where a use from `from` towards `to` stops: the first line with a
    /// live use special, or a wall with no opening; `None` when nothing
    /// does. (The autopilot asks it before pressing: another switch in
    /// front swallows the press.)
    pub fn use_stop(&self, scratch: &mut trace::Scratch, from: DVec2, to: DVec2) -> Option<trace::Crossing> {
        let lines = Lines { map: &self.level.compiled.map, walls: &self.blockmap, triggers: &self.triggers };
        lines.along(scratch, from, to).into_iter().find(|c| {
            self.world.special(&self.level, c.line).is_some_and(|s| s.on == Activation::Use)
                || matches!(c.line, SpecialLine::Wall(i) if !self.opening(i).is_some_and(|(bottom, top)| top > bottom))
        })
    }

    /// The lines with shoot specials that this tick's shots crossed before
    /// what they hit.
    fn shoot_lines(&mut self) {
        for (from, to) in std::mem::take(&mut self.shots) {
            let lines = Lines { map: &self.level.compiled.map, walls: &self.blockmap, triggers: &self.triggers };
            let crossings = lines.along(&mut self.scratch, from, to);
            for c in crossings {
                let (world, mut ctx) = self.ctx();
                activate(world, &mut ctx, c.line, Activation::Shoot, Activator::Player, c.from_front);
            }
        }
    }

    /// What the actors asked of the world: a boss's tagged special, an
    /// exit, the lines monsters crossed and the doors they pushed.
    fn do_requests(&mut self) {
        use actors::attacks::Request;
        for r in std::mem::take(&mut self.requests) {
            match r {
                Request::Tagged(action, tag) => {
                    let (world, mut ctx) = self.ctx();
                    world::specials::perform_tagged(world, &mut ctx, action, tag);
                }
                Request::Exit => self.exit = Some(Exit::Normal),
                Request::Cross { actor, from, to } => self.cross_lines(from, to, Activator::Monster(actor)),
                Request::Use { actor, line } => {
                    let (world, mut ctx) = self.ctx();
                    activate(
                        world,
                        &mut ctx,
                        SpecialLine::Wall(line),
                        Activation::Use,
                        Activator::Monster(actor),
                        true,
                    );
                }
            }
        }
        self.deal_harm();
    }

    /// The damage the world did to actors this tick (crushing, telefrags).
    fn deal_harm(&mut self) {
        if self.harmed.is_empty() {
            return;
        }
        let harmed = std::mem::take(&mut self.harmed);
        let (actors, mut ctx) = self.actor_ctx();
        for &(n, damage) in &harmed {
            actors.hurt(actors::Target::Actor(n), damage, None, actors::Target::None, &mut ctx);
        }
    }

    /// The opening of wall `i` (the higher floor and lower ceiling of its
    /// sides), `None` for a one-sided wall.
    fn opening(&self, i: usize) -> Option<(f64, f64)> {
        let map = &self.level.compiled.map;
        let line = &map.lines[i];
        let back = line.back.as_ref()?;
        let (f, b) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
        Some((f.floor.max(b.floor), f.ceiling.min(b.ceiling)))
    }

    /// The sector under the feet, pickups, then every thinker and the animations.
    fn run_world(&mut self) {
        let collision = Collision { compiled: &self.level.compiled, blockmap: &self.blockmap };
        let near = collision.lines_near(&mut self.query, self.player.pos, RADIUS + 1.0);
        collision.sectors_touched(near, self.player.pos, self.player.sector, &mut self.touched);
        // Conveyors (Boom's 252) push a body standing on their floor.
        for &s in &self.touched {
            let sector = &self.level.compiled.map.sectors[s];
            if let Some(c) = sector.carry.filter(|_| self.player.z <= sector.floor) {
                self.player.velocity += DVec2::new(c.x, c.y);
            }
        }
        let (world, mut ctx) = self.ctx();
        world::sectors::player_in_sector(world, &mut ctx);
        self.items +=
            pickups::touch(&mut self.actors, &mut self.level, &mut self.player, &mut self.events, self.options.skill);
        let (world, mut ctx) = self.ctx();
        world.tick(&mut ctx);
        self.deal_harm();
        let (actors, mut ctx) = self.actor_ctx();
        actors.tick(&mut ctx);
        self.shoot_lines();
        self.do_requests();
        self.actors.draw(&mut self.level);
    }

    /// The level as it is now: sectors at their current heights and light,
    /// switches and animations as they show, grid door panels slid as far as
    /// they are. Render this.
    pub fn level(&self) -> &Level {
        &self.level
    }

    /// The level to draw into, for a game shown from elsewhere (a Doom demo
    /// played on `sim`, drawn by `sim::draw`).
    pub fn level_mut(&mut self) -> &mut Level {
        &mut self.level
    }

    /// The eye, interpolated between the start (`alpha` 0) and the end
    /// (`alpha` 1) of the last tick; `alpha` is clamped to `[0, 1]`.
    pub fn view(&self, alpha: f64) -> View {
        let now = pose(&self.player);
        let a = if alpha.is_nan() { 1.0 } else { alpha.clamp(0.0, 1.0) };
        if a == 1.0 {
            return View::new(now.pos, now.eye, now.angle);
        }
        let prev = self.previous;
        let turned = (now.angle - prev.angle + 540.0).rem_euclid(360.0) - 180.0;
        View::new(
            prev.pos + (now.pos - prev.pos) * a,
            prev.eye + (now.eye - prev.eye) * a,
            (prev.angle + turned * a).rem_euclid(360.0),
        )
    }

    /// Wakes every monster waiting for the player, as if it had seen it
    /// ([`actors::Actors::wake_all`]).
    pub fn wake_monsters(&mut self) {
        let (actors, mut ctx) = self.actor_ctx();
        actors.wake_all(&mut ctx);
        self.do_requests();
        self.actors.draw(&mut self.level);
    }

    /// The things in play.
    pub fn actors(&self) -> &actors::Actors {
        &self.actors
    }

    pub fn player(&self) -> &Player {
        &self.player
    }

    /// The player, to change by hand (tests, tools). The next tick works
    /// from whatever it finds: speed is clamped to [`player::MAX_SPEED`],
    /// and a body left overlapping a wall can move out of it but not further in.
    /// Puts the player at `pos` facing `angle`, standing on the floor there,
    /// still (a map reloaded under a map maker keeps their pose). Returns
    /// `false`, and leaves the player as it was, when `pos` is outside every
    /// sector or the body does not fit there.
    pub fn place_player(&mut self, pos: DVec2, angle: f64) -> bool {
        if !pos.is_finite() || self.level.compiled.locate(pos).is_none() {
            return false;
        }
        let collision = Collision { compiled: &self.level.compiled, blockmap: &self.blockmap };
        let near = collision.lines_near(&mut self.query, pos, RADIUS + 1.0);
        let area = collision.area(near, pos);
        if area.ceiling - area.floor < HEIGHT {
            return false;
        }
        let p = &mut self.player;
        (p.pos, p.angle, p.velocity, p.vz) = (pos, angle.rem_euclid(360.0), DVec2::ZERO, 0.0);
        (p.sector, p.floor, p.ceiling, p.z) = (area.sector, area.floor, area.ceiling, area.floor);
        self.previous = pose(&self.player);
        true
    }

    pub fn player_mut(&mut self) -> &mut Player {
        &mut self.player
    }

    /// Puts the player at `pos` looking along `angle`, standing still on the
    /// floor there, as if it had started there (health and keys are kept).
    pub fn teleport(&mut self, pos: DVec2, angle: f64) -> Result<(), PlayError> {
        let map = &self.level.compiled.map;
        if !(pos.is_finite() && angle.is_finite()) || self.level.compiled.locate(pos).is_none() {
            return Err(PlayError::Outside { map: map.name.clone(), x: pos.x, y: pos.y });
        }
        let collision = Collision { compiled: &self.level.compiled, blockmap: &self.blockmap };
        let near = collision.lines_near(&mut self.query, pos, RADIUS + 1.0);
        let area = collision.area(near, pos);
        self.player.teleport_to(pos, angle, area, 0);
        self.player.view_height = crate::render::view::EYE_HEIGHT;
        self.player.view_delta = 0.0;
        self.previous = pose(&self.player);
        Ok(())
    }

    /// Ticks run since the start.
    pub fn ticks(&self) -> u64 {
        self.ticks
    }

    /// The world's machinery: its thinkers at work.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// What happened on the last tick: sounds and messages.
    pub fn events(&self) -> &[Event] {
        &self.events
    }

    /// How the level ended, once it has.
    pub fn exit(&self) -> Option<Exit> {
        self.exit
    }

    pub fn options(&self) -> GameOptions {
        self.options
    }

    /// Kills, items and secrets found of the level's totals, and the time.
    pub fn stats(&self) -> Stats {
        Stats {
            kills: (self.kills, self.totals.0),
            items: (self.items, self.totals.1),
            secrets: (self.world.secrets.1, self.world.secrets.0),
            ticks: self.ticks,
        }
    }
}

fn pose(player: &Player) -> Pose {
    Pose { pos: player.pos, eye: player.eye_z(), angle: player.angle }
}
