//! Splitting the screen into vertical strips, each walked front to back on its
//! own (sort-first, in the parallel-rendering literature's terms).
//!
//! Why: renderers here draw columns, and a frame must end up row-major. Each
//! strip is drawn into a small column-major canvas that stays in L2, then
//! copied out a cache line at a time (see [`super::columns`]). Marking the
//! columns outside the strip as already occluded is all the BSP walk needs:
//! its bounding-box culling and early stop do the rest, so each strip visits
//! only what it shows. The same strips are the unit of parallel rendering.

/// Bytes of canvas a strip may span. Measured on the maze at 1920x1080 (ms per
/// frame): 128 KiB 2.3-3.2, 256 KiB 2.0-2.2, 512 KiB 2.3, 1 MiB 2.4-3.6.
const STRIP_BYTES: usize = 256 * 1024;

/// Strip widths are multiples of this many columns (one 64-byte cache line of
/// pixels), so neighbouring strips never share a line.
const ALIGN: usize = 16;

/// The strips `[x0, x1)` covering `width` columns of a frame `height` rows tall.
pub fn strips(width: usize, height: usize) -> impl Iterator<Item = (usize, usize)> {
    let fit = STRIP_BYTES / (height.max(1) * 4);
    let step = (fit / ALIGN * ALIGN).max(ALIGN);
    (0..width).step_by(step).map(move |x0| (x0, (x0 + step).min(width)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strips_cover_the_screen_once() {
        for (w, h) in [(320, 200), (1920, 1080), (7, 3), (16384, 1)] {
            let s: Vec<_> = strips(w, h).collect();
            assert_eq!(s.first().map(|s| s.0), Some(0));
            assert_eq!(s.last().map(|s| s.1), Some(w));
            assert!(s.windows(2).all(|p| p[0].1 == p[1].0));
        }
        assert_eq!(strips(320, 200).count(), 1, "small frames are one strip");
    }
}
