//! Saved games: a game saved at tick N and loaded plays on exactly as the
//! original (state and frames) on shipped maps and on Freedoom's, with
//! monsters fighting and machinery moving; a save file is written
//! atomically; and bad saves (truncated at every length, any byte flipped,
//! another version, a changed map, a forged body, not a save at all) are
//! errors naming the file, never a panic or a half-loaded game.
//! (The default level's own check, through its whole fight, is in
//! `outpost.rs`; the machinery map's in `machinery.rs`.)

use std::path::Path;

use sightline::campaign::MapRef;
use sightline::play::input::wander;
use sightline::play::playthrough::{Phase, Playthrough};
use sightline::play::save::{peek, SaveError, MAGIC, VERSION};
use sightline::play::{GameOptions, TickInput};
use sightline_tests::{map_path, saves_continue_exactly};

/// A wandering player who presses use now and then and fires in bursts,
/// so that monsters wake, chase, shoot and hit each other.
fn fighting(seed: u64, ticks: usize) -> Vec<TickInput> {
    let mut inputs = wander(seed, ticks, true);
    for (i, input) in inputs.iter_mut().enumerate() {
        input.fire = (i / 40) % 3 == 0;
    }
    inputs
}

/// Plays `map` with an unkillable player firing as it wanders, saving every
/// `every` ticks and following each save for `ahead` ticks: the game's
/// state in the save is `sim::save`'s, bit for bit.
fn check_map(map: &MapRef, ticks: usize, every: usize, ahead: usize) -> sightline_tests::SaveCheck {
    let options = GameOptions { skill: 4, seed: 7, ..Default::default() };
    let mut play = Playthrough::of(map, options).unwrap_or_else(|e| panic!("{e}"));
    play.game.set_health(1_000_000);
    let inputs = fighting(11, ticks);
    let save_at: Vec<usize> = (every..ticks - ahead).step_by(every).collect();
    let check = saves_continue_exactly(&mut play, &inputs, &save_at, ahead);
    println!("{}: {check:?}", map.label());
    assert_eq!(check.saves, save_at.len());
    check
}

#[test]
fn a_loaded_game_continues_tick_for_tick_on_the_shipped_maps() {
    for name in ["outpost.ron", "machinery.ron", "gridmaze.ron", "doors.ron"] {
        let check = check_map(&MapRef::File(map_path(name)), 1400, 200, 70);
        if name == "outpost.ron" {
            assert!(check.fighting > 0, "no monster was fighting at any save point: {check:?}");
        }
    }
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn a_loaded_game_continues_tick_for_tick_on_freedoom_maps_with_monsters_fighting() {
    let wad = |name: &str| sightline_tests::freedoom_wads::path(name).display().to_string();
    for map in [format!("{}:E1M1", wad("freedoom1.wad")), format!("{}:MAP01", wad("freedoom2.wad"))] {
        let check = check_map(&MapRef::parse(&map, None), 1500, 300, 70);
        assert!(check.fighting > 0, "{map}: no monster was fighting at any save point: {check:?}");
        assert!(check.machinery > 0, "{map}: no door or lift moved at any save point: {check:?}");
    }
}

/// A save of a short game on `map`.
fn save_of(map: &Path, ticks: usize) -> (Playthrough, Vec<u8>) {
    let mut play = Playthrough::of(&MapRef::File(map.to_path_buf()), GameOptions::default()).unwrap();
    for input in fighting(3, ticks) {
        play.tick(&input).unwrap();
    }
    let bytes = play.save_bytes().unwrap();
    (play, bytes)
}

#[test]
fn a_save_file_is_written_atomically_and_loads_from_anywhere() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("slot1.slsave");
    let (play, bytes) = save_of(&map_path("outpost.ron"), 300);
    play.save(&path).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
    let info = peek(&path).unwrap();
    assert_eq!((info.level_ticks, info.options), (300, GameOptions::default()));
    assert!(matches!(&info.map, MapRef::File(p) if p.is_absolute()), "{:?}", info.map);
    let loaded = Playthrough::load(&path).unwrap();
    assert!(loaded.game.state_bytes() == play.game.state_bytes());
    // No temporary file is left beside it.
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, ["slot1.slsave"]);
    // A write that fails (into a directory that does not exist) says so and
    // leaves the old save as it was.
    let missing = dir.path().join("no-such-dir").join("slot.slsave");
    let e = play.save(&missing).unwrap_err();
    assert!(matches!(e, SaveError::Write { .. }) && e.to_string().contains("no-such-dir"), "{e}");
    let over_a_dir = dir.path().to_path_buf();
    assert!(play.save(&over_a_dir).is_err());
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
}

