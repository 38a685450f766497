//! Freedoom's own patches: both IWADs (Debian's `freedoom` package) carry a
//! DEHACKED lump. Where the WADs are missing this test is ignored with the
//! reason (`engine/build.rs`), and CI, which requires them, fails instead.

use super::*;

fn wad(name: &str) -> Option<crate::wad::Wad> {
    Some(crate::sim::test_wad(name))
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's IWADs: apt-get install freedoom")]
fn freedoom_s_dehacked_lumps_apply() {
    for name in ["freedoom1.wad", "freedoom2.wad"] {
        let Some(wad) = wad(name) else { continue };
        let lumps = lumps(&wad);
        assert_eq!(lumps.len(), 1, "{name}");
        let patch = parse(wad.bytes(lumps[0]), name).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            patch.header,
            Header { version: Some("v3.0".into()), doom_version: Some(19), patch_format: Some(6) }
        );
        assert!(patch.warnings.is_empty(), "{name}: {:?}", patch.warnings);

        let base = ActorTable::doom();
        let (table, report) = base.with_wad_dehacked(&wad).unwrap_or_else(|e| panic!("{e}"));
        let map = Dehacked::new(base.as_ref().clone()).map().clone();
        let info = doom_info();

        // Frames: the zombie's, the minigun zombie's and the assault
        // tripod's firing frames are drawn at full brightness.
        let bright = ["S_POSS_ATK2", "S_CPOS_ATK4", "S_CYBER_ATK2", "S_CYBER_ATK4", "S_CYBER_ATK6"];
        for (frame, state_name) in [185, 419, 685, 687, 689].into_iter().zip(bright) {
            assert_eq!(info.states[frame].name, state_name);
            let id = map.state(frame).unwrap();
            let (before, after) = (base.state(id), table.state(id));
            assert!(!before.bright && after.bright, "{name}: {state_name}");
            assert_eq!(State { bright: false, ..after.clone() }, *before, "{name}: only the brightness changes");
        }
        // Nothing else of the table.
        let changed = (0..base.states.len()).filter(|&k| base.states[k] != table.states[k]).count();
        assert_eq!((changed, table.states.len()), (5, base.states.len()));
        // Pickup messages are doom.exe's strings, which Freedoom rewrites
        // (all but the box of shells', which it writes as Doom had it).
        let mut messages = 0;
        for (a, b) in base.actors.iter().zip(&table.actors) {
            let unchanged_but_message = ActorDef { pickup: b.pickup.clone(), ..a.clone() };
            assert_eq!(&unchanged_but_message, b, "{name}: {}", a.name);
            if let (Some(pa), Some(pb)) = (&a.pickup, &b.pickup) {
                assert_eq!(pb.message, report.strings.text(&pa.message));
                messages += usize::from(pa.message != pb.message);
            }
        }
        let pickups = table.actors.iter().filter(|a| a.pickup.is_some()).count();
        assert_eq!((messages, pickups), (35, 36), "{name}");

        // Strings: every level name, message and finale text of both
        // games, and ZDoom's and Boom's names kept besides.
        let s = &report.strings;
        assert_eq!(s.get("HUSTR_E1M1"), Some("C1M1: Outer Prison"));
        assert_eq!(s.get("HUSTR_1"), Some("MAP01: Hydroelectric Plant"));
        assert_eq!(s.get("GOTARMOR"), Some("Picked up a light armor vest."));
        assert_eq!(table.get("green_armor").unwrap().pickup.as_ref().unwrap().message, "Picked up a light armor vest.");
        assert_eq!(table.get("chaingun").unwrap().pickup.as_ref().unwrap().message, "You got the minigun!");
        assert!(s.get("E1TEXT").unwrap().starts_with("You've made it out of the outpost.\n"));
        assert_eq!(s.get("OB_IMP"), Some("%o was burned by a serpentipede."));
        assert_eq!(s.replaced().count(), 233);
        // Par times: E1-E3 (27, E3M5's 0) and MAP01-MAP32.
        let p = &report.pars;
        assert_eq!(
            (p.episode(1, 1), p.episode(1, 7), p.episode(3, 5), p.episode(4, 1)),
            (Some(30), Some(690), Some(0), None)
        );
        assert_eq!((p.map(1), p.map(24), p.map(32), p.len()), (Some(30), Some(420), Some(210), 59));
        // Phase 1's IDCLIP; Phase 2 keeps Doom II's cheats.
        let cheats: Vec<(&str, &str)> = report.settings.cheats.iter().map(|(a, b)| (a.as_str(), b.as_str())).collect();
        match name {
            "freedoom1.wad" => assert_eq!(cheats, [("No Clipping 1", "idclip"), ("No Clipping 2", "idspispopd")]),
            _ => assert_eq!(cheats, []),
        }
        let a = report.applied;
        assert_eq!(
            (a.frames, a.strings, a.pars, a.cheats, a.things),
            (5, 1, 1, usize::from(name == "freedoom1.wad"), 0)
        );
        // One warning: the 66 names doom.exe has no string for.
        let warnings: Vec<String> = report.warnings.iter().map(ToString::to_string).collect();
        assert_eq!(warnings.len(), 1, "{warnings:?}");
        assert!(warnings[0].contains("[STRINGS]: 66 names doom.exe has no string for"), "{}", warnings[0]);
        eprintln!("{name}: {}", warnings[0]);
    }
}
