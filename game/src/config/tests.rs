use super::*;
use crate::play::input::{Controls, Keymap, Move, Settings};

fn read(text: &str) -> Loaded {
    parse(text, Path::new("/home/p/.config/sightline/config.ron"))
}

/// The warnings' texts, as printed.
fn said(loaded: &Loaded) -> Vec<String> {
    loaded.warnings.iter().map(ToString::to_string).collect()
}

#[test]
fn the_defaults_round_trip_through_the_file() {
    let config = Config::default();
    let loaded = read(&config.to_text());
    assert_eq!(said(&loaded), Vec::<String>::new());
    assert_eq!(loaded.config, config);
    assert!(!loaded.needs_backup);
}

#[test]
fn changed_settings_round_trip_through_a_written_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("sightline").join("config.ron");
    let mut config = Config::default();
    config.sound.effects_volume = 35;
    config.sound.soundfont = Some(PathBuf::from("/usr/share/sounds/sf2/x.sf2"));
    config.video.window = Some((1280, 800));
    config.video.renderer = Some("painter".into());
    config.controls.always_run = true;
    config.controls.keys.insert("forward".into(), vec!["KeyI".into()]);
    config.save(&path, false).unwrap();
    let loaded = load(&path);
    assert_eq!(said(&loaded), Vec::<String>::new());
    assert_eq!(loaded.config, config);
    // No temporary file is left behind.
    let names: Vec<_> = std::fs::read_dir(path.parent().unwrap()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, vec![std::ffi::OsString::from("config.ron")]);
}

#[test]
fn a_missing_file_is_the_defaults_without_a_word() {
    let dir = tempfile::tempdir().unwrap();
    let loaded = load(&dir.path().join("none.ron"));
    assert!(loaded.warnings.is_empty());
    assert_eq!(loaded.config, Config::default());
}

#[test]
fn a_syntax_error_names_the_file_and_line_and_keeps_the_defaults() {
    let loaded = read("(\n    sound: (\n        effects_volume: 40,\n        music_volume: [,\n    ),\n)\n");
    assert_eq!(loaded.config, Config::default());
    let said = said(&loaded);
    assert_eq!(said.len(), 1, "{said:?}");
    assert!(said[0].starts_with("/home/p/.config/sightline/config.ron:4:"), "{said:?}");
    assert!(loaded.needs_backup);
}

#[test]
fn an_unknown_key_is_one_warning_and_the_good_keys_are_kept() {
    let loaded =
        read("(\n    sound: (\n        effects_volume: 40,\n        volume: 3,\n    ),\n    colour: (a: 1),\n)\n");
    assert_eq!(loaded.config.sound.effects_volume, 40);
    assert_eq!(
        said(&loaded),
        vec![
            "/home/p/.config/sightline/config.ron:4: `sound.volume`: unknown key (known in `sound`: effects_volume, \
             music_volume, channels, soundfont, music)",
            "/home/p/.config/sightline/config.ron:6: `colour`: unknown section (known: controls, gamepad, sound, video, gameplay)",
        ]
    );
    assert!(loaded.needs_backup);
}

#[test]
fn a_wrong_type_is_one_warning_naming_the_key_and_what_was_expected() {
    let loaded = read("(\n  video: (\n    vsync: \"yes\",\n    size: (320, 200),\n  ),\n)\n");
    assert_eq!(loaded.config.video.size, (320, 200));
    assert!(loaded.config.video.vsync);
    assert_eq!(
        said(&loaded),
        vec![
            "/home/p/.config/sightline/config.ron:3: `video.vsync`: expected true or false, found `\"yes\"`; kept \
             the default"
        ]
    );
}

#[test]
fn out_of_range_values_are_refused_one_by_one() {
    let text = "(sound: (effects_volume: 150, channels: 0, music_volume: 20),\n \
                video: (size: (0, 200), window: Some((100000, 10)), renderer: Some(\"fast\"), threads: 999),\n \
                controls: (mouse_sensitivity: -1.0))";
    let loaded = read(text);
    let said = said(&loaded);
    assert_eq!(said.len(), 7, "{said:#?}");
    assert!(said
        .iter()
        .any(|w| w.contains("`sound.effects_volume`: 150 is out of range (expected a whole number 0 to 100)")));
    assert!(said.iter().any(|w| w.contains("`sound.channels`: 0 is out of range")));
    assert!(said.iter().any(|w| w.contains(":2: `video.size`: 0x200 is out of range")));
    assert!(said.iter().any(|w| w.contains("`video.window`: 100000x10 is out of range")));
    assert!(said.iter().any(|w| w.contains("`video.renderer`: unknown renderer `fast`")));
    assert!(said.iter().any(|w| w.contains("`video.threads`: 999 is out of range")));
    assert!(said.iter().any(|w| w.contains(":3: `controls.mouse_sensitivity`: -1 is out of range")));
    // The good key among them stays; the rest are the defaults.
    let defaults = Config::default();
    assert_eq!(loaded.config.sound.music_volume, 20);
    assert_eq!(loaded.config.sound.effects_volume, defaults.sound.effects_volume);
    assert_eq!(loaded.config.video, defaults.video);
}

