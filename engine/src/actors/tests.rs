//! The shipped table's content, and every load error with its message.

use super::*;

fn table(text: &str) -> Result<ActorTable, ActorTableError> {
    ActorTable::parse(&[(DOOM_TABLE, DOOM_TABLE_PATH), (text, "mod.ron")])
}

fn error(text: &str) -> String {
    table(text).expect_err("the table should be refused").to_string()
}

/// One actor in a mod file.
fn one(actor: &str) -> String {
    format!("Actors(actors: [{actor}])")
}

#[test]
fn the_shipped_table_adds_sightline_s_own_roster() {
    let (t, doom) = (ActorTable::doom(), ActorTable::parse(&[(DOOM_TABLE, DOOM_TABLE_PATH)]).unwrap());
    let own = ["sentry", "stalker", "spitter", "spitter_bolt"];
    assert_eq!(t.actors.len(), doom.actors.len() + own.len());
    for name in own {
        let a = t.get(name).unwrap_or_else(|| panic!("{name}"));
        // RON maps name them; no WAD number can collide with them.
        assert_eq!(a.doomednum, None, "{name}");
    }
    // Doom's actors are untouched by the roster.
    assert_eq!(t.get("imp").unwrap().health, doom.get("imp").unwrap().health);
    let spitter = t.get("spitter").unwrap();
    assert!(spitter.has(ActorFlag::CountKill));
}

#[test]
fn the_shipped_table_loads_with_doom_s_roster() {
    let t = &ActorTable::parse(&[(DOOM_TABLE, DOOM_TABLE_PATH)]).unwrap();
    // Every thing of Doom and Doom II, the player, missiles and effects, the
    // nine weapons; and ZDoom's two map markers (MapSpot, PatrolPoint).
    assert_eq!(t.actors.len(), 148);
    // Doom's 967 states less S_NULL and six unused, with the states that
    // Doom's actors share (the weapons' light-done, the pistol's flash...)
    // written once for each actor that uses them.
    assert_eq!(t.states.len(), 1011);
    assert_eq!(t.sprites.len(), 138);
    let zombie = t.get("zombieman").unwrap();
    assert_eq!((zombie.doomednum, zombie.health, zombie.pain_chance, zombie.speed), (Some(3004), 20, 200, 8.0));
    assert_eq!((zombie.radius, zombie.height, zombie.mass, zombie.reaction_time), (20.0, 56.0, 100, 8));
    assert!(zombie.has(ActorFlag::CountKill) && zombie.has(ActorFlag::Shootable));
    assert_eq!(zombie.drop, t.index("clip"));
    assert_eq!(t.sounds[zombie.sounds.see.unwrap()], "posit1");
    // Spawn: POSS AB 10 A_Look, loop.
    let spawn = zombie.label("Spawn").unwrap();
    let (a, b) = (t.state(spawn), t.state(t.state(spawn).next.unwrap()));
    assert_eq!((t.sprites[usize::from(a.sprite)].as_str(), a.frame, a.tics), ("POSS", 0, 10));
    assert_eq!(actions::spec(a.action.as_ref().unwrap().action).name, "A_Look");
    assert_eq!((b.frame, b.next), (1, Some(spawn)));
    // Death ends on a body that stays.
    let mut at = zombie.label("Death").unwrap();
    while t.state(at).tics != -1 {
        at = t.state(at).next.unwrap();
    }
    assert_eq!((t.state(at).frame, t.state(at).next), (11, None));
    // The imp's attack fires Doom's fireball by default.
    let imp = t.get("imp").unwrap();
    let call = (0..t.states.len() as u32)
        .map(|i| t.state(StateId(i)))
        .filter_map(|s| s.action.as_ref())
        .find(|c| actions::spec(c.action).name == "A_TroopAttack")
        .unwrap();
    assert_eq!(call.args, vec![Arg::Actor(t.index("imp_fireball").unwrap())]);
    assert_eq!(imp.doomednum, Some(3001));
    assert_eq!(t.get("hell_knight").unwrap().species, t.index("baron_of_hell").unwrap());
    assert_eq!(t.by_doomednum(5).map(|a| a.name.as_str()), Some("blue_card"));
    assert_eq!(t.get("player_start").map(|a| a.category), Some(Category::PlayerStart(1)));
    assert_eq!(t.get("red_skull").and_then(ActorDef::key), Some(KeyColour::Red));
    assert_eq!(t.first_frame(t.get("blue_card").unwrap()).as_deref(), Some("BKEYA"));
    assert_eq!(t.first_frame(t.get("teleport_destination").unwrap()), None);
    assert_eq!(t.nearest("imps"), Some("imp"));
    let shotgun = t.get("shotgun").unwrap();
    assert_eq!(shotgun.weapon.as_ref().map(|w| (w.slot, w.ammo, w.ammo_use)), Some((3, Some(AmmoKind::Shells), 1)));
    assert!(shotgun.pickup.as_ref().unwrap().give.contains(&Give::Weapon("shotgun".into())));
}

