//! The sky: one 360-degree panorama, 1024x200, that the renderer maps by view
//! angle. Its columns wrap (column 0 continues column 1023) because every
//! noise in it has a whole number of lattice cells across the width.

use super::paint::{fbm, hex, mix, opaque, scale, smoothstep, value_noise, Rgb, TileNoise};
use crate::texture::Texture;

const W: usize = 1024;
const H: usize = 200;

/// 1-D periodic fBm around the horizon: `cells` lattice cells across the
/// panorama's width, a row of the 2-D lattice (its y period is irrelevant).
/// `ridged` folds each octave (1 - |2n - 1|) so peaks come out sharp.
fn profile(seed: u32, u: usize, cells: i32, octaves: u32, ridged: bool) -> f32 {
    let x = u as f32 / W as f32 * cells as f32;
    if !ridged {
        return fbm(seed, x, 0.5, cells, 1, octaves);
    }
    let (mut sum, mut weight, mut total) = (0.0, 1.0, 0.0);
    for o in 0..octaves {
        let f = 1 << o;
        let n = value_noise(seed.wrapping_add(o), x * f as f32, 0.5, cells * f, 1);
        sum += weight * (1.0 - (2.0 * n - 1.0).abs());
        total += weight;
        weight *= 0.5;
    }
    sum / total
}

/// Cloud density sampled on a half-resolution grid and interpolated: clouds
/// are soft, and evaluating their noise per texel of the 1024x200 panorama
/// cost more than all the other textures together.
struct Clouds {
    /// Row-major, `GH` rows of `GW` samples, sample (i, j) at texel (2i, 2j).
    grid: Vec<f32>,
}

const GW: usize = W / 2;
const GH: usize = H / 2 + 1;

impl Clouds {
    fn new(seed: u32) -> Clouds {
        let noise = TileNoise::new(seed, (W, H), (12, 5), 5);
        let mut grid = Vec::with_capacity(GW * GH);
        for j in 0..GH {
            for i in 0..GW {
                grid.push(noise.at(i as f32 * 2.0, j as f32 * 2.0));
            }
        }
        Clouds { grid }
    }

    /// Density at texel (u, v) for u in 0..W: wraps across, clamps down.
    fn at(&self, u: f32, v: f32) -> f32 {
        let (x, y) = (u / 2.0, (v / 2.0).clamp(0.0, (GH - 1) as f32));
        let (i, j) = (x as usize, (y as usize).min(GH - 2));
        let (tx, ty) = (x - i as f32, y - j as f32);
        // GW is a constant power of two, so these are masks, not divisions.
        let (i, i1) = (i % GW, (i + 1) % GW);
        let g = |i: usize, j: usize| self.grid[j * GW + i];
        let top = g(i, j) + (g(i1, j) - g(i, j)) * tx;
        let bottom = g(i, j + 1) + (g(i1, j + 1) - g(i, j + 1)) * tx;
        top + (bottom - top) * ty
    }
}

pub fn sky(seed: u32) -> Texture {
    let clouds = Clouds::new(seed);
    let trees = TileNoise::new(seed ^ 2, (W, H), (64, 16), 2);
    // Gullies: noise much finer across than down, so it streaks vertically.
    let gullies = TileNoise::new(seed ^ 6, (W, H), (48, 12), 3);
    // Per-column ridge lines (row of the crest): far mountains with sharp
    // peaks, then a nearer line of wooded hills with a bumpy tree line.
    let far: Vec<f32> = (0..W).map(|u| H as f32 - 25.0 - 95.0 * profile(seed ^ 3, u, 7, 6, true).powf(1.5)).collect();
    // Which way each column's slope faces: rising to the right faces the
    // light (from the left) and is lit.
    let facing: Vec<f32> = (0..W)
        .map(|u| {
            let (l, r) = ((u + W - 3) % W, (u + 3) % W);
            ((far[l] - far[r]) / 6.0).clamp(-1.0, 1.0)
        })
        .collect();
    let near: Vec<f32> = (0..W)
        .map(|u| {
            let hills = profile(seed ^ 4, u, 5, 4, false);
            let trees = profile(seed ^ 5, u, 256, 2, false);
            H as f32 - 8.0 - 40.0 * hills - 4.0 * trees
        })
        .collect();
    let horizon = H as f32 - 20.0;
    let snowline = H as f32 - 80.0;
    // Per row: the sky's gradient (deep blue overhead, pale at the horizon)
    // and how much cloud it may hold (none at the top edge or the horizon).
    let rows: Vec<(Rgb, f32)> = (0..H)
        .map(|v| {
            let t = v as f32 / horizon;
            let c = if t < 0.55 {
                mix(hex(0x1d3e78), hex(0x4a7cc2), t / 0.55)
            } else {
                mix(hex(0x4a7cc2), hex(0xdde5ec), smoothstep(0.55, 1.05, t))
            };
            (c, smoothstep(0.0, 0.3, t) * smoothstep(1.0, 0.55, t))
        })
        .collect();
    // A ragged snow line, per column.
    let snow: Vec<f32> =
        (0..W).map(|u| snowline + 3.0 * (u as f32 * std::f32::consts::TAU * 53.0 / W as f32).sin()).collect();

    Texture::from_fn(W, H, |u, v| {
        let (uf, vf) = (u as f32, v as f32);
        if vf >= near[u] {
            // Near hills: dark wooded green, a little hazier at the crest.
            let depth = vf - near[u];
            let r = trees.at(uf * 2.0, vf * 3.0);
            let g = mix(hex(0x24402c), hex(0x3b5a36), r);
            return opaque(mix(g, hex(0x5c7a6c), 0.3 * smoothstep(6.0, 0.0, depth)));
        }
        if vf >= far[u] {
            // Far mountains: hazy blue rock, lighter towards the crest, snow
            // above the snow line.
            let depth = vf - far[u];
            let r = gullies.at(uf, vf);
            let mut m = mix(hex(0x566a8c), hex(0x74869f), r);
            if vf < snow[u] + 14.0 * (r - 0.5) {
                m = mix(hex(0xb4c0d2), hex(0xf2f5f8), r);
            }
            let lit = 1.0 + 0.2 * facing[u] * smoothstep(14.0, 0.0, depth);
            m = scale(m, lit);
            return opaque(mix(m, hex(0xb8c6d8), 0.5 * smoothstep(0.0, 70.0, depth)));
        }
        // Clouds: thresholded fBm; greyer where more cloud lies just above
        // (lit from above).
        let (mut c, band) = rows[v];
        if band > 0.0 {
            let d = clouds.at(uf, vf);
            if d > 0.45 {
                let density = smoothstep(0.45, 0.75, d) * band;
                let shade = smoothstep(0.0, 0.12, clouds.at(uf, vf - 5.0) - d);
                let cloud = mix(hex(0xfbfbfd), hex(0xa3adbf), shade);
                c = mix(c, cloud, density * 0.92);
            }
        }
        opaque(c)
    })
}
