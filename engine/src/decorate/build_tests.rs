//! The DECORATE builder on ViZDoom's six lumps and on hand-written ones:
//! what each actor becomes, what is listed as unread, what is refused; and
//! a chainsaw marine built from deathmatch.wad's lump hurting a player.

use super::{apply, parse, parse_lump, Built, Decorate, DecorateBuildError};
use crate::actors::{zdoom, ActorFlag, ActorTable, AmmoKind, Category, Give};

/// The scenario WADs with a DECORATE lump.
const WITH_DECORATE: [&str; 6] = [
    "cig.wad",
    "cig_with_unknown.wad",
    "deathmatch.wad",
    "defend_the_center.wad",
    "health_gathering_supreme.wad",
    "rocket_basic.wad",
];

/// A scenario WAD's DECORATE lump, named as `apply` wants it.
fn lump_of(dir: &std::path::Path, name: &str) -> (String, Decorate) {
    let wad = crate::wad::Wad::open(&dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    let index = wad.find("DECORATE").unwrap_or_else(|| panic!("{name} has no DECORATE"));
    let tree = parse_lump(wad.bytes(index)).unwrap_or_else(|e| panic!("{name}: {e}"));
    (format!("{name}:DECORATE"), tree)
}

fn build(dir: &std::path::Path, name: &str) -> Built {
    apply(&[lump_of(dir, name)], ActorTable::doom()).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn built_text(text: &str) -> Result<Built, DecorateBuildError> {
    let tree = parse(text).expect("the test's DECORATE parses");
    apply(&[("test.wad:DECORATE".to_string(), tree)], ActorTable::doom())
}

#[test]
fn every_shipped_lump_builds() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    for name in WITH_DECORATE {
        let built = build(&dir, name);
        for line in &built.unread {
            assert!(line.starts_with(&format!("{name}:DECORATE:")), "{line}");
        }
    }
}

#[test]
fn cig_marines_fire_their_weapons() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    let built = build(&dir, "cig.wad");
    let t = &built.table;
    for (class, number, attack) in [
        ("CustomMarineRocket", 9112, "A_M_FireMissile"),
        ("CystomMarinePistol", 9113, "A_M_FirePistol"),
        ("CustomMarineChaingun", 9114, "A_M_FireCGun"),
        ("CustomMarinePlasma", 9115, "A_M_FirePlasma"),
    ] {
        let i = zdoom::find(t, class).unwrap_or_else(|| panic!("{class} is in the table"));
        let a = &t.actors[i];
        assert_eq!(a.doomednum, Some(number), "{class}");
        assert_eq!(t.by_doomednum(number).map(|d| d.name.as_str()), Some(a.name.as_str()));
        assert!(a.has(ActorFlag::CountKill) && a.has(ActorFlag::Solid) && a.has(ActorFlag::Shootable), "{class}");
        assert_eq!(
            (a.health, a.radius, a.height, a.pain_chance, a.category),
            (100, 16.0, 56.0, 160, Category::Monster)
        );
        // Missile leads, within a few states, to the weapon's attack.
        let mut at = a.label("Missile");
        let mut actions = Vec::new();
        for _ in 0..4 {
            let Some(id) = at else { break };
            let state = t.state(id);
            actions.extend(state.action.as_ref().map(|c| crate::actors::actions::spec(c.action).name));
            assert_eq!(t.sprites[usize::from(state.sprite)], "PLAY");
            at = state.next;
        }
        assert!(actions.contains(&attack), "{class}: {actions:?}");
        // Melee is the marine's (none), the See state chases.
        assert_eq!(a.label("Melee"), None, "{class}");
        let see = t.state(a.label("See").unwrap());
        assert_eq!(crate::actors::actions::spec(see.action.as_ref().unwrap().action).name, "A_MarineChase");
    }
    // +AVOIDMELEE has no equivalent: listed once per actor, with its line.
    let avoid: Vec<&String> = built.unread.iter().filter(|l| l.contains("AVOIDMELEE")).collect();
    assert_eq!(avoid.len(), 4, "{:?}", built.unread);
    assert!(avoid[0].starts_with("cig.wad:DECORATE:4: actor CustomMarineRocket: flag +AVOIDMELEE"), "{}", avoid[0]);
}

