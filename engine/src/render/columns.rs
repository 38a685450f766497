//! The pixel writer, the one piece every renderer shares: it fills vertical
//! runs of one colour and counts what it writes (the overdraw figures).
//!
//! Runs land in a column-major canvas covering one strip of the screen
//! (contiguous fills that stay in cache); [`present_strip`] then copies the
//! strip into the row-major framebuffer a whole cache line at a time. Why not
//! fill the framebuffer directly: a column of a 1920x1080 row-major buffer
//! touches 1080 cache lines, more than L1 holds, and that store took 88% of a
//! maze frame (measurements in ARCHITECTURE.md).

use super::buffers::BufferWriter;
use super::light::Tint;

pub struct ColumnWriter<'a> {
    /// Column-major strip: pixel (x, y) is `canvas[(x - x0) * height + y]`.
    canvas: &'a mut [u32],
    x0: usize,
    height: usize,
    /// Per-pixel write counts, laid out like the canvas, when asked for.
    counts: Option<&'a mut [u16]>,
    pub written: u64,
    /// Pixels the masked pass wrote over the opaque pass (not in `counts`).
    pub masked_written: u64,
    /// How textures are sampled (the sampling study's switches).
    pub sampling: Sampling,
    /// The strip's depth and label canvases, when the frame fills them:
    /// whoever paints a run says what surface it is (see [`super::buffers`]).
    pub buffers: BufferWriter<'a>,
}

/// Texture sampling other than the default, for the sampling study: bilinear
/// filtering on walls and flats, and affine (screen-linear) texture
/// coordinates on floors and ceilings drawn per column. The defaults are
/// Doom's: nearest texels, perspective-correct everywhere.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sampling {
    pub bilinear: bool,
    pub affine_planes: bool,
}

impl<'a> ColumnWriter<'a> {
    /// A writer for columns `[x0, x0 + canvas.len() / height)` of a frame
    /// `height` rows tall; `counts`, if given, is as long as the canvas.
    pub fn new(canvas: &'a mut [u32], x0: usize, height: usize, counts: Option<&'a mut [u16]>) -> Self {
        ColumnWriter {
            canvas,
            x0,
            height,
            counts,
            written: 0,
            masked_written: 0,
            sampling: Sampling::default(),
            buffers: BufferWriter::default(),
        }
    }

    /// Fills rows `[y0, y1)` of column `x`. Empty and inverted runs write nothing;
    /// callers keep rows within `0..=height` and `x` inside the strip.
    #[inline]
    pub fn fill(&mut self, x: usize, y0: i32, y1: i32, colour: u32) {
        if y1 <= y0 {
            return;
        }
        let base = (x - self.x0) * self.height;
        self.canvas[base + y0 as usize..base + y1 as usize].fill(colour);
        self.count(x, y0, y1);
    }

    /// Records a write of rows `[y0, y1)` of column `x` (callers: non-empty runs).
    #[inline]
    fn count(&mut self, x: usize, y0: i32, y1: i32) {
        let (y0, y1) = (y0 as usize, y1 as usize);
        self.written += (y1 - y0) as u64;
        if let Some(counts) = self.counts.as_deref_mut() {
            let base = (x - self.x0) * self.height;
            for c in &mut counts[base + y0..base + y1] {
                *c = c.saturating_add(1);
            }
        }
    }
}

