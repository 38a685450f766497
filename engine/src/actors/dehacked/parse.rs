//! A patch's lines into a [`Patch`]. The signature line, then `key = value`
//! lines before the first section (the header's "Doom version" and "Patch
//! format"), then sections: a header line (`Thing 5 (Imp)`, `[STRINGS]`)
//! and its lines, up to the next header. `#` starts a comment line; blank
//! lines are skipped.
//!
//! Errors (a [`DehackedError`] with the file and line): a number that is
//! not one, a thing, frame, sound, sprite or weapon number out of Doom's
//! range, a section header that names no section, a `Text` block the file
//! ends inside, an `Include`. Warnings (as Chocolate Doom prints them): a
//! field a section does not have, a line that is not `key = value`, a
//! section Sightline reads but does not use.

use super::doom::{self, NUM_SOUNDS, NUM_SPRITES, NUM_STATES, NUM_THINGS, NUM_WEAPONS};
use super::model::*;
use super::read::{decode, Reader};
use super::{DehackedError, Warning};

pub fn parse(bytes: &[u8], path: &str) -> Result<Patch, DehackedError> {
    let mut parser = Parser {
        reader: Reader::new(bytes),
        patch: Patch { path: path.to_string(), ..Patch::default() },
        open: Open::Header,
    };
    parser.run()?;
    Ok(parser.patch)
}

/// What the lines being read belong to.
#[derive(Clone, Copy, PartialEq)]
enum Open {
    /// Before the first section.
    Header,
    /// The last section of `patch.sections`.
    Section,
    /// A section read past: a `Text` block's remainder, or a section
    /// Sightline does not use (its lines are skipped).
    Skipped,
}

struct Parser<'a> {
    reader: Reader<'a>,
    patch: Patch,
    open: Open,
}

/// A section header, before its lines are read.
enum Start {
    Section(SectionKind),
    /// `Text A B`: its characters follow.
    Text(usize, usize),
    /// A section Sightline skips, and why.
    Skip(String),
}

