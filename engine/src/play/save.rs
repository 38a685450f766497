//! Saved games: a playthrough's whole state in one file, loaded into a new
//! game that continues exactly as the original would have, tick for tick.
//!
//! What is saved is what play changes: the level's moving parts (sector
//! heights, light, floor textures and specials, wall and plane textures
//! that switches and animations changed, grid doors, the things drawn), the
//! player, the world's thinkers, every actor with its place in the thing
//! grid and the tick's lists, the tallies, the random generator's state and
//! the tick. What play never changes (the map's geometry, the BSP, the
//! blockmaps, the art, the actor table) is not saved: loading opens the map
//! afresh, checks that it and the actor table are the ones the game was
//! saved with (by their fingerprints), starts a game on it and puts the
//! saved state in place, checked against the map (every index in range)
//! before anything replaces the running game.
//!
//! | Bytes | Content |
//! | --- | --- |
//! | 0-14 | magic `SIGHTLINE-SAVE\n` (15 bytes) |
//! | 15 | format version, [`VERSION`] |
//! | 16-19 | CRC-32 of every byte after the length (little-endian u32) |
//! | 20-27 | length of the rest in bytes (little-endian u64) |
//! | rest | [`SaveInfo`], then the game's state, each in CBOR |
//!
//! The game's state is the f64 game's ([`Game::state_bytes`]), or, when the
//! level is played on the simulation with Doom's arithmetic
//! ([`GameOptions::sim`]), the simulation's own saved state
//! ([`crate::sim::save`], bit-exact, checked against the map and the actor
//! table by its own fingerprints). Version 2 brought the simulation; a
//! version 1 save is refused with that message.
//!
//! CBOR (RFC 8949, by `ciborium`) is self-describing: fields go by name, so
//! the map types' defaulted fields (left out when they hold their default,
//! as in a RON map) read back, and a field that is missing or of the wrong
//! kind is an error that names it.
//!
//! A file is written to a temporary name beside the target and renamed
//! over it, so a failed write never leaves a half-written save or clobbers
//! the one there.

use std::path::Path;
use std::sync::Arc;

use serde::{Deserialize, Serialize};

use crate::actors::ActorTable;
use crate::bsp::BuildOptions;
use crate::campaign::{open, Campaign, MapRef};
use crate::envelope::{self, encode, EnvelopeError};
use crate::level::Level;
use crate::map::Sector;
use crate::materials::{SectorTextures, SideTextures};
use crate::texture::TextureId;

use super::actors::Actors;
use super::playthrough::{Phase, Played, Playthrough, PlaythroughError};
use super::random::GameRng;
use super::world::{Exit, World};
use super::{Game, GameOptions, Player, Pose};
use crate::sim::game::SimGame;

pub const MAGIC: &[u8] = b"SIGHTLINE-SAVE\n";
/// Bumped whenever the saved state's meaning changes (a field renamed, or
/// the same field meaning something else). 2: the level's game may be the
/// simulation with Doom's arithmetic.
pub const VERSION: u8 = 2;

#[derive(Debug, thiserror::Error)]
pub enum SaveError {
    #[error("{path}: cannot read: {error}")]
    Read { path: String, error: std::io::Error },
    #[error("{path}: cannot write: {error}")]
    Write { path: String, error: std::io::Error },
    #[error("{path}: not a Sightline saved game (bad header)")]
    Magic { path: String },
    #[error("{path}: saved-game format version {found}, this build reads version {VERSION}")]
    Version { path: String, found: u8 },
    #[error("{path}: truncated: {what}")]
    Truncated { path: String, what: String },
    #[error("{path}: corrupt: {what}")]
    Corrupt { path: String, what: String },
    #[error("{path}: the map {map} has changed since the game was saved")]
    MapChanged { path: String, map: String },
    #[error("{path}: the actor table has changed since the game was saved")]
    TableChanged { path: String },
    #[error("{path}: the saved game's map cannot be opened: {error}")]
    Open { path: String, error: Box<PlaythroughError> },
    #[error("{path}: nothing to save: {why}")]
    NotPlaying { path: String, why: &'static str },
}

/// What a save says about itself, readable without loading the game.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SaveInfo {
    /// The map being played (paths made absolute, so the save loads from anywhere).
    pub map: MapRef,
    /// What follows it.
    pub campaign: Campaign,
    pub options: GameOptions,
    /// Ticks since the playthrough began, and since this map began.
    pub playthrough_ticks: u64,
    pub level_ticks: u64,
    /// The playthrough's last tick held use or fire.
    held: bool,
    /// CRC-32 of the map as opened (before play) and of the actor table.
    map_fingerprint: u32,
    table_fingerprint: u32,
}

