//! Sight and shots: the geometry questions of Doom's `p_sight.c` (can one
//! body see another, P_CheckSight) and of the attack half of `p_map.c` (what
//! a shot hits, P_LineAttack; where auto-aim points, P_AimLineAttack). Each
//! comes twice and the two answer identically: a fast path that asks the BSP
//! which lines lie near the segment ([`sight`], [`hitscan`], [`aim_slope`])
//! and a brute-force oracle that tries every line of the map
//! ([`sight_brute`], [`hitscan_brute`], [`aim_slope_brute`]). It hands the
//! simulation a bool, a [`Hit`] or an [`Aimed`] slope; it changes nothing.
//!
//! **The model.** Everything happens in the vertical plane over the 2D
//! segment from `p` (the looker or shooter) to `q` (the target, or the end of
//! the shot's range), at fractions `f` of it (0 at `p`, 1 at `q`). A line
//! acts wherever the closed segment meets it ([`meet`]). Sector heights are
//! read from `Map::sectors` at the call, so moving floors and ceilings count.
//! A two-sided line's *opening* is the higher of its two floors up to the
//! lower of its two ceilings; it is *closed* when that floor is at or above
//! that ceiling. Every two-sided line acts by its opening, not only those
//! whose floors (or ceilings) differ as in Doom: Doom's shortcut lets a line
//! of sight or a shot dip under a floor and come back up between lines of
//! one floor height, where here it is stopped at the first line it is under.
//!
//! **Sight** (P_CheckSight). From the looker's eye, `z + 3/4 height`, to the
//! target's extent `[z, z + height]`: a window of slopes (height per unit of
//! `f`) starts as the target's extent seen at `f = 1`. A one-sided line met
//! anywhere blocks; a closed opening blocks; an open one narrows the window to
//! the slopes through it at each `f` where it is met. The target is seen when
//! nothing blocked and the window is still open (top above bottom, strictly:
//! Doom's `topslope <= bottomslope` fails).
//!
//! **Shots** (P_LineAttack). From `(origin, z)` along `angle` (degrees) with
//! `slope` (height per horizontal unit) up to `range` (Doom's 2048 for
//! bullets, [`crate::play::SHOT_RANGE`]; 64 for melee, [`MELEE_RANGE`]). The shot
//! stops at the first of:
//! - a one-sided wall ([`Part::Middle`]);
//! - a two-sided line whose opening is closed or does not hold the shot's
//!   height there: [`Part::Lower`] below the opening's floor, else
//!   [`Part::Upper`];
//! - a body: the shot enters its box, a square `2 radius` on a side, axis
//!   aligned, from `z` to `z + height` (the whole box, entered in 3D; not
//!   Doom's bounding-box diagonal facing the shooter, which makes a hit
//!   depend on the direction of the shot). The shooter's own body is skipped;
//!   the caller passes only shootable bodies;
//! - the sky: a wall hit above the sky ceiling of the sector the shot comes
//!   from, or below its sky floor, or the upper part between two sky ceilings
//!   (where the renderer draws sky, `shade::ceiling_at_line`) is
//!   [`Struck::Sky`]: the shot stops with no puff (PTR_ShootTraverse returns
//!   without P_SpawnPuff).
//!
//! The puff goes 4 units short of a wall and the blood 10 short of a body,
//! as Doom's; unlike Doom, never behind the origin. Floors and ceilings are
//! not hit between lines (as in Doom): a shot aimed into the floor stops at
//! the next line it meets, as that line's lower part, where its height is
//! already under the floor.
//!
//! **Auto-aim** (P_AimLineAttack). The window of slopes starts at `±100/160`
//! ([`AIM_SLOPE`]) and narrows at every line in order of distance as sight's
//! does (a one-sided line or a closed opening ends the search); the first body
//! whose box, at the distance where the shot enters it, shows within the
//! window is the target, and the slope is the middle of the part of it the
//! window shows (Doom's clipped middle, not the body's own middle when the
//! window cuts it).
//!
//! **Tie rules.** Decided exactly (orient2d), and the same in both paths.
//! - *Touching counts.* A segment through a vertex meets every line ending
//!   there: exactly through the corner of a pillar, the end of a wall or a
//!   door jamb, sight is blocked and a shot hits the wall; through a vertex
//!   where only two-sided lines meet it passes if it is inside each opening
//!   there.
//! - *Along a line* (collinear, overlapping more than a point): a one-sided
//!   wall stops it where the overlap begins; a two-sided line acts at both
//!   ends of the overlap (the segment and the opening's limits are straight,
//!   so both ends inside means every point between is); a shot is stopped
//!   where its height leaves the opening.
//! - *Starting on a line* (`f = 0`): a one-sided line blocks (the shot hits
//!   it at the muzzle); for a two-sided line, slopes mean nothing at distance
//!   0, so sight and aim ask only that the eye (shot height) be within the
//!   opening, limits included; a shot is checked like anywhere else.
//! - *Ending on a line* (a target exactly on it, `f = 1`): an ordinary
//!   contact. A target on a one-sided line is never seen; on a two-sided one
//!   the opening at the target narrows the window.
//! - *Equal distances*: lines before bodies (a body flush with a wall is
//!   behind it), then the lower line or body index. Lines meeting the
//!   segment at one vertex get one fraction ([`meet`]), so they do tie.
//! - *The side a shot comes from* is the origin's side of the line, a point
//!   on the line counting as in front (the BSP's tie rule).
//! - *Huge coordinates*: every decision is an exact orientation, so a map at
//!   ±30,000 (or anywhere within `geom::MAX_COORD`) is judged as at the
//!   origin; only fractions and heights carry rounding.
//!
//! **Why the two paths agree bit for bit.** Both run the same per-line
//! function (where the segment meets the line, and what that does to the
//! window or the shot) on the same sector heights, and combine its results in
//! a way that does not depend on the order lines come in: a minimum, a
//! maximum, "any blocks", or a sort by (fraction, index). So they agree
//! exactly as long as the fast path offers every line the segment meets. It
//! does: the descent enters a child whenever the segment comes within a
//! margin of its side of the partition and of the box round its segs. Every
//! seg lies on its side of each ancestor's partition to within the compiler's
//! `ON_EPSILON` (1e-6, plus 1e-12 of the coordinates for split points: what
//! `bsp::check` allows), the pieces of a line's side cover the line, and a
//! node's boxes bound its children's segs (the renderer's culling relies on
//! that too); so a point where the segment meets a line is within that
//! tolerance of the leaf holding the piece through it, and a margin of a
//! hundred times the tolerance reaches that leaf (a test moves partitions by
//! `ON_EPSILON` to prove it; with no margin it fails). The descent never
//! prunes by fraction: a fraction is computed, not decided, and at a glancing
//! angle a line could be listed nearer than the subtree it lies in.
//!
//! **Why the BSP, not the blockmap.** Doom 1.2 walked the blockmap for sight
//! (Heretic kept that code; ports keep it as `P_CheckSight_12` for old demos)
//! and 1.666 the BSP (P_CrossBSPNode). Here the argument above rests on
//! invariants the compiler states and `bsp::check` verifies, and needs no cell
//! size: the blockmap's grid is private to it and grows its cells on huge maps
//! (512 a side at most), so a walk along the segment would query boxes not
//! matched to its cells. The descent costs the nodes whose cells and boxes the
//! segment passes near, whatever the map's extent. Measured (20,000 pairs of
//! points in the map, bodies 56 high on the floor; release build, the shared
//! 2-core VM, two runs, microseconds per query), fast / brute force / the
//! blockmap (every line in the cells of the segment's bounding box, as
//! `trace.rs` queries, then the window):
//!
//! | map | lines | sight | shot, 2048 units |
//! |---|---|---|---|
//! | E1M1 (freedoom1) | 812 | 1.5-2.0 / 2.5-3.2 / 1.6-2.6 | 5.3-7.7 / 10-13 |
//! | MAP10 (freedoom2) | 3,154 | 3.3-3.8 / 7.0-8.9 / 4.5-5.8 | 8-12 / 46-48 |
//! | maze.ron | 2,290 | 0.5-0.6 / 6.4-7.5 / 1.8-2.2 | 5.4-7.0 / 26-32 |
//!
//! The brute force is not far behind on small maps because most pairs are
//! blocked by a wall it reaches early and its box test rejects most lines
//! without an orientation; it grows with the map, the descent barely.

