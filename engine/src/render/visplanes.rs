//! Textured floors and ceilings as horizontal spans (Doom's visplanes).
//!
//! Along a screen row a horizontal plane is at one distance, so a span needs
//! its light once and steps its texture coordinates by a constant: two adds
//! and two predictable wraps per pixel, where the per-column alternative
//! ([`super::planes`]) pays a distance, two wraps through float conversions
//! and a light level per pixel. The walk records which rows of each column
//! show which plane; after the strip's walk the planes are drawn row by row.
//! Figures and the choice are in ARCHITECTURE.md.

use super::columns::ColumnWriter;
use super::light::Lighting;
use super::view::Camera;
use crate::texture::{Texture, TextureId};

/// What makes two plane runs the same visplane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PlaneKey {
    pub texture: TextureId,
    pub height: f64,
    pub light: u8,
}

/// One plane's rows per column of the strip: `top[i]..bottom[i]` for column
/// `x0 + i` (empty when `top >= bottom`).
#[derive(Debug)]
pub(crate) struct Visplane {
    key: PlaneKey,
    top: Vec<u16>,
    bottom: Vec<u16>,
    min: usize,
    max: usize,
}

/// The strip's visplanes, reused frame to frame (no static limit: a new
/// visplane opens whenever a column of the current one is taken).
#[derive(Debug, Default)]
pub(crate) struct Visplanes {
    planes: Vec<Visplane>,
    used: usize,
    x0: usize,
    width: usize,
    /// Per row, the column where the span being gathered started.
    span_start: Vec<usize>,
    /// One span's texels, lit in place before they go to the canvas.
    row: Vec<u32>,
}

impl Visplanes {
    pub(crate) fn begin_strip(&mut self, x0: usize, x1: usize) {
        self.used = 0;
        self.x0 = x0;
        self.width = x1 - x0;
    }

    /// Records that rows `[y0, y1)` of column `x` show the plane `key`.
    pub(crate) fn add(&mut self, key: PlaneKey, x: usize, y0: i32, y1: i32) {
        if y1 <= y0 {
            return;
        }
        let i = x - self.x0;
        // The latest visplane of this key, if column x is still free in it.
        let found = self.planes[..self.used]
            .iter()
            .rposition(|p| p.key == key)
            .filter(|&k| self.planes[k].top[i] >= self.planes[k].bottom[i]);
        let k = match found {
            Some(k) => k,
            None => self.open(key),
        };
        let p = &mut self.planes[k];
        p.top[i] = y0 as u16;
        p.bottom[i] = y1 as u16;
        p.min = p.min.min(i);
        p.max = p.max.max(i);
    }

    fn open(&mut self, key: PlaneKey) -> usize {
        if self.used == self.planes.len() {
            self.planes.push(Visplane { key, top: Vec::new(), bottom: Vec::new(), min: 0, max: 0 });
        }
        let p = &mut self.planes[self.used];
        p.key = key;
        p.top.clear();
        p.top.resize(self.width, u16::MAX);
        p.bottom.clear();
        p.bottom.resize(self.width, 0);
        p.min = usize::MAX;
        p.max = 0;
        self.used += 1;
        self.used - 1
    }

