//! Line and sector specials (`p_spec.c`): what crossing, shooting or using
//! a line does, damaging and secret sectors, the level's animated textures
//! and flats, scrolling walls, and the helpers the movers share (the
//! lowest floor around a sector, the next higher, ...).

use super::Sim;

/// `p_spec.c`'s globals: active plats and ceilings, pressed buttons,
/// animations, scrolling lines.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SpecialState {}

/// `P_SpawnSpecials`: the level's sector specials' thinkers (lights,
/// secrets counted, doors that close in 30 seconds) and the scrolling lines.
pub fn spawn_specials(sim: &mut Sim) {
    let _ = sim;
}

/// `P_UpdateSpecials`: animations, scrolling walls, switch returns.
pub fn update_specials(sim: &mut Sim) {
    let _ = sim;
}

/// `P_RespawnSpecials`: items come back in altdeath.
pub fn respawn_specials(sim: &mut Sim) {
    let _ = sim;
}

use super::MobjId;

/// `P_CrossSpecialLine`: `thing` crossed line `line` from side `side`.
pub fn cross_special_line(sim: &mut Sim, line: usize, side: usize, thing: MobjId) {
    let _ = (sim, line, side, thing);
}

/// `P_ShootSpecialLine`: a hitscan shot by `thing` hit line `line`.
pub fn shoot_special_line(sim: &mut Sim, thing: MobjId, line: usize) {
    let _ = (sim, thing, line);
}

/// `P_PlayerInSpecialSector`: player `player` stands in a damaging or
/// secret sector.
pub fn player_in_special_sector(sim: &mut Sim, player: usize) {
    let _ = (sim, player);
}
