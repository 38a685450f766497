//! The weapon in hand and its flash (Doom's R_DrawPlayerSprites): each
//! layer's frame, a [`TextureKind::Screen`] picture, drawn at its place on
//! the 320x200 screen (raised, lowered, bobbing), scaled to the frame. It is
//! lit by the light of the sector the player stands in and the weapon's
//! own light, or full bright in a bright frame (the flash).
//!
//! [`TextureKind::Screen`]: crate::texture::TextureKind::Screen

use super::{scale, view_scale};
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
    let (lift, (s, margin)) = if status_bar { (STATUS_LIFT, scale(fb)) } else { (0.0, view_scale(fb)) };
    for p in &player.psprites {
        let Some(state) = p.state else { continue };
        let st = table.state(state);
        let slot = Materials::view_index(st.sprite, st.frame);
        let Some(id) = level.materials.screen_views.get(slot).copied().flatten() else { continue };
        let texture = level.materials.textures.get(id);
        let shade = if st.bright { 1.0 } else { lit };
        blit(fb, texture, (p.sx - 1.0, p.sy - 32.0 - lift), (s, margin), shade);
    }
}

/// Draws a screen picture with its top-left at (`x`, `y`) in 320x200
/// units, `s` pixels a unit from `margin` pixels left of the frame (a
/// negative margin: left of its edge), its opaque texels darkened by
/// `shade`.
fn blit(
    fb: &mut Framebuffer,
    texture: &crate::texture::Texture,
    (x, y): (f64, f64),
    (s, margin): (f64, f64),
    shade: f32,
) {
    let x0 = margin + x * s;
    let y0 = y * s;
    // Only the screen pixels over the texels that show: texel u covers
    // pixels whose centres fall in [x0 + u s, x0 + (u + 1) s).
    let [u0, u1, v0, v1] = texture.shown;
    let span = |origin: f64, t0: usize, t1: usize, limit: usize| {
        // One pixel wider each side than the exact bounds: a rounding there
        // only adds a pixel whose texel is tested below.
        let first = ((origin + t0 as f64 * s - 0.5).ceil() - 1.0).max(0.0) as usize;
        let end = ((origin + t1 as f64 * s - 0.5).ceil() + 1.0).max(0.0).min(limit as f64) as usize;
        first..end.max(first)
    };
    let k = (shade * 256.0) as u32;
    let d = |c: u8| ((u32::from(c) * k) >> 8).min(255) as u8;
    // The texel index under screen pixel `p` of an axis, if inside.
    let texel = |p: usize, origin: f64, size: usize| {
        let t = ((p as f64 + 0.5 - origin) / s).floor();
        (t >= 0.0 && t < size as f64).then_some(t as usize)
    };
    // The texel row of each screen row and the texel column of each screen
    // column, found once for the whole picture.
    let rows: Vec<(usize, usize)> =
        span(y0, v0, v1, fb.height).filter_map(|py| texel(py, y0, texture.height).map(|v| (py, v))).collect();
    // A screen column's texel column is monotone in it, so the columns
    // inside the picture are one run, from `first`.
    let across = span(x0, u0, u1, fb.width);
    let Some(first) = across.clone().find(|&px| texel(px, x0, texture.width).is_some()) else { return };
    let columns: Vec<&[u32]> =
        (first..across.end).map_while(|px| texel(px, x0, texture.width).map(|u| texture.column(u))).collect();
    // Each texel row lit once into `line` (0 where the picture is clear),
    // then laid on every screen row it covers as one run the compiler
    // keeps in vector registers. Writing pixel by pixel, branching on each
    // texel's alpha, cost 9% of a 640x480 ViZDoom frame.
    let mut line = vec![0u32; columns.len()];
    let mut lit_row = usize::MAX;
    for &(py, v) in &rows {
        if v != lit_row {
            for (lit, column) in line.iter_mut().zip(&columns) {
                let [r, g, b, a] = column[v].to_le_bytes();
                *lit = if a >= 128 { u32::from_le_bytes([d(r), d(g), d(b), 255]) } else { 0 };
            }
            lit_row = v;
        }
        let row = &mut fb.pixels[py * fb.width + first..][..line.len()];
        for (pixel, &lit) in row.iter_mut().zip(&line) {
            *pixel = if lit >> 24 != 0 { lit } else { *pixel };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::Texture;

    /// Every screen pixel looked up on its own: the texel under its centre.
    fn reference(fb: &mut Framebuffer, texture: &Texture, x: f64, y: f64, (s, margin): (f64, f64)) {
        for py in 0..fb.height {
            for px in 0..fb.width {
                let u = ((px as f64 + 0.5 - (margin + x * s)) / s).floor();
                let v = ((py as f64 + 0.5 - y * s) / s).floor();
                if u < 0.0 || v < 0.0 || u >= texture.width as f64 || v >= texture.height as f64 {
                    continue;
                }
                let t = texture.texel(u as usize, v as usize);
                if t >> 24 >= 128 {
                    fb.pixels[py * fb.width + px] = t | 0xff00_0000;
                }
            }
        }
    }

    #[test]
    fn a_picture_is_drawn_where_its_texels_show_and_nowhere_else() {
        // A 320x200 picture showing only a ragged patch, as the procedural
        // weapons are, at several screen sizes and offsets (some off screen).
        let picture = Texture::from_fn(320, 200, |u, v| {
            let shows = (100..170).contains(&u) && (120..200).contains(&v) && (u * 7 + v * 3) % 5 != 0;
            [(u % 256) as u8, (v % 256) as u8, 9, if shows { 255 } else { 0 }]
        });
        assert_eq!(picture.shown, [100, 170, 120, 200]);
        for (w, h) in [(160, 120), (320, 200), (333, 211), (640, 480), (97, 61), (400, 225)] {
            for (x, y) in [(0.0, 0.0), (-1.0, -32.0), (13.7, 5.25), (-120.0, 40.0), (250.0, -150.0)] {
                for scaling in [scale, view_scale] {
                    let frame = Framebuffer::new(w, h);
                    let (mut fast, mut slow) = (frame.clone(), frame.clone());
                    blit(&mut fast, &picture, (x, y), scaling(&frame), 1.0);
                    reference(&mut slow, &picture, x, y, scaling(&frame));
                    assert!(fast.pixels == slow.pixels, "{w}x{h} at ({x}, {y}), {:?}", scaling(&frame));
                }
            }
        }
        let clear = Texture::from_fn(4, 4, |_, _| [1, 2, 3, 0]);
        assert_eq!(clear.shown, [0, 0, 0, 0]);
        let mut fb = Framebuffer::new(160, 120);
        let scaling = scale(&fb);
        blit(&mut fb, &clear, (0.0, 0.0), scaling, 1.0);
        assert!(fb.pixels.iter().all(|&p| p == Framebuffer::new(160, 120).pixels[0]));
    }

    #[test]
    fn without_the_status_bar_the_weapon_takes_the_height_s_scale_as_zdoom_draws_it() {
        // ViZDoom 1.3.2 with its HUD off puts Freedoom's pistol (top offset
        // -97) at rows 129-199 of 320x200, 155-239 of 320x240, 77-119 of
        // 160x120 and 145-224 of 400x225: Doom's 320x200 place times the
        // height over 200, centred across the width.
        for ((w, h), top) in [((320, 200), 129), ((320, 240), 155), ((160, 120), 77), ((400, 225), 145)] {
            let frame = Framebuffer::new(w, h);
            let (s, margin) = view_scale(&frame);
            assert_eq!((129.0 * s).round(), f64::from(top), "{w}x{h}");
            assert!((margin + 160.0 * s - w as f64 / 2.0).abs() < 1e-9, "{w}x{h}: centred");
        }
        // With the status bar the screen keeps fitting the width: 320x240
        // draws Doom's 320x200 at scale 1.
        assert_eq!(scale(&Framebuffer::new(320, 240)), (1.0, 0.0));
    }
}
