//! The menu's pages drawn over the frame: the view dimmed, a heading, the
//! items in our own lettering (the 8x8 font scaled, each glyph shaded top
//! to bottom over a dark shadow), a pointer at the chosen item, and a line
//! of hints at the foot. Placed in Doom's 320x200 units like the status bar
//! ([`super::super::scale`]), so every frame size shows the same page.
//! [`item_at`] answers which item a pointer is over, from the same layout.

use font8x8::{UnicodeFonts, BASIC_FONTS};

use super::{Item, Menu, Page, SlotInfo, SKILLS, SLOTS};
use crate::framebuffer::{rgb, Framebuffer};
use crate::screen::scale;
use crate::screen::text::fill_rect;

/// Colours of text: top and bottom of each glyph.
type Shade = (u32, u32);
const RED: Shade = (rgb(255, 96, 64), rgb(150, 10, 0));
const GOLD: Shade = (rgb(255, 244, 170), rgb(236, 150, 20));
const GREY: Shade = (rgb(150, 146, 140), rgb(96, 92, 88));
const PALE: Shade = (rgb(232, 226, 214), rgb(176, 168, 156));

/// Rows of the key page shown at once.
const KEY_ROWS: usize = 15;

/// Places in 320x200 units, mapped to pixels.
struct Place {
    s: f64,
    margin: f64,
}

impl Place {
    fn of(fb: &Framebuffer) -> Place {
        let (s, margin) = scale(fb);
        // Centred down the frame too when it is taller than 16:10.
        Place { s, margin }
    }
    fn x(&self, u: f64) -> usize {
        (self.margin + u * self.s).round().max(0.0) as usize
    }
    fn y(&self, v: f64, fb: &Framebuffer) -> usize {
        let top = ((fb.height as f64 - 200.0 * self.s) / 2.0).max(0.0);
        (top + v * self.s).round().max(0.0) as usize
    }
    fn len(&self, u: f64) -> usize {
        (u * self.s).round().max(1.0) as usize
    }
    /// The font scale for glyphs about `units` high.
    fn k(&self, units: f64) -> usize {
        ((units * self.s / 8.0).round() as usize).max(1)
    }
}

/// How a page lays out its items: where the first is, how far apart, how
/// big their text, and where they start across (None: centred).
struct Layout {
    top: f64,
    step: f64,
    text: f64,
    left: Option<f64>,
    /// The first item shown (the key page scrolls).
    first: usize,
    shown: usize,
}

fn layout(menu: &Menu) -> Layout {
    let count = menu.items().len();
    let all = |top, step, text, left| Layout { top, step, text, left, first: 0, shown: count };
    match menu.page() {
        Page::Main => all(78.0, 20.0, 16.0, None),
        Page::Episode | Page::Skill { .. } => all(64.0, 18.0, 12.0, Some(56.0)),
        Page::Options => all(64.0, 22.0, 16.0, None),
        Page::Controls | Page::Sound | Page::Video | Page::Gameplay => all(60.0, 20.0, 8.0, Some(40.0)),
        Page::Keys => {
            let first = menu.cursor().saturating_sub(KEY_ROWS / 2).min(count.saturating_sub(KEY_ROWS));
            Layout { top: 44.0, step: 9.0, text: 5.0, left: Some(28.0), first, shown: KEY_ROWS.min(count) }
        }
        Page::Load | Page::Save | Page::SaveName { .. } => all(38.0, 17.0, 8.0, Some(20.0)),
        Page::QuitConfirm => all(104.0, 20.0, 12.0, None),
    }
}

/// The item under the pointer at pixel (`x`, `y`) of a `width` by
/// `height` frame, if any.
pub fn item_at(menu: &Menu, width: usize, height: usize, x: usize, y: usize) -> Option<usize> {
    let fb = Framebuffer { width, height, pixels: Vec::new() };
    let p = Place::of(&fb);
    let l = layout(menu);
    let slots = matches!(menu.page(), Page::Load | Page::Save);
    if slots && (x < p.x(14.0) || x > p.x(166.0)) {
        return None;
    }
    (l.first..l.first + l.shown).find(|&i| {
        let v = l.top + (i - l.first) as f64 * l.step;
        let (y0, y1) = (p.y(v - 3.0, &fb), p.y(v + l.step - 3.0, &fb));
        (y0..y1).contains(&y)
    })
}

