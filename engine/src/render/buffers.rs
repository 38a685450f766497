//! Per-pixel depth and labels, written by the walk beside the colour: the
//! same columns, segs, planes and sprites that paint a pixel say how far
//! away its surface is and which thing, if any, it shows.
//!
//! - **Depth** is camera-space depth (map units along the view direction,
//!   not the distance to the eye) of the surface the pixel shows: a wall's
//!   depth at its column, a floor's or ceiling's where the row's ray meets
//!   the plane, a sprite's or see-through middle's where it stands. Sky and
//!   void are `f32::INFINITY`.
//! - **Labels** are `key + 1` of the thing whose sprite shows at the pixel
//!   (an opaque texel, not hidden by a wall or a nearer sprite or middle),
//!   0 elsewhere; the simulation sets a thing's key to its body's id.
//!
//! Like the colour, both go into column-major strip canvases and are copied
//! into the row-major buffers of the [`super::Frame`] with the strip, so
//! they do not depend on how the screen is cut. With both off the writer is
//! empty and every call is one untaken branch per run of rows.

use super::columns::present_pixels;

/// Which per-pixel buffers a frame fills besides the colour
/// ([`super::RenderOptions::buffers`]; read them with
/// [`super::Frame::depth`] and [`super::Frame::labels`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Buffers {
    pub depth: bool,
    pub labels: bool,
}

impl Buffers {
    /// Every combination, by name: `off`, `depth`, `labels`, `both`.
    pub const ALL: [Buffers; 4] = [
        Buffers { depth: false, labels: false },
        Buffers { depth: true, labels: false },
        Buffers { depth: false, labels: true },
        Buffers { depth: true, labels: true },
    ];

    pub fn any(self) -> bool {
        self.depth || self.labels
    }

    pub fn name(self) -> &'static str {
        match (self.depth, self.labels) {
            (false, false) => "off",
            (true, false) => "depth",
            (false, true) => "labels",
            (true, true) => "both",
        }
    }

    pub fn from_name(name: &str) -> Option<Buffers> {
        Self::ALL.into_iter().find(|b| b.name() == name)
    }
}

/// The depth of a pixel that shows no surface (sky, void).
pub const FAR: f32 = f32::INFINITY;

/// Where the row with inverse slope `inv_row` meets a plane `rise` above
/// the eye (negative: below it), for a plane pixel the walk found at a line
/// `limit` deep. The ray reaches the plane before that line whenever the eye
/// is between the sector's floor and ceiling; from outside them (an eye above
/// a low ceiling) it never does in front of the eye, and the pixel gets the
/// line's depth. The BSP walk and the reference both call this with the
/// same numbers (`inv_row` is `1 / row_slope(y)` in both), so they agree
/// to the bit.
#[inline]
pub fn plane_depth(rise: f64, inv_row: f64, limit: f64) -> f32 {
    let d = rise * inv_row;
    (if d > 0.0 && d <= limit { d } else { limit }) as f32
}

/// The strip's depth and label canvases, laid out like the colour canvas
/// (pixel (x, y) at `(x - x0) * height + y`), when the frame asks for them.
#[derive(Default)]
pub struct BufferWriter<'a> {
    depth: Option<&'a mut [f32]>,
    labels: Option<&'a mut [u32]>,
    x0: usize,
    height: usize,
}

impl<'a> BufferWriter<'a> {
    pub(crate) fn new(depth: Option<&'a mut [f32]>, labels: Option<&'a mut [u32]>, x0: usize, height: usize) -> Self {
        BufferWriter { depth, labels, x0, height }
    }

    /// Whether any buffer is written (callers skip per-row set-up otherwise).
    #[inline]
    pub fn on(&self) -> bool {
        self.depth.is_some() || self.labels.is_some()
    }

    #[inline]
    fn range(&self, x: usize, y0: i32, y1: i32) -> std::ops::Range<usize> {
        let base = (x - self.x0) * self.height;
        base + y0 as usize..base + y1 as usize
    }

    /// Rows `[y0, y1)` of column `x` show a surface at `depth` (a wall, or
    /// anything at one depth), not a thing.
    #[inline]
    pub fn flat(&mut self, x: usize, (y0, y1): (i32, i32), depth: f64) {
        self.fill(x, (y0, y1), depth as f32);
    }

    /// Rows `[y0, y1)` of column `x` show the sky or the void.
    #[inline]
    pub fn far(&mut self, x: usize, rows: (i32, i32)) {
        self.fill(x, rows, FAR);
    }

    #[inline]
    fn fill(&mut self, x: usize, (y0, y1): (i32, i32), depth: f32) {
        if y1 <= y0 {
            return;
        }
        let range = self.range(x, y0, y1);
        if let Some(d) = self.depth.as_deref_mut() {
            d[range].fill(depth);
        }
    }