impl ColumnWriter<'_> {
    /// Fills columns `[x0, x1)` of row `y` with `colour(x)`: a horizontal span
    /// of the opaque pass.
    #[inline]
    pub fn fill_row(&mut self, y: i32, x0: usize, x1: usize, mut colour: impl FnMut(usize) -> u32) {
        let y = y as usize;
        let start = (x0 - self.x0) * self.height + y;
        for (x, p) in (x0..x1).zip(self.canvas[start..].iter_mut().step_by(self.height)) {
            *p = colour(x);
        }
        self.count_row(start, x1 - x0);
    }

    /// Records a write of `n` pixels along a row from canvas index `start`.
    #[inline]
    fn count_row(&mut self, start: usize, n: usize) {
        self.written += n as u64;
        if let Some(counts) = self.counts.as_deref_mut() {
            for c in counts[start..].iter_mut().step_by(self.height).take(n) {
                *c = c.saturating_add(1);
            }
        }
    }

    /// Writes `pixels` to row `y` from column `x0` on: a horizontal span of
    /// the opaque pass.
    #[inline]
    pub fn put_row(&mut self, y: i32, x0: usize, pixels: &[u32]) {
        let start = (x0 - self.x0) * self.height + y as usize;
        // A plain strided store: through `fill_row`'s closure the compiler
        // kept the iterator on the stack, a third of the spans' time; and
        // `step_by`'s iterator cost more than the stores (deadly_corridor
        // at 160x120: 61k instructions a frame in its `Option`s).
        if let Some((&last, most)) = pixels.split_last() {
            let end = start + most.len() * self.height;
            for (column, &c) in self.canvas[start..end].chunks_exact_mut(self.height).zip(most) {
                column[0] = c;
            }
            self.canvas[end] = last;
        }
        self.count_row(start, pixels.len());
    }

    /// Writes four rows `y..y + 4` of the same span, from column `x0` on:
    /// each column's four pixels are adjacent in the canvas, so they go as
    /// one piece (a cache line touched once, where four rows' strided stores
    /// touch it four times).
    #[inline]
    pub fn put_four_rows(&mut self, y: i32, x0: usize, rows: [&[u32]; 4]) {
        let start = (x0 - self.x0) * self.height + y as usize;
        let n = rows[0].len();
        #[cfg(target_arch = "x86_64")]
        let done = sse2::four_columns(self.canvas, self.height, start, rows);
        #[cfg(not(target_arch = "x86_64"))]
        let done = 0;
        let pixels = rows[0].iter().zip(rows[1]).zip(rows[2]).zip(rows[3]);
        for (j, (((&a, &b), &c), &d)) in pixels.enumerate().skip(done) {
            let at = start + j * self.height;
            self.canvas[at..at + 4].copy_from_slice(&[a, b, c, d]);
        }
        for k in 0..4 {
            self.count_row(start + k, n);
        }
    }

    /// Writes one pixel of the masked pass (sprites, see-through middles).
    #[inline]
    pub fn put_masked(&mut self, x: usize, y: i32, colour: u32) {
        self.canvas[(x - self.x0) * self.height + y as usize] = colour;
        self.masked_written += 1;
    }

    /// Writes `texels`, lit by `tint`, down column `x` from row `y0` in the
    /// masked pass, where a texel is opaque (alpha not zero), keeping what is
    /// there elsewhere: a select, not a branch (a sprite's transparent texels
    /// mispredicted at every edge), vectorised ([`tint_over`]).
    #[inline]
    pub fn tint_opaque(&mut self, x: usize, y0: i32, texels: &[u32], tint: Tint) {
        let start = (x - self.x0) * self.height + y0 as usize;
        self.masked_written += tint_over(&mut self.canvas[start..start + texels.len()], texels, tint);
    }

    /// Writes one pixel of the masked pass two-thirds over what is there (a
    /// translucent middle texture: Boom's default translucency table is
    /// about 66% opaque).
    #[inline]
    /// The spectre's fuzz at `(x, y)`: the pixel `offset` rows away in the
    /// same column (clamped to the column), darkened by a quarter.
    pub fn put_fuzz(&mut self, x: usize, y: i32, offset: i32) {
        let column = (x - self.x0) * self.height;
        let from = (y + offset).clamp(0, self.height as i32 - 1) as usize;
        let [r, g, b, a] = self.canvas[column + from].to_le_bytes();
        let dark = |c: u8| (u16::from(c) * 3 / 4) as u8;
        self.canvas[column + y as usize] = u32::from_le_bytes([dark(r), dark(g), dark(b), a]);
        self.masked_written += 1;
    }

    pub fn put_blended(&mut self, x: usize, y: i32, colour: u32) {
        let p = &mut self.canvas[(x - self.x0) * self.height + y as usize];
        let (a, b) = (colour.to_le_bytes(), p.to_le_bytes());
        let mix = |k: usize| ((2 * u32::from(a[k]) + u32::from(b[k])) / 3) as u8;
        *p = u32::from_le_bytes([mix(0), mix(1), mix(2), b[3]]);
        self.masked_written += 1;
    }

    /// Fills rows `[y0, y1)` of column `x` with `colour(y)`.
    #[inline]
    pub fn fill_with(&mut self, x: usize, y0: i32, y1: i32, mut colour: impl FnMut(i32) -> u32) {
        if y1 <= y0 {
            return;
        }
        let base = (x - self.x0) * self.height;
        let run = &mut self.canvas[base + y0 as usize..base + y1 as usize];
        for (y, p) in (y0..y1).zip(run) {
            *p = colour(y);
        }
        self.count(x, y0, y1);
    }

    /// Fills rows `[y0, y1)` of column `x` from a texture column: row `y0`
    /// shows texel row `v`, each row below `dv` further, wrapping at the
    /// column's end, every texel tinted.
    #[inline]
    pub fn textured(&mut self, x: usize, (y0, y1): (i32, i32), column: &[u32], v: f64, dv: f64, tint: Tint) {
        if y1 <= y0 || column.is_empty() {
            return;
        }
        // 16.16 fixed point: an integer add and a compare per texel instead
        // of a float add, compare and conversion.
        const FRAC: u32 = 16;
        let h = column.len() as i64;
        let wrap = h << FRAC;
        // Wrapped without libm's `fmod` or, for power-of-two heights (most
        // textures), an integer division: both showed per column at 320x200.
        let v = crate::geom::floor_i64(v * f64::from(1u32 << FRAC));
        let mut v = crate::texture::wrap(v, wrap);
        // Steps of a whole texture or more (far walls) wrap by modulo.
        let dv = (dv * f64::from(1u32 << FRAC)) as i64;
        let dv = if dv < wrap { dv } else { dv % wrap };
        let base = (x - self.x0) * self.height;
        let run = &mut self.canvas[base + y0 as usize..base + y1 as usize];
        // Two passes: the texels first (a load and a store each, the wrap
        // tested once per stretch), then the light over the whole run, a
        // loop of plain arithmetic the compiler vectorises.
        let mut rest = &mut run[..];
        while !rest.is_empty() {
            // Rows before v wraps: the stretch needs no wrap test. A run that
            // ends first (a magnified wall) needs no division to say so.
            let until_wrap = if dv == 0 || (rest.len() as i64 - 1) * dv < wrap - v {
                rest.len()
            } else {
                ((wrap - v + dv - 1) / dv) as usize
            };
            let (stretch, tail) = rest.split_at_mut(until_wrap.min(rest.len()));
            v = stretch_texels(stretch, column, v, dv);
            if v >= wrap {
                v -= wrap;
            }
            rest = tail;
        }
        tint.apply_all(run);
        self.count(x, y0, y1);
    }
}

