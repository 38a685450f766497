//! Random valid maps and random poses for the property tests.
//!
//! A map is one room (a random simple polygon: a circle-ish convex polygon, a
//! star-shaped concave one, or an axis-aligned rectangle) holding up to six
//! small polygonal pillars, each either solid or a sector of its own. The
//! construction is valid by design, not by filtering:
//!
//! - The room's vertices sit at strictly increasing angles around the origin,
//!   every angular gap in `[MIN_GAP, 0.9 pi]`, so the polygon is star-shaped
//!   about the origin and therefore simple; an x-stretch (0.3..1) is affine
//!   and keeps that. Radii are at least 40 units (12 stretched), so snapping
//!   to the 1/16 grid turns a vertex by at most ~0.004 rad, well under the
//!   smallest (stretched) gap: the snapped polygon is still simple.
//! - A pillar is a regular-ish polygon (jittered angles and radii) inside its
//!   circumscribed circle; the circle keeps `margin >= 0.25` units away from
//!   every room edge and every other pillar's circle, which grid snapping
//!   (at most 0.045 units a vertex) cannot close.
//! - Lines: the room ring clockwise (room on the right), pillar rings
//!   counter-clockwise with the room in front and, for a pillar sector, the
//!   pillar's sector behind.
//! - Large translations are by integers and scalings by powers of two, so on
//!   the 1/16 grid they are exact and preserve validity exactly. Scaling by
//!   down to 2^-5 deliberately goes below the documented smallest features
//!   (0.5-unit segments, 1-unit pillars): a 1/32-unit pillar, a 0.4-unit room.
//!   `Raw` placement keeps unsnapped f64 coordinates.
//!
//! Everything is driven by a [`MapSpec`] whose parts have their own seeds, so
//! that shrinking (fewer room vertices, fewer pillars, a plainer placement)
//! keeps the rest of the map as it was. `validate` still runs on every
//! generated map; a rejection is reported as a generator bug.

use sightline::level::Level;
use std::f64::consts::{PI, TAU};

use glam::DVec2;
use proptest::prelude::*;
use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use sightline::map::source::{LineSource, MapSource, SectorSource, SideSource, ThingSource};
use sightline::map::validate::validate;
use sightline::map::{Map, PLAYER_START};
use sightline::render::view::EYE_HEIGHT;
use sightline::render::View;

/// Smallest angular gap between consecutive room vertices (radians).
const MIN_GAP: f64 = 0.04;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RoomKind {
    /// An axis-aligned rectangle (integer sides).
    Rectangle,
    /// Vertices on an ellipse: strictly convex.
    Convex,
    /// Random radii at sorted random angles: star-shaped, usually concave.
    Star,
}

#[derive(Clone, Debug)]
pub struct RoomSpec {
    pub kind: RoomKind,
    /// 3..=24 (4 for a rectangle, whatever this says).
    pub vertices: usize,
    pub seed: u64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PillarKind {
    /// One-sided lines: a hole in the room.
    Solid,
    /// Its own sector, floor above the room's.
    Platform,
    /// Its own sector, floor below the room's.
    Pit,
    /// Its own sector, ceiling below the room's.
    LowCeiling,
    /// Its own sector with floor == ceiling.
    ClosedDoor,
    /// Its own sector with any heights.
    AnyHeights,
}

impl PillarKind {
    fn is_solid(self) -> bool {
        self == PillarKind::Solid
    }
}

#[derive(Clone, Debug)]
pub struct PillarSpec {
    pub kind: PillarKind,
    /// 3..=8.
    pub sides: usize,
    /// Circumradius before placement, 1..=60.
    pub radius: f64,
    /// An exactly axis-aligned square instead of a rotated polygon.
    pub axis_square: bool,
    pub seed: u64,
}

/// Where the finished map goes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Placement {
    /// Coordinates exactly as generated (arbitrary f64s).
    Raw,
    /// Snapped to the 1/16 grid.
    Grid,
    /// Snapped, then moved by a large integer offset.
    Offset(f64, f64),
    /// Snapped, then scaled by `2^k` (negative `k`: tiny).
    Scale(i32),
}

