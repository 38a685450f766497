//! Real levels: every map of Freedoom's two IWADs (Debian package
//! `freedoom`) imported, validated, compiled with each heuristic splitter to
//! a tree `bsp::check` accepts, rendered from a tour of poses and played,
//! with every door line tried. The WADs are a fixture. Where they are
//! missing, `build.rs` marks these tests ignored with the reason (so
//! `cargo test` lists them as skipped, never as passed), or fails the build
//! under `SIGHTLINE_REQUIRE_FREEDOOM=1`, which CI sets; a WAD that goes
//! missing after the build still fails the test that opens it.

use std::path::{Path, PathBuf};

use glam::DVec2;
use sightline::autopilot::observe::Observe;
use sightline::bsp::check::check_invariants;
use sightline::bsp::{build, BuildOptions, SplitterKind};
use sightline::geom::{exact_side, Side};
use sightline::level::open_level;
use sightline::map::validate::validate;
use sightline::map::{Action, Activation};
use sightline::play::events::Event;
use sightline::play::world::SpecialLine;
use sightline::play::{GameOptions, TickInput};
use sightline::render::{render_frame, Frame, RenderOptions, Renderer, View};
use sightline::sim::game::SimGame;
use sightline::sim::mobj::mf;
use sightline::sim::MobjId;
use sightline::tour::tour;
use sightline::wad::import::{convert, write_art, Art};
use sightline::wad::{wad_bytes, Wad};
use sightline::Framebuffer;
use sightline_tests::sim_play::{player_mo, pos as body_pos, present, sees, try_teleport, wake_all};
use sightline_tests::{
    assert_agree, assert_agree_on_two_sided_lines, freedoom_wads, points_on_two_sided_lines, random_inputs,
};

/// The IWAD `name` (see `freedoom_wads` for where it is looked for).
fn wad_path(name: &str) -> PathBuf {
    let path = freedoom_wads::path(name);
    assert!(path.is_file(), "missing fixture {}: {}", path.display(), freedoom_wads::HOW_TO_GET);
    path
}

/// Imports every map of `wad` into `dir` (RON files and PNGs) and returns the
/// RON paths, checking that each converted map validates and that every
/// special and thing was translated.
fn import_all(wad: &Path, dir: &Path) -> Vec<PathBuf> {
    let wad = Wad::open(wad).unwrap_or_else(|e| panic!("{e}"));
    let art = Art::read(&wad).unwrap_or_else(|e| panic!("{e}"));
    let mut converted = Vec::new();
    let mut paths = Vec::new();
    for name in wad.map_names() {
        let raw = wad.map(&name).unwrap_or_else(|e| panic!("{e}"));
        let c = convert(&wad, &raw, &art).unwrap_or_else(|e| panic!("{e}"));
        let r = &c.report;
        assert!(r.unsupported_specials.is_empty(), "{name}: untranslated specials: {:?}", r.unsupported_specials);
        assert!(r.unknown_things.is_empty(), "{name}: unknown things: {:?}", r.unknown_things);
        // Map bugs Doom forgives (a walk line closing doors of a tag no
        // sector has, a teleporter to a tag with no destination) are listed
        // by the importer, not fatal.
        for d in &r.dangling {
            eprintln!("{name}: {d}");
        }
        validate(&c.source).unwrap_or_else(|p| panic!("{name}: {p:?}"));
        let path = dir.join(format!("{}.ron", name.to_ascii_lowercase()));
        std::fs::write(&path, c.source.to_ron()).unwrap();
        paths.push(path);
        converted.push(c);
    }
    write_art(&wad, &art, &converted, dir).unwrap_or_else(|e| panic!("{e}"));
    paths
}

fn check_wad(name: &str, maps: usize) {
    let dir = tempfile::tempdir().unwrap();
    let paths = import_all(&wad_path(name), dir.path());
    assert_eq!(paths.len(), maps, "{name} should hold {maps} maps");
    let mut switches = 0;
    // SIGHTLINE_FREEDOOM_MAPS=map07,e2m3 plays only those (a local aid; CI plays all).
    let only = std::env::var("SIGHTLINE_FREEDOOM_MAPS").ok();
    for path in &paths {
        let stem = path.file_stem().unwrap().to_string_lossy().to_string();
        if only.as_ref().is_some_and(|o| !o.split(',').any(|m| m.eq_ignore_ascii_case(&stem))) {
            continue;
        }
        let level = open_level(path, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        render_tour(&level, path);
        switches += play(level, path);
    }
    assert!(only.is_some() || switches > 10 * maps, "{name}: only {switches} switches and doors were used");
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
#[cfg_attr(
    not(freedoom_missing),
    ignore = "long suite (every Freedoom map): scripts/long-suites.sh runs it, as CI does"
)]
fn every_freedoom1_map_imports_compiles_renders_and_plays() {
    check_wad("freedoom1.wad", 36);
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
#[cfg_attr(
    not(freedoom_missing),
    ignore = "long suite (every Freedoom map): scripts/long-suites.sh runs it, as CI does"
)]
fn every_freedoom2_map_imports_compiles_renders_and_plays() {
    check_wad("freedoom2.wad", 32);
}

/// The player start looking eight ways and a few seeded poses: every frame
/// is drawn without panicking and shows more than one colour.
fn render_tour(level: &sightline::level::Level, path: &Path) {
    let mut frame = Frame::new();
    let mut fb = Framebuffer::new(160, 100);
    for view in tour(level, 8, 1) {
        render_frame(level, &view, &RenderOptions::default(), &mut frame, &mut fb);
        let first = fb.pixels[0];
        assert!(fb.pixels.iter().any(|&p| p != first), "{}: a flat frame at {view:?}", path.display());
    }
}

