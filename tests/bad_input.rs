//! Bad input through the library: every malformed, truncated, empty, binary or
//! invalid map, and every corrupt compiled map, is an error value that names the
//! file and the element at fault, never a panic.
//!
//! Source cases are table rows (name, bytes, expectation), each a small edit of
//! `maps/two_rooms.ron`. Every row goes through every door: `parse_map` with a
//! label, `load_map` and `open_level` on a file holding it, and
//! `level_from_bytes`; all must give the same error, naming the file.
//!
//! Tests named `bug_*` are ignored: each pins a defect reported to the team and
//! passes once it is fixed.

use std::path::{Path, PathBuf};

use glam::DVec2;
use rand::{RngExt, SeedableRng};
use sightline::bsp::check::check_invariants;
use sightline::bsp::{build, file, BuildOptions, CompiledMap};
use sightline::level::{level_from_bytes, open_level, LevelError};
use sightline::map::source::MapSource;
use sightline::map::{load_map, parse_map, MapError, Problem};
use sightline::render::{Renderer, Shade, View};
use sightline_tests::{map_path, render};

// ---------------------------------------------------------------------------
// Fixtures and edits

fn read_map(name: &str) -> String {
    std::fs::read_to_string(map_path(name)).expect("shipped map is readable")
}

fn two_rooms() -> String {
    read_map("two_rooms.ron")
}

/// `text` with the one occurrence of `from` replaced by `to`. Panics if `from`
/// is missing or ambiguous, so that an edit can never silently do nothing.
fn edit(text: &str, from: &str, to: &str) -> String {
    let n = text.matches(from).count();
    assert_eq!(n, 1, "edit: `{from}` occurs {n} times, expected once");
    text.replacen(from, to, 1)
}

/// two_rooms with an edit.
fn tr(from: &str, to: &str) -> String {
    edit(&two_rooms(), from, to)
}

/// two_rooms with extra vertices (numbered from 6) and extra lines (from 7).
fn tr_plus(vertices: &str, line: &str) -> String {
    tr_plus_lines(vertices, &[line])
}

fn tr_plus_lines(vertices: &str, lines: &[impl AsRef<str>]) -> String {
    let text = tr("(256.0, 0.0),\n", &format!("(256.0, 0.0), {vertices}\n"));
    let lines: String = lines.iter().map(|l| format!("        {},\n", l.as_ref())).collect();
    edit(&text, "    ],\n    things", &format!("{lines}    ],\n    things"))
}

/// A square loop of lines through vertices 6, 7, 8, 9, clockwise when
/// `clockwise`, each with the given sides.
fn square_loop(clockwise: bool, sides: &str) -> Vec<String> {
    let order = if clockwise { [6, 7, 8, 9] } else { [6, 9, 8, 7] };
    (0..4).map(|k| format!("Line(from: {}, to: {}, {sides})", order[k], order[(k + 1) % 4])).collect()
}

/// The problems of a one-sided square loop (lines 7 to 10) inside sector 0
/// whose front says `front` but finds `found`: each side of each line.
fn square_mismatches(front: usize, found: &[usize]) -> Vec<Problem> {
    (7..=10)
        .flat_map(|line| {
            [
                Problem::SideMismatch { line, side: "front", expected: Some(front), found: found.to_vec() },
                Problem::SideMismatch { line, side: "back", expected: None, found: vec![0] },
            ]
        })
        .collect()
}

/// Corners of a 64-unit square inside sector 0, south-west first, clockwise.
const SQUARE: &str = "(96.0, 96.0), (96.0, 160.0), (160.0, 160.0), (160.0, 96.0),";

/// A source map with every line reversed: each sector ends up on the left.
fn reversed(text: &str) -> String {
    let mut src: MapSource = sightline::map::load::parse_source(text.as_bytes(), "fixture").expect("fixture parses");
    for l in &mut src.lines {
        std::mem::swap(&mut l.from, &mut l.to);
    }
    src.to_ron()
}

/// (line, column), both 1-based and the column in characters, of the one
/// occurrence of `marker` in `text`.
fn position_of(text: &str, marker: &str) -> (usize, usize) {
    let n = text.matches(marker).count();
    assert_eq!(n, 1, "marker `{marker}` occurs {n} times, expected once");
    let before = &text[..text.find(marker).unwrap()];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().unwrap_or("").chars().count() + 1;
    (line, col)
}

/// A directory under the target dir for files the tests write.
fn scratch(sub: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("bad_input").join(sub);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

/// Deterministic pseudo-random bytes.
fn noise(seed: u64, len: usize) -> Vec<u8> {
    let mut rng = rand::rngs::ChaCha8Rng::seed_from_u64(seed);
    (0..len).map(|_| rng.random::<u8>()).collect()
}

// ---------------------------------------------------------------------------
// The table machinery for source maps

enum Want {
    /// A RON error reported on the line of `at` (the one occurrence of that
    /// marker in the text), at its first character give or take one column,
    /// with a message containing `says`.
    Syntax {
        at: &'static str,
        says: &'static str,
    },
    /// A RON error on the text's last line, with a message containing `says`.
    SyntaxAtEnd {
        says: &'static str,
    },
    Empty,
    /// Binary data first seen at this byte.
    Binary {
        offset: usize,
    },
    /// Exactly these problems, in this order, and these words in the message.
    Invalid {
        problems: Vec<Problem>,
        mentions: &'static [&'static str],
    },
}

struct Case {
    name: &'static str,
    bytes: Vec<u8>,
    want: Want,
}

fn case(name: &'static str, text: impl Into<Vec<u8>>, want: Want) -> Case {
    Case { name, bytes: text.into(), want }
}

