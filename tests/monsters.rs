//! Monsters on small maps, driven tic by tic on the simulation with Doom's
//! rules (`sim`): a zombieman that does not see the player stays put; one
//! that does wakes, fires, and follows the player around a pillar; shots
//! kill, barrels burst in a chain, a rocket's splash stops at a wall, a
//! monster opens a door and takes a monsters-only teleporter, a user's
//! actor file replaces a monster, and on Nightmare the dead come back.
//!
//! The f64 game's test that a monster out of the player's reach was
//! "parked" (off the tick's list, its timer stopped) has no counterpart:
//! Doom runs every thinker every tic. What that test said of waking (on
//! sight after a teleport, through a door once opened) is kept.

use glam::DVec2;
use sightline::autopilot::observe::Observe;
use sightline::play::{GameOptions, TickInput};
use sightline::sim::game::SimGame;
use sightline::sim::mobj::mf;
use sightline_tests::sim_play::{
    assert_drawn_as_they_stand, first, game, game_with, idle, named, player_mo, pos, present, teleport, turn, wake,
};
use sightline_tests::{load, root};

fn fire() -> TickInput {
    TickInput { fire: true, ..TickInput::default() }
}

/// Whether a body has a target (a monster's: it is awake).
fn awake_one(g: &SimGame, id: sightline::sim::MobjId) -> bool {
    g.sim.mo(id).target.is_some()
}

#[test]
fn a_zombieman_wakes_on_sight_fires_and_walks_round_a_pillar() {
    let mut g = game("monsters");
    g.set_health(1_000_000);
    let z = first(&g, "zombieman");
    let start = pos(&g, z);
    // Hidden behind the pillar: it sleeps, where it stands.
    idle(&mut g, 105);
    assert!(!awake_one(&g, z) && pos(&g, z) == start, "woke or moved without seeing the player");
    // North of the pillar the player is in its view: it wakes within its
    // look period (POSS_STND lasts 10 tics, each A_Look).
    teleport(&mut g, DVec2::new(64.0, 480.0), 0.0);
    idle(&mut g, 11);
    assert_eq!(g.sim.mo(z).target, Some(player_mo(&g)), "did not wake on sight");
    // It shoots: the player is hurt within 20 s.
    let mut hurt = false;
    for _ in 0..35 * 20 {
        g.tick(&TickInput::default());
        if g.sim.players[0].as_ref().unwrap().health < 1_000_000 {
            hurt = true;
            break;
        }
    }
    assert!(hurt, "the zombieman never hit the player");
    // Back behind the pillar: it comes round after the player.
    teleport(&mut g, DVec2::new(64.0, 256.0), 0.0);
    let mut rounded = false;
    for _ in 0..35 * 30 {
        g.tick(&TickInput::default());
        let p = pos(&g, z);
        // Its radius is 20: it keeps that far from the walls and the pillar.
        assert!((20.0..=1004.0).contains(&p.x) && (20.0..=492.0).contains(&p.y), "{p}");
        assert!(!((448.0 - 20.0..576.0 + 20.0).contains(&p.x) && (192.0 - 20.0..320.0 + 20.0).contains(&p.y)), "{p}");
        if p.x < 448.0 {
            rounded = true;
            break;
        }
    }
    assert!(rounded, "the zombieman did not come round the pillar: {}", pos(&g, z));
    assert_drawn_as_they_stand(&g);
}

/// Holds fire until the first kill (10 s at most); the bullets it took.
fn fire_until_a_kill(g: &mut SimGame) -> i32 {
    let bullets = Observe::player(g).ammo[0];
    for _ in 0..35 * 10 {
        if g.stats().kills.0 > 0 {
            break;
        }
        g.tick(&fire());
    }
    bullets - Observe::player(g).ammo[0]
}

