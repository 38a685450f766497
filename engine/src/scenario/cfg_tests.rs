use super::*;
use crate::scenario::{
    AutomapMode, Button, GameVariable, Mode, SamplingRate, ScreenFormat, ScreenResolution, RESOLUTIONS,
};
use proptest::prelude::*;
use std::path::PathBuf;

/// ViZDoom 1.3.2's `scenarios/basic.cfg`, as shipped in the wheel.
const BASIC_CFG: &str = "\
# Lines starting with # are treated as comments (or with whitespaces+#).
# It doesn't matter if you use capital letters or not.
# It doesn't matter if you use underscore or camel notation for keys, e.g. episode_timeout is the same as episodeTimeout.

# This path can be absolute or relative to the config file location
doom_scenario_path = basic.wad
# Map to use, this is case insensitive
doom_map = map01

# Rewards
living_reward = -1

# Rendering options
screen_resolution = RES_320X240
render_hud = false

# Examples of other rendering options (set to defaults)
render_crosshair = false
render_weapon = true
render_decals = true
render_particles = true

# Make episodes start after 14 tics (after unholstering the gun)
episode_start_time = 14

# Make episodes finish after 300 actions (tics)
episode_timeout = 300

# Available buttons
available_buttons =
    {
        MOVE_LEFT
        MOVE_RIGHT
        ATTACK
    }

# Game variables that will be in the state
available_game_variables = { AMMO2 }

mode = PLAYER
doom_skill = 5
";

/// ViZDoom 1.3.2's `scenarios/predict_position.cfg`: an empty list and
/// `game_args +=`.
const PREDICT_POSITION_CFG: &str = "\
doom_scenario_path = predict_position.wad
doom_skill = 1

# Rewards
living_reward = -0.001

# Rendering options
screen_resolution = RES_320X240
render_hud = false

# Make episodes start after 16 tics (after the rocket launcher is ready)
episode_start_time = 16

# Make episodes finish after 300 actions (tics)
episode_timeout = 300

# Available buttons
available_buttons =
    {
        TURN_LEFT
        TURN_RIGHT
        ATTACK
    }

# Empty list is allowed, no additional variables will be available to the agent
available_game_variables = {  }

# Disable aim assist (autoaim)
game_args += +sv_noautoaim 1

mode = PLAYER
";

fn parse(text: &str) -> ScenarioConfig {
    ScenarioConfig::parse(text, "scenarios/test.cfg").unwrap_or_else(|e| panic!("{e}"))
}

fn error(text: &str) -> String {
    match ScenarioConfig::parse(text, "test.cfg") {
        Ok(cfg) => panic!("parsed, expected an error: {cfg:?}"),
        Err(e) => e.to_string(),
    }
}

fn check_basic(cfg: &ScenarioConfig) {
    assert_eq!(cfg.doom_scenario_path.as_deref(), Some("basic.wad"));
    assert_eq!(cfg.doom_map, "MAP01");
    assert_eq!(cfg.rewards.living, -1.0);
    assert_eq!(cfg.episode_start_time, 14);
    assert_eq!(cfg.episode_timeout, 300);
    assert_eq!(cfg.available_buttons, [Button::MoveLeft, Button::MoveRight, Button::Attack]);
    assert_eq!(cfg.available_game_variables, [GameVariable::Ammo(2)]);
    assert_eq!(cfg.doom_skill, 5);
    assert_eq!(cfg.mode, Mode::Player);
    assert_eq!(cfg.screen_resolution, ScreenResolution { width: 320, height: 240 });
    assert!(!cfg.render.hud && !cfg.render.crosshair && cfg.render.weapon && cfg.render.decals);
}

#[test]
fn basic_cfg_parses_with_its_values_and_defaults_elsewhere() {
    let cfg = parse(BASIC_CFG);
    check_basic(&cfg);
    assert_eq!(cfg.base_dir, Path::new("scenarios"));
    assert_eq!(cfg.scenario_wad(), Some(PathBuf::from("scenarios/basic.wad")));
    let untouched = ScenarioConfig { base_dir: PathBuf::new(), ..cfg.clone() };
    assert_eq!(untouched.rewards.death_penalty, 0.0);
    assert_eq!((cfg.ticrate, cfg.seed, cfg.screen_format), (35, None, ScreenFormat::Crcgcb));
    assert!(cfg.render.screen_flashes && !cfg.window_visible && !cfg.sound_enabled);
}

