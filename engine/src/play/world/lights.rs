//! Lights (Doom's p_lights.c): the sector light effects that run all level
//! long (blinking, strobing, glowing, fire flicker), and the light changes
//! line specials make. Each effect swings the sector's light between its
//! level at load and the darkest neighbour's (Doom's
//! P_FindMinSurroundingLight); the renderer reads the level each frame.

use super::{specials, Ctx, World};
use crate::map::special::{LightChange, LightEffect};

/// Ticks a strobe stays bright (Doom's STROBEBRIGHT).
pub const STROBE_BRIGHT: u32 = 5;
/// Ticks a fast and a slow strobe stay dark (Doom's FASTDARK and SLOWDARK).
pub const FAST_DARK: u32 = 15;
pub const SLOW_DARK: u32 = 35;
/// Light levels a glow moves per tick (Doom's GLOWSPEED).
pub const GLOW_SPEED: i32 = 8;

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Effect {
    /// Doom's LIGHTFLASH: dark for 1 to 8 ticks, bright for 1 or 65.
    Blink,
    Strobe {
        dark: u32,
    },
    Glow {
        rising: bool,
    },
    Flicker,
}

#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Light {
    pub sector: usize,
    pub effect: Effect,
    pub min: u8,
    pub max: u8,
    /// Ticks until the next change.
    pub count: u32,
}

impl Light {
    /// The effect `kind` on `sector`, starting from its level now. Random
    /// starts (unsynchronised strobes, blinks) draw from the game's generator.
    pub fn new(
        ctx_level: &crate::level::Level,
        rng: &mut crate::play::random::GameRng,
        sector: usize,
        kind: LightEffect,
    ) -> Light {
        let max = ctx_level.compiled.map.sectors[sector].light;
        let min = specials::min_light_around(ctx_level, sector, max);
        let strobe = |dark: u32, sync: bool, rng: &mut crate::play::random::GameRng| {
            // A strobe with no darker neighbour goes black instead.
            let min = if min == max { 0 } else { min };
            let count = if sync { 1 } else { u32::from(rng.byte() & 7) + 1 };
            Light { sector, effect: Effect::Strobe { dark }, min, max, count }
        };
        match kind {
            LightEffect::BlinkRandom => {
                let count = u32::from(rng.byte() & 64) + 1;
                Light { sector, effect: Effect::Blink, min, max, count }
            }
            LightEffect::StrobeFast => strobe(FAST_DARK, false, rng),
            LightEffect::StrobeSlow => strobe(SLOW_DARK, false, rng),
            LightEffect::StrobeFastSync => strobe(FAST_DARK, true, rng),
            LightEffect::StrobeSlowSync => strobe(SLOW_DARK, true, rng),
            LightEffect::Glow => Light { sector, effect: Effect::Glow { rising: false }, min, max, count: 1 },
            // Doom flickers between its level and 16 above the darkest
            // neighbour (so with none darker, between its level and 16 above).
            LightEffect::Flicker => {
                let min = min.saturating_add(16);
                Light { sector, effect: Effect::Flicker, min, max, count: 4 }
            }
        }
    }

    pub(super) fn think(&mut self, ctx: &mut Ctx) -> bool {
        let light = &mut ctx.level.compiled.map.sectors[self.sector].light;
        if let Effect::Glow { rising } = self.effect {
            let (level, min, max) = (i32::from(*light), i32::from(self.min), i32::from(self.max));
            let next = if rising { level + GLOW_SPEED } else { level - GLOW_SPEED };
            // A step that reaches the end is undone and the glow turns (Doom's T_Glow).
            let (next, rising) = match rising {
                false if next <= min => (next + GLOW_SPEED, true),
                true if next >= max => (next - GLOW_SPEED, false),
                _ => (next, rising),
            };
            *light = next.clamp(0, 255) as u8;
            self.effect = Effect::Glow { rising };
            return true;
        }
        self.count -= 1;
        if self.count > 0 {
            return true;
        }
        match self.effect {
            Effect::Blink => {
                let bright = *light == self.max;
                *light = if bright { self.min } else { self.max };
                let mask = if bright { 7 } else { 64 };
                self.count = u32::from(ctx.rng.byte() & mask) + 1;
            }
            Effect::Strobe { dark } => {
                if *light == self.min {
                    *light = self.max;
                    self.count = STROBE_BRIGHT;
                } else {
                    *light = self.min;
                    self.count = dark;
                }
            }
            Effect::Flicker => {
                let amount = (ctx.rng.byte() & 3) * 16;
                let dimmed = i32::from(*light) - i32::from(amount);
                *light = if dimmed < i32::from(self.min) { self.min } else { self.max.saturating_sub(amount) };
                self.count = 4;
            }
            Effect::Glow { .. } => {}
        }
        true
    }
}

/// A light special on `sectors` (Doom's EV_LightTurnOn, EV_TurnTagLightsOff,
/// EV_StartLightStrobing). The brightest and darkest neighbour are found per
/// sector (Boom's fix of vanilla's reuse of the first sector's level).
pub fn change(world: &mut World, ctx: &mut Ctx, sectors: &[usize], change: LightChange) -> bool {
    for &s in sectors {
        let level = &*ctx.level;
        let new = match change {
            LightChange::Set(v) => v,
            LightChange::BrightestNeighbour => {
                specials::neighbours(level, s).map(|n| level.compiled.map.sectors[n].light).max().unwrap_or(0)
            }
            LightChange::DimmestNeighbour => specials::min_light_around(level, s, level.compiled.map.sectors[s].light),
            LightChange::Strobe => {
                if !world.is_busy(s) {
                    let light = Light::new(ctx.level, ctx.rng, s, LightEffect::StrobeSlow);
                    world.start_light(s, light);
                }
                continue;
            }
        };
        ctx.level.compiled.map.sectors[s].light = new;
    }
    true
}
