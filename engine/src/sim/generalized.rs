//! Sightline's generalized specials on the simulation: the typed specials
//! of a RON map (`map::special`) that no vanilla number says (a door with
//! its own speed or wait, a trigger and a "who" Doom never paired, a
//! floor to any target, line teleports, sector effects Doom's seventeen
//! types cannot combine, wall scrolls and conveyors) run here through the
//! same movers vanilla's numbers drive, with their parameters: a door is
//! `doors::start_door` with a [`DoorParams`], a lift `plats::start_plat`
//! with a [`PlatParams`], and so on. `from_map` hands them over; the
//! crossing, use and shot code (`specials.rs`, `switches.rs`) hands a
//! line whose special is one of these to [`cross`], [`use_line`] and
//! [`shoot`].
//!
//! How they are stored is Boom's idea: Boom kept its generalized linedefs
//! in the line's own `special` field, as numbers from 0x2F80 up whose
//! bits say the trigger, speed and target. Sightline's parameters are
//! free (any speed, any wait), so bits cannot hold them: a generalized
//! special is a *negative* number, which no Doom or Boom map uses
//! (`special` is a C `short`), naming an entry of the level's table
//! ([`Generalized`]). So everything that asks "has this line a special?"
//! (`special != 0`: the crossing list, the use trace, the shot trace) sees
//! them without being told, a once-only line is spent as Doom spends one
//! (its special set to 0), and a saved game keeps them in the field it
//! already saves. Sectors' generalized specials are numbered likewise,
//! and a floor that copies a sector's special copies them too.
//!
//! Rules where vanilla has none (all under Sightline's rules, since only a
//! RON map has these): a once-only special is spent only when it did
//! something (Boom's rule for its generalized lines; vanilla spends a W1
//! line whatever it did); a special with tag 0 acts on the sector behind
//! its line (Boom's manual specials), never on every untagged sector;
//! monsters set one off only where it says `Anyone` or `Monsters`, never
//! with a missile, never through a key, never a secret line by use.

use serde::{Deserialize, Serialize};

use super::ceilings::{self, activate_in_stasis_ceiling, ceiling_crush_stop, start_ceiling};
use super::doors::{self, card_of, DoorParams, ManualDoor};
use super::floors::{self, Arrival, FloorMove, FloorType, Stairs};
use super::level::ml;
use super::plats::{self, PlatParams, PlatType};
use super::specials::{
    exit_level, find_highest_ceiling_surrounding, find_lowest_ceiling_surrounding, find_min_surrounding_light,
    neighbours, FloorDamage,
};
use super::{lights, mobj::mf, switches, teleport, MobjId, Sim};
use crate::fixed::Fixed;
use crate::map::special::{
    Action, Activation, CeilingTarget, Change, ChangeFrom, DoorKind, DoorTimer, FloorTarget, KeyColour, LightChange,
    LightEffect, SectorSpecial, SpecialChange, Who,
};
use crate::map::LineSpecial;

/// A line's generalized special: its trigger and action. Its tag is the
/// line's own `tag`, which `from_map` sets from the special.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct GenLine {
    pub on: Activation,
    pub repeat: bool,
    pub by: Who,
    pub action: GenAction,
}

/// What a generalized special does: `map::special::Action` in Doom's
/// units (16.16 speeds and heights, tics).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum GenAction {
    Door { kind: DoorKind, speed: Fixed, wait: i32, shut: i32, key: Option<KeyColour> },
    Lift { speed: Fixed, wait: i32 },
    PerpetualLift { speed: Fixed, wait: i32 },
    StopLift,
    Floor { to: FloorTarget, offset: Fixed, speed: Fixed, crush: bool, change: Option<Change> },
    Ceiling { to: CeilingTarget, offset: Fixed, speed: Fixed, crush: bool },
    Crusher { speed: Fixed, silent: bool },
    StopCrusher,
    Stairs { step: Fixed, speed: Fixed, crush: bool },
    Donut { speed: Fixed },
    Light(LightChange),
    Teleport,
    LineTeleport { to: usize },
    Exit,
    SecretExit,
}

