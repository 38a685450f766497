//! The player's settings, kept between runs in
//! `$XDG_CONFIG_HOME/sightline/config.ron` (else `~/.config/sightline/`):
//! controls and key bindings, sound, video and gameplay. Read at start;
//! command-line flags override it for that run; what the player changes in
//! the game (volumes, status bar, HUD, full screen) is written back at exit.
//!
//! A file that is partly wrong is never fatal: each bad key (unknown, of the
//! wrong type, out of range) is one warning naming the file, the line and
//! the key; the good keys are kept and the rest take their defaults. A file
//! that cannot be read or parsed at all gives one warning and the defaults.
//! Either way the file is copied to `config.ron.bak` before the game first
//! writes over it, and every write goes to a temporary file renamed over
//! the old one, so a failed write leaves the old file whole.

use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use ron::Value;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use winit::keyboard::KeyCode;

use crate::play::gamepad::{default_buttons, PadMap, BUTTONS};
use crate::play::input::{Bind, BINDS};

/// Every setting, in the file's sections.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Config {
    pub controls: Controls,
    pub gamepad: Gamepad,
    pub sound: Sound,
    pub video: Video,
    pub gameplay: Gameplay,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Controls {
    /// Degrees of turn per mouse count.
    pub mouse_sensitivity: f32,
    /// Mouse right turns left.
    pub invert_mouse: bool,
    /// Run without holding the run key (holding it then walks).
    pub always_run: bool,
    /// Each action's keys (winit's `KeyCode` names: `KeyW`, `ArrowUp`,
    /// `ShiftLeft`, `Digit1`, `F11`, ...), at most two each.
    pub keys: BTreeMap<String, Vec<String>>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Gamepad {
    /// Read gamepads at all.
    pub enabled: bool,
    /// Stick positions nearer the centre than this (0 to 0.9) are centred.
    pub dead_zone: f32,
    /// Degrees per tick of turn with the right stick fully over (0.5 to 20).
    pub turn_speed: f32,
    /// Each button's action (`South`, `East`, `West`, `North`,
    /// `LeftShoulder`, `RightShoulder`, `LeftTrigger`, `RightTrigger`,
    /// `Select`, `Start`, `LeftStick`, `RightStick`, `DpadUp`, ...), by the
    /// action names of `controls.keys`.
    pub buttons: BTreeMap<String, String>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Sound {
    /// 0 to 100.
    pub effects_volume: u8,
    /// 0 to 100.
    pub music_volume: u8,
    /// Sounds played at once, 1 to 64 (Doom's `snd_channels`: 8).
    pub channels: u16,
    /// The General MIDI SoundFont music is played with (None: Debian's).
    pub soundfont: Option<PathBuf>,
    pub music: bool,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Video {
    pub fullscreen: bool,
    /// The window's inner size (None: the frame times the largest whole
    /// factor that fits the screen).
    pub window: Option<(u32, u32)>,
    /// The internal frame size.
    pub size: (u32, u32),
    /// `bsp`, `reference`, `raycast`, `painter` or `zbuffer` (None: the
    /// map's default).
    pub renderer: Option<String>,
    pub vsync: bool,
    /// Doom's status bar (false: the minimal full-screen HUD).
    pub status_bar: bool,
    /// The HUD's extra lines (frame time, messages).
    pub hud: bool,
    /// Threads drawing each frame (0: one per core).
    pub threads: usize,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Gameplay {
    /// Doom's vertical autoaim for hitscan and missiles.
    pub autoaim: bool,
}

impl Default for Config {
    fn default() -> Config {
        let keys = BINDS
            .iter()
            .map(|(name, _, keys)| (name.to_string(), keys.iter().map(|k| key_name(*k)).collect()))
            .collect();
        Config {
            controls: Controls { mouse_sensitivity: 0.15, invert_mouse: false, always_run: false, keys },
            gamepad: Gamepad { enabled: true, dead_zone: 0.2, turn_speed: 7.0, buttons: default_buttons() },
            sound: Sound { effects_volume: 80, music_volume: 60, channels: 8, soundfont: None, music: true },
            video: Video {
                fullscreen: false,
                window: None,
                size: (640, 400),
                renderer: None,
                vsync: true,
                status_bar: true,
                hud: true,
                threads: 0,
            },
            gameplay: Gameplay { autoaim: true },
        }
    }
}

/// One thing wrong with the file: where and what.
#[derive(Clone, Debug, PartialEq)]
pub struct Warning {
    pub file: PathBuf,
    /// 1-based; 0 when the whole file is meant.
    pub line: usize,
    /// `section.key`, or empty for the whole file.
    pub key: String,
    pub message: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, self.key.is_empty()) {
            (0, true) => write!(f, "{}: {}", self.file.display(), self.message),
            (0, false) => write!(f, "{}: `{}`: {}", self.file.display(), self.key, self.message),
            (line, _) => write!(f, "{}:{line}: `{}`: {}", self.file.display(), self.key, self.message),
        }
    }
}

/// The config file's path: `$XDG_CONFIG_HOME/sightline/config.ron`, else
/// `$HOME/.config/sightline/config.ron` (None without either).
pub fn default_path() -> Option<PathBuf> {
    let var = |v: &str| std::env::var_os(v).filter(|s| !s.is_empty()).map(PathBuf::from);
    let base = var("XDG_CONFIG_HOME").or_else(|| var("HOME").map(|h| h.join(".config")))?;
    Some(base.join("sightline").join("config.ron"))
}

/// A loaded config and what was wrong with its file.
pub struct Loaded {
    pub config: Config,
    pub warnings: Vec<Warning>,
    /// The file exists but was not wholly good: back it up before writing.
    pub needs_backup: bool,
}

/// Reads `path`: a missing file is the defaults and no warning.
pub fn load(path: &Path) -> Loaded {
    let whole = |message: String| Loaded {
        config: Config::default(),
        warnings: vec![Warning { file: path.to_path_buf(), line: 0, key: String::new(), message }],
        needs_backup: true,
    };
    let text = match std::fs::read(path) {
        Ok(bytes) => match String::from_utf8(bytes) {
            Ok(text) => text,
            Err(_) => return whole("not UTF-8 text; using the default settings".into()),
        },
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Loaded { config: Config::default(), warnings: Vec::new(), needs_backup: false }
        }
        Err(e) => return whole(format!("cannot be read ({e}); using the default settings")),
    };
    parse(&text, path)
}

/// Parses a config file's text, keeping every good key.
pub fn parse(text: &str, path: &Path) -> Loaded {
    let mut reader = Reader { text, file: path, config: Config::default(), warnings: Vec::new() };
    match ron::from_str::<Value>(text) {
        Ok(Value::Map(top)) => reader.top(top),
        Ok(_) => reader.warn(1, "", "the file is not a settings table `( controls: (...), sound: (...), ... )`"),
        Err(e) => {
            let message = format!("{} (at column {}); using the default settings", e.code, e.span.start.col);
            reader.warnings.push(Warning {
                file: path.to_path_buf(),
                line: e.span.start.line,
                key: String::new(),
                message,
            });
        }
    }
    // The parsed table is sorted by name: give the warnings in the file's order.
    reader.warnings.sort_by_key(|w| w.line);
    let needs_backup = !reader.warnings.is_empty();
    Loaded { config: reader.config, warnings: reader.warnings, needs_backup }
}

struct Reader<'a> {
    text: &'a str,
    file: &'a Path,
    config: Config,
    warnings: Vec<Warning>,
}