#[test]
fn every_shipped_label_and_state_resolves() {
    let t = ActorTable::doom();
    for a in &t.actors {
        for (label, id) in &a.labels {
            assert!((id.0 as usize) < t.states.len(), "{} {label}", a.name);
        }
        if a.category == Category::Monster {
            for label in ["Spawn", "Death"] {
                assert!(a.label(label).is_some(), "{} has no {label}", a.name);
            }
            // Commander Keen only hangs and dies.
            if a.label("See").is_some() {
                assert!(a.label("Melee").is_some() || a.label("Missile").is_some(), "{} cannot attack", a.name);
            }
        }
        if a.weapon.is_some() {
            for label in ["Ready", "Select", "Deselect", "Fire"] {
                assert!(a.label(label).is_some(), "{} has no {label}", a.name);
            }
        }
        let drawn = !a.category.is_marker() && !a.has(ActorFlag::NoSector);
        assert_eq!(t.first_frame(a).is_some(), drawn && a.label("Spawn").is_some(), "{}", a.name);
    }
    for s in &t.states {
        assert!(s.next.is_none_or(|n| (n.0 as usize) < t.states.len()));
        assert!(usize::from(s.sprite) < t.sprites.len());
    }
}

#[test]
fn a_mod_adds_replaces_and_inherits() {
    let text = r#"Actors(
        sprites: ["ZOMB"],
        actors: [
            // Replaces the shipped zombieman outright (same name).
            Actor(name: "zombieman", doomednum: 3004, category: Monster, health: 60, flags: [Solid, Shootable],
                states: "Spawn:\n ZOMB A -1\n stop"),
            // Inherits the imp, tougher; spawns wherever an imp would.
            Actor(name: "dark_imp", based_on: "imp", replaces: "imp", doomednum: 30001, health: 120,
                add_flags: [NoRadiusDamage], remove_flags: [CountKill],
                states: "Missile:\n TROO EF 8 A_FaceTarget\n TROO G 6 A_TroopAttack(\"baron_fireball\")\n goto See"),
        ],
    )"#;
    let t = table(text).unwrap();
    let zombie = t.get("zombieman").unwrap();
    assert_eq!((zombie.health, zombie.label("See")), (60, None));
    assert_eq!(t.sprites[usize::from(t.state(zombie.label("Spawn").unwrap()).sprite)], "ZOMB");
    let imp = t.index("imp").unwrap();
    let dark = t.index("dark_imp").unwrap();
    assert_eq!(t.spawned(imp), dark);
    let d = &t.actors[dark];
    assert_eq!((d.health, d.speed, d.radius, d.pain_chance), (120, 8.0, 20.0, 200));
    assert!(d.has(ActorFlag::NoRadiusDamage) && !d.has(ActorFlag::CountKill) && d.has(ActorFlag::Shootable));
    // Its own Missile; See and Spawn are the imp's states.
    assert_eq!(d.label("See"), t.actors[imp].label("See"));
    assert_ne!(d.label("Missile"), t.actors[imp].label("Missile"));
    let fire = t.state(StateId(d.label("Missile").unwrap().0 + 2));
    assert_eq!(fire.action.as_ref().unwrap().args, vec![Arg::Actor(t.index("baron_fireball").unwrap())]);
    assert_eq!(fire.next, t.actors[imp].label("See"));
    assert_eq!(t.by_doomednum(30001).map(|a| a.name.as_str()), Some("dark_imp"));
}