    /// Draws every visplane of the strip as horizontal spans.
    pub(crate) fn draw(
        &mut self,
        out: &mut ColumnWriter,
        cam: &Camera,
        lighting: &Lighting,
        inv_rows: &[f64],
        textures: &crate::texture::TextureSet,
    ) {
        self.span_start.resize(cam.height, 0);
        self.row.resize(4 * self.width, 0);
        for k in 0..self.used {
            let p = &self.planes[k];
            if p.min > p.max {
                continue;
            }
            let texture = textures.get(p.key.texture);
            let ray = cam.forward + cam.right * cam.column_slope(0);
            let span = SpanPainter { cam, lighting, inv_rows, texture, key: p.key, x0: self.x0, ray };
            // Doom's R_MakeSpans: walk the columns; rows that stop being
            // covered end a span, rows that start being covered open one.
            let (mut t1, mut b1) = (0u16, 0u16);
            for i in p.min..=p.max + 1 {
                let (t2, b2) = if i <= p.max && p.top[i] < p.bottom[i] { (p.top[i], p.bottom[i]) } else { (0, 0) };
                if (t2, b2) == (t1, b1) {
                    continue;
                }
                // Only the rows where the two columns differ matter:
                // [t1, b1) minus [t2, b2) ends spans, the reverse opens them.
                // Written out, each range tested before it is walked: as
                // arrays of ranges and a chained iterator the walk cost 64k
                // instructions a frame on deadly_corridor at 160x120, most
                // of it on empty ranges.
                if t1 < b1.min(t2) {
                    draw_ending(&span, out, &mut self.row, &self.span_start, t1..b1.min(t2), i);
                }
                if t1.max(b2) < b1 {
                    draw_ending(&span, out, &mut self.row, &self.span_start, t1.max(b2)..b1, i);
                }
                if t2 < b2.min(t1) {
                    self.span_start[usize::from(t2)..usize::from(b2.min(t1))].fill(i);
                }
                if t2.max(b1) < b2 {
                    self.span_start[usize::from(t2.max(b1))..usize::from(b2)].fill(i);
                }
                (t1, b1) = (t2, b2);
            }
        }
    }
}

/// Draws the spans of rows `ends` that end before strip column `i`. Four
/// rows in a row that began at the same column go to the canvas together,
/// each column's four pixels adjacent there: one cache line touched per
/// column where four single rows touch it four times.
#[inline(always)]
fn draw_ending(
    span: &SpanPainter,
    out: &mut ColumnWriter,
    row: &mut [u32],
    span_start: &[usize],
    ends: std::ops::Range<u16>,
    i: usize,
) {
    let width = row.len() / 4;
    let mut y = ends.start as usize;
    while y < ends.end as usize {
        let i0 = span_start[y];
        let n = i - i0;
        let four = y + 4 <= ends.end as usize && span_start[y + 1..y + 4].iter().all(|&s| s == i0);
        if four && !out.sampling.bilinear {
            let (r0, rest) = row.split_at_mut(width);
            let (r1, rest) = rest.split_at_mut(width);
            let (r2, r3) = rest.split_at_mut(width);
            for (k, r) in [&mut *r0, &mut *r1, &mut *r2, &mut *r3].into_iter().enumerate() {
                span.lit_row(&mut r[..n], (y + k) as i32, i0, i);
            }
            out.put_four_rows(y as i32, span.x0 + i0, [&r0[..n], &r1[..n], &r2[..n], &r3[..n]]);
            y += 4;
        } else {
            span.draw(out, &mut row[..width], y as i32, i0, i);
            y += 1;
        }
    }
}

/// Draws one plane's spans.
struct SpanPainter<'a> {
    cam: &'a Camera,
    lighting: &'a Lighting,
    inv_rows: &'a [f64],
    texture: &'a Texture,
    key: PlaneKey,
    x0: usize,
    /// The ray of column 0 (forward + right * slope(0)), the same for every span.
    ray: glam::DVec2,
}

/// Fixed-point fraction bits of the texture coordinate steppers.
const FRAC: u32 = 16;

