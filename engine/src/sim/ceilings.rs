//! Ceilings and crushers (`p_ceilng.c`): the ceiling thinker
//! `T_MoveCeiling` (through the shared `T_MovePlane`), ceilings started by
//! tag (`EV_DoCeiling`), and the active-ceiling list that lets a crusher be
//! stopped (`EV_CeilingCrushStop`: direction 0, in stasis) and started
//! again (`P_ActivateInStasisCeiling`).

use super::floors::{move_plane, MoveResult, Plane};
use super::specials::{find_highest_ceiling_surrounding, next_free_tagged, MAXCEILINGS};
use super::think::{Status, ThinkerKind};
use super::{Sim, ThinkerId};
use crate::fixed::Fixed;

/// A ceiling's speed a tic (`CEILSPEED`).
pub const CEILSPEED: Fixed = Fixed::ONE;

/// `ceiling_e`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum CeilingType {
    #[default]
    LowerToFloor,
    RaiseToHighest,
    LowerAndCrush,
    CrushAndRaise,
    FastCrushAndRaise,
    SilentCrushAndRaise,
    /// A generalized crusher (Boom's `genCrusher`, `genSilentCrusher`): its
    /// speed is its own, it slows while crushing only when slower than a
    /// fast crusher, and it gets its speed back at the bottom.
    GenCrusher,
    GenSilentCrusher,
}

/// The thinker's data (`ceiling_t`). `direction` 1 up, -1 down, 0 in
/// stasis.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Ceiling {
    pub kind: CeilingType,
    pub sector: usize,
    pub bottomheight: Fixed,
    pub topheight: Fixed,
    pub speed: Fixed,
    pub crush: bool,
    pub direction: i32,
    pub tag: i16,
    pub olddirection: i32,
    /// The speed it started with (Boom's `oldspeed`): a crusher slowed by a
    /// body goes back to it at the bottom. Vanilla's slow crushers start at
    /// `CEILSPEED`, which is what they go back to.
    pub oldspeed: Fixed,
}

/// Runs the thinker one tic (`T_MoveCeiling`).
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let ThinkerKind::Ceiling(mut c) = sim.thinker(id).kind.clone() else { return };
    move_ceiling(sim, id, &mut c);
    if let ThinkerKind::Ceiling(slot) = &mut sim.thinker_mut(id).kind {
        *slot = c;
    }
}

fn move_ceiling(sim: &mut Sim, id: ThinkerId, c: &mut Ceiling) {
    let sec = c.sector;
    let silent = matches!(c.kind, CeilingType::SilentCrushAndRaise | CeilingType::GenSilentCrusher);
    match c.direction {
        1 => {
            let res = move_plane(sim, sec, c.speed, c.topheight, 0, Plane::Ceiling, 1);
            if sim.leveltime & 7 == 0 && !silent {
                sound(sim, sec, "stnmov");
            }
            if res == MoveResult::PastDest {
                match c.kind {
                    CeilingType::RaiseToHighest => remove_active_ceiling(sim, id),
                    CeilingType::SilentCrushAndRaise | CeilingType::GenSilentCrusher => {
                        sound(sim, sec, "pstop");
                        c.direction = -1;
                    }
                    CeilingType::FastCrushAndRaise | CeilingType::CrushAndRaise | CeilingType::GenCrusher => {
                        c.direction = -1
                    }
                    _ => {}
                }
            }
        }
        -1 => {
            let res = move_plane(sim, sec, c.speed, c.bottomheight, i32::from(c.crush), Plane::Ceiling, -1);
            if sim.leveltime & 7 == 0 && !silent {
                sound(sim, sec, "stnmov");
            }
            match res {
                MoveResult::PastDest => match c.kind {
                    // Vanilla's fall-through: the silent crusher clicks, the
                    // slow ones get their speed back, all three turn up.
                    CeilingType::SilentCrushAndRaise => {
                        sound(sim, sec, "pstop");
                        c.speed = CEILSPEED;
                        c.direction = 1;
                    }
                    CeilingType::CrushAndRaise => {
                        c.speed = CEILSPEED;
                        c.direction = 1;
                    }
                    CeilingType::GenSilentCrusher | CeilingType::GenCrusher => {
                        if c.kind == CeilingType::GenSilentCrusher {
                            sound(sim, sec, "pstop");
                        }
                        c.speed = c.oldspeed;
                        c.direction = 1;
                    }
                    CeilingType::FastCrushAndRaise => c.direction = 1,
                    CeilingType::LowerAndCrush | CeilingType::LowerToFloor => remove_active_ceiling(sim, id),
                    CeilingType::RaiseToHighest => {}
                },
                MoveResult::Crushed => {
                    if matches!(
                        c.kind,
                        CeilingType::SilentCrushAndRaise | CeilingType::CrushAndRaise | CeilingType::LowerAndCrush
                    ) {
                        c.speed = Fixed(CEILSPEED.0 / 8);
                    }
                    // Boom's generalized crushers: an eighth of their own speed, unless
                    // as fast as vanilla's fast crusher.
                    let generalized = matches!(c.kind, CeilingType::GenCrusher | CeilingType::GenSilentCrusher);
                    if generalized && c.oldspeed < CEILSPEED * 2 {
                        c.speed = Fixed(c.oldspeed.0 / 8);
                    }
                }
                MoveResult::Ok => {}
            }
        }
        _ => {}
    }
}

