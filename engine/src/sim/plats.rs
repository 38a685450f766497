//! Lifts and platforms (`p_plats.c`): the plat thinker `T_PlatRaise` (a
//! floor moved through the shared `T_MovePlane`), plats started by tag
//! (`EV_DoPlat`), and the active-plat list that lets a perpetual lift be
//! stopped (`EV_StopPlat`: the thinker stays in the list, in stasis) and
//! started again (`P_ActivateInStasis`).

use super::floors::{move_plane, MoveResult, Plane};
use super::specials::{find_highest_floor_surrounding, find_lowest_floor_surrounding, find_next_highest_floor};
use super::specials::{next_free_tagged, MAXPLATS};
use super::think::{Status, ThinkerKind};
use super::{Sim, ThinkerId, TICRATE};
use crate::fixed::Fixed;

/// A plat's speed a tic (`PLATSPEED`) and its wait in seconds (`PLATWAIT`).
pub const PLATSPEED: Fixed = Fixed::ONE;
pub const PLATWAIT: i32 = 3;

/// `plat_e`, in Doom's order (a perpetual lift's start is `P_Random() & 1`
/// of it: up or down).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum PlatStatus {
    #[default]
    Up,
    Down,
    Waiting,
    InStasis,
}

/// `plattype_e`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum PlatType {
    PerpetualRaise,
    #[default]
    DownWaitUpStay,
    RaiseAndChange,
    RaiseToNearestAndChange,
    BlazeDwus,
}

/// The thinker's data (`plat_t`).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Plat {
    pub sector: usize,
    pub speed: Fixed,
    pub low: Fixed,
    pub high: Fixed,
    pub wait: i32,
    pub count: i32,
    pub status: PlatStatus,
    pub oldstatus: PlatStatus,
    pub crush: bool,
    pub tag: i16,
    pub kind: PlatType,
}

/// Runs the thinker one tic (`T_PlatRaise`).
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let ThinkerKind::Plat(mut plat) = sim.thinker(id).kind.clone() else { return };
    plat_raise(sim, id, &mut plat);
    if let ThinkerKind::Plat(slot) = &mut sim.thinker_mut(id).kind {
        *slot = plat;
    }
}

fn plat_raise(sim: &mut Sim, id: ThinkerId, plat: &mut Plat) {
    let sec = plat.sector;
    match plat.status {
        PlatStatus::Up => {
            let res = move_plane(sim, sec, plat.speed, plat.high, i32::from(plat.crush), Plane::Floor, 1);
            let changes = matches!(plat.kind, PlatType::RaiseAndChange | PlatType::RaiseToNearestAndChange);
            if changes && sim.leveltime & 7 == 0 {
                sound(sim, sec, "stnmov");
            }
            if res == MoveResult::Crushed && !plat.crush {
                plat.count = plat.wait;
                plat.status = PlatStatus::Down;
                sound(sim, sec, "pstart");
            } else if res == MoveResult::PastDest {
                plat.count = plat.wait;
                plat.status = PlatStatus::Waiting;
                sound(sim, sec, "pstop");
                if plat.kind != PlatType::PerpetualRaise {
                    remove_active_plat(sim, id);
                }
            }
        }
        PlatStatus::Down => {
            if move_plane(sim, sec, plat.speed, plat.low, 0, Plane::Floor, -1) == MoveResult::PastDest {
                plat.count = plat.wait;
                plat.status = PlatStatus::Waiting;
                sound(sim, sec, "pstop");
            }
        }
        PlatStatus::Waiting => {
            plat.count -= 1;
            if plat.count == 0 {
                plat.status =
                    if sim.level.sectors[sec].floorheight == plat.low { PlatStatus::Up } else { PlatStatus::Down };
                sound(sim, sec, "pstart");
            }
        }
        PlatStatus::InStasis => {}
    }
}

fn sound(sim: &mut Sim, sector: usize, name: &str) {
    let s = sim.info.sound(name);
    sim.sector_sound(sector, s);
}

/// How a plat moves: a vanilla type's speed and wait ([`PlatParams::of`])
/// or a generalized lift's own.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlatParams {
    pub kind: PlatType,
    pub speed: Fixed,
    /// Tics it waits at either end.
    pub wait: i32,
    /// The rise of a raise-and-change plat.
    pub amount: i32,
}

impl PlatParams {
    /// Vanilla's plat of `kind` (`EV_DoPlat`'s constants).
    pub fn of(kind: PlatType, amount: i32) -> PlatParams {
        let (speed, wait) = match kind {
            PlatType::RaiseToNearestAndChange | PlatType::RaiseAndChange => (Fixed(PLATSPEED.0 / 2), 0),
            PlatType::DownWaitUpStay => (PLATSPEED * 4, TICRATE as i32 * PLATWAIT),
            PlatType::BlazeDwus => (PLATSPEED * 8, TICRATE as i32 * PLATWAIT),
            PlatType::PerpetualRaise => (PLATSPEED, TICRATE as i32 * PLATWAIT),
        };
        PlatParams { kind, speed, wait, amount }
    }
}

/// `EV_DoPlat`: a plat in each tagged sector without a mover; `amount` is
/// the rise of raise-and-change. A perpetual raise first restarts the
/// stopped plats of the tag. Whether any started.
pub fn do_plat(sim: &mut Sim, line: usize, kind: PlatType, amount: i32) -> bool {
    start_plats(sim, line, PlatParams::of(kind, amount))
}

