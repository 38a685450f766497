//! Profiling a frame (`RenderOptions::profile`, what `sightline bench tour`
//! reports as the breakdown) changes no pixel and no count, and times each
//! part the frame has; without it the breakdown stays zero.

use sightline::render::{render_frame, Breakdown, Frame, RenderOptions, Shade};
use sightline::tour::tour;
use sightline::Framebuffer;
use sightline_tests::{load, root};

#[test]
fn profiling_times_the_parts_and_changes_nothing() {
    let level = load(&root().join("maps/outpost.ron"));
    let views = tour(&level, 6, 3);
    let (w, h) = (640, 400);
    for threads in [1, 2] {
        let plain = RenderOptions { shade: Shade::Textured, threads, ..Default::default() };
        let profiled = RenderOptions { profile: true, ..plain };
        let (mut a, mut b) = (Frame::new(), Frame::new());
        let mut total = Breakdown::default();
        for view in &views {
            let (mut fa, mut fb) = (Framebuffer::new(w, h), Framebuffer::new(w, h));
            let sa = render_frame(&level, view, &plain, &mut a, &mut fa);
            let sb = render_frame(&level, view, &profiled, &mut b, &mut fb);
            assert!(fa.pixels == fb.pixels, "{threads} threads, {view:?}: profiling changed pixels");
            assert_eq!(sa, sb, "{threads} threads, {view:?}: profiling changed the counts");
            assert_eq!(a.breakdown, Breakdown::default(), "a frame not profiled has no breakdown");
            assert!(b.breakdown.total() > 0, "{threads} threads, {view:?}: a profiled frame took no time");
            total += b.breakdown;
        }
        // Over the tour every part of a textured frame with floors, walls and
        // things shows up.
        for (name, ns) in total.parts() {
            assert!(ns > 0, "{threads} threads: no time in {name} over the tour: {total:?}");
        }
    }
}
