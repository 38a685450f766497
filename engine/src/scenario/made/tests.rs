//! Made scenarios played: each event pays as specified, once where it
//! should, and bad specifications and maps are refused by name.

use super::*;
use crate::scenario::{End, Episode, GameVariable};

/// A corridor 128 units wide of rooms side by side along x, each
/// `(x0, x1, sector fields)`, floor 0 and ceiling 128; the line between
/// room `i` and `i + 1` carries `specials[i]` when given. `things` is the
/// RON of the things list.
fn corridor(rooms: &[(f64, f64, &str)], between: &[&str], things: &str) -> String {
    let xs: Vec<f64> = std::iter::once(rooms[0].0).chain(rooms.iter().map(|r| r.1)).collect();
    let n = xs.len();
    // Vertices: bottom row 0..n, top row n..2n.
    let mut vertices: Vec<String> = xs.iter().map(|x| format!("({x:?}, 0.0)")).collect();
    vertices.extend(xs.iter().map(|x| format!("({x:?}, 128.0)")));
    let sectors: Vec<String> = rooms
        .iter()
        .map(|r| format!("Sector(floor: 0.0, ceiling: 128.0, light: 160, floor_texture: \"FLOOR\", {})", r.2))
        .collect();
    let mut lines = vec![format!("Line(from: 0, to: {n}, front: Side(sector: 0, middle: \"BRICK\"))")];
    for i in 0..rooms.len() {
        lines.push(format!("Line(from: {}, to: {}, front: Side(sector: {i}, middle: \"BRICK\"))", n + i, n + i + 1));
        lines.push(format!("Line(from: {}, to: {i}, front: Side(sector: {i}, middle: \"BRICK\"))", i + 1));
    }
    lines.push(format!("Line(from: {}, to: {}, front: Side(sector: {}, middle: \"BRICK\"))", 2 * n - 1, n - 1, n - 2));
    for i in 1..n - 1 {
        let special = between.get(i - 1).map_or(String::new(), |s| format!(", {s}"));
        lines.push(format!(
            "Line(from: {i}, to: {}, front: Side(sector: {i}), back: Side(sector: {}){special})",
            n + i,
            i - 1
        ));
    }
    format!(
        "Map(version: 2, name: \"Made\", vertices: [{}], sectors: [{}], lines: [{}], things: [{things}])",
        vertices.join(", "),
        sectors.join(", "),
        lines.join(", ")
    )
}

fn text(ron: String) -> MapInput {
    MapInput::Text { text: ron, label: "made.ron".into(), dir: None, wad: None }
}

fn settings(buttons: &str) -> ScenarioConfig {
    let mut config = ScenarioConfig::default();
    config.apply(&format!("available_buttons = {{ {buttons} }}"), "test").unwrap();
    config
}

fn episode(map: String, rewards: &str, buttons: &str) -> Episode {
    let made = Made::open(&text(map), RewardSpec::from_ron(rewards).unwrap()).unwrap_or_else(|e| panic!("{e}"));
    made.scenario(&settings(buttons)).unwrap().episode(7).unwrap()
}

/// Plays `action` until the episode ends or `most` actions; the rewards
/// paid, one per action.
fn play(e: &mut Episode, action: &[f64], most: u32) -> Vec<f64> {
    let mut paid = Vec::new();
    while e.end().is_none() && paid.len() < most as usize {
        paid.push(e.step(action));
    }
    paid
}

const START: &str = "Thing(kind: \"player_start\", x: 64.0, y: 64.0, angle: 0.0)";

