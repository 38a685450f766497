//! Gamepads, read from the kernel's event devices (`/dev/input/event*`)
//! with the pure-Rust `evdev` crate, so the game builds on a bare machine
//! (gilrs would need libudev's headers). Each pad found at start gets a
//! reader thread that turns its events into [`PadEvent`]s (buttons by
//! their standard names, axes scaled to -1..1) on one channel; the window
//! drains it every frame into `input::Controls`, which maps buttons to the
//! same actions as keys ([`PadMap`], from the settings file's `gamepad`
//! section) and sticks to movement and turning.
//!
//! Reading `/dev/input/event*` needs read access to it (on most desktops
//! the seat's user has it for pads; else the `input` group). A pad that
//! cannot be opened is left out without a word; one that is read is named
//! on the terminal. Pads plugged in after the start are not seen.

use std::collections::BTreeMap;
use std::sync::mpsc::{channel, Receiver, Sender};

use evdev::{AbsoluteAxisCode, Device, EventSummary, KeyCode};

use super::input::{Bind, BINDS};

/// A pad's button, by its position (Xbox letters in brackets).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum PadButton {
    /// Bottom face button (A).
    South,
    /// Right face button (B).
    East,
    /// Left face button (X).
    West,
    /// Top face button (Y).
    North,
    LeftShoulder,
    RightShoulder,
    LeftTrigger,
    RightTrigger,
    Select,
    Start,
    LeftStick,
    RightStick,
    DpadUp,
    DpadDown,
    DpadLeft,
    DpadRight,
}

/// Every button and its name in the settings file.
pub const BUTTONS: &[(&str, PadButton)] = &[
    ("South", PadButton::South),
    ("East", PadButton::East),
    ("West", PadButton::West),
    ("North", PadButton::North),
    ("LeftShoulder", PadButton::LeftShoulder),
    ("RightShoulder", PadButton::RightShoulder),
    ("LeftTrigger", PadButton::LeftTrigger),
    ("RightTrigger", PadButton::RightTrigger),
    ("Select", PadButton::Select),
    ("Start", PadButton::Start),
    ("LeftStick", PadButton::LeftStick),
    ("RightStick", PadButton::RightStick),
    ("DpadUp", PadButton::DpadUp),
    ("DpadDown", PadButton::DpadDown),
    ("DpadLeft", PadButton::DpadLeft),
    ("DpadRight", PadButton::DpadRight),
];

/// A stick's axis; up and left are negative, as the kernel reports them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PadAxis {
    LeftX,
    LeftY,
    RightX,
    RightY,
}

/// One thing a pad did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PadEvent {
    Button {
        button: PadButton,
        down: bool,
    },
    /// An axis's position, -1 to 1.
    Axis {
        axis: PadAxis,
        value: f32,
    },
}

/// What the pad's buttons and sticks do.
#[derive(Clone, Debug)]
pub struct PadMap {
    buttons: BTreeMap<PadButton, Bind>,
    /// Stick positions nearer the centre than this count as centred.
    pub dead_zone: f32,
    /// Degrees per tick of turn with the right stick fully over (keys
    /// turn 3.5 walking and 7 running).
    pub turn_speed: f32,
}

impl Default for PadMap {
    fn default() -> PadMap {
        let defaults = default_buttons();
        PadMap::of(defaults.iter().map(|(b, a)| (b.as_str(), a.as_str())), 0.2, 7.0)
    }
}

impl PadMap {
    /// From (button name, action name) pairs; unknown names are skipped
    /// (the settings file's reader has warned of them).
    pub fn of<'a>(pairs: impl IntoIterator<Item = (&'a str, &'a str)>, dead_zone: f32, turn_speed: f32) -> PadMap {
        let mut buttons = BTreeMap::new();
        for (button, action) in pairs {
            let button = BUTTONS.iter().find(|(n, _)| *n == button).map(|(_, b)| *b);
            let bind = BINDS.iter().find(|(n, _, _)| *n == action).map(|(_, b, _)| *b);
            if let (Some(button), Some(bind)) = (button, bind) {
                buttons.insert(button, bind);
            }
        }
        PadMap { buttons, dead_zone, turn_speed }
    }

    pub fn get(&self, button: PadButton) -> Option<Bind> {
        self.buttons.get(&button).copied()
    }

    /// `value` with the dead zone taken out and the rest stretched back
    /// to -1..1.
    pub fn live(&self, value: f32) -> f32 {
        let zone = self.dead_zone.clamp(0.0, 0.95);
        let size = value.abs();
        if size <= zone {
            0.0
        } else {
            value.signum() * ((size - zone) / (1.0 - zone)).min(1.0)
        }
    }
}

/// The buttons' default actions, by name: a right trigger fires, the
/// bottom face button uses, the left stick's press runs, Start releases
/// the cursor, Select shows the automap, the d-pad moves and turns.
pub fn default_buttons() -> BTreeMap<String, String> {
    [
        ("RightTrigger", "fire"),
        ("South", "use"),
        ("West", "use"),
        ("LeftStick", "run"),
        ("LeftTrigger", "run"),
        ("Start", "release_cursor"),
        ("Select", "automap"),
        ("DpadUp", "forward"),
        ("DpadDown", "back"),
        ("DpadLeft", "turn_left"),
        ("DpadRight", "turn_right"),
        ("North", "weapon3"),
        ("East", "weapon2"),
        ("LeftShoulder", "weapon4"),
        ("RightShoulder", "weapon5"),
    ]
    .into_iter()
    .map(|(b, a)| (b.to_string(), a.to_string()))
    .collect()
}

