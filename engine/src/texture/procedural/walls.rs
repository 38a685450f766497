//! Opaque wall surfaces: masonry, wood, metal, a stair riser, a door and a
//! support beam. Most are a height field lit by [`Field::light`] over an
//! albedo, so mortar, seams and rivets read as depth.

use super::paint::{add, hex, mix, opaque, rand01, scale, smoothstep, Field, TileNoise};
use crate::texture::Texture;

/// Staggered red-brown bricks, 32x16 with 2-texel mortar: a 128x64 texture
/// holds four courses, an even number so the half-brick stagger tiles.
pub fn brick(seed: u32) -> Texture {
    const W: usize = 128;
    const H: usize = 64;
    const BW: f32 = 32.0;
    const BH: f32 = 16.0;
    let grain = TileNoise::new(seed, (W, H), (32, 16), 3);
    let grime = TileNoise::new(seed ^ 0x51, (W, H), (4, 2), 3);
    let chips = TileNoise::new(seed ^ 0x77, (W, H), (24, 12), 2);
    // Brick (column, course) and position inside it, for texel (u, v).
    let cell = |u: usize, v: usize| {
        let course = v / BH as usize;
        let shift = if course % 2 == 1 { BW as usize / 2 } else { 0 };
        let x = (u + shift) % W;
        let col = x / BW as usize;
        let (bx, by) = ((x % BW as usize) as f32 + 0.5, (v % BH as usize) as f32 + 0.5);
        (col, course, bx, by)
    };
    let height = Field::new(W, H, |u, v| {
        let (_, _, bx, by) = cell(u, v);
        // Distance into the brick from its nearest edge; mortar is the 2 texels
        // along the right and bottom, edges chipped by noise.
        let edge = bx.min(BW - 2.0 - bx).min(by).min(BH - 2.0 - by);
        let chip = (chips.at(u as f32, v as f32) - 0.5) * 2.2;
        smoothstep(-0.2, 1.6, edge + chip)
    });
    Texture::from_fn(W, H, |u, v| {
        let (col, course, _, _) = cell(u, v);
        let hgt = height.at(u, v);
        let (uf, vf) = (u as f32, v as f32);
        let tone = rand01(seed, col as i32, course as i32);
        let mut brick = mix(hex(0x7e3324), hex(0xa3573a), tone);
        if rand01(seed ^ 9, col as i32, course as i32) < 0.18 {
            brick = mix(brick, hex(0x5a2a20), 0.5); // the odd over-fired brick
        }
        brick = scale(brick, 0.8 + 0.4 * grain.at(uf, vf));
        let mortar = scale(hex(0x8a8276), 0.75 + 0.4 * grain.at(uf * 2.0, vf));
        let albedo = mix(mortar, brick, smoothstep(0.05, 0.35, hgt));
        let dirt = 0.8 + 0.3 * grime.at(uf, vf);
        opaque(scale(albedo, height.light(u, v, 0.9) * dirt))
    })
}