#[test]
fn walking_into_the_goal_sector_pays_once_and_ends_the_episode() {
    let map = corridor(&[(0.0, 256.0, ""), (256.0, 384.0, ""), (384.0, 512.0, "")], &[], START);
    let rewards =
        "Rewards(living: -0.01, reach: [Reach(sector: 1, reward: 5.0), Reach(sector: 2, reward: 10.0, end: true)])";
    let mut e = episode(map, rewards, "MOVE_FORWARD");
    let paid = play(&mut e, &[1.0], 400);
    assert_eq!(e.end(), Some(End::Exit), "walked {} actions without reaching the goal", paid.len());
    let goals: Vec<f64> = paid.iter().map(|r| r + 0.01).filter(|r| r.abs() > 1e-9).collect();
    assert_eq!(goals.len(), 2, "{goals:?}");
    assert!((goals[0] - 5.0).abs() < 1e-9 && (goals[1] - 10.0).abs() < 1e-9, "{goals:?}");
    assert!((e.total_reward - (15.0 - 0.01 * paid.len() as f64)).abs() < 1e-9, "{}", e.total_reward);
    assert_eq!(e.reached(), [true, true]);
    let x = crate::scenario::variables::value(&e.game, 0, GameVariable::PositionX);
    assert!((384.0..512.0).contains(&x), "ended at x {x}, not in the goal");
}

#[test]
fn a_goal_is_paid_once_however_often_it_is_entered() {
    let map = corridor(&[(0.0, 256.0, ""), (256.0, 384.0, "")], &[], START);
    let mut e =
        episode(map, "Rewards(reach: [Reach(sector: 1, reward: 3.0)], timeout: 400)", "MOVE_FORWARD MOVE_BACKWARD");
    // There and back, three times.
    for _ in 0..3 {
        play(&mut e, &[1.0, 0.0], 60);
        play(&mut e, &[0.0, 1.0], 60);
    }
    let x = crate::scenario::variables::value(&e.game, 0, GameVariable::PositionX);
    assert!(x < 256.0, "not back in the first room: {x}");
    assert_eq!(e.total_reward, 3.0);
    assert_eq!(e.end(), None);
}

#[test]
fn a_monster_killed_by_shooting_pays_kill() {
    let things = format!("{START}, Thing(kind: \"zombieman\", x: 320.0, y: 64.0, angle: 180.0)");
    let map = corridor(&[(0.0, 512.0, "")], &[], &things);
    let mut e = episode(map, "Rewards(kill: 1.5, timeout: 350)", "ATTACK");
    let paid = play(&mut e, &[1.0], 1000);
    assert_eq!(e.end(), Some(End::Timeout));
    assert_eq!(paid.len(), 350);
    assert_eq!(crate::scenario::variables::value(&e.game, 0, GameVariable::KillCount), 1.0);
    assert_eq!(paid.iter().filter(|&&r| r != 0.0).count(), 1, "paid on more than one tic");
    assert_eq!(e.total_reward, 1.5);
}

#[test]
fn picking_up_a_medikit_pays_pickup_by_kind_and_one_left_lying_pays_nothing() {
    // A clip, then two medikits on the way: the first heals 90 to 100,
    // so the second stays where it is.
    let things = format!(
        "{START}, Thing(kind: \"clip\", x: 128.0, y: 64.0), Thing(kind: \"medikit\", x: 192.0, y: 64.0), \
         Thing(kind: \"medikit\", x: 320.0, y: 64.0)"
    );
    let map = corridor(&[(0.0, 512.0, "")], &[], &things);
    let mut e = episode(map, "Rewards(pickup: (each: 0.5, kinds: {\"medikit\": 2.0}), timeout: 120)", "MOVE_FORWARD");
    e.game.set_health(90);
    play(&mut e, &[1.0], 1000);
    let x = crate::scenario::variables::value(&e.game, 0, GameVariable::PositionX);
    assert!(x > 330.0, "did not walk over every item: x {x}");
    assert_eq!(crate::scenario::variables::value(&e.game, 0, GameVariable::Health), 100.0);
    assert_eq!(e.total_reward, 2.5);
    let medikits = e.game.sim.mobjs.iter().filter(|m| !m.removed && m.has(crate::sim::mobj::mf::SPECIAL)).count();
    assert_eq!(medikits, 1, "the second medikit should still lie there");
}

