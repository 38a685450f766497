//! Monsters on small maps, driven tick by tick: a zombieman that does not
//! see the player stays put; one that does wakes, fires, and follows the
//! player around a pillar.

use glam::DVec2;
use sightline::play::actors::Target;
use sightline::play::{Game, TickInput};
use sightline_tests::{load, root};

fn game(name: &str) -> Game {
    let p = root().join("tests").join("maps").join(format!("{name}.ron"));
    assert!(p.exists(), "missing fixture {}", p.display());
    Game::new(load(&p)).unwrap_or_else(|e| panic!("{e}"))
}

/// The first actor of that name.
fn actor<'g>(g: &'g Game, name: &str) -> &'g sightline::play::actors::Actor {
    let table = &g.actors().table;
    g.actors().list.iter().find(|a| table.actors[a.kind].name == name).expect("the actor is in play")
}

/// What the renderers draw is every actor still there, where it stands
/// (`Actors::draw` updates only the actors that changed).
fn assert_drawn_as_they_stand(g: &Game) {
    let mut drawn: Vec<_> = g.level().things.iter().map(|t| (t.key, t.pos.to_array(), t.angle.to_bits())).collect();
    let mut want: Vec<_> = g
        .actors()
        .list
        .iter()
        .filter(|a| !a.removed && a.views.is_some())
        .map(|a| (a.key, a.pos.to_array(), a.angle.to_bits()))
        .collect();
    drawn.sort_by(|a, b| a.0.cmp(&b.0));
    want.sort_by(|a, b| a.0.cmp(&b.0));
    assert_eq!(drawn, want);
}

fn idle(g: &mut Game, ticks: usize) {
    for _ in 0..ticks {
        g.tick(&TickInput::default());
    }
}

#[test]
fn a_zombieman_wakes_on_sight_fires_and_walks_round_a_pillar() {
    let mut g = game("monsters");
    g.player_mut().health = 1_000_000;
    let start = actor(&g, "zombieman").pos;
    // Hidden behind the pillar: it sleeps, where it stands.
    idle(&mut g, 105);
    let z = actor(&g, "zombieman");
    assert!(z.target == Target::None && z.pos == start, "woke or moved without seeing the player");
    // North of the pillar the player is in its view: it wakes within its
    // look period (A_Look every 10 ticks).
    g.teleport(DVec2::new(64.0, 480.0), 0.0).unwrap();
    idle(&mut g, 11);
    assert!(actor(&g, "zombieman").target == Target::Player, "did not wake on sight");
    // It shoots: the player is hurt within 20 s.
    let mut hurt = false;
    for _ in 0..35 * 20 {
        g.tick(&TickInput::default());
        if g.player().health < 1_000_000 {
            hurt = true;
            break;
        }
    }
    assert!(hurt, "the zombieman never hit the player");
    // Back behind the pillar: it comes round after the player.
    g.teleport(DVec2::new(64.0, 256.0), 0.0).unwrap();
    let mut rounded = false;
    for _ in 0..35 * 30 {
        g.tick(&TickInput::default());
        let z = actor(&g, "zombieman");
        assert!(z.pos.is_finite() && (16.0..=1008.0).contains(&z.pos.x) && (16.0..=496.0).contains(&z.pos.y));
        assert!(!((448.0 - 20.0..576.0 + 20.0).contains(&z.pos.x) && (192.0 - 20.0..320.0 + 20.0).contains(&z.pos.y)));
        if z.pos.x < 448.0 {
            rounded = true;
            break;
        }
    }
    assert!(rounded, "the zombieman did not come round the pillar: {:?}", actor(&g, "zombieman").pos);
    assert_drawn_as_they_stand(&g);
}

