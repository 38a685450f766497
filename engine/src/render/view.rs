//! The viewer and the projection from map units to screen columns and rows.
//!
//! Screen conventions shared by every renderer: column `x` samples the ray
//! through its centre `x + 0.5`; a surface covers row `y` when the row centre
//! `y + 0.5` lies inside its projected interval (so an interval `[a, b)`
//! covers rows `ceil(a - 0.5) .. ceil(b - 0.5)`). Pixels are square, so the
//! vertical focal length equals the horizontal one.

use glam::DVec2;

use crate::bsp::CompiledMap;
use crate::geom::sin_cos_degrees;

/// Nothing nearer than this (map units of depth) is drawn.
///
/// Why 1e-4: walls 0.01 units from the eye must still show; and a box or wall
/// 1 unit from the eye but nearer than this in depth lies at least 1e4 times
/// further sideways than forward, far off any screen narrower than 179.9 degrees.
pub const NEAR: f64 = 1e-4;

/// Depths this close (relative) are one: crossings of a ray through a
/// shared vertex, or a thing standing at a wall's vertex. Two computations
/// of one point's depth (from either line through it, or from the thing's
/// position) can differ in their last bits, and both renderers must then
/// decide alike.
pub const TIE: f64 = 1e-9;

/// Is a wall or middle at depth `near` in front of a sprite at `depth`?
/// Depths within [`TIE`] are one, and a sprite against a wall is in front of
/// it. The one rule for both renderers (the walk's clip windows, the
/// reference's ray).
#[inline]
pub fn hides_sprite(near: f64, depth: f64) -> bool {
    depth - near > near * TIE
}

/// Eye height above the floor when a pose gives none (Doom's viewheight).
pub const EYE_HEIGHT: f64 = 41.0;

/// Where the viewer stands and looks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    pub pos: DVec2,
    /// Eye height in map units.
    pub z: f64,
    /// Degrees, counter-clockwise from +x.
    pub angle: f64,
    /// Horizontal field of view in degrees.
    pub fov: f64,
}

impl View {
    pub fn new(pos: DVec2, z: f64, angle: f64) -> View {
        View { pos, z, angle, fov: 90.0 }
    }
}

/// A view bound to a screen size: the basis and focal length every stage uses.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    pub eye: DVec2,
    pub z: f64,
    /// Unit vector of the view direction.
    pub forward: DVec2,
    /// Unit vector to the viewer's right (screen x grows this way).
    pub right: DVec2,
    pub width: usize,
    pub height: usize,
    /// Pixels per unit of slope (`(width / 2) / tan(fov / 2)`).
    pub focal: f64,
    pub cx: f64,
    pub cy: f64,
}

impl Camera {
    pub fn new(view: &View, width: usize, height: usize) -> Camera {
        let (sin, cos) = sin_cos_degrees(view.angle);
        let forward = DVec2::new(cos, sin);
        let right = DVec2::new(sin, -cos);
        // tan(45 degrees) computes as 0.9999999999999999; make the default exact.
        let fov = if view.fov.is_finite() { view.fov.clamp(1.0, 179.0) } else { 90.0 };
        let tan_half = if fov == 90.0 { 1.0 } else { (fov / 2.0).to_radians().tan() };
        let focal = (width as f64 / 2.0) / tan_half;
        Camera {
            eye: view.pos,
            z: view.z,
            forward,
            right,
            width,
            height,
            focal,
            cx: width as f64 / 2.0,
            cy: height as f64 / 2.0,
        }
    }

    /// The view direction in radians, counter-clockwise from +x.
    pub fn angle_radians(&self) -> f64 {
        self.forward.y.atan2(self.forward.x)
    }

    /// Slope (sideways per unit forward) of the ray through column `x`'s centre.
    #[inline]
    pub fn column_slope(&self, x: usize) -> f64 {
        (x as f64 + 0.5 - self.cx) / self.focal
    }

    /// Camera coordinates `(depth, sideways)` of a map point, computed from the
    /// view-relative offset so that far-out maps keep their precision.
    #[inline]
    pub fn to_camera(&self, p: DVec2) -> DVec2 {
        let q = p - self.eye;
        DVec2::new(q.dot(self.forward), q.dot(self.right))
    }