/// Loading `bytes` must fail (and not panic).
fn refused(bytes: &[u8], what: &str) -> SaveError {
    match Playthrough::from_save_bytes(bytes, "bad.slsave") {
        Ok(_) => panic!("{what}: loaded"),
        Err(e) => {
            assert!(e.to_string().starts_with("bad.slsave: "), "{what}: the error does not name the file: {e}");
            e
        }
    }
}

#[test]
fn truncated_flipped_and_foreign_saves_are_errors_naming_the_file() {
    let (_, bytes) = save_of(&map_path("room.ron"), 200);
    // Truncated at every length.
    for len in 0..bytes.len() {
        refused(&bytes[..len], &format!("truncated to {len} bytes"));
    }
    // Every byte flipped (every bit of the header; one bit elsewhere).
    for i in 0..bytes.len() {
        let bits: &[u8] = if i < 28 { &[1, 2, 4, 8, 16, 32, 64, 128] } else { &[1 << (i % 8)] };
        for &bit in bits {
            let mut bad = bytes.clone();
            bad[i] ^= bit;
            refused(&bad, &format!("byte {i} flipped by {bit:#04x}"));
        }
    }
    // Another version, bytes after the end, not a save, nothing.
    let mut other = bytes.clone();
    other[MAGIC.len()] = VERSION + 1;
    assert!(matches!(refused(&other, "version"), SaveError::Version { found, .. } if found == VERSION + 1));
    // Versions 1 and 2, which could hold the f64 game, and 3, which kept
    // the held buttons apart: refused, saying so.
    for old in [1, 2, 3] {
        other[MAGIC.len()] = old;
        let e = refused(&other, "an older version");
        let says = e.to_string().contains(&format!("version {old}, this build reads version {VERSION}"));
        assert!(matches!(e, SaveError::Version { found, .. } if found == old) && says, "{e}");
    }
    let mut longer = bytes.clone();
    longer.push(0);
    assert!(matches!(refused(&longer, "longer"), SaveError::Corrupt { .. }));
    assert!(matches!(refused(b"", "empty"), SaveError::Magic { .. }));
    assert!(matches!(refused(b"RIFF....WAVEfmt ", "a WAV"), SaveError::Magic { .. }));
    let demo = sightline::play::Demo::new("maps/room.ron").to_bytes();
    assert!(matches!(refused(&demo, "a demo"), SaveError::Magic { .. }));
    let e = Playthrough::load(Path::new("/no/such/save.slsave")).err().unwrap();
    assert!(matches!(e, SaveError::Read { .. }) && e.to_string().contains("/no/such/save.slsave"), "{e}");
}

/// Rewrites the header of a save whose body was changed, so that only the
/// body's meaning can give it away.
fn reseal(mut bytes: Vec<u8>) -> Vec<u8> {
    let body = bytes[28..].to_vec();
    bytes[16..20].copy_from_slice(&crc32fast::hash(&body).to_le_bytes());
    bytes[20..28].copy_from_slice(&(body.len() as u64).to_le_bytes());
    bytes
}