/// [`ColumnWriter::tint_opaque`]'s loop, compiled for AVX2 as well (picked
/// at run time), where the light and the select are eight pixels an
/// instruction. Returns the texels written.
#[multiversion::multiversion(targets("x86_64+avx2"))]
fn tint_over(run: &mut [u32], texels: &[u32], tint: Tint) -> u64 {
    for (p, &t) in run.iter_mut().zip(texels) {
        let lit = tint.apply(t);
        *p = if t >> 24 != 0 { lit } else { *p };
    }
    texels.iter().map(|&t| u64::from(t >> 24 != 0)).sum()
}

/// One stretch of a wall run, texel row `v` (16.16 fixed point) first and
/// `dv` further each row, none of them past the column's end: a load and a
/// store a pixel. With AVX2 a wall seen no smaller than its texels (`dv` at
/// most one texel a row: at 1080p every wall nearer than 960 units) takes
/// eight rows at once, whose texels lie within eight of the first, as one
/// load of those eight and a permute ([`window`]). Returns `v` past the
/// stretch.
#[multiversion::multiversion(targets("x86_64+avx2"))]
fn stretch_texels(stretch: &mut [u32], column: &[u32], v: i64, dv: i64) -> i64 {
    const FRAC: u32 = 16;
    let (done, mut v) = multiversion::target::match_target! {
        "x86_64+avx2" => window::eights(stretch, column, v, dv),
        _ => (0, v),
    };
    // Two rows an iteration: half the loop's own count and test.
    let mut pairs = stretch[done..].chunks_exact_mut(2);
    for pair in &mut pairs {
        pair[0] = column[(v >> FRAC) as usize];
        pair[1] = column[((v + dv) >> FRAC) as usize];
        v += 2 * dv;
    }
    for p in pairs.into_remainder() {
        *p = column[(v >> FRAC) as usize];
        v += dv;
    }
    v
}

