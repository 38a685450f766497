//! Line and sector specials (`p_spec.c`): what crossing or shooting a line
//! does, damaging and secret sectors, the sector specials' thinkers started
//! with the level, the per-tic updates (scrolling walls, switch returns),
//! altdeath's item respawns, and the sector searches the movers share (the
//! lowest floor around a sector, the next higher, ...). Using a line is
//! `switches.rs`; the movers themselves are `doors.rs` .. `teleport.rs`;
//! a RON map's specials that no vanilla number says (negative numbers)
//! are handed to `generalized.rs`, which starts the same movers.

use super::ceilings::{self, CeilingType};
use super::doors::{self, DoorType};
use super::floors::{self, FloorType, StairType};
use super::level::{ml, Level, NameId};
use super::plats::{self, PlatType};
use super::{generalized, interaction, lights, teleport, MobjId, Sim, SimEvent, ThinkerId};
use crate::fixed::{Angle, Fixed, ANG45};
use crate::map::special::{Suit, SUIT_LEAK};

/// Plats that can be stopped and restarted at once (`MAXPLATS`).
pub const MAXPLATS: usize = 30;
/// Crushers likewise (`MAXCEILINGS`).
pub const MAXCEILINGS: usize = 30;
/// Switches that can be waiting to pop back at once (`MAXBUTTONS`).
pub const MAXBUTTONS: usize = 16;
/// Tics a pressed button stays pressed (`BUTTONTIME`).
pub const BUTTONTIME: i32 = 35;
/// Scrolling walls vanilla holds (`MAXLINEANIMS`; more is a fatal error
/// there, here the extra lines simply do not scroll).
pub const MAXLINEANIMS: usize = 64;

/// The power and card numbers the specials read (`powertype_t`, `card_t`).
pub const PW_IRONFEET: usize = 3;
/// `CF_GODMODE`.
pub const CF_GODMODE: i32 = 2;

/// Which texture of a switch's front side changed (`bwhere_e`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum ButtonWhere {
    #[default]
    Top,
    Middle,
    Bottom,
}

/// A pressed button waiting to pop back (`button_t`); free when `timer`
/// is 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Button {
    pub line: usize,
    pub place: ButtonWhere,
    pub texture: NameId,
    pub timer: i32,
    /// The sector whose sound origin plays the return click (the line's
    /// front sector).
    pub sector: usize,
}

impl Default for Button {
    fn default() -> Button {
        Button { line: 0, place: ButtonWhere::Top, texture: super::level::NO_TEXTURE, timer: 0, sector: 0 }
    }
}

/// `p_spec.c`'s globals: active plats and ceilings (the thinkers of each,
/// as Doom's fixed arrays with their empty slots), pressed buttons and the
/// scrolling lines.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SpecialState {
    pub activeplats: [Option<ThinkerId>; MAXPLATS],
    pub activeceilings: [Option<ThinkerId>; MAXCEILINGS],
    pub buttons: [Button; MAXBUTTONS],
    /// Lines with special 48, scrolled one unit a tic (`linespeciallist`).
    pub scrollers: Vec<usize>,
    /// Texture heights by name, for raise-to-texture floors
    /// (`textureheight`); see [`set_texture_heights`].
    pub texture_heights: Vec<(String, Fixed)>,
    /// The height of texture 0, which a side's `-` reads in Doom.
    pub texture0_height: Fixed,
}

/// Fills the texture heights that `EV_DoFloor`'s raise-to-texture reads,
/// from the WAD's TEXTURE1/TEXTURE2 (the first texture of TEXTURE1 is
/// texture 0, which a side with no lower texture reads). `Sim::new` has
/// the WAD and should call this before `spawn_specials`; until then such
/// floors do not move. A name that repeats keeps its first height.
pub fn set_texture_heights(sim: &mut Sim, wad: &crate::wad::Wad) {
    let mut heights = Vec::new();
    for lump in ["TEXTURE1", "TEXTURE2"] {
        let Some(index) = wad.find(lump) else { continue };
        heights.extend(texture_lump_heights(wad.bytes(index)));
    }
    sim.spec.texture0_height = heights.first().map_or(Fixed::ZERO, |h: &(String, Fixed)| h.1);
    sim.spec.texture_heights = heights;
}