/// The player is in the map (where point location answers).
fn check_state(game: &SimGame, path: &Path, at: &str) {
    let p = Observe::player(game).pos;
    let level = Observe::level(game);
    assert!(level.map.contains(p), "{} {at}: the player left the map at {p}", path.display());
    assert!(level.compiled.locate(p).is_some(), "{} {at}: no sector at the player's {p}", path.display());
}

/// Whether a square of half-width `r` round `c` straddles the segment
/// `a`-`b` (Doom's `PIT_CheckLine`: the boxes overlap and the line has
/// corners of the square strictly on both sides).
fn box_crosses(c: DVec2, r: f64, a: DVec2, b: DVec2) -> bool {
    if a.x.max(b.x) <= c.x - r || a.x.min(b.x) >= c.x + r || a.y.max(b.y) <= c.y - r || a.y.min(b.y) >= c.y + r {
        return false;
    }
    let side = |p: DVec2| (b - a).perp_dot(p - a);
    let corners = [(-r, -r), (-r, r), (r, -r), (r, r)].map(|(dx, dy)| side(c + DVec2::new(dx, dy)));
    corners.iter().any(|&s| s > 0.0) && corners.iter().any(|&s| s < 0.0)
}

/// Every body that has moved from where it appeared (a map may place a
/// thing outside or in a wall; play must never put one there) and that
/// takes part in movement (not `MF_NOBLOCKMAP`: effects such as puffs and
/// the arch-vile's fire are put where Doom puts them, which may be in a
/// wall) is inside the map, and a solid one's box crosses no one-sided
/// wall.
fn check_walls(game: &SimGame, start: &[(DVec2, bool)], path: &Path, at: &str) {
    let sim = &game.sim;
    let table = &sim.info.table;
    let map = &Observe::level(game).compiled.map;
    // A thing the map put outside (E3M7 has a cacodemon in the void) and
    // what it fires stay where they are, as in Doom.
    let outside = |id: MobjId| start.get(id.0 as usize).is_some_and(|&(_, inside)| !inside);
    for id in sim.live_mobjs() {
        let m = sim.mo(id);
        let p = body_pos(game, id);
        let moved = start.get(id.0 as usize).is_none_or(|&(s, _)| s != p);
        let from_outside = m.has(mf::MISSILE) && m.target.is_some_and(outside);
        if !present(game, id) || !moved || m.has(mf::NOBLOCKMAP) || outside(id) || from_outside {
            continue;
        }
        let name = &table.actors[m.kind].name;
        let inside = Observe::level(game).compiled.locate(p).is_some();
        assert!(inside, "{} {at}: body {} ({name}) left the map at {p}", path.display(), id.0);
        // A body still falling in its death frames may be where it was
        // killed: a pain elemental's soul spawned into a wall dies there
        // at once (Doom's A_PainShootSkull), solid until it falls.
        if !m.has(mf::SOLID) || m.health <= 0 {
            continue;
        }
        for (i, line) in map.lines.iter().enumerate().filter(|(_, l)| l.back.is_none()) {
            let (a, b) = map.line_points(line);
            assert!(
                !box_crosses(p, m.radius.to_f64(), a, b),
                "{} {at}: body {} ({name}) at {p} is in wall {i}",
                path.display(),
                id.0
            );
        }
    }
}

/// Plays the map on skill 4 on the simulation: every use special (door,
/// switch; every key held, exits left out) is used from in front of its
/// line, and must start something or find its sectors already at work;
/// then, with everything it set going still running and every monster
/// awake, 2,000 tics of seeded play, firing in bursts, by a player too
/// tough to die. At every tic the player is in the map; every 50 tics
/// every body that moved is in the map and out of the walls
/// (`check_walls`). Returns the number of lines used.
fn play(level: sightline::level::Level, path: &Path) -> usize {
    let map = level.map.clone();
    let options = GameOptions { skill: 4, ..GameOptions::default() };
    let label = path.display().to_string();
    let mut game = SimGame::on_level(level, &label, options).unwrap_or_else(|e| panic!("{label}: {e}"));
    game.sim.players[0].as_mut().expect("a player").cards = [true; sightline::sim::NUMCARDS];
    // A new player starts with use held (G_PlayerReborn's usedown): let go.
    game.tick(&TickInput::default());
    let mut used = 0;
    for (i, line) in map.lines.iter().enumerate() {
        let Some(special) = &line.special else { continue };
        if special.on != Activation::Use || matches!(special.action, Action::Exit | Action::SecretExit) {
            continue;
        }
        let (a, b) = map.line_points(line);
        let d = (b - a).normalize();
        let normal = DVec2::new(d.y, -d.x); // the front is the right-hand side
        let middle = (a + b) / 2.0;
        // Stand in front, facing the line (nearer if a wall is close).
        let Some(pos) = [20.0, 8.0, 2.0].into_iter().map(|k| middle + normal * k).find(|&p| {
            exact_side(a, b, p) == Side::Front && map.sector_strictly_containing(p) == Some(line.front.sector)
        }) else {
            continue;
        };
        let angle = (-normal).y.atan2((-normal).x).to_degrees();
        if !try_teleport(&mut game, pos, angle) {
            continue;
        }
        let targets: Vec<usize> = match special.tag {
            0 => line.back.iter().map(|b| b.sector).collect(),
            tag => map.sectors_tagged(tag).collect(),
        };
        let busy = targets.iter().all(|&s| game.is_busy(s));
        game.tick(&TickInput { use_line: true, ..Default::default() });
        let started = game.events().contains(&Event::Special { line: SpecialLine::Wall(i), started: true });
        assert!(
            busy || started,
            "{}: using line {i} ({:?}) set nothing going (targets {targets:?})",
            path.display(),
            special.action
        );
        check_state(&game, path, &format!("after using line {i}"));
        game.tick(&TickInput::default());
        used += 1;
    }
    let start = map.player_start();
    assert!(try_teleport(&mut game, start.pos, start.angle), "{}: the start is taken", path.display());
    game.set_health(1_000_000);
    wake_all(&mut game);
    let compiled = &Observe::level(&game).compiled;
    let spawned: Vec<(DVec2, bool)> = (0..game.sim.mobjs.len() as u32)
        .map(|k| {
            let p = body_pos(&game, MobjId(k));
            (p, compiled.locate(p).is_some())
        })
        .collect();
    for (tick, input) in random_inputs(7, 2_000).iter().enumerate() {
        let fire = (tick / 35) % 3 == 0;
        game.tick(&TickInput { fire, ..*input });
        check_state(&game, path, &format!("random play, tic {tick}"));
        if tick % 50 == 49 {
            check_walls(&game, &spawned, path, &format!("random play, tic {tick}"));
        }
        if game.exit().is_some() {
            break;
        }
    }
    used
}