impl GenAction {
    /// `action` in Doom's units; `fixed` converts a speed or a height.
    pub fn of(action: &Action, mut fixed: impl FnMut(f64) -> Fixed) -> GenAction {
        let tics = |t: u32| t.min(i32::MAX as u32) as i32;
        match *action {
            Action::Door { kind, speed, wait, shut, key } => {
                GenAction::Door { kind, speed: fixed(speed), wait: tics(wait), shut: tics(shut), key }
            }
            Action::Lift { speed, wait } => GenAction::Lift { speed: fixed(speed), wait: tics(wait) },
            Action::PerpetualLift { speed, wait } => GenAction::PerpetualLift { speed: fixed(speed), wait: tics(wait) },
            Action::StopLift => GenAction::StopLift,
            Action::Floor { to, offset, speed, crush, change } => {
                GenAction::Floor { to, offset: fixed(offset), speed: fixed(speed), crush, change }
            }
            Action::Ceiling { to, offset, speed, crush } => {
                GenAction::Ceiling { to, offset: fixed(offset), speed: fixed(speed), crush }
            }
            Action::Crusher { speed, silent } => GenAction::Crusher { speed: fixed(speed), silent },
            Action::StopCrusher => GenAction::StopCrusher,
            Action::Stairs { step, speed, crush } => {
                GenAction::Stairs { step: fixed(step), speed: fixed(speed), crush }
            }
            Action::Donut { speed } => GenAction::Donut { speed: fixed(speed) },
            Action::Light(change) => GenAction::Light(change),
            Action::Teleport => GenAction::Teleport,
            Action::LineTeleport { to } => GenAction::LineTeleport { to },
            Action::Exit => GenAction::Exit,
            Action::SecretExit => GenAction::SecretExit,
        }
    }

    /// Does it act on sectors (by tag, or the sector behind the line)?
    fn moves_sectors(&self) -> bool {
        !matches!(self, GenAction::Exit | GenAction::SecretExit | GenAction::Teleport | GenAction::LineTeleport { .. })
    }
}

impl GenLine {
    pub fn of(special: &LineSpecial, fixed: impl FnMut(f64) -> Fixed) -> GenLine {
        GenLine {
            on: special.on,
            repeat: special.repeat,
            by: special.by,
            action: GenAction::of(&special.action, fixed),
        }
    }
}

/// A side that scrolls by (`dx`, `dy`) a tic (Boom's 250-series scrollers;
/// vanilla's 48 is `(1, 0)` on a front side).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SideScroll {
    pub side: usize,
    pub dx: Fixed,
    pub dy: Fixed,
}

/// A floor that pushes what stands on it by (`dx`, `dy`) of momentum a tic
/// (Boom's 252 conveyors).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Carry {
    pub sector: usize,
    pub dx: Fixed,
    pub dy: Fixed,
}

/// The level's generalized specials: what the negative line and sector
/// specials name, and the effects that are not set off. Static: play
/// changes which number a line or sector holds, never the table.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Generalized {
    pub lines: Vec<GenLine>,
    pub sectors: Vec<SectorSpecial>,
    pub scrolls: Vec<SideScroll>,
    pub carries: Vec<Carry>,
}

/// The entries a table can hold: the negative `short`s.
const MAX_ENTRIES: usize = 32768;

/// The table entry a negative special names.
fn entry(special: i16) -> Option<usize> {
    (special < 0).then(|| (-1 - i32::from(special)) as usize)
}

/// The special number of table entry `k`.
fn number(k: usize) -> i16 {
    (-1 - k as i32) as i16
}

impl Generalized {
    /// The generalized line special `special` names, if it names one.
    pub fn line(&self, special: i16) -> Option<&GenLine> {
        self.lines.get(entry(special)?)
    }

    /// The generalized sector special `special` names, if it names one.
    pub fn sector(&self, special: i16) -> Option<&SectorSpecial> {
        self.sectors.get(entry(special)?)
    }

    /// The number for `line`, the same entry for equal specials; `None`
    /// when the table is full.
    pub fn line_number(&mut self, line: GenLine) -> Option<i16> {
        intern(&mut self.lines, line)
    }