impl SpanPainter<'_> {
    /// Row `y`, strip columns `[i0, i1)`; `row` is scratch as wide as the strip.
    fn draw(&self, out: &mut ColumnWriter, row: &mut [u32], y: i32, i0: usize, i1: usize) {
        let (x0, x1) = (self.x0 + i0, self.x0 + i1);
        if out.sampling.bilinear {
            let (tint, anchor, step) = self.row_walk(y);
            let texture = self.texture;
            out.fill_row(y, x0, x1, |x| {
                let p = anchor + step * x as f64;
                tint.apply(texture.bilinear(p.x, -p.y))
            });
            return;
        }
        let row = &mut row[..x1 - x0];
        self.lit_row(row, y, i0, i1);
        out.put_row(y, x0, row);
    }

    /// Row `y`'s light, and the map point under screen column 0 and the
    /// step to the next column.
    fn row_walk(&self, y: i32) -> (super::light::Tint, glam::DVec2, glam::DVec2) {
        let cam = self.cam;
        let dist = (self.key.height - cam.z) * self.inv_rows[y as usize];
        // On or beyond the horizon the row never meets the plane: sample far.
        let dist = if dist >= 0.0 { dist.min(1e12) } else { 0.0 };
        let tint = self.lighting.tint(self.key.light, dist);
        // The map point under column x is eye + dist * (forward + right * t_x),
        // and t steps by 1/focal per column. Every span of the row steps from
        // the same anchor, the point under column 0, so a pixel's texel
        // depends on its position alone, not on where its span began: the
        // same however the screen is cut into strips or the plane into spans.
        let anchor = cam.eye + self.ray * dist;
        let step = cam.right * (dist / cam.focal);
        (tint, anchor, step)
    }

    /// Row `y`'s texels for strip columns `[i0, i1)`, lit, into `row` (as
    /// long as the span), point sampled.
    fn lit_row(&self, row: &mut [u32], y: i32, i0: usize, i1: usize) {
        let (tint, anchor, step) = self.row_walk(y);
        let x0 = self.x0 + i0;
        let (w, h) = (self.texture.width as i64, self.texture.height as i64);
        let one = 1i64 << FRAC;
        let fixed = |c: f64, size: i64| -> i64 {
            let size_f = size as f64;
            // A power of two's reciprocal is exact, and so the product is
            // the quotient to the bit, for a multiply where a division was.
            let whole = if size.count_ones() == 1 { c * (1.0 / size_f) } else { c / size_f };
            ((c - crate::geom::floor(whole) * size_f) * one as f64) as i64
        };
        let (wf, hf) = (w << FRAC, h << FRAC);
        let (du, dv) = ((step.x * one as f64) as i64, (-step.y * one as f64) as i64);
        let (u0, v0) = (fixed(anchor.x, w).clamp(0, wf - 1), fixed(-anchor.y, h).clamp(0, hf - 1));
        let columns = x0 as i64;
        let texels = &self.texture.texels;
        // Three passes, as the wall columns: the texels into `row`, the
        // light over it (vectorised), then (the caller) the row into the
        // canvas.
        debug_assert_eq!(row.len(), i1 - i0);
        if w.count_ones() == 1 && h.count_ones() == 1 {
            // Power-of-two sizes (every Doom flat): wrap by masking, with no
            // tests and no divisions (a mask keeps a sum modulo the size
            // whatever multiples of it the steps carry).
            let u = u0.wrapping_add(columns.wrapping_mul(du)) & (wf - 1);
            let v = v0.wrapping_add(columns.wrapping_mul(dv)) & (hf - 1);
            let steps = Steps { u, v, du, dv, umask: wf - 1, vmask: hf - 1, shift: h.trailing_zeros() };
            let lit = flat_texels(row, texels, steps, tint);
            if lit < row.len() {
                tint.apply_all(&mut row[lit..]);
            }
            return;
        } else {
            // Steps of a whole texture or more (far planes) wrap by modulo.
            let (du, dv) = (du % wf, dv % hf);
            let mut u = (u0 + columns * du).rem_euclid(wf);
            let mut v = (v0 + columns * dv).rem_euclid(hf);
            let height = self.texture.height;
            for p in row.iter_mut() {
                *p = texels[(u >> FRAC) as usize * height + (v >> FRAC) as usize];
                u += du;
                if u >= wf {
                    u -= wf;
                } else if u < 0 {
                    u += wf;
                }
                v += dv;
                if v >= hf {
                    v -= hf;
                } else if v < 0 {
                    v += hf;
                }
            }
        }
        tint.apply_all(row);
    }
}

/// A span's walk over a power-of-two texture: texture coordinates `u` and
/// `v` (16.16 fixed point) stepped by `du` and `dv` a pixel, kept modulo the
/// texture's size by `umask` and `vmask`; the texel is `texels[u << shift | v]`
/// (column-major texels, `shift` the log2 of the height).
#[derive(Clone, Copy)]
struct Steps {
    u: i64,
    v: i64,
    du: i64,
    dv: i64,
    umask: i64,
    vmask: i64,
    shift: u32,
}

