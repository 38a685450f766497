//! The autopilot's line of sight: the geometry question of Doom's
//! `p_sight.c` (can one body see another, P_CheckSight) asked in f64 over the
//! converted map, for the planner to judge what it may expect. The game's own
//! sight is `sim/sight.rs` (Doom's P_CheckSight on Doom's nodes, in fixed
//! point); this one is the planner's: it answers what the bot may expect,
//! never what happens. It comes twice and the two answer identically: a fast path that asks the compiled
//! BSP which lines lie near the segment ([`sight`]) and a brute-force oracle
//! that tries every line of the map ([`sight_brute`]). It hands the
//! autopilot a bool; it changes nothing.
//!
//! **The model.** Everything happens in the vertical plane over the 2D
//! segment from `p` (the looker) to `q` (the target), at fractions `f` of it
//! (0 at `p`, 1 at `q`). A line acts wherever the closed segment meets it
//! ([`meet`]). Sector heights are read from `Map::sectors` at the call, so
//! moving floors and ceilings count. A two-sided line's *opening* is the
//! higher of its two floors up to the lower of its two ceilings; it is
//! *closed* when that floor is at or above that ceiling. Every two-sided line
//! acts by its opening, not only those whose floors (or ceilings) differ as
//! in Doom: Doom's shortcut lets a line of sight dip under a floor and come
//! back up between lines of one floor height, where here it is stopped at the
//! first line it is under.
//!
//! **Sight** (P_CheckSight). From the looker's eye, `z + 3/4 height`
//! ([`EYE_SHARE`]), to the target's extent `[z, z + height]`: a window of
//! slopes (height per unit of `f`) starts as the target's extent seen at
//! `f = 1`. A one-sided line met anywhere blocks; a closed opening blocks; an
//! open one narrows the window to the slopes through it at each `f` where it
//! is met. The target is seen when nothing blocked and the window is still
//! open (top above bottom, strictly: Doom's `topslope <= bottomslope` fails).
//!
//! **Tie rules.** Decided exactly (orient2d), and the same in both paths.
//! - *Touching counts.* A segment through a vertex meets every line ending
//!   there: exactly through the corner of a pillar, the end of a wall or a
//!   door jamb, sight is blocked; through a vertex where only two-sided lines
//!   meet it passes if it is inside each opening there.
//! - *Along a line* (collinear, overlapping more than a point): a one-sided
//!   wall blocks; a two-sided line acts at both ends of the overlap (the
//!   segment and the opening's limits are straight, so both ends inside
//!   means every point between is).
//! - *Starting on a line* (`f = 0`): a one-sided line blocks; for a
//!   two-sided line, slopes mean nothing at distance 0, so sight asks only
//!   that the eye be within the opening, limits included.
//! - *Ending on a line* (a target exactly on it, `f = 1`): an ordinary
//!   contact. A target on a one-sided line is never seen; on a two-sided one
//!   the opening at the target narrows the window.
//! - *Huge coordinates*: every decision is an exact orientation, so a map at
//!   ±30,000 (or anywhere within `geom::MAX_COORD`) is judged as at the
//!   origin; only fractions and heights carry rounding.
//!
//! **Why the two paths agree bit for bit.** Both run the same per-line
//! function (where the segment meets the line, and what that does to the
//! window) on the same sector heights, and combine its results in a way that
//! does not depend on the order lines come in: a minimum of the tops, a
//! maximum of the bottoms and "any blocks". Both stop at the first line after
//! which the target cannot be seen, which is safe because none of the three
//! can be undone by a later line. So they agree exactly as long as the fast
//! path offers every line the segment meets. It does: the descent enters a
//! child whenever the segment comes within a margin of its side of the
//! partition and of the box round its segs. Every seg lies on its side of
//! each ancestor's partition to within the compiler's `ON_EPSILON` (1e-6,
//! plus 1e-12 of the coordinates for split points: what `bsp::check`
//! allows), the pieces of a line's side cover the line, and a node's boxes
//! bound its children's segs (the renderer's culling relies on that too); so
//! a point where the segment meets a line is within that tolerance of the
//! leaf holding the piece through it, and a margin of a hundred times the
//! tolerance reaches that leaf (a test moves partitions by `ON_EPSILON` to
//! prove it; with no margin it fails). The descent never prunes by fraction:
//! a fraction is computed, not decided, and at a glancing angle a line could
//! be listed nearer than the subtree it lies in.
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
//! `autopilot/blockmap.rs` lists them, then the window):
//!
//! | map | lines | sight |
//! |---|---|---|
//! | E1M1 (freedoom1) | 812 | 1.5-2.0 / 2.5-3.2 / 1.6-2.6 |
//! | MAP10 (freedoom2) | 3,154 | 3.3-3.8 / 7.0-8.9 / 4.5-5.8 |
//! | maze.ron | 2,290 | 0.5-0.6 / 6.4-7.5 / 1.8-2.2 |
//!
//! The brute force is not far behind on small maps because most pairs are
//! blocked by a wall it reaches early and its box test rejects most lines
//! without an orientation; it grows with the map, the descent barely.