    /// The number for sector special `s` (0 for none). Its remainders after
    /// the level starts (the light and door timer spawned) and after its
    /// secret is found are entered too, so play never adds one.
    pub fn sector_number(&mut self, s: SectorSpecial) -> Option<i16> {
        if s.is_none() {
            return Some(0);
        }
        let running = SectorSpecial { light: None, timer: None, ..s };
        if !running.is_none() {
            intern(&mut self.sectors, running)?;
            let found = SectorSpecial { secret: false, ..running };
            if !found.is_none() {
                intern(&mut self.sectors, found)?;
            }
        }
        intern(&mut self.sectors, s)
    }

    /// The number of sector special `s` if the table has it (0 for none).
    fn sector_number_of(&self, s: SectorSpecial) -> i16 {
        if s.is_none() {
            return 0;
        }
        self.sectors.iter().position(|&e| e == s).map_or(0, number)
    }
}

fn intern<T: PartialEq>(table: &mut Vec<T>, value: T) -> Option<i16> {
    if let Some(k) = table.iter().position(|e| *e == value) {
        return Some(number(k));
    }
    if table.len() >= MAX_ENTRIES {
        return None;
    }
    table.push(value);
    Some(number(table.len() - 1))
}

/// The generalized special of `line`, if it has one.
fn special_of(sim: &Sim, line: usize) -> Option<GenLine> {
    let special = sim.level.lines.get(line)?.special;
    sim.level.generalized.line(special).cloned()
}

/// Whether `thing` may set off `g` on `line` by `on`.
fn may(sim: &Sim, thing: MobjId, line: usize, g: &GenLine, on: Activation) -> bool {
    if g.on != on {
        return false;
    }
    let mo = sim.mo(thing);
    if mo.player.is_some() {
        return g.by.players();
    }
    let locked = matches!(g.action, GenAction::Door { key: Some(_), .. });
    let secret = on == Activation::Use && sim.level.lines[line].flags & ml::SECRET != 0;
    g.by.monsters() && !mo.has(mf::MISSILE) && !locked && !secret
}

/// `P_CrossSpecialLine` for a generalized special: whether `line` has one
/// (then the caller is done with it).
pub fn cross(sim: &mut Sim, line: usize, side: usize, thing: MobjId) -> bool {
    let Some(g) = special_of(sim, line) else { return false };
    if may(sim, thing, line, &g, Activation::Walk) && perform(sim, line, side, thing, &g) && !g.repeat {
        sim.level.lines[line].special = 0;
    }
    true
}

/// `P_UseSpecialLine` for a generalized special (used from the front):
/// `None` when `line` has none; else whether the use was taken (any line
/// the user may use) and whether it started something. A switch that
/// started something flips (a once-only one is spent by the flip); a
/// door used on its own line has no switch.
pub fn use_line(sim: &mut Sim, line: usize, thing: MobjId) -> Option<(bool, bool)> {
    let g = special_of(sim, line)?;
    if !may(sim, thing, line, &g, Activation::Use) {
        return Some((false, false));
    }
    let started = perform(sim, line, 0, thing, &g);
    let manual_door = matches!(g.action, GenAction::Door { .. }) && sim.level.lines[line].tag == 0;
    if started && manual_door && !g.repeat {
        sim.level.lines[line].special = 0;
    } else if started && !manual_door {
        switches::change_switch_texture(sim, line, g.repeat);
    }
    Some((true, started))
}

/// `P_ShootSpecialLine` for a generalized special: whether `line` has one.
pub fn shoot(sim: &mut Sim, thing: MobjId, line: usize) -> bool {
    let Some(g) = special_of(sim, line) else { return false };
    if may(sim, thing, line, &g, Activation::Shoot) && perform(sim, line, 0, thing, &g) {
        switches::change_switch_texture(sim, line, g.repeat);
    }
    true
}

/// The sectors a special on `line` acts on: those with its tag, in order,
/// or with tag 0 the sector behind the line.
fn targets(sim: &Sim, line: usize) -> Vec<usize> {
    let l = &sim.level.lines[line];
    if l.tag == 0 {
        return l.backsector.into_iter().collect();
    }
    (0..sim.level.sectors.len()).filter(|&s| sim.level.sectors[s].tag == l.tag).collect()
}

