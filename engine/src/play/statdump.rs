//! Chocolate Doom's `-statdump` text, read back: what the intermission
//! showed for each level a demo completed (kills, items and secrets found of
//! those in the level, the time and the par time, and in a game of two or
//! more players the frags table). It is how a demo we record is checked
//! against vanilla Doom: Chocolate plays it (`scripts/chocolate-statdump.sh`)
//! and the tallies it prints must be the ones our game finished with.
//!
//! The format is Chocolate's `src/doom/statdump.c` (Chocolate Doom 3.0), which
//! copies the output of id's `statdump.exe` (ctrlapi.zip in the /idgames
//! archive). One block per completed level, in the order they were completed
//! (at most 32: `MAX_CAPTURES`), each ending with a blank line; a demo that
//! completes no level leaves an empty file:
//!
//! ```text
//! ===========================================
//! MAP02
//! ===========================================
//!
//! Time: 0:04 (par: 1:30)
//!
//! Player 1 (Green):
//! \tKills: 1 / 2 (50%)
//! \tItems: 1 / 2 (50%)
//! \tSecrets: 0
//!
//! ```
//!
//! (`\t` is a tab.) The parser accepts exactly what `statdump.c` can print
//! and nothing else, and [`to_text`] prints it back byte for byte, so a
//! parsed dump keeps everything the text says. What the text does not say
//! is lost before we see it: the time is whole seconds, and a count whose
//! level total is 0 prints as a bare `0`, without the player's count.

use std::fmt;
use std::path::Path;

/// The line above and below a level's name: 43 `=`.
pub const BANNER: &str = "===========================================";
/// The colour `statdump.c` names each of the four players by.
pub const PLAYER_COLORS: [&str; 4] = ["Green", "Indigo", "Brown", "Red"];

/// One completed level's intermission, as the text gives it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LevelStats {
    pub level: LevelName,
    /// The level's time: player 1's (all players' are the same).
    pub time: Clock,
    pub par: Clock,
    /// The players in the game, in player order.
    pub players: Vec<PlayerStats>,
}

/// How the level's name is printed. `statdump.c` does not know which game it
/// watched (`statdump.exe` could not), so it guesses from every level in the
/// dump at once: an episode past the first or a map past the ninth settles
/// it, else a par time that only one game gives that map; when nothing
/// settles it, both names are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LevelName {
    /// `E1M4`: Doom.
    Episode { episode: i32, map: i32 },
    /// `MAP02`: Doom II (the number printed with at least two digits).
    Map(i32),
    /// `E1M1 / MAP01`: either. The map number is printed twice.
    Either { episode: i32, map: i32 },
}

/// A time printed `m:ss`: whole minutes and seconds of the tics counted.
/// `statdump.c` divides the tics by 35 into a C `short` and prints that
/// number's minutes and remainder, so a time past 32,767 s (9 h 6 min)
/// wraps to a negative one; the fields hold what was printed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Clock {
    pub minutes: i32,
    pub seconds: i32,
}

/// One player's lines.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlayerStats {
    /// 1 to 4, as printed (`Player 1 (Green)`): Doom's player index plus one.
    pub number: u8,
    pub kills: Tally,
    pub items: Tally,
    pub secrets: Tally,
    /// This player's row of the frags table: how often they killed each
    /// player in the game, in the order of [`LevelStats::players`]. Empty
    /// when the level had fewer than two players (no table is printed).
    pub frags: Vec<i32>,
}

/// A count of things found out of those in the level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tally {
    /// `0`: the level had none. `statdump.c` then prints neither count.
    NoneInLevel,
    /// `found / total (percent%)`, the percentage worked out by
    /// [`Tally::percent`].
    Counted { found: i32, total: i32 },
}

#[derive(Debug, thiserror::Error)]
pub enum StatdumpError {
    #[error("{path}: cannot read: {error}")]
    Read { path: String, error: std::io::Error },
    /// `line` counts from 1; one past the last line when the text ends early.
    #[error("{path}:{line}: {what}")]
    Malformed { path: String, line: usize, what: String },
}

