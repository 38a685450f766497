//! The pairing of Doom's numbers with the shipped table, and a patch that
//! writes Doom's own values everywhere, which must change nothing: it
//! checks every conversion (fixed point, missile speeds, flag bits, sound
//! and frame numbers) against the data the table was written from.

use std::fmt::Write;

use super::*;
use crate::actors::dehacked::doom::{NUM_STATES, NUM_THINGS, NUM_WEAPONS};

/// Doom's frames no actor reaches, which the table therefore lacks:
/// the super shotgun's two "not ready" states (d_items.c never names
/// them), a grey stalagmite no thing uses (MT_MISC47 is S_STALAGTITE), and
/// the dead torso and bottom half no thing uses.
const UNUSED: [&str; 5] = ["S_DSNR1", "S_DSNR2", "S_STALAG", "S_DEADTORSO", "S_DEADBOTTOM"];

#[test]
fn every_thing_weapon_and_used_frame_of_doom_pairs_with_the_shipped_table() {
    let d = Dehacked::new(ActorTable::doom().as_ref().clone());
    let (map, info) = (d.map(), doom_info());
    assert_eq!(map.problems, Vec::<String>::new());
    assert_eq!(info.states.len(), NUM_STATES);
    assert_eq!(map.things.iter().flatten().count(), NUM_THINGS);
    assert_eq!(map.weapons.iter().flatten().count(), NUM_WEAPONS);
    // Each thing is its own actor.
    let mut actors: Vec<usize> = map.things.iter().flatten().copied().collect();
    actors.dedup();
    assert_eq!(actors.len(), NUM_THINGS);
    let unmapped: Vec<&str> = map.unmapped().iter().map(|&f| info.states[f].name.as_str()).collect();
    assert_eq!(unmapped, UNUSED);
    // 961 of 967: all but S_NULL (no state) and the five unused.
    assert_eq!((1..NUM_STATES).filter(|&f| !map.frames[f].is_empty()).count(), 961);
    // Shared frames are copies: S_LIGHTDONE in each of seven weapons.
    assert_eq!(map.frames[1].len(), 7);
    assert_eq!(map.parked, vec![info.state("S_KEENSTND").unwrap()]);
    // No table state is two Doom frames.
    let mut all: Vec<StateId> = map.frames.iter().flatten().copied().collect();
    let n = all.len();
    all.sort();
    all.dedup();
    assert_eq!(all.len(), n);
}

#[test]
fn a_patch_naming_an_unused_frame_adds_it_as_doom_has_it() {
    let table = ActorTable::doom();
    let mut text = String::from("Patch File for DeHackEd v3.0\n");
    // The imp's spawn state goes to S_DSNR1, which leads to S_DSNR2 and on
    // to the super shotgun's lowering state.
    writeln!(text, "Thing 12 (Imp)\nInitial frame = 45\n").unwrap();
    for f in [887, 892, 893] {
        writeln!(text, "Frame {f}\nDuration = 7\n").unwrap();
    }
    let mut d = Dehacked::new(table.as_ref().clone());
    d.load(text.as_bytes(), "unused.deh").unwrap();
    let (map, info) = (d.map(), doom_info());
    assert_eq!(map.unmapped(), Vec::<usize>::new());
    assert_eq!(map.added, vec![45, 46, 887, 892, 893]);
    let imp = d.table.get("imp").unwrap();
    let s1 = d.table.state(imp.label("Spawn").unwrap());
    assert_eq!((d.table.sprites[usize::from(s1.sprite)].as_str(), s1.frame, s1.tics), ("SHT2", 1, 7));
    let s2 = d.table.state(s1.next.unwrap());
    assert_eq!((s2.frame, s2.tics), (0, 3));
    let ssg = d.table.get("super_shotgun").unwrap();
    assert_eq!(s2.next, ssg.label("Deselect"));
    let lamp = d.table.state(map.state(887).unwrap());
    assert_eq!((d.table.sprites[usize::from(lamp.sprite)].as_str(), lamp.tics), ("SMT2", 7));
    assert_eq!(info.states[887].tics, -1);
    assert_eq!(d.table.states.len(), table.states.len() + 5);
}

