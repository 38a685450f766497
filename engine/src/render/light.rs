//! Light and fog: how a surface's colour changes with its sector's light and
//! its distance, as a [`Tint`] the column loops apply per texel.
//!
//! Doom darkens with distance through colormaps (palette remaps); in 32-bit
//! colour a tint is a per-channel scale, plus a blend toward the fog colour.
//! Each effect costs only where the map asks for it: with diminishing light
//! off the scale depends on the sector alone, and without fog there is no
//! blend at all.

use crate::map::{Fog, Map};

/// Light levels gained right at the eye, and lost per map unit of depth.
/// From Doom's look: near walls a little brighter than their sector, a wall
/// 1024 units away about 64 levels darker.
const NEAR_BOOST: f64 = 32.0;
const LOSS_PER_UNIT: f64 = 96.0 / 1024.0;
/// However far, a surface keeps this share of its sector's light.
const FLOOR_SHARE: f64 = 0.25;

/// The map's light model for one frame.
#[derive(Clone, Copy, Debug)]
pub struct Lighting {
    pub diminishing: bool,
    pub fog: Option<Fog>,
}

impl Lighting {
    /// The light model the frame's plan allows.
    pub fn for_plan(map: &Map, plan: &super::plan::Plan) -> Lighting {
        Lighting { diminishing: plan.diminishing, fog: if plan.fog { map.fog } else { None } }
    }

    /// The tint of a surface lit at `light` (0..=255) seen at `depth`.
    #[inline]
    pub fn tint(&self, light: u8, depth: f64) -> Tint {
        let light = f64::from(light);
        let level = if self.diminishing {
            (light + NEAR_BOOST - depth * LOSS_PER_UNIT).clamp(light * FLOOR_SHARE, (light + NEAR_BOOST).min(255.0))
        } else {
            light
        };
        let scale = ((level / 255.0 * 256.0) as u32).min(256);
        match self.fog {
            None => Tint { scale, fog: 0 },
            Some(f) => {
                let share = (depth / f.distance).clamp(0.0, 1.0);
                let fog = (share * 256.0) as u32;
                let [r, g, b] = f.colour.map(|c| (u32::from(c) * fog) >> 8);
                Tint { scale: (scale * (256 - fog)) >> 8, fog: r | g << 8 | b << 16 }
            }
        }
    }
}

/// Doom's fake contrast (r_segs.c): walls running north-south one light step
/// (16 of 256) brighter, walls running east-west one step darker, so that
/// corners read without real lighting. Wolfenstein 3D gets the same effect
/// from a darker copy of each wall texture for its north and south faces.
pub fn fake_contrast(light: u8, direction: glam::DVec2) -> u8 {
    if direction.x == 0.0 && direction.y != 0.0 {
        light.saturating_add(16)
    } else if direction.y == 0.0 && direction.x != 0.0 {
        light.saturating_sub(16)
    } else {
        light
    }
}

/// A colour transform: channels scaled by `scale / 256` (at most 1), then the
/// fog colour, already weighted by its share, added (packed like a pixel).
/// No channel can overflow: `c * scale / 256 + fog_c * share` stays within 255
/// because `scale` already left room for the fog's share.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tint {
    scale: u32,
    fog: u32,
}

impl Tint {
    /// Scales red and blue in one multiply and green in another (they sit in
    /// separate bytes of the pixel, 8 bits of headroom each).
    #[inline]
    pub fn apply(&self, c: u32) -> u32 {
        let rb = (((c & 0x00ff_00ff) * self.scale) >> 8) & 0x00ff_00ff;
        let g = (((c & 0x0000_ff00) * self.scale) >> 8) & 0x0000_ff00;
        ((rb | g) + self.fog) | 0xff00_0000
    }

    /// [`Tint::apply`] to every pixel of `pixels`, in place: the light of a
    /// wall column or a span, as one vectorised loop.
    #[inline]
    pub fn apply_all(&self, pixels: &mut [u32]) {
        tint_all(*self, pixels);
    }
}

/// Compiled for AVX2 and SSE4.1 as well as the baseline, picked at run time
/// (`multiversion`): the 32-bit multiplies are one instruction per 8 pixels
/// with AVX2, where the baseline's SSE2 emulates them with shuffles.
#[multiversion::multiversion(targets("x86_64+avx2", "x86_64+sse4.1"))]
fn tint_all(tint: Tint, pixels: &mut [u32]) {
    for p in pixels {
        *p = tint.apply(*p);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::rgb;

    #[test]
    fn light_and_fog() {
        let plain = Lighting { diminishing: false, fog: None };
        assert_eq!(plain.tint(255, 5000.0).apply(rgb(200, 100, 0)), rgb(200, 100, 0));
        assert_eq!(plain.tint(0, 1.0).apply(rgb(200, 100, 50)), rgb(0, 0, 0));
        let dim = Lighting { diminishing: true, fog: None };
        let near = dim.tint(160, 10.0).apply(rgb(200, 200, 200));
        let far = dim.tint(160, 2000.0).apply(rgb(200, 200, 200));
        assert!(near.to_le_bytes()[0] > far.to_le_bytes()[0]);
        let fog = Lighting { diminishing: false, fog: Some(Fog { colour: [100, 110, 120], distance: 1000.0 }) };
        assert_eq!(fog.tint(255, 1000.0).apply(rgb(0, 0, 0)), rgb(100, 110, 120));
        assert_eq!(fog.tint(255, 0.0).apply(rgb(10, 20, 30)), rgb(10, 20, 30));
    }
}
