//! Sight on the simulation (`sim::sight`, Doom's `P_CheckSight`: REJECT,
//! then the trace down the BSP, `P_CrossBSPNode`) agrees with a brute-force
//! check by the same rule over every line of the level, on the hard cases:
//! eyes and targets exactly on lines and vertices, lines of sight through
//! corners and along faces, a hand-built map at the origin and at ±30,000,
//! a 60,000-unit room (within 16.16 fixed point's ±32,768), and Freedoom's
//! E1M1 and MAP01 (their own WAD nodes, vanilla rules), before and after
//! every door and lift is opened.
//!
//! The brute force keeps Doom's per-line test (`P_CrossSubsector`: the
//! line's ends on different sides of the trace and the trace's ends on
//! different sides of the line, by `P_DivlineSide`, whose "on" answer
//! counts as a side) and its slopes; it differs only in asking every line
//! rather than those of the subsectors the tree leads to. Because the
//! slopes only ever narrow, the order lines are met in cannot change the
//! answer.
//!
//! Exact ties (through a corner, along a face, from a ledge's edge, the
//! same point) are compared in tables with Doom's answers. Random pairs
//! are compared away from ties only: within a unit and a half of a line or
//! its end `P_DivlineSide` rounds, and the answer there depends on which
//! subsectors the tree visits, which no brute force reproduces; those
//! pairs are counted as `fuzzy`. On Freedoom's maps vanilla's typo in
//! `P_DivlineSide` is switched off (Sightline's rules) for the same reason.
//!
//! The f64 sight the autopilot plans with (`autopilot::sight`, once the
//! f64 game's) keeps its own unit tests. Dropped here with the f64 game:
//! its shots and aim (deleted with it), the agreement on random maps of both splitters
//! (a random map's sectors can be too thin for Doom's fixed-point
//! arithmetic and its `Scratch` reuse), and its f64 tie rules on moved
//! heights as a map edit: the simulation's shots are
//! `P_AimLineAttack`/`P_LineAttack` over `P_PathTraverse`, held to
//! Chocolate Doom by `demo_sync.rs`.

use glam::DVec2;
use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use sightline::bsp::{build, BuildOptions, CompiledMap};
use sightline::fixed::{intercept_vector, Divline, Fixed};
use sightline::map::source::{MapSource, SectorSource, ThingSource};
use sightline::map::validate::validate;
use sightline::map::PLAYER_START;
use sightline::play::GameOptions;
use sightline::sim::game::SimGame;
use sightline::sim::level::ml;
use sightline::sim::mobj::point_in_subsector;
use sightline::sim::sight::divline_side;
use sightline::sim::{Compat, MobjId, Sim};
use sightline_tests::freedoom_wads;

/// What a run of pairs met and answered.
#[derive(Debug, Default)]
struct Tally {
    pairs: usize,
    seen: usize,
    hidden: usize,
    /// Pairs whose trace passes exactly through a line's end, and pairs
    /// that start or end exactly on a line (all drawn; those within
    /// P_DivlineSide's rounding are among the `fuzzy`).
    through_vertex: usize,
    on_line: usize,
    /// Pairs within P_DivlineSide's rounding of a line or its end, not
    /// compared (see `check_pairs`).
    fuzzy: usize,
}