/// A patch that sets every field of every thing, mapped frame, code
/// pointer and weapon to doom.exe's own value.
fn doom_values_patch() -> String {
    let info = doom_info();
    let mut p = String::from("Patch File for DeHackEd v3.0\nDoom version = 19\nPatch format = 6\n\n");
    for (k, t) in info.things.iter().enumerate() {
        let [spawn, see, pain, melee, missile, death, xdeath, raise] = t.states;
        let [s_see, s_attack, s_pain, s_death, s_active] = t.sounds;
        #[rustfmt::skip]
        let fields: [(&str, i64); 23] = [
            ("ID #", t.doomednum.into()), ("Initial frame", spawn as i64), ("Hit points", t.health.into()),
            ("First moving frame", see as i64), ("Alert sound", s_see as i64),
            ("Reaction time", t.reaction_time.into()), ("Attack sound", s_attack as i64),
            ("Injury frame", pain as i64), ("Pain chance", t.pain_chance.into()), ("Pain sound", s_pain as i64),
            ("Close attack frame", melee as i64), ("Far attack frame", missile as i64),
            ("Death frame", death as i64), ("Exploding frame", xdeath as i64), ("Death sound", s_death as i64),
            ("Speed", t.speed.into()), ("Width", t.radius.into()), ("Height", t.height.into()),
            ("Mass", t.mass.into()), ("Missile damage", t.damage.into()), ("Action sound", s_active as i64),
            ("Bits", t.flags.into()), ("Respawn frame", raise as i64),
        ];
        writeln!(p, "Thing {} ({})", k + 1, t.mt).unwrap();
        fields.iter().for_each(|(key, v)| writeln!(p, "{key} = {v}").unwrap());
        p.push('\n');
    }
    let table = ActorTable::doom();
    let map = Dehacked::new(table.as_ref().clone()).map().clone();
    for (f, s) in info.states.iter().enumerate().skip(1).take(NUM_STATES - 2) {
        if map.frames[f].is_empty() {
            continue;
        }
        let (sprite, frame, tics, next) = (s.sprite, s.frame, s.tics, s.next);
        writeln!(p, "Frame {f}\nSprite number = {sprite}\nSprite subnumber = {frame}").unwrap();
        writeln!(p, "Duration = {tics}\nNext frame = {next}\n").unwrap();
        writeln!(p, "Pointer 0 (Frame {f})\nCodep Frame = {f}\n").unwrap();
    }
    for (k, w) in info.weapons.iter().enumerate() {
        let [up, down, ready, attack, flash] = w.states;
        writeln!(p, "Weapon {k} ({})\nAmmo type = {}\nDeselect frame = {up}\nSelect frame = {down}", w.name, w.ammo)
            .unwrap();
        writeln!(p, "Bobbing frame = {ready}\nShooting frame = {attack}\nFiring frame = {flash}\n").unwrap();
    }
    writeln!(p, "Misc 0\nMax Health = 200\nMax Armor = 200\nGreen Armor Class = 1\nBlue Armor Class = 2").unwrap();
    writeln!(p, "Max Soulsphere = 200\nSoulsphere Health = 100\nMegasphere Health = 200\nBFG Cells/Shot = 40\n")
        .unwrap();
    for (k, clip) in doom::CLIP_AMMO.iter().enumerate() {
        writeln!(p, "Ammo {k}\nPer ammo = {clip}\nMax ammo = {}\n", doom::MAX_AMMO[k]).unwrap();
    }
    p
}

#[test]
fn doom_s_own_values_change_nothing() {
    let table = ActorTable::doom();
    let text = doom_values_patch();
    let (patched, report) = table.with_dehacked(&text, "doom.deh").unwrap_or_else(|e| panic!("{e}"));
    for (a, b) in table.actors.iter().zip(&patched.actors) {
        assert_eq!(a, b);
    }
    assert_eq!(table.states.len(), patched.states.len());
    // S_KEENSTND lasts for ever and names itself next, where the table
    // stops: the one state the patch (writing Doom's next) changes, to a
    // next never reached.
    let keen = Dehacked::new(table.as_ref().clone()).map().state(doom_info().state("S_KEENSTND").unwrap());
    for (k, (a, b)) in table.states.iter().zip(&patched.states).enumerate() {
        if Some(StateId(k as u32)) == keen {
            assert_eq!((a.next, b.next, a.tics), (None, keen, -1));
            assert_eq!(&State { next: None, ..b.clone() }, a);
            continue;
        }
        assert_eq!(a, b, "state {k}");
    }
    assert_eq!(table.sprites, patched.sprites);
    for n in [3004, 2014, 83, 47] {
        assert_eq!(table.by_doomednum(n).map(|a| &a.name), patched.by_doomednum(n).map(|a| &a.name));
    }
    // What it says that Sightline does not take: the player's melee frame
    // (the table's player `Melee` is its firing frame).
    let warnings: Vec<String> = report.warnings.iter().map(|w| w.message.clone()).collect();
    assert_eq!(warnings, ["Thing 1 (player): Close attack frame is not applied to the player"]);
    assert_eq!((report.applied.things, report.applied.weapons, report.applied.ammo), (137, 9, 4));
    assert_eq!(report.settings, Settings::default());
}