/// Reads a statdump file.
pub fn read(path: &Path) -> Result<Vec<LevelStats>, StatdumpError> {
    let label = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|error| StatdumpError::Read { path: label.clone(), error })?;
    parse(&text, &label)
}

/// Reads a statdump's text; `label` names it in errors, with the line.
/// Lines may end in `\r\n` (a dump written on DOS or Windows).
pub fn parse(text: &str, label: &str) -> Result<Vec<LevelStats>, StatdumpError> {
    let mut lines = Lines { lines: text.lines().collect(), next: 0 };
    let mut levels = Vec::new();
    while lines.next < lines.lines.len() {
        let level = parse_level(&mut lines).map_err(|(line, what)| StatdumpError::Malformed {
            path: label.to_string(),
            line,
            what: format!("level {} of the dump: {what}", levels.len() + 1),
        })?;
        levels.push(level);
    }
    Ok(levels)
}

/// The text `statdump.c` prints for `levels`.
pub fn to_text(levels: &[LevelStats]) -> String {
    levels.iter().map(|l| l.to_string()).collect()
}

impl LevelName {
    /// Whether the map lump `lump` (`E1M4`, `MAP02`) can be this level.
    pub fn could_be(&self, lump: &str) -> bool {
        let episode_map = |e: i32, m: i32| lump.eq_ignore_ascii_case(&format!("E{e}M{m}"));
        let map = |m: i32| lump.eq_ignore_ascii_case(&format!("MAP{m:02}"));
        match *self {
            LevelName::Episode { episode, map: m } => episode_map(episode, m),
            LevelName::Map(m) => map(m),
            LevelName::Either { episode, map: m } => episode_map(episode, m) || map(m),
        }
    }
}

impl Clock {
    /// What `statdump.c` prints for a level that took `tics` tics:
    /// `short leveltime = tics / TICRATE`, then minutes and remainder.
    pub fn from_tics(tics: i32) -> Clock {
        let seconds = (tics / super::TICRATE as i32) as i16 as i32;
        Clock { minutes: seconds / 60, seconds: seconds % 60 }
    }

    pub fn total_seconds(self) -> i64 {
        i64::from(self.minutes) * 60 + i64::from(self.seconds)
    }
}

impl Tally {
    /// What `statdump.c` prints for `found` of `total`: a total of 0 prints
    /// as a bare `0`.
    pub fn of(found: i32, total: i32) -> Tally {
        if total == 0 {
            Tally::NoneInLevel
        } else {
            Tally::Counted { found, total }
        }
    }

    /// The percentage as `statdump.c` works it out: `found * 100` cut to a
    /// 16-bit `short` first, as the 16-bit `statdump.exe` did (so a large
    /// count can print a wrong, even negative, percentage), then divided by
    /// the total, truncating. `None` for no total.
    pub fn percent(self) -> Option<i32> {
        match self {
            Tally::NoneInLevel => None,
            Tally::Counted { found, total } => (found.wrapping_mul(100) as i16 as i32).checked_div(total),
        }
    }
}

impl PlayerStats {
    /// The colour the player is named by; `?` for a number outside 1 to 4.
    pub fn color(&self) -> &'static str {
        usize::from(self.number).checked_sub(1).and_then(|i| PLAYER_COLORS.get(i)).copied().unwrap_or("?")
    }
}

impl fmt::Display for LevelName {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match *self {
            LevelName::Episode { episode, map } => write!(f, "E{episode}M{map}"),
            LevelName::Map(map) => write!(f, "MAP{map:02}"),
            LevelName::Either { episode, map } => write!(f, "E{episode}M{map} / MAP{map:02}"),
        }
    }
}

impl fmt::Display for Clock {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        // C's `%02i` and Rust's `{:02}` agree, negative numbers included
        // (-5 prints `-5`: the sign counts towards the width).
        write!(f, "{}:{:02}", self.minutes, self.seconds)
    }
}