#[test]
fn a_nukage_floor_pays_damage_taken_per_point() {
    let nukage = "special: SectorSpecial(damage: Damage(amount: 10))";
    let map = corridor(&[(0.0, 256.0, nukage)], &[], START);
    let mut e = episode(map, "Rewards(damage_taken: -0.25, timeout: 200)", "MOVE_FORWARD");
    // The episode starts after its start time (a tic, which hurt already).
    let health = || crate::scenario::variables::value(&e.game, 0, GameVariable::Health);
    let before = health();
    let paid = play(&mut e, &[0.0], 1000);
    let lost = before - crate::scenario::variables::value(&e.game, 0, GameVariable::Health);
    assert!(lost >= 50.0, "the floor hurt only {lost} points in 200 tics");
    assert_eq!(e.total_reward, -0.25 * lost);
    // Every hurt is paid on its tic: a multiple of 10 points.
    assert!(paid.iter().all(|&r| r == 0.0 || r == -2.5), "{paid:?}");
}

#[test]
fn a_secret_and_the_exit_pay_and_the_exit_ends_the_episode_at_once() {
    let exit = "special: LineSpecial(on: Walk, action: Exit)";
    let secret = "special: SectorSpecial(secret: true)";
    let map = corridor(&[(0.0, 192.0, ""), (192.0, 320.0, secret), (320.0, 512.0, "")], &["", exit], START);
    let mut e = episode(map, "Rewards(secret: 2.0, exit: 7.0, death: -100.0)", "MOVE_FORWARD");
    let paid = play(&mut e, &[1.0], 400);
    assert_eq!(e.end(), Some(End::Exit));
    assert_eq!(paid.last(), Some(&7.0), "the exit's action should pay it and be the last");
    assert_eq!(e.total_reward, 9.0);
}

#[test]
fn death_pays_the_death_reward_and_the_timeout_ends_the_episode() {
    let map = corridor(&[(0.0, 256.0, "special: SectorSpecial(damage: Damage(amount: 20))")], &[], START);
    let mut e = episode(map.clone(), "Rewards(death: -100.0, living: 1.0)", "MOVE_FORWARD");
    e.game.set_health(15);
    let paid = play(&mut e, &[0.0], 1000);
    assert_eq!(e.end(), Some(End::Death));
    assert_eq!(e.total_reward, paid.len() as f64 - 100.0);
    let mut e = episode(map, "Rewards(timeout: 40, living: 1.0)", "MOVE_FORWARD");
    assert_eq!(play(&mut e, &[0.0], 1000).len(), 40);
    assert_eq!(e.end(), Some(End::Timeout));
}

#[test]
fn the_specification_reads_from_json_as_from_ron() {
    let json = r#"{"kill": 1, "pickup": {"kinds": {"medikit": 2}}, "reach": [{"sector": 1, "reward": 5, "end": true}],
                  "living": -0.01, "death": -10, "timeout": 2100}"#;
    let ron = "(kill: 1.0, pickup: (kinds: {\"medikit\": 2.0}), reach: [(sector: 1, reward: 5.0, end: true)], \
               living: -0.01, death: -10.0, timeout: 2100)";
    assert_eq!(RewardSpec::parse(json).unwrap(), RewardSpec::parse(ron).unwrap());
    let number = RewardSpec::parse("Rewards(pickup: 0.5)").unwrap();
    assert_eq!(number.pickup, Pickup { each: 0.5, kinds: Default::default() });
    let spec = RewardSpec::parse(ron).unwrap();
    assert_eq!(RewardSpec::from_ron(&spec.to_ron()).unwrap(), spec);
}

