//! The UDMF reader: the syntax, the fields and their defaults, and every
//! error with its message and place.

use super::udmf::{parse, parse_document, At, Namespace, UdmfError, Value};

/// A square room as ViZDoom's basic.wad has it, with a thing and a
/// two-sided line added.
const ROOM: &str = r#"namespace = "zdoom";
thing
{
x = -384.000;
y = 32.000;
type = 1;
id = 1;
skill1 = true;
skill4 = true;
single = true;
class1 = true;
skill6 = true;
}

vertex { x = -448.000; y = 256.000; }
vertex { x = 64.000; y = 256.000; }
vertex { x = 64.000; y = -192.000; }
vertex { x = -448; y = -192.0; }

linedef { v1 = 0; v2 = 1; sidefront = 0; blocking = true; }
linedef { v1 = 1; v2 = 2; sidefront = 1; blocking = true; special = 80; arg0 = 3; arg2 = 7; playeruse = true; }
linedef { v1 = 2; v2 = 3; sidefront = 2; sideback = 3; twosided = true; alpha = 0.5; }
linedef { v1 = 3; v2 = 0; sidefront = 3; blocking = true; id = 12; }

sidedef { sector = 0; texturemiddle = "BRICK9"; }
sidedef { sector = 0; texturemiddle = "BRICK9"; offsetx = 16; }
sidedef { sector = 0; texturetop = "STONE"; offsety = -8; }
sidedef { sector = 0; texturemiddle = "BRICK9"; }

sector
{
texturefloor = "FLOOR0_1";
textureceiling = "FLAT4";
heightceiling = 104;
lightlevel = 210;
}
"#;

fn err(text: &str) -> UdmfError {
    parse(text.as_bytes()).expect_err("the text should not parse")
}

/// The message of the error `text` gives, with its place.
fn message(text: &str) -> String {
    err(text).to_string()
}

#[test]
fn a_room_reads_with_its_values_and_the_defaults() {
    let map = parse(ROOM.as_bytes()).unwrap();
    assert_eq!(map.namespace, Namespace::ZDoom);
    assert_eq!((map.vertices.len(), map.lines.len(), map.sides.len(), map.sectors.len()), (4, 4, 4, 1));
    assert_eq!((map.vertices[3].x, map.vertices[3].y), (-448.0, -192.0));
    let thing = &map.things[0];
    assert_eq!((thing.x, thing.y, thing.kind, thing.id, thing.angle, thing.height), (-384.0, 32.0, 1, 1, 0, 0.0));
    assert_eq!(thing.flags.skills, [true, false, false, true, false]);
    assert!(thing.flags.single && !thing.flags.coop && !thing.flags.deathmatch);
    assert_eq!(thing.at, At { line: 2, column: 1 });
    // zdoom: a line's id defaults to -1, its special has arguments.
    assert_eq!((map.lines[0].id, map.lines[3].id), (-1, 12));
    assert_eq!((map.lines[1].special, map.lines[1].args), (80, [3, 0, 7, 0, 0]));
    assert!(map.lines[1].flags.player_use && !map.lines[1].flags.repeat_special);
    assert!(map.lines[0].flags.blocking && !map.lines[0].flags.two_sided);
    assert_eq!((map.lines[2].back, map.lines[0].back), (Some(3), None));
    assert_eq!((map.sides[1].offset_x, map.sides[2].offset_y), (16, -8));
    assert_eq!((map.sides[2].top.as_str(), map.sides[2].middle.as_str()), ("STONE", "-"));
    let sector = &map.sectors[0];
    assert_eq!((sector.floor, sector.ceiling, sector.light, sector.special, sector.id), (0, 104, 210, 0, 0));
    assert_eq!((sector.floor_texture.as_str(), sector.ceiling_texture.as_str()), ("FLOOR0_1", "FLAT4"));
    // What the map sets that is not read: counted (a class or skill 6 is not).
    assert_eq!(map.ignored.iter().collect::<Vec<_>>(), [(&"linedef.alpha".to_string(), &1)]);
}

#[test]
fn the_doom_namespace_gives_lines_id_zero_and_a_light_of_160() {
    let text = ROOM.replace("\"zdoom\"", "\"Doom\"").replace("lightlevel = 210;", "");
    let map = parse(text.as_bytes()).unwrap();
    assert_eq!(map.namespace, Namespace::Doom);
    assert_eq!((map.lines[0].id, map.sectors[0].light), (0, 160));
}