/// Grey irregular blocks: courses of varying height, each cut into blocks of
/// varying width, edges wobbled by noise. 96x128.
pub fn stone(seed: u32) -> Texture {
    const W: usize = 96;
    const H: usize = 128;
    const COURSES: [usize; 5] = [28, 22, 30, 24, 24];
    let warp = TileNoise::new(seed ^ 1, (W, H), (8, 8), 2);
    let grain = TileNoise::new(seed ^ 2, (W, H), (24, 32), 4);
    let stain = TileNoise::new(seed ^ 3, (W, H), (3, 4), 3);
    // For each course: its top, and its block boundaries (cumulative, shifted).
    let mut courses = Vec::new();
    let mut top = 0;
    for (i, &ch) in COURSES.iter().enumerate() {
        let mut cuts = Vec::new();
        let shift = (rand01(seed, i as i32, 99) * W as f32) as usize;
        let mut x = 0;
        let mut k = 0;
        while x < W {
            cuts.push((x + shift) % W);
            x += 22 + (rand01(seed, i as i32, k) * 22.0) as usize;
            k += 1;
            if W - x.min(W) < 18 {
                break; // a sliver at the end would read as a crack
            }
        }
        cuts.sort_unstable();
        courses.push((top, ch, cuts));
        top += ch;
    }
    // Block id and distance to the block's edge at a (warped) point.
    let block = |x: f32, y: f32| {
        let y = y.rem_euclid(H as f32);
        let x = x.rem_euclid(W as f32);
        let c = courses.iter().position(|(t, ch, _)| y < (t + ch) as f32).unwrap_or(0);
        let (t, ch, cuts) = &courses[c];
        let dy = (y - *t as f32).min((t + ch) as f32 - y);
        let next = cuts.iter().position(|&cx| cx as f32 > x).unwrap_or(cuts.len());
        let left = if next == 0 { cuts[cuts.len() - 1] as f32 - W as f32 } else { cuts[next - 1] as f32 };
        let right = if next == cuts.len() { cuts[0] as f32 + W as f32 } else { cuts[next] as f32 };
        let dx = (x - left).min(right - x);
        let id = (c as i32, ((next + cuts.len() - 1) % cuts.len()) as i32);
        (id, dx.min(dy))
    };
    // Block and edge distance per texel, column-major; computed once, as the
    // height field and the colours both need it.
    let blocks: Vec<((i32, i32), f32)> = (0..W * H)
        .map(|i| {
            let (uf, vf) = ((i / H) as f32 + 0.5, (i % H) as f32 + 0.5);
            let wx = (warp.at(uf, vf) - 0.5) * 6.0;
            let wy = (warp.at(uf + 40.0, vf + 17.0) - 0.5) * 6.0;
            block(uf + wx, vf + wy)
        })
        .collect();
    let grain = Field::new(W, H, |u, v| grain.at(u as f32, v as f32));
    let height = Field::new(W, H, |u, v| {
        let (_, d) = blocks[u * H + v];
        smoothstep(0.6, 3.5, d) + 0.25 * grain.at(u, v)
    });
    Texture::from_fn(W, H, |u, v| {
        let ((c, b), d) = blocks[u * H + v];
        let (uf, vf) = (u as f32, v as f32);
        let tone = rand01(seed, c, b);
        let tint = mix(hex(0x7d7a72), hex(0x8e8f92), rand01(seed ^ 5, c, b));
        let face = scale(tint, 0.78 + 0.3 * tone);
        let face = scale(face, 0.75 + 0.45 * grain.at(u, v));
        let face = mix(face, hex(0x4d4a40), 0.35 * smoothstep(0.55, 0.8, stain.at(uf, vf)));
        let albedo = mix(hex(0x2e2c29), face, smoothstep(0.3, 1.4, d));
        opaque(scale(albedo, height.light(u, v, 0.7)))
    })
}

/// Vertical planks with grain, dark gaps and nails at the butt joints. 64x128.
pub fn wood(seed: u32) -> Texture {
    const W: usize = 64;
    const H: usize = 128;
    const PLANKS: [usize; 4] = [15, 17, 16, 16];
    let figure = TileNoise::new(seed ^ 1, (W, H), (6, 3), 3);
    let fibre = TileNoise::new(seed ^ 2, (W, H), (64, 6), 2);
    let plank_of = |u: usize| {
        let mut left = 0;
        for (i, &pw) in PLANKS.iter().enumerate() {
            if u < left + pw {
                return (i, u - left, pw);
            }
            left += pw;
        }
        (0, 0, PLANKS[0])
    };
    // Each plank has one butt joint somewhere along its length.
    let joint = |p: usize| 8 + (rand01(seed, p as i32, 7) * (H - 16) as f32) as usize;
    let height = Field::new(W, H, |u, v| {
        let (p, x, pw) = plank_of(u);
        let edge = (x as f32 + 0.5).min(pw as f32 - 0.5 - x as f32);
        let j = joint(p) as f32;
        let along = (v as f32 + 0.5 - j).abs().min(H as f32 - (v as f32 + 0.5 - j).abs());
        let nail = |nv: f32, nu: f32| {
            let d = ((v as f32 + 0.5 - nv).powi(2) + (x as f32 + 0.5 - nu).powi(2)).sqrt();
            smoothstep(1.8, 0.6, d)
        };
        let nails = nail(j - 4.0, 3.5)
            .max(nail(j - 4.0, pw as f32 - 3.5))
            .max(nail(j + 4.0, 3.5))
            .max(nail(j + 4.0, pw as f32 - 3.5));
        smoothstep(0.0, 1.5, edge).min(smoothstep(0.0, 1.2, along)) + 0.4 * nails
    });
    Texture::from_fn(W, H, |u, v| {
        let (p, x, pw) = plank_of(u);
        let (uf, vf) = (u as f32, v as f32);
        let j = joint(p);
        // The boards either side of a joint are different trees.
        let piece = (p * 2 + usize::from(v >= j)) as i32;
        let tone = rand01(seed ^ 3, piece, 0);
        let light = mix(hex(0xa0703e), hex(0xb98a52), tone);
        let dark = mix(hex(0x5c3a1c), hex(0x6e4624), tone);
        // Grain: rings cut lengthwise are stripes along the plank, bent by
        // low-frequency noise (the figure) and broken by fine fibres.
        let bend = figure.at(uf + piece as f32 * 13.0, vf) * 9.0;
        let ring = ((x as f32 * 0.9 + bend + tone * 5.0) * 1.7).sin() * 0.5 + 0.5;
        let ring = smoothstep(0.55, 1.0, ring);
        let mut c = mix(light, dark, ring * 0.6 + 0.3 * fibre.at(uf, vf));
        let edge = (x as f32 + 0.5).min(pw as f32 - 0.5 - x as f32);
        let along = (v as f32 + 0.5 - j as f32).abs();
        let gap = smoothstep(0.0, 1.5, edge).min(smoothstep(0.0, 1.2, along));
        c = scale(c, 0.5 + 0.5 * gap);
        let hgt = height.at(u, v);
        if hgt > 1.05 {
            c = mix(hex(0x3a3a3c), hex(0x9a9a9c), (hgt - 1.05) * 1.5); // nail heads
        }
        opaque(scale(c, height.light(u, v, 0.6)))
    })
}

