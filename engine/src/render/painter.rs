//! Painter's algorithm over the compiled BSP, for the visibility study: the
//! tree walked far child first, every facing seg's columns drawn whole
//! (ceiling from the top row, wall parts, floor to the bottom row) over
//! whatever is there. Nothing is occluded and nothing culled, so nearer segs
//! simply overwrite; the overdraw is what the study measures against the
//! front-to-back walk's exactly-once.
//!
//! Why the picture is the front-to-back one: in a column, a seg paints every
//! row outside its opening (all rows, for a solid wall), and the BSP
//! renderer's open window at a seg is exactly the rows outside every nearer
//! seg's painted rows. So "the last seg painted, far to near" and "the first
//! seg met, near to far" pick the same seg for every pixel. Both renderers
//! draw a seg through the one [`draw_seg`], with the column window
//! opened to the whole column first, so the pixels are computed alike.
//!
//! Left out: sprites and see-through middles (the masked pass), and
//! visplane spans (textured floors and ceilings are painted per column:
//! spans gathered during a far-to-near walk would be drawn after it, over
//! nearer walls).

use super::columns::ColumnWriter;
use super::frame::{Scene, StripFrame};
use super::plan::Plan;
use super::shade::{colour, Surface};
use super::walls::draw_seg;
use crate::bsp::{Child, Seg};

/// Draws the strip `[x0, x1)` far to near.
pub(crate) fn render(scene: &Scene, frame: &mut StripFrame, out: &mut ColumnWriter, strip: (usize, usize)) {
    let scene = &without_deferred(scene);
    clear(scene, out, strip);
    let bsp = &scene.level.bsp;
    // Near child pushed first, so the far one is popped (and finished) first.
    frame.stack.clear();
    frame.stack.push((bsp.root, None, None));
    while let Some((child, ..)) = frame.stack.pop() {
        match child {
            Child::Node(i) => {
                frame.stats.nodes_visited += 1;
                let node = &bsp.nodes[i];
                let near = super::bsp::near_side(node, scene.cam) as usize;
                frame.stack.push((node.children[near], None, None));
                frame.stack.push((node.children[1 - near], None, None));
            }
            Child::Leaf(i) => {
                frame.stats.leaves_visited += 1;
                // A leaf is convex and its segs face into it: facing segs
                // never overlap on screen, so their order does not matter.
                for seg in bsp.leaf_segs(&bsp.leaves[i]) {
                    if open_whole_columns(scene, seg, frame, strip).is_some() {
                        draw_seg(scene, seg, frame, out, None);
                    } else {
                        frame.stats.walls_considered += 1;
                    }
                }
            }
        }
    }
}

/// The scene as painter's and the z-buffer draw it: no masked pass (no clip
/// events or masked middles recorded) and planes painted per column.
pub(super) fn without_deferred<'a>(scene: &Scene<'a>) -> Scene<'a> {
    Scene { spans: false, plan: Plan { sprites: false, masked: false, ..scene.plan }, ..*scene }
}

/// Paints the strip void: both overwriting renderers start from a cleared
/// screen (neither knows beforehand which pixels no surface will cover), and
/// the clear counts as one write per pixel.
pub(super) fn clear(scene: &Scene, out: &mut ColumnWriter, (x0, x1): (usize, usize)) {
    let void = colour(scene.shade, Surface::Void, 0, 1.0);
    let h = scene.cam.height as i32;
    for x in x0..x1 {
        out.fill(x, 0, h, void);
    }
}

/// Opens exactly the columns of the strip that `seg` covers, each over all
/// its rows, so that [`draw_seg`] paints the seg's whole columns and
/// nothing else; returns those columns, or `None` when the seg covers no
/// column of the strip (`draw_seg` still decides facing itself).
pub(super) fn open_whole_columns(
    scene: &Scene,
    seg: &Seg,
    frame: &mut StripFrame,
    (x0, x1): (usize, usize),
) -> Option<(usize, usize)> {
    let cam = scene.cam;
    // A back-facing seg projects right to left, an empty span.
    let (a, b) = cam.project_span_in(scene.slopes, cam.to_camera(seg.v1), cam.to_camera(seg.v2))?;
    let (a, b) = (a.max(x0), b.min(x1));
    if a >= b {
        return None;
    }
    // O(width / 64) words: cheap beside the seg's columns.
    frame.occlusion.reset_to_strip(cam.width, a, b);
    frame.clip_top[a..b].fill(0);
    frame.clip_bottom[a..b].fill(cam.height as i32);
    Some((a, b))
}