#[test]
fn names_and_keywords_ignore_case_and_comments_are_skipped() {
    let text = "NameSpace = \"ZDOOM\"; // a comment\n/* a block\n comment */ VERTEX { X = 1; Y = 2.5e1; }\n\
                Thing { x = 0; y = 0; type = 3004; Skill2 = TRUE; Ambush = False; }";
    let map = parse(text.as_bytes()).unwrap();
    assert_eq!((map.vertices[0].x, map.vertices[0].y), (1.0, 25.0));
    assert!(map.things[0].flags.skills[1] && !map.things[0].flags.ambush);
}

#[test]
fn numbers_come_in_every_form_the_grammar_has() {
    let doc =
        parse_document(b"a = 0x1F; b = 017; c = -12; d = +3.5; e = 1.5e2; f = .25; g = 0; h = 4294967295;").unwrap();
    let values: Vec<Value> = doc.globals.into_iter().map(|f| f.value).collect();
    use Value::{Float, Int};
    assert_eq!(values, [Int(31), Int(15), Int(-12), Float(3.5), Float(150.0), Float(0.25), Int(0), Int(4_294_967_295)]);
}

#[test]
fn unknown_blocks_and_globals_are_counted_not_refused() {
    let text = format!("{ROOM}\nfoo {{ bar = 1; }}\nversion = 3;");
    let map = parse(text.as_bytes()).unwrap();
    assert_eq!(map.ignored.get("block:foo"), Some(&1));
    assert_eq!(map.ignored.get("global:version"), Some(&1));
}

#[test]
fn a_field_given_twice_takes_the_last_value() {
    let map = parse(b"namespace = \"zdoom\"; vertex { x = 1; x = 2; y = 0; }").unwrap();
    assert_eq!(map.vertices[0].x, 2.0);
}

#[test]
fn syntax_errors_say_what_and_where() {
    let ns = "namespace = \"zdoom\";\n";
    let cases = [
        ("/* never closed", "line 1, column 1: a /* comment is never closed"),
        ("namespace = \"zdoom;\n", "line 1, column 13: a string is never closed (no '\"' before the end)"),
        ("namespace = \"zdoom\";\nvertex { x = 1 $ }", "line 2, column 16: unexpected character '$'"),
        ("x = 12abc;", "line 1, column 5: \"12abc\" is not a number"),
        ("x = 1.2.3;", "line 1, column 5: \"1.2.3\" is not a number"),
        ("x = 99999999999;", "line 1, column 5: 99999999999 is too large for an integer (UDMF integers are 32 bits)"),
        ("x = 1e999;", "line 1, column 5: 1e999 is too large for a float"),
        ("x 1;", "line 1, column 3: expected '=' or '{' after \"x\", found the integer 1"),
        ("x = 1 y = 2;", "line 1, column 7: expected ';' after x's value, found the name \"y\""),
        ("x = ;", "line 1, column 5: expected a value for \"x\", found ';'"),
        ("x = maybe;", "line 1, column 5: x = maybe: a value is a number, a quoted string, true or false"),
        ("= 1;", "line 1, column 1: expected a block or an assignment, found '='"),
        ("vertex { x 1; }", "line 1, column 12: expected '=' after \"x\", found the integer 1"),
        ("vertex { x = 1;", "line 1, column 16: the vertex block opened at line 1, column 1 is never closed (no '}')"),
        ("vertex { sub { } }", "line 1, column 14: expected '=' after \"sub\", found '{'"),
        ("vertex { 5 }", "line 1, column 10: expected a field or '}' in the vertex block, found the integer 5"),
    ];
    for (text, want) in cases {
        assert_eq!(message(text), want, "{text:?}");
    }
    // The namespace comes first in a real map; errors after it count its line.
    assert_eq!(
        message(&format!("{ns}vertex {{ x = 1;")),
        "line 2, column 16: the vertex block opened at line 2, column 1 is never closed (no '}')"
    );
}