impl Parser<'_> {
    fn error(&self, line: usize, message: impl Into<String>) -> DehackedError {
        DehackedError::At { path: self.patch.path.clone(), line, message: message.into() }
    }

    fn warn(&mut self, line: usize, message: impl Into<String>) {
        let path = self.patch.path.clone();
        self.patch.warnings.push(Warning { path, line, message: message.into() });
    }

    fn run(&mut self) -> Result<(), DehackedError> {
        let mut first = true;
        loop {
            let extended = self.open == Open::Section
                && matches!(self.patch.sections.last(), Some(Section { kind: SectionKind::Strings { .. }, .. }));
            let Some((line, bytes)) = self.reader.next_line(extended) else { return Ok(()) };
            let text = decode(&bytes);
            let text = text.trim();
            if text.is_empty() || text.starts_with('#') {
                continue;
            }
            if std::mem::take(&mut first) {
                if let Some(rest) = text.strip_prefix("Patch File for DeHackEd") {
                    let version = rest.trim();
                    if version != "v2.3" && version != "v3.0" {
                        let m = format!("DeHackEd {version} patch: only v2.3 and v3.0 text patches can be read");
                        return Err(self.error(line, m));
                    }
                    self.patch.header.version = Some(version.to_string());
                    continue;
                }
                self.warn(line, "no \"Patch File for DeHackEd v3.0\" line: read as a BEX file");
            }
            match self.start(line, text)? {
                Some(Start::Section(kind)) => {
                    self.patch.sections.push(Section { line, kind });
                    self.open = Open::Section;
                }
                Some(Start::Text(from, to)) => {
                    let kind = self.text(line, from, to)?;
                    self.patch.sections.push(Section { line, kind });
                    self.open = Open::Skipped;
                }
                Some(Start::Skip(why)) => {
                    self.warn(line, why);
                    self.open = Open::Skipped;
                }
                None => self.body(line, text)?,
            }
        }
    }

    /// The section `text` opens, if it is a header.
    fn start(&self, line: usize, text: &str) -> Result<Option<Start>, DehackedError> {
        let head = text.split('(').next().unwrap_or("");
        if head.contains('=') {
            return Ok(None);
        }
        if text.starts_with('[') {
            let name = text.split(']').next().unwrap_or(text).trim_start_matches('[').trim().to_ascii_uppercase();
            let kind = match name.as_str() {
                "STRINGS" => SectionKind::Strings { entries: Vec::new() },
                "PARS" => SectionKind::Pars { entries: Vec::new() },
                "CODEPTR" => SectionKind::CodePointers { entries: Vec::new() },
                "SPRITES" => SectionKind::Renames { kind: RenameKind::Sprites, entries: Vec::new() },
                "SOUNDS" => SectionKind::Renames { kind: RenameKind::Sounds, entries: Vec::new() },
                "MUSIC" => SectionKind::Renames { kind: RenameKind::Music, entries: Vec::new() },
                "HELPER" => return Ok(Some(Start::Skip("[HELPER] (MBF's helper dogs) is not supported".into()))),
                _ => return Err(self.error(line, format!("unknown section `{text}`"))),
            };
            return Ok(Some(Start::Section(kind)));
        }
        let words: Vec<&str> = head.split_whitespace().collect();
        let keyword = words.first().unwrap_or(&"").to_ascii_lowercase();
        // The header's `k`-th number, below `limit`.
        let nth = |what: &str, k: usize, limit: usize| -> Result<usize, DehackedError> {
            let word = words.get(k).unwrap_or(&"");
            let n = int(word).map_err(|m| self.error(line, format!("{what}: {m}")))?;
            usize::try_from(n)
                .ok()
                .filter(|&n| n < limit)
                .ok_or_else(|| self.error(line, format!("{what} {n} is out of range (0 to {})", limit - 1)))
        };
        let number = |what: &str, limit: usize| nth(what, 1, limit);
        let kind = match keyword.as_str() {
            "thing" => {
                let n = number("Thing", usize::MAX)?;
                if !(1..=NUM_THINGS).contains(&n) {
                    return Err(self.error(line, format!("Thing {n} is out of range (1 to {NUM_THINGS})")));
                }
                let name = text.split_once('(').map(|(_, r)| r.trim_end_matches(')').trim().to_string());
                SectionKind::Thing { number: n, name, fields: Vec::new() }
            }
            "frame" => SectionKind::Frame { number: number("Frame", NUM_STATES)?, fields: Vec::new() },
            "pointer" => {
                // `Pointer 12 (Frame 34)`: the frame is the one in brackets.
                let inner = text.split_once('(').map(|(_, r)| r.trim_end_matches(')')).unwrap_or("");
                let mut inner_words = inner.split_whitespace();
                if !inner_words.next().is_some_and(|w| w.eq_ignore_ascii_case("frame")) {
                    return Err(self.error(line, format!("`{text}`: a pointer is `Pointer N (Frame M)`")));
                }
                let word = inner_words.next().unwrap_or("");
                let n = int(word).map_err(|m| self.error(line, format!("Pointer's frame: {m}")))?;
                let frame = usize::try_from(n).ok().filter(|&n| n < NUM_STATES).ok_or_else(|| {
                    self.error(line, format!("Pointer's frame {n} is out of range (0 to {})", NUM_STATES - 1))
                })?;
                SectionKind::Pointer { frame, code_frames: Vec::new() }
            }
            "sound" => SectionKind::Sound { number: number("Sound", NUM_SOUNDS)?, fields: Vec::new() },
            "ammo" => SectionKind::Ammo { number: number("Ammo", doom::AMMO.len())?, fields: Vec::new() },
            "weapon" => SectionKind::Weapon { number: number("Weapon", NUM_WEAPONS)?, fields: Vec::new() },
            "cheat" => {
                number("Cheat", usize::MAX)?;
                SectionKind::Cheat { cheats: Vec::new() }
            }
            "misc" => {
                number("Misc", usize::MAX)?;
                SectionKind::Misc { fields: Vec::new() }
            }
            "sprite" => {
                number("Sprite", NUM_SPRITES)?;
                let why = "Sprite sections (offsets into doom.exe) are not supported: rename sprites with Text or \
                           [SPRITES]";
                return Ok(Some(Start::Skip(why.into())));
            }
            "text" => {
                let from = nth("Text", 1, usize::MAX)?;
                let to = nth("Text", 2, usize::MAX)?;
                return Ok(Some(Start::Text(from, to)));
            }
            "include" => {
                let m = "Include is not supported: give the included patch as its own --deh file";
                return Err(self.error(line, m));
            }
            _ => return Ok(None),
        };
        Ok(Some(Start::Section(kind)))
    }

    /// A `Text` block's characters, read raw after its header line.
    fn text(&mut self, line: usize, from: usize, to: usize) -> Result<SectionKind, DehackedError> {
        let raw = self.reader.raw(from.saturating_add(to)).map_err(|got| {
            let all = from.saturating_add(to);
            self.error(line, format!("Text {from} {to}: the file ends after {got} of its {all} characters"))
        })?;
        let (old, new) = raw.split_at(from);
        // doom.exe's strings sit on four-byte boundaries: a replacement may
        // fill the padding after the old string, and no more.
        let room = from.saturating_add(1).div_ceil(4).saturating_mul(4) - 1;
        if to > room {
            let m = format!("Text {from} {to}: longer than doom.exe had room for ({room}); Chocolate Doom refuses it");
            self.warn(line, m);
        }
        Ok(SectionKind::Text { from: decode(old), to: decode(new) })
    }

    /// A line that is not a header.
    fn body(&mut self, line: usize, text: &str) -> Result<(), DehackedError> {
        match self.open {
            Open::Section => {}
            Open::Skipped => return Ok(()),
            Open::Header => {
                if let Some((key, value)) = text.split_once('=') {
                    let (key, value) = (key.trim(), value.trim());
                    let n = Some(value_int(value).map_err(|m| self.error(line, format!("{key}: {m}")))?);
                    if key.eq_ignore_ascii_case("Doom version") {
                        self.patch.header.doom_version = n;
                    } else if key.eq_ignore_ascii_case("Patch format") {
                        self.patch.header.patch_format = n;
                        if n != Some(6) {
                            self.warn(line, format!("Patch format {value}: only format 6 is known"));
                        }
                    } else {
                        self.warn(line, format!("`{key}` before any section (ignored)"));
                    }
                    return Ok(());
                }
                return self.stray(line, text);
            }
        }
        let Some(section) = self.patch.sections.last_mut() else { return Ok(()) };
        if let SectionKind::Pars { entries } = &mut section.kind {
            let par = par(text).map_err(|m| DehackedError::At { path: self.patch.path.clone(), line, message: m })?;
            match par {
                Some((episode, map, seconds)) => entries.push(Par { line, episode, map, seconds }),
                None => return self.stray(line, text),
            }
            return Ok(());
        }
        let Some((key, value)) = text.split_once('=') else { return self.stray(line, text) };
        let (key, value) = (key.trim(), value.trim());
        let path = self.patch.path.clone();
        let fail = |m: String| DehackedError::At { path: path.clone(), line, message: format!("{key}: {m}") };
        let mut unknown: Option<String> = None;
        match &mut section.kind {
            SectionKind::Thing { number, fields, .. } => match ThingField::find(key) {
                Some(f) => fields.push(Field { line, key: f, value: thing_value(f, value).map_err(fail)? }),
                None => unknown = Some(format!("Thing {number}")),
            },
            SectionKind::Frame { number, fields } => match FrameField::find(key) {
                Some(f) => {
                    let value = match f {
                        FrameField::Sprite => ranged(value, NUM_SPRITES, "sprite"),
                        FrameField::Next | FrameField::Codep => ranged(value, NUM_STATES, "frame"),
                        _ => value_int(value),
                    };
                    fields.push(Field { line, key: f, value: value.map_err(fail)? })
                }
                None => unknown = Some(format!("Frame {number}")),
            },
            SectionKind::Pointer { frame, code_frames } => {
                if key.eq_ignore_ascii_case("Codep Frame") {
                    code_frames.push(Field { line, key: (), value: ranged(value, NUM_STATES, "frame").map_err(fail)? });
                } else {
                    unknown = Some(format!("Pointer (Frame {frame})"));
                }
            }
            SectionKind::Sound { number, fields } => match SoundField::find(key) {
                Some(f) => fields.push(Field { line, key: f, value: value_int(value).map_err(fail)? }),
                None => unknown = Some(format!("Sound {number}")),
            },
            SectionKind::Ammo { number, fields } => match AmmoField::find(key) {
                Some(f) => fields.push(Field { line, key: f, value: value_int(value).map_err(fail)? }),
                None => unknown = Some(format!("Ammo {number}")),
            },
            SectionKind::Weapon { number, fields } => match WeaponField::find(key) {
                Some(f) => {
                    let value = match f {
                        WeaponField::Ammo => value_int(value),
                        _ => ranged(value, NUM_STATES, "frame"),
                    };
                    fields.push(Field { line, key: f, value: value.map_err(fail)? })
                }
                None => unknown = Some(format!("Weapon {number}")),
            },
            SectionKind::Misc { fields } => match MiscField::find(key) {
                Some(f) => fields.push(Field { line, key: f, value: value_int(value).map_err(fail)? }),
                None => unknown = Some("Misc".into()),
            },
            SectionKind::Cheat { cheats } => match CHEATS.iter().find(|c| c.eq_ignore_ascii_case(key)) {
                // doom.exe's cheat sequences end at a 0xff byte.
                Some(name) => cheats.push((line, name.to_string(), value.split('\u{ff}').next().unwrap_or("").into())),
                None => unknown = Some("Cheat".into()),
            },
            SectionKind::Strings { entries } => entries.push((line, key.to_string(), value.to_string())),
            SectionKind::CodePointers { entries } => {
                let mut words = key.split_whitespace();
                if !words.next().is_some_and(|w| w.eq_ignore_ascii_case("frame")) {
                    return Err(fail("a code pointer is `FRAME N = Action`".into()));
                }
                let frame = ranged(words.next().unwrap_or(""), NUM_STATES, "frame").map_err(fail)? as usize;
                let action = Some(value.to_string()).filter(|a| !a.eq_ignore_ascii_case("NULL"));
                entries.push((line, frame, action));
            }
            SectionKind::Renames { entries, .. } => entries.push((line, key.to_string(), value.to_string())),
            SectionKind::Text { .. } | SectionKind::Pars { .. } => {}
        }
        if let Some(section) = unknown {
            self.warn(line, format!("{section}: no field named `{key}` (ignored)"));
        }
        Ok(())
    }

    /// A line that is neither a header nor a line of the open section:
    /// a header of a section no format has is an error, anything else is
    /// skipped with a warning (Chocolate's "Failed to parse assignment").
    fn stray(&mut self, line: usize, text: &str) -> Result<(), DehackedError> {
        let mut words = text.split_whitespace();
        let looks_like_header = words.next().is_some_and(|w| w.chars().all(|c| c.is_ascii_alphabetic()))
            && words.next().is_some_and(|w| int(w).is_ok());
        if looks_like_header {
            return Err(self.error(line, format!("unknown section `{text}`")));
        }
        self.warn(line, format!("`{text}` is not `key = value` (ignored)"));
        Ok(())
    }
}

