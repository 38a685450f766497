use super::*;

const ROCKET: &str = r#####"
// A weapon, after rocket_basic.wad's.
actor Launcher : DoomWeapon replaces RocketLauncher 2003
{
  Weapon.AmmoUse 1
  Health.LowMessage 25, "$GOTMEDINEED"
  Inventory.Amount -25 // a comment
  Speed 2.5
  Damage (random(1, 8) * 4)
  Projectile
  +INVENTORY.ALWAYSPICKUP
  -SOLID
  var int user_x;
  States
  {
  Fire:
    MISG B 12 Bright Offset(0, -32) A_FireCustomMissile ("CustomRocket", 0, (1 + 2))
    "####" "#" random(1, 5)
    /* a long
       comment */ MISG B -1 A_ReFire
    Goto Super::Missile.Rocket+2
  Missile.Rocket:
    stop
  }
}
"#####;

fn expr(tokens: &[&str]) -> Expr {
    Expr { tokens: tokens.iter().map(|t| t.to_string()).collect() }
}

fn at(line: usize, column: usize) -> At {
    At { line, column }
}

#[test]
fn an_actor_reads_field_by_field() {
    let decorate = parse(ROCKET).unwrap();
    assert_eq!(decorate.items.len(), 1);
    let actor = decorate.actor("LAUNCHER").unwrap();
    assert_eq!(actor.name, "Launcher");
    assert_eq!(actor.parent.as_deref(), Some("DoomWeapon"));
    assert_eq!(actor.replaces.as_deref(), Some("RocketLauncher"));
    assert_eq!((actor.doomednum, actor.native, actor.at), (Some(2003), false, at(3, 1)));
    let property = |name: &str, values: Vec<Value>, line: usize| {
        ActorItem::Property(Property { name: name.to_string(), values, at: at(line, 3) })
    };
    let expected_body = [
        property("Weapon.AmmoUse", vec![Value::Int(1)], 5),
        property("Health.LowMessage", vec![Value::Int(25), Value::Str("$GOTMEDINEED".into())], 6),
        property("Inventory.Amount", vec![Value::Int(-25)], 7),
        property("Speed", vec![Value::Float(2.5)], 8),
        property("Damage", vec![Value::Expr(expr(&["(", "random", "(", "1", ",", "8", ")", "*", "4", ")"]))], 9),
        property("Projectile", vec![], 10),
        ActorItem::Flag { name: "INVENTORY.ALWAYSPICKUP".into(), set: true, at: at(11, 3) },
        ActorItem::Flag { name: "SOLID".into(), set: false, at: at(12, 3) },
        ActorItem::Unknown { text: "var int user_x ;".into(), at: at(13, 3) },
    ];
    assert_eq!(actor.body[..9], expected_body);
    let ActorItem::States(states) = &actor.body[9] else { panic!("{:?}", actor.body[9]) };
    assert_eq!(actor.body.len(), 10);
    let fire = Frame {
        sprite: "MISG".into(),
        frames: "B".into(),
        duration: Duration::Tics(12),
        keywords: vec![FrameKeyword::Bright],
        offset: Some((expr(&["0"]), expr(&["-", "32"]))),
        action: Some(Action {
            name: "A_FireCustomMissile".into(),
            args: vec![expr(&["\"CustomRocket\""]), expr(&["0"]), expr(&["(", "1", "+", "2", ")"])],
        }),
        at: at(17, 5),
    };
    let keep = Frame {
        sprite: "####".into(),
        frames: "#".into(),
        duration: Duration::Random(expr(&["1"]), expr(&["5"])),
        keywords: vec![],
        offset: None,
        action: None,
        at: at(18, 5),
    };
    let refire = Frame {
        sprite: "MISG".into(),
        frames: "B".into(),
        duration: Duration::Tics(-1),
        keywords: vec![],
        offset: None,
        action: Some(Action { name: "A_ReFire".into(), args: vec![] }),
        at: at(20, 19),
    };
    let goto = Flow::Goto { scope: Some("Super".into()), label: "Missile.Rocket".into(), offset: 2 };
    let expected_states = [
        StateItem::Label { name: "Fire".into(), at: at(16, 3) },
        StateItem::Frame(fire),
        StateItem::Frame(keep),
        StateItem::Frame(refire),
        StateItem::Flow { flow: goto, at: at(21, 5) },
        StateItem::Label { name: "Missile.Rocket".into(), at: at(22, 3) },
        StateItem::Flow { flow: Flow::Stop, at: at(23, 5) },
    ];
    assert_eq!(states[..], expected_states);
    assert_eq!(actor.frames_of("fire").len(), 3);
}

#[test]
fn the_top_level_reads_includes_constants_and_enums() {
    let text =
        "#INCLUDE \"actors/more.txt\"\nConst Int MAX = 2 * (3 + 1);\nenum { A, B = 2, };\nACTOR Thing native { }";
    let decorate = parse(text).unwrap();
    assert_eq!(
        decorate.items[..3],
        [
            TopLevel::Include { path: "actors/more.txt".into(), at: at(1, 1) },
            TopLevel::Const {
                ty: "Int".into(),
                name: "MAX".into(),
                value: expr(&["2", "*", "(", "3", "+", "1", ")"]),
                at: at(2, 1)
            },
            TopLevel::Enum {
                entries: vec![
                    EnumEntry { name: "A".into(), value: None },
                    EnumEntry { name: "B".into(), value: Some(expr(&["2"])) }
                ],
                at: at(3, 1)
            },
        ]
    );
    let thing = decorate.actor("thing").unwrap();
    assert!(thing.native && thing.body.is_empty() && thing.parent.is_none());
}

