//! Hand-worked checks of `p_map.c`, `p_maputl.c` and `p_sight.c` on a
//! room built in memory: 256 units square, split at x = 128 by a
//! two-sided line into a west sector (0) and an east one (1) whose heights
//! each test sets. The blockmap is 3x3 cells from (-8, -8), every cell
//! listing every line (validcount keeps each to one visit); one node splits
//! the room at x = 128.

use super::*;
use crate::actors::ActorTable;
use crate::fixed::{Angle, Fixed};
use crate::sim::info::mt;
use crate::sim::level::{ml, Blockmap, Level, Line, Node, Sector, Seg, Side, Subsector, NO_TEXTURE};
use crate::sim::mobj::ONFLOORZ;
use crate::sim::setup::Players;
use crate::sim::{sight, slide, Compat, GameMode, GameVersion, Rules, Sim};

fn u(n: i32) -> Fixed {
    Fixed::from_int(n)
}

fn sector(floor: i32, ceiling: i32) -> Sector {
    Sector {
        floorheight: u(floor),
        ceilingheight: u(ceiling),
        floorpic: NO_TEXTURE,
        ceilingpic: NO_TEXTURE,
        lightlevel: 160,
        special: 0,
        tag: 0,
        soundtraversed: 0,
        soundtarget: None,
        blockbox: [2, 0, 0, 2],
        soundorg: (u(0), u(0)),
        specialdata: None,
        lines: Vec::new(),
    }
}

fn line(v1: (i32, i32), v2: (i32, i32), front: usize, back: Option<usize>, sides: [Option<usize>; 2]) -> Line {
    let ends = ((u(v1.0), u(v1.1)), (u(v2.0), u(v2.1)));
    let flags = if back.is_some() { ml::TWOSIDED } else { ml::BLOCKING };
    Line::new(ends, flags, 0, 0, sides, [Some(front), back])
}

/// The room, its east sector at `floor1`..`ceiling1`.
fn room(floor1: i32, ceiling1: i32) -> Level {
    let lines = vec![
        line((0, 0), (0, 256), 0, None, [Some(0), None]),
        line((0, 256), (128, 256), 0, None, [Some(1), None]),
        line((128, 256), (256, 256), 1, None, [Some(2), None]),
        line((256, 256), (256, 0), 1, None, [Some(3), None]),
        line((256, 0), (128, 0), 1, None, [Some(4), None]),
        line((128, 0), (0, 0), 0, None, [Some(5), None]),
        // The divider goes north: its front (right) is the east sector.
        line((128, 0), (128, 256), 1, Some(0), [Some(6), Some(7)]),
    ];
    let sides = [0, 0, 1, 1, 1, 0, 1, 0]
        .iter()
        .map(|&sector| Side {
            textureoffset: u(0),
            rowoffset: u(0),
            toptexture: NO_TEXTURE,
            bottomtexture: NO_TEXTURE,
            midtexture: NO_TEXTURE,
            sector,
        })
        .collect();
    let seg = |l: usize, sidedef: usize, front: usize, back: Option<usize>| {
        let ld: &Line = &lines[l];
        Seg {
            v1: ld.v1,
            v2: ld.v2,
            offset: u(0),
            angle: Angle::ZERO,
            sidedef,
            linedef: l,
            frontsector: front,
            backsector: back,
        }
    };
    let segs = vec![
        seg(0, 0, 0, None),
        seg(1, 1, 0, None),
        seg(5, 5, 0, None),
        seg(6, 7, 0, Some(1)),
        seg(2, 2, 1, None),
        seg(3, 3, 1, None),
        seg(4, 4, 1, None),
        seg(6, 6, 1, Some(0)),
    ];
    let mut words: Vec<i16> = vec![-8, -8, 3, 3];
    words.extend([13; 9]);
    words.extend([0, 0, 1, 2, 3, 4, 5, 6, -1]);
    let mut sectors = vec![sector(0, 128), sector(floor1, ceiling1)];
    sectors[0].lines = vec![0, 1, 5, 6];
    sectors[1].lines = vec![2, 3, 4, 6];
    Level {
        name: "MAP01".into(),
        vertices: Vec::new(),
        sectors,
        sides,
        lines,
        segs,
        subsectors: vec![
            Subsector { sector: 0, numlines: 4, firstline: 0 },
            Subsector { sector: 1, numlines: 4, firstline: 4 },
        ],
        nodes: vec![Node {
            x: u(128),
            y: u(0),
            dx: u(0),
            dy: u(256),
            bbox: [[u(256), u(0), u(128), u(256)], [u(256), u(0), u(0), u(128)]],
            children: [0x8001, 0x8000],
        }],
        blockmap: Blockmap { orgx: u(-8), orgy: u(-8), width: 3, height: 3, words },
        reject: Vec::new(),
        names: vec!["-".into()],
        things: Vec::new(),
        generalized: Default::default(),
        thing_fields: Vec::new(),
    }
}