/// Draws the menu over `fb` (the game's view or the title picture).
pub fn draw(fb: &mut Framebuffer, menu: &Menu) {
    dim(fb, 0.42);
    let p = Place::of(fb);
    if *menu.page() == Page::Main {
        super::title::logo(fb, 14.0);
    } else {
        let k = p.k(16.0);
        centred(fb, &p, 14.0, k, menu.heading(), GOLD);
        let w = p.len(180.0);
        let x = fb.width.saturating_sub(w) / 2;
        fill_rect(fb, x, p.y(34.0, fb), w, p.len(1.0), rgb(150, 30, 10));
    }
    match menu.page() {
        Page::Load | Page::Save | Page::SaveName { .. } => slots(fb, &p, menu),
        Page::QuitConfirm => {
            let (w, h) = (p.len(220.0), p.len(90.0));
            panel(fb, fb.width.saturating_sub(w) / 2, p.y(60.0, fb), w, h);
            centred(fb, &p, 74.0, p.k(8.0), "Leave the game?", PALE);
            items(fb, &p, menu);
        }
        _ => items(fb, &p, menu),
    }
    hints(fb, &p, menu);
}

/// The list of items, the chosen one in gold with the pointer beside it.
fn items(fb: &mut Framebuffer, p: &Place, menu: &Menu) {
    let l = layout(menu);
    let list = menu.items();
    if l.left.is_some() && !matches!(menu.page(), Page::Episode | Page::Skill { .. }) {
        let rows = l.shown as f64 * l.step;
        let (x, w) = (p.x(l.left.unwrap_or(0.0) - 12.0), p.len(320.0 - 2.0 * (l.left.unwrap_or(0.0) - 12.0)));
        panel(fb, x, p.y(l.top - 6.0, fb), w, p.len(rows + 6.0));
    }
    let k = p.k(l.text);
    for (row, item) in list.iter().enumerate().skip(l.first).take(l.shown) {
        let v = l.top + (row - l.first) as f64 * l.step;
        let y = p.y(v, fb);
        let chosen = row == menu.cursor();
        let waiting = chosen && menu.binding.is_some();
        let shade = match item {
            Item::Disabled(_) => GREY,
            _ if chosen => GOLD,
            _ => RED,
        };
        let label = match item {
            Item::Link(t) | Item::Disabled(t) | Item::Toggle(t, _) | Item::Slider(t, ..) => t.to_string(),
            Item::Keys(action, _) => pretty(action),
            Item::Text(t) => t.clone(),
            Item::Slot(n) => format!("Slot {}", n + 1),
        };
        let width = label.len() * 8 * k;
        let x = match l.left {
            Some(u) => p.x(u),
            None => fb.width.saturating_sub(width) / 2,
        };
        text(fb, x, y, k, &label, shade);
        if chosen {
            pointer(fb, x.saturating_sub(p.len(4.0) + 8 * k), y, 8 * k, menu.ticks);
        }
        let right = p.x(320.0 - l.left.unwrap_or(0.0));
        let value_x = p.x(180.0);
        match item {
            Item::Toggle(_, on) => {
                let v = if *on { "On" } else { "Off" };
                text(fb, right.saturating_sub(v.len() * 8 * k), y, k, v, if *on { GOLD } else { GREY });
            }
            Item::Slider(_, at, steps, value) => {
                slider(fb, p, value_x, y, 8 * k, *at, *steps);
                text(fb, right.saturating_sub(value.len() * 8 * k), y, k, value, PALE);
            }
            Item::Keys(_, keys) => {
                let shown = if waiting {
                    if menu.ticks / 16 % 2 == 0 {
                        "press a key".to_string()
                    } else {
                        String::new()
                    }
                } else if keys.is_empty() {
                    "-".to_string()
                } else {
                    keys.clone()
                };
                text(fb, p.x(150.0), y, k, &shown, if waiting { GOLD } else { PALE });
            }
            _ => {}
        }
    }
    if menu.items().len() > l.shown {
        let more = format!("{}-{} of {}", l.first + 1, l.first + l.shown, list.len());
        let k = p.k(5.0);
        let x = p.x(300.0).saturating_sub(more.len() * 8 * k);
        text(fb, x, p.y(36.0, fb), k, &more, GREY);
    }
}

