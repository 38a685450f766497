//! Golden frames: fixed poses of each shipped map, compared exactly against
//! PNGs checked in under `tests/images/`. After an intended change to how
//! frames look, regenerate them with `SIGHTLINE_BLESS=1 cargo test -p
//! sightline-tests --test golden`, look at every changed image, and commit.

use sightline::render::{Renderer, Shade};
use sightline::tour::tour;
use sightline_tests::{golden, load, render, root, shipped_maps};

const SIZE: (usize, usize) = (320, 200);
/// Poses per map: the player start, then tour poses.
const POSES: usize = 3;

#[test]
fn frames_match_golden_images() {
    let mut failures = Vec::new();
    for path in shipped_maps() {
        let level = load(&path);
        let stem = path.file_stem().unwrap().to_string_lossy().to_string();
        let views = tour(&level, 8, 11);
        // The start facing its own angle, then two seeded poses from the tour.
        for (i, view) in [views[0], views[8], views[9]].iter().take(POSES).enumerate() {
            // Grid maps also through the ray-caster, textured as players see them.
            let raycast = level.grid().map(|_| (Renderer::Raycast, Shade::Textured));
            let frames =
                [Shade::Textured, Shade::Flat, Shade::Ids].map(|s| (Renderer::Bsp, s)).into_iter().chain(raycast);
            for (renderer, shade) in frames {
                let frame = render(&level, view, SIZE, renderer, shade);
                let kind = match renderer {
                    Renderer::Bsp => shade.name().to_string(),
                    other => format!("{}-{}", other.name(), shade.name()),
                };
                if let Err(e) = golden(&format!("{stem}-{i}-{kind}"), &frame) {
                    failures.push(e);
                }
            }
        }
    }
    assert!(failures.is_empty(), "golden frames changed:\n{}", failures.join("\n"));
}

/// A frame of play on the simulation with no Freedoom:
/// `tests/maps/monsters.ron` with its trooper in view (the procedural sprite), the procedural pistol raised and
/// firing (its flash), and the status bar; then the minimal HUD with a
/// pickup's gold tint. Compared as the frames above.
#[test]
fn play_frames_with_the_status_bar_and_a_weapon_match_golden_images() {
    use sightline::autopilot::observe::Observe;
    use sightline::play::TickInput;
    use sightline::screen::{draw, Hud};
    use sightline_tests::sim_play::{game, teleport};
    let mut g = game("monsters");
    g.set_health(1_000_000);
    teleport(&mut g, glam::DVec2::new(700.0, 256.0), 0.0);
    for _ in 0..20 {
        g.tick(&TickInput::default());
    }
    let mut frames = Vec::new();
    for (name, hud, fire) in
        [("play-status", Hud::StatusBar, 0), ("play-firing", Hud::StatusBar, 5), ("play-minimal", Hud::Minimal, 0)]
    {
        for _ in 0..fire {
            g.tick(&TickInput { fire: true, ..TickInput::default() });
        }
        // What is shown only: the next tic reads the player afresh.
        if hud == Hud::Minimal {
            g.player_mut().health = 75;
            g.player_mut().bonus_count = 6;
        }
        let shown = Observe::player(&g).health.min(100);
        g.player_mut().health = shown;
        let mut frame = render(Observe::level(&g), &g.view(1.0), SIZE, Renderer::Bsp, Shade::Textured);
        draw(&mut frame, Observe::level(&g), Observe::table(&g), Observe::player(&g), hud);
        frames.push((name, frame));
    }
    for (name, frame) in frames {
        if let Err(e) = golden(name, &frame) {
            panic!("{e}");
        }
    }
}

/// The default level's main views as a person sees them, with the status
/// bar and the weapon in hand: the start (the window onto the courtyard,
/// the pistol), the courtyard from its door (the slime pool, the lift, the
/// sky; the shotgun), the hall from its door (the dais, the flickering
/// light, monsters) and the exit yard (the scrolling chevrons, the exit
/// building). Played on the simulation; compared as the frames above;
/// looked at when blessed.
#[test]
fn the_default_level_s_main_views_match_golden_images() {
    use sightline::autopilot::observe::Observe;
    use sightline::play::{GameOptions, TickInput};
    use sightline::screen::{draw, Hud};
    use sightline::sim::game::SimGame;
    use sightline_tests::sim_play::teleport;
    let level = load(&root().join("maps/outpost.ron"));
    let options = GameOptions::default();
    let mut g = SimGame::on_level(level, "outpost.ron", options).unwrap_or_else(|e| panic!("{e}"));
    let shotgun = g.sim.info.table.index("shotgun").unwrap();
    let views = [
        ("start", None),
        ("courtyard", Some((416.0, 440.0, 70.0))),
        ("hall", Some((352.0, 1060.0, 80.0))),
        ("exit-yard", Some((1216.0, 1080.0, 80.0))),
    ];
    for (k, (name, pose)) in views.into_iter().enumerate() {
        if let Some((x, y, angle)) = pose {
            teleport(&mut g, glam::DVec2::new(x, y), angle);
        }
        if k == 1 {
            // Doom's weapon 2 is the shotgun, its ammunition 1 shells.
            let p = g.sim.players[0].as_mut().unwrap();
            p.weaponowned[2] = true;
            p.ammo[1] = 8;
            g.tick(&TickInput { weapon: 3, ..TickInput::default() });
        }
        for _ in 0..40 {
            g.set_health(100);
            g.tick(&TickInput::default());
        }
        assert!(k != 1 || Observe::player(&g).ready_weapon == Some(shotgun), "the shotgun is not up");
        let mut frame = render(Observe::level(&g), &g.view(1.0), SIZE, Renderer::Bsp, Shade::Textured);
        draw(&mut frame, Observe::level(&g), Observe::table(&g), Observe::player(&g), Hud::StatusBar);
        if let Err(e) = golden(&format!("outpost-play-{k}-{name}"), &frame) {
            panic!("{e}");
        }
    }
}
