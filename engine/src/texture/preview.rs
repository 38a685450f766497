//! A contact sheet of every procedural texture, for a person to look at: set
//! `SIGHTLINE_TEXTURE_PREVIEW=1` and run the texture tests to get
//! `/tmp/textures_preview/sheet.png` (and one PNG per texture). Tiling
//! textures are drawn 2x2 so seams show; the sky is drawn rolled by half its
//! width so its wrap seam sits in the middle; masked texels show a checker.

use std::path::Path;
use std::time::Instant;

use super::procedural::{generate, names};
use super::{Texture, TextureKind, TextureSet};

const KINDS: [TextureKind; 3] = [TextureKind::Wall, TextureKind::Flat, TextureKind::Sprite];
const SHEET_WIDTH: usize = 1100;
const MARGIN: usize = 8;

struct Sheet {
    w: usize,
    h: usize,
    rgb: Vec<[u8; 3]>,
}

impl Sheet {
    fn put(&mut self, x: usize, y: usize, c: [u8; 3]) {
        if x < self.w && y < self.h {
            self.rgb[y * self.w + x] = c;
        }
    }

    /// Draws `t` at `(x0, y0)`, `tiles` copies each way, each texel `zoom` pixels,
    /// its columns rolled left by `roll`.
    fn draw(&mut self, t: &Texture, x0: usize, y0: usize, zoom: usize, tiles: usize, roll: usize) {
        for py in 0..t.height * tiles * zoom {
            for px in 0..t.width * tiles * zoom {
                let (u, v) = ((px / zoom + roll) % t.width, (py / zoom) % t.height);
                let [r, g, b, a] = t.texel(u, v).to_le_bytes();
                let check = if (px / 4 + py / 4) % 2 == 0 { 90 } else { 60 };
                let c = if a == 0 { [check, check, check + 20] } else { [r, g, b] };
                self.put(x0 + px, y0 + py, c);
            }
        }
    }

    fn write(&self, path: &Path) {
        write_rgb(path, self.w, self.h, &self.rgb.concat());
    }
}

fn write_rgb(path: &Path, w: usize, h: usize, bytes: &[u8]) {
    let file = std::fs::File::create(path).unwrap();
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), w as u32, h as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(bytes).unwrap();
    writer.finish().unwrap();
}

/// The texture as a row-major RGBA PNG, transparency kept.
fn write_texture(path: &Path, t: &Texture) {
    let mut bytes = Vec::with_capacity(t.width * t.height * 4);
    for v in 0..t.height {
        for u in 0..t.width {
            bytes.extend(t.texel(u, v).to_le_bytes());
        }
    }
    let file = std::fs::File::create(path).unwrap();
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), t.width as u32, t.height as u32);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(&bytes).unwrap();
    writer.finish().unwrap();
}

