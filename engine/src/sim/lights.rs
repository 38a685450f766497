//! Lights (`p_lights.c`): the sector light thinkers (fire flicker, broken
//! flashing, strobes, glow) that `P_SpawnSpecials` starts from sector
//! specials, and the light-level line specials. Flicker and flash spend
//! `P_Random` at spawn and whenever their count runs out, so a level's
//! random index depends on them from the first tic.

use super::specials::{find_min_surrounding_light, find_sector_from_line_tag, next_sector};
use super::think::ThinkerKind;
use super::{Sim, ThinkerId};

/// Light levels a glow steps by each tic (`GLOWSPEED`).
pub const GLOWSPEED: i16 = 8;
/// Tics a strobe stays bright (`STROBEBRIGHT`).
pub const STROBEBRIGHT: i32 = 5;
/// Dark tics of a fast and a slow strobe (`FASTDARK`, `SLOWDARK`).
pub const FASTDARK: i32 = 15;
pub const SLOWDARK: i32 = 35;

/// Which of Doom's four light thinkers (`fireflicker_t`, `lightflash_t`,
/// `strobe_t`, `glow_t`), with the fields each keeps.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum LightKind {
    FireFlicker,
    /// Broken light: `maxtime` and `mintime` mask the random waits.
    Flash {
        maxtime: i32,
        mintime: i32,
    },
    Strobe {
        darktime: i32,
        brighttime: i32,
    },
    /// `direction` -1 down, 1 up.
    Glow {
        direction: i32,
    },
}

/// The thinker's data: the sector it lights and its two levels.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Light {
    pub sector: usize,
    pub kind: LightKind,
    pub count: i32,
    pub maxlight: i16,
    pub minlight: i16,
}

/// Runs the thinker one tic (`T_FireFlicker`, `T_LightFlash`,
/// `T_StrobeFlash`, `T_Glow`).
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let ThinkerKind::Light(mut light) = sim.thinker(id).kind.clone() else { return };
    let Some(sector) = sim.level.sectors.get(light.sector) else { return };
    let level = sector.lightlevel;
    let new_level = match light.kind {
        LightKind::FireFlicker => fire_flicker(sim, &mut light, level),
        LightKind::Flash { maxtime, mintime } => light_flash(sim, &mut light, level, maxtime, mintime),
        LightKind::Strobe { darktime, brighttime } => strobe_flash(&mut light, level, darktime, brighttime),
        LightKind::Glow { direction } => glow(&mut light, level, direction),
    };
    if let Some(l) = new_level {
        sim.level.sectors[light.sector].lightlevel = l;
    }
    if let ThinkerKind::Light(slot) = &mut sim.thinker_mut(id).kind {
        *slot = light;
    }
}

/// `T_FireFlicker`: every fourth tic, a random drop of 0-48 below the
/// brightest, never under the darkest.
fn fire_flicker(sim: &mut Sim, light: &mut Light, level: i16) -> Option<i16> {
    light.count -= 1;
    if light.count != 0 {
        return None;
    }
    let amount = ((sim.p_random() & 3) * 16) as i16;
    light.count = 4;
    Some(if level - amount < light.minlight { light.minlight } else { light.maxlight - amount })
}

/// `T_LightFlash`: bright for a random 1-65 tics, dark for 1-8.
fn light_flash(sim: &mut Sim, light: &mut Light, level: i16, maxtime: i32, mintime: i32) -> Option<i16> {
    light.count -= 1;
    if light.count != 0 {
        return None;
    }
    if level == light.maxlight {
        light.count = (sim.p_random() & mintime) + 1;
        Some(light.minlight)
    } else {
        light.count = (sim.p_random() & maxtime) + 1;
        Some(light.maxlight)
    }
}

/// `T_StrobeFlash`: no randomness once running.
fn strobe_flash(light: &mut Light, level: i16, darktime: i32, brighttime: i32) -> Option<i16> {
    light.count -= 1;
    if light.count != 0 {
        return None;
    }
    if level == light.minlight {
        light.count = brighttime;
        Some(light.maxlight)
    } else {
        light.count = darktime;
        Some(light.minlight)
    }
}

/// `T_Glow`: steps of 8 between the two levels, turning one step past each.
fn glow(light: &mut Light, level: i16, direction: i32) -> Option<i16> {
    match direction {
        -1 => {
            let mut l = level - GLOWSPEED;
            if l <= light.minlight {
                l += GLOWSPEED;
                light.kind = LightKind::Glow { direction: 1 };
            }
            Some(l)
        }
        1 => {
            let mut l = level + GLOWSPEED;
            if l >= light.maxlight {
                l -= GLOWSPEED;
                light.kind = LightKind::Glow { direction: -1 };
            }
            Some(l)
        }
        _ => None,
    }
}

