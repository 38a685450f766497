//! The round trip's far end: Chocolate Doom plays a vanilla demo headless
//! and its `-statdump` comes back parsed (`sightline_tests::chocolate`).
//! One demo finishes two levels, with tallies known from the map; one of
//! Freedoom's own demos finishes none, which is an empty statdump, not an
//! error. Without Chocolate these tests say so and pass, unless
//! `SIGHTLINE_REQUIRE_CHOCOLATE=1` (CI); without Freedoom's WADs they are
//! ignored, as the other Freedoom suites are.

use std::path::Path;

use sightline::play::lmp::{buttons, DemoHeader, Ticcmd, VanillaDemo};
use sightline::play::statdump::{self, Clock, LevelName, LevelStats, PlayerStats, Tally};
use sightline::wad::{wad_bytes, Wad};
use sightline_tests::chocolate::{self, ChocolateError, Options};
use sightline_tests::freedoom_wads;

/// The room's size: a corridor 64 wide, 512 long, from (0, 0).
const WIDTH: i16 = 64;
const LENGTH: i16 = 512;

/// Two levels, MAP02 and MAP03, each the same room: the player shoots the
/// zombieman ahead, walks over a health bonus to the far wall and presses
/// its exit switch; one sector, a secret, so it is found at once. A second
/// zombieman (deaf, so it never wakes) and a second bonus stand outside the
/// walls, counted in the totals and out of reach. Chocolate's tallies are
/// then known: 1 of 2 kills, 1 of 2 items, 1 of 1 secret; the time is what
/// it printed when this test was written (Chocolate Doom 3.0.0).
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn two_levels_finished_give_chocolates_tallies() {
    if !chocolate::present_or_skip("two_levels_finished_give_chocolates_tallies") {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let pwad = dir.path().join("room.wad");
    let mut lumps = room("MAP02");
    lumps.extend(room("MAP03"));
    std::fs::write(&pwad, wad_bytes(b"PWAD", &lumps)).unwrap();
    let mut demo = VanillaDemo::new(DemoHeader::single(2, 1, 2));
    let command = |forward: i8, buttons: u8| Ticcmd { forward, buttons, ..Ticcmd::default() };
    let level = [
        vec![command(0, buttons::ATTACK); 105],
        vec![command(50, 0); 40],
        vec![command(0, buttons::USE)],
        vec![command(0, 0); 10],
    ]
    .concat();
    demo.commands.extend(&level);
    // Presses that end the intermission (Doom waits for a fresh press).
    for _ in 0..8 {
        demo.commands.push(command(0, buttons::USE));
        demo.commands.extend([command(0, 0); 9]);
    }
    demo.commands.extend(&level);
    let lmp = dir.path().join("room.lmp");
    demo.save(&lmp).unwrap();

    let options = Options { files: vec![pwad], ..Options::default() };
    let played =
        chocolate::play_with(&freedoom_wads::path("freedoom2.wad"), &lmp, &options).unwrap_or_else(|e| panic!("{e}"));
    let player = PlayerStats {
        number: 1,
        kills: Tally::Counted { found: 1, total: 2 },
        items: Tally::Counted { found: 1, total: 2 },
        secrets: Tally::Counted { found: 1, total: 1 },
        frags: Vec::new(),
    };
    let expected = [
        LevelStats {
            level: LevelName::Map(2),
            time: Clock { minutes: 0, seconds: 4 },
            par: Clock { minutes: 1, seconds: 30 },
            players: vec![player.clone()],
        },
        LevelStats {
            level: LevelName::Map(3),
            time: Clock { minutes: 0, seconds: 5 },
            par: Clock { minutes: 2, seconds: 0 },
            players: vec![player],
        },
    ];
    assert_eq!(played.levels, expected, "as text:\n{}", statdump::to_text(&played.levels));
    assert_eq!(played.gametics, demo.tics() as u64);
}

/// Freedoom's DEMO1 (E1M1 in freedoom1.wad) ends before its level does:
/// Chocolate plays it to its end and captures no level.
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn a_freedoom_demo_lump_plays_to_its_end_and_finishes_no_level() {
    if !chocolate::present_or_skip("a_freedoom_demo_lump_plays_to_its_end_and_finishes_no_level") {
        return;
    }
    let iwad = freedoom_wads::path("freedoom1.wad");
    let wad = Wad::open(&iwad).unwrap_or_else(|e| panic!("{e}"));
    let bytes = wad.lump("DEMO1", "the test").unwrap_or_else(|e| panic!("{e}"));
    let demo = VanillaDemo::from_bytes(bytes, "freedoom1.wad:DEMO1").unwrap_or_else(|e| panic!("{e}"));
    let dir = tempfile::tempdir().unwrap();
    let lmp = dir.path().join("freedoom1-demo1.lmp");
    std::fs::write(&lmp, bytes).unwrap();

    let played = chocolate::play(&iwad, &lmp).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(played.levels, []);
    assert_eq!(played.gametics, demo.tics() as u64);
}

/// A demo of a map the IWAD lacks stops Chocolate early: the error says so
/// and carries Chocolate's own message. The file is named like the map: the
/// helper's copy keeps Chocolate from taking the demo for the map's lump
/// (it then fails with "W_LumpLength: 3659 >= numlumps" instead).
#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn a_demo_chocolate_cannot_play_is_an_error_with_its_words() {
    if !chocolate::present_or_skip("a_demo_chocolate_cannot_play_is_an_error_with_its_words") {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let lmp = dir.path().join("map33.lmp");
    let mut demo = VanillaDemo::new(DemoHeader::single(2, 1, 33));
    demo.commands.extend([Ticcmd::default(); 10]);
    demo.save(&lmp).unwrap();
    let err = chocolate::play(&freedoom_wads::path("freedoom2.wad"), &lmp).expect_err("freedoom2.wad has no MAP33");
    assert!(matches!(err, ChocolateError::Unfinished { .. }), "{err}");
    assert!(err.to_string().contains("map33 not found"), "{err}");
}

/// Needs no Chocolate: a binary that is not there is an error saying how
/// to get one.
#[test]
fn a_missing_chocolate_is_an_error_that_says_how_to_get_it() {
    let nowhere = Path::new("/nonexistent/chocolate-doom");
    let options = Options { binary: Some(nowhere.to_path_buf()), ..Options::default() };
    let err = chocolate::play_with(Path::new("doom.wad"), Path::new("x.lmp"), &options).unwrap_err();
    assert!(matches!(err, ChocolateError::Absent { .. }), "{err}");
    let text = err.to_string();
    assert!(text.contains("/nonexistent/chocolate-doom") && text.contains("apt-get install chocolate-doom"), "{text}");
}

/// The room's map lumps under the marker `name`. No NODES: a map of one
/// subsector needs none (Doom's R_PointInSubsector and R_RenderBSPNode
/// take subsector 0 when there are no nodes), so one convex sector is a
/// whole level without a node builder.
fn room(name: &str) -> Vec<(String, Vec<u8>)> {
    fn shorts(values: &[i16]) -> Vec<u8> {
        values.iter().flat_map(|v| v.to_le_bytes()).collect()
    }
    fn name8(name: &str) -> [u8; 8] {
        let mut padded = [0u8; 8];
        padded[..name.len()].copy_from_slice(name.as_bytes());
        padded
    }
    const EVERY_SKILL: i16 = 7;
    const DEAF: i16 = 8;
    // x, y, angle, type, flags: the player, a health bonus and a zombieman
    // in the room; a bonus and a deaf zombieman beyond its far wall.
    let things: [[i16; 5]; 5] = [
        [32, 32, 90, 1, EVERY_SKILL],
        [32, 240, 90, 2014, EVERY_SKILL],
        [32, 448, 270, 3004, EVERY_SKILL],
        [32, 600, 90, 2014, EVERY_SKILL],
        [32, 700, 270, 3004, EVERY_SKILL | DEAF],
    ];
    let vertices: [[i16; 2]; 4] = [[0, 0], [WIDTH, 0], [WIDTH, LENGTH], [0, LENGTH]];
    // Clockwise, so each wall's right (front) side faces in. The far wall
    // (the second) is an S1 exit switch, special 11.
    let walls: [(usize, usize, i16); 4] = [(0, 3, 0), (3, 2, 11), (2, 1, 0), (1, 0, 0)];
    let angles: [u16; 4] = [0x4000, 0, 0xC000, 0x8000]; // north, east, south, west
    const IMPASSABLE: i16 = 1;
    const SECRET: i16 = 9;

    let mut linedefs = Vec::new();
    let mut sidedefs = Vec::new();
    let mut segs = Vec::new();
    for (i, &(v1, v2, special)) in walls.iter().enumerate() {
        let i = i as i16;
        linedefs.extend(shorts(&[v1 as i16, v2 as i16, IMPASSABLE, special, 0, i, -1]));
        sidedefs.extend(shorts(&[0, 0]));
        sidedefs.extend(name8("-"));
        sidedefs.extend(name8("-"));
        sidedefs.extend(name8(if special == 11 { "SW1STRTN" } else { "STARTAN3" }));
        sidedefs.extend(shorts(&[0]));
        segs.extend(shorts(&[v1 as i16, v2 as i16, angles[i as usize] as i16, i, 0, 0]));
    }
    let mut sector = shorts(&[0, 128]);
    sector.extend(name8("FLOOR4_8"));
    sector.extend(name8("CEIL3_5"));
    sector.extend(shorts(&[160, SECRET, 0]));

    vec![
        (name.to_string(), Vec::new()),
        ("THINGS".into(), things.iter().flat_map(|t| shorts(t)).collect()),
        ("LINEDEFS".into(), linedefs),
        ("SIDEDEFS".into(), sidedefs),
        ("VERTEXES".into(), vertices.iter().flat_map(|v| shorts(v)).collect()),
        ("SEGS".into(), segs),
        ("SSECTORS".into(), shorts(&[4, 0])),
        ("NODES".into(), Vec::new()),
        ("SECTORS".into(), sector),
        ("REJECT".into(), vec![0]),
        ("BLOCKMAP".into(), blockmap(&vertices, &walls)),
    ]
}

/// Doom's blockmap: 128-unit cells from an origin 8 units outside the map,
/// each listing (after a 0) the lines whose bounding box touches it, ended
/// by -1. Boxes are generous; Doom only needs no line left out.
fn blockmap(vertices: &[[i16; 2]], walls: &[(usize, usize, i16)]) -> Vec<u8> {
    let (x0, y0) = (-8i16, -8i16);
    let (columns, rows) = ((WIDTH + 16) / 128 + 1, (LENGTH + 16) / 128 + 1);
    let mut offsets = Vec::new();
    let mut lists: Vec<i16> = Vec::new();
    let start = 4 + columns * rows;
    for row in 0..rows {
        for column in 0..columns {
            let (left, bottom) = (x0 + 128 * column, y0 + 128 * row);
            offsets.push(start + lists.len() as i16);
            lists.push(0);
            for (i, &(a, b, _)) in walls.iter().enumerate() {
                let (a, b) = (vertices[a], vertices[b]);
                let touches = a[0].min(b[0]) <= left + 128
                    && a[0].max(b[0]) >= left
                    && a[1].min(b[1]) <= bottom + 128
                    && a[1].max(b[1]) >= bottom;
                if touches {
                    lists.push(i as i16);
                }
            }
            lists.push(-1);
        }
    }
    [vec![x0, y0, columns, rows], offsets, lists].concat().iter().flat_map(|v| v.to_le_bytes()).collect()
}
