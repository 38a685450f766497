//! Doom's monster behaviours worked by hand: each test sets up bodies in
//! freedoom2's MAP01 (its level only; the monsters' own bodies are placed
//! here) and checks what `p_enemy.c` computes, `P_Random` draws included.
//! The draws come from Doom's table from index 0: 8, 109, 220, 222, 241,
//! 149, 107, 75, ...

use std::sync::Arc;

use crate::actors::ActorTable;
use crate::fixed::{finecosine, Angle, DoomRandom, Fixed, ANG45, ANG90, FRACUNIT};
use crate::sim::info::mt;
use crate::sim::mobj::mf;
use crate::sim::setup::Players;
use crate::sim::{GameMode, GameVersion, MobjId, Rules, Sim};

fn u(n: i32) -> Fixed {
    Fixed::from_int(n)
}

/// MAP01 of freedoom2 with one player and no monsters, `P_Random` at 0.
fn sim() -> Sim {
    let wad = crate::sim::test_wad("freedoom2.wad");
    let rules = Rules { no_monsters: true, ..Rules::single(3, GameVersion::Doom19, GameMode::Commercial) };
    let players = Players::first(1);
    let mut sim = Sim::new(&wad, "MAP01", rules, players, Arc::clone(ActorTable::doom())).expect("MAP01 loads");
    sim.rng = DoomRandom::new();
    sim
}