/// `EV_DoPlat` with its parameters given.
pub fn start_plats(sim: &mut Sim, line: usize, params: PlatParams) -> bool {
    if params.kind == PlatType::PerpetualRaise {
        activate_in_stasis(sim, sim.level.lines[line].tag);
    }
    let mut sec = None;
    let mut started = false;
    while let Some(s) = next_free_tagged(sim, line, sec) {
        sec = Some(s);
        started = true;
        start_plat(sim, line, s, params);
    }
    started
}

/// One plat of `EV_DoPlat` on sector `s` (which has no mover), set off by
/// `line`: the change kinds take the flat of its front sector.
pub fn start_plat(sim: &mut Sim, line: usize, s: usize, params: PlatParams) {
    let plat = new_plat(sim, line, s, params);
    let id = sim.add_thinker(ThinkerKind::Plat(plat));
    sim.level.sectors[s].specialdata = Some(id);
    add_active_plat(sim, id);
}

/// One plat of `EV_DoPlat`'s kinds; the change kinds take the flat of the
/// line's front sector at once.
fn new_plat(sim: &mut Sim, line: usize, s: usize, params: PlatParams) -> Plat {
    let PlatParams { kind, speed, wait, amount } = params;
    let tag = sim.level.lines[line].tag;
    let here = sim.level.sectors[s].floorheight;
    let mut plat = Plat { sector: s, kind, tag, speed, wait, ..Plat::default() };
    let lowest = |sim: &Sim| find_lowest_floor_surrounding(&sim.level, s).min(here);
    let front_pic = sim.level.lines[line].sidenum[0].map(|side| {
        let front = sim.level.sides[side].sector;
        sim.level.sectors[front].floorpic
    });
    let noise = match kind {
        PlatType::RaiseToNearestAndChange => {
            if let Some(pic) = front_pic {
                sim.level.sectors[s].floorpic = pic;
                sim.textures_changed += 1;
            }
            plat.high = find_next_highest_floor(&sim.level, s, here);
            plat.status = PlatStatus::Up;
            // No more damage, if it hurt.
            sim.level.sectors[s].special = 0;
            "stnmov"
        }
        PlatType::RaiseAndChange => {
            if let Some(pic) = front_pic {
                sim.level.sectors[s].floorpic = pic;
                sim.textures_changed += 1;
            }
            plat.high = here + Fixed::from_int(amount);
            plat.status = PlatStatus::Up;
            "stnmov"
        }
        PlatType::DownWaitUpStay | PlatType::BlazeDwus => {
            plat.low = lowest(sim);
            plat.high = here;
            plat.status = PlatStatus::Down;
            "pstart"
        }
        PlatType::PerpetualRaise => {
            plat.low = lowest(sim);
            plat.high = find_highest_floor_surrounding(&sim.level, s).max(here);
            plat.status = if sim.p_random() & 1 == 0 { PlatStatus::Up } else { PlatStatus::Down };
            "pstart"
        }
    };
    sound(sim, s, noise);
    plat
}

/// `P_ActivateInStasis`: the stopped plats of `tag` go on as they were.
pub fn activate_in_stasis(sim: &mut Sim, tag: i16) {
    for i in 0..MAXPLATS {
        let Some(id) = sim.spec.activeplats[i] else { continue };
        let t = sim.thinker_mut(id);
        if let ThinkerKind::Plat(plat) = &mut t.kind {
            if plat.tag == tag && plat.status == PlatStatus::InStasis {
                plat.status = plat.oldstatus;
                if t.status == Status::Stasis {
                    t.status = Status::Active;
                }
            }
        }
    }
}

/// `EV_StopPlat`: the moving plats of the line's tag stop where they are.
pub fn stop_plat(sim: &mut Sim, line: usize) {
    let tag = sim.level.lines[line].tag;
    for i in 0..MAXPLATS {
        let Some(id) = sim.spec.activeplats[i] else { continue };
        let t = sim.thinker_mut(id);
        if let ThinkerKind::Plat(plat) = &mut t.kind {
            if plat.status != PlatStatus::InStasis && plat.tag == tag {
                plat.oldstatus = plat.status;
                plat.status = PlatStatus::InStasis;
                if t.status == Status::Active {
                    t.status = Status::Stasis;
                }
            }
        }
    }
}

/// `P_AddActivePlat`: the first free slot. Vanilla stops with "no more
/// plats" when all 30 are taken; here the plat runs but cannot be stopped.
pub fn add_active_plat(sim: &mut Sim, id: ThinkerId) {
    if let Some(slot) = sim.spec.activeplats.iter_mut().find(|s| s.is_none()) {
        *slot = Some(id);
    }
}

/// `P_RemoveActivePlat`: the plat is done; its sector is free. (Vanilla
/// stops with an error for a plat not in the list; it is removed anyway.)
pub fn remove_active_plat(sim: &mut Sim, id: ThinkerId) {
    if let Some(slot) = sim.spec.activeplats.iter_mut().find(|s| **s == Some(id)) {
        *slot = None;
    }
    if let ThinkerKind::Plat(plat) = &sim.thinker(id).kind {
        let sector = plat.sector;
        sim.level.sectors[sector].specialdata = None;
    }
    sim.remove_thinker(id);
}