#[test]
fn bad_bindings_keep_their_defaults_and_good_ones_apply() {
    let text = "(controls: (keys: {\n  \"forward\": [\"KeyI\"],\n  \"fly\": [\"KeyZ\"],\n  \"back\": [\"KeyK\", \
                \"Nope\"],\n  \"use\": [\"KeyU\", \"KeyJ\", \"KeyO\"],\n}))";
    let loaded = read(text);
    let keys = &loaded.config.controls.keys;
    assert_eq!(keys["forward"], vec!["KeyI"]);
    assert_eq!(keys["back"], Config::default().controls.keys["back"]);
    assert_eq!(keys["use"], Config::default().controls.keys["use"]);
    let said = said(&loaded);
    assert_eq!(said.len(), 3, "{said:#?}");
    assert!(said.iter().all(|w| w.starts_with("/home/p/.config/sightline/config.ron:1: `controls.keys`: ")));
    assert!(said.iter().any(|w| w.contains("unknown action `fly`")));
    assert!(said.iter().any(|w| w.contains("`back`: unknown key `Nope`")));
    assert!(said.iter().any(|w| w.contains("`use` has 3 keys; at most two")));
}

#[test]
fn an_unreadable_file_is_one_warning() {
    let dir = tempfile::tempdir().unwrap();
    // A directory where the file should be cannot be read as one.
    let loaded = load(dir.path());
    assert_eq!(loaded.config, Config::default());
    assert_eq!(loaded.warnings.len(), 1);
    assert!(said(&loaded)[0].contains("cannot be read"), "{:?}", said(&loaded));
    let path = dir.path().join("binary.ron");
    std::fs::write(&path, [0xff, 0xfe, 0x00]).unwrap();
    assert!(said(&load(&path))[0].ends_with("not UTF-8 text; using the default settings"));
}

#[test]
fn a_bad_file_is_backed_up_before_it_is_written_over() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("config.ron");
    let bad = "(sound: (effects_volume: 40, volume: 3))";
    std::fs::write(&path, bad).unwrap();
    let loaded = load(&path);
    assert!(loaded.needs_backup);
    loaded.config.save(&path, loaded.needs_backup).unwrap();
    assert_eq!(std::fs::read_to_string(dir.path().join("config.ron.bak")).unwrap(), bad);
    let again = load(&path);
    assert!(again.warnings.is_empty());
    assert_eq!(again.config.sound.effects_volume, 40);
}

#[test]
fn a_failed_write_leaves_the_old_file_whole() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("config.ron");
    std::fs::write(&path, "(sound: (effects_volume: 40))").unwrap();
    // The temporary file's name is taken by a directory: the write fails.
    std::fs::create_dir(dir.path().join("config.ron.tmp")).unwrap();
    let err = Config::default().save(&path, false).unwrap_err();
    assert!(format!("{err:#}").contains("config.ron.tmp"), "{err:#}");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "(sound: (effects_volume: 40))");
}

#[test]
fn a_rebound_key_drives_the_game() {
    let loaded = read("(controls: (keys: {\"forward\": [\"KeyI\"], \"fire\": [\"KeyW\"], \"use\": [\"ArrowDown\"]}, always_run: true))");
    assert!(loaded.warnings.is_empty(), "{:?}", said(&loaded));
    let config = loaded.config;
    let settings = Settings {
        keys: Keymap::of(&config.bindings()),
        sensitivity: config.controls.mouse_sensitivity,
        invert_mouse: config.controls.invert_mouse,
        always_run: config.controls.always_run,
        pad: config.pad_map(),
    };
    let mut controls = Controls::new(settings);
    controls.key(KeyCode::KeyI, true, false);
    let input = controls.tick_input();
    assert_eq!(input.forward, 1);
    assert!(input.run, "always run");
    assert!(!input.fire);
    // W now fires and no longer walks; the arrow is unbound from forward.
    controls.key(KeyCode::KeyI, false, false);
    controls.key(KeyCode::KeyW, true, false);
    controls.key(KeyCode::ArrowUp, true, false);
    let input = controls.tick_input();
    assert_eq!(input.forward, 0);
    assert!(input.fire);
    // Down arrow now uses, and back keeps only its other default, S.
    controls.key(KeyCode::ArrowDown, true, false);
    assert!(controls.tick_input().use_line);
    assert_eq!(config.controls.keys["back"], vec!["KeyS"]);
    // Holding run with always-run walks.
    controls.key(KeyCode::ShiftLeft, true, false);
    assert!(!controls.tick_input().run);
    // The other keys keep Doom's defaults.
    assert_eq!(controls.keys().get(KeyCode::KeyS), Some(crate::play::input::Bind::Move(Move::Back)));
}

#[test]
fn every_default_binding_names_a_real_key_and_no_key_is_bound_twice() {
    let config = Config::default();
    let bindings = config.bindings();
    let keys: std::collections::BTreeSet<_> = bindings.iter().map(|(k, _)| format!("{k:?}")).collect();
    assert_eq!(keys.len(), bindings.len(), "a key bound twice in BINDS");
    for (name, _, defaults) in BINDS {
        assert!(!defaults.is_empty() && defaults.len() <= 2, "{name}");
        for k in *defaults {
            assert_eq!(parse_key(&key_name(*k)), Some(*k));
        }
    }
}

#[test]
fn keys_are_found_on_their_lines() {
    let text = "(\n  sound: (music: false),\n  video: (\n    hud: true,\n    status_bar: 3,\n  ),\n)";
    assert_eq!(line_of(text, Some("sound"), "music"), 2);
    assert_eq!(line_of(text, Some("video"), "status_bar"), 5);
    assert_eq!(line_of(text, Some("video"), "hud"), 4);
    assert_eq!(line_of(text, None, "video"), 3);
    assert_eq!(line_of(text, Some("video"), "absent"), 1);
}
