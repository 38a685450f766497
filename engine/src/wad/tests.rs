//! WAD reading on small hand-built WADs: the happy path, and every kind of
//! corruption the reader must turn into an error naming the lump.

use proptest::prelude::*;

use super::art::{flat, picture, Palette};
use super::import::{convert, sky_of, stand_on_origin, Art};
use super::*;

/// Builds a WAD from `(name, bytes)` lumps, directory at the end.
pub(crate) fn build(kind: &[u8; 4], lumps: &[(&str, Vec<u8>)]) -> Vec<u8> {
    let mut data = kind.to_vec();
    data.extend((lumps.len() as i32).to_le_bytes());
    data.extend(0i32.to_le_bytes()); // patched below
    let mut dir = Vec::new();
    for (name, bytes) in lumps {
        dir.extend((data.len() as i32).to_le_bytes());
        dir.extend((bytes.len() as i32).to_le_bytes());
        let mut n = [0u8; 8];
        n[..name.len()].copy_from_slice(name.as_bytes());
        dir.extend(n);
        data.extend(bytes);
    }
    let table = data.len() as i32;
    data[8..12].copy_from_slice(&table.to_le_bytes());
    data.extend(dir);
    data
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