const SECTIONS: &[(&str, &[&str])] = &[
    ("controls", &["mouse_sensitivity", "invert_mouse", "always_run", "keys"]),
    ("gamepad", &["enabled", "dead_zone", "turn_speed", "buttons"]),
    ("sound", &["effects_volume", "music_volume", "channels", "soundfont", "music"]),
    ("video", &["fullscreen", "window", "size", "renderer", "vsync", "status_bar", "hud", "threads"]),
    ("gameplay", &["autoaim"]),
];

impl Reader<'_> {
    fn warn(&mut self, line: usize, key: &str, message: impl Into<String>) {
        let message = message.into();
        self.warnings.push(Warning { file: self.file.to_path_buf(), line, key: key.into(), message });
    }

    fn top(&mut self, top: ron::Map) {
        for (name, value) in top {
            let Value::String(section) = name else {
                self.warn(1, "", format!("a section name must be a word, not {name:?}"));
                continue;
            };
            let Some(&(_, keys)) = SECTIONS.iter().find(|(s, _)| *s == section) else {
                let known: Vec<_> = SECTIONS.iter().map(|(s, _)| *s).collect();
                let line = line_of(self.text, None, &section);
                self.warn(line, &section, format!("unknown section (known: {})", known.join(", ")));
                continue;
            };
            let Value::Map(entries) = value else {
                let line = line_of(self.text, None, &section);
                self.warn(line, &section, "a section is a table `( key: value, ... )`");
                continue;
            };
            for (key, value) in entries {
                let Value::String(key) = key else { continue };
                let dotted = format!("{section}.{key}");
                let line = line_of(self.text, Some(&section), &key);
                if !keys.contains(&key.as_str()) {
                    self.warn(line, &dotted, format!("unknown key (known in `{section}`: {})", keys.join(", ")));
                    continue;
                }
                if let Err(message) = self.set(&section, &key, value) {
                    self.warn(line, &dotted, format!("{message}; kept the default"));
                }
            }
        }
    }

    /// Sets one key from its value, or says what is wrong with it.
    fn set(&mut self, section: &str, key: &str, value: Value) -> Result<(), String> {
        let c = &mut self.config;
        match (section, key) {
            ("controls", "mouse_sensitivity") => {
                c.controls.mouse_sensitivity = ranged(value, 0.0, 10.0, "a number from 0 to 10")?
            }
            ("controls", "invert_mouse") => c.controls.invert_mouse = typed(value, "true or false")?,
            ("controls", "always_run") => c.controls.always_run = typed(value, "true or false")?,
            ("controls", "keys") => {
                let keys: BTreeMap<String, Vec<String>> = typed(value, "a map of action names to lists of key names")?;
                let mut bad = Vec::new();
                let mut given = BTreeMap::new();
                for (action, names) in keys {
                    match check_binding(&action, &names) {
                        Ok(()) => {
                            given.insert(action, names);
                        }
                        Err(e) => bad.push(e),
                    }
                }
                // A key the file binds leaves the default of any action the
                // file does not name (W bound to fire no longer walks).
                for (action, names) in c.controls.keys.iter_mut() {
                    if !given.contains_key(action) {
                        names.retain(|k| !given.values().flatten().any(|g| g == k));
                    }
                }
                c.controls.keys.extend(given);
                if !bad.is_empty() {
                    let line = line_of(self.text, Some(section), key);
                    for e in bad {
                        self.warn(line, "controls.keys", format!("{e}; kept its default keys"));
                    }
                }
            }
            ("gamepad", "enabled") => c.gamepad.enabled = typed(value, "true or false")?,
            ("gamepad", "dead_zone") => c.gamepad.dead_zone = ranged(value, 0.0, 0.9, "a number from 0 to 0.9")?,
            ("gamepad", "turn_speed") => c.gamepad.turn_speed = ranged(value, 0.5, 20.0, "a number from 0.5 to 20")?,
            ("gamepad", "buttons") => {
                let buttons: BTreeMap<String, String> = typed(value, "a map of button names to action names")?;
                let line = line_of(self.text, Some(section), key);
                for (button, action) in buttons {
                    if !BUTTONS.iter().any(|(n, _)| *n == button) {
                        let known: Vec<_> = BUTTONS.iter().map(|(n, _)| *n).collect();
                        let message = format!("unknown button `{button}` (known: {})", known.join(", "));
                        self.warn(line, "gamepad.buttons", message);
                    } else if !BINDS.iter().any(|(n, _, _)| *n == action) {
                        self.warn(line, "gamepad.buttons", format!("`{button}`: unknown action `{action}`"));
                    } else {
                        self.config.gamepad.buttons.insert(button, action);
                    }
                }
            }
            ("sound", "effects_volume") => c.sound.effects_volume = ranged(value, 0, 100, "a whole number 0 to 100")?,
            ("sound", "music_volume") => c.sound.music_volume = ranged(value, 0, 100, "a whole number 0 to 100")?,
            ("sound", "channels") => c.sound.channels = ranged(value, 1, 64, "a whole number 1 to 64")?,
            ("sound", "soundfont") => c.sound.soundfont = typed(value, "None or Some(\"path.sf2\")")?,
            ("sound", "music") => c.sound.music = typed(value, "true or false")?,
            ("video", "fullscreen") => c.video.fullscreen = typed(value, "true or false")?,
            ("video", "window") => {
                let window: Option<(u32, u32)> = typed(value, "None or Some((width, height))")?;
                c.video.window = window.map(|s| sized(s, 16_384)).transpose()?;
            }
            ("video", "size") => c.video.size = sized(typed(value, "(width, height)")?, 8192)?,
            ("video", "renderer") => {
                let name: Option<String> = typed(value, "None or Some(\"bsp\")")?;
                if let Some(name) = &name {
                    crate::cli::parse_renderer(name)?;
                }
                c.video.renderer = name;
            }
            ("video", "vsync") => c.video.vsync = typed(value, "true or false")?,
            ("video", "status_bar") => c.video.status_bar = typed(value, "true or false")?,
            ("video", "hud") => c.video.hud = typed(value, "true or false")?,
            ("video", "threads") => {
                c.video.threads = ranged(value, 0, crate::cli::MAX_THREADS, "a whole number 0 (one per core) to 64")?
            }
            ("gameplay", "autoaim") => c.gameplay.autoaim = typed(value, "true or false")?,
            _ => unreachable!("every key of SECTIONS is set"),
        }
        Ok(())
    }
}