/// Checks the numbers of a patch built by hand (the parser already has):
/// every one that indexes Doom's arrays must be within them, so that
/// applying cannot index past them.
pub fn check(patch: &Patch) -> Result<(), DehackedError> {
    let within = |line: usize, what: &str, n: i64, range: std::ops::Range<usize>| {
        if (range.start as i64..range.end as i64).contains(&n) {
            return Ok(());
        }
        let message = format!("{what} {n} is out of range ({} to {})", range.start, range.end - 1);
        Err(DehackedError::At { path: patch.path.clone(), line, message })
    };
    let frame = |line, n| within(line, "frame", n, 0..NUM_STATES);
    for section in &patch.sections {
        let line = section.line;
        match &section.kind {
            SectionKind::Thing { number, fields, .. } => {
                within(line, "Thing", *number as i64, 1..NUM_THINGS + 1)?;
                for f in fields {
                    use ThingField::*;
                    match f.key {
                        SpawnFrame | SeeFrame | PainFrame | MeleeFrame | MissileFrame | DeathFrame | XDeathFrame
                        | RaiseFrame => frame(f.line, f.value)?,
                        SeeSound | AttackSound | PainSound | DeathSound | ActiveSound => {
                            within(f.line, "sound", f.value, 0..NUM_SOUNDS)?
                        }
                        _ => {}
                    }
                }
            }
            SectionKind::Frame { number, fields } => {
                frame(line, *number as i64)?;
                for f in fields {
                    match f.key {
                        FrameField::Sprite => within(f.line, "sprite", f.value, 0..NUM_SPRITES)?,
                        FrameField::Next | FrameField::Codep => frame(f.line, f.value)?,
                        _ => {}
                    }
                }
            }
            SectionKind::Pointer { frame: n, code_frames } => {
                frame(line, *n as i64)?;
                code_frames.iter().try_for_each(|f| frame(f.line, f.value))?;
            }
            SectionKind::Sound { number, .. } => within(line, "Sound", *number as i64, 0..NUM_SOUNDS)?,
            SectionKind::Ammo { number, .. } => within(line, "Ammo", *number as i64, 0..doom::AMMO.len())?,
            SectionKind::Weapon { number, fields } => {
                within(line, "Weapon", *number as i64, 0..NUM_WEAPONS)?;
                fields.iter().filter(|f| f.key != WeaponField::Ammo).try_for_each(|f| frame(f.line, f.value))?;
            }
            SectionKind::CodePointers { entries } => entries.iter().try_for_each(|(l, n, _)| frame(*l, *n as i64))?,
            _ => {}
        }
    }
    Ok(())
}

