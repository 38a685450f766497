//! Switches (`p_switch.c`): the switch textures' pairs for the game's
//! mode (`P_InitSwitchList`), a pressed switch's texture and, for a
//! button, its return (`P_ChangeSwitchTexture`, `P_StartButton`), and
//! what using a line does (`P_UseSpecialLine`: doors by use, every S1 and
//! SR type).

use super::ceilings::{self, CeilingType};
use super::doors::{self, DoorType};
use super::floors::{self, FloorType, StairType};
use super::level::{ml, Level, NameId};
use super::plats::{self, PlatType};
use super::specials::{exit_level, Button, ButtonWhere, BUTTONTIME, MAXBUTTONS};
use super::{lights, Compat, GameMode, MobjId, Sim, SimEvent};
use crate::texture::animdefs::{AnimDefs, SwitchGame};

/// `P_InitSwitchList`: the switch textures, in pairs (off, on), from the
/// shipped list (`engine/data/animations.ron`) as far as the game's mode
/// goes (shareware's, the registered game's, Doom II's), and Sightline's
/// own under Sightline's rules.
pub fn switch_list(mode: GameMode, compat: Compat) -> Vec<&'static str> {
    let last = match (compat, mode) {
        (Compat::Sightline, _) => SwitchGame::Sightline,
        (_, GameMode::Shareware) => SwitchGame::Shareware,
        (_, GameMode::Registered | GameMode::Retail) => SwitchGame::Registered,
        (_, GameMode::Commercial) => SwitchGame::Doom2,
    };
    let defs = &AnimDefs::doom().switches;
    defs.iter().filter(|s| s.game <= last).flat_map(|s| [s.off.as_str(), s.on.as_str()]).collect()
}

/// The id of a texture name, added to the level's names if the level did
/// not use it yet (a switch's other face).
fn name_id_or_add(level: &mut Level, name: &str) -> NameId {
    level.name_id(name).unwrap_or_else(|| {
        level.names.push(name.to_ascii_uppercase());
        NameId((level.names.len() - 1) as u16)
    })
}

/// `P_ChangeSwitchTexture`: the line's front side shows the switch's other
/// face (top, then middle, then bottom texture, for each pair in order);
/// a button (`use_again`) pops back after a second; a once-only switch's
/// line loses its special first (so the exit switch, special 11, clicks
/// the exit sound only as a button). The click comes from the line's
/// front sector (vanilla plays it from the first button slot's origin, a
/// slip that changes only where the sound is heard).
pub fn change_switch_texture(sim: &mut Sim, line: usize, use_again: bool) {
    if !use_again {
        sim.level.lines[line].special = 0;
    }
    let Some(side) = sim.level.lines[line].sidenum[0] else { return };
    let click = if sim.level.lines[line].special == 11 { "swtchx" } else { "swtchn" };
    let s = &sim.level.sides[side];
    let faces =
        [(ButtonWhere::Top, s.toptexture), (ButtonWhere::Middle, s.midtexture), (ButtonWhere::Bottom, s.bottomtexture)];
    let list = switch_list(sim.rules.mode, sim.rules.compat);
    for (i, name) in list.iter().enumerate() {
        let Some(&(place, texture)) = faces.iter().find(|(_, t)| sim.level.name(*t).eq_ignore_ascii_case(name)) else {
            continue;
        };
        let sector = sim.level.lines[line].frontsector.unwrap_or(0);
        let sound = sim.info.sound(click);
        sim.sector_sound(sector, sound);
        let other = name_id_or_add(&mut sim.level, list[i ^ 1]);
        let s = &mut sim.level.sides[side];
        match place {
            ButtonWhere::Top => s.toptexture = other,
            ButtonWhere::Middle => s.midtexture = other,
            ButtonWhere::Bottom => s.bottomtexture = other,
        }
        sim.textures_changed += 1;
        if use_again {
            start_button(sim, line, place, texture, BUTTONTIME);
        }
        return;
    }
}

/// `P_StartButton`: a button waits `time` tics to pop back to `texture`,
/// unless the line is already waiting. Vanilla stops with an error when
/// all 16 slots are busy; here the button stays pressed.
pub fn start_button(sim: &mut Sim, line: usize, place: ButtonWhere, texture: NameId, time: i32) {
    let buttons = &mut sim.spec.buttons;
    if buttons.iter().any(|b| b.timer != 0 && b.line == line) {
        return;
    }
    let sector = sim.level.lines[line].frontsector.unwrap_or(0);
    if let Some(b) = buttons.iter_mut().take(MAXBUTTONS).find(|b| b.timer == 0) {
        *b = Button { line, place, texture, timer: time, sector };
    }
}