    /// Is the camera-space point `p` (depth, sideways) on or left of column
    /// `x`'s ray? The one predicate that decides which column owns a point
    /// exactly on a ray, in every renderer: a wall owns its left end's column,
    /// not its right end's, so walls sharing a vertex never both take it.
    #[inline]
    pub fn left_of_or_on(&self, p: DVec2, x: usize) -> bool {
        p.y <= self.column_slope(x) * p.x
    }

    /// The first column whose ray has `p` (camera space, depth > 0) on or to its
    /// left, in `0..=width`. The projection gives the answer up to rounding;
    /// [`Self::left_of_or_on`] settles it.
    pub fn first_column_at_or_right(&self, p: DVec2) -> usize {
        self.first_column_by(p, |x| self.column_slope(x))
    }

    /// [`Self::first_column_at_or_right`] with each column's slope looked up
    /// in `slopes` (`slopes[x] == self.column_slope(x)`, the frame's table):
    /// the same answer without a division per column tried.
    #[inline]
    pub(crate) fn first_column_in(&self, slopes: &[f64], p: DVec2) -> usize {
        self.first_column_by(p, |x| slopes[x])
    }

    #[inline]
    fn first_column_by(&self, p: DVec2, slope: impl Fn(usize) -> f64) -> usize {
        let sx = self.cx + p.y / p.x * self.focal;
        // The searches below end on the same column from any start; from
        // the ceil, each tests once and stops.
        let mut x = ceil_within(sx - 0.5, self.width) as usize;
        // `left_of_or_on`, with the slope given.
        let left_of_or_on = |x: usize| p.y <= slope(x) * p.x;
        while x > 0 && left_of_or_on(x - 1) {
            x -= 1;
        }
        while x < self.width && !left_of_or_on(x) {
            x += 1;
        }
        x
    }

    /// Slope (up per unit forward) of the ray through row `y`'s centre.
    #[inline]
    pub fn row_slope(&self, y: i32) -> f64 {
        (self.cy - (f64::from(y) + 0.5)) / self.focal
    }

    /// Does row `y`'s ray, at `depth`, pass above `height`? The one predicate
    /// that decides, in every renderer, which surface a row centre exactly on
    /// an edge belongs to: heights above an edge belong to what is above it.
    #[inline]
    pub fn row_above(&self, y: i32, depth: f64, height: f64) -> bool {
        self.z + depth * self.row_slope(y) > height
    }

    /// The first row whose ray at `depth` is at or below `height`, in
    /// `0..=height_px`. The projection gives it up to rounding;
    /// [`Self::row_above`] settles it.
    pub fn first_row_at_or_below(&self, depth: f64, height: f64) -> i32 {
        let sy = self.cy - (height - self.z) * self.focal / depth;
        // NaN clamps to NaN and casts to 0: harmless, never UB.
        let mut y = ceil_within(sy - 0.5, self.height);
        while y > 0 && !self.row_above(y - 1, depth, height) {
            y -= 1;
        }
        while y < self.height as i32 && self.row_above(y, depth, height) {
            y += 1;
        }
        y
    }

    /// Every row's slope ([`Self::row_slope`]), top to bottom.
    pub fn row_slopes(&self) -> impl Iterator<Item = f64> + '_ {
        (0..self.height as i32).map(|y| self.row_slope(y))
    }

    /// Columns `[x0, x1)` covered by the segment `a -> b` (camera coordinates),
    /// after clipping it to depth >= [`NEAR`]. The segment must face the viewer
    /// (viewer on its right), so that `a` projects left of `b`.
    pub fn project_span(&self, a: DVec2, b: DVec2) -> Option<(usize, usize)> {
        self.project_span_by(a, b, |p| self.first_column_at_or_right(p))
    }

    /// [`Self::project_span`] with the frame's column slopes (see [`Self::first_column_in`]).
    #[inline]
    pub(crate) fn project_span_in(&self, slopes: &[f64], a: DVec2, b: DVec2) -> Option<(usize, usize)> {
        self.project_span_by(a, b, |p| self.first_column_in(slopes, p))
    }

    #[inline]
    fn project_span_by(&self, a: DVec2, b: DVec2, column: impl Fn(DVec2) -> usize) -> Option<(usize, usize)> {
        let (mut a, mut b) = (a, b);
        if a.x < NEAR && b.x < NEAR {
            return None;
        }
        if a.x < NEAR {
            a = a + (b - a) * ((NEAR - a.x) / (b.x - a.x));
        } else if b.x < NEAR {
            b = b + (a - b) * ((NEAR - b.x) / (a.x - b.x));
        }
        let (x0, x1) = (column(a), column(b));
        (x0 < x1).then_some((x0, x1))
    }
}

