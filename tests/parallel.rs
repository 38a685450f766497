//! Parallel rendering changes nothing: frames drawn with 1, 2, 3 and 4
//! threads are bit-identical, with the same write counts, lines seen and
//! pixel totals, on every shipped map at several sizes (odd widths, a frame
//! narrower than one strip, 1080p), textured with sprites, for the BSP
//! renderer, the ray-caster on grid maps and the reference.
//!
//! What may differ: the walk's own counters (nodes, leaves, walls looked at
//! and drawn) are sums over strips, and more threads split a small frame
//! into more strips, each walking the tree for its columns. Where the strips
//! are the same for every thread count (1080p), those are equal too.

use sightline::level::Level;
use sightline::render::strips::strips;
use sightline::render::{render_frame, Frame, FrameStats, RenderOptions, Renderer, Shade, View};
use sightline::tour::tour;
use sightline::Framebuffer;
use sightline_tests::{load, shipped_maps};

const THREADS: [usize; 3] = [2, 3, 4];

/// One frame drawn with one thread: the pixels and everything counted.
struct Drawn {
    fb: Framebuffer,
    stats: FrameStats,
    counts: Vec<u16>,
    seen: Vec<bool>,
}

fn draw(level: &Level, view: &View, size: (usize, usize), options: RenderOptions, frame: &mut Frame) -> Drawn {
    let mut fb = Framebuffer::new(size.0, size.1);
    let stats = render_frame(level, view, &options, frame, &mut fb);
    Drawn { fb, stats, counts: frame.write_counts().to_vec(), seen: frame.seen_lines().to_vec() }
}

/// Renders `views` at `size` with one thread and with each of [`THREADS`],
/// keeping one `Frame` per thread count across poses (and calls), and
/// asserts that everything agrees.
fn check(name: &str, level: &Level, views: &[View], size: (usize, usize), renderer: Renderer, frames: &mut [Frame; 4]) {
    let options = RenderOptions { renderer, shade: Shade::Textured, count_writes: true, ..Default::default() };
    let same_strips = THREADS.iter().all(|&t| strips(size.0, size.1, 1).eq(strips(size.0, size.1, t)));
    let [one, rest @ ..] = frames;
    for view in views {
        let serial = draw(level, view, size, RenderOptions { threads: 1, ..options }, one);
        let context = format!("{name} {} {}x{} from {view:?}", renderer.name(), size.0, size.1);
        assert!(serial.counts.iter().all(|&c| c == 1), "{context}: overdraw with one thread");
        for (&threads, frame) in THREADS.iter().zip(rest.iter_mut()) {
            let parallel = draw(level, view, size, RenderOptions { threads, ..options }, frame);
            let context = format!("{context}, {threads} threads");
            let differ = serial.fb.pixels.iter().zip(&parallel.fb.pixels).filter(|(a, b)| a != b).count();
            assert_eq!(differ, 0, "{context}: pixels differ");
            assert!(serial.counts == parallel.counts, "{context}: write counts differ");
            assert!(serial.seen == parallel.seen, "{context}: lines seen differ");
            let (s, p) = (serial.stats, parallel.stats);
            assert_eq!(
                (s.pixels_written, s.masked_pixels_written, s.sprites_in_view),
                (p.pixels_written, p.masked_pixels_written, p.sprites_in_view),
                "{context}: pixel totals differ"
            );
            if same_strips {
                assert_eq!(s, p, "{context}: same strips, different stats");
            }
        }
    }
}

#[test]
fn every_thread_count_draws_the_same_frame() {
    let mut frames: [Frame; 4] = Default::default();
    for path in shipped_maps() {
        let name = path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned());
        let level = load(&path);
        let views = tour(&level, 6, 11);
        assert!(views.len() >= 12, "{name}: tour too short");
        let renderers = [Renderer::Bsp, Renderer::Raycast].into_iter().filter(|r| r.supports(&level));
        for renderer in renderers {
            for size in [(320, 200), (321, 200), (7, 5), (64, 40)] {
                check(&name, &level, &views, size, renderer, &mut frames);
            }
            // 1080p is costly: the start's eight directions and four more poses.
            check(&name, &level, &views[..12], (1920, 1080), renderer, &mut frames);
        }
        // The oracle is slow: small frames, a few poses.
        check(&name, &level, &views[..4], (97, 61), Renderer::Reference, &mut frames);
    }
}

#[test]
fn sprites_and_masked_middles_agree_across_threads() {
    // The hall has things in view from most poses and see-through middles;
    // at 1080p a sprite spans several strips.
    let level = load(&sightline_tests::map_path("hall.ron"));
    let views = sightline::tour::things_tour(&level);
    let mut frames: [Frame; 4] = Default::default();
    let mut fb = Framebuffer::new(640, 400);
    let masked: u64 = views
        .iter()
        .map(|v| render_frame(&level, v, &RenderOptions::default(), &mut frames[0], &mut fb).masked_pixels_written)
        .sum();
    assert!(masked > 0, "the hall tour draws no sprite or masked middle");
    check("hall.ron", &level, &views, (640, 400), Renderer::Bsp, &mut frames);
}