/// A number as doom.exe's `%i` reads one: decimal, or hex after `0x`.
/// (Not octal after a leading 0: no patch means that.)
pub fn int(text: &str) -> Result<i64, String> {
    let t = text.trim();
    let (negative, digits) = match t.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, t.strip_prefix('+').unwrap_or(t)),
    };
    let parsed = match digits.strip_prefix("0x").or_else(|| digits.strip_prefix("0X")) {
        Some(hex) => i64::from_str_radix(hex, 16),
        None if digits.bytes().all(|b| b.is_ascii_digit()) => digits.parse::<i64>(),
        None => return Err(format!("`{t}` is not a number")),
    };
    match parsed.map(|n| if negative { -n } else { n }) {
        Ok(n) if (i64::from(i32::MIN)..=i64::from(u32::MAX)).contains(&n) => Ok(n),
        _ => Err(format!("`{t}` is not a number doom.exe can hold")),
    }
}

/// A field's value: a number, and perhaps a `#` comment after it.
fn value_int(value: &str) -> Result<i64, String> {
    int(value.split('#').next().unwrap_or(""))
}

/// A number that indexes one of Doom's arrays.
fn ranged(value: &str, limit: usize, what: &str) -> Result<i64, String> {
    let n = value_int(value)?;
    if !(0..limit as i64).contains(&n) {
        return Err(format!("{what} {n} is out of range (0 to {})", limit - 1));
    }
    Ok(n)
}