/// The targets that have no mover, each read when its turn comes (a
/// mover started on one is seen by the next, as `EV_DoFloor`'s loop sees it).
fn each_free(sim: &mut Sim, line: usize, mut start: impl FnMut(&mut Sim, usize)) -> bool {
    let mut started = false;
    for s in targets(sim, line) {
        if sim.level.sectors[s].specialdata.is_none() {
            start(sim, s);
            started = true;
        }
    }
    started
}

/// Carries out `g` set off on `line` from `side` by `thing`; whether it
/// started (or changed) anything.
fn perform(sim: &mut Sim, line: usize, side: usize, thing: MobjId, g: &GenLine) -> bool {
    let tag = sim.level.lines[line].tag;
    if tag == 0 && g.action.moves_sectors() && sim.level.lines[line].backsector.is_none() {
        return false;
    }
    match g.action {
        GenAction::Door { kind, speed, wait, shut, key } => {
            let params = DoorParams::generalized(kind, speed, wait, shut);
            let key = key.map(card_of);
            if tag == 0 {
                doors::manual_door(sim, line, thing, ManualDoor { params, key, once: false })
            } else if key.is_some() {
                doors::locked_doors(sim, line, params, key, thing)
            } else {
                each_free(sim, line, |sim, s| doors::start_door(sim, s, params))
            }
        }
        GenAction::Lift { speed, wait } => {
            let params = PlatParams { kind: PlatType::DownWaitUpStay, speed, wait, amount: 0 };
            each_free(sim, line, |sim, s| plats::start_plat(sim, line, s, params))
        }
        GenAction::PerpetualLift { speed, wait } => {
            plats::activate_in_stasis(sim, tag);
            let params = PlatParams { kind: PlatType::PerpetualRaise, speed, wait, amount: 0 };
            each_free(sim, line, |sim, s| plats::start_plat(sim, line, s, params))
        }
        GenAction::StopLift => {
            plats::stop_plat(sim, line);
            true
        }
        GenAction::Floor { to, offset, speed, crush, change } => {
            each_free(sim, line, |sim, s| start_floor(sim, line, s, (to, offset, speed, crush), change))
        }
        GenAction::Ceiling { to, offset, speed, crush } => each_free(sim, line, |sim, s| {
            let dest = ceiling_target(sim, s, to) + offset;
            let c = ceilings::gen_ceiling(sim, s, dest, speed, crush);
            start_ceiling(sim, c);
        }),
        GenAction::Crusher { speed, silent } => {
            activate_in_stasis_ceiling(sim, line);
            each_free(sim, line, |sim, s| {
                let c = ceilings::gen_crusher(sim, s, speed, silent);
                start_ceiling(sim, c);
            })
        }
        GenAction::StopCrusher => ceiling_crush_stop(sim, line),
        // With tag 0 vanilla's search would build from every untagged sector.
        GenAction::Stairs { step, speed, crush } if tag != 0 => {
            floors::stairs(sim, line, Stairs { speed, stairsize: step, crush: i32::from(crush) })
        }
        GenAction::Stairs { .. } => false,
        GenAction::Donut { speed } => {
            let mut started = false;
            for s in targets(sim, line) {
                if sim.level.sectors[s].specialdata.is_none() {
                    started = true;
                    if !floors::donut(sim, s, speed) {
                        break;
                    }
                }
            }
            started
        }
        GenAction::Light(change) => {
            for s in targets(sim, line) {
                change_light(sim, s, change);
            }
            true
        }
        GenAction::Teleport => teleport::teleport(sim, line, side, thing),
        GenAction::LineTeleport { to } => teleport::line_teleport(sim, line, to, side, thing),
        GenAction::Exit | GenAction::SecretExit => {
            exit_level(sim, g.action == GenAction::SecretExit);
            true
        }
    }
}