use std::cmp::Ordering;
use std::ops::ControlFlow;

use glam::{DVec2, DVec3};

use crate::bsp::{Bsp, Child, CompiledMap, LineSide};
use crate::geom::{cross, on_segment, sin_cos_degrees, Aabb};
use crate::map::{Line, Map, Sector};

/// Doom's `MELEERANGE`: a punch or a saw reaches 64 units.
pub const MELEE_RANGE: f64 = 64.0;
/// Auto-aim looks this far up and down (Doom's `100*FRACUNIT/160`: the
/// height of the view over the width, at Doom's 320x200 with a 90 degree field).
pub const AIM_SLOPE: f64 = 100.0 / 160.0;
/// The eye is this share of a body's height above its feet (Doom:
/// `height - (height >> 2)`).
pub const EYE_SHARE: f64 = 0.75;
/// Doom spawns a wall's puff this far back along the shot.
pub const PUFF_BACK: f64 = 4.0;
/// And a body's blood this far back.
pub const BLOOD_BACK: f64 = 10.0;

/// A body as sight and shots see it: where it stands, how tall and wide it
/// is, and the caller's name for it (reported back in hits).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    pub pos: DVec2,
    /// Its feet.
    pub z: f64,
    pub height: f64,
    /// Half the side of its square box.
    pub radius: f64,
    pub index: usize,
}

impl Body {
    /// Where it looks from.
    pub fn eye(&self) -> f64 {
        self.z + self.height * EYE_SHARE
    }

    fn valid(&self) -> bool {
        self.pos.is_finite()
            && self.z.is_finite()
            && self.height.is_finite()
            && self.radius.is_finite()
            && self.height >= 0.0
            && self.radius >= 0.0
    }
}

/// A shot's or an aim's line: from `origin` at height `z` along `angle`
/// (degrees, counter-clockwise from +x) for `range` map units; the body with
/// index `shooter` is not hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    pub origin: DVec2,
    pub z: f64,
    pub angle: f64,
    pub range: f64,
    pub shooter: Option<usize>,
}

impl Ray {
    /// Where the range ends (exact along the axes: [`sin_cos_degrees`]).
    pub fn end(&self) -> DVec2 {
        let (sin, cos) = sin_cos_degrees(self.angle);
        self.origin + DVec2::new(cos, sin) * self.range
    }

    fn valid(&self) -> bool {
        self.origin.is_finite() && self.z.is_finite() && self.angle.is_finite() && self.range.is_finite()
    }
}

/// How the closed segment `p -> q` meets a closed line segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Meet {
    /// At one point, this fraction of the way from `p` to `q`.
    Point(f64),
    /// Along it (collinear), from the first fraction to the second (larger).
    Along(f64, f64),
}

impl Meet {
    pub fn first(self) -> f64 {
        match self {
            Meet::Point(f) | Meet::Along(f, _) => f,
        }
    }

    /// The fractions where the line acts: the point, or both ends of the overlap.
    fn ends(self) -> impl Iterator<Item = f64> {
        let (a, b) = match self {
            Meet::Point(f) => (f, None),
            Meet::Along(f0, f1) => (f0, Some(f1)),
        };
        std::iter::once(a).chain(b)
    }
}

/// The wall part a shot hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// A one-sided wall.
    Middle,
    /// A two-sided line below its opening's floor.
    Lower,
    /// A two-sided line above its opening's ceiling (or in a closed opening).
    Upper,
}

/// What a shot stopped at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Struck {
    /// Line `line`, on the side the shot came from.
    Wall { line: usize, side: LineSide, part: Part },
    /// Line `line`, where the sky is: the shot is gone, with no puff.
    Sky { line: usize },
    /// The body with this index.
    Body { index: usize },
}

/// Where a shot stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    pub struck: Struck,
    /// Fraction of the range.
    pub fraction: f64,
    /// The point struck.
    pub point: DVec3,
    /// Where the puff (a wall) or the blood (a body) appears; none in the sky.
    pub puff: Option<DVec3>,
}

/// Auto-aim's answer: the slope (height per horizontal unit) and the body it aims at.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aimed {
    pub slope: f64,
    pub index: usize,
}

/// Reusable scratch for the fast paths: the descent's stack, a stamp per
/// line so each is tried once per query (Doom's `validcount`), and the
/// contacts auto-aim sorts. Cleared per query, never shrunk.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    walk: Walk,
    events: Vec<Event>,
    bodies: Vec<(f64, usize)>,
}

#[derive(Clone, Debug, Default)]
struct Walk {
    stack: Vec<Child>,
    seen: Vec<u32>,
    stamp: u32,
}

/// Can `looker` see `target`? Through the BSP; the same answer as
/// [`sight_brute`] on every input.
pub fn sight(compiled: &CompiledMap, scratch: &mut Scratch, looker: &Body, target: &Body) -> bool {
    let Some(mut window) = Window::new(looker, target) else { return false };
    let map = &compiled.map;
    let _ = bsp_lines(map, &compiled.bsp, &mut scratch.walk, looker.pos, target.pos, |i| window.cross(map, i));
    window.open()
}

/// [`sight`] by trying every line of the map.
pub fn sight_brute(map: &Map, looker: &Body, target: &Body) -> bool {
    let Some(mut window) = Window::new(looker, target) else { return false };
    for i in 0..map.lines.len() {
        if window.cross(map, i).is_break() {
            break;
        }
    }
    window.open()
}

