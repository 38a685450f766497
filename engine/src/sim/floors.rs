//! Floors (`p_floor.c`): the one mover every door, lift, floor and
//! crusher goes through (`T_MovePlane`, which refits the things in the
//! sector after each step and undoes a step that does not fit), the floor
//! thinker `T_MoveFloor`, floors started by tag (`EV_DoFloor`), stairs
//! (`EV_BuildStairs`) and donuts (`EV_DoDonut`).

use super::level::NameId;
use super::specials::{
    find_highest_floor_surrounding, find_lowest_ceiling_surrounding, find_lowest_floor_surrounding,
    find_next_highest_floor, find_next_lowest_floor, find_sector_from_line_tag, next_free_tagged, next_sector,
    texture_height,
};
use super::think::ThinkerKind;
use super::{collision, level::ml, Compat, Sim, ThinkerId};
use crate::fixed::Fixed;
use crate::map::special::{FloorTarget, SpecialChange};

/// A floor's speed a tic (`FLOORSPEED`).
pub const FLOORSPEED: Fixed = Fixed::ONE;

/// What a step of `T_MovePlane` came to (`result_e`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MoveResult {
    Ok,
    Crushed,
    PastDest,
}

/// Which plane moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Plane {
    Floor,
    Ceiling,
}

/// `T_MovePlane`: moves the floor or ceiling of `sector` by `speed`
/// towards `dest` (`direction` 1 up, -1 down), refitting the things in it
/// (`P_ChangeSector`, crushing if `crush` is non-zero). `crush` is Doom's
/// int: the stairs leave it uninitialised (Chocolate's 10), which crushes
/// in `P_ChangeSector` but is not `true` for the "keep going" test here.
/// A step that reaches `dest` is kept even when something no longer fits
/// (the fitting is redone at the old height but `pastdest` returned, as
/// vanilla does); a step short of it that does not fit is undone, except a
/// crushing floor going up or ceiling going down, which stays. A ceiling
/// going up never reports a crush.
pub fn move_plane(
    sim: &mut Sim,
    sector: usize,
    speed: Fixed,
    dest: Fixed,
    crush: i32,
    plane: Plane,
    direction: i32,
) -> MoveResult {
    let crunch = crush != 0;
    let height = |sim: &Sim| match plane {
        Plane::Floor => sim.level.sectors[sector].floorheight,
        Plane::Ceiling => sim.level.sectors[sector].ceilingheight,
    };
    let set = |sim: &mut Sim, h: Fixed| match plane {
        Plane::Floor => sim.level.sectors[sector].floorheight = h,
        Plane::Ceiling => sim.level.sectors[sector].ceilingheight = h,
    };
    if direction != -1 && direction != 1 {
        return MoveResult::Ok;
    }
    let lastpos = height(sim);
    let past = if direction == -1 { lastpos - speed < dest } else { lastpos + speed > dest };
    if past {
        set(sim, dest);
        if collision::change_sector(sim, sector, crunch) {
            set(sim, lastpos);
            collision::change_sector(sim, sector, crunch);
        }
        return MoveResult::PastDest;
    }
    set(sim, if direction == -1 { lastpos - speed } else { lastpos + speed });
    let blocked = collision::change_sector(sim, sector, crunch);
    // A ceiling going up has nothing to run into (vanilla's check is
    // compiled out).
    if !blocked || (plane == Plane::Ceiling && direction == 1) {
        return MoveResult::Ok;
    }
    let may_crush = (plane == Plane::Floor && direction == 1) || (plane == Plane::Ceiling && direction == -1);
    if may_crush && crush == 1 {
        return MoveResult::Crushed;
    }
    set(sim, lastpos);
    collision::change_sector(sim, sector, crunch);
    MoveResult::Crushed
}

/// `floor_e`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum FloorType {
    #[default]
    LowerFloor,
    LowerFloorToLowest,
    TurboLower,
    RaiseFloor,
    RaiseFloorToNearest,
    RaiseToTexture,
    LowerAndChange,
    RaiseFloor24,
    RaiseFloor24AndChange,
    RaiseFloorCrush,
    RaiseFloorTurbo,
    DonutRaise,
    RaiseFloor512,
}

