//! DeHackEd and BEX patches over the actor table: the stage between the
//! shipped table (or a modder's `--actors` file) and a game. Doom, Freedoom
//! (whose IWADs carry a `DEHACKED` lump) and a `--deh FILE` mod then play
//! with one table, patched as Chocolate Doom patches doom.exe's.
//!
//! A patch addresses Doom's arrays by number: "Thing 2" is mobjinfo[1],
//! "Frame 185" is states[185] (S_POSS_ATK2), sounds and sprites by their
//! index. `engine/data/doom_info.ron` holds those arrays (from Chocolate
//! Doom's info.c), and `mapping.rs` pairs each with the table: every thing
//! with an actor, every frame with the state(s) that are it.
//!
//! - `read.rs`: bytes to lines, with Chocolate Doom's rules (CRLF, BEX's
//!   `\n` and `\` continuations, the raw characters of a `Text` block);
//! - `parse.rs`: lines to a [`Patch`] (`model.rs`), a plain description of
//!   what the patch sets, with warnings for what it cannot mean;
//! - `doom.rs`: Doom's numbering (states, things, weapons, sprites, sounds,
//!   flag bits);
//! - `mapping.rs`: Doom's frames and things to the table's states and
//!   actors;
//! - `apply/`: a [`Patch`] onto a table (`things.rs`, `frames.rs`, and
//!   `items.rs` for weapons, ammunition and Misc), with `text.rs`'s
//!   [`Strings`], [`Pars`] and [`Settings`] for what is not the table's
//!   (level names, par times, the player's limits, cheats).
//!
//! Where this differs from Chocolate Doom, on purpose: a malformed number,
//! an unknown section or a thing, frame or sound number out of range is an
//! error naming the file and line (Chocolate warns and skips the section);
//! a section runs to the next section's header, so a blank line inside one
//! does not end it (Chocolate ends a section at a blank line and then
//! ignores the stray lines); BEX's `[STRINGS]`, `[PARS]`, `[CODEPTR]`,
//! `[SPRITES]`, `[SOUNDS]` and `[MUSIC]` are read without Chocolate's magic
//! comment; a `Text` replacement longer than doom.exe had room for is
//! accepted with a warning (Chocolate refuses it).

// Errors are made once, when a patch is refused; their size does not matter.
#![allow(clippy::result_large_err)]

mod apply;
mod doom;
mod mapping;
mod model;
mod parse;
mod read;
#[cfg(test)]
mod tests;
mod text;

pub use doom::{doom_info, DoomInfo, DoomState, DoomThing, DoomWeapon, MF_BITS};
pub use mapping::DoomMap;
pub use model::*;
pub use text::{Pars, Settings, Strings};

use super::{ActionCall, ActorTable};
use crate::wad::Wad;

/// Why a patch could not be read or applied.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum DehackedError {
    /// Something at one line of the patch.
    #[error("{path}:{line}: {message}")]
    At { path: String, line: usize, message: String },
    #[error("{path}: {message}")]
    File { path: String, message: String },
}

/// What a patch says that Sightline ignores or reads loosely, by line, as
/// Chocolate Doom prints it (`file:line: warning: ...`).
#[derive(Clone, Debug, PartialEq)]
pub struct Warning {
    pub path: String,
    pub line: usize,
    pub message: String,
}

impl std::fmt::Display for Warning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}: warning: {}", self.path, self.line, self.message)
    }
}

/// What loading patches gave besides the table: the warnings, and the
/// game's text, par times and settings as the patches left them.
#[derive(Clone, Debug, Default)]
pub struct DehackedReport {
    pub warnings: Vec<Warning>,
    pub strings: Strings,
    pub pars: Pars,
    pub settings: Settings,
    /// Sections applied, by kind, for a log line.
    pub applied: Applied,
}

/// How many sections of each kind were applied.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Applied {
    pub things: usize,
    pub frames: usize,
    pub pointers: usize,
    pub weapons: usize,
    pub ammo: usize,
    pub misc: usize,
    pub cheats: usize,
    pub texts: usize,
    pub strings: usize,
    pub pars: usize,
    pub code_pointers: usize,
}

