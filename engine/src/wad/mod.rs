//! Reading Doom's WAD files: the lump directory ([`Wad`]), the map lumps
//! ([`level`]), the art ([`art`]: palette, patches, composite textures, flats,
//! sprites), and turning a map into a Sightline RON map with its PNGs
//! ([`import`]).
//!
//! A WAD is untrusted input. Every read is bounds-checked and every failure is
//! a [`WadError`] naming the file and the lump (and the record in it), never a
//! panic. Nothing is allocated from a count in the file without first checking
//! that the bytes the count implies are there, so a corrupt header cannot ask
//! for gigabytes. The format is the one id's Doom reads (the "Unofficial Doom
//! Specs" 1.666 describe it): a 12-byte header, a directory of 16-byte
//! entries, little-endian integers.

pub mod art;
pub mod import;
pub mod level;
pub mod library;
pub mod specials;
pub mod udmf;
pub mod udmf_records;
#[cfg(test)]
mod udmf_tests;

use std::path::Path;

/// Why a WAD, or a lump in it, could not be read.
#[derive(Debug, thiserror::Error)]
pub enum WadError {
    #[error("{path}: cannot read: {error}")]
    Io { path: String, error: std::io::Error },
    #[error("{path}: {message}")]
    Header { path: String, message: String },
    /// Something wrong inside one lump: `lump` is its name, with its map when it
    /// is a map lump (`E1M4/LINEDEFS`).
    #[error("{path}: lump {lump}: {message}")]
    Lump { path: String, lump: String, message: String },
    #[error("{path}: lump {lump} is missing{context}")]
    Missing { path: String, lump: String, context: String },
    #[error("{path}: no map named {name}; the maps are: {available}")]
    NoMap { path: String, name: String, available: String },
}

/// One entry of the directory: a named byte range of the file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lump {
    pub name: String,
    pub offset: usize,
    pub size: usize,
}

/// A WAD file held in memory with its checked directory.
pub struct Wad {
    /// The file's name, for errors.
    pub path: String,
    pub data: Vec<u8>,
    pub lumps: Vec<Lump>,
    /// `true` for an IWAD, `false` for a PWAD.
    pub iwad: bool,
}

/// Bytes in the header and in each directory entry.
const HEADER: usize = 12;
const ENTRY: usize = 16;

impl Wad {
    pub fn open(path: &Path) -> Result<Wad, WadError> {
        let label = path.display().to_string();
        let data = std::fs::read(path).map_err(|error| WadError::Io { path: label.clone(), error })?;
        Wad::from_bytes(data, &label)
    }

    /// Parses the header and directory of `data`; `label` names it in errors.
    pub fn from_bytes(data: Vec<u8>, label: &str) -> Result<Wad, WadError> {
        let header = |message: String| WadError::Header { path: label.to_string(), message };
        if data.len() < HEADER {
            return Err(header(format!("truncated: {} bytes, shorter than the 12-byte header", data.len())));
        }
        let iwad = match &data[0..4] {
            b"IWAD" => true,
            b"PWAD" => false,
            other => return Err(header(format!("not a WAD: it starts with {:?}, not IWAD or PWAD", escape(other)))),
        };
        let count = i32_at(&data, 4);
        let table = i32_at(&data, 8);
        if count < 0 || table < 0 {
            return Err(header(format!("negative lump count ({count}) or directory offset ({table})")));
        }
        let (count, table) = (count as usize, table as usize);
        // Checked before allocating: the directory must fit in the file.
        let end = count.checked_mul(ENTRY).and_then(|n| n.checked_add(table));
        if end.is_none_or(|end| end > data.len()) {
            return Err(header(format!(
                "the directory of {count} lumps at byte {table} runs past the end of the file ({} bytes)",
                data.len()
            )));
        }
        let mut lumps = Vec::with_capacity(count);
        for k in 0..count {
            let at = table + k * ENTRY;
            let name = lump_name(&data[at + 8..at + 16]);
            let (offset, size) = (i32_at(&data, at), i32_at(&data, at + 4));
            let fits = offset >= 0
                && size >= 0
                && (offset as usize).checked_add(size as usize).is_some_and(|e| e <= data.len());
            if !fits {
                return Err(WadError::Lump {
                    path: label.to_string(),
                    lump: format!("{name} (directory entry {k})"),
                    message: format!("{size} bytes at offset {offset} lie outside the file ({} bytes)", data.len()),
                });
            }
            lumps.push(Lump { name, offset: offset as usize, size: size as usize });
        }
        Ok(Wad { path: label.to_string(), data, lumps, iwad })
    }

    /// The bytes of directory entry `index`.
    pub fn bytes(&self, index: usize) -> &[u8] {
        let l = &self.lumps[index];
        &self.data[l.offset..l.offset + l.size]
    }

    /// The last lump named `name` (later lumps override earlier ones, as in Doom).
    pub fn find(&self, name: &str) -> Option<usize> {
        self.lumps.iter().rposition(|l| l.name.eq_ignore_ascii_case(name))
    }

    /// The bytes of the lump `name`, or an error saying what needed it.
    pub fn lump(&self, name: &str, context: &str) -> Result<&[u8], WadError> {
        self.find(name).map(|i| self.bytes(i)).ok_or_else(|| self.missing(name, context))
    }