#[cfg(target_arch = "x86_64")]
mod window {
    use std::arch::x86_64::{
        __m256i, _mm256_add_epi32, _mm256_permutevar8x32_epi32, _mm256_set1_epi32, _mm256_setr_epi32, _mm256_srli_epi32,
    };

    /// [`super::stretch_texels`]'s rows eight at a time while `dv` is at most
    /// one texel a row: then rows `y..y + 8` read texels `t..t + 8` at most,
    /// `t` row `y`'s (its fraction plus seven steps stays under eight
    /// texels), so one load of those eight and a permute by each row's
    /// offset from `t` fetch them all. Stops eight texels short of the
    /// column's end and leaves fewer than eight rows; returns the rows done
    /// and `v` after them.
    #[target_feature(enable = "avx2")]
    pub(super) fn eights(stretch: &mut [u32], column: &[u32], mut v: i64, dv: i64) -> (usize, i64) {
        const ONE: i64 = 1 << 16;
        if !(0..=ONE).contains(&dv) || v < 0 {
            return (0, v);
        }
        // Row k's offset from the first row, k * dv (at most 7 << 16).
        let d = dv as i32;
        let steps = _mm256_setr_epi32(0, d, 2 * d, 3 * d, 4 * d, 5 * d, 6 * d, 7 * d);
        let mut done = 0;
        for rows in stretch.as_chunks_mut::<8>().0 {
            let first = (v >> 16) as usize;
            let Some(&texels) = column.get(first..).and_then(<[u32]>::first_chunk::<8>) else { break };
            let offsets = _mm256_srli_epi32::<16>(_mm256_add_epi32(_mm256_set1_epi32((v & (ONE - 1)) as i32), steps));
            let pixels = _mm256_permutevar8x32_epi32(bytemuck::cast::<[u32; 8], __m256i>(texels), offsets);
            *rows = bytemuck::cast::<__m256i, [u32; 8]>(pixels);
            v += 8 * dv;
            done += 8;
        }
        (done, v)
    }
}

/// Copies a column-major strip canvas `height` rows tall into `rows`, the
/// strip's piece of each row of the destination, top to bottom (pixels, or
/// write counts), a pixel at a time. [`present_pixels`] is the fast one.
pub fn present_strip<'a, T: Copy + 'a>(canvas: &[T], height: usize, rows: impl Iterator<Item = &'a mut [T]>) {
    for (y, row) in rows.enumerate() {
        copy_row(canvas, height, y, row);
    }
}

/// Row `y` of a column-major canvas `height` rows tall into `row`.
fn copy_row<T: Copy>(canvas: &[T], height: usize, y: usize, row: &mut [T]) {
    for (i, p) in row.iter_mut().enumerate() {
        *p = canvas[i * height + y];
    }
}