fn sound(sim: &mut Sim, sector: usize, name: &str) {
    let s = sim.info.sound(name);
    sim.sector_sound(sector, s);
}

/// `EV_DoCeiling`: a ceiling in each tagged sector without a mover (the
/// crushers first restart their stopped fellows of the tag); whether any
/// started.
pub fn do_ceiling(sim: &mut Sim, line: usize, kind: CeilingType) -> bool {
    if matches!(kind, CeilingType::FastCrushAndRaise | CeilingType::SilentCrushAndRaise | CeilingType::CrushAndRaise) {
        activate_in_stasis_ceiling(sim, line);
    }
    let mut sec = None;
    let mut started = false;
    while let Some(s) = next_free_tagged(sim, line, sec) {
        sec = Some(s);
        started = true;
        let c = new_ceiling(sim, s, kind);
        start_ceiling(sim, c);
    }
    started
}

/// Starts ceiling `c` as its sector's mover, listed as active.
pub fn start_ceiling(sim: &mut Sim, c: Ceiling) {
    let s = c.sector;
    let id = sim.add_thinker(ThinkerKind::Ceiling(c));
    sim.level.sectors[s].specialdata = Some(id);
    add_active_ceiling(sim, id);
}

/// One ceiling of `EV_DoCeiling`'s kinds on sector `s`.
fn new_ceiling(sim: &Sim, s: usize, kind: CeilingType) -> Ceiling {
    let (floor, ceiling) = (sim.level.sectors[s].floorheight, sim.level.sectors[s].ceilingheight);
    let mut c = Ceiling { kind, sector: s, tag: sim.level.sectors[s].tag, ..Ceiling::default() };
    match kind {
        CeilingType::FastCrushAndRaise => {
            c.crush = true;
            c.topheight = ceiling;
            c.bottomheight = floor + Fixed::from_int(8);
            c.direction = -1;
            c.speed = CEILSPEED * 2;
        }
        CeilingType::SilentCrushAndRaise
        | CeilingType::CrushAndRaise
        | CeilingType::LowerAndCrush
        | CeilingType::LowerToFloor => {
            if matches!(kind, CeilingType::SilentCrushAndRaise | CeilingType::CrushAndRaise) {
                c.crush = true;
                c.topheight = ceiling;
            }
            c.bottomheight = floor;
            if kind != CeilingType::LowerToFloor {
                c.bottomheight += Fixed::from_int(8);
            }
            c.direction = -1;
            c.speed = CEILSPEED;
        }
        CeilingType::RaiseToHighest => {
            c.topheight = find_highest_ceiling_surrounding(&sim.level, s);
            c.direction = 1;
            c.speed = CEILSPEED;
        }
        CeilingType::GenCrusher | CeilingType::GenSilentCrusher => {
            c.crush = true;
            c.topheight = ceiling;
            c.bottomheight = floor + Fixed::from_int(8);
            c.direction = -1;
            c.speed = CEILSPEED;
        }
    }
    c.oldspeed = c.speed;
    c
}

