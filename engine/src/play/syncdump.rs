//! Reference dumps: the state of a game after every tic, as a patched
//! Chocolate Doom prints it while it plays a demo
//! (`scripts/chocolate-demo-dumps.sh`; the format is specified in
//! `tests/fixtures/demo-dumps/README.md`), and the comparison of our game's
//! state with it, tic by tic. The first tic whose fields differ is where a
//! desync starts: `sightline replay DEMO --check-against DUMP` names it and
//! the fields, which is where a person bisecting a desync starts reading.
//!
//! A line, after `#` header lines:
//!
//! ```text
//! <gametic> <leveltime> rnd=<prndindex> p0=<x>,<y>,<z>,<angle>,<momx>,<momy>,<health>,<armor>,<a0>/<a1>/<a2>/<a3> [p1=...] mobjs=<count>:<hash> sectors=<hash>
//! ```
//!
//! Positions and momentum are 16.16 fixed point, the angle a 32-bit binary
//! angle, the hashes 32-bit FNV-1a in hexadecimal.

use std::fmt;
use std::path::Path;

/// One player's state after a tic, in Doom's units.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PlayerState {
    pub x: i32,
    pub y: i32,
    pub z: i32,
    pub angle: u32,
    pub momx: i32,
    pub momy: i32,
    pub health: i32,
    pub armor: i32,
    pub ammo: [i32; 4],
}

/// The state after one tic. Fields our side cannot give yet are `None` and
/// are not compared (the comparison says which were left out).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TicState {
    pub gametic: u32,
    pub leveltime: Option<u32>,
    /// `P_Random`'s index after the tic.
    pub rnd: Option<u8>,
    /// Player `k` of the game, if in it.
    pub players: [Option<PlayerState>; 4],
    /// The mobjs' count and their hash.
    pub mobjs: Option<(u32, u32)>,
    pub sectors: Option<u32>,
}

/// A whole dump: its header lines (without `#`) and one state a tic.
#[derive(Clone, Debug, Default)]
pub struct SyncDump {
    pub header: Vec<String>,
    pub tics: Vec<TicState>,
}

#[derive(Debug, thiserror::Error)]
pub enum DumpError {
    #[error("{path}: cannot read: {error}")]
    Read { path: String, error: std::io::Error },
    #[error("{path}:{line}: {what}")]
    Parse { path: String, line: usize, what: String },
}

impl SyncDump {
    pub fn load(path: &Path) -> Result<SyncDump, DumpError> {
        let label = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|error| DumpError::Read { path: label.clone(), error })?;
        SyncDump::parse(&text, &label)
    }

    /// Reads a dump; `label` names it in errors, with the line number.
    pub fn parse(text: &str, label: &str) -> Result<SyncDump, DumpError> {
        let mut dump = SyncDump::default();
        for (i, line) in text.lines().enumerate() {
            let line = line.trim();
            if let Some(comment) = line.strip_prefix('#') {
                dump.header.push(comment.trim().to_string());
                continue;
            }
            if line.is_empty() {
                continue;
            }
            let state =
                parse_line(line).map_err(|what| DumpError::Parse { path: label.to_string(), line: i + 1, what })?;
            dump.tics.push(state);
        }
        Ok(dump)
    }

    /// The header's `key=value` (or `key: value`) entry, if any.
    pub fn header_value(&self, key: &str) -> Option<&str> {
        self.header.iter().flat_map(|h| h.split_whitespace()).find_map(|word| {
            let (k, v) = word.split_once('=')?;
            (k == key).then_some(v)
        })
    }
}

fn parse_line(line: &str) -> Result<TicState, String> {
    let mut words = line.split_whitespace();
    let number = |w: Option<&str>, what: &str| -> Result<u32, String> {
        let w = w.ok_or_else(|| format!("no {what}"))?;
        w.parse().map_err(|_| format!("{what} {w:?} is not a number"))
    };
    let mut state = TicState {
        gametic: number(words.next(), "gametic")?,
        leveltime: Some(number(words.next(), "leveltime")?),
        ..TicState::default()
    };
    for word in words {
        let (key, value) = word.split_once('=').ok_or_else(|| format!("{word:?} is not key=value"))?;
        match key {
            "rnd" => state.rnd = Some(value.parse().map_err(|_| format!("rnd {value:?} is not 0 to 255"))?),
            "mobjs" => {
                let (count, hash) = value.split_once(':').ok_or_else(|| format!("mobjs {value:?} is not N:HASH"))?;
                let count = count.parse().map_err(|_| format!("mobj count {count:?} is not a number"))?;
                state.mobjs = Some((count, hex(hash)?));
            }
            "sectors" => state.sectors = Some(hex(value)?),
            _ => {
                let k = key
                    .strip_prefix('p')
                    .and_then(|n| n.parse::<usize>().ok())
                    .filter(|&k| k < 4)
                    .ok_or_else(|| format!("unknown field {key:?}"))?;
                state.players[k] = Some(parse_player(value).map_err(|e| format!("{key}: {e}"))?);
            }
        }
    }
    Ok(state)
}

