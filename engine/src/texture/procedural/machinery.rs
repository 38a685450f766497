//! The built-in textures of a level's machinery: switches (each an off and an
//! on picture, paired in `engine/data/animations.ron`), an exit switch, a
//! chevron strip to scroll, frames of animated slime, a teleporter pad, and
//! keys (cards and skulls, under Doom's sprite names so a version-2 map's
//! `blue_card` finds its picture with no art files).

use super::paint::{hex, mix, opaque, rand01, scale, smoothstep, Rgb, TileNoise, CLEAR};
use crate::texture::Texture;

/// A steel wall panel with a lever switch and a lamp: red and the lever up
/// when off, green and the lever down when on. 64x128.
pub fn switch(seed: u32, on: bool) -> Texture {
    const W: usize = 64;
    const H: usize = 128;
    let brushed = TileNoise::new(seed, (W, H), (2, 64), 2);
    let lamp = if on { hex(0x4cff5a) } else { hex(0xff3a2a) };
    Texture::from_fn(W, H, |u, v| {
        let (x, y) = (u as f32 + 0.5, v as f32 + 0.5);
        let steel = scale(hex(0x5b636b), 0.85 + 0.3 * brushed.at(u as f32, v as f32));
        let edge = x.min(W as f32 - x).min(y).min(H as f32 - y);
        let mut c = mix(hex(0x1c2024), steel, smoothstep(0.5, 2.0, edge));
        // The switch box: a dark recessed plate in the middle.
        let in_box = (16.0..48.0).contains(&x) && (40.0..96.0).contains(&y);
        if in_box {
            let inner = (x - 16.0).min(48.0 - x).min(y - 40.0).min(96.0 - y);
            c = scale(hex(0x2a2e33), 0.7 + 0.3 * smoothstep(0.0, 3.0, inner));
            // The lever: a bright bar from the pivot up (off) or down (on).
            let (pivot, tip) = (68.0, if on { 88.0 } else { 48.0 });
            let (lo, hi) = if tip < pivot { (tip, pivot) } else { (pivot, tip) };
            if (x - 32.0).abs() < 3.0 && (lo..=hi).contains(&y) {
                c = hex(0xc8c8c0);
            }
            if ((x - 32.0).powi(2) + (y - pivot).powi(2)).sqrt() < 5.0 {
                c = hex(0x6e7378);
            }
        }
        // The lamp above the box.
        let d = ((x - 32.0).powi(2) + (y - 26.0).powi(2)).sqrt();
        if d < 7.0 {
            c = mix(lamp, hex(0xffffff), 0.5 * (1.0 - d / 7.0));
        } else if d < 8.5 {
            c = hex(0x16181a);
        }
        opaque(c)
    })
}

/// An exit switch: a panel with a big arrow, dim red when off, bright green
/// when on. 64x128.
pub fn exit(seed: u32, on: bool) -> Texture {
    let panel = switch(seed, on);
    let glow = if on { hex(0x66ff70) } else { hex(0xd8302a) };
    Texture::from_fn(64, 128, |u, v| {
        let (x, y) = (u as f32 + 0.5, v as f32 + 0.5);
        // An arrow pointing right across the top of the panel, in place of the lamp.
        let shaft = (10.0..40.0).contains(&x) && (y - 22.0).abs() < 4.0;
        let head = (38.0..54.0).contains(&x) && (y - 22.0).abs() < (54.0 - x) * 0.7;
        if shaft || head {
            return opaque(glow);
        }
        if (6.0..58.0).contains(&x) && (8.0..36.0).contains(&y) {
            return opaque(hex(0x121416));
        }
        panel.texel(u, v).to_le_bytes()
    })
}

/// Yellow and black chevrons pointing left, for a wall that scrolls along
/// them (a conveyor's edge). 64x32.
pub fn chevron(seed: u32) -> Texture {
    const W: usize = 64;
    const H: usize = 32;
    let wear = TileNoise::new(seed, (W, H), (8, 4), 3);
    Texture::from_fn(W, H, |u, v| {
        let (x, y) = (u as f32 + 0.5, v as f32 + 0.5);
        let band = (4.0..28.0).contains(&y);
        let c = if band {
            // A chevron every 32 texels: stripes slanting away from the middle row.
            let k = (x + (y - 16.0).abs()).rem_euclid(32.0);
            let yellow = k < 16.0;
            let base = if yellow { hex(0xe0b622) } else { hex(0x1a1a18) };
            scale(base, 0.8 + 0.3 * wear.at(x, y))
        } else {
            scale(hex(0x4a4f55), 0.75 + 0.3 * wear.at(x, y))
        };
        opaque(c)
    })
}

