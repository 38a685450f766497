//! A [`Patch`] onto a table, section by section in file order, as
//! Chocolate Doom writes each value into doom.exe's arrays: a thing's
//! fields into its actor (16.16 sizes to map units, `MF_` bits to flags,
//! Doom's sound numbers to the sound list, its eight frame fields to the
//! labels `Spawn` ... `Raise`), a frame's into every state that is that
//! frame, a weapon's into its weapon actor, and what the table cannot hold
//! into the report's [`Strings`](super::Strings), [`Pars`](super::Pars)
//! and [`Settings`](super::Settings). Then it checks what the loader
//! checks of states (no loop of 0-tic states) and re-indexes editor
//! numbers.

mod frames;
mod items;
mod things;

use std::collections::HashMap;

use super::doom::{self, doom_info, FRACUNIT, FULL_BRIGHT};
use super::mapping::DoomMap;
use super::model::*;
use super::{DehackedError, DehackedReport};
use crate::actors::actions::{self, ArgSpec};
use crate::actors::{ActionCall, ActorTable, Arg, Give, State, StateId};

/// Doom's frame letters run from A to `]` (29 of them, as in the state
/// text); a sprite subnumber beyond names no lump.
const LAST_FRAME: i64 = 28;

pub(super) struct Run<'a> {
    pub table: &'a mut ActorTable,
    pub map: &'a mut DoomMap,
    pub report: &'a mut DehackedReport,
    pub code_pointers: &'a [Option<ActionCall>],
    pub clip_counts: &'a [(usize, usize, usize, i32)],
    pub messages: &'a [(usize, String)],
    pub path: &'a str,
}

/// Each Doom frame's action in the unpatched table (or, for a frame the
/// table lacks, Doom's action with its default arguments).
pub(super) fn code_pointers(table: &ActorTable, map: &DoomMap) -> Vec<Option<ActionCall>> {
    let info = doom_info();
    (0..info.states.len())
        .map(|f| match map.state(f) {
            Some(id) => table.state(id).action.clone(),
            None => info.states[f].action.as_deref().and_then(|a| default_call(table, a).ok()),
        })
        .collect()
}

/// Every pickup's ammunition as a count of Doom's clips (a clip is 1, a
/// box 5, a weapon 2), for "Per ammo". An amount that is not a whole
/// number of clips (a modder's) is left alone.
pub(super) fn clip_counts(table: &ActorTable) -> Vec<(usize, usize, usize, i32)> {
    let mut counts = Vec::new();
    for (a, actor) in table.actors.iter().enumerate() {
        for (g, give) in actor.pickup.iter().flat_map(|p| p.give.iter().enumerate()) {
            if let Give::Ammo(kind, amount) = give {
                let n = doom::AMMO.iter().position(|k| k == kind).unwrap_or(0);
                if amount % doom::CLIP_AMMO[n] == 0 {
                    counts.push((a, g, n, amount / doom::CLIP_AMMO[n]));
                }
            }
        }
    }
    counts
}

/// An action called with its default arguments, as a patch's code
/// pointer gives it (Doom's actions take none; the table's defaults are
/// Doom's values).
pub(super) fn default_call(table: &ActorTable, name: &str) -> Result<ActionCall, String> {
    let id = actions::find(name)
        .or_else(|| actions::find(&format!("A_{name}")))
        .ok_or_else(|| format!("no action {name} in Sightline"))?;
    let spec = actions::spec(id);
    let arg = |a: &ArgSpec| -> Result<Arg, String> {
        match (a.kind, a.default) {
            (actions::ArgKind::Int, Some(actions::Default::Int(v))) => Ok(Arg::Int(v as i32)),
            (actions::ArgKind::Number, Some(actions::Default::Int(v))) => Ok(Arg::Number(v as f64)),
            (actions::ArgKind::Actor, Some(actions::Default::Name(n))) => {
                table.index(n).map(Arg::Actor).ok_or(format!("{}'s {}: no actor {n}", spec.name, a.name))
            }
            (actions::ArgKind::Sound, Some(actions::Default::Name(n))) => {
                table.sounds.iter().position(|s| s == n).map(Arg::Sound).ok_or(format!("no sound {n}"))
            }
            _ => Err(format!("{} needs its arguments ({})", spec.name, actions::signature(spec))),
        }
    };
    let args = spec.args.iter().map(arg).collect::<Result<_, _>>()?;
    Ok(ActionCall { action: id, args })
}

/// Sightline's value for a 16.16 size, checked as the loader checks one.
fn size(value: i64, what: &str) -> Result<f64, String> {
    let units = value as f64 / FRACUNIT;
    if !(0.0..=4096.0).contains(&units) {
        return Err(format!("{what} {value} ({units} units) is not within 0 to 4096 units"));
    }
    Ok(units)
}

fn int32(value: i64, what: &str) -> Result<i32, String> {
    i32::try_from(value).map_err(|_| format!("{what} {value} does not fit doom.exe's int"))
}