#[derive(Clone, Debug)]
pub struct MapSpec {
    pub room: RoomSpec,
    pub pillars: Vec<PillarSpec>,
    pub placement: Placement,
    /// Room heights, light, the player start, pillar margins.
    pub seed: u64,
}

fn room_kind() -> impl Strategy<Value = RoomKind> {
    prop_oneof![
        1 => Just(RoomKind::Rectangle),
        2 => Just(RoomKind::Convex),
        4 => Just(RoomKind::Star),
    ]
}

fn pillar_kind() -> impl Strategy<Value = PillarKind> {
    prop_oneof![
        3 => Just(PillarKind::Solid),
        1 => Just(PillarKind::Platform),
        1 => Just(PillarKind::Pit),
        1 => Just(PillarKind::LowCeiling),
        1 => Just(PillarKind::ClosedDoor),
        1 => Just(PillarKind::AnyHeights),
    ]
}

fn placement() -> impl Strategy<Value = Placement> {
    prop_oneof![
        3 => Just(Placement::Grid),
        2 => Just(Placement::Raw),
        1 => Just(Placement::Offset(1_000_000.0, 1_000_000.0)),
        1 => Just(Placement::Offset(-3_000_000.0, 250_000.0)),
        1 => (-8_000_000i64..=8_000_000, -8_000_000i64..=8_000_000)
            .prop_map(|(x, y)| Placement::Offset(x as f64, y as f64)),
        1 => (-5i32..=-2).prop_map(Placement::Scale),
        1 => (3i32..=9).prop_map(Placement::Scale),
    ]
}

pub fn pillar_spec() -> impl Strategy<Value = PillarSpec> {
    (
        pillar_kind(),
        3usize..=8,
        prop_oneof![1 => Just(1.0), 3 => 1.0f64..=60.0],
        prop::bool::weighted(0.15),
        any::<u64>(),
    )
        .prop_map(|(kind, sides, radius, axis_square, seed)| PillarSpec { kind, sides, radius, axis_square, seed })
}

/// Any map the generator makes.
pub fn map_spec() -> impl Strategy<Value = MapSpec> {
    (room_kind(), 3usize..=24, any::<u64>(), prop::collection::vec(pillar_spec(), 0..=6), placement(), any::<u64>())
        .prop_map(|(kind, vertices, room_seed, pillars, placement, seed)| MapSpec {
            room: RoomSpec { kind, vertices, seed: room_seed },
            pillars,
            placement,
            seed,
        })
}

/// A generated map and what the poses need to know about it.
pub struct Generated {
    pub source: MapSource,
    pub map: Map,
    /// Map units per generator unit (the placement's scale).
    pub unit: f64,
    pub pillars_placed: usize,
}

fn rng(seed: u64, stream: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed ^ stream.wrapping_mul(0x9e37_79b9_7f4a_7c15))
}

/// Room ring, counter-clockwise (strictly increasing angle about the origin).
fn room_ring(spec: &RoomSpec) -> Vec<DVec2> {
    let mut r = rng(spec.seed, 1);
    if spec.kind == RoomKind::Rectangle {
        let w = r.random_range(80..=4000) as f64 / 2.0;
        let h = r.random_range(80..=4000) as f64 / 2.0;
        return vec![DVec2::new(w, h), DVec2::new(-w, h), DVec2::new(-w, -h), DVec2::new(w, -h)];
    }
    let n = spec.vertices.clamp(3, 24);
    // Gaps: MIN_GAP plus a random share of the rest, none reaching 0.9 pi.
    let gaps = loop {
        let w: Vec<f64> = (0..n).map(|_| r.random_range(0.05..1.0)).collect();
        let total: f64 = w.iter().sum();
        let spare = TAU - n as f64 * MIN_GAP;
        let gaps: Vec<f64> = w.iter().map(|x| MIN_GAP + x / total * spare).collect();
        if gaps.iter().all(|&g| g < 0.9 * PI) {
            break gaps;
        }
    };
    let big: f64 = r.random_range(40.0..=2000.0);
    let low: f64 = if spec.kind == RoomKind::Star { r.random_range(0.05f64..0.95) } else { 1.0 };
    let stretch = if r.random_bool(0.5) { 1.0 } else { r.random_range(0.3..1.0) };
    let mut angle = r.random_range(0.0..TAU);
    gaps.iter()
        .map(|g| {
            let radius = r.random_range((big * low).max(40.0)..=big);
            let p = DVec2::new(angle.cos() * radius * stretch, angle.sin() * radius);
            angle += g;
            p
        })
        .collect()
}