    /// Rows `[y0, y1)` of column `x` show a floor or ceiling `rise` above
    /// the eye, or the sky (`rise` is `None`), found at a line `limit` deep
    /// ([`plane_depth`]); `inv_rows[y]` is `1 / row_slope(y)`.
    #[inline]
    pub fn plane(&mut self, x: usize, (y0, y1): (i32, i32), rise: Option<f64>, inv_rows: &[f64], limit: f64) {
        if y1 <= y0 {
            return;
        }
        let range = self.range(x, y0, y1);
        if let Some(d) = self.depth.as_deref_mut() {
            match rise {
                Some(rise) => {
                    for (p, &inv) in d[range].iter_mut().zip(&inv_rows[y0 as usize..y1 as usize]) {
                        *p = plane_depth(rise, inv, limit);
                    }
                }
                None => d[range].fill(FAR),
            }
        }
    }

    /// The masked pass drew `texels` down column `x` from row `y0` where
    /// they are opaque: those pixels now show a sprite or middle at `depth`,
    /// labelled `label` (0 for a middle).
    #[inline]
    pub fn opaque(&mut self, x: usize, y0: i32, texels: &[u32], depth: f64, label: u32) {
        let range = self.range(x, y0, y0 + texels.len() as i32);
        if let Some(d) = self.depth.as_deref_mut() {
            for (p, &t) in d[range.clone()].iter_mut().zip(texels) {
                *p = if t >> 24 != 0 { depth as f32 } else { *p };
            }
        }
        if let Some(l) = self.labels.as_deref_mut() {
            for (p, &t) in l[range].iter_mut().zip(texels) {
                *p = if t >> 24 != 0 { label } else { *p };
            }
        }
    }

    /// Pixel `(x, y)` shows a surface at `depth` with `label` (the masked
    /// pass's single pixels, and the reference's every pixel).
    #[inline]
    pub fn pixel(&mut self, x: usize, y: i32, depth: f32, label: u32) {
        let i = (x - self.x0) * self.height + y as usize;
        if let Some(d) = self.depth.as_deref_mut() {
            d[i] = depth;
        }
        if let Some(l) = self.labels.as_deref_mut() {
            l[i] = label;
        }
    }
}

/// The strip's canvases, kept in its worker's `StripFrame`.
#[derive(Debug, Default)]
pub(crate) struct Canvases {
    pub depth: Vec<f32>,
    pub labels: Vec<u32>,
}

impl Canvases {
    /// Readies the canvases for a strip of `pixels` pixels: labels start at
    /// 0 (sprites write only where they show); depth is written by the
    /// opaque pass everywhere, so it is not cleared.
    pub(crate) fn begin_strip(&mut self, buffers: Buffers, pixels: usize) {
        self.depth.resize(if buffers.depth { pixels } else { 0 }, FAR);
        self.labels.clear();
        if buffers.labels {
            self.labels.resize(pixels, 0);
        }
    }

    /// A writer over the canvases for columns from `x0` of a `height`-row frame.
    pub(crate) fn writer(&mut self, x0: usize, height: usize) -> BufferWriter<'_> {
        let depth = (!self.depth.is_empty()).then_some(self.depth.as_mut_slice());
        let labels = (!self.labels.is_empty()).then_some(self.labels.as_mut_slice());
        BufferWriter::new(depth, labels, x0, height)
    }

    /// Copies the strip into its piece of each row of the frame's buffers
    /// (empty iterators for a buffer not asked for).
    pub(crate) fn present<'a>(
        &self,
        height: usize,
        depth_rows: impl Iterator<Item = &'a mut [f32]>,
        label_rows: impl Iterator<Item = &'a mut [u32]>,
    ) {
        if !self.depth.is_empty() {
            // The blocked copy moves 32-bit words; depths are copied as their bits.
            let rows = depth_rows.map(bytemuck::cast_slice_mut::<f32, u32>);
            present_pixels(bytemuck::cast_slice(&self.depth), height, rows);
        }
        if !self.labels.is_empty() {
            present_pixels(&self.labels, height, label_rows);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plane pixel gets the plane's depth where the ray meets the plane
    /// before the line, the line's otherwise (behind the eye, on the
    /// horizon, or beyond the line).
    #[test]
    fn plane_depth_is_the_plane_or_the_line() {
        assert_eq!(plane_depth(87.0, 2.0, 500.0), 174.0);
        assert_eq!(plane_depth(-41.0, -4.0, 500.0), 164.0);
        assert_eq!(plane_depth(87.0, -2.0, 500.0), 500.0);
        assert_eq!(plane_depth(87.0, f64::INFINITY, 500.0), 500.0);
        assert_eq!(plane_depth(0.0, 3.0, 500.0), 500.0);
        assert_eq!(plane_depth(87.0, 10.0, 500.0), 500.0);
    }

    /// Opaque texels write depth and label; transparent ones keep what is there.
    #[test]
    fn opaque_writes_only_opaque_texels() {
        let (mut depth, mut labels) = (vec![FAR; 8], vec![0u32; 8]);
        let mut w = BufferWriter::new(Some(&mut depth), Some(&mut labels), 3, 4);
        w.opaque(4, 1, &[0xff00_0000, 0x0012_3456, 0x0100_0000], 12.5, 7);
        assert_eq!(depth, [FAR, FAR, FAR, FAR, FAR, 12.5, FAR, 12.5]);
        assert_eq!(labels, [0, 0, 0, 0, 0, 7, 0, 7]);
    }
}