/// Our BSP renderer agrees with the brute-force reference on a real map
/// (sprites and see-through textures included) from the player start of
/// E1M4, the map Chocolate Doom's demo1 plays.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn e1m4_agrees_with_the_reference() {
    let dir = tempfile::tempdir().unwrap();
    let paths = import_all(&wad_path("freedoom1.wad"), dir.path());
    let path = paths.iter().find(|p| p.ends_with("e1m4.ron")).expect("E1M4 is in freedoom1.wad");
    let level = open_level(path, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    for view in tour(&level, 4, 7) {
        assert_agree(&level, &view, (160, 100), "E1M4");
    }
    let start = level.map.player_start();
    let view = View::at_pose(&level, start.pos.x, start.pos.y, start.angle, None).unwrap();
    let mut fb = Framebuffer::new(320, 200);
    render_frame(
        &level,
        &view,
        &RenderOptions { renderer: Renderer::Bsp, ..Default::default() },
        &mut Frame::new(),
        &mut fb,
    );
}

/// Every map of both IWADs, compiled with the cost and the random splitter,
/// gives a tree `check_invariants` accepts (the tests above render and play
/// the default splitter's trees; this holds both splitters' trees to every
/// invariant). Moved here from the engine's bsp tests so that one build
/// script, in this test-only crate, decides for every test that needs the
/// WADs: one in the engine would recompile the library, and the game above
/// it, whenever `SIGHTLINE_DOOM_DIR` or the WAD directory changes.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn freedoom_maps_compile_to_valid_trees() {
    for file in freedoom_wads::WADS {
        let wad = Wad::open(&wad_path(file)).unwrap_or_else(|e| panic!("{e}"));
        let art = Art::read(&wad).unwrap_or_else(|e| panic!("{e}"));
        for name in wad.map_names() {
            let raw = wad.map(&name).unwrap_or_else(|e| panic!("{e}"));
            let converted = convert(&wad, &raw, &art).unwrap_or_else(|e| panic!("{e}"));
            let map = validate(&converted.source).unwrap_or_else(|problems| panic!("{file} {name}: {problems:?}"));
            for options in [
                BuildOptions { splitter: SplitterKind::Cost, seed: 0 },
                BuildOptions { splitter: SplitterKind::Random, seed: 1 },
            ] {
                let compiled = build(&map, &options).unwrap_or_else(|e| panic!("{file} {name}: {e}"));
                if let Err(e) = check_invariants(&compiled.map, &compiled.bsp) {
                    panic!("{file} {name} with {}: {e}", options.splitter.name());
                }
            }
        }
    }
}

/// The importer on mutated copies of the real freedoom1.wad: bytes of the
/// directory, of E1M1's lumps and of the texture tables overwritten, the
/// file cut short. Every case returns an error or a map, never a panic.
/// (PROPTEST_CASES raises the count; the issue note gives a long run.)
mod fuzz {
    use proptest::prelude::*;
    use sightline::wad::import::{convert, Art};
    use sightline::wad::Wad;

    fn original() -> &'static (Vec<u8>, Vec<(usize, usize)>) {
        static ORIGINAL: std::sync::OnceLock<(Vec<u8>, Vec<(usize, usize)>)> = std::sync::OnceLock::new();
        ORIGINAL.get_or_init(|| {
            let bytes = std::fs::read(super::wad_path("freedoom1.wad")).unwrap();
            let wad = Wad::from_bytes(bytes.clone(), "freedoom1.wad").unwrap();
            // The byte ranges worth mutating: the directory, E1M1's lumps and
            // the tables every texture goes through.
            let table = i32::from_le_bytes(bytes[8..12].try_into().unwrap()) as usize;
            let mut ranges = vec![(0, 12), (table, bytes.len())];
            let e1m1 = wad.lumps.iter().position(|l| l.name == "E1M1").unwrap();
            for l in &wad.lumps[e1m1 + 1..e1m1 + 11] {
                ranges.push((l.offset, l.offset + l.size));
            }
            for name in ["PNAMES", "TEXTURE1", "PLAYPAL"] {
                let l = &wad.lumps[wad.find(name).unwrap()];
                ranges.push((l.offset, l.offset + l.size));
            }
            ranges.retain(|r| r.1 > r.0);
            (bytes, ranges)
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(
            std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(48)
        ))]