/// Frame `frame` (0, 1, 2) of glowing green slime: the same swirl, its
/// bright bands a third of a turn on each frame, so the three in turn seem
/// to flow. 64x64.
pub fn goo(seed: u32, frame: u32) -> Texture {
    const W: usize = 64;
    let swirl = TileNoise::new(seed, (W, W), (4, 4), 3);
    let tau = std::f32::consts::TAU;
    let phase = frame as f32 / 3.0 * tau;
    Texture::from_fn(W, W, |u, v| {
        let (uf, vf) = (u as f32, v as f32);
        let s = swirl.at(uf, vf);
        let wave = ((tau * (uf + vf) / W as f32) * 2.0 + s * 6.0 + phase).sin() * 0.5 + 0.5;
        let c: Rgb = mix(hex(0x1f5a12), hex(0x7be83a), wave * 0.7 + 0.3 * s);
        let bubble = rand01(seed ^ frame, u as i32 / 4, v as i32 / 4) > 0.97;
        opaque(if bubble { hex(0xc8ff9a) } else { c })
    })
}

/// A teleporter pad: a dark disc with a glowing ring and runes. 64x64.
pub fn telepad(seed: u32) -> Texture {
    const W: usize = 64;
    let grain = TileNoise::new(seed, (W, W), (8, 8), 3);
    Texture::from_fn(W, W, |u, v| {
        let (x, y) = (u as f32 + 0.5 - 32.0, v as f32 + 0.5 - 32.0);
        let r = (x * x + y * y).sqrt();
        let base = scale(hex(0x2b2433), 0.8 + 0.3 * grain.at(u as f32, v as f32));
        let ring = 1.0 - ((r - 24.0).abs() / 3.0).min(1.0);
        let rune = r < 18.0 && ((x.atan2(y) * 4.0).sin() * 0.5 + 0.5) > 0.85 && r > 8.0;
        let mut c = mix(base, hex(0xff5cf0), ring);
        if rune {
            c = mix(c, hex(0xc08cff), 0.7);
        }
        opaque(c)
    })
}

/// A key's colour (blue, yellow, red) from Doom's sprite name (BKEY, YSKU, ...).
fn key_colour(name: &str) -> Rgb {
    match name.as_bytes().first() {
        Some(b'B') => hex(0x2f5cff),
        Some(b'Y') => hex(0xf2cc22),
        _ => hex(0xe02a2a),
    }
}

/// A keycard lying on the floor, seen from the front: a white card with a
/// coloured stripe and a chip. 16x12.
pub fn card(name: &str) -> Texture {
    let colour = key_colour(name);
    Texture::from_fn(16, 12, |u, v| {
        let (x, y) = (u as f32 + 0.5, v as f32 + 0.5);
        if u == 0 || u == 15 || !(1.0..12.0).contains(&y) || !(2.0..14.0).contains(&x) {
            return CLEAR;
        }
        let c = if (4.0..7.0).contains(&y) {
            colour
        } else if (8.0..10.0).contains(&y) && (4.0..7.0).contains(&x) {
            hex(0xd4b04a)
        } else {
            scale(hex(0xe8e8e0), 1.0 - 0.15 * y / 12.0)
        };
        opaque(c)
    })
}

/// A skull key: a bone-white skull with a coloured gem on its brow. 16x16.
pub fn skull(name: &str) -> Texture {
    let colour = key_colour(name);
    Texture::from_fn(16, 16, |u, v| {
        let (x, y) = (u as f32 + 0.5 - 8.0, v as f32 + 0.5);
        if u == 0 || u == 15 {
            return CLEAR;
        }
        let cranium = (x * x) / 36.0 + ((y - 7.0) * (y - 7.0)) / 36.0 <= 1.0;
        let jaw = y >= 11.0 && x.abs() < 3.5;
        if !(cranium || jaw) {
            return CLEAR;
        }
        let eye = ((x.abs() - 2.5).powi(2) + (y - 8.0).powi(2)).sqrt() < 1.5;
        let gem = (x * x + (y - 4.0).powi(2)).sqrt() < 1.6;
        let teeth = jaw && (x.round() as i32).rem_euclid(2) == 0 && y > 13.0;
        let c = if gem {
            colour
        } else if eye || teeth {
            hex(0x1a1410)
        } else {
            scale(hex(0xe9e2c8), 0.8 + 0.2 * (1.0 - y / 16.0))
        };
        opaque(c)
    })
}