/// A generalized floor on sector `s` (which has no mover): to its target
/// plus the offset (which, as for vanilla's turbo lower, is not added to
/// a highest-neighbour target that is the floor's own height), up or down
/// as that lies, with its change of flat (and special) now from the
/// trigger's front sector or on arrival from the neighbour at the
/// destination.
fn start_floor(
    sim: &mut Sim,
    line: usize,
    s: usize,
    (to, offset, speed, crush): (FloorTarget, Fixed, Fixed, bool),
    change: Option<Change>,
) {
    let here = sim.level.sectors[s].floorheight;
    let lonely = neighbours(&sim.level, s).next().is_none();
    let dest = match to {
        // Doom's -500 is for vanilla's numbers; a lone sector stays.
        FloorTarget::HighestNeighbourFloor if lonely => here,
        FloorTarget::HighestNeighbourFloor => {
            let h = floors::floor_target(sim, s, to);
            if h == here {
                h
            } else {
                h + offset
            }
        }
        _ => floors::floor_target(sim, s, to) + offset,
    };
    let up = dest > here;
    let mut f = FloorMove {
        kind: if up { FloorType::RaiseFloor } else { FloorType::LowerFloor },
        crush: i32::from(crush),
        sector: s,
        direction: if up { 1 } else { -1 },
        speed,
        floordestheight: dest,
        texture: sim.level.sectors[s].floorpic,
        newspecial: sim.level.sectors[s].special,
        ..FloorMove::default()
    };
    match change {
        Some(Change { from: ChangeFrom::Trigger, special }) => floors::change_from_trigger(sim, line, s, special),
        Some(Change { from: ChangeFrom::Neighbour, special }) => {
            if let Some((pic, model)) = floors::change_source(sim, s, dest) {
                f.texture = pic;
                (f.arrival, f.newspecial) = match special {
                    SpecialChange::Keep => (Arrival::Flat, f.newspecial),
                    SpecialChange::Copy => (Arrival::FlatAndSpecial, model),
                    SpecialChange::Clear => (Arrival::FlatAndSpecial, 0),
                };
            }
        }
        None => {}
    }
    floors::start(sim, f);
}

/// Where a generalized ceiling goes, before its offset; a sector with no
/// neighbour keeps its own ceiling (vanilla's searches give 0 and
/// `INT_MAX` there).
fn ceiling_target(sim: &Sim, s: usize, to: CeilingTarget) -> Fixed {
    let level = &sim.level;
    let own = level.sectors[s].ceilingheight;
    let lonely = neighbours(level, s).next().is_none();
    match to {
        CeilingTarget::Floor => level.sectors[s].floorheight,
        CeilingTarget::Current => own,
        _ if lonely => own,
        CeilingTarget::HighestNeighbourCeiling => find_highest_ceiling_surrounding(level, s),
        CeilingTarget::LowestNeighbourCeiling => find_lowest_ceiling_surrounding(level, s),
    }
}

/// A light special on sector `s`. The brightest neighbour is each
/// sector's own (Boom's fix: vanilla's `EV_LightTurnOn` reuses the first
/// sector's for the rest); the strobe starts only on a sector with no
/// mover, as `EV_StartLightStrobing`.
fn change_light(sim: &mut Sim, s: usize, change: LightChange) {
    let level = &sim.level;
    let own = level.sectors[s].lightlevel;
    let new = match change {
        LightChange::Set(v) => i16::from(v),
        LightChange::BrightestNeighbour => neighbours(level, s).map(|o| level.sectors[o].lightlevel).fold(0, i16::max),
        LightChange::DimmestNeighbour => find_min_surrounding_light(level, s, own),
        LightChange::Strobe => {
            if level.sectors[s].specialdata.is_none() {
                lights::spawn_strobe_flash(sim, s, lights::SLOWDARK, false);
            }
            return;
        }
    };
    sim.level.sectors[s].lightlevel = new;
}

