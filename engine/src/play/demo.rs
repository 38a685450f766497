//! Demos: a map and the inputs of every tick, enough to replay a game exactly
//! (the simulation reads nothing else). Saved as a small binary file:
//!
//! | Bytes | Content |
//! | --- | --- |
//! | 0-14 | magic `SIGHTLINE-DEMO\n` (15 bytes) |
//! | 15 | format version, [`VERSION`] |
//! | 16-19 | CRC-32 of every byte after these four (little-endian u32) |
//! | 20-23 | length `N` of the map string in bytes (u32), at most [`MAX_MAP_BYTES`] |
//! | 24-(24+N) | the map (a path, or `WAD:MAP`), UTF-8 |
//! | next 1 | skill, 1 to 5, plus 128 for a game without monsters |
//! | next 8 | the game's random seed (u64) |
//! | next 4 | tick count `T` (u32) |
//! | rest | `T` records of 7 bytes: forward (i8), strafe (i8), flags (bit 0 run, bit 1 use, bit 2 fire, bits 3-5 the weapon number asked for, 0 for none), turn (f32, degrees) |
//!
//! Every length is checked against the bytes actually present before
//! anything is allocated, so a corrupt file is an error, never a panic or a
//! huge allocation.

use std::path::Path;

use super::input::TickInput;

pub const MAGIC: &[u8] = b"SIGHTLINE-DEMO\n";
/// Bumped whenever the layout or the simulation's meaning of an input changes.
/// Version 2: skill and seed in the header, fire, and use acting once per
/// press (the world's machinery came with it, so version 1 games would not
/// replay the same). Version 3: actors run (monsters wake, chase and
/// shoot; pickups give), and fire shoots them. Version 4: weapons (fire
/// held keeps firing, weapon numbers in the flags), missiles and infighting.
/// Version 5: the simulation with Doom's arithmetic is the only game (a
/// version 4 demo of the f64 game that came first cannot replay).
pub const VERSION: u8 = 5;
/// Longest map string accepted (a path, not a map).
pub const MAX_MAP_BYTES: u32 = 4096;
const RECORD: usize = 7;
/// The skill byte's flag for a game without monsters.
const NO_MONSTERS: u8 = 128;
const RUN: u8 = 1;
const USE: u8 = 2;
const FIRE: u8 = 4;
/// The weapon number, in bits 3 to 5.
const WEAPON_SHIFT: u8 = 3;
const WEAPON_BITS: u8 = 7 << WEAPON_SHIFT;

/// A recorded game.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Demo {
    /// The map played, as the recorder named it (normally its path).
    pub map: String,
    /// The skill played on, 1 to 5.
    pub skill: u8,
    /// The game's random seed.
    pub seed: u64,
    /// Played without monsters (`--no-monsters`).
    pub no_monsters: bool,
    /// One input per tick, from the first.
    pub inputs: Vec<TickInput>,
}

#[derive(Debug, thiserror::Error)]
pub enum DemoError {
    #[error("{path}: cannot read: {error}")]
    Read { path: String, error: std::io::Error },
    #[error("{path}: cannot write: {error}")]
    Write { path: String, error: std::io::Error },
    #[error("{path}: not a Sightline demo (bad header)")]
    Magic { path: String },
    #[error("{path}: demo format version {found}, this build reads version {VERSION}")]
    Version { path: String, found: u8 },
    #[error("{path}: truncated: {what}")]
    Truncated { path: String, what: String },
    #[error("{path}: corrupt: {what}")]
    Corrupt { path: String, what: String },
    #[error("{path}: {ticks} ticks are more than a demo file holds")]
    TooLong { path: String, ticks: usize },
    #[error("{path}: the map name is {len} bytes, over the limit of {MAX_MAP_BYTES}")]
    MapTooLong { path: String, len: usize },
}

impl Demo {
    pub fn new(map: impl Into<String>) -> Demo {
        Demo { map: map.into(), skill: crate::play::DEFAULT_SKILL, seed: 0, no_monsters: false, inputs: Vec::new() }
    }

    /// The options the recorded game was played with.
    pub fn options(&self) -> crate::play::GameOptions {
        crate::play::GameOptions { skill: self.skill, seed: self.seed, no_monsters: self.no_monsters }
    }

