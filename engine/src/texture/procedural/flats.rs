//! Flats: floor and ceiling textures. They are seen from above or below at
//! every angle, so they tile both ways and keep their emboss light mild: a
//! strong top-left light would look wrong from the other side of the room.

use super::paint::{add, hex, mix, opaque, rand01, scale, smoothstep, Field, TileNoise};
use crate::texture::Texture;

/// Square tiles of `cell` texels with `gap` texels of grout: the tile index,
/// and the distance from the texel's centre to the tile's nearest edge.
fn tiles(u: usize, v: usize, cell: usize, gap: f32) -> ((i32, i32), f32) {
    let (x, y) = ((u % cell) as f32 + 0.5, (v % cell) as f32 + 0.5);
    let c = cell as f32 - gap;
    let edge = x.min(c - x).min(y).min(c - y);
    (((u / cell) as i32, (v / cell) as i32), edge)
}

/// Large worn stone floor tiles, 32x32 with grout, four to a 64x64 flat.
pub fn floor(seed: u32) -> Texture {
    const W: usize = 64;
    let grain = TileNoise::new(seed, (W, W), (16, 16), 4);
    let wear = TileNoise::new(seed ^ 1, (W, W), (3, 3), 3);
    let height = Field::new(W, W, |u, v| {
        let (_, edge) = tiles(u, v, 32, 2.0);
        smoothstep(-0.5, 2.0, edge) + 0.15 * grain.at(u as f32, v as f32)
    });
    Texture::from_fn(W, W, |u, v| {
        let ((tx, ty), edge) = tiles(u, v, 32, 2.0);
        let (uf, vf) = (u as f32, v as f32);
        let tone = rand01(seed, tx, ty);
        let stone = mix(hex(0x6e665c), hex(0x8a8172), tone);
        let mut c = scale(stone, 0.78 + 0.35 * grain.at(uf, vf));
        // Feet polish the middle of each tile and leave dirt at its edges.
        c = mix(c, hex(0x4a4238), 0.4 * smoothstep(0.5, 0.8, wear.at(uf, vf)));
        c = scale(c, 0.88 + 0.12 * smoothstep(2.0, 10.0, edge));
        // Pits: the odd darker texel in the stone.
        if rand01(seed ^ 3, u as i32, v as i32) < 0.04 {
            c = scale(c, 0.8);
        }
        c = mix(hex(0x2c2823), c, smoothstep(-0.5, 1.0, edge));
        opaque(scale(c, height.light(u, v, 0.6)))
    })
}

/// A checkerboard of glazed cream and terracotta 16-texel tiles. 64x64.
pub fn tile(seed: u32) -> Texture {
    const W: usize = 64;
    let speck = TileNoise::new(seed, (W, W), (32, 32), 2);
    let height = Field::new(W, W, |u, v| smoothstep(-0.5, 1.5, tiles(u, v, 16, 1.0).1));
    Texture::from_fn(W, W, |u, v| {
        let ((tx, ty), edge) = tiles(u, v, 16, 1.0);
        let dark = (tx + ty) % 2 == 1;
        let base = if dark { hex(0x8a3c2a) } else { hex(0xd9ccb0) };
        let tone = 0.92 + 0.12 * rand01(seed, tx, ty);
        let mut c = scale(base, tone * (0.93 + 0.12 * speck.at(u as f32, v as f32)));
        // Glaze: a soft sheen towards each tile's upper left.
        let (x, y) = ((u % 16) as f32, (v % 16) as f32);
        c = add(c, scale([1.0, 0.97, 0.9], 0.06 * smoothstep(14.0, 2.0, x + y)));
        c = mix(hex(0x8c8880), c, smoothstep(-0.2, 0.6, edge));
        opaque(scale(c, height.light(u, v, 0.5)))
    })
}

/// Grass seen from above: clumps of green, light blade tips over dark roots
/// as texel-sized specks, and the odd yellow flower. 64x64.
pub fn grass(seed: u32) -> Texture {
    const W: usize = 64;
    let clumps = TileNoise::new(seed, (W, W), (4, 4), 4);
    let tufts = TileNoise::new(seed ^ 1, (W, W), (16, 16), 2);
    Texture::from_fn(W, W, |u, v| {
        let (uf, vf) = (u as f32, v as f32);
        let k = clumps.at(uf, vf);
        let t = tufts.at(uf, vf);
        let mut c = mix(hex(0x2f5220), hex(0x5f8f34), smoothstep(0.3, 0.7, k));
        c = scale(c, 0.8 + 0.4 * t);
        // Specks: a blade seen end on is one texel, lit tip or shadowed root.
        let r = rand01(seed ^ 3, u as i32, v as i32);
        if r < 0.18 {
            c = mix(c, hex(0x9cc45a), 0.5 + 0.3 * t);
        } else if r > 0.8 {
            c = scale(c, 0.65);
        }
        if rand01(seed ^ 4, u as i32, v as i32) > 0.996 && k > 0.45 {
            c = hex(0xe8d050);
        }
        opaque(c)
    })
}

