use evdev::{AbsoluteAxisCode, EventType, InputEvent, KeyCode};

use super::*;
use crate::play::input::{Action, Controls, Settings};

fn key(code: KeyCode, value: i32) -> EventSummary {
    InputEvent::new(EventType::KEY.0, code.0, value).destructure()
}

fn abs(code: AbsoluteAxisCode, value: i32) -> EventSummary {
    InputEvent::new(EventType::ABSOLUTE.0, code.0, value).destructure()
}

/// A pad's ranges as an Xbox pad reports them: sticks -32768..32767,
/// triggers 0..1023, the hat -1..1.
fn ranges() -> BTreeMap<u16, Range> {
    let stick = Range { min: -32768, max: 32767 };
    let mut r = BTreeMap::new();
    for code in [AbsoluteAxisCode::ABS_X, AbsoluteAxisCode::ABS_Y, AbsoluteAxisCode::ABS_RX, AbsoluteAxisCode::ABS_RY] {
        r.insert(code.0, stick);
    }
    r.insert(AbsoluteAxisCode::ABS_Z.0, Range { min: 0, max: 1023 });
    r.insert(AbsoluteAxisCode::ABS_RZ.0, Range { min: 0, max: 1023 });
    r.insert(AbsoluteAxisCode::ABS_HAT0X.0, Range { min: -1, max: 1 });
    r.insert(AbsoluteAxisCode::ABS_HAT0Y.0, Range { min: -1, max: 1 });
    r
}

#[test]
fn kernel_events_become_pad_events() {
    let (r, mut held) = (ranges(), Vec::new());
    let mut t = |e| translate(e, &r, &mut held);
    assert_eq!(t(key(KeyCode::BTN_SOUTH, 1)), vec![PadEvent::Button { button: PadButton::South, down: true }]);
    assert_eq!(t(key(KeyCode::BTN_SOUTH, 2)), vec![], "auto-repeat is no new press");
    assert_eq!(t(key(KeyCode::BTN_SOUTH, 0)), vec![PadEvent::Button { button: PadButton::South, down: false }]);
    assert_eq!(t(key(KeyCode::KEY_A, 1)), vec![], "a keyboard's key is not a pad's");
    assert_eq!(t(abs(AbsoluteAxisCode::ABS_Y, -32768)), vec![PadEvent::Axis { axis: PadAxis::LeftY, value: -1.0 }]);
    assert_eq!(t(abs(AbsoluteAxisCode::ABS_RX, 32767)), vec![PadEvent::Axis { axis: PadAxis::RightX, value: 1.0 }]);
    // An analog trigger presses once past half way, and lets go below it.
    assert_eq!(t(abs(AbsoluteAxisCode::ABS_RZ, 300)), vec![]);
    assert_eq!(
        t(abs(AbsoluteAxisCode::ABS_RZ, 900)),
        vec![PadEvent::Button { button: PadButton::RightTrigger, down: true }]
    );
    assert_eq!(t(abs(AbsoluteAxisCode::ABS_RZ, 1000)), vec![]);
    assert_eq!(
        t(abs(AbsoluteAxisCode::ABS_RZ, 10)),
        vec![PadEvent::Button { button: PadButton::RightTrigger, down: false }]
    );
    // The hat is the d-pad.
    assert_eq!(
        t(abs(AbsoluteAxisCode::ABS_HAT0Y, -1)),
        vec![PadEvent::Button { button: PadButton::DpadUp, down: true }]
    );
    assert_eq!(
        t(abs(AbsoluteAxisCode::ABS_HAT0Y, 1)),
        vec![
            PadEvent::Button { button: PadButton::DpadUp, down: false },
            PadEvent::Button { button: PadButton::DpadDown, down: true }
        ]
    );
}

