//! Floors, ceilings and the sky, per column: each pixel's ray meets the
//! plane at a distance fixed by its row, so flats are sampled
//! perspective-correct at the exact map point; the sky is mapped by view
//! angle, not distance, as Doom maps it.

use std::f64::consts::TAU;

use super::columns::ColumnWriter;
use super::frame::Scene;
use crate::texture::{Texture, TextureId};

/// How a run of plane rows is painted.
#[derive(Clone, Copy)]
pub enum PlanePaint<'a> {
    Solid(u32),
    /// A flat at `height`, lit by `light`.
    Flat {
        id: TextureId,
        texture: &'a Texture,
        height: f64,
        light: u8,
    },
    Sky(&'a Texture),
}

/// Sky texels across a full turn, Doom's: its 256-wide skies repeat four
/// times around (ANGLETOSKYSHIFT maps 360 degrees to 1024 columns). The
/// built-in sky is 1024 wide, once around.
const SKY_TEXELS_AROUND: f64 = 1024.0;

/// Where the horizon sits in the sky texture, as a share of its height from
/// the top: the lowest fifth (hills) hangs below the horizon.
const SKY_HORIZON: f64 = 0.8;

/// Paints rows `[y0, y1)` of column `x`, whose ray has sideways slope `t`.
pub(crate) fn paint_plane(
    out: &mut ColumnWriter,
    scene: &Scene,
    x: usize,
    (y0, y1): (i32, i32),
    t: f64,
    paint: PlanePaint,
) {
    if y1 <= y0 {
        return;
    }
    let (cam, lighting, inv_rows) = (scene.cam, &scene.lighting, scene.inv_rows);
    match paint {
        PlanePaint::Solid(c) => out.fill(x, y0, y1, c),
        PlanePaint::Flat { texture, height, light, .. } => {
            let ray = cam.forward + cam.right * t;
            let rise = height - cam.z;
            let (w, h) = (texture.width as f64, texture.height as f64);
            let (inv_w, inv_h) = (1.0 / w, 1.0 / h);
            out.fill_with(x, y0, y1, |y| {
                // The row's ray reaches the plane after `dist` units of depth;
                // a row on the horizon, or on the wrong side of it, never
                // does: sample it far away (NaN and negatives become 0).
                let dist = rise * inv_rows[y as usize];
                let dist = if dist >= 0.0 { dist.min(1e12) } else { 0.0 };
                let u = wrap(cam.eye.x + ray.x * dist, w, inv_w);
                let v = wrap(-(cam.eye.y + ray.y * dist), h, inv_h);
                lighting.tint(light, dist).apply(texture.texels[u * texture.height + v])
            });
        }
        PlanePaint::Sky(texture) => {
            let (w, h) = (texture.width as f64, texture.height as f64);
            let texels_per_radian = SKY_TEXELS_AROUND / TAU;
            let angle = cam.angle_radians() - t.atan();
            let u = (-angle * texels_per_radian).rem_euclid(w) as usize;
            let column = texture.column(u.min(texture.width - 1));
            let slopes = scene.rows.slopes;
            out.fill_with(x, y0, y1, |y| {
                // `-slope(y)` is `(y + 0.5 - cy) / focal` to the bit.
                let v = h * SKY_HORIZON + -slopes[y as usize] * texels_per_radian;
                column[(v.max(0.0) as usize).min(texture.height - 1)]
            });
        }
    }
}

/// `c` wrapped into `0..size` texels (`inv` is `1 / size`), without the
/// integer division of `rem_euclid` or a call to libm's `floor`.
#[inline]
fn wrap(c: f64, size: f64, inv: f64) -> usize {
    let q = c * inv;
    let whole = q as i64 as f64;
    let whole = if whole > q { whole - 1.0 } else { whole };
    (((q - whole) * size) as usize).min(size as usize - 1)
}