fn pillar_ring(spec: &PillarSpec, centre: DVec2, radius: f64) -> Vec<DVec2> {
    let mut r = rng(spec.seed, 2);
    if spec.axis_square {
        let h = radius / 2f64.sqrt();
        return [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
            .iter()
            .map(|&(x, y)| centre + DVec2::new(x * h, y * h))
            .collect();
    }
    let k = spec.sides.clamp(3, 8);
    let rotation = r.random_range(0.0..TAU);
    (0..k)
        .map(|j| {
            let a = rotation + (j as f64 + r.random_range(-0.2..=0.2)) * TAU / k as f64;
            let rho = radius * r.random_range(0.9..=1.0);
            centre + DVec2::new(a.cos(), a.sin()) * rho
        })
        .collect()
}

/// Crossing-number test (points exactly on the ring may go either way).
fn inside(ring: &[DVec2], p: DVec2) -> bool {
    let mut odd = false;
    for (i, &a) in ring.iter().enumerate() {
        let b = ring[(i + 1) % ring.len()];
        if (a.y > p.y) != (b.y > p.y) && a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) > p.x {
            odd = !odd;
        }
    }
    odd
}

fn segment_distance(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    (a + d * t).distance(p)
}

fn ring_distance(ring: &[DVec2], p: DVec2) -> f64 {
    (0..ring.len()).map(|i| segment_distance(ring[i], ring[(i + 1) % ring.len()], p)).fold(f64::INFINITY, f64::min)
}

fn bbox(ring: &[DVec2]) -> (DVec2, DVec2) {
    ring.iter().fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)))
}

/// A height: often exactly one already in use, sometimes fractional.
fn height(r: &mut ChaCha8Rng, lo: f64, hi: f64, shared: &[f64]) -> f64 {
    let usable: Vec<f64> = shared.iter().copied().filter(|h| (lo..=hi).contains(h)).collect();
    if !usable.is_empty() && r.random_bool(0.3) {
        return usable[r.random_range(0..usable.len())];
    }
    if lo.ceil() > hi.floor() || r.random_bool(0.2) {
        r.random_range(lo..=hi)
    } else {
        r.random_range(lo.ceil() as i64..=hi.floor() as i64) as f64
    }
}

fn sector(floor: f64, ceiling: f64, light: i64) -> SectorSource {
    SectorSource { floor, ceiling, light, ..SectorSource::default() }
}

fn pillar_sector(r: &mut ChaCha8Rng, kind: PillarKind, room: &SectorSource) -> SectorSource {
    let (rf, rc) = (room.floor, room.ceiling);
    let shared = [rf, rc];
    let light = r.random_range(0..=255);
    let (floor, ceiling) = match kind {
        PillarKind::Solid => unreachable!(),
        PillarKind::Platform => {
            let f = height(r, (rf + 1.0).min(256.0), (rf + 96.0).min(256.0), &shared);
            (f, height(r, f, 256.0, &shared))
        }
        PillarKind::Pit => {
            let f = height(r, -64.0, (rf - 1.0).max(-64.0), &shared);
            (f, height(r, f.max(rc - 32.0), 256.0, &shared))
        }
        PillarKind::LowCeiling => {
            let c = height(r, rf, rc, &shared);
            (height(r, (rf - 16.0).max(-64.0), c, &shared), c)
        }
        PillarKind::ClosedDoor => {
            let h = height(r, -64.0, 256.0, &shared);
            (h, h)
        }
        PillarKind::AnyHeights => {
            let f = height(r, -64.0, 256.0, &shared);
            (f, height(r, f, 256.0, &shared))
        }
    };
    sector(floor, ceiling, light)
}

