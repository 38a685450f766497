//! The window's side of the menus (`sightline::screen::menu`): the settings
//! file's values in and out of the menu's [`Settings`], the named save
//! slots on disk, and the window's keys and mouse as menu [`Command`]s (a
//! gamepad's cross, buttons and left stick send the same commands).
//!
//! A named slot is `slotN.slsave` (the save format, unchanged) with two
//! files beside it: `slotN.name` (the name typed, UTF-8) and `slotN.png`
//! (a 160x100 picture of the game). A save made before names existed, or by
//! F2, shows as `Slot N` with no picture; map, time and skill come from the
//! save's own description (`sightline::play::save::peek`).

use std::path::Path;

use sightline::play::save::peek;
use sightline::screen::menu::{Binding, Command, Menu, Settings, Setup, SlotInfo, SLOTS};
use sightline::Framebuffer;
use winit::keyboard::KeyCode;

use super::input::BINDS;
use super::saves::{self, Slot};
use crate::config::{key_name, Config};

/// The menu and whether it is showing; `title`: no game has started yet
/// (the title picture is behind the menu, and closing it is refused).
pub struct Front {
    pub menu: Menu,
    pub open: bool,
    pub title: bool,
    /// Where the pointer was last seen: the first position reported (a
    /// window opening under a still mouse) chooses nothing, only motion does.
    pub pointer: Option<(f64, f64)>,
    /// The pad's left stick, as the menu reads it.
    pub stick: Stick,
}

impl Front {
    pub fn new(config: &Config, title: bool, episodes: Vec<String>, save_dir: &Path) -> Front {
        let setup = Setup { episodes, slots: slots(save_dir), in_game: !title };
        Front {
            menu: Menu::new(settings_of(config), setup),
            open: title,
            title,
            pointer: None,
            stick: Stick::default(),
        }
    }
}

/// The menu's view of the settings.
pub fn settings_of(config: &Config) -> Settings {
    let bindings = BINDS
        .iter()
        .map(|(name, _, _)| Binding {
            action: name.to_string(),
            keys: config.controls.keys.get(*name).cloned().unwrap_or_default(),
        })
        .collect();
    Settings {
        mouse_sensitivity: config.controls.mouse_sensitivity,
        always_run: config.controls.always_run,
        effects_volume: config.sound.effects_volume,
        music_volume: config.sound.music_volume,
        status_bar: config.video.status_bar,
        hud: config.video.hud,
        fullscreen: config.video.fullscreen,
        autoaim: config.gameplay.autoaim,
        bindings,
    }
}

/// The controls of `settings` written into `config` (the rest is written
/// back through `Changeable`, as the keys outside the menu change them).
pub fn controls_into(settings: &Settings, config: &mut Config) {
    config.controls.mouse_sensitivity = settings.mouse_sensitivity;
    config.controls.always_run = settings.always_run;
    config.gameplay.autoaim = settings.autoaim;
    for b in &settings.bindings {
        config.controls.keys.insert(b.action.clone(), b.keys.clone());
    }
}

/// The slots' particulars (None: empty, or not a save this build reads).
pub fn slots(dir: &Path) -> Vec<Option<SlotInfo>> {
    (0..SLOTS)
        .map(|n| {
            let path = saves::path(dir, Slot::Numbered(n as u8 + 1));
            let info = peek(&path).ok()?;
            let name = std::fs::read_to_string(path.with_extension("name"))
                .map(|s| s.trim().to_string())
                .ok()
                .filter(|s| !s.is_empty())
                .unwrap_or_else(|| format!("Slot {}", n + 1));
            Some(SlotInfo {
                name,
                map: info.map.short_name(),
                seconds: info.playthrough_ticks / u64::from(sightline::play::TICRATE),
                skill: info.options.skill,
                thumbnail: Framebuffer::read_png(&path.with_extension("png")).ok(),
            })
        })
        .collect()
}

/// Writes the name and picture of the save just made in slot `n` (0-based).
pub fn label_slot(dir: &Path, n: usize, name: &str, fb: &Framebuffer) -> anyhow::Result<()> {
    let path = saves::path(dir, Slot::Numbered(n as u8 + 1));
    std::fs::write(path.with_extension("name"), name)?;
    std::fs::write(path.with_extension("png"), thumbnail(fb, 160, 100).to_png())?;
    Ok(())
}

