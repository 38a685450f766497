//! Each kind of section applied to the shipped table, and what applying
//! refuses.

use super::*;

const HEAD: &str = "Patch File for DeHackEd v3.0\nDoom version = 19\nPatch format = 6\n\n";

fn apply(body: &str) -> (ActorTable, DehackedReport) {
    ActorTable::doom().with_dehacked(&format!("{HEAD}{body}"), "test.deh").unwrap_or_else(|e| panic!("{e}"))
}

fn refused(body: &str) -> String {
    ActorTable::doom().with_dehacked(&format!("{HEAD}{body}"), "test.deh").expect_err("should be refused").to_string()
}

fn sprite(t: &ActorTable, id: StateId) -> (&str, u8, bool) {
    let s = t.state(id);
    (t.sprites[usize::from(s.sprite)].as_str(), s.frame, s.bright)
}

fn action(t: &ActorTable, id: StateId) -> Option<&'static str> {
    t.state(id).action.as_ref().map(|c| crate::actors::actions::spec(c.action).name)
}

#[test]
fn a_thing_s_fields_reach_its_actor() {
    let (t, _) = apply(
        "Thing 12 (Imp)\nHit points = 75\nSpeed = 12\nWidth = 1572864\nHeight = 4194304\nMass = 200\n\
         Pain chance = 300\nReaction time = 4\nBits = SOLID+SHOOTABLE+COUNTKILL+FLOAT+NOGRAVITY\n\
         Alert sound = 39\nInitial frame = 174\nRespawn frame = 0\nID # = 3004\n\n\
         Thing 32 (Imp fireball)\nSpeed = 1310720\n",
    );
    let imp = t.get("imp").unwrap();
    assert_eq!((imp.health, imp.speed, imp.radius, imp.height, imp.mass), (75, 12.0, 24.0, 64.0, 200));
    assert_eq!((imp.pain_chance, imp.reaction_time), (256, 4));
    assert!(imp.has(ActorFlag::Float) && imp.has(ActorFlag::NoGravity) && imp.has(ActorFlag::CountKill));
    assert_eq!(t.sounds[imp.sounds.see.unwrap()], "bgsit1");
    let zombie = t.get("zombieman").unwrap();
    assert_eq!(imp.label("Spawn"), zombie.label("Spawn"));
    assert_eq!(imp.label("Raise"), None);
    // Two things numbered 3004: the first in mobjinfo (the zombieman)
    // spawns, as P_SpawnMapThing finds it first; 3001 is no one's now.
    assert_eq!(imp.doomednum, Some(3004));
    assert_eq!(t.by_doomednum(3004).unwrap().name, "zombieman");
    assert!(t.by_doomednum(3001).is_none());
    // A missile's speed is 16.16.
    assert_eq!(t.get("imp_fireball").unwrap().speed, 20.0);
}

#[test]
fn a_frame_s_fields_reach_every_copy_of_it() {
    let (t, _) = apply(
        "Frame 185\nSprite subnumber = 32773\nDuration = 4\nNext frame = 174\n\n\
         Frame 1\nDuration = 3\n\n\
         Frame 193\nSprite number = 30\nSprite subnumber = 12\n",
    );
    let d = Dehacked::new(ActorTable::doom().as_ref().clone());
    let map = d.map();
    let attack = map.state(185).unwrap();
    assert_eq!(sprite(&t, attack), ("POSS", 5, true));
    assert_eq!((t.state(attack).tics, t.state(attack).next), (4, map.state(174)));
    for &copy in &map.frames[1] {
        assert_eq!(t.state(copy).tics, 3);
    }
    // S_POSS_DIE5 is the zombieman's last death frame and the dead
    // zombieman's only one.
    assert_eq!(map.frames[193].len(), 2);
    for &copy in &map.frames[193] {
        assert_eq!(sprite(&t, copy), ("SPOS", 12, false));
    }
}

#[test]
fn code_pointers_copy_doom_s_actions() {
    let (t, report) = apply(
        "Pointer 0 (Frame 174)\nCodep Frame = 185\n\n\
         [CODEPTR]\nFRAME 175 = Scream\nFRAME 176 = NULL\nFRAME 177 = Mushroom\n",
    );
    let map = Dehacked::new(ActorTable::doom().as_ref().clone()).map().clone();
    assert_eq!(action(&t, map.state(174).unwrap()), Some("A_PosAttack"));
    assert_eq!(action(&t, map.state(175).unwrap()), Some("A_Scream"));
    assert_eq!(action(&t, map.state(176).unwrap()), None);
    assert_eq!(action(&t, map.state(177).unwrap()), Some("A_Chase"));
    assert_eq!(
        report.warnings[0].to_string(),
        "test.deh:11: warning: FRAME 177: no action Mushroom in Sightline (it keeps its action)"
    );
}

