//! Line specials set off: who may, from which side, with which key, once or
//! every time (Doom's P_CrossSpecialLine, P_UseSpecialLine and
//! P_ShootSpecialLine), and the dispatch from an [`Action`] to the module
//! that carries it out. Also the neighbour searches every mover uses to find
//! its destination (Doom's P_FindLowestFloorSurrounding and kin).

use super::{ceilings, doors, floors, has_key, lights, plats, say, switches, teleport, Ctx, Exit, SpecialLine, World};
use crate::level::Level;
use crate::map::special::{Action, Activation};
use crate::map::LineSpecial;
use crate::play::events::{sound, Origin};

/// Who set a special off.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Activator {
    Player,
    /// An actor (by index): a monster walking or pushing a door.
    Monster(u32),
}

/// Sets off the special of `line` by `on`, if it goes off that way for
/// `who`. `from_front`: the activator was on the line's front side (a use
/// always is; a walk may come from either). Returns whether it did
/// something (for a switch: whether its texture changes).
pub fn activate(
    world: &mut World,
    ctx: &mut Ctx,
    line: SpecialLine,
    on: Activation,
    who: Activator,
    from_front: bool,
) -> bool {
    let Some(special) = world.special(ctx.level, line) else { return false };
    let allowed = match who {
        Activator::Player => special.by.players(),
        Activator::Monster(_) => special.by.monsters(),
    };
    if special.on != on || !allowed {
        return false;
    }
    let manual = special.tag == 0 && special.action.moves_sectors();
    if let Action::Door { key: Some(colour), .. } = special.action {
        if who != Activator::Player {
            return false;
        }
        if !has_key(ctx.bodies.player, colour) {
            let what = if manual { "open this door" } else { "activate this object" };
            say(ctx, format!("You need a {} key to {what}", colour.name()));
            ctx.events.push(sound("oof", Origin::Player));
            return false;
        }
    }
    let started = perform(world, ctx, line, &special, from_front, who);
    ctx.events.push(crate::play::events::Event::Special { line, started });
    if started && !special.repeat {
        world.spend(ctx.level, line);
    }
    // Switches and shot lines change their texture when they work; manual
    // doors and walk lines have no switch.
    if started && on != Activation::Walk && !manual {
        if let SpecialLine::Wall(wall) = line {
            let exit = matches!(special.action, Action::Exit | Action::SecretExit);
            switches::flip(world, ctx, wall, special.repeat, exit);
        }
    }
    started
}

/// Does `action` to the sectors tagged `tag`, as if a line had (a boss's
/// death: Doom's A_BossDeath, A_KeenDie). Returns whether anything started.
pub fn perform_tagged(world: &mut World, ctx: &mut Ctx, action: Action, tag: u16) -> bool {
    let special = LineSpecial { on: Activation::Walk, repeat: true, by: Default::default(), tag, action };
    perform(world, ctx, SpecialLine::Trigger(usize::MAX), &special, true, Activator::Player)
}

/// Carries out `special`'s action. Returns whether anything started.
fn perform(
    world: &mut World,
    ctx: &mut Ctx,
    line: SpecialLine,
    special: &LineSpecial,
    from_front: bool,
    who: Activator,
) -> bool {
    let sectors = target_sectors(ctx.level, line, special);
    let front = match line {
        SpecialLine::Wall(i) => Some(ctx.level.compiled.map.lines[i].front.sector),
        SpecialLine::Trigger(_) => None,
    };
    match &special.action {
        Action::Door { kind, speed, wait, shut, .. } => {
            let manual = special.tag == 0;
            // Monsters never close a door (Doom's EV_VerticalDoor).
            let closes = who == Activator::Player;
            doors::start(world, ctx, &sectors, *kind, *speed, (*wait, *shut), manual, closes)
        }
        Action::Lift { speed, wait } => plats::start_lift(world, ctx, &sectors, *speed, *wait, special.tag),
        Action::PerpetualLift { speed, wait } => {
            plats::start_perpetual(world, ctx, &sectors, *speed, *wait, special.tag)
        }
        Action::StopLift => plats::stop(world, special.tag),
        Action::Floor { to, offset, speed, crush, change } => {
            let floor = floors::Floor { to: *to, offset: *offset, speed: *speed, crush: *crush, change: *change };
            floors::start(world, ctx, &sectors, &floor, front)
        }
        Action::Ceiling { to, offset, speed, crush } => {
            ceilings::start(world, ctx, &sectors, *to, *offset, *speed, *crush)
        }
        Action::Crusher { speed, silent } => {
            ceilings::start_crusher(world, ctx, &sectors, *speed, *silent, special.tag)
        }
        Action::StopCrusher => ceilings::stop(world, special.tag),
        Action::Stairs { step, speed, crush } => floors::stairs(world, ctx, special.tag, *step, *speed, *crush),
        Action::Donut { speed } => floors::donut(world, ctx, &sectors, *speed),
        Action::Light(change) => lights::change(world, ctx, &sectors, *change),
        Action::Teleport => from_front && teleport::teleport(ctx, special.tag, who),
        Action::LineTeleport { to } => match line {
            SpecialLine::Wall(from) if from_front && who == Activator::Player => {
                teleport::line_teleport(ctx, from, *to)
            }
            _ => false,
        },
        Action::Exit | Action::SecretExit => {
            let secret = special.action == Action::SecretExit;
            *ctx.exit = Some(if secret { Exit::Secret } else { Exit::Normal });
            true
        }
    }
}