    pub fn missing(&self, lump: &str, context: &str) -> WadError {
        WadError::Missing { path: self.path.clone(), lump: lump.to_string(), context: context.to_string() }
    }

    pub fn error(&self, lump: &str, message: impl Into<String>) -> WadError {
        WadError::Lump { path: self.path.clone(), lump: lump.to_string(), message: message.into() }
    }

    /// The names of the maps, in directory order: a map is a marker lump
    /// followed directly by THINGS, or by TEXTMAP for a UDMF map (Doom's own
    /// test in P_SetupLevel is the name alone; looking at the next lump also
    /// finds maps with odd names).
    pub fn map_names(&self) -> Vec<String> {
        self.lumps
            .windows(2)
            .filter(|w| {
                (w[1].name == "THINGS" || w[1].name == udmf::TEXTMAP) && !level::MAP_LUMPS.contains(&w[0].name.as_str())
            })
            .map(|w| w[0].name.clone())
            .collect()
    }

    /// Directory indices of the lumps between any of the `start` markers
    /// and the next `end` marker (F_START or FF_START to F_END or FF_END), in
    /// directory order: a PWAD stacked on an IWAD ([`Wad::stack`]) adds a
    /// second run. Empty lumps (inner markers such as F1_START) are skipped.
    pub fn namespace(&self, start: &[&str], end: &[&str]) -> Result<Vec<usize>, WadError> {
        let mut found = Vec::new();
        let mut k = 0;
        let mut runs = 0;
        while let Some(from) = self.lumps[k..].iter().position(|l| start.contains(&l.name.as_str())).map(|p| k + p) {
            let to = self.lumps[from..]
                .iter()
                .position(|l| end.contains(&l.name.as_str()))
                .map(|p| from + p)
                .ok_or_else(|| self.missing(end[0], &format!(" (after {})", self.lumps[from].name)))?;
            found.extend(((from + 1)..to).filter(|&i| self.lumps[i].size > 0));
            runs += 1;
            k = to + 1;
        }
        if runs == 0 {
            return Err(self.missing(start[0], ""));
        }
        Ok(found)
    }

    /// WADs read as one, later ones over earlier ones (a PWAD on its IWAD,
    /// as `doom -iwad doom2.wad -file map.wad`): lumps of the same name in a
    /// later WAD replace those before, and namespaces (flats, sprites) join.
    pub fn stack(wads: Vec<Wad>) -> Wad {
        let mut data = Vec::new();
        let mut lumps = Vec::new();
        let path = wads.iter().map(|w| w.path.as_str()).collect::<Vec<_>>().join(" + ");
        let iwad = wads.first().is_some_and(|w| w.iwad);
        for w in wads {
            let base = data.len();
            lumps.extend(w.lumps.into_iter().map(|l| Lump { offset: l.offset + base, ..l }));
            data.extend(w.data);
        }
        Wad { path, data, lumps, iwad }
    }
}

/// A WAD's bytes: `kind` (`b"IWAD"` or `b"PWAD"`), the lumps in order, the
/// directory at the end, as Doom editors write one. A name longer than 8
/// bytes is cut to 8.
pub fn wad_bytes<N: AsRef<str>, B: AsRef<[u8]>>(kind: &[u8; 4], lumps: &[(N, B)]) -> Vec<u8> {
    let mut data = kind.to_vec();
    data.extend((lumps.len() as i32).to_le_bytes());
    data.extend(0i32.to_le_bytes()); // the directory's offset, known at the end
    let mut dir = Vec::with_capacity(lumps.len() * ENTRY);
    for (name, bytes) in lumps {
        let (name, bytes) = (name.as_ref().as_bytes(), bytes.as_ref());
        dir.extend((data.len() as i32).to_le_bytes());
        dir.extend((bytes.len() as i32).to_le_bytes());
        let mut padded = [0u8; 8];
        let n = name.len().min(8);
        padded[..n].copy_from_slice(&name[..n]);
        dir.extend(padded);
        data.extend(bytes);
    }
    let table = data.len() as i32;
    data[8..12].copy_from_slice(&table.to_le_bytes());
    data.extend(dir);
    data
}

/// A lump name: up to 8 bytes, NUL-padded, upper-cased as Doom does
/// (W_CheckNumForName compares upper case). Bytes outside printable ASCII
/// are shown escaped so that a corrupt name still prints.
pub fn lump_name(bytes: &[u8]) -> String {
    let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
    escape(&bytes[..end]).to_ascii_uppercase()
}

fn escape(bytes: &[u8]) -> String {
    bytes.iter().flat_map(|&b| std::ascii::escape_default(b)).map(char::from).collect()
}

/// Little-endian reads; callers have checked the bounds.
pub(crate) fn i32_at(b: &[u8], at: usize) -> i32 {
    i32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
}

pub(crate) fn i16_at(b: &[u8], at: usize) -> i16 {
    i16::from_le_bytes([b[at], b[at + 1]])
}

pub(crate) fn u16_at(b: &[u8], at: usize) -> u16 {
    u16::from_le_bytes([b[at], b[at + 1]])
}

#[cfg(test)]
mod tests;
