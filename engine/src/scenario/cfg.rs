//! Reads a ViZDoom scenario `.cfg` into a typed [`ScenarioConfig`]; whoever
//! runs the scenario takes it from there.
//!
//! The grammar is that of ViZDoom 1.3.2's `ConfigLoader::load`
//! (`src/lib/ViZDoomConfigLoader.cpp`), read, not copied:
//!
//! - A line is `key = value`, `key += value`, blank, or a comment: a line
//!   whose first character after leading whitespace is `#`. A `#` after a
//!   value is part of the value, as in ViZDoom (so `doom_skill = 5 # hard`
//!   is a bad number there and here).
//! - If a line holds `+=` anywhere, it splits there, else at its first `=`.
//!   Key and value are trimmed and runs of inner whitespace squeezed to one
//!   character (boost's `trim_all`).
//! - Keys ignore case, and each is known by two spellings: snake case and
//!   the same with every `_` removed, so `episode_timeout`, `episodeTimeout`
//!   and `EPISODETIMEOUT` are one key. Only those two: ViZDoom compares
//!   whole strings, so `episode_startTime` is unknown to it and here.
//! - `available_buttons` and `available_game_variables` take a list in
//!   `{ ... }`: the `{` may be on a following line, the list may span lines,
//!   and `#` lines inside it are skipped; `+=` appends to the list (a name
//!   already in it is not added twice, as ViZDoom's `addAvailableButton`).
//!   `game_args` is a string that `+=` appends to.
//! - Values ignore case, except paths and `game_args`. Booleans are `true`,
//!   `false`, `1` or `0`; counts are unsigned integers; rewards are numbers.
//!
//! Where ViZDoom prints a warning, skips the line and carries on, this
//! reader stops with a [`CfgError`] naming the file, the line and the key
//! or value. Where the two differ otherwise, this reader is the stricter or
//! the clearer, never the looser on a file ViZDoom would take as meant:
//! list items are split at any whitespace (ViZDoom splits at spaces only,
//! so a tab between two names on one line makes one unknown name there); a
//! `key = value` line inside an open list ends it with "never closed" (ViZDoom
//! reads on and fails on the key's words, or swallows lines up to a later
//! `}`); a `{` list given to a one-value key is refused (ViZDoom would take
//! `doom_map = { map01 }` as a map named `{ map01 }`); and a reward that
//! parses to an infinity or NaN is refused (it would poison every total).

use std::path::Path;

use super::config::ScenarioConfig;
use super::names::{AutomapMode, Button, GameVariable, Mode, SamplingRate, ScreenFormat, ScreenResolution};

/// Why a `.cfg` was refused.
#[derive(Debug, thiserror::Error)]
pub enum CfgError {
    #[error("{path}: cannot read: {error}")]
    Io { path: String, error: std::io::Error },
    #[error("{path}:{line}: {problem}")]
    Line { path: String, line: usize, problem: Problem },
}

impl CfgError {
    /// The line's problem, if it is not a read error.
    pub fn problem(&self) -> Option<&Problem> {
        match self {
            CfgError::Line { problem, .. } => Some(problem),
            CfgError::Io { .. } => None,
        }
    }
}

