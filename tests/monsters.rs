//! Monsters on small maps, driven tick by tick: a zombieman that does not
//! see the player stays put; one that does wakes, fires, and follows the
//! player around a pillar.

use glam::DVec2;
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
    assert!(!z.target && z.pos == start, "woke or moved without seeing the player");
    // North of the pillar the player is in its view: it wakes within its
    // look period (A_Look every 10 ticks).
    g.teleport(DVec2::new(64.0, 480.0), 0.0).unwrap();
    idle(&mut g, 11);
    assert!(actor(&g, "zombieman").target, "did not wake on sight");
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
    let mut shots = 0;
    while g.stats().kills.0 == 0 && shots < 20 {
        // Fire goes off once per press.
        g.tick(&fire);
        g.tick(&TickInput::default());
        shots += 1;
    }
    assert_eq!(g.stats().kills, (1, 1), "after {shots} shots");
    assert!(shots >= 2, "a zombieman has 20 health and a shot does at most 15");
    idle(&mut g, 70);
    let z = actor(&g, "zombieman");
    let table = &g.actors().table;
    assert!(!z.flags.has(sightline::actors::ActorFlag::Solid) && !z.removed, "the body stays and can be walked over");
    assert_eq!(z.tics, -1, "the body lies still: nothing left to run");
    let clip = actor(&g, "clip");
    assert!(clip.flags.has(sightline::actors::ActorFlag::Dropped) && clip.pos == z.pos);
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
    g.actors().list.iter().filter(|a| table.actors[a.kind].name == "zombieman").map(|a| a.target).collect()
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
