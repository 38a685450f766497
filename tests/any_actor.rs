//! Any actor on any map: RON maps naming every monster and every item of
//! the actor table (`tests/maps/roster_monsters.ron`, `roster_items.ron`,
//! made by `maps/generators/roster.py`) load, `check` and autoplay with no
//! WAD and no art looked up; drawn with no WAD they show our stand-in
//! figures, with `--iwad freedoom2.wad` Freedoom's sprites, and with
//! freedoom1 (no Doom II monsters) placeholders with one warning a frame.
//! The frames are compared against golden PNGs in `tests/images/`
//! (`SIGHTLINE_BLESS=1` writes them; look at each).

use std::collections::BTreeSet;
use std::path::PathBuf;

use sightline::actors::{ActorTable, Category};
use sightline::autopilot::{check, run_through};
use sightline::bsp::BuildOptions;
use sightline::campaign::{open_with, ArtOptions, MapRef};
use sightline::level::Level;
use sightline::play::playthrough::Playthrough;
use sightline::play::GameOptions;
use sightline::render::{Renderer, Shade};
use sightline::sim::game::Setup;
use sightline_tests::{freedoom_wads, golden, render, root, view};

const MAPS: [&str; 2] = ["roster_monsters", "roster_items"];

fn map_path(name: &str) -> PathBuf {
    let p = root().join("tests/maps").join(format!("{name}.ron"));
    assert!(p.is_file(), "missing fixture {} (maps/generators/roster.py makes it)", p.display());
    p
}

fn open(name: &str, art: ArtOptions) -> Level {
    let map = MapRef::File(map_path(name));
    let mut level = open_with(&map, &BuildOptions::default(), &art).unwrap_or_else(|e| panic!("{name}: {e}")).level;
    level.show_skill(3);
    level
}

fn freedoom(name: &str) -> ArtOptions {
    let wad = freedoom_wads::path(name);
    assert!(wad.is_file(), "missing fixture {}: {}", wad.display(), freedoom_wads::HOW_TO_GET);
    ArtOptions { wads: vec![wad], missing: None }
}

/// The kinds a map names.
fn kinds(name: &str) -> Vec<String> {
    let text = std::fs::read_to_string(map_path(name)).unwrap();
    text.split("kind: \"").skip(1).map(|s| s.split('"').next().unwrap().to_string()).collect()
}

#[test]
fn the_roster_maps_name_every_placeable_actor() {
    let named: BTreeSet<String> = MAPS.iter().flat_map(|m| kinds(m)).collect();
    let table = ActorTable::active();
    let placeable = table.actors.iter().filter(|a| {
        a.doomednum.is_some()
            && !a.category.is_marker()
            && !matches!(a.category, Category::EditorOnly | Category::BossTarget | Category::BossSpawner)
    });
    let missing: Vec<&str> = placeable.map(|a| a.name.as_str()).filter(|n| !named.contains(*n)).collect();
    assert!(missing.is_empty(), "not in the roster maps (run maps/generators/roster.py): {missing:?}");
    let monsters = kinds("roster_monsters");
    for m in ["imp", "shotgun_guy", "demon", "cyberdemon", "spiderdemon"] {
        assert!(monsters.iter().any(|k| k == m), "{m}");
    }
    assert!(kinds("roster_items").iter().any(|k| k == "box_of_bullets"));
}

#[test]
fn the_roster_maps_check_and_autoplay_with_no_art() {
    for name in MAPS {
        let level = open(name, ArtOptions::none());
        let m = &level.materials;
        assert!(m.sprites.iter().all(Option::is_none), "{name}: a sprite was looked up");
        assert!(m.sprite_views.iter().all(Option::is_none), "{name}: a frame was looked up");
        let (report, _) = check::check(level, 3);
        assert!(report.exit_reachable, "{name}: {}", report.text());
        let map = MapRef::File(map_path(name));
        let options = GameOptions { skill: 3, seed: 1, no_monsters: false };
        let mut play = Playthrough::of_with(&map, options, Setup::SINGLE, ArtOptions::none())
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let (outcome, _) = run_through(&mut play, 350, |i| i, |_, _| true).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(outcome.inputs.len() > 10, "{name}: the autopilot stopped at once");
    }
}

