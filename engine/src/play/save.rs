//! Saved games: a playthrough's whole state in one file, loaded into a new
//! game that continues exactly as the original would have, tick for tick.
//!
//! What is saved is the simulation's whole state ([`crate::sim::save`],
//! bit-exact, checked against the map and the actor table by its own
//! fingerprints) and the playthrough around it: the map, the campaign, the
//! options and the ticks. What play never changes (the map's geometry, the
//! BSP, the blockmaps, the art) is not saved: loading opens the map afresh,
//! checks that it is the one the game was saved with (by its
//! fingerprint), starts a game on it and puts the saved state in place,
//! checked before anything replaces the running game.
//!
//! | Bytes | Content |
//! | --- | --- |
//! | 0-14 | magic `SIGHTLINE-SAVE\n` (15 bytes) |
//! | 15 | format version, [`VERSION`] |
//! | 16-19 | CRC-32 of every byte after the length (little-endian u32) |
//! | 20-27 | length of the rest in bytes (little-endian u64) |
//! | rest | [`SaveInfo`], then the game's state, each in CBOR |
//!
//! Version 3: the simulation is the only game (version 2 could hold the
//! f64 game that came first); older saves are refused with that message.
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

use serde::{Deserialize, Serialize};

use crate::bsp::BuildOptions;
use crate::campaign::{open, Campaign, MapRef};
use crate::envelope::{self, encode, EnvelopeError};
use crate::level::Level;

use super::playthrough::{Phase, Playthrough, PlaythroughError};
use super::GameOptions;
use crate::sim::game::SimGame;

pub const MAGIC: &[u8] = b"SIGHTLINE-SAVE\n";
/// Bumped whenever the saved state's meaning changes (a field renamed, or
/// the same field meaning something else). 2: the level's game may be the
/// simulation with Doom's arithmetic. 3: it is (the f64 game is gone).
pub const VERSION: u8 = 4;

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
    /// CRC-32 of the map as opened (before play).
    map_fingerprint: u32,
}

/// The CRC-32 of a map as opened, before play: a save is only good for the
/// map it was made on.
pub fn map_fingerprint(level: &Level) -> u32 {
    crc32fast::hash(&postcard::to_stdvec(&level.compiled.map).unwrap_or_default())
}

impl Playthrough {
    /// The save's bytes (see the module docs); only while a level is being
    /// played, as in Doom (not in an intermission).
    pub fn save_bytes(&self) -> Result<Vec<u8>, &'static str> {
        if self.phase != Phase::Playing {
            return Err("the level is over (saves are made while playing)");
        }
        if self.game.scripts().is_some() {
            // The VM's threads, variables and generator are not saved yet:
            // a save would lose the scenario's logic.
            return Err("this map's ACS scripts cannot be saved yet (a ZDoom-format map)");
        }
        let (map_fingerprint, state) = (self.game.fingerprint(), self.game.state_bytes());
        let info = SaveInfo {
            map: absolute_map(&self.map),
            campaign: absolute_campaign(&self.campaign),
            options: self.options(),
            playthrough_ticks: self.ticks,
            level_ticks: self.game.ticks(),
            map_fingerprint,
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
        // The simulation's state checks its own actor table and map.
        let map = opened.map.clone();
        let mut game = SimGame::new(opened, info.options).map_err(|e| corrupt(e.to_string()))?;
        game.restore(state, label).map_err(|e| corrupt(e.to_string()))?;
        if game.ticks() != info.level_ticks {
            return Err(corrupt("the header and the game's state disagree".into()));
        }
        Ok(Playthrough::resume(info.campaign, map, game, info.playthrough_ticks))
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
