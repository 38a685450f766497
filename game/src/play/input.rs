//! Keyboard and mouse to simulation input: which keys are held, presses that
//! must not be lost between ticks, mouse motion summed since the last tick;
//! once per tick they become one `TickInput`. Keys that act on the window
//! (HUD, automap, screenshot, ...) come back as `Action`s at once.

use std::collections::HashMap;

use sightline::play::TickInput;
use winit::keyboard::KeyCode;

use super::gamepad::{PadAxis, PadEvent, PadMap};

/// Keyboard turning, degrees per tick: Doom's `angleturn` of 640 (walking) and
/// 1280 (running) in 16.16 binary angles, 640 / 65536 * 360 = 3.5 degrees, so
/// the arrows turn 123 and 246 degrees per second at 35 Hz.
const TURN_WALK: f32 = 640.0 / 65536.0 * 360.0;
const TURN_RUN: f32 = 1280.0 / 65536.0 * 360.0;
/// A left stick pushed further than this (after the dead zone) runs.
const STICK_RUN: f32 = 0.8;

/// Something a key does to the window rather than to the player.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    Quit,
    ReleaseCursor,
    ToggleFullscreen,
    ToggleHud,
    ToggleAutomap,
    Screenshot,
    CycleRenderer,
    /// The status bar, or the minimal full-screen HUD (Doom's `-` and `=`).
    ToggleStatusBar,
    /// Doom's keys: F6 saves to the quick slot, F9 loads it; F2 and F3 ask
    /// for a slot (a digit) to save to or load from.
    QuickSave,
    QuickLoad,
    SaveSlot,
    LoadSlot,
    /// Effects' and music's volume down and up, a tenth at a time.
    EffectsVolume(i8),
    MusicVolume(i8),
}

/// Movement keys, as bits of `Controls::held` and `Controls::pressed`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Move {
    Forward = 1,
    Back = 2,
    StrafeLeft = 4,
    StrafeRight = 8,
    TurnLeft = 16,
    TurnRight = 32,
    Run = 64,
    Use = 128,
    Fire = 256,
}

/// What a bound key does: move the player, ask for a weapon, or act on
/// the window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bind {
    Move(Move),
    Weapon(u8),
    Window(Action),
}

/// Every bindable action: its name in the config file, what it does, and
/// its default keys (at most two).
pub const BINDS: &[(&str, Bind, &[KeyCode])] = {
    use Action::*;
    use Bind::{Move as M, Weapon as W, Window as A};
    use KeyCode::*;
    &[
        ("forward", M(Move::Forward), &[KeyW, ArrowUp]),
        ("back", M(Move::Back), &[KeyS, ArrowDown]),
        ("strafe_left", M(Move::StrafeLeft), &[KeyA]),
        ("strafe_right", M(Move::StrafeRight), &[KeyD]),
        ("turn_left", M(Move::TurnLeft), &[ArrowLeft]),
        ("turn_right", M(Move::TurnRight), &[ArrowRight]),
        ("run", M(Move::Run), &[ShiftLeft, ShiftRight]),
        ("use", M(Move::Use), &[KeyE, Space]),
        ("fire", M(Move::Fire), &[ControlLeft, KeyF]),
        ("weapon1", W(1), &[Digit1]),
        ("weapon2", W(2), &[Digit2]),
        ("weapon3", W(3), &[Digit3]),
        ("weapon4", W(4), &[Digit4]),
        ("weapon5", W(5), &[Digit5]),
        ("weapon6", W(6), &[Digit6]),
        ("weapon7", W(7), &[Digit7]),
        ("quit", A(Quit), &[KeyQ]),
        ("release_cursor", A(ReleaseCursor), &[Escape]),
        ("fullscreen", A(ToggleFullscreen), &[F11]),
        ("hud", A(ToggleHud), &[KeyH]),
        ("automap", A(ToggleAutomap), &[Tab]),
        ("screenshot", A(Screenshot), &[F12]),
        ("renderer", A(CycleRenderer), &[KeyR]),
        ("status_bar", A(ToggleStatusBar), &[Minus, Equal]),
        ("effects_down", A(EffectsVolume(-1)), &[BracketLeft]),
        ("effects_up", A(EffectsVolume(1)), &[BracketRight]),
        ("music_down", A(MusicVolume(-1)), &[PageDown]),
        ("music_up", A(MusicVolume(1)), &[PageUp]),
        ("quick_save", A(QuickSave), &[F6]),
        ("quick_load", A(QuickLoad), &[F9]),
        ("save_slot", A(SaveSlot), &[F2]),
        ("load_slot", A(LoadSlot), &[F3]),
    ]
};