fn side(sector: usize) -> SideSource {
    SideSource { sector: sector as i64, ..SideSource::default() }
}

/// Builds, places and validates the map `spec` describes. Panics on a
/// generator bug (a map that fails validation).
pub fn generate(spec: &MapSpec) -> Generated {
    let mut r = rng(spec.seed, 3);
    let room = room_ring(&spec.room);
    let (lo, hi) = bbox(&room);

    // Pillars, each tried at random spots, shrinking if it does not fit.
    let mut pillars: Vec<(usize, Vec<DVec2>, DVec2, f64)> = Vec::new();
    for (i, p) in spec.pillars.iter().enumerate() {
        let mut pr = rng(p.seed, 4);
        let margin = [0.25, 1.0, 8.0][pr.random_range(0..3)];
        let mut radius = p.radius.clamp(1.0, 60.0);
        let mut spot = None;
        'search: for _ in 0..4 {
            for _ in 0..48 {
                let c = DVec2::new(pr.random_range(lo.x..=hi.x), pr.random_range(lo.y..=hi.y));
                if inside(&room, c)
                    && ring_distance(&room, c) >= radius + margin
                    && pillars.iter().all(|(_, _, q, rq)| c.distance(*q) >= radius + rq + margin)
                {
                    spot = Some(c);
                    break 'search;
                }
            }
            radius = (radius / 2.0).max(1.0);
        }
        if let Some(c) = spot {
            pillars.push((i, pillar_ring(p, c, radius), c, radius));
        }
    }

    // Heights and light.
    let room_floor = if r.random_bool(0.3) { 0.0 } else { height(&mut r, -64.0, 128.0, &[]) };
    let room_ceiling =
        if r.random_bool(0.05) { room_floor } else { height(&mut r, room_floor + 1.0, 256.0, &[room_floor + 128.0]) };
    let mut sectors = vec![sector(room_floor, room_ceiling, r.random_range(0..=255))];

    // The player start: in the room, clear of every solid pillar.
    let solid: Vec<&Vec<DVec2>> =
        pillars.iter().filter(|(i, ..)| spec.pillars[*i].kind.is_solid()).map(|(_, ring, ..)| ring).collect();
    let start = (0..10_000)
        .map(|_| DVec2::new(r.random_range(lo.x..=hi.x), r.random_range(lo.y..=hi.y)))
        .find(|&p| {
            inside(&room, p)
                && ring_distance(&room, p) > 0.5
                && solid.iter().all(|ring| !inside(ring, p) && ring_distance(ring, p) > 0.5)
        })
        .unwrap_or_else(|| panic!("generator bug: no room for the player start in {spec:?}"));
    let start_angle = r.random_range(0.0..360.0);

    // Placement.
    let snap = |v: f64| (v * 16.0).round() / 16.0;
    let (unit, place): (f64, Box<dyn Fn(DVec2) -> DVec2>) = match spec.placement {
        Placement::Raw => (1.0, Box::new(|p| p)),
        Placement::Grid => (1.0, Box::new(move |p: DVec2| DVec2::new(snap(p.x), snap(p.y)))),
        Placement::Offset(x, y) => (1.0, Box::new(move |p: DVec2| DVec2::new(snap(p.x) + x, snap(p.y) + y))),
        Placement::Scale(k) => {
            let s = 2f64.powi(k);
            (s, Box::new(move |p: DVec2| DVec2::new(snap(p.x) * s, snap(p.y) * s)))
        }
    };

    let mut vertices = Vec::new();
    let mut lines = Vec::new();
    let mut add_ring = |ring: &[DVec2], clockwise: bool, front: usize, back: Option<usize>| {
        let first = vertices.len();
        vertices.extend(ring.iter().map(|&p| {
            let q = place(p);
            (q.x, q.y)
        }));
        let n = ring.len();
        for j in 0..n {
            let (a, b) = (first + j, first + (j + 1) % n);
            let (from, to) = if clockwise { (b, a) } else { (a, b) };
            lines.push(LineSource {
                from: from as i64,
                to: to as i64,
                front: side(front),
                back: back.map(side),
                ..LineSource::default()
            });
        }
    };
    // The room ring is counter-clockwise; reversed, the room is on the right.
    add_ring(&room, true, 0, None);
    for (i, ring, ..) in &pillars {
        let kind = spec.pillars[*i].kind;
        let back = if kind.is_solid() {
            None
        } else {
            let mut sr = rng(spec.pillars[*i].seed, 5);
            sectors.push(pillar_sector(&mut sr, kind, &sectors[0]));
            Some(sectors.len() - 1)
        };
        add_ring(ring, false, 0, back);
    }
    let start = place(start);
    let source = MapSource {
        name: "random".into(),
        vertices,
        sectors,
        lines,
        things: vec![ThingSource::new(PLAYER_START, start.x, start.y, start_angle)],
        diminishing_light: true,
        fog: None,
        ..MapSource::default()
    };
    let map = validate(&source).unwrap_or_else(|problems| {
        panic!("generator bug: invalid map {problems:?}\nspec {spec:?}\n{}", source.to_ron())
    });
    Generated { source, map, unit, pillars_placed: pillars.len() }
}