use std::ops::ControlFlow;

use glam::DVec2;

use crate::bsp::{Bsp, Child, CompiledMap};
use crate::geom::{cross, on_segment, Aabb};
use crate::map::{Line, Map};

/// The eye is this share of a body's height above its feet (Doom:
/// `height - (height >> 2)`).
pub const EYE_SHARE: f64 = 0.75;

/// A body as sight sees it: where it stands and how tall it is. Its radius
/// and the caller's name for it (`index`) ride along for the caller; sight
/// only refuses a radius that is negative or not finite.
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

/// How the closed segment `p -> q` meets a closed line segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Meet {
    /// At one point, this fraction of the way from `p` to `q`.
    Point(f64),
    /// Along it (collinear), from the first fraction to the second (larger).
    Along(f64, f64),
}

impl Meet {
    /// The fractions where the line acts: the point, or both ends of the overlap.
    fn ends(self) -> impl Iterator<Item = f64> {
        let (a, b) = match self {
            Meet::Point(f) => (f, None),
            Meet::Along(f0, f1) => (f0, Some(f1)),
        };
        std::iter::once(a).chain(b)
    }
}

/// Reusable scratch for the fast path: the descent's stack and a stamp per
/// line so each is tried once per query (Doom's `validcount`). Cleared per
/// query, never shrunk.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    walk: Walk,
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

/// A two-sided line's opening: the higher floor and the lower ceiling;
/// `None` for a one-sided line.
fn opening(map: &Map, line: &Line) -> Option<(f64, f64)> {
    let back = line.back.as_ref()?;
    let (front, back) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
    Some((front.floor.max(back.floor), front.ceiling.min(back.ceiling)))
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
        match opening(map, line) {
            Some((floor, ceiling)) if floor < ceiling => {
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
        // Along the pillar's south face: blocked.
        assert!(!sees(&map, &body(128.0, 192.0, 0.0, 56.0, 0), &body(448.0, 192.0, 0.0, 56.0, 1)));
        // Along the platform's south edge: both ends of the overlap count.
        let (a, b) = (body(576.0, 192.0, 0.0, 56.0, 0), body(768.0, 192.0, 0.0, 56.0, 1));
        assert!(sees(&map, &a, &b));
        let mut raised = map.clone();
        raised.map.sectors[1].floor = 50.0;
        assert!(!sees(&raised, &a, &b));
    }

    #[test]
    fn starting_and_ending_on_lines() {
        let map = tie_map();
        // Standing on the platform's edge with the eye in its opening: sees.
        let on = body(672.0, 192.0, 0.0, 56.0, 0);
        assert!(sees(&map, &on, &body(672.0, 64.0, 0.0, 56.0, 1)));
        // With the eye under the lip (24): not at all.
        assert!(!sees(&map, &body(672.0, 192.0, -40.0, 56.0, 0), &body(672.0, 64.0, 0.0, 56.0, 1)));
        // A target on a one-sided face: never; on the platform's edge: if it shows over the lip.
        assert!(!sees(&map, &body(64.0, 224.0, 0.0, 56.0, 0), &body(256.0, 224.0, 0.0, 56.0, 1)));
        let looker = body(576.0, 224.0, 0.0, 56.0, 0);
        assert!(sees(&map, &looker, &body(640.0, 224.0, 0.0, 56.0, 1)));
        assert!(!sees(&map, &looker, &body(640.0, 224.0, 0.0, 20.0, 1)));
    }
}
