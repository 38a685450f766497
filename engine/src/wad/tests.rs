//! WAD reading on small hand-built WADs: the happy path, and every kind of
//! corruption the reader must turn into an error naming the lump.

use proptest::prelude::*;

use super::art::{flat, picture, Palette};
use super::import::{convert, sky_of, stand_on_origin, Art};
use super::*;

/// Builds a WAD from `(name, bytes)` lumps, directory at the end.
pub(crate) fn build(kind: &[u8; 4], lumps: &[(&str, Vec<u8>)]) -> Vec<u8> {
    wad_bytes(kind, lumps)
}

fn name8(s: &str) -> [u8; 8] {
    let mut n = [0u8; 8];
    n[..s.len()].copy_from_slice(s.as_bytes());
    n
}

fn i16s(values: &[i16]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// A one-sector square room, 256 on a side, with the player start in it, and
/// just enough art (a palette, one texture of one patch, one flat).
pub(crate) fn square_room() -> Vec<(&'static str, Vec<u8>)> {
    let things = i16s(&[128, 128, 90, 1, 7]);
    let vertices = i16s(&[0, 0, 0, 256, 256, 256, 256, 0]);
    let mut lines = Vec::new();
    for (a, b) in [(0, 1), (1, 2), (2, 3), (3, 0)] {
        lines.extend(i16s(&[a, b, 1, 0, 0, 0, -1]));
    }
    let mut side = i16s(&[0, 0]);
    side.extend(name8("-"));
    side.extend(name8("-"));
    side.extend(name8("WALL"));
    side.extend(i16s(&[0]));
    let mut sector = i16s(&[0, 128]);
    sector.extend(name8("FLAT"));
    sector.extend(name8("F_SKY1"));
    sector.extend(i16s(&[160, 0, 0]));
    let palette: Vec<u8> = (0..768).map(|k| (k % 256) as u8).collect();
    let mut pnames = 1i32.to_le_bytes().to_vec();
    pnames.extend(name8("PATCH"));
    // TEXTURE1: WALL 8x8 of PATCH at (0, 0), and SKY1 the same, after the
    // texture Doom never draws (index 0).
    let names = ["AASHITTY", "WALL", "SKY1"];
    let mut texture1 = (names.len() as i32).to_le_bytes().to_vec();
    for k in 0..names.len() as i32 {
        texture1.extend((4 + 4 * names.len() as i32 + 32 * k).to_le_bytes());
    }
    for name in names {
        texture1.extend(name8(name));
        texture1.extend(0i32.to_le_bytes());
        texture1.extend(i16s(&[8, 8]));
        texture1.extend(0i32.to_le_bytes());
        texture1.extend(i16s(&[1, 0, 0, 0, 1, 0]));
    }
    vec![
        ("PLAYPAL", palette),
        ("PNAMES", pnames),
        ("TEXTURE1", texture1),
        ("PATCH", patch(8, 8)),
        ("E1M1", vec![]),
        ("THINGS", things),
        ("LINEDEFS", lines),
        ("SIDEDEFS", side.repeat(4)),
        ("VERTEXES", vertices),
        ("SECTORS", sector),
        ("F_START", vec![]),
        ("FLAT", vec![7; 4096]),
        ("F_END", vec![]),
        ("S_START", vec![]),
        ("S_END", vec![]),
    ]
}

/// A solid picture: every column one post covering its height.
fn patch(w: i16, h: i16) -> Vec<u8> {
    let mut b = i16s(&[w, h, 0, 0]);
    let start = 8 + 4 * w as i32;
    let column = 4 + h as i32 + 1;
    for x in 0..i32::from(w) {
        b.extend((start + x * column).to_le_bytes());
    }
    for x in 0..w {
        b.extend([0, h as u8, 0]);
        b.extend(std::iter::repeat_n(x as u8, h as usize));
        b.extend([0, 0xFF]);
    }
    b
}

fn wad(lumps: &[(&str, Vec<u8>)]) -> Result<Wad, WadError> {
    Wad::from_bytes(build(b"IWAD", lumps), "test.wad")
}

fn with(lump: &str, bytes: Vec<u8>) -> Vec<(&'static str, Vec<u8>)> {
    square_room().into_iter().map(|(n, b)| if n == lump { (n, bytes.clone()) } else { (n, b) }).collect()
}

fn message(r: Result<impl Sized, WadError>) -> String {
    match r {
        Ok(_) => panic!("expected an error"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn a_small_wad_reads_and_converts() {
    let w = wad(&square_room()).unwrap();
    assert_eq!(w.map_names(), ["E1M1"]);
    let m = w.map("e1m1").unwrap();
    assert_eq!((m.vertices.len(), m.lines.len(), m.sides.len(), m.sectors.len()), (4, 4, 4, 1));
    let art = Art::read(&w).unwrap();
    let c = convert(&w, &m, &art).unwrap();
    let map = crate::map::validate::validate(&c.source).unwrap();
    assert_eq!(map.sky.as_deref(), Some("SKY1"));
    assert!(map.sectors[0].ceiling_is_sky());
    assert_eq!(map.player_start().pos, glam::DVec2::new(128.0, 128.0));
    assert_eq!(c.walls.iter().collect::<Vec<_>>(), ["SKY1", "WALL"]);
    assert_eq!(c.flats.iter().collect::<Vec<_>>(), ["FLAT"]);
}

#[test]
fn pictures_decode_posts_and_leave_gaps_transparent() {
    let palette = Palette(std::array::from_fn(|k| [k as u8, 0, 0]));
    let img = picture(&patch(3, 2), &palette).unwrap();
    assert_eq!((img.width, img.height), (3, 2));
    assert_eq!(img.rgba[2], [2, 0, 0, 255]);
    // One post of one pixel at row 1 of a 1x3 picture.
    let mut b = i16s(&[1, 3, 0, 0]);
    b.extend(12i32.to_le_bytes());
    b.extend([1, 1, 0, 9, 0, 0xFF]);
    let img = picture(&b, &palette).unwrap();
    assert_eq!(img.rgba.iter().map(|p| p[3]).collect::<Vec<_>>(), [0, 255, 0]);
}

#[test]
fn skies_follow_doom() {
    assert_eq!(sky_of("E1M4"), "SKY1");
    assert_eq!(sky_of("E3M1"), "SKY3");
    assert_eq!(sky_of("MAP11"), "SKY1");
    assert_eq!(sky_of("MAP12"), "SKY2");
    assert_eq!(sky_of("MAP21"), "SKY3");
}

#[test]
fn headers_and_directories_are_checked() {
    assert!(message(Wad::from_bytes(b"IWAD".to_vec(), "t.wad")).contains("truncated"));
    assert!(message(Wad::from_bytes(b"JUNKJUNKJUNK".to_vec(), "t.wad")).contains("not a WAD"));
    let mut b = build(b"PWAD", &square_room());
    b[4..8].copy_from_slice(&i32::MAX.to_le_bytes());
    let m = message(Wad::from_bytes(b, "t.wad"));
    assert!(m.contains("t.wad") && m.contains("runs past the end"), "{m}");
    let mut b = build(b"PWAD", &square_room());
    b[4..8].copy_from_slice(&(-1i32).to_le_bytes());
    assert!(message(Wad::from_bytes(b, "t.wad")).contains("negative"));
    // A lump pointing past the end of the file names the lump.
    let mut b = build(b"PWAD", &square_room());
    let table = i32_at(&b, 8) as usize;
    b[table + 4..table + 8].copy_from_slice(&1_000_000i32.to_le_bytes());
    let m = message(Wad::from_bytes(b, "t.wad"));
    assert!(m.contains("lump PLAYPAL") && m.contains("outside the file"), "{m}");
}

#[test]
fn truncated_files_are_errors_at_every_length() {
    let full = build(b"IWAD", &square_room());
    for len in 0..full.len() {
        // Whatever is cut, reading the map and the art must not panic.
        if let Ok(w) = Wad::from_bytes(full[..len].to_vec(), "t.wad") {
            let _ = w.map("E1M1");
            let _ = Art::read(&w);
        }
    }
}

#[test]
fn bad_map_lumps_name_the_lump_and_the_record() {
    let m = message(wad(&with("LINEDEFS", i16s(&[0, 9, 1, 0, 0, 0, -1]))).unwrap().map("E1M1"));
    assert!(m.contains("E1M1/LINEDEFS") && m.contains("record 0") && m.contains("vertex 9"), "{m}");
    let m = message(wad(&with("LINEDEFS", i16s(&[0, 1, 1, 0, 0, 7, -1]))).unwrap().map("E1M1"));
    assert!(m.contains("sidedef 7"), "{m}");
    let m = message(wad(&with("LINEDEFS", i16s(&[0, 1, 1, 0, 0, -1, -1]))).unwrap().map("E1M1"));
    assert!(m.contains("no right sidedef"), "{m}");
    let m = message(wad(&with("VERTEXES", vec![0; 5])).unwrap().map("E1M1"));
    assert!(m.contains("E1M1/VERTEXES") && m.contains("5 bytes"), "{m}");
    let mut side = square_room().into_iter().find(|l| l.0 == "SIDEDEFS").unwrap().1;
    side[28] = 3;
    let m = message(wad(&with("SIDEDEFS", side)).unwrap().map("E1M1"));
    assert!(m.contains("E1M1/SIDEDEFS") && m.contains("sector 3"), "{m}");
    let lumps: Vec<_> = square_room().into_iter().filter(|l| l.0 != "SECTORS").collect();
    let m = message(wad(&lumps).unwrap().map("E1M1"));
    assert!(m.contains("E1M1/SECTORS is missing"), "{m}");
    let m = message(wad(&square_room()).unwrap().map("E9M9"));
    assert!(m.contains("no map named E9M9") && m.contains("E1M1"), "{m}");
}

#[test]
fn bad_art_names_the_lump() {
    let m = message(Art::read(&wad(&with("PLAYPAL", vec![0; 100])).unwrap()));
    assert!(m.contains("PLAYPAL") && m.contains("100 bytes"), "{m}");
    let m = message(Art::read(&wad(&with("PNAMES", i32::MAX.to_le_bytes().to_vec())).unwrap()));
    assert!(m.contains("PNAMES"), "{m}");
    let mut tex = 1i32.to_le_bytes().to_vec();
    tex.extend(9999i32.to_le_bytes());
    let m = message(Art::read(&wad(&with("TEXTURE1", tex)).unwrap()));
    assert!(m.contains("TEXTURE1") && m.contains("past the end"), "{m}");
    // A patch whose column offsets point past the lump.
    let mut bad = i16s(&[4, 4, 0, 0]);
    bad.extend(5000i32.to_le_bytes().repeat(4));
    let w = wad(&with("PATCH", bad)).unwrap();
    let art = Art::read(&w).unwrap();
    let m = message(art::compose(&w, &art.textures["WALL"], &art.palette));
    assert!(m.contains("lump PATCH") && m.contains("column 0"), "{m}");
    // Absurd sizes are refused before anything is allocated.
    let m = picture(&i16s(&[30000, 30000, 0, 0]), &Palette([[0; 3]; 256])).unwrap_err();
    assert!(m.contains("30000x30000"), "{m}");
    let lumps: Vec<_> = square_room().into_iter().filter(|l| l.0 != "F_END").collect();
    let m = message(Art::read(&wad(&lumps).unwrap()));
    assert!(m.contains("F_END"), "{m}");
}

#[test]
fn a_texture_not_in_texture1_is_named() {
    let mut side = square_room().into_iter().find(|l| l.0 == "SIDEDEFS").unwrap().1;
    side[20..28].copy_from_slice(&name8("NOPE"));
    let w = wad(&with("SIDEDEFS", side)).unwrap();
    let art = Art::read(&w).unwrap();
    let m = message(convert(&w, &w.map("E1M1").unwrap(), &art));
    assert!(m.contains("E1M1/SIDEDEFS") && m.contains("linedef 0") && m.contains("\"NOPE\""), "{m}");
}

/// `default` cases, or PROPTEST_CASES when set (for long fuzzing runs).
fn cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

/// Everything the importer does with a WAD's bytes, short of writing files:
/// whatever the bytes, it must return (an error or a map), never panic.
fn exercise(bytes: Vec<u8>) {
    let Ok(wad) = Wad::from_bytes(bytes, "fuzz.wad") else { return };
    let art = Art::read(&wad);
    for name in wad.map_names() {
        let (Ok(m), Ok(art)) = (wad.map(&name), &art) else { continue };
        if let Ok(c) = convert(&wad, &m, art) {
            let _ = crate::map::validate::validate(&c.source);
            for t in &c.walls {
                let _ = art::compose(&wad, &art.textures[t], &art.palette);
            }
        }
    }
    if let Ok(art) = &art {
        for &f in art.flats.values() {
            let _ = flat(wad.bytes(f), &art.palette);
        }
        for &s in art.sprites.values() {
            if let Ok(p) = picture(wad.bytes(s), &art.palette) {
                stand_on_origin(&p);
            }
        }
    }
}

proptest! {
    // Cases per run: PROPTEST_CASES overrides (the long run in the issue note
    // used 200000).
    #![proptest_config(ProptestConfig::with_cases(cases(512)))]

    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..512), iwad in any::<bool>()) {
        // Half the cases start with a valid magic so the directory code runs.
        let mut bytes = bytes;
        if iwad && bytes.len() >= 4 {
            bytes[..4].copy_from_slice(b"PWAD");
        }
        exercise(bytes);
    }

    #[test]
    fn mutated_wads_never_panic(
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..16),
        cut in proptest::option::of(any::<prop::sample::Index>()),
    ) {
        let mut bytes = build(b"IWAD", &square_room());
        for (at, value) in edits {
            let k = at.index(bytes.len());
            bytes[k] = value;
        }
        if let Some(cut) = cut {
            bytes.truncate(cut.index(bytes.len()));
        }
        exercise(bytes);
    }
}

// ---------------------------------------------------------------------------
// Specials, tags, sector types and thing types that make no sense: listed in
// the report, never a panic, and the map still validates.

/// Little-endian u16s, as the map lumps store specials, tags and types.
fn u16s(values: &[u16]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// Two rooms side by side, west (sector 0, x 0..256) and east (sector 1,
/// x 256..512, both y 0..256), joined by linedef 6, two-sided, from (256, 0)
/// to (256, 256) with the east room on its right. Linedefs 0-5 are the walls:
/// 0 west, 1 north of sector 0, 2 north of sector 1, 3 east, 4 south of 1, 5
/// south of 0. `lines` gives each linedef's special and tag, `sectors` each
/// sector's type and tag; `things` (x, y, type, all skills) follow player 1's
/// start at (128, 128).
fn two_rooms(
    lines: &[(u16, u16); 7],
    sectors: &[(i16, u16); 2],
    things: &[(i16, i16, u16)],
) -> Vec<(&'static str, Vec<u8>)> {
    let vertices = i16s(&[0, 0, 0, 256, 256, 256, 512, 256, 512, 0, 256, 0]);
    let ends = [(0, 1), (1, 2), (2, 3), (3, 4), (4, 5), (5, 0), (5, 2)];
    let mut linedefs = Vec::new();
    for (k, (&(a, b), &(special, tag))) in ends.iter().zip(lines).enumerate() {
        let two_sided = k == 6;
        let (flags, left) = if two_sided { (level::flags::TWO_SIDED, 7) } else { (level::flags::BLOCKING, 0xFFFF) };
        linedefs.extend(u16s(&[a, b, flags, special, tag, k as u16, left]));
    }
    let side = |middle: &str, sector: i16| {
        let mut s = i16s(&[0, 0]);
        s.extend(name8("-"));
        s.extend(name8("-"));
        s.extend(name8(middle));
        s.extend(i16s(&[sector]));
        s
    };
    let mut sidedefs = Vec::new();
    for sector in [0, 0, 1, 1, 1, 0] {
        sidedefs.extend(side("WALL", sector));
    }
    sidedefs.extend(side("-", 1));
    sidedefs.extend(side("-", 0));
    let mut sector_bytes = Vec::new();
    for &(kind, tag) in sectors {
        sector_bytes.extend(i16s(&[0, 128]));
        sector_bytes.extend(name8("FLAT"));
        sector_bytes.extend(name8("FLAT"));
        sector_bytes.extend(i16s(&[160, kind]));
        sector_bytes.extend(u16s(&[tag]));
    }
    let mut thing_bytes = i16s(&[128, 128, 90, 1, 7]);
    for &(x, y, kind) in things {
        thing_bytes.extend(i16s(&[x, y, 0]));
        thing_bytes.extend(u16s(&[kind, 7]));
    }
    let replaced = [
        ("THINGS", thing_bytes),
        ("LINEDEFS", linedefs),
        ("SIDEDEFS", sidedefs),
        ("VERTEXES", vertices),
        ("SECTORS", sector_bytes),
    ];
    square_room()
        .into_iter()
        .map(|(n, b)| match replaced.iter().find(|r| r.0 == n) {
            Some((_, bytes)) => (n, bytes.clone()),
            None => (n, b),
        })
        .collect()
}

/// No specials, no tags, no sector types.
const PLAIN_LINES: [(u16, u16); 7] = [(0, 0); 7];
const PLAIN_SECTORS: [(i16, u16); 2] = [(0, 0); 2];

/// Imports E1M1 of `lumps`; the conversion itself must succeed.
fn import(lumps: &[(&str, Vec<u8>)]) -> super::import::Converted {
    let w = wad(lumps).unwrap_or_else(|e| panic!("{e}"));
    let art = Art::read(&w).unwrap_or_else(|e| panic!("{e}"));
    convert(&w, &w.map("E1M1").unwrap_or_else(|e| panic!("{e}")), &art).unwrap_or_else(|e| panic!("{e}"))
}

/// Imports and validates; returns the conversion and the validated map.
fn import_valid(lumps: &[(&str, Vec<u8>)]) -> (super::import::Converted, crate::map::Map) {
    let c = import(lumps);
    let map = crate::map::validate::validate(&c.source).unwrap_or_else(|p| panic!("{p:?}\n{}", c.source.to_ron()));
    (c, map)
}

#[test]
fn the_two_room_wad_imports_as_two_rooms() {
    let (c, map) = import_valid(&two_rooms(&PLAIN_LINES, &PLAIN_SECTORS, &[]));
    assert_eq!((map.sectors.len(), map.lines.len(), map.things.len()), (2, 7, 1));
    let opening = &map.lines[6];
    assert_eq!((opening.front.sector, opening.back.as_ref().map(|b| b.sector)), (1, Some(0)));
    assert_eq!(c.report, super::import::Report::default());
}

#[test]
fn unknown_special_numbers_and_thing_types_are_listed_and_left_out() {
    let mut lines = PLAIN_LINES;
    lines[0] = (9999, 0);
    // A Boom locked door that opens for any key: a lock Sightline cannot say.
    lines[6] = (0x3800 | 7, 0);
    let things = [(64, 64, 12345), (384, 64, 2014)];
    let (c, map) = import_valid(&two_rooms(&lines, &PLAIN_SECTORS, &things));
    assert_eq!(
        c.report.unsupported_specials,
        [
            "linedef 0: line special 9999 (not a Doom or Boom special Sightline knows)",
            "linedef 6: generalized line type 0x3807 (a lock that wants any key or all keys)",
        ]
    );
    assert_eq!(c.report.unknown_things, ["thing 1: type 12345 at (64, 64)"]);
    assert_eq!((c.report.specials, c.report.dangling.len()), (0, 0));
    assert!(map.lines.iter().all(|l| l.special.is_none()));
    // The known thing (a health bonus) is kept, the unknown one left out.
    let kinds: Vec<&str> = map.things.iter().map(|t| t.kind.as_str()).collect();
    assert_eq!(kinds, ["player_start", "health_bonus"]);
}

#[test]
fn specials_that_name_nothing_are_dropped_or_unlocked_and_listed() {
    // (lines, sectors, things, the report's dangling entries, what line 6 keeps)
    let dr_on_a_wall = {
        let mut l = PLAIN_LINES;
        l[0] = (1, 0);
        l
    };
    let on_opening = |special, tag| {
        let mut l = PLAIN_LINES;
        l[6] = (special, tag);
        l
    };
    let east_tagged = |tag| [(0, 0), (0, tag)];
    type Case = ([(u16, u16); 7], [(i16, u16); 2], Vec<(i16, i16, u16)>, Vec<&'static str>);
    let cases: Vec<Case> = vec![
        // A manual door (DR, 1) on a one-sided wall: nothing behind it to open.
        (
            dr_on_a_wall,
            PLAIN_SECTORS,
            vec![],
            vec![
                "line 0 door special: with no tag it acts on the sector behind the line, but the line has no back \
                 side; give it a tag or a back side (dropped)",
            ],
        ),
        // W1 open door (2) tagged 42: no sector has it.
        (
            on_opening(2, 42),
            PLAIN_SECTORS,
            vec![],
            vec!["line 6 door special: acts on sectors tagged 42, but no sector has tag 42 (dropped)"],
        ),
        // WR teleport (97) to the tagged east room, which has no destination
        // (the one there is in the west room).
        (
            on_opening(97, 3),
            east_tagged(3),
            vec![(64, 64, 14)],
            vec![
                "line 6 teleporter special: teleports to a destination in a sector tagged 3, but none of those \
                 sectors holds a \"teleport_destination\" thing (dropped)",
            ],
        ),
        // DR blue door (26) with no blue card or skull anywhere: it opens for anyone.
        (
            on_opening(26, 0),
            PLAIN_SECTORS,
            vec![(64, 64, 6)],
            vec![
                "line 6 door special: the door needs the blue key, but no thing in the map is a blue card or skull \
                 (unlocked)",
            ],
        ),
        // Boom's line teleporter (244) with no other line of its tag.
        (on_opening(244, 5), PLAIN_SECTORS, vec![], vec!["linedef 6: line teleporter with no exit line tagged 5"]),
    ];
    for (k, (lines, sectors, things, dangling)) in cases.into_iter().enumerate() {
        let (c, map) = import_valid(&two_rooms(&lines, &sectors, &things));
        assert_eq!(c.report.dangling, dangling, "case {k}");
        assert_eq!((c.report.unsupported_specials.len(), c.report.unknown_things.len()), (0, 0), "case {k}");
        let left: Vec<_> = map.lines.iter().filter_map(|l| l.special.as_ref()).collect();
        if k == 3 {
            // Unlocked, not dropped.
            assert!(
                matches!(left[..], [s] if matches!(s.action, crate::map::Action::Door { key: None, .. })),
                "{left:?}"
            );
        } else {
            assert!(left.is_empty(), "case {k}: {left:?}");
        }
    }
}

#[test]
fn bad_sector_types_are_listed_with_the_number_the_wad_has() {
    for (kind, why) in [
        (6, "sector 1: sector type 6 (not a Doom sector type)"),
        (15, "sector 1: sector type 15 (not a Doom sector type)"),
        (38, "sector 1: sector type 38 (its low five bits, 6, are not a Doom sector type)"),
        (0x300, "sector 1: sector type 768 (Boom's friction, wind or current bits)"),
        (-1, "sector 1: sector type -1 (its low five bits, 31, are not a Doom sector type)"),
    ] {
        let (c, map) = import_valid(&two_rooms(&PLAIN_LINES, &[(9, 0), (kind, 0)], &[]));
        assert_eq!(c.report.unsupported_specials, [why]);
        assert_eq!(c.report.sector_specials, 2);
        // The sector is kept without a special; the good one keeps its own.
        assert!(map.sectors[1].special.is_none());
        assert!(map.sectors[0].special.secret);
    }
}

/// Special numbers: mostly from the ranges that mean something (vanilla,
/// Boom's, generalized), some anything at all.
fn special_number() -> impl Strategy<Value = u16> {
    prop_oneof![3 => 1u16..=141, 1 => 213u16..=261, 3 => 0x2F80u16..=0x7FFF, 2 => any::<u16>(), 1 => Just(0u16)]
}

/// Thing types: keys, teleport destinations and starts often, anything else too.
fn thing_type() -> impl Strategy<Value = u16> {
    prop_oneof![2 => prop::sample::select(vec![1u16, 5, 6, 13, 14, 38, 39, 40]), 1 => 1u16..=3006, 1 => any::<u16>()]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases(256)))]

    /// Whatever the specials, tags, sector types and thing types, the
    /// importer returns a map that validates, and lists what it could not keep.
    #[test]
    fn random_specials_tags_and_types_import_to_a_valid_map(
        lines in proptest::collection::vec((special_number(), prop_oneof![3 => 0u16..4, 1 => any::<u16>()]), 7),
        sectors in proptest::collection::vec((any::<i16>(), prop_oneof![3 => 0u16..4, 1 => any::<u16>()]), 2),
        things in proptest::collection::vec(
            (prop_oneof![3 => 0i16..=512, 1 => any::<i16>()], prop_oneof![3 => 0i16..=256, 1 => any::<i16>()], thing_type()),
            0..6,
        ),
    ) {
        let lines: [(u16, u16); 7] = lines.try_into().expect("7 lines");
        let sectors: [(i16, u16); 2] = sectors.try_into().expect("2 sectors");
        let c = import(&two_rooms(&lines, &sectors, &things));
        let validated = crate::map::validate::validate(&c.source);
        prop_assert!(validated.is_ok(), "{:?}\n{:?}\n{}", validated.err(), c.report, c.source.to_ron());
        // Every special number is accounted for: kept, ignored, unsupported or dangling.
        let given = lines.iter().filter(|l| l.0 != 0).count();
        let r = &c.report;
        prop_assert!(r.specials + r.ignored.len() + r.unsupported_specials.len() >= given, "{r:?}");
        let unknown = things.iter().filter(|t| crate::actors::ActorTable::doom().by_doomednum(t.2).is_none()).count();
        prop_assert_eq!(r.unknown_things.len(), unknown);
    }
}