#[test]
fn field_errors_name_the_block_and_the_field() {
    let ns = "namespace = \"zdoom\";\n";
    let cases = [
        ("vertex { y = 1; }".to_string(), "line 2, column 1: vertex 0 (the block at line 2, column 1) has no x, which has no default"),
        ("vertex { x = \"a\"; y = 1; }".to_string(), "line 2, column 10: vertex 0 (the block at line 2, column 1): x is the string \"a\", not a number"),
        (
            "vertex { x = 0; y = 0; }\nsector { texturefloor = \"F\"; textureceiling = \"C\"; heightfloor = 1.5; }".to_string(),
            "line 3, column 52: sector 0 (the block at line 3, column 1): heightfloor is the float 1.5, not a whole number",
        ),
        ("sector { texturefloor = \"F\"; }".to_string(), "line 2, column 1: sector 0 (the block at line 2, column 1) has no textureceiling, which has no default"),
        ("linedef { v1 = 0; v2 = 1; sidefront = 0; blocking = 1; }".to_string(), "line 2, column 42: linedef 0 (the block at line 2, column 1): blocking is the integer 1, not true or false"),
        ("linedef { v1 = -2; v2 = 1; sidefront = 0; }".to_string(), "line 2, column 11: linedef 0 (the block at line 2, column 1): v1 = -2 is not an index"),
        ("thing { x = 0; y = 0; }".to_string(), "line 2, column 1: thing 0 (the block at line 2, column 1) has no type, which has no default"),
    ];
    for (text, want) in cases {
        assert_eq!(message(&format!("{ns}{text}")), want, "{text:?}");
    }
}

#[test]
fn references_to_missing_records_are_refused() {
    let base = "namespace = \"zdoom\";\nvertex { x = 0; y = 0; }\nvertex { x = 64; y = 0; }\n\
                sector { texturefloor = \"F\"; textureceiling = \"C\"; }\nsidedef { sector = 0; }\n";
    let cases = [
        (
            "linedef { v1 = 0; v2 = 2; sidefront = 0; }",
            "line 6, column 1: linedef 0: v2 = 2 names no vertex (the map has 2)",
        ),
        (
            "linedef { v1 = 0; v2 = 1; sidefront = 1; }",
            "line 6, column 1: linedef 0: sidefront = 1 names no sidedef (the map has 1)",
        ),
        (
            "linedef { v1 = 0; v2 = 1; sidefront = 0; sideback = 4; }",
            "line 6, column 1: linedef 0: sideback = 4 names no sidedef (the map has 1)",
        ),
        ("sidedef { sector = 3; }", "line 6, column 1: sidedef 1: sector = 3 names no sector (the map has 1)"),
    ];
    for (text, want) in cases {
        assert_eq!(message(&format!("{base}{text}")), want, "{text:?}");
    }
}

#[test]
fn the_namespace_is_required_and_must_be_one_this_reader_knows() {
    assert_eq!(
        message("vertex { x = 0; y = 0; }"),
        "line 1, column 1: no namespace: a TEXTMAP starts with namespace = \"...\";"
    );
    assert_eq!(
        message("namespace = \"hexen\";"),
        "line 1, column 1: namespace \"hexen\" is not supported (Sightline reads the \"doom\" and \"zdoom\" namespaces)"
    );
    assert_eq!(message("namespace = 1;"), "line 1, column 1: namespace is the integer 1, not a string");
}

mod fuzz {
    use super::{parse, ROOM};
    use proptest::prelude::*;

    proptest! {
        /// Any bytes: an answer, never a panic.
        #[test]
        fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
            let _ = parse(&bytes);
        }

        /// A real map cut anywhere, or with one byte changed.
        #[test]
        fn a_cut_or_changed_map_never_panics(cut in 0..ROOM.len(), at in 0..ROOM.len(), byte in any::<u8>()) {
            let _ = parse(&ROOM.as_bytes()[..cut]);
            let mut changed = ROOM.as_bytes().to_vec();
            changed[at] = byte;
            let _ = parse(&changed);
        }

        /// Text made of the format's own pieces, shuffled.
        #[test]
        fn shuffled_tokens_never_panic(tokens in proptest::collection::vec(
            prop_oneof![Just("{"), Just("}"), Just("="), Just(";"), Just("vertex"), Just("linedef"), Just("x"),
                        Just("v1"), Just("namespace"), Just("\"zdoom\""), Just("1"), Just("-1"), Just("2.5"),
                        Just("true"), Just("/*"), Just("*/"), Just("//"), Just("\n"), Just("sidefront"), Just("sector")],
            0..60)) {
            let _ = parse(tokens.join(" ").as_bytes());
        }
    }
}

mod records {
    use super::{parse, ROOM};