#[test]
fn predict_position_has_an_empty_list_and_appended_game_args() {
    let cfg = parse(PREDICT_POSITION_CFG);
    assert!(cfg.available_game_variables.is_empty());
    assert_eq!(cfg.game_args, ["+sv_noautoaim", "1"]);
    assert_eq!(cfg.rewards.living, -0.001);
    assert_eq!(cfg.doom_skill, 1);
}

#[test]
fn empty_text_gives_vizdooms_defaults() {
    let cfg = parse("");
    assert_eq!(cfg, ScenarioConfig { base_dir: PathBuf::from("scenarios"), ..ScenarioConfig::default() });
    assert_eq!(
        (cfg.doom_map.as_str(), cfg.doom_skill, cfg.episode_start_time, cfg.episode_timeout),
        ("MAP01", 3, 1, 0)
    );
    assert_eq!(cfg.outputs.audio_sampling_rate.hertz(), 44100);
    assert!(cfg.automap.render_textures && !cfg.automap.rotate);
}

#[test]
fn keys_are_snake_or_squashed_in_any_case_and_nothing_between() {
    for key in ["episode_timeout", "episodeTimeout", "EPISODE_TIMEOUT", "EpisodeTimeout", "episodetimeout"] {
        assert_eq!(parse(&format!("{key} = 7")).episode_timeout, 7, "{key}");
    }
    assert_eq!(error("episode_startTime = 7"), "test.cfg:1: unknown key `episode_starttime`");
    assert_eq!(error("episode__timeout = 7"), "test.cfg:1: unknown key `episode__timeout`");
}

#[test]
fn every_key_is_known_in_both_spellings() {
    assert_eq!(KEY_COUNT, 61);
    for name in key_names() {
        for spelling in [name.to_string(), name.replace('_', "").to_ascii_uppercase()] {
            let text = format!("{spelling} = x");
            let found = ScenarioConfig::parse(&text, "k.cfg").err().and_then(|e| e.problem().cloned());
            assert!(!matches!(found, Some(Problem::UnknownKey { .. })), "{spelling}: {found:?}");
        }
    }
}

#[test]
fn whitespace_and_comments_follow_vizdoom() {
    let cfg = parse("\t  # indented comment\r\n  doom_skill\t=\t4 \r\n\n#x = y\nrender_hud=TRUE\r\nrender_weapon = 0");
    assert_eq!(cfg.doom_skill, 4);
    assert!(cfg.render.hud && !cfg.render.weapon);
    // A `#` after a value belongs to the value, as in ViZDoom.
    assert_eq!(error("doom_skill = 5 # hard"), "test.cfg:1: `doom_skill`: `5 # hard` is not an unsigned integer");
}

#[test]
fn lists_span_lines_skip_comments_and_append_without_repeats() {
    let text = "available_buttons =\n\n# the brace comes later\n{ ATTACK\n# not = a button\n  use }\n\
                available_buttons += { USE select_weapon3 MOVE_LEFT_RIGHT_DELTA }\n\
                available_game_variables = { user60 player16_fragcount position_x }\n\
                available_game_variables = { HEALTH }";
    let cfg = parse(text);
    let buttons = [Button::Attack, Button::Use, Button::SelectWeapon(3), Button::MoveLeftRightDelta];
    assert_eq!(cfg.available_buttons, buttons);
    assert_eq!(cfg.available_game_variables, [GameVariable::Health]);
    let cfg = parse("available_game_variables = { user60 player16_fragcount position_x }");
    let variables = [GameVariable::User(60), GameVariable::PlayerFragCount(16), GameVariable::PositionX];
    assert_eq!(cfg.available_game_variables, variables);
    assert!(cfg.available_buttons.is_empty());
}

#[test]
fn game_args_append_with_plus_equals_and_reset_with_equals() {
    let cfg = parse("game_args = -fast\ngame_args += +sv_noautoaim 1\ngame_args += -respawn");
    assert_eq!(cfg.game_args, ["-fast", "+sv_noautoaim", "1", "-respawn"]);
    assert_eq!(parse("game_args += -fast\ngame_args = -Nomonsters").game_args, ["-Nomonsters"]);
    assert!(parse("game_args = -fast\ngame_args =").game_args.is_empty());
}

