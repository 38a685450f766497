//! Doom's art in a WAD, decoded to RGBA images: the palette (PLAYPAL),
//! pictures in the patch format (wall patches and sprites), composite wall
//! textures (PNAMES + TEXTURE1/TEXTURE2) and flats (64x64 raw, between
//! F_START and F_END).
//!
//! Every size is checked against the lump before a buffer is made, and
//! images are capped at [`MAX_SIDE`] on a side (Doom's own are at most 256
//! wide and 128 or so tall; tall skies are 512), so no lump can make us
//! allocate more than 64 MiB for one image.

use std::collections::HashMap;

use super::{i16_at, i32_at, lump_name, u16_at, Wad, WadError};
use crate::texture::MAX_SIDE;

/// An RGBA image, row-major, `width * height` pixels; alpha 0 is transparent.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub rgba: Vec<[u8; 4]>,
    /// A picture's offsets (Doom's `leftoffset`, `topoffset`): where its
    /// origin is, which for a sprite is the point on the floor below it.
    pub left: i32,
    pub top: i32,
}

impl Image {
    fn blank(width: usize, height: usize) -> Image {
        Image { width, height, rgba: vec![[0, 0, 0, 0]; width * height], left: 0, top: 0 }
    }
}

/// The 256 colours of palette 0 of PLAYPAL.
pub struct Palette(pub [[u8; 3]; 256]);

impl Palette {
    pub fn read(wad: &Wad) -> Result<Palette, WadError> {
        let bytes = wad.lump("PLAYPAL", " (the colour palette every picture needs)")?;
        if bytes.len() < 768 {
            return Err(wad.error("PLAYPAL", format!("{} bytes, shorter than one 768-byte palette", bytes.len())));
        }
        let mut p = [[0u8; 3]; 256];
        for (k, c) in p.iter_mut().enumerate() {
            c.copy_from_slice(&bytes[3 * k..3 * k + 3]);
        }
        Ok(Palette(p))
    }

    fn rgba(&self, index: u8) -> [u8; 4] {
        let [r, g, b] = self.0[usize::from(index)];
        [r, g, b, 255]
    }
}

/// Decodes a picture (patch format): a header of width, height and offsets,
/// a column offset per column, and each column a list of posts
/// `(topdelta, length, pad, pixels[length], pad)` ended by `topdelta = 255`.
/// Pixels no post covers stay transparent.
pub fn picture(bytes: &[u8], palette: &Palette) -> Result<Image, String> {
    if bytes.len() < 8 {
        return Err(format!("{} bytes, shorter than a picture header", bytes.len()));
    }
    let (width, height) = (i16_at(bytes, 0), i16_at(bytes, 2));
    check_size(i32::from(width), i32::from(height))?;
    let (width, height) = (width as usize, height as usize);
    if bytes.len() < 8 + 4 * width {
        return Err(format!("{} columns need {} bytes of offsets, but the lump has {}", width, 4 * width, bytes.len()));
    }
    let mut image = Image::blank(width, height);
    image.left = i32::from(i16_at(bytes, 4));
    image.top = i32::from(i16_at(bytes, 6));
    for x in 0..width {
        let mut at = usize::try_from(i32_at(bytes, 8 + 4 * x)).map_err(|_| format!("column {x}: negative offset"))?;
        // A column has at most `height` posts that draw anything, plus the
        // end marker; more means a loop or garbage. 256 bounds the walk.
        for _ in 0..=256 {
            let top = *bytes.get(at).ok_or_else(|| format!("column {x}: runs past the end of the lump"))?;
            if top == 0xFF {
                break;
            }
            let length = usize::from(*bytes.get(at + 1).ok_or_else(|| format!("column {x}: post cut short"))?);
            let pixels = bytes
                .get(at + 3..at + 3 + length)
                .ok_or_else(|| format!("column {x}: a post of {length} pixels runs past the end of the lump"))?;
            for (k, &p) in pixels.iter().enumerate() {
                let y = usize::from(top) + k;
                if y < height {
                    image.rgba[y * width + x] = palette.rgba(p);
                }
            }
            at += length + 4;
        }
    }
    Ok(image)
}

fn check_size(width: i32, height: i32) -> Result<(), String> {
    if width <= 0 || height <= 0 || width > MAX_SIDE as i32 || height > MAX_SIDE as i32 {
        return Err(format!("size {width}x{height} is not within 1..={MAX_SIDE}"));
    }
    Ok(())
}

/// A flat: 64x64 palette indices, row-major (Doom's flats are 4096 bytes;
/// some WADs pad them, so only the first 4096 are read).
pub fn flat(bytes: &[u8], palette: &Palette) -> Result<Image, String> {
    if bytes.len() < 4096 {
        return Err(format!("{} bytes, not a 64x64 flat (4096 bytes)", bytes.len()));
    }
    let mut image = Image::blank(64, 64);
    for (px, &b) in image.rgba.iter_mut().zip(bytes) {
        *px = palette.rgba(b);
    }
    Ok(image)
}