/// The level's parts that play changes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct LevelState {
    sectors: Vec<Sector>,
    sides: Vec<[SideTextures; 2]>,
    planes: Vec<SectorTextures>,
    translation: Vec<TextureId>,
    grid_doors: Option<Vec<f64>>,
    things: Vec<crate::level::DrawnThing>,
    thing_shown: Vec<bool>,
    time: u64,
}

/// A game's state: everything that differs from a game just started on the
/// same map with the same options.
#[derive(Clone, Serialize, Deserialize)]
struct GameState {
    level: LevelState,
    player: Player,
    world: World,
    touched: Vec<usize>,
    actors: Actors,
    kills: u32,
    items: u32,
    rng: GameRng,
    exit: Option<Exit>,
    options: GameOptions,
    totals: (u32, u32),
    previous: Pose,
    ticks: u64,
}

/// The CRC-32 of a map as opened, before play: a save is only good for the
/// map it was made on.
pub fn map_fingerprint(level: &Level) -> u32 {
    crc32fast::hash(&postcard::to_stdvec(&level.compiled.map).unwrap_or_default())
}

/// The CRC-32 of what an actor table says (its actors, states, sprites and sounds).
pub fn table_fingerprint(table: &ActorTable) -> u32 {
    let text = format!("{:?}{:?}{:?}{:?}", table.actors, table.states, table.sprites, table.sounds);
    crc32fast::hash(text.as_bytes())
}

impl Game {
    fn state(&self) -> GameState {
        let level = &self.level;
        GameState {
            level: LevelState {
                sectors: level.compiled.map.sectors.clone(),
                sides: level.materials.sides.clone(),
                planes: level.materials.sectors.clone(),
                translation: level.materials.translation.clone(),
                grid_doors: level.grid.as_ref().map(|g| g.open.clone()),
                things: level.things.clone(),
                thing_shown: level.thing_shown.clone(),
                time: level.time,
            },
            player: self.player.clone(),
            world: self.world.clone(),
            touched: self.touched.clone(),
            actors: self.actors.clone(),
            kills: self.kills,
            items: self.items,
            rng: self.rng.clone(),
            exit: self.exit,
            options: self.options,
            totals: self.totals,
            previous: self.previous,
            ticks: self.ticks,
        }
    }

    /// The game's whole state as bytes: equal bytes, equal games (what a
    /// save holds after its header).
    pub fn state_bytes(&self) -> Vec<u8> {
        encode(&self.state())
    }

    /// A game on `level` (opened afresh, untouched by play) in the state
    /// `bytes` hold ([`Game::state_bytes`]), with `table`'s actors; `Err`
    /// says what in the state does not fit the level.
    pub fn from_state(level: Level, table: Arc<ActorTable>, bytes: &[u8]) -> Result<Game, String> {
        let mut rest = bytes;
        let state: GameState =
            ciborium::from_reader(&mut rest).map_err(|e| format!("the game's state does not decode: {e}"))?;
        if !rest.is_empty() {
            return Err(format!("{} bytes after the game's state", rest.len()));
        }
        Game::restore(level, table, state)
    }

    fn restore(level: Level, table: Arc<ActorTable>, state: GameState) -> Result<Game, String> {
        let mut game = Game::with_table(level, state.options, table).map_err(|e| e.to_string())?;
        check(&game, &state)?;
        let GameState {
            level: saved,
            player,
            world,
            touched,
            mut actors,
            kills,
            items,
            rng,
            exit,
            options,
            totals,
            previous,
            ticks,
        } = state;
        let level = &mut game.level;
        level.compiled.map.sectors = saved.sectors;
        level.materials.sides = saved.sides;
        level.materials.sectors = saved.planes;
        level.materials.translation = saved.translation;
        if let (Some(grid), Some(open)) = (level.grid.as_mut(), saved.grid_doors) {
            grid.open = open;
        }
        level.things = saved.things;
        level.thing_shown = saved.thing_shown;
        level.time = saved.time;
        actors.take_tools(&mut game.actors);
        game.actors = actors;
        game.player = player;
        game.world = world;
        game.touched = touched;
        (game.kills, game.items, game.totals) = (kills, items, totals);
        game.rng = rng;
        game.exit = exit;
        game.options = options;
        game.previous = previous;
        game.ticks = ticks;
        Ok(game)
    }
}