fn thing_value(field: ThingField, value: &str) -> Result<i64, String> {
    use ThingField::*;
    match field {
        SpawnFrame | SeeFrame | PainFrame | MeleeFrame | MissileFrame | DeathFrame | XDeathFrame | RaiseFrame => {
            ranged(value, NUM_STATES, "frame")
        }
        SeeSound | AttackSound | PainSound | DeathSound | ActiveSound => ranged(value, NUM_SOUNDS, "sound"),
        Bits => bits(value),
        _ => value_int(value),
    }
}

/// `Bits = 4194310`, or BEX's names: `SOLID+SHOOTABLE+COUNTKILL` (joined by
/// `+`, `|`, `,` or blanks).
fn bits(value: &str) -> Result<i64, String> {
    let value = value.split('#').next().unwrap_or("").trim();
    if let Ok(n) = int(value) {
        return Ok(i64::from(n as u32));
    }
    let mut bits = 0u32;
    for name in value.split(|c: char| c == '+' || c == '|' || c == ',' || c.is_whitespace()).filter(|n| !n.is_empty()) {
        bits |= doom::flag_bit(name).ok_or_else(|| format!("`{name}` is neither a number nor a flag name"))?;
    }
    Ok(i64::from(bits))
}

/// `par EPISODE MAP SECONDS` or `par MAP SECONDS` (Doom II), perhaps with
/// a `#` comment; `None` if the line is not a `par` line.
fn par(text: &str) -> Result<Option<(Option<u8>, u8, u32)>, String> {
    let code = text.split('#').next().unwrap_or("");
    let mut words = code.split_whitespace();
    if !words.next().is_some_and(|w| w.eq_ignore_ascii_case("par")) {
        return Ok(None);
    }
    let numbers: Vec<i64> = words.map(int).collect::<Result<_, _>>()?;
    let small = |n: i64, what: &str| u8::try_from(n).map_err(|_| format!("par: {what} {n} is out of range"));
    let seconds = |n: i64| u32::try_from(n).map_err(|_| format!("par: {n} seconds is out of range"));
    match numbers[..] {
        [e, m, s] => Ok(Some((Some(small(e, "episode")?), small(m, "map")?, seconds(s)?))),
        [m, s] => Ok(Some((None, small(m, "map")?, seconds(s)?))),
        _ => Err(format!("`{text}`: a par is `par EPISODE MAP SECONDS` or `par MAP SECONDS`")),
    }
}
