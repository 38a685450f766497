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
    let packed = |bytes: usize, out: &mut [u8], f: &dyn Fn([u8; 3]) -> [u8; 4]| {
        for (o, &p) in out.chunks_exact_mut(bytes).zip(&fb.pixels) {
            o.copy_from_slice(&f(rgb_of(p))[..bytes]);
        }
    };
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
        ScreenFormat::Rgb24 => packed(3, out, &|[r, g, b]| [r, g, b, 0]),
        ScreenFormat::Bgr24 => packed(3, out, &|[r, g, b]| [b, g, r, 0]),
        ScreenFormat::Rgba32 => packed(4, out, &|[r, g, b]| [r, g, b, 255]),
        ScreenFormat::Argb32 => packed(4, out, &|[r, g, b]| [255, r, g, b]),
        ScreenFormat::Bgra32 => packed(4, out, &|[r, g, b]| [b, g, r, 255]),
        ScreenFormat::Abgr32 => packed(4, out, &|[r, g, b]| [255, b, g, r]),
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
        for n in [1, 3, 4, 7, 8, 13] {
            let mut fb = Framebuffer::new(n, 1);
            fb.pixels = (0..n as u8).map(|i| rgb(i, 100 + i, 200 + i) & 0x7fff_ffff).collect();
            let want: Vec<u8> = (0..n as u8).flat_map(|i| [i, 100 + i, 200 + i]).collect();
            let mut out = Vec::new();
            convert(&fb, ScreenFormat::Rgb24, &mut out).unwrap();
            assert_eq!(out, want, "{n} pixels");
        }
    }
}
