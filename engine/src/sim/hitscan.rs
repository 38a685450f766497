//! Traces along a line of fire (`p_map.c`'s second half): aiming
//! (`P_AimLineAttack`), hitscan shots (`P_LineAttack`), using lines
//! (`P_UseLines`) and blast damage (`P_RadiusAttack`). Each walks
//! `maputl::path_traverse` or the blockmap and hands its effects to the
//! owners: puffs and blood to `movement.rs`, damage to `interaction.rs`,
//! shot and used lines to `specials.rs` and `switches.rs`.

use super::level::{ml, MAPBLOCKSHIFT, MAXRADIUS};
use super::maputl::{self, Hit, Intercept, PT_ADDLINES, PT_ADDTHINGS};
use super::mobj::mf;
use super::{info::mt, interaction, movement, sight, specials, switches, MobjId, Sim};
use crate::fixed::{Angle, Divline, Fixed, FRACUNIT};

/// `USERANGE`: how far a player reaches to use a line.
const USERANGE: Fixed = Fixed(64 * FRACUNIT);
/// The aim's slope limits: the view's half-height over its half-width,
/// `(SCREENHEIGHT/2)*FRACUNIT/(SCREENWIDTH/2)` = 100/160.
const AIM_SLOPE: i32 = 100 * FRACUNIT / 160;

/// What a shot or aim carries along its trace (`shootthing`, `shootz`,
/// `attackrange`, `aimslope`, `la_damage`).
struct Shot {
    shooter: MobjId,
    z: Fixed,
    range: Fixed,
    slope: Fixed,
    damage: i32,
}

impl Shot {
    fn new(sim: &Sim, shooter: MobjId, distance: Fixed, slope: Fixed, damage: i32) -> Shot {
        let mo = sim.mo(shooter);
        let z = mo.z + (mo.height >> 1) + Fixed(8 * FRACUNIT);
        Shot { shooter, z, range: distance, slope, damage }
    }
}

/// The trace's far end: `distance` (whole units) along `angle`, wrapping.
fn trace_end(sim: &Sim, from: MobjId, angle: Angle, distance: Fixed) -> (Fixed, Fixed) {
    let mo = sim.mo(from);
    let units = distance.0 >> 16;
    (mo.x + angle.cos() * units, mo.y + angle.sin() * units)
}

/// `P_AimLineAttack`: the slope to the first shootable thing along
/// `angle` within `distance`, or 0; sets `sim.tm.linetarget`.
pub fn aim_line_attack(sim: &mut Sim, shooter: MobjId, angle: Angle, distance: Fixed) -> Fixed {
    let (x2, y2) = trace_end(sim, shooter, angle, distance);
    sim.tm.attackrange = distance;
    let mut shot = Shot::new(sim, shooter, distance, Fixed::ZERO, 0);
    sim.tm.topslope = Fixed(AIM_SLOPE);
    sim.tm.bottomslope = Fixed(-AIM_SLOPE);
    sim.tm.linetarget = None;
    let (x1, y1) = (sim.mo(shooter).x, sim.mo(shooter).y);
    maputl::path_traverse(sim, x1, y1, x2, y2, PT_ADDLINES | PT_ADDTHINGS, |sim, i, _| aim_traverse(sim, &mut shot, i));
    if sim.tm.linetarget.is_some() {
        shot.slope
    } else {
        Fixed::ZERO
    }
}

/// `PTR_AimTraverse`: two-sided lines narrow the slopes; the first
/// shootable thing inside them is the target, aimed at the middle of its
/// visible part.
fn aim_traverse(sim: &mut Sim, shot: &mut Shot, i: &Intercept) -> bool {
    let th = match i.hit {
        Hit::Line(line) => return aim_through_line(sim, shot, line, i.frac),
        Hit::Thing(th) => th,
    };
    if th == shot.shooter || !sim.mo(th).has(mf::SHOOTABLE) {
        return true;
    }
    let dist = shot.range * i.frac;
    let mo = sim.mo(th);
    let mut top = (mo.z + mo.height - shot.z) / dist;
    if top < sim.tm.bottomslope {
        return true;
    }
    let mut bottom = (mo.z - shot.z) / dist;
    if bottom > sim.tm.topslope {
        return true;
    }
    top = top.min(sim.tm.topslope);
    bottom = bottom.max(sim.tm.bottomslope);
    shot.slope = Fixed((top + bottom).0 / 2);
    sim.tm.linetarget = Some(th);
    false
}

