//! The compiled map file: a magic header, a format version, a CRC-32 of the
//! payload, then the map (as its RON source text) and its BSP in postcard (a
//! compact serde binary format).
//!
//! Loading never rebuilds the tree, but it checks the checksum, re-validates
//! the map and holds the tree to the compiler's invariants, so a corrupt or
//! hostile file is an error, not a panic and not a wrong picture.

use serde::{Deserialize, Serialize};

use super::check::check_invariants;
use super::{Bsp, BuildStats, CompiledMap};
use crate::grid::Grid;
use crate::map::validate::validate;

/// First bytes of every compiled map.
pub const MAGIC: &[u8] = b"SIGHTLINE-BSP\n";
/// Bumped whenever the layout below changes; older files are refused.
/// (6: a grid door's panel faces are `door` lines; a version 5 file of a grid
/// map would otherwise fail as "its grid and its map disagree". 7: sector
/// tags, line triggers and the map's sky texture. 8: the map as RON text,
/// for map format 2's specials.)
pub const VERSION: u8 = 8;

/// What the file holds. The map goes as its RON source: loading validates it
/// again anyway, and postcard, not being self-describing, cannot carry the
/// defaults the specials leave out when written.
#[derive(Serialize, Deserialize)]
struct Contents {
    map: String,
    bsp: Bsp,
    stats: BuildStats,
    grid: Option<Grid>,
}

pub fn is_compiled(bytes: &[u8]) -> bool {
    bytes.starts_with(MAGIC)
}

pub fn to_bytes(compiled: &CompiledMap) -> Vec<u8> {
    let contents = Contents {
        map: compiled.map.to_source().to_ron(),
        bsp: compiled.bsp.clone(),
        stats: compiled.stats.clone(),
        grid: compiled.grid.clone(),
    };
    // Serializing plain in-memory data into a Vec cannot fail.
    let payload = postcard::to_stdvec(&contents).unwrap_or_default();
    let mut bytes = MAGIC.to_vec();
    bytes.push(VERSION);
    bytes.extend(crc32fast::hash(&payload).to_le_bytes());
    bytes.extend(payload);
    bytes
}

/// Decodes a compiled map; the error says what is wrong with it.
pub fn from_bytes(bytes: &[u8]) -> Result<CompiledMap, String> {
    let rest = bytes.strip_prefix(MAGIC).ok_or("not a compiled map (bad header)")?;
    let (&version, payload) = rest.split_first().ok_or("truncated after the header")?;
    if version != VERSION {
        return Err(format!("format version {version}, this build reads version {VERSION}; recompile the map"));
    }
    let (checksum, payload) = payload.split_first_chunk::<4>().ok_or("truncated after the header")?;
    if crc32fast::hash(payload) != u32::from_le_bytes(*checksum) {
        return Err("corrupt or truncated: checksum mismatch".into());
    }
    let contents: Contents = postcard::from_bytes(payload).map_err(|e| format!("corrupt or truncated: {e}"))?;
    // Validate again, from source: the bytes may have been tampered with.
    let source = crate::map::load::parse_source(contents.map.as_bytes(), "the compiled map")
        .map_err(|e| format!("its map does not parse: {e}"))?;
    let map = validate(&source).map_err(|problems| {
        let first = problems.first().map(|p| p.to_string()).unwrap_or_default();
        format!("its map is invalid: {first}")
    })?;
    // A file can be well-formed and checksummed yet hand-made: hold its tree to
    // every promise the compiler makes (a few ms even for large maps).
    check_invariants(&map, &contents.bsp)?;
    // A grid must be sound and be exactly the grid the map was compiled from.
    if let Some(grid) = &contents.grid {
        crate::grid::load::check(grid).map_err(|e| format!("its grid is invalid: {e}"))?;
        if validate(&crate::grid::compile(grid).0).ok().as_ref() != Some(&map) {
            return Err("its grid and its map disagree".into());
        }
    }
    Ok(CompiledMap { map, bsp: contents.bsp, stats: contents.stats, grid: contents.grid })
}