        #[test]
        #[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
        fn mutated_freedoom_never_panics(
            edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<prop::sample::Index>(), any::<u8>()), 1..12),
            cut in proptest::option::weighted(0.1, any::<prop::sample::Index>()),
        ) {
            let (original, ranges) = original();
            let mut bytes = original.clone();
            for (range, at, value) in edits {
                let (a, b) = ranges[range.index(ranges.len())];
                bytes[a + at.index(b - a)] = value;
            }
            if let Some(cut) = cut {
                bytes.truncate(cut.index(bytes.len()));
            }
            let Ok(wad) = Wad::from_bytes(bytes, "fuzz.wad") else { return Ok(()) };
            let (Ok(art), Ok(map)) = (Art::read(&wad), wad.map("E1M1")) else { return Ok(()) };
            if let Ok(c) = convert(&wad, &map, &art) {
                let _ = sightline::map::validate::validate(&c.source);
                for t in &c.walls {
                    let _ = sightline::wad::art::compose(&wad, &art.textures[t], &art.palette);
                }
            }
        }
    }
}

/// Imports the one map `name` of `wad` into `dir` with its art; returns its RON path.
fn import_one(wad: &Path, name: &str, dir: &Path) -> PathBuf {
    let wad = Wad::open(wad).unwrap_or_else(|e| panic!("{e}"));
    let art = Art::read(&wad).unwrap_or_else(|e| panic!("{e}"));
    let raw = wad.map(name).unwrap_or_else(|e| panic!("{e}"));
    let c = convert(&wad, &raw, &art).unwrap_or_else(|e| panic!("{e}"));
    let path = dir.join(format!("{}.ron", name.to_ascii_lowercase()));
    std::fs::write(&path, c.source.to_ron()).unwrap();
    write_art(&wad, &art, [&c], dir).unwrap_or_else(|e| panic!("{e}"));
    path
}

/// freedoom2's MAP10, where issue 12 saw random play stand the player
/// exactly on a line between two sectors. (The seeded runs below never land
/// exactly on one, so the test also puts the player there.) Poses exactly on
/// its two-sided lines and at vertices where only such lines meet are
/// accepted and render as the reference does; the game teleports there and
/// plays on; and seeded random play keeps the player in the map, where point
/// location always answers.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn map10_poses_and_play_on_two_sided_lines() {
    let dir = tempfile::tempdir().unwrap();
    let path = import_one(&wad_path("freedoom2.wad"), "MAP10", dir.path());
    let level = open_level(&path, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let frames = assert_agree_on_two_sided_lines(&level, "MAP10", 16, &[(160, 100), (161, 101)]);
    assert!(frames > 300, "MAP10: only {frames} frames from poses on two-sided lines");
    let map = level.map.clone();
    let points = points_on_two_sided_lines(&map);
    assert!(points.len() > 100, "MAP10: only {} points on two-sided lines", points.len());
    let options = GameOptions::default();
    let mut game = SimGame::on_level(level, "MAP10", options).unwrap_or_else(|e| panic!("{e}"));
    let in_map = |game: &SimGame, at: &str| {
        let p = Observe::player(game).pos;
        assert!(
            map.contains(p) && Observe::level(game).locate(p).is_some(),
            "MAP10 {at}: ({:?}, {:?}) not in the map",
            p.x,
            p.y
        );
    };
    let (mut tried, mut stood) = (0, 0);
    for (k, (what, p, directions)) in points.iter().enumerate().step_by(7) {
        // Doom's player is a box 32 wide: on a line near a wall it does
        // not fit, and is not put there.
        tried += 1;
        if !try_teleport(&mut game, *p, directions[0]) {
            continue;
        }
        stood += 1;
        for (tick, input) in random_inputs(k as u64, 35).iter().enumerate() {
            game.tick(input);
            in_map(&game, &format!("{what}, tic {tick} after teleporting there"));
        }
    }
    eprintln!("MAP10: the player stood on {stood} of {tried} points on two-sided lines");
    assert!(stood * 2 > tried, "MAP10: the player stood on only {stood} of {tried} points on two-sided lines");
    assert!(try_teleport(&mut game, map.player_start().pos, map.player_start().angle));
    for seed in 0..4 {
        for (tick, input) in random_inputs(seed, 20_000).iter().enumerate() {
            game.tick(input);
            in_map(&game, &format!("random play seed {seed}, tic {tick}"));
        }
    }
}