/// Each texture's name and height in a TEXTURE lump (`maptexture_t`: name
/// at 0, height at 14), in the lump's order; a malformed entry is skipped.
pub(crate) fn texture_lump_heights(bytes: &[u8]) -> Vec<(String, Fixed)> {
    let word = |at: usize| bytes.get(at..at + 4).map(|b| i32::from_le_bytes([b[0], b[1], b[2], b[3]]));
    let count = word(0).unwrap_or(0).max(0) as usize;
    (0..count)
        .filter_map(|i| {
            let at = usize::try_from(word(4 + 4 * i)?).ok()?;
            let entry = bytes.get(at..at + 16)?;
            let name = crate::wad::lump_name(&entry[..8]);
            let height = i16::from_le_bytes([entry[14], entry[15]]);
            Some((name.to_ascii_uppercase(), Fixed::from_int(height.into())))
        })
        .collect()
}

/// `textureheight[]` of a side texture (texture 0 for `-`).
pub fn texture_height(sim: &Sim, id: NameId) -> Option<Fixed> {
    if id == super::level::NO_TEXTURE {
        return Some(sim.spec.texture0_height);
    }
    let name = sim.level.name(id);
    sim.spec.texture_heights.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map(|h| h.1)
}

/// `getNextSector`: the sector across `line` from `sec`, if the line is
/// two-sided (Doom's test is the flag, not the back side).
pub fn next_sector(level: &Level, line: usize, sec: usize) -> Option<usize> {
    let l = &level.lines[line];
    if l.flags & ml::TWOSIDED == 0 {
        return None;
    }
    if l.frontsector == Some(sec) {
        l.backsector
    } else {
        l.frontsector
    }
}

/// The neighbours of `sec`, one per line in Doom's order (a sector met by
/// two lines is met twice, as Doom's loops meet it).
pub fn neighbours(level: &Level, sec: usize) -> impl Iterator<Item = usize> + '_ {
    level.sectors[sec].lines.iter().filter_map(move |&l| next_sector(level, l, sec))
}

/// `P_FindLowestFloorSurrounding` (the sector's own floor if none lower).
pub fn find_lowest_floor_surrounding(level: &Level, sec: usize) -> Fixed {
    neighbours(level, sec).map(|o| level.sectors[o].floorheight).fold(level.sectors[sec].floorheight, Fixed::min)
}

/// `P_FindHighestFloorSurrounding` (-500 if no neighbour is higher).
pub fn find_highest_floor_surrounding(level: &Level, sec: usize) -> Fixed {
    neighbours(level, sec).map(|o| level.sectors[o].floorheight).fold(Fixed::from_int(-500), Fixed::max)
}

/// Neighbours vanilla's `P_FindNextHighestFloor` has room for
/// (`MAX_ADJOINING_SECTORS`).
const MAX_ADJOINING_SECTORS: usize = 20;

/// `P_FindNextHighestFloor`: the lowest neighbouring floor above
/// `current`, or `current`. Vanilla keeps the candidates in a 20-entry
/// stack array; Chocolate (after PrBoom+) emulates the 21st overwriting
/// `height`, so later candidates must clear that one; a 22nd crashes
/// vanilla, and is simply counted here.
pub fn find_next_highest_floor(level: &Level, sec: usize, current: Fixed) -> Fixed {
    let mut height = current;
    let mut list: Vec<Fixed> = Vec::new();
    for o in neighbours(level, sec) {
        let floor = level.sectors[o].floorheight;
        if floor > height {
            if list.len() == MAX_ADJOINING_SECTORS + 1 {
                height = floor;
            }
            list.push(floor);
        }
    }
    list.into_iter().min().unwrap_or(current)
}