fn invalid(name: &'static str, text: String, problems: Vec<Problem>, mentions: &'static [&'static str]) -> Case {
    case(name, text, Want::Invalid { problems, mentions })
}

fn syntax(name: &'static str, text: String, at: &'static str, says: &'static str) -> Case {
    case(name, text, Want::Syntax { at, says })
}

/// Problems compared through `Debug`, so that NaN equals NaN.
fn same_problems(got: &[Problem], want: &[Problem]) -> bool {
    format!("{got:?}") == format!("{want:?}")
}

/// Runs one case through every door; returns what is wrong, if anything.
fn check(case: &Case) -> Result<(), String> {
    // Named by content too, so that rows of tests running in parallel never share a file.
    let hash = {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        case.bytes.hash(&mut h);
        h.finish()
    };
    let name = case.name.replace(|c: char| !c.is_ascii_alphanumeric(), "_");
    let path = scratch("maps").join(format!("{name}-{hash:016x}.ron"));
    std::fs::write(&path, &case.bytes).map_err(|e| e.to_string())?;
    let label = path.display().to_string();
    let options = BuildOptions::default();

    let loaded = match load_map(&path) {
        Ok(_) => return Err("load_map accepted it".into()),
        Err(e) => e,
    };
    let message = loaded.to_string();
    let mut also = vec![
        ("open_level", open_level(&path, &options).err().map(|e| e.to_string())),
        ("level_from_bytes", level_from_bytes(&case.bytes, &label, &options).err().map(|e| e.to_string())),
    ];
    if let Ok(text) = std::str::from_utf8(&case.bytes) {
        also.push(("parse_map", parse_map(text, &label).err().map(|e| e.to_string())));
    }
    for (door, other) in also {
        match other {
            None => return Err(format!("{door} accepted it")),
            Some(m) if m != message => return Err(format!("{door} says `{m}` but load_map says `{message}`")),
            Some(_) => {}
        }
    }
    if !message.starts_with(&label) {
        return Err(format!("message does not start with the file: {message}"));
    }

    match (&case.want, &loaded) {
        (Want::Syntax { at, says }, MapError::Syntax { line, col, message: m, .. }) => {
            let text = std::str::from_utf8(&case.bytes).expect("syntax cases are text");
            let (want_line, want_col) = position_of(text, at);
            if *line != want_line || col.abs_diff(want_col) > 1 {
                return Err(format!("reported at {line}:{col}, but `{at}` is at {want_line}:{want_col}: {message}"));
            }
            if !m.contains(says) {
                return Err(format!("message lacks `{says}`: {message}"));
            }
            if !message.starts_with(&format!("{label}:{line}:{col}: ")) {
                return Err(format!("message is not FILE:LINE:COL: {message}"));
            }
        }
        (Want::SyntaxAtEnd { says }, MapError::Syntax { line, message: m, .. }) => {
            let text = std::str::from_utf8(&case.bytes).expect("syntax cases are text");
            let last = text.trim_end().lines().count();
            if *line != last || !m.contains(says) {
                return Err(format!("expected `{says}` on the last line, {last}: {message}"));
            }
        }
        (Want::Empty, MapError::Empty { .. }) => {
            if !message.contains("empty") {
                return Err(format!("message does not say empty: {message}"));
            }
        }
        (Want::Binary { offset }, MapError::Binary { offset: got, .. }) => {
            if got != offset {
                return Err(format!("binary at byte {got}, expected {offset}: {message}"));
            }
            if !message.contains(&format!("byte {offset}")) {
                return Err(format!("message does not name byte {offset}: {message}"));
            }
        }
        (Want::Invalid { problems, mentions }, MapError::Invalid { problems: got, .. }) => {
            if !same_problems(got, problems) {
                return Err(format!("problems {got:?}, expected {problems:?}"));
            }
            if let Some(m) = mentions.iter().find(|m| !message.contains(*m)) {
                return Err(format!("message lacks `{m}`: {message}"));
            }
        }
        _ => return Err(format!("wrong kind of error: {loaded:?}")),
    }
    Ok(())
}

/// Checks every row and reports all failures at once.
fn check_all(cases: &[Case]) {
    let failures: Vec<String> =
        cases.iter().filter_map(|c| check(c).err().map(|e| format!("{}: {e}", c.name))).collect();
    assert!(failures.is_empty(), "{} of {} cases failed:\n{}", failures.len(), cases.len(), failures.join("\n"));
}

// ---------------------------------------------------------------------------
// Source maps: text-level failures

#[test]
fn malformed_ron_is_a_syntax_error_at_the_right_line_and_column() {
    let missing_comma = tr("(0.0, 256.0), (256.0", "(0.0, 256.0) (256.0");
    check_all(&[
        syntax("missing comma between vertices", missing_comma.clone(), "(256.0, 256.0)", "comma"),
        syntax(
            "missing comma between sector fields",
            tr("light: 192)", "light: 192 ceiling_texture: \"X\")"),
            "ceiling_texture: \"X\"",
            "comma",
        ),
        syntax(
            "missing comma after a line: reported on the next line",
            tr("middle: \"BRICK\")),", "middle: \"BRICK\"))"),
            "Line(from: 1,",
            "comma",
        ),
        syntax(
            "extra closing paren",
            tr("Side(sector: 1)),\n        Line(from: 3", "Side(sector: 1))),\n        Line(from: 3"),
            "),\n        Line(from: 3",
            "comma",
        ),
        syntax("string for an integer", tr("light: 160,", "light:\"bright\","), "\"bright\"", "integer"),
        syntax("string for a float", tr("(512.0, 0.0)", "(\"east\", 0.0)"), "\"east\"", "float"),
        syntax(
            "float for an index",
            tr("from: 3, to: 4", "from: 3.5, to: 4"),
            // ron reads the integer 3, then wants a comma where `.5` starts.
            ".5, to: 4",
            "comma",
        ),
        syntax(
            "integer too large for i64",
            tr("light: 160", "light: 99999999999999999999999"),
            "99999999999999999999999",
            "out of bounds",
        ),
        syntax("misspelt struct name", tr("Sector(floor: 24.0", "Sectr(floor: 24.0"), "Sectr", "Sector"),
        syntax("missing required field", tr("light: 160, ", ""), "),\n    ],\n    lines", "light"),
        syntax("`nan` is not a RON float (`NaN` is)", tr("(512.0, 0.0)", "(nan, 0.0)"), "nan", "float"),
        syntax(
            "trailing garbage",
            format!("{}extra stuff\n", two_rooms()),
            // ron points just past the map's closing paren.
            ")\nextra stuff",
            "trailing",
        ),
        syntax("wrong top-level value", "[1, 2, 3]\n".to_string(), "[1, 2, 3]", "Map"),
        syntax("unknown sector field", tr("light: 160,", "light: 160, brightness: 3,"), "brightness", "brightness"),
        syntax(
            "misspelt optional field",
            tr("ceiling_texture: \"SKY\"", "ceiling_textur: \"SKY\""),
            "ceiling_textur",
            "ceiling_textur",
        ),
        syntax("misspelt back side", tr("back: Some(Side(sector: 0))", "bakc: Some(Side(sector: 0))"), "bakc", "bakc"),
        syntax("CRLF line endings", missing_comma.replace('\n', "\r\n"), "(256.0, 256.0)", "comma"),
        syntax(
            "tab before the error counts as one column",
            edit(&missing_comma, "        (0.0, 0.0)", "\t(0.0, 0.0)"),
            "(256.0, 256.0)",
            "comma",
        ),
        syntax(
            "non-ASCII before the error counts characters",
            edit(&missing_comma, "(0.0, 0.0), ", "(0.0, 0.0), /* Räume */ "),
            "(256.0, 256.0)",
            "comma",
        ),
    ]);
}

#[test]
fn truncated_ron_is_a_syntax_error_at_its_end() {
    let text = two_rooms();
    check_all(&[
        case("two_rooms cut in half", &text[..text.len() / 2], Want::SyntaxAtEnd { says: "end" }),
        case(
            "two_rooms cut before its last paren",
            text.trim_end().trim_end_matches(')'),
            Want::SyntaxAtEnd { says: "" },
        ),
        case("comment only", "// nothing here\n", Want::SyntaxAtEnd { says: "Map" }),
    ]);
}

/// Every prefix of two_rooms that stops before its last `)` is an error, at or
/// before the end of the text, never a panic and never a map.
#[test]
fn every_truncation_of_a_map_is_an_error() {
    let text = two_rooms();
    let last = text.rfind(')').expect("map has a closing paren");
    for cut in 0..=last {
        let prefix = &text[..cut];
        let lines = prefix.matches('\n').count() + 1;
        match parse_map(prefix, "cut.ron") {
            Ok(_) => panic!("prefix of {cut} bytes parsed as a map"),
            Err(MapError::Empty { .. }) if prefix.trim().is_empty() => {}
            Err(MapError::Syntax { line, .. }) if line <= lines => {}
            Err(e) => panic!("prefix of {cut} bytes: unexpected {e:?}"),
        }
    }
}

#[test]
fn empty_and_whitespace_files_are_empty() {
    check_all(&[
        case("empty", "", Want::Empty),
        case("one newline", "\n", Want::Empty),
        case("whitespace", " \t\r\n  \n\t", Want::Empty),
    ]);
}

#[test]
fn binary_files_are_binary() {
    let mut random = noise(7, 4096);
    random[100] = 0;
    let first_nul = random.iter().position(|&b| b == 0).unwrap();
    let mut map_with_nul = two_rooms().into_bytes();
    map_with_nul[200] = 0;
    // "Zwei Räume" saved as Latin-1: a lone 0xe4 is not UTF-8.
    let mut latin1 = tr("\"Two rooms\"", "\"Zwei R?ume\"").into_bytes();
    let latin1_at = latin1.iter().position(|&b| b == b'?').unwrap();
    latin1[latin1_at] = 0xe4;
    check_all(&[
        case("random bytes", random, Want::Binary { offset: first_nul }),
        case("a NUL inside a map", map_with_nul, Want::Binary { offset: 200 }),
        case("latin-1 text", latin1, Want::Binary { offset: latin1_at }),
        case("a PNG", b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR".to_vec(), Want::Binary { offset: 8 }),
        case("invalid UTF-8 without NULs", b"Map(name: \"\xff\xfe\")".to_vec(), Want::Binary { offset: 11 }),
    ]);
}

// ---------------------------------------------------------------------------
// Source maps: validation failures, each naming its element

#[test]
fn bad_indices_name_the_line() {
    check_all(&[
        invalid(
            "dangling vertex",
            tr("from: 3, to: 4", "from: 99, to: 4"),
            vec![Problem::DanglingVertex { line: 3, end: "from", vertex: 99, count: 6 }],
            &["line 3", "`from`", "vertex 99", "0..6"],
        ),
        invalid(
            "negative vertex",
            tr("from: 4, to: 5", "from: 4, to: -1"),
            vec![Problem::DanglingVertex { line: 4, end: "to", vertex: -1, count: 6 }],
            &["line 4", "`to`", "vertex -1"],
        ),
        invalid(
            "most negative vertex",
            tr("from: 4, to: 5", "from: 4, to: -9223372036854775808"),
            vec![Problem::DanglingVertex {
                line: 4,
                end: "to",
                vertex: i64::MIN,
                count: 6,
            }],
            &["line 4", "vertex -9223372036854775808"],
        ),
        invalid(
            "dangling front sector",
            tr("from: 2, to: 3, front: Side(sector: 1)", "from: 2, to: 3, front: Side(sector: 5)"),
            vec![Problem::DanglingSector { line: 2, side: "front", sector: 5, count: 2 }],
            &["line 2", "front side", "sector 5", "0..2"],
        ),
        invalid(
            "dangling back sector",
            tr("back: Some(Side(sector: 0))", "back: Some(Side(sector: 7))"),
            vec![Problem::DanglingSector { line: 6, side: "back", sector: 7, count: 2 }],
            &["line 6", "back side", "sector 7"],
        ),
        invalid(
            "negative back sector",
            tr("back: Some(Side(sector: 0))", "back: Some(Side(sector: -1))"),
            vec![Problem::DanglingSector { line: 6, side: "back", sector: -1, count: 2 }],
            &["line 6", "back side", "sector -1"],
        ),
        invalid(
            "no sectors at all",
            edit(
                &tr("Sector(floor: 0.0, ceiling: 128.0, light: 192),\n", ""),
                "        Sector(floor: 24.0, ceiling: 128.0, light: 160, floor_texture: \"FLOOR\", ceiling_texture: \"SKY\"),\n",
                "",
            ),
            [Problem::Missing { what: "sectors" }]
                .into_iter()
                .chain([0, 0, 1, 1, 1, 0, 1].iter().enumerate().map(|(line, &sector)| {
                    Problem::DanglingSector { line, side: "front", sector, count: 0 }
                }))
                .chain([Problem::DanglingSector { line: 6, side: "back", sector: 0, count: 0 }])
                .collect(),
            &["no sectors", "line 0: front side refers to sector 0"],
        ),
        invalid(
            "texture offset NaN",
            tr("Side(sector: 0, middle: \"BRICK\")", "Side(sector: 0, middle: \"BRICK\", x_offset: NaN)"),
            vec![Problem::BadOffset { line: 0, side: "front" }],
            &["line 0", "front side", "offset"],
        ),
    ]);
}

#[test]
fn bad_numbers_name_the_vertex_or_sector() {
    let vertex4 = |name, x: &str, value: f64| {
        invalid(
            name,
            tr("(512.0, 0.0)", &format!("({x}, 0.0)")),
            vec![Problem::BadVertex { vertex: 4, x: value, y: 0.0 }],
            &["vertex 4", "not a finite coordinate"],
        )
    };
    check_all(&[
        vertex4("vertex NaN", "NaN", f64::NAN),
        vertex4("vertex inf", "inf", f64::INFINITY),
        vertex4("vertex -inf", "-inf", f64::NEG_INFINITY),
        vertex4("vertex 1e300", "1e300", 1e300),
        vertex4("vertex just out of range", "16777217.0", 16_777_217.0),
        invalid(
            "floor NaN",
            tr("floor: 24.0", "floor: NaN"),
            vec![Problem::BadHeight { sector: 1, which: "floor", value: f64::NAN }],
            &["sector 1", "floor height NaN"],
        ),
        invalid(
            "ceiling inf",
            tr("ceiling: 128.0, light: 192", "ceiling: inf, light: 192"),
            vec![Problem::BadHeight { sector: 0, which: "ceiling", value: f64::INFINITY }],
            &["sector 0", "ceiling height inf"],
        ),
        invalid(
            "floor above ceiling",
            tr("floor: 24.0", "floor: 200.0"),
            vec![Problem::FloorAboveCeiling { sector: 1, floor: 200.0, ceiling: 128.0 }],
            &["sector 1", "floor 200.0 is above ceiling 128.0"],
        ),
        invalid(
            "light 256",
            tr("light: 160", "light: 256"),
            vec![Problem::BadLight { sector: 1, light: 256 }],
            &["sector 1", "light 256", "0..=255"],
        ),
        invalid(
            "light -1",
            tr("light: 192", "light: -1"),
            vec![Problem::BadLight { sector: 0, light: -1 }],
            &["sector 0", "light -1"],
        ),
        invalid("thing at NaN", tr("x: 64.0", "x: NaN"), vec![Problem::BadThing { thing: 0 }], &["thing 0"]),
        invalid("thing angle inf", tr("angle: 0.0", "angle: inf"), vec![Problem::BadThing { thing: 0 }], &["thing 0"]),
    ]);
}

#[test]
fn bad_geometry_names_the_lines_and_vertices() {
    check_all(&[
        invalid(
            "zero-length line",
            tr("from: 3, to: 4", "from: 4, to: 4"),
            vec![Problem::ZeroLength { line: 3 }],
            &["line 3", "zero length"],
        ),
        invalid(
            "two vertices at one position",
            tr_plus("(0.0, 0.0),", "Line(from: 6, to: 2, front: Side(sector: 0))"),
            vec![Problem::SharedPosition { vertex: 6, first: 0 }],
            &["vertex 6", "vertex 0"],
        ),
        invalid(
            "minus zero is the same position as zero",
            tr_plus("(-0.0, -0.0),", "Line(from: 6, to: 2, front: Side(sector: 0))"),
            vec![Problem::SharedPosition { vertex: 6, first: 0 }],
            &["vertex 6", "vertex 0"],
        ),
        invalid(
            "sector left open",
            tr("        Line(from: 3, to: 4, front: Side(sector: 1)),\n", ""),
            vec![Problem::Unclosed { sector: 1, vertex: 3, into: 1, out_of: 0 }],
            &["sector 1", "vertex 3", "do not close"],
        ),
        invalid(
            "diagonal crossing the doorway",
            tr_plus("", "Line(from: 0, to: 3, front: Side(sector: 0))"),
            vec![Problem::Crossing { line: 6, other: 7, at: glam::DVec2::new(256.0, 128.0) }],
            &["line 6", "crosses line 7", "(256.0, 128.0)"],
        ),
        invalid(
            "T-junction",
            tr_plus("(128.0, 0.0),", "Line(from: 6, to: 1, front: Side(sector: 0))"),
            vec![Problem::Touching { line: 5, other: 7, at: glam::DVec2::new(128.0, 0.0) }],
            &["line 5", "line 7", "(128.0, 0.0)", "split the line"],
        ),
        invalid(
            "collinear overlap",
            tr_plus("(128.0, 0.0),", "Line(from: 0, to: 6, front: Side(sector: 0))"),
            vec![Problem::Overlap { line: 5, other: 7 }],
            &["line 5", "overlaps line 7"],
        ),
        invalid(
            "duplicate line",
            tr_plus("", "Line(from: 0, to: 1, front: Side(sector: 0))"),
            vec![Problem::DuplicateLine { line: 7, first: 0 }],
            &["line 7", "duplicates line 0"],
        ),
        invalid(
            "duplicate line reversed",
            tr_plus("", "Line(from: 1, to: 0, front: Side(sector: 0))"),
            vec![Problem::DuplicateLine { line: 7, first: 0 }],
            &["line 7", "duplicates line 0"],
        ),
        invalid(
            "inside-out room",
            reversed(&read_map("room.ron")),
            vec![Problem::InsideOut { sector: 0 }],
            &["sector 0", "face away"],
        ),
        invalid(
            "inside-out two rooms",
            reversed(&two_rooms()),
            vec![Problem::InsideOut { sector: 0 }, Problem::InsideOut { sector: 1 }],
            &["2 problems", "sector 0", "sector 1", "face away"],
        ),
        invalid(
            "nested sector without a portal",
            edit(
                &tr_plus_lines(SQUARE, &square_loop(true, "front: Side(sector: 2)")),
                "    ],\n    lines",
                "        Sector(floor: 0.0, ceiling: 64.0, light: 0),\n    ],\n    lines",
            ),
            square_mismatches(2, &[0, 2]),
            &[
                "line 7: just off its front side lies sectors [0, 2] at once, but the line says sector 2",
                "line 7: just off its back side lies sector 0, but the line says nothing",
            ],
        ),
        invalid(
            "pillar wound the wrong way",
            tr_plus_lines(SQUARE, &square_loop(true, "front: Side(sector: 0)")),
            square_mismatches(0, &[]),
            &["line 10: just off its front side lies no sector", "winding"],
        ),
        invalid(
            "a sector no line uses",
            tr("    ],\n    lines", "        Sector(floor: 0.0, ceiling: 64.0, light: 0),\n    ],\n    lines"),
            vec![Problem::NoLines { sector: 2 }],
            &["sector 2", "no line side"],
        ),
    ]);
}

#[test]
fn player_start_problems_name_the_thing() {
    let start = "Thing(kind: \"player_start\", x: 64.0, y: 128.0, angle: 0.0),";
    check_all(&[
        invalid("no things", tr(start, ""), vec![Problem::NoPlayerStart], &["no thing of kind \"player_start\""]),
        invalid(
            "no things field",
            tr(&format!("    things: [\n        {start}\n    ],\n"), ""),
            vec![Problem::NoPlayerStart],
            &["player_start"],
        ),
        invalid(
            "only other things",
            tr("kind: \"player_start\"", "kind: \"lamp\""),
            vec![Problem::NoPlayerStart],
            &["player_start"],
        ),
        invalid(
            "start outside the map",
            tr("x: 64.0", "x: 1000.0"),
            vec![Problem::StartOutside { thing: 0, x: 1000.0, y: 128.0 }],
            &["thing 0", "(1000.0, 128.0)", "not inside any sector"],
        ),
        invalid(
            "start exactly on a one-sided wall",
            tr("x: 64.0", "x: 0.0"),
            vec![Problem::StartOutside { thing: 0, x: 0.0, y: 128.0 }],
            &["thing 0", "(0.0, 128.0)", "on a one-sided wall"],
        ),
        invalid(
            "start at a corner of the outer wall and the open line",
            tr("x: 64.0, y: 128.0", "x: 256.0, y: 0.0"),
            vec![Problem::StartOutside { thing: 0, x: 256.0, y: 0.0 }],
            &["thing 0", "(256.0, 0.0)"],
        ),
        invalid(
            "second thing is the start, outside",
            tr(
                start,
                "Thing(kind: \"lamp\", x: 64.0, y: 64.0),\n        \
                 Thing(kind: \"player_start\", x: -5.0, y: 128.0),",
            ),
            vec![Problem::StartOutside { thing: 1, x: -5.0, y: 128.0 }],
            &["thing 1", "(-5.0, 128.0)"],
        ),
    ]);
}

/// A start exactly on the open line between the rooms is in the map: the
/// map loads, and the game starts there.
#[test]
fn a_start_on_a_two_sided_line_is_accepted() {
    let text = tr("x: 64.0", "x: 256.0");
    let map = parse_map(&text, "doorway.ron").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(map.player_start().pos, DVec2::new(256.0, 128.0));
    let compiled = build(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    assert!(compiled.locate(map.player_start().pos).is_some());
    render_both(&compiled);
    let level = sightline::level::Level::with_builtin_textures(compiled).unwrap_or_else(|e| panic!("{e}"));
    let options = sightline::play::GameOptions::default();
    let game = sightline::sim::game::SimGame::on_level(level, "doorway.ron", options).unwrap_or_else(|e| panic!("{e}"));
    let start = sightline::autopilot::observe::Observe::player(&game).pos;
    assert_eq!(start, DVec2::new(256.0, 128.0), "the game did not start at the map's start");
}

/// The edit helpers make valid maps when asked to: a pillar wound
/// counter-clockwise, and a nested sector behind two-sided lines.
#[test]
fn the_edit_helpers_make_valid_maps_too() {
    let pillar = tr_plus_lines(SQUARE, &square_loop(false, "front: Side(sector: 0)"));
    parse_map(&pillar, "pillar.ron").unwrap_or_else(|e| panic!("{e}"));
    let nested = edit(
        &tr_plus_lines(SQUARE, &square_loop(true, "front: Side(sector: 2), back: Some(Side(sector: 0))")),
        "    ],\n    lines",
        "        Sector(floor: 8.0, ceiling: 64.0, light: 0),\n    ],\n    lines",
    );
    parse_map(&nested, "nested.ron").unwrap_or_else(|e| panic!("{e}"));
}

/// Many problems are listed with a count, the first twelve shown.
#[test]
fn many_problems_are_counted_and_capped() {
    let lights: String = (0..20).map(|_| "        Sector(floor: 0.0, ceiling: 64.0, light: 300),\n").collect();
    let text = tr("    ],\n    lines", &format!("{lights}    ],\n    lines"));
    let err = parse_map(&text, "many.ron").expect_err("20 bad lights");
    assert_eq!(err.problems().len(), 20, "{err}");
    let message = err.to_string();
    assert!(message.starts_with("many.ron: 20 problems:"), "{message}");
    assert!(message.contains("sector 2: light 300"), "{message}");
    assert!(message.contains("... and 8 more"), "{message}");
    assert!(!message.contains("sector 14:"), "only twelve are shown: {message}");
}

/// A missing file and a directory are I/O errors naming the path.
#[test]
fn unreadable_paths_are_io_errors() {
    let missing = scratch("io").join("no such map.ron");
    let dir = scratch("io").join("a directory.ron");
    std::fs::create_dir_all(&dir).unwrap();
    for path in [missing, dir] {
        let label = path.display().to_string();
        let err = load_map(&path).expect_err("unreadable");
        assert!(matches!(err, MapError::Io { .. }), "{err:?}");
        assert!(err.to_string().starts_with(&format!("{label}: cannot read")), "{err}");
        let err = open_level(&path, &BuildOptions::default()).expect_err("unreadable");
        assert!(matches!(err, LevelError::Map(MapError::Io { .. })), "{err:?}");
        assert!(err.to_string().contains(&label), "{err}");
    }
}

// ---------------------------------------------------------------------------
// Source maps: specials (map format version 2), each problem naming its element

/// two_rooms in format version 2.
fn v2(text: &str) -> String {
    edit(text, "Map(\n", "Map(\n    version: 2,\n")
}

/// two_rooms with a special on line 0 (the west wall, one-sided, sector 0).
fn on_wall(special: &str) -> String {
    tr(
        "front: Side(sector: 0, middle: \"BRICK\"))",
        &format!("front: Side(sector: 0, middle: \"BRICK\"), special: {special})"),
    )
}

/// two_rooms with a special on line 6 (the open line, sector 1 in front, 0 behind).
fn on_opening(special: &str) -> String {
    tr("back: Some(Side(sector: 0)))", &format!("back: Some(Side(sector: 0)), special: {special})"))
}

/// `text` with sector 1 (the east room) tagged `tag`.
fn tag_east(text: &str, tag: u16) -> String {
    edit(
        text,
        "Sector(floor: 24.0, ceiling: 128.0, light: 160,",
        &format!("Sector(floor: 24.0, ceiling: 128.0, light: 160, tag: {tag},"),
    )
}

/// `text` with `things` added after the player start.
fn with_things(text: &str, things: &str) -> String {
    edit(text, "angle: 0.0),\n", &format!("angle: 0.0),\n        {things}\n"))
}

/// `text` with these trigger lines.
fn with_trigger_lines(text: &str, lines: &str) -> String {
    edit(text, "    ],\n)", &format!("    ],\n    trigger_lines: [{lines}],\n)"))
}

fn bad_special(element: &str, message: &str) -> Problem {
    Problem::BadSpecial { element: element.into(), message: message.into() }
}

#[test]
fn specials_that_name_nothing_name_their_line() {
    use sightline::map::SpecialAt::{Line, TriggerLine};
    let destination = "Thing(kind: \"teleport_destination\", x: 384.0, y: 128.0, angle: 90.0),";
    let teleport = "LineSpecial(on: Walk, repeat: true, tag: 5, action: Teleport)";
    check_all(&[
        invalid(
            "a special whose tag matches no sector",
            on_wall("LineSpecial(on: Use, tag: 9, action: Lift())"),
            vec![Problem::TagMatchesNothing { at: Line(0), action: "lift", tag: 9 }],
            &["line 0 lift special: acts on sectors tagged 9, but no sector has tag 9"],
        ),
        invalid(
            "a manual special (no tag) on a one-sided line",
            on_wall("LineSpecial(on: Use, repeat: true, action: Door(kind: Raise))"),
            vec![Problem::NoBackSector { at: Line(0), action: "door" }],
            &["line 0 door special", "acts on the sector behind the line, but the line has no back side"],
        ),
        invalid(
            "a trigger line's special with no tag",
            with_trigger_lines(
                &two_rooms(),
                "TriggerLine(from: 0, to: 2, special: LineSpecial(on: Walk, action: Floor(to: Current, offset: 8.0)))",
            ),
            vec![Problem::NoBackSector { at: TriggerLine(0), action: "floor" }],
            &["trigger line 0 floor special"],
        ),
        invalid(
            "a door locked with a key no thing gives (a blue card does not open red)",
            with_things(
                &v2(&on_opening("LineSpecial(on: Use, repeat: true, action: Door(kind: Raise, key: Red))")),
                "Thing(kind: \"blue_card\", x: 128.0, y: 64.0),",
            ),
            vec![Problem::MissingKey { at: Line(6), colour: "red" }],
            &["line 6 door special: the door needs the red key, but no thing in the map is a red card or skull"],
        ),
        invalid(
            "a teleporter with no destination",
            tag_east(&on_opening(teleport), 5),
            vec![Problem::NoTeleportDestination { at: Line(6), tag: 5 }],
            &["line 6 teleporter special", "sector tagged 5", "\"teleport_destination\""],
        ),
        invalid(
            "a teleporter whose destination is in an untagged sector",
            with_things(
                &tag_east(&on_opening(teleport), 5),
                "Thing(kind: \"teleport_destination\", x: 128.0, y: 64.0),",
            ),
            vec![Problem::NoTeleportDestination { at: Line(6), tag: 5 }],
            &["line 6 teleporter special"],
        ),
        invalid(
            "a line teleporter to a one-sided line",
            on_opening("LineSpecial(on: Walk, repeat: true, action: LineTeleport(to: 0))"),
            vec![Problem::BadTeleportLine { at: Line(6), to: 0 }],
            &["line 6 teleporter special: teleports to line 0, which must be another two-sided line"],
        ),
        invalid(
            "a line teleporter to a line that does not exist",
            on_opening("LineSpecial(on: Walk, repeat: true, action: LineTeleport(to: 99))"),
            vec![Problem::BadTeleportLine { at: Line(6), to: 99 }],
            &["line 6", "line 99"],
        ),
        invalid(
            "a line teleporter to itself",
            on_opening("LineSpecial(on: Walk, repeat: true, action: LineTeleport(to: 6))"),
            vec![Problem::BadTeleportLine { at: Line(6), to: 6 }],
            &["line 6 teleporter special: teleports to line 6"],
        ),
    ]);
    // The same teleporter with its destination in the tagged room is fine.
    let good = with_things(&tag_east(&on_opening(teleport), 5), destination);
    parse_map(&good, "teleporter.ron").unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn unknown_thing_kinds_in_version_2_are_named_with_a_suggestion() {
    check_all(&[
        invalid(
            "a misspelt thing kind",
            with_things(&v2(&two_rooms()), "Thing(kind: \"imps\", x: 128.0, y: 64.0),"),
            vec![Problem::UnknownThing { thing: 1, kind: "imps".into(), nearest: Some("imp".into()) }],
            &["thing 1: no thing type is named \"imps\"; did you mean \"imp\"?"],
        ),
        invalid(
            "a thing kind like no other",
            with_things(&v2(&two_rooms()), "Thing(kind: \"qqqqqqqqqqqq\", x: 128.0, y: 64.0),"),
            vec![Problem::UnknownThing { thing: 1, kind: "qqqqqqqqqqqq".into(), nearest: None }],
            &["thing 1: no thing type is named \"qqqqqqqqqqqq\" (the actors are listed in engine/data/actors.ron)"],
        ),
    ]);
    // In version 1 a kind names the sprite drawn: anything goes.
    parse_map(&with_things(&two_rooms(), "Thing(kind: \"imps\", x: 128.0, y: 64.0),"), "v1.ron")
        .unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn unknown_special_names_and_fields_are_syntax_errors_where_they_are() {
    check_all(&[
        syntax(
            "an unknown action",
            on_wall("LineSpecial(on: Use, tag: 1, action: Elevator())"),
            "Elevator",
            "Elevator",
        ),
        syntax("an unknown activation", on_wall("LineSpecial(on: Touch, tag: 1, action: Lift())"), "Touch", "Touch"),
        syntax("a misspelt special field", on_wall("LineSpecial(on: Use, tagg: 1, action: Lift())"), "tagg", "tagg"),
        syntax(
            "an unknown key colour",
            on_opening("LineSpecial(on: Use, action: Door(kind: Raise, key: Green))"),
            "Green",
            "Green",
        ),
        syntax(
            "a misspelt sector special field",
            tr("light: 160,", "light: 160, special: SectorSpecial(secrett: true),"),
            "secrett",
            "secrett",
        ),
        syntax("a negative wait", on_opening("LineSpecial(on: Use, action: Door(kind: Raise, wait: -1))"), "-1", ""),
    ]);
}

/// Misspelt parameters inside specials are silently dropped (the default
/// is used instead): `Action`'s struct variants, `Change`, `Damage` and
/// `Scroll` in engine/src/map/special.rs lack `#[serde(deny_unknown_fields)]`
/// (`SectorSpecial` and every source struct have it).
#[test]
fn misspelt_fields_inside_specials_are_syntax_errors() {
    let tagged = |t: String| tag_east(&t, 1);
    check_all(&[
        syntax(
            "a misspelt lift speed",
            tagged(on_wall("LineSpecial(on: Use, tag: 1, action: Lift(sped: 4.0))")),
            "sped",
            "sped",
        ),
        syntax(
            "a misspelt door wait",
            tagged(on_wall("LineSpecial(on: Use, tag: 1, action: Door(kind: Raise, wiat: 10))")),
            "wiat",
            "wiat",
        ),
        syntax(
            "a misspelt change field",
            tagged(on_wall(
                "LineSpecial(on: Use, tag: 1, action: Floor(to: Current, change: Change(from: Trigger, specal: Copy)))",
            )),
            "specal",
            "specal",
        ),
        syntax(
            "a misspelt damage field",
            tr("light: 160,", "light: 160, special: SectorSpecial(damage: Damage(amount: 5, evry: 3)),"),
            "evry",
            "evry",
        ),
        syntax(
            "a third scroll axis",
            tr("light: 160,", "light: 160, carry: Scroll(x: 1.0, y: 0.0, z: 4.0),"),
            "z: 4.0",
            "z",
        ),
    ]);
}

#[test]
fn bad_numbers_in_specials_name_the_special() {
    let wall = |action: &str| tag_east(&on_wall(&format!("LineSpecial(on: Use, tag: 5, action: {action})")), 5);
    let sector = |special: &str| tr("light: 160,", &format!("light: 160, special: {special},"));
    check_all(&[
        invalid(
            "a speed of 0",
            wall("Lift(speed: 0.0)"),
            vec![bad_special("line 0 lift special", "speed 0.0 must be above 0 and at most 1024 units a tick")],
            &["line 0 lift special: speed 0.0"],
        ),
        invalid(
            "a NaN speed",
            wall("Door(kind: Raise, speed: NaN)"),
            vec![bad_special("line 0 door special", "speed NaN must be above 0 and at most 1024 units a tick")],
            &["line 0 door special: speed NaN"],
        ),
        invalid(
            "a speed too high",
            wall("Crusher(speed: 2000.0)"),
            vec![bad_special("line 0 crusher special", "speed 2000.0 must be above 0 and at most 1024 units a tick")],
            &["line 0 crusher special"],
        ),
        invalid(
            "a wait over an hour",
            wall("Door(kind: Raise, wait: 200000)"),
            vec![bad_special("line 0 door special", "wait 200000 is more than an hour (126000 ticks)")],
            &["line 0 door special: wait 200000"],
        ),
        invalid(
            "an infinite offset",
            wall("Floor(to: Current, offset: inf)"),
            vec![bad_special("line 0 floor special", "offset inf is not finite within the supported range")],
            &["line 0 floor special: offset inf"],
        ),
        invalid(
            "a stair step of 0",
            wall("Stairs(step: 0.0)"),
            vec![bad_special("line 0 stairs special", "step 0.0 must be finite, not 0, and at most 4096")],
            &["line 0 stairs special: step 0.0"],
        ),
        invalid(
            "a special tag out of range",
            on_wall("LineSpecial(on: Use, tag: 70000, action: Lift())"),
            vec![Problem::BadTag { element: "line 0 special".into(), tag: 70000 }],
            &["line 0 special: tag 70000 is outside 0..=65535"],
        ),
        invalid(
            "too much damage",
            sector("SectorSpecial(damage: Damage(amount: 2000))"),
            vec![bad_special(
                "sector 1",
                "damage 2000 every 32 ticks: the amount must be 0..=1000 and every at least 1",
            )],
            &["sector 1: damage 2000 every 32 ticks"],
        ),
        invalid(
            "damage every 0 ticks",
            sector("SectorSpecial(damage: Damage(amount: 5, every: 0))"),
            vec![bad_special("sector 1", "damage 5 every 0 ticks: the amount must be 0..=1000 and every at least 1")],
            &["sector 1: damage 5 every 0 ticks"],
        ),
        invalid(
            "a scroll too fast",
            tr(
                "front: Side(sector: 0, middle: \"BRICK\")",
                "front: Side(sector: 0, middle: \"BRICK\", scroll: Scroll(x: 5000.0, y: 0.0))",
            ),
            vec![bad_special("line 0 front side", "scroll (5000.0, 0.0) must be finite and at most 1024 units a tick")],
            &["line 0 front side: scroll (5000.0, 0.0)"],
        ),
        invalid(
            "a conveyor too fast",
            tr("light: 160,", "light: 160, carry: Scroll(x: 100.0, y: 0.0),"),
            vec![bad_special("sector 1", "carry (100.0, 0.0) must be finite and at most 64 units a tick")],
            &["sector 1: carry (100.0, 0.0)"],
        ),
        invalid(
            "a light transfer from a sector that does not exist",
            tr("light: 160,", "light: 160, floor_light: 7,"),
            vec![bad_special("sector 1", "floor_light refers to sector 7, but the sectors are numbered 0..2")],
            &["sector 1: floor_light refers to sector 7"],
        ),
    ]);
}

#[test]
fn versions_and_special_line_forms_are_checked() {
    check_all(&[
        invalid(
            "version 3",
            edit(&two_rooms(), "Map(\n", "Map(\n    version: 3,\n"),
            vec![Problem::BadVersion { version: 3 }],
            &["version 3: this build reads map format versions 1 and 2"],
        ),
        invalid(
            "version 0",
            edit(&two_rooms(), "Map(\n", "Map(\n    version: 0,\n"),
            vec![Problem::BadVersion { version: 0 }],
            &["version 0"],
        ),
        invalid(
            "`door` and `special` on one line",
            on_opening("LineSpecial(on: Use, action: Door(kind: Open)), door: true"),
            vec![bad_special("line 6", "give at most one of `door`, `trigger` and `special`")],
            &["line 6: give at most one of `door`, `trigger` and `special`"],
        ),
        invalid(
            "a trigger line with a bad vertex",
            with_trigger_lines(
                &tag_east(&two_rooms(), 5),
                "TriggerLine(from: 0, to: 99, special: LineSpecial(on: Walk, tag: 5, action: Lift()))",
            ),
            vec![bad_special("trigger line 0", "refers to vertex 99, but the vertices are numbered 0..6")],
            &["trigger line 0: refers to vertex 99"],
        ),
        invalid(
            "a trigger line of zero length",
            with_trigger_lines(
                &tag_east(&two_rooms(), 5),
                "TriggerLine(from: 2, to: 2, special: LineSpecial(on: Walk, tag: 5, action: Lift()))",
            ),
            vec![bad_special("trigger line 0", "has zero length")],
            &["trigger line 0: has zero length"],
        ),
    ]);
}

// ---------------------------------------------------------------------------
// Compiled maps

fn compiled(name: &str) -> (CompiledMap, Vec<u8>) {
    let map = parse_map(&read_map(name), name).expect("shipped map is valid");
    let c = build(&map, &BuildOptions::default()).expect("shipped map compiles");
    let bytes = file::to_bytes(&c);
    (c, bytes)
}

fn from_bytes(bytes: &[u8], label: &str) -> Result<CompiledMap, LevelError> {
    level_from_bytes(bytes, label, &BuildOptions::default())
}

/// A loaded map, however odd, must render through both renderers.
fn render_both(level: &CompiledMap) {
    let view = View::at_start(level).expect("a loaded map has a valid start");
    let level = sightline::level::Level::with_builtin_textures(level.clone()).unwrap_or_else(|e| panic!("{e}"));
    for r in Renderer::ALL {
        render(&level, &view, (32, 20), r, Shade::Ids);
    }
}

/// The baseline the corruption tests start from.
#[test]
fn compiled_map_round_trips() {
    for name in ["two_rooms.ron", "room.ron", "pillars.ron"] {
        let (c, bytes) = compiled(name);
        let back = from_bytes(&bytes, name).unwrap_or_else(|e| panic!("{e}"));
        assert!(back == c, "{name}: the loaded map differs from the compiled one");
    }
}

#[test]
fn compiled_headers_and_versions_are_refused() {
    let (_, good) = compiled("two_rooms.ron");
    let magic = file::MAGIC;
    let with_version = |v: u8| [magic, &[v], &good[magic.len() + 1..]].concat();
    let rows: Vec<(&str, Vec<u8>, String)> = vec![
        ("only the magic", magic.to_vec(), "truncated after the header".into()),
        ("magic and version", [magic, &[file::VERSION]].concat(), "truncated".into()),
        ("version 0", with_version(0), format!("format version 0, this build reads version {}", file::VERSION)),
        ("the previous version", with_version(file::VERSION - 1), format!("format version {}", file::VERSION - 1)),
        ("the next version", with_version(file::VERSION + 1), format!("format version {}", file::VERSION + 1)),
        ("version 255", with_version(255), "recompile the map".into()),
        (
            "garbage after the header",
            [magic, &[file::VERSION], &[0xff; 64][..]].concat(),
            "corrupt or truncated".into(),
        ),
        (
            "magic without its newline, then the rest",
            [&magic[..magic.len() - 1], &good[magic.len()..]].concat(),
            "binary".into(),
        ),
    ];
    for (name, bytes, says) in rows {
        let label = format!("{name}.slbsp");
        let err = match from_bytes(&bytes, &label) {
            Ok(_) => panic!("{name}: loaded"),
            Err(e) => e.to_string(),
        };
        assert!(err.starts_with(&format!("{label}: ")), "{name}: {err}");
        assert!(err.contains(&says), "{name}: expected `{says}` in: {err}");
    }
}

#[test]
fn every_truncation_of_a_compiled_map_is_an_error() {
    let (_, bytes) = compiled("two_rooms.ron");
    for len in 0..bytes.len() {
        let err = match from_bytes(&bytes[..len], "cut.slbsp") {
            Ok(_) => panic!("a compiled map cut to {len} bytes loaded"),
            Err(e) => e,
        };
        let message = err.to_string();
        assert!(message.starts_with("cut.slbsp"), "{len}: {message}");
        if len > file::MAGIC.len() {
            assert!(
                matches!(err, LevelError::Compiled { .. }) && message.contains("truncated"),
                "cut to {len}: {message}"
            );
        }
    }
}

/// Flip bits at every byte: each result is an error naming the file, or a map
/// that passes every load check and renders. No panic either way.
#[test]
fn flipped_bytes_in_a_compiled_map_never_panic() {
    let (original, bytes) = compiled("two_rooms.ron");
    let (mut refused, mut loaded) = (0, 0);
    for pos in 0..bytes.len() {
        for mask in [0x01, 0x10, 0x80, 0xff] {
            let mut b = bytes.clone();
            b[pos] ^= mask;
            match from_bytes(&b, "flip.slbsp") {
                Err(e) => {
                    refused += 1;
                    let m = e.to_string();
                    assert!(m.starts_with("flip.slbsp: "), "byte {pos} ^ {mask:#x}: {m}");
                }
                Ok(level) => {
                    loaded += 1;
                    assert!(pos > file::MAGIC.len(), "a damaged header loaded: byte {pos}");
                    if level != original {
                        render_both(&level);
                    }
                }
            }
        }
    }
    eprintln!("{refused} flips refused, {loaded} loaded");
    // The checksum refuses every flip (see the test below); this one only
    // insists that nothing panics on the way.
    assert!(refused > 0, "{refused} refused, {loaded} loaded");
}

/// A valid header followed by noise, of many lengths and seeds.
#[test]
fn random_payloads_after_a_valid_header_are_errors() {
    for seed in 0..400u64 {
        let len = (seed as usize * 37) % 2000;
        let bytes = [file::MAGIC, &[file::VERSION], &noise(seed, len)].concat();
        match from_bytes(&bytes, "noise.slbsp") {
            Ok(level) => render_both(&level),
            Err(e) => assert!(e.to_string().starts_with("noise.slbsp: "), "{e}"),
        }
    }
}

/// The tail of one compiled map spliced onto the head of another: the map and
/// the tree disagree, which loading must notice or survive.
#[test]
fn spliced_compiled_maps_never_panic() {
    let (_, a) = compiled("two_rooms.ron");
    let (_, b) = compiled("room.ron");
    let (_, c) = compiled("pillars.ron");
    for (head, tail) in [(&a, &b), (&b, &a), (&a, &c), (&c, &a), (&b, &c)] {
        for cut in (file::MAGIC.len() + 1..head.len().min(tail.len())).step_by(3) {
            let bytes = [&head[..cut], &tail[cut..]].concat();
            if let Ok(level) = from_bytes(&bytes, "splice.slbsp") {
                render_both(&level);
            }
        }
    }
}

#[test]
fn a_corrupt_compiled_file_names_its_path() {
    let (_, mut bytes) = compiled("two_rooms.ron");
    bytes.truncate(bytes.len() / 2);
    let path = scratch("compiled").join("half.slbsp");
    std::fs::write(&path, &bytes).unwrap();
    let err = open_level(&path, &BuildOptions::default()).expect_err("half a file");
    let message = err.to_string();
    assert!(message.starts_with(&format!("{}: corrupt or truncated", path.display())), "{message}");
}

// ---------------------------------------------------------------------------
// Known bugs, reported; each passes once fixed.

#[test]

fn bug_a_byte_order_mark_is_accepted() {
    let text = format!("\u{feff}{}", two_rooms());
    parse_map(&text, "bom.ron").unwrap_or_else(|e| panic!("{e}"));
}

#[test]

fn bug_huge_and_tiny_numbers_print_compactly() {
    let cases = [
        tr("(512.0, 0.0)", "(1e300, 0.0)"),
        tr("floor: 24.0", "floor: 1e300"),
        tr("floor: 0.0, ceiling: 128.0", "floor: 1e-300, ceiling: 0.0"),
    ];
    for text in cases {
        let message = parse_map(&text, "big.ron").expect_err("bad number").to_string();
        assert!(message.len() < 200, "{} chars: {message}", message.len());
    }
}

/// Every single-byte corruption of `bytes` (two masks per byte) that loads.
fn loading_flips(bytes: &[u8]) -> Vec<(usize, u8, CompiledMap)> {
    let mut loaded = Vec::new();
    for pos in 0..bytes.len() {
        for mask in [0x01, 0x80] {
            let mut b = bytes.to_vec();
            b[pos] ^= mask;
            if let Ok(level) = from_bytes(&b, "flip.slbsp") {
                loaded.push((pos, mask, level));
            }
        }
    }
    loaded
}

#[test]

fn bug_a_compiled_tree_that_disagrees_with_its_map_is_refused() {
    let (_, bytes) = compiled("two_rooms.ron");
    let broken: Vec<String> = loading_flips(&bytes)
        .into_iter()
        .filter_map(|(pos, mask, level)| {
            let e = check_invariants(&level.map, &level.bsp).err()?;
            Some(format!("byte {pos} ^ {mask:#04x}: {e}"))
        })
        .collect();
    assert!(
        broken.is_empty(),
        "{} corrupted files loaded with a tree that breaks the compiler's invariants, e.g.:\n{}",
        broken.len(),
        broken[..broken.len().min(10)].join("\n")
    );
}

#[test]

fn bug_every_flipped_byte_in_a_compiled_map_is_refused() {
    let (original, bytes) = compiled("two_rooms.ron");
    let loaded: Vec<String> = loading_flips(&bytes)
        .into_iter()
        .map(|(pos, mask, level)| {
            let what = if level == original { "identical" } else { "changed" };
            format!("byte {pos} ^ {mask:#04x}: loads, {what}")
        })
        .collect();
    assert!(
        loaded.is_empty(),
        "{} of {} flips loaded, e.g.:\n{}",
        loaded.len(),
        2 * bytes.len(),
        loaded[..loaded.len().min(10)].join("\n")
    );
}
