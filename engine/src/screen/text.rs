//! 8x8 text (font8x8's public-domain glyphs) and filled boxes, for the
//! status bar and the window's HUD.

use font8x8::{UnicodeFonts, BASIC_FONTS};

use crate::framebuffer::{rgb, Framebuffer};

/// Glyph cell in font pixels.
pub const GLYPH: usize = 8;

/// Draws `text` with its top-left corner at (`x`, `y`), each font pixel
/// `scale` screen pixels, in `colour` over a one-pixel dark shadow so it
/// reads on any background. Characters outside ASCII draw as `?`; whatever
/// falls off the frame is clipped.
pub fn draw_text_in(fb: &mut Framebuffer, x: usize, y: usize, scale: usize, text: &str, colour: u32) {
    for (i, c) in text.chars().enumerate() {
        let glyph = BASIC_FONTS.get(c).or_else(|| BASIC_FONTS.get('?')).unwrap_or([0; 8]);
        let gx = x + i * GLYPH * scale;
        draw_glyph(fb, gx + scale, y + scale, scale, &glyph, rgb(0, 0, 0));
        draw_glyph(fb, gx, y, scale, &glyph, colour);
    }
}

/// [`draw_text_in`] in white.
pub fn draw_text(fb: &mut Framebuffer, x: usize, y: usize, scale: usize, text: &str) {
    draw_text_in(fb, x, y, scale, text, rgb(255, 255, 255));
}

fn draw_glyph(fb: &mut Framebuffer, x: usize, y: usize, scale: usize, glyph: &[u8; 8], colour: u32) {
    for (row, bits) in glyph.iter().enumerate() {
        for col in 0..GLYPH {
            // font8x8 stores each row with bit 0 as the leftmost pixel.
            if bits >> col & 1 == 0 {
                continue;
            }
            fill_rect(fb, x + col * scale, y + row * scale, scale, scale, colour);
        }
    }
}

/// Fills the part of the rectangle that lies on the frame.
pub fn fill_rect(fb: &mut Framebuffer, x: usize, y: usize, w: usize, h: usize, colour: u32) {
    let x1 = x.saturating_add(w).min(fb.width);
    let y1 = y.saturating_add(h).min(fb.height);
    for yy in y.min(y1)..y1 {
        let row = yy * fb.width;
        fb.pixels[row + x.min(x1)..row + x1].fill(colour);
    }
}