#[test]
fn the_player_s_shots_kill_a_zombieman_which_drops_a_clip() {
    let mut g = game("monsters");
    g.set_health(1_000_000);
    teleport(&mut g, DVec2::new(700.0, 256.0), 0.0);
    let shots = fire_until_a_kill(&mut g);
    assert_eq!(g.stats().kills, (1, 1), "after {shots} shots");
    // A zombieman has 20 health; the pistol does 5 * (1 to 3) (P_GunShot).
    assert!(shots >= 2, "{shots} shots");
    idle(&mut g, 70);
    let z = first(&g, "zombieman");
    let body = g.sim.mo(z);
    assert!(!body.has(mf::SOLID) && present(&g, z), "the body stays and can be walked over");
    assert_eq!(body.tics, -1, "the body lies still: nothing left to run");
    let clip = first(&g, "clip");
    // Dropped where it died (A_Fall's P_SpawnMobj at the body); the body
    // slides on, pushed by the last shot (P_DamageMobj's thrust: damage
    // * 100 / mass / 8 a tic, at most 15 / 8 = 1.9, slowed by friction
    // 0xe800 / 0x10000 a tic: some 20 units in all).
    let slid = pos(&g, clip).distance(pos(&g, z));
    assert!(g.sim.mo(clip).has(mf::DROPPED) && slid < 48.0, "{} {}", pos(&g, clip), pos(&g, z));
    // Walked over, the clip gives half a clip, as a dropped one does
    // (P_GiveAmmo: clipammo 10 / 2). Doom picks up in a move only
    // (P_TryMove's PIT_CheckThing), so the player walks onto it.
    let (at, bullets) = (pos(&g, clip), Observe::player(&g).ammo[0]);
    teleport(&mut g, at + DVec2::new(-48.0, 0.0), 0.0);
    let mut message = false;
    for _ in 0..35 {
        g.tick(&TickInput { forward: 1, ..TickInput::default() });
        let picked = |e: &sightline::play::events::Event| matches!(e, sightline::play::events::Event::Message(m) if m == "Picked up a clip.");
        message |= g.events().iter().any(picked);
        if !present(&g, clip) {
            break;
        }
    }
    assert_eq!(Observe::player(&g).ammo[0], bullets + 5);
    assert!(message, "no pickup message");
    assert!(!present(&g, clip));
    assert_drawn_as_they_stand(&g);
}

/// The zombiemen of `hearing.ron`, west to east: whether each has woken.
fn awake(g: &SimGame) -> Vec<bool> {
    named(g, "zombieman").into_iter().map(|z| awake_one(g, z)).collect()
}

#[test]
fn a_shot_is_heard_across_one_sound_blocking_line_not_two() {
    let mut g = game("hearing");
    g.set_health(1_000_000);
    idle(&mut g, 35);
    assert_eq!(awake(&g), [false, false], "they face away: nothing to see or hear");
    // A shot into the wall (P_FireWeapon's P_NoiseAlert): the next room
    // hears it, the far one does not (P_RecursiveSound passes one
    // ML_SOUNDBLOCK line, not two).
    g.tick(&fire());
    idle(&mut g, 11);
    assert_eq!(awake(&g), [true, false]);
    idle(&mut g, 70);
    assert!(!awake(&g)[1], "the far zombieman stays asleep");
}

/// The barrels still standing (not bursting), by where they stand.
fn barrels_standing(g: &SimGame) -> Vec<(f64, f64)> {
    let standing = |id: &sightline::sim::MobjId| present(g, *id) && g.sim.mo(*id).health > 0;
    named(g, "barrel").into_iter().filter(standing).map(|id| pos(g, id).into()).collect()
}

/// Holds fire (turned to `angle` first) for `ticks`.
fn fire_at(g: &mut SimGame, angle: f64, ticks: usize) {
    turn(g, angle);
    for _ in 0..ticks {
        g.tick(&fire());
    }
}

#[test]
fn a_barrel_chain_explodes() {
    let mut g = game("barrels");
    g.set_health(1_000_000);
    // Raise the pistol, then fire at the first barrel of the row, south
    // of east (the others are behind it).
    idle(&mut g, 20);
    let d = DVec2::new(400.0, 40.0) - Observe::player(&g).pos;
    let bullets = Observe::player(&g).ammo[0];
    fire_at(&mut g, d.y.atan2(d.x).to_degrees(), 70);
    assert!(Observe::player(&g).ammo[0] < bullets, "the pistol did not fire");
    idle(&mut g, 120);
    let standing = barrels_standing(&g);
    assert!(standing.iter().all(|&(_, y)| y > 150.0), "the chain did not all go off: {standing:?}");
    assert_eq!(standing.len(), 2, "the barrels by the pillar are too far to go off: {standing:?}");
    // Their bursts are gone from the level by now (BEXP's last state
    // leads to S_NULL).
    assert!(Observe::level(&g).things.iter().all(|t| t.pos.y > 150.0));
}

