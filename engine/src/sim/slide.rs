//! The player's wall slide (`p_map.c`'s `P_SlideMove`, `PTR_SlideTraverse`,
//! `P_HitSlideLine`): when a move is blocked, three traces from the body's
//! leading corners find the nearest blocking line; the body moves up to it
//! and its momentum turns along it. Called by `P_XYMovement` for players.

use super::level::{ml, SlopeType};
use super::maputl::{self, Hit, PT_ADDLINES};
use super::{collision, MobjId, Sim};
use crate::fixed::{approx_distance, point_to_angle2, Fixed, ANG180, FRACUNIT};

/// The nearest blocking line found by the three traces (`bestslidefrac`,
/// `bestslideline`); Doom's `secondslide*` are written but never read.
struct Best {
    frac: Fixed,
    line: Option<usize>,
}

/// `PTR_SlideTraverse`: whether the line lets the body through (the back
/// of a one-sided line does); a blocking one nearer than the best so far
/// becomes the best. Always stops at the first blocking line.
fn slide_traverse(sim: &mut Sim, mo: MobjId, best: &mut Best, line: usize, frac: Fixed) -> bool {
    let ld = &sim.level.lines[line];
    let m = sim.mo(mo);
    let blocking = if ld.flags & ml::TWOSIDED == 0 {
        if maputl::point_on_map_line_side(m.x, m.y, ld) != 0 {
            return true;
        }
        true
    } else {
        maputl::line_opening(sim, line);
        let o = sim.tm.opening;
        let m = sim.mo(mo);
        o.range < m.height || o.top - m.z < m.height || o.bottom - m.z > Fixed(24 * FRACUNIT)
    };
    if !blocking {
        return true;
    }
    if frac < best.frac {
        best.frac = frac;
        best.line = Some(line);
    }
    false
}

/// `P_HitSlideLine`: turns the move (`tmxmove`, `tmymove`) along the line:
/// an axis-aligned wall zeroes one component; any other keeps the move's
/// length times the cosine of its angle to the wall.
fn hit_slide_line(sim: &Sim, mo: MobjId, line: usize, xmove: Fixed, ymove: Fixed) -> (Fixed, Fixed) {
    let ld = &sim.level.lines[line];
    match ld.slopetype {
        SlopeType::Horizontal => return (xmove, Fixed::ZERO),
        SlopeType::Vertical => return (Fixed::ZERO, ymove),
        _ => {}
    }
    let m = sim.mo(mo);
    let side = maputl::point_on_map_line_side(m.x, m.y, ld);
    let mut lineangle = point_to_angle2(Fixed::ZERO, Fixed::ZERO, ld.dx, ld.dy);
    if side == 1 {
        lineangle += ANG180;
    }
    let moveangle = point_to_angle2(Fixed::ZERO, Fixed::ZERO, xmove, ymove);
    let mut deltaangle = moveangle - lineangle;
    if deltaangle.0 > ANG180.0 {
        deltaangle += ANG180;
    }
    let movelen = approx_distance(xmove, ymove);
    let newlen = movelen * deltaangle.cos();
    (newlen * lineangle.cos(), newlen * lineangle.sin())
}

/// `P_SlideMove`: the blocked move of `mo`'s momentum slid along the wall
/// it hit. Up to two tries of tracing and sliding; the third, or a trace
/// that found nothing, falls back to the "stairstep" (the y move, else the
/// x move).
pub fn slide_move(sim: &mut Sim, mo: MobjId) {
    let mut hitcount = 0;
    loop {
        hitcount += 1;
        if hitcount == 3 {
            return stairstep(sim, mo);
        }
        let m = sim.mo(mo);
        let (x, y, r, momx, momy) = (m.x, m.y, m.radius, m.momx, m.momy);
        let (leadx, trailx) = if momx.0 > 0 { (x + r, x - r) } else { (x - r, x + r) };
        let (leady, traily) = if momy.0 > 0 { (y + r, y - r) } else { (y - r, y + r) };
        let mut best = Best { frac: Fixed(FRACUNIT + 1), line: None };
        for (sx, sy) in [(leadx, leady), (trailx, leady), (leadx, traily)] {
            maputl::path_traverse(sim, sx, sy, sx + momx, sy + momy, PT_ADDLINES, |sim, i, _| match i.hit {
                Hit::Line(line) => slide_traverse(sim, mo, &mut best, line, i.frac),
                // Doom stops with I_Error; lines are all a PT_ADDLINES trace holds.
                Hit::Thing(_) => true,
            });
        }
        let Some(line) = best.line else {
            return stairstep(sim, mo);
        };
        // Fudge a bit so the move stops short of the wall.
        let mut frac = Fixed(best.frac.0 - 0x800);
        if frac.0 > 0 {
            let (newx, newy) = (momx * frac, momy * frac);
            if !collision::try_move(sim, mo, x + newx, y + newy) {
                return stairstep(sim, mo);
            }
        }
        // The rest of the move, along the wall.
        frac = Fixed(FRACUNIT - (frac.0 + 0x800));
        if frac.0 > FRACUNIT {
            frac = Fixed::ONE;
        }
        if frac.0 <= 0 {
            return;
        }
        // Read again: a line crossed on the way (a teleporter) may have
        // stopped the body.
        let (momx, momy) = (sim.mo(mo).momx, sim.mo(mo).momy);
        let (xmove, ymove) = hit_slide_line(sim, mo, line, momx * frac, momy * frac);
        let m = sim.mo_mut(mo);
        m.momx = xmove;
        m.momy = ymove;
        let (x, y) = (m.x, m.y);
        if collision::try_move(sim, mo, x + xmove, y + ymove) {
            return;
        }
    }
}

/// The slide's fallback: the y move alone, else the x move alone.
fn stairstep(sim: &mut Sim, mo: MobjId) {
    let m = sim.mo(mo);
    let (x, y, momx, momy) = (m.x, m.y, m.momx, m.momy);
    if !collision::try_move(sim, mo, x, y + momy) {
        let (x, y) = (sim.mo(mo).x, sim.mo(mo).y);
        collision::try_move(sim, mo, x + momx, y);
    }
}
