//! What colour a surface gets: `ids` (a colour derived only from the element's
//! index, for comparing renderers pixel by pixel) or `flat` (sector light on
//! per-line and per-sector colours, for looking at).

use crate::framebuffer::rgb;

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Shade {
    /// A colour per element index, for comparing renderers pixel by pixel.
    Ids,
    /// Lit flat colours, for looking at geometry.
    Flat,
    /// Textures, sky, light and fog: the game's look. Surfaces without a
    /// texture fall back to their flat colour.
    #[default]
    Textured,
}

impl Shade {
    pub fn name(self) -> &'static str {
        match self {
            Shade::Ids => "ids",
            Shade::Flat => "flat",
            Shade::Textured => "textured",
        }
    }

    pub fn from_name(name: &str) -> Option<Shade> {
        [Shade::Ids, Shade::Flat, Shade::Textured].into_iter().find(|s| s.name() == name)
    }
}

/// What a pixel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    Wall {
        line: usize,
    },
    Floor {
        sector: usize,
    },
    Ceiling {
        sector: usize,
    },
    /// A `"SKY"` ceiling or floor: the same sky whichever sector shows it.
    Sky,
    /// A thing's sprite.
    Thing {
        thing: usize,
    },
    Void,
}

/// Colour of the void: black, which no `ids` surface colour can be.
pub const VOID: u32 = rgb(0, 0, 0);

/// SplitMix64's finalizer: spreads consecutive indices over the colour space.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// An `ids` colour: bright hashed channels, with the low two bits of blue
/// tagging the kind (1 wall, 2 floor, 3 ceiling) so kinds never collide and
/// nothing is black.
fn id_colour(index: usize, kind: u8) -> u32 {
    let h = mix(index as u64 ^ (u64::from(kind) << 56));
    let [r, g, b] = [h as u8, (h >> 8) as u8, (h >> 16) as u8].map(|c| 48 + c % 200);
    rgb(r, g, (b & !3) | kind)
}

pub fn ids_colour(surface: Surface) -> u32 {
    match surface {
        Surface::Wall { line } => id_colour(line, 1),
        Surface::Floor { sector } => id_colour(sector, 2),
        Surface::Ceiling { sector } => id_colour(sector, 3),
        // Tag 0 like the void, but never black.
        Surface::Sky => rgb(96, 160, 224),
        // Tag 0 with an odd red channel: neither sky (red 96) nor void.
        Surface::Thing { thing } => {
            let c = id_colour(thing, 0).to_le_bytes();
            rgb(c[0] | 1, c[1], c[2] & !3)
        }
        Surface::Void => VOID,
    }
}

/// Colour of a surface in `shade`, lit by `light` (the sector the viewer sees
/// it from). `facing` scales walls by their angle to the light (Doom's fake
/// contrast: walls running east-west a little darker than north-south).
pub fn colour(shade: Shade, surface: Surface, light: u8, facing: f64) -> u32 {
    let (base, scale) = match (shade, surface) {
        (Shade::Ids, _) => return ids_colour(surface),
        (_, Surface::Void) => return VOID,
        (_, Surface::Wall { line }) => {
            const PALETTE: [[u8; 3]; 4] = [[170, 120, 90], [150, 150, 160], [120, 140, 110], [175, 160, 120]];
            (PALETTE[line % PALETTE.len()], facing)
        }
        (_, Surface::Floor { .. }) => ([110, 100, 90], 0.85),
        (_, Surface::Thing { .. }) => ([200, 180, 60], 1.0),
        (_, Surface::Ceiling { .. }) => ([140, 140, 150], 0.7),
        // The sky is not lit by sectors.
        (_, Surface::Sky) => return rgb(110, 150, 200),
    };
    let k = f64::from(light) / 255.0 * scale;
    let [r, g, b] = base.map(|c| (f64::from(c) * k).clamp(0.0, 255.0) as u8);
    rgb(r, g, b)
}

/// Fake-contrast factor for a wall running along `d`: 1 for north-south,
/// 0.8 for east-west, in between for diagonals.
pub fn wall_facing(d: glam::DVec2) -> f64 {
    let len = d.length();
    if len > 0.0 {
        0.8 + 0.2 * (d.y.abs() / len)
    } else {
        1.0
    }
}

/// What a sector's ceiling and floor show.
pub fn plane_surfaces(sector: usize, s: &crate::map::Sector) -> (Surface, Surface) {
    let ceiling = if s.ceiling_is_sky() { Surface::Sky } else { Surface::Ceiling { sector } };
    let floor = if s.floor_is_sky() { Surface::Sky } else { Surface::Floor { sector } };
    (ceiling, floor)
}

/// The ceiling height a line's near sector shows at that line. Doom's sky
/// rule: between two sky ceilings there is no upper wall; the sky reaches
/// down to the far sector's ceiling instead.
pub fn ceiling_at_line(near: &crate::map::Sector, far: Option<&crate::map::Sector>) -> f64 {
    match far {
        Some(far) if near.ceiling_is_sky() && far.ceiling_is_sky() => far.ceiling,
        _ => near.ceiling,
    }
}

/// Height of texel row 0 of a see-through middle texture on a two-sided line,
/// seen from its front (`back_side == false`) or back. Doom's rule: it hangs
/// from the lower of the two ceilings, or with `lower_unpegged` stands on the
/// higher of the two floors; it is drawn once, not tiled.
pub fn masked_top(
    map: &crate::map::Map,
    line: &crate::map::Line,
    back_side: bool,
    texture_height: f64,
    time: u64,
) -> f64 {
    let front = &map.sectors[line.front.sector];
    let back = line.back.as_ref().map_or(front, |b| &map.sectors[b.sector]);
    let side = line.side(back_side);
    let top = if line.flags.lower_unpegged {
        front.floor.max(back.floor) + texture_height
    } else {
        front.ceiling.min(back.ceiling)
    };
    top + side_offsets(side, time).1
}

/// A side's texture offsets at tick `time`: its own, plus its scrolling
/// that many ticks on.
pub fn side_offsets(side: &crate::map::Side, time: u64) -> (f64, f64) {
    let t = time as f64;
    (side.x_offset + side.scroll.x * t, side.y_offset + side.scroll.y * t)
}

/// The light a sector's ceiling and floor are drawn with: its own, or the
/// sector's each takes its light from (Boom's light transfers).
pub fn plane_lights(map: &crate::map::Map, sector: &crate::map::Sector) -> (u8, u8) {
    let from = |s: Option<usize>| s.map_or(sector.light, |s| map.sectors[s].light);
    (from(sector.ceiling_light), from(sector.floor_light))
}
