//! Small 3D models rendered into sprites: the roster's monsters, the items
//! and the weapons on the screen are a few solids each (balls, limbs,
//! blocks), posed per frame, seen from Doom's eight directions, lit by one
//! light that stays with the viewer, and outlined so they read at 320x200.
//!
//! Coordinates are map units, x forward (where the figure faces), y to its
//! left, z up, the origin on the floor under its middle. A picture's
//! bottom-middle texel is that origin, as the renderer stands sprites.
//!
//! Rendering is orthographic ray casting with 3x3 samples per texel: a texel
//! is opaque when most of its samples hit (masks stay binary), and its
//! colour is the mean of the hits. Then a dark line is drawn round the
//! silhouette and where a nearer part overlaps a farther one.

use glam::{Mat3, Vec3};

use super::paint::{mix, opaque, scale, Rgb, CLEAR};
use crate::texture::Texture;

/// The shape of a solid, in model coordinates.
#[derive(Clone, Copy, Debug)]
pub enum Solid {
    /// An ellipsoid: its centre, and its radii along its axes (`Part::axes`).
    Ball { centre: Vec3, radii: Vec3 },
    /// The points within `radius` of the segment from `a` to `b`.
    Limb { a: Vec3, b: Vec3, radius: f32 },
    /// A box: its centre, and half its size along its axes.
    Block { centre: Vec3, half: Vec3 },
}

/// A solid with its colour.
#[derive(Clone, Copy, Debug)]
pub struct Part {
    pub solid: Solid,
    /// The solid's axes (columns), for balls and blocks: a rotation.
    pub axes: Mat3,
    pub colour: Rgb,
    /// Lit by itself: drawn in its colour whatever the light (eyes, flames).
    pub glow: bool,
    /// 0 for matte; up to 1 for a metal's highlight.
    pub shine: f32,
}

impl Part {
    pub fn ball(centre: Vec3, radii: Vec3, colour: Rgb) -> Part {
        Part { solid: Solid::Ball { centre, radii }, axes: Mat3::IDENTITY, colour, glow: false, shine: 0.0 }
    }

    pub fn sphere(centre: Vec3, radius: f32, colour: Rgb) -> Part {
        Part::ball(centre, Vec3::splat(radius), colour)
    }

    pub fn limb(a: Vec3, b: Vec3, radius: f32, colour: Rgb) -> Part {
        Part { solid: Solid::Limb { a, b, radius }, axes: Mat3::IDENTITY, colour, glow: false, shine: 0.0 }
    }

    pub fn block(centre: Vec3, half: Vec3, colour: Rgb) -> Part {
        Part { solid: Solid::Block { centre, half }, axes: Mat3::IDENTITY, colour, glow: false, shine: 0.0 }
    }

    pub fn glowing(self) -> Part {
        Part { glow: true, ..self }
    }

    pub fn shiny(self, shine: f32) -> Part {
        Part { shine, ..self }
    }

    /// Turned by `axes` about its own centre (a limb: about its first end).
    pub fn turned(self, axes: Mat3) -> Part {
        match self.solid {
            Solid::Limb { a, b, radius } => Part { solid: Solid::Limb { a, b: a + axes * (b - a), radius }, ..self },
            _ => Part { axes: axes * self.axes, ..self },
        }
    }

    /// Moved by `m` about the origin (a whole figure falling, turning).
    pub fn moved(self, m: Mat3, by: Vec3) -> Part {
        let solid = match self.solid {
            Solid::Ball { centre, radii } => Solid::Ball { centre: m * centre + by, radii },
            Solid::Limb { a, b, radius } => Solid::Limb { a: m * a + by, b: m * b + by, radius },
            Solid::Block { centre, half } => Solid::Block { centre: m * centre + by, half },
        };
        Part { solid, axes: m * self.axes, ..self }
    }

    /// The lowest point of the part.
    fn bottom(&self) -> f32 {
        match self.solid {
            // The lowest point of a turned ellipsoid: its centre less the
            // length of diag(radii) * axesᵀ * z.
            Solid::Ball { centre, radii } => centre.z - (self.axes.transpose() * Vec3::Z * radii).length(),
            Solid::Limb { a, b, radius } => a.z.min(b.z) - radius,
            Solid::Block { centre, half } => centre.z - (self.axes.transpose() * Vec3::Z).abs().dot(half),
        }
    }

