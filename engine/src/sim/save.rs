//! Saved games for the simulation with Doom's arithmetic: a [`Sim`] in one
//! file, loaded into a game that goes on exactly as the original would
//! have, bit for bit and tic for tic (`save_tests.rs` plays Freedoom's
//! demos across a save to prove it).
//!
//! A playthrough's save (`play/save.rs`, what `play --load` reads) holds
//! these bytes as its game's state when the level is played on the
//! simulation; they are a file of their own too (the tests use it), in the
//! same envelope as the playthrough's with a magic of their own, so either
//! loader refuses the other's bytes by their header rather than by a
//! decoding error:
//!
//! | Bytes | Content |
//! | --- | --- |
//! | 0-14 | magic `SIGHTLINE-SIMS\n` (15 bytes) |
//! | 15 | format version, [`VERSION`] |
//! | 16-19 | CRC-32 of every byte after the length (little-endian u32) |
//! | 20-27 | length of the rest in bytes (little-endian u64) |
//! | rest | [`SaveInfo`], then the game's state, each in CBOR |
//!
//! What is saved is what play changes: every body (removed ones too, since
//! a [`super::MobjId`] of a removed body still reads it), the thinkers with
//! their movers, the players, `P_Random`'s indices, the tic counters, the
//! blockmap links, `validcount` and its marks, `p_map.c`'s globals
//! ([`super::collision::MapCheck`]: Doom reads some of them a tic later),
//! the specials' and the boss brain's state, the respawn and body queues,
//! the tallies, and the level's moving parts: each sector's heights, flats,
//! light, special, tag, sound and mover links, each side's textures and
//! offsets, each line's flags, special and tag, and the texture names
//! (switches add names the map did not use). A RON map's generalized
//! specials are numbers in those same special fields; the table they name
//! is a static part of the level (`sim::generalized`).
//!
//! What is not saved: the actor table ([`Info`]), which the loader is given
//! and checks by [`info_fingerprint`]; the sounds and exits not yet taken
//! ([`Sim::events`], the outside world's to drain, not the game's state);
//! and the level's static parts (vertices, line geometry, segs, nodes,
//! blockmap, REJECT, things, each sector's lines and boxes). The loader is
//! given the map as loaded afresh and checks it by [`map_fingerprint`].
//! Saving the whole level would make a file that loads without the WAD, but
//! it would be five to ten times larger (Freedoom 2's MAP15 alone is 2.9 MB
//! of CBOR, lines and segs most of it; its whole save here is 330 KB), a
//! changed WAD would then load silently against the old geometry while the
//! renderer draws the new, and a hand-edited save could put a bad index
//! into the BSP or the blockmap, which would each need the WAD loader's own
//! checks again. The static parts come from `Level::load`, which checks
//! them; only the moving parts, whose indices are few, are checked here.
//!
//! Every index a loaded state holds (bodies, thinkers, sectors, lines,
//! subsectors, blockmap cells, states, kinds, texture names, players,
//! weapons) is checked against the game before a [`Sim`] is made, so a
//! file that decodes but does not fit (a bug, or a hand edit) is an error
//! naming the element, never a panic some tics later.
//!
//! A file is written to a temporary name beside the target and renamed
//! over it ([`crate::level::write_file_atomic`]), so a failed write never
//! leaves a half-written save or clobbers the one there.

use std::path::Path;
use std::sync::Arc;

use serde::{Deserialize, Serialize};

use super::collision::MapCheck;
use super::level::{Level, LevelError, Line, NameId, Sector, Side};
use super::monsters::BrainState;
use super::specials::SpecialState;
use super::{Info, Mobj, MobjId, Player, Rules, Sim, Thinker, ThinkerId, ThinkerKind, MAXPLAYERS, NUMWEAPONS};
use crate::actors::{ActorTable, StateId};
use crate::envelope::{self, encode, EnvelopeError};
use crate::fixed::{DoomRandom, Fixed};
use crate::play::syncdump::Fnv;
use crate::wad::level::WadThing;
use crate::wad::Wad;