/// A usable pose: inside a sector and not on (or within 1e-3 of) a line.
pub fn usable(map: &Map, p: DVec2) -> bool {
    map.sector_strictly_containing(p).is_some() && map.distance_to_nearest_line(p) > 1e-3
}

/// Is `p` on the infinite line of some wall, up to rounding (1e-12 of the
/// coordinates' magnitude)? From there a column's ray can run exactly along
/// the wall's line, which is where the renderers' known bugs live (see
/// `properties.rs`).
pub fn on_wall_line(map: &Map, p: DVec2) -> bool {
    map.lines.iter().any(|line| {
        let (a, b) = map.line_points(line);
        let d = b - a;
        let scale = p.abs().max_element().max(a.abs().max_element()).max(b.abs().max_element());
        let distance = sightline::geom::cross(p - a, d).abs() / d.length();
        distance <= 1e-12 * scale.max(1.0)
    })
}

/// Which poses [`random_poses`] returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WallLines {
    /// Any pose.
    Any,
    /// Only poses off every wall's line ([`on_wall_line`] false).
    Avoid,
    /// Only poses on some wall's line; there may be none (a convex room with
    /// no pillars has no wall line through its inside), so fewer may return.
    Only,
}

const AXES: [(f64, f64, f64); 4] = [(1.0, 0.0, 0.0), (0.0, 1.0, 90.0), (-1.0, 0.0, 180.0), (0.0, -1.0, 270.0)];