/// Boom's `P_FindNextLowestFloor`: the highest neighbouring floor below
/// `current`, or `current`.
pub fn find_next_lowest_floor(level: &Level, sec: usize, current: Fixed) -> Fixed {
    neighbours(level, sec).map(|o| level.sectors[o].floorheight).filter(|&f| f < current).max().unwrap_or(current)
}

/// `P_FindLowestCeilingSurrounding` (`INT_MAX` with no neighbour).
pub fn find_lowest_ceiling_surrounding(level: &Level, sec: usize) -> Fixed {
    neighbours(level, sec).map(|o| level.sectors[o].ceilingheight).fold(Fixed::MAX, Fixed::min)
}

/// `P_FindHighestCeilingSurrounding` (0 with no neighbour higher).
pub fn find_highest_ceiling_surrounding(level: &Level, sec: usize) -> Fixed {
    neighbours(level, sec).map(|o| level.sectors[o].ceilingheight).fold(Fixed::ZERO, Fixed::max)
}

/// `P_FindSectorFromLineTag`: the next sector after `after` (from the
/// first with `None`) whose tag is the line's.
pub fn find_sector_from_line_tag(level: &Level, line: usize, after: Option<usize>) -> Option<usize> {
    let tag = level.lines[line].tag;
    let start = after.map_or(0, |s| s + 1);
    (start..level.sectors.len()).find(|&s| level.sectors[s].tag == tag)
}

/// The tagged sectors of `line` that have no mover yet, in order, read
/// one at a time so a mover started for one is seen by the next search.
pub fn next_free_tagged(sim: &Sim, line: usize, after: Option<usize>) -> Option<usize> {
    let mut at = after;
    while let Some(s) = find_sector_from_line_tag(&sim.level, line, at) {
        if sim.level.sectors[s].specialdata.is_none() {
            return Some(s);
        }
        at = Some(s);
    }
    None
}

/// `P_FindMinSurroundingLight`.
pub fn find_min_surrounding_light(level: &Level, sec: usize, max: i16) -> i16 {
    neighbours(level, sec).map(|o| level.sectors[o].lightlevel).fold(max, i16::min)
}

/// `G_ExitLevel` and `G_SecretExitLevel`: the level ends after this tic.
pub fn exit_level(sim: &mut Sim, secret: bool) {
    sim.exit = Some(secret);
    sim.events.push(SimEvent::Exit { secret });
}

/// `P_SpawnSpecials`: the sector specials' thinkers, in sector order (the
/// flashes' and strobes' `P_Random` draws follow it), secrets counted,
/// the 30-second and 5-minute doors; then the scrolling lines; the plat,
/// ceiling and button lists start empty.
pub fn spawn_specials(sim: &mut Sim) {
    for s in 0..sim.level.sectors.len() {
        match sim.level.sectors[s].special {
            1 => lights::spawn_light_flash(sim, s),
            2 => lights::spawn_strobe_flash(sim, s, lights::FASTDARK, false),
            3 => lights::spawn_strobe_flash(sim, s, lights::SLOWDARK, false),
            4 => {
                // Strobe and hurt: the strobe clears the special, the hurt
                // needs it back.
                lights::spawn_strobe_flash(sim, s, lights::FASTDARK, false);
                sim.level.sectors[s].special = 4;
            }
            8 => lights::spawn_glowing_light(sim, s),
            9 => sim.total_secrets += 1,
            10 => doors::spawn_door_close_in_30(sim, s),
            12 => lights::spawn_strobe_flash(sim, s, lights::SLOWDARK, true),
            13 => lights::spawn_strobe_flash(sim, s, lights::FASTDARK, true),
            14 => doors::spawn_door_raise_in_5_mins(sim, s),
            // Fire flicker came with 1.4's beta; every version we play has it.
            17 => lights::spawn_fire_flicker(sim, s),
            _ => _ = generalized::spawn_sector(sim, s),
        }
    }
    sim.spec.scrollers =
        (0..sim.level.lines.len()).filter(|&l| sim.level.lines[l].special == 48).take(MAXLINEANIMS).collect();
    sim.spec.activeceilings = [None; MAXCEILINGS];
    sim.spec.activeplats = [None; MAXPLATS];
    sim.spec.buttons = [Button::default(); MAXBUTTONS];
}

