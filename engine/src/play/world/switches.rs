//! Switches (Doom's p_switch.c): a switch line that works swaps its front
//! side's switch texture for its partner; a repeatable one (a button) swaps
//! back after a second. The pairs are data (`engine/data/animations.ron`),
//! resolved by [`crate::materials`].

use super::{Ctx, Thinker, World};
use crate::play::events::{sound, Origin};
use crate::texture::TextureId;

/// Ticks before a button flips back (Doom's BUTTONTIME, 1 s).
pub const BUTTON_TIME: u32 = 35;

/// Which texture of a side.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Part {
    Upper,
    Middle,
    Lower,
}

/// A pressed button waiting to flip back.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Button {
    pub line: usize,
    pub part: Part,
    /// The texture it goes back to.
    pub original: TextureId,
    pub count: u32,
}

impl Button {
    pub(super) fn think(&mut self, ctx: &mut Ctx) -> bool {
        self.count -= 1;
        if self.count > 0 {
            return true;
        }
        set(ctx, self.line, self.part, self.original);
        let front = ctx.level.compiled.map.lines[self.line].front.sector;
        ctx.events.push(sound("swtchn", Origin::Sector(front)));
        false
    }
}

fn set(ctx: &mut Ctx, line: usize, part: Part, id: TextureId) {
    let side = &mut ctx.level.materials.sides[line][0];
    match part {
        Part::Upper => side.upper = Some(id),
        Part::Middle => side.middle = Some(id),
        Part::Lower => side.lower = Some(id),
    }
}

/// Flips the switch texture on `line`'s front side: of its upper, middle and
/// lower textures, the one that comes first in the switch list. A `repeat`
/// switch flips back after [`BUTTON_TIME`]; a button already waiting to flip
/// back is left as it is. Exit switches make their own sound.
pub fn flip(world: &mut World, ctx: &mut Ctx, line: usize, repeat: bool, exit: bool) {
    if world.thinkers.iter().any(|t| matches!(t, Thinker::Button(b) if b.line == line)) {
        return;
    }
    let side = ctx.level.materials.sides[line][0];
    let switches = &ctx.level.materials.switches;
    let found = [(Part::Upper, side.upper), (Part::Middle, side.middle), (Part::Lower, side.lower)]
        .into_iter()
        .filter_map(|(part, id)| {
            let id = id?;
            let &(partner, order) = switches.get(&id)?;
            Some((order, part, id, partner))
        })
        .min_by_key(|&(order, ..)| order);
    let Some((_, part, id, partner)) = found else { return };
    set(ctx, line, part, partner);
    let front = ctx.level.compiled.map.lines[line].front.sector;
    ctx.events.push(sound(if exit { "swtchx" } else { "swtchn" }, Origin::Sector(front)));
    if repeat {
        world.thinkers.push(Thinker::Button(Button { line, part, original: id, count: BUTTON_TIME }));
    }
}
