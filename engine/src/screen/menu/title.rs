//! Our own title picture, drawn from nothing (no WAD art): a night sky
//! reddening to the horizon, a ridge of towers against it, a floor whose
//! lines of sight run to one vanishing point, and the name in steel
//! lettering. A WAD's game shows its TITLEPIC instead (the game's side).

use font8x8::{UnicodeFonts, BASIC_FONTS};

use super::draw::{mix, text};
use crate::framebuffer::{rgb, Framebuffer};
use crate::screen::scale;
use crate::screen::text::fill_rect;

/// The horizon, in 320x200 units from the top.
const HORIZON: f64 = 128.0;

/// Draws the title picture over the whole of `fb`: the backdrop, the
/// name and the line under it.
pub fn draw(fb: &mut Framebuffer) {
    backdrop(fb);
    let (s, _) = scale(fb);
    let top = ((fb.height as f64 - 200.0 * s) / 2.0).max(0.0);
    logo(fb, 30.0);
    let k = ((8.0 * s / 8.0).round() as usize).max(1);
    let line = "A DOOM-STYLE ENGINE";
    let w = line.len() * 8 * k;
    let y = (top + 82.0 * s).round() as usize;
    text(fb, fb.width.saturating_sub(w) / 2, y, k, line, (rgb(230, 200, 170), rgb(170, 120, 90)));
}

/// The picture without lettering (the menu writes over it).
pub fn backdrop(fb: &mut Framebuffer) {
    let (s, margin) = scale(fb);
    let top = ((fb.height as f64 - 200.0 * s) / 2.0).max(0.0);
    let horizon = top + HORIZON * s;
    let vanish_x = fb.width as f64 / 2.0;
    for y in 0..fb.height {
        let yf = y as f64 + 0.5;
        for x in 0..fb.width {
            let xf = x as f64 + 0.5;
            let c =
                if yf < horizon { sky(xf, yf, vanish_x, horizon, s) } else { floor(xf - vanish_x, yf - horizon, s) };
            fb.pixels[y * fb.width + x] = c;
        }
    }
    ridge(fb, horizon, s, margin);
}

/// The sky: near black above, deep red at the horizon, a glow where the
/// lines meet, and a few fixed stars.
fn sky(x: f64, y: f64, vx: f64, horizon: f64, s: f64) -> u32 {
    let t = (y / horizon).clamp(0.0, 1.0).powf(2.2);
    let base = mix(rgb(6, 4, 10), rgb(120, 24, 10), t);
    let d = ((x - vx) / s).hypot((y - horizon) / s * 2.4);
    let glow = (1.0 - d / 140.0).max(0.0).powi(2);
    let c = mix(base, rgb(255, 150, 60), glow * 0.7);
    let (cx, cy) = ((x / s) as u64, (y / s) as u64);
    if t < 0.5 && hash(cx, cy) % 509 == 0 {
        return mix(c, rgb(255, 240, 220), 0.8 - t);
    }
    c
}

/// The floor: dark stone; lines towards the vanishing point and rows that
/// close up with distance, fading into the haze at the horizon.
fn floor(dx: f64, dy: f64, s: f64) -> u32 {
    let dy = dy.max(0.5);
    // Depth of the row (a floor 1 unit under the eye, focal length 160).
    let z = 40.0 * s / dy;
    let across = dx / dy * 40.0;
    let haze = (1.0 / (1.0 + dy / s / 10.0)).clamp(0.0, 1.0);
    let row = (z * 2.0).rem_euclid(1.0);
    let col = (across / 16.0).rem_euclid(1.0);
    let width_row = (0.05 * z).clamp(0.04, 0.5);
    let width_col = 0.045 * (1.0 + 1.0 / (dy / s + 1.0) * 4.0);
    let line = row < width_row || col < width_col || col > 1.0 - width_col;
    let stone = mix(rgb(26, 14, 10), rgb(10, 6, 6), (dy / s / 72.0).min(1.0));
    let c = if line { mix(rgb(220, 70, 20), rgb(90, 20, 10), (dy / s / 72.0).min(1.0)) } else { stone };
    mix(c, rgb(120, 30, 14), haze * 0.8)
}

/// Towers along the horizon, their heights from a hash of their place.
fn ridge(fb: &mut Framebuffer, horizon: f64, s: f64, margin: f64) {
    let unit = |u: f64| (u * s).round().max(1.0) as usize;
    let mut u = -margin / s;
    while u < (fb.width as f64 - margin) / s {
        let h = hash(u.to_bits() >> 40, 7);
        let w = 6.0 + (h % 14) as f64;
        let tall = 3.0 + (h / 16 % 19) as f64 * if (h / 1000) % 5 == 0 { 1.6 } else { 0.7 };
        let x = (margin + u * s).max(0.0) as usize;
        let y = (horizon - tall * s).max(0.0) as usize;
        fill_rect(fb, x, y, unit(w), (horizon as usize).saturating_sub(y), rgb(14, 6, 8));
        // A lit window now and then.
        if h % 3 == 0 {
            fill_rect(fb, x + unit(w / 2.0), y + unit(tall / 3.0), unit(1.0), unit(1.0), rgb(255, 170, 70));
        }
        u += w;
    }
}

/// The name in steel letters, `v` units from the top: each font pixel a
/// bevelled block, light above and dark below, outlined in red.
pub fn logo(fb: &mut Framebuffer, v: f64) {
    let (s, _) = scale(fb);
    let top = ((fb.height as f64 - 200.0 * s) / 2.0).max(0.0);
    let name = "SIGHTLINE";
    // Font pixels of 3.5 units: 9 letters of 8 are 252 units wide.
    let k = ((3.5 * s).round() as usize).max(2);
    let width = name.len() * 8 * k;
    let x0 = fb.width.saturating_sub(width) / 2;
    let y0 = (top + v * s).round() as usize;
    let pixel = |c: char, col: usize, row: usize| {
        let glyph = BASIC_FONTS.get(c).unwrap_or([0; 8]);
        col < 8 && row < 8 && glyph[row] >> col & 1 == 1
    };
    let edge = (k / 3).max(1);
    for pass in 0..3 {
        for (i, c) in name.chars().enumerate() {
            for row in 0..8 {
                for col in 0..8 {
                    if !pixel(c, col, row) {
                        continue;
                    }
                    let x = x0 + (i * 8 + col) * k;
                    let y = y0 + row * k;
                    match pass {
                        // A shadow, then a red outline round every block.
                        0 => fill_rect(fb, x + k / 2, y + k, k, k, rgb(0, 0, 0)),
                        1 => fill_rect(
                            fb,
                            x.saturating_sub(edge),
                            y.saturating_sub(edge),
                            k + 2 * edge,
                            k + 2 * edge,
                            rgb(150, 16, 0),
                        ),
                        _ => {
                            let t = (row as f64 + 0.5) / 8.0;
                            let face = mix(rgb(236, 232, 226), rgb(92, 88, 96), t);
                            fill_rect(fb, x, y, k, k, face);
                            // Bevel: a light top edge where the block above is empty.
                            if row == 0 || !pixel(c, col, row - 1) {
                                fill_rect(fb, x, y, k, edge, rgb(255, 255, 250));
                            }
                            if row == 7 || !pixel(c, col, row + 1) {
                                fill_rect(fb, x, y + k - edge, k, edge, rgb(50, 46, 54));
                            }
                        }
                    }
                }
            }
        }
    }
}

fn hash(a: u64, b: u64) -> u64 {
    let mut h = a.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ b.wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
    h ^= h >> 29;
    h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^ (h >> 32)
}
