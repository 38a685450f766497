//! The occlusion invariant: in the opaque pass every screen pixel is written
//! exactly once, so overdraw is exactly 1.0, on every shipped map and pose.

use sightline::render::{render_frame, Frame, RenderOptions, Renderer, Shade};
use sightline::tour::tour;
use sightline::Framebuffer;
use sightline_tests::{load, shipped_maps};

#[test]
fn every_pixel_written_exactly_once() {
    for path in shipped_maps() {
        let level = load(&path);
        let views = tour(&level, 24, 3);
        assert!(views.len() >= 30, "{}: tour too short", path.display());
        let mut frame = Frame::new();
        for (w, h) in [(320, 200), (97, 61)] {
            let mut fb = Framebuffer::new(w, h);
            // Painter's and the z-buffer overwrite by design (tests/visibility.rs).
            for renderer in Renderer::ALL.into_iter().filter(|r| r.writes_each_pixel_once()) {
                for view in &views {
                    let options =
                        RenderOptions { renderer, shade: Shade::Ids, count_writes: true, ..Default::default() };
                    let stats = render_frame(&level, view, &options, &mut frame, &mut fb);
                    let counts = frame.write_counts();
                    assert_eq!(counts.len(), w * h);
                    let bad = counts.iter().filter(|&&c| c != 1).count();
                    assert_eq!(
                        bad,
                        0,
                        "{} {}: {bad} pixels not written exactly once from {view:?}",
                        path.display(),
                        renderer.name()
                    );
                    assert_eq!(stats.overdraw(w, h), 1.0);
                }
            }
        }
    }
}

#[test]
fn occlusion_culls_and_stops_early_on_the_maze() {
    // The point of the W-bit array: most of the maze is never visited.
    let level = load(&sightline_tests::map_path("maze.ron"));
    let mut frame = Frame::new();
    let mut fb = Framebuffer::new(320, 200);
    let mut culled = 0;
    for view in tour(&level, 8, 4) {
        let stats = render_frame(&level, &view, &RenderOptions::default(), &mut frame, &mut fb);
        assert!(stats.walls_considered * 4 < level.bsp.segs.len() as u64, "{stats:?}");
        culled += stats.subtrees_culled;
    }
    assert!(culled > 0, "no subtree was ever culled by its bounding box");
}