/// Does the saved state fit the game just started on its map? Every index
/// the simulation follows without checking is checked here, so that a
/// state that decodes but does not belong (a bug, or a forged file) is an
/// error rather than a panic some ticks later.
fn check(game: &Game, state: &GameState) -> Result<(), String> {
    let level = &game.level;
    let map = &level.compiled.map;
    let saved = &state.level;
    let (sectors, lines, textures) = (map.sectors.len(), map.lines.len(), level.materials.textures.len());
    let same = |what: &str, have: usize, want: usize| {
        if have == want {
            Ok(())
        } else {
            Err(format!("{have} {what}, the map has {want}"))
        }
    };
    same("sectors", saved.sectors.len(), sectors)?;
    same("sides' textures", saved.sides.len(), lines)?;
    same("sectors' plane textures", saved.planes.len(), sectors)?;
    same("texture translations", saved.translation.len(), level.materials.translation.len())?;
    same("things shown", saved.thing_shown.len(), level.thing_shown.len())?;
    same("grid doors", saved.grid_doors.as_ref().map_or(0, Vec::len), level.grid.as_ref().map_or(0, |g| g.open.len()))?;
    let texture = |id: &TextureId| (id.0 as usize) < textures;
    let sides = saved.sides.iter().flatten().flat_map(|s| [s.upper, s.middle, s.lower]).flatten();
    let planes = saved.planes.iter().flat_map(|s| [s.floor, s.ceiling]).flatten();
    let views = saved.things.iter().flat_map(|t| t.views);
    if !(sides.chain(planes).chain(views).all(|id| texture(&id)) && saved.translation.iter().all(texture)) {
        return Err("a texture that the map does not have".into());
    }
    for s in &saved.sectors {
        let light = |l: Option<usize>| l.is_none_or(|l| l < sectors);
        if !(light(s.floor_light) && light(s.ceiling_light)) {
            return Err("a sector lit from a sector that the map does not have".into());
        }
    }
    if saved.things.iter().any(|t| t.sector >= sectors) || state.touched.iter().any(|&s| s >= sectors) {
        return Err("a thing in a sector that the map does not have".into());
    }
    let table = &game.actors.table;
    let player = &state.player;
    let weapon = |w: &usize| *w < table.actors.len();
    let psprite_state = |p: &super::player::PSprite| p.state.is_none_or(|s| (s.0 as usize) < table.states.len());
    if player.sector >= sectors
        || !player.weapons.iter().all(weapon)
        || !player.ready_weapon.iter().chain(&player.pending_weapon).all(weapon)
        || !player.psprites.iter().all(psprite_state)
    {
        return Err("the player's sector, weapons or weapon frames are not the map's or the table's".into());
    }
    state.world.check(level)?;
    state.actors.check(&game.actors, level, saved.things.len())
}

