//! Checks of the RON map -> simulation level conversion: point location
//! through Doom's nodes against the map's own (BSP-free) point location on
//! every shipped sector map, the blockmap against a brute-force segment/box
//! test, the coordinate and blockmap limits, the reverse of Doom's special
//! numbers, and a game walking on two shipped maps.

use std::path::{Path, PathBuf};

use glam::DVec2;

use super::*;
use crate::bsp::{build, BuildOptions};
use crate::level::open_compiled;
use crate::map::parse_map;
use crate::play::lmp::Ticcmd;
use crate::sim::mobj::point_in_subsector;
use crate::sim::{GameMode, GameVersion, MAXPLAYERS};

fn maps_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../maps")
}

/// Every shipped map, compiled; grid maps and sector maps alike.
fn shipped() -> Vec<(String, CompiledMap)> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(maps_dir())
        .expect("the maps folder")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 10, "the shipped maps are missing: {paths:?}");
    paths
        .iter()
        .map(|p| {
            let compiled =
                open_compiled(p, &BuildOptions::default()).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            (p.display().to_string(), compiled)
        })
        .collect()
}

/// The shipped maps Doom's format can hold: all but `nasty.ron`, whose
/// vertices reach a million units on purpose (and which must be refused).
fn convertible() -> Vec<(String, CompiledMap)> {
    let mut out = Vec::new();
    for (path, compiled) in shipped() {
        match level_from_map(&compiled, ActorTable::doom()) {
            Ok(_) => out.push((path, compiled)),
            Err(FromMapError::OutOfRange { .. }) if path.ends_with("nasty.ron") => {}
            Err(e) => panic!("{path}: {e}"),
        }
    }
    assert!(out.iter().all(|(p, _)| !p.ends_with("nasty.ron")), "nasty.ron was not refused");
    out
}

fn sector_maps() -> Vec<(String, CompiledMap)> {
    let maps: Vec<_> = convertible().into_iter().filter(|(_, c)| c.grid.is_none()).collect();
    assert!(maps.len() >= 8, "fewer sector maps than shipped");
    maps
}

