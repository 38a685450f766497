//! PNG files to [`Texture`]s: any colour type and bit depth in, 8-bit RGBA
//! column-major texels out, and every malformed file an error value.

use std::io::{BufRead, Seek};
use std::path::Path;

use super::{Texture, TextureError};

/// The largest side a texture may have. Doom's largest patches are 256 wide;
/// 4096 leaves room for panoramic skies while bounding one texture at 64 MiB
/// of texels, checked from the header before anything is allocated.
pub const MAX_SIDE: u32 = 4096;

pub(super) fn read_png(path: &Path) -> Result<Texture, TextureError> {
    let file = std::fs::File::open(path).map_err(|e| png_error(path, e))?;
    decode_png(std::io::BufReader::new(file), path)
}

pub(super) fn decode_png(input: impl BufRead + Seek, path: &Path) -> Result<Texture, TextureError> {
    let mut decoder = ::png::Decoder::new(input);
    // EXPAND turns palette into RGB(A) (tRNS becomes alpha), grey below 8 bits
    // into 8-bit grey (scaled to the full range) and a tRNS colour key into an
    // alpha channel; STRIP_16 keeps the high byte of 16-bit samples. What is
    // left is one of four 8-bit layouts, converted below.
    decoder.set_transformations(::png::Transformations::normalize_to_color8());
    let (width, height) = {
        let info = decoder.read_header_info().map_err(|e| png_error(path, e))?;
        (info.width, info.height)
    };
    if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
        return Err(TextureError::Size { path: path.to_path_buf(), width, height });
    }
    let mut reader = decoder.read_info().map_err(|e| png_error(path, e))?;
    let size = reader.output_buffer_size().ok_or_else(|| png_error(path, "image too large for memory"))?;
    let mut buf = vec![0u8; size];
    let frame = reader.next_frame(&mut buf).map_err(|e| png_error(path, e))?;
    if frame.bit_depth != ::png::BitDepth::Eight {
        return Err(png_error(path, format!("unexpected {:?} output", frame.bit_depth)));
    }
    let samples = frame.color_type.samples();
    if !(1..=4).contains(&samples) {
        return Err(png_error(path, format!("{samples} samples per pixel")));
    }
    let (w, h) = (frame.width as usize, frame.height as usize);
    let rows = &buf[..frame.buffer_size()];
    if frame.line_size < w * samples || rows.len() < h * frame.line_size {
        return Err(png_error(path, "decoder returned a short frame"));
    }

    // Transpose while converting: read rows, write columns.
    let mut texels = vec![0u32; w * h];
    for (v, row) in rows.chunks_exact(frame.line_size).take(h).enumerate() {
        for (u, px) in row[..w * samples].chunks_exact(samples).enumerate() {
            let rgba = match *px {
                [g] => [g, g, g, 255],
                [g, a] => [g, g, g, a],
                [r, g, b] => [r, g, b, 255],
                [r, g, b, a] => [r, g, b, a],
                // Checked above: 1 to 4 samples per pixel.
                _ => [0, 0, 0, 0],
            };
            texels[u * h + v] = u32::from_le_bytes(rgba);
        }
    }
    Ok(Texture::from_texels(w, h, texels))
}

