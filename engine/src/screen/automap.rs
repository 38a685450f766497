//! The automap: the map lines the player has seen so far, drawn from above in
//! place of the 3D view, scaled to fit the frame, with an arrow for the
//! player. It remembers what every rendered frame reported as drawn
//! (`Frame::seen_lines`), so it fills in as you explore.

use crate::framebuffer::rgb;
use crate::map::Map;
use crate::Framebuffer;

/// Blank border around the map, as a fraction of the frame's smaller side.
const MARGIN: f64 = 0.05;
/// Player arrow length, as a fraction of the frame height: a fixed screen size
/// so it shows on a map of any extent.
const ARROW: f64 = 0.04;

// Doom's automap palette: red walls, brown where the floor changes, yellow
// where the ceiling changes, grey for openings with no height change.
const WALL: u32 = rgb(252, 0, 0);
const FLOOR_STEP: u32 = rgb(188, 120, 72);
const CEILING_STEP: u32 = rgb(252, 252, 0);
const OPENING: u32 = rgb(120, 120, 120);
const PLAYER: u32 = rgb(255, 255, 255);
/// Things, in the modes that show them (ViZDoom's `OBJECTS`).
const THING: u32 = rgb(0, 252, 0);
const BACKGROUND: u32 = rgb(0, 0, 0);

pub struct Automap {
    pub visible: bool,
    seen: Vec<bool>,
}

/// Map-to-screen transform: north up, the map's bounding box centred.
struct Fit {
    scale: f64,
    origin: (f64, f64),
    centre: (f64, f64),
}

impl Fit {
    fn new(map: &Map, width: usize, height: usize) -> Fit {
        let (mut lo, mut hi) = ((f64::MAX, f64::MAX), (f64::MIN, f64::MIN));
        for v in &map.vertices {
            lo = (lo.0.min(v.x), lo.1.min(v.y));
            hi = (hi.0.max(v.x), hi.1.max(v.y));
        }
        let (w, h) = (width as f64, height as f64);
        let margin = MARGIN * w.min(h);
        // A validated map has lines of positive length, so the box has some
        // extent; the floor of one unit keeps a degenerate one finite anyway.
        let extent = ((hi.0 - lo.0).max(1.0), (hi.1 - lo.1).max(1.0));
        let scale = ((w - 2.0 * margin) / extent.0).min((h - 2.0 * margin) / extent.1).max(1e-9);
        Fit { scale, origin: ((lo.0 + hi.0) / 2.0, (lo.1 + hi.1) / 2.0), centre: (w / 2.0, h / 2.0) }
    }

    fn to_screen(&self, x: f64, y: f64) -> (f64, f64) {
        (self.centre.0 + (x - self.origin.0) * self.scale, self.centre.1 - (y - self.origin.1) * self.scale)
    }
}

impl Automap {
    pub fn new(map: &Map) -> Automap {
        Automap { visible: false, seen: vec![false; map.lines.len()] }
    }

    /// Adds the lines one frame drew (an empty slice, as the reference
    /// renderer gives, adds nothing).
    pub fn accumulate(&mut self, frame_seen: &[bool]) {
        for (seen, &now) in self.seen.iter_mut().zip(frame_seen) {
            *seen |= now;
        }
    }

    /// Replaces the frame with the automap: seen lines and the player at
    /// `pos` facing `angle` degrees (counter-clockwise from east).
    pub fn draw(&self, map: &Map, pos: (f64, f64), angle: f64, fb: &mut Framebuffer) {
        self.draw_showing(map, pos, angle, Show::Seen, fb);
    }