fn hex(text: &str) -> Result<u32, String> {
    u32::from_str_radix(text, 16).map_err(|_| format!("{text:?} is not a hexadecimal hash"))
}

fn parse_player(value: &str) -> Result<PlayerState, String> {
    let fields: Vec<&str> = value.split(',').collect();
    let [x, y, z, angle, momx, momy, health, armor, ammo] = fields[..] else {
        return Err(format!("{} fields, 9 expected", fields.len()));
    };
    let int = |w: &str, what: &str| w.parse::<i32>().map_err(|_| format!("{what} {w:?} is not a number"));
    let ammo: Vec<&str> = ammo.split('/').collect();
    let [a0, a1, a2, a3] = ammo[..] else {
        return Err(format!("{} ammo counts, 4 expected", ammo.len()));
    };
    Ok(PlayerState {
        x: int(x, "x")?,
        y: int(y, "y")?,
        z: int(z, "z")?,
        angle: angle.parse().map_err(|_| format!("angle {angle:?} is not 0 to 2^32-1"))?,
        momx: int(momx, "momx")?,
        momy: int(momy, "momy")?,
        health: int(health, "health")?,
        armor: int(armor, "armor")?,
        ammo: [int(a0, "ammo")?, int(a1, "ammo")?, int(a2, "ammo")?, int(a3, "ammo")?],
    })
}

/// One field that differs: its name and both values.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FieldDiff {
    pub field: String,
    pub ours: String,
    pub theirs: String,
}

impl fmt::Display for FieldDiff {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "{}: ours {}, reference {}", self.field, self.ours, self.theirs)
    }
}

/// The fields of `ours` that differ from `theirs`, among those both give.
pub fn compare(ours: &TicState, theirs: &TicState) -> Vec<FieldDiff> {
    let mut diffs = Vec::new();
    let mut check = |field: String, a: String, b: String| {
        if a != b {
            diffs.push(FieldDiff { field, ours: a, theirs: b });
        }
    };
    // The game's tic count runs on through intermissions: it checks how
    // long each lasted.
    check("gametic".into(), ours.gametic.to_string(), theirs.gametic.to_string());
    if let (Some(a), Some(b)) = (ours.leveltime, theirs.leveltime) {
        check("leveltime".into(), a.to_string(), b.to_string());
    }
    if let (Some(a), Some(b)) = (ours.rnd, theirs.rnd) {
        check("rnd".into(), a.to_string(), b.to_string());
    }
    for (k, (a, b)) in ours.players.iter().zip(&theirs.players).enumerate() {
        match (a, b) {
            (Some(a), Some(b)) => {
                let pairs: [(&str, i64, i64); 8] = [
                    ("x", a.x.into(), b.x.into()),
                    ("y", a.y.into(), b.y.into()),
                    ("z", a.z.into(), b.z.into()),
                    ("angle", a.angle.into(), b.angle.into()),
                    ("momx", a.momx.into(), b.momx.into()),
                    ("momy", a.momy.into(), b.momy.into()),
                    ("health", a.health.into(), b.health.into()),
                    ("armor", a.armor.into(), b.armor.into()),
                ];
                for (name, x, y) in pairs {
                    check(format!("p{k}.{name}"), x.to_string(), y.to_string());
                }
                check(format!("p{k}.ammo"), format!("{:?}", a.ammo), format!("{:?}", b.ammo));
            }
            (None, None) => {}
            (a, b) => check(format!("p{k}"), in_game(a.is_some()), in_game(b.is_some())),
        }
    }
    if let (Some(a), Some(b)) = (ours.mobjs, theirs.mobjs) {
        check("mobjs".into(), format!("{}:{:08x}", a.0, a.1), format!("{}:{:08x}", b.0, b.1));
    }
    if let (Some(a), Some(b)) = (ours.sectors, theirs.sectors) {
        check("sectors".into(), format!("{a:08x}"), format!("{b:08x}"));
    }
    diffs
}