impl Run<'_> {
    fn error(&self, line: usize, message: impl Into<String>) -> DehackedError {
        DehackedError::At { path: self.path.to_string(), line, message: message.into() }
    }

    fn warn(&mut self, line: usize, message: impl Into<String>) {
        let w = super::Warning { path: self.path.to_string(), line, message: message.into() };
        self.report.warnings.push(w);
    }

    pub fn patch(&mut self, patch: &Patch) -> Result<(), DehackedError> {
        let mut touched: HashMap<StateId, usize> = HashMap::new();
        for section in &patch.sections {
            let line = section.line;
            let applied = &mut self.report.applied;
            match &section.kind {
                SectionKind::Thing { number, fields, .. } => {
                    applied.things += 1;
                    self.thing(line, *number, fields)?;
                }
                SectionKind::Frame { number, fields } => {
                    applied.frames += 1;
                    for id in self.frame(line, *number, fields)? {
                        touched.insert(id, line);
                    }
                }
                SectionKind::Pointer { frame, code_frames } => {
                    applied.pointers += 1;
                    for f in code_frames {
                        let call = self.code_pointers[f.value as usize].clone();
                        self.set_action(*frame, call);
                    }
                }
                SectionKind::Sound { number, .. } => {
                    let m = format!("Sound {number}: not applied (priorities and links are the sound module's)");
                    self.warn(line, m);
                }
                SectionKind::Ammo { number, fields } => {
                    applied.ammo += 1;
                    self.ammo(*number, fields);
                }
                SectionKind::Weapon { number, fields } => {
                    applied.weapons += 1;
                    self.weapon(*number, fields)?;
                }
                SectionKind::Cheat { cheats } => {
                    applied.cheats += 1;
                    for (_, name, keys) in cheats {
                        self.report.settings.cheats.insert(name.clone(), keys.clone());
                    }
                }
                SectionKind::Misc { fields } => {
                    applied.misc += 1;
                    self.misc(fields)?;
                }
                SectionKind::Text { from, to } => {
                    applied.texts += 1;
                    self.report.strings.replace_text(from, to);
                    // doom.exe looks its sprite names up in the same list
                    // (R_InitSprites calls DEH_String on each).
                    if from.len() == 4 && to.len() == 4 {
                        self.rename_sprite(line, from, to);
                    }
                }
                SectionKind::Strings { entries } => {
                    applied.strings += 1;
                    let unknown: Vec<&str> = entries
                        .iter()
                        .filter(|(_, name, text)| !self.report.strings.set(name, text))
                        .map(|(_, name, _)| name.as_str())
                        .collect();
                    if !unknown.is_empty() {
                        let m = format!(
                            "[STRINGS]: {} names doom.exe has no string for, kept for ports that use them: {}",
                            unknown.len(),
                            unknown.join(", ")
                        );
                        self.warn(line, m);
                    }
                }
                SectionKind::Pars { entries } => {
                    applied.pars += 1;
                    for p in entries {
                        self.report.pars.set(p.episode, p.map, p.seconds);
                    }
                }
                SectionKind::CodePointers { entries } => {
                    applied.code_pointers += 1;
                    for (l, frame, name) in entries {
                        match name.as_deref().map(|n| default_call(self.table, n)).transpose() {
                            Ok(call) => self.set_action(*frame, call),
                            Err(m) => self.warn(*l, format!("FRAME {frame}: {m} (it keeps its action)")),
                        }
                    }
                }
                SectionKind::Renames { kind, entries } => {
                    for (l, from, to) in entries {
                        match kind {
                            RenameKind::Sprites => self.rename_sprite(*l, from, to),
                            RenameKind::Sounds => self.report.strings.rename_sound(from, to),
                            RenameKind::Music => self.report.strings.rename_music(from, to),
                        }
                    }
                }
            }
        }
        // Pickup messages are doom.exe's strings (GOTARMOR, ...): shown as
        // the patches left them.
        for (a, original) in self.messages {
            if let Some(p) = self.table.actors[*a].pickup.as_mut() {
                p.message = self.report.strings.text(original).to_string();
            }
        }
        self.check_tics(&touched)?;
        self.reindex();
        Ok(())
    }

    /// The state a label or `next` naming `frame` points at, adding the
    /// frame (and the frames its `next` chain leads to) as Doom has them if
    /// the table has no state for it. `None` for S_NULL.
    fn state(&mut self, frame: usize) -> Option<StateId> {
        if frame == 0 {
            return None;
        }
        if let Some(id) = self.map.state(frame) {
            return Some(id);
        }
        let info = doom_info();
        let mut added = Vec::new();
        let mut at = frame;
        while at != 0 && self.map.frames[at].is_empty() {
            let id = StateId(self.table.states.len() as u32);
            let placeholder =
                State { sprite: 0, frame: 0, tics: -1, bright: false, fast: false, action: None, next: None };
            self.table.states.push(placeholder);
            self.map.frames[at].push(id);
            self.map.added.push(at);
            added.push((at, id));
            at = info.states[at].next;
        }
        for (f, id) in added {
            let d = &info.states[f];
            self.map.home.push(None);
            let sprite = self.sprite_index(d.sprite);
            let action = d.action.as_deref().and_then(|a| default_call(self.table, a).ok());
            self.table.states[id.0 as usize] = State {
                sprite,
                frame: (d.frame & !FULL_BRIGHT) as u8,
                tics: d.tics,
                bright: d.frame & FULL_BRIGHT != 0,
                fast: false,
                action,
                next: self.map.state(d.next),
            };
        }
        self.map.state(frame)
    }

    /// The table's index of Doom's sprite `n` (added to the list if a
    /// modder's table lacks it).
    fn sprite_index(&mut self, n: usize) -> u16 {
        let name = &doom_info().sprites[n];
        match self.table.sprites.iter().position(|s| s == name) {
            Some(i) => i as u16,
            None => {
                self.table.sprites.push(name.clone());
                (self.table.sprites.len() - 1) as u16
            }
        }
    }

    fn rename_sprite(&mut self, line: usize, from: &str, to: &str) {
        let Some(i) = self.table.sprites.iter().position(|s| s.eq_ignore_ascii_case(from)) else {
            if !from.contains(char::is_whitespace) {
                self.warn(line, format!("no sprite named {from} to rename"));
            }
            return;
        };
        if to.len() != 4 || !to.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
            self.warn(line, format!("sprite {from} renamed to {to:?}: a sprite name is four letters or digits"));
            return;
        }
        self.table.sprites[i] = to.to_ascii_uppercase();
    }

    /// Points each copy at `frame`'s copy with the same home.
    fn set_next(&mut self, copies: &[StateId], frame: usize) {
        self.state(frame);
        for &id in copies {
            let next = self.map.state_near(frame, self.map.home_of(id));
            self.table.states[id.0 as usize].next = next;
        }
    }

    fn set_action(&mut self, frame: usize, call: Option<ActionCall>) {
        if frame == 0 {
            return;
        }
        self.state(frame);
        for id in self.map.frames[frame].clone() {
            self.table.states[id.0 as usize].action = call.clone();
        }
    }

    /// Sets (or, for frame 0, removes) an actor's label.
    fn set_label(&mut self, actor: usize, label: &str, frame: usize) {
        self.state(frame);
        let target = self.map.state_near(frame, Some(actor));
        let labels = &mut self.table.actors[actor].labels;
        let slot = labels.iter().position(|(l, _)| l.eq_ignore_ascii_case(label));
        match (slot, target) {
            (Some(i), Some(id)) => labels[i].1 = id,
            (None, Some(id)) => labels.push((label.to_string(), id)),
            (Some(i), None) => {
                labels.remove(i);
            }
            (None, None) => {}
        }
    }

    /// The loader's rule, kept after patching: a loop of 0-tic states would
    /// spin the simulation for ever within one tick (doom.exe hangs).
    fn check_tics(&self, touched: &HashMap<StateId, usize>) -> Result<(), DehackedError> {
        let states = &self.table.states;
        let mut clear = vec![false; states.len()];
        for start in 0..states.len() {
            let mut seen: Vec<usize> = Vec::new();
            let mut at = Some(start);
            while let Some(i) = at.filter(|&i| !clear[i] && states[i].tics == 0) {
                if seen.contains(&i) {
                    let frames: Vec<String> = seen
                        .iter()
                        .map(|&s| {
                            self.map.frame_of(StateId(s as u32)).map_or(format!("state {s}"), |f| format!("frame {f}"))
                        })
                        .collect();
                    let m = format!(
                        "states of 0 tics lead back to themselves ({}): the game would hang",
                        frames.join(", ")
                    );
                    let line = seen.iter().find_map(|&s| touched.get(&StateId(s as u32)).copied());
                    return Err(match line {
                        Some(line) => self.error(line, m),
                        None => DehackedError::File { path: self.path.to_string(), message: m },
                    });
                }
                seen.push(i);
                at = states[i].next.map(|n| n.0 as usize);
            }
            seen.iter().for_each(|&i| clear[i] = true);
            clear[start] = true;
        }
        Ok(())
    }

    /// Editor numbers to actors again, after "ID #" changes: the loader's
    /// rule (a later actor takes a number over), except that between two of
    /// Doom's things the first in mobjinfo keeps it, as P_SpawnMapThing's
    /// search finds it first.
    fn reindex(&mut self) {
        let mut rank: HashMap<usize, usize> = HashMap::new();
        for (k, a) in self.map.things.iter().enumerate() {
            if let Some(a) = a {
                rank.entry(*a).or_insert(k);
            }
        }
        let mut by_number: HashMap<u16, usize> = HashMap::new();
        for (i, def) in self.table.actors.iter().enumerate() {
            let Some(n) = def.doomednum else { continue };
            let keep = by_number
                .get(&n)
                .is_some_and(|held| matches!((rank.get(held), rank.get(&i)), (Some(h), Some(me)) if h < me));
            if !keep {
                by_number.insert(n, i);
            }
        }
        self.table.by_number = by_number;
    }
}
