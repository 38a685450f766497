//! Doom's own demo files (`.lmp`, and the `DEMOn` lumps inside IWADs): a
//! header naming the game's settings, then each tic's command for each
//! player in the game, then the end marker. Every vanilla port reads them,
//! so they are how a Doom player shares a game and how a port proves its
//! simulation keeps Doom's rules (see `ARCHITECTURE.md`, "Vanilla demos").
//!
//! The layout, as Doom 1.9's `G_BeginRecording` and `G_ReadDemoTiccmd`
//! write and read it (Chocolate Doom's `g_game.c`):
//!
//! | bytes | content |
//! | --- | --- |
//! | 0 | version: 104 to 109 for Doom 1.4 to 1.9, 111 for the "1.91" longtics form |
//! | 1, 2, 3 | skill 0-4, episode, map |
//! | 4 | deathmatch: 0 co-op, 1 deathmatch, 2 altdeath |
//! | 5, 6, 7 | respawn, fast, no monsters (0 or 1) |
//! | 8 | the player whose view the demo shows |
//! | 9-12 | which of the four players are in the game |
//! | then | per tic, per player in the game in order: forward (i8), side (i8), turn (one byte, the high byte of the 16-bit turn; two bytes little-endian for longtics), buttons |
//! | last | 0x80, the end marker (read where a tic's next command would start) |
//!
//! Doom 1.0 to 1.2 wrote no version and no settings: the file starts with
//! the skill (0-4), episode and map, then the four players. Bytes after
//! the end marker are kept (ports append footers there) but not read.
//!
//! Boom's and MBF's formats (versions 200 and up) carry options and a
//! different command layout; they are refused with their names.

use std::path::Path;

/// The byte that ends a demo's commands. A command's forward move can never
/// be -128 (Doom clamps moves to ±50), so the marker is unambiguous.
pub const DEMO_MARKER: u8 = 0x80;
/// Doom 1.9's version byte.
pub const VERSION_1_9: u8 = 109;
/// The "Doom 1.91" longtics form: turns stored in 16 bits.
pub const VERSION_LONGTICS: u8 = 111;
/// Player slots in a demo's header: a vanilla game's four.
pub const MAX_PLAYERS: usize = crate::sim::VANILLA_PLAYERS;
/// Length of the header in the 1.4-1.9 and longtics forms.
const HEADER: usize = 13;
/// Length of the header in the 1.0-1.2 form (no version, no settings).
const OLD_HEADER: usize = 7;

/// The buttons byte (Doom's `d_event.h`).
pub mod buttons {
    pub const ATTACK: u8 = 1;
    pub const USE: u8 = 2;
    /// A weapon change: the weapon's number (0 fist .. 8 super shotgun) sits
    /// in bits 3-5.
    pub const CHANGE: u8 = 4;
    pub const WEAPON_MASK: u8 = 8 | 16 | 32;
    pub const WEAPON_SHIFT: u8 = 3;
    /// A special event (pause, save) instead of the bits above.
    pub const SPECIAL: u8 = 0x80;
}

/// One player's command for one tic, as a demo stores it (Doom's
/// `ticcmd_t` without the fields demos do not carry).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Ticcmd {
    /// Forward (positive) or back; Doom's keys give ±25 walking, ±50 running.
    pub forward: i8,
    /// Right (positive) or left; ±24 walking, ±40 running.
    pub side: i8,
    /// The turn in the high 16 bits of a 32-bit angle, counter-clockwise
    /// positive. A 1.9 demo keeps only its high byte (a multiple of 256).
    pub turn: i16,
    /// See [`buttons`].
    pub buttons: u8,
}

/// The version a demo was written by, which decides its header and turns.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum DemoFormat {
    /// Doom 1.0 to 1.2: no version byte, skill, episode, map and players only.
    Old,
    /// Doom 1.4 to 1.9 (the byte is 104 to 109).
    Vanilla(u8),
    /// Version 111: a 1.9 header with 16-bit turns.
    Longtics,
}

