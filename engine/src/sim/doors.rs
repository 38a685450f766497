//! Doors (`p_doors.c`): the door thinker `T_VerticalDoor` (a ceiling moved
//! through the shared `T_MovePlane`), doors started by tag (`EV_DoDoor`,
//! `EV_DoLockedDoor`), doors opened by use on their own line
//! (`EV_VerticalDoor`: keys, monsters, re-using a moving door), and the two
//! timed doors sector specials start.

use super::floors::{move_plane, MoveResult, Plane};
use super::specials::{find_lowest_ceiling_surrounding, next_free_tagged};
use super::think::ThinkerKind;
use super::Compat;
use super::{MobjId, Sim, ThinkerId, TICRATE};
use crate::fixed::Fixed;
use crate::map::special::{DoorKind, KeyColour};

/// A door's speed a tic (`VDOORSPEED`) and wait at the top (`VDOORWAIT`).
pub const VDOORSPEED: Fixed = Fixed(2 << 16);
pub const VDOORWAIT: i32 = 150;

/// `vldoor_e`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum DoorType {
    #[default]
    Normal,
    Close30ThenOpen,
    Close,
    Open,
    RaiseIn5Mins,
    BlazeRaise,
    BlazeOpen,
    BlazeClose,
}

/// The thinker's data (`vldoor_t`). `direction`: 1 up, 0 waiting, -1
/// down, 2 the initial wait of a 5-minute door.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Door {
    pub kind: DoorType,
    pub sector: usize,
    pub topheight: Fixed,
    pub speed: Fixed,
    pub direction: i32,
    pub topwait: i32,
    pub topcountdown: i32,
    /// Tics a close-then-open door stays shut (vanilla's 30 seconds; a
    /// generalized special's own).
    pub shut: i32,
}

/// What a door does and how fast and long: a vanilla type's constants
/// ([`DoorParams::of`]) or a generalized special's own
/// ([`DoorParams::generalized`]), started by the same code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DoorParams {
    pub kind: DoorType,
    pub speed: Fixed,
    /// Tics a raise door stays open (`topwait`).
    pub wait: i32,
    /// Tics a close-then-open door stays shut.
    pub shut: i32,
}

/// A close-then-open door's wait shut in vanilla (`EV_DoDoor`'s 30 seconds).
pub const CLOSE30_WAIT: i32 = 30 * TICRATE as i32;

impl DoorParams {
    /// Vanilla's door of `kind`: the blazing kinds four times as fast.
    pub fn of(kind: DoorType) -> DoorParams {
        let blazing = matches!(kind, DoorType::BlazeRaise | DoorType::BlazeOpen | DoorType::BlazeClose);
        let speed = if blazing { VDOORSPEED * 4 } else { VDOORSPEED };
        DoorParams { kind, speed, wait: VDOORWAIT, shut: CLOSE30_WAIT }
    }

    /// A generalized door: a door at four times Doom's speed or faster is
    /// a blazing one (its sounds), as in Boom's `EV_DoGenDoor`.
    pub fn generalized(kind: DoorKind, speed: Fixed, wait: i32, shut: i32) -> DoorParams {
        let blazing = speed >= VDOORSPEED * 4;
        let kind = match (kind, blazing) {
            (DoorKind::Raise, false) => DoorType::Normal,
            (DoorKind::Raise, true) => DoorType::BlazeRaise,
            (DoorKind::Open, false) => DoorType::Open,
            (DoorKind::Open, true) => DoorType::BlazeOpen,
            (DoorKind::Close, false) => DoorType::Close,
            (DoorKind::Close, true) => DoorType::BlazeClose,
            (DoorKind::CloseThenOpen, _) => DoorType::Close30ThenOpen,
        };
        DoorParams { kind, speed, wait, shut }
    }
}

/// Runs the thinker one tic (`T_VerticalDoor`).
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let ThinkerKind::Door(mut door) = sim.thinker(id).kind.clone() else { return };
    run_door(sim, id, &mut door);
    if let ThinkerKind::Door(slot) = &mut sim.thinker_mut(id).kind {
        *slot = door;
    }
}

