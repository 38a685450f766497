//! The W-bit column occlusion array: one bit per screen column, set once the
//! column's open interval has closed. Packed in u64 words so that runs of
//! closed columns are skipped 64 at a time.

#[derive(Clone, Debug, Default)]
pub struct Occlusion {
    words: Vec<u64>,
    width: usize,
    open: usize,
}

impl Occlusion {
    /// Opens all `width` columns, reusing the allocation.
    pub fn reset(&mut self, width: usize) {
        let n = width.div_ceil(64);
        self.words.clear();
        self.words.resize(n, 0);
        // Bits past the last column stay set, so scans never report them open.
        if !width.is_multiple_of(64) {
            self.words[n - 1] = !0u64 << (width % 64);
        }
        self.width = width;
        self.open = width;
    }

    /// Opens only columns `[x0, x1)` of `width`: the rest count as closed, so
    /// a walk confined to a strip culls everything outside it for free.
    pub fn reset_to_strip(&mut self, width: usize, x0: usize, x1: usize) {
        self.reset(width);
        let (x0, x1) = (x0.min(width), x1.min(width).max(x0.min(width)));
        for (w, word) in self.words.iter_mut().enumerate() {
            let (lo, hi) = (w * 64, w * 64 + 64);
            // Bits of this word inside the strip stay open; all others close.
            let open_lo = x0.clamp(lo, hi) - lo;
            let open_hi = x1.clamp(lo, hi) - lo;
            let open_bits = ones(open_hi) & !ones(open_lo);
            *word |= !open_bits;
        }
        self.open = x1 - x0;
    }

    pub fn width(&self) -> usize {
        self.width
    }

    pub fn open_count(&self) -> usize {
        self.open
    }

    pub fn all_closed(&self) -> bool {
        self.open == 0
    }

    #[inline]
    pub fn close(&mut self, x: usize) {
        let (w, bit) = (x / 64, 1u64 << (x % 64));
        if self.words[w] & bit == 0 {
            self.words[w] |= bit;
            self.open -= 1;
        }
    }

    /// First open column in `[x, end)`.
    pub fn next_open(&self, x: usize, end: usize) -> Option<usize> {
        self.scan(x, end, true)
    }

    /// First closed column in `[x, end)`, or `end` (at most the width).
    pub fn next_closed(&self, x: usize, end: usize) -> usize {
        let end = end.min(self.width);
        self.scan(x, end, false).unwrap_or(end)
    }

    /// Is any column in `[x0, x1)` still open?
    pub fn any_open(&self, x0: usize, x1: usize) -> bool {
        self.next_open(x0, x1).is_some()
    }

    /// First column in `[x, end)` whose bit is clear (`want_open`) or set.
    fn scan(&self, mut x: usize, end: usize, want_open: bool) -> Option<usize> {
        let end = end.min(self.width);
        while x < end {
            let word = self.words[x / 64];
            // Bits that match what we look for, from column x on.
            let hits = (if want_open { !word } else { word }) >> (x % 64);
            if hits != 0 {
                let found = x + hits.trailing_zeros() as usize;
                return (found < end).then_some(found);
            }
            x = (x / 64 + 1) * 64;
        }
        None
    }

    /// Runs `[start, end)` of open columns within `[x0, x1)`.
    pub fn open_runs(&self, x0: usize, x1: usize) -> OpenRuns<'_> {
        OpenRuns { mask: self, x: x0, end: x1 }
    }
}

/// The low `n` bits set (`n <= 64`).
fn ones(n: usize) -> u64 {
    if n >= 64 {
        !0
    } else {
        (1u64 << n) - 1
    }
}

pub struct OpenRuns<'a> {
    mask: &'a Occlusion,
    x: usize,
    end: usize,
}

impl Iterator for OpenRuns<'_> {
    type Item = (usize, usize);

    fn next(&mut self) -> Option<(usize, usize)> {
        let start = self.mask.next_open(self.x, self.end)?;
        let stop = self.mask.next_closed(start, self.end);
        self.x = stop;
        Some((start, stop))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_skip_closed_words() {
        let mut m = Occlusion::default();
        m.reset(200);
        for x in (0..130).chain(140..150) {
            m.close(x);
        }
        assert_eq!(m.open_runs(0, 200).collect::<Vec<_>>(), vec![(130, 140), (150, 200)]);
        assert_eq!(m.open_runs(135, 145).collect::<Vec<_>>(), vec![(135, 140)]);
        assert_eq!(m.open_count(), 60);
        assert!(!m.any_open(0, 130));
        for x in 0..200 {
            m.close(x);
        }
        assert!(m.all_closed());
        assert_eq!(m.next_open(0, 200), None);
    }

    #[test]
    fn strips_open_only_their_columns() {
        let mut m = Occlusion::default();
        for (x0, x1) in [(0, 64), (64, 128), (10, 130), (190, 200), (0, 200)] {
            m.reset_to_strip(200, x0, x1);
            assert_eq!(m.open_runs(0, 200).collect::<Vec<_>>(), vec![(x0, x1)]);
            assert_eq!(m.open_count(), x1 - x0);
        }
    }

    #[test]
    fn tail_bits_never_open() {
        let mut m = Occlusion::default();
        m.reset(70);
        assert_eq!(m.next_closed(0, 70), 70);
        assert_eq!(m.open_runs(60, 1000).collect::<Vec<_>>(), vec![(60, 70)]);
    }
}
