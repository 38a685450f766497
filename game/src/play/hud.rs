//! The heads-up display, drawn over the finished frame just before it is
//! uploaded, in 8x8 text: frame time and fps, the map and renderer, the
//! player's health and keys, the game's messages; and between levels the
//! intermission's tallies (also drawn on `sightline replay`'s captures).

use std::time::Duration;

use font8x8::{UnicodeFonts, BASIC_FONTS};
use sightline::actors::KeyForm;
use sightline::framebuffer::rgb;
use sightline::map::special::KeyColour;
use sightline::play::playthrough::Phase;
use sightline::play::{Player, TICRATE};
use sightline::Framebuffer;

/// How long a message stays on screen (Doom's MESSAGETICS, 4 s).
const MESSAGE_TIME: Duration = Duration::from_secs(4);
/// At most this many messages show at once, newest last.
const MESSAGES_SHOWN: usize = 3;

/// Frame time shown as an average over this long, so the figures can be read
/// rather than flicker with every frame.
const SMOOTHING_WINDOW: Duration = Duration::from_millis(500);

/// Glyph cell in font pixels; the font is 8x8 (font8x8's public-domain set).
const GLYPH: usize = 8;

pub struct Hud {
    pub visible: bool,
    window_time: Duration,
    window_frames: u32,
    window_render: Duration,
    /// The figures last shown: ms per frame, frames per second, render ms.
    shown: Option<(f64, f64, f64)>,
    /// Messages and how long each has shown.
    messages: Vec<(String, Duration)>,
}

impl Hud {
    pub fn new(visible: bool) -> Hud {
        Hud {
            visible,
            window_time: Duration::ZERO,
            window_frames: 0,
            window_render: Duration::ZERO,
            shown: None,
            messages: Vec::new(),
        }
    }

    /// Counts one frame: `interval` since the previous one, `render` of it
    /// spent in the renderer.
    pub fn frame(&mut self, interval: Duration, render: Duration) {
        for m in &mut self.messages {
            m.1 += interval;
        }
        self.messages.retain(|m| m.1 < MESSAGE_TIME);
        self.window_time += interval;
        self.window_render += render;
        self.window_frames += 1;
        if self.window_time >= SMOOTHING_WINDOW {
            let frames = f64::from(self.window_frames);
            let secs = self.window_time.as_secs_f64();
            self.shown =
                Some((secs * 1000.0 / frames, frames / secs, self.window_render.as_secs_f64() * 1000.0 / frames));
            self.window_time = Duration::ZERO;
            self.window_render = Duration::ZERO;
            self.window_frames = 0;
        }
    }

    /// Shows `text` for a few seconds.
    pub fn message(&mut self, text: String) {
        self.messages.push((text, Duration::ZERO));
        if self.messages.len() > MESSAGES_SHOWN {
            self.messages.remove(0);
        }
    }

    /// The player's health and keys at the bottom left, the game's messages
    /// under the figures.
    pub fn draw_status(&self, fb: &mut Framebuffer, player: &Player) {
        if !self.visible {
            return;
        }
        let scale = text_scale(fb);
        let line = (GLYPH + 2) * scale;
        let mut y = scale * 4 + 2 * line;
        for (text, _) in &self.messages {
            draw_text(fb, scale * 4, y, scale, text);
            y += line;
        }
        let bottom = fb.height.saturating_sub(line + scale * 4);
        let health =
            if player.dead() { "DEAD: press use to restart".to_string() } else { format!("HEALTH {}", player.health) };
        draw_text(fb, scale * 4, bottom, scale, &health);
        // Keys: a coloured box each, a card square, a skull with a dot.
        let mut x = fb.width.saturating_sub(scale * 4);
        for key in player.keys.iter().rev() {
            let size = GLYPH * scale;
            x = x.saturating_sub(size + 2 * scale);
            let colour = match key.colour {
                KeyColour::Blue => rgb(40, 80, 255),
                KeyColour::Yellow => rgb(250, 220, 40),
                KeyColour::Red => rgb(230, 30, 30),
            };
            fill_rect(fb, x, bottom, size, size, colour);
            if key.form == KeyForm::Skull {
                fill_rect(fb, x + size / 4, bottom + size / 4, size / 2, size / 2, rgb(240, 240, 230));
            }
        }
    }

