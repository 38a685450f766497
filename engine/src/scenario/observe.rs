//! What an agent sees of a scenario's game after each action, as ViZDoom's
//! state carries it: the screen drawn as the `.cfg`'s `render_*` switches
//! say (the weapon, the flashes, the HUD, a crosshair), in any of
//! ViZDoom's screen formats, and the automap buffer.
//!
//! The screen is the game's own frame (`render_frame` and `screen::draw`,
//! as the window and `replay` draw it), so what an agent learns from is
//! what a player sees.

use super::{AutomapMode, ScenarioConfig, ScreenFormat};
use crate::framebuffer::{channels, rgb, Framebuffer};
use crate::render::{render_frame, Frame, RenderOptions};
use crate::screen::automap::{Automap, Show};
use crate::screen::{self, Hud};
use crate::sim::game::SimGame;

/// Renders a game's frames at one size, keeping the renderer's scratch
/// space and the automap's memory of seen lines from frame to frame.
pub struct Observer {
    config: ScenarioConfig,
    options: RenderOptions,
    frame: Frame,
    screen: Framebuffer,
    automap: Option<(Automap, Framebuffer)>,
}

impl Observer {
    /// An observer of `config`'s screen size, drawing with `threads`
    /// threads (the frame is the same whatever the count).
    pub fn new(config: &ScenarioConfig, threads: usize) -> Observer {
        let (w, h) = (usize::from(config.screen_resolution.width), usize::from(config.screen_resolution.height));
        Observer {
            config: config.clone(),
            options: RenderOptions {
                threads,
                buffers: crate::render::Buffers {
                    depth: config.outputs.depth_buffer,
                    labels: config.outputs.labels_buffer,
                },
                ..RenderOptions::default()
            },
            frame: Frame::new(),
            screen: Framebuffer::new(w, h),
            automap: None,
        }
    }

    /// Forgets the lines the automap has seen (a new episode).
    pub fn reset(&mut self) {
        self.automap = None;
    }

    /// Draws `game`'s frame for its console player, and the automap if the
    /// `.cfg` asks for it.
    pub fn render(&mut self, game: &SimGame) {
        let level = game.level();
        let view = game.view(1.0);
        render_frame(level, &view, &self.options, &mut self.frame, &mut self.screen);
        let flags = self.config.render;
        let player = game.player();
        let table = &game.sim.info.table;
        if flags.screen_flashes {
            screen::tint::apply(&mut self.screen, player);
        }
        let hud = match (flags.hud, flags.minimal_hud) {
            (false, _) => Hud::Off,
            (true, false) => Hud::StatusBar,
            (true, true) => Hud::Minimal,
        };
        if flags.weapon {
            screen::weapon::draw(&mut self.screen, level, table, player, hud == Hud::StatusBar);
        }
        match hud {
            Hud::StatusBar => screen::status::status_bar(&mut self.screen, level, table, player),
            Hud::Minimal => screen::status::minimal(&mut self.screen, level, table, player),
            Hud::Off => {}
        }
        if flags.crosshair {
            crosshair(&mut self.screen);
        }
        if self.config.outputs.automap_buffer {
            let (w, h) = (self.screen.width, self.screen.height);
            let (map, fb) = self.automap.get_or_insert_with(|| (Automap::new(&level.map), Framebuffer::new(w, h)));
            map.accumulate(self.frame.seen_lines());
            let show = match self.config.automap.mode {
                AutomapMode::Normal => Show::Seen,
                AutomapMode::Whole => Show::Whole,
                AutomapMode::Objects | AutomapMode::ObjectsWithSize => Show::Things(&level.things),
            };
            map.draw_showing(&level.map, (view.pos.x, view.pos.y), view.angle, show, fb);
        }
    }

    /// The last screen drawn, RGBA.
    pub fn screen(&self) -> &Framebuffer {
        &self.screen
    }

