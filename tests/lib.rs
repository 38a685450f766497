//! Shared support for the workspace tests: the shipped maps, Freedoom's
//! WADs, Chocolate Doom as a demo's referee, rendering a pose through both
//! renderers, and comparing frames.

use std::path::{Path, PathBuf};

use glam::DVec2;
use sightline::bsp::BuildOptions;
use sightline::level::{open_level, Level};
use sightline::play::input::wander;
use sightline::play::TickInput;
use sightline::render::{render_frame, Frame, RenderOptions, Renderer, Shade, View};
use sightline::Framebuffer;

pub mod chocolate;
pub mod freedoom_wads;
pub mod puzzle;
pub mod sim_play;

/// The repository root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every shipped sector map. Panics (fails the test) if the maps are missing.
pub fn shipped_maps() -> Vec<PathBuf> {
    let dir = root().join("maps");
    let mut maps: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .collect();
    maps.sort();
    assert!(maps.len() >= 5, "expected the shipped maps in {}, found {maps:?}", dir.display());
    maps
}

pub fn map_path(name: &str) -> PathBuf {
    let p = root().join("maps").join(name);
    assert!(p.exists(), "missing fixture {}", p.display());
    p
}

pub fn load(path: &Path) -> Level {
    open_level(path, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

pub fn render(level: &Level, view: &View, size: (usize, usize), renderer: Renderer, shade: Shade) -> Framebuffer {
    let mut fb = Framebuffer::new(size.0, size.1);
    let options = RenderOptions { renderer, shade, count_writes: false, ..Default::default() };
    render_frame(level, view, &options, &mut Frame::new(), &mut fb);
    fb
}

/// How two frames differ.
#[derive(Debug)]
pub struct Difference {
    pub pixels: usize,
    pub total: usize,
    /// Widest run of adjacent columns that contain a differing pixel.
    pub widest_column_run: usize,
}

impl Difference {
    pub fn equal_share(&self) -> f64 {
        1.0 - self.pixels as f64 / self.total as f64
    }
}

pub fn difference(a: &Framebuffer, b: &Framebuffer) -> Difference {
    assert_eq!((a.width, a.height), (b.width, b.height));
    let mut pixels = 0;
    let mut column_differs = vec![false; a.width];
    for (i, (p, q)) in a.pixels.iter().zip(&b.pixels).enumerate() {
        if p != q {
            pixels += 1;
            column_differs[i % a.width] = true;
        }
    }
    let mut widest = 0;
    let mut run = 0;
    for d in column_differs {
        run = if d { run + 1 } else { 0 };
        widest = widest.max(run);
    }
    Difference { pixels, total: a.pixels.len(), widest_column_run: widest }
}

/// `frame` against the golden image `tests/images/NAME.png`: `Err` says
/// how many pixels differ and where the new frame was written. With
/// `SIGHTLINE_BLESS` set the golden image is written instead (look at it).
pub fn golden(name: &str, frame: &Framebuffer) -> Result<(), String> {
    let file = root().join("tests/images").join(format!("{name}.png"));
    if std::env::var_os("SIGHTLINE_BLESS").is_some() {
        std::fs::write(&file, frame.to_png()).unwrap();
        return Ok(());
    }
    let golden = Framebuffer::read_png(&file)
        .unwrap_or_else(|e| panic!("missing golden image ({e}); create it with SIGHTLINE_BLESS=1 and look at it"));
    let diff = difference(frame, &golden);
    if diff.pixels == 0 {
        return Ok(());
    }
    let out = std::env::temp_dir().join(format!("golden-{name}.png"));
    std::fs::write(&out, frame.to_png()).unwrap();
    Err(format!("{}: {} pixels differ (got {})", file.display(), diff.pixels, out.display()))
}

/// Renders `view` with both renderers in `ids` shading and returns how they differ.
pub fn bsp_vs_reference(level: &Level, view: &View, size: (usize, usize)) -> (Difference, Framebuffer, Framebuffer) {
    let bsp = render(level, view, size, Renderer::Bsp, Shade::Ids);
    let reference = render(level, view, size, Renderer::Reference, Shade::Ids);
    (difference(&bsp, &reference), bsp, reference)
}

/// Asserts the exactness criterion: at least 99.9% of pixels equal, differences
/// only in isolated columns (wall edges). Saves both frames on failure.
pub fn assert_agree(level: &Level, view: &View, size: (usize, usize), what: &str) {
    let (diff, bsp, reference) = bsp_vs_reference(level, view, size);
    let ok = diff.equal_share() >= 0.999 && diff.widest_column_run <= 1;
    if !ok {
        let dir = std::env::temp_dir().join("sightline-failures");
        let _ = std::fs::create_dir_all(&dir);
        let stem = what.replace(|c: char| !c.is_ascii_alphanumeric(), "_");
        let _ = std::fs::write(dir.join(format!("{stem}-bsp.png")), bsp.to_png());
        let _ = std::fs::write(dir.join(format!("{stem}-reference.png")), reference.to_png());
        panic!(
            "{what}: bsp and reference differ in {} of {} pixels ({:.4}% equal), widest run of differing columns {} \
             (frames saved in {})",
            diff.pixels,
            diff.total,
            diff.equal_share() * 100.0,
            diff.widest_column_run,
            dir.display()
        );
    }
}

pub fn view(level: &Level, x: f64, y: f64, angle: f64) -> View {
    View::at_pose(level, x, y, angle, None).unwrap_or_else(|e| panic!("pose ({x}, {y}): {e}"))
}

pub fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// Columns whose ray runs, within rounding, along a map line passing within
/// rounding of the eye. What such a column shows is decided by the last bits
/// of two independent f64 computations (a ray from a point on a line,
/// "along" it, may pass either side of the line's vertices), so comparisons
/// of degenerate poses exempt exactly these columns and nothing else.
pub fn columns_along_lines_through_eye(level: &Level, view: &View, size: (usize, usize)) -> Vec<usize> {
    let cam = sightline::render::Camera::new(view, size.0, size.1);
    let mut columns = Vec::new();
    for line in &level.map.lines {
        let (a, b) = level.map.line_points(line);
        let scale = a.abs().max(b.abs()).max(view.pos.abs()).max_element().max(1.0);
        if sightline::geom::front_distance(a, b, view.pos).abs() > 1e-9 * scale {
            continue;
        }
        for dir in [b - a, a - b] {
            let c = glam::DVec2::new(dir.dot(cam.forward), dir.dot(cam.right));
            if c.x <= 0.0 {
                continue;
            }
            let slope = c.y / c.x;
            columns.extend((0..size.0).filter(|&x| (cam.column_slope(x) - slope).abs() <= 1e-9 * (1.0 + slope.abs())));
        }
    }
    columns.sort_unstable();
    columns.dedup();
    columns
}

/// [`assert_agree`] for degenerate poses: pixels in the columns of
/// [`columns_along_lines_through_eye`] are exempt; all others must meet the
/// same criterion.
pub fn assert_agree_off_eye_lines(level: &Level, view: &View, size: (usize, usize), what: &str) {
    let exempt = columns_along_lines_through_eye(level, view, size);
    let (mut bsp, reference) = (
        render(level, view, size, Renderer::Bsp, Shade::Ids),
        render(level, view, size, Renderer::Reference, Shade::Ids),
    );
    for &x in &exempt {
        for y in 0..size.1 {
            bsp.pixels[y * size.0 + x] = reference.get(x, y);
        }
    }
    let diff = difference(&bsp, &reference);
    let counted = diff.total - exempt.len() * size.1;
    let equal = 1.0 - diff.pixels as f64 / counted.max(1) as f64;
    assert!(
        equal >= 0.999 && diff.widest_column_run <= 1,
        "{what}: outside the {} exempt column(s) {exempt:?}, bsp and reference differ in {} of {counted} pixels",
        exempt.len(),
        diff.pixels
    );
}

/// Points where a user or the game may stand that lie on lines: exactly on
/// two-sided lines (at a quarter, the middle, three quarters; only the
/// rounded points that are exactly on the line) and at vertices where only
/// two-sided lines meet, each with the directions of its lines in degrees.
pub fn points_on_two_sided_lines(map: &sightline::map::Map) -> Vec<(String, DVec2, Vec<f64>)> {
    use sightline::geom::{exact_side, Side};
    let mut points = Vec::new();
    for (i, line) in map.lines.iter().enumerate().filter(|(_, l)| l.back.is_some()) {
        let (a, b) = map.line_points(line);
        let d = b - a;
        let along = d.y.atan2(d.x).to_degrees();
        for t in [0.25, 0.5, 0.75] {
            let p = a + d * t;
            if exact_side(a, b, p) == Side::On {
                points.push((format!("on line {i} at {t}"), p, vec![along]));
            }
        }
    }
    for (i, &p) in map.vertices.iter().enumerate() {
        let lines: Vec<_> = map.lines.iter().filter(|l| l.from == i || l.to == i).collect();
        if !lines.is_empty() && lines.iter().all(|l| l.back.is_some()) {
            let directions = lines
                .iter()
                .map(|l| {
                    let (a, b) = map.line_points(l);
                    let d = if l.from == i { b - a } else { a - b };
                    d.y.atan2(d.x).to_degrees()
                })
                .collect();
            points.push((format!("at vertex {i}"), p, directions));
        }
    }
    points
}

/// Poses at up to `max_points` of [`points_on_two_sided_lines`] (spread
/// over the list), looking along each line there, across it, back and at
/// a few other angles: every one is accepted, its eye at the located
/// sector's floor plus the eye height, and the BSP frame agrees with the
/// reference at each of `sizes`. Along an axis-aligned line a column's ray
/// runs exactly along it and both renderers settle it by the same rule, so
/// every column counts; along a slanted one it runs along only within
/// rounding, and which side of the line's vertices it passes is decided by
/// the last bits of two independent computations, so that column alone is
/// exempt ([`assert_agree_off_eye_lines`]). Returns the frames compared.
pub fn assert_agree_on_two_sided_lines(
    level: &Level,
    name: &str,
    max_points: usize,
    sizes: &[(usize, usize)],
) -> usize {
    let points = points_on_two_sided_lines(&level.map);
    let step = (points.len() / max_points.max(1)).max(1);
    let mut frames = 0;
    for (what, p, directions) in points.into_iter().step_by(step) {
        let sector = level.locate(p).unwrap_or_else(|| panic!("{name} {what}: ({}, {}) not located", p.x, p.y));
        let axis_aligned = directions.iter().all(|d| d.rem_euclid(90.0) == 0.0);
        let mut angles: Vec<f64> = directions.iter().flat_map(|&d| [d, d + 90.0, d + 180.0, d + 270.0]).collect();
        angles.extend([0.0, 45.0, 200.0, directions[0] + 37.0, directions[0] - 0.3]);
        for angle in angles {
            let view = self::view(level, p.x, p.y, angle);
            assert_eq!(view.z, level.map.sectors[sector].floor + sightline::render::view::EYE_HEIGHT, "{name} {what}");
            for &size in sizes {
                let what = format!("{name} {what} ({:?}, {:?}) angle {angle} {size:?}", p.x, p.y);
                if axis_aligned {
                    assert_agree(level, &view, size, &what);
                } else {
                    assert_agree_off_eye_lines(level, &view, size, &what);
                }
                frames += 1;
            }
        }
    }
    frames
}

/// Seeded input that mostly runs into things, use pressed now and then
/// ([`wander`] with presses).
pub fn random_inputs(seed: u64, ticks: usize) -> Vec<TickInput> {
    wander(seed, ticks, true)
}

/// What [`saves_continue_exactly`] saw at its save points.
#[derive(Debug, Default)]
pub struct SaveCheck {
    /// Saves made, loaded and followed.
    pub saves: usize,
    /// The largest save, in bytes.
    pub largest: usize,
    /// Save points at which some monster was after the player or another monster.
    pub fighting: usize,
    /// Save points at which some sector was moving or a light changing.
    pub machinery: usize,
}

/// Plays `inputs` on `play` (a game on the simulation); at each tick in `save_at` (while a level is
/// being played) saves the playthrough, loads the save into a new
/// playthrough and plays the next `ahead` inputs on both, side by side:
/// the loaded game must equal the original in its whole state after every
/// tick, and in its frames (the BSP renderer, at the tick and between ticks)
/// at the end. Panics (fails the test) at the first difference.
pub fn saves_continue_exactly(
    play: &mut sightline::play::playthrough::Playthrough,
    inputs: &[TickInput],
    save_at: &[usize],
    ahead: usize,
) -> SaveCheck {
    use sightline::play::playthrough::{Phase, Playthrough};
    let mut check = SaveCheck::default();
    let mut followers: Vec<(usize, Playthrough, usize)> = Vec::new();
    for (i, input) in inputs.iter().enumerate() {
        if save_at.contains(&i) && play.phase == Phase::Playing {
            let bytes = play.save_bytes().unwrap_or_else(|e| panic!("tick {i}: {e}"));
            let loaded = Playthrough::from_save_bytes(&bytes, &format!("the save at tick {i}"))
                .unwrap_or_else(|e| panic!("{e}"));
            assert!(loaded.game.state_bytes() == play.game.state_bytes(), "tick {i}: the loaded game differs at once");
            check.saves += 1;
            check.largest = check.largest.max(bytes.len());
            let sim = &play.game.sim;
            let chasing = |id: sightline::sim::MobjId| {
                let m = sim.mo(id);
                m.player.is_none() && m.health > 0 && m.target.is_some()
            };
            let moving = |t: &sightline::sim::Thinker| {
                t.status == sightline::sim::think::Status::Active
                    && !matches!(t.kind, sightline::sim::ThinkerKind::Mobj(_) | sightline::sim::ThinkerKind::Light(_))
            };
            let (fighting, machinery) = (sim.live_mobjs().any(chasing), sim.thinkers.iter().any(moving));
            check.fighting += usize::from(fighting);
            check.machinery += usize::from(machinery);
            followers.push((i, loaded, ahead));
        }
        play.tick(input).unwrap_or_else(|e| panic!("tick {i}: {e}"));
        for (from, loaded, left) in &mut followers {
            loaded.tick(input).unwrap_or_else(|e| panic!("tick {i}: {e}"));
            let what = format!("the game saved at tick {from} and loaded, {} ticks on", i + 1 - *from);
            assert!(loaded.game.state_bytes() == play.game.state_bytes(), "{what}: its state differs");
            assert_eq!(loaded.phase, play.phase, "{what}");
            *left -= 1;
            if *left == 0 {
                for alpha in [1.0, 0.5] {
                    let (a, b) = (play.game.view(alpha), loaded.game.view(alpha));
                    let size = (160, 100);
                    let fa = render(play.game.level(), &a, size, Renderer::Bsp, Shade::Textured);
                    let fb = render(loaded.game.level(), &b, size, Renderer::Bsp, Shade::Textured);
                    assert!(fa.pixels == fb.pixels, "{what}: its frame differs (alpha {alpha})");
                }
            }
        }
        followers.retain(|(_, _, left)| *left > 0);
    }
    check
}

/// A run's sound rendered offline as `sightline replay --audio` renders it
/// (no music): interleaved stereo at [`sightline::sound::OUTPUT_RATE`], and
/// every sound event with its tick (counted from 1).
pub fn render_audio(
    play: &mut sightline::play::playthrough::Playthrough,
    inputs: &[TickInput],
) -> (Vec<f32>, Vec<(usize, &'static str, sightline::play::events::Origin)>) {
    use sightline::play::events::Event;
    use sightline::sound::{Audio, Sounds};
    let (mut sounds, mut audio) = (Sounds::new(), Audio::new(8, None));
    let (mut samples, mut events) = (Vec::new(), Vec::new());
    for (i, input) in inputs.iter().enumerate() {
        play.tick(input).unwrap_or_else(|e| panic!("tick {i}: {e}"));
        for e in play.game.events() {
            if let Event::Sound { sound, origin } = e {
                events.push((i + 1, *sound, *origin));
            }
        }
        audio.render_tick(&sounds.cues(play), &mut samples).unwrap_or_else(|e| panic!("tick {i}: {e}"));
    }
    (samples, events)
}