/// `stair_e`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StairType {
    Build8,
    Turbo16,
}

/// What a floor does to its sector when it arrives: vanilla's donut ring
/// and lower-and-change floors take `texture` and `newspecial`; a
/// generalized change may take the flat alone (Boom's `genFloorChg`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Arrival {
    #[default]
    Nothing,
    Flat,
    FlatAndSpecial,
}

/// The thinker's data (`floormove_t`).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FloorMove {
    pub kind: FloorType,
    /// Doom's int (see [`move_plane`]).
    pub crush: i32,
    pub sector: usize,
    pub direction: i32,
    pub newspecial: i16,
    pub texture: NameId,
    pub floordestheight: Fixed,
    pub speed: Fixed,
    /// What changes on arrival (vanilla decides by `kind` and `direction`,
    /// which never change: set where the floor starts).
    pub arrival: Arrival,
}

impl Default for FloorMove {
    fn default() -> FloorMove {
        FloorMove {
            kind: FloorType::LowerFloor,
            crush: 0,
            sector: 0,
            direction: 0,
            newspecial: 0,
            texture: super::level::NO_TEXTURE,
            floordestheight: Fixed::ZERO,
            speed: Fixed::ZERO,
            arrival: Arrival::Nothing,
        }
    }
}

/// Runs the thinker one tic (`T_MoveFloor`): at its destination the
/// sector is freed, a donut's rising ring and a lower-and-change floor
/// take their new flat and special.
pub fn think(sim: &mut Sim, id: ThinkerId) {
    let ThinkerKind::Floor(floor) = sim.thinker(id).kind.clone() else { return };
    let sec = floor.sector;
    let res = move_plane(sim, sec, floor.speed, floor.floordestheight, floor.crush, Plane::Floor, floor.direction);
    if sim.leveltime & 7 == 0 {
        sound(sim, sec, "stnmov");
    }
    if res != MoveResult::PastDest {
        return;
    }
    let s = &mut sim.level.sectors[sec];
    s.specialdata = None;
    if floor.arrival == Arrival::FlatAndSpecial {
        s.special = floor.newspecial;
    }
    if floor.arrival != Arrival::Nothing {
        s.floorpic = floor.texture;
        sim.textures_changed += 1;
    }
    sim.remove_thinker(id);
    sound(sim, sec, "pstop");
}

fn sound(sim: &mut Sim, sector: usize, name: &str) {
    let s = sim.info.sound(name);
    sim.sector_sound(sector, s);
}

/// Starts a floor thinker on `sector` and makes it the sector's mover.
pub fn start(sim: &mut Sim, floor: FloorMove) -> ThinkerId {
    let sector = floor.sector;
    let id = sim.add_thinker(ThinkerKind::Floor(floor));
    sim.level.sectors[sector].specialdata = Some(id);
    id
}

/// `EV_DoFloor`: a floor in each tagged sector without a mover; whether
/// any started.
pub fn do_floor(sim: &mut Sim, line: usize, kind: FloorType) -> bool {
    let mut sec = None;
    let mut started = false;
    while let Some(s) = next_free_tagged(sim, line, sec) {
        sec = Some(s);
        started = true;
        let floor = new_floor(sim, line, s, kind);
        start(sim, floor);
    }
    started
}

