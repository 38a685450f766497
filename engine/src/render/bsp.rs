//! The front-to-back walk of the compiled BSP. Near subtrees are drawn before
//! far ones; a subtree whose bounding box projects only onto closed columns is
//! skipped; the walk stops as soon as every column has closed. Leaves hand
//! their segs to [`super::walls`].

use super::columns::ColumnWriter;
use super::frame::{Scene, StripFrame};
use super::shade::{Shade, Surface, VOID};
use super::view::Camera;
use super::walls::draw_seg;
use crate::bsp::build::ON_EPSILON;
use crate::bsp::{Child, Node};
use crate::geom::{front_distance, Aabb};
use glam::DVec2;

/// Walks the tree for the strip `frame` was readied for.
pub(crate) fn render(scene: &Scene, frame: &mut StripFrame, out: &mut ColumnWriter) {
    let (cam, bsp) = (scene.cam, &scene.level.bsp);
    frame.stack.push((bsp.root, None, None));
    while let Some((child, bbox, along)) = frame.stack.pop() {
        if frame.occlusion.all_closed() {
            break;
        }
        if let Some(bbox) = bbox {
            if !box_visible(cam, scene.slopes, &bbox, frame, along) {
                frame.stats.subtrees_culled += 1;
                continue;
            }
        }
        match child {
            Child::Node(i) => {
                frame.stats.nodes_visited += 1;
                let node = &bsp.nodes[i];
                let near = near_side(node, cam) as usize;
                // Below a partition the eye looks along, seg ends the
                // compiler counted as on it count as on it (see `along`).
                let along = along.or_else(|| looks_along(node, cam));
                frame.stack.push((node.children[1 - near], Some(node.bbox[1 - near]), along));
                frame.stack.push((node.children[near], Some(node.bbox[near]), along));
            }
            Child::Leaf(i) => {
                frame.stats.leaves_visited += 1;
                let leaf = &bsp.leaves[i];
                for seg in bsp.leaf_segs(leaf) {
                    draw_seg(scene, seg, frame, out, along);
                    if frame.occlusion.all_closed() {
                        break;
                    }
                }
            }
        }
    }
    fill_void(frame, out, scene.shade);
}

/// Which child of `node` is nearer the eye: `false` for the front, `true` for the back.
///
/// Off the partition line it is the eye's side, as computed: near-ties are
/// left to the same rounding the column predicates see. Exactly on it, every
/// ray but one meets only one side, so order matters only for the column whose
/// ray runs along the line. The screen's half-open rule gives that column to
/// what starts at the ray, as if the ray were an infinitesimal step to its
/// right: the front side when the ray runs `a -> b`, the back when `b -> a`.
/// That order is right only if the pieces touching the ray from that side
/// reach it, which split points rounded off the line need not: see
/// [`looks_along`].
pub(crate) fn near_side(node: &Node, cam: &Camera) -> bool {
    let d = front_distance(node.a, node.b, cam.eye);
    if d == 0.0 {
        (node.b - node.a).dot(cam.forward) < 0.0
    } else {
        d < 0.0
    }
}

/// Does the eye look exactly along `node`'s partition, on it or within the
/// compiler's `ON_EPSILON` of it? The answer is the partition's sideways
/// offset in camera space (the line is the camera's y = offset; 0 with the
/// eye exactly on it, so that with an odd width the centre column's ray runs
/// along it).
///
/// Then the column along the line is drawn from the side [`near_side`]
/// picks, and the segs that should claim it are the pieces of the lines
/// crossing the partition, cut at it. Their cut points are rounded: one that
/// lands an ulp on the near side leaves its near piece short of the ray, so
/// the near subtree's farther walls took the column, and the far piece, drawn
/// later, found it closed (a random map of `tests/locate.rs`: a pillar's face
/// lost 65 pixels of column 63 to the wall behind it; `tests/properties.rs`,
/// `regression_eye_on_partition_looking_along_it`). The compiler counts any
/// seg end within `ON_EPSILON` of a partition as on it; below such a node
/// the walk does too ([`onto_partition`]), so the near piece reaches the
/// partition exactly and owns the column, and the far piece stops there and
/// does not. An eye a hair off the line, looking exactly along it, has the
/// same trouble (the centre ray runs between the line and a rounded cut
/// point: `tests/buffers.rs`,
/// `a_ray_a_hair_beside_a_partition_meets_the_near_pieces`), and the same
/// cure: the cut points go onto the line, on its side of the ray.
pub(crate) fn looks_along(node: &Node, cam: &Camera) -> Option<f64> {
    // The distance first: most nodes are far from the eye, and it rules them out.
    if front_distance(node.a, node.b, cam.eye).abs() >= ON_EPSILON {
        return None;
    }
    let (a, b) = (cam.to_camera(node.a), cam.to_camera(node.b));
    (b.y - a.y == 0.0).then_some(a.y)
}