fn png_error(path: &Path, message: impl ToString) -> TextureError {
    TextureError::Png { path: path.to_path_buf(), message: message.to_string() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ::png::{BitDepth, ColorType};

    /// Encodes an image with the png crate, exactly as a paint program might.
    fn encode(
        width: u32,
        height: u32,
        color: ColorType,
        depth: BitDepth,
        data: &[u8],
        palette: Option<(&[u8], Option<&[u8]>)>,
    ) -> Vec<u8> {
        let mut out = Vec::new();
        let mut encoder = ::png::Encoder::new(&mut out, width, height);
        encoder.set_color(color);
        encoder.set_depth(depth);
        if let Some((plte, trns)) = palette {
            encoder.set_palette(plte.to_vec());
            if let Some(trns) = trns {
                encoder.set_trns(trns.to_vec());
            }
        }
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(data).unwrap();
        writer.finish().unwrap();
        out
    }

    fn decode(bytes: &[u8]) -> Result<Texture, TextureError> {
        Texture::decode_png(bytes, Path::new("test.png"))
    }

    fn rgba(t: &Texture, u: usize, v: usize) -> [u8; 4] {
        t.texel(u, v).to_le_bytes()
    }

    #[test]
    fn rgb_is_transposed_to_columns() {
        // 3x2, row-major: distinct colour per pixel.
        let data: Vec<u8> = (0..6).flat_map(|i| [i * 10, i * 10 + 1, i * 10 + 2]).collect();
        let t = decode(&encode(3, 2, ColorType::Rgb, BitDepth::Eight, &data, None)).unwrap();
        assert_eq!((t.width, t.height), (3, 2));
        assert!(t.opaque);
        assert_eq!(rgba(&t, 0, 0), [0, 1, 2, 255]);
        assert_eq!(rgba(&t, 2, 0), [20, 21, 22, 255]);
        assert_eq!(rgba(&t, 0, 1), [30, 31, 32, 255]);
        assert_eq!(rgba(&t, 2, 1), [50, 51, 52, 255]);
        assert_eq!(t.column(1), &[t.texel(1, 0), t.texel(1, 1)]);
    }

    #[test]
    fn rgba_keeps_alpha() {
        let data = [255, 0, 0, 255, 0, 255, 0, 0];
        let t = decode(&encode(2, 1, ColorType::Rgba, BitDepth::Eight, &data, None)).unwrap();
        assert_eq!(rgba(&t, 0, 0), [255, 0, 0, 255]);
        assert_eq!(rgba(&t, 1, 0)[3], 0);
        assert!(!t.opaque);
    }

    #[test]
    fn palette_with_trns_gives_transparency() {
        let plte = [10, 20, 30, 200, 100, 50];
        let trns = [0];
        // 2-bit indices, 3 pixels: 0, 1, 1 packed MSB first.
        let data = [0b00_01_01_00];
        let png = encode(3, 1, ColorType::Indexed, BitDepth::Two, &data, Some((&plte, Some(&trns))));
        let t = decode(&png).unwrap();
        assert_eq!(rgba(&t, 0, 0), [10, 20, 30, 0]);
        assert_eq!(rgba(&t, 1, 0), [200, 100, 50, 255]);
        assert_eq!(rgba(&t, 2, 0), [200, 100, 50, 255]);
        assert!(!t.opaque);

        let png = encode(3, 1, ColorType::Indexed, BitDepth::Two, &data, Some((&plte, None)));
        let t = decode(&png).unwrap();
        assert_eq!(rgba(&t, 0, 0), [10, 20, 30, 255]);
        assert!(t.opaque);
    }

    #[test]
    fn grey_low_depth_and_grey_alpha_expand() {
        let t = decode(&encode(2, 1, ColorType::Grayscale, BitDepth::Eight, &[7, 200], None)).unwrap();
        assert_eq!(rgba(&t, 1, 0), [200, 200, 200, 255]);
        // 1-bit grey scales to the full range: 1 -> 255.
        let t = decode(&encode(8, 1, ColorType::Grayscale, BitDepth::One, &[0b1000_0001], None)).unwrap();
        assert_eq!(rgba(&t, 0, 0), [255, 255, 255, 255]);
        assert_eq!(rgba(&t, 1, 0), [0, 0, 0, 255]);
        assert_eq!(rgba(&t, 7, 0), [255, 255, 255, 255]);
        let t = decode(&encode(1, 1, ColorType::GrayscaleAlpha, BitDepth::Eight, &[90, 0], None)).unwrap();
        assert_eq!(rgba(&t, 0, 0), [90, 90, 90, 0]);
    }

    #[test]
    fn sixteen_bit_keeps_the_high_byte() {
        // Big-endian samples: 0x1234 -> 0x12.
        let data = [0x12, 0x34, 0xab, 0xcd, 0xff, 0x00, 0x80, 0x00];
        let t = decode(&encode(1, 1, ColorType::Rgba, BitDepth::Sixteen, &data, None)).unwrap();
        assert_eq!(rgba(&t, 0, 0), [0x12, 0xab, 0xff, 0x80]);
        let t = decode(&encode(1, 1, ColorType::Grayscale, BitDepth::Sixteen, &[0xee, 0x01], None)).unwrap();
        assert_eq!(rgba(&t, 0, 0), [0xee, 0xee, 0xee, 255]);
    }

    /// A PNG from raw chunks, to state headers the encoder refuses to write.
    fn raw_png(width: u32, height: u32) -> Vec<u8> {
        let mut out = b"\x89PNG\r\n\x1a\n".to_vec();
        let mut ihdr = Vec::new();
        ihdr.extend(width.to_be_bytes());
        ihdr.extend(height.to_be_bytes());
        ihdr.extend([8, 6, 0, 0, 0]); // 8-bit RGBA, deflate, no filter, no interlace
        for (kind, data) in [(&b"IHDR"[..], &ihdr[..]), (b"IEND", &[])] {
            out.extend((data.len() as u32).to_be_bytes());
            let mut crc = crc32fast::Hasher::new();
            crc.update(kind);
            crc.update(data);
            out.extend(kind);
            out.extend(data);
            out.extend(crc.finalize().to_be_bytes());
        }
        out
    }

    #[test]
    fn absurd_dimensions_are_errors_not_allocations() {
        for (w, h) in [(MAX_SIDE + 1, 1), (1, 100_000), (0x7fff_ffff, 0x7fff_ffff)] {
            match decode(&raw_png(w, h)) {
                Err(TextureError::Size { width, height, path }) => {
                    assert_eq!((width, height), (w, h));
                    assert_eq!(path, Path::new("test.png"));
                }
                other => panic!("{w}x{h}: {other:?}"),
            }
        }
        // The PNG format itself forbids a zero side; either error will do, as
        // long as it names the file.
        for (w, h) in [(0, 5), (5, 0)] {
            let err = decode(&raw_png(w, h)).unwrap_err();
            assert!(matches!(err, TextureError::Png { .. } | TextureError::Size { .. }), "{err:?}");
            assert!(err.to_string().starts_with("test.png: "), "{err}");
        }
    }

    #[test]
    fn malformed_files_are_errors() {
        let good = encode(4, 4, ColorType::Rgb, BitDepth::Eight, &[77; 48], None);
        let mut bad_crc = good.clone();
        // The last byte of the IDAT chunk's CRC (IEND is the final 12 bytes).
        let last = bad_crc.len() - 13;
        bad_crc[last] ^= 0xff;
        let cases: Vec<(&str, Vec<u8>)> = vec![
            ("empty", vec![]),
            ("not a png", b"GIF89a this is not a PNG at all".to_vec()),
            ("signature only", good[..8].to_vec()),
            ("truncated header", good[..20].to_vec()),
            ("truncated data", good[..good.len() - 16].to_vec()),
            ("header without data", raw_png(4, 4)),
            ("bad checksum", bad_crc),
        ];
        for (what, bytes) in cases {
            match decode(&bytes) {
                Err(TextureError::Png { path, message }) => {
                    assert_eq!(path, Path::new("test.png"), "{what}");
                    assert!(!message.is_empty(), "{what}");
                }
                other => panic!("{what}: {other:?}"),
            }
        }
        assert!(decode(&good).is_ok());
    }

    #[test]
    fn every_prefix_of_a_file_fails_cleanly() {
        // Truncation at any byte must be an error value, never a panic.
        let data: Vec<u8> = (0..5 * 3 * 4).map(|i| i as u8).collect();
        let good = encode(5, 3, ColorType::Rgba, BitDepth::Eight, &data, None);
        // Cutting only the IEND chunk leaves every pixel intact; that may load.
        for n in 0..good.len() - 12 {
            assert!(decode(&good[..n]).is_err(), "prefix of {n} bytes decoded");
        }
    }
}