/// `P_UseSpecialLine`: `thing` used line `line` from side `side`; whether
/// the use was taken (true for any line a player may use, as vanilla
/// returns; false for a back side or a line a monster may not use).
/// Monsters open only plain and locked manual doors, never secret ones.
pub fn use_special_line(sim: &mut Sim, thing: MobjId, line: usize, side: usize) -> bool {
    let Some(l) = sim.level.lines.get(line) else { return false };
    let by_player = sim.mo(thing).player.is_some();
    let special = l.special;
    // Only 124 (a sliding door that was never finished) is usable from
    // the back, and it does nothing.
    if side != 0 && special != 124 {
        return false;
    }
    if let Some((taken, started)) = super::generalized::use_line(sim, line, thing) {
        if by_player {
            sim.events.push(SimEvent::Special { line, started });
        }
        return taken;
    }
    if sim.mo(thing).player.is_none() {
        if sim.level.lines[line].flags & ml::SECRET != 0 || !matches!(special, 1 | 32 | 33 | 34) {
            return false;
        }
    }
    let started = match special {
        1 | 26 | 27 | 28 | 31 | 32 | 33 | 34 | 117 | 118 => {
            doors::vertical_door(sim, line, thing);
            true
        }
        11 => {
            change_switch_texture(sim, line, false);
            exit_level(sim, false);
            true
        }
        51 => {
            change_switch_texture(sim, line, false);
            exit_level(sim, true);
            true
        }
        138 => {
            lights::light_turn_on(sim, line, 255);
            change_switch_texture(sim, line, true);
            true
        }
        139 => {
            lights::light_turn_on(sim, line, 35);
            change_switch_texture(sim, line, true);
            true
        }
        _ => match switch_action(sim, line, special, thing) {
            Some((acted, use_again)) => {
                if acted {
                    change_switch_texture(sim, line, use_again);
                }
                acted
            }
            None => false,
        },
    };
    // For the outside only (the autopilot hears whether its press worked).
    if by_player {
        sim.events.push(SimEvent::Special { line, started });
    }
    true
}

/// The S1 (`false`) and SR (`true`) switches that act through a mover:
/// whether the mover started, and whether the switch is a button.
fn switch_action(sim: &mut Sim, line: usize, special: i16, thing: MobjId) -> Option<(bool, bool)> {
    use CeilingType as C;
    use DoorType as D;
    use FloorType as F;
    use PlatType as P;
    let once = |acted: bool| Some((acted, false));
    let again = |acted: bool| Some((acted, true));
    match special {
        7 => once(floors::build_stairs(sim, line, StairType::Build8)),
        9 => once(floors::do_donut(sim, line)),
        14 => once(plats::do_plat(sim, line, P::RaiseAndChange, 32)),
        15 => once(plats::do_plat(sim, line, P::RaiseAndChange, 24)),
        18 => once(floors::do_floor(sim, line, F::RaiseFloorToNearest)),
        20 => once(plats::do_plat(sim, line, P::RaiseToNearestAndChange, 0)),
        21 => once(plats::do_plat(sim, line, P::DownWaitUpStay, 0)),
        23 => once(floors::do_floor(sim, line, F::LowerFloorToLowest)),
        29 => once(doors::do_door(sim, line, D::Normal)),
        41 => once(ceilings::do_ceiling(sim, line, C::LowerToFloor)),
        71 => once(floors::do_floor(sim, line, F::TurboLower)),
        49 => once(ceilings::do_ceiling(sim, line, C::CrushAndRaise)),
        50 => once(doors::do_door(sim, line, D::Close)),
        55 => once(floors::do_floor(sim, line, F::RaiseFloorCrush)),
        101 => once(floors::do_floor(sim, line, F::RaiseFloor)),
        102 => once(floors::do_floor(sim, line, F::LowerFloor)),
        103 => once(doors::do_door(sim, line, D::Open)),
        111 => once(doors::do_door(sim, line, D::BlazeRaise)),
        112 => once(doors::do_door(sim, line, D::BlazeOpen)),
        113 => once(doors::do_door(sim, line, D::BlazeClose)),
        122 => once(plats::do_plat(sim, line, P::BlazeDwus, 0)),
        127 => once(floors::build_stairs(sim, line, StairType::Turbo16)),
        131 => once(floors::do_floor(sim, line, F::RaiseFloorTurbo)),
        133 | 135 | 137 => once(doors::do_locked_door(sim, line, D::BlazeOpen, thing)),
        140 => once(floors::do_floor(sim, line, F::RaiseFloor512)),
        42 => again(doors::do_door(sim, line, D::Close)),
        43 => again(ceilings::do_ceiling(sim, line, C::LowerToFloor)),
        45 => again(floors::do_floor(sim, line, F::LowerFloor)),
        60 => again(floors::do_floor(sim, line, F::LowerFloorToLowest)),
        61 => again(doors::do_door(sim, line, D::Open)),
        62 => again(plats::do_plat(sim, line, P::DownWaitUpStay, 1)),
        63 => again(doors::do_door(sim, line, D::Normal)),
        64 => again(floors::do_floor(sim, line, F::RaiseFloor)),
        66 => again(plats::do_plat(sim, line, P::RaiseAndChange, 24)),
        67 => again(plats::do_plat(sim, line, P::RaiseAndChange, 32)),
        65 => again(floors::do_floor(sim, line, F::RaiseFloorCrush)),
        68 => again(plats::do_plat(sim, line, P::RaiseToNearestAndChange, 0)),
        69 => again(floors::do_floor(sim, line, F::RaiseFloorToNearest)),
        70 => again(floors::do_floor(sim, line, F::TurboLower)),
        114 => again(doors::do_door(sim, line, D::BlazeRaise)),
        115 => again(doors::do_door(sim, line, D::BlazeOpen)),
        116 => again(doors::do_door(sim, line, D::BlazeClose)),
        123 => again(plats::do_plat(sim, line, P::BlazeDwus, 0)),
        132 => again(floors::do_floor(sim, line, F::RaiseFloorTurbo)),
        99 | 134 | 136 => again(doors::do_locked_door(sim, line, D::BlazeOpen, thing)),
        _ => None,
    }
}