/// `P_SpawnFireFlicker`: the sector's special is cleared (it has done its
/// job at spawn).
pub fn spawn_fire_flicker(sim: &mut Sim, sector: usize) {
    let s = &mut sim.level.sectors[sector];
    s.special = 0;
    let maxlight = s.lightlevel;
    let minlight = find_min_surrounding_light(&sim.level, sector, maxlight) + 16;
    sim.add_thinker(ThinkerKind::Light(Light { sector, kind: LightKind::FireFlicker, count: 4, maxlight, minlight }));
}

/// `P_SpawnLightFlash`: one `P_Random` for the first wait.
pub fn spawn_light_flash(sim: &mut Sim, sector: usize) {
    let s = &mut sim.level.sectors[sector];
    s.special = 0;
    let maxlight = s.lightlevel;
    let minlight = find_min_surrounding_light(&sim.level, sector, maxlight);
    let (maxtime, mintime) = (64, 7);
    // The thinker is added before the draw, as Doom adds it; the order
    // matters not for the draw but for the list.
    let id = sim.add_thinker(ThinkerKind::Light(Light {
        sector,
        kind: LightKind::Flash { maxtime, mintime },
        count: 0,
        maxlight,
        minlight,
    }));
    let count = (sim.p_random() & maxtime) + 1;
    if let ThinkerKind::Light(l) = &mut sim.thinker_mut(id).kind {
        l.count = count;
    }
}

/// `P_SpawnStrobeFlash`: `fast_or_slow` is the dark time; a strobe not in
/// sync draws its first wait from `P_Random`. A sector whose neighbours
/// are no darker strobes down to 0.
pub fn spawn_strobe_flash(sim: &mut Sim, sector: usize, fast_or_slow: i32, in_sync: bool) {
    let maxlight = sim.level.sectors[sector].lightlevel;
    let mut minlight = find_min_surrounding_light(&sim.level, sector, maxlight);
    if minlight == maxlight {
        minlight = 0;
    }
    sim.level.sectors[sector].special = 0;
    let count = if in_sync { 1 } else { (sim.p_random() & 7) + 1 };
    sim.add_thinker(ThinkerKind::Light(Light {
        sector,
        kind: LightKind::Strobe { darktime: fast_or_slow, brighttime: STROBEBRIGHT },
        count,
        maxlight,
        minlight,
    }));
}

/// `P_SpawnGlowingLight`.
pub fn spawn_glowing_light(sim: &mut Sim, sector: usize) {
    let maxlight = sim.level.sectors[sector].lightlevel;
    let minlight = find_min_surrounding_light(&sim.level, sector, maxlight);
    sim.level.sectors[sector].special = 0;
    sim.add_thinker(ThinkerKind::Light(Light {
        sector,
        kind: LightKind::Glow { direction: -1 },
        count: 0,
        maxlight,
        minlight,
    }));
}

/// `EV_StartLightStrobing`: slow strobes in the tagged sectors that have
/// no mover (the strobe itself does not become one).
pub fn start_light_strobing(sim: &mut Sim, line: usize) {
    let mut sec = None;
    while let Some(s) = find_sector_from_line_tag(&sim.level, line, sec) {
        sec = Some(s);
        if sim.level.sectors[s].specialdata.is_some() {
            continue;
        }
        spawn_strobe_flash(sim, s, SLOWDARK, false);
    }
}

/// `EV_TurnTagLightsOff`: each tagged sector to its darkest neighbour.
pub fn turn_tag_lights_off(sim: &mut Sim, line: usize) {
    let tag = sim.level.lines[line].tag;
    for s in 0..sim.level.sectors.len() {
        if sim.level.sectors[s].tag != tag {
            continue;
        }
        let mut min = sim.level.sectors[s].lightlevel;
        for &l in &sim.level.sectors[s].lines {
            if let Some(t) = next_sector(&sim.level, l, s) {
                min = min.min(sim.level.sectors[t].lightlevel);
            }
        }
        sim.level.sectors[s].lightlevel = min;
    }
}

/// `EV_LightTurnOn`: each tagged sector to `bright`, or with 0 to its
/// brightest neighbour. Vanilla searches into the same variable, so once
/// one sector has found a level the later sectors take that level instead
/// of searching their own neighbours; kept, demos may depend on it.
pub fn light_turn_on(sim: &mut Sim, line: usize, mut bright: i16) {
    let tag = sim.level.lines[line].tag;
    for s in 0..sim.level.sectors.len() {
        if sim.level.sectors[s].tag != tag {
            continue;
        }
        if bright == 0 {
            for &l in &sim.level.sectors[s].lines {
                if let Some(t) = next_sector(&sim.level, l, s) {
                    bright = bright.max(sim.level.sectors[t].lightlevel);
                }
            }
        }
        sim.level.sectors[s].lightlevel = bright;
    }
}