/// A table with patches applied in turn (the IWAD's `DEHACKED` lump, then
/// each `--deh` file), and what they gave besides. The pairing of Doom's
/// numbers with the table is made once, on the table as it was before any
/// patch: a patched frame no longer looks like Doom's, yet is still the
/// frame a later patch means.
pub struct Dehacked {
    pub table: ActorTable,
    pub report: DehackedReport,
    map: DoomMap,
    /// Each Doom frame's action as the unpatched table had it: what a
    /// `Pointer` section's "Codep Frame = N" copies (Chocolate copies from
    /// its saved codeptrs[], not from the patched states).
    code_pointers: Vec<Option<ActionCall>>,
    /// Ammunition a pickup gives, as a count of Doom's clips (for "Per
    /// ammo"): actor, its `give` entry, Doom's ammo number, the count.
    clip_counts: Vec<(usize, usize, usize, i32)>,
    /// Each pickup's message as the unpatched table has it (doom.exe's
    /// text, which [`Strings`] replaces).
    messages: Vec<(usize, String)>,
}

impl Dehacked {
    pub fn new(table: ActorTable) -> Dehacked {
        let map = mapping::map(&table);
        let code_pointers = apply::code_pointers(&table, &map);
        let clip_counts = apply::clip_counts(&table);
        let messages = table
            .actors
            .iter()
            .enumerate()
            .filter_map(|(a, def)| def.pickup.as_ref().map(|p| (a, p.message.clone())))
            .collect();
        Dehacked { table, report: DehackedReport::default(), map, code_pointers, clip_counts, messages }
    }

    /// The pairing of Doom's numbers with the table.
    pub fn map(&self) -> &DoomMap {
        &self.map
    }

    /// Parses a patch (`path` names it in errors) and applies it. On an
    /// error nothing of this patch is kept.
    pub fn load(&mut self, bytes: &[u8], path: &str) -> Result<(), DehackedError> {
        let patch = parse::parse(bytes, path)?;
        self.apply(&patch)
    }

    /// Applies a parsed patch. On an error nothing of it is kept.
    pub fn apply(&mut self, patch: &Patch) -> Result<(), DehackedError> {
        parse::check(patch)?;
        let mut table = self.table.clone();
        let mut map = self.map.clone();
        let mut report = self.report.clone();
        report.warnings.extend(patch.warnings.iter().cloned());
        let mut run = apply::Run {
            table: &mut table,
            map: &mut map,
            report: &mut report,
            code_pointers: &self.code_pointers,
            clip_counts: &self.clip_counts,
            messages: &self.messages,
            path: &patch.path,
        };
        run.patch(patch)?;
        (self.table, self.map, self.report) = (table, map, report);
        Ok(())
    }

    /// Applies every `DEHACKED` lump of `wad`, in directory order (an IWAD
    /// has one; a PWAD stacked on it may add its own, which Boom's ports
    /// load too). Returns how many there were.
    pub fn load_wad(&mut self, wad: &Wad) -> Result<usize, DehackedError> {
        let lumps = lumps(wad);
        for &i in &lumps {
            self.load(wad.bytes(i), &format!("{}:{}", wad.path, wad.lumps[i].name))?;
        }
        Ok(lumps.len())
    }

    pub fn finish(self) -> (ActorTable, DehackedReport) {
        (self.table, self.report)
    }
}

/// The directory indices of `wad`'s `DEHACKED` lumps, in order.
pub fn lumps(wad: &Wad) -> Vec<usize> {
    (0..wad.lumps.len()).filter(|&i| wad.lumps[i].name.eq_ignore_ascii_case("DEHACKED")).collect()
}

/// Reads a patch into its model without applying it.
pub fn parse(bytes: &[u8], path: &str) -> Result<Patch, DehackedError> {
    parse::parse(bytes, path)
}

impl ActorTable {
    /// This table with one DeHackEd/BEX patch applied (`--deh FILE`; `path`
    /// names it in errors and warnings).
    pub fn with_dehacked(&self, text: &str, path: &str) -> Result<(ActorTable, DehackedReport), DehackedError> {
        let mut d = Dehacked::new(self.clone());
        d.load(text.as_bytes(), path)?;
        Ok(d.finish())
    }

    /// This table with `wad`'s `DEHACKED` lumps applied (none: the table
    /// unchanged and an empty report).
    pub fn with_wad_dehacked(&self, wad: &Wad) -> Result<(ActorTable, DehackedReport), DehackedError> {
        let mut d = Dehacked::new(self.clone());
        d.load_wad(wad)?;
        Ok(d.finish())
    }
}
