//! The status bar (Doom's 320x32 strip at the bottom) and the minimal
//! full-screen HUD, drawn in our own style with the 8x8 font: no art from a
//! WAD is needed, so a test level shows the same bar as Freedoom.
//!
//! The bar, left to right as Doom's: the ammunition of the weapon in hand,
//! health, the weapons owned (slots 2 to 7), a face that shows how hurt the
//! player is, armour, the keys, and every kind of ammunition against its
//! limit.

use super::scale;
use super::text::{draw_text_in, fill_rect, GLYPH};
use crate::actors::{ActorTable, KeyForm};
use crate::framebuffer::{rgb, Framebuffer};
use crate::level::Level;
use crate::map::special::KeyColour;
use crate::play::Player;

/// The bar's height in 320x200 units.
pub const BAR_HEIGHT: f64 = 32.0;

const RED: u32 = rgb(220, 40, 30);
const GOLD: u32 = rgb(240, 200, 60);
const GREY: u32 = rgb(150, 150, 150);

/// The ammunition of the weapon in hand, if it uses any.
fn current_ammo(table: &ActorTable, player: &Player) -> Option<(i32, i32)> {
    let weapon = table.actors.get(player.ready_weapon?)?.weapon.as_ref()?;
    let k = weapon.ammo?.index();
    Some((player.ammo[k], player.max_ammo[k]))
}

/// A box of the bar in 320x200 units, mapped to pixels.
struct Layout {
    s: f64,
    margin: f64,
    top: f64,
}

impl Layout {
    fn x(&self, u: f64) -> usize {
        (self.margin + u * self.s).round() as usize
    }
    fn y(&self, v: f64) -> usize {
        (self.top + v * self.s).round() as usize
    }
    fn len(&self, u: f64) -> usize {
        (u * self.s).round().max(1.0) as usize
    }
    /// Text scale for glyphs about `units` high.
    fn text(&self, units: f64) -> usize {
        ((units * self.s / GLYPH as f64).round() as usize).max(1)
    }
    /// `text` centred in the box `u0..u1` at row `v`, glyphs `units` high
    /// (smaller if it would not fit the box's width).
    fn centred(&self, fb: &mut Framebuffer, u0: f64, u1: f64, v: f64, units: f64, text: &str, colour: u32) {
        let room = self.x(u1).saturating_sub(self.x(u0)) / (text.len().max(1) * GLYPH);
        let k = self.text(units).min(room.max(1));
        let width = text.len() * GLYPH * k;
        let mid = (self.x(u0) + self.x(u1)) / 2;
        draw_text_in(fb, mid.saturating_sub(width / 2), self.y(v), k, text, colour);
    }
}

/// `table` is the game's actor table (its weapons' slots and ammunition).
pub fn status_bar(fb: &mut Framebuffer, _level: &Level, table: &ActorTable, player: &Player) {
    let (s, margin) = scale(fb);
    let top = fb.height as f64 - BAR_HEIGHT * s;
    let l = Layout { s, margin, top };
    // The panel: the full width, dark with a lighter rim.
    fill_rect(fb, 0, l.y(0.0), fb.width, fb.height, rgb(48, 46, 44));
    fill_rect(fb, 0, l.y(0.0), fb.width, l.len(1.0), rgb(110, 104, 96));
    let boxes =
        [(0.0, 48.0), (48.0, 104.0), (104.0, 144.0), (144.0, 176.0), (176.0, 236.0), (236.0, 250.0), (250.0, 320.0)];
    for (u0, u1) in boxes {
        fill_rect(fb, l.x(u0 + 1.0), l.y(2.0), l.len(u1 - u0 - 2.0), l.len(29.0), rgb(28, 27, 26));
    }
    let (ammo, _) = current_ammo(table, player).unwrap_or((-1, 0));
    if ammo >= 0 {
        l.centred(fb, 0.0, 48.0, 5.0, 16.0, &ammo.to_string(), RED);
    }
    l.centred(fb, 0.0, 48.0, 23.0, 6.0, "AMMO", GREY);
    l.centred(fb, 48.0, 104.0, 5.0, 16.0, &format!("{}%", player.health.clamp(0, 999)), RED);
    l.centred(fb, 48.0, 104.0, 23.0, 6.0, "HEALTH", GREY);
    // Arms: 2 3 4 / 5 6 7, lit when a weapon of that slot is owned.
    for slot in 2..=7u8 {
        let owned = player
            .weapons
            .iter()
            .any(|&w| table.actors.get(w).and_then(|d| d.weapon.as_ref()).is_some_and(|d| d.slot == slot));
        let (col, row) = (f64::from((slot - 2) % 3), f64::from((slot - 2) / 3));
        let u = 106.0 + col * 12.0;
        l.centred(fb, u, u + 12.0, 4.0 + row * 10.0, 8.0, &slot.to_string(), if owned { GOLD } else { GREY });
    }
    l.centred(fb, 104.0, 144.0, 23.0, 6.0, "ARMS", GREY);
    face(fb, &l, player);
    l.centred(fb, 176.0, 236.0, 5.0, 16.0, &format!("{}%", player.armor), RED);
    l.centred(fb, 176.0, 236.0, 23.0, 6.0, "ARMOR", GREY);
    for colour in [KeyColour::Blue, KeyColour::Yellow, KeyColour::Red] {
        let v = 3.0 + 9.5 * f64::from(colour as u8);
        if let Some(key) = player.keys.iter().find(|k| k.colour == colour) {
            key_box(fb, l.x(239.0), l.y(v), l.len(8.0), key.colour, key.form);
        }
    }
    // Bullets, shells, rockets, cells: what is carried of the limit.
    for k in 0..4 {
        let text = format!("{:>3}/{:<3}", player.ammo[k].clamp(0, 999), player.max_ammo[k].clamp(0, 999));
        l.centred(fb, 250.0, 320.0, 0.5 + 7.75 * k as f64, 7.0, &text, GOLD);
    }
}

