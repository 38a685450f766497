//! The reference renderer: the oracle every test compares against.
//!
//! Brute force in f64 and independent of the BSP path: each column's ray is
//! intersected with every line of the map, the crossings sorted by depth, and
//! each pixel's ray followed through them one by one (the z-buffer idea, per
//! ray). It shares only the view definition and the pixel writer.
//!
//! A pixel's ray at depth `d` is at height `h = z + d * slope`; at a crossing
//! with a sector `F` on the near side it sees F's ceiling if `h > F.ceiling`,
//! F's floor if `h <= F.floor`, else the line: solid if one-sided, and on a
//! two-sided line the upper wall if `h > B.ceiling`, the lower if
//! `h <= B.floor`, otherwise it passes on to the next crossing.

use glam::DVec2;

use super::columns::ColumnWriter;
use super::frame::{Hit, StripFrame};
use super::shade::{
    ceiling_at_line, colour, masked_top, plane_lights, plane_surfaces, side_offsets, wall_facing, Shade, Surface,
};
use super::view::{hides_sprite, Camera, NEAR, TIE};
use crate::geom::{cross, on_segment};
use crate::level::Level;
use crate::map::Map;
use crate::texture::Texture;

/// The reference's per-frame set-up, shared by every strip: each line's ends
/// in camera space (and whether it is two-sided), the sector each ray starts
/// in, and the things in front of the eye.
pub struct Reference<'a> {
    level: &'a Level,
    cam: &'a Camera,
    ends: Vec<(DVec2, DVec2, bool)>,
    eye: EyeSector,
    things: Vec<Billboard<'a>>,
    /// See-through middles are drawn (not disabled).
    masked: bool,
}

impl<'a> Reference<'a> {
    pub fn new(level: &'a Level, cam: &'a Camera) -> Reference<'a> {
        let map = &level.map;
        let ends = map
            .lines
            .iter()
            .map(|l| {
                let (a, b) = map.line_points(l);
                (cam.to_camera(a), cam.to_camera(b), l.back.is_some())
            })
            .collect();
        Reference { level, cam, ends, eye: EyeSector::new(map, cam), things: things_in_front(level, cam), masked: true }
    }

    /// Leaves out the effects `disabled` names that the reference draws:
    /// things (sprites) and see-through middles, as the other renderers do.
    pub fn leaving_out(mut self, disabled: super::plan::Disabled) -> Reference<'a> {
        if disabled.sprites {
            self.things.clear();
        }
        self.masked &= !disabled.masked;
        self
    }

    /// Renders `columns` (one strip) of the frame.
    pub(crate) fn render(
        &self,
        columns: std::ops::Range<usize>,
        frame: &mut StripFrame,
        out: &mut ColumnWriter,
        shade: Shade,
    ) {
        let (level, cam, ends, things) = (self.level, self.cam, &self.ends, &self.things);
        let map = &level.map;
        for x in columns {
            collect_hits(cam, ends, x, &mut frame.hits);
            order_ties(map, self.eye.of_column(cam, x), &mut frame.hits);
            let sprites = sprites_on_column(cam, things, x);
            frame.stats.walls_considered += ends.len() as u64;
            let mut run: Option<(i32, u32)> = None;
            let buffers = out.buffers.on();
            for y in 0..cam.height as i32 {
                let seen =
                    pixel(level, cam, ends, &frame.hits, &sprites, (cam.column_slope(x), y), (shade, self.masked));
                if buffers {
                    out.buffers.pixel(x, y, seen.depth(cam, y), seen.label());
                }
                let c = seen.colour;
                match run {
                    Some((_, rc)) if rc == c => {}
                    Some((start, rc)) => {
                        out.fill(x, start, y, rc);
                        run = Some((y, c));
                    }
                    None => run = Some((y, c)),
                }
            }
            if let Some((start, rc)) = run {
                out.fill(x, start, cam.height as i32, rc);
            }
        }
    }
}