/// `sightline play freedoom1.wad`, as the window plays it: E1M1 straight
/// from the WAD (no import step, its art read from the WAD), the exit
/// switch used (the player put in front of it), the intermission with
/// E1M1's tallies, a press, and E1M2 from the WAD; then E1M2's exit leads
/// to E1M3, and E1M3's secret exit to E1M9, which returns to E1M4.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn freedoom1_plays_from_the_wad_through_exits_and_intermissions() {
    use sightline::campaign::MapRef;
    use sightline::play::playthrough::{Phase, Playthrough};
    use sightline::play::{Exit, GameOptions};
    use sightline::sim::intermission::Stage;

    let wad = wad_path("freedoom1.wad");
    let options = GameOptions::default();
    let mut play =
        Playthrough::of(&MapRef::parse(wad.to_str().unwrap(), None), options).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(play.map.short_name(), "E1M1");
    let press = TickInput { use_line: true, ..Default::default() };
    for (exit, next) in [(Exit::Normal, "E1M2"), (Exit::Normal, "E1M3"), (Exit::Secret, "E1M9"), (Exit::Normal, "E1M4")]
    {
        let map = play.game.level().map.clone();
        let wanted = if exit == Exit::Secret { Action::SecretExit } else { Action::Exit };
        // An exit switch, used from in front; or an exit walk line, crossed.
        let (i, line) = map
            .lines
            .iter()
            .enumerate()
            .find(|(_, l)| l.special.as_ref().is_some_and(|s| s.action == wanted && s.on == Activation::Use))
            .unwrap_or_else(|| panic!("{}: no {wanted:?} switch", play.map.short_name()));
        let (a, b) = map.line_points(line);
        let d = (b - a).normalize();
        let normal = DVec2::new(d.y, -d.x);
        // In front, as near as the player's box fits (Doom's use range is
        // 64; the switch's own sector may be too shallow for the box).
        let angle = (-normal).y.atan2((-normal).x).to_degrees();
        let stood = [20.0, 24.0, 32.0, 40.0, 48.0]
            .into_iter()
            .map(|k| (a + b) / 2.0 + normal * k)
            .any(|p| try_teleport(game_mut(&mut play), p, angle));
        assert!(stood, "{}: no room in front of line {i} ({a} to {b})", play.map.short_name());
        // Use must be let go first: a new player starts with it held
        // (G_PlayerReborn's usedown, "don't do anything immediately").
        play.tick(&TickInput::default()).unwrap();
        play.tick(&press).unwrap();
        let Phase::Intermission { exit: ended, next: Some(ref to), ref stats, .. } = play.phase else {
            panic!("{}: using line {i} did not end the level: {:?}", play.map.short_name(), play.phase)
        };
        assert_eq!((ended, to.short_name().as_str()), (exit, next));
        assert!(stats.kills.1 > 0 && stats.items.1 > 0, "no tallies: {stats:?}");
        // Use still held from the switch is no press: the tallies count on.
        for _ in 0..10 {
            play.tick(&press).unwrap();
        }
        let stage = |play: &Playthrough| match &play.phase {
            Phase::Intermission { wi, .. } => Some(wi.stage),
            _ => None,
        };
        assert!(matches!(stage(&play), Some(Stage::Tallies { step: 1, .. })), "{:?}", stage(&play));
        // A press shows the tallies finished, the next the episode's map,
        // the next its last ten tics (Doom 1's intermission).
        let finished = |s: Option<Stage>| matches!(s, Some(Stage::Tallies { step: 10, .. }));
        let next_location = |s| s == Some(Stage::NextLocation { left: 140 });
        let closing = |s| s == Some(Stage::Closing { left: 10 });
        for wanted in [&finished as &dyn Fn(Option<Stage>) -> bool, &next_location, &closing] {
            play.tick(&TickInput::default()).unwrap();
            play.tick(&press).unwrap();
            assert!(wanted(stage(&play)), "{:?}", stage(&play));
        }
        // The next level loads on the tic after the last, and plays it.
        for _ in 0..10 {
            play.tick(&TickInput::default()).unwrap();
        }
        assert_eq!(stage(&play), Some(Stage::Done));
        let before = play.game.sim.gametic;
        play.tick(&TickInput::default()).unwrap();
        assert_eq!((play.game.ticks(), play.game.sim.gametic), (1, before + 1));
        assert_eq!((play.phase.clone(), play.map.short_name()), (Phase::Playing, next.to_string()));
        assert_eq!(play.game.player().health, 100);
    }
}

/// A PWAD played on its IWAD, as `sightline play --iwad freedoom2.wad
/// mymap.wad:MAP01` does: a PWAD holding one map of its own (freedoom2's
/// MAP05, renamed MAP01, as a Doom editor saves a map) and no art opens over
/// the IWAD, its map (not the IWAD's MAP01) with the IWAD's textures. Alone
/// it is refused, naming what it lacks.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn a_pwad_plays_on_its_iwad_without_importing() {
    use sightline::campaign::{open, MapRef};
    let iwad_path = wad_path("freedoom2.wad");
    let iwad = Wad::open(&iwad_path).unwrap();
    let marker = iwad.lumps.iter().position(|l| l.name == "MAP05").unwrap();
    let mut lumps: Vec<(String, Vec<u8>)> = vec![("MAP01".into(), Vec::new())];
    for k in 1..=10 {
        lumps.push((iwad.lumps[marker + k].name.clone(), iwad.bytes(marker + k).to_vec()));
    }
    let tmp = tempfile::tempdir().unwrap();
    let pwad = tmp.path().join("mymap.wad");
    std::fs::write(&pwad, wad_bytes(b"PWAD", &lumps)).unwrap();

    let text = format!("{}:MAP01", pwad.display());
    let opened =
        open(&MapRef::parse(&text, Some(&iwad_path)), &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let theirs = convert(&iwad, &iwad.map("MAP05").unwrap(), &Art::read(&iwad).unwrap()).unwrap();
    assert_eq!(opened.level.map.lines.len(), theirs.source.lines.len(), "not the PWAD's map");
    assert_eq!(opened.map.label(), format!("{}+{}:MAP01", iwad_path.display(), pwad.display()));
    let view = View::at_start(&opened.level).unwrap();
    let mut fb = Framebuffer::new(160, 100);
    render_frame(&opened.level, &view, &RenderOptions::default(), &mut Frame::new(), &mut fb);
    assert!(fb.pixels.iter().collect::<std::collections::BTreeSet<_>>().len() > 100, "a flat frame");
    let err = open(&MapRef::parse(&text, None), &BuildOptions::default()).err().expect("no art without its IWAD");
    assert!(err.to_string().contains("mymap.wad") && err.to_string().contains("PLAYPAL"), "{err}");
}

/// The game of a playthrough on the simulation.
fn game(play: &sightline::play::playthrough::Playthrough) -> &SimGame {
    &play.game
}

fn game_mut(play: &mut sightline::play::playthrough::Playthrough) -> &mut SimGame {
    &mut play.game
}