/// `fb` shrunk to `w` by `h` (each pixel the average of its box).
fn thumbnail(fb: &Framebuffer, w: usize, h: usize) -> Framebuffer {
    let mut out = Framebuffer::new(w, h);
    for y in 0..h {
        for x in 0..w {
            let (x0, x1) = (x * fb.width / w, ((x + 1) * fb.width / w).max(x * fb.width / w + 1));
            let (y0, y1) = (y * fb.height / h, ((y + 1) * fb.height / h).max(y * fb.height / h + 1));
            let mut sum = [0u32; 3];
            let mut n = 0;
            for yy in y0..y1.min(fb.height) {
                for xx in x0..x1.min(fb.width) {
                    let c = fb.pixels[yy * fb.width + xx].to_le_bytes();
                    for i in 0..3 {
                        sum[i] += u32::from(c[i]);
                    }
                    n += 1;
                }
            }
            let n = n.max(1);
            out.pixels[y * w + x] =
                sightline::framebuffer::rgb((sum[0] / n) as u8, (sum[1] / n) as u8, (sum[2] / n) as u8);
        }
    }
    out
}

/// A key pressed while the menu shows, as its command: arrows (and the
/// keypad's) move, Enter chooses, Esc goes back, Backspace erases; other
/// keys type their text on the name page and bind on the key page.
pub fn command(menu: &Menu, key: KeyCode, text: Option<&str>) -> Option<Command> {
    use KeyCode::*;
    if menu.wants_key() {
        return Some(if key == Escape { Command::Back } else { Command::Key(key_name(key)) });
    }
    let typed = text.and_then(|t| t.chars().next()).filter(|c| !c.is_control());
    Some(match key {
        ArrowUp | Numpad8 => Command::Up,
        ArrowDown | Numpad2 => Command::Down,
        ArrowLeft | Numpad4 => Command::Left,
        ArrowRight | Numpad6 => Command::Right,
        Enter | NumpadEnter => Command::Select,
        Space if !menu.wants_text() => Command::Select,
        Escape => Command::Back,
        Backspace | Delete => Command::Erase,
        _ => Command::Text(typed?),
    })
}

/// A gamepad's button pressed, as a menu command: the pad's cross moves,
/// A (south) chooses, B (east) or Start goes back, Y (north) erases.
/// (Start while playing opens the menu: the app's side.)
pub fn pad_command(event: &super::gamepad::PadEvent) -> Option<Command> {
    use super::gamepad::{PadButton as B, PadEvent};
    let PadEvent::Button { button, down: true } = event else { return None };
    Some(match button {
        B::DpadUp => Command::Up,
        B::DpadDown => Command::Down,
        B::DpadLeft => Command::Left,
        B::DpadRight => Command::Right,
        B::South => Command::Select,
        B::East | B::Start => Command::Back,
        B::North => Command::Erase,
        _ => return None,
    })
}

/// The left stick in the menus: pushed past half way it moves the cursor
/// once, as the pad's cross does; it must come back inside a third of the
/// way before it moves again.
#[derive(Clone, Copy, Debug, Default)]
pub struct Stick {
    /// Where each axis (x, y) points now: -1, 0 or 1.
    at: [i8; 2],
}

impl Stick {
    const PUSHED: f32 = 0.5;
    const CENTRED: f32 = 0.3;

    /// A pad event as a menu command: a button's (see [`pad_command`]), or
    /// the left stick newly pushed up, down, left or right.
    pub fn command(&mut self, event: &super::gamepad::PadEvent) -> Option<Command> {
        use super::gamepad::{PadAxis, PadEvent};
        let PadEvent::Axis { axis, value } = *event else { return pad_command(event) };
        let i = match axis {
            PadAxis::LeftX => 0,
            PadAxis::LeftY => 1,
            PadAxis::RightX | PadAxis::RightY => return None,
        };
        let was = self.at[i];
        let now = if value >= Self::PUSHED {
            1
        } else if value <= -Self::PUSHED {
            -1
        } else if value.abs() < Self::CENTRED {
            0
        } else {
            was
        };
        self.at[i] = now;
        if now == was || now == 0 {
            return None;
        }
        // Up is negative on the pad's Y axis.
        Some(match (i, now) {
            (0, -1) => Command::Left,
            (0, _) => Command::Right,
            (_, -1) => Command::Up,
            _ => Command::Down,
        })
    }
}

/// The episodes of a WAD (`E1M1` to `E4M1` where present; none for Doom
/// II's `MAPxx` or a RON map).
pub fn episodes(map: &sightline::campaign::MapRef) -> Vec<String> {
    let sightline::campaign::MapRef::Wad { wads, .. } = map else { return Vec::new() };
    let Some(names) = wads.iter().map(|w| sightline::wad::Wad::open(w).ok()).collect::<Option<Vec<_>>>() else {
        return Vec::new();
    };
    (1..=4)
        .filter(|e| names.iter().any(|w| w.find(&format!("E{e}M1")).is_some()))
        .map(|e| format!("Episode {e}"))
        .collect()
}