/// Every line column `x`'s ray crosses at depth >= NEAR, nearest first.
///
/// A ray exactly through a line's end follows the screen's half-open rule
/// ([`Camera::left_of_or_on`]): the line seen from its visible side owns its
/// left end, not its right, so two walls meeting at a vertex never both claim
/// the ray through it and never both miss it.
///
/// The back of a one-sided wall is skipped: from inside the map a ray meets
/// the solid's front faces first, and at most ties with its back at a corner.
fn collect_hits(cam: &Camera, ends: &[(DVec2, DVec2, bool)], x: usize, hits: &mut Vec<Hit>) {
    hits.clear();
    let t = cam.column_slope(x);
    let ray = DVec2::new(1.0, t);
    for (line, &(a, b, two_sided)) in ends.iter().enumerate() {
        let d = b - a;
        let den = cross(ray, d);
        // On the line, or along it: edge-on, nothing to see.
        let c = cross(a, d);
        if den == 0.0 || c == 0.0 {
            continue;
        }
        // Solve depth * ray = a + w * d.
        let depth = c / den;
        // NaN fails both tests; so does a depth behind or at infinity.
        if !depth.is_finite() || depth < NEAR {
            continue;
        }
        // Camera space mirrors the map, so the eye is on the line's front
        // (right-hand) side when cross(a, d) > 0 here.
        let from_front = c > 0.0;
        if !from_front && !two_sided {
            continue;
        }
        // Each end in front of the eye is settled by the half-open rule; an end
        // behind it (no ray on screen passes near it) by the line parameter.
        let w = cross(a, ray) / den;
        let (left, right) = if from_front { (a, b) } else { (b, a) };
        let (left_bound, right_bound) = if from_front { (w >= 0.0, w <= 1.0) } else { (w <= 1.0, w >= 0.0) };
        let left_ok = if left.x > 0.0 { cam.left_of_or_on(left, x) } else { left_bound };
        let right_ok = if right.x > 0.0 { !cam.left_of_or_on(right, x) } else { right_bound };
        let crosses = left_ok && right_ok;
        if crosses {
            hits.push(Hit { depth, line, from_front });
        }
    }
    hits.sort_by(|p, q| p.depth.total_cmp(&q.depth).then(p.line.cmp(&q.line)));
}

/// The sector a column's ray is in as it leaves the eye: where
/// [`order_ties`] starts its chain.
///
/// Not one sector for the whole frame: an eye on a line between two sectors
/// (a pose in a doorway) sends the rays on one side of the line through one
/// sector and the rest through the other. Decided from the map alone, as
/// the rest of the reference is.
enum EyeSector {
    /// The eye is on no line: every ray starts in the sector strictly
    /// containing it (`None` in the void).
    Inside(Option<usize>),
    /// The eye is on lines. One spoke per line end seen from the eye (two
    /// for a line through it, one for a line ending at it); a ray starts in
    /// the wedge it leaves into, whose sector is the one clockwise of the
    /// first spoke counter-clockwise from the ray.
    OnLines(Vec<Spoke>),
}

struct Spoke {
    /// Where the spoke goes, in camera space (depth, sideways) from the eye.
    to: DVec2,
    /// The sector on its clockwise side (right, looking out along it).
    right: Option<usize>,
}

impl EyeSector {
    fn new(map: &Map, cam: &Camera) -> EyeSector {
        let mut spokes = Vec::new();
        for line in &map.lines {
            let (a, b) = map.line_points(line);
            if !on_segment(a, b, cam.eye) {
                continue;
            }
            let (front, back) = (Some(line.front.sector), line.back.as_ref().map(|s| s.sector));
            // Out along `a -> b` the front is on the right; out along `b -> a` the back.
            if cam.eye != b {
                spokes.push(Spoke { to: cam.to_camera(b), right: front });
            }
            if cam.eye != a {
                spokes.push(Spoke { to: cam.to_camera(a), right: back });
            }
        }
        if spokes.is_empty() {
            EyeSector::Inside(map.sector_strictly_containing(cam.eye))
        } else {
            EyeSector::OnLines(spokes)
        }
    }

    /// The sector column `x`'s ray starts in. A ray exactly along a spoke
    /// counts as stepped to its right, the screen's half-open rule
    /// ([`Camera::left_of_or_on`], whose sign test this repeats): it starts
    /// clockwise of that spoke, as the walk draws that column from the
    /// partition's side the ray runs `a -> b` along.
    fn of_column(&self, cam: &Camera, x: usize) -> Option<usize> {
        match self {
            EyeSector::Inside(sector) => *sector,
            EyeSector::OnLines(spokes) => {
                let t = cam.column_slope(x);
                // Counter-clockwise (map) angle from the ray (1, t) to the
                // spoke, in [0, 2 pi): camera space mirrors the map, so its
                // sine is t * p.x - p.y, and 0 exactly when the column's ray
                // passes through the spoke's end (left_of_or_on's tie).
                let angle = |p: DVec2| (t * p.x - p.y).atan2(p.x + t * p.y).rem_euclid(std::f64::consts::TAU);
                spokes.iter().min_by(|p, q| angle(p.to).total_cmp(&angle(q.to))).and_then(|s| s.right)
            }
        }
    }
}

