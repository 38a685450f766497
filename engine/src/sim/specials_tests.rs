//! Hand-worked checks of the movers and lights on a corridor built in
//! memory: sectors 0..n side by side, each joined to the next by a
//! two-sided line whose front is the lower-numbered sector (no outer walls:
//! the specials read only the sectors' line lists). One blockmap cell with
//! no lines, one subsector; no bodies, so `P_ChangeSector` finds nothing.

use crate::actors::ActorTable;
use crate::fixed::{Fixed, RNDTABLE};
use crate::sim::ceilings::{self, CeilingType};
use crate::sim::doors::{self, DoorType};
use crate::sim::floors::{self, FloorType, StairType};
use crate::sim::level::{ml, Blockmap, Level, Line, NameId, Sector, Side, SlopeType, Subsector, NO_TEXTURE};
use crate::sim::plats::{self, PlatStatus, PlatType};
use crate::sim::setup::Players;
use crate::sim::specials::{self, find_next_highest_floor};
use crate::sim::think::{run_thinkers, Status, ThinkerKind};
use crate::sim::{lights, GameMode, GameVersion, Rules, Sim};

fn u(n: i32) -> Fixed {
    Fixed::from_int(n)
}

fn sector(floor: i32, ceiling: i32, light: i16) -> Sector {
    Sector {
        floorheight: u(floor),
        ceilingheight: u(ceiling),
        floorpic: NO_TEXTURE,
        ceilingpic: NO_TEXTURE,
        lightlevel: light,
        special: 0,
        tag: 0,
        soundtraversed: 0,
        soundtarget: None,
        blockbox: [0, 0, 0, 0],
        soundorg: (u(0), u(0)),
        specialdata: None,
        lines: Vec::new(),
    }
}

/// Sectors of the given (floor, ceiling, light) in a row; line `i` joins
/// sector `i` (front, side 2i) to sector `i + 1` (back, side 2i + 1).
fn corridor(sectors: &[(i32, i32, i16)]) -> Level {
    let mut secs: Vec<Sector> = sectors.iter().map(|&(f, c, l)| sector(f, c, l)).collect();
    let mut lines = Vec::new();
    let mut sides = Vec::new();
    for i in 0..secs.len().saturating_sub(1) {
        let x = u(64 * (i as i32 + 1));
        lines.push(Line {
            v1: (x, u(0)),
            v2: (x, u(64)),
            dx: u(0),
            dy: u(64),
            flags: ml::TWOSIDED,
            special: 0,
            tag: 0,
            sidenum: [Some(2 * i), Some(2 * i + 1)],
            bbox: [u(64), u(0), x, x],
            slopetype: SlopeType::Vertical,
            frontsector: Some(i),
            backsector: Some(i + 1),
        });
        for sector in [i, i + 1] {
            sides.push(Side {
                textureoffset: u(0),
                rowoffset: u(0),
                toptexture: NO_TEXTURE,
                bottomtexture: NO_TEXTURE,
                midtexture: NO_TEXTURE,
                sector,
            });
        }
        secs[i].lines.push(i);
        secs[i + 1].lines.push(i);
    }
    Level {
        name: "MAP01".into(),
        vertices: Vec::new(),
        sectors: secs,
        sides,
        lines,
        segs: Vec::new(),
        subsectors: vec![Subsector { sector: 0, numlines: 0, firstline: 0 }],
        nodes: Vec::new(),
        blockmap: Blockmap { orgx: u(0), orgy: u(0), width: 1, height: 1, words: vec![0, 0, 1, 1, 5, 0, -1] },
        reject: Vec::new(),
        names: vec!["-".into(), "FLAT1".into(), "FLAT2".into()],
        things: Vec::new(),
        generalized: Default::default(),
        thing_fields: Vec::new(),
    }
}