#[test]
fn the_player_s_shots_kill_a_zombieman_which_drops_a_clip() {
    let mut g = game("monsters");
    g.player_mut().health = 1_000_000;
    g.teleport(DVec2::new(700.0, 256.0), 0.0).unwrap();
    let fire = TickInput { fire: true, ..TickInput::default() };
    let bullets = g.player().ammo[0];
    for _ in 0..35 * 10 {
        if g.stats().kills.0 > 0 {
            break;
        }
        g.tick(&fire);
    }
    let shots = bullets - g.player().ammo[0];
    assert_eq!(g.stats().kills, (1, 1), "after {shots} shots");
    assert!(shots >= 2, "a zombieman has 20 health and a shot does at most 15");
    idle(&mut g, 70);
    let z = actor(&g, "zombieman");
    let table = &g.actors().table;
    assert!(!z.flags.has(sightline::actors::ActorFlag::Solid) && !z.removed, "the body stays and can be walked over");
    assert_eq!(z.tics, -1, "the body lies still: nothing left to run");
    let clip = actor(&g, "clip");
    // Dropped where it died; the body slides on, pushed by the last shot
    // (up to 15 damage on a mass of 100 pushes 1.9 a tick: some 20 units).
    let slid = clip.pos.distance(z.pos);
    assert!(clip.flags.has(sightline::actors::ActorFlag::Dropped) && slid < 48.0, "{:?} {:?}", clip.pos, z.pos);
    assert_eq!(table.actors[clip.kind].name, "clip");
    // Walked over, the clip gives half a clip, as a dropped one does.
    let (at, bullets) = (clip.pos, g.player().ammo[0]);
    g.teleport(at + DVec2::new(-8.0, 0.0), 0.0).unwrap();
    g.tick(&TickInput::default());
    assert_eq!(g.player().ammo[0], bullets + 5);
    assert!(g
        .events()
        .iter()
        .any(|e| matches!(e, sightline::play::events::Event::Message(m) if m == "Picked up a clip.")));
    assert!(actor(&g, "clip").removed);
    assert_drawn_as_they_stand(&g);
}

/// The zombiemen of `hearing.ron`, west to east: whether each has woken.
fn awake(g: &Game) -> Vec<bool> {
    let table = &g.actors().table;
    g.actors()
        .list
        .iter()
        .filter(|a| table.actors[a.kind].name == "zombieman")
        .map(|a| a.target != Target::None)
        .collect()
}

#[test]
fn a_shot_is_heard_across_one_sound_blocking_line_not_two() {
    let mut g = game("hearing");
    g.player_mut().health = 1_000_000;
    idle(&mut g, 35);
    assert_eq!(awake(&g), [false, false], "they face away: nothing to see or hear");
    // A shot into the wall: the next room hears it, the far one does not.
    g.tick(&TickInput { fire: true, ..TickInput::default() });
    idle(&mut g, 11);
    assert_eq!(awake(&g), [true, false]);
    idle(&mut g, 70);
    assert!(!awake(&g)[1], "the far zombieman stays asleep");
}

/// The barrels still standing (not bursting), by where they stand.
fn barrels_standing(g: &Game) -> Vec<(f64, f64)> {
    let table = &g.actors().table;
    g.actors()
        .list
        .iter()
        .filter(|a| !a.removed && table.actors[a.kind].name == "barrel" && a.health > 0)
        .map(|a| (a.pos.x, a.pos.y))
        .collect()
}

/// Holds fire (turned to `angle` first) for `ticks`.
fn fire_at(g: &mut Game, angle: f64, ticks: usize) {
    let pos = g.player().pos;
    g.teleport(pos, angle).unwrap();
    for _ in 0..ticks {
        g.tick(&TickInput { fire: true, ..TickInput::default() });
    }
}