/// The first thing a shot along `ray` with `slope` hits, through the BSP;
/// `None` when it reaches its range. The same answer as [`hitscan_brute`].
pub fn hitscan(compiled: &CompiledMap, scratch: &mut Scratch, ray: &Ray, slope: f64, bodies: &[Body]) -> Option<Hit> {
    let shot = Shot::new(ray, slope)?;
    let map = &compiled.map;
    let mut best = None;
    let _ = bsp_lines(map, &compiled.bsp, &mut scratch.walk, shot.p, shot.q, |i| {
        shot.keep_first(&mut best, map, i);
        ControlFlow::Continue(())
    });
    shot.finish(best, bodies)
}

/// [`hitscan`] by trying every line of the map.
pub fn hitscan_brute(map: &Map, ray: &Ray, slope: f64, bodies: &[Body]) -> Option<Hit> {
    let shot = Shot::new(ray, slope)?;
    let mut best = None;
    for i in 0..map.lines.len() {
        shot.keep_first(&mut best, map, i);
    }
    shot.finish(best, bodies)
}

/// Auto-aim along `ray` (its `z` is the shot's height): the slope to the
/// nearest body in view within [`AIM_SLOPE`] up or down, through the BSP;
/// `None` when there is none. The same answer as [`aim_slope_brute`].
pub fn aim_slope(compiled: &CompiledMap, scratch: &mut Scratch, ray: &Ray, bodies: &[Body]) -> Option<Aimed> {
    let aim = Aim::new(ray)?;
    let map = &compiled.map;
    let Scratch { walk, events, bodies: order } = scratch;
    events.clear();
    let _ = bsp_lines(map, &compiled.bsp, walk, aim.p, aim.q, |i| {
        aim.events(map, i, events);
        ControlFlow::Continue(())
    });
    aim.first_in_view(events, order, bodies)
}

/// [`aim_slope`] by trying every line of the map.
pub fn aim_slope_brute(map: &Map, ray: &Ray, bodies: &[Body]) -> Option<Aimed> {
    let aim = Aim::new(ray)?;
    let mut events = Vec::new();
    for i in 0..map.lines.len() {
        aim.events(map, i, &mut events);
    }
    aim.first_in_view(&mut events, &mut Vec::new(), bodies)
}

/// How the closed segment `p -> q` meets the closed segment `a-b`, decided
/// exactly; `None` when they do not touch. Where they cross, the fraction is
/// `o_p / (o_p - o_q)` from the orientations of `p` and `q` against `a-b`;
/// at `p` it is exactly 0, at `q` exactly 1, and at an end of `a-b` (a map
/// vertex) it is measured along `p -> q`'s longer axis, so every line ending
/// at that vertex meets the segment at the same fraction and ties are ties.
/// The answer does not depend on which way round the line is given. A
/// zero-length `p -> q` meets a line it lies on at 0.
pub fn meet(p: DVec2, q: DVec2, a: DVec2, b: DVec2) -> Option<Meet> {
    if p == q {
        return on_segment(a, b, p).then_some(Meet::Point(0.0));
    }
    // Closed boxes apart (compared exactly): the segments are too. Most
    // lines offered are rejected here, before any orientation.
    let (lo, hi) = (p.min(q), p.max(q));
    if a.x.max(b.x) < lo.x || a.x.min(b.x) > hi.x || a.y.max(b.y) < lo.y || a.y.min(b.y) > hi.y {
        return None;
    }
    let (op, oq) = (orient(a, b, p), orient(a, b, q));
    if op == 0.0 && oq == 0.0 {
        return collinear(p, q, a, b);
    }
    let same = |x: f64, y: f64| (x > 0.0 && y > 0.0) || (x < 0.0 && y < 0.0);
    let (oa, ob) = (orient(p, q, a), orient(p, q, b));
    // Both ends of one strictly on one side of the other: apart. Otherwise,
    // not being collinear, they share exactly one point.
    if same(op, oq) || same(oa, ob) {
        return None;
    }
    let f = if op == 0.0 {
        0.0
    } else if oq == 0.0 {
        1.0
    } else if oa == 0.0 {
        along(p, q, a)
    } else if ob == 0.0 {
        along(p, q, b)
    } else {
        // Opposite signs: |op - oq| = |op| + |oq| rounded, never below |op|, so f is in [0, 1].
        op / (op - oq)
    };
    Some(Meet::Point(f))
}

/// `p`, `q`, `a`, `b` on one line (`p != q`): compare coordinates along
/// `p -> q`'s longer axis, which is exact for points known to be collinear.
fn collinear(p: DVec2, q: DVec2, a: DVec2, b: DVec2) -> Option<Meet> {
    let d = q - p;
    let axis = |v: DVec2| if d.x.abs() >= d.y.abs() { v.x } else { v.y };
    let (pa, qa) = (axis(p), axis(q));
    let from = axis(a).min(axis(b)).max(pa.min(qa));
    let to = axis(a).max(axis(b)).min(pa.max(qa));
    if from > to {
        return None;
    }
    // The overlap's ends are ends of one segment or the other.
    let end = |v: f64| [p, q, a, b].into_iter().find(|&e| axis(e) == v).map_or(0.0, |e| along(p, q, e));
    let (t0, t1) = (end(from), end(to));
    let (f0, f1) = (t0.min(t1), t0.max(t1));
    Some(if f0 == f1 { Meet::Point(f0) } else { Meet::Along(f0, f1) })
}

/// The fraction of `p -> q` at `v`, a point on it, measured along its
/// longer axis: exactly 0 at `p` and 1 at `q`.
fn along(p: DVec2, q: DVec2, v: DVec2) -> f64 {
    let d = q - p;
    let (pa, qa, va) = if d.x.abs() >= d.y.abs() { (p.x, q.x, v.x) } else { (p.y, q.y, v.y) };
    if v == p {
        0.0
    } else if v == q {
        1.0
    } else {
        ((va - pa) / (qa - pa)).clamp(0.0, 1.0)
    }
}

/// Orientation of `c` against `a -> b`: positive to the left, exact in sign.
fn orient(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    let coord = |p: DVec2| robust::Coord { x: p.x, y: p.y };
    robust::orient2d(coord(a), coord(b), coord(c))
}

/// A two-sided line's opening: the higher floor and the lower ceiling, with
/// the sector on the side the segment comes from (the back when
/// `from_back`) and the one across; `None` for a one-sided line.
fn opening<'m>(map: &'m Map, line: &Line, from_back: bool) -> Option<(f64, f64, &'m Sector, &'m Sector)> {
    let back = line.back.as_ref()?;
    let (front, back) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
    let (near, far) = if from_back { (back, front) } else { (front, back) };
    Some((front.floor.max(back.floor), front.ceiling.min(back.ceiling), near, far))
}

/// How far the descent reaches past a partition: a hundred times the
/// compiler's `ON_EPSILON` and the 1e-12 of the coordinates its split points
/// may stray (`bsp::check` allows 4 `ON_EPSILON` plus that), which also
/// covers the rounding of the distances themselves (about 1e-8 at
/// `geom::MAX_COORD`).
fn margin(scale: f64) -> f64 {
    1e-4 + 1e-10 * scale
}

