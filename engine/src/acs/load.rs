//! Reads a BEHAVIOR lump into a [`Module`]: the header (Hexen's ACS0, or
//! ZDoom's chunked ACSE/ACSe, bare or behind an ACS0 header), the chunks
//! (scripts, functions, strings, map variables and arrays, libraries), then
//! hands the code to `decode` so every instruction is checked before a
//! script runs. Every count is checked against the bytes that hold it before
//! anything is allocated from it.

use std::collections::BTreeMap;

use thiserror::Error;

use super::decode::{self, Code};
use super::text::{decrypt, unescape};
use super::ScriptKind;

/// A BEHAVIOR lump that could not be read: which lump, and what is wrong.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
#[error("{lump}: {problem}")]
pub struct LoadError {
    /// The lump as the caller named it (for example "BEHAVIOR of MAP01 in basic.wad").
    pub lump: String,
    pub problem: Problem,
}

/// What is wrong with a BEHAVIOR lump. Offsets are bytes from the lump's start.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
pub enum Problem {
    #[error("{0} bytes is too short for an ACS header (8 bytes)")]
    TooShort(usize),
    #[error("header {0:?} is not ACS\\0, ACSE or ACSe")]
    BadMagic(String),
    #[error("directory offset {0} lies outside the lump")]
    BadDirectory(u32),
    #[error("chunk {id} at byte {at} declares {size} bytes, past the end of the chunks at byte {end}")]
    ChunkOverrun { id: String, at: usize, size: u32, end: usize },
    #[error("chunk {chunk} at byte {at}: {what}")]
    BadChunk { chunk: String, at: usize, what: String },
    #[error("the old-format script directory at byte {at} lists {count} scripts, more than the lump holds")]
    BadDirectoryCount { at: usize, count: u32 },
    #[error("string {index} at byte {at} is not terminated inside its table")]
    UnterminatedString { index: usize, at: usize },
    #[error("the module loads the libraries {0}; ACS libraries are not supported")]
    Libraries(String),
    #[error("function {0} is imported from a library; ACS libraries are not supported")]
    ImportedFunction(String),
    #[error("{owner} starts at byte {offset}, outside the code (bytes 0..{end})")]
    BadEntry { owner: String, offset: u32, end: usize },
    #[error("unknown pcode {pcode} at byte {offset}")]
    UnknownPcode { pcode: u32, offset: usize },
    #[error("pcode {pcode} ({name}) at byte {offset} is not supported")]
    UnsupportedPcode { pcode: u16, name: &'static str, offset: usize },
    #[error("{name} at byte {offset} runs past the end of the code (byte {end})")]
    Truncated { name: &'static str, offset: usize, end: usize },
    #[error("{name} at byte {offset} jumps to byte {target}, outside the code")]
    BadJump { name: &'static str, offset: usize, target: i64 },
    #[error("{name} at byte {offset} uses {what} {index}; only {limit} exist")]
    BadIndex { name: &'static str, offset: usize, what: &'static str, index: i64, limit: usize },
    #[error("extended function {id} ({name}) called at byte {offset} is not supported by the host")]
    UnsupportedFunction { id: u16, name: &'static str, offset: usize },
}

/// Which encoding the code uses (ZDoom's `ACSFormat`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Hexen's ACS0: four-byte pcodes and operands, no chunks.
    Old,
    /// ACSE: chunks, four-byte pcodes and operands.
    Enhanced,
    /// ACSe: chunks, one-byte pcodes (two above 239) and one-byte index operands.
    LittleEnhanced,
}

/// Map variables per module (ZDoom's `NUM_MAPVARS`).
pub const MAP_VARS: usize = 128;
/// Locals of one script or function, arrays included, and elements of all
/// map arrays together: far above what acc's own limits let a source
/// declare, low enough that a corrupt count cannot exhaust memory.
const MAX_LOCALS: usize = 1 << 20;
const MAX_ARRAY_ELEMENTS: usize = 1 << 24;

/// Local variables of a script without an SVCT entry (ZDoom's `LOCAL_SIZE`).
pub const DEFAULT_SCRIPT_VARS: u16 = 20;

/// An array inside a script's or function's locals (SARY, FARY).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LocalArray {
    pub offset: usize,
    pub size: usize,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Script {
    /// Positive for numbered scripts; named scripts get -1, -2, ... in SNAM order.
    pub number: i32,
    pub name: Option<String>,
    pub kind: ScriptKind,
    pub args: u8,
    /// Local variables including the arguments and any local arrays.
    pub vars: usize,
    pub flags: u16,
    pub arrays: Vec<LocalArray>,
    pub address: u32,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Function {
    pub name: Option<String>,
    pub args: u8,
    /// Locals beyond the arguments, including local arrays.
    pub locals: usize,
    pub returns: bool,
    pub arrays: Vec<LocalArray>,
    pub address: u32,
}

/// A map array (ARAY): the map variable that names it, its size and AINI's values.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MapArray {
    pub var: u32,
    pub size: usize,
    pub init: Vec<i32>,
}

/// A loaded BEHAVIOR lump: what it declares and its decoded code.
#[derive(Clone, Debug)]
pub struct Module {
    /// The label it was loaded under, for messages.
    pub lump: String,
    pub format: Format,
    /// Sorted by number, as ZDoom sorts them (named scripts, negative, first).
    pub scripts: Vec<Script>,
    pub functions: Vec<Function>,
    pub strings: Vec<String>,
    /// Initial values of the 128 map variables (MINI); an array's variable holds its index.
    pub map_vars: Vec<i32>,
    /// Exported map variable names (MEXP), by variable.
    pub map_var_names: BTreeMap<u32, String>,
    /// Map variables (MSTR) and arrays (ASTR) that hold strings.
    pub string_vars: Vec<u32>,
    pub string_arrays: Vec<u32>,
    pub arrays: Vec<MapArray>,
    /// Code offsets of GOTOSTACK targets (JUMP).
    pub jumps: Vec<u32>,
    pub code: Code,
}

impl Module {
    /// Reads `bytes`; `lump` names it in errors.
    pub fn load(bytes: &[u8], lump: &str) -> Result<Module, LoadError> {
        let mut module = read(bytes).map_err(|problem| LoadError { lump: lump.to_string(), problem })?;
        module.lump = lump.to_string();
        Ok(module)
    }

    /// The script with this number (negative for named scripts).
    pub fn script(&self, number: i32) -> Option<&Script> {
        let i = self.scripts.binary_search_by_key(&number, |s| s.number).ok()?;
        self.scripts.get(i)
    }

    /// The number of the script with this name (case-insensitive, as ZDoom's names are).
    pub fn named(&self, name: &str) -> Option<i32> {
        self.scripts.iter().find(|s| s.name.as_deref().is_some_and(|n| n.eq_ignore_ascii_case(name))).map(|s| s.number)
    }
}

pub(super) fn u32_at(b: &[u8], at: usize) -> Option<u32> {
    let s = b.get(at..at.checked_add(4)?)?;
    Some(u32::from_le_bytes([s[0], s[1], s[2], s[3]]))
}

fn u16_at(b: &[u8], at: usize) -> Option<u16> {
    let s = b.get(at..at.checked_add(2)?)?;
    Some(u16::from_le_bytes([s[0], s[1]]))
}

/// One chunk: its id, where its data starts in the lump, and the data.
struct Chunk<'a> {
    id: [u8; 4],
    at: usize,
    data: &'a [u8],
}

impl Chunk<'_> {
    fn name(&self) -> String {
        String::from_utf8_lossy(&self.id).into_owned()
    }

    fn bad(&self, what: impl Into<String>) -> Problem {
        Problem::BadChunk { chunk: self.name(), at: self.at, what: what.into() }
    }

    fn u32(&self, at: usize) -> Result<u32, Problem> {
        u32_at(self.data, at).ok_or_else(|| self.bad(format!("a value at byte {at} of the chunk lies past its end")))
    }
}

fn read(b: &[u8]) -> Result<Module, Problem> {
    if b.len() < 8 {
        return Err(Problem::TooShort(b.len()));
    }
    let dir = u32_at(b, 4).unwrap_or(0);
    let magic = &b[..4];
    match magic {
        b"ACS\0" => {
            // An ACSE/ACSe module behind an old header (what acc writes): the
            // directory offset points just past the tag, and the word before the
            // tag is where the chunks start (ZDoom's FBehavior::Init).
            let d = dir as usize;
            let tag = d.checked_sub(4).and_then(|t| b.get(t..d));
            if d >= 24 && d <= b.len() && matches!(tag, Some(b"ACSE") | Some(b"ACSe")) {
                let format = if tag == Some(b"ACSe") { Format::LittleEnhanced } else { Format::Enhanced };
                let chunks = u32_at(b, d - 8).unwrap_or(u32::MAX) as usize;
                let end = d - 8;
                if chunks > end {
                    return Err(Problem::BadDirectory(dir));
                }
                read_chunked(b, format, chunks, end, true)
            } else {
                read_old(b, dir)
            }
        }
        b"ACSE" | b"ACSe" => {
            let format = if magic == b"ACSe" { Format::LittleEnhanced } else { Format::Enhanced };
            if dir as usize > b.len() {
                return Err(Problem::BadDirectory(dir));
            }
            read_chunked(b, format, dir as usize, b.len(), false)
        }
        _ => Err(Problem::BadMagic(String::from_utf8_lossy(magic).into_owned())),
    }
}

/// Hexen's format: at the directory, a script count and (number + 1000 × type,
/// address, argument count) triples, then the string count and offsets.
fn read_old(b: &[u8], dir: u32) -> Result<Module, Problem> {
    let d = dir as usize;
    let count = u32_at(b, d).ok_or(Problem::BadDirectory(dir))?;
    let table_end = (count as usize).checked_mul(12).and_then(|n| n.checked_add(d + 4));
    if table_end.is_none_or(|e| e > b.len()) {
        return Err(Problem::BadDirectoryCount { at: d, count });
    }
    let mut scripts = Vec::with_capacity(count as usize);
    for i in 0..count as usize {
        let at = d + 4 + i * 12;
        let raw = u32_at(b, at).unwrap_or(0);
        scripts.push(Script {
            number: (raw % 1000) as i32,
            name: None,
            kind: ScriptKind::from_code((raw / 1000) as u8),
            args: u32_at(b, at + 8).unwrap_or(0).min(255) as u8,
            vars: usize::from(DEFAULT_SCRIPT_VARS),
            flags: 0,
            arrays: Vec::new(),
            address: u32_at(b, at + 4).unwrap_or(0),
        });
    }
    sort_scripts(&mut scripts);
    let strings_at = table_end.unwrap_or(b.len());
    let strings = read_string_table(b, strings_at, 0, b)?;
    let mut module = Module {
        lump: String::new(),
        format: Format::Old,
        scripts,
        functions: Vec::new(),
        strings,
        map_vars: vec![0; MAP_VARS],
        map_var_names: BTreeMap::new(),
        string_vars: Vec::new(),
        string_arrays: Vec::new(),
        arrays: Vec::new(),
        jumps: Vec::new(),
        code: Code::default(),
    };
    // Strings live between the code and the directory, so the code ends there.
    module.code = decode::decode(b, d, &module)?;
    Ok(module)
}

/// ZDoom sorts scripts by number and, for old lumps with a duplicate number,
/// puts a closed script first; a stable sort keeps the lump's order otherwise.
fn sort_scripts(scripts: &mut [Script]) {
    scripts.sort_by_key(|s| (s.number, s.kind != ScriptKind::Closed));
}

/// A string table: a count at `at` (after `pad` bytes), then offsets relative
/// to `base`'s start, each string NUL-terminated inside `base`.
fn read_string_table(b: &[u8], at: usize, pad: usize, base: &[u8]) -> Result<Vec<String>, Problem> {
    let count = u32_at(b, at).ok_or(Problem::BadDirectory(at as u32))? as usize;
    let first = at + 4 + pad;
    if count.checked_mul(4).and_then(|n| n.checked_add(first)).is_none_or(|e| e > b.len()) {
        return Err(Problem::BadDirectoryCount { at, count: count as u32 });
    }
    (0..count)
        .map(|i| {
            let ofs = u32_at(b, first + i * 4).unwrap_or(u32::MAX) as usize;
            c_string(base, ofs).map(unescape).ok_or(Problem::UnterminatedString { index: i, at: ofs })
        })
        .collect()
}

fn c_string(b: &[u8], at: usize) -> Option<&[u8]> {
    let rest = b.get(at..)?;
    let len = rest.iter().position(|&c| c == 0)?;
    Some(&rest[..len])
}

fn read_chunked(b: &[u8], format: Format, start: usize, end: usize, wrapped: bool) -> Result<Module, Problem> {
    let mut chunks = Vec::new();
    let mut at = start;
    while at + 8 <= end {
        let id = [b[at], b[at + 1], b[at + 2], b[at + 3]];
        let size = u32_at(b, at + 4).unwrap_or(0);
        let data_end = (at + 8).checked_add(size as usize).filter(|&e| e <= end);
        let Some(data_end) = data_end else {
            return Err(Problem::ChunkOverrun { id: String::from_utf8_lossy(&id).into_owned(), at, size, end });
        };
        chunks.push(Chunk { id, at, data: &b[at + 8..data_end] });
        at = data_end;
    }
    let find = |id: &[u8; 4]| chunks.iter().find(|c| &c.id == id);
    let all = |id: &'static [u8; 4]| chunks.iter().filter(move |c| &c.id == id);

    if let Some(load) = find(b"LOAD") {
        let names: Vec<String> = load
            .data
            .split(|&c| c == 0)
            .filter(|n| !n.is_empty())
            .map(|n| String::from_utf8_lossy(n).into_owned())
            .collect();
        if !names.is_empty() {
            return Err(Problem::Libraries(names.join(", ")));
        }
    }

    let mut scripts = match find(b"SPTR") {
        // ZDoom reads the 8-byte entries when the lump starts with ACS\0 and
        // the 12-byte (intermediate) ones when it starts with ACSE/ACSe.
        Some(c) if wrapped => (0..c.data.len() / 8)
            .map(|i| {
                let e = &c.data[i * 8..i * 8 + 8];
                script(i16::from_le_bytes([e[0], e[1]]), e[2], e[3], u32_at(e, 4).unwrap_or(0))
            })
            .collect(),
        Some(c) => (0..c.data.len() / 12)
            .map(|i| {
                let e = &c.data[i * 12..i * 12 + 12];
                let args = u32_at(e, 8).unwrap_or(0).min(255) as u8;
                script(i16::from_le_bytes([e[0], e[1]]), e[2], args, u32_at(e, 4).unwrap_or(0))
            })
            .collect(),
        None => Vec::new(),
    };
    if let Some(c) = find(b"SNAM") {
        let names = name_table(c)?;
        for s in &mut scripts {
            if s.number < 0 {
                let i = (-(s.number as i64) - 1) as usize;
                s.name =
                    Some(names.get(i).cloned().ok_or_else(|| c.bad(format!("no name {i} for script {}", s.number)))?);
            }
        }
    }
    sort_scripts(&mut scripts);
    for (id, flags) in [(b"SFLG", true), (b"SVCT", false)] {
        if let Some(c) = find(id) {
            for e in c.data.chunks_exact(4) {
                let number = i32::from(i16::from_le_bytes([e[0], e[1]]));
                let value = u16::from_le_bytes([e[2], e[3]]);
                if let Some(s) = scripts.iter_mut().find(|s| s.number == number) {
                    if flags {
                        s.flags = value;
                    } else {
                        s.vars = usize::from(value);
                    }
                }
            }
        }
    }
    for c in all(b"SARY") {
        let number = i32::from(u16_at(c.data, 0).ok_or_else(|| c.bad("no script number"))? as i16);
        if let Some(s) = scripts.iter_mut().find(|s| s.number == number) {
            s.vars = local_arrays(c, s.vars, &mut s.arrays)?;
        }
    }

    let mut functions = Vec::new();
    if let Some(c) = find(b"FUNC") {
        let names = find(b"FNAM").map(name_table).transpose()?.unwrap_or_default();
        for (i, e) in c.data.chunks_exact(8).enumerate() {
            let name = names.get(i).cloned();
            let address = u32_at(e, 4).unwrap_or(0);
            if address == 0 || e[3] != 0 {
                return Err(Problem::ImportedFunction(name.unwrap_or_else(|| format!("#{i}"))));
            }
            let f = Function {
                name,
                args: e[0],
                locals: usize::from(e[1]),
                returns: e[2] != 0,
                arrays: Vec::new(),
                address,
            };
            functions.push(f);
        }
    }
    for c in all(b"FARY") {
        let index = usize::from(u16_at(c.data, 0).ok_or_else(|| c.bad("no function number"))?);
        if let Some(f) = functions.get_mut(index) {
            // Function arrays sit after the arguments and locals.
            let args = usize::from(f.args);
            f.locals = local_arrays(c, f.locals + args, &mut f.arrays)? - args;
        }
    }

    let strings = match (find(b"STRL"), find(b"STRE")) {
        (Some(c), _) => read_string_table(c.data, 4, 4, c.data).map_err(|p| c.bad(p.to_string()))?,
        (None, Some(c)) => {
            let plain = decrypt(c.data);
            read_string_table(&plain, 4, 4, &plain).map_err(|p| c.bad(p.to_string()))?
        }
        (None, None) => Vec::new(),
    };

    let mut map_vars = vec![0; MAP_VARS];
    for c in all(b"MINI") {
        let first = c.u32(0)? as usize;
        let values = &c.data[4.min(c.data.len())..];
        let count = values.len() / 4;
        if first.checked_add(count).is_none_or(|e| e > MAP_VARS) {
            return Err(c.bad(format!("initialises map variables {first}..{}, only {MAP_VARS} exist", first + count)));
        }
        for i in 0..count {
            map_vars[first + i] = u32_at(values, i * 4).unwrap_or(0) as i32;
        }
    }
    let mut arrays = Vec::new();
    let mut total = 0usize;
    if let Some(c) = find(b"ARAY") {
        for (i, e) in c.data.chunks_exact(8).enumerate() {
            let var = u32_at(e, 0).unwrap_or(0);
            let size = u32_at(e, 4).unwrap_or(0) as usize;
            if var as usize >= MAP_VARS {
                return Err(c.bad(format!("array {i} is map variable {var}; only {MAP_VARS} exist")));
            }
            total += size;
            if total > MAX_ARRAY_ELEMENTS {
                return Err(
                    c.bad(format!("array {i} brings the map arrays to {total} elements, over {MAX_ARRAY_ELEMENTS}"))
                );
            }
            map_vars[var as usize] = i as i32;
            arrays.push(MapArray { var, size, init: Vec::new() });
        }
    }
    for c in all(b"AINI") {
        let var = c.u32(0)?;
        let values: Vec<i32> =
            c.data[4.min(c.data.len())..].chunks_exact(4).map(|v| u32_at(v, 0).unwrap_or(0) as i32).collect();
        match arrays.iter_mut().find(|a| a.var == var) {
            Some(a) => a.init = values.into_iter().take(a.size).collect(),
            None => return Err(c.bad(format!("initialises map variable {var}, which is not an array"))),
        }
    }
    let var_list = |id: &[u8; 4]| {
        find(id).map(|c| c.data.chunks_exact(4).map(|v| u32_at(v, 0).unwrap_or(0)).collect()).unwrap_or_default()
    };
    let string_vars = var_list(b"MSTR");
    let string_arrays = var_list(b"ASTR");
    let jumps = var_list(b"JUMP");
    let mut map_var_names = BTreeMap::new();
    if let Some(c) = find(b"MEXP") {
        for (i, name) in name_table(c)?.into_iter().enumerate() {
            map_var_names.insert(i as u32, name);
        }
    }

    // acc writes the code before the chunks; nothing may run into them.
    let mut module = Module {
        lump: String::new(),
        format,
        scripts,
        functions,
        strings,
        map_vars,
        map_var_names,
        string_vars,
        string_arrays,
        arrays,
        jumps,
        code: Code::default(),
    };
    module.code = decode::decode(b, start, &module)?;
    Ok(module)
}

fn script(number: i16, kind: u8, args: u8, address: u32) -> Script {
    Script {
        number: i32::from(number),
        name: None,
        kind: ScriptKind::from_code(kind),
        args,
        vars: usize::from(DEFAULT_SCRIPT_VARS),
        flags: 0,
        arrays: Vec::new(),
        address,
    }
}

/// SARY/FARY: a two-byte owner, then four-byte array sizes; the arrays are
/// laid out after `vars` locals. Returns the new local count.
fn local_arrays(c: &Chunk, mut vars: usize, arrays: &mut Vec<LocalArray>) -> Result<usize, Problem> {
    for s in c.data.get(2..).unwrap_or(&[]).chunks_exact(4) {
        let size = u32_at(s, 0).unwrap_or(0) as usize;
        if size > MAX_LOCALS - vars {
            return Err(c.bad(format!("local arrays of more than {MAX_LOCALS} elements")));
        }
        arrays.push(LocalArray { offset: vars, size });
        vars += size;
    }
    Ok(vars)
}

/// FNAM, SNAM, MEXP: a count, offsets relative to the chunk's data, names.
fn name_table(c: &Chunk) -> Result<Vec<String>, Problem> {
    let count = c.u32(0)? as usize;
    if count.checked_mul(4).is_none_or(|n| n + 4 > c.data.len()) {
        return Err(c.bad(format!("lists {count} names, more than it holds")));
    }
    (0..count)
        .map(|i| {
            let ofs = u32_at(c.data, 4 + i * 4).unwrap_or(u32::MAX) as usize;
            c_string(c.data, ofs)
                .map(|s| String::from_utf8_lossy(s).into_owned())
                .ok_or_else(|| c.bad(format!("name {i} at byte {ofs} of the chunk is not terminated")))
        })
        .collect()
}