    /// A sphere holding the whole part: its centre and radius.
    fn bounding_sphere(&self) -> (Vec3, f32) {
        match self.solid {
            Solid::Ball { centre, radii } => (centre, radii.max_element()),
            Solid::Limb { a, b, radius } => ((a + b) * 0.5, (b - a).length() * 0.5 + radius),
            Solid::Block { centre, half } => (centre, half.length()),
        }
    }

    /// Where a ray from `o` along unit `d` first enters the part: the
    /// distance and the outward normal there.
    fn hit(&self, o: Vec3, d: Vec3) -> Option<(f32, Vec3)> {
        match self.solid {
            Solid::Ball { centre, radii } => {
                // In the ball's frame, scaled to a unit sphere.
                let inv = self.axes.transpose();
                let (lo, ld) = ((inv * (o - centre)) / radii, (inv * d) / radii);
                let (a, b, c) = (ld.dot(ld), lo.dot(ld), lo.dot(lo) - 1.0);
                let disc = b * b - a * c;
                if disc < 0.0 {
                    return None;
                }
                let t = (-b - disc.sqrt()) / a;
                let p = lo + ld * t;
                Some((t, (self.axes * (p / radii)).normalize()))
            }
            Solid::Limb { a, b, radius } => limb_hit(o, d, a, b, radius),
            Solid::Block { centre, half } => {
                let inv = self.axes.transpose();
                let (lo, ld) = (inv * (o - centre), inv * d);
                let (mut near, mut far, mut axis) = (f32::MIN, f32::MAX, 0);
                for k in 0..3 {
                    if ld[k].abs() < 1e-9 {
                        if lo[k].abs() > half[k] {
                            return None;
                        }
                        continue;
                    }
                    let (t0, t1) = ((-half[k] - lo[k]) / ld[k], (half[k] - lo[k]) / ld[k]);
                    let (t0, t1) = (t0.min(t1), t0.max(t1));
                    if t0 > near {
                        (near, axis) = (t0, k);
                    }
                    far = far.min(t1);
                }
                if near > far {
                    return None;
                }
                let mut n = Vec3::ZERO;
                n[axis] = -ld[axis].signum();
                Some((near, self.axes * n))
            }
        }
    }
}

/// The entry into a capsule: the nearer of its cylinder's side and its two
/// end spheres.
fn limb_hit(o: Vec3, d: Vec3, a: Vec3, b: Vec3, r: f32) -> Option<(f32, Vec3)> {
    let mut best: Option<(f32, Vec3)> = None;
    let mut keep = |t: f32, n: Vec3| {
        if best.is_none_or(|(bt, _)| t < bt) {
            best = Some((t, n));
        }
    };
    for c in [a, b] {
        let oc = o - c;
        let (bb, cc) = (oc.dot(d), oc.dot(oc) - r * r);
        let disc = bb * bb - cc;
        if disc >= 0.0 {
            let t = -bb - disc.sqrt();
            keep(t, (oc + d * t) / r);
        }
    }
    let axis = b - a;
    let len = axis.length();
    if len > 1e-6 {
        let w = axis / len;
        let (dp, op) = (d - w * d.dot(w), (o - a) - w * (o - a).dot(w));
        let (qa, qb, qc) = (dp.dot(dp), op.dot(dp), op.dot(op) - r * r);
        let disc = qb * qb - qa * qc;
        if qa > 1e-9 && disc >= 0.0 {
            let t = (-qb - disc.sqrt()) / qa;
            let along = (o + d * t - a).dot(w);
            if (0.0..=len).contains(&along) {
                keep(t, (op + dp * t) / r);
            }
        }
    }
    best
}

/// Lifts a figure so that its lowest point is on the floor.
pub fn settle(parts: &mut [Part]) {
    let low = parts.iter().map(Part::bottom).fold(f32::MAX, f32::min);
    if low.is_finite() {
        for p in parts.iter_mut() {
            *p = p.moved(Mat3::IDENTITY, Vec3::new(0.0, 0.0, -low));
        }
    }
}