/// Riveted steel panels, two 48-texel panels per 64x96 tile.
pub fn metal(seed: u32) -> Texture {
    const W: usize = 64;
    const H: usize = 96;
    const PH: usize = 48;
    let brushed = TileNoise::new(seed ^ 1, (W, H), (2, 48), 2);
    let rust = TileNoise::new(seed ^ 2, (W, H), (6, 9), 4);
    let rivet = |x: f32, y: f32| {
        // Distance to the nearest rivet: rivets 4.5 in from each edge, five
        // along each side including the corners, evenly spaced.
        let (x0, x1, y0, y1) = (4.5, W as f32 - 4.5, 4.5, PH as f32 - 4.5);
        let (sx, sy) = ((x1 - x0) / 4.0, (y1 - y0) / 4.0);
        let near = |p: f32, lo: f32, step: f32| lo + ((p - lo) / step).round().clamp(0.0, 4.0) * step;
        let dist = |cx: f32, cy: f32| ((x - cx).powi(2) + (y - cy).powi(2)).sqrt();
        let ry = near(y, y0, sy);
        let rx = near(x, x0, sx);
        dist(x0, ry).min(dist(x1, ry)).min(dist(rx, y0)).min(dist(rx, y1))
    };
    let height = Field::new(W, H, |u, v| {
        let (x, y) = (u as f32 + 0.5, (v % PH) as f32 + 0.5);
        let edge = x.min(W as f32 - x).min(y).min(PH as f32 - y);
        let r = rivet(x, y);
        let dome = if r < 1.9 { (1.0 - (r / 1.9).powi(2)).sqrt() * 0.8 } else { 0.0 };
        smoothstep(0.5, 2.5, edge) * 0.6 + dome
    });
    Texture::from_fn(W, H, |u, v| {
        let (uf, vf) = (u as f32, v as f32);
        let (x, y) = (uf + 0.5, (v % PH) as f32 + 0.5);
        let panel = (v / PH) as i32;
        let base = mix(hex(0x5d666f), hex(0x6f7780), rand01(seed, panel, 0));
        let mut c = scale(base, 0.85 + 0.3 * brushed.at(uf, vf));
        // Rust gathers towards the bottom of each panel and around rivets.
        let wet = rust.at(uf, vf) + 0.35 * (y / PH as f32) - 0.2 * (rivet(x, y) / 9.0);
        c = mix(c, hex(0x6b4a32), 0.7 * smoothstep(0.6, 0.85, wet));
        let edge = x.min(W as f32 - x).min(y).min(PH as f32 - y);
        c = mix(hex(0x1e2226), c, smoothstep(0.2, 1.4, edge));
        if rivet(x, y) < 1.9 {
            c = hex(0x848c94);
        }
        opaque(scale(c, height.light(u, v, 1.1)))
    })
}

/// A stair riser: dark worn stone with a bright nosing along the top. 64x24.
pub fn step(seed: u32) -> Texture {
    const W: usize = 64;
    const H: usize = 24;
    let grain = TileNoise::new(seed, (W, H), (16, 6), 3);
    Texture::from_fn(W, H, |u, v| {
        let g = grain.at(u as f32, v as f32);
        let c = match v {
            0 => hex(0xe6dcc2),
            1..=3 => scale(hex(0xb8ab8e), 0.85 + 0.3 * g),
            4 => hex(0x3a342c),
            5 => hex(0x1a1714),
            _ => scale(mix(hex(0x2a2723), hex(0x3e3832), g), 1.0 - 0.2 * (v as f32 / H as f32)),
        };
        opaque(c)
    })
}