/// `P_SpawnSpecials` for a generalized sector special: its light effect
/// and door timer start (each clears the sector's special, as vanilla's
/// do), its secret is counted, and the sector keeps what acts on the
/// player (damage, the secret) as its special.
pub fn spawn_sector(sim: &mut Sim, s: usize) -> bool {
    let Some(&special) = sim.level.generalized.sector(sim.level.sectors[s].special) else { return false };
    match special.light {
        Some(LightEffect::BlinkRandom) => lights::spawn_light_flash(sim, s),
        Some(LightEffect::StrobeFast) => lights::spawn_strobe_flash(sim, s, lights::FASTDARK, false),
        Some(LightEffect::StrobeSlow) => lights::spawn_strobe_flash(sim, s, lights::SLOWDARK, false),
        Some(LightEffect::StrobeFastSync) => lights::spawn_strobe_flash(sim, s, lights::FASTDARK, true),
        Some(LightEffect::StrobeSlowSync) => lights::spawn_strobe_flash(sim, s, lights::SLOWDARK, true),
        Some(LightEffect::Glow) => lights::spawn_glowing_light(sim, s),
        Some(LightEffect::Flicker) => lights::spawn_fire_flicker(sim, s),
        None => {}
    }
    match special.timer {
        Some(DoorTimer::CloseIn30s) => doors::spawn_door_close_in_30(sim, s),
        Some(DoorTimer::RaiseIn5Min) => doors::spawn_door_raise_in_5_mins(sim, s),
        None => {}
    }
    if special.secret {
        sim.total_secrets += 1;
    }
    let running = SectorSpecial { light: None, timer: None, ..special };
    sim.level.sectors[s].special = sim.level.generalized.sector_number_of(running);
    true
}

/// `P_PlayerInSpecialSector` for a generalized sector special (player
/// `player`, body `mo`, on the floor of `sector`): its damage by the same
/// rule as vanilla's floors, its secret found once.
pub fn player_in_sector(sim: &mut Sim, player: usize, mo: MobjId, sector: usize, ironfeet: bool) -> bool {
    let Some(&special) = sim.level.generalized.sector(sim.level.sectors[sector].special) else { return false };
    if let Some(d) = special.damage {
        let damage = FloorDamage {
            amount: d.amount.min(i32::MAX as u32) as i32,
            every: d.every,
            suit: d.suit,
            exit_below: d.exit_below.min(i32::MAX as u32) as i32,
        };
        super::specials::floor_damage(sim, player, mo, ironfeet, damage);
    }
    if special.secret {
        super::specials::found_secret(sim, player);
        let rest = SectorSpecial { secret: false, ..special };
        sim.level.sectors[sector].special = sim.level.generalized.sector_number_of(rest);
    }
    true
}

/// The per-tic effects (after the thinkers, where Boom's scroller
/// thinkers run): scrolling sides move, and conveyors push every body on
/// their floor whose centre is over them (Doom's test for a sector's
/// specials; Boom pushes what touches the sector) and that neither floats
/// nor passes through walls.
pub fn update(sim: &mut Sim) {
    for k in 0..sim.level.generalized.scrolls.len() {
        let SideScroll { side, dx, dy } = sim.level.generalized.scrolls[k];
        if let Some(s) = sim.level.sides.get_mut(side) {
            s.textureoffset += dx;
            s.rowoffset += dy;
        }
    }
    for k in 0..sim.level.generalized.carries.len() {
        let Carry { sector, dx, dy } = sim.level.generalized.carries[k];
        let Some(sec) = sim.level.sectors.get(sector) else { continue };
        let (floor, b) = (sec.floorheight, sec.blockbox);
        let width = sim.level.blockmap.width.max(0) as usize;
        let mut bodies = Vec::new();
        for y in b[super::level::BOXBOTTOM]..=b[super::level::BOXTOP] {
            for x in b[super::level::BOXLEFT]..=b[super::level::BOXRIGHT] {
                if let Some(cell) = sim.blocklinks.get(y as usize * width + x as usize) {
                    bodies.extend_from_slice(cell);
                }
            }
        }
        for id in bodies {
            let m = sim.mo(id);
            let on = m.z <= floor && !m.has(mf::NOCLIP) && !m.has(mf::NOGRAVITY);
            if on && sim.sector_of(id) == sector {
                let m = sim.mo_mut(id);
                m.momx += dx;
                m.momy += dy;
            }
        }
    }
}

#[cfg(test)]
#[path = "generalized_tests.rs"]
mod tests;