/// How a picture is taken.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// Where the viewer is, seen from the figure: degrees anticlockwise
    /// from its front (Doom's rotation 1 is 0, rotation 2 is 45, ...).
    pub around: f32,
    /// Degrees above the horizontal the viewer looks down from.
    pub above: f32,
    /// Picture size in texels (one texel per map unit, times `zoom`).
    pub size: (usize, usize),
    /// Texels per map unit.
    pub zoom: f32,
    /// The model point at the picture's bottom-middle (the origin for a
    /// sprite; for a weapon on the screen, a point below the hand).
    pub origin: Vec3,
    /// Line colour round the figure; `None` for none.
    pub outline: Option<Rgb>,
    /// How far the eye is from the origin, for a picture in perspective (a
    /// weapon in hand); `None` looks from afar (orthographic).
    pub eye: Option<f32>,
}

impl Camera {
    /// A sprite seen from Doom's `rotation` (1 front, 3 its left, 5 back).
    pub fn sprite(rotation: u8, size: (usize, usize)) -> Camera {
        Camera {
            around: 45.0 * f32::from(rotation.max(1) - 1),
            above: 10.0,
            size,
            zoom: 1.0,
            origin: Vec3::ZERO,
            outline: Some([0.04, 0.03, 0.03]),
            eye: None,
        }
    }
}

/// What one texel saw.
#[derive(Clone, Copy)]
struct Sample {
    colour: Rgb,
    depth: f32,
}

/// Renders `parts` as a picture, the camera's origin at its bottom-middle.
pub fn render(parts: &[Part], camera: &Camera) -> Texture {
    render_at(parts, camera, (camera.size.0 as f32 / 2.0, camera.size.1 as f32))
}

/// Renders `parts` with the camera's origin at texel position `anchor`.
pub fn render_at(parts: &[Part], camera: &Camera, anchor: (f32, f32)) -> Texture {
    let (w, h) = camera.size;
    let (th, ph) = (camera.around.to_radians(), camera.above.to_radians());
    // `toward` points from the figure to the viewer; rays go the other way.
    let toward = Vec3::new(th.cos() * ph.cos(), th.sin() * ph.cos(), ph.sin());
    let right = (-toward).cross(Vec3::Z).normalize();
    let up = right.cross(-toward);
    // The light: from the viewer's upper left, a little in front.
    let light = (toward * 0.7 - right * 0.45 + up * 0.55).normalize();
    const N: usize = 3;
    // Looking from afar, a part can only cover the texels within its
    // bounding sphere's outline: each texel tests those parts alone. (A
    // stand-in of forty parts 60x80 texels took 20 ms testing all of them.)
    let bounds: Option<Vec<[f32; 4]>> = camera.eye.is_none().then(|| {
        parts
            .iter()
            .map(|p| {
                let (c, r) = p.bounding_sphere();
                let d = c - camera.origin;
                let (x, y) = (anchor.0 + d.dot(right) * camera.zoom, anchor.1 - d.dot(up) * camera.zoom);
                let r = r * camera.zoom + 1.5;
                [x - r, x + r, y - r, y + r]
            })
            .collect()
    });
    let mut texels: Vec<Option<Sample>> = vec![None; w * h];
    let mut near: Vec<&Part> = Vec::with_capacity(parts.len());
    for v in 0..h {
        for u in 0..w {
            near.clear();
            let (fu, fv) = (u as f32 + 0.5, v as f32 + 0.5);
            match &bounds {
                Some(b) => near.extend(
                    parts
                        .iter()
                        .zip(b)
                        .filter(|(_, b)| b[0] <= fu && fu <= b[1] && b[2] <= fv && fv <= b[3])
                        .map(|(p, _)| p),
                ),
                None => near.extend(parts.iter()),
            }
            if near.is_empty() {
                continue;
            }
            let (mut sum, mut hits, mut depth) = ([0.0f32; 3], 0usize, f32::MAX);
            for sv in 0..N {
                for su in 0..N {
                    let x = (u as f32 + (su as f32 + 0.5) / N as f32 - anchor.0) / camera.zoom;
                    let y = (anchor.1 - v as f32 - (sv as f32 + 0.5) / N as f32) / camera.zoom;
                    let on_plane = camera.origin + right * x + up * y;
                    let (o, d) = match camera.eye {
                        Some(far) => {
                            let eye = camera.origin + toward * far;
                            (eye, (on_plane - eye).normalize())
                        }
                        None => (on_plane + toward * 1000.0, -toward),
                    };
                    let nearest = near
                        .iter()
                        .filter_map(|&p| p.hit(o, d).map(|(t, n)| (t, n, p)))
                        .filter(|h| h.0 > 0.0)
                        .min_by(|a, b| a.0.total_cmp(&b.0));
                    if let Some((t, n, p)) = nearest {
                        let c = shade(p, n, light, -d);
                        sum = [sum[0] + c[0], sum[1] + c[1], sum[2] + c[2]];
                        hits += 1;
                        depth = depth.min(t);
                    }
                }
            }
            if hits * 2 > N * N {
                texels[v * w + u] = Some(Sample { colour: scale(sum, 1.0 / hits as f32), depth });
            }
        }
    }
    let at = |u: i64, v: i64| -> Option<Sample> {
        if u < 0 || v < 0 || u >= w as i64 || v >= h as i64 {
            None
        } else {
            texels[v as usize * w + u as usize]
        }
    };
    Texture::from_fn(w, h, |u, v| {
        // Keep the outer columns clear, as every sprite does.
        if u == 0 || u == w - 1 {
            return CLEAR;
        }
        let (ui, vi) = (u as i64, v as i64);
        let near = [(1, 0), (-1, 0), (0, 1), (0, -1)].map(|(du, dv)| at(ui + du, vi + dv));
        match (at(ui, vi), camera.outline) {
            (Some(s), line) => {
                // A farther texel next to a much nearer one: a crease line.
                let behind = near.iter().flatten().any(|n| s.depth - n.depth > 6.0 / camera.zoom.max(1.0));
                match line {
                    Some(c) if behind => opaque(mix(s.colour, c, 0.7)),
                    _ => opaque(s.colour),
                }
            }
            (None, Some(c)) if near.iter().any(Option::is_some) => opaque(c),
            _ => CLEAR,
        }
    })
}

