//! The BEHAVIOR lumps of ViZDoom's 18 scenario WADs: each loads, uses only
//! what the VM and the recording host provide, and runs its OPEN and ENTER
//! scripts for a minute of game time without a warning.

use std::collections::BTreeSet;

use super::record::{HostCall, RecordingHost};
use super::*;
use crate::wad::Wad;

const WADS: [&str; 18] = [
    "basic.wad",
    "basic_audio.wad",
    "basic_notifications.wad",
    "cig.wad",
    "cig_with_unknown.wad",
    "deadly_corridor.wad",
    "deathmatch.wad",
    "defend_the_center.wad",
    "defend_the_line.wad",
    "health_gathering.wad",
    "health_gathering_supreme.wad",
    "multi_deathmatch.wad",
    "multi_duel.wad",
    "my_way_home.wad",
    "predict_position.wad",
    "rocket_basic.wad",
    "simpler_basic.wad",
    "take_cover.wad",
];

/// Every map's module in the WAD, with its label.
fn modules(dir: &std::path::Path, file: &str) -> Vec<(String, Module, i32)> {
    let wad = Wad::open(&dir.join(file)).unwrap_or_else(|e| panic!("{e}"));
    wad.map_names()
        .into_iter()
        .filter_map(|map| {
            let index = behavior_for_map(&wad, &map)?;
            let label = format!("BEHAVIOR of {map} in {file}");
            let module = Module::load(wad.bytes(index), &label).unwrap_or_else(|e| panic!("{e}"));
            Some((label, module, default_level_number(&map)))
        })
        .collect()
}

#[test]
fn the_last_behavior_of_a_udmf_map_is_the_one_zdoom_runs() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    for file in ["defend_the_center.wad", "health_gathering.wad"] {
        let wad = Wad::open(&dir.join(file)).unwrap_or_else(|e| panic!("{e}"));
        let all: Vec<usize> = (0..wad.lumps.len()).filter(|&i| wad.lumps[i].name == "BEHAVIOR").collect();
        assert_eq!(all.len(), 2, "{file}");
        assert_eq!(behavior_for_map(&wad, "MAP01"), Some(all[1]), "{file}");
    }
    // health_gathering's second module has the SpawnMedikit function its
    // SCRIPTS source declares; the first, stale one has none.
    let m = modules(&dir, "health_gathering.wad");
    assert_eq!(m[0].1.functions.len(), 1);
    // (acc writes names in lower case.)
    assert_eq!(m[0].1.functions[0].name.as_deref(), Some("spawnmedikit"));
}

#[test]
fn every_scenario_module_loads_and_runs_2100_tics() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    let mut pcodes_used = BTreeSet::new();
    let mut functions_used = BTreeSet::new();
    let mut specials_used = BTreeSet::new();
    for file in WADS {
        let mods = modules(&dir, file);
        assert!(!mods.is_empty(), "{file} has no BEHAVIOR");
        for (label, module, level) in mods {
            pcodes_used.extend(module.code.used.iter().copied());
            functions_used.extend(module.code.functions.keys().copied());
            let mut host = RecordingHost::default();
            host.inventory.insert("Clip".into(), 50);
            let mut vm = Vm::new(module, &host).unwrap_or_else(|e| panic!("{e}"));
            vm.level_number = level;
            vm.start_typed(ScriptKind::Open, Activator::World, false, 0);
            vm.start_typed(ScriptKind::Enter, Activator::Thing(1), true, 0);
            for _ in 0..2100 {
                vm.tick(&mut host);
            }
            assert!(vm.warnings.is_empty(), "{label}: {:?}", vm.warnings);
            specials_used.extend(host.calls.iter().filter_map(|c| match c {
                HostCall::Special { special, .. } => Some(*special),
                _ => None,
            }));
        }
    }
    let names: Vec<&str> = pcodes_used.iter().map(|&p| pcodes::name(p)).collect();
    eprintln!("pcodes used: {}", names.join(" "));
    eprintln!("extended functions used: {functions_used:?}; specials reaching the host: {specials_used:?}");
}

/// basic.wad's script 3 takes 5.0 from the reward (global 0) each tic the
/// Clip count drops (its SCRIPTS source: `reward = reward - 5.0`).
#[test]
fn basic_wad_script_3_charges_five_per_shot() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    let (_, module, level) = modules(&dir, "basic.wad").remove(0);
    let mut host = RecordingHost::default();
    host.inventory.insert("Clip".into(), 50);
    let mut vm = Vm::new(module, &host).unwrap_or_else(|e| panic!("{e}"));
    // basic.wad runs script 3 with ACS_Execute(3, 1, ...): map 1 is MAP01.
    assert_eq!(level, 1);
    vm.level_number = level;
    vm.start_typed(ScriptKind::Open, Activator::World, false, 0);
    vm.start_typed(ScriptKind::Enter, Activator::Thing(1), true, 0);
    vm.tick(&mut host); // OPEN spawns the target, ENTER takes the fist and starts script 3
    assert!(vm.is_running(3));
    assert_eq!(host.game_calls(149).len(), 1, "one Cacodemon spawned");
    assert_eq!(host.specials(177), vec![[10, 100, 6, 0, 0]], "Thing_Hate(target_id, 100, 6)");
    for _ in 0..3 {
        vm.tick(&mut host);
    }
    assert_eq!(vm.globals.global[0], 0);
    for shot in 1..=4 {
        *host.inventory.get_mut("Clip").expect("clip") -= 1;
        vm.tick(&mut host);
        assert_eq!(vm.globals.global[0], -shot * (5 << 16));
        vm.tick(&mut host);
        assert_eq!(vm.globals.global[0], -shot * (5 << 16), "no charge without a shot");
    }
    // Script 4 (the target's death special) adds 106.0 and ends the level.
    vm.execute(4, &[], Activator::Thing(7), true);
    vm.tick(&mut host);
    assert_eq!(vm.globals.global[0], (106 - 20) << 16);
    assert_eq!(host.specials(243), vec![[0; 5]]);
}
