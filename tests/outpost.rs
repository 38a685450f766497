//! maps/outpost.ron, the default level: everything it names exists and it
//! compiles; and it is fought through from start to exit on the middle
//! skill by the player's own inputs alone (no teleporting, no healing): a
//! small driver walks a route of waypoints, presses use where the level
//! asks, and whenever a monster is in sight stops, turns to it and fires
//! (the shotgun once it has one). Reaching the intermission alive is the
//! level's balance check; the inputs replayed as a demo end the same way,
//! saved and loaded every few seconds on the way. Played on the
//! simulation with Doom's rules; the driver sees a monster as the monsters
//! see the player (`sim::sight::check_sight`, Doom's `P_CheckSight`).

use glam::DVec2;
use sightline::actors::ActorFlag;
use sightline::campaign::MapRef;
use sightline::materials::Materials;
use sightline::play::events::Origin;
use sightline::play::playthrough::{Phase, Playthrough};
use sightline::play::{Demo, Exit, GameOptions, TickInput};
use sightline::sim::game::SimGame;
use sightline::sim::mobj::mf;
use sightline::sim::MobjId;
use sightline_tests::map_path;

#[test]
fn every_actor_and_texture_the_outpost_names_exists_and_it_compiles() {
    let path = map_path("outpost.ron");
    let text = std::fs::read_to_string(&path).unwrap();
    let map = sightline::map::parse_map(&text, "outpost.ron").unwrap_or_else(|e| panic!("{e}"));
    // Resolved with no art folders and no WAD: all of it is built in.
    let materials = Materials::resolve(&map, &[], "outpost.ron").unwrap_or_else(|e| panic!("{e}"));
    let table = sightline::actors::ActorTable::active();
    for (i, t) in map.things.iter().enumerate() {
        assert!(table.get(&t.kind).is_some(), "thing {i}: {} is not an actor", t.kind);
    }
    // Every thing but the player start and the teleport destination is drawn.
    let drawn = materials.sprites.iter().filter(|s| s.is_some()).count();
    assert_eq!(drawn, map.things.len() - 2);
    // Every frame the roster's monsters can show has all eight views.
    for name in ["sentry", "stalker", "spitter"] {
        let def = table.get(name).unwrap();
        for id in table.states_of(def) {
            let s = table.state(id);
            let slot = Materials::view_index(s.sprite, s.frame);
            assert!(materials.sprite_views[slot].is_some(), "{name}: state {} has no picture", id.0);
        }
    }
    let level = sightline_tests::load(&path);
    assert!(level.compiled.map.things.len() > 40);
    // Kinds of monster, and the level's range of machinery.
    let kinds: std::collections::BTreeSet<&str> = map
        .things
        .iter()
        .filter(|t| table.get(&t.kind).is_some_and(|d| d.has(ActorFlag::CountKill)))
        .map(|t| t.kind.as_str())
        .collect();
    assert_eq!(kinds.into_iter().collect::<Vec<_>>(), ["sentry", "spitter", "stalker"]);
}

/// Plays a playthrough from the player's inputs and remembers them.
struct Driver {
    play: Playthrough,
    inputs: Vec<TickInput>,
    /// Ticks spent fighting, and shots fired.
    fighting: usize,
}

impl Driver {
    fn tick(&mut self, input: TickInput) {
        self.play.tick(&input).unwrap_or_else(|e| panic!("{e}"));
        self.inputs.push(input);
        let p = self.play.game.player();
        assert!(!p.dead(), "the player died at {} on tick {}: {:?}", p.pos, self.play.game.ticks(), self.stats());
    }

    fn stats(&self) -> String {
        let (p, s) = (self.play.game.player(), self.play.game.stats());
        format!("health {} armour {} ammo {:?} kills {:?} items {:?}", p.health, p.armor, p.ammo, s.kills, s.items)
    }

    fn pos(&self) -> DVec2 {
        self.play.game.player().pos
    }

    fn sim(&self) -> &SimGame {
        &self.play.game
    }