/// One span's texels from a power-of-two texture into `row`. Masks keep a
/// sum modulo the size whatever multiples of it the steps carry, so there
/// are no tests and no divisions. With AVX2 eight pixels' texel indices are
/// found at once in 32-bit lanes ([`eights`]) and the eight texels lit by
/// `tint` while in a register (the last few too); the loads stay one a
/// pixel. Returns how many pixels from the start are lit already (the rest
/// are texels as they are).
#[multiversion::multiversion(targets("x86_64+avx2"))]
fn flat_texels(row: &mut [u32], texels: &[u32], steps: Steps, tint: super::light::Tint) -> usize {
    let Steps { mut u, mut v, du, dv, umask, vmask, shift } = steps;
    let done = multiversion::target::match_target! {
        "x86_64+avx2" => eights::texels(row, texels, steps, tint),
        _ => { let _ = tint; 0 },
    };
    if done == row.len() {
        return done;
    }
    u = u.wrapping_add((done as i64).wrapping_mul(du)) & umask;
    v = v.wrapping_add((done as i64).wrapping_mul(dv)) & vmask;
    let texel = |u: i64, v: i64| texels[((u >> FRAC) << shift | v >> FRAC) as usize];
    // Two pixels an iteration: half the loop's own count and test.
    let mut pairs = row[done..].chunks_exact_mut(2);
    for pair in &mut pairs {
        let (u1, v1) = (u.wrapping_add(du) & umask, v.wrapping_add(dv) & vmask);
        pair[0] = texel(u, v);
        pair[1] = texel(u1, v1);
        u = u1.wrapping_add(du) & umask;
        v = v1.wrapping_add(dv) & vmask;
    }
    for p in pairs.into_remainder() {
        *p = texel(u, v);
    }
    done
}

#[cfg(target_arch = "x86_64")]
mod eights {
    use super::{Steps, FRAC};
    use crate::render::light::{lanes16::Eight, Tint};
    use std::arch::x86_64::{
        __m256i, _mm256_add_epi32, _mm256_and_si256, _mm256_mullo_epi32, _mm256_or_si256, _mm256_set1_epi32,
        _mm256_setr_epi32, _mm256_sll_epi32, _mm256_srli_epi32, _mm_cvtsi32_si128,
    };

    /// Doom's flats are 64x64: their texels as a fixed-size array, whose
    /// masked indices need no bounds test.
    const FLAT: usize = 64 * 64;

    /// [`super::flat_texels`]'s pixels eight at a time: the eight `u` and
    /// `v` in 32-bit lanes (the texture's size in fixed point, at most
    /// 2^32, divides the lanes' wrap, so the masks give what the 64-bit
    /// steps give), the indices in five instructions, then the loads, then
    /// the light on the eight in a register. Leaves fewer than eight
    /// pixels; returns how many it did.
    #[target_feature(enable = "avx2")]
    pub(super) fn texels(row: &mut [u32], texels: &[u32], s: Steps, tint: Tint) -> usize {
        match <&[u32; FLAT]>::try_from(texels) {
            // Every index is below the texture's size, so the mask changes
            // none; it only lets the compiler drop the bounds tests.
            Ok(flat) => walk(row, s, tint, |i| flat[i as usize & (FLAT - 1)]),
            Err(_) => walk(row, s, tint, |i| texels[i as usize]),
        }
    }