/// A simulation's saved state (a playthrough's save is `SIGHTLINE-SAVE\n`).
pub const MAGIC: &[u8] = b"SIGHTLINE-SIMS\n";
/// Bumped whenever the saved state's meaning changes. 2: the movers
/// carry their parameters (a door's wait shut, a floor's change on
/// arrival, a ceiling's starting speed) and the level its generalized
/// specials, which the map's fingerprint covers. 3: the bodies' ZDoom
/// fields (thing ids and specials, script-set properties). 4: ViZDoom's
/// tallies of hits, damage and deaths. 5: sixteen player slots (the
/// players, each one's frags, the starts and the tallies hold sixteen).
pub const VERSION: u8 = 5;

#[derive(Debug, thiserror::Error)]
pub enum SaveError {
    #[error("{path}: cannot read: {error}")]
    Read { path: String, error: std::io::Error },
    #[error("{path}: cannot write: {error}")]
    Write { path: String, error: std::io::Error },
    #[error("{path}: not a saved state of the simulation with Doom's arithmetic (bad header)")]
    Magic { path: String },
    #[error("{path}: a saved game from an older format (version {found}); this build reads version {VERSION} and cannot load it")]
    OldVersion { path: String, found: u8 },
    #[error("{path}: a saved game from a newer build (format version {found}); this build reads version {VERSION}")]
    NewVersion { path: String, found: u8 },
    #[error("{path}: truncated: {what}")]
    Truncated { path: String, what: String },
    #[error("{path}: corrupt: {what}")]
    Corrupt { path: String, what: String },
    #[error("{path}: the actor table is not the one the game was saved with (fingerprint {found:08x}, the save's {saved:08x})")]
    InfoChanged { path: String, saved: u32, found: u32 },
    #[error(
        "{path}: the map {map} is not the one the game was saved on (fingerprint {found:08x}, the save's {saved:08x})"
    )]
    MapChanged { path: String, map: String, saved: u32, found: u32 },
    #[error("{path}: the saved game's map cannot be opened: {error}")]
    Open { path: String, error: Box<LevelError> },
    #[error("{path}: {element}: {what}")]
    Invalid { path: String, element: String, what: String },
}

/// What a save says about itself, readable without loading the game
/// ([`peek`], [`read_info`]): what the loader must open, and the rules the
/// actor table was built for (`-fast` changes it).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SaveInfo {
    /// The level's name (`MAP01`, `E1M1`, a RON map's name).
    pub map: String,
    pub rules: Rules,
    pub gametic: u32,
    pub leveltime: u32,
    pub info_fingerprint: u32,
    pub map_fingerprint: u32,
}

/// A sector's moving parts: floor and ceiling heights, floor and ceiling
/// flats, light, special, tag, `soundtraversed`, `soundtarget` and
/// `specialdata`. The level's parts are tuples because CBOR writes a
/// struct's field names into every element: named, Freedoom 2's MAP15 had
/// 500 KB of sides alone; as tuples its whole save is 330 KB.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
struct SectorState(Fixed, Fixed, NameId, NameId, i16, i16, i16, i32, Option<MobjId>, Option<ThinkerId>);

/// A side's moving parts (switches change textures, scrollers the offset):
/// texture and row offsets, upper, lower and middle textures.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
struct SideState(Fixed, Fixed, NameId, NameId, NameId);

/// A line's moving parts (a used once-only special is cleared): flags,
/// special and tag.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
struct LineState(u16, i16, i16);

/// The level's moving parts. The destructuring in `of` names every field of
/// each element, so a field added to a sector, side or line is a compile
/// error here until it is sorted into saved or static; a field added to
/// the level itself counts as static, so if play changed it the map's
/// fingerprint would refuse the save (loudly, in the round-trip tests).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct LevelState {
    sectors: Vec<SectorState>,
    sides: Vec<SideState>,
    lines: Vec<LineState>,
    names: Vec<String>,
}