#[test]
fn a_barrel_chain_explodes() {
    let mut g = game("barrels");
    g.player_mut().health = 1_000_000;
    // Raise the pistol, then fire at the first barrel of the row, south
    // of east (the others are behind it).
    idle(&mut g, 20);
    let d = DVec2::new(400.0, 40.0) - g.player().pos;
    let bullets = g.player().ammo[0];
    fire_at(&mut g, d.y.atan2(d.x).to_degrees(), 70);
    assert!(g.player().ammo[0] < bullets, "the pistol did not fire");
    idle(&mut g, 120);
    let standing = barrels_standing(&g);
    assert!(standing.iter().all(|&(_, y)| y > 150.0), "the chain did not all go off: {standing:?}");
    assert_eq!(standing.len(), 2, "the barrels by the pillar are too far to go off: {standing:?}");
    // Their bursts are gone from the level by now.
    assert!(g.level().things.iter().all(|t| t.pos.y > 150.0));
}

#[test]
fn a_rockets_splash_does_not_pass_a_wall() {
    let mut g = game("barrels");
    let table = g.actors().table.clone();
    let launcher = table.index("rocket_launcher").unwrap();
    let p = g.player_mut();
    p.health = 1_000_000;
    p.weapons.push(launcher);
    p.ammo[2] = 10;
    // Change to the launcher (number 5), wait for it to come up, fire east
    // at the pillar's west face.
    g.tick(&TickInput { weapon: 5, ..TickInput::default() });
    idle(&mut g, 60);
    assert_eq!(g.player().ready_weapon, Some(launcher));
    fire_at(&mut g, 0.0, 1);
    idle(&mut g, 60);
    assert_eq!(g.player().ammo[2], 9, "no rocket left");
    let standing = barrels_standing(&g);
    assert!(!standing.contains(&(380.0, 200.0)), "the barrel in the open survived the blast: {standing:?}");
    assert!(standing.contains(&(510.0, 350.0)), "the blast went through the pillar: {standing:?}");
}

#[test]
fn weapons_change_by_number_and_use_their_ammunition() {
    let mut g = game("monsters");
    let table = g.actors().table.clone();
    idle(&mut g, 20);
    assert_eq!(g.player().ready_weapon, table.index("pistol"));
    // Four shots held: an accurate first one, then the refire.
    let before = g.player().ammo[0];
    fire_at(&mut g, 0.0, 40);
    let used = before - g.player().ammo[0];
    assert!((2..=4).contains(&used), "{used} bullets for 40 ticks of fire");
    // The fist: down (at most 16 ticks), then up.
    g.tick(&TickInput { weapon: 1, ..TickInput::default() });
    idle(&mut g, 40);
    assert_eq!(g.player().ready_weapon, table.index("fist"));
    let w = g.player().psprites[0];
    assert_eq!(w.sy, sightline::play::weapons::WEAPON_TOP, "not raised: {w:?}");
    // A number with no weapon owned changes nothing.
    g.tick(&TickInput { weapon: 6, ..TickInput::default() });
    idle(&mut g, 40);
    assert_eq!(g.player().ready_weapon, table.index("fist"));
}

/// Plays `inputs` on a fresh game and returns its state as text and the
/// last frame's pixels.
fn play_through(inputs: &[TickInput]) -> (String, Vec<u32>) {
    let mut g = game("monsters");
    g.player_mut().health = 1_000_000;
    for i in inputs {
        g.tick(i);
    }
    let state = format!("{:?}\n{:?}\n{:?}", g.actors().list, g.player(), g.stats());
    let options = sightline::render::RenderOptions::default();
    let mut fb = sightline::Framebuffer::new(160, 100);
    sightline::render::render_frame(g.level(), &g.view(1.0), &options, &mut sightline::render::Frame::new(), &mut fb);
    sightline::screen::draw(&mut fb, g.level(), g.player(), sightline::screen::Hud::StatusBar);
    (state, fb.pixels)
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
    assert!(first.0.contains("Player"), "the zombieman never noticed the player");
}