/// The player's eye as the simulation has it now (between tics, just
/// after a teleport: `SimGame::view` is read at the end of a tic).
fn eye_of(game: &SimGame) -> View {
    let m = game.sim.mo(player_mo(game));
    let viewz = game.sim.players[game.sim.console].as_ref().expect("a player").viewz;
    View::new(DVec2::new(m.x.to_f64(), m.y.to_f64()), viewz.to_f64(), m.angle.to_degrees())
}

/// E1M1's monsters as a game draws them: a zombieman seen from eight sides
/// shows eight different views (Doom's rotations, the mirrored ones
/// included), the BSP renderer agrees with the reference in `ids` shading
/// on each, and the frames are written for a person to look at
/// (`target/e1m1-rotations/`).
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn e1m1_monsters_are_drawn_from_every_side() {
    use sightline::campaign::MapRef;
    use sightline::play::playthrough::Playthrough;

    let wad = wad_path("freedoom1.wad");
    let map = format!("{}:E1M1", wad.display());
    let options = GameOptions::default();
    let mut play = Playthrough::of(&MapRef::parse(&map, None), options).unwrap_or_else(|e| panic!("{e}"));
    play.tick(&TickInput::default()).unwrap();
    let game = &play.game;
    // The first zombieman spawned (bodies are drawn keyed by their index).
    let zombie = game
        .sim
        .live_mobjs()
        .find(|&id| game.sim.info.table.actors[game.sim.mo(id).kind].name == "zombieman")
        .expect("E1M1 has a zombieman");
    let pos = body_pos(game, zombie);
    let drawn = *play.game.level().things.iter().find(|t| t.key == zombie.0 as usize).expect("the zombieman is drawn");
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("e1m1-rotations");
    std::fs::create_dir_all(&out).unwrap();
    let mut seen = Vec::new();
    for k in 0..8 {
        // From direction k+1: 0 is in front of it, then round anticlockwise... as
        // Doom numbers them (1 front, 2 front-left of the viewer, ...).
        let from = drawn.angle + 45.0 * k as f64;
        let (s, c) = from.to_radians().sin_cos();
        let eye = pos + DVec2::new(c, s) * 96.0;
        seen.push(drawn.texture_seen_from(eye));
        if !try_teleport(&mut play.game, eye, from + 180.0) {
            continue;
        }
        let view = eye_of(&play.game);
        let level = play.game.level();
        assert_agree(level, &view, (160, 100), &format!("E1M1 zombieman from side {}", k + 1));
        let mut fb = Framebuffer::new(320, 200);
        render_frame(level, &view, &RenderOptions::default(), &mut Frame::new(), &mut fb);
        std::fs::write(out.join(format!("side{}.png", k + 1)), fb.to_png()).unwrap();
    }
    let distinct: std::collections::BTreeSet<_> = seen.iter().map(|t| t.0).collect();
    assert_eq!(distinct.len(), 8, "the eight sides show {seen:?}");
}

/// The BSP renderer and the reference agree in `ids` shading on frames full
/// of actors: E1M1 and E3M9 (22 hanging things) on skill 4, every monster
/// awake and 70 ticks into the fight, each of up to eight monsters seen
/// from eight sides (every rotation) and every hanging thing from two.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn frames_full_of_actors_agree_with_the_reference() {
    use sightline::campaign::MapRef;
    use sightline::play::playthrough::Playthrough;

    let wad = wad_path("freedoom1.wad");
    let (mut hanging, mut rotations) = (0, std::collections::BTreeSet::new());
    for name in ["E1M1", "E3M9"] {
        let map = format!("{}:{name}", wad.display());
        let options = GameOptions { skill: 4, ..GameOptions::default() };
        let mut play = Playthrough::of(&MapRef::parse(&map, None), options).unwrap_or_else(|e| panic!("{e}"));
        let game = &mut play.game;
        game.set_health(1_000_000);
        wake_all(game);
        for _ in 0..70 {
            play.tick(&TickInput::default()).unwrap();
        }
        let game = &play.game;
        let drawn: std::collections::BTreeSet<usize> = play.game.level().things.iter().map(|t| t.key).collect();
        let mut targets = Vec::new();
        let mut monsters = 0;
        for id in game.sim.live_mobjs().filter(|id| drawn.contains(&(id.0 as usize))) {
            let m = game.sim.mo(id);
            if m.has(mf::SPAWNCEILING) {
                targets.push((id.0 as usize, 2));
                hanging += 1;
            } else if m.has(mf::COUNTKILL) && m.health > 0 && monsters < 8 {
                targets.push((id.0 as usize, 8));
                monsters += 1;
            }
        }
        for (key, sides) in targets {
            let Some(drawn) = play.game.level().things.iter().find(|t| t.key == key).copied() else { continue };
            for k in 0..sides {
                let from = drawn.angle + 360.0 / sides as f64 * k as f64;
                let (s, c) = from.to_radians().sin_cos();
                let eye = drawn.pos + DVec2::new(c, s) * 128.0;
                if !try_teleport(&mut play.game, eye, from + 180.0) {
                    continue;
                }
                let view = eye_of(&play.game);
                rotations.insert(drawn.texture_seen_from(view.pos).0);
                assert_agree(play.game.level(), &view, (160, 100), &format!("{name} thing {key} from {from:.0}"));
                if sides == 2 && k == 0 {
                    // Textured, to look at (hanging things hang).
                    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("actors-in-view");
                    std::fs::create_dir_all(&dir).unwrap();
                    let mut fb = Framebuffer::new(320, 200);
                    render_frame(play.game.level(), &view, &RenderOptions::default(), &mut Frame::new(), &mut fb);
                    std::fs::write(dir.join(format!("{name}-{key}.png")), fb.to_png()).unwrap();
                }
            }
        }
    }
    assert!(hanging >= 15, "only {hanging} hanging things were seen");
    assert!(rotations.len() >= 40, "only {} distinct views were drawn", rotations.len());
}