impl DemoFormat {
    pub fn version_byte(self) -> Option<u8> {
        match self {
            DemoFormat::Old => None,
            DemoFormat::Vanilla(v) => Some(v),
            DemoFormat::Longtics => Some(VERSION_LONGTICS),
        }
    }

    fn command_bytes(self) -> usize {
        if self == DemoFormat::Longtics {
            5
        } else {
            4
        }
    }
}

/// The game a demo starts, as its header gives it.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct DemoHeader {
    pub format: DemoFormat,
    /// Doom's skill number 0-4 (one less than the menu's 1-5).
    pub skill: u8,
    pub episode: u8,
    pub map: u8,
    /// 0 co-op (or single player), 1 deathmatch, 2 altdeath.
    pub deathmatch: u8,
    pub respawn: bool,
    pub fast: bool,
    pub no_monsters: bool,
    /// The player whose view is shown (`consoleplayer`).
    pub console_player: u8,
    pub in_game: [bool; MAX_PLAYERS],
}

impl DemoHeader {
    /// A single-player 1.9 game on `episode`/`map` at Doom's `skill` (0-4).
    pub fn single(skill: u8, episode: u8, map: u8) -> DemoHeader {
        DemoHeader {
            format: DemoFormat::Vanilla(VERSION_1_9),
            skill,
            episode,
            map,
            deathmatch: 0,
            respawn: false,
            fast: false,
            no_monsters: false,
            console_player: 0,
            in_game: [true, false, false, false],
        }
    }

    /// How many players' commands each tic holds.
    pub fn players(&self) -> usize {
        self.in_game.iter().filter(|&&p| p).count()
    }

    /// The map's lump name: `MAPnn` in Doom II (a `commercial` IWAD, one
    /// with no episodes), else `EeMm`.
    pub fn map_name(&self, commercial: bool) -> String {
        if commercial {
            format!("MAP{:02}", self.map)
        } else {
            format!("E{}M{}", self.episode, self.map)
        }
    }
}

/// A vanilla demo: its header and every tic's commands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VanillaDemo {
    pub header: DemoHeader,
    /// The commands, tic by tic: tic `t`'s command for the `k`th player in
    /// the game is `commands[t * players + k]`.
    pub commands: Vec<Ticcmd>,
    /// Bytes found after the end marker (a port's footer), kept unread.
    pub trailing: usize,
}

#[derive(Debug, thiserror::Error)]
pub enum LmpError {
    #[error("{path}: cannot read: {error}")]
    Read { path: String, error: std::io::Error },
    #[error("{path}: cannot write: {error}")]
    Write { path: String, error: std::io::Error },
    #[error("{path}: {what}")]
    Unsupported { path: String, what: String },
    #[error("{path}: truncated: {what}")]
    Truncated { path: String, what: String },
    #[error("{path}: corrupt: {what}")]
    Corrupt { path: String, what: String },
}

/// What a version byte that this engine does not play stands for, for the
/// error that refuses it (the numbers ports have used; PrBoom+'s and
/// dsda-doom's `G_ReadDemoHeader` list them).
fn version_name(version: u8) -> String {
    let name = match version {
        100..=103 => "a Doom 1.0-1.3 development build",
        110 => "Doom 1.10 (an unofficial build)",
        200 => "Boom 2.00",
        201 => "Boom 2.01",
        202 => "Boom 2.02",
        203 => "LxDoom or MBF",
        210 => "PrBoom 2.1",
        211..=214 => "PrBoom+",
        221 => "MBF21",
        255 => "a port's signature-prefixed format (Eternity or ZDoom)",
        _ => "no Doom release",
    };
    format!("{version} ({name})")
}

impl VanillaDemo {
    /// A game with no tics yet (record into `commands`).
    pub fn new(header: DemoHeader) -> VanillaDemo {
        VanillaDemo { header, commands: Vec::new(), trailing: 0 }
    }

    /// The number of tics the demo plays.
    pub fn tics(&self) -> usize {
        self.commands.len() / self.header.players().max(1)
    }

    /// Tic `t`'s commands, one per player in the game (in player order).
    pub fn tic(&self, t: usize) -> &[Ticcmd] {
        let n = self.header.players();
        self.commands.get(t * n..(t + 1) * n).unwrap_or(&[])
    }