/// A game on the room: Freedoom 2's MAP01 is loaded for the tables, then
/// its level and bodies are swapped for the room's (no bodies yet).
fn sim(floor1: i32, ceiling1: i32) -> Sim {
    let wad = crate::sim::test_wad("freedoom2.wad");
    let rules = Rules { no_monsters: true, ..Rules::single(2, GameVersion::Final, GameMode::Commercial) };
    let players = Players { in_game: [false; crate::sim::MAXPLAYERS], console: 0 };
    let mut sim = Sim::new(&wad, "MAP01", rules, players, ActorTable::doom().clone()).expect("MAP01 loads");
    sim.level = room(floor1, ceiling1);
    sim.blocklinks = vec![Vec::new(); 9];
    sim.line_valid = vec![0; sim.level.lines.len()];
    sim.mobjs.clear();
    sim.thinkers.clear();
    sim
}

/// A player-sized body (radius 16, height 56) that is a monster to the
/// rules (no player record).
fn body(sim: &mut Sim, x: i32, y: i32) -> MobjId {
    let kind = sim.kind_of(mt::PLAYER);
    sim.spawn_mobj(u(x), u(y), ONFLOORZ, kind)
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_position_takes_floor_and_ceiling_from_the_lines_it_touches() {
    let mut sim = sim(16, 128);
    let mo = body(&mut sim, 64, 128);
    assert!(check_position(&mut sim, mo, u(64), u(128)));
    assert_eq!((sim.tm.floorz, sim.tm.ceilingz, sim.tm.dropoffz), (u(0), u(128), u(0)));
    // Straddling the divider: the step's top is the floor, the low side the drop-off.
    assert!(check_position(&mut sim, mo, u(120), u(128)));
    assert_eq!((sim.tm.floorz, sim.tm.ceilingz, sim.tm.dropoffz), (u(16), u(128), u(0)));
    assert_eq!(sim.tm.opening, maputl::Opening { top: u(128), bottom: u(16), range: u(112), lowfloor: u(0) });
    // Into the west wall (one-sided): blocked.
    assert!(!check_position(&mut sim, mo, u(10), u(128)));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_move_steps_up_24_units_and_no_more() {
    let mut sim = sim(16, 128);
    let mo = body(&mut sim, 64, 128);
    assert!(try_move(&mut sim, mo, u(120), u(128)));
    assert_eq!((sim.mo(mo).x, sim.mo(mo).floorz), (u(120), u(16)));
    let mut sim = self::sim(32, 128);
    let mo = body(&mut sim, 64, 128);
    assert!(!try_move(&mut sim, mo, u(120), u(128)));
    // It would fit between floor and ceiling, so floating could get there.
    assert!(sim.tm.floatok);
    assert_eq!(sim.mo(mo).x, u(64));
    // A low ceiling: 56 units of body under 50 of opening do not fit at all.
    let mut sim = self::sim(0, 50);
    let mo = body(&mut sim, 64, 128);
    assert!(!try_move(&mut sim, mo, u(120), u(128)));
    assert!(!sim.tm.floatok);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_slide_along_a_wall_stops_short_of_it_then_turns() {
    // Running west-north-west into the west wall from (40, 128): 30 units
    // west and 10 north a tic. The leading corner (24, 144) meets x = 0 at
    // FixedDiv(-1572864, -1966080) = 52428 of the move (0.8). Less Doom's
    // 0x800 fudge, 50380: the body moves FixedMul(-30u, 50380) = -1511400 and
    // FixedMul(10u, 50380) = 503800. The rest, 65536 - 52428 = 13108, slides
    // along the vertical wall: x move zeroed, y move FixedMul(10u, 13108) = 131080.
    let mut sim = sim(0, 128);
    let mo = body(&mut sim, 40, 128);
    sim.mo_mut(mo).momx = u(-30);
    sim.mo_mut(mo).momy = u(10);
    slide::slide_move(&mut sim, mo);
    let m = sim.mo(mo);
    assert_eq!((m.x, m.y), (Fixed(u(40).0 - 1511400), Fixed(u(128).0 + 503800 + 131080)));
    assert_eq!((m.momx, m.momy), (Fixed(0), Fixed(131080)));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_closed_door_blocks_sight_and_an_open_one_does_not() {
    let mut sim = sim(16, 128);
    let (a, b) = (body(&mut sim, 64, 100), body(&mut sim, 192, 100));
    assert!(sight::check_sight(&mut sim, a, b));
    assert!(sight::check_sight(&mut sim, b, a));
    sim.level.sectors[1].ceilingheight = u(16);
    assert!(!sight::check_sight(&mut sim, a, b));
    // REJECT says no before any trace: sector 0 cannot see sector 1 (bit 1).
    sim.level.sectors[1].ceilingheight = u(128);
    sim.level.reject = vec![0b0010];
    assert!(!sight::check_sight(&mut sim, a, b));
    assert!(sight::check_sight(&mut sim, b, a));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn doom_s_divline_typo_sees_through_a_closed_door() {
    // The trace runs along y = 128 and the door's line lies at x = 128:
    // P_DivlineSide compares the ends' x with the trace's y, calls both
    // "on", and the line is not crossed. Doom 1.9 does the same.
    let mut sim = sim(16, 16);
    let (a, b) = (body(&mut sim, 64, 128), body(&mut sim, 192, 128));
    assert!(sight::check_sight(&mut sim, a, b));
    // Sightline's rules fix the typo, and the door blocks.
    sim.rules.compat = Compat::Sightline;
    assert!(!sight::check_sight(&mut sim, a, b));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn aiming_picks_the_middle_of_what_the_step_leaves_visible() {
    // Shooter's z for shots: z + 28 + 8 = 36. Facing east, the trace ends
    // at 1024 * finecosine[0] = 1024 * 65535 east and 1024 * finesine[0] =
    // 1024 * 25 north (Doom's tables are sampled half a step off). The
    // target at (192, 128) is crossed at frac 8189, dist
    // FixedMul(1024u, 8189) = 8385536.
    let mut sim = sim(0, 128);
    let (a, b) = (body(&mut sim, 64, 128), body(&mut sim, 192, 128));
    // Level floors: top FixedDiv(20u, dist) = 10243, bottom
    // FixedDiv(-36u, dist) = -18438; (10243 - 18438) / 2 = -4097 (C truncates).
    assert_eq!(aim_line_attack(&mut sim, a, Angle::ZERO, u(1024)), Fixed(-4097));
    assert_eq!(sim.tm.linetarget, Some(b));
    // The target on a 16-unit step: top 18438, bottom -10243. The step's
    // edge (frac 4096, 64 units) raises the bottom slope to
    // FixedDiv(-20u, 64u) = -20480, which does not clip the target.
    let mut sim = self::sim(16, 128);
    let (a, b) = (body(&mut sim, 64, 128), body(&mut sim, 192, 128));
    assert_eq!(aim_line_attack(&mut sim, a, Angle::ZERO, u(1024)), Fixed(4097));
    assert_eq!(sim.tm.linetarget, Some(b));
    assert_eq!(sim.tm.bottomslope, Fixed(-20480));
    // Facing north, nothing: slope 0 and no target.
    assert_eq!(aim_line_attack(&mut sim, a, crate::fixed::ANG90, u(1024)), Fixed(0));
    assert_eq!(sim.tm.linetarget, None);
}

/// A body whose centre is in one blockmap cell and whose box reaches into
/// the next is missed by a shot through that next cell in Doom, which
/// looks only at the bodies linked in the cells the trace crosses, each
/// linked in its centre's cell (the room's cells meet at x = 120 and y =
/// 120). Under Sightline's rules, as in ZDoom, whose bodies are linked in
/// every cell they overlap, the shot finds it.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_shot_finds_a_body_across_a_cell_edge_under_sightlines_rules() {
    // (shooter, target, facing): east along y = 126 at a body centred at
    // y = 112 (its box 96..128), north along x = 126 at one at x = 112.
    let cases = [((20, 126), (64, 112), Angle::ZERO), ((126, 20), (112, 180), crate::fixed::ANG90)];
    for (compat, hits) in [(Compat::Vanilla, false), (Compat::Sightline, true)] {
        for (from, to, facing) in cases {
            let mut sim = sim(0, 128);
            sim.rules.compat = compat;
            let (a, b) = (body(&mut sim, from.0, from.1), body(&mut sim, to.0, to.1));
            let what = format!("{compat:?}, from {from:?} at {to:?}");
            assert_ne!(sim.mo(a).block, sim.mo(b).block, "{what}: the bodies share a cell");
            let slope = aim_line_attack(&mut sim, a, facing, u(1024));
            assert_eq!(sim.tm.linetarget == Some(b), hits, "{what}: aim");
            let health = sim.mo(b).health;
            line_attack(&mut sim, a, facing, u(1024), slope, 10);
            assert_eq!(sim.mo(b).health < health, hits, "{what}: shot");
        }
    }
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_lowered_ceiling_squeezes_and_gibs() {
    let mut sim = sim(0, 128);
    let (alive, dead) = (body(&mut sim, 192, 100), body(&mut sim, 192, 180));
    sim.mo_mut(dead).health = 0;
    assert!(!change_sector(&mut sim, 1, false));
    sim.level.sectors[1].ceilingheight = u(40);
    // The live body no longer fits (nofit); without crunch nothing is hurt.
    assert!(change_sector(&mut sim, 1, false));
    assert_eq!((sim.mo(alive).z, sim.mo(alive).ceilingz), (u(0), u(40)));
    let gib = sim.mo(dead);
    assert_eq!((gib.radius, gib.height), (u(0), u(0)));
    assert!(!gib.has(mf::SOLID));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn monsters_telefrag_only_on_map30() {
    let mut sim = sim(0, 128);
    let (a, b) = (body(&mut sim, 64, 128), body(&mut sim, 192, 128));
    assert!(!teleport_move(&mut sim, a, u(200), u(128)));
    assert_eq!(sim.mo(a).x, u(64));
    // Somewhere clear: moved, with the floor and ceiling of the spot.
    assert!(teleport_move(&mut sim, a, u(60), u(40)));
    assert_eq!((sim.mo(a).x, sim.mo(a).y, sim.mo(a).ceilingz), (u(60), u(40), u(128)));
    let _ = b;
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn the_blockmap_walk_is_newest_first_and_survives_removal() {
    let mut sim = sim(0, 128);
    // Three bodies in cell (0, 1) (x -8..120, y 120..248).
    let ids: Vec<MobjId> = (0..3).map(|i| body(&mut sim, 20 + 30 * i, 130)).collect();
    let mut seen = Vec::new();
    maputl::block_things(&mut sim, 0, 1, |sim, mo| {
        seen.push(mo);
        // Removing the body being visited does not end the walk.
        sim.remove_mobj(mo);
        true
    });
    assert_eq!(seen, [ids[2], ids[1], ids[0]]);
    assert!(sim.blocklinks[3].is_empty());
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_shot_at_a_wall_puffs_four_units_short_of_it() {
    // From (64, 100) facing west, 2048 units: the trace's end is 2048 *
    // finecosine[4096] = 2048 * -65535 east and 2048 * finesine[4096] =
    // 2048 * -25 north. It meets the west wall at frac 2048 (1/32, 64
    // units); less FixedDiv(4u, 2048u) = 128, 1920: the puff at x =
    // 64u + FixedMul(-134215680, 1920) = 262204, y = 100u + FixedMul(-51200,
    // 1920) = 6552100.
    let mut sim = sim(0, 128);
    let a = body(&mut sim, 64, 100);
    let before = sim.mobjs.len();
    line_attack(&mut sim, a, crate::fixed::ANG180, u(2048), Fixed(0), 0);
    let puff = sim.kind_of(mt::PUFF);
    let puffs: Vec<&crate::sim::Mobj> = sim.mobjs[before..].iter().filter(|m| m.kind == puff).collect();
    assert_eq!(puffs.len(), 1);
    assert_eq!((puffs[0].x, puffs[0].y), (Fixed(262204), Fixed(6552100)));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn using_a_plain_wall_says_oof_and_an_open_line_does_not() {
    let mut sim = sim(0, 128);
    let mo = body(&mut sim, 40, 100);
    let mut player = crate::sim::Player::reborn(&sim.info, [0; crate::sim::MAXPLAYERS], (0, 0, 0));
    player.mo = mo;
    sim.players[0] = Some(player);
    sim.mo_mut(mo).player = Some(0);
    // Facing west: the wall is 40 units away, within the 64 of USERANGE.
    sim.mo_mut(mo).angle = crate::fixed::ANG180;
    sim.events.clear();
    use_lines(&mut sim, 0);
    let noway = sim.info.sound("noway");
    let oof = |sim: &Sim| {
        sim.events.iter().any(|e| matches!(e, crate::sim::SimEvent::Sound { sound, .. } if *sound == noway))
    };
    assert!(oof(&sim));
    // Facing east from (100, 100): the divider at 28 units is two-sided
    // and open, so the trace goes on and finds nothing else in reach.
    sim.events.clear();
    sim.mo_mut(mo).angle = Angle::ZERO;
    assert!(teleport_move(&mut sim, mo, u(100), u(100)));
    use_lines(&mut sim, 0);
    assert!(!oof(&sim));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn the_overruns_write_where_chocolate_writes() {
    let mut sim = sim(0, 128);
    // The 9th special line overwrites tmbbox[BOXTOP] with line 5's
    // "address" in doom2.exe: 0x01C09C98 + 5 * 0x3E.
    sim.tm.spechit = vec![6; 9];
    spechit_overrun(&mut sim, 5);
    assert_eq!(sim.tm.bbox[crate::sim::level::BOXTOP], Fixed(0x01C0_9C98 + 5 * 0x3E));
    sim.tm.spechit = vec![6; 14];
    sim.tm.nofit = false;
    spechit_overrun(&mut sim, 0);
    assert!(sim.tm.nofit);
}

mod no_panics {
    //! Moves, traces, sight and crushing from random places of a real
    //! map, far outside it included: nothing may panic.

    use std::sync::OnceLock;

    use proptest::prelude::*;

    use super::*;

    fn map01() -> &'static Sim {
        static SIM: OnceLock<Sim> = OnceLock::new();
        SIM.get_or_init(|| {
            let wad = crate::sim::test_wad("freedoom2.wad");
            let rules = Rules::single(3, GameVersion::Final, GameMode::Commercial);
            let mut in_game = [false; crate::sim::MAXPLAYERS];
            in_game[0] = true;
            let players = Players { in_game, console: 0 };
            Sim::new(&wad, "MAP01", rules, players, ActorTable::doom().clone()).expect("MAP01 loads")
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(96))]
        #[test]
        #[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
        fn anything_anywhere(
            who in 0usize..1000,
            other in 0usize..1000,
            x in -40000i32..40000,
            y in -40000i32..40000,
            near in any::<bool>(),
            mom in (-120i32..120, -120i32..120),
            angle in any::<u32>(),
            damage in 0i32..400,
            sector in 0usize..1000,
            crunch in any::<bool>(),
        ) {
            let mut sim = map01().clone();
            let live: Vec<MobjId> = sim.live_mobjs().collect();
            let mo = live[who % live.len()];
            let target = live[other % live.len()];
            // Half the time a point near the body (inside the map, mostly).
            let (tx, ty) = if near {
                (sim.mo(mo).x + Fixed::from_int(x % 300), sim.mo(mo).y + Fixed::from_int(y % 300))
            } else {
                (Fixed::from_int(x), Fixed::from_int(y))
            };
            if try_move(&mut sim, mo, tx, ty) {
                // Where it moved to, unless a teleporter line crossed on
                // the way sent it to a destination (P_TryMove then still
                // answers true, as Doom's does).
                let at = (sim.mo(mo).x, sim.mo(mo).y);
                let teleported = sim.live_mobjs().any(|d| sim.is(d, mt::TELEPORTMAN) && (sim.mo(d).x, sim.mo(d).y) == at);
                prop_assert!(at == (tx, ty) || teleported, "moved to {at:?}, asked for {:?}", (tx, ty));
            }
            check_position(&mut sim, target, tx, ty);
            sim.mo_mut(mo).momx = Fixed::from_int(mom.0);
            sim.mo_mut(mo).momy = Fixed::from_int(mom.1);
            slide::slide_move(&mut sim, mo);
            let slope = aim_line_attack(&mut sim, mo, Angle(angle), Fixed::from_int(2048));
            line_attack(&mut sim, mo, Angle(angle), Fixed::from_int(2048), slope, damage);
            sight::check_sight(&mut sim, mo, target);
            sight::check_sight(&mut sim, target, mo);
            radius_attack(&mut sim, target, Some(mo), damage);
            if let Some(p) = sim.players[0].as_ref().map(|p| p.mo) {
                sim.mo_mut(p).angle = Angle(angle);
                use_lines(&mut sim, 0);
            }
            let sectors = sim.level.sectors.len();
            sim.level.sectors[sector % sectors].ceilingheight -= Fixed::from_int(damage);
            change_sector(&mut sim, sector % sectors, crunch);
            teleport_move(&mut sim, mo, tx, ty);
        }
    }
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_spawn_spot_queues_the_corpse_and_puts_fog_ahead_of_it() {
    use crate::wad::level::WadThing;
    let mut sim = sim(0, 128);
    let corpse = body(&mut sim, 200, 200);
    let fog = sim.kind_of(mt::TFOG);
    // Facing east: 20 * finecosine[0] = 20 * 65535 east, 20 * finesine[0] = 500 north.
    let east = WadThing { x: 64, y: 100, angle: 0, kind: 1, flags: 7 };
    assert!(check_spot(&mut sim, 0, Some(corpse), &east));
    let f = sim.mobjs.last().expect("the fog");
    assert_eq!((f.kind, f.x, f.y), (fog, Fixed(u(64).0 + 1_310_700), Fixed(u(100).0 + 500)));
    assert_eq!(sim.bodyque, [corpse]);
    // Facing west: vanilla's an is -4096, read from finetangent: x from
    // finetangent[2048], y from finetangent[0] = -170910304 (times 20, wrapping).
    let west = WadThing { angle: 180, ..east };
    assert!(check_spot(&mut sim, 0, Some(corpse), &west));
    let f = sim.mobjs.last().expect("the fog");
    let (xa, ya) = (crate::fixed::finetangent(2048).0, -170_910_304i32);
    assert_eq!((f.x, f.y), (Fixed(u(64).0 + xa * 20), Fixed(u(100).0.wrapping_add(ya.wrapping_mul(20)))));
    // A spot inside another body is refused, and nothing is queued.
    let blocked = WadThing { x: 200, y: 200, ..east };
    let other = body(&mut sim, 64, 40);
    assert!(!check_spot(&mut sim, 0, Some(other), &blocked));
    assert_eq!(sim.bodyque.len(), 2);
    // The level's first spawn: only an earlier player exactly there blocks.
    assert!(check_spot(&mut sim, 0, None, &blocked));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_charging_lost_soul_hits_for_1d8_times_3_and_stops() {
    let mut sim = sim(0, 128);
    let victim = body(&mut sim, 100, 100);
    let skull_kind = sim.kind_of(mt::SKULL);
    let skull = sim.spawn_mobj(u(40), u(100), u(20), skull_kind);
    sim.mo_mut(skull).flags |= mf::SKULLFLY;
    sim.mo_mut(skull).momx = u(20);
    // The next P_Random is the table's entry after the index.
    let next = crate::fixed::RNDTABLE[usize::from(sim.rng.p_index().wrapping_add(1))];
    let damage = (i32::from(next) % 8 + 1) * 3;
    // 10 units short of the victim: the boxes (16 + 16) overlap.
    assert!(!check_position(&mut sim, skull, u(90), u(100)));
    assert_eq!(sim.mo(victim).health, 100 - damage);
    let s = sim.mo(skull);
    assert!(!s.has(mf::SKULLFLY));
    assert_eq!((s.momx, s.momy, s.momz), (u(0), u(0), u(0)));
    assert_eq!(s.state, sim.info.things[skull_kind].spawnstate);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn an_imp_s_fireball_spares_imps_but_burns_others() {
    let mut sim = sim(0, 128);
    let imp_kind = sim.kind_of(mt::TROOP);
    let (imp, other_imp) =
        (sim.spawn_mobj(u(20), u(60), ONFLOORZ, imp_kind), sim.spawn_mobj(u(100), u(100), ONFLOORZ, imp_kind));
    let shot_kind = sim.kind_of(mt::TROOPSHOT);
    let shot = sim.spawn_mobj(u(70), u(100), u(20), shot_kind);
    sim.mo_mut(shot).target = Some(imp);
    let (index, health) = (sim.rng.p_index(), sim.mo(other_imp).health);
    // Same species: the shot stops (explodes) without a draw or damage.
    assert!(!check_position(&mut sim, shot, u(90), u(100)));
    assert_eq!((sim.rng.p_index(), sim.mo(other_imp).health), (index, health));
    // A body of another kind: 1d8 times the fireball's 3.
    let victim = body(&mut sim, 100, 200);
    let next = crate::fixed::RNDTABLE[usize::from(sim.rng.p_index().wrapping_add(1))];
    assert!(!check_position(&mut sim, shot, u(90), u(200)));
    assert_eq!(sim.mo(victim).health, 100 - (i32::from(next) % 8 + 1) * 3);
    // Over its head: untouched.
    sim.mo_mut(shot).z = u(60);
    assert!(check_position(&mut sim, shot, u(90), u(200)));
}

/// A missile of radius 0 (a DECORATE rocket's) passes a one-sided wall in
/// Doom (the line check tests only where a step ends); under Sightline's
/// rules it leaves the game at the wall instead of flying on outside the
/// map. A missile whose box touches the wall at the step's end explodes
/// there under both rules.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_missile_too_thin_for_its_step_leaves_the_game_at_a_wall_under_sightlines_rules() {
    let shot = |compat: Compat, x: i32, radius: i32| {
        let mut sim = sim(0, 128);
        sim.rules.compat = compat;
        let kind = sim.kind_of(mt::TROOPSHOT);
        let ball = sim.spawn_mobj(u(x), u(128), u(32), kind);
        let mo = sim.mo_mut(ball);
        mo.radius = u(radius);
        mo.momx = u(12);
        crate::sim::movement::xy_movement(&mut sim, ball);
        let mo = sim.mo(ball);
        (mo.removed, mo.x.to_f64(), mo.has(crate::sim::mobj::mf::MISSILE))
    };
    // From 250 the thin ball's step ends at 262, past the east wall (256).
    assert_eq!(shot(Compat::Vanilla, 250, 0), (false, 262.0, true), "Doom lets it through");
    assert_eq!(shot(Compat::Sightline, 250, 0).0, true, "Sightline's rules take it out");
    // A ball of radius 6 whose end box reaches the wall explodes there.
    for compat in [Compat::Vanilla, Compat::Sightline] {
        assert_eq!(shot(compat, 246, 6), (false, 246.0, false), "{compat:?}");
    }
}