fn aim_through_line(sim: &mut Sim, shot: &Shot, line: usize, frac: Fixed) -> bool {
    let ld = &sim.level.lines[line];
    if ld.flags & ml::TWOSIDED == 0 {
        return false;
    }
    let (front, back) = (ld.frontsector, ld.backsector);
    maputl::line_opening(sim, line);
    let o = sim.tm.opening;
    if o.bottom >= o.top {
        return false;
    }
    let dist = shot.range * frac;
    let sector = |s: Option<usize>| s.and_then(|s| sim.level.sectors.get(s));
    let (f, b) = (sector(front), sector(back));
    if b.is_none() || f.map(|f| f.floorheight) != b.map(|b| b.floorheight) {
        let slope = (o.bottom - shot.z) / dist;
        if slope > sim.tm.bottomslope {
            sim.tm.bottomslope = slope;
        }
    }
    if b.is_none() || f.map(|f| f.ceilingheight) != b.map(|b| b.ceilingheight) {
        let slope = (o.top - shot.z) / dist;
        if slope < sim.tm.topslope {
            sim.tm.topslope = slope;
        }
    }
    sim.tm.topslope > sim.tm.bottomslope
}

/// `P_LineAttack`: a hitscan shot along `angle` and `slope` that hurts the
/// first thing it meets by `damage`, or puffs on a wall. Damage 0 is a test
/// trace (puffs and blood still appear, as in Doom).
pub fn line_attack(sim: &mut Sim, shooter: MobjId, angle: Angle, distance: Fixed, slope: Fixed, damage: i32) {
    let (x2, y2) = trace_end(sim, shooter, angle, distance);
    sim.tm.attackrange = distance;
    let shot = Shot::new(sim, shooter, distance, slope, damage);
    let sky = sim.level.name_id("F_SKY1");
    let (x1, y1) = (sim.mo(shooter).x, sim.mo(shooter).y);
    maputl::path_traverse(sim, x1, y1, x2, y2, PT_ADDLINES | PT_ADDTHINGS, |sim, i, trace| {
        shoot_traverse(sim, &shot, sky, i, trace)
    });
}

/// The point `back` before the intercept along the trace, at the shot's
/// height there.
fn shot_point(shot: &Shot, trace: &Divline, frac: Fixed, back: Fixed) -> (Fixed, Fixed, Fixed) {
    let frac = frac - back / shot.range;
    let x = trace.x + trace.dx * frac;
    let y = trace.y + trace.dy * frac;
    let z = shot.z + shot.slope * (frac * shot.range);
    (x, y, z)
}

/// `PTR_ShootTraverse`.
fn shoot_traverse(
    sim: &mut Sim,
    shot: &Shot,
    sky: Option<super::level::NameId>,
    i: &Intercept,
    trace: &Divline,
) -> bool {
    let th = match i.hit {
        Hit::Line(line) => return shoot_through_line(sim, shot, sky, line, i.frac, trace),
        Hit::Thing(th) => th,
    };
    if th == shot.shooter || !sim.mo(th).has(mf::SHOOTABLE) {
        return true;
    }
    let dist = shot.range * i.frac;
    let mo = sim.mo(th);
    if (mo.z + mo.height - shot.z) / dist < shot.slope {
        return true;
    }
    if (mo.z - shot.z) / dist > shot.slope {
        return true;
    }
    let (x, y, z) = shot_point(shot, trace, i.frac, Fixed(10 * FRACUNIT));
    if sim.mo(th).has(mf::NOBLOOD) {
        movement::spawn_puff(sim, x, y, z);
    } else {
        movement::spawn_blood(sim, x, y, z, shot.damage);
    }
    if shot.damage != 0 {
        interaction::damage_mobj(sim, th, Some(shot.shooter), Some(shot.shooter), shot.damage);
    }
    false
}

