//! What a scenario `.cfg` sets, typed: [`ScenarioConfig`] with every key
//! ViZDoom 1.3.2 reads and ViZDoom's defaults for those it leaves out.
//! `cfg` fills it from the text; paths stay as written, with
//! [`ScenarioConfig::resolve`] to open them as ViZDoom does.

use std::collections::BTreeMap;
use std::path::{Component, PathBuf};

use super::names::{AutomapMode, Button, GameVariable, Mode, SamplingRate, ScreenFormat, ScreenResolution};

/// A scenario `.cfg`, every key ViZDoom 1.3.2 reads, with ViZDoom's
/// defaults (from the 1.3.2 wheel's `vizdoom.pyi` and `DoomGame`'s
/// constructor) where the file does not set one.
#[derive(Clone, Debug, PartialEq)]
pub struct ScenarioConfig {
    /// The directory the `.cfg` is in; its relative paths are relative to it.
    pub base_dir: PathBuf,
    /// `vizdoom_path`: ViZDoom's executable, as written (see [`Self::resolve`]).
    pub vizdoom_path: Option<String>,
    /// `doom_game_path`: the IWAD, as written.
    pub doom_game_path: Option<String>,
    /// `doom_scenario_path`: the PWAD holding the scenario's map, as written.
    pub doom_scenario_path: Option<String>,
    /// `doom_config_path`: ZDoom's own ini file, as written.
    pub doom_config_path: Option<String>,
    /// `doom_map`, upper-cased as WAD lump names are (ViZDoom lower-cases
    /// it; ZDoom finds the map either way). Default `MAP01`.
    pub doom_map: String,
    /// `doom_skill`, 1 (easiest) to 5, as written; default 3.
    pub doom_skill: u32,
    /// `seed`: `None` when absent (ViZDoom then draws one at start-up).
    pub seed: Option<u32>,
    /// `game_args`: extra ZDoom command-line arguments, split at whitespace.
    pub game_args: Vec<String>,
    pub mode: Mode,
    /// `ticrate`: tics a second in the asynchronous modes; default 35.
    pub ticrate: u32,
    /// `episode_timeout` in tics; 0 (the default) means none.
    pub episode_timeout: u32,
    /// `episode_start_time`: the tic the agent's episode starts at; default 1.
    pub episode_start_time: u32,
    pub rewards: Rewards,
    /// `available_buttons`, in order, without repeats.
    pub available_buttons: Vec<Button>,
    /// `button_max_value = BUTTON N`, one line per button (the last wins).
    pub button_max_values: BTreeMap<Button, u32>,
    /// `available_game_variables`, in order, without repeats.
    pub available_game_variables: Vec<GameVariable>,
    /// `screen_resolution`; default `RES_320X240`.
    pub screen_resolution: ScreenResolution,
    /// `screen_format`; default `CRCGCB`.
    pub screen_format: ScreenFormat,
    pub render: RenderFlags,
    pub outputs: Outputs,
    pub automap: AutomapOptions,
    /// `window_visible`; default false.
    pub window_visible: bool,
    /// `console_enabled`; default false.
    pub console_enabled: bool,
    /// `sound_enabled`; default false.
    pub sound_enabled: bool,
}

/// The rewards ViZDoom adds each tic (all 0 by default). A `*_reward` key
/// whose twin is a `*_penalty` sets the penalty to its negation, as
/// ViZDoom's `setDeathReward` and the like do: one number, two names.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Rewards {
    /// `living_reward`, per tic alive.
    pub living: f64,
    /// `death_penalty` (or minus `death_reward`), subtracted on death.
    pub death_penalty: f64,
    /// `map_exit_reward`, on leaving the map alive.
    pub map_exit: f64,
    /// `kill_reward`, per monster killed.
    pub kill: f64,
    /// `item_reward`, per item picked up.
    pub item: f64,
    /// `secret_reward`, per secret found.
    pub secret: f64,
    /// `frag_reward`, per frag.
    pub frag: f64,
    /// `hit_reward`, per hit on an enemy.
    pub hit: f64,
    /// `hit_taken_penalty` (or minus `hit_taken_reward`), per hit taken.
    pub hit_taken_penalty: f64,
    /// `damage_made_reward`, per point of damage dealt.
    pub damage_made: f64,
    /// `damage_taken_penalty` (or minus `damage_taken_reward`), per point taken.
    pub damage_taken_penalty: f64,
    /// `health_reward`, per point of health gained.
    pub health: f64,
    /// `armor_reward`, per point of armour gained.
    pub armor: f64,
}

/// The `render_*` keys: what ZDoom draws into the screen buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderFlags {
    pub hud: bool,
    pub minimal_hud: bool,
    pub weapon: bool,
    pub crosshair: bool,
    pub decals: bool,
    pub particles: bool,
    pub effects_sprites: bool,
    pub messages: bool,
    pub corpses: bool,
    pub screen_flashes: bool,
    pub all_frames: bool,
}