/// The depth and label buffers in play, as the Python environment reads
/// them: E1M1 on skill 4, every monster awake and 35 ticks into the fight,
/// eight monsters each seen from four sides at 96 units. The BSP walk's
/// buffers equal the reference's wherever the `ids` frames agree (labels
/// exactly, depth to the bit here), and a labelled pixel names a live body:
/// the simulation keys a drawn thing by its body's id, the label is id + 1.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn buffers_in_play_agree_with_the_reference_and_name_bodies() {
    use sightline::campaign::MapRef;
    use sightline::play::playthrough::Playthrough;
    use sightline::render::{Buffers, Shade};

    let wad = wad_path("freedoom1.wad");
    let map = format!("{}:E1M1", wad.display());
    let options = GameOptions { skill: 4, ..GameOptions::default() };
    let mut play = Playthrough::of(&MapRef::parse(&map, None), options).unwrap_or_else(|e| panic!("{e}"));
    play.game.set_health(1_000_000);
    wake_all(&mut play.game);
    for _ in 0..35 {
        play.tick(&TickInput::default()).unwrap();
    }
    let monsters: Vec<MobjId> = {
        let game = &play.game;
        game.sim.live_mobjs().filter(|&id| game.sim.mo(id).has(mf::COUNTKILL)).take(8).collect()
    };
    let size = (160, 100);
    let (mut frames, mut labelled, mut named) = (0, 0, 0);
    for id in monsters {
        let pos = body_pos(&play.game, id);
        for k in 0..4 {
            let from = 90.0 * f64::from(k);
            let (s, c) = from.to_radians().sin_cos();
            let eye = pos + DVec2::new(c, s) * 96.0;
            if !try_teleport(&mut play.game, eye, from + 180.0) {
                continue;
            }
            let view = eye_of(&play.game);
            let level = play.game.level();
            let shot = |renderer| {
                let options = RenderOptions {
                    renderer,
                    shade: Shade::Ids,
                    buffers: Buffers { depth: true, labels: true },
                    ..Default::default()
                };
                let (mut fb, mut frame) = (Framebuffer::new(size.0, size.1), Frame::new());
                render_frame(level, &view, &options, &mut frame, &mut fb);
                (fb, frame.depth().to_vec(), frame.labels().to_vec())
            };
            let (bsp, reference) = (shot(Renderer::Bsp), shot(Renderer::Reference));
            let what = format!("E1M1 body {} from {from}", id.0);
            for i in 0..size.0 * size.1 {
                if bsp.0.pixels[i] != reference.0.pixels[i] {
                    continue;
                }
                assert_eq!(bsp.2[i], reference.2[i], "{what}: labels at {i}");
                assert_eq!(bsp.1[i].to_bits(), reference.1[i].to_bits(), "{what}: depth at {i}");
                if let Some(key) = bsp.2[i].checked_sub(1) {
                    labelled += 1;
                    let body = MobjId(key);
                    assert!(play.game.sim.live_mobjs().any(|m| m == body), "{what}: label {} names no body", key + 1);
                    named += usize::from(body == id);
                }
            }
            assert_agree(level, &view, size, &what);
            frames += 1;
        }
    }
    assert!(
        frames >= 16 && named > 1_000 && labelled >= named,
        "{frames} frames, {labelled} labelled, {named} of the targets"
    );
}