/// The sectors a special acts on: those with its tag, or with none, the
/// sector behind its line.
pub fn target_sectors(level: &Level, line: SpecialLine, special: &LineSpecial) -> Vec<usize> {
    let map = &level.compiled.map;
    if special.tag != 0 {
        return map.sectors_tagged(special.tag).collect();
    }
    match line {
        SpecialLine::Wall(i) => map.lines[i].back.as_ref().map(|b| b.sector).into_iter().collect(),
        SpecialLine::Trigger(_) => Vec::new(),
    }
}

/// The sectors across the two-sided lines of `sector`, once per line, in the
/// order of its lines (Doom's `getNextSector` over `sector->lines`); a line
/// with `sector` on both sides leads nowhere (Boom's rule).
pub fn neighbours(level: &Level, sector: usize) -> impl Iterator<Item = usize> + '_ {
    let map = &level.compiled.map;
    level.sector_lines[sector].iter().filter_map(move |&i| {
        let line = &map.lines[i as usize];
        let back = line.back.as_ref()?.sector;
        match (line.front.sector == sector, back == sector) {
            (true, false) => Some(back),
            (false, true) => Some(line.front.sector),
            _ => None,
        }
    })
}

/// The lowest floor around `sector`, its own included (never above it).
pub fn lowest_floor_around(level: &Level, sector: usize) -> f64 {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].floor).fold(sectors[sector].floor, f64::min)
}

/// The highest neighbouring floor, its own not included; `None` with no neighbours.
pub fn highest_floor_around(level: &Level, sector: usize) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].floor).reduce(f64::max)
}

/// The lowest neighbouring floor above `height`, if any.
pub fn next_higher_floor(level: &Level, sector: usize, height: f64) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].floor).filter(|&f| f > height).reduce(f64::min)
}

/// The highest neighbouring floor below `height`, if any (Boom's P_FindNextLowestFloor).
pub fn next_lower_floor(level: &Level, sector: usize, height: f64) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].floor).filter(|&f| f < height).reduce(f64::max)
}

/// The lowest neighbouring ceiling, its own not included; `None` with no neighbours.
pub fn lowest_ceiling_around(level: &Level, sector: usize) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].ceiling).reduce(f64::min)
}

/// The highest neighbouring ceiling; `None` with no neighbours.
pub fn highest_ceiling_around(level: &Level, sector: usize) -> Option<f64> {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].ceiling).reduce(f64::max)
}

/// The darkest light around `sector`, at most `max` (Doom's P_FindMinSurroundingLight).
pub fn min_light_around(level: &Level, sector: usize, max: u8) -> u8 {
    let sectors = &level.compiled.map.sectors;
    neighbours(level, sector).map(|s| sectors[s].light).fold(max, u8::min)
}

/// The height of the shortest lower texture on either side of the
/// two-sided lines of `sector` (Doom's raise-to-texture; sides without a
/// lower texture do not count, as in Boom). `None` when there is none.
pub fn shortest_lower_texture(level: &Level, sector: usize) -> Option<f64> {
    let map = &level.compiled.map;
    let mut shortest: Option<usize> = None;
    for &i in &level.sector_lines[sector] {
        let i = i as usize;
        if map.lines[i].back.is_none() {
            continue;
        }
        for side in &level.materials.sides[i] {
            if let Some(id) = side.lower {
                let h = level.materials.textures.get(id).height;
                shortest = Some(shortest.map_or(h, |s| s.min(h)));
            }
        }
    }
    shortest.map(|h| h as f64)
}