#[test]
fn a_monster_opens_a_door_and_another_takes_a_monsters_teleporter() {
    let mut g = game("monster_lines");
    g.player_mut().health = 1_000_000;
    let door = 1;
    idle(&mut g, 35);
    assert_eq!(g.level().compiled.map.sectors[door].ceiling, 0.0, "the door opened by itself");
    let of_thing = |g: &Game, t: usize| g.actors().list.iter().find(|a| a.thing == Some(t)).unwrap().clone();
    let walker = of_thing(&g, 2);
    assert_eq!(walker.pos, DVec2::new(448.0, 512.0), "the second zombieman moved while asleep");
    g.wake_monsters();
    let mut opened = false;
    let mut through = false;
    for _ in 0..35 * 30 {
        g.tick(&TickInput::default());
        opened |= g.level().compiled.map.sectors[door].ceiling > 56.0;
        through |= of_thing(&g, 1).pos.x < 256.0;
        if opened && through {
            break;
        }
    }
    assert!(opened, "the zombieman never opened the door");
    assert!(through, "the zombieman never came through the door");
    let walker = of_thing(&g, 2);
    assert!(walker.pos.y > 768.0 && walker.pos.x < 256.0, "it did not teleport: it is at {}", walker.pos);
    assert_eq!(walker.z, 16.0, "it does not stand on room B's floor");
    assert_drawn_as_they_stand(&g);
}

#[test]
fn the_player_does_not_set_off_a_monsters_only_teleporter() {
    let mut g = game("monster_lines");
    g.teleport(DVec2::new(448.0, 512.0 - 40.0), 180.0).unwrap();
    let forward = TickInput { forward: 1, ..TickInput::default() };
    for _ in 0..70 {
        g.tick(&forward);
    }
    let p = g.player().pos;
    assert!(p.x < 256.0 && p.y < 640.0, "the player crossed into T-west or was teleported: {p}");
}