/// Frames of more bytes than this are copied out with streaming stores
/// ([`present_pixels_to`]): twice the 2 MiB L2 of the machine measured, so
/// a frame that could stay in cache for whatever reads it next does. Freedoom
/// 2's DEMO2 timedemo, one thread, ms per frame (copy, whole frame), two
/// runs each, cached stores against streamed: 320x200 0.009 / 0.28 against
/// 0.012 / 0.29; 640x480 0.067-0.074 / 0.70-0.74 against 0.065-0.071 /
/// 0.66-0.73; 1280x800 0.28-0.29 / 1.75-1.78 against 0.24-0.26 /
/// 1.74-1.79; 1920x1080 0.71-0.81 / 3.27-3.48 against 0.51-0.52 / 2.96-3.00
/// (the walls and spans gain too, their canvas no longer pushed out of L2).
pub const STREAM_BYTES: usize = 4 * 1024 * 1024;

/// [`present_strip`] for pixels, four rows at a time: each 4x4 block is four
/// loads (four rows of four columns, adjacent in the canvas), a transpose in
/// SSE2 registers (every x86-64 has SSE2) and four stores, where the
/// pixel-at-a-time copy does sixteen loads and sixteen stores. The figures are
/// in ARCHITECTURE.md's performance section.
pub fn present_pixels<'a>(canvas: &[u32], height: usize, rows: impl Iterator<Item = &'a mut [u32]>) {
    present_pixels_to(canvas, height, rows, false)
}