/// An iron-bound wooden door in a steel frame, with a ring handle. 80x128.
pub fn door(seed: u32) -> Texture {
    const W: usize = 80;
    const H: usize = 128;
    const FRAME: f32 = 6.0;
    let figure = TileNoise::new(seed ^ 1, (W, H), (4, 2), 3);
    let brushed = TileNoise::new(seed ^ 2, (W, H), (2, 64), 2);
    let straps = [30.0, 98.0];
    let strap_at = |y: f32| straps.iter().any(|&s| (y - s).abs() < 4.0);
    let ring = |x: f32, y: f32| ((x - 62.0).powi(2) + (y - 66.0).powi(2)).sqrt();
    let height = Field::new(W, H, |u, v| {
        let (x, y) = (u as f32 + 0.5, v as f32 + 0.5);
        let edge = x.min(W as f32 - x).min(y).min(H as f32 - y);
        let mut h = if edge < FRAME { 1.0 - smoothstep(FRAME - 1.5, FRAME, edge) * 0.6 } else { 0.4 };
        if edge >= FRAME {
            let board = ((x - FRAME) / 17.0).fract() * 17.0;
            h -= 0.3 * (1.0 - smoothstep(0.0, 1.2, board.min(17.0 - board)));
            if strap_at(y) {
                h = 0.75;
                let bolt = ((x - FRAME - 8.5) / 17.0).round() * 17.0 + FRAME + 8.5;
                let s = straps.iter().map(|&s| (y - s).abs()).fold(9.0, f32::min);
                if ((x - bolt).powi(2) + s.powi(2)).sqrt() < 1.8 {
                    h = 1.0;
                }
            }
        }
        if (ring(x, y) - 5.0).abs() < 1.3 || ring(x, y) < 1.5 {
            h = 1.2;
        }
        h
    });
    Texture::from_fn(W, H, |u, v| {
        let (x, y) = (u as f32 + 0.5, v as f32 + 0.5);
        let edge = x.min(W as f32 - x).min(y).min(H as f32 - y);
        let steel = scale(hex(0x5a6068), 0.85 + 0.3 * brushed.at(u as f32, v as f32));
        let c = if edge < FRAME || (strap_at(y) && edge >= FRAME) {
            steel
        } else {
            let board = ((x - FRAME) / 17.0) as i32;
            let tone = rand01(seed, board, 0);
            let across = (x - FRAME) % 17.0;
            let seam = smoothstep(0.0, 1.2, across.min(17.0 - across));
            let grain = ((x * 0.8 + figure.at(x, y) * 10.0 + tone * 7.0) * 1.5).sin() * 0.5 + 0.5;
            let wood = mix(mix(hex(0x7a5230), hex(0x8d6238), tone), hex(0x4d3119), smoothstep(0.5, 1.0, grain) * 0.6);
            scale(wood, 0.45 + 0.55 * seam)
        };
        let c = if (ring(x, y) - 5.0).abs() < 1.3 || ring(x, y) < 1.5 { hex(0x9c8450) } else { c };
        opaque(scale(c, height.light(u, v, 0.8)))
    })
}

/// A vertical steel I-beam with bolted plates, 32x128.
pub fn support(seed: u32) -> Texture {
    const W: usize = 32;
    const H: usize = 128;
    let brushed = TileNoise::new(seed, (W, H), (2, 32), 3);
    let height = Field::new(W, H, |u, v| {
        let x = u as f32 + 0.5;
        let y = (v % 64) as f32 + 0.5;
        let flange = !(6.0..26.0).contains(&x);
        let plate = (4.0..28.0).contains(&x) && (24.0..40.0).contains(&y);
        let bolt = [10.0, 22.0].iter().any(|&bx| {
            ((x - bx).powi(2) + (y - 28.0).powi(2)).sqrt() < 1.8 || ((x - bx).powi(2) + (y - 36.0).powi(2)).sqrt() < 1.8
        });
        let edge = x.min(W as f32 - x);
        if bolt {
            1.3
        } else if plate {
            0.9
        } else if flange {
            0.8 * smoothstep(0.0, 1.5, edge)
        } else {
            0.1
        }
    });
    Texture::from_fn(W, H, |u, v| {
        let x = u as f32 + 0.5;
        let hgt = height.at(u, v);
        let base = add(scale(hex(0x505a60), 0.8 + 0.35 * brushed.at(u as f32, v as f32)), [0.02, 0.01, 0.0]);
        let c = if hgt < 0.2 {
            // The web, recessed and in shadow from the flanges.
            let shadow = smoothstep(6.0, 10.0, x).min(smoothstep(26.0, 22.0, x));
            scale(base, 0.45 + 0.25 * shadow)
        } else if hgt > 1.2 {
            hex(0x8b939a)
        } else {
            base
        };
        opaque(scale(c, height.light(u, v, 0.9)))
    })
}