#[test]
fn a_rockets_splash_does_not_pass_a_wall() {
    let mut g = game("barrels");
    g.set_health(1_000_000);
    let launcher = g.sim.info.table.index("rocket_launcher").unwrap();
    // Doom's weapon 4 is the launcher, its ammunition 3 rockets.
    let p = g.sim.players[0].as_mut().unwrap();
    p.weaponowned[4] = true;
    p.ammo[3] = 10;
    // Change to the launcher (number 5), wait for it to come up, fire east
    // at the pillar's west face.
    g.tick(&TickInput { weapon: 5, ..TickInput::default() });
    idle(&mut g, 60);
    assert_eq!(Observe::player(&g).ready_weapon, Some(launcher));
    fire_at(&mut g, 0.0, 1);
    idle(&mut g, 60);
    assert_eq!(Observe::player(&g).ammo[2], 9, "no rocket left");
    // P_RadiusAttack hurts only what the burst can see (P_CheckSight).
    let standing = barrels_standing(&g);
    assert!(!standing.contains(&(380.0, 200.0)), "the barrel in the open survived the blast: {standing:?}");
    assert!(standing.contains(&(510.0, 350.0)), "the blast went through the pillar: {standing:?}");
}

#[test]
fn weapons_change_by_number_and_use_their_ammunition() {
    let mut g = game("monsters");
    let table = g.sim.info.table.clone();
    idle(&mut g, 20);
    assert_eq!(Observe::player(&g).ready_weapon, table.index("pistol"));
    // 40 tics held: the pistol's cycle is 4 + 6 + 4 + 5 = 19 tics
    // (S_PISTOL1..4), so two or three shots.
    let before = Observe::player(&g).ammo[0];
    fire_at(&mut g, 0.0, 40);
    let used = before - Observe::player(&g).ammo[0];
    assert!((2..=3).contains(&used), "{used} bullets for 40 tics of fire");
    // The fist: down and up at 6 units a tic over 96 (WEAPONBOTTOM 128 to
    // WEAPONTOP 32), 32 tics with the refire's end.
    g.tick(&TickInput { weapon: 1, ..TickInput::default() });
    idle(&mut g, 40);
    assert_eq!(Observe::player(&g).ready_weapon, table.index("fist"));
    let w = Observe::player(&g).psprites[0];
    assert_eq!(w.sy, sightline::sim::weapons::WEAPONTOP.to_f64(), "not raised: {w:?}");
    // A number with no weapon owned changes nothing.
    g.tick(&TickInput { weapon: 6, ..TickInput::default() });
    idle(&mut g, 40);
    assert_eq!(Observe::player(&g).ready_weapon, table.index("fist"));
}

/// Plays `inputs` on a fresh game and returns its whole state, the last
/// frame's pixels, and whether the zombieman ever had the player for its
/// target.
fn play_through(inputs: &[TickInput]) -> (Vec<u8>, Vec<u32>, bool) {
    let mut g = game("monsters");
    g.set_health(1_000_000);
    let z = first(&g, "zombieman");
    let mut noticed = false;
    for i in inputs {
        g.tick(i);
        noticed |= g.sim.mo(z).target == Some(player_mo(&g));
    }
    let options = sightline::render::RenderOptions::default();
    let mut fb = sightline::Framebuffer::new(160, 100);
    let level = Observe::level(&g);
    sightline::render::render_frame(level, &g.view(1.0), &options, &mut sightline::render::Frame::new(), &mut fb);
    sightline::screen::draw(&mut fb, level, Observe::table(&g), Observe::player(&g), sightline::screen::Hud::StatusBar);
    (g.state_bytes(), fb.pixels, noticed)
}

#[test]
fn a_fight_replays_to_the_same_state_and_frames_twice() {
    // Walk out from behind the pillar and fight: fire held in bursts.
    let mut inputs = sightline::play::input::wander(7, 700, true);
    for (k, i) in inputs.iter_mut().enumerate() {
        i.fire = k % 50 < 30;
        if k < 60 {
            *i = TickInput { forward: 1, strafe: -1, run: true, ..TickInput::default() };
        }
    }
    let first = play_through(&inputs);
    let second = play_through(&inputs);
    assert!(first.0 == second.0, "the state differs between two replays");
    assert!(first.1 == second.1, "the frames differ between two replays");
    assert!(first.2, "the zombieman never noticed the player");
}