fn in_game(present: bool) -> String {
    if present { "in the game" } else { "absent" }.to_string()
}

/// The fields the reference gives that `ours` leaves out (not compared).
pub fn not_compared(ours: &TicState, theirs: &TicState) -> Vec<&'static str> {
    let mut out = Vec::new();
    if ours.rnd.is_none() && theirs.rnd.is_some() {
        out.push("rnd");
    }
    if ours.mobjs.is_none() && theirs.mobjs.is_some() {
        out.push("mobjs");
    }
    if ours.sectors.is_none() && theirs.sectors.is_some() {
        out.push("sectors");
    }
    out
}

/// 32-bit FNV-1a, the dumps' hash, over little-endian `i32`s.
#[derive(Clone, Copy, Debug)]
pub struct Fnv(pub u32);

impl Default for Fnv {
    fn default() -> Fnv {
        Fnv(0x811c_9dc5)
    }
}

impl Fnv {
    pub fn bytes(&mut self, bytes: &[u8]) {
        for &byte in bytes {
            self.0 ^= u32::from(byte);
            self.0 = self.0.wrapping_mul(0x0100_0193);
        }
    }

    pub fn int(&mut self, v: i32) {
        self.bytes(&v.to_le_bytes());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SAMPLE: &str = "# iwad=freedoom1.wad lump=DEMO1 gameversion=ultimate skill=3\n\
        1 0 rnd=3 p0=1048576,-2097152,0,1073741824,0,0,100,0,50/0/0/0 mobjs=12:deadbeef sectors=0badf00d\n\
        2 1 rnd=5 p0=1048576,-2097152,0,1073741824,16384,0,100,0,50/0/0/0 mobjs=12:deadbeef sectors=0badf00d\n";

    #[test]
    fn reads_a_dump() {
        let dump = SyncDump::parse(SAMPLE, "d.txt").unwrap();
        assert_eq!(dump.tics.len(), 2);
        assert_eq!(dump.header_value("lump"), Some("DEMO1"));
        let p = dump.tics[1].players[0].unwrap();
        assert_eq!((p.x, p.y, p.angle, p.momx, p.ammo[0]), (1 << 20, -(1 << 21), 1 << 30, 16384, 50));
        assert_eq!(dump.tics[1].mobjs, Some((12, 0xdead_beef)));
        assert_eq!(dump.tics[1].rnd, Some(5));
    }

    #[test]
    fn names_the_line_and_the_field_that_is_wrong() {
        let bad = SAMPLE.replace("p0=1048576,-2097152,0,1073741824,16384", "p0=1048576,-2097152,0,x,16384");
        let e = SyncDump::parse(&bad, "d.txt").unwrap_err().to_string();
        assert_eq!(e, "d.txt:3: p0: angle \"x\" is not 0 to 2^32-1");
        let e = SyncDump::parse("1 0 zz=1\n", "d.txt").unwrap_err().to_string();
        assert_eq!(e, "d.txt:1: unknown field \"zz\"");
    }

    #[test]
    fn compares_only_what_both_give() {
        let dump = SyncDump::parse(SAMPLE, "d.txt").unwrap();
        let mut ours = dump.tics[1].clone();
        ours.mobjs = None;
        assert!(compare(&ours, &dump.tics[1]).is_empty());
        assert_eq!(not_compared(&ours, &dump.tics[1]), ["mobjs"]);
        ours.players[0].as_mut().unwrap().momx = 16385;
        let diffs = compare(&ours, &dump.tics[1]);
        assert_eq!(diffs.len(), 1);
        assert_eq!(diffs[0].to_string(), "p0.momx: ours 16385, reference 16384");
    }

    #[test]
    fn fnv_matches_the_published_vectors() {
        let hash = |text: &[u8]| {
            let mut h = Fnv::default();
            h.bytes(text);
            h.0
        };
        assert_eq!(hash(b""), 0x811c_9dc5);
        assert_eq!(hash(b"a"), 0xe40c_292c);
        assert_eq!(hash(b"foobar"), 0xbf9c_f968);
        let mut h = Fnv::default();
        h.int(i32::from_le_bytes(*b"foob"));
        assert_eq!(h.0, hash(b"foob"));
    }
}