/// Up to `count` random poses in `g`'s map (exactly `count` unless `lines`
/// is [`WallLines::Only`]), described for failure messages: uniform points,
/// points on a vertex's axis lines looking at it, points on wall extensions
/// (partition lines) looking along them, points very near walls; angles
/// sometimes exactly axis-aligned; eye heights sometimes exactly a sector's
/// floor or ceiling.
pub fn random_poses(g: &Generated, count: usize, seed: u64, lines: WallLines) -> Vec<(String, View)> {
    let map = &g.map;
    let mut r = rng(seed, 6);
    let (lo, hi) = bbox(&map.vertices);
    let extent = (hi - lo).max_element();
    let mut poses = Vec::new();
    let mut attempts = 0;
    while poses.len() < count {
        attempts += 1;
        if attempts >= 20_000 {
            assert!(lines == WallLines::Only, "generator bug: cannot find poses in\n{}", g.source.to_ron());
            break;
        }
        let axis_angle = |r: &mut ChaCha8Rng| AXES[r.random_range(0..4)].2;
        let kind = if lines == WallLines::Only { 7 } else { r.random_range(0..10) };
        let (what, p, angle) = match kind {
            0..=3 => {
                let p = DVec2::new(r.random_range(lo.x..=hi.x), r.random_range(lo.y..=hi.y));
                let angle = if r.random_bool(0.3) { axis_angle(&mut r) } else { r.random_range(0.0..360.0) };
                ("uniform", p, angle)
            }
            4..=6 => {
                // On an axis line through a vertex, looking along it at the vertex.
                let v = map.vertices[r.random_range(0..map.vertices.len())];
                let (dx, dy, angle) = AXES[r.random_range(0..4)];
                let d = r.random_range(0.0..extent) * if r.random_bool(0.3) { 0.01 } else { 1.0 };
                let p = DVec2::new(v.x - dx * d, v.y - dy * d);
                let angle = if r.random_bool(0.8) { angle } else { r.random_range(0.0..360.0) };
                ("vertex axis", p, angle)
            }
            7..=8 => {
                // On the extension of a wall (a partition line), mostly
                // looking along it.
                let line = &map.lines[r.random_range(0..map.lines.len())];
                let (a, b) = map.line_points(line);
                let t = if r.random_bool(0.5) { r.random_range(-4.0..-0.001) } else { r.random_range(1.001..5.0) };
                let d = b - a;
                let along = d.y.atan2(d.x).to_degrees();
                let angle = [along, along + 180.0, along, along + 180.0, along + 90.0, r.random_range(0.0..360.0)]
                    [r.random_range(0..6)];
                let p = a + d * t;
                if lines == WallLines::Avoid {
                    // Just off the line instead: a hair to either side.
                    let normal = DVec2::new(d.y, -d.x) / d.length();
                    let scale = p.abs().max_element().max(1.0);
                    let gap = [1e-10, 1e-9, 1e-6, 1e-3][r.random_range(0..4)] * scale;
                    let side = if r.random_bool(0.5) { 1.0 } else { -1.0 };
                    ("beside wall extension", p + normal * gap * side, angle)
                } else {
                    ("wall extension", p, angle)
                }
            }
            _ => {
                // Just in front of a wall's midpoint.
                let line = &map.lines[r.random_range(0..map.lines.len())];
                let (a, b) = map.line_points(line);
                let d = (b - a).normalize();
                let normal = DVec2::new(d.y, -d.x) * if r.random_bool(0.5) { 1.0 } else { -1.0 };
                let gap = [0.002, 0.01, 0.1, 1.0][r.random_range(0..4)] * g.unit.max(1.0);
                let facing = (-normal).y.atan2((-normal).x).to_degrees();
                let angle = facing + r.random_range(-60.0..60.0);
                ("near wall", (a + b) * 0.5 + normal * gap, angle)
            }
        };
        if !usable(map, p) {
            continue;
        }
        let on_line = on_wall_line(map, p);
        match lines {
            WallLines::Avoid if on_line => continue,
            WallLines::Only if !on_line => continue,
            _ => {}
        }
        // Strictly inside (usable), so the map alone says which sector: the
        // poses serve every compile of the map.
        let sector = map.sector_strictly_containing(p).expect("a usable pose is inside a sector");
        let z = match r.random_range(0..4) {
            0 | 1 => map.sectors[sector].floor + EYE_HEIGHT,
            2 => {
                let s = &map.sectors[r.random_range(0..map.sectors.len())];
                if r.random_bool(0.5) {
                    s.floor
                } else {
                    s.ceiling
                }
            }
            _ => r.random_range(-80.0..300.0),
        };
        let view = View::new(p, z, angle);
        poses.push((
            format!(
                "{what} pose{} ({:?}, {:?}) angle {angle:?} z {:?} in sector {sector}",
                if on_line { " on a wall line" } else { "" },
                p.x,
                p.y,
                view.z
            ),
            view,
        ));
    }
    poses
}

/// The map's text and the spec, for failure messages.
pub fn describe(spec: &MapSpec, g: &Generated) -> String {
    format!("spec {spec:?}\nmap:\n{}", g.source.to_ron())
}

/// Compiles with the given splitter or fails with the map attached.
pub fn compile(spec: &MapSpec, g: &Generated, splitter: sightline::bsp::SplitterKind, seed: u64) -> Level {
    let options = sightline::bsp::BuildOptions { splitter, seed };
    let compiled = sightline::bsp::build(&g.map, &options)
        .unwrap_or_else(|e| panic!("{} (seed {seed}) failed to compile: {e}\n{}", splitter.name(), describe(spec, g)));
    Level::with_builtin_textures(compiled).unwrap_or_else(|e| panic!("{e}"))
}