/// Calls `visit` once with every line that has a seg in a leaf whose cell
/// comes within [`margin`] of the segment `p -> q`, nearer subtrees first,
/// until `visit` breaks.
fn bsp_lines(
    map: &Map,
    bsp: &Bsp,
    walk: &mut Walk,
    p: DVec2,
    q: DVec2,
    mut visit: impl FnMut(usize) -> ControlFlow<()>,
) -> ControlFlow<()> {
    if walk.seen.len() != map.lines.len() {
        walk.seen = vec![0; map.lines.len()];
        walk.stamp = 0;
    }
    walk.stamp = walk.stamp.wrapping_add(1);
    if walk.stamp == 0 {
        walk.seen.fill(0);
        walk.stamp = 1;
    }
    let reach = p.abs().max(q.abs()).max_element();
    walk.stack.clear();
    walk.stack.push(bsp.root);
    while let Some(child) = walk.stack.pop() {
        match child {
            Child::Leaf(i) => {
                for seg in bsp.leaf_segs(&bsp.leaves[i]) {
                    if walk.seen[seg.line] != walk.stamp {
                        walk.seen[seg.line] = walk.stamp;
                        visit(seg.line)?;
                    }
                }
            }
            Child::Node(i) => {
                let node = &bsp.nodes[i];
                let m = margin(reach.max(node.a.abs().max(node.b.abs()).max_element()));
                // Distances from the partition times its length (positive in
                // front), against the margin times a length at least as long
                // (|dx| + |dy|): no square root, and a margin of m to 1.42 m.
                let d = node.b - node.a;
                let (dp, dq) = (cross(p - node.a, d), cross(q - node.a, d));
                let slack = m * (d.x.abs() + d.y.abs());
                // A child is entered when the segment comes within the margin
                // of its half-plane and of the box round its segs.
                let reaches = [dp.max(dq) >= -slack, dp.min(dq) <= slack];
                let order = if dp >= 0.0 { [1, 0] } else { [0, 1] };
                // Popped last-in first-out: the far child goes on first.
                for k in order {
                    if reaches[k] && near_box(p, q, &node.bbox[k], m) {
                        walk.stack.push(node.children[k]);
                    }
                }
            }
        }
    }
    ControlFlow::Continue(())
}

/// Sight's window of slopes, in height per unit of fraction.
struct Window {
    p: DVec2,
    q: DVec2,
    eye: f64,
    top: f64,
    bottom: f64,
    blocked: bool,
}

impl Window {
    fn new(looker: &Body, target: &Body) -> Option<Window> {
        if !(looker.valid() && target.valid()) {
            return None;
        }
        let eye = looker.eye();
        Some(Window {
            p: looker.pos,
            q: target.pos,
            eye,
            top: target.z + target.height - eye,
            bottom: target.z - eye,
            blocked: false,
        })
    }

    /// Line `i` acts on the window; breaks once the target cannot be seen.
    fn cross(&mut self, map: &Map, i: usize) -> ControlFlow<()> {
        let line = &map.lines[i];
        let (a, b) = map.line_points(line);
        let Some(meet) = meet(self.p, self.q, a, b) else { return ControlFlow::Continue(()) };
        match opening(map, line, false) {
            Some((floor, ceiling, ..)) if floor < ceiling => {
                for f in meet.ends() {
                    if f == 0.0 {
                        self.blocked |= !(floor <= self.eye && self.eye <= ceiling);
                    } else {
                        self.top = self.top.min((ceiling - self.eye) / f);
                        self.bottom = self.bottom.max((floor - self.eye) / f);
                    }
                }
            }
            _ => self.blocked = true,
        }
        if self.open() {
            ControlFlow::Continue(())
        } else {
            ControlFlow::Break(())
        }
    }

    fn open(&self) -> bool {
        !self.blocked && self.top > self.bottom
    }
}

/// A shot being traced: its segment and heights.
struct Shot {
    p: DVec2,
    q: DVec2,
    z: f64,
    slope: f64,
    range: f64,
    shooter: Option<usize>,
}

/// A candidate first hit, ordered by fraction, then lines before bodies, then index.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    fraction: f64,
    struck: Struck,
}

impl Candidate {
    fn key(&self) -> (f64, u8, usize) {
        match self.struck {
            Struck::Wall { line, .. } | Struck::Sky { line } => (self.fraction, 0, line),
            Struck::Body { index } => (self.fraction, 1, index),
        }
    }

    fn before(&self, other: &Candidate) -> bool {
        let (a, b) = (self.key(), other.key());
        a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)) == Ordering::Less
    }
}

impl Shot {
    fn new(ray: &Ray, slope: f64) -> Option<Shot> {
        if !(ray.valid() && slope.is_finite() && ray.range > 0.0) {
            return None;
        }
        Some(Shot { p: ray.origin, q: ray.end(), z: ray.z, slope, range: ray.range, shooter: ray.shooter })
    }

    fn height(&self, f: f64) -> f64 {
        self.z + self.slope * (f * self.range)
    }

    fn at(&self, f: f64) -> DVec3 {
        let xy = self.p + (self.q - self.p) * f;
        DVec3::new(xy.x, xy.y, self.height(f))
    }

    /// Keeps in `best` whichever stops the shot first: it, or line `i`.
    fn keep_first(&self, best: &mut Option<Candidate>, map: &Map, i: usize) {
        if let Some(c) = self.line_hit(map, i) {
            if best.is_none_or(|b| c.before(&b)) {
                *best = Some(c);
            }
        }
    }

    /// Where line `i` alone would stop the shot.
    fn line_hit(&self, map: &Map, i: usize) -> Option<Candidate> {
        let line = &map.lines[i];
        let (a, b) = map.line_points(line);
        let meet = meet(self.p, self.q, a, b)?;
        let from_back = orient(a, b, self.p) > 0.0;
        let side = if from_back { LineSide::Back } else { LineSide::Front };
        let Some((floor, ceiling, near, far)) = opening(map, line, from_back) else {
            let near = &map.sectors[line.front.sector];
            let f = meet.first();
            return Some(self.stop(i, side, Part::Middle, f, near, None));
        };
        let part = |z: f64| if z < floor { Part::Lower } else { Part::Upper };
        let inside = |z: f64| floor < ceiling && floor <= z && z <= ceiling;
        let (f, part) = match meet {
            Meet::Point(f) => {
                let z = self.height(f);
                if inside(z) {
                    return None;
                }
                (f, part(z))
            }
            Meet::Along(f0, f1) => {
                let (z0, z1) = (self.height(f0), self.height(f1));
                if !inside(z0) {
                    (f0, part(z0))
                } else if inside(z1) {
                    return None;
                } else {
                    // It leaves the opening between the ends, through the limit it passes.
                    let limit = if z1 < floor { floor } else { ceiling };
                    let f = f0 + (limit - z0) / (z1 - z0) * (f1 - f0);
                    (f.clamp(f0, f1), part(z1))
                }
            }
        };
        Some(self.stop(i, side, part, f, near, Some(far)))
    }