    pub fn draw(&self, fb: &mut Framebuffer, map_name: &str, renderer: &str) {
        if !self.visible {
            return;
        }
        let timing = match self.shown {
            Some((ms, fps, render)) => format!("{ms:.1} ms  {fps:.0} fps  render {render:.2} ms"),
            None => "-- ms  -- fps".to_string(),
        };
        let lines = [timing, format!("{map_name}  [{renderer}]")];
        let scale = text_scale(fb);
        let mut y = scale * 4;
        for line in &lines {
            draw_text(fb, scale * 4, y, scale, line);
            y += (GLYPH + 2) * scale;
        }
    }
}

/// Between levels: the frame dimmed, and the level's tallies over it (Doom's
/// intermission: kills, items, secrets, time); at the end of a campaign, its
/// last tallies. Nothing while playing.
pub fn draw_phase(fb: &mut Framebuffer, phase: &Phase) {
    let (title, stats, next) = match phase {
        Phase::Playing => return,
        Phase::Intermission { map, stats, next, .. } => {
            let next = match next {
                Some(m) => format!("Entering {}", m.short_name()),
                None => "The end of the campaign".to_string(),
            };
            (format!("{map} finished"), stats, next)
        }
        Phase::Finished { stats } => ("The end".to_string(), stats, "Thanks for playing".to_string()),
    };
    for p in &mut fb.pixels {
        // A quarter of the brightness: the text reads over any scene.
        let [r, g, b, _] = p.to_le_bytes();
        *p = rgb(r / 4, g / 4, b / 4);
    }
    let seconds = stats.ticks / u64::from(TICRATE);
    let tally = |name: &str, (found, total): (u32, u32)| {
        let percent = if total == 0 { 100 } else { found * 100 / total };
        format!("{name:<8}{found:>4} / {total:<4} {percent:>3}%")
    };
    let lines = [
        title,
        String::new(),
        tally("Kills", stats.kills),
        tally("Items", stats.items),
        tally("Secrets", stats.secrets),
        format!("{:<8}{:>4}:{:02}", "Time", seconds / 60, seconds % 60),
        String::new(),
        next,
        "Press use or fire".to_string(),
    ];
    let scale = (fb.height / 200).max(1);
    let line = (GLYPH + 4) * scale;
    let widest = lines.iter().map(|l| l.len()).max().unwrap_or(0) * GLYPH * scale;
    let x = fb.width.saturating_sub(widest) / 2;
    let mut y = fb.height.saturating_sub(line * lines.len()) / 2;
    for l in &lines {
        draw_text(fb, x, y, scale, l);
        y += line;
    }
}

/// Text grows with the frame so it stays readable at 1080p: one font pixel
/// per screen pixel up to 400 rows, then whole multiples.
pub fn text_scale(fb: &Framebuffer) -> usize {
    (fb.height / 400).max(1)
}

/// Draws `text` with its top-left corner at (`x`, `y`), each font pixel
/// `scale` screen pixels, in white over a one-pixel dark shadow so it reads on
/// any background. Characters outside ASCII draw as `?`; whatever falls off
/// the frame is clipped.
pub fn draw_text(fb: &mut Framebuffer, x: usize, y: usize, scale: usize, text: &str) {
    for (i, c) in text.chars().enumerate() {
        let glyph = BASIC_FONTS.get(c).or_else(|| BASIC_FONTS.get('?')).unwrap_or([0; 8]);
        let gx = x + i * GLYPH * scale;
        draw_glyph(fb, gx + scale, y + scale, scale, &glyph, rgb(0, 0, 0));
        draw_glyph(fb, gx, y, scale, &glyph, rgb(255, 255, 255));
    }
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
    let x1 = (x + w).min(fb.width);
    let y1 = (y + h).min(fb.height);
    for yy in y.min(y1)..y1 {
        let row = yy * fb.width;
        fb.pixels[row + x.min(x1)..row + x1].fill(colour);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_clipped_and_drawn() {
        let mut fb = Framebuffer::new(20, 10);
        // Runs off the right and bottom edges: must clip, not panic.
        draw_text(&mut fb, 4, 4, 1, "HUD");
        assert!(fb.pixels.contains(&rgb(255, 255, 255)));
        let mut hud = Hud::new(true);
        for _ in 0..40 {
            hud.frame(Duration::from_millis(20), Duration::from_millis(2));
        }
        let (ms, fps, render) = hud.shown.unwrap();
        assert!((ms - 20.0).abs() < 1e-9 && (fps - 50.0).abs() < 1e-9 && (render - 2.0).abs() < 1e-9);
        hud.draw(&mut Framebuffer::new(3, 3), "map", "bsp");
    }
}