/// Doom's sight rule over every line of the level, without the tree.
fn sight_brute(sim: &Sim, looker: MobjId, target: MobjId) -> bool {
    let (s1, s2) = (sim.sector_of(looker), sim.sector_of(target));
    if sim.level.rejected(s1, s2) {
        return false;
    }
    let typo = sim.rules.compat == Compat::Vanilla;
    let (t1, t2) = (sim.mo(looker), sim.mo(target));
    let zstart = t1.z + t1.height - (t1.height >> 2);
    let (mut top, mut bottom) = (t2.z + t2.height - zstart, t2.z - zstart);
    let trace = Divline { x: t1.x, y: t1.y, dx: t2.x - t1.x, dy: t2.y - t1.y };
    for line in &sim.level.lines {
        let (v1, v2) = (line.v1, line.v2);
        if divline_side(v1.0, v1.1, &trace, typo) == divline_side(v2.0, v2.1, &trace, typo) {
            continue;
        }
        let divl = Divline { x: v1.0, y: v1.1, dx: v2.0 - v1.0, dy: v2.1 - v1.1 };
        if divline_side(trace.x, trace.y, &divl, typo) == divline_side(t2.x, t2.y, &divl, typo) {
            continue;
        }
        let (Some(front), Some(back)) = (line.frontsector, line.backsector) else { return false };
        if line.flags & ml::TWOSIDED == 0 {
            return false;
        }
        let (f, b) = (&sim.level.sectors[front], &sim.level.sectors[back]);
        if f.floorheight == b.floorheight && f.ceilingheight == b.ceilingheight {
            continue;
        }
        let opentop = f.ceilingheight.min(b.ceilingheight);
        let openbottom = f.floorheight.max(b.floorheight);
        if openbottom >= opentop {
            return false;
        }
        let frac = intercept_vector(&trace, &divl);
        if f.floorheight != b.floorheight {
            bottom = bottom.max((openbottom - zstart) / frac);
        }
        if f.ceilingheight != b.ceilingheight {
            top = top.min((opentop - zstart) / frac);
        }
        if top <= bottom {
            return false;
        }
    }
    true
}

/// A game on `compiled` (a RON map's tree converted by `sim::from_map`).
fn game_on(compiled: CompiledMap, label: &str) -> SimGame {
    let level = sightline::level::Level::with_builtin_textures(compiled).unwrap_or_else(|e| panic!("{e}"));
    let options = GameOptions { no_monsters: true, ..Default::default() };
    SimGame::on_level(level, label, options).unwrap_or_else(|e| panic!("{label}: {e}"))
}

/// Two bodies to look between, spawned once and moved for each pair.
fn two_bodies(game: &mut SimGame) -> (MobjId, MobjId) {
    let kind = game.sim.info.table.index("zombieman").expect("the zombieman");
    let a = game.sim.spawn_mobj(Fixed::ZERO, Fixed::ZERO, Fixed::ZERO, kind);
    let b = game.sim.spawn_mobj(Fixed::ZERO, Fixed::ZERO, Fixed::ZERO, kind);
    (a, b)
}

/// Puts `id` at `p` (feet at `z`, `height` tall), in the subsector there.
fn place(sim: &mut Sim, id: MobjId, p: DVec2, z: f64, height: f64) {
    let (x, y) = (Fixed::from_f64(p.x), Fixed::from_f64(p.y));
    let subsector = point_in_subsector(&sim.level, x, y);
    let m = sim.mo_mut(id);
    (m.x, m.y, m.z, m.height, m.subsector) = (x, y, Fixed::from_f64(z), Fixed::from_f64(height), subsector);
}

/// Sight from `a` to `b` by the tree, which must agree with the brute force.
fn sees(sim: &mut Sim, a: MobjId, b: MobjId, what: &dyn Fn() -> String) -> bool {
    let fast = sightline::sim::sight::check_sight(sim, a, b);
    assert_eq!(fast, sight_brute(sim, a, b), "{}", what());
    fast
}

/// A random point of `map`: anywhere in (or a little beyond) its bounds, in
/// it, exactly on a vertex, exactly on a line, or a hair from a vertex.
fn point(level: &CompiledMap, r: &mut ChaCha8Rng) -> DVec2 {
    let map = &level.map;
    let (lo, hi) =
        map.vertices.iter().fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let pad = (hi - lo) * 0.05;
    let uniform = |r: &mut ChaCha8Rng| {
        DVec2::new(r.random_range(lo.x - pad.x..=hi.x + pad.x), r.random_range(lo.y - pad.y..=hi.y + pad.y))
    };
    match r.random_range(0..10) {
        0..=1 => uniform(r),
        2..=5 => (0..50).map(|_| uniform(r)).find(|&p| map.contains(p)).unwrap_or_else(|| uniform(r)),
        6 => map.vertices[r.random_range(0..map.vertices.len())],
        7 | 8 => {
            let line = &map.lines[r.random_range(0..map.lines.len())];
            let (a, b) = map.line_points(line);
            a + (b - a) * [0.25, 0.5, 0.75, 1.0 / 3.0][r.random_range(0..4)]
        }
        _ => {
            let v = map.vertices[r.random_range(0..map.vertices.len())];
            v + DVec2::new(r.random_range(-1.0..=1.0), r.random_range(-1.0..=1.0))
                * 1e-6
                * v.abs().max_element().max(1.0)
        }
    }
}