/// `P_UpdateSpecials`: scrolling walls move a unit, pressed buttons count
/// down and pop back with a click. Doom also cycles its animated textures
/// and flats here; those are drawing-only translations (no hashed or
/// read game state depends on them), so the renderer owns them. `-timer`
/// is not among our rules, so there is no level timer.
pub fn update_specials(sim: &mut Sim) {
    generalized::update(sim);
    for i in 0..sim.spec.scrollers.len() {
        let line = sim.spec.scrollers[i];
        if sim.level.lines[line].special != 48 {
            continue;
        }
        if let Some(side) = sim.level.lines[line].sidenum[0] {
            sim.level.sides[side].textureoffset += Fixed::ONE;
        }
    }
    for i in 0..MAXBUTTONS {
        let b = sim.spec.buttons[i];
        if b.timer == 0 {
            continue;
        }
        sim.spec.buttons[i].timer -= 1;
        if b.timer - 1 != 0 {
            continue;
        }
        if let Some(side) = sim.level.lines.get(b.line).and_then(|l| l.sidenum[0]) {
            let s = &mut sim.level.sides[side];
            match b.place {
                ButtonWhere::Top => s.toptexture = b.texture,
                ButtonWhere::Middle => s.midtexture = b.texture,
                ButtonWhere::Bottom => s.bottomtexture = b.texture,
            }
            sim.textures_changed += 1;
        }
        let click = sim.info.sound("swtchn");
        sim.sector_sound(b.sector, click);
        sim.spec.buttons[i] = Button::default();
    }
}

/// Tics an item waits before it comes back in altdeath (30 seconds).
const ITEM_RESPAWN_TICS: u32 = 30 * super::TICRATE;

/// `P_RespawnSpecials`: in altdeath, the oldest picked-up item comes back
/// 30 seconds after it was taken, with an item fog on the floor under it.
pub fn respawn_specials(sim: &mut Sim) {
    if sim.rules.deathmatch != 2 {
        return;
    }
    let Some((thing, taken)) = sim.item_respawn.first().cloned() else { return };
    if sim.leveltime.wrapping_sub(taken) < ITEM_RESPAWN_TICS {
        return;
    }
    let (x, y) = (Fixed::from_int(thing.x.into()), Fixed::from_int(thing.y.into()));
    let ss = super::mobj::point_in_subsector(&sim.level, x, y);
    let floor = sim.level.sectors[sim.level.subsectors[ss].sector].floorheight;
    let fog = sim.spawn_mobj(x, y, floor, sim.kind_of(super::info::mt::IFOG));
    sim.sound_named(Some(fog), "itmbk");
    sim.item_respawn.remove(0);
    // Chocolate stops with an error where vanilla would overrun; we drop it.
    let Some(kind) = sim.info.by_doomednum(thing.kind.into()) else { return };
    let z = if sim.info.things[kind].flags & super::mobj::mf::SPAWNCEILING != 0 {
        super::mobj::ONCEILINGZ
    } else {
        super::mobj::ONFLOORZ
    };
    let mo = sim.spawn_mobj(x, y, z, kind);
    let angle = Angle(ANG45.0.wrapping_mul((i32::from(thing.angle) / 45) as u32));
    let m = sim.mo_mut(mo);
    m.spawnpoint = thing;
    m.angle = angle;
}

/// Missiles that never set off a line they cross (vanilla 1.4 and later).
const INERT_MISSILES: [usize; 6] = {
    use super::info::mt;
    [mt::ROCKET, mt::PLASMA, mt::BFG, mt::TROOPSHOT, mt::HEADSHOT, mt::BRUISERSHOT]
};