/// A seg end (camera space) under a partition the eye looks along, at
/// sideways offset `line` ([`looks_along`]): within the compiler's
/// `ON_EPSILON` of that line, it is on it.
#[inline]
pub(crate) fn onto_partition(p: DVec2, line: f64) -> DVec2 {
    if (p.y - line).abs() < ON_EPSILON {
        DVec2::new(p.x, line)
    } else {
        p
    }
}

/// Columns still open after the walk look out of the map: paint them void, so
/// that every pixel is still written exactly once.
fn fill_void(frame: &mut StripFrame, out: &mut ColumnWriter, shade: Shade) {
    let colour = if shade == Shade::Ids { super::shade::ids_colour(Surface::Void) } else { VOID };
    let width = frame.occlusion.width();
    let mut x = 0;
    while let Some(start) = frame.occlusion.next_open(x, width) {
        let stop = frame.occlusion.next_closed(start, width);
        for col in start..stop {
            out.fill(col, frame.clip_top[col], frame.clip_bottom[col], colour);
            out.buffers.far(col, (frame.clip_top[col], frame.clip_bottom[col]));
        }
        x = stop;
    }
}

/// Could anything inside `bbox` still show? Projects the box's silhouette (the
/// two corners that bound it as seen from the eye, as Doom's R_CheckBBox picks
/// them) and asks the occlusion array about the columns between.
///
/// Under a partition the eye looks `along`, a box that reaches within
/// `ON_EPSILON` of that line in front of the eye is visible: a seg end in it
/// may be moved onto the line ([`onto_partition`]), and the silhouette of
/// the unmoved box could miss the column along it.
fn box_visible(cam: &Camera, slopes: &[f64], bbox: &Aabb, frame: &StripFrame, along: Option<f64>) -> bool {
    // Within a unit of the box, call it visible: the silhouette argument below
    // needs the eye clear of the box by much more than NEAR.
    let grown = Aabb { min: bbox.min - 1.0, max: bbox.max + 1.0 };
    if grown.contains(cam.eye) {
        return true;
    }
    let (e, lo, hi) = (cam.eye, bbox.min, bbox.max);
    if let Some(line) = along {
        let corners = [lo, hi, glam::DVec2::new(lo.x, hi.y), glam::DVec2::new(hi.x, lo.y)].map(|c| cam.to_camera(c));
        let (low, high) = corners.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), c| (l.min(c.y), h.max(c.y)));
        if low < line + ON_EPSILON && high > line - ON_EPSILON && corners.iter().any(|c| c.x > 0.0) {
            return true;
        }
    }
    let region = |v: f64, lo: f64, hi: f64| {
        if v < lo {
            0
        } else if v <= hi {
            1
        } else {
            2
        }
    };
    // Corners counter-clockwise from bottom-left.
    let c = [lo, glam::DVec2::new(hi.x, lo.y), hi, glam::DVec2::new(lo.x, hi.y)];
    // The visible chain of box edges runs counter-clockwise from `a` to `b`, so
    // the eye is on the right of a -> b and `a` projects left of `b`.
    let (a, b) = match (region(e.x, lo.x, hi.x), region(e.y, lo.y, hi.y)) {
        (0, 0) => (c[3], c[1]),
        (1, 0) => (c[0], c[1]),
        (2, 0) => (c[0], c[2]),
        (0, 1) => (c[3], c[0]),
        (2, 1) => (c[1], c[2]),
        (0, 2) => (c[2], c[0]),
        (1, 2) => (c[2], c[3]),
        (2, 2) => (c[1], c[3]),
        _ => return true,
    };
    match cam.project_span_in(slopes, cam.to_camera(a), cam.to_camera(b)) {
        Some((x0, x1)) => frame.occlusion.any_open(x0, x1),
        None => false,
    }
}
