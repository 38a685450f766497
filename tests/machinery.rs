//! maps/machinery.rs played from start to exit through the player's own
//! inputs: a small driver turns and walks towards waypoints, presses use
//! where the map asks, and every machine is checked as it is met (the lift
//! rides, the switch flips and opens the remote door, the blue door refuses
//! and then opens, the key is picked up, the teleporter teleports, the
//! secret counts, the exit ends the level). The inputs it fed are a demo:
//! played again they end the same way (saved and loaded on the way, the
//! same game), and it is what the window test plays.

use glam::DVec2;
use sightline::autopilot::observe::Observe;
use sightline::campaign::MapRef;
use sightline::map::special::KeyColour;
use sightline::play::events::Event;
use sightline::play::playthrough::{Phase, Playthrough};
use sightline::play::{Demo, Exit, GameOptions, TickInput};
use sightline_tests::map_path;

/// Plays a playthrough and remembers every input it was given.
struct Driver {
    play: Playthrough,
    inputs: Vec<TickInput>,
    messages: Vec<String>,
}

impl Driver {
    fn tick(&mut self, input: TickInput) {
        self.play.tick(&input).unwrap_or_else(|e| panic!("{e}"));
        for e in self.play.game.events() {
            if let Event::Message(m) = e {
                self.messages.push(m.clone());
            }
        }
        self.inputs.push(input);
    }

    fn pos(&self) -> DVec2 {
        self.play.game.player().pos
    }

    /// Turns towards `to` and walks there, up to `limit` ticks, and stops
    /// on it. A body coasts about ten times its speed after the last thrust
    /// (friction keeps 0.90625 a tick), so it thrusts only while slower than
    /// a tenth of the distance left, and runs only when that is above a
    /// walk's top speed.
    fn walk_to(&mut self, to: DVec2, limit: usize) {
        for _ in 0..limit {
            let d = to - self.pos();
            let velocity = self.play.game.player().velocity;
            if d.length() < 10.0 && velocity.length() < 1.0 {
                return;
            }
            let turn = self.turn_towards(d.y.atan2(d.x).to_degrees());
            let wanted = (d.length() / 10.0).min(16.0);
            let going = velocity.dot(d.normalize_or_zero());
            let push = turn.abs() < 20.0 && going < wanted && d.length() >= 10.0;
            let run = wanted > 8.0;
            self.tick(TickInput { forward: i8::from(push), turn: turn as f32, run, ..Default::default() });
        }
        let p = self.play.game.player();
        panic!(
            "did not reach {to} from {} in {limit} ticks (velocity {}, angle {}, z {})",
            self.pos(),
            p.velocity,
            p.angle,
            p.z
        );
    }

    /// The turn that faces `angle` degrees, at most 15 a tick.
    fn turn_towards(&self, angle: f64) -> f64 {
        let now = self.play.game.player().angle;
        ((angle - now + 540.0).rem_euclid(360.0) - 180.0).clamp(-15.0, 15.0)
    }

    /// Faces `angle` (degrees) standing, then presses use.
    fn use_facing(&mut self, angle: f64) {
        self.face(angle);
        self.tick(TickInput { use_line: true, ..Default::default() });
        self.tick(TickInput::default());
    }

    fn face(&mut self, angle: f64) {
        for _ in 0..40 {
            let turn = self.turn_towards(angle);
            if turn.abs() < 1e-9 {
                return;
            }
            self.tick(TickInput { turn: turn as f32, ..Default::default() });
        }
    }

    fn wait(&mut self, ticks: usize) {
        for _ in 0..ticks {
            self.tick(TickInput::default());
        }
    }

    fn sector_of(&self, p: DVec2) -> usize {
        self.play.game.level().locate(p).expect("in the map")
    }
}

