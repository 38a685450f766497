//! The brushes the procedural textures are painted with: seeded hash noise,
//! value noise that tiles at any texture size, colour arithmetic, and an
//! emboss light over a height field.
//!
//! Everything is a pure function of its arguments and the seed (a hash of the
//! texture's name), so a texture is the same on every run: no clock, no
//! global random state. Across platforms the integer hashing is exact and
//! `+ - * / sqrt` round identically (IEEE 754); the few libm calls (`sin`,
//! `powf`, `asin`) may differ in the last bit, which can at worst move a texel
//! by one step of 8-bit colour.

/// A colour, each channel 0..=1 (sRGB values, mixed as plain numbers).
pub type Rgb = [f32; 3];

/// A fully transparent texel.
pub const CLEAR: [u8; 4] = [0, 0, 0, 0];

/// `0xRRGGBB` as a colour.
pub const fn hex(c: u32) -> Rgb {
    [((c >> 16) & 0xff) as f32 / 255.0, ((c >> 8) & 0xff) as f32 / 255.0, (c & 0xff) as f32 / 255.0]
}

pub fn mix(a: Rgb, b: Rgb, t: f32) -> Rgb {
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t]
}

pub fn scale(c: Rgb, k: f32) -> Rgb {
    [c[0] * k, c[1] * k, c[2] * k]
}