#[test]
fn with_no_wad_every_actor_is_a_stand_in_figure_of_its_own() {
    let level = open("roster_monsters", ArtOptions::default());
    let m = &level.materials;
    assert!(m.warnings.is_empty(), "{:?}", m.warnings);
    let fronts: Vec<_> = m.sprites.iter().skip(1).map(|s| s.expect("every monster is drawn")).collect();
    // Distinct figures: no two monsters of different sprites look alike.
    let map = &level.compiled.map;
    let mut seen = std::collections::BTreeMap::new();
    for (thing, id) in map.things.iter().skip(1).zip(&fronts) {
        let name = m.textures.name(*id).to_string();
        let texels = &m.textures.get(*id).texels;
        if let Some((other, t)) = seen.insert(name[..4].to_string(), (thing.kind.clone(), texels.clone())) {
            assert_eq!(&t, texels, "{} and {other} share a sprite but not its picture", thing.kind);
        }
    }
    let all: Vec<_> = seen.values().collect();
    for (i, a) in all.iter().enumerate() {
        for b in &all[i + 1..] {
            assert!(a.1 != b.1, "{} looks like {}", a.0, b.0);
        }
    }
    let items = open("roster_items", ArtOptions::default());
    assert!(items.materials.warnings.is_empty(), "{:?}", items.materials.warnings);
    let drawn = items.materials.sprites.iter().filter(|s| s.is_some()).count();
    assert!(drawn >= 90, "{drawn} of {} items drawn", items.compiled.map.things.len());
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn with_an_iwad_actors_take_its_sprites_and_its_holes_are_placeholders() {
    let ours = open("roster_monsters", ArtOptions::default());
    let theirs = open("roster_monsters", freedoom("freedoom2.wad"));
    assert!(theirs.materials.warnings.is_empty(), "{:?}", theirs.materials.warnings);
    assert!(theirs.materials.placeholders.is_empty());
    let imp = ours.compiled.map.things.iter().position(|t| t.kind == "imp").unwrap();
    let picture = |l: &Level| l.materials.textures.get(l.materials.sprites[imp].unwrap()).clone();
    assert!(picture(&ours) != picture(&theirs), "the imp is our stand-in under freedoom2.wad");
    // Doom's first episode has no arch-vile: under freedoom1 it is a
    // placeholder, with one warning for each of its frames.
    let doom1 = open("roster_monsters", freedoom("freedoom1.wad"));
    let w = &doom1.materials.warnings;
    assert!(w.iter().any(|w| w.contains("arch_vile's frame A (sprite VILEA)")), "{w:#?}");
    let unique: BTreeSet<&String> = w.iter().collect();
    assert_eq!(unique.len(), w.len(), "a warning repeated: {w:#?}");
    assert!(!w.iter().any(|w| w.contains("imp's")), "{w:#?}");
}

/// The poses the golden frames are taken from: along the row of actors,
/// looking north at it.
fn poses(name: &str) -> Vec<(f64, f64, f64)> {
    match name {
        "roster_monsters" => [250.0, 700.0, 1200.0, 1900.0].map(|x| (x, 120.0, 90.0)).to_vec(),
        _ => [400.0, 1500.0, 3000.0, 5000.0, 7000.0].map(|x| (x, 200.0, 90.0)).to_vec(),
    }
}

fn compare_golden(level: &Level, name: &str, art: &str, failures: &mut Vec<String>) {
    for (i, (x, y, angle)) in poses(name).into_iter().enumerate() {
        let frame = render(level, &view(level, x, y, angle), (320, 200), Renderer::Bsp, Shade::Textured);
        if let Err(e) = golden(&format!("{name}-{art}-{i}"), &frame) {
            failures.push(e);
        }
    }
}

#[test]
fn stand_in_frames_match_golden_images() {
    let mut failures = Vec::new();
    for name in MAPS {
        compare_golden(&open(name, ArtOptions::default()), name, "standins", &mut failures);
    }
    assert!(failures.is_empty(), "golden frames changed:\n{}", failures.join("\n"));
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn freedoom_frames_match_golden_images() {
    let mut failures = Vec::new();
    for name in MAPS {
        compare_golden(&open(name, freedoom("freedoom2.wad")), name, "freedoom2", &mut failures);
    }
    assert!(failures.is_empty(), "golden frames changed:\n{}", failures.join("\n"));
}