/// [`present_pixels`], with the stores `stream`ed past the caches when
/// asked: for a frame too big to stay in cache, whose every line would
/// otherwise be read from memory before it is overwritten and then push the
/// strip's canvas out of L2 (see [`STREAM_BYTES`]).
pub fn present_pixels_to<'a>(canvas: &[u32], height: usize, rows: impl Iterator<Item = &'a mut [u32]>, stream: bool) {
    #[cfg(target_arch = "x86_64")]
    {
        let mut rows = rows;
        let mut y = 0;
        while let Some(r0) = rows.next() {
            match (rows.next(), rows.next(), rows.next()) {
                (Some(r1), Some(r2), Some(r3)) if stream => {
                    sse2::four_rows_streamed(canvas, height, y, [r0, r1, r2, r3])
                }
                (Some(r1), Some(r2), Some(r3)) => sse2::four_rows(canvas, height, y, [r0, r1, r2, r3]),
                (r1, r2, r3) => {
                    for (k, row) in [Some(r0), r1, r2, r3].into_iter().flatten().enumerate() {
                        copy_row(canvas, height, y + k, row);
                    }
                }
            }
            y += 4;
        }
        if stream {
            sse2::fence();
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        // Only x86-64's copy streams.
        let _ = stream;
        present_strip(canvas, height, rows);
    }
}

#[cfg(target_arch = "x86_64")]
mod sse2 {
    use safe_arch::{m128i, unpack_high_i32_m128i, unpack_high_i64_m128i, unpack_low_i32_m128i, unpack_low_i64_m128i};

    /// Rows `y..y + 4` of the canvas into `rows`, in 4x4 blocks. The rows
    /// are taken in pieces of four and the canvas in groups of four
    /// columns, so only the column loads are bounds tested (4.4
    /// instructions a pixel at 160x120 when every load and store was).
    #[inline]
    pub(super) fn four_rows(canvas: &[u32], height: usize, y: usize, rows: [&mut [u32]; 4]) {
        four_rows_by(canvas, height, y, rows, |q, v| *q = bytemuck::cast(v));
    }

    /// [`four_rows`] with streaming (non-temporal) stores, where every row
    /// piece starts on a 16-byte boundary as they require (else as
    /// [`four_rows`]). Safe Rust has no streaming store, hence the
    /// renderer's only `unsafe` code: this store and [`fence`].
    #[inline]
    pub(super) fn four_rows_streamed(canvas: &[u32], height: usize, y: usize, rows: [&mut [u32]; 4]) {
        use std::arch::x86_64::{__m128i, _mm_stream_si128};
        if rows.iter().any(|r| !(r.as_ptr() as usize).is_multiple_of(16)) {
            return four_rows(canvas, height, y, rows);
        }
        four_rows_by(canvas, height, y, rows, |q, v| {
            // SAFETY: `q` is a live, exclusively borrowed 16-byte piece of a
            // row that starts 16-byte aligned (tested above), a whole number
            // of pieces from the row's start, so it is aligned too.
            unsafe { _mm_stream_si128(q.as_mut_ptr().cast::<__m128i>(), bytemuck::cast(v)) };
        });
    }

    /// The blocks of [`four_rows`], each block row stored by `store`.
    #[inline(always)]
    fn four_rows_by(
        canvas: &[u32],
        height: usize,
        y: usize,
        rows: [&mut [u32]; 4],
        store: impl Fn(&mut [u32; 4], m128i),
    ) {
        let n = rows[0].len();
        let blocks = n / 4;
        let [r0, r1, r2, r3] = rows;
        let (p0, p1, p2, p3) = (
            r0.as_chunks_mut::<4>().0,
            r1.as_chunks_mut::<4>().0,
            r2.as_chunks_mut::<4>().0,
            r3.as_chunks_mut::<4>().0,
        );
        let groups = canvas[..blocks * 4 * height].chunks_exact(4 * height);
        for ((((group, q0), q1), q2), q3) in
            groups.zip(p0.iter_mut()).zip(p1.iter_mut()).zip(p2.iter_mut()).zip(p3.iter_mut())
        {
            // Column k of the group's rows y..y + 4: the block's k-th column.
            let column = |k: usize| -> m128i {
                let texels: [u32; 4] = group[k * height + y..][..4].try_into().unwrap_or_default();
                bytemuck::cast(texels)
            };
            let block = transpose([column(0), column(1), column(2), column(3)]);
            for (q, v) in [q0, q1, q2, q3].into_iter().zip(block) {
                store(q, v);
            }
        }
        for i in blocks * 4..n {
            for (k, row) in [&mut *r0, &mut *r1, &mut *r2, &mut *r3].into_iter().enumerate() {
                row[i] = canvas[i * height + y + k];
            }
        }
    }

    /// Orders the streamed stores before whatever the caller does next
    /// (another thread may read the frame once the strip is done).
    pub(super) fn fence() {
        // SAFETY: SSE is part of every x86-64; the fence has no operands.
        unsafe { std::arch::x86_64::_mm_sfence() };
    }

    /// [`super::ColumnWriter::put_four_rows`]'s columns four at a time:
    /// four rows' four pixels transposed in registers into four columns'
    /// four rows (the column-at-a-time form gathered each column's four
    /// pixels from the rows one by one: seven instructions a pixel on
    /// basic's floors). Returns the columns done (a multiple of four).
    #[inline]
    pub(super) fn four_columns(canvas: &mut [u32], height: usize, start: usize, rows: [&[u32]; 4]) -> usize {
        let n = rows[0].len();
        let blocks = n / 4;
        let [r0, r1, r2, r3] = rows.map(|r| r[..blocks * 4].as_chunks::<4>().0);
        for (b, (((p0, p1), p2), p3)) in r0.iter().zip(r1).zip(r2).zip(r3).enumerate() {
            let columns = transpose([p0, p1, p2, p3].map(|p| bytemuck::cast::<[u32; 4], m128i>(*p)));
            let base = start + 4 * b * height;
            for (k, column) in columns.into_iter().enumerate() {
                canvas[base + k * height..][..4].copy_from_slice(&bytemuck::cast::<m128i, [u32; 4]>(column));
            }
        }
        blocks * 4
    }

    /// Four columns of four pixels become four rows of four.
    #[inline]
    fn transpose([a, b, c, d]: [m128i; 4]) -> [m128i; 4] {
        let (ab_low, cd_low) = (unpack_low_i32_m128i(a, b), unpack_low_i32_m128i(c, d));
        let (ab_high, cd_high) = (unpack_high_i32_m128i(a, b), unpack_high_i32_m128i(c, d));
        [
            unpack_low_i64_m128i(ab_low, cd_low),
            unpack_high_i64_m128i(ab_low, cd_low),
            unpack_low_i64_m128i(ab_high, cd_high),
            unpack_high_i64_m128i(ab_high, cd_high),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stretch's texels, the AVX2 eights included, are the texels of the
    /// plain formula, for steps either side of one texel a row, every start
    /// fraction, columns shorter and longer than eight, and stretches that
    /// run to the column's last texel.
    #[test]
    fn stretch_texels_match_the_formula() {
        const ONE: i64 = 1 << 16;
        for h in [1usize, 3, 8, 9, 17, 64, 128] {
            let column: Vec<u32> = (0..h as u32).map(|i| i.wrapping_mul(0x9E37_79B9) | 1).collect();
            let wrap = (h as i64) << 16;
            for dv in [0, 1, 4_681, ONE / 3, ONE / 2 + 7, ONE - 1, ONE, ONE + 1, 3 * ONE / 2, 5 * ONE] {
                for v in (0..wrap).step_by(4_099).chain([wrap - 1]) {
                    // Every row of the stretch stays in the column.
                    let rows = if dv == 0 { 40 } else { ((wrap - v + dv - 1) / dv).min(40) as usize };
                    let mut got = vec![0u32; rows];
                    let end = stretch_texels(&mut got, &column, v, dv);
                    let want: Vec<u32> = (0..rows as i64).map(|k| column[((v + k * dv) >> 16) as usize]).collect();
                    assert_eq!(got, want, "h {h} dv {dv} v {v}");
                    assert_eq!(end, v + rows as i64 * dv);
                }
            }
        }
    }

    /// Four rows put together land, and are counted, as four single rows.
    #[test]
    fn four_rows_are_four_single_rows() {
        // Spans shorter than, as long as and past the four-column blocks.
        let (width, height, x0) = (13usize, 9usize, 3usize);
        for n in 1..=11u32 {
            let rows: Vec<Vec<u32>> = (0..4u32).map(|k| (0..n).map(|j| k * 100 + j + 1).collect()).collect();
            let (mut one, mut four) = (vec![0u32; width * height], vec![0u32; width * height]);
            let (mut one_counts, mut four_counts) = (vec![0u16; width * height], vec![0u16; width * height]);
            let mut w = ColumnWriter::new(&mut one, x0, height, Some(&mut one_counts));
            for (k, row) in rows.iter().enumerate() {
                w.put_row(5 + k as i32, x0 + 2, row);
            }
            let written = w.written;
            let mut w = ColumnWriter::new(&mut four, x0, height, Some(&mut four_counts));
            w.put_four_rows(5, x0 + 2, [&rows[0], &rows[1], &rows[2], &rows[3]]);
            assert_eq!(w.written, written, "{n} columns");
            assert_eq!((four, four_counts), (one, one_counts), "{n} columns");
        }
    }

    /// The blocked copy equals the pixel-at-a-time one at every size, the
    /// blocks' leftover rows and columns included.
    #[test]
    fn present_pixels_matches_present_strip() {
        for width in 1..=11 {
            for height in 1..=11 {
                let canvas: Vec<u32> = (0..(width * height) as u32).map(|i| i.wrapping_mul(0x9E37_79B9)).collect();
                let (mut fast, mut slow) = (vec![0u32; width * height], vec![0u32; width * height]);
                present_pixels(&canvas, height, fast.chunks_exact_mut(width));
                present_strip(&canvas, height, slow.chunks_exact_mut(width));
                assert_eq!(fast, slow, "{width}x{height}");
                // Streamed, into rows that start aligned (a 4-wide frame) or
                // not (the others, and the frame moved by a pixel).
                for shift in [0, 1] {
                    let mut streamed = vec![0u32; width * height + shift];
                    present_pixels_to(&canvas, height, streamed[shift..].chunks_exact_mut(width), true);
                    assert_eq!(streamed[shift..], slow, "{width}x{height} streamed, shifted {shift}");
                }
                assert_eq!(fast[width * (height - 1)], canvas[height - 1]);
            }
        }
    }
}