#[test]
fn contact_sheet() {
    if std::env::var_os("SIGHTLINE_TEXTURE_PREVIEW").is_none() {
        return; // a preview for people, not a check
    }
    let start = Instant::now();
    let mut all: Vec<(TextureKind, &str, Texture)> = Vec::new();
    for kind in KINDS {
        for &name in names(kind) {
            let t0 = Instant::now();
            let t = generate(name, kind).unwrap();
            let elapsed = t0.elapsed();
            let size = format!("{}x{}", t.width, t.height);
            eprintln!("{:<6} {name:<8} {size:>8} {elapsed:?}", format!("{kind:?}"));
            all.push((kind, name, t));
        }
    }
    eprintln!("generated {} textures in {:?}", all.len(), start.elapsed());
    // Through a TextureSet, as a map loads them: the sky is generated once
    // for both kinds. The machine may be busy: the fastest of a few runs is
    // the honest figure.
    let best = (0..5)
        .map(|_| {
            let t0 = Instant::now();
            let mut set = TextureSet::new();
            for kind in KINDS {
                for &name in names(kind) {
                    set.resolve(name, kind, &[]).unwrap();
                }
            }
            (t0.elapsed(), set.len())
        })
        .min();
    eprintln!("all textures, fastest of 5 runs: {best:?}");

    let out = Path::new("/tmp/textures_preview");
    std::fs::create_dir_all(out).unwrap();
    // Shelf packing: left to right, a new shelf when the row is full.
    let mut placed = Vec::new();
    let (mut x, mut y, mut shelf) = (MARGIN, MARGIN, 0);
    for (kind, name, t) in &all {
        write_texture(&out.join(format!("{kind:?}_{name}.png").to_lowercase()), t);
        if *kind == TextureKind::Flat && *name == "SKY" {
            continue; // the wall entry already shows it
        }
        let (zoom, tiles, roll) = match (kind, *name) {
            (_, "SKY") => (1, 1, t.width / 2),
            (TextureKind::Sprite, _) => (3, 1, 0),
            (_, "DEBUG1") => (16, 2, 0),
            _ => (2, 2, 0),
        };
        let (w, h) = (t.width * zoom * tiles, t.height * zoom * tiles);
        if x + w + MARGIN > SHEET_WIDTH {
            (x, y, shelf) = (MARGIN, y + shelf + MARGIN, 0);
        }
        placed.push((t, x, y, zoom, tiles, roll));
        x += w + MARGIN;
        shelf = shelf.max(h);
    }
    let height = y + shelf + MARGIN;
    let mut sheet = Sheet { w: SHEET_WIDTH, h: height, rgb: vec![[32, 32, 40]; SHEET_WIDTH * height] };
    for (t, x, y, zoom, tiles, roll) in placed {
        sheet.draw(t, x, y, zoom, tiles, roll);
    }
    sheet.write(&out.join("sheet.png"));
}

/// The modelled figures' frames, for a person to look at: set
/// `SIGHTLINE_TEXTURE_PREVIEW=1` to get `/tmp/textures_preview/figures.png`
/// (a row per frame, its eight views across, at 3x on grey) and
/// `screens.png` (the weapons on the screen).
#[test]
fn figures_sheet() {
    if std::env::var_os("SIGHTLINE_TEXTURE_PREVIEW").is_none() {
        return; // a preview for people, not a check
    }
    let dir = Path::new("/tmp/textures_preview");
    std::fs::create_dir_all(dir).unwrap();
    let zoom = 3;
    let mut rows: Vec<Vec<Texture>> = Vec::new();
    let mut stem = String::new();
    for &name in super::procedural::figure_names() {
        let t = generate(name, TextureKind::Sprite).unwrap();
        // A row per frame seen from eight sides; frames seen alike from
        // every side share rows.
        if name[..4] != stem || name.ends_with('1') || rows.last().is_some_and(|r| r.len() == 10) {
            rows.push(Vec::new());
            stem = name[..4].to_string();
        }
        rows.last_mut().unwrap().push(t);
    }
    let row_w = |r: &[Texture]| r.iter().map(|t| t.width * zoom + MARGIN).sum::<usize>();
    let row_h = |r: &[Texture]| r.iter().map(|t| t.height * zoom + MARGIN).max().unwrap_or(0);
    let w = rows.iter().map(|r| row_w(r)).max().unwrap() + MARGIN;
    let h = rows.iter().map(|r| row_h(r)).sum::<usize>() + MARGIN;
    let mut sheet = Sheet { w, h, rgb: vec![[96, 100, 104]; w * h] };
    let mut y = MARGIN;
    for r in &rows {
        let mut x = MARGIN;
        for t in r {
            sheet.draw(t, x, y, zoom, 1, 0);
            x += t.width * zoom + MARGIN;
        }
        y += row_h(r);
    }
    sheet.write(&dir.join("figures.png"));
    let screens: Vec<Texture> =
        names(TextureKind::Screen).iter().map(|n| generate(n, TextureKind::Screen).unwrap()).collect();
    let (w, h) = (4 * (320 + MARGIN) + MARGIN, screens.len().div_ceil(4) * (200 + MARGIN) + MARGIN);
    let mut sheet = Sheet { w, h, rgb: vec![[60, 64, 70]; w * h] };
    for (k, t) in screens.iter().enumerate() {
        sheet.draw(t, MARGIN + (k % 4) * (320 + MARGIN), MARGIN + (k / 4) * (200 + MARGIN), 1, 1, 0);
    }
    sheet.write(&dir.join("screens.png"));
}
