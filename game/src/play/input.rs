//! Keyboard and mouse to simulation input: which keys are held, presses that
//! must not be lost between ticks, mouse motion summed since the last tick;
//! once per tick they become one `TickInput`. Keys that act on the window
//! (HUD, automap, screenshot, ...) come back as `Action`s at once.

use sightline::play::TickInput;
use winit::keyboard::KeyCode;

/// Keyboard turning, degrees per tick: Doom's `angleturn` of 640 (walking) and
/// 1280 (running) in 16.16 binary angles, 640 / 65536 * 360 = 3.5 degrees, so
/// the arrows turn 123 and 246 degrees per second at 35 Hz.
const TURN_WALK: f32 = 640.0 / 65536.0 * 360.0;
const TURN_RUN: f32 = 1280.0 / 65536.0 * 360.0;

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
#[derive(Clone, Copy)]
enum Move {
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

fn binding(key: KeyCode) -> Option<Move> {
    Some(match key {
        KeyCode::KeyW | KeyCode::ArrowUp => Move::Forward,
        KeyCode::KeyS | KeyCode::ArrowDown => Move::Back,
        KeyCode::KeyA => Move::StrafeLeft,
        KeyCode::KeyD => Move::StrafeRight,
        KeyCode::ArrowLeft => Move::TurnLeft,
        KeyCode::ArrowRight => Move::TurnRight,
        KeyCode::ShiftLeft | KeyCode::ShiftRight => Move::Run,
        KeyCode::KeyE | KeyCode::Space => Move::Use,
        KeyCode::ControlLeft | KeyCode::ControlRight | KeyCode::KeyF => Move::Fire,
        _ => return None,
    })
}

/// The weapon number a key asks for (the number keys 1 to 7).
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

fn weapon_key(key: KeyCode) -> Option<u8> {
    Some(match key {
        KeyCode::Digit1 => 1,
        KeyCode::Digit2 => 2,
        KeyCode::Digit3 => 3,
        KeyCode::Digit4 => 4,
        KeyCode::Digit5 => 5,
        KeyCode::Digit6 => 6,
        KeyCode::Digit7 => 7,
        _ => return None,
    })
}

/// The window action of a key event: fresh presses only (auto-repeat does
/// not repeat actions).
pub fn window_action(key: KeyCode, down: bool, repeat: bool) -> Option<Action> {
    if !down || repeat {
        return None;
    }
    Some(match key {
        KeyCode::KeyQ => Action::Quit,
        KeyCode::Escape => Action::ReleaseCursor,
        KeyCode::F11 => Action::ToggleFullscreen,
        KeyCode::KeyH => Action::ToggleHud,
        KeyCode::Tab => Action::ToggleAutomap,
        KeyCode::F12 => Action::Screenshot,
        KeyCode::KeyR => Action::CycleRenderer,
        KeyCode::Minus | KeyCode::Equal => Action::ToggleStatusBar,
        KeyCode::BracketLeft => Action::EffectsVolume(-1),
        KeyCode::BracketRight => Action::EffectsVolume(1),
        KeyCode::PageDown => Action::MusicVolume(-1),
        KeyCode::PageUp => Action::MusicVolume(1),
        KeyCode::F6 => Action::QuickSave,
        KeyCode::F9 => Action::QuickLoad,
        KeyCode::F2 => Action::SaveSlot,
        KeyCode::F3 => Action::LoadSlot,
        _ => return None,
    })
}

#[derive(Default)]
pub struct Controls {
    /// Movement keys down now.
    held: u16,
    /// Movement keys pressed since the last tick, so a tap shorter than a
    /// tick (28.6 ms) still moves or uses once.
    pressed: u16,
    /// Mouse counts to the right since the last tick.
    mouse_dx: f64,
    /// Degrees per mouse count.
    sensitivity: f32,
    /// The weapon number last pressed since the last tick (0: none).
    weapon: u8,
}

impl Controls {
    pub fn new(sensitivity: f32) -> Controls {
        Controls { sensitivity, ..Default::default() }
    }

    /// A key went down (`down`) or up. Returns the window action of a fresh
    /// press (auto-repeat does not repeat actions).
    pub fn key(&mut self, key: KeyCode, down: bool, repeat: bool) -> Option<Action> {
        if let Some(slot) = weapon_key(key) {
            if down {
                self.weapon = slot;
            }
            return None;
        }
        if let Some(m) = binding(key) {
            self.set(m, down);
            return None;
        }
        window_action(key, down, repeat)
    }

    fn set(&mut self, m: Move, down: bool) {
        let bit = m as u16;
        if down {
            self.held |= bit;
            self.pressed |= bit;
        } else {
            self.held &= !bit;
        }
    }

    /// The left mouse button (fire) went down or up, while the cursor is grabbed.
    pub fn mouse_button(&mut self, down: bool) {
        self.set(Move::Fire, down);
    }

    /// Mouse motion while the cursor is grabbed.
    pub fn mouse(&mut self, dx: f64) {
        self.mouse_dx += dx;
    }

    /// Lets go of everything, e.g. when the window loses focus and would
    /// never hear the key-up.
    pub fn release_all(&mut self) {
        self.held = 0;
        self.pressed = 0;
        self.mouse_dx = 0.0;
    }

    /// The input for the next tick; clears what was latched for this one.
    pub fn tick_input(&mut self) -> TickInput {
        let on = |m: Move| (self.held | self.pressed) & m as u16 != 0;
        let axis = |plus: Move, minus: Move| i8::from(on(plus)) - i8::from(on(minus));
        let run = on(Move::Run);
        let keys_turn = f32::from(axis(Move::TurnLeft, Move::TurnRight)) * if run { TURN_RUN } else { TURN_WALK };
        // Mouse right turns clockwise, which is negative (angles grow
        // counter-clockwise).
        let mouse_turn = -(self.mouse_dx as f32) * self.sensitivity;
        let input = TickInput {
            forward: axis(Move::Forward, Move::Back),
            strafe: axis(Move::StrafeRight, Move::StrafeLeft),
            turn: keys_turn + mouse_turn,
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
        let mut c = Controls::new(0.5);
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