impl LevelState {
    fn of(level: &Level) -> LevelState {
        let sector = |s: &Sector| {
            let Sector {
                floorheight,
                ceilingheight,
                floorpic,
                ceilingpic,
                lightlevel,
                special,
                tag,
                soundtraversed,
                soundtarget,
                specialdata,
                blockbox: _,
                soundorg: _,
                lines: _,
            } = *s;
            SectorState(
                floorheight,
                ceilingheight,
                floorpic,
                ceilingpic,
                lightlevel,
                special,
                tag,
                soundtraversed,
                soundtarget,
                specialdata,
            )
        };
        let side = |s: &Side| {
            let Side { textureoffset, rowoffset, toptexture, bottomtexture, midtexture, sector: _ } = *s;
            SideState(textureoffset, rowoffset, toptexture, bottomtexture, midtexture)
        };
        let line = |l: &Line| {
            let Line {
                flags,
                special,
                tag,
                v1: _,
                v2: _,
                dx: _,
                dy: _,
                sidenum: _,
                bbox: _,
                slopetype: _,
                frontsector: _,
                backsector: _,
            } = *l;
            LineState(flags, special, tag)
        };
        LevelState {
            sectors: level.sectors.iter().map(sector).collect(),
            sides: level.sides.iter().map(side).collect(),
            lines: level.lines.iter().map(line).collect(),
            names: level.names.clone(),
        }
    }

    /// Puts the moving parts into `level` (of the same lengths: checked).
    fn put(self, level: &mut Level) {
        for (s, saved) in level.sectors.iter_mut().zip(self.sectors) {
            let SectorState(floor, ceiling, floorpic, ceilingpic, light, special, tag, traversed, target, data) = saved;
            (s.floorheight, s.ceilingheight, s.floorpic, s.ceilingpic) = (floor, ceiling, floorpic, ceilingpic);
            (s.lightlevel, s.special, s.tag, s.soundtraversed) = (light, special, tag, traversed);
            (s.soundtarget, s.specialdata) = (target, data);
        }
        for (s, SideState(x, y, top, bottom, middle)) in level.sides.iter_mut().zip(self.sides) {
            (s.textureoffset, s.rowoffset, s.toptexture, s.bottomtexture, s.midtexture) = (x, y, top, bottom, middle);
        }
        for (l, LineState(flags, special, tag)) in level.lines.iter_mut().zip(self.lines) {
            (l.flags, l.special, l.tag) = (flags, special, tag);
        }
        level.names = self.names;
    }
}

/// The game's state beside the level's moving parts: every field of [`Sim`]
/// but the level, the actor table, the rules and tic counters (in the
/// [`SaveInfo`]) and the events.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct SimState {
    level: LevelState,
    mobjs: Vec<Mobj>,
    thinkers: Vec<Thinker>,
    players: [Option<Player>; MAXPLAYERS],
    console: usize,
    starts: [Option<WadThing>; MAXPLAYERS],
    deathmatch_starts: Vec<WadThing>,
    rng: DoomRandom,
    blocklinks: Vec<Vec<MobjId>>,
    validcount: i32,
    line_valid: Vec<i32>,
    tm: MapCheck,
    spec: SpecialState,
    brain: BrainState,
    item_respawn: Vec<(WadThing, u32)>,
    bodyque: Vec<MobjId>,
    total_kills: i32,
    total_items: i32,
    total_secrets: i32,
    exit: Option<bool>,
    zdoom: super::zdoom::Zdoom,
}

