//! Teleporters (Doom's p_telept.c): a body crossing a teleport line from
//! its front appears at the teleport destination in a sector with the
//! line's tag, facing the destination's angle, standing still on the floor,
//! and (the player) held for 18 ticks.

use glam::DVec2;

use super::specials::Activator;
use super::Ctx;
use crate::actors::ActorFlag;
use crate::geom::sin_cos_degrees;
use crate::map::semantics::teleport_destination;
use crate::play::actors::movement::Ground;
use crate::play::events::{sound, Origin};
use crate::play::player::RADIUS;

/// Ticks the player cannot move after teleporting (Doom's reactiontime 18).
pub const TELEPORT_FREEZE: u32 = 18;

/// Teleports `who` through a line tagged `tag`. Returns whether it did.
/// The player kills any shootable actor standing where it arrives (a
/// telefrag); a monster goes only where no shootable body stands (Doom's
/// P_TeleportMove, outside MAP30).
pub fn teleport(ctx: &mut Ctx, tag: u16, who: Activator) -> bool {
    let map = &ctx.level.compiled.map;
    let sectors = &ctx.level.thing_sectors;
    let shown = &ctx.level.thing_shown;
    let Some(dest) = teleport_destination(map, tag, |i| shown[i].then_some(sectors[i])) else { return false };
    let thing = &map.things[dest];
    // Doom spawns things facing a multiple of 45 degrees (the angle divided
    // by 45, truncated).
    let angle = (thing.angle / 45.0).trunc() * 45.0;
    let to = thing.pos;
    let from = match who {
        Activator::Player => {
            let from = ctx.bodies.player.pos;
            let world = crate::play::collision::World { compiled: &ctx.level.compiled, blockmap: ctx.bodies.blockmap };
            let near = world.lines_near(ctx.bodies.query, to, RADIUS + 1.0);
            let area = world.area(near, to);
            ctx.bodies.player.teleport_to(to, angle, area, TELEPORT_FREEZE);
            for n in ctx.bodies.actors.overlapping(to, RADIUS, ActorFlag::Shootable, None) {
                ctx.bodies.harmed.push((n, TELEFRAG));
            }
            from
        }
        Activator::Monster(n) => {
            let actors = &*ctx.bodies.actors;
            let (a, def) = (&actors.list[n as usize], &actors.table.actors[actors.list[n as usize].kind]);
            let (from, radius) = (a.pos, def.radius);
            let player = &ctx.bodies.player;
            let on_player = !player.dead()
                && (player.pos.x - to.x).abs() < RADIUS + radius
                && (player.pos.y - to.y).abs() < RADIUS + radius;
            if on_player || !ctx.bodies.actors.overlapping(to, radius, ActorFlag::Shootable, Some(n)).is_empty() {
                return false;
            }
            let ground = Ground { compiled: &ctx.level.compiled, blockmap: ctx.bodies.blockmap };
            let Ok(o) = ground.opening(ctx.bodies.query, to, radius, true) else { return false };
            ctx.bodies.actors.teleport(n as usize, to, angle, o);
            from
        }
    };
    // The fog (and its sound) appears where the body left and 20 units in
    // front of where it arrives.
    let (sin, cos) = sin_cos_degrees(angle);
    ctx.events.push(sound("telept", Origin::At(from)));
    ctx.events.push(sound("telept", Origin::At(to + DVec2::new(cos, sin) * 20.0)));
    true
}

/// Damage that kills whatever it meets (Doom's telefrag: 10000).
pub const TELEFRAG: i32 = 10_000;

/// Boom's silent line teleport (244): the body goes to the same place along
/// line `to` (measured from its far end, so a line facing the other way
/// mirrors it), just in front of it, turned by the angle between the lines
/// plus a half turn, with its speed turned alike and its height above the
/// floor kept. Returns whether it did.
pub fn line_teleport(ctx: &mut Ctx, from: usize, to: usize) -> bool {
    let map = &ctx.level.compiled.map;
    let (a, b) = map.line_points(&map.lines[from]);
    let (c, d) = map.line_points(&map.lines[to]);
    let player = &mut *ctx.bodies.player;
    let (src, dst) = (b - a, d - c);
    // Where along the source line the body crossed, 0 at its start.
    let along = if src.x.abs() > src.y.abs() { (player.pos.x - a.x) / src.x } else { (player.pos.y - a.y) / src.y };
    let turn = dst.y.atan2(dst.x) - src.y.atan2(src.x) + std::f64::consts::PI;
    // Just in front of the exit line: its right-hand side.
    let normal = DVec2::new(dst.y, -dst.x) / dst.length();
    let to_pos = d - dst * along + normal * (1.0 / 64.0);
    let above = player.z - player.floor;
    let world = crate::play::collision::World { compiled: &ctx.level.compiled, blockmap: ctx.bodies.blockmap };
    let near = world.lines_near(ctx.bodies.query, to_pos, RADIUS + 1.0);
    let area = world.area(near, to_pos);
    let (sin, cos) = turn.sin_cos();
    let v = player.velocity;
    let velocity = DVec2::new(v.x * cos - v.y * sin, v.y * cos + v.x * sin);
    let angle = player.angle + turn.to_degrees();
    player.teleport_to(to_pos, angle, area, 0);
    player.velocity = velocity;
    player.z = area.floor + above;
    true
}