/// Two points: independent, through a vertex exactly (where the arithmetic
/// allows), along a line's extension, starting on a line, or the same.
fn pair(level: &CompiledMap, r: &mut ChaCha8Rng) -> (DVec2, DVec2) {
    let map = &level.map;
    match r.random_range(0..10) {
        0..=4 => (point(level, r), point(level, r)),
        5 | 6 => {
            let p = point(level, r);
            let v = map.vertices[r.random_range(0..map.vertices.len())];
            (p, v + (v - p) * [1.0, 0.5, 2.0, 0.25][r.random_range(0..4)])
        }
        7 => {
            let line = &map.lines[r.random_range(0..map.lines.len())];
            let (a, b) = map.line_points(line);
            let mut t = || [-1.5, -0.5, 0.0, 0.25, 0.5, 1.0, 1.25, 2.0][r.random_range(0..8)];
            (a + (b - a) * t(), a + (b - a) * t())
        }
        8 => {
            let p = point(level, r);
            (p, p)
        }
        9 if r.random_bool(0.5) => {
            // Ending exactly where the compiler cut a line (a seg's end off
            // the map's vertices, within rounding of a partition): where the
            // descent needs its margin.
            let seg = &level.bsp.segs[r.random_range(0..level.bsp.segs.len())];
            (point(level, r), if r.random_bool(0.5) { seg.v1 } else { seg.v2 })
        }
        _ => {
            let line = &map.lines[r.random_range(0..map.lines.len())];
            let (a, b) = map.line_points(line);
            (a + (b - a) * 0.5, point(level, r))
        }
    }
}

/// A random height for a body's feet at `p`: on the floor of the sector
/// there (as the simulation's level has it), or off it; and a height.
fn feet(sim: &Sim, r: &mut ChaCha8Rng, p: DVec2) -> (f64, f64) {
    let sub = point_in_subsector(&sim.level, Fixed::from_f64(p.x), Fixed::from_f64(p.y));
    let floor = sim.level.sectors[sim.level.subsectors[sub].sector].floorheight.to_f64();
    let z = if r.random_bool(0.7) { floor } else { floor + r.random_range(-64.0..=64.0) };
    (z, [56.0, 16.0, 0.0, 120.0][r.random_range(0..4)])
}