impl fmt::Display for Tally {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match (*self, self.percent()) {
            (Tally::Counted { found, total }, Some(percent)) => write!(f, "{found} / {total} ({percent}%)"),
            // A `Counted` with a total of 0 prints as statdump.c would print it.
            _ => write!(f, "0"),
        }
    }
}

impl fmt::Display for LevelStats {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        writeln!(f, "{BANNER}\n{}\n{BANNER}\n", self.level)?;
        writeln!(f, "Time: {} (par: {})\n", self.time, self.par)?;
        for p in &self.players {
            writeln!(f, "Player {} ({}):", p.number, p.color())?;
            writeln!(f, "\tKills: {}\n\tItems: {}\n\tSecrets: {}", p.kills, p.items, p.secrets)?;
        }
        if self.players.len() >= 2 {
            writeln!(f, "Frags:")?;
            let colors: String = self.players.iter().map(|p| format!("{}\t", p.color())).collect();
            writeln!(f, "\t\t{colors}\n\t\t-------------------------------- VICTIMS")?;
            for p in &self.players {
                let row: String = p.frags.iter().map(|n| format!("{n}\t")).collect();
                writeln!(f, "\t{}\t|{row}", p.color())?;
            }
            writeln!(f, "\t\t|\n\t     KILLERS")?;
        }
        writeln!(f)
    }
}

/// Where a parse failed: the line (from 1) and what was wrong.
type Failure = (usize, String);

struct Lines<'a> {
    lines: Vec<&'a str>,
    /// The index of the next line to read.
    next: usize,
}

impl<'a> Lines<'a> {
    fn peek(&self) -> Option<&'a str> {
        self.lines.get(self.next).copied()
    }

    /// The next line read by `read`, whose error is put on that line.
    fn parse<T>(&mut self, what: &str, read: impl FnOnce(&'a str) -> Result<T, String>) -> Result<T, Failure> {
        let Some(line) = self.peek() else {
            return Err((self.next + 1, format!("the text ends where {what} should be")));
        };
        self.next += 1;
        read(line).map_err(|e| (self.next, format!("{what}: {e}")))
    }

    fn literal(&mut self, what: &str, expected: &str) -> Result<(), Failure> {
        self.parse(what, |line| if line == expected { Ok(()) } else { Err(expected_found(expected, line)) })
    }
}

fn parse_level(lines: &mut Lines) -> Result<LevelStats, Failure> {
    lines.literal("the banner above the level's name", BANNER)?;
    let level = lines.parse("the level's name", level_name)?;
    lines.literal("the banner below the level's name", BANNER)?;
    lines.literal("the blank line before the time", "")?;
    let (time, par) = lines.parse("the time", time_line)?;
    lines.literal("the blank line after the time", "")?;
    let mut players: Vec<PlayerStats> = Vec::new();
    while lines.peek().is_some_and(|l| l.starts_with("Player ")) {
        let number = lines.parse("a player's heading", player_heading)?;
        if let Some(last) = players.last().filter(|last| last.number >= number) {
            return Err((
                lines.next,
                format!("player {number} follows player {}: statdump lists them in order", last.number),
            ));
        }
        let kills = lines.parse("the kills", |l| tally_line(l, "\tKills: "))?;
        let items = lines.parse("the items", |l| tally_line(l, "\tItems: "))?;
        let secrets = lines.parse("the secrets", |l| tally_line(l, "\tSecrets: "))?;
        players.push(PlayerStats { number, kills, items, secrets, frags: Vec::new() });
    }
    if players.len() >= 2 {
        frags_table(lines, &mut players)?;
    }
    lines.literal("the blank line that ends the level (or another player)", "")?;
    Ok(LevelStats { level, time, par, players })
}