    /// The file's bytes (see the module docs for the layout).
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut body = Vec::with_capacity(8 + self.map.len() + self.inputs.len() * RECORD);
        body.extend((self.map.len() as u32).to_le_bytes());
        body.extend(self.map.as_bytes());
        body.push(self.skill | if self.no_monsters { NO_MONSTERS } else { 0 });
        body.extend(self.seed.to_le_bytes());
        body.extend((self.inputs.len() as u32).to_le_bytes());
        for input in &self.inputs {
            let flags = if input.run { RUN } else { 0 }
                | if input.use_line { USE } else { 0 }
                | if input.fire { FIRE } else { 0 }
                | (input.weapon.min(7) << WEAPON_SHIFT);
            body.extend([input.forward as u8, input.strafe as u8, flags]);
            body.extend(input.turn.to_le_bytes());
        }
        let mut bytes = MAGIC.to_vec();
        bytes.push(VERSION);
        bytes.extend(crc32fast::hash(&body).to_le_bytes());
        bytes.extend(body);
        bytes
    }

    /// Writes the demo to `path` (atomically: a temporary file, then a rename).
    pub fn save(&self, path: &Path) -> Result<(), DemoError> {
        if self.map.len() > MAX_MAP_BYTES as usize {
            return Err(DemoError::MapTooLong { path: path.display().to_string(), len: self.map.len() });
        }
        if u32::try_from(self.inputs.len()).is_err() {
            return Err(DemoError::TooLong { path: path.display().to_string(), ticks: self.inputs.len() });
        }
        crate::level::write_file_atomic(path, &self.to_bytes())
            .map_err(|error| DemoError::Write { path: path.display().to_string(), error })
    }

    pub fn load(path: &Path) -> Result<Demo, DemoError> {
        let label = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|error| DemoError::Read { path: label.clone(), error })?;
        Demo::from_bytes(&bytes, &label)
    }

    /// Decodes a demo; `label` names the file in errors.
    pub fn from_bytes(bytes: &[u8], label: &str) -> Result<Demo, DemoError> {
        let path = || label.to_string();
        let truncated = |what: &str| DemoError::Truncated { path: path(), what: what.to_string() };
        let rest = bytes.strip_prefix(MAGIC).ok_or_else(|| DemoError::Magic { path: path() })?;
        let (&version, rest) = rest.split_first().ok_or_else(|| truncated("no version after the header"))?;
        if version != VERSION {
            return Err(DemoError::Version { path: path(), found: version });
        }
        let (checksum, body) = rest.split_first_chunk::<4>().ok_or_else(|| truncated("no checksum"))?;
        let mut reader = Reader { bytes: body };
        let map_len = reader.u32().ok_or_else(|| truncated("no map name length"))?;
        if map_len > MAX_MAP_BYTES {
            return Err(DemoError::MapTooLong { path: path(), len: map_len as usize });
        }
        let map = reader.take(map_len as usize).ok_or_else(|| truncated("the map name is cut short"))?;
        let byte = reader.take(1).ok_or_else(|| truncated("no skill"))?[0];
        let (skill, no_monsters) = (byte & !NO_MONSTERS, byte & NO_MONSTERS != 0);
        let seed = reader.take(8).ok_or_else(|| truncated("no seed"))?;
        let seed = u64::from_le_bytes(seed.try_into().unwrap_or_default());
        let ticks = reader.u32().ok_or_else(|| truncated("no tick count"))? as usize;
        let present = reader.bytes.len();
        // Compare before allocating: a forged count cannot reserve memory.
        match (ticks as u64 * RECORD as u64).cmp(&(present as u64)) {
            std::cmp::Ordering::Greater => {
                return Err(truncated(&format!("{ticks} ticks need {} bytes, {present} remain", ticks * RECORD)))
            }
            std::cmp::Ordering::Less => {
                return Err(DemoError::Corrupt {
                    path: path(),
                    what: format!("{} bytes after the {ticks} ticks", present - ticks * RECORD),
                })
            }
            std::cmp::Ordering::Equal => {}
        }
        if crc32fast::hash(body) != u32::from_le_bytes(*checksum) {
            return Err(DemoError::Corrupt { path: path(), what: "checksum mismatch".into() });
        }
        let map = String::from_utf8(map.to_vec())
            .map_err(|_| DemoError::Corrupt { path: path(), what: "the map name is not UTF-8".into() })?;
        if !(1..=5).contains(&skill) {
            return Err(DemoError::Corrupt { path: path(), what: format!("skill {skill} is not 1 to 5") });
        }
        let mut inputs = Vec::with_capacity(ticks);
        for (tick, r) in reader.bytes.chunks_exact(RECORD).enumerate() {
            if r[2] & !(RUN | USE | FIRE | WEAPON_BITS) != 0 {
                return Err(DemoError::Corrupt {
                    path: path(),
                    what: format!("tick {tick}: unknown flags {:#04x}", r[2]),
                });
            }
            inputs.push(TickInput {
                forward: r[0] as i8,
                strafe: r[1] as i8,
                run: r[2] & RUN != 0,
                use_line: r[2] & USE != 0,
                fire: r[2] & FIRE != 0,
                weapon: (r[2] & WEAPON_BITS) >> WEAPON_SHIFT,
                turn: f32::from_le_bytes([r[3], r[4], r[5], r[6]]),
            });
        }
        Ok(Demo { map, skill, seed, no_monsters, inputs })
    }
}

/// Reads little-endian fields off the front of a byte slice.
struct Reader<'a> {
    bytes: &'a [u8],
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        if self.bytes.len() < n {
            return None;
        }
        let (head, tail) = self.bytes.split_at(n);
        self.bytes = tail;
        Some(head)
    }

    fn u32(&mut self) -> Option<u32> {
        self.take(4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    }
}
