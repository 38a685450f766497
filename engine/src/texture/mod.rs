//! Textures: the stage between a map's texture names and the renderer's texel
//! loops. Each name resolves once, to a PNG under the map's `textures/` or
//! `sprites/` folder or to a built-in [`procedural`] texture, and is handed on
//! as a column-major [`Texture`] behind a [`TextureId`] in a [`TextureSet`].
//!
//! Column-major because walls and sprites are drawn a screen column at a time,
//! and one screen column samples one texture column: walking `v` down a
//! contiguous slice stays in cache, where row-major storage would stride by the
//! texture's width on every texel.

pub mod animdefs;
pub mod colours;
mod decode;
pub mod procedural;

#[cfg(test)]
mod preview;

use std::collections::HashMap;
use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::wad::library::WadArt;

pub use decode::MAX_SIDE;

/// A decoded image, ready for column sampling.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Texture {
    pub width: usize,
    pub height: usize,
    /// Column-major: texel (u, v) is `texels[u * height + v]`; v = 0 is the top row.
    /// Packed like [`crate::framebuffer::rgb`] (RGBA bytes, R first); alpha 0 is
    /// transparent, 255 opaque.
    pub texels: Vec<u32>,
    /// True when every texel's alpha is 255, so a renderer may skip the mask test.
    pub opaque: bool,
    /// The smallest box of columns `u0..u1` and rows `v0..v1` holding every
    /// texel a masked draw shows (alpha 128 and over), as `[u0, u1, v0, v1]`;
    /// empty (`u0 == u1`) for a wholly transparent texture. A screen picture
    /// drawn 320x200 (the procedural weapons) covers a small part of itself,
    /// and its blit walks only this box. Texels may be recoloured after
    /// construction but never made more or less transparent.
    pub shown: [usize; 4],
}

/// `i` wrapped into `0..size` (`size > 0`): a mask when `size` is a power
/// of two (most texture sizes, and so their fixed-point spans), else
/// `rem_euclid`'s integer division.
#[inline]
pub fn wrap(i: i64, size: i64) -> i64 {
    if size.count_ones() == 1 {
        i & (size - 1)
    } else {
        i.rem_euclid(size)
    }
}

/// [`Texture::shown`] of column-major texels.
fn shown_box(width: usize, height: usize, texels: &[u32]) -> [usize; 4] {
    let mut b = [width, 0, height, 0];
    for (u, column) in texels.chunks_exact(height).enumerate() {
        let shows = |t: &u32| t >> 24 >= 128;
        let (Some(first), Some(last)) = (column.iter().position(shows), column.iter().rposition(shows)) else {
            continue;
        };
        b = [b[0].min(u), u + 1, b[2].min(first), b[3].max(last + 1)];
    }
    if b[0] >= b[1] {
        [0, 0, 0, 0]
    } else {
        b
    }
}

impl Texture {
    /// Builds a texture from `f(u, v) -> [r, g, b, a]`, called column by column.
    ///
    /// Panics on a zero side: every texture in a set has at least one texel, so
    /// sampling never divides by zero (PNG loading rejects empty images first).
    pub fn from_fn(width: usize, height: usize, mut f: impl FnMut(usize, usize) -> [u8; 4]) -> Texture {
        assert!(width > 0 && height > 0, "texture of size {width}x{height}");
        let mut texels = Vec::with_capacity(width * height);
        for u in 0..width {
            for v in 0..height {
                texels.push(u32::from_le_bytes(f(u, v)));
            }
        }
        Texture::from_texels(width, height, texels)
    }

    /// Wraps column-major texels, working out [`Texture::opaque`].
    fn from_texels(width: usize, height: usize, texels: Vec<u32>) -> Texture {
        debug_assert_eq!(texels.len(), width * height);
        let opaque = texels.iter().all(|&t| t >> 24 == 0xff);
        let shown = if opaque { [0, width, 0, height] } else { shown_box(width, height, &texels) };
        Texture { width, height, texels, opaque, shown }
    }

    /// Reads a PNG file (any colour type and bit depth) into a texture.
    pub fn read_png(path: &Path) -> Result<Texture, TextureError> {
        decode::read_png(path)
    }

