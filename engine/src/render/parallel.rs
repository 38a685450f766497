//! Sort-first parallel rendering: the frame's strips handed out to worker
//! threads, each drawing whole strips with its own [`StripFrame`] and
//! copying them into its own disjoint columns of the framebuffer.
//!
//! Why this split works: a strip's walk reads only shared, read-only state
//! (the level, the camera, the frame's tables) and writes only its worker's
//! state and its own columns, so the output does not depend on which worker
//! draws which strip, or in what order: frames are bit-identical for any
//! thread count (tested on every shipped map).
//!
//! Threads. [`Pool`] is a rayon `ThreadPool` of `threads - 1` threads owned
//! by the [`super::Frame`], so it lives as long as the caller keeps its
//! frame and nothing is global; the calling thread is the last worker rather
//! than sleeping while the pool works. Strips go to whichever worker asks
//! next (a queue under a mutex, locked once per strip), which evens out
//! strips of unequal cost.
//!
//! Columns of a row-major framebuffer are not contiguous, so each strip's
//! destination is split out in safe code as one slice per row
//! ([`split_rows`]): `height * strips` slices per frame, allocated afresh
//! because they borrow this frame's framebuffer.

use std::sync::Mutex;

use super::frame::StripFrame;

/// The worker threads besides the caller's, built on first use and rebuilt
/// only when the thread count changes.
#[derive(Default)]
pub(crate) struct Pool {
    pool: Option<(usize, rayon::ThreadPool)>,
}

impl std::fmt::Debug for Pool {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Pool").field("threads", &self.pool.as_ref().map(|p| p.0)).finish()
    }
}

impl Pool {
    /// A pool of `threads` threads; `None` if they could not be started, and
    /// the frame is then drawn on the calling thread alone (same output).
    pub(crate) fn get(&mut self, threads: usize) -> Option<&rayon::ThreadPool> {
        if !matches!(self.pool, Some((n, _)) if n == threads) {
            self.pool = None;
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .thread_name(|i| format!("sightline-render-{i}"))
                .build()
                .ok()?;
            self.pool = Some((threads, pool));
        }
        self.pool.as_ref().map(|p| &p.1)
    }
}

/// One strip to draw: its columns and where its pixels (and write counts,
/// depth and labels, when asked for) go, one slice per row.
pub(crate) struct Job<'a> {
    pub x0: usize,
    pub x1: usize,
    pub rows: Vec<&'a mut [u32]>,
    pub counts: Vec<&'a mut [u16]>,
    /// Its depth and label rows, when the frame fills those buffers.
    pub depth: Vec<&'a mut [f32]>,
    pub labels: Vec<&'a mut [u32]>,
}

/// Each strip's piece of every row of a row-major `buf` that is `width` wide
/// (strips cover `0..width` in order); nothing for an empty `buf`.
pub(crate) fn split_rows<'a, T>(buf: &'a mut [T], width: usize, strips: &[(usize, usize)]) -> Vec<Vec<&'a mut [T]>> {
    let height = buf.len().checked_div(width).unwrap_or(0);
    let mut pieces: Vec<Vec<&mut [T]>> = strips.iter().map(|_| Vec::with_capacity(height)).collect();
    for row in buf.chunks_exact_mut(width.max(1)) {
        let mut rest = row;
        for (piece, &(x0, x1)) in pieces.iter_mut().zip(strips) {
            let (this, tail) = rest.split_at_mut(x1 - x0);
            piece.push(this);
            rest = tail;
        }
    }
    pieces
}

/// Draws `jobs` with `workers` (one per thread: the pool's and the
/// caller's), each strip by `draw`.
pub(crate) fn run<'a>(
    pool: &rayon::ThreadPool,
    workers: &mut [StripFrame],
    jobs: Vec<Job<'a>>,
    draw: &(dyn Fn(&mut StripFrame, Job<'a>) + Sync),
) {
    let queue = Mutex::new(jobs.into_iter());
    // A poisoned lock means another worker panicked; the scope re-raises it.
    let work = |worker: &mut StripFrame| {
        while let Some(job) = queue.lock().ok().and_then(|mut q| q.next()) {
            draw(worker, job);
        }
    };
    let Some((mine, theirs)) = workers.split_first_mut() else { return };
    pool.in_place_scope(|scope| {
        for worker in theirs {
            scope.spawn(|_| work(worker));
        }
        work(mine);
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_split_into_strip_pieces() {
        let mut buf: Vec<u32> = (0..20).collect();
        let pieces = split_rows(&mut buf, 5, &[(0, 2), (2, 5)]);
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0].iter().map(|r| r.to_vec()).collect::<Vec<_>>(), [[0, 1], [5, 6], [10, 11], [15, 16]]);
        assert_eq!(pieces[1][3], [17, 18, 19]);
        assert!(split_rows::<u16>(&mut [], 5, &[(0, 5)])[0].is_empty());
    }
}