    pub fn load(path: &Path) -> Result<VanillaDemo, LmpError> {
        let label = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|error| LmpError::Read { path: label.clone(), error })?;
        VanillaDemo::from_bytes(&bytes, &label)
    }

    /// Decodes a demo; `label` names the file (or `WAD:LUMP`) in errors.
    pub fn from_bytes(bytes: &[u8], label: &str) -> Result<VanillaDemo, LmpError> {
        let path = || label.to_string();
        let corrupt = |what: String| LmpError::Corrupt { path: path(), what };
        let Some(&first) = bytes.first() else {
            return Err(LmpError::Truncated { path: path(), what: "the file is empty".into() });
        };
        let format = match first {
            0..=4 => DemoFormat::Old,
            104..=109 => DemoFormat::Vanilla(first),
            VERSION_LONGTICS => DemoFormat::Longtics,
            other => {
                return Err(LmpError::Unsupported {
                    path: path(),
                    what: format!(
                        "demo version {}: this engine plays vanilla Doom's demos (versions 104 to 109, \
                         111 for longtics, and Doom 1.0-1.2's)",
                        version_name(other)
                    ),
                })
            }
        };
        let header_len = if format == DemoFormat::Old { OLD_HEADER } else { HEADER };
        let Some(head) = bytes.get(..header_len) else {
            return Err(LmpError::Truncated {
                path: path(),
                what: format!("the header needs {header_len} bytes, the file has {}", bytes.len()),
            });
        };
        let header = match format {
            DemoFormat::Old => DemoHeader {
                format,
                skill: head[0],
                episode: head[1],
                map: head[2],
                deathmatch: 0,
                respawn: false,
                fast: false,
                no_monsters: false,
                console_player: 0,
                in_game: [head[3] != 0, head[4] != 0, head[5] != 0, head[6] != 0],
            },
            _ => DemoHeader {
                format,
                skill: head[1],
                episode: head[2],
                map: head[3],
                deathmatch: head[4],
                respawn: head[5] != 0,
                fast: head[6] != 0,
                no_monsters: head[7] != 0,
                console_player: head[8],
                in_game: [head[9] != 0, head[10] != 0, head[11] != 0, head[12] != 0],
            },
        };
        check_header(&header).map_err(corrupt)?;
        let players = header.players();
        let size = format.command_bytes();
        let mut commands = Vec::new();
        let mut at = header_len;
        loop {
            // Doom looks for the marker where each player's command would start.
            for k in 0..players {
                match bytes.get(at) {
                    None => {
                        return Err(LmpError::Truncated {
                            path: path(),
                            what: format!(
                                "no end marker (0x80): the commands stop at byte {at}, in tic {} (player slot {k})",
                                commands.len() / players
                            ),
                        })
                    }
                    Some(&DEMO_MARKER) if k == 0 => {
                        let trailing = bytes.len() - at - 1;
                        return Ok(VanillaDemo { header, commands, trailing });
                    }
                    Some(&DEMO_MARKER) => {
                        return Err(corrupt(format!(
                            "the end marker at byte {at} falls inside tic {} (player slot {k} of {players})",
                            commands.len() / players
                        )))
                    }
                    Some(_) => {}
                }
                let Some(c) = bytes.get(at..at + size) else {
                    return Err(LmpError::Truncated {
                        path: path(),
                        what: format!("tic {} is cut short at byte {}", commands.len() / players, bytes.len()),
                    });
                };
                let (turn, buttons) = match format {
                    DemoFormat::Longtics => (i16::from_le_bytes([c[2], c[3]]), c[4]),
                    _ => (i16::from_be_bytes([c[2], 0]), c[3]),
                };
                commands.push(Ticcmd { forward: c[0] as i8, side: c[1] as i8, turn, buttons });
                at += size;
            }
        }
    }

    /// The file's bytes. A 1.9 demo keeps a turn's high byte, rounded
    /// ([`Ticcmd::as_recorded`]); a recorder plays each command as recorded
    /// so the game it shows is the one the file holds.
    pub fn to_bytes(&self) -> Vec<u8> {
        let h = &self.header;
        let mut out = Vec::with_capacity(HEADER + self.commands.len() * 5 + 1);
        match h.format.version_byte() {
            Some(v) => out.extend([
                v,
                h.skill,
                h.episode,
                h.map,
                h.deathmatch,
                h.respawn as u8,
                h.fast as u8,
                h.no_monsters as u8,
                h.console_player,
            ]),
            None => out.extend([h.skill, h.episode, h.map]),
        }
        out.extend(h.in_game.map(u8::from));
        for c in &self.commands {
            // -128 would read as the end marker; Doom never moves that fast.
            out.extend([c.forward.max(-127) as u8, c.side as u8]);
            match h.format {
                DemoFormat::Longtics => out.extend(c.turn.to_le_bytes()),
                _ => out.push(c.as_recorded(h.format).turn.to_be_bytes()[0]),
            }
            out.push(c.buttons);
        }
        out.push(DEMO_MARKER);
        out
    }

    /// Writes the demo to `path` atomically (a temporary file, then a
    /// rename), so a failed write never clobbers an existing file.
    pub fn save(&self, path: &Path) -> Result<(), LmpError> {
        crate::level::write_file_atomic(path, &self.to_bytes())
            .map_err(|error| LmpError::Write { path: path.display().to_string(), error })
    }
}