/// `n` random pairs on `game`'s map (`level` its compiled tree, where the
/// pairs are drawn): sight both ways, by the tree and by brute force.
fn check_pairs(game: &mut SimGame, level: &CompiledMap, seed: u64, n: usize, what: &str) -> Tally {
    let map = &level.map;
    let (a, b) = two_bodies(game);
    let mut r = ChaCha8Rng::seed_from_u64(seed);
    let mut tally = Tally::default();
    for k in 0..n {
        let (p, q) = pair(level, &mut r);
        let (za, ha) = feet(&game.sim, &mut r, p);
        let (zb, hb) = feet(&game.sim, &mut r, q);
        place(&mut game.sim, a, p, za, ha);
        place(&mut game.sim, b, q, zb, hb);
        tally.pairs += 1;
        let on = |v: DVec2, a: DVec2, b: DVec2| (b - a).perp_dot(v - a) == 0.0;
        let lines = map.lines.iter().map(|l| map.line_points(l));
        let within = |v: DVec2, a: DVec2, b: DVec2| (v - a).dot(b - a) >= 0.0 && (v - b).dot(a - b) >= 0.0;
        let mut through = false;
        let mut online = false;
        for (la, lb) in lines {
            through |= p != q && [la, lb].iter().any(|&v| on(v, p, q) && within(v, p, q));
            online |= [p, q].iter().any(|&v| on(v, la, lb) && within(v, la, lb));
        }
        tally.through_vertex += usize::from(through);
        tally.on_line += usize::from(online);
        // Within a unit and a half of a line's end (or an end within that
        // of a line) P_DivlineSide, which drops both factors' fractions,
        // may call a point "on" or on the wrong side: there the tree's
        // answer depends on which subsectors it visits, and no brute force
        // over every line reproduces it. Such pairs are counted, not
        // compared; the table of exact ties above compares its own.
        let near = |v: DVec2, a: DVec2, b: DVec2| {
            let d = b - a;
            let t = if d == DVec2::ZERO { 0.0 } else { ((v - a).dot(d) / d.length_squared()).clamp(0.0, 1.0) };
            v.distance(a + d * t) < 1.5
        };
        let fuzzy = map.lines.iter().any(|l| {
            let (la, lb) = map.line_points(l);
            (p != q && (near(la, p, q) || near(lb, p, q))) || near(p, la, lb) || near(q, la, lb)
        });
        if fuzzy {
            tally.fuzzy += 1;
            continue;
        }
        let at = || {
            format!("{what}, pair {k}: ({:?}, {:?}) z {za} h {ha} -> ({:?}, {:?}) z {zb} h {hb}", p.x, p.y, q.x, q.y)
        };
        for (looker, target) in [(a, b), (b, a)] {
            if sees(&mut game.sim, looker, target, &at) {
                tally.seen += 1;
            } else {
                tally.hidden += 1;
            }
        }
    }
    tally
}

/// The engine's tie map moved by `o`: a 1024x512 sky-ceilinged room
/// (floor 0, ceiling 256) with a solid pillar at [256, 320]x[192, 256]
/// (lines 4-7), a platform (floor 24) at [640, 704]x[192, 256] (lines
/// 8-11) and a low alcove (ceiling 128, sky) at [832, 896]x[320, 384]
/// (lines 12-15).
fn tie_map(o: DVec2) -> CompiledMap {
    let at = |x: f64, y: f64| (x + o.x, y + o.y);
    let square = |x0, y0, x1, y1| [at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y1)];
    let sector = |floor: f64, ceiling: f64| SectorSource {
        floor,
        ceiling,
        light: 160,
        ceiling_texture: Some("SKY".into()),
        ..SectorSource::default()
    };
    let start = at(64.0, 64.0);
    let mut source = MapSource {
        name: "ties".into(),
        sectors: vec![sector(0.0, 256.0), sector(24.0, 256.0), sector(0.0, 128.0)],
        things: vec![ThingSource::new(PLAYER_START, start.0, start.1, 0.0)],
        ..MapSource::default()
    };
    source.add_ring(&[at(0.0, 0.0), at(0.0, 512.0), at(1024.0, 512.0), at(1024.0, 0.0)], 0, None);
    source.add_ring(&square(256.0, 192.0, 320.0, 256.0), 0, None);
    source.add_ring(&square(640.0, 192.0, 704.0, 256.0), 0, Some(1));
    source.add_ring(&square(832.0, 320.0, 896.0, 384.0), 0, Some(2));
    let map = validate(&source).unwrap_or_else(|p| panic!("{p:?}"));
    build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

