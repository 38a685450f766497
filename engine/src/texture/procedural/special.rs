//! Wall textures that are not plain surfaces: the two masked ones (GRATE,
//! FENCE), whose holes are alpha 0, and the renderer's hard cases (DEBUG1,
//! THIN, ODD), whose sizes and texel values tests can reason about.

use super::paint::{hex, mix, opaque, scale, smoothstep, TileNoise, CLEAR};
use crate::texture::Texture;

/// Masked: round iron bars every 16 texels each way, transparent between. 64x64.
pub fn grate(seed: u32) -> Texture {
    const W: usize = 64;
    const PITCH: usize = 16;
    const BAR: f32 = 5.0;
    let rust = TileNoise::new(seed, (W, W), (8, 8), 3);
    Texture::from_fn(W, W, |u, v| {
        let across = |p: usize| (p % PITCH) as f32 + 0.5 - BAR / 2.0; // 0..BAR on a bar
        let (ax, ay) = (across(u), across(v));
        let on_v = (0.0..BAR).contains(&ax);
        let on_h = (0.0..BAR).contains(&ay);
        if !on_v && !on_h {
            return CLEAR;
        }
        // Round bars: shade by the offset across the bar; the horizontal bar
        // passes in front at crossings.
        let t = (if on_h { ay } else { ax }) / BAR * 2.0 - 1.0;
        let lit = 0.45 + 0.75 * (1.0 - t * t).sqrt() - 0.25 * t;
        let metal = mix(hex(0x4a5058), hex(0x6e4b34), smoothstep(0.55, 0.8, rust.at(u as f32, v as f32)));
        opaque(scale(metal, lit))
    })
}

/// Masked chain-link: two sets of diagonal wires forming 16-texel diamonds,
/// transparent between. 64x64 (a multiple of the pitch, so it tiles).
pub fn fence(seed: u32) -> Texture {
    const W: usize = 64;
    const PITCH: usize = 16;
    let tarnish = TileNoise::new(seed, (W, W), (4, 4), 2);
    Texture::from_fn(W, W, |u, v| {
        let a = (u + v) % PITCH;
        let b = (u + PITCH * W - v) % PITCH;
        let (on_a, on_b) = (a < 2, b < 2);
        if !on_a && !on_b {
            return CLEAR;
        }
        // Wires weave: at alternate crossings one or the other is in front.
        let front_a = ((u + v) / PITCH + (u + PITCH * W - v) / PITCH) & 1 == 0;
        let use_a = on_a && (!on_b || front_a);
        let lit = if use_a { [1.05, 0.8][a] } else { [0.95, 0.7][b] };
        let c = mix(hex(0xa9afb5), hex(0x7d7766), tarnish.at(u as f32, v as f32));
        opaque(scale(c, lit))
    })
}

/// A single magenta texel: the smallest texture there is.
pub fn debug1() -> Texture {
    Texture::from_fn(1, 1, |_, _| [255, 0, 255, 255])
}

/// One column, 64 tall: an amber gradient banded every 8 rows, so a renderer
/// test can see which row landed where.
pub fn thin() -> Texture {
    Texture::from_fn(1, 64, |_, v| {
        let band = if (v / 8) % 2 == 0 { 1.0 } else { 0.7 };
        opaque(scale(mix(hex(0xffd27a), hex(0x8a4a10), v as f32 / 63.0), band))
    })
}

/// 37x23, both prime: red is `7 u` and green `11 v`, so every texel names its
/// own coordinates; blue draws a 4-texel checker to make it legible.
pub fn odd() -> Texture {
    Texture::from_fn(37, 23, |u, v| {
        let check = if (u / 4 + v / 4) % 2 == 0 { 0x90 } else { 0x50 };
        [(u * 7) as u8, (v * 11) as u8, check, 255]
    })
}
