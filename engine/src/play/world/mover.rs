//! The one plane mover (Doom's T_MovePlane): every door, lift, floor,
//! ceiling, crusher, stair step and donut moves a sector's floor or ceiling
//! through [`move_plane`], which also settles the bodies over the sector
//! (Doom's P_ChangeSector): a body on the floor rides it, a body under a
//! lowering ceiling is pushed down, and a body that no longer fits either
//! stops the plane or, when the plane crushes, is hurt while it keeps going.

use super::Ctx;
use crate::play::actors::movement::Ground;
use crate::play::player::{HEIGHT, RADIUS};

/// Which plane of a sector moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Plane {
    Floor,
    Ceiling,
}

/// What one tick of movement came to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Moved {
    /// Moved by its speed, not there yet.
    Ok,
    /// A body is in the way: the plane stayed put (or, crushing, moved
    /// into it anyway).
    Crushed,
    /// Reached its destination this tick.
    Arrived,
}

/// Damage a crushing plane does to a body that does not fit, every fourth
/// tick (Doom's PIT_ChangeSector: 10 when `leveltime & 3` is 0).
pub const CRUSH_DAMAGE: i32 = 10;

/// Moves `plane` of `sector` one tick towards `dest` at `speed` (units per
/// tick), `up` or down, by Doom's T_MovePlane rules. A step that would pass
/// `dest` stops on it, and one already at or past it has arrived (Doom
/// would snap it back to `dest`). When a body no longer fits over the
/// sector: a floor going up or a ceiling going down that `crush`es keeps
/// moving into it (the crush hurts it); any other plane goes back where it
/// was, except a rising ceiling, which Doom never checks. A step cut short
/// to `dest` that does not fit is undone and the plane has arrived all the
/// same (Doom's `pastdest`), so a crusher with a body under it still turns
/// at the bottom.
pub fn move_plane(ctx: &mut Ctx, sector: usize, plane: Plane, speed: f64, dest: f64, crush: bool, up: bool) -> Moved {
    let before = height(ctx, sector, plane);
    if (up && dest <= before) || (!up && dest >= before) {
        return Moved::Arrived;
    }
    let stepped = if up { before + speed } else { before - speed };
    let past = if up { stepped > dest } else { stepped < dest };
    let next = if past { dest } else { stepped };
    let arrived = next == dest;
    let squeezes = (plane == Plane::Floor) == up;
    set_height(ctx, sector, plane, next);
    let fits = settle_bodies(ctx, sector, crush);
    if fits {
        return if arrived { Moved::Arrived } else { Moved::Ok };
    }
    let keeps = !past && ((crush && squeezes) || (plane == Plane::Ceiling && up));
    if !keeps {
        set_height(ctx, sector, plane, before);
        settle_bodies(ctx, sector, false);
    }
    match (past, keeps) {
        (true, _) => Moved::Arrived,
        (false, true) if arrived => Moved::Arrived,
        // A rising ceiling carries on as if nothing were there.
        (false, true) if !squeezes => Moved::Ok,
        _ => Moved::Crushed,
    }
}

fn height(ctx: &Ctx, sector: usize, plane: Plane) -> f64 {
    let s = &ctx.level.compiled.map.sectors[sector];
    match plane {
        Plane::Floor => s.floor,
        Plane::Ceiling => s.ceiling,
    }
}

fn set_height(ctx: &mut Ctx, sector: usize, plane: Plane, h: f64) {
    let s = &mut ctx.level.compiled.map.sectors[sector];
    match plane {
        Plane::Floor => s.floor = h,
        Plane::Ceiling => s.ceiling = h,
    }
    ctx.bodies.actors.plane_moved(ctx.level, sector);
}

/// Doom's P_ChangeSector for the bodies over `sector`: each is re-clipped
/// to the floor and ceiling under it (on the floor: it rides the floor;
/// else a low ceiling pushes it down), and one that no longer fits is hurt
/// when `crush`. A dead body has no height (Doom's PIT_ChangeSector turns a
/// corpse into gibs of height 0), so it always fits, and so does an actor
/// that cannot be shot (a lamp, an item). Returns whether every body fits.
fn settle_bodies(ctx: &mut Ctx, sector: usize, crush: bool) -> bool {
    let player_fits = !ctx.bodies.touched.contains(&sector) || settle_player(ctx, crush);
    settle_actors(ctx, sector, crush) && player_fits
}

fn settle_player(ctx: &mut Ctx, crush: bool) -> bool {
    let player = &mut *ctx.bodies.player;
    let height = if player.dead() { 0.0 } else { HEIGHT };
    let on_floor = player.z <= player.floor;
    let world = crate::play::collision::World { compiled: &ctx.level.compiled, blockmap: ctx.bodies.blockmap };
    let near = world.lines_near(ctx.bodies.query, player.pos, RADIUS + 1.0);
    let area = world.area(near, player.pos);
    (player.floor, player.ceiling) = (area.floor, area.ceiling);
    if on_floor {
        player.z = area.floor;
    } else if player.z + height > area.ceiling {
        player.z = (area.ceiling - height).max(area.floor);
    }
    let fits = area.ceiling - area.floor >= height;
    if !fits && crush && ctx.time % 4 == 0 {
        player.hurt(CRUSH_DAMAGE);
    }
    fits
}

/// The actors listed in the grid over the box of `sector`'s lines, each
/// re-clipped to the opening under it (an actor whose box does not reach
/// the sector finds its opening unchanged).
fn settle_actors(ctx: &mut Ctx, sector: usize, crush: bool) -> bool {
    let bounds = ctx.level.sector_boxes[sector];
    if bounds.min.x > bounds.max.x {
        return true;
    }
    let ground = Ground { compiled: &ctx.level.compiled, blockmap: ctx.bodies.blockmap };
    let near = ctx.bodies.actors.near(bounds.min, bounds.max);
    let mut fits = true;
    for &n in &near {
        if !ctx.bodies.actors.settle(n as usize, &ground, ctx.bodies.query) {
            fits = false;
            if crush && ctx.time % 4 == 0 {
                ctx.bodies.harmed.push((n, CRUSH_DAMAGE));
            }
        }
    }
    ctx.bodies.actors.give_back(near);
    fits
}