    /// UDMF's flags become Doom's bits: skills 1 and 4 give easy and hard,
    /// single player only gives Boom's not-deathmatch and not-co-op bits;
    /// the zdoom line special is listed as not translated (a thing's id is
    /// the game's to read, from the UDMF map).
    #[test]
    fn a_zdoom_room_becomes_doom_records() {
        let records = parse(ROOM.as_bytes()).unwrap().to_records("map01").unwrap();
        let map = &records.map;
        assert_eq!(map.name, "MAP01");
        assert_eq!(map.vertices[0], (-448.0, 256.0));
        assert_eq!((map.things[0].x, map.things[0].y, map.things[0].kind), (-384, 32, 1));
        assert_eq!(map.things[0].flags, 1 | 4 | 32 | 64);
        assert_eq!((map.lines[1].special, map.lines[1].tag), (0, 0));
        assert_eq!((map.lines[2].flags, map.lines[2].left), (4, Some(3)));
        assert_eq!((map.sides[2].upper.as_str(), map.sides[1].x_offset), ("STONE", 16));
        assert_eq!(
            records.unread,
            ["linedef 1: ZDoom line special 80 with arguments [3, 0, 7, 0, 0] (not translated yet)",]
        );
    }

    /// In the doom namespace a special is Doom's number and arg0 its tag.
    #[test]
    fn the_doom_namespace_keeps_doom_specials_and_tags() {
        let text = ROOM.replace("\"zdoom\"", "\"doom\"");
        let records = parse(text.as_bytes()).unwrap().to_records("E1M1").unwrap();
        assert_eq!((records.map.lines[1].special, records.map.lines[1].tag), (80, 3));
        assert!(records.unread.is_empty(), "{:?}", records.unread);
    }

    /// What Doom's 16-bit records cannot hold is refused, naming the record.
    #[test]
    fn values_past_doom_s_fields_are_refused() {
        let cases = [
            (
                "heightceiling = 104;",
                "heightceiling = 40000;",
                "sector 0: heightceiling = 40000 does not fit Doom's 16-bit field (-32768 to 32767)",
            ),
            (
                "offsetx = 16;",
                "offsetx = -40000;",
                "sidedef 1: offsetx = -40000 does not fit Doom's 16-bit field (-32768 to 32767)",
            ),
            ("type = 1;", "type = 70000;", "thing 0: type = 70000 does not fit Doom's 16-bit field (0 to 65535)"),
            ("x = -384.000;", "x = 40000.4;", "thing 0: x = 40000 does not fit Doom's 16-bit field (-32768 to 32767)"),
        ];
        for (from, to, want) in cases {
            let text = ROOM.replace(from, to);
            assert_eq!(parse(text.as_bytes()).unwrap().to_records("MAP01").unwrap_err(), want);
        }
    }
}

mod zdoom_sectors {
    use crate::map::special::{Damage, Suit};
    use crate::wad::udmf_records::zdoom_sector_special;

    /// ZDoom's sector numbers with a Doom meaning: Doom's moved up by 64,
    /// the lava floors (health_gathering's 83), instant death, and the
    /// damage and secret bits; the rest are not translated.
    #[test]
    fn zdoom_sector_specials_translate_where_doom_can_say_them() {
        let damage = |n| zdoom_sector_special(n).and_then(|s| s.damage);
        assert_eq!(damage(83), Some(Damage { amount: 8, every: 32, exit_below: 0, suit: Suit::Useless }));
        assert_eq!(damage(82).map(|d| d.amount), Some(5));
        assert_eq!(damage(115).map(|d| (d.amount, d.every)), Some((1000, 1)));
        assert_eq!(damage(512).map(|d| (d.amount, d.every, d.suit)), Some((10, 32, Suit::Shields)));
        assert_eq!(damage(768).map(|d| (d.amount, d.suit)), Some((20, Suit::Leaks)));
        // 71 is Doom's 7, nukage: 5 every 32 tics.
        assert_eq!(damage(71).map(|d| d.amount), Some(5));
        assert!(zdoom_sector_special(1024).is_some_and(|s| s.secret && s.damage.is_none()));
        assert_eq!(zdoom_sector_special(1), None, "Light_Phased is not Doom's");
        assert_eq!(zdoom_sector_special(227), None, "a carry sector is not Doom's");
        assert_eq!(zdoom_sector_special(4096 + 83), None, "a push bit is not Doom's");
    }
}