/// The save's description and state of `sim`.
fn split(sim: &Sim) -> (SaveInfo, SimState) {
    let header = SaveInfo {
        map: sim.level.name.clone(),
        rules: sim.rules,
        gametic: sim.gametic,
        leveltime: sim.leveltime,
        info_fingerprint: info_fingerprint(&sim.info),
        map_fingerprint: map_fingerprint(&sim.level),
    };
    let state = SimState {
        level: LevelState::of(&sim.level),
        mobjs: sim.mobjs.clone(),
        thinkers: sim.thinkers.clone(),
        players: sim.players.clone(),
        console: sim.console,
        starts: sim.starts.clone(),
        deathmatch_starts: sim.deathmatch_starts.clone(),
        rng: sim.rng,
        blocklinks: sim.blocklinks.clone(),
        validcount: sim.validcount,
        line_valid: sim.line_valid.clone(),
        tm: sim.tm.clone(),
        spec: sim.spec.clone(),
        brain: sim.brain.clone(),
        item_respawn: sim.item_respawn.clone(),
        bodyque: sim.bodyque.clone(),
        total_kills: sim.total_kills,
        total_items: sim.total_items,
        total_secrets: sim.total_secrets,
        exit: sim.exit,
        zdoom: sim.zdoom.clone(),
    };
    (header, state)
}

/// The game `state` holds on `level` (loaded afresh) with `info`. The
/// literal names every field of [`Sim`], so one added to it is a compile
/// error here until it is saved (in [`split`] too) or said not to be.
fn join(header: &SaveInfo, state: SimState, mut level: Level, info: Arc<Info>) -> Sim {
    state.level.put(&mut level);
    Sim {
        level,
        info,
        rules: header.rules,
        mobjs: state.mobjs,
        thinkers: state.thinkers,
        players: state.players,
        console: state.console,
        starts: state.starts,
        deathmatch_starts: state.deathmatch_starts,
        rng: state.rng,
        gametic: header.gametic,
        leveltime: header.leveltime,
        blocklinks: state.blocklinks,
        validcount: state.validcount,
        line_valid: state.line_valid,
        tm: state.tm,
        spec: state.spec,
        brain: state.brain,
        item_respawn: state.item_respawn,
        bodyque: state.bodyque,
        total_kills: state.total_kills,
        total_items: state.total_items,
        total_secrets: state.total_secrets,
        exit: state.exit,
        events: Vec::new(),
        textures_changed: 0,
        zdoom: state.zdoom,
    }
}

/// FNV-1a fed by `Debug` text or by a serializer's bytes, so a fingerprint
/// needs no copy of what it hashes.
struct FnvSink(Fnv);

impl std::io::Write for FnvSink {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        self.0.bytes(bytes);
        Ok(bytes.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The fingerprint of the actor table as the simulation reads it: every
/// kind, state (with `-fast`'s tics), weapon and Doom number, and the sound
/// names. `Debug` text, as `play/save.rs` fingerprints its table; its
/// derived form is stable for these plain structs.
pub fn info_fingerprint(info: &Info) -> u32 {
    use std::io::Write;
    let mut sink = FnvSink(Fnv::default());
    let _ = write!(sink, "{:?}{:?}{:?}{:?}{:?}", info.things, info.states, info.weapons, info.by_mt, info.table.sounds);
    sink.0 .0
}

/// The fingerprint of a level's static parts: the level with every moving
/// part blanked and no texture names (switches add some in play), so the
/// level being played and the same map loaded afresh agree.
pub fn map_fingerprint(level: &Level) -> u32 {
    let mut blank = level.clone();
    let lengths = (level.sectors.len(), level.sides.len(), level.lines.len());
    LevelState {
        sectors: vec![SectorState::default(); lengths.0],
        sides: vec![SideState::default(); lengths.1],
        lines: vec![LineState::default(); lengths.2],
        names: Vec::new(),
    }
    .put(&mut blank);
    let sink = postcard::to_io(&blank, FnvSink(Fnv::default())).unwrap_or(FnvSink(Fnv(0)));
    sink.0 .0
}

/// The save's bytes (see the module docs).
pub fn to_bytes(sim: &Sim) -> Vec<u8> {
    let (header, state) = split(sim);
    seal(&header, &state)
}

fn seal(header: &SaveInfo, state: &SimState) -> Vec<u8> {
    let mut body = encode(header);
    body.extend(encode(state));
    envelope::seal(MAGIC, VERSION, &body)
}

/// The envelope's header: magic, version, checksum, length.
#[cfg(test)]
const HEADER: usize = MAGIC.len() + 1 + 4 + 8;

/// `body` sealed as a save of this format.
#[cfg(test)]
fn in_envelope(body: &[u8]) -> Vec<u8> {
    envelope::seal(MAGIC, VERSION, body)
}

/// Saves `sim` to `path`, atomically (a failed write leaves whatever was there).
pub fn save(path: &Path, sim: &Sim) -> Result<(), SaveError> {
    let bytes = to_bytes(sim);
    crate::level::write_file_atomic(path, &bytes)
        .map_err(|error| SaveError::Write { path: path.display().to_string(), error })
}

/// What the save in `path` says about itself, its envelope checked.
pub fn peek(path: &Path) -> Result<SaveInfo, SaveError> {
    let label = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|error| SaveError::Read { path: label.clone(), error })?;
    read_info(&bytes, &label)
}

/// What the save `bytes` says about itself; `label` names the file in errors.
pub fn read_info(bytes: &[u8], label: &str) -> Result<SaveInfo, SaveError> {
    read(bytes, label).map(|(info, _)| info)
}

/// Loads the save in `path` on `wad`: the map it names loaded afresh, and
/// `table` built for its rules.
pub fn load(path: &Path, wad: &Wad, table: Arc<ActorTable>) -> Result<Sim, SaveError> {
    let label = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|error| SaveError::Read { path: label.clone(), error })?;
    from_bytes_on_wad(&bytes, &label, wad, table)
}