/// E1M1 on skill 3 is a game that can be won: every monster can be
/// fought and killed with the weapons found, and the exit switch ends the
/// level, on the simulation. A scripted fighter (not a person, and it moves by teleporting)
/// stands 128 to 320 units from each monster in turn, at the first spot
/// it can stand on round it from which it sees it, faces it and fires
/// (the shotgun, picked up first with the green armour), backing off from what comes near,
/// nearest monsters first. It takes no cover and no medikits, as a person
/// would: it is healed to 100 between fights and when below 30, and the
/// health so given is printed beside what the map's items hold.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn e1m1_can_be_fought_through_to_its_exit_on_skill_3() {
    use sightline::campaign::MapRef;
    use sightline::play::playthrough::Playthrough;

    let wad = wad_path("freedoom1.wad");
    let map = MapRef::parse(&format!("{}:E1M1", wad.display()), None);
    let options = GameOptions::default();
    let mut play = Playthrough::of(&map, options).unwrap_or_else(|e| panic!("{e}"));
    let table = game(&play).sim.info.table.clone();
    let name = |play: &Playthrough, id: MobjId| table.actors[game(play).sim.mo(id).kind].name.clone();
    let idle = TickInput::default();
    let total = play.game.stats().kills.1;
    assert!(total > 0, "E1M1 has monsters on skill 3");
    let mut healed = 0;
    let heal = |play: &mut Playthrough, to: i32| {
        let game = game_mut(play);
        let health = game.sim.players[0].as_ref().expect("a player").health;
        let more = (to - health).max(0);
        game.set_health(health + more);
        more
    };
    let bodies = |play: &Playthrough| game(play).sim.live_mobjs().collect::<Vec<_>>();
    // The health the map holds (what a person would pick up).
    let supply: i32 = bodies(&play)
        .into_iter()
        .filter_map(|id| match name(&play, id).as_str() {
            "stimpack" => Some(10),
            "medikit" => Some(25),
            "health_bonus" => Some(1),
            "soulsphere" => Some(100),
            _ => None,
        })
        .sum();
    // Doom picks up in a move only (P_TryMove): put beside an item, the
    // fighter walks onto it.
    let fetch = |play: &mut Playthrough, id: MobjId| {
        let at = body_pos(game(play), id);
        for k in 0..8 {
            let from = 45.0 * k as f64;
            let (s, c) = from.to_radians().sin_cos();
            if try_teleport(game_mut(play), at + DVec2::new(c, s) * 40.0, from + 180.0) {
                for _ in 0..20 {
                    if !present(game(play), id) {
                        break;
                    }
                    play.tick(&TickInput { forward: 1, ..TickInput::default() }).unwrap();
                }
                return;
            }
        }
    };
    // The shotgun and the armour first, where they lie.
    for want in ["shotgun", "green_armor"] {
        if let Some(id) = bodies(&play).into_iter().find(|&id| name(&play, id) == want) {
            fetch(&mut play, id);
            assert!(!present(game(&play), id), "the {want} was not picked up");
        }
    }
    for round in 0..3 {
        // Nearest first, from where the fighter stands.
        let here = play.game.player().pos;
        let alive = |play: &Playthrough, id: MobjId| {
            let m = game(play).sim.mo(id);
            present(game(play), id) && m.health > 0 && m.has(mf::COUNTKILL)
        };
        let mut targets: Vec<MobjId> = bodies(&play).into_iter().filter(|&id| alive(&play, id)).collect();
        targets.sort_by(|&i, &j| {
            let d = |k: MobjId| body_pos(game(&play), k).distance(here);
            d(i).total_cmp(&d(j))
        });
        for i in targets {
            // Between fights, healed to 100: a person takes cover and the
            // map's health; the fighter stands in the open and does neither.
            healed += heal(&mut play, 100);
            // Low on ammunition: the nearest box or clip that lies about.
            let ammo = play.game.player().ammo;
            if ammo[1] < 4 && ammo[0] < 20 {
                let here = play.game.player().pos;
                let kinds = ["box_of_shells", "shotgun_shells", "box_of_bullets", "clip"];
                let item = bodies(&play)
                    .into_iter()
                    .filter(|&id| present(game(&play), id) && kinds.contains(&name(&play, id).as_str()))
                    .min_by(|&p, &q| {
                        body_pos(game(&play), p).distance(here).total_cmp(&body_pos(game(&play), q).distance(here))
                    });
                if let Some(id) = item {
                    fetch(&mut play, id);
                }
            }
            // At most 20 s on one monster (a person gives up on one it cannot hit, for now).
            let began = play.game.ticks();
            'spots: for distance in [320.0, 224.0, 128.0] {
                for k in 0..16 {
                    if !alive(&play, i) || play.game.ticks() > began + 700 {
                        break 'spots;
                    }
                    let from = 22.5 * k as f64;
                    let (s, c) = from.to_radians().sin_cos();
                    let eye = body_pos(game(&play), i) + DVec2::new(c, s) * distance;
                    if !try_teleport(game_mut(&mut play), eye, from + 180.0) {
                        continue;
                    }
                    // Only where it can see the monster.
                    let me = player_mo(game(&play));
                    if !sees(game_mut(&mut play), me, i) {
                        continue;
                    }
                    for _ in 0..35 * 3 {
                        if !alive(&play, i) {
                            break 'spots;
                        }
                        // Keep facing it as it moves.
                        let d = body_pos(game(&play), i) - play.game.player().pos;
                        let turn = (d.y.atan2(d.x).to_degrees() - play.game.player().angle + 540.0) % 360.0 - 180.0;
                        let weapon = if play.game.player().ammo[1] > 0 { 3 } else { 0 };
                        // Back off from what comes close, as a person would.
                        let forward = if d.length() < 160.0 { -1 } else { 0 };
                        // Sidestep, a second each way, to dodge missiles.
                        let strafe = if (play.game.ticks() / 35) % 2 == 0 { 1 } else { -1 };
                        let input = TickInput { fire: true, turn: turn as f32, weapon, forward, strafe, ..idle };
                        play.tick(&input).unwrap();
                        if play.game.player().health < 30 {
                            healed += heal(&mut play, 100);
                        }
                        assert!(
                            !play.game.player().dead(),
                            "round {round}: the fighter died facing body {} ({}), kills {:?}, tic {}",
                            i.0,
                            name(&play, i),
                            play.game.stats().kills,
                            play.game.ticks()
                        );
                    }
                }
            }
        }
    }
    let kills = play.game.stats().kills;
    let left: Vec<String> = bodies(&play)
        .into_iter()
        .filter(|&id| game(&play).sim.mo(id).health > 0 && game(&play).sim.mo(id).has(mf::COUNTKILL))
        .map(|id| {
            let m = game(&play).sim.mo(id);
            format!("{} at {} (target {:?})", name(&play, id), body_pos(game(&play), id), m.target)
        })
        .collect();
    assert_eq!(kills.0, kills.1, "monsters left alive: {left:?}");
    // The exit switch, used from in front.
    let level_map = play.game.level().compiled.map.clone();
    let (i, line) = level_map
        .lines
        .iter()
        .enumerate()
        .find(|(_, l)| l.special.as_ref().is_some_and(|s| s.action == Action::Exit))
        .expect("E1M1 has an exit line");
    let (a, b) = level_map.line_points(line);
    let d = (b - a).normalize();
    let normal = DVec2::new(d.y, -d.x);
    let angle = (-normal).y.atan2((-normal).x).to_degrees();
    assert!(try_teleport(game_mut(&mut play), (a + b) / 2.0 + normal * 20.0, angle), "line {i}: no room in front");
    play.tick(&TickInput { use_line: true, ..idle }).unwrap();
    assert_eq!(play.game.exit(), Some(sightline::play::Exit::Normal), "the exit switch did not end the level");
    eprintln!(
        "E1M1: {kills:?} kills, health {} at the exit; healed {healed} in all, the map holds {supply}",
        play.game.player().health
    );
}