#[test]
fn the_dead_zone_centres_small_pushes_and_stretches_the_rest() {
    let pad = PadMap::default();
    assert_eq!(pad.live(0.15), 0.0);
    assert_eq!(pad.live(-0.2), 0.0);
    assert!((pad.live(0.6) - 0.5).abs() < 1e-6);
    assert_eq!(pad.live(-1.0), -1.0);
}

#[test]
fn a_pad_drives_the_game_through_its_bindings() {
    let mut c = Controls::new(Settings::with_sensitivity(0.15));
    // The left stick half up walks forward; a small push sideways is in
    // the dead zone.
    c.pad(PadEvent::Axis { axis: PadAxis::LeftY, value: -0.5 });
    c.pad(PadEvent::Axis { axis: PadAxis::LeftX, value: 0.1 });
    let input = c.tick_input();
    assert_eq!((input.forward, input.strafe, input.run), (1, 0, false));
    // Pushed all the way it runs; the right stick turns right in proportion.
    c.pad(PadEvent::Axis { axis: PadAxis::LeftY, value: -1.0 });
    c.pad(PadEvent::Axis { axis: PadAxis::RightX, value: 1.0 });
    let input = c.tick_input();
    assert!(input.run);
    assert!((input.turn + 7.0).abs() < 1e-5, "{}", input.turn);
    // The right trigger fires while held; the bottom face button uses.
    c.pad(PadEvent::Button { button: PadButton::RightTrigger, down: true });
    c.pad(PadEvent::Button { button: PadButton::South, down: true });
    let input = c.tick_input();
    assert!(input.fire && input.use_line);
    c.pad(PadEvent::Button { button: PadButton::RightTrigger, down: false });
    c.pad(PadEvent::Button { button: PadButton::South, down: false });
    assert!(!c.tick_input().fire);
    // A key let go does not let go of the pad's button, nor the other way.
    c.pad(PadEvent::Button { button: PadButton::RightTrigger, down: true });
    c.key(winit::keyboard::KeyCode::ControlLeft, true, false);
    c.key(winit::keyboard::KeyCode::ControlLeft, false, false);
    c.tick_input();
    assert!(c.tick_input().fire);
    // Weapon buttons and window actions.
    c.pad(PadEvent::Button { button: PadButton::North, down: true });
    assert_eq!(c.tick_input().weapon, 3);
    assert_eq!(c.pad(PadEvent::Button { button: PadButton::Select, down: true }), Some(Action::ToggleAutomap));
    assert_eq!(c.pad(PadEvent::Button { button: PadButton::Select, down: false }), None);
    // Losing focus lets go of everything.
    c.release_all();
    let input = c.tick_input();
    assert_eq!((input.forward, input.fire, input.turn), (0, false, 0.0));
}

#[test]
fn a_rebound_button_does_its_new_action() {
    let loaded = crate::config::parse(
        "(gamepad: (dead_zone: 0.5, buttons: {\"South\": \"fire\", \"Turbo\": \"use\", \"East\": \"fly\"}))",
        std::path::Path::new("config.ron"),
    );
    let said: Vec<_> = loaded.warnings.iter().map(ToString::to_string).collect();
    assert_eq!(said.len(), 2, "{said:?}");
    assert!(said[0].contains("`gamepad.buttons`: ") && said.iter().any(|w| w.contains("unknown button `Turbo`")));
    assert!(said.iter().any(|w| w.contains("`East`: unknown action `fly`")));
    let config = loaded.config;
    let settings = Settings { pad: config.pad_map(), ..Settings::with_sensitivity(0.15) };
    let mut c = Controls::new(settings);
    c.pad(PadEvent::Button { button: PadButton::South, down: true });
    let input = c.tick_input();
    assert!(input.fire && !input.use_line);
    // East keeps its default (weapon 2); the dead zone is the file's.
    c.pad(PadEvent::Button { button: PadButton::East, down: true });
    assert_eq!(c.tick_input().weapon, 2);
    c.pad(PadEvent::Axis { axis: PadAxis::LeftY, value: -0.45 });
    assert_eq!(c.tick_input().forward, 0);
}