/// The tie rules, at the origin and with the map's corners at ±30,000:
/// the same answers everywhere, by both paths. The answers are Doom's:
/// a line of sight exactly through a solid corner is blocked (the
/// corner's wall has one end "on" the trace, the other off it, and the
/// trace's ends either side of it); a unit beside it passes.
#[test]
fn tie_rules_hold_at_the_origin_and_at_30000() {
    let offsets = [DVec2::ZERO, DVec2::new(30_000.0 - 1024.0, 30_000.0 - 512.0), DVec2::splat(-30_000.0)];
    for o in offsets {
        let mut game = game_on(tie_map(o), "ties");
        let (a, t) = two_bodies(&mut game);
        let check = |sim: &mut Sim, (x, y, z, h): (f64, f64, f64, f64), (tx, ty, tz, th): (f64, f64, f64, f64)| {
            place(sim, a, DVec2::new(x, y) + o, z, h);
            place(sim, t, DVec2::new(tx, ty) + o, tz, th);
            sees(sim, a, t, &|| format!("offset {o}: ({x}, {y}) -> ({tx}, {ty})"))
        };
        let cases = [
            // (what, looker, target, seen)
            ("through the pillar", (64.0, 224.0, 0.0, 56.0), (448.0, 224.0, 0.0, 56.0), false),
            ("over the platform", (576.0, 224.0, 0.0, 56.0), (768.0, 224.0, 0.0, 56.0), true),
            ("exactly through the pillar's corner", (192.0, 256.0, 0.0, 56.0), (320.0, 128.0, 0.0, 56.0), false),
            ("a unit beside the corner", (192.0, 255.0, 0.0, 56.0), (320.0, 127.0, 0.0, 56.0), true),
            ("exactly through the platform's corner", (576.0, 256.0, 0.0, 56.0), (704.0, 128.0, 0.0, 56.0), true),
            ("along the pillar's face", (128.0, 192.0, 0.0, 56.0), (448.0, 192.0, 0.0, 56.0), false),
            ("along the platform's edge", (576.0, 192.0, 0.0, 56.0), (768.0, 192.0, 0.0, 56.0), true),
            ("from the platform's edge", (672.0, 192.0, 0.0, 56.0), (672.0, 64.0, 0.0, 56.0), true),
            ("from the edge, eye under the lip", (672.0, 192.0, -40.0, 56.0), (672.0, 64.0, 0.0, 56.0), false),
            ("to the pillar's face", (64.0, 224.0, 0.0, 56.0), (256.0, 224.0, 0.0, 56.0), false),
            ("to the platform's edge", (576.0, 224.0, 0.0, 56.0), (640.0, 224.0, 0.0, 56.0), true),
            ("to the edge, under the lip", (576.0, 224.0, 0.0, 56.0), (640.0, 224.0, 0.0, 20.0), false),
            ("the same point", (128.0, 128.0, 0.0, 56.0), (128.0, 128.0, 0.0, 56.0), true),
        ];
        for (what, looker, target, expected) in cases {
            assert_eq!(check(&mut game.sim, looker, target), expected, "{what} at offset {o}");
        }
        // Live heights: the platform's lip raised above the line of sight
        // through its corner and along its edge.
        game.sim.level.sectors[1].floorheight = Fixed::from_int(50);
        let raised = [
            ((576.0, 256.0, 0.0, 56.0), (704.0, 128.0, 0.0, 56.0)),
            ((576.0, 192.0, 0.0, 56.0), (768.0, 192.0, 0.0, 56.0)),
        ];
        for (looker, target) in raised {
            assert!(!check(&mut game.sim, looker, target), "raised lip at offset {o}");
        }
        // And random pairs, ties among them.
        game.sim.level.sectors[1].floorheight = Fixed::from_int(24);
        let level = tie_map(o);
        let tally = check_pairs(&mut game, &level, 7, 2_000, &format!("ties at offset {o}"));
        assert!(tally.seen > 100 && tally.hidden > 100, "offset {o}: {tally:?}");
        assert!(tally.through_vertex > 50 && tally.on_line > 50, "offset {o}: {tally:?}");
    }
}

