//! 2D geometry in map units (f64): the predicates that validation, the BSP
//! compiler and the renderers agree on.
//!
//! Convention used everywhere: the *front* of a directed line `a -> b` is its
//! right-hand side. [`front_distance`] is positive in front, negative behind.

use glam::DVec2;

/// Largest coordinate or height magnitude a map may use: 2^24 map units.
///
/// Why this bound: at 2^24 an f64 still resolves 2^-28 units, so view-relative
/// coordinates keep ~28 bits of fraction, and differences of two coordinates
/// (2^25) stay far from where products of them lose the sub-unit detail that
/// one-unit pillars need. Doom's 16.16 fixed point stops at 2^15.
pub const MAX_COORD: f64 = 16_777_216.0;

/// 2D cross product (z of the 3D cross): positive when `b` is counter-clockwise of `a`.
#[inline]
pub fn cross(a: DVec2, b: DVec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Where segment `p-q` crosses segment `a-b`, as a fraction of `p-q`;
/// touching counts.
pub fn crossing(p: DVec2, q: DVec2, a: DVec2, b: DVec2) -> Option<f64> {
    let r = q - p;
    let s = b - a;
    let denom = cross(r, s);
    if denom == 0.0 {
        return None;
    }
    let t = cross(a - p, s) / denom;
    let u = cross(a - p, r) / denom;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then_some(t)
}

/// Distance from `p` to the segment `a-b`.
pub fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    (a + d * t).distance(p)
}

/// Signed distance of `p` from the line through `a` and `b`; positive on the
/// front (right-hand) side. `a != b` is required; the caller guarantees it.
#[inline]
pub fn front_distance(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    let d = b - a;
    cross(p - a, d) / d.length()
}

/// Which side of a directed line a point is on, decided exactly (Shewchuk's
/// adaptive predicate), so that validation never misjudges a near-collinear case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    Front,
    On,
    Back,
}

/// Exact side of `p` relative to the directed line `a -> b`.
pub fn exact_side(a: DVec2, b: DVec2, p: DVec2) -> Side {
    let o = robust::orient2d(coord(a), coord(b), coord(p));
    if o < 0.0 {
        Side::Front
    } else if o > 0.0 {
        Side::Back
    } else {
        Side::On
    }
}

/// Is `p` exactly on the closed segment `a-b` (an end point included)?
pub fn on_segment(a: DVec2, b: DVec2, p: DVec2) -> bool {
    // Collinear exactly; then comparisons of stored coordinates are exact.
    exact_side(a, b, p) == Side::On
        && p.x >= a.x.min(b.x)
        && p.x <= a.x.max(b.x)
        && p.y >= a.y.min(b.y)
        && p.y <= a.y.max(b.y)
}

fn coord(p: DVec2) -> robust::Coord<f64> {
    robust::Coord { x: p.x, y: p.y }
}

/// How two closed segments meet, decided exactly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Contact {
    /// Disjoint, or touching only at a shared endpoint.
    None,
    /// Interiors cross at a single point.
    Cross(DVec2),
    /// An endpoint of one segment lies strictly inside the other.
    Touch(DVec2),
    /// Collinear with an overlap longer than a point.
    Overlap,
}

/// Classifies how segment `p0-p1` meets segment `q0-q1`.
pub fn segment_contact(p0: DVec2, p1: DVec2, q0: DVec2, q1: DVec2) -> Contact {
    let a = exact_side(p0, p1, q0);
    let b = exact_side(p0, p1, q1);
    let c = exact_side(q0, q1, p0);
    let d = exact_side(q0, q1, p1);
    if a == Side::On && b == Side::On {
        return collinear_contact(p0, p1, q0, q1);
    }
    let opposite = |s: Side, t: Side| matches!((s, t), (Side::Front, Side::Back) | (Side::Back, Side::Front));
    if opposite(a, b) && opposite(c, d) {
        return Contact::Cross(line_intersection(p0, p1, q0, q1));
    }
    for (side, point, s0, s1) in [(a, q0, p0, p1), (b, q1, p0, p1), (c, p0, q0, q1), (d, p1, q0, q1)] {
        if side == Side::On && strictly_between(s0, s1, point) {
            return Contact::Touch(point);
        }
    }
    Contact::None
}

/// For a point known to be collinear with `a-b`: is it strictly inside the segment?
fn strictly_between(a: DVec2, b: DVec2, p: DVec2) -> bool {
    if p == a || p == b {
        return false;
    }
    // Comparisons of stored coordinates are exact; use the axis with the larger extent.
    if (b.x - a.x).abs() >= (b.y - a.y).abs() {
        (a.x.min(b.x) < p.x) && (p.x < a.x.max(b.x))
    } else {
        (a.y.min(b.y) < p.y) && (p.y < a.y.max(b.y))
    }
}

fn collinear_contact(p0: DVec2, p1: DVec2, q0: DVec2, q1: DVec2) -> Contact {
    let axis = |v: DVec2| {
        if (p1.x - p0.x).abs() >= (p1.y - p0.y).abs() {
            v.x
        } else {
            v.y
        }
    };
    let (pa, pb) = (axis(p0).min(axis(p1)), axis(p0).max(axis(p1)));
    let (qa, qb) = (axis(q0).min(axis(q1)), axis(q0).max(axis(q1)));
    if pa.max(qa) < pb.min(qb) {
        Contact::Overlap
    } else if strictly_between(p0, p1, q0) {
        Contact::Touch(q0)
    } else if strictly_between(p0, p1, q1) {
        Contact::Touch(q1)
    } else {
        Contact::None
    }
}

