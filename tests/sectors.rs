//! Sector rendering's hard cases and its lack of static limits: thousands of
//! visible lines and sprites, sprites at a wall and at the eye, light 0 and
//! 255, textures one texel wide and of odd sizes.

use sightline::bsp::{build, BuildOptions, SplitterKind};
use sightline::level::Level;
use sightline::map::source::{LineSource, MapSource, SectorSource, SideSource, ThingSource};
use sightline::map::validate::validate;
use sightline::render::shade::{ids_colour, Surface, VOID};
use sightline::render::{render_frame, Frame, RenderOptions, Renderer, Shade, View};
use sightline::Framebuffer;
use sightline_tests::{assert_agree, render};

fn side(sector: i64, middle: Option<&str>) -> SideSource {
    SideSource { sector, middle: middle.map(str::to_string), ..Default::default() }
}

/// A one-sector room through `points` (clockwise), its walls textured `wall`.
fn room(points: &[(f64, f64)], light: i64, wall: &str, things: Vec<ThingSource>) -> MapSource {
    let n = points.len() as i64;
    MapSource {
        name: "test room".into(),
        vertices: points.to_vec(),
        sectors: vec![SectorSource {
            floor: 0.0,
            ceiling: 128.0,
            light,
            floor_texture: Some("FLOOR".into()),
            ceiling_texture: Some("CEIL".into()),
            ..SectorSource::default()
        }],
        lines: (0..n)
            .map(|i| LineSource {
                from: i,
                to: (i + 1) % n,
                front: side(0, Some(wall)),
                back: None,
                ..LineSource::default()
            })
            .collect(),
        things,
        diminishing_light: false,
        fog: None,
        ..MapSource::default()
    }
}

fn thing(kind: &str, x: f64, y: f64, angle: f64) -> ThingSource {
    ThingSource::new(kind, x, y, angle)
}

fn level(source: &MapSource, splitter: SplitterKind) -> Level {
    let map = validate(source).unwrap_or_else(|p| panic!("{p:?}"));
    let compiled = build(&map, &BuildOptions { splitter, seed: 1 }).unwrap();
    Level::with_builtin_textures(compiled).unwrap()
}

fn no_void(fb: &Framebuffer, what: &str) {
    let void = fb.pixels.iter().filter(|&&p| p == VOID).count();
    assert_eq!(void, 0, "{what}: {void} void pixels inside a closed room");
}

#[test]
fn ten_thousand_visible_lines_and_a_thousand_sprites() {
    // The far wall: an arc of 10,000 segments spanning the whole view.
    let radius = 4000.0;
    let mut points: Vec<(f64, f64)> = (0..=10_000)
        .map(|i| {
            let angle = (135.0 - 90.0 * f64::from(i) / 10_000.0_f64).to_radians();
            (radius * angle.cos(), radius * angle.sin())
        })
        .collect();
    let r = radius * std::f64::consts::FRAC_1_SQRT_2;
    points.extend([(r, -200.0), (-r, -200.0)]);
    let mut things = vec![thing("player_start", 0.0, 0.0, 90.0)];
    for row in 0..25u32 {
        for k in 0..40u32 {
            let y = 300.0 + 100.0 * f64::from(row);
            let x = (f64::from(k) - 19.5) / 20.0 * y * 0.9;
            things.push(thing(["barrel", "lamp", "column", "plant"][((row + k) % 4) as usize], x, y, 0.0));
        }
    }
    let source = room(&points, 200, "STONE", things);
    let level = level(&source, SplitterKind::Random);
    assert!(level.map.lines.len() > 10_000);
    let view = View::at_start(&level).unwrap();
    // 10,000 columns: enough that thousands of lines each claim columns.
    let size = (10_000, 120);
    let mut frame = Frame::new();
    let mut fb = Framebuffer::new(size.0, size.1);
    let stats =
        render_frame(&level, &view, &RenderOptions { shade: Shade::Ids, ..Default::default() }, &mut frame, &mut fb);
    assert!(stats.walls_drawn > 8_000, "{stats:?}");
    assert_eq!(stats.sprites_in_view, 1_000, "{stats:?}");
    assert!(stats.masked_pixels_written > 0);
    no_void(&fb, "ids");
    assert_agree(&level, &view, size, "10,000 lines, 1,000 sprites");
    // And the textured frame renders too (no panic, no void).
    no_void(&render(&level, &view, (1920, 1080), Renderer::Bsp, Shade::Textured), "textured");
}

#[test]
fn sprites_at_a_wall_and_at_the_eye() {
    let square = [(0.0, 0.0), (0.0, 512.0), (512.0, 512.0), (512.0, 0.0)];
    let things = vec![
        thing("player_start", 256.0, 100.0, 90.0),
        // On the north wall's line: half the billboard is behind the wall.
        thing("barrel", 256.0, 512.0, 0.0),
        // Exactly at the eye: nearer than anything can be drawn.
        thing("lamp", 256.0, 100.0, 0.0),
        // Against the east wall, seen edge-on to it.
        thing("column", 512.0 - 1e-9, 300.0, 0.0),
    ];
    let level = level(&room(&square, 160, "BRICK", things), SplitterKind::Cost);
    for angle in [90.0, 45.0, 0.0, 270.0, 12.5] {
        let view = View::at_pose(&level, 256.0, 100.0, angle, None).unwrap();
        assert_agree(&level, &view, (320, 200), &format!("angle {angle}"));
        for shade in [Shade::Textured, Shade::Flat] {
            no_void(&render(&level, &view, (320, 200), Renderer::Bsp, shade), "sprites at wall and eye");
        }
    }
}

