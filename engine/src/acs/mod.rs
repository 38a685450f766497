//! ACS, ZDoom's map scripting: BEHAVIOR lumps loaded and run, apart from
//! the game simulation.
//!
//! ```text
//! BEHAVIOR bytes --load::Module::load--> Module (chunks read, code decoded and checked)
//!     --vm::Vm::new(module, host)--> Vm --start_typed(Open/Enter), execute(..)-->
//!     scripts --Vm::tick(host), once per 35 Hz tic--> calls on the Host
//! ```
//!
//! `load` reads the lump's formats (`text` its escapes and STRE's
//! scrambling), `decode` turns the code into checked instructions, `pcodes` is the instruction set, `vm` holds the variables
//! and schedules scripts in ZDoom's order, `exec` runs one script's
//! instructions and `calls` its calls out (line specials, extended
//! functions, script control). Everything the game answers goes through the
//! [`Host`] trait (`host`); `record` is a host that records its calls, for
//! tests and for running a module without a game.

pub mod calls;
pub mod decode;
pub mod exec;
pub mod host;
pub mod load;
pub mod pcodes;
pub mod record;
mod text;
pub mod vm;

#[cfg(test)]
mod asm_tests;
#[cfg(test)]
mod load_tests;
#[cfg(test)]
mod scenario_tests;
#[cfg(test)]
mod test_asm;
#[cfg(test)]
mod vm_tests;

pub use host::{Activator, Host, HostCx, PrintKind, Strings};
pub use load::{LoadError, Module, Problem};
pub use record::RecordingHost;
pub use vm::{Vm, RUNAWAY_LIMIT};

use crate::wad::Wad;

/// When a script starts by itself (ZDoom's `SCRIPT_*` types).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ScriptKind {
    /// Started only by a special or another script.
    Closed,
    /// When the level starts.
    Open,
    Respawn,
    Death,
    /// When a player enters the level.
    Enter,
    Pickup,
    BlueReturn,
    RedReturn,
    WhiteReturn,
    Lightning,
    Unloading,
    Disconnect,
    Return,
    Event,
    Kill,
    Reopen,
    /// A type number ZDoom does not define.
    Other(u8),
}

impl ScriptKind {
    /// From the type number in SPTR (or the thousands of Hexen's script number).
    pub fn from_code(code: u8) -> ScriptKind {
        use ScriptKind::*;
        match code {
            0 => Closed,
            1 => Open,
            2 => Respawn,
            3 => Death,
            4 => Enter,
            5 => Pickup,
            6 => BlueReturn,
            7 => RedReturn,
            8 => WhiteReturn,
            12 => Lightning,
            13 => Unloading,
            14 => Disconnect,
            15 => Return,
            16 => Event,
            17 => Kill,
            18 => Reopen,
            other => Other(other),
        }
    }
}

/// The level number ZDoom gives a map without a MAPINFO `levelnum`: `xx`
/// for `MAPxx`, 0 (none) for other names. `ACS_Execute(script, map, ...)`
/// names the current map by this number or 0; see [`Vm::level_number`].
pub fn default_level_number(map: &str) -> i32 {
    let upper = map.to_ascii_uppercase();
    upper.strip_prefix("MAP").and_then(|n| n.parse().ok()).unwrap_or(0)
}

/// Lumps that may follow a Doom-format map's marker, in the order ZDoom's
/// `GetMapIndex` expects them.
const BINARY_MAP_LUMPS: [&str; 11] = [
    "THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS", "NODES", "SECTORS", "REJECT", "BLOCKMAP",
    "BEHAVIOR",
];

/// The index of the BEHAVIOR lump ZDoom runs for `map`, if it has one.
///
/// For a UDMF map ZDoom's `P_OpenMapData` walks the lumps from TEXTMAP to
/// ENDMAP and files each BEHAVIOR it meets in the same slot, so the last one
/// wins: defend_the_center.wad and health_gathering.wad carry two, and the
/// second (the one whose SCRIPTS source follows it) is the one that runs.
/// A Doom-format map's lumps follow the marker in a fixed order, BEHAVIOR last.
pub fn behavior_for_map(wad: &Wad, map: &str) -> Option<usize> {
    let marker = wad.find(map)?;
    let lumps = &wad.lumps;
    let is = |i: usize, name: &str| lumps.get(i).is_some_and(|l| l.name.eq_ignore_ascii_case(name));
    if is(marker + 1, "TEXTMAP") {
        (marker + 2..lumps.len()).take_while(|&i| !is(i, "ENDMAP")).filter(|&i| is(i, "BEHAVIOR")).last()
    } else {
        (marker + 1..lumps.len())
            .take_while(|&i| BINARY_MAP_LUMPS.iter().any(|n| is(i, n)))
            .find(|&i| is(i, "BEHAVIOR"))
    }
}