/// A game whose tables come from Freedoom 2's MAP01, on `level`, with no
/// bodies or thinkers and `P_Random` at its start.
fn sim(level: Level) -> Sim {
    let wad = crate::sim::test_wad("freedoom2.wad");
    let rules = Rules { no_monsters: true, ..Rules::single(2, GameVersion::Doom19, GameMode::Commercial) };
    let players = Players { in_game: [false; crate::sim::MAXPLAYERS], console: 0 };
    let mut sim = Sim::new(&wad, "MAP01", rules, players, ActorTable::doom().clone()).expect("MAP01 loads");
    sim.level = level;
    sim.blocklinks = vec![Vec::new(); 1];
    sim.line_valid = vec![0; sim.level.lines.len()];
    sim.mobjs.clear();
    sim.thinkers.clear();
    sim.spec = specials::SpecialState::default();
    sim.rng = crate::fixed::DoomRandom::new();
    sim
}

fn tics(sim: &mut Sim, n: usize) {
    for _ in 0..n {
        run_thinkers(sim);
        sim.leveltime += 1;
    }
}

fn r(i: usize) -> i32 {
    i32::from(RNDTABLE[i])
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_broken_light_draws_its_waits_from_p_random() {
    // Sector 0 at 200 next to a 100: flashes between the two.
    let mut sim = sim(corridor(&[(0, 128, 200), (0, 128, 100)]));
    sim.level.sectors[0].special = 1;
    specials::spawn_specials(&mut sim);
    assert_eq!(sim.level.sectors[0].special, 0);
    // Spawn: count = (P_Random() & 64) + 1 = (8 & 64) + 1 = 1.
    assert_eq!(r(1), 8);
    assert_eq!(sim.rng.p_index(), 1);
    // Tic 1: the count runs out at full light: dark, for (109 & 7) + 1 = 6.
    tics(&mut sim, 1);
    assert_eq!(sim.level.sectors[0].lightlevel, 100);
    assert_eq!(sim.rng.p_index(), 2);
    tics(&mut sim, 5);
    assert_eq!((sim.level.sectors[0].lightlevel, sim.rng.p_index()), (100, 2));
    // Tic 7: bright again for (220 & 64) + 1 = 65 tics.
    tics(&mut sim, 1);
    assert_eq!((sim.level.sectors[0].lightlevel, sim.rng.p_index()), (200, 3));
    let ThinkerKind::Light(l) = &sim.thinkers[0].kind else { panic!("a light") };
    assert_eq!(l.count, (r(3) & 64) + 1);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_fire_flicker_drops_by_a_random_16s_every_fourth_tic() {
    let mut sim = sim(corridor(&[(0, 128, 192), (0, 128, 96)]));
    lights::spawn_fire_flicker(&mut sim, 0);
    // No draw at spawn; the first on tic 4: (8 & 3) * 16 = 0 below 192.
    tics(&mut sim, 3);
    assert_eq!(sim.rng.p_index(), 0);
    tics(&mut sim, 1);
    assert_eq!((sim.level.sectors[0].lightlevel, sim.rng.p_index()), (192, 1));
    // Tic 8: (109 & 3) * 16 = 16 below.
    tics(&mut sim, 4);
    assert_eq!(sim.level.sectors[0].lightlevel, 176);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_glow_turns_one_step_past_the_darkest_neighbour() {
    let mut sim = sim(corridor(&[(0, 128, 160), (0, 128, 100)]));
    lights::spawn_glowing_light(&mut sim, 0);
    tics(&mut sim, 7);
    assert_eq!(sim.level.sectors[0].lightlevel, 104);
    // 96 is at or below 100: back up to 104, now rising.
    tics(&mut sim, 1);
    assert_eq!(sim.level.sectors[0].lightlevel, 104);
    tics(&mut sim, 1);
    assert_eq!(sim.level.sectors[0].lightlevel, 112);
    assert_eq!(sim.rng.p_index(), 0);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn strobes_in_sector_order_draw_one_p_random_each_unless_in_sync() {
    let mut sim = sim(corridor(&[(0, 128, 200), (0, 128, 100), (0, 128, 200)]));
    sim.level.sectors[0].special = 2;
    sim.level.sectors[1].special = 12;
    sim.level.sectors[2].special = 3;
    specials::spawn_specials(&mut sim);
    assert_eq!(sim.rng.p_index(), 2);
    let counts: Vec<i32> = sim
        .thinkers
        .iter()
        .map(|t| match &t.kind {
            ThinkerKind::Light(l) => l.count,
            _ => -1,
        })
        .collect();
    assert_eq!(counts, [(r(1) & 7) + 1, 1, (r(2) & 7) + 1]);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_used_door_opens_waits_150_tics_and_closes() {
    // Sector 1 is the shut door behind line 0, between rooms 128 high.
    let mut sim = sim(corridor(&[(0, 128, 160), (0, 0, 160), (0, 128, 160)]));
    sim.level.lines[0].special = 1;
    let kind = sim.kind_of(crate::sim::info::mt::POSSESSED);
    let monster = sim.spawn_mobj(u(32), u(32), crate::sim::mobj::ONFLOORZ, kind);
    // The monster only uses the door; it does not think.
    let its_thinker = sim.mo(monster).thinker;
    sim.remove_thinker(its_thinker);
    let first = sim.thinkers.len();
    doors::vertical_door(&mut sim, 0, monster);
    let door = crate::sim::ThinkerId(first as u32);
    assert_eq!(sim.level.sectors[1].specialdata, Some(door));
    // Up at 2 a tic to the lowest neighbouring ceiling less 4: 124, on tic 62.
    tics(&mut sim, 62);
    assert_eq!(sim.level.sectors[1].ceilingheight, u(124));
    tics(&mut sim, 1);
    let ThinkerKind::Door(d) = &sim.thinkers[first].kind else { panic!("a door") };
    assert_eq!((d.direction, d.topcountdown), (0, 150));
    // Used again while open by a monster: nothing (bad guys never close doors).
    doors::vertical_door(&mut sim, 0, monster);
    tics(&mut sim, 150);
    let ThinkerKind::Door(d) = &sim.thinkers[first].kind else { panic!("a door") };
    assert_eq!(d.direction, -1);
    tics(&mut sim, 62);
    assert_eq!(sim.level.sectors[1].ceilingheight, u(0));
    assert_eq!(sim.thinkers[first].status, Status::Active);
    tics(&mut sim, 1);
    assert_eq!(sim.thinkers[first].status, Status::Removed);
    assert_eq!(sim.level.sectors[1].specialdata, None);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_lift_goes_down_waits_three_seconds_and_comes_back() {
    let mut sim = sim(corridor(&[(0, 128, 160), (64, 128, 160), (16, 128, 160)]));
    sim.level.sectors[1].tag = 5;
    sim.level.lines[0].tag = 5;
    assert!(plats::do_plat(&mut sim, 0, PlatType::DownWaitUpStay, 0));
    // Down at 4 a tic to the lowest neighbour (0): 16 tics, past on the 17th.
    tics(&mut sim, 16);
    assert_eq!(sim.level.sectors[1].floorheight, u(0));
    tics(&mut sim, 1);
    let ThinkerKind::Plat(p) = &sim.thinkers[0].kind else { panic!("a plat") };
    assert_eq!((p.status, p.count), (PlatStatus::Waiting, 105));
    tics(&mut sim, 105 + 16 + 1);
    assert_eq!(sim.level.sectors[1].floorheight, u(64));
    assert_eq!(sim.thinkers[0].status, Status::Removed);
    assert_eq!(sim.spec.activeplats[0], None);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_perpetual_lift_starts_by_p_random_and_stops_in_stasis() {
    let mut sim = sim(corridor(&[(0, 128, 160), (32, 128, 160), (64, 128, 160)]));
    sim.level.sectors[1].tag = 3;
    sim.level.lines[0].tag = 3;
    assert!(plats::do_plat(&mut sim, 0, PlatType::PerpetualRaise, 0));
    // P_Random() & 1 = 8 & 1 = 0: up first, to the highest neighbour.
    let ThinkerKind::Plat(p) = &sim.thinkers[0].kind else { panic!("a plat") };
    assert_eq!((p.status, p.low, p.high), (PlatStatus::Up, u(0), u(64)));
    tics(&mut sim, 10);
    assert_eq!(sim.level.sectors[1].floorheight, u(42));
    plats::stop_plat(&mut sim, 0);
    assert_eq!(sim.thinkers[0].status, Status::Stasis);
    tics(&mut sim, 10);
    assert_eq!(sim.level.sectors[1].floorheight, u(42));
    assert!(!plats::do_plat(&mut sim, 0, PlatType::PerpetualRaise, 0));
    assert_eq!(sim.thinkers[0].status, Status::Active);
    tics(&mut sim, 1);
    assert_eq!(sim.level.sectors[1].floorheight, u(43));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn stairs_rise_eight_a_step_along_the_same_flat() {
    let mut sim = sim(corridor(&[(0, 256, 160), (0, 256, 160), (0, 256, 160), (0, 256, 160)]));
    for s in 0..3 {
        sim.level.sectors[s].floorpic = NameId(1);
    }
    sim.level.sectors[3].floorpic = NameId(2);
    sim.level.sectors[0].tag = 7;
    sim.level.lines[0].tag = 7;
    assert!(floors::build_stairs(&mut sim, 0, StairType::Build8));
    let dests: Vec<(usize, Fixed, i32)> = sim
        .thinkers
        .iter()
        .map(|t| match &t.kind {
            ThinkerKind::Floor(f) => (f.sector, f.floordestheight, f.crush),
            _ => (99, u(0), 0),
        })
        .collect();
    assert_eq!(dests, [(0, u(8), 10), (1, u(16), 10), (2, u(24), 10)]);
    // A quarter unit a tic: 8 units in 32 tics, the step removed on the 33rd.
    tics(&mut sim, 32);
    assert_eq!(sim.level.sectors[0].floorheight, u(8));
    tics(&mut sim, 1);
    assert_eq!(sim.level.sectors[0].specialdata, None);
    assert_eq!(sim.level.sectors[2].floorheight, u(8) + Fixed(16384));
}

/// A generalized staircase's step may be negative: the same search builds
/// it, each step lower and moving down, at its own speed, not crushing.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn generalized_stairs_go_down_a_step_at_a_time() {
    let mut sim = sim(corridor(&[(64, 256, 160), (64, 256, 160), (64, 256, 160)]));
    sim.level.sectors[0].tag = 7;
    sim.level.lines[0].tag = 7;
    let params = floors::Stairs { speed: u(2), stairsize: u(-16), crush: 0 };
    assert!(floors::stairs(&mut sim, 0, params));
    let dests: Vec<(usize, Fixed, i32)> = sim
        .thinkers
        .iter()
        .map(|t| match &t.kind {
            ThinkerKind::Floor(f) => (f.sector, f.floordestheight, f.direction),
            _ => (99, u(0), 0),
        })
        .collect();
    assert_eq!(dests, [(0, u(48), -1), (1, u(32), -1), (2, u(16), -1)]);
    tics(&mut sim, 8);
    assert_eq!(sim.level.sectors[0].floorheight, u(48));
    assert_eq!(sim.level.sectors[2].floorheight, u(48));
    tics(&mut sim, 17);
    assert_eq!(sim.level.sectors[2].floorheight, u(16));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_crusher_stops_on_command_restarts_and_turns_up_8_above_the_floor() {
    let mut sim = sim(corridor(&[(0, 128, 160), (0, 72, 160)]));
    sim.level.sectors[1].tag = 9;
    sim.level.lines[0].tag = 9;
    assert!(ceilings::do_ceiling(&mut sim, 0, CeilingType::CrushAndRaise));
    tics(&mut sim, 4);
    assert_eq!(sim.level.sectors[1].ceilingheight, u(68));
    assert!(ceilings::ceiling_crush_stop(&mut sim, 0));
    assert_eq!(sim.thinkers[0].status, Status::Stasis);
    // A crushing raise restarts it.
    assert!(!ceilings::do_ceiling(&mut sim, 0, CeilingType::CrushAndRaise));
    tics(&mut sim, 1);
    assert_eq!(sim.level.sectors[1].ceilingheight, u(67));
    // Down to the floor plus 8 (64 more tics from 72), then back up.
    tics(&mut sim, 59);
    assert_eq!(sim.level.sectors[1].ceilingheight, u(8));
    tics(&mut sim, 1);
    let ThinkerKind::Ceiling(c) = &sim.thinkers[0].kind else { panic!("a ceiling") };
    assert_eq!(c.direction, 1);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_floor_lowers_to_the_highest_neighbour_and_a_w1_line_is_used_up() {
    let mut sim = sim(corridor(&[(0, 128, 160), (40, 128, 160), (24, 128, 160)]));
    sim.level.sectors[1].tag = 2;
    sim.level.lines[0].tag = 2;
    sim.level.lines[0].special = 19;
    let kind = sim.kind_of(crate::sim::info::mt::PLAYER);
    let mo = sim.spawn_mobj(u(32), u(32), crate::sim::mobj::ONFLOORZ, kind);
    sim.mo_mut(mo).player = Some(0);
    specials::cross_special_line(&mut sim, 0, 0, mo);
    assert_eq!(sim.level.lines[0].special, 0);
    let ThinkerKind::Floor(f) = &sim.thinkers.last().expect("a floor").kind else { panic!("a floor") };
    assert_eq!((f.direction, f.floordestheight), (-1, u(24)));
    // A monster does not set off a floor line.
    sim.level.lines[1].special = 19;
    sim.mo_mut(mo).player = None;
    let before = sim.thinkers.len();
    specials::cross_special_line(&mut sim, 1, 0, mo);
    assert_eq!((sim.thinkers.len(), sim.level.lines[1].special), (before, 19));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn next_highest_floor_keeps_chocolates_overflow_emulation() {
    // Sector 0 (floor 0) has 23 neighbours across 23 lines: 21 at 100, a
    // 22nd at 200 (which, in vanilla's overrun, becomes the bar later ones
    // must clear) and a 23rd at 50, which is therefore not a candidate.
    let mut floors = vec![(0, 256, 160)];
    let mut level = corridor(&[(0, 256, 160)]);
    for i in 0..23 {
        let h = match i {
            21 => 200,
            22 => 50,
            _ => 100,
        };
        floors.push((h, 256, 160));
    }
    level.sectors = floors.iter().map(|&(f, c, l)| sector(f, c, l)).collect();
    for i in 0..23 {
        level.lines.push(Line {
            v1: (u(0), u(0)),
            v2: (u(0), u(64)),
            dx: u(0),
            dy: u(64),
            flags: ml::TWOSIDED,
            special: 0,
            tag: 0,
            sidenum: [None, None],
            bbox: [u(64), u(0), u(0), u(0)],
            slopetype: SlopeType::Vertical,
            frontsector: Some(0),
            backsector: Some(i + 1),
        });
        level.sectors[0].lines.push(i);
    }
    assert_eq!(find_next_highest_floor(&level, 0, u(0)), u(100));
    // With 20 neighbours there is no overrun: the 50 counts.
    level.sectors[0].lines = (0..20).chain([22]).collect();
    assert_eq!(find_next_highest_floor(&level, 0, u(0)), u(50));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_close_in_30_door_from_a_sector_special_closes_after_30_seconds() {
    let mut sim = sim(corridor(&[(0, 128, 160), (0, 64, 160)]));
    sim.level.sectors[1].special = 10;
    specials::spawn_specials(&mut sim);
    assert_eq!(sim.level.sectors[1].special, 0);
    assert!(sim.level.sectors[1].specialdata.is_some());
    tics(&mut sim, 30 * 35);
    let ThinkerKind::Door(d) = &sim.thinkers[0].kind else { panic!("a door") };
    assert_eq!((d.kind, d.direction), (DoorType::Normal, -1));
    tics(&mut sim, 32);
    assert_eq!(sim.level.sectors[1].ceilingheight, u(0));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn lower_and_change_takes_the_flat_of_the_sector_at_its_destination() {
    let mut sim = sim(corridor(&[(8, 128, 160), (64, 128, 160), (32, 128, 160)]));
    sim.level.sectors[0].floorpic = NameId(2);
    sim.level.sectors[0].special = 7;
    sim.level.sectors[1].tag = 4;
    sim.level.lines[0].tag = 4;
    assert!(floors::do_floor(&mut sim, 0, FloorType::LowerAndChange));
    tics(&mut sim, 57);
    assert_eq!(sim.level.sectors[1].floorheight, u(8));
    assert_eq!((sim.level.sectors[1].floorpic, sim.level.sectors[1].special), (NameId(2), 7));
}

/// A player's body at (32, 32) in sector 0, with player 0's record.
fn player(sim: &mut Sim) -> crate::sim::MobjId {
    let kind = sim.kind_of(crate::sim::info::mt::PLAYER);
    let mo = sim.spawn_mobj(u(32), u(32), crate::sim::mobj::ONFLOORZ, kind);
    let its_thinker = sim.mo(mo).thinker;
    sim.remove_thinker(its_thinker);
    let mut p = crate::sim::Player::reborn(&sim.info, [0; crate::sim::MAXPLAYERS], (0, 0, 0));
    p.mo = mo;
    sim.players[0] = Some(p);
    sim.mo_mut(mo).player = Some(0);
    mo
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_button_shows_its_other_face_and_pops_back_after_a_second() {
    let mut sim = sim(corridor(&[(0, 128, 160), (64, 128, 160), (0, 128, 160)]));
    sim.level.names.push("SW1BRCOM".into());
    let off = NameId(3);
    sim.level.sides[0].toptexture = off;
    sim.level.lines[0].special = 62;
    sim.level.lines[0].tag = 1;
    sim.level.sectors[1].tag = 1;
    let mo = player(&mut sim);
    assert!(crate::sim::switches::use_special_line(&mut sim, mo, 0, 0));
    let on = sim.level.sides[0].toptexture;
    assert_eq!(sim.level.name(on), "SW2BRCOM");
    assert_eq!(sim.level.lines[0].special, 62);
    assert!(matches!(sim.thinkers.last().map(|t| &t.kind), Some(ThinkerKind::Plat(_))));
    for _ in 0..34 {
        specials::update_specials(&mut sim);
    }
    assert_eq!(sim.level.sides[0].toptexture, on);
    specials::update_specials(&mut sim);
    assert_eq!(sim.level.sides[0].toptexture, off);
    assert_eq!(sim.spec.buttons[0].timer, 0);
    // From the back side nothing happens.
    assert!(!crate::sim::switches::use_special_line(&mut sim, mo, 0, 1));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_secret_sector_counts_once_and_a_suit_leaks_when_p_random_is_under_5() {
    let mut sim = sim(corridor(&[(0, 128, 160), (0, 128, 160)]));
    let mo = player(&mut sim);
    sim.level.sectors[0].special = 9;
    specials::player_in_special_sector(&mut sim, 0);
    specials::player_in_special_sector(&mut sim, 0);
    assert_eq!(sim.player(0).map(|p| p.secretcount), Some(1));
    assert_eq!(sim.level.sectors[0].special, 0);
    // Super hellslime with a radiation suit: a draw every tic, bite or not.
    sim.level.sectors[0].special = 16;
    sim.players[0].as_mut().map(|p| p.powers[specials::PW_IRONFEET] = 100);
    sim.leveltime = 1;
    specials::player_in_special_sector(&mut sim, 0);
    assert_eq!(sim.rng.p_index(), 2);
    // The next draw is RNDTABLE[0] = 0, under 5, and leveltime 32 bites.
    sim.rng = crate::fixed::DoomRandom::from_indices(255, 0);
    sim.leveltime = 32;
    specials::player_in_special_sector(&mut sim, 0);
    assert_eq!(sim.mo(mo).health, 80);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_teleport_puts_the_player_on_the_destination_with_two_fogs() {
    let mut sim = sim(corridor(&[(0, 128, 160), (16, 128, 160)]));
    sim.level.sectors[0].tag = 6;
    sim.level.lines[0].tag = 6;
    sim.level.lines[0].special = 97;
    let kind = sim.kind_of(crate::sim::info::mt::TELEPORTMAN);
    let dest = sim.spawn_mobj(u(20), u(40), crate::sim::mobj::ONFLOORZ, kind);
    sim.mo_mut(dest).angle = crate::fixed::ANG90;
    let mo = player(&mut sim);
    sim.mo_mut(mo).momx = u(3);
    let before = sim.mobjs.len();
    // From the back: nothing.
    specials::cross_special_line(&mut sim, 0, 1, mo);
    assert_eq!(sim.mobjs.len(), before);
    specials::cross_special_line(&mut sim, 0, 0, mo);
    let m = sim.mo(mo);
    assert_eq!((m.x, m.y, m.angle, m.momx, m.reactiontime), (u(20), u(40), crate::fixed::ANG90, u(0), 18));
    assert_eq!(sim.mobjs.len(), before + 2);
    // The second fog 20 units ahead of the destination (facing north), by
    // Doom's table: finecosine[2048] is -25 and finesine[2048] 65535.
    assert_eq!((crate::fixed::finecosine(2048), crate::fixed::finesine(2048)), (Fixed(-25), Fixed(65535)));
    let fog = sim.mo(crate::sim::MobjId(before as u32 + 1));
    assert_eq!((fog.x, fog.y), (u(20) - Fixed(500), u(40) + Fixed(20 * 65535)));
    // WR: the line keeps its special.
    assert_eq!(sim.level.lines[0].special, 97);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn raise_to_texture_rises_by_the_shortest_lower_texture_around() {
    let mut sim = sim(corridor(&[(0, 128, 160), (0, 128, 160), (0, 128, 160)]));
    sim.level.names.extend(["TEX1".to_string(), "TEX2".to_string()]);
    sim.spec.texture_heights = vec![("TEX1".into(), u(32)), ("TEX2".into(), u(16))];
    sim.spec.texture0_height = u(64);
    sim.level.sides[0].bottomtexture = NameId(3);
    sim.level.sides[2].bottomtexture = NameId(4);
    sim.level.sectors[1].tag = 8;
    sim.level.lines[1].tag = 8;
    assert!(floors::do_floor(&mut sim, 1, FloorType::RaiseToTexture));
    let ThinkerKind::Floor(f) = &sim.thinkers[0].kind else { panic!("a floor") };
    assert_eq!(f.floordestheight, u(16));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn texture_heights_read_from_a_texture_lump() {
    let mut lump = vec![];
    lump.extend(2i32.to_le_bytes());
    lump.extend(12i32.to_le_bytes());
    lump.extend(34i32.to_le_bytes());
    for (name, height) in [(*b"AASHITTY", 64i16), (*b"BIGDOOR1", 128)] {
        lump.extend(name);
        lump.extend([0u8; 4]);
        lump.extend(64i16.to_le_bytes());
        lump.extend(height.to_le_bytes());
        lump.extend([0u8; 6]);
    }
    let heights = specials::texture_lump_heights(&lump);
    assert_eq!(heights, [("AASHITTY".to_string(), u(64)), ("BIGDOOR1".to_string(), u(128))]);
    // A truncated lump gives what it holds.
    assert_eq!(specials::texture_lump_heights(&lump[..20]).len(), 0);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn the_switch_list_grows_with_the_game_mode() {
    use crate::sim::switches::switch_list;
    use crate::sim::Compat;
    assert_eq!(switch_list(GameMode::Shareware, Compat::Vanilla).len(), 2 * 19);
    assert_eq!(switch_list(GameMode::Retail, Compat::Vanilla).len(), 2 * 29);
    // Sightline's own switches (SWITCH1, EXITSW1) are switches in RON maps only.
    let ours = switch_list(GameMode::Commercial, Compat::Sightline);
    assert_eq!((ours.len(), ours[80], ours[83]), (2 * 42, "SWITCH1", "EXITSW2"));
    let doom2 = switch_list(GameMode::Commercial, Compat::Vanilla);
    assert_eq!(doom2.len(), 2 * 40);
    // Off and on faces alternate, so `i ^ 1` is the other face.
    assert_eq!((doom2[0], doom2[1], doom2[79]), ("SW1BRCOM", "SW2BRCOM", "SW2SKULL"));
}