/// Which key does what: the defaults of [`BINDS`], or a config's.
#[derive(Clone, Debug)]
pub struct Keymap(HashMap<KeyCode, Bind>);

impl Default for Keymap {
    fn default() -> Keymap {
        Keymap(BINDS.iter().flat_map(|(_, bind, keys)| keys.iter().map(move |k| (*k, *bind))).collect())
    }
}

impl Keymap {
    /// Each key's binding, the later of two bindings of one key winning.
    pub fn of(bindings: &[(KeyCode, Bind)]) -> Keymap {
        Keymap(bindings.iter().copied().collect())
    }

    pub fn get(&self, key: KeyCode) -> Option<Bind> {
        self.0.get(&key).copied()
    }

    /// The window action of a key event: fresh presses only (auto-repeat
    /// does not repeat actions).
    pub fn window_action(&self, key: KeyCode, down: bool, repeat: bool) -> Option<Action> {
        match self.get(key) {
            Some(Bind::Window(action)) if down && !repeat => Some(action),
            _ => None,
        }
    }
}

/// The digit of a number key, 0 to 9 (the top row and the keypad).
pub fn digit(key: KeyCode) -> Option<u8> {
    use KeyCode::*;
    let keys = [
        [Digit0, Numpad0],
        [Digit1, Numpad1],
        [Digit2, Numpad2],
        [Digit3, Numpad3],
        [Digit4, Numpad4],
        [Digit5, Numpad5],
        [Digit6, Numpad6],
        [Digit7, Numpad7],
        [Digit8, Numpad8],
        [Digit9, Numpad9],
    ];
    keys.iter().position(|k| k.contains(&key)).map(|d| d as u8)
}

/// How the keyboard and mouse are read: the keymap and the mouse's
/// settings.
#[derive(Clone, Debug)]
pub struct Settings {
    pub keys: Keymap,
    /// Degrees of turn per mouse count.
    pub sensitivity: f32,
    /// Mouse right turns left.
    pub invert_mouse: bool,
    /// Run unless the run key is held.
    pub always_run: bool,
    /// What the gamepad's buttons and sticks do.
    pub pad: PadMap,
}

impl Settings {
    /// Doom's keys and the given mouse sensitivity.
    #[cfg(test)]
    pub fn with_sensitivity(sensitivity: f32) -> Settings {
        Settings {
            keys: Keymap::default(),
            sensitivity,
            invert_mouse: false,
            always_run: false,
            pad: PadMap::default(),
        }
    }
}

pub struct Controls {
    settings: Settings,
    /// Movement keys down now.
    held: u16,
    /// Movement buttons of the gamepad down now (apart from the keys, so
    /// that letting go of one does not let go of the other).
    pad_held: u16,
    /// The sticks' positions, -1 to 1: left x, left y, right x, right y.
    sticks: [f32; 4],
    /// Movement keys pressed since the last tick, so a tap shorter than a
    /// tick (28.6 ms) still moves or uses once.
    pressed: u16,
    /// Mouse counts to the right since the last tick.
    mouse_dx: f64,
    /// The weapon number last pressed since the last tick (0: none).
    weapon: u8,
}

impl Controls {
    pub fn new(settings: Settings) -> Controls {
        Controls { settings, held: 0, pad_held: 0, sticks: [0.0; 4], pressed: 0, mouse_dx: 0.0, weapon: 0 }
    }