#[test]
fn the_chainsaw_marine_saws_and_never_shoots() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    for name in ["deathmatch.wad", "defend_the_center.wad"] {
        let built = build(&dir, name);
        assert!(built.unread.is_empty(), "{name}: {:?}", built.unread);
        let t = &built.table;
        let a = &t.actors[zdoom::find(t, "MarineChainsawVzd").unwrap()];
        assert!(a.has(ActorFlag::CountKill));
        assert_eq!(a.doomednum, None);
        assert_eq!(a.label("Missile"), None);
        let saw = t.state(t.state(a.label("Melee").unwrap()).next.unwrap());
        assert_eq!(crate::actors::actions::spec(saw.action.as_ref().unwrap().action).name, "A_M_Saw");
    }
}

#[test]
fn health_pickups_give_what_zdoom_gives() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    let built = build(&dir, "health_gathering_supreme.wad");
    let t = &built.table;
    let medikit = &t.actors[zdoom::find(t, "CustomMedikit").unwrap()];
    assert_eq!(medikit.category, Category::Health);
    assert!(medikit.has(ActorFlag::Special));
    let pickup = medikit.pickup.as_ref().unwrap();
    assert_eq!(pickup.give, [Give::Health { amount: 20, max: 100 }]);
    assert_eq!((pickup.message.as_str(), pickup.always), ("Picked up a medikit.", true));
    assert_eq!(t.sprites[usize::from(t.state(medikit.label("Spawn").unwrap()).sprite)], "MEDI");
    // Amount -25: up to 25% of 100 when below it, else nothing (P_GiveBody).
    let poison = &t.actors[zdoom::find(t, "Poison").unwrap()];
    let pickup = poison.pickup.as_ref().unwrap();
    assert_eq!(pickup.give, [Give::Health { amount: 25, max: 25 }]);
    assert_eq!((pickup.message.as_str(), pickup.always), ("Picked up a poison!", true));
    assert!(poison.has(ActorFlag::CountItem));
    let spawn: Vec<u8> = {
        let mut at = poison.label("Spawn");
        let mut frames = Vec::new();
        while let Some(id) = at.filter(|_| frames.len() < 6) {
            frames.push(t.state(id).frame);
            at = t.state(id).next;
        }
        frames
    };
    assert_eq!(spawn, [0, 1, 2, 3, 2, 1]);
    // The low-health message has no place in our pickup: listed.
    assert!(built.unread.iter().any(|l| l.contains("Health.LowMessage")), "{:?}", built.unread);
}