fn message(text: &str) -> String {
    parse(text).unwrap_err().to_string()
}

#[test]
fn each_error_names_its_place() {
    assert_eq!(message("actor A {\n  Tag \"open"), "line 2, column 7: unterminated string");
    assert_eq!(message("actor A { } /* never closed"), "line 1, column 13: unterminated /* comment");
    assert_eq!(
        message("actor A { }\n= 3"),
        "line 2, column 1: expected `actor`, `const`, `enum` or `#include`, found `=`"
    );
    assert_eq!(message("actor A : B\n  +SOLID"), "line 2, column 3: expected `{` after the actor's header, found `+`");
    assert_eq!(message("actor A {\n  +SOLID\n"), "line 3, column 1: the text ends inside actor A (opened at line 1)");
    assert_eq!(
        message("actor A {\n  States {\n  Spawn:\n    TNT1 A 1\n  }\n"),
        "line 6, column 1: the text ends inside actor A (opened at line 1)"
    );
    assert_eq!(
        message("actor A { States { Spawn: TNT1 A fast } }"),
        "line 1, column 34: a frame's duration must be a whole number or random(min, max), found `fast`"
    );
    assert_eq!(
        message("actor A { States { Spawn: TNT1 A random(1) } }"),
        "line 1, column 34: a frame's duration must be a whole number or random(min, max), found `random`"
    );
    assert_eq!(message("actor A { States { Spawn: goto } }"), "line 1, column 27: goto without a label");
    assert_eq!(message("actor A { Tag \"a\" é }"), "line 1, column 19: unexpected character 'é'");
    assert_eq!(message("enum { A"), "line 1, column 9: expected `,` or `}` in the enum, found end of file");
    assert_eq!(
        message("actor A { States { Spawn: TNT1 A 1 A_Jump(256, \"x\" } }"),
        "line 1, column 52: expected `,` or `)` after an argument, found `}`"
    );
    assert_eq!(
        message("actor A 99999999999999999999 { }"),
        "line 1, column 9: 99999999999999999999 is not a number DECORATE can hold"
    );
}

mod fuzz {
    use super::{parse, parse_lump, ROCKET};
    use proptest::prelude::*;

    proptest! {
        /// Any bytes: an answer, never a panic.
        #[test]
        fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
            let _ = parse_lump(&bytes);
        }

        /// A real actor cut anywhere.
        #[test]
        fn a_cut_actor_never_panics(cut in 0..ROCKET.len()) {
            let _ = parse(&ROCKET[..cut]);
        }

        /// Text made of DECORATE's own pieces, shuffled.
        #[test]
        fn shuffled_tokens_never_panic(tokens in proptest::collection::vec(
            prop_oneof![Just("actor"), Just("{"), Just("}"), Just("("), Just(")"), Just(":"), Just("::"), Just(","),
                        Just(";"), Just("+"), Just("-"), Just("."), Just("States"), Just("Spawn:"), Just("goto"),
                        Just("loop"), Just("TNT1"), Just("A"), Just("1"), Just("-1"), Just("2.5"), Just("\"x\""),
                        Just("random"), Just("Bright"), Just("Offset"), Just("A_Look"), Just("Super"), Just("const"),
                        Just("enum"), Just("#include"), Just("var"), Just("/*"), Just("*/"), Just("//"), Just("\n")],
            0..80)) {
            let _ = parse(&tokens.join(" "));
        }
    }
}

const WITH_DECORATE: [&str; 6] = [
    "cig.wad",
    "cig_with_unknown.wad",
    "deathmatch.wad",
    "defend_the_center.wad",
    "health_gathering_supreme.wad",
    "rocket_basic.wad",
];

fn decorate_of(dir: &std::path::Path, name: &str) -> Decorate {
    let wad = crate::wad::Wad::open(&dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    let index = wad.find("DECORATE").unwrap_or_else(|| panic!("{name} has no DECORATE"));
    parse_lump(wad.bytes(index)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

#[test]
fn every_shipped_decorate_lump_parses() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    for name in WITH_DECORATE {
        assert!(decorate_of(&dir, name).actors().count() > 0, "{name}");
    }
    let rocket = decorate_of(&dir, "rocket_basic.wad");
    let launcher = rocket.actor("CustomRocketLauncher").unwrap();
    assert_eq!(launcher.parent.as_deref(), Some("DoomWeapon"));
    let fire = launcher.frames_of("Fire");
    assert_eq!(fire.len(), 3);
    let action = fire[1].action.as_ref().unwrap();
    assert_eq!((action.name.as_str(), &action.args[..]), ("A_FireCustomMissile", &[expr(&["\"CustomRocket\""])][..]));
    let rocket_actor = rocket.actor("CustomRocket").unwrap();
    assert_eq!(rocket_actor.property("Projectile").map(|p| p.values.len()), Some(0));

    let health = decorate_of(&dir, "health_gathering_supreme.wad");
    let poison = health.actor("Poison").unwrap();
    assert_eq!(poison.property("Inventory.Amount").unwrap().values, [Value::Int(-25)]);
    let medikit = health.actor("CustomMedikit").unwrap();
    assert_eq!(
        medikit.property("Health.LowMessage").unwrap().values,
        [Value::Int(25), Value::Str("$GOTMEDINEED".into())]
    );

    let cig = decorate_of(&dir, "cig.wad");
    let marine = cig.actor("CustomMarineRocket").unwrap();
    assert_eq!(marine.doomednum, Some(9112));
    let goto = Flow::Goto { scope: Some("Super".into()), label: "Missile.Rocket".into(), offset: 0 };
    assert!(marine.states().any(|item| matches!(item, StateItem::Flow { flow, .. } if *flow == goto)));
}