/// A 16,000-unit room from 14,000 to 30,000 (as large as Doom's 16-bit
/// blockmap allows, as far out as 16.16 fixed point reaches) with a pillar
/// in the middle: lines of sight across it, grazing the pillar's corners
/// exactly, and random pairs, by both paths.
#[test]
fn huge_room_out_at_30000() {
    let c = 22_000.0;
    let mut source = MapSource {
        name: "huge".into(),
        sectors: vec![SectorSource { floor: 0.0, ceiling: 512.0, light: 160, ..SectorSource::default() }],
        things: vec![ThingSource::new(PLAYER_START, c - 7_000.0, c - 7_000.0, 0.0)],
        ..MapSource::default()
    };
    let (lo, hi) = (c - 8_000.0, c + 8_000.0);
    source.add_ring(&[(lo, lo), (lo, hi), (hi, hi), (hi, lo)], 0, None);
    source.add_ring(&[(c - 64.0, c - 64.0), (c + 64.0, c - 64.0), (c + 64.0, c + 64.0), (c - 64.0, c + 64.0)], 0, None);
    let map = validate(&source).unwrap_or_else(|p| panic!("{p:?}"));
    let level = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let mut game = game_on(level.clone(), "huge");
    let (a, t) = two_bodies(&mut game);
    let check = |sim: &mut Sim, p: (f64, f64), q: (f64, f64)| {
        let (p, q) = (DVec2::new(c + p.0, c + p.1), DVec2::new(c + q.0, c + q.1));
        place(sim, a, p, 0.0, 56.0);
        place(sim, t, q, 0.0, 56.0);
        sees(sim, a, t, &|| format!("{p} -> {q}"))
    };
    // Corner to corner: through the pillar. Along x + y = 128 (from the
    // middle), which touches the pillar only at its corner (64, 64):
    // blocked; a unit off it: seen.
    assert!(!check(&mut game.sim, (-7_999.0, -7_999.0), (7_999.0, 7_999.0)));
    assert!(!check(&mut game.sim, (-7_000.0, 7_128.0), (7_128.0, -7_000.0)));
    assert!(check(&mut game.sim, (-7_000.0, 7_129.0), (7_129.0, -7_000.0)));
    assert!(check(&mut game.sim, (-7_999.0, 7_999.0), (7_999.0, 7_999.0)));
    let tally = check_pairs(&mut game, &level, 30_000, 2_000, "huge room");
    // The pillar is small in so large a room: few pairs are hidden.
    assert!(tally.seen > 100 && tally.hidden > 20, "{tally:?}");
}

/// Freedoom's E1M1 and MAP01 on their own WAD nodes and REJECT, vanilla
/// rules: 10,000 random pairs each (half with the map's heights as
/// shipped, half with every shut door and raised lift opened), the tree
/// agreeing with the brute force on every one.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn freedoom_pairs_agree() {
    use sightline::campaign::{open, MapRef};
    for (wad, name) in [("freedoom1.wad", "E1M1"), ("freedoom2.wad", "MAP01")] {
        let path = freedoom_wads::path(wad);
        assert!(path.is_file(), "missing fixture {}: {}", path.display(), freedoom_wads::HOW_TO_GET);
        let map = MapRef::Wad { wads: vec![path], map: Some(name.into()) };
        let opened = open(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        let level = opened.level.compiled.clone();
        let options = GameOptions { no_monsters: true, ..Default::default() };
        let mut game = SimGame::new(opened, options).unwrap_or_else(|e| panic!("{e}"));
        // Without vanilla's typo in P_DivlineSide (Sightline's rules, which
        // both paths read): with it a horizontal line's test is garbage,
        // and garbage differs by which lines are asked.
        game.sim.rules.compat = Compat::Sightline;
        let mut tally = check_pairs(&mut game, &level, 1, 5_000, name);
        for s in &mut game.sim.level.sectors {
            if s.ceilingheight <= s.floorheight + Fixed::from_int(8) {
                s.ceilingheight = s.floorheight + Fixed::from_int(72);
            }
        }
        let more = check_pairs(&mut game, &level, 2, 5_000, &format!("{name}, doors open"));
        tally.pairs += more.pairs;
        tally.seen += more.seen;
        tally.hidden += more.hidden;
        tally.through_vertex += more.through_vertex;
        tally.on_line += more.on_line;
        tally.fuzzy += more.fuzzy;
        eprintln!("{name}: {tally:?}");
        let t = &tally;
        // Both ways for each pair compared.
        let compared = 2 * (t.pairs - t.fuzzy);
        assert!(compared > 2_000, "{name}: {t:?}");
        assert!(t.seen > compared / 10 && t.hidden > compared / 10, "{name}: {t:?}");
    }
}
