//! Freedoom's eight vanilla demos on the simulation with Doom's arithmetic,
//! each tic compared with Chocolate Doom's dump of the same demo
//! (`tests/fixtures/demo-dumps/`, made by `scripts/chocolate-demo-dumps.sh`).
//! Each demo must stay in sync at least as long as [`FLOORS`] says: the
//! floors rise as the simulation learns more of Doom's rules, and reach
//! every tic when the demo plays in sync. A run prints how far each got and
//! the first fields that differ.

#[path = "freedoom_wads.rs"]
#[allow(dead_code)]
mod freedoom_wads;

use std::path::Path;

use sightline::actors::ActorTable;
use sightline::play::lmp::VanillaDemo;
use sightline::play::syncdump::SyncDump;
use sightline::sim::demo;
use sightline::wad::Wad;

/// (IWAD, lump, tics in sync at least).
const FLOORS: [(&str, &str, usize); 8] = [
    ("freedoom1", "DEMO1", 0),
    ("freedoom1", "DEMO2", 0),
    ("freedoom1", "DEMO3", 0),
    ("freedoom1", "DEMO4", 0),
    ("freedoom2", "DEMO1", 0),
    ("freedoom2", "DEMO2", 0),
    ("freedoom2", "DEMO3", 0),
    ("freedoom2", "DEMO4", 0),
];

fn run(iwad: &str, lump: &str) -> demo::SyncReport {
    let wad = Wad::open(&freedoom_wads::path(&format!("{iwad}.wad"))).expect("the IWAD opens");
    let index = wad.find(lump).expect("the IWAD has the demo");
    let demo = VanillaDemo::from_bytes(wad.bytes(index), &format!("{iwad}.wad:{lump}")).expect("the demo reads");
    let dump_path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("fixtures/demo-dumps/{iwad}-{lump}.txt"));
    let dump = SyncDump::load(&dump_path).expect("the dump reads");
    let table = demo::table_for(&wad, ActorTable::doom()).expect("the IWAD's DEHACKED applies");
    let mut sim = demo::start(&wad, &demo, table).expect("the demo's game starts");
    demo::check(&mut sim, &demo, &dump)
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "Freedoom's IWADs are missing: apt-get install freedoom")]
fn freedoom_demos_stay_in_sync() {
    let mut short = Vec::new();
    for (iwad, lump, floor) in FLOORS {
        let report = run(iwad, lump);
        match &report.first_difference {
            None => println!("{iwad} {lump}: in sync for all {} tics", report.tics),
            Some((tic, diffs)) => {
                let fields: Vec<String> = diffs.iter().take(6).map(ToString::to_string).collect();
                println!(
                    "{iwad} {lump}: in sync {} of {} tics; tic {tic}: {}",
                    report.in_sync,
                    report.tics,
                    fields.join("; ")
                );
            }
        }
        if report.in_sync < floor {
            short.push(format!("{iwad} {lump}: {} tics in sync, at least {floor} expected", report.in_sync));
        }
    }
    assert!(short.is_empty(), "{}", short.join("\n"));
}
