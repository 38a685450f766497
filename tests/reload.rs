//! Live reload, headless: a map file edited under a running game is read
//! again (the new geometry in play, the player where it stood); a broken
//! edit is reported with the file and the line, and the old level goes on;
//! an edit that leaves the player outside the map puts it at the start.

use sightline::campaign::MapRef;
use sightline::play::playthrough::Playthrough;
use sightline::play::reload::{Reload, Watch};
use sightline::play::{GameOptions, TickInput};
use sightline_tests::map_path;

/// Writes `text` to `path` so that the watch sees a change (a new length or a later time).
fn edit(path: &std::path::Path, text: &str) {
    std::thread::sleep(std::time::Duration::from_millis(20));
    std::fs::write(path, text).unwrap();
}

#[test]
fn an_edited_map_is_reloaded_under_the_player_and_a_broken_one_keeps_the_old() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("room.ron");
    let text = std::fs::read_to_string(map_path("room.ron")).unwrap();
    std::fs::write(&path, &text).unwrap();
    let map = MapRef::File(path.clone());
    let mut play = Playthrough::of(&map, GameOptions::default()).unwrap();
    let mut watch = Watch::new(&map).expect("a RON map is watched");
    for _ in 0..30 {
        play.tick(&TickInput { forward: 1, turn: 1.0, ..Default::default() }).unwrap();
    }
    let (pos, angle) = (play.game.player().pos, play.game.player().angle);
    assert_eq!(watch.poll(&mut play), Reload::Unchanged);

    // Brighter and taller: the new geometry is in play, the player where it stood.
    edit(&path, &text.replacen("ceiling: 128.0, light: 200", "ceiling: 160.0, light: 120", 1));
    assert_eq!(watch.poll(&mut play), Reload::Reloaded { kept_pose: true });
    let sector = &play.game.level().map.sectors[0];
    assert_eq!((sector.ceiling, sector.light), (160.0, 120));
    assert_eq!((play.game.player().pos, play.game.player().angle), (pos, angle));
    assert_eq!(play.game.ticks(), 0);
    assert_eq!(watch.poll(&mut play), Reload::Unchanged);

    // A broken edit: the error names the file and the line; the level stays.
    edit(&path, &text.replacen("Sector(floor: 0.0,", "Sector(floor: 0.0,,", 1));
    let Reload::Broken(e) = watch.poll(&mut play) else { panic!("a broken map was taken") };
    assert!(e.contains("room.ron") && e.contains(":14:"), "{e}");
    assert_eq!(play.game.level().map.sectors[0].light, 120);
    play.tick(&TickInput::default()).unwrap();
    // A validation error names the element.
    edit(&path, &text.replacen("light: 200", "light: 999", 1));
    let Reload::Broken(e) = watch.poll(&mut play) else { panic!("an invalid map was taken") };
    assert!(e.contains("room.ron") && e.contains("sector 0"), "{e}");

    // Another map in the file, with the player's spot outside it: the start.
    let other = std::fs::read_to_string(map_path("two_rooms.ron")).unwrap();
    edit(&path, &other);
    let start = play.game.player().pos;
    let reloaded = watch.poll(&mut play);
    let inside = play.game.level().compiled.locate(start).is_some();
    assert_eq!(reloaded, Reload::Reloaded { kept_pose: inside });
    if !inside {
        assert_eq!(play.game.player().pos, play.game.level().map.player_start().pos);
    }
    // WADs and campaign files are not watched.
    assert!(Watch::new(&MapRef::parse("x.wad", None)).is_none());
}