fn typed<T: DeserializeOwned>(value: Value, expected: &str) -> Result<T, String> {
    let shown = ron::to_string(&value).unwrap_or_else(|_| format!("{value:?}"));
    value.into_rust::<T>().map_err(|_| format!("expected {expected}, found `{shown}`"))
}

fn ranged<T: DeserializeOwned + PartialOrd + fmt::Display + Copy>(
    value: Value,
    min: T,
    max: T,
    expected: &str,
) -> Result<T, String> {
    let v: T = typed(value, expected)?;
    if v < min || v > max {
        return Err(format!("{v} is out of range (expected {expected})"));
    }
    Ok(v)
}

fn sized((w, h): (u32, u32), max: u32) -> Result<(u32, u32), String> {
    if w == 0 || h == 0 || w > max || h > max {
        return Err(format!("{w}x{h} is out of range (1 to {max} each way)"));
    }
    Ok((w, h))
}

/// Whether `action` is a bindable action and `names` one or two keys.
fn check_binding(action: &str, names: &[String]) -> Result<(), String> {
    if !BINDS.iter().any(|(name, _, _)| *name == action) {
        return Err(format!("unknown action `{action}`"));
    }
    if names.len() > 2 {
        return Err(format!("`{action}` has {} keys; at most two", names.len()));
    }
    for name in names {
        parse_key(name).ok_or_else(|| {
            format!("`{action}`: unknown key `{name}` (winit's KeyCode names: KeyW, ArrowUp, ShiftLeft, ...)")
        })?;
    }
    Ok(())
}