/// The zombiemen of `monster_lines.ron`: by the door, and in T-east.
fn monster_lines_zombies(g: &SimGame) -> (sightline::sim::MobjId, sightline::sim::MobjId) {
    let z = named(g, "zombieman");
    assert_eq!(z.len(), 2);
    let (a, b) = (z[0], z[1]);
    if pos(g, a).y < pos(g, b).y {
        (a, b)
    } else {
        (b, a)
    }
}

#[test]
fn a_monster_opens_a_door_and_another_takes_a_monsters_teleporter() {
    let mut g = game("monster_lines");
    g.set_health(1_000_000);
    let door = 1;
    idle(&mut g, 35);
    let ceiling = |g: &SimGame| Observe::level(g).compiled.map.sectors[door].ceiling;
    assert_eq!(ceiling(&g), 0.0, "the door opened by itself");
    let (by_door, walker) = monster_lines_zombies(&g);
    assert_eq!(pos(&g, walker), DVec2::new(448.0, 512.0), "the second zombieman moved while asleep");
    wake(&mut g, by_door);
    wake(&mut g, walker);
    let mut opened = false;
    let mut through = false;
    for _ in 0..35 * 30 {
        g.tick(&TickInput::default());
        opened |= ceiling(&g) > 56.0;
        through |= pos(&g, by_door).x < 256.0;
        if opened && through {
            break;
        }
    }
    assert!(opened, "the zombieman never opened the door");
    assert!(through, "the zombieman never came through the door");
    let at = pos(&g, walker);
    assert!(at.y > 768.0 && at.x < 256.0, "it did not teleport: it is at {at}");
    assert_eq!(g.sim.mo(walker).z.to_f64(), 16.0, "it does not stand on room B's floor");
    assert_drawn_as_they_stand(&g);
}

#[test]
fn the_player_does_not_set_off_a_monsters_only_teleporter() {
    let mut g = game("monster_lines");
    teleport(&mut g, DVec2::new(448.0, 512.0 - 40.0), 180.0);
    let forward = TickInput { forward: 1, ..TickInput::default() };
    for _ in 0..70 {
        g.tick(&forward);
    }
    let p = Observe::player(&g).pos;
    assert!(p.x < 256.0 && p.y < 640.0, "the player crossed into T-west or was teleported: {p}");
}

