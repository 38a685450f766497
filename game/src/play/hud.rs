//! The heads-up display, drawn over the finished frame just before it is
//! uploaded, in 8x8 text: frame time and fps, the map and renderer, the
//! player's health and keys, the game's messages; and between levels the
//! intermission's tallies (also drawn on `sightline replay`'s captures).

use std::time::Duration;

use sightline::framebuffer::rgb;
use sightline::play::playthrough::Phase;
use sightline::play::{Player, TICRATE};
use sightline::screen::text::GLYPH;
use sightline::Framebuffer;

/// How long a message stays on screen (Doom's MESSAGETICS, 4 s).
const MESSAGE_TIME: Duration = Duration::from_secs(4);
/// At most this many messages show at once, newest last.
const MESSAGES_SHOWN: usize = 3;

/// Frame time shown as an average over this long, so the figures can be read
/// rather than flicker with every frame.
const SMOOTHING_WINDOW: Duration = Duration::from_millis(500);

pub struct Hud {
    pub visible: bool,
    window_time: Duration,
    window_frames: u32,
    window_render: Duration,
    /// The figures last shown: ms per frame, frames per second, render ms.
    shown: Option<(f64, f64, f64)>,
    /// Messages and how long each has shown.
    messages: Vec<(String, Duration)>,
    /// What is wrong with the map file being watched, shown until it is fixed.
    pub map_error: Option<String>,
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
            map_error: None,
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

    /// The game's messages under the figures, and how to restart when dead
    /// (health, armour, ammunition and keys are on the status bar).
    pub fn draw_status(&self, fb: &mut Framebuffer, player: &Player) {
        if !self.visible && self.map_error.is_none() {
            return;
        }
        let scale = text_scale(fb);
        let line = (GLYPH + 2) * scale;
        let mut y = scale * 4 + 2 * line;
        for (text, _) in &self.messages {
            draw_text(fb, scale * 4, y, scale, text);
            y += line;
        }
        if player.dead() {
            draw_text(fb, scale * 4, fb.height / 3, scale, "You are dead: press use to restart");
        }
        if let Some(error) = &self.map_error {
            // Wrapped to the frame's width, under a heading; shown even with the HUD off.
            let columns = (fb.width / (GLYPH * scale)).saturating_sub(8).max(16);
            let mut y = fb.height / 2;
            let heading = "The map file has errors; the last good level goes on:";
            for text in std::iter::once(heading.to_string()).chain(wrap(error, columns)).take(8) {
                draw_text(fb, scale * 4, y, scale, &text);
                y += line;
            }
        }
    }

    /// A scenario's reward so far, at the top right (shown with the HUD
    /// off too: it is the point of the scenario).
    pub fn draw_reward(&self, fb: &mut Framebuffer, reward: f64) {
        let scale = text_scale(fb);
        let text = format!("REWARD {reward:.2}");
        let x = fb.width.saturating_sub((text.len() + 4) * GLYPH * scale);
        draw_text(fb, x, scale * 4, scale, &text);
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
    let (title, stats, next, shown) = match phase {
        Phase::Playing => return,
        Phase::Intermission { map, stats, next, wi, .. } => {
            let next = match next {
                Some(m) => format!("Entering {}", m.short_name()),
                None => "The end of the campaign".to_string(),
            };
            (format!("{map} finished"), stats, next, Some(wi.shown))
        }
        Phase::Finished { stats } => ("The end".to_string(), stats, "Thanks for playing".to_string(), None),
    };
    for p in &mut fb.pixels {
        // A quarter of the brightness: the text reads over any scene.
        let [r, g, b, _] = p.to_le_bytes();
        *p = rgb(r / 4, g / 4, b / 4);
    }
    // Doom's intermission counts the percentages and the time up (`shown`,
    // -1 before a line's count begins); the end of a campaign shows them.
    let seconds = match shown {
        Some(s) if s.time < 0 => None,
        Some(s) => Some(s.time as u64),
        None => Some(stats.ticks / u64::from(TICRATE)),
    };
    let tally = |name: &str, (found, total): (u32, u32), counted: Option<i32>| {
        let percent = match counted {
            Some(p) if p < 0 => return format!("{name:<8}"),
            Some(p) => p as u32,
            None if total == 0 => 100,
            None => found * 100 / total,
        };
        format!("{name:<8}{found:>4} / {total:<4} {percent:>3}%")
    };
    let lines = [
        title,
        String::new(),
        tally("Kills", stats.kills, shown.map(|s| s.kills)),
        tally("Items", stats.items, shown.map(|s| s.items)),
        tally("Secrets", stats.secrets, shown.map(|s| s.secrets)),
        match seconds {
            Some(t) => format!("{:<8}{:>4}:{:02}", "Time", t / 60, t % 60),
            None => "Time".to_string(),
        },
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

pub use sightline::screen::text::draw_text;

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

    /// The intermission shows the tallies as Doom counts them up: a line
    /// whose count has not begun shows only its name, and the counted
    /// frame differs from the finished one.
    #[test]
    fn the_intermission_counts_up_on_screen() {
        use sightline::play::Stats;
        use sightline::sim::intermission::{Intermission, Tallies};
        use sightline::sim::GameMode;
        let tallies = Tallies { kills: 3, max_kills: 4, items: 1, max_items: 2, time: 35 * 70, ..Tallies::default() };
        let mut wi = Intermission::start(GameMode::Commercial, "MAP01", false, tallies);
        let stats = Stats { kills: (3, 4), items: (1, 2), secrets: (0, 0), ticks: 35 * 70 };
        let white = |wi: &Intermission| {
            let phase = Phase::Intermission {
                map: "MAP01".into(),
                stats,
                exit: sightline::play::Exit::Normal,
                next: None,
                wi: Box::new(wi.clone()),
            };
            let mut fb = Framebuffer::new(320, 200);
            draw_phase(&mut fb, &phase);
            if let Some(dir) = std::env::var_os("SIGHTLINE_HUD_PNG") {
                let path = std::path::Path::new(&dir).join(format!("intermission-{}.png", wi.tics));
                std::fs::write(path, fb.to_png()).unwrap();
            }
            fb.pixels.iter().filter(|&&p| p == rgb(255, 255, 255)).count()
        };
        let mut players = Default::default();
        let mut count = |wi: &mut Intermission, tics: u32| {
            for _ in 0..tics {
                wi.tick(&mut players, &[None; sightline::sim::MAXPLAYERS]);
            }
        };
        let before = white(&wi);
        count(&mut wi, 40);
        let counting = white(&wi);
        count(&mut wi, 300);
        let finished = white(&wi);
        assert!(before < counting && counting < finished, "{before} {counting} {finished}");
    }
}

/// `text` in lines of at most `columns` characters, broken at spaces where it can be.
fn wrap(text: &str, columns: usize) -> Vec<String> {
    let mut lines = Vec::new();
    for paragraph in text.lines() {
        let mut line = String::new();
        for word in paragraph.split(' ') {
            if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > columns {
                lines.push(std::mem::take(&mut line));
            }
            if !line.is_empty() {
                line.push(' ');
            }
            line.push_str(word);
            while line.chars().count() > columns {
                let rest: String = line.chars().skip(columns).collect();
                line = line.chars().take(columns).collect();
                lines.push(std::mem::replace(&mut line, rest));
            }
        }
        lines.push(line);
    }
    lines
}