fn spawn(sim: &mut Sim, mt: usize, x: i32, y: i32) -> MobjId {
    let kind = sim.kind_of(mt);
    sim.spawn_mobj(u(x), u(y), Fixed::ZERO, kind)
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_lost_soul_charges_at_twenty_units_towards_the_target_s_middle() {
    let mut sim = sim();
    let skull = spawn(&mut sim, mt::SKULL, 0, 0);
    let target = spawn(&mut sim, mt::POSSESSED, 200, 0);
    sim.mo_mut(skull).target = Some(target);
    let before = sim.rng.p_index();
    super::super::attacks::skull_attack(&mut sim, skull);
    let s = sim.mo(skull);
    assert!(s.has(mf::SKULLFLY));
    assert_eq!(s.angle, Angle::ZERO);
    // Doom's tables sit half a step off: finecosine[0] is 65535 and
    // finesine[0] is 25.
    assert_eq!((s.momx, s.momy), (Fixed(20 * 65535), Fixed(20 * 25)));
    // 200 units at 20 a tic is 10 tics; the zombie's middle is 28 up:
    // 28 * 65536 / 10 = 183500 (C's division truncates).
    assert_eq!(s.momz, Fixed(183_500));
    assert_eq!(sim.rng.p_index(), before, "no P_Random in a charge at a visible target");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn facing_a_shadow_is_off_by_p_subrandom_shifted_21() {
    let mut sim = sim();
    let imp = spawn(&mut sim, mt::TROOP, 0, 0);
    let target = spawn(&mut sim, mt::SHADOWS, 100, 100);
    sim.mo_mut(imp).target = Some(target);
    sim.mo_mut(imp).flags |= mf::AMBUSH;
    sim.rng = DoomRandom::new();
    super::face_target(&mut sim, imp);
    // 45 degrees is tantoangle[2048], 0x1fff_ffff (one short of ANG45);
    // then (8 - 109) << 21 = -0x0ca0_0000.
    assert_eq!(sim.mo(imp).angle, Angle(ANG45.0 - 1 - 0x0ca0_0000));
    assert!(!sim.mo(imp).has(mf::AMBUSH), "facing ends an ambush");
    assert_eq!(sim.rng.p_index(), 2);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_chaser_turns_45_degrees_a_tic_towards_its_direction() {
    let mut sim = sim();
    let imp = spawn(&mut sim, mt::TROOP, 0, 0);
    // No target and a dead player: it looks, finds nobody, goes back to
    // its spawn state, but turns first.
    if let Some(p) = sim.players[0].as_mut() {
        p.health = 0;
    }
    let m = sim.mo_mut(imp);
    m.movedir = crate::sim::chase::DI_NORTH;
    m.angle = Angle(0x0123_4567); // the turn first snaps to a multiple of 45
    m.threshold = 5;
    m.reactiontime = 2;
    super::chase_target(&mut sim, imp);
    let m = sim.mo(imp);
    assert_eq!(m.angle, ANG45);
    assert_eq!(m.threshold, 0, "no target: the threshold is dropped");
    assert_eq!(m.reactiontime, 1);
    assert_eq!(m.state, sim.info.things[m.kind].spawnstate);
    super::chase_target(&mut sim, imp);
    assert_eq!(sim.mo(imp).angle, ANG90);
    super::chase_target(&mut sim, imp);
    assert_eq!(sim.mo(imp).angle, ANG90, "there: no more turning");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn looking_starts_from_lastlook_and_gives_up_at_the_stop() {
    let mut sim = sim();
    let imp = spawn(&mut sim, mt::TROOP, 0, 0);
    // lastlook 1 with only player 0: the walk reaches player 0 as the stop
    // (lastlook - 1) and gives up without a look; lastlook stays there.
    sim.mo_mut(imp).lastlook = 1;
    assert!(!super::look_for_players(&mut sim, imp, true));
    assert_eq!(sim.mo(imp).lastlook, 0);
    // From 0 a dead player is passed over until the third visit.
    if let Some(p) = sim.players[0].as_mut() {
        p.health = 0;
    }
    assert!(!super::look_for_players(&mut sim, imp, true));
    assert_eq!(sim.mo(imp).lastlook, 0);
    assert_eq!(sim.mo(imp).target, None);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_homing_missile_turns_by_traceangle_and_climbs_an_eighth_on_every_fourth_tic() {
    let mut sim = sim();
    let tracer = spawn(&mut sim, mt::TRACER, 0, 0);
    let dest = spawn(&mut sim, mt::POSSESSED, 0, 1000);
    sim.mo_mut(tracer).tracer = Some(dest);
    sim.gametic = 1;
    let call =
        crate::actors::ActionCall { action: crate::actors::actions::find("A_Tracer").expect("A_Tracer"), args: vec![] };
    super::action(&mut sim, tracer, "A_Tracer", &call);
    assert_eq!(sim.mo(tracer).angle, Angle::ZERO, "gametic 1: nothing");
    sim.gametic = 4;
    super::action(&mut sim, tracer, "A_Tracer", &call);
    let m = sim.mo(tracer);
    // Due north is 90 degrees away: one TRACEANGLE step, 16.875 degrees,
    // fine angle 384.
    assert_eq!(m.angle, Angle(0x0c00_0000));
    assert_eq!(m.momx, u(10) * finecosine(384));
    // 1000 units at 10 a tic: 100 tics; (40 units up) / 100 = 26214 is
    // above momz 0, so it climbs by 1/8.
    assert_eq!(m.momz, Fixed(FRACUNIT / 8));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn noise_floods_open_lines_and_stops_at_the_second_sound_block() {
    use crate::sim::level::ml;
    let mut sim = sim();
    let player = sim.players[0].as_ref().map(|p| p.mo).expect("player 0");
    // Sectors 0-1 open, 1-2 across one sound-blocking line, 2-3 across
    // another, 0-4 a closed door (no opening), 5 unconnected.
    let template_sector = sim.level.sectors[0].clone();
    let mut sectors = vec![template_sector; 6];
    for s in &mut sectors {
        s.floorheight = u(0);
        s.ceilingheight = u(128);
        s.soundtarget = None;
        s.soundtraversed = 0;
        s.lines.clear();
    }
    sectors[4].ceilingheight = u(0);
    let template_side = sim.level.sides[0].clone();
    let template_line = sim.level.lines[0].clone();
    let mut sides = Vec::new();
    let mut lines = Vec::new();
    for (a, b, flags) in [(0, 1, 0), (1, 2, ml::SOUNDBLOCK), (2, 3, ml::SOUNDBLOCK), (0, 4, 0)] {
        let mut line = template_line.clone();
        line.flags = ml::TWOSIDED | flags;
        line.frontsector = Some(a);
        line.backsector = Some(b);
        line.sidenum = [Some(sides.len()), Some(sides.len() + 1)];
        for s in [a, b] {
            let mut side = template_side.clone();
            side.sector = s;
            sides.push(side);
            sectors[s].lines.push(lines.len());
        }
        lines.push(line);
    }
    sim.level.sectors = sectors;
    sim.level.sides = sides;
    sim.level.lines = lines;
    let sub = sim.mo(player).subsector;
    sim.level.subsectors[sub].sector = 0;
    super::noise_alert(&mut sim, player, player);
    let heard: Vec<(i32, bool)> =
        sim.level.sectors.iter().map(|s| (s.soundtraversed, s.soundtarget == Some(player))).collect();
    assert_eq!(heard, [(1, true), (1, true), (2, true), (0, false), (0, false), (0, false)]);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_pain_elemental_spits_no_skull_when_more_than_twenty_are_about() {
    let mut sim = sim();
    let pain = spawn(&mut sim, mt::PAIN, 0, 0);
    let target = spawn(&mut sim, mt::POSSESSED, 500, 0);
    sim.mo_mut(pain).target = Some(target);
    for n in 0..21 {
        spawn(&mut sim, mt::SKULL, 1000 + 64 * n, 0);
    }
    let bodies = sim.mobjs.len();
    let call = crate::actors::ActionCall {
        action: crate::actors::actions::find("A_PainAttack").expect("A_PainAttack"),
        args: vec![],
    };
    let index = sim.rng.p_index();
    super::action(&mut sim, pain, "A_PainAttack", &call);
    assert_eq!(sim.mobjs.len(), bodies);
    assert_eq!(sim.rng.p_index(), index);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn the_brain_s_explosion_draws_five_randoms_around_its_spawn() {
    let mut sim = sim();
    let brain = spawn(&mut sim, mt::BOSSBRAIN, 0, 0);
    sim.rng = DoomRandom::new();
    let call = crate::actors::ActionCall {
        action: crate::actors::actions::find("A_BrainExplode").expect("A_BrainExplode"),
        args: vec![],
    };
    let first = sim.mobjs.len();
    // No explosion argument: the rocket's own spawn state stands in; the
    // draws are the same.
    super::action(&mut sim, brain, "A_BrainExplode", &call);
    let boom = sim.mo(MobjId(first as u32));
    // x: (8 - 109) * 2048; z: 128 + 220 * 2 * FRACUNIT; the spawn's
    // lastlook takes 222; momz 241 * 512; tics less 149 & 7 = 5.
    assert_eq!(boom.x, Fixed(-101 * 2048));
    assert_eq!(boom.z, Fixed(128 + 440 * FRACUNIT));
    assert_eq!(boom.momz, Fixed(241 * 512));
    assert!(sim.is(MobjId(first as u32), mt::ROCKET));
    assert_eq!(sim.rng.p_index(), 6);
}

/// MAP01's first room runs from x -224 to -32 and y -256 to about -100;
/// player 1 starts at (-192, -160).
fn room_imp(sim: &mut Sim, x: i32, y: i32) -> MobjId {
    let imp = spawn(sim, mt::TROOP, x, y);
    let floor = sim.mo(imp).floorz;
    sim.mo_mut(imp).z = floor;
    imp
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_chaser_takes_the_diagonal_when_it_is_clear() {
    let mut sim = sim();
    let imp = room_imp(&mut sim, -180, -220);
    let player = sim.players[0].as_ref().map(|p| p.mo).expect("player 0");
    sim.mo_mut(imp).target = Some(player);
    sim.mo_mut(imp).movedir = crate::sim::chase::DI_NODIR;
    sim.rng = DoomRandom::new();
    crate::sim::chase::new_chase_dir(&mut sim, imp);
    let m = sim.mo(imp);
    // The player is 12 west and 60 north: north-west, 8 units a step of
    // 47000 (cos 45) each way; then P_Random() & 15 = 8 steps.
    assert_eq!(m.movedir, crate::sim::chase::DI_NORTHWEST);
    assert_eq!((m.x, m.y), (Fixed(-180 * FRACUNIT - 8 * 47000), Fixed(-220 * FRACUNIT + 8 * 47000)));
    assert_eq!(m.movecount, 8);
    assert_eq!(sim.rng.p_index(), 1);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_chaser_against_a_wall_tries_the_longer_axis_first() {
    let mut sim = sim();
    // Against the west wall (x -224, radius 20): the diagonal is blocked
    // (and clear of the player, who would block the way north).
    let imp = room_imp(&mut sim, -203, -230);
    let target = spawn(&mut sim, mt::POSSESSED, -250, -170);
    sim.mo_mut(imp).target = Some(target);
    sim.mo_mut(imp).movedir = crate::sim::chase::DI_NODIR;
    sim.rng = DoomRandom::new();
    crate::sim::chase::new_chase_dir(&mut sim, imp);
    let m = sim.mo(imp);
    // 47 west and 60 north: P_Random() = 8 is not above 200, but north is
    // the longer way, so it comes first and is clear; the steps are 109 & 15.
    assert_eq!(m.movedir, crate::sim::chase::DI_NORTH);
    assert_eq!((m.x, m.y), (u(-203), u(-222)));
    assert_eq!(m.movecount, 13);
    assert_eq!(sim.rng.p_index(), 2);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn the_missile_range_check_draws_against_the_distance() {
    let mut sim = sim();
    let imp = room_imp(&mut sim, -100, -200);
    let player = sim.players[0].as_ref().map(|p| p.mo).expect("player 0");
    sim.mo_mut(imp).target = Some(player);
    sim.mo_mut(imp).reactiontime = 0;
    sim.rng = DoomRandom::new();
    // 92 east and 40 south: P_AproxDistance 92 + 40 - 20 = 112, less 64
    // for an imp (it has a melee attack): 48. P_Random 8 < 48: no; then
    // 109: yes.
    assert!(!super::check_missile_range(&mut sim, imp));
    assert!(super::check_missile_range(&mut sim, imp));
    // Just hit: fight back without a draw, once.
    sim.mo_mut(imp).flags |= mf::JUSTHIT;
    assert!(super::check_missile_range(&mut sim, imp));
    assert!(!sim.mo(imp).has(mf::JUSTHIT));
    assert_eq!(sim.rng.p_index(), 2);
    // Not yet able to react: no, without a draw.
    sim.mo_mut(imp).reactiontime = 3;
    assert!(!super::check_missile_range(&mut sim, imp));
    assert_eq!(sim.rng.p_index(), 2);
}

fn call(name: &str) -> crate::actors::ActionCall {
    crate::actors::ActionCall { action: crate::actors::actions::find(name).expect("a registered action"), args: vec![] }
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn an_arch_vile_raises_a_corpse_touching_its_next_step() {
    let mut sim = sim();
    let vile = room_imp(&mut sim, -150, -200);
    let vile_kind = sim.kind_of(mt::VILE);
    sim.mo_mut(vile).kind = vile_kind;
    sim.mo_mut(vile).movedir = crate::sim::chase::DI_EAST;
    let player = sim.players[0].as_ref().map(|p| p.mo).expect("player 0");
    sim.mo_mut(vile).target = Some(player);
    // A zombie's corpse at rest 45 units east: the vile's step of 15
    // lands 30 from it, within the two radii (20 + 20).
    let corpse = room_imp(&mut sim, -105, -200);
    let zombie = sim.kind_of(mt::POSSESSED);
    let info = sim.info.things[zombie].clone();
    let c = sim.mo_mut(corpse);
    c.kind = zombie;
    c.flags = (info.flags | mf::CORPSE | mf::DROPOFF) & !(mf::SOLID | mf::SHOOTABLE);
    c.tics = -1;
    c.health = 0;
    c.height = info.height >> 2;
    c.target = Some(vile);
    super::action(&mut sim, vile, "A_VileChase", &call("A_VileChase"));
    let c = sim.mo(corpse);
    assert_eq!(c.state, info.raisestate);
    assert_eq!((c.health, c.flags, c.height, c.target), (info.spawnhealth, info.flags, info.height, None));
    let heal = sim.info.table.actors[vile_kind].label("Heal");
    assert!(heal.is_some());
    assert_eq!(sim.mo(vile).state, heal);
    assert_eq!(sim.mo(vile).angle, Angle::ZERO, "it faced the corpse, due east");
    assert_eq!(sim.mo(vile).target, Some(player), "and kept its target");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_boss_death_ends_only_its_own_episode_s_map() {
    let mut sim = sim();
    sim.rules.mode = GameMode::Retail;
    sim.rules.version = GameVersion::Ultimate;
    sim.level.name = "E2M8".into();
    let baron = spawn(&mut sim, mt::BRUISER, 0, 0);
    let cyber = spawn(&mut sim, mt::CYBORG, 300, 0);
    let other = spawn(&mut sim, mt::CYBORG, 600, 0);
    sim.mo_mut(baron).health = 0;
    sim.mo_mut(cyber).health = 0;
    // The Ultimate Doom: a baron means nothing on E2M8; the cyberdemon
    // does, once the other one is dead too.
    super::action(&mut sim, baron, "A_BossDeath", &call("A_BossDeath"));
    super::action(&mut sim, cyber, "A_BossDeath", &call("A_BossDeath"));
    assert_eq!(sim.exit, None, "another cyberdemon lives");
    sim.mo_mut(other).health = -5;
    super::action(&mut sim, cyber, "A_BossDeath", &call("A_BossDeath"));
    assert_eq!(sim.exit, Some(false));
    // Doom 1.9 before it: any boss on map 8 but a baron off episode 1.
    sim.exit = None;
    sim.rules.version = GameVersion::Doom19;
    super::action(&mut sim, baron, "A_BossDeath", &call("A_BossDeath"));
    assert_eq!(sim.exit, None);
    let spider = spawn(&mut sim, mt::SPIDER, 900, 0);
    sim.mo_mut(spider).health = 0;
    super::action(&mut sim, spider, "A_BossDeath", &call("A_BossDeath"));
    assert_eq!(sim.exit, Some(false));
    // No one alive: no victory.
    sim.exit = None;
    if let Some(p) = sim.players[0].as_mut() {
        p.health = 0;
    }
    super::action(&mut sim, spider, "A_BossDeath", &call("A_BossDeath"));
    assert_eq!(sim.exit, None);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn the_brain_spits_cubes_at_its_spots_in_turn_every_other_time_on_easy() {
    let mut sim = sim();
    let brain = room_imp(&mut sim, -150, -240);
    let brain_kind = sim.kind_of(mt::BOSSBRAIN);
    sim.mo_mut(brain).kind = brain_kind;
    let first = spawn(&mut sim, mt::BOSSTARGET, -150, 760);
    let second = spawn(&mut sim, mt::BOSSTARGET, 500, 500);
    super::action(&mut sim, brain, "A_BrainAwake", &call("A_BrainAwake"));
    assert_eq!(sim.brain.targets, [first, second]);
    let bodies = sim.mobjs.len();
    super::action(&mut sim, brain, "A_BrainSpit", &call("A_BrainSpit"));
    let cube = MobjId(bodies as u32);
    assert!(sim.is(cube, mt::SPAWNSHOT));
    let c = sim.mo(cube);
    assert_eq!(c.target, Some(first));
    // Due north (ANG90 - 1, fine angle 2047) at 10 a tic: 1000 units take
    // 1000 * 65536 / momy tics, over the state's 3 tics a frame.
    assert_eq!(c.momy, u(10) * crate::fixed::finesine(2047));
    assert_eq!(c.reactiontime, (1000 * FRACUNIT / c.momy.0) / 3);
    assert_eq!(sim.brain.target_on, 1);
    // On the easy skills only every other call spits.
    sim.rules.skill = 1;
    let bodies = sim.mobjs.len();
    super::action(&mut sim, brain, "A_BrainSpit", &call("A_BrainSpit"));
    assert_eq!(sim.mobjs.len(), bodies, "easy turned off: no cube");
    super::action(&mut sim, brain, "A_BrainSpit", &call("A_BrainSpit"));
    assert!(sim.mobjs.len() > bodies);
    assert_eq!(sim.brain.target_on, 0, "back to the first spot");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_cube_at_its_spot_becomes_fire_and_a_monster_by_p_random() {
    let mut sim = sim();
    let spot = spawn(&mut sim, mt::BOSSTARGET, -150, -200);
    let cube = spawn(&mut sim, mt::SPAWNSHOT, -150, -180);
    sim.mo_mut(cube).target = Some(spot);
    sim.mo_mut(cube).reactiontime = 2;
    super::action(&mut sim, cube, "A_SpawnFly", &call("A_SpawnFly"));
    assert!(!sim.mo(cube).removed, "still flying");
    sim.rng = DoomRandom::new();
    let bodies = sim.mobjs.len();
    super::action(&mut sim, cube, "A_SpawnFly", &call("A_SpawnFly"));
    assert!(sim.mo(cube).removed);
    // The fire's spawn draws 8; then 109 picks the monster (90..120: a
    // spectre).
    let fire = MobjId(bodies as u32);
    let monster = MobjId(bodies as u32 + 1);
    assert!(sim.is(fire, mt::SPAWNFIRE));
    assert!(sim.is(monster, mt::SHADOWS));
    // It looked all round, saw the player and went into its see state,
    // whose A_Chase took a first step (10 units) from the spot.
    let player = sim.players[0].as_ref().map(|p| p.mo);
    assert_eq!(sim.mo(monster).target, player);
    let m = sim.mo(monster);
    let moved = crate::fixed::approx_distance(m.x - u(-150), m.y - u(-200));
    assert_eq!(moved, u(10));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_mancubus_spreads_its_fireballs_by_fatspread() {
    use crate::fixed::finesine;
    let mut sim = sim();
    let fatso = room_imp(&mut sim, -150, -200);
    let fatso_kind = sim.kind_of(mt::FATSO);
    sim.mo_mut(fatso).kind = fatso_kind;
    let target = spawn(&mut sim, mt::POSSESSED, -50, -200);
    sim.mo_mut(fatso).target = Some(target);
    let spread = 0x0800_0000u32; // FATSPREAD, ANG90 / 8
    for (name, body, first, second) in [
        ("A_FatAttack1", spread, 0, spread),
        ("A_FatAttack2", spread.wrapping_neg(), 0, (2 * spread).wrapping_neg()),
        ("A_FatAttack3", 0, (spread / 2).wrapping_neg(), spread / 2),
    ] {
        let bodies = sim.mobjs.len() as u32;
        super::action(&mut sim, fatso, name, &call(name));
        // Each missile aims at the target itself (due east, angle 0); the
        // second, or both in the third attack, are turned after.
        assert_eq!(sim.mo(fatso).angle, Angle(body), "{name}: the body");
        for (n, angle) in [(0, first), (1, second)] {
            let m = sim.mo(MobjId(bodies + n));
            assert!(sim.is(MobjId(bodies + n), mt::FATSHOT));
            assert_eq!(m.angle, Angle(angle), "{name}: missile {n}");
            let fine = Angle(angle).fine_index();
            assert_eq!((m.momx, m.momy), (u(20) * finecosine(fine), u(20) * finesine(fine)), "{name}: missile {n}");
        }
    }
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_dying_pain_elemental_spits_three_skulls_one_through_a_wall() {
    let mut sim = sim();
    let pain = room_imp(&mut sim, -150, -200);
    let pain_kind = sim.kind_of(mt::PAIN);
    sim.mo_mut(pain).kind = pain_kind;
    let player = sim.players[0].as_ref().map(|p| p.mo).expect("player 0");
    sim.mo_mut(pain).target = Some(player);
    let bodies = sim.mobjs.len() as u32;
    super::action(&mut sim, pain, "A_PainDie", &call("A_PainDie"));
    assert!(!sim.mo(pain).has(mf::SOLID), "A_Fall first");
    let skulls: Vec<MobjId> = (bodies..sim.mobjs.len() as u32).map(MobjId).filter(|&m| sim.is(m, mt::SKULL)).collect();
    assert_eq!(skulls.len(), 3);
    // 4 + 1.5 * (31 + 16) = 74.5 units out. North lands in the room and
    // flies at the player. West (x -224.5) straddles the wall at x -224
    // and is killed at once. South (y -274.5) is wholly past the wall at
    // y -256, touching no line, so P_TryMove lets it be: Doom's lost souls
    // spat through walls.
    let north = sim.mo(skulls[0]);
    assert_eq!(north.target, Some(player));
    assert!(north.has(mf::SKULLFLY));
    assert!(north.health > 0);
    assert!(sim.mo(skulls[1]).health <= 0, "the skull in the west wall dies");
    let south = sim.mo(skulls[2]);
    assert!(south.health > 0 && south.y < u(-256), "the skull past the south wall lives");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_pain_elemental_s_skull_starts_74_and_a_half_units_out() {
    let mut sim = sim();
    let pain = room_imp(&mut sim, -150, -200);
    let pain_kind = sim.kind_of(mt::PAIN);
    sim.mo_mut(pain).kind = pain_kind;
    let target = spawn(&mut sim, mt::POSSESSED, -20, -200);
    sim.mo_mut(pain).target = Some(target);
    let bodies = sim.mobjs.len() as u32;
    super::action(&mut sim, pain, "A_PainAttack", &call("A_PainAttack"));
    let skull = MobjId(bodies);
    assert!(sim.is(skull, mt::SKULL));
    // prestep 4882432 times finecosine[0] = 65535 and finesine[0] = 25.
    let s = sim.mo(skull);
    assert_eq!((s.x, s.y), (u(-150) + Fixed(4_882_357), u(-200) + Fixed(1862)));
    assert_eq!(s.z, sim.mo(pain).z + u(8));
    assert_eq!(s.target, Some(target));
    assert!(s.has(mf::SKULLFLY));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn an_arch_vile_s_fire_stands_in_front_of_the_target_then_blasts_it_up() {
    let mut sim = sim();
    let vile = room_imp(&mut sim, -150, -200);
    let vile_kind = sim.kind_of(mt::VILE);
    sim.mo_mut(vile).kind = vile_kind;
    let player = sim.players[0].as_ref().map(|p| p.mo).expect("player 0");
    sim.mo_mut(vile).target = Some(player);
    let bodies = sim.mobjs.len() as u32;
    super::action(&mut sim, vile, "A_VileTarget", &call("A_VileTarget"));
    let fire = MobjId(bodies);
    assert!(sim.is(fire, mt::FIRE));
    assert_eq!(sim.mo(vile).tracer, Some(fire));
    assert_eq!((sim.mo(fire).target, sim.mo(fire).tracer), (Some(vile), Some(player)));
    // 24 units in front of the player (facing east): 24 * 65535 and
    // 24 * 25 in 16.16.
    let (px, py, pz) = (sim.mo(player).x, sim.mo(player).y, sim.mo(player).z);
    let f = sim.mo(fire);
    assert_eq!((f.x, f.y, f.z), (px + Fixed(1_572_840), py + Fixed(600), pz));
    super::action(&mut sim, vile, "A_VileAttack", &call("A_VileAttack"));
    // Blasted up by 1000 / mass (the player's 100): 10 units a tic.
    assert_eq!(sim.mo(player).momz, u(10));
    // The fire moved between them, 24 units short of the player, and
    // exploded: 20 from the attack and more from the blast.
    let an = sim.mo(vile).angle;
    let f = sim.mo(fire);
    assert_eq!((f.x, f.y), (px - u(24) * an.cos(), py - u(24) * an.sin()));
    assert!(sim.players[0].as_ref().is_some_and(|p| p.health < 80));
}
