//! Only the effects a scene calls for: each shipped map's plan, from its
//! player start, lists exactly the effects the map uses; the view decides
//! sprites; disabled effects leave the plan.

use sightline::render::plan::Disabled;
use sightline::render::{render_frame, Frame, RenderOptions, View};
use sightline::Framebuffer;
use sightline_tests::{load, map_path, shipped_maps};

fn plan_at(level: &sightline::level::Level, view: &View, disabled: Disabled) -> Vec<&'static str> {
    let mut frame = Frame::new();
    let options = RenderOptions { disabled, ..Default::default() };
    render_frame(level, view, &options, &mut frame, &mut Framebuffer::new(160, 100));
    frame.plan.effects()
}

#[test]
fn each_shipped_map_plans_exactly_what_it_uses() {
    let expected: &[(&str, &[&str])] = &[
        ("two_rooms", &["sky", "diminishing light"]),
        ("room", &[]),
        ("pillars", &["sky", "sprites", "diminishing light"]),
        ("maze", &["diminishing light"]),
        ("nasty", &["sprites", "diminishing light"]),
        ("stairs", &["sprites", "masked", "diminishing light"]),
        ("courtyard", &["sky", "sprites", "masked", "diminishing light", "fog"]),
        ("hall", &["sprites", "masked", "diminishing light"]),
        ("doors", &["sprites", "diminishing light"]),
        ("machinery", &["sprites", "diminishing light"]),
        ("outpost", &["sky", "sprites", "diminishing light"]),
        // Grid maps are evenly lit unless they say otherwise.
        ("bunker", &["sprites"]),
        ("gridmaze", &["sprites", "diminishing light"]),
        ("diagonals", &[]),
    ];
    let shipped: Vec<String> =
        shipped_maps().iter().map(|p| p.file_stem().unwrap().to_string_lossy().into_owned()).collect();
    for name in &shipped {
        assert!(expected.iter().any(|(n, _)| n == name), "add the expected plan of new map {name}");
    }
    for (name, effects) in expected {
        let level = load(&map_path(&format!("{name}.ron")));
        let view = View::at_start(&level).unwrap();
        assert_eq!(plan_at(&level, &view, Disabled::default()), *effects, "{name}");
    }
}

#[test]
fn sprites_are_planned_only_when_a_thing_is_in_view() {
    let level = load(&map_path("hall.ron"));
    let start = View::at_start(&level).unwrap();
    assert!(plan_at(&level, &start, Disabled::default()).contains(&"sprites"));
    // Every thing behind the eye: look away from all of them, from a corner.
    let things: Vec<_> = level.map.things.iter().filter(|t| t.kind != "player_start").map(|t| t.pos).collect();
    let west = things.iter().map(|p| p.x).fold(f64::INFINITY, f64::min) - 1.0;
    let view = View::at_pose(&level, west, start.pos.y, 180.0, None).unwrap();
    assert!(!plan_at(&level, &view, Disabled::default()).contains(&"sprites"));
}

#[test]
fn disabled_effects_leave_the_plan() {
    let level = load(&map_path("courtyard.ron"));
    let view = View::at_start(&level).unwrap();
    let all = Disabled { sky: true, sprites: true, masked: true, diminishing: true, fog: true };
    assert_eq!(plan_at(&level, &view, all), Vec::<&str>::new());
}