#[test]
fn the_state_syntax() {
    let text = one(r##"Actor(name: "thing", states: r#"
            Spawn: BAL1 AB 4 bright   // a comment
                   BAL1 C 0 fast A_Explode(64)
                   BAL1 D 3 A_PlaySound("pistol")
                   wait
            Death:
                   goto Spawn+2
        "#)"##);
    let t = table(&text).unwrap();
    let a = t.get("thing").unwrap();
    let s = a.label("Spawn").unwrap().0;
    let explode = t.state(StateId(s + 2));
    assert!(explode.fast && !explode.bright && t.state(StateId(s)).bright);
    assert_eq!(explode.action.as_ref().unwrap().args, vec![Arg::Int(64), Arg::Int(128)]);
    let sound = t.state(StateId(s + 3));
    assert_eq!(
        sound.action.as_ref().unwrap().args,
        vec![Arg::Sound(t.sounds.iter().position(|n| n == "pistol").unwrap())]
    );
    assert_eq!(sound.next, Some(StateId(s + 3)), "wait repeats the last state");
    assert_eq!(a.label("Death"), Some(StateId(s + 2)), "a label that is a goto is an alias");
}

#[test]
fn each_load_error_names_the_file_actor_and_state() {
    let cases: &[(&str, &str)] = &[
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4\n goto Sea")"#,
            "mod.ron: actor a, state Spawn (states line 3: `goto Sea`): no label Sea (this actor has Spawn)",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4 A_Lok\n loop")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 4 A_Lok`): unknown action A_Lok (did you mean A_Look?)",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSX A 4\n loop")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSX A 4`): unknown sprite POSX",
        ),
        (
            r#"Actor(name: "a", sounds: (see: "posit4"))"#,
            "mod.ron: actor a: sounds.see: no sound named \"posit4\" (did you mean posit1?)",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4 A_PlaySound(\"zzzzzz\")\n loop")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 4 A_PlaySound(\"zzzzzz\")`): no sound named \"zzzzzz\"",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4 A_Look(3)\n loop")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 4 A_Look(3)`): A_Look takes 0 arguments, given 1: A_Look()",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4 A_Explode(1, 2, 3)\n loop")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 4 A_Explode(1, 2, 3)`): A_Explode takes 2 arguments, given 3: A_Explode(damage: an integer = 128, radius: an integer = 128)",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4 A_Explode(\"big\")\n loop")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 4 A_Explode(\"big\")`): argument 1 (damage) must be an integer, given Str(\"big\"): A_Explode(damage: an integer = 128, radius: an integer = 128)",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4 A_PlaySound\n loop")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 4 A_PlaySound`): argument 1 (sound) is missing: A_PlaySound(sound: a sound name in quotes)",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4 A_TroopAttack(\"imp_fireboll\")\n loop")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 4 A_TroopAttack(\"imp_fireboll\")`): no actor named \"imp_fireboll\" (did you mean imp_fireball?)",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 0\n POSS B 0\n goto Spawn")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 0`): states of 0 tics lead back to themselves: the actor would never leave the tick",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 0\n wait")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 0`): states of 0 tics lead back to themselves: the actor would never leave the tick",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4")"#,
            "mod.ron: actor a, state Spawn (states line 2: `POSS A 4`): the states end without `loop`, `stop`, `wait` or `goto`",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A x\n loop")"#,
            "mod.ron: actor a, state ? (states line 2: `POSS A x`): `x` is not a number of tics",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n loop")"#,
            "mod.ron: actor a, state Spawn (states line 2: `loop`): a label needs a state before `loop` or `wait`",
        ),
        (
            r#"Actor(name: "a", states: "Spawn:\n POSS A 4\n loop\nDeath:")"#,
            "mod.ron: actor a, state Death (states line 4: `Death:`): label Death has no states after it",
        ),
        (r#"Actor(name: "a", based_on: "impp")"#, "mod.ron: actor a: based_on: no actor named \"impp\" (did you mean imp?)"),
        (r#"Actor(name: "a", based_on: "a")"#, "mod.ron: actor a: its based_on chain loops back to it"),
        (r#"Actor(name: "a", replaces: "a")"#, "mod.ron: actor a: replaces itself"),
        (r#"Actor(name: "a", drop: "clipp")"#, "mod.ron: actor a: drop: no actor named \"clipp\" (did you mean clip?)"),
        (r#"Actor(name: "a", radius: -1)"#, "mod.ron: actor a: radius -1 is not within 0..=4096"),
        (r#"Actor(name: "a", pain_chance: 300)"#, "mod.ron: actor a: pain_chance 300 is not within 0..=256 (out of 256)"),
        (r#"Actor(name: "A b")"#, "mod.ron: actor A b: a name is lower-case letters, digits and _"),
        (
            r#"Actor(name: "gun", weapon: (slot: 2), states: "Ready:\n PISG A 1 A_WeaponReady\n loop")"#,
            "mod.ron: actor gun: a weapon needs a Select: label",
        ),
        (
            r#"Actor(name: "a", pickup: (give: [Weapon("clip")], message: "", sound: "itemup"))"#,
            "mod.ron: actor a: pickup gives \"clip\", which has no weapon definition",
        ),
    ];
    for (actor, message) in cases {
        assert_eq!(error(&one(actor)), *message, "for {actor}");
    }
    // Two actors that replace each other; a name given twice; a doomednum twice.
    let e = error(r#"Actors(actors: [Actor(name: "a", replaces: "b"), Actor(name: "b", replaces: "a")])"#);
    assert_eq!(e, "mod.ron: actor a: its replacements loop back to it");
    let e = error(r#"Actors(actors: [Actor(name: "a"), Actor(name: "a")])"#);
    assert_eq!(e, "mod.ron: actor a: defined twice in this file");
    let e = error(r#"Actors(actors: [Actor(name: "a", doomednum: 9000), Actor(name: "b", doomednum: 9000)])"#);
    assert_eq!(e, "mod.ron: actor b: doomednum 9000 is also a's");
    let e = error(r#"Actors(sprites: ["TOOLONG"], actors: [])"#);
    assert_eq!(e, "mod.ron: sprite \"TOOLONG\": a sprite name is four letters or digits");
    // RON errors give the line and column; unknown fields and flags are errors.
    assert!(error("Actors(actors: [Actor(name: 3)])").starts_with("mod.ron:1:"));
    assert!(error(r#"Actors(actors: [Actor(name: "a", healt: 3)])"#).contains("healt"));
    assert!(error(r#"Actors(actors: [Actor(name: "a", flags: [Solidd])])"#).contains("Solidd"));
    let e = ActorTable::with_file(std::path::Path::new("/nonexistent/mod.ron")).unwrap_err().to_string();
    assert!(e.starts_with("/nonexistent/mod.ron: "), "{e}");
}