/// Deep water: long swells, a warped ripple pattern and soft caustic
/// highlights. 64x64.
pub fn water(seed: u32) -> Texture {
    const W: usize = 64;
    let warp = TileNoise::new(seed, (W, W), (3, 3), 3);
    let caustic = TileNoise::new(seed ^ 1, (W, W), (4, 4), 3);
    let tau = std::f32::consts::TAU;
    Texture::from_fn(W, W, |u, v| {
        let (uf, vf) = (u as f32, v as f32);
        let w = warp.at(uf, vf);
        // Whole waves per tile in each direction, so the sines tile too.
        let phase = tau * (2.0 * uf / W as f32 + vf / W as f32) + w * 7.0;
        let ripple = phase.sin() * 0.5 + 0.5;
        let mut c = mix(hex(0x103752), hex(0x21617f), ripple * 0.6 + 0.4 * w);
        // Caustics: bright where the noise crosses its middle value, a soft
        // band rather than a hard line.
        let line = 1.0 - ((caustic.at(uf, vf) - 0.5).abs() * 7.0).min(1.0);
        c = add(c, scale(hex(0x5fb0cf), 0.35 * line * line * line));
        opaque(c)
    })
}

/// Grey ceiling panels with a recessed light fitting in the middle. 64x64.
pub fn ceil(seed: u32) -> Texture {
    const W: usize = 64;
    let grain = TileNoise::new(seed, (W, W), (16, 16), 3);
    let fitting = |u: usize, v: usize| {
        let (x, y) = ((u as f32 + 0.5 - 32.0).abs(), (v as f32 + 0.5 - 32.0).abs());
        x.max(y)
    };
    let height = Field::new(W, W, |u, v| {
        let (_, edge) = tiles(u, v, 32, 1.0);
        let f = fitting(u, v);
        if f < 12.0 {
            0.2 + 0.6 * smoothstep(12.0, 10.0, f)
        } else {
            smoothstep(-0.5, 1.5, edge)
        }
    });
    Texture::from_fn(W, W, |u, v| {
        let (_, edge) = tiles(u, v, 32, 1.0);
        let f = fitting(u, v);
        let panel = scale(hex(0x7a7c80), 0.85 + 0.25 * grain.at(u as f32, v as f32));
        let mut c = mix(hex(0x2a2b2e), panel, smoothstep(-0.3, 0.8, edge));
        // The fitting: a steel rim around a lit diffuser, glowing outwards.
        if f < 12.0 {
            c = hex(0x9aa0a8);
        }
        if f < 9.0 {
            c = mix(hex(0xffeec4), hex(0xffffff), smoothstep(9.0, 0.0, f));
            // The diffuser's egg-crate grid, every 3 texels.
            if u % 3 == 2 || v % 3 == 2 {
                c = scale(c, 0.85);
            }
        }
        let glow = smoothstep(20.0, 10.0, f) * 0.2;
        c = add(c, scale(hex(0xffe7b0), glow));
        let lit = if f < 9.0 { 1.0 } else { height.light(u, v, 0.6) };
        opaque(scale(c, lit))
    })
}

/// Packed earth with scattered pebbles: 80x80, not a power of two.
pub fn dirt(seed: u32) -> Texture {
    const W: usize = 80;
    const CELL: usize = 10; // at most one pebble per 10x10 cell
    let soil = TileNoise::new(seed, (W, W), (5, 5), 5);
    let fine = TileNoise::new(seed ^ 1, (W, W), (40, 40), 2);
    // Per texel: distance to the nearest pebble centre in radii (searching the
    // 3x3 cells around), and that pebble's tone. Computed once, used twice.
    let pebbles: Vec<(f32, f32)> = (0..W * W)
        .map(|i| {
            let (u, v) = (i / W, i % W);
            let (cx, cy) = ((u / CELL) as i32, (v / CELL) as i32);
            let n = (W / CELL) as i32;
            let mut best = (f32::MAX, 0.0);
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let (gx, gy) = ((cx + dx).rem_euclid(n), (cy + dy).rem_euclid(n));
                    if rand01(seed ^ 2, gx, gy) > 0.4 {
                        continue;
                    }
                    let px = (cx + dx) as f32 * CELL as f32 + 2.0 + 6.0 * rand01(seed ^ 3, gx, gy);
                    let py = (cy + dy) as f32 * CELL as f32 + 2.0 + 6.0 * rand01(seed ^ 4, gx, gy);
                    let r = 1.2 + 1.8 * rand01(seed ^ 5, gx, gy);
                    // Pebbles are flattened: wider than they are deep.
                    let (ex, ey) = (u as f32 + 0.5 - px, (v as f32 + 0.5 - py) * 1.3);
                    let d = (ex * ex + ey * ey).sqrt() / r;
                    if d < best.0 {
                        best = (d, rand01(seed ^ 6, gx, gy));
                    }
                }
            }
            best
        })
        .collect();
    let height = Field::new(W, W, |u, v| {
        let (d, _) = pebbles[u * W + v];
        let stone = if d < 1.0 { 0.6 * (1.0 - d * d).sqrt() } else { 0.0 };
        0.5 * soil.at(u as f32, v as f32) + 0.3 * fine.at(u as f32, v as f32) + stone
    });
    Texture::from_fn(W, W, |u, v| {
        let (uf, vf) = (u as f32, v as f32);
        let s = soil.at(uf, vf);
        let mut c = mix(hex(0x3f2d1f), hex(0x7a5b3d), smoothstep(0.2, 0.8, s));
        c = scale(c, 0.8 + 0.35 * fine.at(uf, vf));
        if rand01(seed ^ 7, u as i32, v as i32) < 0.06 {
            c = scale(c, 1.2); // grit
        }
        let (d, tone) = pebbles[u * W + v];
        if d < 1.0 {
            c = mix(hex(0x6a6258), hex(0x9a8e7c), tone);
        } else {
            c = scale(c, 0.8 + 0.2 * smoothstep(1.0, 1.6, d)); // the hollow it sits in
        }
        opaque(scale(c, height.light(u, v, 0.8)))
    })
}