/// A shot meeting a line: a special one is triggered (guns open doors);
/// through a two-sided line's opening it goes on; otherwise a puff just
/// short of the wall, except against the sky.
fn shoot_through_line(
    sim: &mut Sim,
    shot: &Shot,
    sky: Option<super::level::NameId>,
    line: usize,
    frac: Fixed,
    trace: &Divline,
) -> bool {
    if sim.level.lines[line].special != 0 {
        specials::shoot_special_line(sim, shot.shooter, line);
    }
    let ld = &sim.level.lines[line];
    let (front, back) = (ld.frontsector, ld.backsector);
    if ld.flags & ml::TWOSIDED != 0 {
        maputl::line_opening(sim, line);
        let o = sim.tm.opening;
        let dist = shot.range * frac;
        let sector = |s: Option<usize>| s.and_then(|s| sim.level.sectors.get(s));
        let (f, b) = (sector(front), sector(back));
        // With no back sector Chocolate tests both edges (e6y's emulation
        // of a missing back side); otherwise only where the heights differ.
        let floors_differ = b.is_none() || f.map(|f| f.floorheight) != b.map(|b| b.floorheight);
        let ceilings_differ = b.is_none() || f.map(|f| f.ceilingheight) != b.map(|b| b.ceilingheight);
        let blocked = (floors_differ && (o.bottom - shot.z) / dist > shot.slope)
            || (ceilings_differ && (o.top - shot.z) / dist < shot.slope);
        if !blocked {
            return true;
        }
    }
    let (x, y, z) = shot_point(shot, trace, frac, Fixed(4 * FRACUNIT));
    let sector = |s: Option<usize>| s.and_then(|s| sim.level.sectors.get(s));
    if let (Some(f), Some(sky)) = (sector(front), sky) {
        if f.ceilingpic == sky {
            if z > f.ceilingheight {
                return false;
            }
            if sector(back).is_some_and(|b| b.ceilingpic == sky) {
                return false;
            }
        }
    }
    movement::spawn_puff(sim, x, y, z);
    false
}

/// `P_UseLines`: player `player` presses use: the first special line
/// within reach in front is used (`PTR_UseTraverse`); a wall before it
/// says "oof".
pub fn use_lines(sim: &mut Sim, player: usize) {
    let Some(mo) = sim.player(player).map(|p| p.mo) else {
        return;
    };
    let angle = sim.mo(mo).angle;
    let (x1, y1) = (sim.mo(mo).x, sim.mo(mo).y);
    let (x2, y2) = trace_end(sim, mo, angle, USERANGE);
    maputl::path_traverse(sim, x1, y1, x2, y2, PT_ADDLINES, |sim, i, _| {
        let Hit::Line(line) = i.hit else {
            return true;
        };
        if sim.level.lines[line].special == 0 {
            maputl::line_opening(sim, line);
            if sim.tm.opening.range.0 <= 0 {
                sim.sound_named(Some(mo), "noway");
                return false;
            }
            return true;
        }
        let m = sim.mo(mo);
        let side = maputl::point_on_map_line_side(m.x, m.y, &sim.level.lines[line]);
        switches::use_special_line(sim, mo, line, side);
        false
    });
}

/// `P_RadiusAttack`: `damage` at `spot`, falling off by a unit a unit of
/// distance (the larger of |dx| and |dy|, less the victim's radius), to
/// every shootable thing in sight of the spot but the two spider bosses.
pub fn radius_attack(sim: &mut Sim, spot: MobjId, source: Option<MobjId>, damage: i32) {
    // `(damage + MAXRADIUS) << FRACBITS` in Doom: MAXRADIUS is already in
    // fixed point, so the sum's shift drops it and the reach is `damage`
    // units. Kept as Doom computes it.
    let dist = Fixed(damage.wrapping_add(MAXRADIUS.0) << 16);
    let (sx, sy) = (sim.mo(spot).x, sim.mo(spot).y);
    let (orgx, orgy) = (sim.level.blockmap.orgx, sim.level.blockmap.orgy);
    let yh = (sy + dist - orgy).0 >> MAPBLOCKSHIFT;
    let yl = (sy - dist - orgy).0 >> MAPBLOCKSHIFT;
    let xh = (sx + dist - orgx).0 >> MAPBLOCKSHIFT;
    let xl = (sx - dist - orgx).0 >> MAPBLOCKSHIFT;
    for y in yl..=yh {
        for x in xl..=xh {
            maputl::block_things(sim, x, y, |sim, thing| blast(sim, thing, spot, source, damage));
        }
    }
}

/// `PIT_RadiusAttack`.
fn blast(sim: &mut Sim, thing: MobjId, spot: MobjId, source: Option<MobjId>, damage: i32) -> bool {
    if !sim.mo(thing).has(mf::SHOOTABLE) {
        return true;
    }
    if sim.is(thing, mt::CYBORG) || sim.is(thing, mt::SPIDER) {
        return true;
    }
    let (t, s) = (sim.mo(thing), sim.mo(spot));
    let dx = (t.x - s.x).abs();
    let dy = (t.y - s.y).abs();
    let dist = if dx > dy { dx } else { dy };
    let dist = ((dist - t.radius).0 >> 16).max(0);
    if dist >= damage {
        return true;
    }
    if sight::check_sight(sim, thing, spot) {
        interaction::damage_mobj(sim, thing, Some(spot), source, damage - dist);
    }
    true
}