fn run_door(sim: &mut Sim, id: ThinkerId, door: &mut Door) {
    let sec = door.sector;
    match door.direction {
        0 => {
            door.topcountdown -= 1;
            if door.topcountdown == 0 {
                match door.kind {
                    DoorType::BlazeRaise => {
                        door.direction = -1;
                        sound(sim, sec, "bdcls");
                    }
                    DoorType::Normal => {
                        door.direction = -1;
                        sound(sim, sec, "dorcls");
                    }
                    DoorType::Close30ThenOpen => {
                        door.direction = 1;
                        sound(sim, sec, "doropn");
                    }
                    _ => {}
                }
            }
        }
        2 => {
            door.topcountdown -= 1;
            if door.topcountdown == 0 && door.kind == DoorType::RaiseIn5Mins {
                door.direction = 1;
                door.kind = DoorType::Normal;
                sound(sim, sec, "doropn");
            }
        }
        -1 => {
            let floor = sim.level.sectors[sec].floorheight;
            match move_plane(sim, sec, door.speed, floor, 0, Plane::Ceiling, -1) {
                MoveResult::PastDest => match door.kind {
                    DoorType::BlazeRaise | DoorType::BlazeClose => {
                        finish(sim, id, sec);
                        sound(sim, sec, "bdcls");
                    }
                    DoorType::Normal | DoorType::Close => finish(sim, id, sec),
                    DoorType::Close30ThenOpen => {
                        door.direction = 0;
                        door.topcountdown = door.shut;
                    }
                    _ => {}
                },
                MoveResult::Crushed => match door.kind {
                    // Closing doors do not go back up.
                    DoorType::BlazeClose | DoorType::Close => {}
                    _ => {
                        door.direction = 1;
                        sound(sim, sec, "doropn");
                    }
                },
                MoveResult::Ok => {}
            }
        }
        1 => {
            if move_plane(sim, sec, door.speed, door.topheight, 0, Plane::Ceiling, 1) == MoveResult::PastDest {
                match door.kind {
                    DoorType::BlazeRaise | DoorType::Normal => {
                        door.direction = 0;
                        door.topcountdown = door.topwait;
                    }
                    DoorType::Close30ThenOpen | DoorType::BlazeOpen | DoorType::Open => finish(sim, id, sec),
                    _ => {}
                }
            }
        }
        _ => {}
    }
}

/// The door is done: the sector is free for another mover.
fn finish(sim: &mut Sim, id: ThinkerId, sec: usize) {
    sim.level.sectors[sec].specialdata = None;
    sim.remove_thinker(id);
}

fn sound(sim: &mut Sim, sector: usize, name: &str) {
    let s = sim.info.sound(name);
    sim.sector_sound(sector, s);
}

/// The card a locked vanilla line asks for (`card_t`: blue, yellow, red
/// cards 0-2, skulls 3-5; a key colour opens for either).
fn lock_of(special: i16) -> Option<usize> {
    match special {
        26 | 32 | 99 | 133 => Some(0),
        27 | 34 | 136 | 137 => Some(1),
        28 | 33 | 134 | 135 => Some(2),
        _ => None,
    }
}

/// The card index of a key colour (`card_t`'s order).
pub fn card_of(colour: KeyColour) -> usize {
    match colour {
        KeyColour::Blue => 0,
        KeyColour::Yellow => 1,
        KeyColour::Red => 2,
    }
}

/// What a locked door says without its key: used on the door itself
/// (`PD_*K`) or through a switch (`PD_*O`).
fn lock_message(card: usize, manual: bool) -> &'static str {
    match (card, manual) {
        (0, true) => "You need a blue key to open this door",
        (1, true) => "You need a yellow key to open this door",
        (_, true) => "You need a red key to open this door",
        (0, false) => "You need a blue key to activate this object",
        (1, false) => "You need a yellow key to activate this object",
        (_, false) => "You need a red key to activate this object",
    }
}

/// Whether the player whose body is `thing` holds the card or skull of
/// `colour`; if not, the message and the "oof".
fn has_key(sim: &mut Sim, thing: MobjId, colour: usize, manual: bool) -> bool {
    let Some(n) = sim.mo(thing).player else { return false };
    let Some(p) = sim.players[n].as_mut() else { return false };
    if p.cards[colour] || p.cards[colour + 3] {
        return true;
    }
    p.message = Some(lock_message(colour, manual).to_string());
    sim.sound_named(None, "oof");
    false
}

/// `EV_DoLockedDoor`: a switch-operated blazing door behind a key; only a
/// player with the key opens it.
pub fn do_locked_door(sim: &mut Sim, line: usize, kind: DoorType, thing: MobjId) -> bool {
    let special = sim.level.lines[line].special;
    let key = if matches!(special, 99 | 133 | 134 | 135 | 136 | 137) { lock_of(special) } else { None };
    locked_doors(sim, line, DoorParams::of(kind), key, thing)
}