fn convert(path: &str, compiled: &CompiledMap) -> FromMap {
    level_and_report(compiled, ActorTable::doom()).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// A point on the 1/256 grid: exact both as f64 and in 16.16.
fn snap(p: DVec2) -> DVec2 {
    (p * 256.0).round() / 256.0
}

/// Points to try: a lattice over the map at an odd offset, and a point
/// half a unit inside each side of each line at its middle (so thin
/// sectors and doors get samples too).
fn samples(compiled: &CompiledMap) -> Vec<DVec2> {
    let map = &compiled.map;
    let mut min = DVec2::splat(f64::INFINITY);
    let mut max = DVec2::splat(f64::NEG_INFINITY);
    for v in &map.vertices {
        min = min.min(*v);
        max = max.max(*v);
    }
    let mut out = Vec::new();
    let mut y = min.y + 3.25;
    while y < max.y {
        let mut x = min.x + 5.75;
        while x < max.x {
            out.push(DVec2::new(x, y));
            x += 16.0;
        }
        y += 16.0;
    }
    for line in &map.lines {
        let (a, b) = map.line_points(line);
        let d = (b - a).normalize();
        let right = DVec2::new(d.y, -d.x) * 0.5;
        let mid = (a + b) / 2.0;
        out.push(snap(mid + right));
        out.push(snap(mid - right));
    }
    out
}

#[test]
fn every_sample_lands_in_the_same_sector_through_doom_s_nodes() {
    for (path, compiled) in sector_maps() {
        let level = convert(&path, &compiled).level;
        let mut seen = vec![false; level.sectors.len()];
        let mut checked = 0;
        for p in samples(&compiled) {
            let Some(want) = compiled.map.sector_strictly_containing(p) else { continue };
            let (x, y) = fixed_point(p);
            assert_eq!((x.to_f64(), y.to_f64()), (p.x, p.y), "{path}: sample {p} is not exact in 16.16");
            let ss = point_in_subsector(&level, x, y);
            let got = level.subsectors[ss].sector;
            assert_eq!(
                got, want,
                "{path}: ({}, {}) is in sector {want}, Doom's nodes say {got} (subsector {ss})",
                p.x, p.y
            );
            assert_eq!(compiled.sector_at(p), want, "{path}: the compiled BSP disagrees at {p}");
            seen[want] = true;
            checked += 1;
        }
        let missed: Vec<usize> = seen.iter().enumerate().filter(|(_, s)| !**s).map(|(i, _)| i).collect();
        assert!(missed.is_empty(), "{path}: no sample fell in sectors {missed:?}");
        assert!(checked > 100, "{path}: only {checked} samples");
    }
}

#[test]
fn the_tree_has_doom_s_shape() {
    for (path, compiled) in sector_maps() {
        let level = convert(&path, &compiled).level;
        assert_eq!(level.nodes.len(), compiled.bsp.nodes.len(), "{path}");
        assert_eq!(level.subsectors.len(), compiled.bsp.leaves.len(), "{path}");
        // Post-order: every node's node children come before it, so the
        // root, which R_PointInSubsector starts from, is the last.
        if level.nodes.is_empty() {
            // One convex room: R_PointInSubsector answers subsector 0.
            assert_eq!(level.subsectors.len(), 1, "{path}: no nodes but several subsectors");
            continue;
        }
        let mut parents = vec![0; level.nodes.len()];
        for (i, node) in level.nodes.iter().enumerate() {
            for child in node.children {
                if child & NF_SUBSECTOR == 0 {
                    assert!(usize::from(child) < i, "{path}: node {i} has a later child {child}");
                    parents[usize::from(child)] += 1;
                } else {
                    assert!(usize::from(child & !NF_SUBSECTOR) < level.subsectors.len(), "{path}");
                }
            }
        }
        let roots: Vec<usize> = parents.iter().enumerate().filter(|(_, &p)| p == 0).map(|(i, _)| i).collect();
        assert_eq!(roots, [level.nodes.len() - 1], "{path}: the root is not the last node alone");
        for (i, ss) in level.subsectors.iter().enumerate() {
            for seg in &level.segs[ss.firstline..ss.firstline + ss.numlines] {
                assert_eq!(seg.frontsector, ss.sector, "{path}: subsector {i} holds a seg of another sector");
                assert_eq!(level.sides[seg.sidedef].sector, seg.frontsector, "{path}");
            }
        }
        // Every line has its sectors' lines lists and a front side.
        for (i, line) in level.lines.iter().enumerate() {
            let front = line.frontsector.expect("a front sector");
            assert!(level.sectors[front].lines.contains(&i), "{path}: line {i} not in its sector's list");
        }
    }
}

/// Does the closed segment `a`-`b` touch the closed square with corners
/// `lo` and `hi`? An end inside, or a crossing of one of its edges; exact
/// in integers (16.16 raw values).
fn segment_touches_square(a: (i64, i64), b: (i64, i64), lo: (i64, i64), hi: (i64, i64)) -> bool {
    let inside = |p: (i64, i64)| p.0 >= lo.0 && p.0 <= hi.0 && p.1 >= lo.1 && p.1 <= hi.1;
    if inside(a) || inside(b) {
        return true;
    }
    let corners = [lo, (hi.0, lo.1), hi, (lo.0, hi.1)];
    (0..4).any(|i| segments_meet(a, b, corners[i], corners[(i + 1) % 4]))
}

fn orient(a: (i64, i64), b: (i64, i64), c: (i64, i64)) -> i128 {
    (i128::from(b.0 - a.0) * i128::from(c.1 - a.1) - i128::from(b.1 - a.1) * i128::from(c.0 - a.0)).signum()
}

fn segments_meet(p1: (i64, i64), p2: (i64, i64), q1: (i64, i64), q2: (i64, i64)) -> bool {
    let within = |a: (i64, i64), b: (i64, i64), c: (i64, i64)| {
        c.0 >= a.0.min(b.0) && c.0 <= a.0.max(b.0) && c.1 >= a.1.min(b.1) && c.1 <= a.1.max(b.1)
    };
    let (d1, d2) = (orient(q1, q2, p1), orient(q1, q2, p2));
    let (d3, d4) = (orient(p1, p2, q1), orient(p1, p2, q2));
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    (d1 == 0 && within(q1, q2, p1))
        || (d2 == 0 && within(q1, q2, p2))
        || (d3 == 0 && within(p1, p2, q1))
        || (d4 == 0 && within(p1, p2, q2))
}

fn raw(p: (Fixed, Fixed)) -> (i64, i64) {
    (i64::from(p.0 .0), i64::from(p.1 .0))
}

/// Every cell lists exactly the lines whose segment touches it, after
/// Doom's leading 0.
fn assert_blockmap_exact(what: &str, level_lines: &[Line], bm: &Blockmap) {
    for cy in 0..bm.height {
        for cx in 0..bm.width {
            let mut listed = bm.lines(cx, cy);
            assert_eq!(listed.next(), Some(0), "{what}: cell ({cx}, {cy}) does not start with Doom's 0");
            let listed: Vec<usize> = listed.collect();
            let lo = (i64::from(bm.orgx.0) + i64::from(cx) * BLOCK, i64::from(bm.orgy.0) + i64::from(cy) * BLOCK);
            let hi = (lo.0 + BLOCK, lo.1 + BLOCK);
            let want: Vec<usize> = (0..level_lines.len())
                .filter(|&i| segment_touches_square(raw(level_lines[i].v1), raw(level_lines[i].v2), lo, hi))
                .collect();
            assert_eq!(listed, want, "{what}: cell ({cx}, {cy})");
        }
    }
}

#[test]
fn the_blockmap_lists_each_line_in_every_cell_it_touches() {
    for (path, compiled) in convertible() {
        let level = convert(&path, &compiled).level;
        let bm = &level.blockmap;
        let min_x = level.lines.iter().flat_map(|l| [l.v1.0, l.v2.0]).min().expect("lines");
        let min_y = level.lines.iter().flat_map(|l| [l.v1.1, l.v2.1]).min().expect("lines");
        assert_eq!((bm.orgx, bm.orgy), (Fixed::from_int(min_x.to_int()), Fixed::from_int(min_y.to_int())), "{path}");
        assert_eq!(&bm.words[..4], &[min_x.to_int() as i16, min_y.to_int() as i16, bm.width as i16, bm.height as i16]);
        assert_blockmap_exact(&path, &level.lines, bm);
    }
}

/// A line from `a` to `b` in whole units, with nothing else set.
fn bare_line(a: (i32, i32), b: (i32, i32)) -> Line {
    let f = |(x, y): (i32, i32)| (Fixed::from_int(x), Fixed::from_int(y));
    Line::new((f(a), f(b)), 0, 0, 0, [Some(0), None], [Some(0), None])
}

#[test]
fn lines_along_cell_edges_and_through_corners_are_in_every_cell_they_touch() {
    let lines = vec![
        bare_line((0, 0), (512, 512)),     // through every corner on the diagonal
        bare_line((128, 0), (128, 300)),   // along a cell edge
        bare_line((0, 256), (384, 256)),   // along a cell edge, ending on a corner
        bare_line((5, 500), (500, 7)),     // a long diagonal
        bare_line((300, 300), (301, 302)), // short, inside one cell
        bare_line((0, 130), (260, 129)),   // nearly horizontal, just above an edge
    ];
    let bm = build_blockmap("edges", &lines).expect("a small blockmap");
    assert_eq!((bm.width, bm.height), (5, 5));
    assert_blockmap_exact("edges", &lines, &bm);
    // The diagonal through (128, 128) touches the four cells around it.
    for (cx, cy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        assert!(bm.lines(cx, cy).skip(1).any(|l| l == 0), "cell ({cx}, {cy})");
    }
}

#[test]
fn a_vertex_beyond_doom_s_range_is_refused_with_its_name() {
    let text = std::fs::read_to_string(maps_dir().join("room.ron")).expect("maps/room.ron");
    let text = text.replace("(768.0, 512.0)", "(40000.0, 512.0)");
    assert!(text.contains("40000.0"), "the fixture changed: maps/room.ron has no (768.0, 512.0)");
    let map = parse_map(&text, "room-wide.ron").expect("a wide room is a valid map");
    let compiled = build(&map, &BuildOptions::default()).expect("and compiles");
    let err = level_from_map(&compiled, ActorTable::doom()).expect_err("40000 is beyond Doom's range");
    let message = err.to_string();
    for part in ["Single room", "vertex 3", "40000", "32767"] {
        assert!(message.contains(part), "`{message}` does not name {part}");
    }
}

#[test]
fn a_map_too_wide_for_the_blockmap_is_refused() {
    // Within ±32767, but 60000 units square is 469x469 cells: 220,000
    // offsets alone.
    let lines = vec![bare_line((-30000, -30000), (30000, 30000)), bare_line((30000, 30000), (-30000, -29000))];
    let err = build_blockmap("wide", &lines).expect_err("too many cells");
    let message = err.to_string();
    assert!(message.contains("wide") && message.contains("65536") && message.contains("469x469"), "{message}");
    // A map that fits: 4096 units square is 33x33 cells.
    let lines = vec![bare_line((0, 0), (4096, 4096)), bare_line((4096, 0), (0, 4096))];
    let bm = build_blockmap("fits", &lines).expect("fits");
    assert_blockmap_exact("fits", &lines, &bm);
}

#[test]
fn every_vanilla_special_comes_back_as_a_number_that_means_the_same() {
    for n in 1..=141u16 {
        for tag in [0u16, 7] {
            let Ok(Effect::Special(s)) = translate(n, tag) else { continue };
            let special =
                LineSpecial { on: s.on, repeat: s.repeat, by: s.by, tag: s.tag as u16, action: s.action.clone() };
            let Ok((m, note)) = doom_line_special(&special) else {
                // A tagged special given tag 0 moves every untagged sector
                // in Doom; the typed special means the sector behind the line.
                assert!(tag == 0 && s.action.moves_sectors(), "special {n} tag {tag} found no number");
                continue;
            };
            let Ok(Effect::Special(back)) = translate(m, tag) else { panic!("{m} is not a special") };
            if note.is_some() {
                // Only a tagged number given tag 0 falls back to the manual
                // one of the same action, which differs in who sets it off.
                assert!(tag == 0 && s.action.moves_sectors(), "special {n} tag {tag}: {note:?}");
                assert_eq!((back.on, back.repeat, &back.action), (s.on, s.repeat, &s.action), "{n} came back as {m}");
                continue;
            }
            assert_eq!(back, s, "special {n} tag {tag} came back as {m}");
        }
    }
    for n in 0..=17i16 {
        let Ok(s) = sector_special(n) else { continue };
        let m = doom_sector_type(&s).expect("a vanilla type comes back");
        assert_eq!(sector_special(m).ok(), Some(s), "sector type {n} came back as {m}");
    }
}

#[test]
fn outpost_s_specials_take_doom_s_numbers() {
    let path = maps_dir().join("outpost.ron");
    let compiled = open_compiled(&path, &BuildOptions::default()).expect("maps/outpost.ron");
    let FromMap { level, report } = convert("outpost", &compiled);
    let special_of = |i: usize| (level.lines[i].special, level.lines[i].tag);
    let line_with = |f: &dyn Fn(&crate::map::Line) -> bool| {
        compiled.map.lines.iter().position(f).expect("the line is in outpost.ron")
    };
    use crate::map::special::{Action, DoorKind, KeyColour};
    let blue = line_with(
        &|l| matches!(&l.special, Some(s) if matches!(s.action, Action::Door { key: Some(KeyColour::Blue), .. })),
    );
    assert_eq!(special_of(blue), (26, 0));
    let remote = line_with(&|l| matches!(&l.special, Some(s) if s.tag == 2));
    assert_eq!(special_of(remote), (103, 2));
    let secret = line_with(
        &|l| matches!(&l.special, Some(s) if matches!(s.action, Action::Door { kind: DoorKind::Open, .. }) && s.tag == 0),
    );
    assert_eq!(special_of(secret), (31, 0));
    let exit = line_with(&|l| matches!(&l.special, Some(s) if s.action == Action::Exit));
    assert_eq!(special_of(exit), (11, 0));
    // The teleporter is for the player alone here (Doom's 97 takes monsters
    // too), and the switch lift for anyone (Doom's 62 for players): no
    // number says either, so both are generalized, their trigger kept.
    use crate::map::{Activation, Who};
    let generalized = |i: usize| level.generalized.line(level.lines[i].special).cloned();
    let teleport = line_with(&|l| matches!(&l.special, Some(s) if s.action == Action::Teleport));
    let g = generalized(teleport).expect("a generalized teleporter");
    assert_eq!((g.on, g.repeat, g.by, level.lines[teleport].tag), (Activation::Walk, true, Who::Players, 3));
    let lift = line_with(&|l| matches!(&l.special, Some(s) if s.on == Activation::Use && s.tag == 1));
    let g = generalized(lift).expect("a generalized lift");
    assert_eq!((g.on, g.repeat, g.by, level.lines[lift].tag), (Activation::Use, true, Who::Anyone, 1));
    assert!(!report.iter().any(|n| n.element.starts_with("line")), "{report:?}");
    let types: Vec<i16> = level.sectors.iter().map(|s| s.special).collect();
    assert_eq!((types[4], types[9], types[13]), (7, 17, 9), "slime, flicker, secret");
    // The roster's monsters have no Doom editor numbers: they are stored
    // under numbers from the top of the 16-bit range, and spawn.
    assert!(!report.iter().any(|n| n.what.contains("`sentry`")), "{report:?}");
    let table = ActorTable::doom();
    let sentry = table.index("sentry").expect("the roster's sentry");
    let number = crate::sim::info::editor_number(&table.actors[sentry], sentry).expect("a number");
    assert!(number > 32767, "{number}");
    let sentries = compiled.map.things.iter().filter(|t| t.kind == "sentry").count();
    assert!(sentries > 0 && level.things.iter().filter(|t| t.kind == number).count() == sentries);
}

fn walk(path: &str, tics: usize) {
    let compiled = open_compiled(&maps_dir().join(path), &BuildOptions::default()).expect(path);
    let level = convert(path, &compiled).level;
    let rules = Rules::single(2, GameVersion::Doom19, GameMode::Commercial);
    let mut in_game = [false; MAXPLAYERS];
    in_game[0] = true;
    let mut sim = sim_on_map(level, rules, Players { in_game, console: 0 }, ActorTable::doom().clone());
    let body = sim.player(0).expect("player 1 spawned at the map's start").mo;
    let start = (sim.mo(body).x, sim.mo(body).y);
    let start_thing = &compiled.map.player_start().pos;
    assert_eq!(start, fixed_point(*start_thing), "{path}: the player is not at the start");
    let mut cmds = [None; MAXPLAYERS];
    cmds[0] = Some(Ticcmd { forward: 25, ..Ticcmd::default() });
    let mut moved_at = None;
    for tic in 0..tics {
        sim.tick(&cmds);
        let mo = sim.mo(body);
        if moved_at.is_none() && (mo.x, mo.y) != start {
            moved_at = Some(tic);
        }
    }
    let mo = sim.mo(body);
    assert!(moved_at.is_some_and(|t| t < 5), "{path}: the player did not move ({moved_at:?})");
    let end = DVec2::new(mo.x.to_f64(), mo.y.to_f64());
    assert!(
        compiled.map.contains(end) || compiled.map.distance_to_nearest_line(end) < 1.0,
        "{path}: walked out to {end}"
    );
    assert_eq!(sim.leveltime as usize, tics);
}

#[test]
fn a_game_walks_on_outpost() {
    walk("outpost.ron", 350);
}

#[test]
fn a_game_walks_on_machinery() {
    walk("machinery.ron", 350);
}