    /// [`Automap::draw`] showing more: every line, or every line and the
    /// things (`level.things`), each a dot.
    pub fn draw_showing(&self, map: &Map, pos: (f64, f64), angle: f64, show: Show<'_>, fb: &mut Framebuffer) {
        fb.pixels.fill(BACKGROUND);
        let fit = Fit::new(map, fb.width, fb.height);
        let whole = !matches!(show, Show::Seen);
        for (line, _) in map.lines.iter().zip(&self.seen).filter(|(_, &seen)| seen || whole) {
            let (a, b) = map.line_points(line);
            let colour = match &line.back {
                None => WALL,
                Some(back) => {
                    let (f, k) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
                    if f.floor != k.floor {
                        FLOOR_STEP
                    } else if f.ceiling != k.ceiling {
                        CEILING_STEP
                    } else {
                        OPENING
                    }
                }
            };
            draw_line(fb, fit.to_screen(a.x, a.y), fit.to_screen(b.x, b.y), colour);
        }
        if let Show::Things(things) = show {
            for t in things {
                let (x, y) = fit.to_screen(t.pos.x, t.pos.y);
                for (dx, dy) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)] {
                    draw_line(fb, (x + dx, y + dy), (x + dx, y + dy), THING);
                }
            }
        }
        draw_arrow(fb, fit.to_screen(pos.0, pos.1), angle, ARROW * fb.height as f64);
    }
}

/// What [`Automap::draw_showing`] shows.
#[derive(Clone, Copy, Debug)]
pub enum Show<'a> {
    /// The lines the player has seen (Doom's automap).
    Seen,
    /// Every line.
    Whole,
    /// Every line and these things.
    Things(&'a [crate::level::DrawnThing]),
}

/// An arrow `len` pixels long centred on `at`, pointing along `angle`
/// (degrees counter-clockwise from screen right, screen y pointing down).
fn draw_arrow(fb: &mut Framebuffer, at: (f64, f64), angle: f64, len: f64) {
    let (s, c) = angle.to_radians().sin_cos();
    let point = |along: f64, across: f64| (at.0 + along * c - across * s, at.1 - along * s - across * c);
    let (tip, tail) = (point(len / 2.0, 0.0), point(-len / 2.0, 0.0));
    draw_line(fb, tail, tip, PLAYER);
    draw_line(fb, tip, point(len / 6.0, len / 4.0), PLAYER);
    draw_line(fb, tip, point(len / 6.0, -len / 4.0), PLAYER);
}

/// A one-pixel line: clipped to the frame, then stepped along its longer
/// axis (DDA).
fn draw_line(fb: &mut Framebuffer, a: (f64, f64), b: (f64, f64), colour: u32) {
    let Some((a, b)) = clip(a, b, (fb.width as f64, fb.height as f64)) else { return };
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    // After clipping both ends lie on the frame, so this is at most its
    // width plus height.
    let steps = dx.abs().max(dy.abs()).ceil().max(1.0) as usize;
    for i in 0..=steps {
        let t = i as f64 / steps as f64;
        let (x, y) = ((a.0 + dx * t).floor(), (a.1 + dy * t).floor());
        if x >= 0.0 && y >= 0.0 && (x as usize) < fb.width && (y as usize) < fb.height {
            fb.pixels[y as usize * fb.width + x as usize] = colour;
        }
    }
}

/// The part of segment `a`-`b` inside `[0, w] x [0, h]` (Liang and Barsky's
/// clipping); `None` when nothing of it is, or an end is not finite.
fn clip(a: (f64, f64), b: (f64, f64), (w, h): (f64, f64)) -> Option<((f64, f64), (f64, f64))> {
    if ![a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite()) {
        return None;
    }
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    // Each edge as p * t <= q: left, right, top, bottom.
    for (p, q) in [(-dx, a.0), (dx, w - a.0), (-dy, a.1), (dy, h - a.1)] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 <= t1).then_some(((a.0 + dx * t0, a.1 + dy * t0), (a.0 + dx * t1, a.1 + dy * t1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_clip_and_arrow_points_the_right_way() {
        let mut fb = Framebuffer::new(40, 40);
        draw_line(&mut fb, (-100.0, 20.0), (1e9, 20.0), PLAYER);
        draw_line(&mut fb, (f64::NAN, 0.0), (1.0, 1.0), PLAYER);
        assert_eq!(fb.get(0, 20), PLAYER);
        assert_eq!(fb.get(39, 20), PLAYER);

        // Facing north (90 degrees): the tip is above the centre.
        let mut fb = Framebuffer::new(40, 40);
        draw_arrow(&mut fb, (20.0, 20.0), 90.0, 20.0);
        assert_eq!(fb.get(20, 11), PLAYER);
        assert_eq!(fb.get(20, 29), PLAYER);
        assert_ne!(fb.get(30, 20), PLAYER);
    }
}