/// Doors in the tagged sectors of `line` once the player `thing` has
/// shown the card `key` asks for (any key-locked switch or walk line).
pub fn locked_doors(sim: &mut Sim, line: usize, params: DoorParams, key: Option<usize>, thing: MobjId) -> bool {
    if sim.mo(thing).player.is_none() {
        return false;
    }
    if let Some(colour) = key {
        if !has_key(sim, thing, colour, false) {
            return false;
        }
    }
    start_doors(sim, line, params)
}

/// `EV_DoDoor`: a door in each tagged sector without a mover; whether any
/// started.
pub fn do_door(sim: &mut Sim, line: usize, kind: DoorType) -> bool {
    start_doors(sim, line, DoorParams::of(kind))
}

/// `EV_DoDoor` with its parameters given.
pub fn start_doors(sim: &mut Sim, line: usize, params: DoorParams) -> bool {
    let mut sec = None;
    let mut started = false;
    while let Some(s) = next_free_tagged(sim, line, sec) {
        sec = Some(s);
        started = true;
        start_door(sim, s, params);
    }
    started
}

/// One door of `EV_DoDoor` on sector `s` (which has no mover).
pub fn start_door(sim: &mut Sim, s: usize, params: DoorParams) {
    let DoorParams { kind, speed, wait, shut } = params;
    let mut door =
        Door { kind, sector: s, topheight: Fixed::ZERO, speed, direction: 0, topwait: wait, topcountdown: 0, shut };
    let ceiling = sim.level.sectors[s].ceilingheight;
    let top = || find_lowest_ceiling_surrounding(&sim.level, s) - Fixed::from_int(4);
    let noise = match kind {
        DoorType::BlazeClose => {
            door.topheight = top();
            door.direction = -1;
            Some("bdcls")
        }
        DoorType::Close => {
            door.topheight = top();
            door.direction = -1;
            Some("dorcls")
        }
        DoorType::Close30ThenOpen => {
            door.topheight = ceiling;
            door.direction = -1;
            Some("dorcls")
        }
        DoorType::BlazeRaise | DoorType::BlazeOpen => {
            door.direction = 1;
            door.topheight = top();
            (door.topheight != ceiling).then_some("bdopn")
        }
        DoorType::Normal | DoorType::Open => {
            door.direction = 1;
            door.topheight = top();
            (door.topheight != ceiling).then_some("doropn")
        }
        DoorType::RaiseIn5Mins => None,
    };
    let id = sim.add_thinker(ThinkerKind::Door(door));
    sim.level.sectors[s].specialdata = Some(id);
    if let Some(n) = noise {
        sound(sim, s, n);
    }
}

/// `EV_VerticalDoor`: `thing` used the door line `line` (its back sector
/// is the door). Keys are checked for players; monsters are turned away
/// from locked doors. A raise door already moving goes back up if it was
/// closing, or (for a player) starts closing.
pub fn vertical_door(sim: &mut Sim, line: usize, thing: MobjId) {
    let special = sim.level.lines[line].special;
    let key = if matches!(special, 26 | 27 | 28 | 32 | 33 | 34) { lock_of(special) } else { None };
    let kind = match special {
        31..=34 => DoorType::Open,
        117 => DoorType::BlazeRaise,
        118 => DoorType::BlazeOpen,
        _ => DoorType::Normal,
    };
    let door = ManualDoor { params: DoorParams::of(kind), key, once: matches!(special, 31..=34 | 118) };
    manual_door(sim, line, thing, door);
}

/// A door used on its own line (Doom's D1 and DR lines, and generalized
/// doors with no tag).
#[derive(Clone, Copy, Debug)]
pub struct ManualDoor {
    pub params: DoorParams,
    /// The card it asks for.
    pub key: Option<usize>,
    /// The line loses its special when the door starts (D1).
    pub once: bool,
}