/// The slot pages: the slots down the left, the chosen one's picture and
/// particulars on the right.
fn slots(fb: &mut Framebuffer, p: &Place, menu: &Menu) {
    let l = layout(menu);
    let k = p.k(l.text);
    let (editing, typed) = match menu.page() {
        Page::SaveName { slot, text } => (Some(*slot), text.as_str()),
        _ => (None, ""),
    };
    let at = editing.unwrap_or(menu.cursor());
    for n in 0..SLOTS {
        let v = l.top + n as f64 * l.step;
        let chosen = n == at;
        let (x, y, w, h) = (p.x(14.0), p.y(v - 4.0, fb), p.len(152.0), p.len(l.step - 3.0));
        fill_rect(fb, x, y, w, h, if chosen { rgb(120, 24, 8) } else { rgb(70, 14, 6) });
        fill_rect(fb, x + p.len(1.0), y + p.len(1.0), w - 2 * p.len(1.0), h - 2 * p.len(1.0), rgb(22, 18, 16));
        let info = menu.setup.slots.get(n).and_then(Option::as_ref);
        let name = match (editing == Some(n), info) {
            (true, _) => {
                let caret = if menu.ticks / 16 % 2 == 0 { "_" } else { " " };
                format!("{typed}{caret}")
            }
            (false, Some(info)) => info.name.clone(),
            (false, None) => "- empty slot -".into(),
        };
        let shade = match (chosen, info.is_some() || editing == Some(n)) {
            (true, _) => GOLD,
            (false, true) => RED,
            (false, false) => GREY,
        };
        // 17 letters fit the box: a longer name is cut (its end shown while typed).
        let letters: Vec<char> = name.chars().collect();
        let name: String = match (letters.len() > 17, editing == Some(n)) {
            (false, _) => name,
            (true, true) => letters[letters.len() - 17..].iter().collect(),
            (true, false) => letters[..14].iter().collect::<String>() + "...",
        };
        text(fb, p.x(20.0), p.y(v, fb), k, &name, shade);
    }
    // The right panel.
    let (x, y, w, h) = (p.x(174.0), p.y(34.0, fb), p.len(134.0), p.len(136.0));
    panel(fb, x, y, w, h);
    let (tx, ty, tw, th) = (p.x(179.0), p.y(39.0, fb), p.len(124.0), p.len(77.5));
    let info = menu.setup.slots.get(at).and_then(Option::as_ref);
    match info.and_then(|i| i.thumbnail.as_ref()) {
        Some(thumb) => blit(fb, thumb, tx, ty, tw, th),
        None => {
            fill_rect(fb, tx, ty, tw, th, rgb(12, 10, 10));
            let k = p.k(8.0);
            let label = if info.is_some() { "no picture" } else { "empty" };
            text(fb, tx + tw.saturating_sub(label.len() * 8 * k) / 2, ty + th / 2 - 4 * k, k, label, GREY);
        }
    }
    if let Some(info) = info {
        for (i, line) in particulars(info).iter().enumerate() {
            let k = fit(p, 8.0, line, 126.0);
            text(fb, p.x(179.0), p.y(121.0 + 11.0 * i as f64, fb), k, line, if i == 0 { GOLD } else { PALE });
        }
    }
}

/// What a slot's panel says under its picture: map, time played, skill.
fn particulars(info: &SlotInfo) -> [String; 3] {
    let skill = SKILLS.get(usize::from(info.skill.max(1)) - 1).copied().unwrap_or("?");
    let (h, m, s) = (info.seconds / 3600, info.seconds / 60 % 60, info.seconds % 60);
    let time = if h > 0 { format!("{h}:{m:02}:{s:02}") } else { format!("{m}:{s:02}") };
    [info.map.clone(), format!("Time {time}"), skill.to_string()]
}

/// The largest font scale up to `units` high at which `line` fits `room` units.
fn fit(p: &Place, units: f64, line: &str, room: f64) -> usize {
    let widest = (room * p.s / (8.0 * line.len().max(1) as f64)).floor() as usize;
    p.k(units).min(widest).max(1)
}

/// The line of hints at the foot of the page.
fn hints(fb: &mut Framebuffer, p: &Place, menu: &Menu) {
    let line = match menu.page() {
        _ if menu.binding.is_some() => "Press the key to bind   Esc: cancel",
        Page::SaveName { .. } => "Type a name   Enter: save   Esc: back",
        Page::Keys => "Enter: bind a key   Backspace: clear   Esc: back",
        Page::Controls | Page::Sound | Page::Video | Page::Gameplay => "Left, Right: change   Esc: back",
        Page::QuitConfirm => "Y: quit   N or Esc: stay",
        Page::Main => "Arrows: move   Enter: choose   Esc: close",
        _ => "Arrows: move   Enter: choose   Esc: back",
    };
    let k = fit(p, 5.0, line, 300.0);
    let width = line.len() * 8 * k;
    text(fb, fb.width.saturating_sub(width) / 2, p.y(188.0, fb), k, line, GREY);
}

/// An action's name as the key page shows it: `strafe_left` as `Strafe left`.
fn pretty(action: &str) -> String {
    let spaced = action.replace('_', " ");
    let mut chars = spaced.chars();
    chars.next().map(|c| c.to_ascii_uppercase().to_string() + chars.as_str()).unwrap_or_default()
}