    /// The nearest live monster the player can see, within 1,500 units.
    /// Looking leaves the game as it was: Doom's sight check marks lines
    /// with `validcount` and sets the shared slopes, which are put back.
    fn enemy(&mut self) -> Option<MobjId> {
        let game = &mut self.play.game;
        let sim = &mut game.sim;
        let me = sim.player(sim.console).expect("a player").mo;
        let kept = (sim.validcount, sim.line_valid.clone(), sim.tm.clone());
        let at = |sim: &sightline::sim::Sim, id: MobjId| {
            let m = sim.mo(id);
            DVec2::new(m.x.to_f64(), m.y.to_f64())
        };
        let mut best: Option<(f64, MobjId)> = None;
        let monsters: Vec<MobjId> = sim.live_mobjs().collect();
        for id in monsters {
            let m = sim.mo(id);
            if m.removed || m.health <= 0 || !m.has(mf::COUNTKILL) {
                continue;
            }
            let d = at(sim, id).distance(at(sim, me));
            if d > 1500.0 || best.is_some_and(|(bd, _)| bd <= d) {
                continue;
            }
            if sightline::sim::sight::check_sight(sim, me, id) {
                best = Some((d, id));
            }
        }
        (sim.validcount, sim.line_valid, sim.tm) = kept;
        best.map(|(_, id)| id)
    }

    /// Fights what it sees until nothing is in sight: turns to it and fires
    /// when facing it, backing off from what comes close.
    fn fight(&mut self) {
        while let Some(id) = self.enemy() {
            let m = self.sim().sim.mo(id);
            let to = DVec2::new(m.x.to_f64(), m.y.to_f64()) - self.pos();
            let turn = self.turn_towards(to.y.atan2(to.x).to_degrees());
            let p = self.play.game.player();
            let table = &self.sim().sim.info.table;
            let shotgun = p.ammo[1] > 0 && p.weapons.iter().any(|&w| table.actors[w].name == "shotgun");
            let weapon = if shotgun { 3 } else { 2 };
            let forward = if to.length() < 96.0 { -1 } else { 0 };
            self.fighting += 1;
            self.tick(TickInput { fire: turn.abs() < 6.0, turn: turn as f32, weapon, forward, ..Default::default() });
        }
    }

    /// Walks to `to` (fighting whatever comes into sight on the way) and
    /// stops on it. Friction keeps 0.90625 of the speed a tick, so a body
    /// coasts about ten times its speed: it thrusts only while slower than
    /// a tenth of the distance left.
    fn walk_to(&mut self, to: DVec2) {
        for _ in 0..600 {
            self.fight();
            let d = to - self.pos();
            let velocity = self.play.game.player().velocity;
            if d.length() < 12.0 && velocity.length() < 1.0 {
                return;
            }
            let turn = self.turn_towards(d.y.atan2(d.x).to_degrees());
            let wanted = (d.length() / 10.0).min(16.0);
            let going = velocity.dot(d.normalize_or_zero());
            let push = turn.abs() < 20.0 && going < wanted && d.length() >= 12.0;
            self.tick(TickInput {
                forward: i8::from(push),
                turn: turn as f32,
                run: wanted > 8.0,
                ..Default::default()
            });
        }
        panic!("did not reach {to} from {}: {}", self.pos(), self.stats());
    }

    /// The turn that faces `angle` degrees, at most 15 a tick.
    fn turn_towards(&self, angle: f64) -> f64 {
        let now = self.play.game.player().angle;
        ((angle - now + 540.0).rem_euclid(360.0) - 180.0).clamp(-15.0, 15.0)
    }

    fn use_facing(&mut self, angle: f64) {
        for _ in 0..40 {
            let turn = self.turn_towards(angle);
            if turn.abs() < 1e-9 {
                break;
            }
            self.tick(TickInput { turn: turn as f32, ..Default::default() });
        }
        self.tick(TickInput { use_line: true, ..Default::default() });
        self.tick(TickInput::default());
    }

    /// Stands (fighting) until the player's feet are at `z`.
    fn ride_to(&mut self, z: f64) {
        for _ in 0..300 {
            self.fight();
            if self.play.game.player().z == z {
                return;
            }
            self.tick(TickInput::default());
        }
        panic!("never reached height {z}: at {} z {}", self.pos(), self.play.game.player().z);
    }