/// [`from_bytes`] on `wad`'s copy of the map the save names, with `table`
/// built as a new game builds it for the save's rules.
pub fn from_bytes_on_wad(bytes: &[u8], label: &str, wad: &Wad, table: Arc<ActorTable>) -> Result<Sim, SaveError> {
    let header = read_info(bytes, label)?;
    let level = Level::load(wad, &header.map)
        .map_err(|error| SaveError::Open { path: label.to_string(), error: Box::new(error) })?;
    let info = Arc::new(Info::new(table, header.rules.fast_monsters()));
    from_bytes(bytes, label, level, info)
}

/// The game saved in `bytes` on `level` (the map it was saved on, loaded
/// afresh: a WAD's, or a RON map's through `from_map`) with `info`;
/// `label` names the file in errors.
pub fn from_bytes(bytes: &[u8], label: &str, level: Level, info: Arc<Info>) -> Result<Sim, SaveError> {
    let path = || label.to_string();
    let (header, mut rest) = read(bytes, label)?;
    let found = info_fingerprint(&info);
    if found != header.info_fingerprint {
        return Err(SaveError::InfoChanged { path: path(), saved: header.info_fingerprint, found });
    }
    let found = map_fingerprint(&level);
    if found != header.map_fingerprint || level.name != header.map {
        return Err(SaveError::MapChanged { path: path(), map: header.map, saved: header.map_fingerprint, found });
    }
    let state: SimState = ciborium::from_reader(&mut rest)
        .map_err(|e| SaveError::Corrupt { path: path(), what: format!("the game's state does not decode: {e}") })?;
    if !rest.is_empty() {
        return Err(SaveError::Corrupt { path: path(), what: format!("{} bytes after the game's state", rest.len()) });
    }
    check(&state, &level, &info).map_err(|(element, what)| SaveError::Invalid { path: path(), element, what })?;
    Ok(join(&header, state, level, info))
}

/// The envelope checked, the description decoded, and the state's bytes.
fn read<'a>(bytes: &'a [u8], label: &str) -> Result<(SaveInfo, &'a [u8]), SaveError> {
    let path = || label.to_string();
    envelope::open_described(bytes, MAGIC, VERSION).map_err(|e| match e {
        EnvelopeError::Magic => SaveError::Magic { path: path() },
        EnvelopeError::Version(found) if found < VERSION => SaveError::OldVersion { path: path(), found },
        EnvelopeError::Version(found) => SaveError::NewVersion { path: path(), found },
        EnvelopeError::Truncated(what) => SaveError::Truncated { path: path(), what },
        EnvelopeError::Corrupt(what) => SaveError::Corrupt { path: path(), what },
    })
}