pub fn add(a: Rgb, b: Rgb) -> Rgb {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// Rounds to an opaque 8-bit texel, clamping overbright channels.
pub fn opaque(c: Rgb) -> [u8; 4] {
    let q = |x: f32| (x.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    [q(c[0]), q(c[1]), q(c[2]), 255]
}

pub fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// FNV-1a of the upper-cased name: each texture gets its own noise, and the
/// same texture the same noise whatever case the map spelled it in.
pub fn seed_of(name: &str) -> u32 {
    name.bytes().fold(0x811c_9dc5, |h, b| (h ^ b.to_ascii_uppercase() as u32).wrapping_mul(0x0100_0193))
}

/// A well-mixed 32-bit hash of a lattice point (the `lowbias32` finaliser by
/// Chris Wellons, whose constants were searched for low avalanche bias).
pub fn hash(seed: u32, x: i32, y: i32) -> u32 {
    let mut h = seed ^ (x as u32).wrapping_mul(0x9e37_79b1) ^ (y as u32).wrapping_mul(0x85eb_ca77);
    h ^= h >> 16;
    h = h.wrapping_mul(0x7feb_352d);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846c_a68b);
    h ^ (h >> 16)
}

/// A hash as a number in `[0, 1)`.
pub fn rand01(seed: u32, x: i32, y: i32) -> f32 {
    (hash(seed, x, y) >> 8) as f32 / (1u32 << 24) as f32
}

/// Value noise in `[0, 1]` on an integer lattice that repeats every `px` by
/// `py` cells, so a texture built from `u / width * px` tiles seamlessly at any
/// width, power of two or not.
pub fn value_noise(seed: u32, x: f32, y: f32, px: i32, py: i32) -> f32 {
    let (ix, iy) = (floor(x), floor(y));
    let (tx, ty) = (x - ix as f32, y - iy as f32);
    let (x0, y0) = (wrap(ix, px), wrap(iy, py));
    let x1 = if x0 + 1 == px { 0 } else { x0 + 1 };
    let y1 = if y0 + 1 == py { 0 } else { y0 + 1 };
    let at = |x: i32, y: i32| rand01(seed, x, y);
    // Smoothstep weights hide the lattice's grid lines.
    let (sx, sy) = (tx * tx * (3.0 - 2.0 * tx), ty * ty * (3.0 - 2.0 * ty));
    let top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * sx;
    let bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * sx;
    top + (bottom - top) * sy
}

/// `x.floor() as i32` without the libm call that `f32::floor` compiles to on
/// baseline x86-64 (no SSE4.1 `roundss`). Noise coordinates here are small,
/// well inside the i32 range.
fn floor(x: f32) -> i32 {
    let i = x as i32;
    if (i as f32) > x {
        i - 1
    } else {
        i
    }
}

/// `i` reduced into `0..p`. Noise coordinates are nearly always in range
/// already, and this runs per octave per texel: skip the integer division.
fn wrap(i: i32, p: i32) -> i32 {
    if (0..p).contains(&i) {
        i
    } else {
        i.rem_euclid(p)
    }
}

/// Fractal sum of `octaves` layers of [`value_noise`], each at twice the
/// frequency and half the weight of the last, normalised to `[0, 1]`.
pub fn fbm(seed: u32, x: f32, y: f32, px: i32, py: i32, octaves: u32) -> f32 {
    let (mut sum, mut weight, mut total, mut freq) = (0.0, 1.0, 0.0, 1);
    for octave in 0..octaves {
        let f = freq as f32;
        sum += weight * value_noise(seed.wrapping_add(octave), x * f, y * f, px * freq, py * freq);
        total += weight;
        weight *= 0.5;
        freq *= 2;
    }
    sum / total
}

/// Tileable fBm over a texture of `size` texels with `cells` lattice cells
/// across and down at the coarsest octave: the same values as [`fbm`], but
/// each octave's lattice is hashed once into a table. Hashing four corners per
/// octave per texel instead took all procedural textures 31 ms rather than
/// 20 ms (release, fastest of 5 runs, 2-core dev VM).
pub struct TileNoise {
    /// Texels to lattice cells of the coarsest octave.
    scale: (f32, f32),
    octaves: Vec<Lattice>,
    /// 1 / the sum of the octave weights, so the result spans [0, 1].
    norm: f32,
}

struct Lattice {
    px: i32,
    py: i32,
    /// Row-major, `py + 1` rows of `px + 1` values: the last row and column
    /// repeat the first, so a cell's four corners need no wrapping.
    values: Vec<f32>,
}

impl TileNoise {
    pub fn new(seed: u32, size: (usize, usize), cells: (i32, i32), octaves: u32) -> TileNoise {
        let lattices = (0..octaves)
            .map(|o| {
                let (px, py) = (cells.0 << o, cells.1 << o);
                let values = (0..=py)
                    .flat_map(|y| (0..=px).map(move |x| rand01(seed.wrapping_add(o), x % px, y % py)))
                    .collect();
                Lattice { px, py, values }
            })
            .collect();
        let total: f32 = (0..octaves).map(|o| 0.5f32.powi(o as i32)).sum();
        TileNoise {
            scale: (cells.0 as f32 / size.0 as f32, cells.1 as f32 / size.1 as f32),
            octaves: lattices,
            norm: 1.0 / total,
        }
    }

    /// Noise at texel `(u, v)`; coordinates outside the texture wrap.
    pub fn at(&self, u: f32, v: f32) -> f32 {
        let (mut x, mut y) = (u * self.scale.0, v * self.scale.1);
        let (mut sum, mut weight) = (0.0, 1.0);
        for lattice in &self.octaves {
            sum += weight * lattice.sample(x, y);
            weight *= 0.5;
            x *= 2.0;
            y *= 2.0;
        }
        sum * self.norm
    }
}

impl Lattice {
    fn sample(&self, x: f32, y: f32) -> f32 {
        let (ix, iy) = (floor(x), floor(y));
        let (tx, ty) = (x - ix as f32, y - iy as f32);
        let (x0, y0) = (wrap(ix, self.px) as usize, wrap(iy, self.py) as usize);
        let stride = self.px as usize + 1;
        let i = y0 * stride + x0;
        let (a, b) = (self.values[i], self.values[i + 1]);
        let (c, d) = (self.values[i + stride], self.values[i + stride + 1]);
        let (sx, sy) = (tx * tx * (3.0 - 2.0 * tx), ty * ty * (3.0 - 2.0 * ty));
        let top = a + (b - a) * sx;
        let bottom = c + (d - c) * sx;
        top + (bottom - top) * sy
    }
}

/// A per-texel scalar field, column-major like [`Texture`](crate::texture::Texture).
pub struct Field {
    pub w: usize,
    pub h: usize,
    pub data: Vec<f32>,
}

impl Field {
    pub fn new(w: usize, h: usize, mut f: impl FnMut(usize, usize) -> f32) -> Field {
        let mut data = Vec::with_capacity(w * h);
        for u in 0..w {
            for v in 0..h {
                data.push(f(u, v));
            }
        }
        Field { w, h, data }
    }

    pub fn at(&self, u: usize, v: usize) -> f32 {
        self.data[u * self.h + v]
    }

    /// The value at any coordinates, wrapped: the fields belong to tiling
    /// textures.
    pub fn wrapped(&self, u: i64, v: i64) -> f32 {
        let u = u.rem_euclid(self.w as i64) as usize;
        let v = v.rem_euclid(self.h as i64) as usize;
        self.data[u * self.h + v]
    }

    /// Emboss lighting of this field read as a height map, light from the top
    /// left (as Doom's artists painted it): a slope rising towards the bottom
    /// right faces the light. Returns a brightness factor around 1.
    pub fn light(&self, u: usize, v: usize, strength: f32) -> f32 {
        let (u, v) = (u as i64, v as i64);
        let rise = self.wrapped(u + 1, v + 1) - self.wrapped(u - 1, v - 1);
        (1.0 + strength * rise).max(0.2)
    }
}

/// Brightness of a vertical cylinder of radius `r` centred at `cx`, seen at
/// `x`: Lambert with the light up-left and in front, plus a soft highlight.
/// Used for the round sprites (barrel, pole, column).
pub fn cylinder(x: f32, cx: f32, r: f32) -> f32 {
    let nx = ((x - cx) / r).clamp(-1.0, 1.0);
    let nz = (1.0 - nx * nx).sqrt();
    // Light direction (-0.55, 0.83) in the x-z plane, normalised.
    let diffuse = (-0.55 * nx + 0.83 * nz).max(0.0);
    let highlight = smoothstep(0.9, 1.0, diffuse) * 0.35;
    0.35 + 0.75 * diffuse + highlight
}