/// `EV_VerticalDoor` with its parameters given; whether a door started or
/// a moving one turned. A raise door already moving is turned (see
/// [`reuse_moving_door`]); any other door on a sector with a mover starts a
/// second thinker in vanilla (the sector's `specialdata` then names the
/// new one) and is refused under Sightline's rules, as by Boom.
pub fn manual_door(sim: &mut Sim, line: usize, thing: MobjId, door: ManualDoor) -> bool {
    let ManualDoor { params, key, once } = door;
    if let Some(colour) = key {
        if sim.mo(thing).player.is_none() || !has_key(sim, thing, colour, true) {
            return false;
        }
    }
    // Vanilla stops with an error on a one-sided door line.
    let Some(back) = sim.level.lines[line].sidenum[1] else { return false };
    let sec = sim.level.sides[back].sector;
    let raises = matches!(params.kind, DoorType::Normal | DoorType::BlazeRaise);
    if let Some(existing) = sim.level.sectors[sec].specialdata {
        if raises {
            reuse_moving_door(sim, existing, thing);
            return true;
        }
        if sim.rules.compat == Compat::Sightline {
            return false;
        }
    }
    if !matches!(params.kind, DoorType::Normal | DoorType::BlazeRaise | DoorType::Open | DoorType::BlazeOpen) {
        // A door that closes first starts as a tagged one does.
        if sim.level.sectors[sec].specialdata.is_some() {
            return false;
        }
        start_door(sim, sec, params);
        return true;
    }
    let blazing = matches!(params.kind, DoorType::BlazeRaise | DoorType::BlazeOpen);
    sound(sim, sec, if blazing { "bdopn" } else { "doropn" });
    if once {
        sim.level.lines[line].special = 0;
    }
    let topheight = find_lowest_ceiling_surrounding(&sim.level, sec) - Fixed::from_int(4);
    let DoorParams { kind, speed, wait, shut } = params;
    let door = Door { kind, sector: sec, topheight, speed, direction: 1, topwait: wait, topcountdown: 0, shut };
    let id = sim.add_thinker(ThinkerKind::Door(door));
    sim.level.sectors[sec].specialdata = Some(id);
    true
}

/// A raise door used while its sector already has a mover. Vanilla reads
/// and writes `door->direction` whatever the mover is; Chocolate sends the
/// closing write for a plat to its `wait` (the field at that offset on
/// 32-bit machines), as here; a floor (whose field there is half a flat
/// number and padding) is left alone.
fn reuse_moving_door(sim: &mut Sim, existing: ThinkerId, thing: MobjId) {
    let is_player = sim.mo(thing).player.is_some();
    match &mut sim.thinker_mut(existing).kind {
        ThinkerKind::Door(door) => {
            if door.direction == -1 {
                door.direction = 1;
            } else if is_player {
                door.direction = -1;
            }
        }
        ThinkerKind::Plat(plat) => {
            // On the 64-bit build that made the reference dumps, the door's
            // `direction` lies over the plat's `count`; Chocolate's own
            // write goes to `wait`.
            if plat.count == -1 {
                plat.count = 1;
            } else if is_player {
                plat.wait = -1;
            }
        }
        ThinkerKind::Ceiling(c) => {
            // Likewise a crusher's `speed` lies there on 64-bit.
            if c.speed == Fixed(-1) {
                c.speed = Fixed(1);
            } else if is_player {
                c.speed = Fixed(-1);
            }
        }
        _ => {}
    }
}

/// `P_SpawnDoorCloseIn30`: sector special 10, a door open now that closes
/// after 30 seconds (then stays shut: its type is a normal door). Vanilla
/// leaves `topheight` and `topwait` as the zone memory held them, which
/// matters only if something blocks the closing door and it goes back up;
/// here it goes back to where it started and waits a normal door's wait.
pub fn spawn_door_close_in_30(sim: &mut Sim, sector: usize) {
    let door = Door {
        kind: DoorType::Normal,
        sector,
        topheight: sim.level.sectors[sector].ceilingheight,
        speed: VDOORSPEED,
        direction: 0,
        topwait: VDOORWAIT,
        topcountdown: 30 * TICRATE as i32,
        shut: CLOSE30_WAIT,
    };
    let id = sim.add_thinker(ThinkerKind::Door(door));
    let s = &mut sim.level.sectors[sector];
    s.specialdata = Some(id);
    s.special = 0;
}

/// `P_SpawnDoorRaiseIn5Mins`: sector special 14, a shut door that opens
/// after five minutes and then behaves as a normal door.
pub fn spawn_door_raise_in_5_mins(sim: &mut Sim, sector: usize) {
    let topheight = find_lowest_ceiling_surrounding(&sim.level, sector) - Fixed::from_int(4);
    let door = Door {
        kind: DoorType::RaiseIn5Mins,
        sector,
        topheight,
        speed: VDOORSPEED,
        direction: 2,
        topwait: VDOORWAIT,
        topcountdown: 5 * 60 * TICRATE as i32,
        shut: CLOSE30_WAIT,
    };
    let id = sim.add_thinker(ThinkerKind::Door(door));
    let s = &mut sim.level.sectors[sector];
    s.specialdata = Some(id);
    s.special = 0;
}