#[test]
fn the_custom_rocket_launcher_fires_the_custom_rocket() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    let built = build(&dir, "rocket_basic.wad");
    let t = &built.table;
    let rocket_index = zdoom::find(t, "CustomRocket").unwrap();
    let rocket = &t.actors[rocket_index];
    assert_eq!(rocket.category, Category::Projectile);
    assert!(rocket.has(ActorFlag::Missile) && rocket.has(ActorFlag::NoGravity) && rocket.has(ActorFlag::NoBlockmap));
    assert_eq!((rocket.radius, rocket.height, rocket.speed, rocket.damage), (0.0, 8.0, 20.0, 20));
    assert_eq!(rocket.sounds.see.map(|s| t.sounds[s].as_str()), Some("rlaunc"));
    assert_eq!(rocket.sounds.death.map(|s| t.sounds[s].as_str()), Some("barexp"));
    let death = t.state(rocket.label("Death").unwrap());
    assert_eq!(crate::actors::actions::spec(death.action.as_ref().unwrap().action).name, "A_Explode");

    let launcher = &t.actors[zdoom::find(t, "CustomRocketLauncher").unwrap()];
    let weapon = launcher.weapon.as_ref().unwrap();
    assert_eq!((weapon.slot, weapon.ammo, weapon.ammo_use), (5, Some(AmmoKind::Rockets), 1));
    let pickup = launcher.pickup.as_ref().unwrap();
    assert_eq!(pickup.give, [Give::Weapon("customrocketlauncher".into()), Give::Ammo(AmmoKind::Rockets, 2)]);
    assert_eq!(pickup.message, "You got the rocket launcher!");
    let fire = t.state(launcher.label("Fire").unwrap());
    let shot = t.state(fire.next.unwrap());
    let call = shot.action.as_ref().unwrap();
    assert_eq!(crate::actors::actions::spec(call.action).name, "A_FireCustomMissile");
    assert_eq!(call.args, [crate::actors::Arg::Actor(rocket_index)]);
    // Flash's `Goto LightDone` reaches DoomWeapon's A_Light0 and ends.
    let mut at = launcher.label("Flash");
    let mut last = None;
    while let Some(id) = at {
        last = t.state(id).action.as_ref().map(|c| crate::actors::actions::spec(c.action).name);
        at = t.state(id).next;
    }
    assert_eq!(last, Some("A_Light0"));
    for flag in ["RANDOMIZE", "DEHEXPLOSION", "ROCKETTRAIL", "WEAPON.NOAUTOFIRE"] {
        assert!(built.unread.iter().any(|l| l.contains(flag)), "{flag}: {:?}", built.unread);
    }
    for property in ["Obituary", "Tag", "Weapon.SelectionOrder"] {
        assert!(built.unread.iter().any(|l| l.contains(property)), "{property}: {:?}", built.unread);
    }
}

#[test]
fn an_unknown_parent_names_lump_line_and_actor() {
    let text = "// a comment\n\nactor Thing : NoSuchClass 9500\n{\n  Health 5\n}\n";
    let error = built_text(text).unwrap_err();
    assert_eq!(
        error,
        DecorateBuildError::Actor {
            lump: "test.wad:DECORATE".into(),
            line: 3,
            actor: "Thing".into(),
            message: "unknown parent class NoSuchClass".into(),
        }
    );
    assert_eq!(error.to_string(), "test.wad:DECORATE:3: actor Thing: unknown parent class NoSuchClass");
}

#[test]
fn a_state_the_loader_refuses_names_the_decorate_line() {
    let text = "actor Thing\n{\n  States\n  {\n  Spawn:\n    TROO A 4\n    goto Nowhere\n  }\n}\n";
    let Err(DecorateBuildError::Actor { line, actor, message, .. }) = built_text(text) else { panic!("refused") };
    assert_eq!((line, actor.as_str()), (7, "Thing"));
    assert!(message.contains("no label Nowhere"), "{message}");
}

#[test]
fn unknown_properties_flags_and_actions_are_listed_not_fatal() {
    let text = r#"
actor Gadget : ZombieMan replaces ShotgunGuy 9501
{
  Health 33
  Scale 0.5
  +NOSUCHFLAG
  -SOLID
  SeeSound "weapons/sawup"
  States
  {
  Missile:
    POSS E 10 A_FaceTarget
    POSS F 8 A_NoSuchAction(3)
    POSS F 8 bright A_PosAttack
    goto Super::See
  }
}
"#;
    let built = built_text(text).unwrap();
    let t = &built.table;
    let i = zdoom::find(t, "gadget").unwrap();
    let a = &t.actors[i];
    assert_eq!((a.health, a.doomednum, a.category), (33, Some(9501), Category::Monster));
    assert!(!a.has(ActorFlag::Solid) && a.has(ActorFlag::CountKill));
    assert_eq!(a.sounds.see.map(|s| t.sounds[s].as_str()), Some("sawup"));
    // The zombieman's other sounds are inherited.
    assert_eq!(a.sounds.death.map(|s| t.sounds[s].as_str()), Some("podth1"));
    // ShotgunGuy spawns as the gadget.
    let shotgun_guy = zdoom::find(t, "ShotgunGuy").unwrap();
    assert_eq!(t.spawned(shotgun_guy), i);
    // The state without its action is kept, so the counts hold.
    let missile = a.label("Missile").unwrap();
    let second = t.state(t.state(missile).next.unwrap());
    assert_eq!((second.frame, second.tics, second.action.is_none()), (5, 8, true));
    let see = t.state(t.state(second.next.unwrap()).next.unwrap());
    assert_eq!(t.state(a.label("See").unwrap()), see);
    let unread = built.unread.join("\n");
    for (line, what) in [(5, "property Scale"), (6, "flag +NOSUCHFLAG"), (13, "action A_NoSuchAction")] {
        let prefix = format!("test.wad:DECORATE:{line}: actor Gadget: {what}");
        assert!(built.unread.iter().any(|l| l.starts_with(&prefix)), "{prefix} in\n{unread}");
    }
    assert_eq!(built.unread.len(), 3, "{unread}");
}