#[test]
fn every_typed_key_reads_its_value() {
    let text = "seed = 1993\nticrate = 70\nmode = async_spectator\nautomap_mode = OBJECTS_WITH_SIZE\n\
                screen_resolution = res_1920x1080\nscreen_format = DOOM_256_COLORS8\naudio_sampling_rate = SR_22050\n\
                button_max_value = TURN_LEFT_RIGHT_DELTA 10\nbutton_max_value = turn_left_right_delta 20\n\
                death_reward = -100\nhit_taken_reward = 0.5\ndamage_taken_penalty = 0.25\nmap_exit_reward = 1e2\n\
                kill_reward = +5\nvizdoom_path = ../Bin/VizDoom\ndoom_config_path = /etc/My.ini\n\
                notifications_buffer_size = 8\nnotificationsBufferEnabled = True\nrender_all_frames = 1";
    let cfg = parse(text);
    assert_eq!((cfg.seed, cfg.ticrate, cfg.mode), (Some(1993), 70, Mode::AsyncSpectator));
    assert_eq!(cfg.automap.mode, AutomapMode::ObjectsWithSize);
    assert_eq!(cfg.screen_resolution.to_string(), "RES_1920X1080");
    assert_eq!(
        (cfg.screen_format, cfg.outputs.audio_sampling_rate),
        (ScreenFormat::Doom256Colors8, SamplingRate::Sr22050)
    );
    assert_eq!(cfg.button_max_values.get(&Button::TurnLeftRightDelta), Some(&20));
    let rewards = (cfg.rewards.death_penalty, cfg.rewards.hit_taken_penalty, cfg.rewards.damage_taken_penalty);
    assert_eq!(rewards, (100.0, -0.5, 0.25));
    assert_eq!((cfg.rewards.map_exit, cfg.rewards.kill), (100.0, 5.0));
    assert_eq!(cfg.resolve(cfg.vizdoom_path.as_deref().unwrap_or_default()), PathBuf::from("Bin/VizDoom"));
    assert_eq!(cfg.resolve(cfg.doom_config_path.as_deref().unwrap_or_default()), PathBuf::from("/etc/My.ini"));
    assert_eq!(cfg.outputs.notifications_buffer_size, 8);
    assert!(cfg.outputs.notifications_buffer && cfg.render.all_frames);
}

#[test]
fn paths_resolve_against_the_cfg_directory() {
    let cfg = ScenarioConfig::parse("doom_game_path = ./wads/../doom2.wad", "/opt/vz/scenarios/x.cfg").unwrap();
    assert_eq!(cfg.game_wad(), Some(PathBuf::from("/opt/vz/scenarios/doom2.wad")));
    assert_eq!(cfg.resolve("../../freedoom2.wad"), PathBuf::from("/opt/freedoom2.wad"));
    let cfg = ScenarioConfig::parse("", "x.cfg").unwrap();
    assert_eq!(cfg.resolve("../a.wad"), PathBuf::from("../a.wad"));
}