    /// Decodes PNG bytes; `path` only names the source in errors.
    pub fn decode_png(bytes: &[u8], path: &Path) -> Result<Texture, TextureError> {
        decode::decode_png(std::io::Cursor::new(bytes), path)
    }

    /// Texture column `u` wrapped into `0..width`: a mask for power-of-two
    /// widths (most textures), no integer division.
    #[inline]
    pub fn wrap_column(&self, u: i64) -> usize {
        wrap(u, self.width as i64) as usize
    }

    /// Column `u`, top texel first. `u < width`.
    #[inline]
    pub fn column(&self, u: usize) -> &[u32] {
        &self.texels[u * self.height..(u + 1) * self.height]
    }

    /// The texel at column `u`, row `v`; both in range.
    #[inline]
    pub fn texel(&self, u: usize, v: usize) -> u32 {
        debug_assert!(u < self.width && v < self.height);
        self.texels[u * self.height + v]
    }

    /// The texel at any integer coordinates, wrapped into range (negative ones
    /// too, by `rem_euclid`), so textures repeat in both directions whatever
    /// their size; no power-of-two masking.
    #[inline]
    pub fn wrapped(&self, u: i64, v: i64) -> u32 {
        let u = u.rem_euclid(self.width as i64) as usize;
        let v = v.rem_euclid(self.height as i64) as usize;
        self.texels[u * self.height + v]
    }

    /// Bilinear filtering at texture coordinates `(u, v)` (texel `i` covers
    /// `[i, i + 1)`, so texel centres are at `i + 0.5`), wrapping at the
    /// edges: the four nearest texels, weighted by closeness, per channel.
    /// Only the sampling study uses it; the renderer samples nearest, as Doom.
    pub fn bilinear(&self, u: f64, v: f64) -> u32 {
        let (u, v) = (u - 0.5, v - 0.5);
        let (u0, v0) = (u.floor(), v.floor());
        let (fu, fv) = (u - u0, v - v0);
        // Saturating casts: NaN becomes 0 and huge values clamp; both wrap in range.
        let (iu, iv) = (u0 as i64, v0 as i64);
        let texel = |du: i64, dv: i64| self.wrapped(iu.wrapping_add(du), iv.wrapping_add(dv)).to_le_bytes();
        let (a, b, c, d) = (texel(0, 0), texel(1, 0), texel(0, 1), texel(1, 1));
        let mut out = [0u8; 4];
        for k in 0..4 {
            let top = f64::from(a[k]) + (f64::from(b[k]) - f64::from(a[k])) * fu;
            let bottom = f64::from(c[k]) + (f64::from(d[k]) - f64::from(c[k])) * fu;
            out[k] = (top + (bottom - top) * fv).round().clamp(0.0, 255.0) as u8;
        }
        u32::from_le_bytes(out)
    }
}

/// An index into a [`TextureSet`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct TextureId(pub u32);

/// What a name is looked up as: wall textures live in `<map dir>/textures/`,
/// flats in `<map dir>/flats/` or else `textures/` (Doom keeps flats and
/// walls in two namespaces, so an imported WAD may use one name for both),
/// sprites in `<map dir>/sprites/`; the procedural textures are separate per
/// kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum TextureKind {
    Wall,
    Flat,
    Sprite,
    /// A picture drawn on the screen (a weapon, its flash), framed so that
    /// texel (0, 0) lands on Doom's 320x200 screen at the origin of a
    /// weapon at rest, less (1, 32) (see [`crate::screen::weapon`]).
    Screen,
}

impl TextureKind {
    /// The folders under a map directory that hold this kind's PNGs, in the
    /// order they are searched.
    pub fn subdirs(self) -> &'static [&'static str] {
        match self {
            TextureKind::Wall => &["textures"],
            TextureKind::Flat => &["flats", "textures"],
            TextureKind::Sprite => &["sprites"],
            TextureKind::Screen => &["screens"],
        }
    }
}

impl fmt::Display for TextureKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            TextureKind::Wall => "wall texture",
            TextureKind::Flat => "flat",
            TextureKind::Sprite => "sprite",
            TextureKind::Screen => "screen picture",
        })
    }
}