    /// The shot stops at line `line`: on the wall, or in the sky.
    fn stop(&self, line: usize, side: LineSide, part: Part, f: f64, near: &Sector, far: Option<&Sector>) -> Candidate {
        let z = self.height(f);
        let sky_hack = part == Part::Upper && near.ceiling_is_sky() && far.is_some_and(Sector::ceiling_is_sky);
        let sky = sky_hack || (z > near.ceiling && near.ceiling_is_sky()) || (z < near.floor && near.floor_is_sky());
        let struck = if sky { Struck::Sky { line } } else { Struck::Wall { line, side, part } };
        Candidate { fraction: f, struck }
    }

    /// Where the shot enters `body`'s box, as a fraction, if it does.
    fn body_hit(&self, body: &Body) -> Option<f64> {
        if Some(body.index) == self.shooter || !body.valid() {
            return None;
        }
        let (t0, t1) = box_span(self.p, self.q, body)?;
        let rise = self.slope * self.range;
        let (lo, hi) = (body.z, body.z + body.height);
        let (u0, u1) = if rise == 0.0 {
            if self.z < lo || self.z > hi {
                return None;
            }
            (t0, t1)
        } else {
            let (a, b) = ((lo - self.z) / rise, (hi - self.z) / rise);
            (t0.max(a.min(b)), t1.min(a.max(b)))
        };
        (u0 <= u1).then_some(u0)
    }

    /// The nearer of the first line hit and the first body hit, with its points.
    fn finish(&self, line: Option<Candidate>, bodies: &[Body]) -> Option<Hit> {
        let mut best = line;
        for body in bodies {
            if let Some(f) = self.body_hit(body) {
                let c = Candidate { fraction: f, struck: Struck::Body { index: body.index } };
                if best.is_none_or(|b| c.before(&b)) {
                    best = Some(c);
                }
            }
        }
        let c = best?;
        let back = match c.struck {
            Struck::Wall { .. } => Some(PUFF_BACK),
            Struck::Body { .. } => Some(BLOOD_BACK),
            Struck::Sky { .. } => None,
        };
        let puff = back.map(|b| self.at((c.fraction - b / self.range).max(0.0)));
        Some(Hit { struck: c.struck, fraction: c.fraction, point: self.at(c.fraction), puff })
    }
}

/// The fractions `[t0, t1]` over which the segment `p -> q` is inside the
/// closed square box of `body` (seen from above), if it ever is.
fn box_span(p: DVec2, q: DVec2, body: &Body) -> Option<(f64, f64)> {
    slab_span(p, q, body.pos - body.radius, body.pos + body.radius)
}

/// Does the segment `p -> q` come within `m` of `bbox`? (True for a box
/// that is not finite, which no compiled tree has.)
fn near_box(p: DVec2, q: DVec2, bbox: &Aabb, m: f64) -> bool {
    !(bbox.min.is_finite() && bbox.max.is_finite()) || slab_span(p, q, bbox.min - m, bbox.max + m).is_some()
}

/// The fractions over which the segment `p -> q` is inside the closed box
/// `lo..=hi` (Liang and Barsky's clipping), if it ever is.
fn slab_span(p: DVec2, q: DVec2, lo: DVec2, hi: DVec2) -> Option<(f64, f64)> {
    let d = q - p;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (start, step, lo, hi) in [(p.x, d.x, lo.x, hi.x), (p.y, d.y, lo.y, hi.y)] {
        if step == 0.0 {
            if start < lo || start > hi {
                return None;
            }
        } else {
            let (a, b) = ((lo - start) / step, (hi - start) / step);
            t0 = t0.max(a.min(b));
            t1 = t1.min(a.max(b));
        }
    }
    (t0 <= t1).then_some((t0, t1))
}

/// What a line does to auto-aim at one fraction.
#[derive(Clone, Copy, Debug)]
struct Event {
    fraction: f64,
    line: usize,
    /// `None`: the search ends here; else the opening's floor and ceiling.
    opening: Option<(f64, f64)>,
}

/// An auto-aim being traced.
struct Aim {
    p: DVec2,
    q: DVec2,
    z: f64,
    range: f64,
    shooter: Option<usize>,
}

/// A slope to a height `dz` away at horizontal distance `dist`: at distance
/// 0 straight up or down (level when the heights are equal).
fn slope_to(dz: f64, dist: f64) -> f64 {
    if dist > 0.0 {
        dz / dist
    } else if dz == 0.0 {
        0.0
    } else {
        dz.signum() * f64::INFINITY
    }
}

impl Aim {
    fn new(ray: &Ray) -> Option<Aim> {
        if !(ray.valid() && ray.range > 0.0) {
            return None;
        }
        Some(Aim { p: ray.origin, q: ray.end(), z: ray.z, range: ray.range, shooter: ray.shooter })
    }

    /// Line `i`'s events, into `out`.
    fn events(&self, map: &Map, i: usize, out: &mut Vec<Event>) {
        let line = &map.lines[i];
        let (a, b) = map.line_points(line);
        let Some(meet) = meet(self.p, self.q, a, b) else { return };
        match opening(map, line, false) {
            Some((floor, ceiling, ..)) if floor < ceiling => {
                for f in meet.ends() {
                    let through = f > 0.0 || (floor <= self.z && self.z <= ceiling);
                    out.push(Event { fraction: f, line: i, opening: through.then_some((floor, ceiling)) });
                }
            }
            _ => out.push(Event { fraction: meet.first(), line: i, opening: None }),
        }
    }