impl Playthrough {
    /// The save's bytes (see the module docs); only while a level is being
    /// played, as in Doom (not in an intermission).
    pub fn save_bytes(&self) -> Result<Vec<u8>, &'static str> {
        if self.phase != Phase::Playing {
            return Err("the level is over (saves are made while playing)");
        }
        let (map_fingerprint, table_fingerprint, state) = match &self.game {
            Played::Float(game) => (game.fingerprint, table_fingerprint(&game.actors.table), game.state_bytes()),
            Played::Sim(game) => (game.fingerprint(), 0, game.state_bytes()),
        };
        let info = SaveInfo {
            map: absolute_map(&self.map),
            campaign: absolute_campaign(&self.campaign),
            options: self.options(),
            playthrough_ticks: self.ticks,
            level_ticks: self.game.ticks(),
            held: self.held(),
            map_fingerprint,
            table_fingerprint,
        };
        let mut body = encode(&info);
        body.extend(state);
        Ok(envelope::seal(MAGIC, VERSION, &body))
    }

    /// Saves the playthrough to `path`, atomically (a failed write leaves
    /// whatever was there).
    pub fn save(&self, path: &Path) -> Result<(), SaveError> {
        let label = path.display().to_string();
        let bytes = self.save_bytes().map_err(|why| SaveError::NotPlaying { path: label.clone(), why })?;
        crate::level::write_file_atomic(path, &bytes).map_err(|error| SaveError::Write { path: label, error })
    }

    /// Loads the playthrough saved in `path`.
    pub fn load(path: &Path) -> Result<Playthrough, SaveError> {
        let label = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|error| SaveError::Read { path: label.clone(), error })?;
        Playthrough::from_save_bytes(&bytes, &label)
    }

    /// Loads a playthrough from a save's bytes; `label` names the file in errors.
    pub fn from_save_bytes(bytes: &[u8], label: &str) -> Result<Playthrough, SaveError> {
        let (info, state) = read(bytes, label)?;
        let path = || label.to_string();
        // What the save names is read only if it is a plain file (a forged
        // save naming a device must not read for ever).
        let named = match &info.map {
            MapRef::File(p) => vec![p.clone()],
            MapRef::Wad { wads, .. } => wads.clone(),
        };
        if let Some(odd) = named.iter().find(|p| p.exists() && !p.is_file()) {
            return Err(SaveError::Corrupt {
                path: path(),
                what: format!("it names {}, which is not a file", odd.display()),
            });
        }
        let opened = open(&info.map, &BuildOptions::default())
            .map_err(|e| SaveError::Open { path: path(), error: Box::new(e.into()) })?;
        if map_fingerprint(&opened.level) != info.map_fingerprint {
            return Err(SaveError::MapChanged { path: path(), map: info.map.label() });
        }
        let corrupt = |what: String| SaveError::Corrupt { path: path(), what };
        let game = if info.options.sim {
            // The simulation's state checks its own actor table and map.
            let map = opened.map.clone();
            let mut game = SimGame::new(opened, info.options).map_err(|e| corrupt(e.to_string()))?;
            game.restore(state, label).map_err(|e| corrupt(e.to_string()))?;
            (Played::Sim(Box::new(game)), map)
        } else {
            let table = ActorTable::active().clone();
            if table_fingerprint(&table) != info.table_fingerprint {
                return Err(SaveError::TableChanged { path: path() });
            }
            let game = Game::from_state(opened.level, table, state).map_err(corrupt)?;
            if game.options != info.options {
                return Err(corrupt("the header and the game's state disagree".into()));
            }
            (Played::Float(Box::new(game)), opened.map)
        };
        let (game, map) = game;
        if game.ticks() != info.level_ticks {
            return Err(corrupt("the header and the game's state disagree".into()));
        }
        Ok(Playthrough::resume(info.campaign, map, game, info.playthrough_ticks, info.held))
    }
}

/// What a save file says about itself (for a list of slots), checked as a
/// load checks it but without opening the map.
pub fn peek(path: &Path) -> Result<SaveInfo, SaveError> {
    let label = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|error| SaveError::Read { path: label.clone(), error })?;
    read(&bytes, &label).map(|(info, _)| info)
}

/// The header checked, the info decoded, and the state's bytes.
fn read<'a>(bytes: &'a [u8], label: &str) -> Result<(SaveInfo, &'a [u8]), SaveError> {
    let path = || label.to_string();
    envelope::open_described(bytes, MAGIC, VERSION).map_err(|e| match e {
        EnvelopeError::Magic => SaveError::Magic { path: path() },
        EnvelopeError::Version(found) => SaveError::Version { path: path(), found },
        EnvelopeError::Truncated(what) => SaveError::Truncated { path: path(), what },
        EnvelopeError::Corrupt(what) => SaveError::Corrupt { path: path(), what },
    })
}

/// `path` made absolute (against the working directory), so a save made
/// from one directory loads from another.
fn absolute(path: &Path) -> std::path::PathBuf {
    std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf())
}

fn absolute_map(map: &MapRef) -> MapRef {
    match map {
        MapRef::File(p) => MapRef::File(absolute(p)),
        MapRef::Wad { wads, map } => MapRef::Wad { wads: wads.iter().map(|w| absolute(w)).collect(), map: map.clone() },
    }
}

fn absolute_campaign(campaign: &Campaign) -> Campaign {
    match campaign {
        Campaign::Single(map) => Campaign::Single(absolute_map(map)),
        Campaign::Wad { wads, maps } => {
            Campaign::Wad { wads: wads.iter().map(|w| absolute(w)).collect(), maps: maps.clone() }
        }
        Campaign::List { name, maps } => Campaign::List {
            name: name.clone(),
            maps: maps
                .iter()
                .map(|(map, a, b)| (absolute(map), a.as_deref().map(absolute), b.as_deref().map(absolute)))
                .collect(),
        },
    }
}