#[test]
fn each_error_names_file_line_and_key_or_value() {
    let cases = [
        ("render_hud = true\nrender_hud true", "test.cfg:2: expected `key = value`, found `render_hud true`"),
        ("  = 5", "test.cfg:1: no key before the `=`"),
        ("\n\nFrobnicate = 1", "test.cfg:3: unknown key `frobnicate`"),
        ("doom_map =   ", "test.cfg:1: `doom_map` has no value"),
        (
            "doom_skill += 2",
            "test.cfg:1: `doom_skill`: `+=` appends only to available_buttons, available_game_variables and game_args",
        ),
        ("doom_map = { MAP01 }", "test.cfg:1: `doom_map` takes one value, not a `{ ... }` list"),
        ("available_buttons = ATTACK", "test.cfg:1: `available_buttons` takes a list in `{ ... }`, found `ATTACK`"),
        ("available_buttons =\n\n# x\n", "test.cfg:4: `available_buttons` takes a list in `{ ... }`, found the end of the file"),
        ("available_buttons = {\n ATTACK\n USE\n", "test.cfg:4: `available_buttons`: the `{` opened on line 1 is never closed"),
        (
            "available_buttons = { ATTACK\nmode = PLAYER\n}",
            "test.cfg:2: `available_buttons`: the `{` opened on line 1 is never closed",
        ),
        ("episode_timeout = ten", "test.cfg:1: `episode_timeout`: `ten` is not an unsigned integer"),
        ("episode_timeout = -1", "test.cfg:1: `episode_timeout`: `-1` is not an unsigned integer"),
        ("seed = 4294967296", "test.cfg:1: `seed`: `4294967296` is not an unsigned integer"),
        ("living_reward = NaN", "test.cfg:1: `living_reward`: `NaN` is not a finite number"),
        ("render_hud = yes", "test.cfg:1: `render_hud`: `yes` is not a boolean (true, false, 1 or 0)"),
        (
            "available_buttons = {\n ATTACK\n  FIRE }",
            "test.cfg:3: `available_buttons`: `FIRE` is not a ViZDoom button (MOVE_LEFT, ATTACK, ...)",
        ),
        (
            "available_game_variables = { USER61 }",
            "test.cfg:1: `available_game_variables`: `USER61` is not a ViZDoom game variable (HEALTH, AMMO2, USER1, ...)",
        ),
        (
            "screen_resolution = RES_320X241",
            "test.cfg:1: `screen_resolution`: `RES_320X241` is not a ViZDoom resolution (RES_320X240, RES_640X480, ...)",
        ),
        ("screen_format = RGB", "test.cfg:1: `screen_format`: `RGB` is not a screen format (CRCGCB, RGB24, GRAY8, ...)"),
        (
            "mode = BOT",
            "test.cfg:1: `mode`: `BOT` is not a mode (PLAYER, SPECTATOR, ASYNC_PLAYER or ASYNC_SPECTATOR)",
        ),
        (
            "automap_mode = ALL",
            "test.cfg:1: `automap_mode`: `ALL` is not an automap mode (NORMAL, WHOLE, OBJECTS or OBJECTS_WITH_SIZE)",
        ),
        (
            "audio_sampling_rate = 48000",
            "test.cfg:1: `audio_sampling_rate`: `48000` is not a sampling rate (SR_11025, SR_22050 or SR_44100)",
        ),
        (
            "audio_buffer_size = 2101",
            "test.cfg:1: `audio_buffer_size`: `2101` is not a number of tics from 0 to 2100 (a minute of sound)",
        ),
        (
            "audioBufferSize = -4",
            "test.cfg:1: `audio_buffer_size`: `-4` is not a number of tics from 0 to 2100 (a minute of sound)",
        ),
        (
            "button_max_value = ATTACK",
            "test.cfg:1: `button_max_value`: `ATTACK` is not `BUTTON N`, a button and its maximum value",
        ),
    ];
    for (text, message) in cases {
        assert_eq!(error(text), message, "{text:?}");
    }
}

#[test]
fn a_missing_file_is_a_read_error_naming_it() {
    let message = ScenarioConfig::load("/nonexistent/basic.cfg").err().map(|e| e.to_string()).unwrap_or_default();
    assert!(message.starts_with("/nonexistent/basic.cfg: cannot read: "), "{message}");
}

#[test]
fn load_reads_a_file_and_tolerates_non_utf8_comments() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("basic.cfg");
    let mut bytes = b"# caf\xe9\n".to_vec();
    bytes.extend_from_slice(BASIC_CFG.as_bytes());
    std::fs::write(&path, bytes).unwrap();
    let cfg = ScenarioConfig::load(&path).unwrap();
    check_basic(&cfg);
    assert_eq!(cfg.scenario_wad(), Some(dir.path().join("basic.wad")));
}

#[test]
fn names_round_trip() {
    let buttons = (0..=9).map(Button::SelectWeapon).chain(
        ["attack", "altattack", "turn180", "move_up_down_delta", "drop_selected_item"]
            .map(|n| Button::from_cfg(n).unwrap()),
    );
    for b in buttons {
        assert_eq!(Button::from_cfg(&b.name().to_ascii_lowercase()), Some(b), "{b:?}");
    }
    // ViZDoom's loader spells this one button differently from its enum.
    assert_eq!(Button::from_cfg("activate_selected_weapon"), Some(Button::ActivateSelectedItem));
    assert_eq!(Button::from_cfg("activate_selected_item"), None);
    assert_eq!(Button::from_cfg("alattack"), None);
    let variables: Vec<GameVariable> = (0..=9)
        .map(GameVariable::Ammo)
        .chain((0..=9).map(GameVariable::Weapon))
        .chain((1..=60).map(GameVariable::User))
        .chain((1..=16).map(GameVariable::PlayerFragCount))
        .collect();
    for v in variables {
        assert_eq!(GameVariable::from_cfg(&v.name().to_ascii_lowercase()), Some(v), "{v:?}");
    }
    for bad in ["user0", "user07", "ammo10", "player0_fragcount", "player17_fragcount", "weapon", "user+1"] {
        assert_eq!(GameVariable::from_cfg(bad), None, "{bad}");
    }
    for (width, height) in RESOLUTIONS {
        let r = ScreenResolution { width, height };
        assert_eq!(ScreenResolution::from_cfg(&r.to_string().to_ascii_lowercase()), Some(r));
    }
    assert_eq!(ScreenResolution::from_cfg("res_0320x240"), None);
    assert_eq!(Mode::from_cfg("async_player").map(Mode::name).as_deref(), Some("ASYNC_PLAYER"));
}

