//! Splitting the screen into vertical strips, each walked front to back on its
//! own (sort-first, in the parallel-rendering literature's terms).
//!
//! Why: renderers here draw columns, and a frame must end up row-major. Each
//! strip is drawn into a small column-major canvas that stays in L2, then
//! copied out a cache line at a time (see [`super::columns`]). Marking the
//! columns outside the strip as already occluded is all the BSP walk needs:
//! its bounding-box culling and early stop do the rest, so each strip visits
//! only what it shows. The same strips are the unit of parallel rendering.

/// Bytes of canvas a strip may span: half the 2 MiB L2 of the machine it was
/// measured on. Freedoom's E1M4 tour (ms per frame, medians, one run each;
/// 256 KiB / 512 KiB / 1 MiB / 2 MiB / 4 MiB): 1920x1080 one thread
/// 3.57 / 3.47 / 3.46 / 3.45 / 3.73, two threads 2.43 / 2.17 / 2.03 / 2.05 /
/// 2.22, 3840x2160 one thread 19.5 / 15.5 / 15.3 / 14.7 / 14.4. Narrow strips
/// cost twice: each span is at most a strip wide, so its set-up is paid per
/// few pixels, and at 4K 256 KiB is a 16-column strip whose every row piece
/// is a single cache line. (An older, smaller-L2 machine measured the maze
/// at 1080p best at 256 KiB: 2.0-2.2 against 2.4-3.6 ms for 1 MiB.)
const STRIP_BYTES: usize = 1024 * 1024;

/// Strip widths are multiples of this many columns (one 64-byte cache line of
/// pixels), so neighbouring strips never share a line.
const ALIGN: usize = 16;

/// The strips `[x0, x1)` covering `width` columns of a frame `height` rows
/// tall, and at least `workers` of them when the width allows, so that each
/// worker thread has one even where a single strip would fit in cache
/// (320x200). Every strip but the last is a multiple of 16 columns wide; the
/// last takes the rest (a sliver of a strip would cost a walk of its own).
pub fn strips(width: usize, height: usize, workers: usize) -> impl Iterator<Item = (usize, usize)> {
    let fit = STRIP_BYTES / (height.max(1) * 4);
    let share = width / workers.max(1);
    let step = (fit.min(share) / ALIGN * ALIGN).max(ALIGN);
    let count = if width == 0 { 0 } else { (width / step).max(1) };
    (0..count).map(move |i| (i * step, if i + 1 == count { width } else { (i + 1) * step }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strips_cover_the_screen_once() {
        for (w, h) in [(320, 200), (321, 200), (1920, 1080), (7, 3), (16384, 1)] {
            for workers in 1..=5 {
                let s: Vec<_> = strips(w, h, workers).collect();
                assert_eq!(s.first().map(|s| s.0), Some(0));
                assert_eq!(s.last().map(|s| s.1), Some(w));
                assert!(s.windows(2).all(|p| p[0].1 == p[1].0 && p[0].1 % ALIGN == 0));
                assert!(s.len() >= workers.min(w.div_ceil(ALIGN)), "{w}x{h}, {workers} workers: {s:?}");
            }
        }
        assert_eq!(strips(320, 200, 1).count(), 1, "small frames are one strip");
        assert_eq!(strips(320, 200, 2).collect::<Vec<_>>(), [(0, 160), (160, 320)]);
        assert_eq!(strips(321, 200, 2).collect::<Vec<_>>(), [(0, 160), (160, 321)]);
        assert_eq!(strips(321, 200, 1).collect::<Vec<_>>(), [(0, 321)]);
        assert_eq!(strips(0, 200, 2).count(), 0);
        assert_eq!(strips(1920, 1080, 1).count(), strips(1920, 1080, 4).count(), "big frames have strips to spare");
    }
}
