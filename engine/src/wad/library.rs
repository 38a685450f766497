//! A WAD's art as a texture library: the pictures a map played straight
//! from a WAD names (wall textures composed from patches, flats, sprites)
//! are decoded from the WAD when the level opens, the same way `sightline
//! import` writes them as PNGs, so an imported map and the WAD itself look
//! the same.

use super::art::{self, Image};
use super::import::{sprite_view, stand_on_origin, Art};
use super::{Wad, WadError};
use crate::texture::{Texture, TextureError, TextureKind, MAX_SIDE};

/// A WAD (or a stack of them) and its art index.
pub struct WadArt {
    pub wad: Wad,
    pub art: Art,
}

impl WadArt {
    pub fn new(wad: Wad) -> Result<WadArt, WadError> {
        let art = Art::read(&wad)?;
        Ok(WadArt { wad, art })
    }

    /// Does the WAD have a picture of this name and kind? (Walls and flats
    /// are both images here, as for PNGs: a flat may name a wall texture.)
    pub fn has(&self, name: &str, kind: TextureKind) -> bool {
        let name = name.to_ascii_uppercase();
        match kind {
            TextureKind::Wall | TextureKind::Flat => {
                self.art.textures.contains_key(&name) || self.art.flats.contains_key(&name)
            }
            TextureKind::Sprite => sprite_view(&self.art, &name).is_some(),
            TextureKind::Screen => self.art.sprites.contains_key(&name),
        }
    }

    /// Decodes picture `name` (upper case) of `kind`.
    pub fn texture(&self, name: &str, kind: TextureKind) -> Result<Texture, TextureError> {
        let bad = |message: String| TextureError::Png { path: format!("{}:{name}", self.wad.path).into(), message };
        let image = match kind {
            // A name both lists have: walls prefer the texture, floors the flat.
            TextureKind::Wall if self.art.textures.contains_key(name) => {
                art::compose(&self.wad, &self.art.textures[name], &self.art.palette).map_err(|e| bad(e.to_string()))?
            }
            TextureKind::Wall | TextureKind::Flat if self.art.flats.contains_key(name) => {
                art::flat(self.wad.bytes(self.art.flats[name]), &self.art.palette).map_err(bad)?
            }
            TextureKind::Flat => {
                let def = self.art.textures.get(name).ok_or_else(|| bad("not in the WAD".into()))?;
                art::compose(&self.wad, def, &self.art.palette).map_err(|e| bad(e.to_string()))?
            }
            TextureKind::Sprite => {
                let (lump, mirrored) = sprite_view(&self.art, name).ok_or_else(|| bad("not in the WAD".into()))?;
                let image = stand_on_origin(&art::picture(self.wad.bytes(lump), &self.art.palette).map_err(bad)?);
                // Padded about its origin, so mirroring keeps the origin.
                if mirrored {
                    mirror(&image)
                } else {
                    image
                }
            }
            TextureKind::Screen => {
                let lump = self.art.sprites.get(name).ok_or_else(|| bad("not in the WAD".into()))?;
                on_screen(&art::picture(self.wad.bytes(*lump), &self.art.palette).map_err(bad)?)
            }
            TextureKind::Wall => return Err(bad("not in the WAD".into())),
        };
        texture_of(&image)
            .ok_or_else(|| bad(format!("{}x{} is not 1 to {MAX_SIDE} on a side", image.width, image.height)))
    }
}

/// Re-frames a weapon picture for [`TextureKind::Screen`]: placed where
/// Doom draws it with the weapon at rest (origin at (1, 32) on the 320x200
/// screen, less its offsets), on a canvas whose top-left is the screen's.
/// What falls left of or above the screen is cut.
fn on_screen(image: &Image) -> Image {
    let (dx, dy) = (1 - image.left, 32 - image.top);
    let (w, h) = (image.width as i32, image.height as i32);
    let width = (dx + w).clamp(1, 1024);
    let height = (dy + h).clamp(1, 1024);
    let mut out = Image {
        width: width as usize,
        height: height as usize,
        rgba: vec![[0; 4]; (width * height) as usize],
        left: 0,
        top: 0,
    };
    for y in 0..h {
        for x in 0..w {
            let (ox, oy) = (x + dx, y + dy);
            if (0..width).contains(&ox) && (0..height).contains(&oy) {
                out.rgba[(oy * width + ox) as usize] = image.rgba[(y * w + x) as usize];
            }
        }
    }
    out
}

/// An image flipped left to right.
fn mirror(image: &Image) -> Image {
    let mut rgba = image.rgba.clone();
    for row in rgba.chunks_mut(image.width.max(1)) {
        row.reverse();
    }
    Image { rgba, left: image.width as i32 - image.left, ..image.clone() }
}

/// An RGBA image as a column-major texture.
fn texture_of(image: &Image) -> Option<Texture> {
    let ok = |n: usize| (1..=MAX_SIDE as usize).contains(&n);
    if !ok(image.width) || !ok(image.height) {
        return None;
    }
    Some(Texture::from_fn(image.width, image.height, |u, v| image.rgba[v * image.width + u]))
}