/// Draws `line` with its top-left at (`x`, `y`), each font pixel `k` screen
/// pixels, shaded from the top colour to the bottom one over a shadow.
pub fn text(fb: &mut Framebuffer, x: usize, y: usize, k: usize, line: &str, shade: Shade) {
    let shadow = (k / 2).max(1);
    for pass in 0..2 {
        for (i, c) in line.chars().enumerate() {
            let glyph = BASIC_FONTS.get(c).or_else(|| BASIC_FONTS.get('?')).unwrap_or([0; 8]);
            let gx = x + i * 8 * k;
            for (row, bits) in glyph.iter().enumerate() {
                let colour = if pass == 0 { rgb(0, 0, 0) } else { mix(shade.0, shade.1, row as f64 / 7.0) };
                let off = if pass == 0 { shadow } else { 0 };
                for col in 0..8 {
                    // font8x8 keeps each row's leftmost pixel in bit 0.
                    if bits >> col & 1 == 1 {
                        fill_rect(fb, gx + col * k + off, y + row * k + off, k, k, colour);
                    }
                }
            }
        }
    }
}

/// `line` centred across the frame at row `v`.
fn centred(fb: &mut Framebuffer, p: &Place, v: f64, k: usize, line: &str, shade: Shade) {
    let width = line.len() * 8 * k;
    let y = p.y(v, fb);
    text(fb, fb.width.saturating_sub(width) / 2, y, k, line, shade);
}

/// The pointer: a red arrowhead `size` high, its glow pulsing with `ticks`.
fn pointer(fb: &mut Framebuffer, x: usize, y: usize, size: usize, ticks: u64) {
    let glow = 0.75 + 0.25 * ((ticks as f64) * 0.25).sin();
    let half = size as f64 / 2.0;
    for row in 0..size {
        let reach = (half - (row as f64 + 0.5 - half).abs()) / half;
        let w = (reach * size as f64 * 0.8).round() as usize;
        let c = mix(rgb(255, 220, 120), rgb(200, 20, 0), 1.0 - reach * glow);
        fill_rect(fb, x, y + row, w, 1, c);
    }
}

/// A slider: `steps` + 1 notches, the thumb at `at`.
fn slider(fb: &mut Framebuffer, p: &Place, x: usize, y: usize, h: usize, at: usize, steps: usize) {
    let w = p.len(80.0);
    fill_rect(fb, x, y + h / 3, w, h / 3, rgb(60, 12, 6));
    fill_rect(fb, x, y + h / 3, w * at / steps.max(1), h / 3, rgb(190, 40, 12));
    let thumb = x + (w - p.len(4.0)) * at / steps.max(1);
    fill_rect(fb, thumb, y, p.len(4.0), h, rgb(255, 210, 120));
}

/// A dark box with a red rim.
fn panel(fb: &mut Framebuffer, x: usize, y: usize, w: usize, h: usize) {
    let rim = (h / 120).max(1);
    shade_rect(fb, x, y, w, h, 0.35);
    fill_rect(fb, x, y, w, rim, rgb(130, 28, 10));
    fill_rect(fb, x, (y + h).saturating_sub(rim), w, rim, rgb(130, 28, 10));
}

/// Darkens the whole frame to `level` of its brightness.
fn dim(fb: &mut Framebuffer, level: f64) {
    let (w, h) = (fb.width, fb.height);
    shade_rect(fb, 0, 0, w, h, level);
}

fn shade_rect(fb: &mut Framebuffer, x: usize, y: usize, w: usize, h: usize, level: f64) {
    let x1 = (x + w).min(fb.width);
    let y1 = (y + h).min(fb.height);
    for yy in y.min(y1)..y1 {
        for px in &mut fb.pixels[yy * fb.width + x.min(x1)..yy * fb.width + x1] {
            *px = mix(rgb(0, 0, 0), *px, level);
        }
    }
}

/// `src` scaled (nearest) into the box.
fn blit(fb: &mut Framebuffer, src: &Framebuffer, x: usize, y: usize, w: usize, h: usize) {
    if src.width == 0 || src.height == 0 {
        return;
    }
    for row in 0..h.min(fb.height.saturating_sub(y)) {
        let sy = row * src.height / h;
        for col in 0..w.min(fb.width.saturating_sub(x)) {
            let sx = col * src.width / w;
            fb.pixels[(y + row) * fb.width + x + col] = src.pixels[sy * src.width + sx];
        }
    }
}

/// `a` to `b` by `t` (0 to 1), channel by channel.
pub fn mix(a: u32, b: u32, t: f64) -> u32 {
    let t = t.clamp(0.0, 1.0);
    let (a, b) = (a.to_le_bytes(), b.to_le_bytes());
    let c = |i: usize| (f64::from(a[i]) + (f64::from(b[i]) - f64::from(a[i])) * t).round() as u8;
    rgb(c(0), c(1), c(2))
}
