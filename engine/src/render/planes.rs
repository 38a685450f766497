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

const TEXELS_PER_RADIAN: f64 = SKY_TEXELS_AROUND / TAU;

/// The sky texel row (of a sky `height` texels tall) that a screen row of
/// slope `slope` shows: the same for every column, so a frame tabulates it
/// once ([`SkyView`]).
pub(crate) fn sky_row(height: usize, slope: f64) -> usize {
    // `-slope(y)` is `(y + 0.5 - cy) / focal` to the bit.
    let v = height as f64 * SKY_HORIZON + -slope * TEXELS_PER_RADIAN;
    (v.max(0.0) as usize).min(height - 1)
}

/// What every sky column of a frame shares: the view's angle (an `atan2`
/// once, not per column) and each screen row's sky texel row, for the sky
/// texture `texture_height` texels tall (empty when the frame has no sky).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SkyView<'a> {
    pub angle: f64,
    pub texture_height: usize,
    pub rows: &'a [u32],
}

/// Paints rows `[y0, y1)` of column `x`, whose ray has sideways slope `t`;
/// `sky_column` keeps the column's sky texel column between its sky pieces
/// ([`super::frame::NONE`] until the first finds it).
pub(crate) fn paint_plane(
    out: &mut ColumnWriter,
    scene: &Scene,
    x: usize,
    (y0, y1): (i32, i32),
    t: f64,
    paint: PlanePaint,
    sky_column: &mut u32,
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
            let point = |y: i32| {
                let dist = rise * inv_rows[y as usize];
                let dist = if dist >= 0.0 { dist.min(1e12) } else { 0.0 };
                (cam.eye.x + ray.x * dist, -(cam.eye.y + ray.y * dist), dist)
            };
            if out.sampling.affine_planes || out.sampling.bilinear {
                // Affine: the exact map points at the run's two ends, and
                // texture coordinates linear in screen rows between them
                // (the light too), as renderers without a divide per pixel did.
                let (first, last) = (point(y0), point(y1 - 1));
                let span = f64::from((y1 - 1 - y0).max(1));
                let affine = out.sampling.affine_planes;
                let bilinear = out.sampling.bilinear;
                out.fill_with(x, y0, y1, |y| {
                    let (u, v, dist) = if affine {
                        let s = f64::from(y - y0) / span;
                        (
                            first.0 + (last.0 - first.0) * s,
                            first.1 + (last.1 - first.1) * s,
                            first.2 + (last.2 - first.2) * s,
                        )
                    } else {
                        point(y)
                    };
                    let c = if bilinear {
                        texture.bilinear(u, v)
                    } else {
                        texture.texels[wrap(u, w, inv_w) * texture.height + wrap(v, h, inv_h)]
                    };
                    lighting.tint(light, dist).apply(c)
                });
                return;
            }
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
            if *sky_column == super::frame::NONE {
                let angle = scene.sky.angle - t.atan();
                let u = (-angle * TEXELS_PER_RADIAN).rem_euclid(texture.width as f64) as usize;
                *sky_column = u.min(texture.width - 1) as u32;
            }
            let column = texture.column(*sky_column as usize);
            let sky = scene.sky;
            if sky.texture_height == texture.height && sky.rows.len() == cam.height {
                out.fill_with(x, y0, y1, |y| column[sky.rows[y as usize] as usize]);
            } else {
                let slopes = scene.rows.slopes;
                out.fill_with(x, y0, y1, |y| column[sky_row(texture.height, slopes[y as usize])]);
            }
        }
    }
}

/// `c` wrapped into `0..size` texels (`inv` is `1 / size`), without the
/// integer division of `rem_euclid` or a call to libm's `floor`.
#[inline]
fn wrap(c: f64, size: f64, inv: f64) -> usize {
    let q = c * inv;
    (((q - crate::geom::floor(q)) * size) as usize).min(size as usize - 1)
}