    #[target_feature(enable = "avx2")]
    #[inline]
    fn walk(row: &mut [u32], s: Steps, tint: Tint, texel: impl Fn(u32) -> u32) -> usize {
        const WIDE: i64 = 1 << 32;
        if s.umask >= WIDE || s.vmask >= WIDE {
            return 0;
        }
        // Lane k holds x + k dx (wrapping, as the 64-bit steps do modulo
        // the masks), made in the vector unit: eight scalar multiplies and
        // inserts a lane were a tenth of a short span's cost.
        let ks = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
        let lanes = |x: i64, dx: i64| {
            _mm256_add_epi32(_mm256_set1_epi32(x as i32), _mm256_mullo_epi32(_mm256_set1_epi32(dx as i32), ks))
        };
        let (u, v) = (lanes(s.u, s.du), lanes(s.v, s.dv));
        let (du8, dv8) =
            (_mm256_set1_epi32((s.du as i32).wrapping_mul(8)), _mm256_set1_epi32((s.dv as i32).wrapping_mul(8)));
        let (umask, vmask) = (_mm256_set1_epi32(s.umask as i32), _mm256_set1_epi32(s.vmask as i32));
        let shift = _mm_cvtsi32_si128(s.shift as i32);
        let light = Eight::new(tint);
        let (mut u, mut v) = (_mm256_and_si256(u, umask), _mm256_and_si256(v, vmask));
        // Eight pixels' texels, lit: every lane's index is inside the
        // texture (masked), so a last, partial eight is fetched whole too.
        let lit_eight = |u: __m256i, v: __m256i| -> [u32; 8] {
            let column = _mm256_sll_epi32(_mm256_srli_epi32::<{ FRAC as i32 }>(u), shift);
            let at: [u32; 8] =
                bytemuck::cast::<__m256i, [u32; 8]>(_mm256_or_si256(column, _mm256_srli_epi32::<{ FRAC as i32 }>(v)));
            let fetched = bytemuck::cast::<[u32; 8], __m256i>(at.map(&texel));
            bytemuck::cast::<__m256i, [u32; 8]>(light.apply(fetched))
        };
        let (eights, rest) = row.as_chunks_mut::<8>();
        for eight in eights.iter_mut() {
            *eight = lit_eight(u, v);
            u = _mm256_and_si256(_mm256_add_epi32(u, du8), umask);
            v = _mm256_and_si256(_mm256_add_epi32(v, dv8), vmask);
        }
        // The last few pixels the same way, where a scalar loop and the
        // light's own pass cost more than the pixels: most of a small
        // frame's spans are shorter than 16 pixels.
        if !rest.is_empty() {
            let n = rest.len();
            rest.copy_from_slice(&lit_eight(u, v)[..n]);
        }
        row.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A span's lit texels, the AVX2 eights included (64x64 flats through
    /// the fixed-size path), are those of the plain formula `(u + k du) mod
    /// size`, `(v + k dv) mod size`, lit, for steps of either sign, smaller
    /// and larger than a texel and wider than the texture, spans shorter and
    /// longer than eight, and textures not square.
    #[test]
    fn flat_texels_match_the_formula() {
        let lighting = crate::render::light::Lighting { diminishing: true, fog: None };
        let tint = lighting.tint(150, 700.0);
        for (w, h) in [(64i64, 64i64), (1, 1), (8, 2), (128, 32), (2, 256), (32, 128)] {
            let texels: Vec<u32> = (0..(w * h) as u32).map(|i| i.wrapping_mul(0x9E37_79B9) | 1).collect();
            let (wf, hf) = (w << FRAC, h << FRAC);
            let steps = [0, 1, 5_000, -5_000, 65_536, -70_001, 300_000, 9 * (64 << FRAC) + 3];
            for (k, &du) in steps.iter().enumerate() {
                let dv = steps[(k * 3 + 1) % steps.len()];
                for (u, v) in [(0, 0), (wf - 1, hf - 1), (12_345 % wf, 54_321 % hf)] {
                    for len in [1usize, 7, 8, 9, 17, 240] {
                        let mut got = vec![0u32; len];
                        let shift = h.trailing_zeros();
                        let steps = Steps { u, v, du, dv, umask: wf - 1, vmask: hf - 1, shift };
                        let lit = flat_texels(&mut got, &texels, steps, tint);
                        tint.apply_all(&mut got[lit..]);
                        let want: Vec<u32> = (0..len as i64)
                            .map(|k| {
                                let (tu, tv) =
                                    ((u + k * du).rem_euclid(wf) >> FRAC, (v + k * dv).rem_euclid(hf) >> FRAC);
                                tint.apply(texels[(tu * h + tv) as usize])
                            })
                            .collect();
                        assert_eq!(got, want, "{w}x{h} du {du} dv {dv} u {u} v {v} len {len}");
                    }
                }
            }
        }
    }
}
