//! Hand-worked checks of the player, bodies' movement, weapons, damage and
//! pickups (`p_user.c`, `p_mobj.c`, `p_pspr.c`, `p_inter.c`) on Freedoom
//! 2's MAP01 with one player and no monsters. The player starts at
//! (-192, -160) facing east, with 160 units of open floor ahead.
//!
//! The numbers come from Doom's formulas worked by hand: a run's thrust
//! is `forwardmove * 2048` = 102400 times `finecosine[0]` (65535, the
//! table's value, not 65536) = 102398 a tic, friction keeps
//! `FixedMul(m, 0xe800)`, gravity adds one unit a tic after a first two.

use crate::actors::ActorTable;
use crate::fixed::Fixed;
use crate::play::lmp::{buttons, Ticcmd};
use crate::sim::interaction::pickups::{give_ammo, give_armor};
use crate::sim::interaction::{damage_mobj, touch_special_thing};
use crate::sim::movement::{mobj_thinker, FRICTION, STOPSPEED};
use crate::sim::setup::{Players, VIEWHEIGHT};
use crate::sim::weapons::{WEAPONBOTTOM, WEAPONTOP};
use crate::sim::{mobj::mf, GameMode, GameVersion, MobjId, PlayerState, Rules, Sim, MAXPLAYERS};

fn game() -> Sim {
    let wad = crate::sim::test_wad("freedoom2.wad");
    let rules = Rules { no_monsters: true, ..Rules::single(2, GameVersion::Doom19, GameMode::Commercial) };
    let mut in_game = [false; MAXPLAYERS];
    in_game[0] = true;
    let players = Players { in_game, console: 0 };
    Sim::new(&wad, "MAP01", rules, players, ActorTable::doom().clone()).expect("MAP01 loads")
}

fn tick(sim: &mut Sim, cmd: Ticcmd) {
    let mut cmds = [None; MAXPLAYERS];
    cmds[0] = Some(cmd);
    sim.tick(&cmds);
}

fn run() -> Ticcmd {
    Ticcmd { forward: 50, ..Ticcmd::default() }
}

fn player_body(sim: &Sim) -> MobjId {
    sim.player(0).expect("player 1 is in the game").mo
}

/// The table's kind for Doom's `MT_CLIP`.
fn clip_kind(sim: &Sim) -> usize {
    let mt = crate::actors::dehacked::doom_info().thing("MT_CLIP").expect("Doom has MT_CLIP");
    sim.kind_of(mt)
}