/// The error `rewards` gets on the two-room corridor.
fn refused(rewards: &str) -> String {
    let map = corridor(&[(0.0, 256.0, ""), (256.0, 384.0, "")], &[], START);
    match RewardSpec::parse(rewards).and_then(|spec| Made::open(&text(map), spec)) {
        Ok(_) => panic!("{rewards} was accepted"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bad_specifications_are_refused_naming_the_element() {
    let cases = [
        (
            "Rewards(reach: [Reach(sector: 9, reward: 1.0)])",
            "rewards.reach[0].sector: sector 9 is not in the map (its sectors are 0..2)",
        ),
        ("Rewards(reach: [(sector: -1)])", "rewards.reach[0].sector: sector -1 is not in the map"),
        ("Rewards(reach: [(sector: 1), (sector: 1)])", "rewards.reach[1].sector: sector 1 is already reach[0]"),
        ("Rewards(timeout: -5)", "rewards.timeout: -5 tics is negative"),
        ("Rewards(kill: NaN)", "rewards.kill: NaN is not a finite number"),
        (
            "Rewards(pickup: (kinds: {\"medkit\": 1.0}))",
            "rewards.pickup.kinds[\"medkit\"]: \"medkit\" names no item; did you mean \"medikit\"?",
        ),
        ("Rewards(pickup: (kinds: {\"imp\": 1.0}))", "\"imp\" is not an item"),
        ("Rewards(kil: 1.0)", "rewards: 1:9: Unexpected field named `kil`"),
        ("Rewards(pickup: (every: 1.0))", "rewards: 1:18: Unexpected field named `every`"),
        ("Rewards(kill: 1.0", "rewards: 1:15: Expected comma"),
        (r#"{"reach": [{"sector": 1, "rewrd": 2}]}"#, "rewards: unknown field `rewrd`"),
        (r#"{"timeout": "long"}"#, "rewards: invalid type: string \"long\""),
    ];
    for (rewards, expected) in cases {
        let message = refused(rewards);
        assert!(message.contains(expected), "{rewards}: said {message:?}, not {expected:?}");
    }
}

#[test]
fn bad_maps_are_refused_naming_the_element() {
    let spec = RewardSpec::default();
    let cases = [
        (
            "Map(name: \"x\", vertices: [(0, 0)], sectors: [Sectr()], lines: [])",
            "made.ron:1:46: Expected struct `Sector` but found `Sectr`",
        ),
        (&corridor(&[(0.0, 256.0, "")], &[], "")[..], "made.ron: the map has no thing of kind \"player_start\""),
        (
            &corridor(&[(0.0, 256.0, "")], &[], "Thing(kind: \"player_start\", x: 64.0, y: 900.0)")[..],
            "made.ron: thing 0: the player start (64.0, 900.0) is not inside any sector",
        ),
    ];
    for (map, expected) in cases {
        match Made::open(&text(map.to_string()), spec.clone()) {
            Ok(_) => panic!("{map} was accepted"),
            Err(e) => assert!(e.to_string().contains(expected), "said {e:?}, not {expected:?}"),
        }
    }
    let missing = MapInput::File("no/such/map.ron".into());
    let e = Made::open(&missing, spec).err().map(|e| e.to_string()).unwrap_or_default();
    assert!(e.starts_with("no/such/map.ron: cannot read"), "{e}");
}

#[test]
fn check_finds_what_cannot_be_reached_or_paid() {
    // Two rooms apart: the goal (sector 1) is a closed room of its own.
    let apart = "Map(version: 2, name: \"Apart\", \
        vertices: [(0.0, 0.0), (0.0, 128.0), (128.0, 128.0), (128.0, 0.0), (256.0, 0.0), (256.0, 128.0), (384.0, 128.0), (384.0, 0.0)], \
        sectors: [Sector(floor: 0.0, ceiling: 128.0, light: 160), Sector(floor: 0.0, ceiling: 128.0, light: 160)], \
        lines: [Line(from: 0, to: 1, front: Side(sector: 0, middle: \"BRICK\")), Line(from: 1, to: 2, front: Side(sector: 0, middle: \"BRICK\")), \
                Line(from: 2, to: 3, front: Side(sector: 0, middle: \"BRICK\")), Line(from: 3, to: 0, front: Side(sector: 0, middle: \"BRICK\")), \
                Line(from: 4, to: 5, front: Side(sector: 1, middle: \"BRICK\")), Line(from: 5, to: 6, front: Side(sector: 1, middle: \"BRICK\")), \
                Line(from: 6, to: 7, front: Side(sector: 1, middle: \"BRICK\")), Line(from: 7, to: 4, front: Side(sector: 1, middle: \"BRICK\"))], \
        things: [Thing(kind: \"player_start\", x: 64.0, y: 64.0), Thing(kind: \"medikit\", x: 320.0, y: 64.0)])";
    let spec =
        RewardSpec::from_ron("Rewards(kill: 1.0, exit: 1.0, reach: [(sector: 1, reward: 1.0), (sector: 0)])").unwrap();
    let findings = check(&text(apart.into()), Some(&spec), 3);
    let has =
        |severity: Severity, text: &str| findings.iter().any(|f| f.severity == severity && f.message.contains(text));
    let all: Vec<String> = findings.iter().map(ToString::to_string).collect();
    assert!(has(Severity::Warning, "rewards.reach[0]: sector 1 cannot be reached"), "{all:#?}");
    assert!(!has(Severity::Warning, "rewards.reach[1]: sector 0 cannot"), "{all:#?}");
    assert!(has(Severity::Warning, "rewards.reach[1]: the player starts in sector 0"), "{all:#?}");
    assert!(has(Severity::Warning, "the medikit at (320, 64) cannot be reached"), "{all:#?}");
    assert!(has(Severity::Warning, "rewards.kill: the map has no monster"), "{all:#?}");
    assert!(has(Severity::Warning, "the map has no exit, so rewards.exit is never paid"), "{all:#?}");
    assert!(has(Severity::Note, "0 of 1 items"), "{all:#?}");
    assert!(!findings.iter().any(|f| f.severity == Severity::Error), "{all:#?}");
    // The goal asked as a secret leaves the map's own secrets alone.
    assert!(!has(Severity::Warning, "secret sector"), "{all:#?}");

    // A map that does not validate: each problem an error of its own.
    let broken = apart.replace("(384.0, 0.0)", "(384.0, 128.0)");
    let findings = check(&text(broken), None, 3);
    assert!(findings.len() >= 2 && findings.iter().all(|f| f.severity == Severity::Error), "{findings:#?}");
    assert!(findings.iter().all(|f| f.message.starts_with("made.ron: ")), "{findings:#?}");
}

#[test]
fn a_monster_without_built_in_art_takes_a_stand_in() {
    // The imp has no picture of ours: with no WAD it is drawn as its
    // stand-in figure, eight views of each walking frame.
    let things = format!("{START}, Thing(kind: \"imp\", x: 200.0, y: 64.0, angle: 180.0)");
    let map = text(corridor(&[(0.0, 256.0, "")], &[], &things));
    let made = Made::open(&map, RewardSpec::default()).unwrap_or_else(|e| panic!("{e}"));
    let m = &made.opened.level.materials;
    let id = m.sprites[1].expect("the imp is drawn");
    assert_eq!(m.textures.name(id), "TROOA1");
    assert!(m.warnings.is_empty(), "{:?}", m.warnings);
}

#[test]
fn check_on_a_map_with_no_room_to_stand_reaches_nothing_without_a_panic() {
    // 40 units under the ceiling: the player (56 high) stands nowhere.
    let map = corridor(&[(0.0, 256.0, ""), (256.0, 384.0, "")], &[], START).replace("ceiling: 128.0", "ceiling: 40.0");
    let spec = RewardSpec::from_ron("Rewards(reach: [(sector: 1, reward: 1.0)])").unwrap();
    let findings = check(&text(map), Some(&spec), 3);
    let all: Vec<String> = findings.iter().map(ToString::to_string).collect();
    assert!(all.contains(&"warning: rewards.reach[0]: sector 1 cannot be reached".to_string()), "{all:#?}");
}
