//! Line of sight (`p_sight.c`): REJECT first, then the trace down the WAD's
//! nodes (`P_CrossBSPNode`), as Doom 1.9 checks it. Monsters looking for
//! players, attacks deciding to fire and blast damage ask it; it changes
//! nothing but `validcount` and the shared slopes in `sim.tm`.

use super::level::{ml, NF_SUBSECTOR};
use super::maputl;
use super::{MobjId, Sim};
use crate::fixed::{intercept_vector, Divline, Fixed};

/// The sight trace's fixed parts (`strace`, `t2x`, `t2y`, `sightzstart`),
/// and whether `P_DivlineSide`'s typo is kept (vanilla rules).
struct Trace {
    line: Divline,
    t2x: Fixed,
    t2y: Fixed,
    zstart: Fixed,
    typo: bool,
}

/// `P_DivlineSide`: 0 front, 1 back, 2 on the line. Unlike the other side
/// tests it drops both factors' fractions and multiplies in plain (wrapping)
/// integers, and it says "on" for exact ties. Its horizontal case compares
/// `x` with the line's `y` (a typo in Doom, kept under vanilla rules since
/// it decides sight: `typo`; Sightline's rules compare `y`).
pub fn divline_side(x: Fixed, y: Fixed, node: &Divline, typo: bool) -> u8 {
    if node.dx.0 == 0 {
        if x == node.x {
            return 2;
        }
        if x <= node.x {
            return u8::from(node.dy.0 > 0);
        }
        return u8::from(node.dy.0 < 0);
    }
    if node.dy.0 == 0 {
        if (if typo { x } else { y }) == node.y {
            return 2;
        }
        if y <= node.y {
            return u8::from(node.dx.0 < 0);
        }
        return u8::from(node.dx.0 > 0);
    }
    let (dx, dy) = ((x - node.x).0, (y - node.y).0);
    let left = (node.dy.0 >> 16).wrapping_mul(dx >> 16);
    let right = (dy >> 16).wrapping_mul(node.dx.0 >> 16);
    if right < left {
        0
    } else if left == right {
        2
    } else {
        1
    }
}

/// `P_CrossSubsector`: whether the trace passes subsector `num`'s lines:
/// a one-sided line stops it, a two-sided one narrows the slopes by its
/// opening and stops it when they close.
fn cross_subsector(sim: &mut Sim, t: &Trace, num: usize) -> bool {
    let Some(sub) = sim.level.subsectors.get(num) else {
        return false;
    };
    let (first, count) = (sub.firstline, sub.numlines);
    for segnum in first..first + count {
        let Some(seg) = sim.level.segs.get(segnum) else {
            break;
        };
        let (linedef, front, back) = (seg.linedef, seg.frontsector, seg.backsector);
        let Some(mark) = sim.line_valid.get_mut(linedef) else {
            continue;
        };
        if *mark == sim.validcount {
            continue;
        }
        *mark = sim.validcount;
        let line = &sim.level.lines[linedef];
        let (v1, v2) = (line.v1, line.v2);
        if divline_side(v1.0, v1.1, &t.line, t.typo) == divline_side(v2.0, v2.1, &t.line, t.typo) {
            continue;
        }
        let divl = Divline { x: v1.0, y: v1.1, dx: v2.0 - v1.0, dy: v2.1 - v1.1 };
        if divline_side(t.line.x, t.line.y, &divl, t.typo) == divline_side(t.t2x, t.t2y, &divl, t.typo) {
            continue;
        }
        // No back sector: Chocolate's "impassible glass" hack line.
        if line.backsector.is_none() || line.flags & ml::TWOSIDED == 0 {
            return false;
        }
        let Some(back) = back else {
            return false;
        };
        let (f, b) = (&sim.level.sectors[front], &sim.level.sectors[back]);
        if f.floorheight == b.floorheight && f.ceilingheight == b.ceilingheight {
            continue;
        }
        let opentop = f.ceilingheight.min(b.ceilingheight);
        let openbottom = f.floorheight.max(b.floorheight);
        if openbottom >= opentop {
            return false;
        }
        let frac = intercept_vector(&t.line, &divl);
        if f.floorheight != b.floorheight {
            let slope = (openbottom - t.zstart) / frac;
            if slope > sim.tm.bottomslope {
                sim.tm.bottomslope = slope;
            }
        }
        if f.ceilingheight != b.ceilingheight {
            let slope = (opentop - t.zstart) / frac;
            if slope < sim.tm.topslope {
                sim.tm.topslope = slope;
            }
        }
        if sim.tm.topslope <= sim.tm.bottomslope {
            return false;
        }
    }
    true
}

