//! Saved games of the simulation: Freedoom's demos saved where monsters
//! are awake and movers run, loaded, and played on beside the original to
//! the demo's end, equal every tic (the dumps' state, `P_Random`, every
//! body, the thinkers, the level, and now and then the whole saved state);
//! round trips that change no byte; bad files (truncated, flipped, foreign,
//! another version, another actor table or map, forged indices, random
//! bytes) refused with errors naming the file and the element, never a
//! panic; and the atomic write.

use std::sync::{Arc, OnceLock};

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

use super::*;
use crate::actors::ActorTable;
use crate::play::lmp::{Ticcmd, VanillaDemo};
use crate::sim::mobj::mf;
use crate::sim::think::Status;
use crate::sim::{demo, test_wad};

const LABEL: &str = "slot1.sav";

/// A demo of a Freedoom IWAD, with the actor table it plays with.
struct Recorded {
    wad: Wad,
    demo: VanillaDemo,
    table: Arc<ActorTable>,
}

fn recorded(iwad: &str, lump: &str) -> Recorded {
    let wad = test_wad(iwad);
    let index = wad.find(lump).unwrap_or_else(|| panic!("{iwad} has no {lump}"));
    let demo = VanillaDemo::from_bytes(wad.bytes(index), lump).unwrap_or_else(|e| panic!("{iwad}:{lump}: {e}"));
    let table = demo::table_for(&wad, ActorTable::doom()).unwrap_or_else(|e| panic!("{iwad}: {e}"));
    Recorded { wad, demo, table }
}

impl Recorded {
    fn start(&self) -> Sim {
        demo::start(&self.wad, &self.demo, Arc::clone(&self.table)).unwrap_or_else(|e| panic!("{e}"))
    }

    /// Tic `t`'s commands, each player's in its slot (as `demo::check`).
    fn cmds(&self, t: usize) -> [Option<Ticcmd>; MAXPLAYERS] {
        let mut cmds = [None; MAXPLAYERS];
        let in_game = (0..self.demo.header.in_game.len()).filter(|&n| self.demo.header.in_game[n]);
        for (k, n) in in_game.enumerate() {
            cmds[n] = self.demo.tic(t).get(k).copied();
        }
        cmds
    }

    /// The game after the demo's first `tics` tics.
    fn after(&self, tics: usize) -> Sim {
        let mut sim = self.start();
        for t in 0..tics {
            sim.tick(&self.cmds(t));
        }
        sim
    }

    fn load(&self, bytes: &[u8]) -> Result<Sim, SaveError> {
        from_bytes_on_wad(bytes, LABEL, &self.wad, Arc::clone(&self.table))
    }
}

/// Doors, lifts, floors and crushers moving, and monsters with a target.
fn movers_and_awake(sim: &Sim) -> (usize, usize) {
    let movers = sim
        .thinkers
        .iter()
        .filter(|t| t.status == Status::Active && !matches!(t.kind, ThinkerKind::Mobj(_) | ThinkerKind::Light(_)))
        .count();
    let awake = sim.live_mobjs().filter(|&m| sim.mo(m).has(mf::COUNTKILL) && sim.mo(m).target.is_some()).count();
    (movers, awake)
}

/// The first index at which two lists differ, for a short failure message.
fn first_difference<T: PartialEq>(a: &[T], b: &[T]) -> Option<usize> {
    (0..a.len().max(b.len())).find(|&i| a.get(i) != b.get(i))
}