/// A key: a coloured card, or a skull (a card with a pale mark).
fn key_box(fb: &mut Framebuffer, x: usize, y: usize, size: usize, colour: KeyColour, form: KeyForm) {
    let c = match colour {
        KeyColour::Blue => rgb(40, 80, 255),
        KeyColour::Yellow => rgb(250, 220, 40),
        KeyColour::Red => rgb(230, 30, 30),
    };
    fill_rect(fb, x, y, size, size, c);
    if form == KeyForm::Skull {
        fill_rect(fb, x + size / 4, y + size / 4, size / 2, size / 2, rgb(240, 240, 230));
    }
}

/// The face: skin that reddens and bruises as health falls, eyes, a mouth;
/// grey and eyes shut when dead.
fn face(fb: &mut Framebuffer, l: &Layout, player: &Player) {
    let hurt = (100 - player.health.clamp(0, 100)) as u32;
    let skin =
        if player.dead() { rgb(120, 110, 100) } else { rgb(200, (160 - hurt) as u8, (120 - hurt.min(100)) as u8) };
    fill_rect(fb, l.x(150.0), l.y(3.0), l.len(20.0), l.len(27.0), skin);
    let eye = if player.dead() { rgb(60, 40, 40) } else { rgb(250, 250, 250) };
    let eye_h = if player.dead() { 1.0 } else { 3.0 };
    fill_rect(fb, l.x(153.0), l.y(11.0), l.len(5.0), l.len(eye_h), eye);
    fill_rect(fb, l.x(162.0), l.y(11.0), l.len(5.0), l.len(eye_h), eye);
    let mouth = if player.damage_count > 0 { rgb(90, 10, 10) } else { rgb(120, 60, 50) };
    let open = if player.damage_count > 0 { 4.0 } else { 1.5 };
    fill_rect(fb, l.x(155.0), l.y(22.0), l.len(10.0), l.len(open), mouth);
}

/// The minimal HUD: health and armour at the bottom left, the ammunition
/// of the weapon in hand at the bottom right, keys beside it.
pub fn minimal(fb: &mut Framebuffer, _level: &Level, table: &ActorTable, player: &Player) {
    let (s, margin) = scale(fb);
    let l = Layout { s, margin, top: fb.height as f64 - 20.0 * s };
    let k = l.text(10.0);
    let left = format!("{}% {}%", player.health.clamp(0, 999), player.armor);
    draw_text_in(fb, l.x(4.0), l.y(4.0), k, &left, RED);
    if let Some((ammo, _)) = current_ammo(table, player) {
        let text = ammo.to_string();
        let x = l.x(316.0).saturating_sub(text.len() * GLYPH * k);
        draw_text_in(fb, x, l.y(4.0), k, &text, GOLD);
    }
    for (i, key) in player.keys.iter().enumerate() {
        key_box(fb, l.x(250.0 + 10.0 * i as f64), l.y(5.0), l.len(8.0), key.colour, key.form);
    }
}