/// An element of the state and what is wrong with it.
type Bad = (String, String);

/// How many of each thing the loaded game has.
struct Counts {
    mobjs: usize,
    thinkers: usize,
    sectors: usize,
    lines: usize,
    names: usize,
    states: usize,
}

impl Counts {
    fn below(at: &str, field: &str, index: usize, count: usize, what: &str) -> Result<(), Bad> {
        let bad = || (at.to_string(), format!("{field} {index}, but there are {count} {what}"));
        (index < count).then_some(()).ok_or_else(bad)
    }

    fn mobj(&self, at: &str, field: &str, id: Option<MobjId>) -> Result<(), Bad> {
        id.map_or(Ok(()), |id| Counts::below(at, field, id.0 as usize, self.mobjs, "bodies"))
    }

    fn thinker(&self, at: &str, field: &str, id: Option<ThinkerId>) -> Result<(), Bad> {
        id.map_or(Ok(()), |id| Counts::below(at, field, id.0 as usize, self.thinkers, "thinkers"))
    }

    fn state(&self, at: &str, field: &str, id: Option<StateId>) -> Result<(), Bad> {
        id.map_or(Ok(()), |id| Counts::below(at, field, id.0 as usize, self.states, "states in the actor table"))
    }

    fn sector(&self, at: &str, sector: usize) -> Result<(), Bad> {
        Counts::below(at, "sector", sector, self.sectors, "sectors")
    }

    fn line(&self, at: &str, field: &str, line: usize) -> Result<(), Bad> {
        Counts::below(at, field, line, self.lines, "lines")
    }

    fn name(&self, at: &str, field: &str, id: NameId) -> Result<(), Bad> {
        Counts::below(at, field, usize::from(id.0), self.names, "texture names")
    }
}