/// What is wrong on a line. Keys are named in snake case; values as written.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Problem {
    #[error("expected `key = value`, found `{text}`")]
    MissingEquals { text: String },
    #[error("no key before the `=`")]
    EmptyKey,
    #[error("unknown key `{key}`")]
    UnknownKey { key: String },
    #[error("`{key}` has no value")]
    EmptyValue { key: &'static str },
    #[error("`{key}`: `+=` appends only to available_buttons, available_game_variables and game_args")]
    AppendToScalar { key: &'static str },
    #[error("`{key}` takes one value, not a `{{ ... }}` list")]
    ListForScalar { key: &'static str },
    #[error("`{key}` takes a list in `{{ ... }}`, found {found}")]
    ExpectedList { key: &'static str, found: String },
    #[error("`{key}`: the `{{` opened on line {opened} is never closed")]
    UnclosedList { key: &'static str, opened: usize },
    #[error("`{key}`: `{value}` is not {expected}")]
    BadValue { key: &'static str, value: String, expected: &'static str },
}

impl ScenarioConfig {
    /// Reads and parses the `.cfg` at `path`. Bytes that are not UTF-8
    /// become U+FFFD: harmless in comments, an unknown name in a value.
    pub fn load(path: impl AsRef<Path>) -> Result<ScenarioConfig, CfgError> {
        let path = path.as_ref();
        let bytes = std::fs::read(path).map_err(|error| CfgError::Io { path: path.display().to_string(), error })?;
        ScenarioConfig::parse(&String::from_utf8_lossy(&bytes), &path.display().to_string())
    }

    /// Parses `.cfg` text. `label` names the file in errors, and its parent
    /// directory becomes [`Self::base_dir`].
    pub fn parse(text: &str, label: &str) -> Result<ScenarioConfig, CfgError> {
        let mut cfg = ScenarioConfig {
            base_dir: Path::new(label).parent().map(Path::to_path_buf).unwrap_or_default(),
            ..Default::default()
        };
        cfg.read_lines(text, label)?;
        Ok(cfg)
    }

    /// `.cfg` text applied onto this configuration, as ViZDoom's
    /// `load_config` and `set_config` apply a file onto a game's settings:
    /// the keys it sets replace, `+=` appends, the rest stay. The paths it
    /// sets are resolved against `label`'s directory and kept whole, so
    /// they still name the same files whatever [`Self::base_dir`] is. On
    /// an error nothing changes.
    pub fn apply(&mut self, text: &str, label: &str) -> Result<(), CfgError> {
        let mut next = self.clone();
        next.read_lines(text, label)?;
        let here = ScenarioConfig {
            base_dir: Path::new(label).parent().map(Path::to_path_buf).unwrap_or_default(),
            ..Default::default()
        };
        let whole = |now: &Option<String>, then: &Option<String>| match now {
            Some(p) if now != then => Some(here.resolve(p).display().to_string()),
            other => other.clone(),
        };
        next.vizdoom_path = whole(&next.vizdoom_path, &self.vizdoom_path);
        next.doom_game_path = whole(&next.doom_game_path, &self.doom_game_path);
        next.doom_scenario_path = whole(&next.doom_scenario_path, &self.doom_scenario_path);
        next.doom_config_path = whole(&next.doom_config_path, &self.doom_config_path);
        next.base_dir = self.base_dir.clone();
        *self = next;
        Ok(())
    }

    fn read_lines(&mut self, text: &str, label: &str) -> Result<(), CfgError> {
        let mut lines = text.split('\n').enumerate().map(|(i, l)| (i + 1, squeeze(l)));
        while let Some((number, line)) = lines.next() {
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            self.read_entry(number, &line, &mut lines).map_err(|(line, problem)| CfgError::Line {
                path: label.to_string(),
                line,
                problem,
            })?;
        }
        Ok(())
    }

    /// One `key = value` line, and for a list the lines it spans.
    fn read_entry(
        &mut self,
        number: usize,
        line: &str,
        rest: &mut impl Iterator<Item = (usize, String)>,
    ) -> Result<(), (usize, Problem)> {
        let at = |problem| (number, problem);
        let (key, value, append) = match (line.find("+="), line.find('=')) {
            (Some(i), _) => (&line[..i], &line[i + 2..], true),
            (None, Some(i)) => (&line[..i], &line[i + 1..], false),
            (None, None) => return Err(at(Problem::MissingEquals { text: line.to_string() })),
        };
        let (key, value) = (key.trim_matches(is_space).to_ascii_lowercase(), value.trim_matches(is_space));
        if key.is_empty() {
            return Err(at(Problem::EmptyKey));
        }
        let Some(&(name, slot)) = KEYS.iter().find(|(name, _)| spells(name, &key)) else {
            return Err(at(Problem::UnknownKey { key }));
        };
        match slot {
            Slot::Buttons => {
                let items = read_list(name, number, value, rest)?;
                let buttons = typed_items(name, items, Button::from_cfg, "a ViZDoom button (MOVE_LEFT, ATTACK, ...)")?;
                extend_unique(&mut self.available_buttons, buttons, append);
            }
            Slot::GameVariables => {
                let items = read_list(name, number, value, rest)?;
                let expected = "a ViZDoom game variable (HEALTH, AMMO2, USER1, ...)";
                let variables = typed_items(name, items, GameVariable::from_cfg, expected)?;
                extend_unique(&mut self.available_game_variables, variables, append);
            }
            Slot::GameArgs => {
                if !append {
                    self.game_args.clear();
                }
                self.game_args.extend(value.split_whitespace().map(str::to_string));
            }
            _ if append => return Err(at(Problem::AppendToScalar { key: name })),
            _ if value.is_empty() => return Err(at(Problem::EmptyValue { key: name })),
            _ if value.starts_with('{') => return Err(at(Problem::ListForScalar { key: name })),
            _ => self.set(name, slot, value).map_err(at)?,
        }
        Ok(())
    }

    /// A scalar key's value, converted to its type.
    fn set(&mut self, key: &'static str, slot: Slot, raw: &str) -> Result<(), Problem> {
        let lower = raw.to_ascii_lowercase();
        let given = Given { key, raw };
        match slot {
            Slot::Uint(field) => *field(self) = given.typed(unsigned(&lower), UNSIGNED)?,
            Slot::AudioTics => {
                let tics = unsigned(&lower).filter(|&t| t <= super::buffers::MAX_AUDIO_TICS);
                self.outputs.audio_buffer_size =
                    given.typed(tics, "a number of tics from 0 to 2100 (a minute of sound)")?;
            }
            Slot::Seed => self.seed = Some(given.typed(unsigned(&lower), UNSIGNED)?),
            Slot::Float(field) => *field(self) = given.typed(finite(&lower), NUMBER)?,
            Slot::NegatedFloat(field) => *field(self) = -given.typed(finite(&lower), NUMBER)?,
            Slot::Bool(field) => *field(self) = given.typed(boolean(&lower), BOOLEAN)?,
            Slot::Path(field) => *field(self) = Some(raw.to_string()),
            Slot::Map => self.doom_map = raw.to_ascii_uppercase(),
            Slot::Mode => {
                self.mode = given
                    .typed(Mode::from_cfg(&lower), "a mode (PLAYER, SPECTATOR, ASYNC_PLAYER or ASYNC_SPECTATOR)")?
            }
            Slot::AutomapMode => {
                let expected = "an automap mode (NORMAL, WHOLE, OBJECTS or OBJECTS_WITH_SIZE)";
                self.automap.mode = given.typed(AutomapMode::from_cfg(&lower), expected)?;
            }
            Slot::Resolution => {
                let expected = "a ViZDoom resolution (RES_320X240, RES_640X480, ...)";
                self.screen_resolution = given.typed(ScreenResolution::from_cfg(&lower), expected)?;
            }
            Slot::Format => {
                let expected = "a screen format (CRCGCB, RGB24, GRAY8, ...)";
                self.screen_format = given.typed(ScreenFormat::from_cfg(&lower), expected)?;
            }
            Slot::SamplingRate => {
                let expected = "a sampling rate (SR_11025, SR_22050 or SR_44100)";
                self.outputs.audio_sampling_rate = given.typed(SamplingRate::from_cfg(&lower), expected)?;
            }
            Slot::ButtonMaxValue => {
                // ViZDoom splits at the first space: the button, then the maximum.
                let pair = lower.split_once(is_space).and_then(|(b, n)| Some((Button::from_cfg(b)?, unsigned(n)?)));
                let (button, max) = given.typed(pair, "`BUTTON N`, a button and its maximum value")?;
                self.button_max_values.insert(button, max);
            }
            Slot::Buttons | Slot::GameVariables | Slot::GameArgs => {}
        }
        Ok(())
    }
}

/// A scalar key's value as written, for the error if it does not convert.
struct Given<'a> {
    key: &'static str,
    raw: &'a str,
}

impl Given<'_> {
    fn typed<T>(&self, parsed: Option<T>, expected: &'static str) -> Result<T, Problem> {
        parsed.ok_or_else(|| Problem::BadValue { key: self.key, value: self.raw.to_string(), expected })
    }
}

const UNSIGNED: &str = "an unsigned integer";
const NUMBER: &str = "a finite number";
const BOOLEAN: &str = "a boolean (true, false, 1 or 0)";

/// ViZDoom's `stringToUint`: boost's `lexical_cast<unsigned int>`, which
/// takes a `+` and would wrap a `-`, so ViZDoom refuses a leading `-`.
fn unsigned(text: &str) -> Option<u32> {
    if text.starts_with('-') {
        return None;
    }
    text.parse().ok()
}

fn finite(text: &str) -> Option<f64> {
    text.parse::<f64>().ok().filter(|x| x.is_finite())
}

/// ViZDoom's `stringToBool`, on the lower-cased value.
fn boolean(text: &str) -> Option<bool> {
    match text {
        "true" | "1" => Some(true),
        "false" | "0" => Some(false),
        _ => None,
    }
}

/// Whether `key` (lower-cased) spells the snake-case `name`, with its
/// underscores or without any.
fn spells(name: &str, key: &str) -> bool {
    name == key || name.chars().filter(|&c| c != '_').eq(key.chars())
}

/// The C locale's `isspace`, which boost's `trim_all` uses: Rust's
/// `is_ascii_whitespace` leaves out the vertical tab.
fn is_space(c: char) -> bool {
    matches!(c, ' ' | '\t' | '\n' | '\x0b' | '\x0c' | '\r')
}

/// boost's `trim_all`: whitespace off both ends, each inner run of it cut
/// to its first character.
fn squeeze(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut after_space = false;
    for c in line.trim_matches(is_space).chars() {
        if !(is_space(c) && after_space) {
            out.push(c);
        }
        after_space = is_space(c);
    }
    out
}

/// The items of a `{ ... }` list with the line each is on. `value` is what
/// followed the `=`; if it is empty the `{` may come on a later line.
fn read_list(
    key: &'static str,
    mut number: usize,
    value: &str,
    rest: &mut impl Iterator<Item = (usize, String)>,
) -> Result<Vec<(usize, String)>, (usize, Problem)> {
    let mut first = value.to_string();
    while first.is_empty() {
        let Some((n, line)) = rest.next() else { break };
        number = n;
        if !line.starts_with('#') {
            first = line;
        }
    }
    let Some(body) = first.strip_prefix('{') else {
        let found = if first.is_empty() { "the end of the file".to_string() } else { format!("`{first}`") };
        return Err((number, Problem::ExpectedList { key, found }));
    };
    let opened = number;
    let mut parts = vec![(number, body.to_string())];
    while !parts.last().is_some_and(|(_, text)| text.ends_with('}')) {
        let Some((n, line)) = rest.next() else {
            return Err((number, Problem::UnclosedList { key, opened }));
        };
        number = n;
        // ViZDoom would read on and fail on the next key's words, or swallow
        // lines up to some later `}`; a `key = value` line is the clearer sign.
        if line.contains('=') && !line.starts_with('#') {
            return Err((number, Problem::UnclosedList { key, opened }));
        }
        if !line.is_empty() && !line.starts_with('#') {
            parts.push((n, line));
        }
    }
    if let Some((_, last)) = parts.last_mut() {
        last.pop();
    }
    Ok(parts.iter().flat_map(|(n, text)| text.split_whitespace().map(|item| (*n, item.to_string()))).collect())
}

/// A list's items as typed names; the first unknown one is the error.
fn typed_items<T>(
    key: &'static str,
    items: Vec<(usize, String)>,
    from_cfg: fn(&str) -> Option<T>,
    expected: &'static str,
) -> Result<Vec<T>, (usize, Problem)> {
    items
        .into_iter()
        .map(|(n, item)| {
            from_cfg(&item.to_ascii_lowercase()).ok_or((n, Problem::BadValue { key, value: item, expected }))
        })
        .collect()
}

/// `=` replaces the list, `+=` appends; a name already there is skipped.
fn extend_unique<T: PartialEq>(list: &mut Vec<T>, items: Vec<T>, append: bool) {
    if !append {
        list.clear();
    }
    for item in items {
        if !list.contains(&item) {
            list.push(item);
        }
    }
}

/// Where a key's value goes and what type it has.
#[derive(Clone, Copy)]
enum Slot {
    Buttons,
    GameVariables,
    GameArgs,
    Uint(fn(&mut ScenarioConfig) -> &mut u32),
    Seed,
    Float(fn(&mut ScenarioConfig) -> &mut f64),
    /// A `*_reward` key stored as its `*_penalty` twin.
    NegatedFloat(fn(&mut ScenarioConfig) -> &mut f64),
    Bool(fn(&mut ScenarioConfig) -> &mut bool),
    Path(fn(&mut ScenarioConfig) -> &mut Option<String>),
    Map,
    Mode,
    AutomapMode,
    Resolution,
    Format,
    SamplingRate,
    /// `audio_buffer_size`: tics, at most `buffers::MAX_AUDIO_TICS`.
    AudioTics,
    ButtonMaxValue,
}

/// How many keys ViZDoom 1.3.2's loader knows.
pub const KEY_COUNT: usize = KEYS.len();

/// Every key ViZDoom 1.3.2's loader knows, in snake case: the 61 names
/// whose underscore-free spellings (`availablebuttons` ... `buttonmaxvalue`)
/// are in the 1.3.2 wheel's library, each found there in snake case too.
/// The loader's source on GitHub stops at 1.2 (no `*_reward` keys but
/// `living_reward`, no `notifications_*`, no
/// `automap_render_objects_as_sprites`); the wheel is the 1.3.2 truth.
const KEYS: [(&str, Slot); 61] = [
    ("available_buttons", Slot::Buttons),
    ("available_game_variables", Slot::GameVariables),
    ("game_args", Slot::GameArgs),
    // Integers.
    ("seed", Slot::Seed),
    ("episode_timeout", Slot::Uint(|c| &mut c.episode_timeout)),
    ("episode_start_time", Slot::Uint(|c| &mut c.episode_start_time)),
    ("doom_skill", Slot::Uint(|c| &mut c.doom_skill)),
    ("ticrate", Slot::Uint(|c| &mut c.ticrate)),
    ("audio_buffer_size", Slot::AudioTics),
    ("notifications_buffer_size", Slot::Uint(|c| &mut c.outputs.notifications_buffer_size)),
    // Rewards.
    ("living_reward", Slot::Float(|c| &mut c.rewards.living)),
    ("death_penalty", Slot::Float(|c| &mut c.rewards.death_penalty)),
    ("death_reward", Slot::NegatedFloat(|c| &mut c.rewards.death_penalty)),
    ("map_exit_reward", Slot::Float(|c| &mut c.rewards.map_exit)),
    ("kill_reward", Slot::Float(|c| &mut c.rewards.kill)),
    ("item_reward", Slot::Float(|c| &mut c.rewards.item)),
    ("secret_reward", Slot::Float(|c| &mut c.rewards.secret)),
    ("frag_reward", Slot::Float(|c| &mut c.rewards.frag)),
    ("hit_reward", Slot::Float(|c| &mut c.rewards.hit)),
    ("hit_taken_penalty", Slot::Float(|c| &mut c.rewards.hit_taken_penalty)),
    ("hit_taken_reward", Slot::NegatedFloat(|c| &mut c.rewards.hit_taken_penalty)),
    ("damage_made_reward", Slot::Float(|c| &mut c.rewards.damage_made)),
    ("damage_taken_penalty", Slot::Float(|c| &mut c.rewards.damage_taken_penalty)),
    ("damage_taken_reward", Slot::NegatedFloat(|c| &mut c.rewards.damage_taken_penalty)),
    ("health_reward", Slot::Float(|c| &mut c.rewards.health)),
    ("armor_reward", Slot::Float(|c| &mut c.rewards.armor)),
    // Strings and paths.
    ("doom_map", Slot::Map),
    ("vizdoom_path", Slot::Path(|c| &mut c.vizdoom_path)),
    ("doom_game_path", Slot::Path(|c| &mut c.doom_game_path)),
    ("doom_scenario_path", Slot::Path(|c| &mut c.doom_scenario_path)),
    ("doom_config_path", Slot::Path(|c| &mut c.doom_config_path)),
    // Booleans.
    ("depth_buffer_enabled", Slot::Bool(|c| &mut c.outputs.depth_buffer)),
    ("labels_buffer_enabled", Slot::Bool(|c| &mut c.outputs.labels_buffer)),
    ("automap_buffer_enabled", Slot::Bool(|c| &mut c.outputs.automap_buffer)),
    ("automap_rotate", Slot::Bool(|c| &mut c.automap.rotate)),
    ("automap_render_textures", Slot::Bool(|c| &mut c.automap.render_textures)),
    ("automap_render_objects_as_sprites", Slot::Bool(|c| &mut c.automap.render_objects_as_sprites)),
    ("objects_info_enabled", Slot::Bool(|c| &mut c.outputs.objects_info)),
    ("sectors_info_enabled", Slot::Bool(|c| &mut c.outputs.sectors_info)),
    ("render_hud", Slot::Bool(|c| &mut c.render.hud)),
    ("render_minimal_hud", Slot::Bool(|c| &mut c.render.minimal_hud)),
    ("render_weapon", Slot::Bool(|c| &mut c.render.weapon)),
    ("render_crosshair", Slot::Bool(|c| &mut c.render.crosshair)),
    ("render_decals", Slot::Bool(|c| &mut c.render.decals)),
    ("render_particles", Slot::Bool(|c| &mut c.render.particles)),
    ("render_effects_sprites", Slot::Bool(|c| &mut c.render.effects_sprites)),
    ("render_messages", Slot::Bool(|c| &mut c.render.messages)),
    ("render_corpses", Slot::Bool(|c| &mut c.render.corpses)),
    ("render_screen_flashes", Slot::Bool(|c| &mut c.render.screen_flashes)),
    ("render_all_frames", Slot::Bool(|c| &mut c.render.all_frames)),
    ("window_visible", Slot::Bool(|c| &mut c.window_visible)),
    ("console_enabled", Slot::Bool(|c| &mut c.console_enabled)),
    ("sound_enabled", Slot::Bool(|c| &mut c.sound_enabled)),
    ("audio_buffer_enabled", Slot::Bool(|c| &mut c.outputs.audio_buffer)),
    ("notifications_buffer_enabled", Slot::Bool(|c| &mut c.outputs.notifications_buffer)),
    // Names.
    ("mode", Slot::Mode),
    ("automap_mode", Slot::AutomapMode),
    ("screen_resolution", Slot::Resolution),
    ("screen_format", Slot::Format),
    ("audio_sampling_rate", Slot::SamplingRate),
    ("button_max_value", Slot::ButtonMaxValue),
];

/// Every key's snake-case name, for callers that list them.
pub fn key_names() -> impl Iterator<Item = &'static str> {
    KEYS.iter().map(|(name, _)| *name)
}

#[cfg(test)]
#[path = "cfg_tests.rs"]
mod tests;