fn u(n: i32) -> Fixed {
    Fixed::from_int(n)
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn running_east_builds_momentum_less_friction() {
    let mut sim = game();
    let id = player_body(&sim);
    assert_eq!((sim.mo(id).x, sim.mo(id).y, sim.mo(id).angle.0), (u(-192), u(-160), 0));
    // (x moved, y moved, momx, momy) after each tic, from the rest.
    let expected = [(102398, 39, 92798, 35), (297594, 113, 176896, 67), (576888, 219, 253110, 96)];
    for (x, y, momx, momy) in expected {
        tick(&mut sim, run());
        let mo = sim.mo(id);
        assert_eq!((mo.x - u(-192), mo.y - u(-160)), (Fixed(x), Fixed(y)));
        assert_eq!((mo.momx, mo.momy), (Fixed(momx), Fixed(momy)));
    }
    // The running frames began with the first step.
    assert_ne!(sim.mo(id).state, sim.info.things[sim.mo(id).kind].spawnstate);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_player_coasts_until_below_stopspeed_then_stands() {
    let mut sim = game();
    let id = player_body(&sim);
    for _ in 0..3 {
        tick(&mut sim, run());
    }
    let mut momx = Fixed(253110);
    let mut tics = 0;
    while momx >= STOPSPEED {
        tick(&mut sim, Ticcmd::default());
        momx = momx * FRICTION;
        tics += 1;
        assert_eq!(sim.mo(id).momx, momx, "coasting tic {tics}");
    }
    // 253110 * 0.90625^n falls under 4096 after 42 tics.
    assert_eq!(tics, 42);
    // Below STOPSPEED with no command: the next tic stops it dead and it
    // stands (S_PLAY).
    tick(&mut sim, Ticcmd::default());
    assert_eq!((sim.mo(id).momx, sim.mo(id).momy), (Fixed::ZERO, Fixed::ZERO));
    assert_eq!(sim.mo(id).state, sim.info.things[sim.mo(id).kind].spawnstate);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn the_view_bobs_by_the_speed_and_leveltime() {
    let mut sim = game();
    let id = player_body(&sim);
    tick(&mut sim, run());
    // P_CalcHeight ran after the thrust, before the move: bob =
    // (FixedMul(102398, 102398) + FixedMul(39, 39)) >> 2 = 39998, and at
    // leveltime 0 the view moves FixedMul(39998 / 2, finesine[0] = 25) = 7.
    let p = sim.player(0).expect("player");
    assert_eq!(p.bob, Fixed(39998));
    assert_eq!(p.viewz - sim.mo(id).z, VIEWHEIGHT + Fixed(7));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn the_pistol_comes_up_six_units_a_tic_then_is_ready() {
    let mut sim = game();
    let pistol = sim.info.weapons[1].clone().expect("the pistol");
    // P_SetupPsprites put it at the bottom and its first A_Raise ran.
    let sy = |sim: &Sim| sim.player(0).expect("player").psprites[0].sy;
    assert_eq!(sy(&sim), WEAPONBOTTOM - u(6));
    for _ in 0..14 {
        tick(&mut sim, Ticcmd::default());
    }
    assert_eq!(sy(&sim), u(38));
    assert_eq!(sim.player(0).expect("player").psprites[0].state, pistol.upstate);
    tick(&mut sim, Ticcmd::default());
    let p = sim.player(0).expect("player");
    assert_eq!(p.psprites[0].state, pistol.readystate);
    // A_WeaponReady's bob with a still body: sx 1.0, sy WEAPONTOP.
    assert_eq!((p.psprites[0].sx, p.psprites[0].sy), (Fixed::ONE, WEAPONTOP));
    assert!(!p.attackdown, "A_WeaponReady saw the trigger released");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn the_pistol_fires_on_its_second_attack_frame() {
    let mut sim = game();
    let id = player_body(&sim);
    for _ in 0..15 {
        tick(&mut sim, Ticcmd::default());
    }
    let fire = Ticcmd { buttons: buttons::ATTACK, ..Ticcmd::default() };
    let info = sim.info.things[sim.mo(id).kind].clone();
    let pistol = sim.info.weapons[1].clone().expect("the pistol");
    tick(&mut sim, fire);
    // P_FireWeapon: the body's S_PLAY_ATK1, the weapon's first attack
    // frame (PISG A, 4 tics, no action yet).
    assert_eq!(sim.mo(id).state, info.missilestate);
    assert_eq!(sim.player(0).expect("player").psprites[0].state, pistol.atkstate);
    for _ in 0..3 {
        tick(&mut sim, fire);
    }
    assert_eq!(sim.player(0).expect("player").ammo[0], 50);
    tick(&mut sim, fire);
    // A_FirePistol: one bullet spent, S_PLAY_ATK2, the flash up.
    let p = sim.player(0).expect("player");
    assert_eq!(p.ammo[0], 49);
    assert_eq!(sim.mo(id).state, info.meleestate);
    assert_eq!(p.psprites[1].state, pistol.flashstate);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_weapon_change_is_made_pending_for_the_sprite_to_carry_out() {
    let mut sim = game();
    // BT_CHANGE with weapon 0 (the fist).
    tick(&mut sim, Ticcmd { buttons: buttons::CHANGE, ..Ticcmd::default() });
    assert_eq!(sim.player(0).expect("player").pendingweapon, Some(0));
    // A weapon not owned is ignored.
    let mut sim = game();
    tick(&mut sim, Ticcmd { buttons: buttons::CHANGE | (3 << buttons::WEAPON_SHIFT), ..Ticcmd::default() });
    assert_eq!(sim.player(0).expect("player").pendingweapon, None);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_body_in_the_air_falls_by_gravity_and_lands() {
    let mut sim = game();
    let clip = clip_kind(&sim);
    let id = sim.spawn_mobj(u(-128), u(-200), crate::sim::mobj::ONFLOORZ, clip);
    let floor = sim.mo(id).floorz;
    sim.mo_mut(id).z = floor + u(40);
    // momz: 0, then -2 (the first tic in the air), then one unit more a tic.
    for height in [40, 38, 35, 31, 26, 20, 13, 5] {
        mobj_thinker(&mut sim, id);
        assert_eq!(sim.mo(id).z - floor, u(height));
    }
    mobj_thinker(&mut sim, id);
    assert_eq!((sim.mo(id).z, sim.mo(id).momz), (floor, Fixed::ZERO));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_sliding_item_loses_friction_each_tic_until_it_stops() {
    let mut sim = game();
    let clip = clip_kind(&sim);
    let id = sim.spawn_mobj(u(-128), u(-200), crate::sim::mobj::ONFLOORZ, clip);
    sim.mo_mut(id).momx = Fixed::ONE;
    // 1.0 * 0.90625 = 59392; 59392 * 0.90625 = 53824; then 48778.
    for (moved, momx) in [(65536, 59392), (124928, 53824), (178752, 48778)] {
        mobj_thinker(&mut sim, id);
        assert_eq!((sim.mo(id).x - u(-128), sim.mo(id).momx), (Fixed(moved), Fixed(momx)));
    }
    for _ in 0..40 {
        mobj_thinker(&mut sim, id);
    }
    assert_eq!(sim.mo(id).momx, Fixed::ZERO);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn green_armor_takes_a_third_of_the_damage() {
    let mut sim = game();
    let id = player_body(&sim);
    if let Some(p) = sim.players[0].as_mut() {
        p.armortype = 1;
        p.armorpoints = 100;
    }
    damage_mobj(&mut sim, id, None, None, 10);
    let p = sim.player(0).expect("player");
    // 10 / 3 = 3 saved.
    assert_eq!((p.health, p.armorpoints, p.damagecount), (93, 97, 7));
    assert_eq!(sim.mo(id).health, 93);
    assert_eq!((sim.mo(id).momx, sim.mo(id).momy), (Fixed::ZERO, Fixed::ZERO));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_hit_pushes_the_body_away_from_what_hit_it() {
    let mut sim = game();
    let id = player_body(&sim);
    let clip = clip_kind(&sim);
    let from = sim.spawn_mobj(u(-220), u(-160), crate::sim::mobj::ONFLOORZ, clip);
    damage_mobj(&mut sim, id, Some(from), None, 10);
    // Thrust 10 * (FRACUNIT >> 3) * 100 / mass 100 = 81920 due east:
    // FixedMul(81920, 65535) = 81918, FixedMul(81920, 25) = 31.
    assert_eq!((sim.mo(id).momx, sim.mo(id).momy), (Fixed(81918), Fixed(31)));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_killing_blow_lays_the_player_down() {
    let mut sim = game();
    let id = player_body(&sim);
    let down = sim.info.weapons[1].clone().expect("the pistol").downstate;
    let before = sim.rng.p_index();
    damage_mobj(&mut sim, id, None, None, 200);
    let p = sim.player(0).expect("player");
    assert_eq!((p.health, p.playerstate, p.frags[0]), (0, PlayerState::Dead, 1));
    assert_eq!(p.psprites[0].state, down);
    let mo = sim.mo(id);
    assert!(mo.has(mf::CORPSE | mf::DROPOFF) && !mo.has(mf::SHOOTABLE) && !mo.has(mf::SOLID));
    assert_eq!(mo.height, u(14));
    // -100 is not below -spawnhealth: the plain death, and its tics draw
    // is the only P_Random (no pain check for a kill).
    assert_eq!(mo.state, sim.info.things[mo.kind].deathstate);
    assert_eq!(sim.rng.p_index(), before.wrapping_add(1));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_clip_gives_ten_bullets_and_a_dropped_one_five() {
    let mut sim = game();
    let id = player_body(&sim);
    let clip = clip_kind(&sim);
    let (x, y) = (sim.mo(id).x, sim.mo(id).y);
    let item = sim.spawn_mobj(x, y, crate::sim::mobj::ONFLOORZ, clip);
    touch_special_thing(&mut sim, item, id);
    let p = sim.player(0).expect("player");
    assert_eq!((p.ammo[0], p.bonuscount), (60, 6));
    assert_eq!(p.message.as_deref(), Some("Picked up a clip."));
    assert!(sim.mo(item).removed);
    let item = sim.spawn_mobj(x, y, crate::sim::mobj::ONFLOORZ, clip);
    sim.mo_mut(item).flags |= mf::DROPPED;
    touch_special_thing(&mut sim, item, id);
    assert_eq!(sim.player(0).expect("player").ammo[0], 65);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn ammo_found_with_none_left_brings_out_a_gun() {
    let sim = game();
    let mut p = sim.player(0).expect("player").clone();
    p.readyweapon = 0;
    p.ammo[0] = 0;
    p.pendingweapon = None;
    assert!(give_ammo(&mut p, 0, 1, false));
    assert_eq!((p.ammo[0], p.pendingweapon), (10, Some(1)));
    // Doubled on the easiest and hardest skills; capped at the most carried.
    assert!(give_ammo(&mut p, 0, 1, true));
    assert_eq!(p.ammo[0], 30);
    p.ammo[0] = 195;
    assert!(give_ammo(&mut p, 0, 5, false));
    assert_eq!(p.ammo[0], 200);
    assert!(!give_ammo(&mut p, 0, 1, false), "full");
    // Armor: class 1 is 100 points, and not taken over as much.
    assert!(give_armor(&mut p, 1));
    assert_eq!((p.armortype, p.armorpoints), (1, 100));
    assert!(!give_armor(&mut p, 1));
    assert!(give_armor(&mut p, 2));
    assert_eq!(p.armorpoints, 200);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_charging_skull_bounces_off_the_floor_only_from_the_ultimate_doom_on() {
    for (version, momz) in [(GameVersion::Doom19, 0), (GameVersion::Ultimate, 4)] {
        let mut sim = game();
        sim.rules.version = version;
        let skull = sim.kind_of(crate::sim::info::mt::SKULL);
        let id = sim.spawn_mobj(u(-128), u(-200), crate::sim::mobj::ONFLOORZ, skull);
        let floor = sim.mo(id).floorz;
        let mo = sim.mo_mut(id);
        mo.flags |= mf::SKULLFLY;
        mo.z = floor + u(2);
        mo.momz = u(-4);
        crate::sim::movement::z_movement(&mut sim, id);
        // 1.9 stops the fall and then negates a zero; Ultimate negates
        // the fall first, and the skull climbs away.
        assert_eq!((sim.mo(id).z, sim.mo(id).momz), (floor, u(momz)), "{version:?}");
    }
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_rocket_with_nothing_to_aim_at_flies_level_and_straight() {
    let mut sim = game();
    let id = player_body(&sim);
    let rocket = sim.kind_of(crate::sim::info::mt::ROCKET);
    let before = sim.rng.p_index();
    crate::sim::movement::spawn_player_missile(&mut sim, id, rocket);
    // Three aims find nothing (no monsters): angle 0, slope 0. The spawn's
    // lastlook and P_CheckMissileSpawn's tics are the two P_Randoms.
    assert_eq!(sim.rng.p_index(), before.wrapping_add(2));
    let th = MobjId(sim.mobjs.len() as u32 - 1);
    let (m, p) = (sim.mo(th), sim.mo(id));
    // Speed 20: FixedMul(20 << 16, 65535) = 1310700, FixedMul(20 << 16, 25)
    // = 500; the spawn check moved it half a tic on.
    assert_eq!((m.momx, m.momy, m.momz), (Fixed(1310700), Fixed(500), Fixed::ZERO));
    assert_eq!((m.x - p.x, m.y - p.y, m.z - p.z), (Fixed(655350), Fixed(250), u(32)));
    assert_eq!(m.target, Some(id));
    // Exploding: stopped, no longer a missile, its 8-tic death frame less
    // P_Random() & 3.
    let r = i32::from(crate::fixed::RNDTABLE[usize::from(sim.rng.p_index().wrapping_add(1))]);
    crate::sim::movement::explode_missile(&mut sim, th);
    let m = sim.mo(th);
    assert_eq!((m.momx, m.momy, m.momz, m.has(mf::MISSILE)), (Fixed::ZERO, Fixed::ZERO, Fixed::ZERO, false));
    assert_eq!(m.state, sim.info.things[rocket].deathstate);
    assert_eq!(m.tics, (8 - (r & 3)).max(1));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_weapon_change_lowers_the_pistol_and_raises_the_fist() {
    let mut sim = game();
    for _ in 0..15 {
        tick(&mut sim, Ticcmd::default());
    }
    let fist = sim.info.weapons[0].clone().expect("the fist");
    tick(&mut sim, Ticcmd { buttons: buttons::CHANGE, ..Ticcmd::default() });
    // A_WeaponReady saw the change: down at once, 6 units a tic.
    assert_eq!(sim.player(0).expect("player").psprites[0].sy, u(38));
    for _ in 0..14 {
        tick(&mut sim, Ticcmd::default());
    }
    let p = sim.player(0).expect("player");
    assert_eq!((p.readyweapon, p.psprites[0].sy), (1, u(122)));
    tick(&mut sim, Ticcmd::default());
    // At the bottom the fist became ready and its first A_Raise ran.
    let p = sim.player(0).expect("player");
    assert_eq!((p.readyweapon, p.pendingweapon, p.psprites[0].sy), (0, None, u(122)));
    assert_eq!(p.psprites[0].state, fist.upstate);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_dead_player_sinks_and_turns_to_the_killer_five_degrees_a_tic() {
    let mut sim = game();
    let id = player_body(&sim);
    let clip = clip_kind(&sim);
    // The killer due north; no inflictor, so no push.
    let killer = sim.spawn_mobj(u(-192), u(-64), crate::sim::mobj::ONFLOORZ, clip);
    damage_mobj(&mut sim, id, None, Some(killer), 200);
    assert_eq!(sim.player(0).expect("player").attacker, Some(killer));
    // ANG5 = ANG90 / 18 = 59652323; eighteen of them fall 10 short of ANG90.
    for k in 1..=18u32 {
        tick(&mut sim, Ticcmd::default());
        assert_eq!(sim.mo(id).angle.0, 59_652_323 * k, "tic {k}");
    }
    tick(&mut sim, Ticcmd::default());
    let to = crate::fixed::point_to_angle2(u(-192), u(-160), u(-192), u(-64));
    assert_eq!(sim.mo(id).angle, to);
    // The eye sank a unit a tic for 19 tics.
    assert_eq!(sim.player(0).expect("player").viewheight, u(41 - 19));
    for _ in 0..20 {
        tick(&mut sim, Ticcmd::default());
    }
    let p = sim.player(0).expect("player");
    assert_eq!(p.viewheight, u(6));
    assert_eq!(p.viewz, sim.mo(id).z + u(6));
    assert_eq!(p.psprites[0].sy, WEAPONBOTTOM);
    // Use asks for rebirth.
    tick(&mut sim, Ticcmd { buttons: buttons::USE, ..Ticcmd::default() });
    assert_eq!(sim.player(0).expect("player").playerstate, PlayerState::Reborn);
}