/// A part's colour under the light, seen along `toward`.
fn shade(p: &Part, n: Vec3, light: Vec3, toward: Vec3) -> Rgb {
    if p.glow {
        return p.colour;
    }
    let diffuse = n.dot(light).max(0.0);
    // A rim of light where the surface turns away: the shape reads round.
    let rim = (1.0 - n.dot(toward).max(0.0)).powi(3) * 0.25;
    let half = (light + toward).normalize();
    let spec = p.shine * n.dot(half).max(0.0).powi(24);
    let k = 0.32 + 0.78 * diffuse + rim;
    let c = scale(p.colour, k);
    [c[0] + spec, c[1] + spec, c[2] + spec]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ball_on_the_floor_fills_a_disc_with_a_line_round_it() {
        let ball = [Part::sphere(Vec3::new(0.0, 0.0, 8.0), 7.0, [0.8, 0.2, 0.2])];
        let t = render(&ball, &Camera { above: 0.0, ..Camera::sprite(1, (20, 18)) });
        let a = |u: usize, v: usize| t.texel(u, v) >> 24;
        assert_eq!(a(10, 10), 255);
        assert_eq!(a(2, 2), 0);
        // The line: the texel just outside the disc at mid-height is dark.
        let rgb = t.texel(2, 10).to_le_bytes();
        assert_eq!(rgb[3], 255);
        assert!(rgb[..3].iter().all(|&c| c < 20), "{rgb:?}");
        // Lit from the upper left: the left of the ball is brighter than the right.
        let luma = |u, v| t.texel(u, v).to_le_bytes()[..3].iter().map(|&c| u32::from(c)).sum::<u32>();
        assert!(luma(6, 7) > luma(14, 12));
    }

    #[test]
    fn a_turned_figure_shows_its_side() {
        // A long block along x: narrow from the front, long from the side.
        let rod = [Part::block(Vec3::new(0.0, 0.0, 4.0), Vec3::new(12.0, 2.0, 4.0), [0.5; 3])];
        let width = |rotation| {
            let t = render(&rod, &Camera { outline: None, ..Camera::sprite(rotation, (40, 12)) });
            (0..40).filter(|&u| t.texel(u, 8) >> 24 == 255).count()
        };
        assert_eq!(width(1), 4);
        assert_eq!(width(3), 24);
        assert_eq!(width(5), 4);
    }

    #[test]
    fn settling_puts_the_lowest_point_on_the_floor() {
        let mut parts = [
            Part::sphere(Vec3::new(0.0, 0.0, 20.0), 5.0, [1.0; 3]),
            Part::limb(Vec3::new(0.0, 0.0, 12.0), Vec3::new(0.0, 4.0, 30.0), 2.0, [1.0; 3]),
        ];
        settle(&mut parts);
        assert!(parts.iter().map(Part::bottom).fold(f32::MAX, f32::min).abs() < 1e-4);
    }
}