/// One floor of `EV_DoFloor`'s kinds, with the sector changes some make
/// at once (the 24-and-change floor takes the line's front flat and
/// special now).
fn new_floor(sim: &mut Sim, line: usize, s: usize, kind: FloorType) -> FloorMove {
    use FloorTarget as T;
    let here = sim.level.sectors[s].floorheight;
    let mut f = FloorMove { kind, sector: s, direction: 1, speed: FLOORSPEED, ..FloorMove::default() };
    match kind {
        FloorType::LowerFloor => {
            f.direction = -1;
            f.floordestheight = floor_target(sim, s, T::HighestNeighbourFloor);
        }
        FloorType::LowerFloorToLowest => {
            f.direction = -1;
            f.floordestheight = floor_target(sim, s, T::LowestNeighbourFloor);
        }
        FloorType::TurboLower => {
            f.direction = -1;
            f.speed = FLOORSPEED * 4;
            f.floordestheight = floor_target(sim, s, T::HighestNeighbourFloor);
            // 1.2 always added the 8; later versions not when level.
            if f.floordestheight != here {
                f.floordestheight += Fixed::from_int(8);
            }
        }
        FloorType::RaiseFloorCrush | FloorType::RaiseFloor => {
            f.crush = i32::from(kind == FloorType::RaiseFloorCrush);
            f.floordestheight = floor_target(sim, s, T::LowestNeighbourCeiling);
            if kind == FloorType::RaiseFloorCrush {
                f.floordestheight -= Fixed::from_int(8);
            }
        }
        FloorType::RaiseFloorTurbo => {
            f.speed = FLOORSPEED * 4;
            f.floordestheight = floor_target(sim, s, T::NextHigherFloor);
        }
        FloorType::RaiseFloorToNearest => f.floordestheight = floor_target(sim, s, T::NextHigherFloor),
        FloorType::RaiseFloor24 => f.floordestheight = here + Fixed::from_int(24),
        FloorType::RaiseFloor512 => f.floordestheight = here + Fixed::from_int(512),
        FloorType::RaiseFloor24AndChange => {
            f.floordestheight = here + Fixed::from_int(24);
            change_from_trigger(sim, line, s, SpecialChange::Copy);
        }
        FloorType::RaiseToTexture => f.floordestheight = floor_target(sim, s, T::ShortestLowerTexture),
        FloorType::LowerAndChange => {
            f.direction = -1;
            f.floordestheight = floor_target(sim, s, T::LowestNeighbourFloor);
            f.texture = sim.level.sectors[s].floorpic;
            f.arrival = Arrival::FlatAndSpecial;
            if let Some((pic, special)) = change_source(sim, s, f.floordestheight) {
                f.texture = pic;
                f.newspecial = special;
            }
        }
        FloorType::DonutRaise => {}
    }
    f
}

/// Where a floor special takes sector `s`'s floor, before any offset:
/// the searches `EV_DoFloor`'s types use (`P_FindHighestFloorSurrounding`
/// with its -500, ...), and Boom's next lower floor.
pub fn floor_target(sim: &Sim, s: usize, to: FloorTarget) -> Fixed {
    let level = &sim.level;
    let (here, ceiling) = (level.sectors[s].floorheight, level.sectors[s].ceilingheight);
    match to {
        FloorTarget::LowestNeighbourFloor => find_lowest_floor_surrounding(level, s),
        FloorTarget::HighestNeighbourFloor => find_highest_floor_surrounding(level, s),
        FloorTarget::NextHigherFloor => find_next_highest_floor(level, s, here),
        FloorTarget::NextLowerFloor => find_next_lowest_floor(level, s, here),
        FloorTarget::Ceiling => ceiling,
        FloorTarget::LowestNeighbourCeiling => find_lowest_ceiling_surrounding(level, s).min(ceiling),
        FloorTarget::ShortestLowerTexture => here + shortest_lower_texture(sim, s),
        FloorTarget::Current => here,
    }
}

/// A floor's change taken at once from the front sector of the line that
/// set it off (Doom's "trigger model": the 24-and-change floor, the
/// raise-and-change plats): its flat, and its special as `special` says.
pub fn change_from_trigger(sim: &mut Sim, line: usize, s: usize, special: SpecialChange) {
    let Some(front) = sim.level.lines[line].frontsector else { return };
    let (pic, model_special) = (sim.level.sectors[front].floorpic, sim.level.sectors[front].special);
    let sector = &mut sim.level.sectors[s];
    sector.floorpic = pic;
    match special {
        SpecialChange::Keep => {}
        SpecialChange::Copy => sector.special = model_special,
        SpecialChange::Clear => sector.special = 0,
    }
    sim.textures_changed += 1;
}