/// `P_CrossBSPNode`: the start's side of each partition first, then the
/// far side when the trace crosses the partition. `bspnum` is Doom's int:
/// -1 (no nodes) is subsector 0.
fn cross_bsp_node(sim: &mut Sim, t: &Trace, bspnum: i32) -> bool {
    if bspnum == -1 {
        return cross_subsector(sim, t, 0);
    }
    let child = bspnum as u16;
    if child & NF_SUBSECTOR != 0 {
        return cross_subsector(sim, t, usize::from(child & !NF_SUBSECTOR));
    }
    let Some(node) = sim.level.nodes.get(usize::from(child)) else {
        return false;
    };
    let div = Divline { x: node.x, y: node.y, dx: node.dx, dy: node.dy };
    let children = node.children;
    let mut side = divline_side(t.line.x, t.line.y, &div, t.typo);
    if side == 2 {
        side = 0;
    }
    if !cross_bsp_node(sim, t, i32::from(children[usize::from(side)])) {
        return false;
    }
    if side == divline_side(t.t2x, t.t2y, &div, t.typo) {
        return true;
    }
    cross_bsp_node(sim, t, i32::from(children[usize::from(side ^ 1)]))
}

/// `P_CheckSight`: whether `looker` can see `target`: not if REJECT says
/// their sectors never see each other, else along the trace from the
/// looker's eyes (three quarters up) to any part of the target.
///
/// Every game version these rules follow (1.9, Ultimate, Final) walks the
/// BSP; Doom 1.2's `P_PathTraverse` sight is not needed.
pub fn check_sight(sim: &mut Sim, looker: MobjId, target: MobjId) -> bool {
    let (s1, s2) = (sim.sector_of(looker), sim.sector_of(target));
    if sim.level.rejected(s1, s2) {
        return false;
    }
    maputl::next_validcount(sim);
    let (t1, t2) = (sim.mo(looker), sim.mo(target));
    let zstart = t1.z + t1.height - (t1.height >> 2);
    let (top, bottom) = (t2.z + t2.height - zstart, t2.z - zstart);
    let trace = Trace {
        line: Divline { x: t1.x, y: t1.y, dx: t2.x - t1.x, dy: t2.y - t1.y },
        t2x: t2.x,
        t2y: t2.y,
        zstart,
        typo: sim.rules.compat == super::Compat::Vanilla,
    };
    sim.tm.topslope = top;
    sim.tm.bottomslope = bottom;
    let head = sim.level.nodes.len() as i32 - 1;
    cross_bsp_node(sim, &trace, head)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn u(n: i32) -> Fixed {
        Fixed::from_int(n)
    }

    #[test]
    fn divline_side_has_an_on_answer_and_doom_s_typo() {
        // A partition going north through x = 64: east is the front.
        let north = Divline { x: u(64), y: u(0), dx: u(0), dy: u(128) };
        assert_eq!(divline_side(u(100), u(5), &north, true), 0);
        assert_eq!(divline_side(u(10), u(5), &north, true), 1);
        assert_eq!(divline_side(u(64), u(500), &north, true), 2);
        // A partition going east along y = 32: the south is the front...
        let east = Divline { x: u(0), y: u(32), dx: u(128), dy: u(0) };
        assert_eq!(divline_side(u(5), u(0), &east, true), 0);
        assert_eq!(divline_side(u(5), u(40), &east, true), 1);
        // ...but a point whose x equals the line's y is "on" (Doom compares x).
        assert_eq!(divline_side(u(32), u(0), &east, true), 2);
        assert_eq!(divline_side(u(5), u(32), &east, true), 0);
        // Sightline's rules compare y: a point on the line is "on".
        assert_eq!(divline_side(u(32), u(0), &east, false), 0);
        assert_eq!(divline_side(u(5), u(32), &east, false), 2);
        // Diagonal: whole units only; (1,1) on the line y = x ties.
        let diag = Divline { x: u(0), y: u(0), dx: u(10), dy: u(10) };
        assert_eq!(divline_side(u(3), u(3), &diag, true), 2);
        assert_eq!(divline_side(u(3), u(1), &diag, true), 0);
        assert_eq!(divline_side(u(1), u(3), &diag, true), 1);
        // Fractions are dropped: 3.9 and 3 are both 3, so it is "on".
        assert_eq!(divline_side(Fixed(3 * 65536 + 60000), u(3), &diag, true), 2);
    }
}