/// `ExMy`, `MAPxx` or `ExMy / MAPxx`.
fn level_name(line: &str) -> Result<LevelName, String> {
    let episode_map = |text: &str| -> Option<(i32, i32)> {
        let (e, m) = text.strip_prefix('E')?.split_once('M')?;
        Some((exact(e)?, exact(m)?))
    };
    let map = |text: &str| text.strip_prefix("MAP").and_then(exact_02);
    if let Some((left, right)) = line.split_once(" / ") {
        if let (Some((episode, m)), Some(m2)) = (episode_map(left), map(right)) {
            if m != m2 {
                return Err(format!("{} names two maps: statdump prints one number twice", shown(line)));
            }
            return Ok(LevelName::Either { episode, map: m });
        }
    } else if let Some((episode, m)) = episode_map(line) {
        return Ok(LevelName::Episode { episode, map: m });
    } else if let Some(m) = map(line) {
        return Ok(LevelName::Map(m));
    }
    Err(format!("expected ExMy, MAPxx or \"ExMy / MAPxx\", found {}", shown(line)))
}

/// `Time: m:ss (par: m:ss)`.
fn time_line(line: &str) -> Result<(Clock, Clock), String> {
    let clocks = line.strip_prefix("Time: ").and_then(|rest| rest.strip_suffix(')')?.split_once(" (par: "));
    let (time, par) = clocks.ok_or_else(|| expected_found("Time: m:ss (par: m:ss)", line))?;
    Ok((clock(time)?, clock(par)?))
}

fn clock(text: &str) -> Result<Clock, String> {
    let parsed = text.split_once(':').and_then(|(m, s)| Some(Clock { minutes: exact(m)?, seconds: exact_02(s)? }));
    parsed.ok_or_else(|| format!("{} is not a time m:ss", shown(text)))
}

/// `Player n (Colour):`, the colour the one `statdump.c` gives player n.
fn player_heading(line: &str) -> Result<u8, String> {
    let heading = line.strip_prefix("Player ").and_then(|rest| rest.strip_suffix("):")?.split_once(" ("));
    let (number, color) = heading.ok_or_else(|| expected_found("Player n (Colour):", line))?;
    let n = exact(number).and_then(|n| u8::try_from(n).ok()).filter(|n| (1..=4).contains(n));
    let n = n.ok_or_else(|| format!("player {} is not 1 to 4", shown(number)))?;
    let expected = PLAYER_COLORS[usize::from(n) - 1];
    if color != expected {
        return Err(format!("player {n} is {expected}, not {}", shown(color)));
    }
    Ok(n)
}

/// `<prefix>0` or `<prefix>found / total (percent%)`.
fn tally_line(line: &str, prefix: &str) -> Result<Tally, String> {
    let text = line.strip_prefix(prefix).ok_or_else(|| expected_found(&format!("{prefix}..."), line))?;
    if text == "0" {
        return Ok(Tally::NoneInLevel);
    }
    let parts = text.split_once(" / ").and_then(|(found, rest)| {
        let (total, percent) = rest.split_once(" (")?;
        Some((exact(found)?, exact(total)?, exact(percent.strip_suffix("%)")?)?))
    });
    let (found, total, percent) =
        parts.ok_or_else(|| format!("{} is neither 0 nor \"found / total (percent%)\"", shown(text)))?;
    if total == 0 {
        return Err(format!("{}: statdump prints a total of 0 as a bare 0", shown(text)));
    }
    let tally = Tally::Counted { found, total };
    match tally.percent() {
        Some(p) if p == percent => Ok(tally),
        p => Err(format!("{}: statdump prints {found} of {total} as {}%", shown(text), p.unwrap_or(0))),
    }
}

