//! Tests of texel addressing and of name resolution against real files.

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

use super::*;

/// A fresh map directory under the system temp dir, removed on drop.
struct MapDir(PathBuf);

impl MapDir {
    fn new() -> MapDir {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("sightline-texture-{}-{n}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("textures")).unwrap();
        std::fs::create_dir_all(dir.join("sprites")).unwrap();
        MapDir(dir)
    }

    /// The directory list to resolve against: this one alone.
    fn dirs(&self) -> Vec<PathBuf> {
        vec![self.0.clone()]
    }

    fn write(&self, rel: &str, bytes: &[u8]) -> PathBuf {
        let path = self.0.join(rel);
        std::fs::write(&path, bytes).unwrap();
        path
    }
}

impl Drop for MapDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// An 8-bit RGBA PNG of `w` x `h` texels, every one `rgba`.
fn solid_png(w: u32, h: u32, rgba: [u8; 4]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut encoder = ::png::Encoder::new(&mut out, w, h);
    encoder.set_color(::png::ColorType::Rgba);
    encoder.set_depth(::png::BitDepth::Eight);
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(&rgba.repeat((w * h) as usize)).unwrap();
    writer.finish().unwrap();
    out
}

/// Texel (u, v) encodes its coordinates, to check the indexing arithmetic.
fn coded(w: usize, h: usize) -> Texture {
    Texture::from_fn(w, h, |u, v| [u as u8, v as u8, 7, 255])
}

#[test]
fn from_fn_is_column_major() {
    let t = coded(5, 3);
    assert_eq!((t.width, t.height, t.texels.len()), (5, 3, 15));
    assert!(t.opaque);
    for u in 0..5 {
        for v in 0..3 {
            assert_eq!(t.texels[u * 3 + v], u32::from_le_bytes([u as u8, v as u8, 7, 255]));
            assert_eq!(t.texel(u, v), t.texels[u * 3 + v]);
            assert_eq!(t.column(u)[v], t.texel(u, v));
        }
        assert_eq!(t.column(u).len(), 3);
    }
    assert_eq!(t.texel(0, 0), crate::framebuffer::rgb(0, 0, 7));
}

#[test]
fn wrapped_repeats_any_size_in_both_directions() {
    for (w, h) in [(1, 1), (1, 64), (37, 23), (64, 64), (96, 128)] {
        let t = coded(w, h);
        let (wi, hi) = (w as i64, h as i64);
        for (u, v) in
            [(0, 0), (wi - 1, hi - 1), (wi, hi), (-1, -1), (-wi, -hi), (-wi - 1, 5), (3 * wi + 2, -7 * hi - 3)]
        {
            let expected = t.texel(u.rem_euclid(wi) as usize, v.rem_euclid(hi) as usize);
            assert_eq!(t.wrapped(u, v), expected, "{w}x{h} at ({u}, {v})");
        }
        // Negative wrap lands on the far edge, not on a mirror or on 0.
        assert_eq!(t.wrapped(-1, -1), t.texel(w - 1, h - 1));
        assert_eq!(
            t.wrapped(i64::MIN, i64::MAX),
            t.texel(i64::MIN.rem_euclid(wi) as usize, i64::MAX.rem_euclid(hi) as usize)
        );
    }
}

#[test]
fn opacity_is_computed() {
    let t = Texture::from_fn(3, 2, |u, v| [0, 0, 0, if (u, v) == (2, 1) { 0 } else { 255 }]);
    assert!(!t.opaque);
    let t = Texture::from_fn(3, 2, |_, _| [0, 0, 0, 128]);
    assert!(!t.opaque, "partial alpha is not opaque");
}

#[test]
fn resolve_caches_by_name_and_kind() {
    let mut set = TextureSet::new();
    assert!(set.is_empty());
    let a = set.resolve("BRICK", TextureKind::Wall, &[]).unwrap();
    let b = set.resolve("BRICK", TextureKind::Wall, &[]).unwrap();
    assert_eq!(a, b);
    assert_eq!(set.len(), 1);
    assert_eq!(set.name(a), "BRICK");
    assert_eq!(set.find("BRICK", TextureKind::Wall), Some(a));
    assert_eq!(set.find("BRICK", TextureKind::Flat), None);
    // One sky, whether a wall or a ceiling asks for it.
    let sky_wall = set.resolve("SKY", TextureKind::Wall, &[]).unwrap();
    let sky_flat = set.resolve("SKY", TextureKind::Flat, &[]).unwrap();
    assert_eq!(sky_wall, sky_flat);
    assert_eq!(set.len(), 2);
    // Procedural names are case-insensitive and share the texture; the set
    // keeps the first spelling.
    let lower = set.resolve("brick", TextureKind::Wall, &[]).unwrap();
    assert_eq!(lower, a);
    assert_eq!(set.name(lower), "BRICK");
    assert_eq!(set.find("brick", TextureKind::Wall), Some(a));
    assert_eq!(set.len(), 2);
    let other = set.resolve("STONE", TextureKind::Wall, &[]).unwrap();
    assert_ne!(other, a);
    assert_eq!(set.get(other).width, 96);
}

#[test]
fn png_in_the_map_overrides_the_procedural_texture() {
    let dir = MapDir::new();
    dir.write("textures/BRICK.png", &solid_png(3, 5, [1, 2, 3, 255]));
    dir.write("sprites/barrel.png", &solid_png(2, 2, [9, 9, 9, 0]));
    let mut set = TextureSet::new();
    let brick = set.resolve("BRICK", TextureKind::Wall, &dir.dirs()).unwrap();
    assert_eq!((set.get(brick).width, set.get(brick).height), (3, 5));
    assert_eq!(set.get(brick).texel(2, 4), crate::framebuffer::rgb(1, 2, 3));
    // Wall and flat textures share the folder.
    let flat = set.resolve("BRICK", TextureKind::Flat, &dir.dirs()).unwrap();
    assert_eq!(set.get(flat), set.get(brick));
    // Exact name first, then the lower-case file name.
    let barrel = set.resolve("BARREL", TextureKind::Sprite, &dir.dirs()).unwrap();
    assert_eq!(set.get(barrel).width, 2);
    assert!(!set.get(barrel).opaque);
    // A sprite name is not looked up among the textures, nor the other way.
    let stone = set.resolve("STONE", TextureKind::Wall, &dir.dirs()).unwrap();
    assert_eq!(set.get(stone), &procedural::generate("STONE", TextureKind::Wall).unwrap());
}

#[test]
fn earlier_directories_win() {
    let (first, second) = (MapDir::new(), MapDir::new());
    second.write("textures/WALLX.png", &solid_png(1, 1, [200, 0, 0, 255]));
    let dirs = [first.0.clone(), second.0.clone()];
    let mut set = TextureSet::new();
    let id = set.resolve("WALLX", TextureKind::Wall, &dirs).unwrap();
    assert_eq!(set.get(id).texel(0, 0), crate::framebuffer::rgb(200, 0, 0));

    first.write("textures/wally.png", &solid_png(1, 1, [0, 1, 0, 255]));
    second.write("textures/WALLY.png", &solid_png(1, 1, [0, 2, 0, 255]));
    let id = set.resolve("WALLY", TextureKind::Wall, &dirs).unwrap();
    assert_eq!(set.get(id).texel(0, 0), crate::framebuffer::rgb(0, 1, 0));
}

#[test]
fn missing_name_lists_what_was_tried() {
    let dir = MapDir::new();
    let mut set = TextureSet::new();
    let err = set.resolve("NoSuch", TextureKind::Wall, &dir.dirs()).unwrap_err();
    match &err {
        TextureError::Missing { name, kind, tried } => {
            assert_eq!(name, "NoSuch");
            assert_eq!(*kind, TextureKind::Wall);
            assert_eq!(tried, &[dir.0.join("textures/NoSuch.png"), dir.0.join("textures/nosuch.png")]);
        }
        other => panic!("{other:?}"),
    }
    let text = err.to_string();
    assert!(text.contains("\"NoSuch\"") && text.contains("nosuch.png"), "{text}");
    assert!(text.contains("no procedural wall texture") && text.contains("BRICK, STONE"), "{text}");
    assert_eq!(set.len(), 0);

    // A flat name is not a wall, and a sprite is looked for under sprites/.
    let err = set.resolve("floor", TextureKind::Sprite, &dir.dirs()).unwrap_err();
    let text = err.to_string();
    assert!(text.contains("sprites/floor.png") && text.contains("BARREL"), "{text}");
    assert!(matches!(err, TextureError::Missing { ref tried, .. } if tried.len() == 1));
}

#[test]
fn names_that_are_paths_are_refused() {
    let mut set = TextureSet::new();
    for name in ["", "../BRICK", "a/b", "a\\b", ".hidden", "c:x"] {
        let err = set.resolve(name, TextureKind::Wall, &[PathBuf::from("maps")]).unwrap_err();
        assert!(matches!(err, TextureError::BadName { .. }), "{name:?}: {err:?}");
    }
}

#[test]
fn broken_files_are_errors_naming_the_file_not_fallbacks() {
    let dir = MapDir::new();
    let good = solid_png(4, 4, [1, 1, 1, 255]);
    let truncated = dir.write("textures/BRICK.png", &good[..good.len() / 2]);
    let garbage = dir.write("textures/STONE.png", b"not a png");
    let mut set = TextureSet::new();
    for (name, path) in [("BRICK", &truncated), ("STONE", &garbage)] {
        match set.resolve(name, TextureKind::Wall, &dir.dirs()) {
            Err(err @ TextureError::Png { .. }) => {
                let TextureError::Png { path: p, .. } = &err else { unreachable!() };
                assert_eq!(p, path);
                assert!(err.to_string().starts_with(&path.display().to_string()), "{err}");
            }
            other => panic!("{name}: {other:?}"),
        }
    }
    assert_eq!(set.len(), 0);
}

#[test]
fn absurd_sizes_in_the_map_are_errors() {
    let dir = MapDir::new();
    // The encoder writes the header of any size; it is the decoder that refuses.
    let wide = solid_png(MAX_SIDE + 1, 1, [0; 4]);
    let path = dir.write("textures/WIDE.png", &wide);
    let mut set = TextureSet::new();
    match set.resolve("WIDE", TextureKind::Wall, &dir.dirs()) {
        Err(TextureError::Size { path: p, width, height }) => {
            assert_eq!((p.as_path(), width, height), (path.as_path(), MAX_SIDE + 1, 1));
        }
        other => panic!("{other:?}"),
    }
}

// PNGs written by ImageMagick 6.9 rather than by the png crate the engine
// decodes with, including an interlaced one, which that crate's encoder cannot
// write. Kept here as hex rather than as files because the repository ignores
// `*.png`.
//
// `convert -size 37x23 xc:red -fill '#0000ff' -draw "rectangle 0,0 9,22"
//   -fill '#00ff00' -draw "rectangle 0,12 36,22" -fill '#ffffff'
//   -draw "point 36,22" -strip -interlace PNG -define png:color-type=2
//   PNG24:interlaced_rgb.png`
const INTERLACED_RGB: &str = concat!(
    "89504e470d0a1a0a0000000d49484452000000250000001708020000017449216400000072494441",
    "5448c7ed94510e80200c43dfb8ff9deb878991452759c488d22f082bedba808100610050a861c8ed",
    "d156dc58bfaef6acd37287420873e65ba9d159e4287f677de9a1e14c005d98173379935ba164b649",
    "c12fd392731fa2b7a7930ca36c7ffe7d6d4ebd9feae57ff831fa9b7af762012499173b914667d200",
    "00000049454e44ae426082",
);
// `convert -size 4x3 xc:'#ff8000' -fill none -draw "color 0,0 point"
//   -fill '#102030' -draw "point 3,2" -strip PNG8:palette_trns.png`
const PALETTE_TRNS: &str = concat!(
    "89504e470d0a1a0a0000000d4948445200000004000000030803000000832a5ef400000009504c54",
    "45000000ff8000102030793a45e00000000174524e530040e6d866000000114944415408d7636060",
    "6464046130c10400005c000dc91f9f280000000049454e44ae426082",
);
// `convert -size 2x5 gradient:'#000000-#ffffff' -rotate 90 -strip
//   -define png:bit-depth=16 -define png:color-type=0 grey16.png`
const GREY16: &str = concat!(
    "89504e470d0a1a0a0000000d4948445200000005000000021000000000e59195c200000017494441",
    "5408d763fcffff00c341c6030c07189818e00000593a05044d25a0220000000049454e44ae426082",
);

fn unhex(hex: &str) -> Vec<u8> {
    (0..hex.len()).step_by(2).map(|i| u8::from_str_radix(&hex[i..i + 2], 16).unwrap()).collect()
}

#[test]
fn files_from_another_encoder_decode() {
    // Through the file path, as a map's textures are read.
    let dir = MapDir::new();
    let load = |name: &str, hex: &str| {
        let path = dir.write(&format!("textures/{name}"), &unhex(hex));
        Texture::read_png(&path).unwrap_or_else(|e| panic!("{e}"))
    };
    let rgba = |t: &Texture, u, v| t.texel(u, v).to_le_bytes();

    let t = load("interlaced_rgb.png", INTERLACED_RGB);
    assert_eq!((t.width, t.height), (37, 23));
    assert!(t.opaque);
    for u in 0..37 {
        for v in 0..23 {
            let expected = match (u, v) {
                (36, 22) => [255, 255, 255, 255],
                (_, 12..) => [0, 255, 0, 255],
                (..=9, _) => [0, 0, 255, 255],
                _ => [255, 0, 0, 255],
            };
            assert_eq!(rgba(&t, u, v), expected, "({u}, {v})");
        }
    }

    let t = load("palette_trns.png", PALETTE_TRNS);
    assert_eq!((t.width, t.height), (4, 3));
    assert!(!t.opaque);
    assert_eq!(rgba(&t, 0, 0)[3], 0);
    assert_eq!(rgba(&t, 1, 0), [0xff, 0x80, 0x00, 255]);
    assert_eq!(rgba(&t, 3, 2), [0x10, 0x20, 0x30, 255]);

    let t = load("grey16.png", GREY16);
    assert_eq!((t.width, t.height), (5, 2));
    let row: Vec<u8> = (0..5).map(|u| rgba(&t, u, 1)[0]).collect();
    assert_eq!(row, [0xff, 0xbf, 0x80, 0x40, 0x00]); // high bytes of the 16-bit samples
    assert!((0..5).all(|u| {
        let [r, g, b, a] = rgba(&t, u, 0);
        r == g && g == b && a == 255
    }));
}