#[test]
fn a_pointer_copies_the_action_frame_had_before_any_patch() {
    let mut d = Dehacked::new(ActorTable::doom().as_ref().clone());
    d.load(format!("{HEAD}Pointer 0 (Frame 185)\nCodep Frame = 176\n").as_bytes(), "one.deh").unwrap();
    d.load(format!("{HEAD}Pointer 0 (Frame 174)\nCodep Frame = 185\n").as_bytes(), "two.deh").unwrap();
    let map = d.map().clone();
    assert_eq!(action(&d.table, map.state(185).unwrap()), Some("A_Chase"));
    assert_eq!(action(&d.table, map.state(174).unwrap()), Some("A_PosAttack"));
}

#[test]
fn weapons_ammo_and_misc() {
    let (t, report) = apply(
        "Weapon 1 (Pistol)\nAmmo type = 1\n\n\
         Weapon 3 (Chaingun)\nFiring frame = 79\n\n\
         Ammo 0 (Bullets)\nPer ammo = 20\n\n\
         Ammo 3 (Rockets)\nMax ammo = 100\n\n\
         Misc 0\nGreen Armor Class = 2\nSoulsphere Health = 50\nMax Soulsphere = 150\nMegasphere Health = 150\n\
         BFG Cells/Shot = 30\nInitial Health = 150\nMonsters Infight = 221\nMax Health = 250\n",
    );
    assert_eq!(t.get("pistol").unwrap().weapon.as_ref().unwrap().ammo, Some(AmmoKind::Shells));
    assert_eq!(t.get("chaingun").unwrap().label("Flash"), t.get("plasma_gun").unwrap().label("Flash"));
    let gives = |name: &str| t.get(name).unwrap().pickup.as_ref().unwrap().give.clone();
    assert_eq!(gives("clip"), [Give::Ammo(AmmoKind::Bullets, 20)]);
    assert_eq!(gives("box_of_bullets"), [Give::Ammo(AmmoKind::Bullets, 100)]);
    assert_eq!(gives("chaingun")[1], Give::Ammo(AmmoKind::Bullets, 40));
    assert_eq!(gives("shotgun_shells"), [Give::Ammo(AmmoKind::Shells, 4)]);
    assert_eq!(gives("green_armor"), [Give::Armor { points: 200, class: 2 }]);
    assert_eq!(gives("soul_sphere"), [Give::Health { amount: 50, max: 150 }]);
    assert_eq!(gives("megasphere")[0], Give::Health { amount: 150, max: 150 });
    assert_eq!(gives("health_bonus"), [Give::Health { amount: 1, max: 250 }]);
    assert_eq!(t.get("bfg9000").unwrap().weapon.as_ref().unwrap().ammo_use, 30);
    let s = &report.settings;
    assert_eq!((s.initial_health, s.species_infighting), (150, true));
    assert_eq!(s.clip_ammo[AmmoKind::Bullets.index()], 20);
    assert_eq!(s.max_ammo[AmmoKind::Rockets.index()], 100);
    assert!(report.warnings.is_empty(), "{:?}", report.warnings);
}

#[test]
fn text_strings_pars_and_cheats() {
    let (t, report) = apply(
        "Text 4 4\nTROOFOOB\n\nText 12 12\nE1M1: HangarC1M1: Prison\n\n\
         [STRINGS]\nGOTARMOR = Vest.\nOB_IMP = %o was burned.\n\n\
         [PARS]\npar 1 2 75\npar 15 300\n\n\
         Cheat 0\nGod mode = iddqx\n",
    );
    assert_eq!(t.first_frame(t.get("imp").unwrap()).as_deref(), Some("FOOBA"));
    let s = &report.strings;
    assert_eq!(s.get("HUSTR_E1M1"), Some("C1M1: Prison"));
    assert_eq!(s.get("HUSTR_E1M2"), Some("E1M2: Nuclear Plant"));
    assert_eq!(s.get("GOTARMOR"), Some("Vest."));
    assert_eq!(s.get("OB_IMP"), Some("%o was burned."));
    assert_eq!(s.text("Picked up the armor."), "Vest.");
    assert_eq!(t.get("green_armor").unwrap().pickup.as_ref().unwrap().message, "Vest.");
    assert_eq!((report.pars.episode(1, 2), report.pars.map(15), report.pars.map(1)), (Some(75), Some(300), None));
    assert_eq!(report.settings.cheats["God mode"], "iddqx");
    assert_eq!(report.warnings.len(), 1, "OB_IMP is ZDoom's: {:?}", report.warnings);
}