/// The table `statdump.c` prints for two or more players, its rows put in
/// `players`: a heading of the players' colours, then each player's row of
/// kills of each player.
fn frags_table(lines: &mut Lines, players: &mut [PlayerStats]) -> Result<(), Failure> {
    lines.literal("the frags table (two or more players)", "Frags:")?;
    let colors: String = players.iter().map(|p| format!("\t{}", p.color())).collect();
    let heading = format!("\t{colors}\t");
    lines.literal("the frags table's heading", &heading)?;
    lines.literal("the frags table's rule", "\t\t-------------------------------- VICTIMS")?;
    let columns = players.len();
    for p in players.iter_mut() {
        let start = format!("\t{}\t|", p.color());
        p.frags = lines.parse("a row of the frags table", |line| {
            let cells = line.strip_prefix(start.as_str()).and_then(|rest| rest.strip_suffix('\t'));
            let cells = cells.ok_or_else(|| expected_found(&format!("{start}n\\t..."), line))?;
            let row: Option<Vec<i32>> = cells.split('\t').map(exact).collect();
            let row = row.ok_or_else(|| format!("{} are not whole numbers split by tabs", shown(cells)))?;
            if row.len() != columns {
                return Err(format!("{} frag counts for {columns} players", row.len()));
            }
            Ok(row)
        })?;
    }
    lines.literal("the frags table's foot", "\t\t|")?;
    lines.literal("the frags table's caption", "\t     KILLERS")
}

/// A number as C's `%i` prints it: an optional minus sign and digits,
/// without a leading `+` or zeros, so that printing it gives `text` back.
fn exact(text: &str) -> Option<i32> {
    text.parse::<i32>().ok().filter(|n| n.to_string() == text)
}

/// A number as C's `%02i` prints it (at least two characters, zero-padded).
fn exact_02(text: &str) -> Option<i32> {
    text.parse::<i32>().ok().filter(|n| format!("{n:02}") == text)
}

fn expected_found(expected: &str, line: &str) -> String {
    format!("expected {expected:?}, found {}", shown(line))
}