    /// The last automap drawn, if the `.cfg` asks for one.
    pub fn automap(&self) -> Option<&Framebuffer> {
        self.automap.as_ref().map(|(_, fb)| fb)
    }

    /// The renderer's frame (its per-frame results: the depth and labels
    /// buffers when the `.cfg` turns them on, `Frame::depth`,
    /// `Frame::labels`).
    pub fn frame(&self) -> &Frame {
        &self.frame
    }
}

/// A small white cross at the screen's centre (ZDoom's default crosshair
/// is a few pixels each way).
fn crosshair(fb: &mut Framebuffer) {
    let (cx, cy) = (fb.width / 2, fb.height / 2);
    let arm = (fb.height / 100).max(2);
    let white = rgb(255, 255, 255);
    for d in 1..=arm {
        for (x, y) in [(cx + d, cy), (cx.wrapping_sub(d), cy), (cx, cy + d), (cx, cy.wrapping_sub(d))] {
            if x < fb.width && y < fb.height {
                fb.pixels[y * fb.width + x] = white;
            }
        }
    }
}

/// The array shape ViZDoom gives a buffer of `format` at `width` x
/// `height`: channels first for the planar formats, last for the packed
/// ones, none for the one-byte ones.
pub fn shape(format: ScreenFormat, width: usize, height: usize) -> Vec<usize> {
    match format {
        ScreenFormat::Crcgcb | ScreenFormat::Cbcgcr => vec![3, height, width],
        ScreenFormat::Rgb24 | ScreenFormat::Bgr24 => vec![height, width, 3],
        ScreenFormat::Rgba32 | ScreenFormat::Argb32 | ScreenFormat::Bgra32 | ScreenFormat::Abgr32 => {
            vec![height, width, 4]
        }
        ScreenFormat::Gray8 | ScreenFormat::Doom256Colors8 => vec![height, width],
    }
}

/// Why a screen cannot be given in a format.
#[derive(Debug, thiserror::Error)]
pub enum FormatError {
    #[error(
        "screen format DOOM_256_COLORS8 is not supported: Sightline draws true colour, not palette indices; use RGB24, GRAY8 or another"
    )]
    PaletteIndices,
}

/// `fb`'s pixels in `format`, into `out` (resized to fit). GRAY8 is the
/// luma of ITU-R BT.601 (0.299 R + 0.587 G + 0.114 B), rounded; the alpha
/// byte of the 32-bit formats is 255.
pub fn convert(fb: &Framebuffer, format: ScreenFormat, out: &mut Vec<u8>) -> Result<(), FormatError> {
    out.clear();
    if let Some(order) = Packed3::of(format) {
        // Appended a block at a time from a small buffer on the stack, so
        // the screen is written once, not zeroed first and then written
        // (the zeroing was a third of the conversion's instructions).
        const BLOCK: usize = 256;
        out.reserve_exact(3 * fb.pixels.len());
        let mut buf = [0u8; 3 * BLOCK];
        for block in fb.pixels.chunks(BLOCK) {
            let bytes = &mut buf[..3 * block.len()];
            pack3(block, bytes, order);
            out.extend_from_slice(bytes);
        }
        return Ok(());
    }
    out.resize(shape(format, fb.width, fb.height).iter().product(), 0);
    convert_into(fb, format, out)
}