impl Ticcmd {
    /// The command as a demo of `format` will give it back: a 1.9 demo keeps
    /// the turn's high byte. Doom 1.9 truncated (`angleturn >> 8`); we round
    /// to nearest as Chocolate Doom's `G_BuildTiccmd` does for a recording
    /// game (`(angleturn + 128) & 0xff00`), and a recorder carries the
    /// remainder into the next tic so slow mouse turns still add up.
    pub fn as_recorded(self, format: DemoFormat) -> Ticcmd {
        match format {
            DemoFormat::Longtics => self,
            _ => Ticcmd { turn: ((self.turn as i32 + 128) & 0xff00) as i16, ..self },
        }
    }
}

/// Whether the header describes a game Doom can start; the message names
/// the field that cannot be.
fn check_header(h: &DemoHeader) -> Result<(), String> {
    if h.skill > 4 {
        return Err(format!("skill {} is not 0 to 4", h.skill));
    }
    if h.deathmatch > 2 {
        return Err(format!("deathmatch mode {} is not 0, 1 or 2", h.deathmatch));
    }
    if h.players() == 0 {
        return Err("no player is in the game".into());
    }
    if usize::from(h.console_player) >= MAX_PLAYERS || !h.in_game[usize::from(h.console_player)] {
        return Err(format!("the viewing player {} is not in the game", h.console_player));
    }
    if !(1..=99).contains(&h.map) || h.episode > 9 {
        return Err(format!("episode {} map {} is no Doom map", h.episode, h.map));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> VanillaDemo {
        let mut demo = VanillaDemo::new(DemoHeader::single(2, 1, 4));
        demo.commands = vec![
            Ticcmd { forward: 25, side: 0, turn: 0, buttons: 0 },
            Ticcmd { forward: 50, side: -40, turn: 0x0500, buttons: buttons::ATTACK },
            Ticcmd { forward: -25, side: 24, turn: -0x0300, buttons: buttons::USE },
        ];
        demo
    }

    #[test]
    fn round_trips_a_1_9_demo() {
        let demo = sample();
        let bytes = demo.to_bytes();
        assert_eq!(bytes.len(), 13 + 3 * 4 + 1);
        assert_eq!(bytes[..13], [109, 2, 1, 4, 0, 0, 0, 0, 0, 1, 0, 0, 0]);
        assert_eq!(*bytes.last().unwrap(), DEMO_MARKER);
        let back = VanillaDemo::from_bytes(&bytes, "t.lmp").unwrap();
        assert_eq!(back, demo);
        assert_eq!(back.tics(), 3);
    }

    #[test]
    fn longtics_keep_the_whole_turn_and_1_9_rounds_it() {
        let mut demo = sample();
        demo.commands[0].turn = 0x0123;
        let mut long = demo.clone();
        long.header.format = DemoFormat::Longtics;
        let back = VanillaDemo::from_bytes(&long.to_bytes(), "t.lmp").unwrap();
        assert_eq!(back.commands[0].turn, 0x0123);
        assert_eq!(long.to_bytes().len(), 13 + 3 * 5 + 1);
        // 0x123 rounds to 0x100 in a 1.9 demo; 0x180 would round up to 0x200.
        let short = VanillaDemo::from_bytes(&demo.to_bytes(), "t.lmp").unwrap();
        assert_eq!(short.commands[0].turn, 0x0100);
        let c = Ticcmd { turn: 0x0180, ..Ticcmd::default() };
        assert_eq!(c.as_recorded(DemoFormat::Vanilla(109)).turn, 0x0200);
        let c = Ticcmd { turn: -0x0181, ..Ticcmd::default() };
        assert_eq!(c.as_recorded(DemoFormat::Vanilla(109)).turn, -0x0200);
    }

    #[test]
    fn several_players_interleave_by_tic() {
        let mut demo = sample();
        demo.header.in_game = [true, false, true, false];
        demo.commands.push(Ticcmd { forward: 1, ..Ticcmd::default() });
        let back = VanillaDemo::from_bytes(&demo.to_bytes(), "t.lmp").unwrap();
        assert_eq!(back.tics(), 2);
        assert_eq!(back.tic(1), &demo.commands[2..4]);
        assert!(back.tic(2).is_empty());
    }

    #[test]
    fn reads_the_old_header_and_keeps_a_footer() {
        let mut bytes = vec![3, 1, 1, 1, 0, 0, 0, 25, 0, 0, 0, DEMO_MARKER];
        bytes.extend(b"footer");
        let demo = VanillaDemo::from_bytes(&bytes, "old.lmp").unwrap();
        assert_eq!(demo.header.format, DemoFormat::Old);
        assert_eq!(demo.header.skill, 3);
        assert_eq!(demo.tics(), 1);
        assert_eq!(demo.trailing, 6);
    }

    fn error(bytes: &[u8]) -> String {
        VanillaDemo::from_bytes(bytes, "bad.lmp").unwrap_err().to_string()
    }

    #[test]
    fn bad_demos_say_what_is_wrong() {
        assert_eq!(error(&[]), "bad.lmp: truncated: the file is empty");
        assert!(error(&[202, 0, 0]).contains("demo version 202 (Boom 2.02)"), "{}", error(&[202]));
        assert!(error(&[221]).contains("MBF21"));
        assert!(error(&[109, 2, 1]).contains("the header needs 13 bytes, the file has 3"));
        let good = sample().to_bytes();
        let cut = &good[..good.len() - 1];
        assert!(error(cut).contains("no end marker (0x80): the commands stop at byte 25, in tic 3"), "{}", error(cut));
        assert!(error(&good[..good.len() - 3]).contains("tic 2 is cut short"), "{}", error(&good[..good.len() - 3]));
        let mut skill = good.clone();
        skill[1] = 7;
        assert!(error(&skill).contains("corrupt: skill 7 is not 0 to 4"));
        let mut nobody = good.clone();
        nobody[9] = 0;
        assert!(error(&nobody).contains("no player is in the game"));
        let mut view = good.clone();
        view[8] = 2;
        assert!(error(&view).contains("the viewing player 2 is not in the game"));
        let mut two = good.clone();
        two[10] = 1; // a second player: the marker now falls in its slot
        assert!(error(&two).contains("inside tic 1 (player slot 1 of 2)"), "{}", error(&two));
    }

    proptest::proptest! {
        #[test]
        fn garbage_never_panics(bytes in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..200)) {
            let _ = VanillaDemo::from_bytes(&bytes, "fuzz.lmp");
        }

        #[test]
        fn every_truncation_is_an_error(cut in 0usize..25) {
            let bytes = sample().to_bytes();
            proptest::prop_assert!(VanillaDemo::from_bytes(&bytes[..cut.min(bytes.len() - 1)], "cut.lmp").is_err());
        }
    }
}