/// A piece of the text for an error: quoted, escaped, at most 80 characters.
fn shown(text: &str) -> String {
    let mut s: String = text.chars().take(80).collect();
    if s.len() < text.len() {
        s.push_str("...");
    }
    format!("{s:?}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    // Real dumps, written by Chocolate Doom 3.0.0 (Debian's chocolate-doom
    // 3.0.1+really3.0.0+git1471-1) with `-timedemo -statdump` on demos that
    // finish the one-room map of the tests crate's `chocolate_statdump.rs`
    // (TWO_LEVELS is the dump its two-level test checks; the others came
    // from the same room and demo with one setting changed, as noted).

    /// freedoom2.wad, the room as MAP02 then MAP03, one player.
    const TWO_LEVELS: &str = "\
===========================================\n\
MAP02\n\
===========================================\n\
\n\
Time: 0:04 (par: 1:30)\n\
\n\
Player 1 (Green):\n\
\tKills: 1 / 2 (50%)\n\
\tItems: 1 / 2 (50%)\n\
\tSecrets: 1 / 1 (100%)\n\
\n\
===========================================\n\
MAP03\n\
===========================================\n\
\n\
Time: 0:05 (par: 2:00)\n\
\n\
Player 1 (Green):\n\
\tKills: 1 / 2 (50%)\n\
\tItems: 1 / 2 (50%)\n\
\tSecrets: 1 / 1 (100%)\n\
\n";

    /// freedoom2.wad, the room as MAP02, two players in co-op (player 2
    /// starts behind player 1 and stands still).
    const COOP: &str = "\
===========================================\n\
MAP02\n\
===========================================\n\
\n\
Time: 0:04 (par: 1:30)\n\
\n\
Player 1 (Green):\n\
\tKills: 1 / 2 (50%)\n\
\tItems: 1 / 2 (50%)\n\
\tSecrets: 1 / 1 (100%)\n\
Player 2 (Indigo):\n\
\tKills: 0 / 2 (0%)\n\
\tItems: 0 / 2 (0%)\n\
\tSecrets: 0 / 1 (0%)\n\
Frags:\n\
\t\tGreen\tIndigo\t\n\
\t\t-------------------------------- VICTIMS\n\
\tGreen\t|0\t0\t\n\
\tIndigo\t|0\t0\t\n\
\t\t|\n\
\t     KILLERS\n\
\n";

    /// freedoom1.wad, the room as E1M4 with the demo's "no monsters" set
    /// (and 5 tics of shooting instead of 105).
    const NO_MONSTERS: &str = "\
===========================================\n\
E1M4\n\
===========================================\n\
\n\
Time: 0:01 (par: 1:30)\n\
\n\
Player 1 (Green):\n\
\tKills: 0\n\
\tItems: 1 / 2 (50%)\n\
\tSecrets: 1 / 1 (100%)\n\
\n";

    /// freedoom2.wad, the room as MAP01: E1M1 and MAP01 share a par time
    /// (30 s), so statdump.c cannot tell the games apart.
    const EITHER: &str = "\
===========================================\n\
E1M1 / MAP01\n\
===========================================\n\
\n\
Time: 0:04 (par: 0:30)\n\
\n\
Player 1 (Green):\n\
\tKills: 1 / 2 (50%)\n\
\tItems: 1 / 2 (50%)\n\
\tSecrets: 1 / 1 (100%)\n\
\n";

    const REAL: [&str; 4] = [TWO_LEVELS, COOP, NO_MONSTERS, EITHER];

    fn counted(found: i32, total: i32) -> Tally {
        Tally::Counted { found, total }
    }

    fn read_ok(text: &str) -> Vec<LevelStats> {
        parse(text, "sample.txt").unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn two_levels_read_as_chocolate_printed_them() {
        let player = PlayerStats {
            number: 1,
            kills: counted(1, 2),
            items: counted(1, 2),
            secrets: counted(1, 1),
            frags: Vec::new(),
        };
        let levels = read_ok(TWO_LEVELS);
        assert_eq!(
            levels,
            [
                LevelStats {
                    level: LevelName::Map(2),
                    time: Clock { minutes: 0, seconds: 4 },
                    par: Clock { minutes: 1, seconds: 30 },
                    players: vec![player.clone()],
                },
                LevelStats {
                    level: LevelName::Map(3),
                    time: Clock { minutes: 0, seconds: 5 },
                    par: Clock { minutes: 2, seconds: 0 },
                    players: vec![player],
                },
            ]
        );
        assert_eq!(levels[0].players[0].kills.percent(), Some(50));
        assert!(levels[0].level.could_be("MAP02") && levels[0].level.could_be("map02"));
        assert!(!levels[0].level.could_be("E1M2") && !levels[0].level.could_be("MAP2"));
    }

    #[test]
    fn a_coop_dump_reads_with_its_frags_table() {
        let levels = read_ok(COOP);
        let players = &levels[0].players;
        assert_eq!(players.iter().map(|p| (p.number, p.color())).collect::<Vec<_>>(), [(1, "Green"), (2, "Indigo")]);
        assert_eq!(players[1].kills, counted(0, 2));
        assert_eq!(players[1].kills.percent(), Some(0));
        assert_eq!((players[0].frags.clone(), players[1].frags.clone()), (vec![0, 0], vec![0, 0]));
    }

    #[test]
    fn a_level_without_monsters_prints_a_bare_zero() {
        let levels = read_ok(NO_MONSTERS);
        assert_eq!(levels[0].level, LevelName::Episode { episode: 1, map: 4 });
        assert_eq!(levels[0].players[0].kills, Tally::NoneInLevel);
        assert_eq!(levels[0].players[0].kills.percent(), None);
        assert_eq!(Tally::of(0, 0), Tally::NoneInLevel);
    }

    #[test]
    fn a_level_statdump_cannot_place_keeps_both_names() {
        let level = read_ok(EITHER)[0].level;
        assert_eq!(level, LevelName::Either { episode: 1, map: 1 });
        assert!(level.could_be("E1M1") && level.could_be("MAP01") && !level.could_be("E1M2"));
    }

    #[test]
    fn real_dumps_print_back_byte_for_byte() {
        for text in REAL {
            assert_eq!(to_text(&read_ok(text)), text);
        }
        assert_eq!(read_ok(""), []);
    }

    #[test]
    fn crlf_lines_read_the_same() {
        for text in REAL {
            assert_eq!(read_ok(&text.replace('\n', "\r\n")), read_ok(text));
        }
    }

    #[test]
    fn times_are_statdumps_arithmetic() {
        // statdump.c: short leveltime = tics / 35, printed "%i:%02i".
        assert_eq!(Clock::from_tics(146).to_string(), "0:04");
        assert_eq!(Clock::from_tics(35 * 90).to_string(), "1:30");
        assert_eq!(Clock::from_tics(35 * 60 - 1).to_string(), "0:59");
        // Past 32,767 s the short wraps: -32768 s is -546 min -8 s.
        let wrapped = Clock::from_tics(35 * 32_768);
        assert_eq!((wrapped, wrapped.to_string()), (Clock { minutes: -546, seconds: -8 }, "-546:-8".to_string()));
        assert_eq!(wrapped.total_seconds(), -32_768);
        let text = EITHER.replace("Time: 0:04", "Time: -546:-8");
        assert_eq!(read_ok(&text)[0].time, wrapped);
    }

    #[test]
    fn percentages_overflow_as_in_statdump() {
        // 400 * 100 = 40,000 is -25,536 as a short: statdump prints -25%.
        assert_eq!(counted(400, 1000).to_string(), "400 / 1000 (-25%)");
        let text = EITHER.replace("Items: 1 / 2 (50%)", "Items: 400 / 1000 (-25%)");
        assert_eq!(read_ok(&text)[0].players[0].items, counted(400, 1000));
        assert_eq!(counted(2, 3).percent(), Some(66), "truncated, not rounded");
    }

    /// Each case: what is changed in a real dump, the line the error must
    /// name and words it must say.
    #[test]
    fn malformed_text_is_an_error_naming_the_file_and_line() {
        let cases: [(&str, &str, &str, usize, &str); 14] = [
            (EITHER, "==========\nE1M1", "=\nE1M1", 1, "banner above"),
            (EITHER, "E1M1 / MAP01", "E1M1 / MAP02", 2, "two maps"),
            (EITHER, "E1M1 / MAP01", "E1 M1", 2, "ExMy, MAPxx"),
            (NO_MONSTERS, "E1M4", "E01M4", 2, "level's name"),
            (EITHER, "Time: 0:04", "Time: 0:4", 5, "not a time"),
            (EITHER, " (par: 0:30)", " par 0:30", 5, "Time: m:ss"),
            (EITHER, "Player 1 (Green)", "Player 1 (Red)", 7, "player 1 is Green"),
            (EITHER, "Player 1 (Green)", "Player 5 (Green)", 7, "not 1 to 4"),
            (EITHER, "Kills: 1 / 2 (50%)", "Kills: 1 / 2 (51%)", 8, "prints 1 of 2 as 50%"),
            (EITHER, "Items: 1 / 2 (50%)", "Items: 1 / 0 (0%)", 9, "bare 0"),
            (EITHER, "Secrets: 1 / 1", "Secrets: +1 / 1", 10, "neither 0 nor"),
            (COOP, "Player 2 (Indigo)", "Player 1 (Green)", 11, "follows player 1"),
            (COOP, "\tIndigo\t|0\t0\t\n", "\tIndigo\t|0\t\n", 19, "1 frag counts for 2 players"),
            (COOP, "Frags:\n", "", 15, "frags table"),
        ];
        for (text, from, to, line, words) in cases {
            assert!(text.contains(from), "{from:?} is not in the sample");
            let err = parse(&text.replacen(from, to, 1), "dump.txt").expect_err(to).to_string();
            assert!(err.starts_with(&format!("dump.txt:{line}: level 1 of the dump: ")), "{err}");
            assert!(err.contains(words), "{err}");
        }
    }

    #[test]
    fn a_dump_cut_short_or_with_more_after_it_is_an_error() {
        let cut = &TWO_LEVELS[..TWO_LEVELS.len() - 1];
        let err = parse(cut, "cut.txt").unwrap_err().to_string();
        assert!(err.starts_with("cut.txt:22: level 2 of the dump: the text ends where the blank line"), "{err}");
        let err = parse(&format!("{EITHER}statistics\n"), "more.txt").unwrap_err().to_string();
        assert!(err.starts_with("more.txt:12: level 2 of the dump: the banner above"), "{err}");
        let err = parse(&format!("{NO_MONSTERS}Frags:\n"), "more.txt").unwrap_err().to_string();
        assert!(err.starts_with("more.txt:12: level 2"), "{err}");
        let err = parse(&NO_MONSTERS.replace("(100%)\n\n", "(100%)\nFrags:\n\n"), "one.txt").unwrap_err().to_string();
        assert!(err.contains("one.txt:11:") && err.contains("found \"Frags:\""), "{err}");
        assert!(matches!(read(Path::new("/nonexistent/dump.txt")), Err(StatdumpError::Read { .. })));
    }

    fn any_level() -> impl Strategy<Value = LevelStats> {
        let name = prop_oneof![
            (any::<i32>(), any::<i32>()).prop_map(|(episode, map)| LevelName::Episode { episode, map }),
            any::<i32>().prop_map(LevelName::Map),
            (any::<i32>(), any::<i32>()).prop_map(|(episode, map)| LevelName::Either { episode, map }),
        ];
        let clock = || (any::<i32>(), any::<i32>()).prop_map(|(minutes, seconds)| Clock { minutes, seconds });
        let tally = || {
            prop_oneof![
                Just(Tally::NoneInLevel),
                (any::<i32>(), any::<i32>().prop_filter("a total", |t| *t != 0)).prop_map(|(f, t)| counted(f, t)),
            ]
        };
        let player = (tally(), tally(), tally(), prop::collection::vec(any::<i32>(), 4));
        let players = (prop::sample::subsequence(vec![1u8, 2, 3, 4], 0..=4), prop::collection::vec(player, 4))
            .prop_map(|(numbers, lines)| {
                let n = numbers.len();
                let players = numbers.into_iter().zip(lines).map(|(number, (kills, items, secrets, frags))| {
                    let frags = if n >= 2 { frags[..n].to_vec() } else { Vec::new() };
                    PlayerStats { number, kills, items, secrets, frags }
                });
                players.collect::<Vec<_>>()
            });
        (name, clock(), clock(), players).prop_map(|(level, time, par, players)| LevelStats {
            level,
            time,
            par,
            players,
        })
    }

    proptest! {
        /// Whatever statdump.c can print reads back as what was printed.
        #[test]
        fn printed_levels_read_back(levels in prop::collection::vec(any_level(), 0..4)) {
            let text = to_text(&levels);
            prop_assert_eq!(parse(&text, "printed.txt").map_err(|e| TestCaseError::fail(e.to_string()))?, levels);
        }

        /// A real dump with characters replaced, inserted or removed gives
        /// an error or levels, never a panic; and what it accepts, it keeps
        /// entirely: printed back, the levels give the edited text.
        #[test]
        fn edited_dumps_are_refused_or_kept_whole(
            sample in 0..REAL.len(),
            edits in prop::collection::vec(
                (any::<prop::sample::Index>(), 0..3u8, prop_oneof![
                    any::<char>(),
                    prop::sample::select(vec!['\t', '\n', ' ', '0', '1', '9', '-', '/', '(', ')', '%', ':', '=']),
                ]),
                1..6,
            ),
        ) {
            let mut chars: Vec<char> = REAL[sample].chars().collect();
            for (at, how, c) in edits {
                let at = at.index(chars.len() + 1);
                match how {
                    0 if at < chars.len() => chars[at] = c,
                    1 => chars.insert(at, c),
                    _ if at < chars.len() => { chars.remove(at); }
                    _ => {}
                }
            }
            let text: String = chars.into_iter().collect();
            if let Ok(levels) = parse(&text, "edited.txt") {
                if !text.contains('\r') {
                    prop_assert_eq!(to_text(&levels), text);
                }
            }
        }

        #[test]
        fn random_text_does_not_make_it_panic(text in ".{0,400}", lines in prop::collection::vec("[ -~\t]{0,30}", 0..40)) {
            let _ = parse(&text, "noise.txt");
            let _ = parse(&lines.join("\n"), "noise.txt");
        }
    }
}