/// One patch of a composite texture.
#[derive(Clone, Debug, PartialEq)]
pub struct TexturePatch {
    pub x: i32,
    pub y: i32,
    /// The patch's lump name (from PNAMES).
    pub name: String,
}

/// A composite wall texture from TEXTURE1 or TEXTURE2.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureDef {
    pub name: String,
    pub width: usize,
    pub height: usize,
    pub patches: Vec<TexturePatch>,
    /// Which lump defined it, for errors.
    pub lump: &'static str,
}

/// Every composite texture, by upper-case name (TEXTURE2 after TEXTURE1, as
/// Doom reads them: a later definition of a name wins).
pub fn texture_defs(wad: &Wad) -> Result<HashMap<String, TextureDef>, WadError> {
    let pnames = wad.lump("PNAMES", " (the patch names textures refer to)")?;
    if pnames.len() < 4 {
        return Err(wad.error("PNAMES", "shorter than its 4-byte count"));
    }
    let count = i32_at(pnames, 0);
    if count < 0 || 4 + 8 * count as usize > pnames.len() {
        return Err(wad.error("PNAMES", format!("{count} names do not fit in {} bytes", pnames.len())));
    }
    let names: Vec<String> = pnames[4..4 + 8 * count as usize].chunks_exact(8).map(lump_name).collect();
    let mut defs = HashMap::new();
    for lump in ["TEXTURE1", "TEXTURE2"] {
        let Some(index) = wad.find(lump) else {
            if lump == "TEXTURE1" {
                return Err(wad.missing(lump, " (the wall texture definitions)"));
            }
            continue;
        };
        for def in read_texture_lump(wad.bytes(index), &names).map_err(|m| wad.error(lump, m))? {
            defs.insert(def.name.clone(), TextureDef { lump, ..def });
        }
    }
    Ok(defs)
}

fn read_texture_lump(b: &[u8], pnames: &[String]) -> Result<Vec<TextureDef>, String> {
    if b.len() < 4 {
        return Err("shorter than its 4-byte count".into());
    }
    let count = i32_at(b, 0);
    if count < 0 || 4 + 4 * count as usize > b.len() {
        return Err(format!("{count} texture offsets do not fit in {} bytes", b.len()));
    }
    (0..count as usize)
        .map(|k| {
            let at = usize::try_from(i32_at(b, 4 + 4 * k)).unwrap_or(usize::MAX);
            let head =
                b.get(at..at.saturating_add(22)).ok_or_else(|| format!("texture {k}: offset {at} is past the end"))?;
            let name = lump_name(&head[0..8]);
            let (width, height) = (i16_at(head, 12), i16_at(head, 14));
            check_size(i32::from(width), i32::from(height)).map_err(|m| format!("texture {k} ({name}): {m}"))?;
            let patch_count = i16_at(head, 20).max(0) as usize;
            let list = b
                .get(at + 22..at + 22 + 10 * patch_count)
                .ok_or_else(|| format!("texture {k} ({name}): its {patch_count} patches run past the end"))?;
            let patches = list
                .chunks_exact(10)
                .map(|p| {
                    let index = u16_at(p, 4) as usize;
                    let name_of = pnames.get(index).cloned().ok_or_else(|| {
                        format!("texture {k} ({name}): patch {index} is not in PNAMES ({} names)", pnames.len())
                    })?;
                    Ok(TexturePatch { x: i32::from(i16_at(p, 0)), y: i32::from(i16_at(p, 2)), name: name_of })
                })
                .collect::<Result<Vec<_>, String>>()?;
            Ok(TextureDef { name, width: width as usize, height: height as usize, patches, lump: "" })
        })
        .collect()
}

/// Composes a texture from its patches, each drawn at its origin and clipped
/// to the texture; later patches cover earlier ones. Texels no patch covers
/// are transparent (they show through on see-through middles).
pub fn compose(wad: &Wad, def: &TextureDef, palette: &Palette) -> Result<Image, WadError> {
    let mut image = Image::blank(def.width, def.height);
    for p in &def.patches {
        let context = format!(" (patch of texture {} in {})", def.name, def.lump);
        let index = wad.find(&p.name).ok_or_else(|| wad.missing(&p.name, &context))?;
        let patch = picture(wad.bytes(index), palette).map_err(|m| wad.error(&p.name, m))?;
        for py in 0..patch.height {
            let y = p.y + py as i32;
            if !(0..def.height as i32).contains(&y) {
                continue;
            }
            for px in 0..patch.width {
                let x = p.x + px as i32;
                let texel = patch.rgba[py * patch.width + px];
                if (0..def.width as i32).contains(&x) && texel[3] != 0 {
                    image.rgba[y as usize * def.width + x as usize] = texel;
                }
            }
        }
    }
    Ok(image)
}