/// `P_CrossSpecialLine`: `thing` crossed line `line` from side `side`.
/// Monsters set off only teleporters, raise doors and lifts; a W1 line's
/// special is cleared once it has acted (the exits keep theirs).
pub fn cross_special_line(sim: &mut Sim, line: usize, side: usize, thing: MobjId) {
    let Some(l) = sim.level.lines.get(line) else { return };
    let special = l.special;
    if generalized::cross(sim, line, side, thing) {
        return;
    }
    let is_player = sim.mo(thing).player.is_some();
    if !is_player {
        if INERT_MISSILES.iter().any(|&m| sim.is(thing, m)) {
            return;
        }
        if !matches!(special, 39 | 97 | 125 | 126 | 4 | 10 | 88) {
            return;
        }
    }
    let once = cross_once(sim, line, side, thing, special, is_player);
    if once {
        sim.level.lines[line].special = 0;
    } else {
        cross_repeatable(sim, line, side, thing, special, is_player);
    }
}

/// The W1 specials; whether `special` was one (and so is used up).
fn cross_once(sim: &mut Sim, line: usize, side: usize, thing: MobjId, special: i16, is_player: bool) -> bool {
    match special {
        2 => _ = doors::do_door(sim, line, DoorType::Open),
        3 => _ = doors::do_door(sim, line, DoorType::Close),
        4 => _ = doors::do_door(sim, line, DoorType::Normal),
        5 => _ = floors::do_floor(sim, line, FloorType::RaiseFloor),
        6 => _ = ceilings::do_ceiling(sim, line, CeilingType::FastCrushAndRaise),
        8 => _ = floors::build_stairs(sim, line, StairType::Build8),
        10 => _ = plats::do_plat(sim, line, PlatType::DownWaitUpStay, 0),
        12 => lights::light_turn_on(sim, line, 0),
        13 => lights::light_turn_on(sim, line, 255),
        16 => _ = doors::do_door(sim, line, DoorType::Close30ThenOpen),
        17 => lights::start_light_strobing(sim, line),
        19 => _ = floors::do_floor(sim, line, FloorType::LowerFloor),
        22 => _ = plats::do_plat(sim, line, PlatType::RaiseToNearestAndChange, 0),
        25 => _ = ceilings::do_ceiling(sim, line, CeilingType::CrushAndRaise),
        30 => _ = floors::do_floor(sim, line, FloorType::RaiseToTexture),
        35 => lights::light_turn_on(sim, line, 35),
        36 => _ = floors::do_floor(sim, line, FloorType::TurboLower),
        37 => _ = floors::do_floor(sim, line, FloorType::LowerAndChange),
        38 => _ = floors::do_floor(sim, line, FloorType::LowerFloorToLowest),
        39 => _ = teleport::teleport(sim, line, side, thing),
        40 => {
            ceilings::do_ceiling(sim, line, CeilingType::RaiseToHighest);
            floors::do_floor(sim, line, FloorType::LowerFloorToLowest);
        }
        44 => _ = ceilings::do_ceiling(sim, line, CeilingType::LowerAndCrush),
        53 => _ = plats::do_plat(sim, line, PlatType::PerpetualRaise, 0),
        54 => plats::stop_plat(sim, line),
        56 => _ = floors::do_floor(sim, line, FloorType::RaiseFloorCrush),
        57 => _ = ceilings::ceiling_crush_stop(sim, line),
        58 => _ = floors::do_floor(sim, line, FloorType::RaiseFloor24),
        59 => _ = floors::do_floor(sim, line, FloorType::RaiseFloor24AndChange),
        100 => _ = floors::build_stairs(sim, line, StairType::Turbo16),
        104 => lights::turn_tag_lights_off(sim, line),
        108 => _ = doors::do_door(sim, line, DoorType::BlazeRaise),
        109 => _ = doors::do_door(sim, line, DoorType::BlazeOpen),
        110 => _ = doors::do_door(sim, line, DoorType::BlazeClose),
        119 => _ = floors::do_floor(sim, line, FloorType::RaiseFloorToNearest),
        121 => _ = plats::do_plat(sim, line, PlatType::BlazeDwus, 0),
        125 => {
            // Monsters only; a player leaves the line as it was.
            if is_player {
                return false;
            }
            teleport::teleport(sim, line, side, thing);
        }
        130 => _ = floors::do_floor(sim, line, FloorType::RaiseFloorTurbo),
        141 => _ = ceilings::do_ceiling(sim, line, CeilingType::SilentCrushAndRaise),
        // The exits end the level and keep their special.
        52 => {
            exit_level(sim, false);
            return false;
        }
        124 => {
            exit_level(sim, true);
            return false;
        }
        _ => return false,
    }
    true
}