/// [`convert`] into a slice of exactly the format's size (one game's part
/// of a batch of screens).
pub fn convert_into(fb: &Framebuffer, format: ScreenFormat, out: &mut [u8]) -> Result<(), FormatError> {
    let n = fb.pixels.len();
    debug_assert_eq!(out.len(), shape(format, fb.width, fb.height).iter().product::<usize>());
    let rgb_of = |p: u32| {
        let [r, g, b, _] = channels(p);
        [r, g, b]
    };
    let packed4 = |out: &mut [u8], f: fn([u8; 3]) -> [u8; 4]| {
        for (o, &p) in out.chunks_exact_mut(4).zip(&fb.pixels) {
            o.copy_from_slice(&f(rgb_of(p)));
        }
    };
    if let Some(order) = Packed3::of(format) {
        pack3(&fb.pixels, out, order);
        return Ok(());
    }
    match format {
        ScreenFormat::Crcgcb | ScreenFormat::Cbcgcr => {
            let order = if format == ScreenFormat::Crcgcb { [0, 1, 2] } else { [2, 1, 0] };
            let (a, rest) = out.split_at_mut(n);
            let (b, c) = rest.split_at_mut(n);
            for (i, &p) in fb.pixels.iter().enumerate() {
                let rgb = rgb_of(p);
                a[i] = rgb[order[0]];
                b[i] = rgb[order[1]];
                c[i] = rgb[order[2]];
            }
        }
        ScreenFormat::Rgb24 | ScreenFormat::Bgr24 => unreachable!("packed above"),
        ScreenFormat::Rgba32 => packed4(out, |[r, g, b]| [r, g, b, 255]),
        ScreenFormat::Argb32 => packed4(out, |[r, g, b]| [255, r, g, b]),
        ScreenFormat::Bgra32 => packed4(out, |[r, g, b]| [b, g, r, 255]),
        ScreenFormat::Abgr32 => packed4(out, |[r, g, b]| [255, b, g, r]),
        ScreenFormat::Gray8 => {
            for (o, &p) in out.iter_mut().zip(&fb.pixels) {
                let [r, g, b] = rgb_of(p).map(u32::from);
                *o = ((299 * r + 587 * g + 114 * b + 500) / 1000) as u8;
            }
        }
        ScreenFormat::Doom256Colors8 => return Err(FormatError::PaletteIndices),
    }
    Ok(())
}

/// The three-byte formats' channel order.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Packed3 {
    Rgb,
    Bgr,
}

impl Packed3 {
    fn of(format: ScreenFormat) -> Option<Packed3> {
        match format {
            ScreenFormat::Rgb24 => Some(Packed3::Rgb),
            ScreenFormat::Bgr24 => Some(Packed3::Bgr),
            _ => None,
        }
    }
}

/// `pixels` as three bytes each, in `order`, into `out` (three times as
/// long). With SSSE3 sixteen pixels at a time become 48 bytes in four byte
/// shuffles ([`shuffled`]); the rest one at a time. RGB24 at 160x120 took
/// eight instructions a pixel through a closure per pixel.
#[multiversion::multiversion(targets("x86_64+ssse3"))]
fn pack3(pixels: &[u32], out: &mut [u8], order: Packed3) {
    debug_assert_eq!(out.len(), 3 * pixels.len());
    let done = multiversion::target::match_target! {
        "x86_64+ssse3" => shuffled::sixteens(pixels, out, order == Packed3::Bgr),
        _ => 0,
    };
    for (o, &p) in out[3 * done..].chunks_exact_mut(3).zip(&pixels[done..]) {
        let [r, g, b, _] = channels(p);
        o.copy_from_slice(&if order == Packed3::Rgb { [r, g, b] } else { [b, g, r] });
    }
}

#[cfg(target_arch = "x86_64")]
mod shuffled {
    use std::arch::x86_64::{__m128i, _mm_or_si128, _mm_setr_epi8, _mm_shuffle_epi8, _mm_slli_si128, _mm_srli_si128};