#[test]
fn a_user_actor_file_replaces_the_zombieman() {
    let path = root().join("tests").join("actors").join("user.ron");
    assert!(path.exists(), "missing fixture {}", path.display());
    let table = sightline::actors::ActorTable::with_file(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(table.get("sturdy_zombieman").map(|a| a.health), Some(400));
    let level = load(&root().join("tests").join("maps").join("monsters.ron"));
    let opened = sightline::campaign::Opened::of_level(level, "monsters.ron");
    let options = GameOptions::default();
    let mut g = SimGame::with_table(opened, options, std::sync::Arc::new(table)).unwrap_or_else(|e| panic!("{e}"));
    g.set_health(1_000_000);
    teleport(&mut g, DVec2::new(700.0, 256.0), 0.0);
    let shots = fire_until_a_kill(&mut g);
    // The shipped zombieman takes two shots at least (see above).
    assert_eq!(g.stats().kills, (1, 1));
    assert_eq!(shots, 1, "the user's zombieman has 1 health");
}

/// Doom runs every monster every tic, wherever the player is: one out of
/// reach (a wall, a shut door between) wakes as soon as the player comes
/// into its view, by a teleport or by opening the door.
#[test]
fn a_monster_out_of_the_player_s_reach_wakes_when_the_player_comes() {
    let mut g = game("monster_lines");
    g.set_health(1_000_000);
    let (by_door, walker) = monster_lines_zombies(&g);
    idle(&mut g, 35);
    assert!(!awake_one(&g, by_door) && !awake_one(&g, walker));
    // In T-west, in its view: it wakes.
    teleport(&mut g, DVec2::new(128.0, 512.0), 0.0);
    idle(&mut g, 12);
    assert_eq!(g.sim.mo(walker).target, Some(player_mo(&g)), "it did not wake on sight");
    assert!(!awake_one(&g, by_door), "the zombieman behind the shut door woke");
    // Back in room W, the door opened: the zombieman beyond sees the player.
    teleport(&mut g, DVec2::new(220.0, 128.0), 0.0);
    g.tick(&TickInput { use_line: true, ..TickInput::default() });
    idle(&mut g, 60);
    assert_eq!(g.sim.mo(by_door).target, Some(player_mo(&g)), "the zombieman beyond the door did not wake");
}

/// Skill 5 (Doom's nightmare): a dead zombieman comes back where its map
/// thing stood, no sooner than 12 s after it fell (P_MobjThinker counts
/// `movecount` to 12 * 35 on the still body, then tries every 32nd tic,
/// P_Random() <= 4), as a new body; its corpse goes (P_NightmareRespawn).
#[test]
fn on_skill_5_a_dead_monster_comes_back_at_its_spot() {
    let mut g = game_with("monsters", GameOptions { skill: 5, ..Default::default() });
    g.set_health(1_000_000);
    let spot = pos(&g, first(&g, "zombieman"));
    teleport(&mut g, DVec2::new(700.0, 256.0), 0.0);
    fire_until_a_kill(&mut g);
    assert_eq!(g.stats().kills.0, 1, "the zombieman was not killed");
    // Out of its sight, in the room's far corner.
    teleport(&mut g, DVec2::new(64.0, 64.0), 180.0);
    let died = g.sim.leveltime;
    let alive = |g: &SimGame| named(g, "zombieman").into_iter().filter(|&z| present(g, z)).collect::<Vec<_>>();
    let mut back = None;
    for _ in 0..35 * 300 {
        g.tick(&TickInput::default());
        if let Some(z) = alive(&g).into_iter().find(|&z| g.sim.mo(z).health > 0) {
            back = Some((g.sim.leveltime, z));
            break;
        }
    }
    let (at, z) = back.expect("no zombieman came back in 300 s");
    assert!(at - died >= 12 * 35, "it came back {} tics after dying", at - died);
    assert_eq!((pos(&g, z), g.sim.mo(z).health), (spot, 20));
    assert_ne!(z, named(&g, "zombieman")[0], "the zombieman back is a new body");
    assert_eq!(alive(&g).len(), 1, "the body stayed beside the new zombieman");
    assert_drawn_as_they_stand(&g);
}

/// A lift carries what stands on it: a barrel on lift A of `lift.ron`
/// goes down and up with its floor, tic by tic (P_ChangeSector's
/// P_ThingHeightClip keeps a body on the floor there).
#[test]
fn a_lift_carries_a_barrel_down_and_up() {
    use sightline::bsp::{build, BuildOptions};
    use sightline::level::Level;
    let path = root().join("tests").join("maps").join("lift.ron");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    // Lift A spans x 256..384, y 160..256; the player walks east along y 208.
    let start = text.find("Thing(kind: \"player_start\"").expect("lift.ron has a player start");
    let mut text = text.clone();
    text.insert_str(start, "Thing(kind: \"barrel\", x: 360.0, y: 184.0),\n        ");
    let map = sightline::map::load::parse_map(&text, "lift.ron with a barrel").unwrap_or_else(|e| panic!("{e}"));
    let compiled = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let library = sightline::texture::Library::dirs(&[path.parent().unwrap().to_path_buf()]);
    let materials = sightline::materials::Materials::resolve_in(&compiled.map, &library, "lift.ron")
        .unwrap_or_else(|e| panic!("{e}"));
    let options = GameOptions::default();
    let mut g = SimGame::on_level(Level::new(compiled, materials), "lift.ron with a barrel", options)
        .unwrap_or_else(|e| panic!("{e}"));
    let lift = 1;
    let floor = |g: &SimGame| Observe::level(g).compiled.map.sectors[lift].floor;
    let barrel = |g: &SimGame| g.sim.mo(first(g, "barrel")).z.to_f64();
    assert_eq!((floor(&g), barrel(&g)), (64.0, 64.0));
    // Walk east to the walk line at x 160, then stand still.
    let walk = TickInput { forward: 1, ..TickInput::default() };
    while Observe::player(&g).pos.x < 170.0 {
        g.tick(&walk);
    }
    let (mut low, mut seen) = (f64::MAX, 0);
    for _ in 0..200 {
        g.tick(&TickInput::default());
        assert_eq!(barrel(&g), floor(&g), "the barrel left the lift's floor at tic {}", g.sim.leveltime);
        low = low.min(floor(&g));
        seen += 1;
    }
    assert_eq!((low, floor(&g), seen), (0.0, 64.0, 200), "the lift did not go down and back up");
    assert_drawn_as_they_stand(&g);
}