#[test]
fn a_user_actor_file_replaces_the_zombieman() {
    let path = root().join("tests").join("actors").join("user.ron");
    assert!(path.exists(), "missing fixture {}", path.display());
    let table = sightline::actors::ActorTable::with_file(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(table.get("sturdy_zombieman").map(|a| a.health), Some(400));
    let level = load(&root().join("tests").join("maps").join("monsters.ron"));
    let options = sightline::play::GameOptions::default();
    let mut g = Game::with_table(level, options, std::sync::Arc::new(table)).unwrap();
    g.player_mut().health = 1_000_000;
    g.teleport(DVec2::new(700.0, 256.0), 0.0).unwrap();
    let bullets = g.player().ammo[0];
    for _ in 0..35 * 10 {
        if g.stats().kills.0 > 0 {
            break;
        }
        g.tick(&TickInput { fire: true, ..TickInput::default() });
    }
    // The shipped zombieman takes two shots at least (see above).
    assert_eq!(g.stats().kills, (1, 1));
    assert_eq!(bullets - g.player().ammo[0], 1, "the user's zombieman has 1 health");
}

/// A monster waiting in a part of the map the player cannot see or hear
/// (no open two-sided line leads there: a wall, or a shut door) is off the
/// tick's list; it is back on it, and wakes as before, once the player is
/// in its part, by a teleport or by opening the door.
#[test]
fn a_monster_out_of_the_player_s_reach_costs_nothing_until_the_player_comes() {
    let mut g = game("monster_lines");
    idle(&mut g, 2);
    // Both zombiemen are parked: one in the T rooms, one behind the shut door.
    assert_eq!(g.actors().parked(), 2);
    let of_thing = |g: &Game, t: usize| g.actors().list.iter().find(|a| a.thing == Some(t)).unwrap().clone();
    let (state, tics) = (of_thing(&g, 2).state, of_thing(&g, 2).tics);
    idle(&mut g, 35);
    assert_eq!((of_thing(&g, 2).state, of_thing(&g, 2).tics), (state, tics), "a parked monster's timer ran");
    // In T-west, in its view: it is back on the list and wakes.
    g.teleport(DVec2::new(128.0, 512.0), 0.0).unwrap();
    idle(&mut g, 12);
    assert_eq!(of_thing(&g, 2).target, Target::Player, "it did not wake on sight");
    assert_eq!(g.actors().parked(), 1);
    // Back in room W, the door opened: the zombieman beyond is in the
    // player's part again and sees it.
    g.teleport(DVec2::new(220.0, 128.0), 0.0).unwrap();
    g.tick(&TickInput { use_line: true, ..TickInput::default() });
    idle(&mut g, 60);
    // (The T-rooms' zombieman, awake now, is not parked: only a monster
    // waiting for the player is.)
    assert_eq!(g.actors().parked(), 0);
    assert_eq!(of_thing(&g, 1).target, Target::Player, "the zombieman beyond the door did not wake");
}

/// Skill 5 (Doom's nightmare): a dead zombieman comes back where its map
/// thing stood, no sooner than 12 s after it fell, as a new actor; its
/// body goes.
#[test]
fn on_skill_5_a_dead_monster_comes_back_at_its_spot() {
    let p = root().join("tests").join("maps").join("monsters.ron");
    let options = sightline::play::GameOptions { skill: 5, seed: 3, ..Default::default() };
    let mut g = Game::with_options(load(&p), options).unwrap();
    g.player_mut().health = 1_000_000;
    let spot = actor(&g, "zombieman").pos;
    g.teleport(DVec2::new(700.0, 256.0), 0.0).unwrap();
    for _ in 0..35 * 10 {
        if g.stats().kills.0 > 0 {
            break;
        }
        g.tick(&TickInput { fire: true, ..TickInput::default() });
    }
    assert_eq!(g.stats().kills.0, 1, "the zombieman was not killed");
    // Out of its sight, in the room's far corner.
    g.teleport(DVec2::new(64.0, 64.0), 180.0).unwrap();
    let died = g.ticks();
    let zombies = |g: &Game| {
        let t = &g.actors().table;
        g.actors()
            .list
            .iter()
            .filter(|a| !a.removed && t.actors[a.kind].name == "zombieman")
            .cloned()
            .collect::<Vec<_>>()
    };
    let mut back = None;
    for _ in 0..35 * 300 {
        g.tick(&TickInput::default());
        if let Some(z) = zombies(&g).into_iter().find(|z| z.health > 0) {
            back = Some((g.ticks(), z));
            break;
        }
    }
    let (at, z) = back.expect("no zombieman came back in 300 s");
    assert!(at - died >= 12 * 35, "it came back {} ticks after dying", at - died);
    assert_eq!((z.pos, z.health, z.thing), (spot, 20, Some(1)));
    assert_eq!(zombies(&g).len(), 1, "the body stayed beside the new zombieman");
    assert_drawn_as_they_stand(&g);
}

/// A lift carries what stands on it: a barrel on lift A of `lift.ron`
/// goes down and up with its floor, tick by tick.
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
    let mut g = Game::new(Level::new(compiled, materials)).unwrap();
    let lift = 1;
    let floor = |g: &Game| g.level().compiled.map.sectors[lift].floor;
    let barrel = |g: &Game| actor(g, "barrel").z;
    assert_eq!((floor(&g), barrel(&g)), (64.0, 64.0));
    // Walk east to the walk line at x 160, then stand still.
    let walk = TickInput { forward: 1, ..TickInput::default() };
    while g.player().pos.x < 170.0 {
        g.tick(&walk);
    }
    let (mut low, mut seen) = (f64::MAX, 0);
    for _ in 0..200 {
        g.tick(&TickInput::default());
        assert_eq!(barrel(&g), floor(&g), "the barrel left the lift's floor at tick {}", g.ticks());
        low = low.min(floor(&g));
        seen += 1;
    }
    assert_eq!((low, floor(&g), seen), (0.0, 64.0, 200), "the lift did not go down and back up");
    assert_drawn_as_they_stand(&g);
}