/// The button of an evdev key code, if a pad's.
fn button_of(code: KeyCode) -> Option<PadButton> {
    Some(match code {
        KeyCode::BTN_SOUTH => PadButton::South,
        KeyCode::BTN_EAST => PadButton::East,
        KeyCode::BTN_WEST => PadButton::West,
        KeyCode::BTN_NORTH => PadButton::North,
        KeyCode::BTN_TL => PadButton::LeftShoulder,
        KeyCode::BTN_TR => PadButton::RightShoulder,
        KeyCode::BTN_TL2 => PadButton::LeftTrigger,
        KeyCode::BTN_TR2 => PadButton::RightTrigger,
        KeyCode::BTN_SELECT => PadButton::Select,
        KeyCode::BTN_START => PadButton::Start,
        KeyCode::BTN_THUMBL => PadButton::LeftStick,
        KeyCode::BTN_THUMBR => PadButton::RightStick,
        KeyCode::BTN_DPAD_UP => PadButton::DpadUp,
        KeyCode::BTN_DPAD_DOWN => PadButton::DpadDown,
        KeyCode::BTN_DPAD_LEFT => PadButton::DpadLeft,
        KeyCode::BTN_DPAD_RIGHT => PadButton::DpadRight,
        _ => return None,
    })
}

/// An axis's range, as the device reports it.
#[derive(Clone, Copy, Debug)]
pub struct Range {
    pub min: i32,
    pub max: i32,
}

impl Range {
    /// `value` scaled to -1..1 (0..1 for a trigger's one-sided range).
    fn scale(self, value: i32) -> f32 {
        let span = (self.max - self.min).max(1) as f32;
        (2.0 * (value - self.min) as f32 / span - 1.0).clamp(-1.0, 1.0)
    }
}

/// Turns one evdev event into pad events: keys into buttons, stick axes
/// into axes, analog triggers into trigger buttons (past half way), the
/// d-pad's hat axes into d-pad buttons. `ranges` holds each absolute
/// axis's range by code; `held` the triggers and hats already down, so a
/// press is sent once.
pub fn translate(event: EventSummary, ranges: &BTreeMap<u16, Range>, held: &mut Vec<PadButton>) -> Vec<PadEvent> {
    let mut out = Vec::new();
    let mut set = |button: PadButton, down: bool, out: &mut Vec<PadEvent>| {
        let was = held.contains(&button);
        if down != was {
            if down {
                held.push(button);
            } else {
                held.retain(|b| *b != button);
            }
            out.push(PadEvent::Button { button, down });
        }
    };
    match event {
        EventSummary::Key(_, code, value) => {
            if let Some(button) = button_of(code) {
                // 2 is the kernel's auto-repeat: not a new press.
                if value != 2 {
                    out.push(PadEvent::Button { button, down: value != 0 });
                }
            }
        }
        EventSummary::AbsoluteAxis(_, code, value) => {
            let range = ranges.get(&code.0).copied().unwrap_or(Range { min: -32768, max: 32767 });
            let axis = match code {
                AbsoluteAxisCode::ABS_X => Some(PadAxis::LeftX),
                AbsoluteAxisCode::ABS_Y => Some(PadAxis::LeftY),
                AbsoluteAxisCode::ABS_RX => Some(PadAxis::RightX),
                AbsoluteAxisCode::ABS_RY => Some(PadAxis::RightY),
                _ => None,
            };
            match (axis, code) {
                (Some(axis), _) => out.push(PadEvent::Axis { axis, value: range.scale(value) }),
                (None, AbsoluteAxisCode::ABS_Z) => set(PadButton::LeftTrigger, range.scale(value) > 0.0, &mut out),
                (None, AbsoluteAxisCode::ABS_RZ) => set(PadButton::RightTrigger, range.scale(value) > 0.0, &mut out),
                (None, AbsoluteAxisCode::ABS_HAT0X) => {
                    set(PadButton::DpadLeft, value < 0, &mut out);
                    set(PadButton::DpadRight, value > 0, &mut out);
                }
                (None, AbsoluteAxisCode::ABS_HAT0Y) => {
                    set(PadButton::DpadUp, value < 0, &mut out);
                    set(PadButton::DpadDown, value > 0, &mut out);
                }
                _ => {}
            }
        }
        _ => {}
    }
    out
}

/// Whether a device is a gamepad: it has a pad's face button and a stick.
fn is_pad(device: &Device) -> bool {
    let keys = device.supported_keys().is_some_and(|k| k.contains(KeyCode::BTN_SOUTH));
    let stick = device.supported_absolute_axes().is_some_and(|a| a.contains(AbsoluteAxisCode::ABS_X));
    keys && stick
}

/// Starts a reader thread for every gamepad found; None when there is none.
pub fn open_all() -> Option<Receiver<PadEvent>> {
    let (tx, rx) = channel();
    let mut found = 0;
    for (path, device) in evdev::enumerate().filter(|(_, d)| is_pad(d)) {
        let name = device.name().unwrap_or("a gamepad").to_string();
        let spawned = std::thread::Builder::new().name("sightline-gamepad".into()).spawn({
            let tx = tx.clone();
            move || read(device, tx)
        });
        if spawned.is_ok() {
            println!("gamepad: {name} ({})", path.display());
            found += 1;
        }
    }
    (found > 0).then_some(rx)
}

/// A pad's reader: its events until it goes away or the game ends.
fn read(mut device: Device, tx: Sender<PadEvent>) {
    let ranges: BTreeMap<u16, Range> = device
        .get_absinfo()
        .map(|infos| infos.map(|(code, info)| (code.0, Range { min: info.minimum(), max: info.maximum() })).collect())
        .unwrap_or_default();
    let mut held = Vec::new();
    loop {
        let Ok(events) = device.fetch_events() else { return };
        for event in events {
            for e in translate(event.destructure(), &ranges, &mut held) {
                if tx.send(e).is_err() {
                    return;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests;