/// The map a new game on episode `n` (0-based) starts on.
pub fn first_map(map: &sightline::campaign::MapRef, episodes: &[String], n: usize) -> sightline::campaign::MapRef {
    match episodes.get(n).and_then(|e| e.strip_prefix("Episode ")) {
        Some(e) => map.in_same_wads(&format!("E{e}M1")),
        None => map.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sightline::screen::menu::Event;

    #[test]
    fn keys_become_menu_commands() {
        let menu = Menu::new(settings_of(&Config::default()), Setup::default());
        assert_eq!(command(&menu, KeyCode::ArrowUp, None), Some(Command::Up));
        assert_eq!(command(&menu, KeyCode::Enter, None), Some(Command::Select));
        assert_eq!(command(&menu, KeyCode::Escape, None), Some(Command::Back));
        assert_eq!(command(&menu, KeyCode::KeyY, Some("y")), Some(Command::Text('y')));
        assert_eq!(command(&menu, KeyCode::F5, None), None);
        use crate::play::gamepad::{PadButton, PadEvent};
        let press = |button| PadEvent::Button { button, down: true };
        assert_eq!(pad_command(&press(PadButton::DpadDown)), Some(Command::Down));
        assert_eq!(pad_command(&press(PadButton::South)), Some(Command::Select));
        assert_eq!(pad_command(&PadEvent::Button { button: PadButton::South, down: false }), None);
    }

    /// The stick moves the cursor once per push, and buttons still work.
    #[test]
    fn the_left_stick_moves_the_cursor_once_per_push() {
        use crate::play::gamepad::{PadAxis, PadButton, PadEvent};
        let mut stick = Stick::default();
        let y = |value| PadEvent::Axis { axis: PadAxis::LeftY, value };
        let x = |value| PadEvent::Axis { axis: PadAxis::LeftX, value };
        let moves: Vec<_> = [y(0.2), y(0.6), y(0.9), y(0.4), y(0.7), y(0.1), y(0.8), y(-0.9), x(-0.6), x(0.0), x(0.55)]
            .iter()
            .filter_map(|e| stick.command(e))
            .collect();
        assert_eq!(moves, [Command::Down, Command::Down, Command::Up, Command::Left, Command::Right]);
        let rx = PadEvent::Axis { axis: PadAxis::RightX, value: 1.0 };
        assert_eq!(stick.command(&rx), None, "the right stick is not the menu's");
        let a = PadEvent::Button { button: PadButton::South, down: true };
        assert_eq!(stick.command(&a), Some(Command::Select));
    }

    /// A key rebound in the menu reaches the keymap the game reads, and the
    /// settings file keeps it.
    #[test]
    fn a_rebound_key_drives_the_game_and_is_kept() {
        let mut menu = Menu::new(settings_of(&Config::default()), Setup::default());
        for c in [Command::Down, Command::Select, Command::Select, Command::Select, Command::Select] {
            menu.command(c);
        }
        assert!(menu.wants_key());
        let bind = command(&menu, KeyCode::KeyI, Some("i")).expect("a command");
        assert!(menu.command(bind).contains(&Event::Settings));
        let mut config = Config::default();
        controls_into(&menu.settings, &mut config);
        assert_eq!(config.controls.keys["forward"], ["KeyI", "KeyW"]);
        let keys = crate::play::input::Keymap::of(&config.bindings());
        let forward = BINDS.iter().find(|b| b.0 == "forward").map(|b| b.1);
        assert_eq!(keys.get(KeyCode::KeyI), forward);
        assert_eq!(keys.get(KeyCode::ArrowUp), None, "its old second key is free");
        assert_eq!(settings_of(&config), menu.settings);
    }

    #[test]
    fn a_named_slot_shows_its_name_and_picture() {
        let dir = std::env::temp_dir().join(format!("sightline-menus-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let map = sightline::campaign::MapRef::File(crate::capture::default_map_path());
        let play = sightline::play::playthrough::Playthrough::of(&map, sightline::play::GameOptions::default())
            .expect("the default level opens");
        play.save(&saves::path(&dir, Slot::Numbered(2))).unwrap();
        let mut fb = Framebuffer::new(320, 200);
        fb.pixels.fill(sightline::framebuffer::rgb(200, 10, 10));
        label_slot(&dir, 1, "By the lift", &fb).unwrap();
        let slots = slots(&dir);
        assert!(slots[0].is_none() && slots[2].is_none());
        let slot = slots[1].as_ref().expect("slot 2 is filled");
        assert_eq!((slot.name.as_str(), slot.map.as_str(), slot.skill), ("By the lift", "outpost.ron", 3));
        let thumb = slot.thumbnail.as_ref().expect("a picture");
        assert_eq!((thumb.width, thumb.height, thumb.pixels[0]), (160, 100, sightline::framebuffer::rgb(200, 10, 10)));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
