//! Floors, ceilings and the sky, per column: each pixel's ray meets the
//! plane at a distance fixed by its row, so flats are sampled
//! perspective-correct at the exact map point; the sky is mapped by view
//! angle, not distance, as Doom maps it.

use std::f64::consts::TAU;

use super::columns::ColumnWriter;
use super::light::Lighting;
use super::view::Camera;
use crate::texture::Texture;

/// How a run of plane rows is painted.
#[derive(Clone, Copy)]
pub enum PlanePaint<'a> {
    Solid(u32),
    /// A flat at `height`, lit by `light`.
    Flat {
        texture: &'a Texture,
        height: f64,
        light: u8,
    },
    Sky(&'a Texture),
}

/// Where the horizon sits in the sky texture, as a share of its height from
/// the top: the lowest fifth (hills) hangs below the horizon.
const SKY_HORIZON: f64 = 0.8;

/// Paints rows `[y0, y1)` of column `x`, whose ray has sideways slope `t`.
pub fn paint_plane(
    out: &mut ColumnWriter,
    cam: &Camera,
    lighting: &Lighting,
    x: usize,
    (y0, y1): (i32, i32),
    t: f64,
    paint: PlanePaint,
) {
    if y1 <= y0 {
        return;
    }
    match paint {
        PlanePaint::Solid(c) => out.fill(x, y0, y1, c),
        PlanePaint::Flat { texture, height, light } => {
            let ray = cam.forward + cam.right * t;
            let rise = height - cam.z;
            out.fill_with(x, y0, y1, |y| {
                // The row's ray reaches the plane after `dist` units of depth;
                // a row on the horizon, or on the wrong side of it, never
                // does: sample it far away rather than divide by zero.
                let dist = (rise / cam.row_slope(y)).clamp(0.0, 1e12);
                let p = cam.eye + ray * dist;
                let texel = texture.wrapped(p.x.floor() as i64, (-p.y).floor() as i64);
                lighting.tint(light, dist).apply(texel)
            });
        }
        PlanePaint::Sky(texture) => {
            let (w, h) = (texture.width as f64, texture.height as f64);
            let texels_per_radian = w / TAU;
            let angle = cam.angle_radians() - t.atan();
            let u = (-angle * texels_per_radian).rem_euclid(w) as usize;
            let column = texture.column(u.min(texture.width - 1));
            out.fill_with(x, y0, y1, |y| {
                let v = h * SKY_HORIZON + (f64::from(y) + 0.5 - cam.cy) / cam.focal * texels_per_radian;
                column[(v.max(0.0) as usize).min(texture.height - 1)]
            });
        }
    }
}