    /// Stands (fighting) until no mover is at work in `sector`.
    fn wait_for_rest(&mut self, sector: usize) {
        use sightline::autopilot::observe::Observe;
        for _ in 0..600 {
            self.fight();
            if !self.sim().is_busy(sector) {
                return;
            }
            self.tick(TickInput::default());
        }
        panic!("sector {sector} never came to rest");
    }

    fn wait(&mut self, ticks: usize) {
        for _ in 0..ticks {
            self.fight();
            self.tick(TickInput::default());
        }
    }
}

#[test]
fn the_outpost_is_fought_through_to_its_exit_on_the_middle_skill() {
    let map = MapRef::File(map_path("outpost.ron"));
    let options = GameOptions::default();
    let play = Playthrough::of(&map, options).unwrap_or_else(|e| panic!("{e}"));
    let mut d = Driver { play, inputs: Vec::new(), fighting: 0 };
    let w = DVec2::new;
    // Out of the guardroom into the courtyard.
    d.walk_to(w(416.0, 330.0));
    d.use_facing(90.0);
    d.wait(30);
    d.walk_to(w(416.0, 470.0));
    // The shotgun, then the armour in the slime.
    d.walk_to(w(200.0, 600.0));
    d.walk_to(w(96.0, 940.0));
    d.walk_to(w(544.0, 570.0));
    d.walk_to(w(544.0, 700.0));
    d.walk_to(w(544.0, 570.0));
    assert!(d.play.game.player().armor >= 100, "no armour: {}", d.stats());
    // The lift up to the control room, its switch, and the lift down.
    d.walk_to(w(730.0, 704.0));
    d.use_facing(0.0);
    d.wait(40);
    d.walk_to(w(800.0, 704.0));
    d.ride_to(104.0);
    d.walk_to(w(900.0, 704.0));
    d.walk_to(w(1110.0, 720.0));
    d.use_facing(0.0);
    d.walk_to(w(1100.0, 620.0));
    d.walk_to(w(900.0, 704.0));
    // Leaving the lift for the control room crossed its walk line too
    // (Doom's walk lines go off from either side): it may still be on its
    // way down and back; once it rests, crossing the line calls it again.
    d.wait_for_rest(6);
    d.walk_to(w(800.0, 704.0));
    d.ride_to(-24.0);
    // Through the door the switch opened, into the hall.
    d.walk_to(w(660.0, 900.0));
    d.walk_to(w(352.0, 980.0));
    d.walk_to(w(352.0, 1100.0));
    // The key on the dais, then the secret room.
    d.walk_to(w(384.0, 1250.0));
    d.walk_to(w(384.0, 1380.0));
    assert_eq!(d.play.game.player().keys.len(), 1, "no key: {}", d.stats());
    d.walk_to(w(384.0, 1250.0));
    d.walk_to(w(160.0, 1216.0));
    d.use_facing(180.0);
    d.wait(40);
    d.walk_to(w(80.0, 1216.0));
    assert_eq!(d.play.game.stats().secrets, (1, 1));
    d.walk_to(w(160.0, 1216.0));
    // The blue door and the teleporter.
    d.walk_to(w(610.0, 1216.0));
    d.use_facing(0.0);
    d.wait(40);
    d.walk_to(w(700.0, 1216.0));
    d.walk_to(w(720.0, 1248.0));
    for _ in 0..100 {
        if d.pos().x > 1000.0 {
            break;
        }
        // Straight at the pad's middle (walking in from wherever the last
        // step ended).
        let to = w(784.0, 1248.0) - d.pos();
        let turn = d.turn_towards(to.y.atan2(to.x).to_degrees());
        d.tick(TickInput { forward: 1, turn: turn as f32, ..Default::default() });
    }
    assert!(d.pos().x > 1000.0, "never teleported: at {}", d.pos());
    // The exit yard, then the switch.
    d.wait(10);
    d.walk_to(w(1216.0, 1300.0));
    d.walk_to(w(1216.0, 1500.0));
    d.use_facing(90.0);
    let Phase::Intermission { exit, stats, .. } = &d.play.phase else {
        panic!("the exit switch did not end the level: {:?}", d.play.phase)
    };
    assert_eq!(*exit, Exit::Normal);
    println!(
        "the outpost: {} ticks ({:.0} s), {} of them fighting; {}; secrets {:?}",
        stats.ticks,
        stats.ticks as f64 / 35.0,
        d.fighting,
        d.stats(),
        stats.secrets
    );
    assert!(stats.kills.0 >= stats.kills.1 / 2, "fought through too few: {:?}", stats.kills);

    // The inputs are the game: played again, the same end.
    let demo = Demo { inputs: d.inputs.clone(), ..Demo::new(map.label()) };
    let demo = Demo::from_bytes(&demo.to_bytes(), "outpost.sldemo").unwrap();
    let mut again = Playthrough::of(&map, demo.options()).unwrap();
    // Saved every 151 ticks on the way (mid-fight, doors and the lift
    // moving), each save loaded and followed 70 ticks: the same game.
    let save_at: Vec<usize> = (40..demo.inputs.len()).step_by(151).collect();
    let saves = sightline_tests::saves_continue_exactly(&mut again, &demo.inputs, &save_at, 70);
    println!("saved and loaded on the way: {saves:?}");
    assert!(saves.saves >= 10 && saves.fighting >= 3, "{saves:?}");
    assert_eq!(again.phase, d.play.phase);
    // Heard: the run's sound rendered offline has sound where the game made
    // sounds (shots, doors and lifts, monsters) and silence where none
    // could still be playing; and the same bytes twice.
    let play = || Playthrough::of(&map, options).unwrap();
    let (samples, events) = sightline_tests::render_audio(&mut play(), &d.inputs);
    assert_eq!(samples.len(), d.inputs.len() * 2 * sightline::sound::FRAMES_PER_TICK);
    let kinds = |f: &dyn Fn(&Origin) -> bool| events.iter().filter(|(_, _, o)| f(o)).count();
    let (mine, machines, monsters) = (
        kinds(&|o| *o == Origin::Player),
        kinds(&|o| matches!(o, Origin::Sector(_))),
        kinds(&|o| matches!(o, Origin::Actor { .. })),
    );
    assert!(
        mine > 20 && machines >= 4 && monsters > 10,
        "{mine} of mine, {machines} of machines, {monsters} of monsters"
    );
    let frames = sightline::sound::FRAMES_PER_TICK;
    let rms = |ticks: std::ops::Range<usize>| {
        let part = &samples[2 * frames * ticks.start..2 * frames * ticks.end.min(d.inputs.len())];
        (part.iter().map(|v| v * v).sum::<f32>() / part.len().max(1) as f32).sqrt()
    };
    for &(tick, sound, origin) in &events {
        // The four ticks after it starts (sounds from afar are quieter, but heard).
        if origin == Origin::Player || matches!(origin, Origin::Sector(_)) {
            assert!(rms(tick - 1..tick + 3) > 0.01, "{sound} at tick {tick} from {origin:?} is not heard");
        }
    }
    let (mut quiet, mut checked) = (0, 0);
    for tick in 0..d.inputs.len() {
        // Our voices last under 1.2 s: 42 ticks after the last start, silence.
        if !events.iter().any(|&(t, _, _)| t <= tick + 1 && tick + 1 < t + 42) {
            checked += 1;
            quiet += usize::from(rms(tick..tick + 1) == 0.0);
        }
    }
    assert!(checked > 100 && quiet == checked, "{quiet} of {checked} ticks with no sound playing are silent");
    assert!(sightline_tests::render_audio(&mut play(), &d.inputs).0 == samples, "the same run sounds different");
    println!("heard: {mine} of mine, {machines} of machines, {monsters} of monsters; {checked} ticks silent");
    if let Some(path) = std::env::var_os("SIGHTLINE_WRITE_OUTPOST_DEMO") {
        Demo { inputs: d.inputs.clone(), ..Demo::new("maps/outpost.ron") }.save(path.as_ref()).unwrap();
    }
}