#[test]
fn light_zero_and_full() {
    let square = [(0.0, 0.0), (0.0, 256.0), (256.0, 256.0), (256.0, 0.0)];
    let lit = |light| {
        level(&room(&square, light, "BRICK", vec![thing("player_start", 128.0, 64.0, 90.0)]), SplitterKind::Cost)
    };
    let view = View::at_pose(&lit(0), 128.0, 64.0, 90.0, None).unwrap();
    let dark = render(&lit(0), &view, (64, 40), Renderer::Bsp, Shade::Textured);
    // Black, but for Doom's fake contrast: walls running north-south one light
    // step (16 of 256) brighter than their sector.
    let dim = |p: u32| sightline::framebuffer::channels(p)[..3].iter().all(|&c| c <= 16);
    assert!(dark.pixels.iter().all(|&p| dim(p)), "light 0 is black but for the fake contrast");
    assert!(dark.pixels.contains(&sightline::framebuffer::rgb(0, 0, 0)), "light 0 is black");
    let full = render(&lit(255), &view, (64, 40), Renderer::Bsp, Shade::Textured);
    let brick = sightline::texture::procedural::generate("BRICK", sightline::texture::TextureKind::Wall).unwrap();
    let texels: std::collections::HashSet<u32> = brick.texels.iter().copied().collect();
    // At full light without diminishing, wall pixels are the texels themselves.
    let wall_pixels = full.pixels.iter().filter(|p| texels.contains(p)).count();
    assert!(wall_pixels > full.pixels.len() / 4, "{wall_pixels} of {} pixels are brick texels", full.pixels.len());
}

#[test]
fn one_texel_wide_and_odd_sized_textures() {
    let square = [(0.0, 0.0), (0.0, 300.0), (300.0, 300.0), (300.0, 0.0)];
    for name in ["THIN", "DEBUG1", "ODD"] {
        let level =
            level(&room(&square, 255, name, vec![thing("player_start", 150.0, 40.0, 90.0)]), SplitterKind::Cost);
        let texture = sightline::texture::procedural::generate(name, sightline::texture::TextureKind::Wall).unwrap();
        // The texels themselves, and as east-west walls show them (fake
        // contrast: one light step, 16 of 256, darker).
        let darker = sightline::render::light::Lighting { diminishing: false, fog: None }.tint(255 - 16, 0.0);
        let texels: std::collections::HashSet<u32> =
            texture.texels.iter().flat_map(|&t| [t, darker.apply(t)]).collect();
        for angle in [90.0, 30.0, 200.0] {
            let view = View::at_pose(&level, 150.0, 40.0, angle, None).unwrap();
            let fb = render(&level, &view, (97, 61), Renderer::Bsp, Shade::Textured);
            no_void(&fb, name);
            // Every wall pixel is one of the texture's own texels: sampling
            // stays inside the texture and wraps, whatever its size.
            let ids = render(&level, &view, (97, 61), Renderer::Bsp, Shade::Ids);
            let walls: Vec<u32> = (0..4).map(|line| ids_colour(Surface::Wall { line })).collect();
            for (i, (&p, id)) in fb.pixels.iter().zip(&ids.pixels).enumerate() {
                if walls.contains(id) {
                    assert!(texels.contains(&p), "{name} angle {angle}: pixel {i} {p:08x} is not a texel");
                }
            }
        }
    }
}

#[test]
fn a_missing_texture_is_a_load_error_naming_file_and_element() {
    let square = [(0.0, 0.0), (0.0, 256.0), (256.0, 256.0), (256.0, 0.0)];
    let mut source = room(&square, 160, "BRICK", vec![thing("player_start", 128.0, 128.0, 0.0)]);
    source.lines[2].front.middle = Some("NOSUCHTEX".into());
    source.things.push(thing("unicorn", 64.0, 64.0, 0.0));
    let dir = std::env::temp_dir().join(format!("sightline-missing-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("missing.ron");
    std::fs::write(&path, source.to_ron()).unwrap();
    let err = sightline::level::open_level(&path, &BuildOptions::default()).expect_err("a missing texture");
    let message = err.to_string();
    for part in [path.display().to_string().as_str(), "line 2 front side middle texture", "NOSUCHTEX"] {
        assert!(message.contains(part), "{message}");
    }
    // Fixed, the unknown thing kind is the next error: its sprite is missing.
    source.lines[2].front.middle = Some("BRICK".into());
    std::fs::write(&path, source.to_ron()).unwrap();
    let message = sightline::level::open_level(&path, &BuildOptions::default()).expect_err("no sprite").to_string();
    assert!(message.contains("thing 1 (kind \"unicorn\") sprite"), "{message}");
    let _ = std::fs::remove_dir_all(&dir);
}