/// The two games are the same after tic `tic`: what the dump tests
/// compare, `P_Random`, every body, thinker and level part, and (when
/// `whole`) every saved byte.
fn assert_same(original: &Sim, loaded: &Sim, tic: usize, whole: bool) {
    assert_eq!(original.tic_state(), loaded.tic_state(), "tic {tic}: the dumps' state differs");
    assert_eq!(original.rng, loaded.rng, "tic {tic}: P_Random differs");
    let mobj = first_difference(&original.mobjs, &loaded.mobjs);
    assert!(mobj.is_none(), "tic {tic}: mobj {mobj:?} differs");
    let thinker = first_difference(&original.thinkers, &loaded.thinkers);
    assert!(thinker.is_none(), "tic {tic}: thinker {thinker:?} differs");
    let sector = first_difference(&original.level.sectors, &loaded.level.sectors);
    assert!(sector.is_none(), "tic {tic}: sector {sector:?} differs");
    assert!(original.level == loaded.level, "tic {tic}: the level differs");
    assert!(original.players == loaded.players, "tic {tic}: a player differs");
    if whole {
        assert!(to_bytes(original) == to_bytes(loaded), "tic {tic}: the saved state differs");
    }
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's IWADs: apt-get install freedoom")]
fn a_loaded_game_plays_on_bit_for_bit_to_the_demo_s_end() {
    // Save points where the exploration of these demos found movers
    // running and monsters awake (asserted below, so a changed demo says so).
    for (iwad, lump, save_at) in [("freedoom2.wad", "DEMO1", [300, 600]), ("freedoom1.wad", "DEMO1", [200, 700])] {
        let r = recorded(iwad, lump);
        for at in save_at {
            let mut original = r.after(at);
            let (movers, awake) = movers_and_awake(&original);
            assert!(movers > 0 && awake > 0, "{iwad} {lump} tic {at}: {movers} movers, {awake} monsters awake");
            let bytes = to_bytes(&original);
            let mut loaded = r.load(&bytes).unwrap_or_else(|e| panic!("{e}"));
            assert_same(&original, &loaded, at, true);
            for t in at..r.demo.tics() {
                original.tick(&r.cmds(t));
                loaded.tick(&r.cmds(t));
                assert_same(&original, &loaded, t + 1, t % 50 == 0 || t + 1 == r.demo.tics());
            }
        }
    }
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_save_at_the_first_and_the_last_tic_round_trips_byte_for_byte() {
    let r = recorded("freedoom2.wad", "DEMO2");
    for tics in [0, r.demo.tics()] {
        let sim = r.after(tics);
        let bytes = to_bytes(&sim);
        let info = read_info(&bytes, LABEL).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((info.map.as_str(), info.gametic as usize, info.rules), (sim.level.name.as_str(), tics, sim.rules));
        let loaded = r.load(&bytes).unwrap_or_else(|e| panic!("tic {tics}: {e}"));
        assert_same(&sim, &loaded, tics, true);
        assert!(to_bytes(&loaded) == bytes, "tic {tics}: the loaded game saves differently");
        println!("freedoom2 DEMO2 ({}) tic {tics}: a save of {} bytes", info.map, bytes.len());
    }
}

/// The save's description and state, decoded as the loader decodes them.
fn unseal(bytes: &[u8]) -> (SaveInfo, SimState) {
    let (info, mut rest) = read(bytes, LABEL).unwrap_or_else(|e| panic!("{e}"));
    let state = ciborium::from_reader(&mut rest).unwrap_or_else(|e| panic!("{e}"));
    (info, state)
}

/// The error of a load or save that must fail (a game is too long to print).
fn error<T>(result: Result<T, SaveError>, case: &str) -> SaveError {
    match result {
        Ok(_) => panic!("{case}: did not fail"),
        Err(e) => e,
    }
}

/// Loading `bytes` fails, with an error naming the file.
fn refused(r: &Recorded, bytes: &[u8], case: &str) -> SaveError {
    let e = error(r.load(bytes), case);
    assert!(e.to_string().starts_with(&format!("{LABEL}: ")), "{case}: the error does not name the file: {e}");
    e
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn bad_saves_are_errors_naming_the_file_and_what_is_wrong() {
    let r = recorded("freedoom2.wad", "DEMO1");
    let bytes = to_bytes(&r.after(300));
    let e = refused(&r, &bytes[..bytes.len() - 10], "truncated");
    assert!(matches!(e, SaveError::Truncated { .. }), "{e}");
    assert!(matches!(refused(&r, &bytes[..9], "a piece of the magic"), SaveError::Truncated { .. }));
    assert!(matches!(refused(&r, &bytes[..HEADER - 3], "no length"), SaveError::Truncated { .. }));
    let mut flipped = bytes.clone();
    flipped[bytes.len() / 2] ^= 0x10;
    let e = refused(&r, &flipped, "a byte flipped");
    assert!(matches!(e, SaveError::Corrupt { .. }) && e.to_string().contains("checksum"), "{e}");
    let mut magic = bytes.clone();
    magic[3] = b'x';
    assert!(matches!(refused(&r, &magic, "wrong magic"), SaveError::Magic { .. }));
    let mut old = bytes.clone();
    old[MAGIC.len()] = 0;
    let e = refused(&r, &old, "version 0");
    assert!(matches!(e, SaveError::OldVersion { found: 0, .. }) && e.to_string().contains("older format"), "{e}");
    let mut newer = bytes.clone();
    newer[MAGIC.len()] = VERSION + 1;
    assert!(matches!(refused(&r, &newer, "a newer version"), SaveError::NewVersion { .. }));
    let mut longer = bytes.clone();
    longer.push(0);
    assert!(matches!(refused(&r, &longer, "a byte after the end"), SaveError::Corrupt { .. }));
    assert!(matches!(refused(&r, b"", "nothing"), SaveError::Magic { .. }));
    assert!(matches!(refused(&r, &r.wad.bytes(0)[..64.min(r.wad.bytes(0).len())], "a lump"), SaveError::Magic { .. }));
    let e = error(load(Path::new("/no/such/slot.sav"), &r.wad, Arc::clone(&r.table)), "no file, no game");
    assert!(matches!(e, SaveError::Read { .. }) && e.to_string().contains("/no/such/slot.sav"), "{e}");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_playthrough_save_is_refused_by_its_header() {
    use crate::campaign::MapRef;
    use crate::play::playthrough::Playthrough;
    let room = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../maps/room.ron");
    let play =
        Playthrough::of(&MapRef::File(room), crate::play::GameOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let float_save = play.save_bytes().unwrap_or_else(|e| panic!("{e}"));
    let r = recorded("freedoom2.wad", "DEMO1");
    let e = refused(&r, &float_save, "a playthrough's save");
    assert!(matches!(e, SaveError::Magic { .. }) && e.to_string().contains("bad header"), "{e}");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn another_actor_table_or_map_is_refused() {
    let r = recorded("freedoom2.wad", "DEMO1");
    let sim = r.after(300);
    let bytes = to_bytes(&sim);
    let level = || Level::load(&r.wad, &sim.level.name).unwrap_or_else(|e| panic!("{e}"));
    // The same table built for -fast (halved tics, faster missiles).
    let fast = Arc::new(Info::new(Arc::clone(&r.table), !sim.rules.fast_monsters()));
    let e = error(from_bytes(&bytes, LABEL, level(), fast), "a -fast table");
    assert!(matches!(e, SaveError::InfoChanged { .. }) && e.to_string().contains("actor table"), "{e}");
    // Another map, and this map with one vertex moved.
    let same_info = || Arc::new(Info::new(Arc::clone(&r.table), sim.rules.fast_monsters()));
    let other = Level::load(&r.wad, if sim.level.name == "MAP02" { "MAP03" } else { "MAP02" }).unwrap();
    let e = error(from_bytes(&bytes, LABEL, other, same_info()), "another map");
    assert!(matches!(e, SaveError::MapChanged { .. }) && e.to_string().contains(&sim.level.name), "{e}");
    let mut moved = level();
    moved.vertices[0].0 += Fixed::ONE;
    let e = error(from_bytes(&bytes, LABEL, moved, same_info()), "a moved vertex");
    assert!(matches!(e, SaveError::MapChanged { .. }), "{e}");
    assert!(from_bytes(&bytes, LABEL, level(), same_info()).is_ok());
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn forged_indices_are_errors_naming_the_element() {
    let r = recorded("freedoom2.wad", "DEMO1");
    let bytes = to_bytes(&r.after(600));
    let (info, state) = unseal(&bytes);
    let far = 1_000_000;
    let mover = state.thinkers.iter().position(|t| matches!(t.kind, ThinkerKind::Door(_) | ThinkerKind::Plat(_)));
    let mover = mover.expect("a door or lift at tic 600");
    type Forge = fn(&mut SimState, usize);
    let cases: [(&str, &str, Forge); 12] = [
        ("mobj 5", "state 1000000", |s, far| s.mobjs[5].state = Some(StateId(far as u32))),
        ("mobj 7", "target 1000000", |s, far| s.mobjs[7].target = Some(MobjId(far as u32))),
        ("mobj 9", "kind 1000000", |s, far| s.mobjs[9].kind = far),
        ("mobj 2", "subsector", |s, far| s.mobjs[2].subsector = far),
        ("player 0", "body 1000000", |s, far| s.players[0].as_mut().unwrap().mo = MobjId(far as u32)),
        ("player 0", "weapon 1000000", |s, far| s.players[0].as_mut().unwrap().readyweapon = far),
        ("thinker 0", "body 1000000", |s, far| s.thinkers[0].kind = ThinkerKind::Mobj(MobjId(far as u32))),
        ("sector 3", "mover 1000000", |s, far| s.level.sectors[3].9 = Some(ThinkerId(far as u32))),
        ("side 4", "texture 60000", |s, _| s.level.sides[4].2 = NameId(60000)),
        ("button 0", "line 1000000", |s, far| s.spec.buttons[0].line = far),
        ("the last move", "special line crossed", |s, far| s.tm.spechit.push(far)),
        ("the level", "sectors saved", |s, _| _ = s.level.sectors.pop()),
    ];
    for (element, what, forge) in cases {
        let mut forged = state.clone();
        forge(&mut forged, far);
        let e = refused(&r, &seal(&info, &forged), element);
        let message = e.to_string();
        assert!(matches!(e, SaveError::Invalid { .. }), "{element}: {message}");
        assert!(message.contains(element) && message.contains(what), "{element}, {what}: {message}");
    }
    let mut forged = state.clone();
    match &mut forged.thinkers[mover].kind {
        ThinkerKind::Door(d) => d.sector = far,
        ThinkerKind::Plat(p) => p.sector = far,
        other => panic!("thinker {mover} is {other:?}"),
    }
    let e = refused(&r, &seal(&info, &forged), "a mover's sector");
    assert!(e.to_string().contains(&format!("thinker {mover}: sector 1000000")), "{e}");
}

/// A save of freedoom2 DEMO1 at tic 600, the map it was made on and the
/// actor table, made once for the property tests.
fn sample() -> &'static (Vec<u8>, Level, Arc<Info>) {
    static SAMPLE: OnceLock<(Vec<u8>, Level, Arc<Info>)> = OnceLock::new();
    SAMPLE.get_or_init(|| {
        let r = recorded("freedoom2.wad", "DEMO1");
        let sim = r.after(600);
        let level = Level::load(&r.wad, &sim.level.name).unwrap_or_else(|e| panic!("{e}"));
        (to_bytes(&sim), level, Arc::clone(&sim.info))
    })
}

/// Loads `bytes` on the sample's map: `Ok` or `Err`, never a panic.
fn try_load(bytes: &[u8]) -> Result<Sim, SaveError> {
    let (_, level, info) = sample();
    from_bytes(bytes, LABEL, level.clone(), Arc::clone(info))
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn random_bytes_truncations_and_resealed_edits_never_panic() {
    let (bytes, _, _) = sample();
    let mut runner = TestRunner::new(Config { failure_persistence: None, ..Config::with_cases(256) });
    // Random bytes, raw and behind a valid header.
    let junk = (proptest::collection::vec(any::<u8>(), 0..4096), any::<bool>());
    runner
        .run(&junk, |(junk, sealed)| {
            let input = if sealed { in_envelope(&junk) } else { junk };
            prop_assert!(try_load(&input).is_err());
            Ok(())
        })
        .unwrap();
    // A real save cut short anywhere.
    runner
        .run(&(0..bytes.len()), |len| {
            let refused = matches!(try_load(&bytes[..len]), Err(SaveError::Truncated { .. } | SaveError::Magic { .. }));
            prop_assert!(refused, "cut to {} bytes", len);
            Ok(())
        })
        .unwrap();
    // A real save with a few bytes of its body changed, the checksum made
    // right again: decoding or checking may refuse it, or a changed number
    // may load, but nothing panics.
    let edits = proptest::collection::vec((HEADER..bytes.len(), any::<u8>()), 1..6);
    runner
        .run(&edits, |edits| {
            let mut body = bytes[HEADER..].to_vec();
            for (at, byte) in edits {
                body[at - HEADER] = byte;
            }
            let _ = try_load(&in_envelope(&body));
            Ok(())
        })
        .unwrap();
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
fn a_failed_write_leaves_the_existing_save_untouched() {
    let r = recorded("freedoom2.wad", "DEMO1");
    let (early, late) = (r.after(100), r.after(300));
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("slot1.sav");
    save(&path, &early).unwrap_or_else(|e| panic!("{e}"));
    let before = std::fs::read(&path).unwrap();
    assert_eq!(before, to_bytes(&early));
    assert_eq!(peek(&path).unwrap().gametic, 100);
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, ["slot1.sav"], "no temporary file is left beside the save");
    // The temporary file cannot be made (its name is taken by a directory;
    // unlike a read-only directory this stops root too): the write fails
    // and names the file, and the old save is as it was.
    let temporary = dir.path().join(format!(".slot1.sav.tmp{}", std::process::id()));
    std::fs::create_dir(&temporary).unwrap();
    let e = error(save(&path, &late), "the write fails");
    assert!(matches!(e, SaveError::Write { .. }) && e.to_string().contains("slot1.sav"), "{e}");
    assert_eq!(std::fs::read(&path).unwrap(), before);
    std::fs::remove_dir(&temporary).unwrap();
    // A directory that cannot be written, where permissions stop the writer.
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o555)).unwrap();
    if std::fs::File::create(dir.path().join("probe")).is_err() {
        assert!(matches!(save(&path, &late), Err(SaveError::Write { .. })));
        assert_eq!(std::fs::read(&path).unwrap(), before);
    }
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
    save(&path, &late).unwrap_or_else(|e| panic!("{e}"));
    let loaded = load(&path, &r.wad, Arc::clone(&r.table)).unwrap_or_else(|e| panic!("{e}"));
    assert_same(&late, &loaded, 300, true);
}