#[test]
fn frame_966_overflows_into_the_fist_as_in_doom_exe() {
    let (t, report) = apply("Frame 966\nDuration = 1\nNext frame = 12\n");
    let fist = t.get("fist").unwrap();
    assert_eq!(fist.weapon.as_ref().unwrap().ammo, Some(AmmoKind::Shells));
    assert_eq!(fist.label("Deselect"), t.get("pistol").unwrap().label("Select"));
    assert_eq!(report.warnings.len(), 1);
    assert_eq!(
        refused("Frame 966\nSprite number = 3\n"),
        "test.deh:6: Frame 966: cannot simulate the overflow of Sprite number"
    );
}

#[test]
fn a_state_that_lasted_for_ever_goes_on_to_doom_s_next() {
    let (t, _) = apply("Frame 763\nDuration = 10\n");
    let map = Dehacked::new(ActorTable::doom().as_ref().clone()).map().clone();
    let keen = map.state(763).unwrap();
    assert_eq!((t.state(keen).tics, t.state(keen).next), (10, Some(keen)));
}

#[test]
fn applying_refuses_what_cannot_run() {
    let cases = [
        ("Thing 12\nHit points = -5\n", "test.deh:6: Thing 12 (imp): Hit points -5 is negative"),
        (
            "Thing 12\nWidth = 268500992\n",
            "test.deh:6: Thing 12 (imp): Width 268500992 (4097 units) is not within 0 to 4096 units",
        ),
        (
            "Thing 12\nID # = 70000\n",
            "test.deh:6: Thing 12 (imp): ID # 70000 is not an editor number (0 to 65535, or -1)",
        ),
        (
            "Weapon 2\nBobbing frame = 0\n",
            "test.deh:6: Weapon 2 (shotgun): Bobbing frame = 0 leaves the weapon without its Ready state",
        ),
        (
            "Frame 12\nSprite subnumber = 40\n",
            "test.deh:6: Frame 12 (S_PISTOLUP): Sprite subnumber 40: frame 40 is past `]` (28)",
        ),
        (
            "Frame 174\nDuration = 0\n\nFrame 175\nDuration = 0\n",
            "test.deh:5: states of 0 tics lead back to themselves (frame 174, frame 175): the game would hang",
        ),
    ];
    for (body, message) in cases {
        assert_eq!(refused(body), message, "{body}");
    }
}

#[test]
fn misc_changes_only_the_pickups_of_the_settings_it_names() {
    // A modder's soul sphere, with its own amounts and states.
    let mod_ron = r#"Actors(actors: [Actor(
        name: "soul_sphere", doomednum: 2013, category: Health, flags: [Special, CountItem],
        pickup: (give: [Health(amount: 50, max: 300)], message: "Supercharge!", sound: "getpow", always: true),
        states: "Spawn:\n SOUL AB 6 bright\n loop",
    )])"#;
    let table = ActorTable::parse(&[(crate::actors::DOOM_TABLE, "actors.ron"), (mod_ron, "mod.ron")]).unwrap();
    let soul = |t: &ActorTable| t.get("soul_sphere").unwrap().pickup.as_ref().unwrap().give.clone();
    let (t, _) = table.with_dehacked(&format!("{HEAD}Misc 0\nInitial Health = 150\n"), "a.deh").unwrap();
    assert_eq!(soul(&t), [Give::Health { amount: 50, max: 300 }]);
    let (t, _) = table.with_dehacked(&format!("{HEAD}Misc 0\nSoulsphere Health = 80\n"), "b.deh").unwrap();
    assert_eq!(soul(&t), [Give::Health { amount: 80, max: 200 }]);
    // Its states are not Doom's (A B, where Doom's run A B C D C B): the
    // pairing says so, and leaves Doom's soulsphere frames without a state
    // until a patch names them, rather than pair the two that look alike.
    let d = Dehacked::new(table);
    assert_eq!(d.map().problems, ["soul_sphere: state 773 is both S_SOUL and S_SOUL3"]);
    let info = doom_info();
    let soul: Vec<usize> = (1..info.states.len()).filter(|&f| info.states[f].name.starts_with("S_SOUL")).collect();
    assert_eq!(soul.len(), 6);
    assert!(soul.iter().all(|&f| d.map().frames[f].is_empty()));
}