/// Raise-to-texture's height: the shortest lower texture on either side
/// of the sector's two-sided lines (`textureheight`, where a `-` reads
/// texture 0); `INT_MAX` when there is none, as vanilla starts it.
fn shortest_lower_texture(sim: &Sim, s: usize) -> Fixed {
    // Heights not loaded (see `specials::set_texture_heights`): the floor
    // stays, rather than wrapping to INT_MAX above itself.
    if sim.spec.texture_heights.is_empty() {
        return Fixed::ZERO;
    }
    // Sightline's rules, as Boom's: a side with no lower texture does not
    // count, and with none at all the floor stays.
    let boom = sim.rules.compat == Compat::Sightline;
    let mut minsize = Fixed::MAX;
    for &l in &sim.level.sectors[s].lines {
        let line = &sim.level.lines[l];
        if line.flags & ml::TWOSIDED == 0 {
            continue;
        }
        for side in line.sidenum.into_iter().flatten() {
            let texture = sim.level.sides[side].bottomtexture;
            if boom && texture == super::level::NO_TEXTURE {
                continue;
            }
            if let Some(h) = texture_height(sim, texture) {
                minsize = minsize.min(h);
            }
        }
    }
    if boom && minsize == Fixed::MAX {
        return Fixed::ZERO;
    }
    minsize
}

/// Lower-and-change's new flat and special: those of the first sector
/// across a two-sided line whose floor is at the destination.
pub fn change_source(sim: &Sim, s: usize, dest: Fixed) -> Option<(NameId, i16)> {
    let level = &sim.level;
    for &l in &level.sectors[s].lines {
        let line = &level.lines[l];
        if line.flags & ml::TWOSIDED == 0 {
            continue;
        }
        let front_is_here = line.sidenum[0].is_some_and(|side| level.sides[side].sector == s);
        let across = if front_is_here { line.sidenum[1] } else { line.sidenum[0] };
        let Some(other) = across.map(|side| level.sides[side].sector) else { continue };
        if level.sectors[other].floorheight == dest {
            return Some((level.sectors[other].floorpic, level.sectors[other].special));
        }
    }
    None
}

/// Chocolate's value for the crush field stairs leave uninitialised
/// (`STAIRS_UNINITIALIZED_CRUSH_FIELD_VALUE`).
const STAIRS_CRUSH: i32 = 10;

/// `EV_BuildStairs`: from each tagged sector, a step rises by the stair
/// size; then the sector behind its first two-sided line facing out (with
/// the same floor flat) rises one step more, and so on. A step already
/// moving is skipped over but still counts a step's height. The search
/// for the next tagged sector goes on from the last step built, as
/// vanilla's does.
pub fn build_stairs(sim: &mut Sim, line: usize, kind: StairType) -> bool {
    let (speed, stairsize) = match kind {
        StairType::Build8 => (Fixed(FLOORSPEED.0 / 4), Fixed::from_int(8)),
        StairType::Turbo16 => (FLOORSPEED * 4, Fixed::from_int(16)),
    };
    stairs(sim, line, Stairs { speed, stairsize, crush: STAIRS_CRUSH })
}

/// A staircase's parameters: vanilla's two types', or a generalized
/// special's (whose step may be negative: stairs down, as Boom's).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stairs {
    pub speed: Fixed,
    pub stairsize: Fixed,
    /// Doom's int (see [`move_plane`]): vanilla's stairs leave it
    /// uninitialised ([`STAIRS_CRUSH`]).
    pub crush: i32,
}