/// Puts crossings at the same depth in the order the ray meets them. Through a
/// vertex where it enters and leaves a sector at once, the ray crosses first
/// the line whose near side is the sector it is in, then the next.
fn order_ties(map: &Map, start: Option<usize>, hits: &mut [Hit]) {
    let sides = |h: &Hit| {
        let line = &map.lines[h.line];
        let (front, back) = (line.front.sector, line.back.as_ref().map(|b| b.sector));
        if h.from_front {
            (Some(front), back)
        } else {
            (back, Some(front))
        }
    };
    let mut current = start;
    let mut i = 0;
    while i < hits.len() {
        let tied = hits[i..].iter().take_while(|h| h.depth - hits[i].depth <= hits[i].depth * TIE).count();
        if tied > 1 {
            if let Some(k) = (i..i + tied).find(|&k| sides(&hits[k]).0 == current) {
                hits[i..=k].rotate_right(1);
            }
        }
        current = sides(&hits[i]).1;
        i += 1;
    }
}

/// A thing in front of the eye: its depth, the sideways position of its
/// left edge, and its sprite.
struct Billboard<'a> {
    thing: usize,
    depth: f64,
    left: f64,
    texture: &'a Texture,
    floor: f64,
    light: u8,
}

impl Billboard<'_> {
    /// Its top and bottom heights, as the walk's sprites have them.
    fn edges(&self) -> (f64, f64) {
        (self.floor + self.texture.height as f64, self.floor)
    }
}

fn things_in_front<'a>(level: &'a Level, cam: &Camera) -> Vec<Billboard<'a>> {
    let mut out = Vec::new();
    for t in &level.things {
        let q = cam.to_camera(t.pos);
        if q.x < NEAR {
            continue;
        }
        let texture = level.materials.textures.get(t.texture_seen_from(cam.eye));
        out.push(Billboard {
            thing: t.key,
            depth: q.x,
            left: q.y - texture.width as f64 / 2.0,
            texture,
            floor: t.z,
            light: if t.bright { u8::MAX } else { level.map.sectors[t.sector].light },
        });
    }
    out
}

/// The billboards column `x`'s ray passes through, nearest first, with the
/// texel column it meets in each.
fn sprites_on_column<'a>(cam: &Camera, things: &'a [Billboard<'a>], x: usize) -> Vec<(&'a Billboard<'a>, usize)> {
    let t = cam.column_slope(x);
    let mut hits: Vec<(&Billboard, usize)> = things
        .iter()
        .filter_map(|b| {
            let u = t * b.depth - b.left;
            (0.0..b.texture.width as f64).contains(&u).then_some((b, u as usize))
        })
        .collect();
    hits.sort_by(|p, q| p.0.depth.total_cmp(&q.0.depth).then(p.0.thing.cmp(&q.0.thing)));
    hits
}

/// The opaque texel of `texture` column `u` that row `y`'s ray meets at
/// `depth`, if the ray passes within `[bottom, top)`.
///
/// Both edges are given, as the walk has them: a sprite's bottom is its
/// floor, not `top - height` (the sum and difference may round off the
/// floor, and with the eye exactly at the floor the horizon row's centre is
/// exactly on it).
fn texel_at(cam: &Camera, texture: &Texture, u: usize, (top, bottom): (f64, f64), depth: f64, y: i32) -> Option<u32> {
    if cam.row_above(y, depth, top) || !cam.row_above(y, depth, bottom) {
        return None;
    }
    let v = top - (cam.z + depth * cam.row_slope(y));
    let texel = texture.column(u.min(texture.width - 1))[(v.max(0.0) as usize).min(texture.height - 1)];
    (texel >> 24 != 0).then_some(texel)
}

/// What a pixel's ray meets first: its colour, and for the depth and label
/// buffers the surface and where.
struct Seen {
    colour: u32,
    surface: Surface,
    at: At,
}

/// Where a [`Seen`] surface is: at one depth (a wall, middle or sprite), on
/// a plane `rise` above the eye found at a crossing `limit` deep, or nowhere
/// (sky, void).
enum At {
    Depth(f64),
    Plane { rise: f64, limit: f64 },
    Far,
}

impl Seen {
    fn new(colour: u32, surface: Surface, at: At) -> Seen {
        Seen { colour, surface, at }
    }