impl Default for RenderFlags {
    fn default() -> Self {
        RenderFlags {
            hud: false,
            minimal_hud: false,
            weapon: true,
            crosshair: false,
            decals: true,
            particles: true,
            effects_sprites: true,
            messages: false,
            corpses: true,
            screen_flashes: true,
            all_frames: false,
        }
    }
}

/// What each state carries besides the screen (all off by default).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outputs {
    /// `depth_buffer_enabled`.
    pub depth_buffer: bool,
    /// `labels_buffer_enabled`.
    pub labels_buffer: bool,
    /// `automap_buffer_enabled`.
    pub automap_buffer: bool,
    /// `audio_buffer_enabled`.
    pub audio_buffer: bool,
    /// `audio_sampling_rate`; default `SR_44100`.
    pub audio_sampling_rate: SamplingRate,
    /// `audio_buffer_size` in tics, 0 to 2,100; default 1 (as ViZDoom 1.3.2).
    pub audio_buffer_size: u32,
    /// `notifications_buffer_enabled`.
    pub notifications_buffer: bool,
    /// `notifications_buffer_size` in tics; default 1.
    pub notifications_buffer_size: u32,
    /// `objects_info_enabled`.
    pub objects_info: bool,
    /// `sectors_info_enabled`.
    pub sectors_info: bool,
}

impl Default for Outputs {
    fn default() -> Self {
        Outputs {
            depth_buffer: false,
            labels_buffer: false,
            automap_buffer: false,
            audio_buffer: false,
            audio_sampling_rate: SamplingRate::default(),
            audio_buffer_size: 1,
            notifications_buffer: false,
            notifications_buffer_size: 1,
            objects_info: false,
            sectors_info: false,
        }
    }
}

/// The `automap_*` keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AutomapOptions {
    pub mode: AutomapMode,
    pub rotate: bool,
    /// Default true.
    pub render_textures: bool,
    pub render_objects_as_sprites: bool,
}

impl Default for AutomapOptions {
    fn default() -> Self {
        AutomapOptions {
            mode: AutomapMode::Normal,
            rotate: false,
            render_textures: true,
            render_objects_as_sprites: false,
        }
    }
}

impl Default for ScenarioConfig {
    fn default() -> Self {
        ScenarioConfig {
            base_dir: PathBuf::new(),
            vizdoom_path: None,
            doom_game_path: None,
            doom_scenario_path: None,
            doom_config_path: None,
            doom_map: "MAP01".to_string(),
            doom_skill: 3,
            seed: None,
            game_args: Vec::new(),
            mode: Mode::Player,
            ticrate: 35,
            episode_timeout: 0,
            episode_start_time: 1,
            rewards: Rewards::default(),
            available_buttons: Vec::new(),
            button_max_values: BTreeMap::new(),
            available_game_variables: Vec::new(),
            screen_resolution: ScreenResolution::default(),
            screen_format: ScreenFormat::default(),
            render: RenderFlags::default(),
            outputs: Outputs::default(),
            automap: AutomapOptions::default(),
            window_visible: false,
            console_enabled: false,
            sound_enabled: false,
        }
    }
}

impl ScenarioConfig {
    /// A path from the `.cfg` as ViZDoom opens it: joined to the `.cfg`'s
    /// directory (an absolute path stays as it is), `.` and `..` resolved
    /// by name (ViZDoom's `relativePath`, less its check for a symbolic link
    /// before a `..`).
    pub fn resolve(&self, given: &str) -> PathBuf {
        let mut out = PathBuf::new();
        for part in self.base_dir.join(given).components() {
            match part {
                Component::CurDir => {}
                Component::ParentDir if matches!(out.components().next_back(), Some(Component::Normal(_))) => {
                    out.pop();
                }
                other => out.push(other),
            }
        }
        out
    }

    /// `doom_scenario_path`, resolved.
    pub fn scenario_wad(&self) -> Option<PathBuf> {
        self.doom_scenario_path.as_deref().map(|p| self.resolve(p))
    }

    /// Whether `game_args` turn autoaim off (`+sv_noautoaim 1`, as
    /// rocket_basic and predict_position do); the other ZDoom settings
    /// they may give are not read.
    pub fn no_autoaim(&self) -> bool {
        self.game_args.windows(2).any(|w| w[0].eq_ignore_ascii_case("+sv_noautoaim") && w[1] != "0")
    }

    /// `doom_game_path`, resolved.
    pub fn game_wad(&self) -> Option<PathBuf> {
        self.doom_game_path.as_deref().map(|p| self.resolve(p))
    }
}