#[test]
fn zdoom_names_find_the_table_actors() {
    let t = ActorTable::doom();
    for (class, ours) in [
        ("ZombieMan", "zombieman"),
        ("zombieman", "zombieman"),
        ("DoomImp", "imp"),
        ("RocketAmmo", "rocket"),
        ("Rocket", "rocket_projectile"),
        ("BFG9000", "bfg9000"),
        ("MapSpot", "map_spot"),
        ("PatrolPoint", "patrol_point"),
        ("TeleportDest", "teleport_destination"),
        ("Stalagtite", "stalagmite"),
    ] {
        assert_eq!(zdoom::find(t, class).map(|i| t.actors[i].name.as_str()), Some(ours), "{class}");
    }
    assert_eq!(zdoom::find(t, "NoSuchClass"), None);
    // ZDoom's bases come with the builder, not the shipped table.
    assert_eq!(zdoom::find(t, "ScriptedMarine"), None);
    let with = zdoom::with_bases(t).unwrap();
    let marine = zdoom::find(&with, "ScriptedMarine").unwrap();
    assert_eq!(zdoom::class_name(&with, marine), Some("ScriptedMarine"));
    assert_eq!(with.by_doomednum(9103).map(|a| a.name.as_str()), Some("marine_chainsaw"));
    // The shipped table's indices are kept under the bases.
    assert_eq!(with.actors[..t.actors.len()], t.actors[..]);
    assert_eq!(zdoom::unread_thing(9027), Some("RedParticleFountain"));
}

/// Freedoom 2's MAP01 (the player at (-192, -160) facing east, open floor
/// ahead) on deathmatch.wad's table: a chainsaw marine 50 units ahead,
/// awake and after the player, saws it within a few seconds.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_chainsaw_marine_hurts_the_player() {
    use crate::fixed::Fixed;
    use crate::sim::mobj::ONFLOORZ;
    use crate::sim::setup::Players;
    use crate::sim::{GameMode, GameVersion, Rules, Sim, MAXPLAYERS};
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    let table = std::sync::Arc::new(build(&dir, "deathmatch.wad").table);
    let wad = crate::sim::test_wad("freedoom2.wad");
    let rules = Rules { no_monsters: true, ..Rules::single(2, GameVersion::Final, GameMode::Commercial) };
    let mut in_game = [false; MAXPLAYERS];
    in_game[0] = true;
    let players = Players { in_game, console: 0 };
    let kind = zdoom::find(&table, "MarineChainsawVzd").unwrap();
    let mut sim = Sim::new(&wad, "MAP01", rules, players, table).expect("MAP01 loads");
    let player = sim.player(0).unwrap().mo;
    let (x, y) = (sim.mo(player).x, sim.mo(player).y);
    let marine = sim.spawn_mobj(x + Fixed::from_int(50), y, ONFLOORZ, kind);
    sim.mo_mut(marine).target = Some(player);
    let see = sim.info.things[kind].seestate;
    sim.set_mobj_state(marine, see);
    let mut hurt_at = None;
    for tic in 0..210 {
        sim.tick(&[None; MAXPLAYERS]);
        if sim.player(0).unwrap().health < 100 {
            hurt_at = Some(tic);
            break;
        }
    }
    assert!(hurt_at.is_some(), "the marine never hurt the player");
    assert!(sim.mo(marine).health > 0);
}