/// `EV_BuildStairs` with its parameters given.
pub fn stairs(sim: &mut Sim, line: usize, params: Stairs) -> bool {
    let Stairs { speed, stairsize, crush } = params;
    let direction = if stairsize < Fixed::ZERO { -1 } else { 1 };
    let mut secnum = None;
    let mut started = false;
    while let Some(first) = find_sector_from_line_tag(&sim.level, line, secnum) {
        secnum = Some(first);
        if sim.level.sectors[first].specialdata.is_some() {
            continue;
        }
        started = true;
        let mut sec = first;
        let mut height = sim.level.sectors[sec].floorheight + stairsize;
        let step = |sector, height| FloorMove {
            kind: FloorType::LowerFloor,
            crush,
            sector,
            direction,
            speed,
            floordestheight: height,
            ..FloorMove::default()
        };
        start(sim, step(sec, height));
        let texture = sim.level.sectors[sec].floorpic;
        while let Some(next) = next_step(sim, sec, texture, stairsize, &mut height) {
            sec = next;
            secnum = Some(next);
            start(sim, step(sec, height));
        }
    }
    started
}

/// The next stair step from `sec`: across the first two-sided line whose
/// front is `sec` and whose back has the stairs' flat and no mover;
/// `height` grows by a step for every candidate with the flat, moving or
/// not.
fn next_step(sim: &Sim, sec: usize, texture: NameId, stairsize: Fixed, height: &mut Fixed) -> Option<usize> {
    let level = &sim.level;
    for &l in &level.sectors[sec].lines {
        let line = &level.lines[l];
        if line.flags & ml::TWOSIDED == 0 || line.frontsector != Some(sec) {
            continue;
        }
        let Some(back) = line.backsector else { continue };
        if level.sectors[back].floorpic != texture {
            continue;
        }
        *height += stairsize;
        if level.sectors[back].specialdata.is_some() {
            continue;
        }
        return Some(back);
    }
    None
}

/// `EV_DoDonut`: each tagged sector (the hole) sinks to, and the ring
/// around it rises to, the floor of the sector beyond the ring (found on
/// the ring's lines); both at half floor speed. A ring line with no back
/// sector makes vanilla read address 0: Chocolate's emulation (its
/// Windows 98 default) gives height 0 and flat 22, kept under
/// `Compat::Vanilla` (flat numbers are not our names, so the ring keeps
/// its flat); with the fixes on, the line is passed over.
pub fn do_donut(sim: &mut Sim, line: usize) -> bool {
    let mut secnum = None;
    let mut started = false;
    while let Some(s1) = find_sector_from_line_tag(&sim.level, line, secnum) {
        secnum = Some(s1);
        if sim.level.sectors[s1].specialdata.is_some() {
            continue;
        }
        started = true;
        if !donut(sim, s1, Fixed(FLOORSPEED.0 / 2)) {
            break;
        }
    }
    started
}

/// One donut of `EV_DoDonut` around the hole `s1` (which has no mover),
/// both floors at `speed`; `false` where Chocolate stops the search (the
/// hole's first line is one-sided).
pub fn donut(sim: &mut Sim, s1: usize, speed: Fixed) -> bool {
    let Some(&first_line) = sim.level.sectors[s1].lines.first() else { return true };
    // Chocolate stops here where vanilla reads invalid memory.
    let Some(s2) = next_sector(&sim.level, first_line, s1) else { return false };
    for i in 0..sim.level.sectors[s2].lines.len() {
        let l = sim.level.sectors[s2].lines[i];
        let s3 = sim.level.lines[l].backsector;
        if s3 == Some(s1) {
            continue;
        }
        let (height, pic) = match s3 {
            Some(s3) => (sim.level.sectors[s3].floorheight, sim.level.sectors[s3].floorpic),
            None if sim.rules.compat == Compat::Vanilla => (Fixed::ZERO, sim.level.sectors[s2].floorpic),
            None => continue,
        };
        start(
            sim,
            FloorMove {
                kind: FloorType::DonutRaise,
                sector: s2,
                direction: 1,
                speed,
                texture: pic,
                newspecial: 0,
                floordestheight: height,
                arrival: Arrival::FlatAndSpecial,
                ..FloorMove::default()
            },
        );
        start(
            sim,
            FloorMove {
                kind: FloorType::LowerFloor,
                sector: s1,
                direction: -1,
                speed,
                floordestheight: height,
                ..FloorMove::default()
            },
        );
        break;
    }
    true
}