#[test]
fn machinery_is_played_through_from_start_to_exit() {
    let map = MapRef::File(map_path("machinery.ron"));
    let play = Playthrough::of(&map, GameOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let mut d = Driver { play, inputs: Vec::new(), messages: Vec::new() };
    let level = d.play.game.level();
    let lift = d.sector_of(DVec2::new(544.0, 192.0));
    let door1 = d.sector_of(DVec2::new(736.0, 392.0));
    let door2 = d.sector_of(DVec2::new(568.0, 592.0));
    let flicker = d.sector_of(DVec2::new(192.0, 1300.0));
    assert_eq!(level.map.sectors[lift].floor, 128.0);

    // The lift: used on its face from the hall, down to the hall's floor.
    d.walk_to(DVec2::new(470.0, 192.0), 200);
    d.use_facing(0.0);
    d.wait(40);
    assert_eq!(d.play.game.level().map.sectors[lift].floor, 0.0, "the lift did not come down");
    d.walk_to(DVec2::new(544.0, 192.0), 60);
    // It waits 105 ticks at the bottom, then rises 4 a tick: ride it up.
    for _ in 0..200 {
        if d.play.game.player().z >= 128.0 {
            break;
        }
        d.tick(TickInput::default());
    }
    assert_eq!(d.play.game.player().z, 128.0, "did not ride the lift up");

    // The switch on the ledge's east wall opens door 1 and flips.
    d.walk_to(DVec2::new(860.0, 192.0), 200);
    let before = d.play.game.level().materials.sides.clone();
    d.use_facing(0.0);
    assert!(d.play.game.is_busy(door1), "the switch did not start door 1");
    assert_ne!(d.play.game.level().materials.sides, before, "the switch texture did not flip");
    d.wait(80);
    assert!(d.play.game.level().map.sectors[door1].ceiling > 200.0, "door 1 did not open");

    // Into the slime hall; the blue door refuses without its key.
    d.walk_to(DVec2::new(736.0, 300.0), 200);
    d.walk_to(DVec2::new(736.0, 470.0), 200);
    d.walk_to(DVec2::new(610.0, 592.0), 200);
    d.use_facing(180.0);
    assert!(d.messages.iter().any(|m| m == "You need a blue key to open this door"), "{:?}", d.messages);
    assert!(!d.play.game.is_busy(door2));

    // The key on the pedestal in the slime (which hurts).
    d.walk_to(DVec2::new(736.0, 500.0), 200);
    d.walk_to(DVec2::new(736.0, 592.0), 200);
    let keys: Vec<_> = d.play.game.player().keys.iter().map(|k| k.colour).collect();
    assert_eq!(keys, [KeyColour::Blue]);
    assert!(d.messages.iter().any(|m| m == "Picked up a blue keycard."));
    // Standing in the slime hurts: 5 every 32 ticks. Doom hurts a body
    // whose feet are on the slime's floor, and a body's floor is the
    // highest its box touches: the ring round the pedestal is 40 wide, so
    // the body (32 across) stands in the middle of its west side.
    d.walk_to(DVec2::new(692.0, 592.0), 100);
    d.wait(8);
    assert_eq!(d.play.game.player().z, 120.0, "not down in the slime at {}", d.pos());
    d.wait(32);
    let health = d.play.game.player().health;
    assert!(health == 95 || health == 90, "the slime did not hurt as Doom's does: health {health}");
    d.walk_to(DVec2::new(736.0, 500.0), 200);

    // Now the blue door opens.
    d.walk_to(DVec2::new(610.0, 592.0), 200);
    d.use_facing(180.0);
    assert!(d.play.game.is_busy(door2), "the blue door did not open with the key");
    d.wait(70);

    // Through it, onto the teleporter pad: to F, facing north, still.
    d.walk_to(DVec2::new(520.0, 592.0), 200);
    d.walk_to(DVec2::new(490.0, 592.0), 200);
    let mut arrived = false;
    for _ in 0..100 {
        let turn = d.turn_towards(180.0);
        d.tick(TickInput { forward: 1, turn: turn as f32, ..Default::default() });
        if d.pos().y > 832.0 {
            arrived = true;
            break;
        }
    }
    assert!(arrived, "never teleported: at {}", d.pos());
    assert_eq!((d.pos(), d.play.game.player().angle), (DVec2::new(192.0, 896.0), 90.0));
    assert_eq!(d.play.game.player().velocity, DVec2::ZERO);

    // The secret recess in F's west wall.
    assert_eq!(d.play.game.stats().secrets, (0, 1));
    d.walk_to(DVec2::new(40.0, 1024.0), 300);
    // A lamp stands in it: Doom's bodies are boxes, so the player's centre
    // gets 32 units from the lamp's, past the recess's mouth at x = 0.
    d.walk_to(DVec2::new(-8.0, 1024.0), 100);
    assert_eq!(d.play.game.stats().secrets, (1, 1));
    assert!(d.messages.iter().any(|m| m == "A secret is revealed!"));

    // North through the flickering corridor (its light changes) to the exit.
    d.walk_to(DVec2::new(192.0, 1100.0), 300);
    let mut lights = std::collections::BTreeSet::new();
    d.walk_to(DVec2::new(192.0, 1200.0), 100);
    for _ in 0..60 {
        d.tick(TickInput::default());
        lights.insert(d.play.game.level().map.sectors[flicker].light);
    }
    assert!(lights.len() >= 2, "the corridor's light never changed: {lights:?}");
    d.walk_to(DVec2::new(192.0, 1600.0), 300);
    d.walk_to(DVec2::new(192.0, 1745.0), 100);
    d.use_facing(90.0);
    let Phase::Intermission { exit, stats, next, .. } = &d.play.phase else {
        panic!("the exit switch did not end the level: {:?}", d.play.phase)
    };
    assert_eq!((*exit, stats.secrets, next.is_none()), (Exit::Normal, (1, 1), true));

    // The inputs are the game: played again as a demo, the same end.
    let demo = Demo { inputs: d.inputs.clone(), ..Demo::new(map.label()) };
    let bytes = demo.to_bytes();
    let demo = Demo::from_bytes(&bytes, "machinery.sldemo").unwrap();
    let mut again = Playthrough::of(&map, demo.options()).unwrap();
    // Saved every 97 ticks on the way (doors, the lift and the switch in
    // motion at some), each save loaded and followed 60 ticks: the same game.
    let save_at: Vec<usize> = (50..demo.inputs.len()).step_by(97).collect();
    let saves = sightline_tests::saves_continue_exactly(&mut again, &demo.inputs, &save_at, 60);
    assert!(saves.saves >= 10 && saves.machinery >= 3, "{saves:?}");
    assert_eq!(again.phase, d.play.phase);
    assert_eq!(again.game.player().pos, d.play.game.player().pos);
    // For the window test (.ci/window-test plays it into a window), when asked.
    if let Some(path) = std::env::var_os("SIGHTLINE_WRITE_MACHINERY_DEMO") {
        Demo { inputs: d.inputs.clone(), ..Demo::new("maps/machinery.ron") }.save(path.as_ref()).unwrap();
    }
}

/// A RON campaign file: its maps in order, the exit leading on, the secret
/// exit to its own map, the end after the last; a campaign naming a missing
/// map is refused naming the file and the entry.
#[test]
fn a_campaign_file_plays_its_maps_in_order() {
    use sightline::campaign::{Campaign, MapRef};
    use sightline::play::Exit;
    let dir = tempfile::tempdir().unwrap();
    let copy = |name: &str| std::fs::copy(map_path(name), dir.path().join(name)).unwrap();
    copy("machinery.ron");
    copy("two_rooms.ron");
    copy("room.ron");
    let campaign = dir.path().join("campaign.ron");
    std::fs::write(
        &campaign,
        r#"// The machinery, then two rooms; its secret exit would go to room.ron.
        Campaign(name: "Test", maps: [
            CampaignMap(map: "machinery.ron", secret: "room.ron"),
            CampaignMap(map: "two_rooms.ron"),
            CampaignMap(map: "room.ron", next: "two_rooms.ron"),
        ])"#,
    )
    .unwrap();
    let c = Campaign::of(&MapRef::File(campaign.clone())).unwrap_or_else(|e| panic!("{e}"));
    let name = |m: Option<MapRef>| m.map(|m| m.short_name());
    let first = c.first();
    assert_eq!(first.short_name(), "machinery.ron");
    assert_eq!(name(c.next(&first, Exit::Normal)).as_deref(), Some("two_rooms.ron"));
    assert_eq!(name(c.next(&first, Exit::Secret)).as_deref(), Some("room.ron"));
    let rooms = MapRef::File(dir.path().join("room.ron"));
    assert_eq!(name(c.next(&rooms, Exit::Normal)).as_deref(), Some("two_rooms.ron"));
    let two = MapRef::File(dir.path().join("two_rooms.ron"));
    assert_eq!(name(c.next(&two, Exit::Normal)).as_deref(), Some("room.ron"));
    // The playthrough starts on its first map.
    let play = Playthrough::of(&MapRef::File(campaign.clone()), GameOptions::default()).unwrap();
    assert_eq!(play.map.short_name(), "machinery.ron");
    std::fs::write(&campaign, r#"Campaign(name: "Bad", maps: [CampaignMap(map: "nowhere.ron")])"#).unwrap();
    let err = Campaign::of(&MapRef::File(campaign.clone())).unwrap_err().to_string();
    assert!(err.contains("campaign.ron: map 0: ") && err.contains("nowhere.ron does not exist"), "{err}");
    std::fs::write(&campaign, r#"Campaign(name: "Bad", maps: [CampaignMap(mapp: "x")])"#).unwrap();
    let err = Campaign::of(&MapRef::File(campaign)).unwrap_err().to_string();
    assert!(err.contains("campaign.ron: 1:") && err.contains("mapp"), "{err}");
}

/// Death and rebirth: a player who dies (here in the slime, health set low)
/// cannot move, its eye sinks to the floor, and use restarts the map from
/// its start with full health: use marks the player reborn that tic
/// (`P_DeathThink`), and the next tic reloads the map and plays its first
/// tic (`G_DoReborn`).
#[test]
fn a_dead_player_restarts_the_map_with_use() {
    let map = MapRef::File(map_path("machinery.ron"));
    let mut play = Playthrough::of(&map, GameOptions::default()).unwrap();
    let start = play.game.player().pos;
    assert!(play.game.place_player(DVec2::new(736.0, 548.0), 0.0), "the slime is out of reach");
    play.game.set_health(5);
    for _ in 0..40 {
        play.tick(&TickInput::default()).unwrap();
    }
    assert!(play.game.player().dead(), "health {}", play.game.player().health);
    let at = play.game.player().pos;
    for _ in 0..60 {
        play.tick(&TickInput { forward: 1, run: true, ..Default::default() }).unwrap();
    }
    let p = play.game.player();
    assert!(p.pos.distance(at) < 1.0, "a dead player walked");
    assert_eq!(play.game.view(1.0).z, p.z + 6.0, "the eye sinks to 6 above the feet");
    play.tick(&TickInput { use_line: true, ..Default::default() }).unwrap();
    assert!(play.game.player().dead() && play.game.reborn());
    play.tick(&TickInput::default()).unwrap();
    assert_eq!((play.game.player().pos, play.game.player().health, play.game.ticks()), (start, 100, 1));
}