/// A key from winit's `KeyCode` variant name.
pub fn parse_key(name: &str) -> Option<KeyCode> {
    let word = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric());
    word.then(|| ron::from_str::<KeyCode>(name).ok()).flatten()
}

/// A key's name in the file.
pub fn key_name(key: KeyCode) -> String {
    ron::to_string(&key).unwrap_or_else(|_| format!("{key:?}"))
}

/// The line of `key` in `text`: its first `key:` (or `"key":`) from the
/// first line with `section:` on (1 if not found).
fn line_of(text: &str, section: Option<&str>, key: &str) -> usize {
    let has = |line: &str, name: &str| {
        line.split(['(', ',', '{']).any(|part| {
            let part = part.trim_start();
            let quoted = format!("\"{name}\"");
            let rest = part.strip_prefix(quoted.as_str()).or_else(|| part.strip_prefix(name));
            rest.is_some_and(|r| r.trim_start().starts_with(':'))
        })
    };
    let lines: Vec<&str> = text.lines().collect();
    let from = section.and_then(|s| lines.iter().position(|l| has(l, s))).unwrap_or(0);
    lines[from..].iter().position(|l| has(l, key)).map_or(1, |i| from + i + 1)
}

impl Config {
    /// The file's text: a commented header, then the settings.
    pub fn to_text(&self) -> String {
        let pretty = ron::ser::PrettyConfig::new().depth_limit(3).struct_names(false);
        let body = ron::ser::to_string_pretty(self, pretty).expect("settings serialize");
        format!(
            "// Sightline's settings, read at start and written at exit when the game changes them.\n\
             // Command-line flags override them for one run. Keys: `sightline --help` and the README.\n\
             {body}\n"
        )
    }

    /// Writes the settings to `path` atomically (a temporary file in the
    /// same directory renamed over it); with `backup`, an existing file is
    /// first copied to `NAME.bak`.
    pub fn save(&self, path: &Path, backup: bool) -> Result<()> {
        let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
        std::fs::create_dir_all(dir).with_context(|| format!("cannot make {}", dir.display()))?;
        if backup && path.exists() {
            let mut bak = path.as_os_str().to_owned();
            bak.push(".bak");
            std::fs::copy(path, &bak)
                .with_context(|| format!("cannot back up {} before writing it", path.display()))?;
        }
        let mut tmp = path.as_os_str().to_owned();
        tmp.push(".tmp");
        let tmp = PathBuf::from(tmp);
        std::fs::write(&tmp, self.to_text()).with_context(|| format!("cannot write {}", tmp.display()))?;
        std::fs::rename(&tmp, path).with_context(|| format!("cannot replace {}", path.display())).inspect_err(|_| {
            let _ = std::fs::remove_file(&tmp);
        })
    }

    /// What the gamepad's buttons and sticks do.
    pub fn pad_map(&self) -> PadMap {
        let g = &self.gamepad;
        PadMap::of(g.buttons.iter().map(|(b, a)| (b.as_str(), a.as_str())), g.dead_zone, g.turn_speed)
    }

    /// Each bound key and what it does.
    pub fn bindings(&self) -> Vec<(KeyCode, Bind)> {
        let mut out = Vec::new();
        for (name, bind, _) in BINDS {
            for key in self.controls.keys.get(*name).into_iter().flatten() {
                if let Some(key) = parse_key(key) {
                    out.push((key, *bind));
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests;