#[test]
fn a_forged_save_with_a_good_checksum_is_an_error_or_a_game_that_runs() {
    let (_, bytes) = save_of(&map_path("outpost.ron"), 150);
    let (mut loaded, mut errors) = (0, 0);
    // Bytes of the body overwritten (with a checksum to match): the state
    // decodes wrongly, names what is not there, or is a game; never a panic.
    for (k, i) in (28..bytes.len()).step_by(7).enumerate() {
        let mut bad = bytes.clone();
        bad[i] = [0xff, 0x00, 0x80, 0x7f][k % 4];
        match Playthrough::from_save_bytes(&reseal(bad), "forged.slsave") {
            Ok(mut play) => {
                loaded += 1;
                for input in fighting(5, 35) {
                    let _ = play.tick(&input);
                }
            }
            Err(e) => {
                assert!(e.to_string().starts_with("forged.slsave: "), "{e}");
                errors += 1;
            }
        }
    }
    // Cut short inside the state, resealed.
    for cut in [bytes.len() - 1, bytes.len() - 100, bytes.len() / 2, 40] {
        refused(&reseal(bytes[..cut].to_vec()), &format!("cut to {cut} and resealed"));
    }
    println!("forged bodies: {loaded} loaded and ran, {errors} refused");
    assert!(errors > 0);
}

#[test]
fn a_save_for_a_map_that_has_changed_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let map = dir.path().join("room.ron");
    std::fs::copy(map_path("room.ron"), &map).unwrap();
    let (_, bytes) = save_of(&map, 100);
    let path = dir.path().join("room.slsave");
    std::fs::write(&path, &bytes).unwrap();
    assert!(Playthrough::load(&path).is_ok());
    // The same map with one light level changed.
    let text = std::fs::read_to_string(&map).unwrap();
    let at = text.find("light: ").expect("a light level in room.ron") + "light: ".len();
    let end = at + text[at..].find(|c: char| !c.is_ascii_digit()).unwrap();
    let light: u8 = text[at..end].parse().unwrap();
    std::fs::write(&map, format!("{}{}{}", &text[..at], light ^ 16, &text[end..])).unwrap();
    let e = Playthrough::load(&path).err().expect("loaded a save for another map");
    assert!(matches!(e, SaveError::MapChanged { .. }), "{e}");
    assert!(e.to_string().contains("room.slsave") && e.to_string().contains("has changed"), "{e}");
    // The map gone: an error naming the save and the map.
    std::fs::remove_file(&map).unwrap();
    let e = Playthrough::load(&path).err().expect("loaded a save for a missing map");
    assert!(matches!(e, SaveError::Open { .. }) && e.to_string().contains("room.ron"), "{e}");
    // A directory (or a device) where the map was: refused before reading it.
    std::fs::create_dir(&map).unwrap();
    let e = Playthrough::load(&path).err().expect("loaded a save naming a directory");
    assert!(matches!(e, SaveError::Corrupt { .. }) && e.to_string().contains("not a file"), "{e}");
}

#[test]
fn only_a_level_in_play_can_be_saved() {
    let map = MapRef::File(sightline_tests::root().join("tests/maps/exit.ron"));
    let mut play = Playthrough::of(&map, GameOptions::default()).unwrap();
    assert!(play.save_bytes().is_ok());
    // West to the exit switch, and use it: the intermission cannot be saved.
    play.tick(&TickInput { turn: 180.0, ..Default::default() }).unwrap();
    for _ in 0..100 {
        if play.game.player().pos.x < 48.0 {
            break;
        }
        play.tick(&TickInput { forward: 1, ..Default::default() }).unwrap();
    }
    for _ in 0..30 {
        play.tick(&TickInput::default()).unwrap();
    }
    play.tick(&TickInput { use_line: true, ..Default::default() }).unwrap();
    assert!(matches!(play.phase, Phase::Intermission { .. }), "{:?}", play.phase);
    let dir = tempfile::tempdir().unwrap();
    let e = play.save(&dir.path().join("x.slsave")).unwrap_err();
    assert!(matches!(e, SaveError::NotPlaying { .. }) && e.to_string().contains("x.slsave"), "{e}");
    assert!(!dir.path().join("x.slsave").exists());
}