/// Why a texture name could not become a [`Texture`].
#[derive(Debug, thiserror::Error)]
pub enum TextureError {
    /// No file and no procedural texture has the name: says which files were
    /// tried and lists the procedural names of that kind.
    #[error(
        "{kind} {name:?} not found: tried {}; no procedural {kind} has that name (built in: {})",
        list_paths(tried),
        procedural::names(*kind).join(", ")
    )]
    Missing { name: String, kind: TextureKind, tried: Vec<PathBuf> },
    /// The name could escape the map's folder or name a hidden file.
    #[error("{kind} name {name:?} is not a plain file name (no path separators, no leading dot)")]
    BadName { name: String, kind: TextureKind },
    /// The file is unreadable or not a valid PNG: the path and the decoder's message.
    #[error("{}: cannot read PNG: {message}", path.display())]
    Png { path: PathBuf, message: String },
    /// The map's animations file could not be read or is invalid.
    #[error("{0}")]
    Animations(String),
    /// A side is 0 or above [`MAX_SIDE`]; refused from the header, before
    /// any pixel memory is allocated.
    #[error(
        "{}: PNG is {width}x{height}; textures must be 1 to {MAX_SIDE} texels on a side",
        path.display()
    )]
    Size { path: PathBuf, width: u32, height: u32 },
}

fn list_paths(paths: &[PathBuf]) -> String {
    if paths.is_empty() {
        return "no files (no map directories given)".to_string();
    }
    let shown: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    shown.join(", ")
}

/// Every texture a map uses, each loaded once, addressed by [`TextureId`].
///
/// Names are cached by exact spelling and kind, not by directory: a set
/// belongs to one map (one list of directories). Names that lead to the same
/// source (a wall and a flat both named SKY, or `brick` and `BRICK` when no
/// file tells them apart) share one texture and one id.
#[derive(Clone, Debug, Default)]
pub struct TextureSet {
    /// Shared, so a copied level (a scenario's game copied for each
    /// episode) shares its texels.
    textures: Vec<std::sync::Arc<Texture>>,
    names: Vec<String>,
    ids: HashMap<(String, TextureKind), TextureId>,
    sources: HashMap<Source, TextureId>,
}

/// Where a map's art is looked for, in order, before the built-in set:
/// folders of PNGs (`textures/`, `flats/`, `sprites/` in each), then a WAD.
#[derive(Clone, Default)]
pub struct Library {
    pub dirs: Vec<PathBuf>,
    pub wad: Option<Arc<WadArt>>,
}

impl Library {
    pub fn dirs(dirs: &[PathBuf]) -> Library {
        Library { dirs: dirs.to_vec(), wad: None }
    }
}

/// Where a texture's texels come from.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Source {
    File(PathBuf),
    /// A lump of the library's WAD, by its (upper-case) name.
    Wad(String, TextureKind),
    /// A procedural texture, by its canonical (upper-case) name; the painters
    /// depend on the name alone, so the kind is not part of the key.
    Builtin(&'static str),
}

impl TextureSet {
    pub fn new() -> TextureSet {
        TextureSet::default()
    }

    /// Resolves `name` once (later calls return the cached id): the first of
    /// `<dir>/<kind subdir>/<name>.png`, then the lower-case `<name>.png`, for
    /// each dir in `dirs` in order; then the procedural texture of that name
    /// (case-insensitive); else [`TextureError::Missing`]. A file that exists
    /// but does not decode is an error, not a reason to fall back, so a broken
    /// art file is never silently replaced by a built-in look.
    pub fn resolve(&mut self, name: &str, kind: TextureKind, dirs: &[PathBuf]) -> Result<TextureId, TextureError> {
        self.resolve_in(name, kind, &Library::dirs(dirs))
    }