/// The WR specials.
fn cross_repeatable(sim: &mut Sim, line: usize, side: usize, thing: MobjId, special: i16, is_player: bool) {
    match special {
        72 => _ = ceilings::do_ceiling(sim, line, CeilingType::LowerAndCrush),
        73 => _ = ceilings::do_ceiling(sim, line, CeilingType::CrushAndRaise),
        74 => _ = ceilings::ceiling_crush_stop(sim, line),
        75 => _ = doors::do_door(sim, line, DoorType::Close),
        76 => _ = doors::do_door(sim, line, DoorType::Close30ThenOpen),
        77 => _ = ceilings::do_ceiling(sim, line, CeilingType::FastCrushAndRaise),
        79 => lights::light_turn_on(sim, line, 35),
        80 => lights::light_turn_on(sim, line, 0),
        81 => lights::light_turn_on(sim, line, 255),
        82 => _ = floors::do_floor(sim, line, FloorType::LowerFloorToLowest),
        83 => _ = floors::do_floor(sim, line, FloorType::LowerFloor),
        84 => _ = floors::do_floor(sim, line, FloorType::LowerAndChange),
        86 => _ = doors::do_door(sim, line, DoorType::Open),
        87 => _ = plats::do_plat(sim, line, PlatType::PerpetualRaise, 0),
        88 => _ = plats::do_plat(sim, line, PlatType::DownWaitUpStay, 0),
        89 => plats::stop_plat(sim, line),
        90 => _ = doors::do_door(sim, line, DoorType::Normal),
        91 => _ = floors::do_floor(sim, line, FloorType::RaiseFloor),
        92 => _ = floors::do_floor(sim, line, FloorType::RaiseFloor24),
        93 => _ = floors::do_floor(sim, line, FloorType::RaiseFloor24AndChange),
        94 => _ = floors::do_floor(sim, line, FloorType::RaiseFloorCrush),
        95 => _ = plats::do_plat(sim, line, PlatType::RaiseToNearestAndChange, 0),
        96 => _ = floors::do_floor(sim, line, FloorType::RaiseToTexture),
        97 => _ = teleport::teleport(sim, line, side, thing),
        98 => _ = floors::do_floor(sim, line, FloorType::TurboLower),
        105 => _ = doors::do_door(sim, line, DoorType::BlazeRaise),
        106 => _ = doors::do_door(sim, line, DoorType::BlazeOpen),
        107 => _ = doors::do_door(sim, line, DoorType::BlazeClose),
        120 => _ = plats::do_plat(sim, line, PlatType::BlazeDwus, 0),
        126 if !is_player => _ = teleport::teleport(sim, line, side, thing),
        128 => _ = floors::do_floor(sim, line, FloorType::RaiseFloorToNearest),
        129 => _ = floors::do_floor(sim, line, FloorType::RaiseFloorTurbo),
        _ => {}
    }
}