    /// The settings to change (from the menu's options).
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.settings
    }

    /// The keymap these controls read.
    #[cfg(test)]
    pub fn keys(&self) -> &Keymap {
        &self.settings.keys
    }

    /// A key went down (`down`) or up. Returns the window action of a fresh
    /// press (auto-repeat does not repeat actions).
    pub fn key(&mut self, key: KeyCode, down: bool, repeat: bool) -> Option<Action> {
        let bind = self.settings.keys.get(key)?;
        self.bound(bind, down && !repeat, down, false)
    }

    /// A bound key or button went down (`down`) or up: a weapon asked
    /// for, a move held (on the pad's bits if `pad`), or the window action
    /// of a fresh press (`fresh`).
    fn bound(&mut self, bind: Bind, fresh: bool, down: bool, pad: bool) -> Option<Action> {
        match bind {
            Bind::Weapon(slot) => {
                if down {
                    self.weapon = slot;
                }
                None
            }
            Bind::Move(m) => {
                let bit = m as u16;
                let held = if pad { &mut self.pad_held } else { &mut self.held };
                if down {
                    *held |= bit;
                    self.pressed |= bit;
                } else {
                    *held &= !bit;
                }
                None
            }
            Bind::Window(action) => fresh.then_some(action),
        }
    }

    /// A gamepad event: a button does what its binding says (as a key
    /// would), a stick moves. Returns the window action of a press.
    pub fn pad(&mut self, event: PadEvent) -> Option<Action> {
        match event {
            PadEvent::Axis { axis, value } => {
                let i = match axis {
                    PadAxis::LeftX => 0,
                    PadAxis::LeftY => 1,
                    PadAxis::RightX => 2,
                    PadAxis::RightY => 3,
                };
                self.sticks[i] = value;
                None
            }
            PadEvent::Button { button, down } => {
                let bind = self.settings.pad.get(button)?;
                self.bound(bind, down, down, true)
            }
        }
    }

    /// The left mouse button (fire) went down or up, while the cursor is grabbed.
    pub fn mouse_button(&mut self, down: bool) {
        self.bound(Bind::Move(Move::Fire), false, down, false);
    }

    /// Mouse motion while the cursor is grabbed.
    pub fn mouse(&mut self, dx: f64) {
        self.mouse_dx += dx;
    }

    /// Lets go of everything, e.g. when the window loses focus and would
    /// never hear the key-up.
    pub fn release_all(&mut self) {
        self.held = 0;
        self.pad_held = 0;
        self.sticks = [0.0; 4];
        self.pressed = 0;
        self.mouse_dx = 0.0;
    }

    /// The input for the next tick; clears what was latched for this one.
    pub fn tick_input(&mut self) -> TickInput {
        let on = |m: Move| (self.held | self.pad_held | self.pressed) & m as u16 != 0;
        let axis = |plus: Move, minus: Move| i8::from(on(plus)) - i8::from(on(minus));
        // The sticks: past the dead zone the left one walks (runs when
        // pushed most of the way) and the right one turns in proportion.
        let pad = &self.settings.pad;
        let [lx, ly, rx, _] = self.sticks.map(|v| pad.live(v));
        let stick = |v: f32| {
            if v > 0.0 {
                1
            } else if v < 0.0 {
                -1
            } else {
                0
            }
        };
        let stick_run = lx.abs().max(ly.abs()) > STICK_RUN;
        let run = (on(Move::Run) || stick_run) != self.settings.always_run;
        let keys_turn = f32::from(axis(Move::TurnLeft, Move::TurnRight)) * if run { TURN_RUN } else { TURN_WALK };
        let stick_turn = -rx * pad.turn_speed;
        // Mouse right turns clockwise, which is negative (angles grow
        // counter-clockwise).
        let sign = if self.settings.invert_mouse { 1.0 } else { -1.0 };
        let mouse_turn = sign * (self.mouse_dx as f32) * self.settings.sensitivity;
        let input = TickInput {
            forward: (axis(Move::Forward, Move::Back) - stick(ly)).clamp(-1, 1),
            strafe: (axis(Move::StrafeRight, Move::StrafeLeft) + stick(lx)).clamp(-1, 1),
            turn: keys_turn + mouse_turn + stick_turn,
            run,
            use_line: on(Move::Use),
            fire: on(Move::Fire),
            weapon: std::mem::take(&mut self.weapon),
        };
        self.pressed = 0;
        self.mouse_dx = 0.0;
        input
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_make_tick_input() {
        let mut c = Controls::new(Settings::with_sensitivity(0.5));
        assert_eq!(c.key(KeyCode::KeyW, true, false), None);
        c.key(KeyCode::KeyD, true, false);
        c.key(KeyCode::ShiftLeft, true, false);
        c.mouse(4.0);
        let input = c.tick_input();
        assert_eq!((input.forward, input.strafe, input.run), (1, 1, true));
        assert_eq!(input.turn, -2.0);
        // Held keys stay; the mouse is used up.
        assert_eq!(c.tick_input().turn, 0.0);
        c.key(KeyCode::KeyW, false, false);
        assert_eq!(c.tick_input().forward, 0);

        // A tap between two ticks still counts once.
        c.key(KeyCode::Space, true, false);
        c.key(KeyCode::Space, false, false);
        assert!(c.tick_input().use_line);
        assert!(!c.tick_input().use_line);

        c.key(KeyCode::ArrowLeft, true, false);
        c.key(KeyCode::ShiftLeft, false, false);
        assert!((c.tick_input().turn - 3.515625).abs() < 1e-6);

        // A number key asks for a weapon once.
        c.key(KeyCode::Digit3, true, false);
        assert_eq!(c.tick_input().weapon, 3);
        assert_eq!(c.tick_input().weapon, 0);

        assert_eq!(c.key(KeyCode::Tab, true, false), Some(Action::ToggleAutomap));
        assert_eq!(c.key(KeyCode::Tab, true, true), None);
        assert_eq!(c.key(KeyCode::Tab, false, false), None);
    }
}