    /// [`TextureSet::resolve`] in a library: its folders, then its WAD,
    /// then the built-in set.
    pub fn resolve_in(&mut self, name: &str, kind: TextureKind, library: &Library) -> Result<TextureId, TextureError> {
        let key = (name.to_string(), kind);
        if let Some(&id) = self.ids.get(&key) {
            return Ok(id);
        }
        let source = find(name, kind, library)?;
        let id = match self.sources.get(&source) {
            Some(&id) => id,
            None => {
                let texture = match &source {
                    Source::File(path) => decode::read_png(path)?,
                    Source::Wad(lump, kind) => match &library.wad {
                        Some(wad) => wad.texture(lump, *kind)?,
                        None => unreachable!("a WAD source comes from a library with a WAD"),
                    },
                    Source::Builtin(canonical) => {
                        procedural::generate(canonical, kind).unwrap_or_else(|| unreachable!("{canonical} was listed"))
                    }
                };
                // Ids are u32 to keep map data small; four billion textures
                // would not fit in memory first.
                let id = TextureId(self.textures.len() as u32);
                self.textures.push(std::sync::Arc::new(texture));
                self.names.push(name.to_string());
                self.sources.insert(source, id);
                id
            }
        };
        self.ids.insert(key, id);
        Ok(id)
    }

    /// Adds `texture`, made in play (a sprite in a player's colour), under
    /// `name`; names are not looked up for it.
    pub fn add(&mut self, name: String, texture: Texture) -> TextureId {
        let id = TextureId(self.textures.len() as u32);
        self.textures.push(std::sync::Arc::new(texture));
        self.names.push(name);
        id
    }

    /// Adds `texture` drawn for `name` of `kind` where nothing else had
    /// that name (a stand-in, a placeholder): later lookups of the name
    /// find it.
    pub fn insert(&mut self, name: &str, kind: TextureKind, texture: Arc<Texture>) -> TextureId {
        if let Some(&id) = self.ids.get(&(name.to_string(), kind)) {
            return id;
        }
        let id = TextureId(self.textures.len() as u32);
        self.textures.push(texture);
        self.names.push(name.to_string());
        self.ids.insert((name.to_string(), kind), id);
        id
    }

    /// The id `name` already resolved to, if it has.
    pub fn find(&self, name: &str, kind: TextureKind) -> Option<TextureId> {
        self.ids.get(&(name.to_string(), kind)).copied()
    }

    pub fn get(&self, id: TextureId) -> &Texture {
        &self.textures[id.0 as usize]
    }

    /// The name as the map spelled it (the first spelling, when several names
    /// share the texture).
    pub fn name(&self, id: TextureId) -> &str {
        &self.names[id.0 as usize]
    }

    pub fn len(&self) -> usize {
        self.textures.len()
    }

    pub fn is_empty(&self) -> bool {
        self.textures.is_empty()
    }
}

/// Where `name` comes from, without loading it.
fn find(name: &str, kind: TextureKind, library: &Library) -> Result<Source, TextureError> {
    let dirs = &library.dirs;
    // A name is joined onto a directory, so a map must not be able to reach
    // outside it ("../../etc/x"), name a hidden file, or (on Windows) a drive.
    let plain = !name.is_empty() && !name.starts_with('.') && !name.contains(['/', '\\', '\0', ':']);
    if !plain {
        // A WAD's lump names are no paths: Doom's sprite frame `\` (the
        // arch-vile's VILE\1) is found there, never beside the map. The
        // WAD's index keeps names as `wad::lump_name` escapes them (a
        // backslash doubled).
        let lump = name.to_ascii_uppercase().replace('\\', "\\\\");
        return match library.wad.as_ref().filter(|w| w.has(&lump, kind)) {
            Some(_) => Ok(Source::Wad(lump, kind)),
            None => Err(TextureError::BadName { name: name.to_string(), kind }),
        };
    }
    let lower = name.to_lowercase();
    let mut tried = Vec::new();
    for folder in dirs.iter().flat_map(|dir| kind.subdirs().iter().map(|sub| dir.join(sub))) {
        for file_stem in [name, lower.as_str()] {
            let path = folder.join(format!("{file_stem}.png"));
            if tried.contains(&path) {
                continue; // the name was already lower case
            }
            if path.is_file() {
                return Ok(Source::File(path));
            }
            tried.push(path);
        }
    }
    if let Some(wad) = library.wad.as_ref().filter(|w| w.has(name, kind)) {
        let _ = wad;
        return Ok(Source::Wad(name.to_ascii_uppercase(), kind));
    }
    match procedural::canonical(name, kind) {
        Some(canonical) => Ok(Source::Builtin(canonical)),
        None => Err(TextureError::Missing { name: name.to_string(), kind, tried }),
    }
}

#[cfg(test)]
mod tests;