    /// Walks `events` and the bodies in order of distance, lines first at
    /// equal distances: the first body the window shows.
    fn first_in_view(&self, events: &mut [Event], order: &mut Vec<(f64, usize)>, bodies: &[Body]) -> Option<Aimed> {
        events.sort_by(|a, b| a.fraction.total_cmp(&b.fraction).then(a.line.cmp(&b.line)));
        order.clear();
        for (k, body) in bodies.iter().enumerate() {
            if Some(body.index) != self.shooter && body.valid() {
                if let Some((t0, _)) = box_span(self.p, self.q, body) {
                    order.push((t0, k));
                }
            }
        }
        order.sort_by(|a, b| a.0.total_cmp(&b.0).then(bodies[a.1].index.cmp(&bodies[b.1].index)));
        let (mut top, mut bottom) = (AIM_SLOPE, -AIM_SLOPE);
        let mut next = events.iter().peekable();
        for &(t, k) in order.iter() {
            while let Some(e) = next.next_if(|e| e.fraction <= t) {
                let (floor, ceiling) = e.opening?;
                if e.fraction > 0.0 {
                    let dist = e.fraction * self.range;
                    bottom = bottom.max(slope_to(floor - self.z, dist));
                    top = top.min(slope_to(ceiling - self.z, dist));
                }
                if top <= bottom {
                    return None;
                }
            }
            let body = &bodies[k];
            let dist = t * self.range;
            let body_top = slope_to(body.z + body.height - self.z, dist);
            let body_bottom = slope_to(body.z - self.z, dist);
            if body_top < bottom || body_bottom > top {
                continue; // over it or under it
            }
            let slope = (body_top.min(top) + body_bottom.max(bottom)) / 2.0;
            return Some(Aimed { slope, index: body.index });
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bsp::{build, BuildOptions};
    use crate::geom::{segment_contact, Contact};
    use crate::map::source::{MapSource, SectorSource, ThingSource};
    use crate::map::validate::validate;
    use crate::map::PLAYER_START;
    use proptest::prelude::*;

    fn v(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    /// Counter-clockwise: a hole with the room on its right.
    fn square(x0: f64, y0: f64, x1: f64, y1: f64) -> [(f64, f64); 4] {
        [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    }

    /// A 1024x512 room (sector 0: floor 0, ceiling 256, sky) holding a solid
    /// pillar at [256, 320]x[192, 256] (lines 4-7) and a platform (sector 1:
    /// floor 24, ceiling 256) at [640, 704]x[192, 256] (lines 8-11), and a
    /// low sky-ceilinged alcove (sector 2: floor 0, ceiling 128) at
    /// [832, 896]x[320, 384] (lines 12-15).
    fn tie_map() -> CompiledMap {
        let sky = Some("SKY".to_string());
        let sector = |floor: f64, ceiling: f64| SectorSource {
            floor,
            ceiling,
            light: 160,
            ceiling_texture: sky.clone(),
            ..SectorSource::default()
        };
        let mut source = MapSource {
            name: "ties".into(),
            sectors: vec![sector(0.0, 256.0), sector(24.0, 256.0), sector(0.0, 128.0)],
            things: vec![ThingSource::new(PLAYER_START, 64.0, 64.0, 0.0)],
            ..MapSource::default()
        };
        source.add_ring(&[(0.0, 0.0), (0.0, 512.0), (1024.0, 512.0), (1024.0, 0.0)], 0, None);
        source.add_ring(&square(256.0, 192.0, 320.0, 256.0), 0, None);
        source.add_ring(&square(640.0, 192.0, 704.0, 256.0), 0, Some(1));
        source.add_ring(&square(832.0, 320.0, 896.0, 384.0), 0, Some(2));
        let map = validate(&source).unwrap_or_else(|p| panic!("{p:?}"));
        build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"))
    }

    fn body(x: f64, y: f64, z: f64, height: f64, index: usize) -> Body {
        Body { pos: v(x, y), z, height, radius: 16.0, index }
    }

    /// Both paths, which must agree.
    fn sees(map: &CompiledMap, a: &Body, b: &Body) -> bool {
        let fast = sight(map, &mut Scratch::default(), a, b);
        assert_eq!(fast, sight_brute(&map.map, a, b), "fast and brute disagree: {a:?} -> {b:?}");
        fast
    }

    fn shoot(map: &CompiledMap, ray: &Ray, slope: f64, bodies: &[Body]) -> Option<Hit> {
        let fast = hitscan(map, &mut Scratch::default(), ray, slope, bodies);
        assert_eq!(fast, hitscan_brute(&map.map, ray, slope, bodies), "{ray:?} slope {slope}");
        fast
    }

    fn aim(map: &CompiledMap, ray: &Ray, bodies: &[Body]) -> Option<Aimed> {
        let fast = aim_slope(map, &mut Scratch::default(), ray, bodies);
        assert_eq!(fast, aim_slope_brute(&map.map, ray, bodies), "{ray:?}");
        fast
    }

    fn ray(x: f64, y: f64, z: f64, angle: f64, range: f64) -> Ray {
        Ray { origin: v(x, y), z, angle, range, shooter: None }
    }

    #[test]
    fn meeting_points_and_fractions() {
        let (a, b) = (v(10.0, -5.0), v(10.0, 5.0));
        assert_eq!(meet(v(0.0, 0.0), v(20.0, 0.0), a, b), Some(Meet::Point(0.5)));
        // Either way round, and touching at an end.
        assert_eq!(meet(v(0.0, 0.0), v(20.0, 0.0), b, a), Some(Meet::Point(0.5)));
        assert_eq!(meet(v(0.0, 5.0), v(20.0, 5.0), a, b), Some(Meet::Point(0.5)));
        assert_eq!(meet(v(0.0, 5.0001), v(20.0, 5.0001), a, b), None);
        // Starting and ending on the line: exactly 0 and 1.
        assert_eq!(meet(v(10.0, 1.0), v(30.0, 7.0), a, b), Some(Meet::Point(0.0)));
        assert_eq!(meet(v(-7.0, 3.0), v(10.0, -2.0), a, b), Some(Meet::Point(1.0)));
        // Collinear: the overlap, in the segment's own direction.
        assert_eq!(meet(v(10.0, -15.0), v(10.0, 5.0), a, b), Some(Meet::Along(0.5, 1.0)));
        assert_eq!(meet(v(10.0, 15.0), v(10.0, -5.0), a, b), Some(Meet::Along(0.5, 1.0)));
        assert_eq!(meet(v(10.0, 5.0), v(10.0, 25.0), a, b), Some(Meet::Point(0.0)));
        assert_eq!(meet(v(10.0, 6.0), v(10.0, 25.0), a, b), None);
        // Lines ending at one vertex meet the segment at one fraction,
        // whichever formula would have rounded differently.
        let (p, q, vertex) = (v(0.0, 0.0), v(3.0, 1.0), v(1.5, 0.5));
        let fractions: Vec<_> =
            [v(1.5, 3.0), v(0.1, 7.3), v(2.9, -0.7)].iter().map(|&end| meet(p, q, vertex, end)).collect();
        assert_eq!(fractions, [Some(Meet::Point(0.5)); 3]);
        // A zero-length segment meets the line it is on.
        assert_eq!(meet(v(10.0, 2.0), v(10.0, 2.0), a, b), Some(Meet::Point(0.0)));
        assert_eq!(meet(v(11.0, 2.0), v(11.0, 2.0), a, b), None);
    }

    proptest! {
        /// `meet` agrees with the validator's exact `segment_contact` on
        /// small integer coordinates (where collinear and touching cases are
        /// common): they meet exactly when the validator sees a contact or
        /// the two share an end, and the point found is on both.
        #[test]
        fn meet_agrees_with_segment_contact(c in prop::array::uniform8(-4i32..=4)) {
            let [px, py, qx, qy, ax, ay, bx, by] = c.map(f64::from);
            let (p, q, a, b) = (v(px, py), v(qx, qy), v(ax, ay), v(bx, by));
            prop_assume!(p != q && a != b);
            let shared = [a, b].contains(&p) || [a, b].contains(&q);
            let contact = segment_contact(p, q, a, b) != Contact::None || shared;
            let m = meet(p, q, a, b);
            prop_assert_eq!(m.is_some(), contact, "{:?}", m);
            prop_assert_eq!(m, meet(p, q, b, a));
            if let Some(m) = m {
                for f in m.ends() {
                    let x = p + (q - p) * f;
                    prop_assert!((0.0..=1.0).contains(&f));
                    prop_assert!(crate::geom::distance_to_segment(x, a, b) < 1e-9, "{:?} at {}", m, f);
                }
            }
        }
    }

    /// The descent's margin at work: each partition of the tie map's tree
    /// moved by `ON_EPSILON` towards the child holding a one-sided wall on
    /// its line, so that the wall's seg lies that far on the wrong side (a
    /// tree `bsp::check` still accepts). Looking from behind the wall at a
    /// point exactly on it, only that seg is met: the fast path must still
    /// find it and say, as the brute force does, that the wall blocks.
    #[test]
    fn the_descent_reaches_segs_astray_within_the_compilers_tolerance() {
        use crate::bsp::build::ON_EPSILON;
        use crate::bsp::check::check_invariants;
        let mut tried = 0;
        let trees = (0..8).map(|seed| BuildOptions { splitter: crate::bsp::SplitterKind::Random, seed });
        for options in trees.chain([BuildOptions::default()]) {
            let base = build(&tie_map().map, &options).unwrap_or_else(|e| panic!("{e}"));
            for k in 0..base.bsp.nodes.len() {
                let (pa, pb) = (base.bsp.nodes[k].a, base.bsp.nodes[k].b);
                let dir = (pb - pa).normalize();
                let right = DVec2::new(dir.y, -dir.x);
                for (i, line) in base.map.lines.iter().enumerate().filter(|(_, l)| l.back.is_none()) {
                    let (a, b) = base.map.line_points(line);
                    if orient(pa, pb, a) != 0.0 || orient(pa, pb, b) != 0.0 {
                        continue;
                    }
                    // Its seg went where it faces; push the partition that way.
                    let towards = if (b - a).dot(dir) > 0.0 { right } else { -right };
                    let mut moved = base.clone();
                    moved.bsp.nodes[k].a += towards * ON_EPSILON;
                    moved.bsp.nodes[k].b += towards * ON_EPSILON;
                    check_invariants(&moved.map, &moved.bsp).unwrap_or_else(|e| panic!("{options:?} node {k}: {e}"));
                    let q = (a + b) / 2.0;
                    let looker = body(q.x - towards.x * 50.0, q.y - towards.y * 50.0, 0.0, 56.0, 0);
                    let target = body(q.x, q.y, 0.0, 56.0, 1);
                    assert!(!sees(&moved, &looker, &target), "{options:?} node {k}, line {i}");
                    tried += 1;
                }
            }
        }
        assert!(tried > 20, "{tried}");
    }

    #[test]
    fn walls_block_and_openings_narrow() {
        let map = tie_map();
        let looker = body(64.0, 224.0, 0.0, 56.0, 0);
        // Through the pillar, no; over the platform's lip, yes.
        assert!(!sees(&map, &looker, &body(448.0, 224.0, 0.0, 56.0, 1)));
        let a = body(576.0, 224.0, 0.0, 56.0, 0);
        assert!(sees(&map, &a, &body(768.0, 224.0, 0.0, 56.0, 1)));
        // A short target behind the lip is hidden, a tall one not.
        assert!(!sees(&map, &body(600.0, 224.0, 0.0, 56.0, 0), &body(744.0, 224.0, 0.0, 8.0, 1)));
        assert!(sees(&map, &body(600.0, 224.0, 0.0, 56.0, 0), &body(744.0, 224.0, 0.0, 40.0, 1)));
        // Heights are read live: the platform raised to the ceiling closes it.
        let mut raised = map.clone();
        raised.map.sectors[1].floor = 256.0;
        assert!(!sees(&raised, &a, &body(768.0, 224.0, 0.0, 56.0, 1)));
        // Zero height is never seen; non-finite input is not an error.
        assert!(!sees(&map, &a, &body(600.0, 224.0, 0.0, 0.0, 1)));
        assert!(!sees(&map, &a, &body(f64::NAN, 224.0, 0.0, 56.0, 1)));
    }

    #[test]
    fn touching_a_wall_corner_blocks_and_an_opening_corner_narrows() {
        let map = tie_map();
        // Exactly through the pillar's corner (256, 192), outside it on both sides.
        assert!(!sees(&map, &body(192.0, 256.0, 0.0, 56.0, 0), &body(320.0, 128.0, 0.0, 56.0, 1)));
        // A hair to the side, it passes.
        assert!(sees(&map, &body(192.0, 255.0, 0.0, 56.0, 0), &body(320.0, 127.0, 0.0, 56.0, 1)));
        // Through the platform's corner (640, 192): the lip at 24 is under the window...
        let (a, b) = (body(576.0, 256.0, 0.0, 56.0, 0), body(704.0, 128.0, 0.0, 56.0, 1));
        assert!(sees(&map, &a, &b));
        // ...until it rises above the line from the eye (42) to the target's top (56).
        let mut raised = map.clone();
        raised.map.sectors[1].floor = 49.5;
        assert!(!sees(&raised, &a, &b));
        raised.map.sectors[1].floor = 48.5;
        assert!(sees(&raised, &a, &b));
    }

    #[test]
    fn along_a_line() {
        let map = tie_map();
        // Along the pillar's south face: blocked; the shot stops where the face begins.
        assert!(!sees(&map, &body(128.0, 192.0, 0.0, 56.0, 0), &body(448.0, 192.0, 0.0, 56.0, 1)));
        let hit = shoot(&map, &ray(128.0, 192.0, 32.0, 0.0, 2048.0), 0.0, &[]).unwrap();
        // Lines 4 (the south face) and 7 (the west face, ending at the corner) tie: the lower index.
        assert_eq!(hit.struck, Struck::Wall { line: 4, side: LineSide::Front, part: Part::Middle });
        assert_eq!((hit.point, hit.puff), (DVec3::new(256.0, 192.0, 32.0), Some(DVec3::new(252.0, 192.0, 32.0))));
        // Along the platform's south edge: both ends of the overlap count.
        let (a, b) = (body(576.0, 192.0, 0.0, 56.0, 0), body(768.0, 192.0, 0.0, 56.0, 1));
        assert!(sees(&map, &a, &b));
        let mut raised = map.clone();
        raised.map.sectors[1].floor = 50.0;
        assert!(!sees(&raised, &a, &b));
        // A shot along it above the lip passes; below, it hits the lower part where the overlap begins.
        let along = ray(576.0, 192.0, 32.0, 0.0, 2048.0);
        assert_eq!(shoot(&map, &along, 0.0, &[]).unwrap().point, DVec3::new(1024.0, 192.0, 32.0));
        let low = shoot(&map, &Ray { z: 10.0, ..along }, 0.0, &[]).unwrap();
        assert_eq!(
            (low.struck, low.point.x),
            (Struck::Wall { line: 8, side: LineSide::Front, part: Part::Lower }, 640.0)
        );
        // Sinking through the lip's height on the way along: stopped where it
        // crosses 24 (72 units out), not where the overlap begins or ends.
        let sinking = shoot(&map, &Ray { z: 30.0, ..along }, -1.0 / 12.0, &[]).unwrap();
        assert_eq!(sinking.struck, Struck::Wall { line: 8, side: LineSide::Front, part: Part::Lower });
        assert!((sinking.point.x - 648.0).abs() < 1e-9 && (sinking.point.z - 24.0).abs() < 1e-9, "{sinking:?}");
    }

    #[test]
    fn starting_and_ending_on_lines() {
        let map = tie_map();
        // Standing on the platform's edge with the eye in its opening: sees.
        let on = body(672.0, 192.0, 0.0, 56.0, 0);
        assert!(sees(&map, &on, &body(672.0, 64.0, 0.0, 56.0, 1)));
        // With the eye under the lip (24): not at all.
        assert!(!sees(&map, &body(672.0, 192.0, -40.0, 56.0, 0), &body(672.0, 64.0, 0.0, 56.0, 1)));
        // A shot from a one-sided face hits it at the muzzle, puff at the origin.
        let hit = shoot(&map, &ray(256.0, 224.0, 32.0, 180.0, 2048.0), 0.0, &[]).unwrap();
        assert_eq!(
            (hit.struck, hit.fraction),
            (Struck::Wall { line: 7, side: LineSide::Front, part: Part::Middle }, 0.0)
        );
        assert_eq!(hit.puff, Some(DVec3::new(256.0, 224.0, 32.0)));
        // From the platform's edge, out over the room: on to the south wall.
        let hit = shoot(&map, &ray(672.0, 192.0, 32.0, 270.0, 2048.0), 0.0, &[]).unwrap();
        assert_eq!(
            (hit.struck, hit.point),
            (Struck::Wall { line: 3, side: LineSide::Front, part: Part::Middle }, DVec3::new(672.0, 0.0, 32.0))
        );
        // A target on a one-sided face: never; on the platform's edge: if it shows over the lip.
        assert!(!sees(&map, &body(64.0, 224.0, 0.0, 56.0, 0), &body(256.0, 224.0, 0.0, 56.0, 1)));
        let looker = body(576.0, 224.0, 0.0, 56.0, 0);
        assert!(sees(&map, &looker, &body(640.0, 224.0, 0.0, 56.0, 1)));
        assert!(!sees(&map, &looker, &body(640.0, 224.0, 0.0, 20.0, 1)));
    }

    #[test]
    fn shots_hit_parts_sky_and_bodies() {
        let map = tie_map();
        // The alcove's face, above its ceiling (128): both ceilings are sky, so the shot is gone.
        let high = ray(800.0, 352.0, 200.0, 0.0, 2048.0);
        let hit = shoot(&map, &high, 0.0, &[]).unwrap();
        assert_eq!((hit.struck, hit.puff), (Struck::Sky { line: 15 }, None));
        let mut plain = map.clone();
        plain.map.sectors[2].ceiling_texture = Some("CEIL".into());
        let hit = shoot(&plain, &high, 0.0, &[]).unwrap();
        assert_eq!(hit.struck, Struck::Wall { line: 15, side: LineSide::Front, part: Part::Upper });
        assert_eq!(hit.puff, Some(DVec3::new(828.0, 352.0, 200.0)));
        // Climbing out of the room through its sky ceiling (256) before the east wall.
        let hit = shoot(&map, &ray(960.0, 64.0, 200.0, 0.0, 2048.0), 1.0, &[]).unwrap();
        assert_eq!(hit.struck, Struck::Sky { line: 2 });
        // A body: entered at its box's face (x = 492), shooter skipped, blood 10 back.
        let bodies = [body(400.0, 384.0, 0.0, 56.0, 7), body(512.0, 384.0, 0.0, 56.0, 3)];
        let shot = Ray { shooter: Some(7), ..ray(400.0, 384.0, 32.0, 0.0, 2048.0) };
        let hit = shoot(&map, &shot, 0.0, &bodies).unwrap();
        assert_eq!((hit.struck, hit.point), (Struck::Body { index: 3 }, DVec3::new(496.0, 384.0, 32.0)));
        assert_eq!(hit.puff, Some(DVec3::new(486.0, 384.0, 32.0)));
        // Over its head, on to the wall; melee range stops short of it.
        assert!(matches!(shoot(&map, &shot, 0.5, &bodies).unwrap().struck, Struck::Sky { .. } | Struck::Wall { .. }));
        assert_eq!(shoot(&map, &Ray { range: MELEE_RANGE, ..shot }, 0.0, &bodies), None);
        // A body in front of a wall is hit first.
        let against = [body(1008.0, 64.0, 0.0, 56.0, 1)];
        let hit = shoot(&map, &ray(960.0, 64.0, 32.0, 0.0, 2048.0), 0.0, &against).unwrap();
        assert_eq!(hit.struck, Struck::Body { index: 1 });
        // Its box's face on the wall (x = 1024): the same distance, and the wall wins.
        let flush = [body(1040.0, 64.0, 0.0, 56.0, 2)];
        let hit = shoot(&map, &ray(960.0, 64.0, 32.0, 0.0, 2048.0), 0.0, &flush).unwrap();
        assert!(matches!(hit.struck, Struck::Wall { line: 2, .. }), "{hit:?}");
    }

    #[test]
    fn auto_aim_takes_the_nearest_body_in_the_window() {
        let map = tie_map();
        let from = Ray { shooter: Some(0), ..ray(400.0, 384.0, 32.0, 0.0, 1024.0) };
        let me = body(400.0, 384.0, 0.0, 56.0, 0);
        let near = body(512.0, 384.0, 0.0, 56.0, 3);
        let far = body(700.0, 384.0, 0.0, 56.0, 4);
        // Entered at 96 units: slopes 24/96 up and -32/96 down, the middle -4/96.
        let aimed = aim(&map, &from, &[me, far, near]).unwrap();
        assert_eq!(aimed.index, 3);
        assert!((aimed.slope - (24.0 - 32.0) / 2.0 / 96.0).abs() < 1e-12, "{aimed:?}");
        // Too high for the window: the next one is taken.
        let perched = Body { z: 200.0, ..near };
        assert_eq!(aim(&map, &from, &[perched, far]).unwrap().index, 4);
        // Cut by the window: the middle of the part it shows.
        let tall = Body { z: 0.0, height: 400.0, ..near };
        let aimed = aim(&map, &from, &[tall]).unwrap();
        assert!((aimed.slope - (AIM_SLOPE - 32.0 / 96.0) / 2.0).abs() < 1e-12, "{aimed:?}");
        // Behind the pillar: nothing.
        let behind = ray(64.0, 224.0, 32.0, 0.0, 1024.0);
        assert_eq!(aim(&map, &behind, &[body(448.0, 224.0, 0.0, 56.0, 1)]), None);
        // Over the platform's lip, a body beyond it is aimed at.
        assert!(aim(&map, &ray(576.0, 224.0, 32.0, 0.0, 1024.0), &[body(768.0, 224.0, 0.0, 56.0, 1)]).is_some());
    }
}