/// A generalized crusher on sector `s` at `speed` (see [`CeilingType::GenCrusher`]).
pub fn gen_crusher(sim: &Sim, s: usize, speed: Fixed, silent: bool) -> Ceiling {
    let kind = if silent { CeilingType::GenSilentCrusher } else { CeilingType::GenCrusher };
    let mut c = new_ceiling(sim, s, kind);
    (c.speed, c.oldspeed) = (speed, speed);
    c
}

/// A ceiling moving once to `dest` at `speed` on sector `s`: up as
/// vanilla's raise-to-highest, down as its lower-to-floor (crushing if
/// `crush`), each done on arrival.
pub fn gen_ceiling(sim: &Sim, s: usize, dest: Fixed, speed: Fixed, crush: bool) -> Ceiling {
    let up = dest > sim.level.sectors[s].ceilingheight;
    let kind = if up { CeilingType::RaiseToHighest } else { CeilingType::LowerToFloor };
    let mut c = new_ceiling(sim, s, kind);
    if up {
        c.topheight = dest;
    } else {
        c.bottomheight = dest;
        c.crush = crush;
    }
    (c.speed, c.oldspeed) = (speed, speed);
    c
}

/// `P_AddActiveCeiling`: the first free slot; none free, it is not listed
/// (as vanilla).
pub fn add_active_ceiling(sim: &mut Sim, id: ThinkerId) {
    if let Some(slot) = sim.spec.activeceilings.iter_mut().find(|s| s.is_none()) {
        *slot = Some(id);
    }
}

/// `P_RemoveActiveCeiling`: a ceiling in the list is done; its sector is
/// freed and its thinker removed. One not in the list goes on (vanilla).
pub fn remove_active_ceiling(sim: &mut Sim, id: ThinkerId) {
    let Some(slot) = sim.spec.activeceilings.iter_mut().find(|s| **s == Some(id)) else { return };
    *slot = None;
    if let ThinkerKind::Ceiling(c) = &sim.thinker(id).kind {
        let sector = c.sector;
        sim.level.sectors[sector].specialdata = None;
    }
    sim.remove_thinker(id);
}

/// `P_ActivateInStasisCeiling`: the stopped crushers of the line's tag go
/// on in their old direction.
pub fn activate_in_stasis_ceiling(sim: &mut Sim, line: usize) {
    let tag = sim.level.lines[line].tag;
    for i in 0..MAXCEILINGS {
        let Some(id) = sim.spec.activeceilings[i] else { continue };
        let t = sim.thinker_mut(id);
        if let ThinkerKind::Ceiling(c) = &mut t.kind {
            if c.tag == tag && c.direction == 0 {
                c.direction = c.olddirection;
                if t.status == Status::Stasis {
                    t.status = Status::Active;
                }
            }
        }
    }
}

/// `EV_CeilingCrushStop`: the moving ceilings of the line's tag stop.
pub fn ceiling_crush_stop(sim: &mut Sim, line: usize) -> bool {
    let tag = sim.level.lines[line].tag;
    let mut stopped = false;
    for i in 0..MAXCEILINGS {
        let Some(id) = sim.spec.activeceilings[i] else { continue };
        let t = sim.thinker_mut(id);
        if let ThinkerKind::Ceiling(c) = &mut t.kind {
            if c.tag == tag && c.direction != 0 {
                c.olddirection = c.direction;
                c.direction = 0;
                if t.status == Status::Active {
                    t.status = Status::Stasis;
                }
                stopped = true;
            }
        }
    }
    stopped
}