proptest! {
    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        let _ = ScenarioConfig::parse(&String::from_utf8_lossy(&bytes), "fuzz.cfg");
    }

    #[test]
    fn random_lines_of_cfg_pieces_never_panic(pieces in proptest::collection::vec(
        prop::sample::select(vec![
            "available_buttons", "available_game_variables", "game_args", "doom_skill", "living_reward", "mode",
            "button_max_value", "screen_resolution", "render_hud", "doom_scenario_path", "=", "+=", "{", "}", "#",
            " ", "\t", "\n", "\r\n", "ATTACK", "USER60", "RES_320X240", "-1", "1e309", "true", "map01", "..", "\u{feff}",
        ]),
        0..60,
    )) {
        let _ = ScenarioConfig::parse(&pieces.concat(), "fuzz.cfg");
    }
}

/// The `.cfg` files ViZDoom 1.3.2's wheel ships in `vizdoom/scenarios/`.
const SHIPPED: [&str; 23] = [
    "basic.cfg",
    "basic_audio.cfg",
    "basic_notifications.cfg",
    "cig.cfg",
    "deadly_corridor.cfg",
    "deathmatch.cfg",
    "defend_the_center.cfg",
    "defend_the_line.cfg",
    "doom.cfg",
    "doom2.cfg",
    "freedoom1.cfg",
    "freedoom2.cfg",
    "health_gathering.cfg",
    "health_gathering_supreme.cfg",
    "learning.cfg",
    "multi.cfg",
    "multi_duel.cfg",
    "my_way_home.cfg",
    "oblige.cfg",
    "predict_position.cfg",
    "rocket_basic.cfg",
    "simpler_basic.cfg",
    "take_cover.cfg",
];

#[test]
fn every_shipped_scenario_cfg_parses() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    for name in SHIPPED {
        let cfg = ScenarioConfig::load(dir.join(name)).unwrap_or_else(|e| panic!("{e}"));
        // ViZDoom's own test_scenario_configs checks this of every file.
        assert_eq!(cfg.screen_resolution, ScreenResolution { width: 320, height: 240 }, "{name}");
        assert!(!cfg.available_buttons.is_empty(), "{name}");
        if let Some(wad) = cfg.scenario_wad() {
            assert!(wad.is_file(), "{name}: {} is missing", wad.display());
        }
    }
    let load = |name: &str| ScenarioConfig::load(dir.join(name)).unwrap_or_else(|e| panic!("{e}"));
    check_basic(&load("basic.cfg"));
    let corridor = load("deadly_corridor.cfg");
    assert_eq!((corridor.doom_skill, corridor.rewards.death_penalty, corridor.available_buttons.len()), (5, 100.0, 7));
    assert!(!corridor.render.screen_flashes);
    let cig = load("cig.cfg");
    assert_eq!((cig.mode, cig.episode_timeout, cig.episode_start_time), (Mode::AsyncPlayer, 25200, 1));
    let doom2 = load("doom2.cfg");
    assert_eq!((doom2.rewards.map_exit, doom2.game_wad()), (1.0, Some(dir.join("doom2.wad"))));
    assert!(doom2.outputs.automap_buffer && doom2.outputs.audio_buffer && doom2.render.messages);
    assert!(load("basic_notifications.cfg").outputs.notifications_buffer);
    assert_eq!(load("my_way_home.cfg").rewards.living, -0.0001);
    assert_eq!(load("predict_position.cfg").game_args, ["+sv_noautoaim", "1"]);
    assert_eq!(load("learning.cfg").screen_format, ScreenFormat::Gray8);
    let deathmatch = load("deathmatch.cfg");
    assert_eq!(deathmatch.available_game_variables.len(), 5);
    assert_eq!(deathmatch.available_game_variables[3], GameVariable::SelectedWeapon);
    assert!(load("multi.cfg").window_visible);
}