/// `x` clamped to `0..=max` and rounded up, without libm's `ceil` (a call
/// on baseline x86-64). NaN clamps to NaN and casts to 0: harmless.
#[inline]
fn ceil_within(x: f64, max: usize) -> i32 {
    let x = x.clamp(0.0, max as f64);
    let t = x as i32;
    t + i32::from(f64::from(t) < x)
}

/// The row predicates of a [`Camera`] with every row's slope looked up in a
/// table made once a frame (`slopes[y] == cam.row_slope(y)`, the same
/// numbers, so the same answers): in the walk's per-column row searches a
/// multiply and an add instead of a division per row tried.
#[derive(Clone, Copy)]
pub(crate) struct Rows<'a> {
    pub cam: &'a Camera,
    pub slopes: &'a [f64],
}

impl Rows<'_> {
    /// [`Camera::row_above`].
    #[inline]
    pub fn above(&self, y: i32, depth: f64, height: f64) -> bool {
        self.cam.z + depth * self.slopes[y as usize] > height
    }

    /// [`Camera::first_row_at_or_below`], with `scale = focal / depth`
    /// (computed once per column) for the first guess. The guess's rounding
    /// does not matter: `above` is monotone in `y`, so the search ends on the
    /// same row from any start.
    #[inline]
    pub fn first_at_or_below(&self, depth: f64, scale: f64, height: f64) -> i32 {
        let cam = self.cam;
        let sy = cam.cy - (height - cam.z) * scale;
        // From the ceil, the searches below test once each and stop, but
        // at rounding's edge: a start off by one cost a third of the walls'
        // per-column time in mispredicted loop exits (the first guess was a
        // truncation, to avoid libm's `ceil`).
        let mut y = ceil_within(sy - 0.5, cam.height);
        while y > 0 && !self.above(y - 1, depth, height) {
            y -= 1;
        }
        while y < cam.height as i32 && self.above(y, depth, height) {
            y += 1;
        }
        y
    }
}

/// Why a pose cannot be used.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum PoseError {
    #[error("pose ({x}, {y}) is not inside any sector (in a hole, outside the map, or on a one-sided wall)")]
    Outside { x: f64, y: f64 },
    #[error("pose has a value that is not finite")]
    NotFinite,
}

impl View {
    /// A view at `(x, y)` looking at `angle`; the eye `z` defaults to
    /// [`EYE_HEIGHT`] above the floor of the sector there. Any point of the
    /// map will do, one on a two-sided line or vertex too: its sector is the
    /// one point location gives ([`CompiledMap::locate`]: on a partition
    /// line, the partition's front).
    pub fn at_pose(compiled: &CompiledMap, x: f64, y: f64, angle: f64, z: Option<f64>) -> Result<View, PoseError> {
        if ![x, y, angle, z.unwrap_or(0.0)].iter().all(|v| v.is_finite()) {
            return Err(PoseError::NotFinite);
        }
        let pos = DVec2::new(x, y);
        let sector = compiled.locate(pos).ok_or(PoseError::Outside { x, y })?;
        let z = z.unwrap_or(compiled.map.sectors[sector].floor + EYE_HEIGHT);
        Ok(View::new(pos, z, angle))
    }

    /// The view from the map's player start.
    pub fn at_start(compiled: &CompiledMap) -> Result<View, PoseError> {
        let start = compiled.map.player_start();
        View::at_pose(compiled, start.pos.x, start.pos.y, start.angle, None)
    }
}