/// Intersection of the infinite lines through `p0-p1` and `q0-q1` (not parallel).
pub fn line_intersection(p0: DVec2, p1: DVec2, q0: DVec2, q1: DVec2) -> DVec2 {
    let r = p1 - p0;
    let s = q1 - q0;
    let t = cross(q0 - p0, s) / cross(r, s);
    p0 + r * t
}

/// `x.floor()` as an integer (saturating, NaN to 0, as `x.floor() as i64`
/// is), without the call to libm's `floor` that baseline x86-64 makes: the
/// renderers' per-column and per-span texture wraps use it.
#[inline]
pub fn floor_i64(x: f64) -> i64 {
    let t = x as i64;
    t.saturating_sub(i64::from(t as f64 > x))
}

/// `x.floor()`, to the bit for every finite `x` (a zero keeps its sign, as
/// libm's does), without the libm call; see [`floor_i64`].
#[inline]
pub fn floor(x: f64) -> f64 {
    // Beyond 2^52 every f64 is whole already (and infinities and NaN pass).
    if !(x.abs() < 4_503_599_627_370_496.0) {
        return x;
    }
    let t = x as i64 as f64;
    let t = if t > x { t - 1.0 } else { t };
    // -0.5 floors to -1; -0.0 must stay -0.0, as 0.0 stays 0.0.
    if t == 0.0 {
        0.0f64.copysign(x)
    } else {
        t
    }
}

/// Sine and cosine of an angle in degrees, exact at multiples of 90 degrees so
/// that axis-aligned views cast exactly axis-aligned rays (cos 90 is 0, not 6e-17).
pub fn sin_cos_degrees(degrees: f64) -> (f64, f64) {
    let reduced = degrees.rem_euclid(360.0);
    match reduced {
        0.0 => (0.0, 1.0),
        90.0 => (1.0, 0.0),
        180.0 => (0.0, -1.0),
        270.0 => (-1.0, 0.0),
        _ => reduced.to_radians().sin_cos(),
    }
}

/// Axis-aligned bounding box in map units.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Aabb {
    pub min: DVec2,
    pub max: DVec2,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb { min: DVec2::INFINITY, max: DVec2::NEG_INFINITY };

    pub fn include(&mut self, p: DVec2) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    pub fn union(self, other: Aabb) -> Aabb {
        Aabb { min: self.min.min(other.min), max: self.max.max(other.max) }
    }

    pub fn contains(&self, p: DVec2) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn floors_agree_with_libm() {
        let mut values = vec![0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 1e-300, -1e-300, 2.5, -2.5, 1e15 + 0.5, -1e15 - 0.5];
        values.extend([4_503_599_627_370_496.0, -4_503_599_627_370_497.0, 1e19, -1e19, 1e300, -1e300]);
        values.extend([f64::INFINITY, f64::NEG_INFINITY, f64::MAX, f64::MIN, f64::EPSILON, -f64::EPSILON]);
        values.extend((0..2000).map(|i| (i as f64 - 1000.0) * 0.37 + 1e-9 * i as f64));
        for v in values {
            assert_eq!(floor(v).to_bits(), v.floor().to_bits(), "{v}");
            assert_eq!(floor_i64(v), v.floor() as i64, "{v}");
        }
        assert!(floor(f64::NAN).is_nan());
        assert_eq!(floor_i64(f64::NAN), 0);
    }

    use super::*;

    fn v(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    #[test]
    fn front_is_right_hand_side() {
        // Walking north along x = 0, east (+x) is on the right.
        assert_eq!(exact_side(v(0.0, 0.0), v(0.0, 10.0), v(5.0, 5.0)), Side::Front);
        assert_eq!(exact_side(v(0.0, 0.0), v(0.0, 10.0), v(-5.0, 5.0)), Side::Back);
        assert!(front_distance(v(0.0, 0.0), v(0.0, 10.0), v(5.0, 5.0)) > 0.0);
    }

    #[test]
    fn contacts() {
        let o = v(0.0, 0.0);
        assert!(matches!(segment_contact(o, v(10.0, 10.0), v(0.0, 10.0), v(10.0, 0.0)), Contact::Cross(_)));
        assert_eq!(segment_contact(o, v(10.0, 0.0), v(10.0, 0.0), v(10.0, 5.0)), Contact::None);
        assert_eq!(segment_contact(o, v(10.0, 0.0), v(5.0, 0.0), v(5.0, 5.0)), Contact::Touch(v(5.0, 0.0)));
        assert_eq!(segment_contact(o, v(10.0, 0.0), v(5.0, 0.0), v(15.0, 0.0)), Contact::Overlap);
        assert_eq!(segment_contact(o, v(10.0, 0.0), v(10.0, 0.0), v(15.0, 0.0)), Contact::None);
        // Near-collinear at a million units: decided exactly, not by an epsilon.
        let a = v(1_000_000.0, 1_000_000.0);
        let b = v(1_010_000.0, 1_000_000.0);
        assert_eq!(exact_side(a, b, v(1_005_000.0, 1_000_000.000_000_1)), Side::Back);
    }

    #[test]
    fn axis_angles_are_exact() {
        assert_eq!(sin_cos_degrees(90.0), (1.0, 0.0));
        assert_eq!(sin_cos_degrees(-90.0), (-1.0, 0.0));
        assert_eq!(sin_cos_degrees(720.0), (0.0, 1.0));
    }
}
