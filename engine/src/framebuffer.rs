//! The software framebuffer every renderer writes into, and its PNG form.
//!
//! Pixels are `u32` holding RGBA bytes in memory order (R first), so the buffer
//! can be handed to a window surface or a PNG encoder without reshuffling.

use std::path::Path;

/// Packs an opaque colour.
#[inline]
pub const fn rgb(r: u8, g: u8, b: u8) -> u32 {
    u32::from_le_bytes([r, g, b, 255])
}

/// Splits a packed colour into `[r, g, b, a]`.
#[inline]
pub const fn channels(c: u32) -> [u8; 4] {
    c.to_le_bytes()
}

#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    pub width: usize,
    pub height: usize,
    /// Row-major, `width * height` pixels.
    pub pixels: Vec<u32>,
}

impl Framebuffer {
    pub fn new(width: usize, height: usize) -> Framebuffer {
        Framebuffer { width, height, pixels: vec![rgb(0, 0, 0); width * height] }
    }

    pub fn get(&self, x: usize, y: usize) -> u32 {
        self.pixels[y * self.width + x]
    }

    /// PNG bytes (8-bit RGB).
    pub fn to_png(&self) -> Vec<u8> {
        let mut out = Vec::new();
        let mut encoder = png::Encoder::new(&mut out, self.width as u32, self.height as u32);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let rgb_bytes: Vec<u8> = self
            .pixels
            .iter()
            .flat_map(|&p| {
                let [r, g, b, _] = channels(p);
                [r, g, b]
            })
            .collect();
        // Encoding into memory fails only on inconsistent sizes, which `new` rules out.
        if let Ok(mut writer) = encoder.write_header() {
            let _ = writer.write_image_data(&rgb_bytes);
        }
        out
    }

    /// Reads an 8-bit RGB or RGBA PNG.
    pub fn read_png(path: &Path) -> Result<Framebuffer, String> {
        let file = std::fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let decoder = png::Decoder::new(std::io::BufReader::new(file));
        let mut reader = decoder.read_info().map_err(|e| format!("{}: {e}", path.display()))?;
        let mut buf = vec![0; reader.output_buffer_size().ok_or("PNG too large")?];
        let info = reader.next_frame(&mut buf).map_err(|e| format!("{}: {e}", path.display()))?;
        let step = match (info.color_type, info.bit_depth) {
            (png::ColorType::Rgb, png::BitDepth::Eight) => 3,
            (png::ColorType::Rgba, png::BitDepth::Eight) => 4,
            other => return Err(format!("{}: unsupported PNG format {other:?}", path.display())),
        };
        let pixels = buf[..info.buffer_size()].chunks_exact(step).map(|c| rgb(c[0], c[1], c[2])).collect();
        Ok(Framebuffer { width: info.width as usize, height: info.height as usize, pixels })
    }
}