/// Does `state` fit `level` and `info`? Every index the simulation follows
/// without checking is checked here.
fn check(state: &SimState, level: &Level, info: &Info) -> Result<(), Bad> {
    let saved = &state.level;
    let c = Counts {
        mobjs: state.mobjs.len(),
        thinkers: state.thinkers.len(),
        sectors: level.sectors.len(),
        lines: level.lines.len(),
        names: saved.names.len(),
        states: info.states.len(),
    };
    let cells = (level.blockmap.width * level.blockmap.height) as usize;
    let same = |what: &str, have: usize, want: usize| {
        let bad = || ("the level".to_string(), format!("{have} {what} saved, the map has {want}"));
        (have == want).then_some(()).ok_or_else(bad)
    };
    same("sectors", saved.sectors.len(), level.sectors.len())?;
    same("sides", saved.sides.len(), level.sides.len())?;
    same("lines", saved.lines.len(), level.lines.len())?;
    same("blockmap cells' links", state.blocklinks.len(), cells)?;
    same("lines' validcount marks", state.line_valid.len(), level.lines.len())?;
    if !saved.names.starts_with(&level.names) || saved.names.len() > usize::from(u16::MAX) + 1 {
        return Err(("the level".into(), "its texture names are not the map's".into()));
    }
    for (i, &SectorState(_, _, floorpic, ceilingpic, .., soundtarget, specialdata)) in saved.sectors.iter().enumerate()
    {
        let at = format!("sector {i}");
        c.name(&at, "floor flat", floorpic)?;
        c.name(&at, "ceiling flat", ceilingpic)?;
        c.mobj(&at, "sound target", soundtarget)?;
        c.thinker(&at, "mover", specialdata)?;
    }
    for (i, &SideState(_, _, top, bottom, middle)) in saved.sides.iter().enumerate() {
        let at = format!("side {i}");
        for (field, id) in [("upper texture", top), ("lower texture", bottom), ("middle texture", middle)] {
            c.name(&at, field, id)?;
        }
    }
    for (i, m) in state.mobjs.iter().enumerate() {
        let at = format!("mobj {i}");
        Counts::below(&at, "subsector", m.subsector, level.subsectors.len(), "subsectors")?;
        Counts::below(&at, "kind", m.kind, info.things.len(), "kinds in the actor table")?;
        c.state(&at, "state", m.state)?;
        c.mobj(&at, "target", m.target)?;
        c.mobj(&at, "tracer", m.tracer)?;
        c.thinker(&at, "thinker", Some(m.thinker))?;
        if let Some(p) = m.player {
            Counts::below(&at, "player", p, MAXPLAYERS, "player slots")?;
        }
        if let Some(b) = m.block {
            Counts::below(&at, "blockmap cell", b, cells, "cells")?;
        }
    }
    for (i, t) in state.thinkers.iter().enumerate() {
        let at = format!("thinker {i}");
        match &t.kind {
            ThinkerKind::Mobj(id) => c.mobj(&at, "body", Some(*id)),
            ThinkerKind::Door(d) => c.sector(&at, d.sector),
            ThinkerKind::Plat(p) => c.sector(&at, p.sector),
            ThinkerKind::Floor(f) => c.sector(&at, f.sector).and_then(|()| c.name(&at, "texture", f.texture)),
            ThinkerKind::Ceiling(x) => c.sector(&at, x.sector),
            ThinkerKind::Light(l) => c.sector(&at, l.sector),
        }?;
    }
    for (n, p) in state.players.iter().enumerate() {
        let Some(p) = p else { continue };
        let at = format!("player {n}");
        c.mobj(&at, "body", Some(p.mo))?;
        c.mobj(&at, "attacker", p.attacker)?;
        for w in std::iter::once(p.readyweapon).chain(p.pendingweapon) {
            Counts::below(&at, "weapon", w, NUMWEAPONS, "weapons")?;
        }
        for psprite in &p.psprites {
            c.state(&at, "weapon sprite's state", psprite.state)?;
        }
    }
    Counts::below("the console player", "player", state.console, MAXPLAYERS, "player slots")?;
    for (cell, links) in state.blocklinks.iter().enumerate() {
        links.iter().try_for_each(|&id| c.mobj(&format!("blockmap cell {cell}"), "body", Some(id)))?;
    }
    check_globals(state, &c)
}

/// The rest of [`check`]: `p_map.c`'s, `p_spec.c`'s and `p_enemy.c`'s globals and the body queue.
fn check_globals(state: &SimState, c: &Counts) -> Result<(), Bad> {
    let tm = &state.tm;
    let at = "the last move's state (p_map.c's globals)";
    c.mobj(at, "thing", tm.thing)?;
    c.mobj(at, "line target", tm.linetarget)?;
    if let Some(line) = tm.ceilingline {
        c.line(at, "ceiling line", line)?;
    }
    tm.spechit.iter().try_for_each(|&line| c.line(at, "special line crossed", line))?;
    let spec = &state.spec;
    for (k, &plat) in spec.activeplats.iter().enumerate() {
        c.thinker(&format!("active plat slot {k}"), "plat", plat)?;
    }
    for (k, &ceiling) in spec.activeceilings.iter().enumerate() {
        c.thinker(&format!("active ceiling slot {k}"), "ceiling", ceiling)?;
    }
    for (k, b) in spec.buttons.iter().enumerate() {
        let at = format!("button {k}");
        c.line(&at, "line", b.line)?;
        c.sector(&at, b.sector)?;
        c.name(&at, "texture", b.texture)?;
    }
    for (k, &line) in spec.scrollers.iter().enumerate() {
        c.line(&format!("scrolling line {k}"), "line", line)?;
    }
    for (k, &id) in state.brain.targets.iter().enumerate() {
        c.mobj(&format!("boss brain target {k}"), "body", Some(id))?;
    }
    for (k, &id) in state.bodyque.iter().enumerate() {
        c.mobj(&format!("body queue slot {k}"), "body", Some(id))?;
    }
    Ok(())
}

#[cfg(test)]
#[path = "save_tests.rs"]
mod tests;