    /// [`super::pack3`]'s pixels sixteen at a time: each four pixels'
    /// twelve colour bytes gathered to the bottom of a register by one
    /// shuffle (the alpha bytes dropped), then the four registers' bytes
    /// shifted together into three 16-byte stores. Returns the pixels done
    /// (a multiple of sixteen).
    #[target_feature(enable = "ssse3")]
    pub(super) fn sixteens(pixels: &[u32], out: &mut [u8], bgr: bool) -> usize {
        // -1 zeroes a byte: the top four of each register.
        let mask = if bgr {
            _mm_setr_epi8(2, 1, 0, 6, 5, 4, 10, 9, 8, 14, 13, 12, -1, -1, -1, -1)
        } else {
            _mm_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1)
        };
        let (groups, _) = pixels.as_chunks::<16>();
        let (pieces, _) = out.as_chunks_mut::<48>();
        for (group, piece) in groups.iter().zip(pieces.iter_mut()) {
            let four = |k: usize| {
                let p: [u32; 4] = [group[4 * k], group[4 * k + 1], group[4 * k + 2], group[4 * k + 3]];
                _mm_shuffle_epi8(bytemuck::cast::<[u32; 4], __m128i>(p), mask)
            };
            let (a, b, c, d) = (four(0), four(1), four(2), four(3));
            let lines: [__m128i; 3] = [
                _mm_or_si128(a, _mm_slli_si128::<12>(b)),
                _mm_or_si128(_mm_srli_si128::<4>(b), _mm_slli_si128::<8>(c)),
                _mm_or_si128(_mm_srli_si128::<8>(c), _mm_slli_si128::<4>(d)),
            ];
            *piece = bytemuck::cast::<[__m128i; 3], [u8; 48]>(lines);
        }
        groups.len().min(pieces.len()) * 16
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_lay_out_channels_as_vizdoom_does() {
        let mut fb = Framebuffer::new(2, 1);
        fb.pixels = vec![rgb(10, 20, 30), rgb(40, 50, 60)];
        let mut out = Vec::new();
        let cases: [(ScreenFormat, &[u8]); 9] = [
            (ScreenFormat::Crcgcb, &[10, 40, 20, 50, 30, 60]),
            (ScreenFormat::Cbcgcr, &[30, 60, 20, 50, 10, 40]),
            (ScreenFormat::Rgb24, &[10, 20, 30, 40, 50, 60]),
            (ScreenFormat::Bgr24, &[30, 20, 10, 60, 50, 40]),
            (ScreenFormat::Rgba32, &[10, 20, 30, 255, 40, 50, 60, 255]),
            (ScreenFormat::Argb32, &[255, 10, 20, 30, 255, 40, 50, 60]),
            (ScreenFormat::Bgra32, &[30, 20, 10, 255, 60, 50, 40, 255]),
            (ScreenFormat::Abgr32, &[255, 30, 20, 10, 255, 60, 50, 40]),
            (ScreenFormat::Gray8, &[18, 48]),
        ];
        for (format, want) in cases {
            convert(&fb, format, &mut out).unwrap();
            assert_eq!(out, want, "{format:?}");
            assert_eq!(shape(format, 2, 1).iter().product::<usize>(), want.len(), "{format:?}");
        }
        assert!(convert(&fb, ScreenFormat::Doom256Colors8, &mut out).is_err());
    }

    #[test]
    fn rgb24_packs_every_pixel() {
        // Lengths either side of the sixteen-pixel groups and of the
        // conversion's 256-pixel blocks, both orders, into a Vec and a slice.
        for n in [1, 3, 4, 7, 8, 13, 15, 16, 17, 31, 32, 33, 255, 256, 257, 600] {
            let mut fb = Framebuffer::new(n, 1);
            fb.pixels = (0..n as u32).map(|i| i.wrapping_mul(0x9E37_79B9)).collect();
            for (format, order) in [(ScreenFormat::Rgb24, [0, 1, 2]), (ScreenFormat::Bgr24, [2, 1, 0])] {
                let want: Vec<u8> = fb.pixels.iter().flat_map(|&p| order.map(|c| p.to_le_bytes()[c])).collect();
                let mut out = vec![7; 5];
                convert(&fb, format, &mut out).unwrap();
                assert_eq!(out, want, "{format:?}, {n} pixels");
                let mut slice = vec![7; 3 * n];
                convert_into(&fb, format, &mut slice).unwrap();
                assert_eq!(slice, want, "{format:?} into a slice, {n} pixels");
            }
        }
    }
}