/// `P_ShootSpecialLine`: a hitscan shot by `thing` hit line `line`.
/// Monsters' shots open only the impact door (46).
pub fn shoot_special_line(sim: &mut Sim, thing: MobjId, line: usize) {
    let Some(l) = sim.level.lines.get(line) else { return };
    let special = l.special;
    if generalized::shoot(sim, thing, line) {
        return;
    }
    if sim.mo(thing).player.is_none() && special != 46 {
        return;
    }
    match special {
        24 => {
            floors::do_floor(sim, line, FloorType::RaiseFloor);
            super::switches::change_switch_texture(sim, line, false);
        }
        46 => {
            doors::do_door(sim, line, DoorType::Open);
            super::switches::change_switch_texture(sim, line, true);
        }
        47 => {
            plats::do_plat(sim, line, PlatType::RaiseToNearestAndChange, 0);
            super::switches::change_switch_texture(sim, line, false);
        }
        _ => {}
    }
}

/// `P_PlayerInSpecialSector`: player `player` stands in a sector with a
/// special, on its floor. Hurting floors bite when `leveltime` is a
/// multiple of 32; the strobe-hurt floors leak through a radiation suit
/// when `P_Random` is under 5 (drawn every tic the suit is worn, bite or
/// not). Vanilla stops with an error on an unknown special; it is passed
/// over here.
pub fn player_in_special_sector(sim: &mut Sim, player: usize) {
    let Some(p) = sim.player(player) else { return };
    let mo = p.mo;
    let ironfeet = p.powers[PW_IRONFEET] != 0;
    let sector = sim.sector_of(mo);
    if sim.mo(mo).z != sim.level.sectors[sector].floorheight {
        return;
    }
    let hurt = |amount, suit| FloorDamage { amount, every: 32, suit, exit_below: 0 };
    match sim.level.sectors[sector].special {
        5 => floor_damage(sim, player, mo, ironfeet, hurt(10, Suit::Shields)),
        7 => floor_damage(sim, player, mo, ironfeet, hurt(5, Suit::Shields)),
        16 | 4 => floor_damage(sim, player, mo, ironfeet, hurt(20, Suit::Leaks)),
        9 => {
            found_secret(sim, player);
            sim.level.sectors[sector].special = 0;
        }
        // E1M8's exit: no god mode, and out at 10 health.
        11 => floor_damage(sim, player, mo, ironfeet, FloorDamage { exit_below: 10, ..hurt(20, Suit::Useless) }),
        _ => _ = generalized::player_in_sector(sim, player, mo, sector, ironfeet),
    }
}

/// A floor that hurts the player standing on it: `amount` every `every`
/// tics, what a radiation suit does against it, and (E1M8's exit floor)
/// the health at or below which the level ends, which also takes god mode
/// away.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FloorDamage {
    pub amount: i32,
    pub every: u32,
    pub suit: Suit,
    pub exit_below: i32,
}

/// What floor `d` does this tic to player `player` (body `mo`) standing
/// on it: vanilla's 5, 7, 4, 16 and 11, and any generalized damage.
pub fn floor_damage(sim: &mut Sim, player: usize, mo: MobjId, ironfeet: bool, d: FloorDamage) {
    if d.exit_below > 0 {
        if let Some(p) = sim.players[player].as_mut() {
            p.cheats &= !CF_GODMODE;
        }
    }
    let bite = sim.leveltime.is_multiple_of(d.every.max(1));
    let hurts = match d.suit {
        Suit::Shields => !ironfeet,
        Suit::Leaks => !ironfeet || sim.p_random() < i32::from(SUIT_LEAK),
        Suit::Useless => true,
    };
    if hurts && bite {
        interaction::damage_mobj(sim, mo, None, None, d.amount);
    }
    if d.exit_below > 0 && sim.player(player).is_some_and(|p| p.health <= d.exit_below) {
        exit_level(sim, false);
    }
}

#[cfg(test)]
#[path = "specials_tests.rs"]
mod tests;

/// A player found a secret: it counts, and under Sightline's rules the
/// player is told so (Boom's message; vanilla says nothing).
pub fn found_secret(sim: &mut Sim, player: usize) {
    let sightline = sim.rules.compat == super::Compat::Sightline;
    if let Some(p) = sim.players[player].as_mut() {
        p.secretcount += 1;
        if sightline {
            p.message = Some("A secret is revealed!".into());
        }
    }
}
