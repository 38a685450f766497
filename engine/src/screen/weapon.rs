//! The weapon in hand and its flash (Doom's R_DrawPlayerSprites): each
//! layer's frame, a [`TextureKind::Screen`] picture, drawn at its place on
//! the 320x200 screen (raised, lowered, bobbing), scaled to the frame. It is
//! lit by the light of the sector the player stands in and the weapon's
//! own light, or full bright in a bright frame (the flash).
//!
//! [`TextureKind::Screen`]: crate::texture::TextureKind::Screen

use super::scale;
use crate::actors::ActorTable;
use crate::framebuffer::Framebuffer;
use crate::level::Level;
use crate::materials::Materials;
use crate::play::Player;

/// How far the weapon is drawn up with the status bar showing (Doom's
/// view window is 168 rows high, its centre 16 rows above the screen's).
pub const STATUS_LIFT: f64 = 16.0;

/// `table` is the game's actor table, whose states the player's sprites
/// are in (a scenario's DECORATE weapons are in its own).
pub fn draw(fb: &mut Framebuffer, level: &Level, table: &ActorTable, player: &Player, status_bar: bool) {
    let light = level.compiled.map.sectors.get(player.sector).map_or(255, |s| i32::from(s.light));
    let lit = ((light + 16 * player.extra_light) as f32 / 255.0).clamp(0.2, 1.0);
    let lift = if status_bar { STATUS_LIFT } else { 0.0 };
    for p in &player.psprites {
        let Some(state) = p.state else { continue };
        let s = table.state(state);
        let slot = Materials::view_index(s.sprite, s.frame);
        let Some(id) = level.materials.screen_views.get(slot).copied().flatten() else { continue };
        let texture = level.materials.textures.get(id);
        let shade = if s.bright { 1.0 } else { lit };
        blit(fb, texture, p.sx - 1.0, p.sy - 32.0 - lift, shade);
    }
}

/// Draws a screen picture with its top-left at (`x`, `y`) in 320x200
/// units, its opaque texels darkened by `shade`.
fn blit(fb: &mut Framebuffer, texture: &crate::texture::Texture, x: f64, y: f64, shade: f32) {
    let (s, margin) = scale(fb);
    let x0 = margin + x * s;
    let y0 = y * s;
    let (w, h) = (texture.width as f64 * s, texture.height as f64 * s);
    let px0 = x0.max(0.0).floor() as usize;
    let py0 = y0.max(0.0).floor() as usize;
    let px1 = ((x0 + w).ceil().max(0.0) as usize).min(fb.width);
    let py1 = ((y0 + h).ceil().max(0.0) as usize).min(fb.height);
    let k = (shade * 256.0) as u32;
    let d = |c: u8| ((u32::from(c) * k) >> 8).min(255) as u8;
    // The texel row of each screen row, found once for the whole picture.
    let texel = |p: usize, origin: f64, size: usize| {
        let t = ((p as f64 + 0.5 - origin) / s).floor();
        (t >= 0.0 && t < size as f64).then_some(t as usize)
    };
    let rows: Vec<(usize, usize)> =
        (py0..py1).filter_map(|py| texel(py, y0, texture.height).map(|v| (py, v))).collect();
    for px in px0..px1 {
        let Some(u) = texel(px, x0, texture.width) else { continue };
        let column = &texture.texels[u * texture.height..(u + 1) * texture.height];
        for &(py, v) in &rows {
            let [r, g, b, a] = column[v].to_le_bytes();
            if a >= 128 {
                fb.pixels[py * fb.width + px] = u32::from_le_bytes([d(r), d(g), d(b), 255]);
            }
        }
    }
}