    /// The depth buffer's value at row `y`, by the walk's formulas.
    fn depth(&self, cam: &Camera, y: i32) -> f32 {
        match (self.surface, &self.at) {
            (Surface::Sky | Surface::Void, _) | (_, At::Far) => super::buffers::FAR,
            (_, At::Depth(d)) => *d as f32,
            // `1 / row_slope`: the number the walk's `inv_rows` holds.
            (_, &At::Plane { rise, limit }) => super::buffers::plane_depth(rise, 1.0 / cam.row_slope(y), limit),
        }
    }

    fn label(&self) -> u32 {
        match self.surface {
            Surface::Thing { thing } => super::sprites::label(thing),
            _ => 0,
        }
    }
}

fn pixel(
    level: &Level,
    cam: &Camera,
    ends: &[(DVec2, DVec2, bool)],
    hits: &[Hit],
    sprites: &[(&Billboard, usize)],
    (t, y): (f64, i32),
    (shade, masked): (Shade, bool),
) -> Seen {
    let map = &level.map;
    let mut sprites = sprites.iter().peekable();
    let thing = |b: &Billboard| {
        let surface = Surface::Thing { thing: b.thing };
        Seen::new(colour(shade, surface, b.light, 1.0), surface, At::Depth(b.depth))
    };
    for hit in hits {
        // Billboards nearer than this crossing (or at its depth: a sprite
        // against a wall is in front of it) come first.
        while let Some(&&(b, u)) = sprites.peek() {
            if hides_sprite(hit.depth, b.depth) {
                break;
            }
            sprites.next();
            if texel_at(cam, b.texture, u, b.edges(), b.depth, y).is_some() {
                return thing(b);
            }
        }
        // Is this row's ray above `height` where it crosses the line?
        let above = |height: f64| cam.row_above(y, hit.depth, height);
        let line = &map.lines[hit.line];
        let (near, far) = if hit.from_front {
            (Some(&line.front), line.back.as_ref())
        } else {
            (line.back.as_ref(), Some(&line.front))
        };
        let wall = Surface::Wall { line: hit.line };
        // Backs of one-sided walls never reach here (see collect_hits).
        let Some(near) = near else { continue };
        let sector = &map.sectors[near.sector];
        let far_sector = far.map(|f| &map.sectors[f.sector]);
        let light = sector.light;
        let (ceiling_light, floor_light) = plane_lights(map, sector);
        let (ceiling, floor) = plane_surfaces(near.sector, sector);
        let plane = |height: f64| At::Plane { rise: height - cam.z, limit: hit.depth };
        if above(ceiling_at_line(sector, far_sector)) {
            return Seen::new(colour(shade, ceiling, ceiling_light, 1.0), ceiling, plane(sector.ceiling));
        }
        if !above(sector.floor) {
            return Seen::new(colour(shade, floor, floor_light, 1.0), floor, plane(sector.floor));
        }
        match far_sector {
            Some(back) if above(back.floor) && !above(back.ceiling) => {
                // Through the opening, unless a see-through middle covers it here.
                let side = usize::from(!hit.from_front);
                if let Some(id) = level.materials.side(hit.line, side).middle.filter(|_| masked) {
                    let texture = level.materials.textures.get(id);
                    let top = masked_top(map, line, !hit.from_front, texture.height as f64, level.time);
                    let u = masked_u(&ends[hit.line], side_offsets(near, level.time).0, hit, t);
                    let u = (u.floor() as i64).rem_euclid(texture.width as i64) as usize;
                    if texel_at(cam, texture, u, (top, top - texture.height as f64), hit.depth, y).is_some() {
                        return Seen::new(colour(shade, wall, light, 1.0), wall, At::Depth(hit.depth));
                    }
                }
                continue;
            }
            _ => {
                let (a, b) = map.line_points(line);
                return Seen::new(colour(shade, wall, light, wall_facing(b - a)), wall, At::Depth(hit.depth));
            }
        }
    }
    for &(b, u) in sprites {
        if texel_at(cam, b.texture, u, b.edges(), b.depth, y).is_some() {
            return thing(b);
        }
    }
    Seen::new(colour(shade, Surface::Void, 0, 1.0), Surface::Void, At::Far)
}

/// Where along its side (plus the side's offset) the crossing `hit` lies:
/// the texture column of a see-through middle.
fn masked_u(&(a, b, _): &(DVec2, DVec2, bool), x_offset: f64, hit: &Hit, t: f64) -> f64 {
    let dir = b - a;
    let length = dir.length();
    let along = (DVec2::new(hit.depth, hit.depth * t) - a).dot(dir) / length;
    x_offset + if hit.from_front { along } else { length - along }
}
