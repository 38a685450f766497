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
/// (`multiversion`): SSE4.1 has the 32-bit multiply the baseline's SSE2
/// emulates with shuffles, and AVX2 lights eight pixels in 16-bit lanes
/// ([`lanes16`]), a third fewer instructions than the 32-bit form.
#[multiversion::multiversion(targets("x86_64+avx2", "x86_64+sse4.1"))]
fn tint_all(tint: Tint, pixels: &mut [u32]) {
    let done = multiversion::target::match_target! {
        "x86_64+avx2" => lanes16::tint_eights(tint, pixels),
        _ => 0,
    };
    for p in &mut pixels[done..] {
        *p = tint.apply(*p);
    }
}

#[cfg(target_arch = "x86_64")]
pub(crate) mod lanes16 {
    use super::Tint;
    use std::arch::x86_64::{
        __m256i, _mm256_add_epi32, _mm256_and_si256, _mm256_mullo_epi16, _mm256_or_si256, _mm256_set1_epi16,
        _mm256_set1_epi32, _mm256_srli_epi16,
    };

    /// A [`Tint`] spread over eight pixels' lanes, for loops that light
    /// texels while they hold them (the spans' texel fetch).
    #[derive(Clone, Copy)]
    pub(crate) struct Eight {
        scale: __m256i,
        fog: __m256i,
        low: __m256i,
        high: __m256i,
        alpha: __m256i,
    }

    impl Eight {
        #[target_feature(enable = "avx2")]
        pub(crate) fn new(tint: Tint) -> Eight {
            Eight {
                scale: _mm256_set1_epi16(tint.scale as i16),
                fog: _mm256_set1_epi32(tint.fog as i32),
                low: _mm256_set1_epi16(0x00ff),
                high: _mm256_set1_epi16(0xff00_u16 as i16),
                alpha: _mm256_set1_epi32(0xff00_0000_u32 as i32),
            }
        }

        /// [`Tint::apply`] to eight pixels in 16-bit lanes, each lane one
        /// channel beside its neighbour: `c * scale` (at most 255 * 256)
        /// fits a lane, so one 16-bit multiply does what the 32-bit form
        /// does in two (each of two instructions) and the results are the
        /// same.
        #[target_feature(enable = "avx2")]
        #[inline]
        pub(crate) fn apply(&self, c: __m256i) -> __m256i {
            // Red and blue, the low byte of each lane, scaled and shifted back.
            let rb = _mm256_srli_epi16::<8>(_mm256_mullo_epi16(_mm256_and_si256(c, self.low), self.scale));
            // Green (and alpha, replaced below) scaled into the high byte.
            let ga = _mm256_and_si256(_mm256_mullo_epi16(_mm256_srli_epi16::<8>(c), self.scale), self.high);
            _mm256_or_si256(_mm256_add_epi32(_mm256_or_si256(rb, ga), self.fog), self.alpha)
        }
    }

    /// [`Tint::apply`] to eight pixels at a time ([`Eight::apply`]).
    /// Leaves fewer than eight pixels; returns how many it did.
    #[target_feature(enable = "avx2")]
    pub(super) fn tint_eights(tint: Tint, pixels: &mut [u32]) -> usize {
        let tint = Eight::new(tint);
        let (eights, _) = pixels.as_chunks_mut::<8>();
        for eight in eights.iter_mut() {
            *eight = bytemuck::cast::<__m256i, [u32; 8]>(tint.apply(bytemuck::cast::<[u32; 8], __m256i>(*eight)));
        }
        eights.len() * 8
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::rgb;

    /// The vectorised light (16-bit lanes with AVX2) gives every pixel what
    /// `Tint::apply` gives it, for every scale, with fog and without, and
    /// leaves the tail past the last eight to the scalar form alike.
    #[test]
    fn tint_all_matches_apply() {
        let pixels: Vec<u32> = (0..259u32).map(|i| i.wrapping_mul(0x9E37_79B9) | 0xff00_0000).collect();
        let fogged = Lighting { diminishing: true, fog: Some(Fog { colour: [250, 7, 128], distance: 900.0 }) };
        let tints = (0..=256)
            .map(|scale| Tint { scale, fog: 0 })
            .chain((0..=255u8).flat_map(|light| [0.0, 300.0, 899.0, 5000.0].map(|depth| fogged.tint(light, depth))));
        for tint in tints {
            let mut lit = pixels.clone();
            tint.apply_all(&mut lit);
            let want: Vec<u32> = pixels.iter().map(|&p| tint.apply(p)).collect();
            assert_eq!(lit, want, "{tint:?}");
        }
    }

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
