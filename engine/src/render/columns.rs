//! The pixel writer: the one piece every renderer shares. It fills vertical
//! runs of one colour and counts what it writes (the overdraw figures).

use crate::framebuffer::Framebuffer;

pub struct ColumnWriter<'a> {
    fb: &'a mut Framebuffer,
    /// Per-pixel write counts, when the caller asked for them.
    counts: Option<&'a mut Vec<u16>>,
    pub written: u64,
}

impl<'a> ColumnWriter<'a> {
    pub fn new(fb: &'a mut Framebuffer, counts: Option<&'a mut Vec<u16>>) -> Self {
        ColumnWriter {
            fb,
            counts,
            written: 0,
        }
    }

    /// Fills rows `[y0, y1)` of column `x`. Empty and inverted runs write nothing;
    /// callers keep rows within `0..=height` and `x < width`.
    #[inline]
    pub fn fill(&mut self, x: usize, y0: i32, y1: i32, colour: u32) {
        if y1 <= y0 {
            return;
        }
        let (y0, y1) = (y0 as usize, y1 as usize);
        let w = self.fb.width;
        self.written += (y1 - y0) as u64;
        for p in self.fb.pixels[y0 * w + x..]
            .iter_mut()
            .step_by(w)
            .take(y1 - y0)
        {
            *p = colour;
        }
        if let Some(counts) = self.counts.as_deref_mut() {
            for c in counts[y0 * w + x..].iter_mut().step_by(w).take(y1 - y0) {
                *c = c.saturating_add(1);
            }
        }
    }
}
