use sightline::map::parse_map;
#[test]
fn explore() {
    let base = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../maps/two_rooms.ron")).unwrap();
    let mc = base.replace("(0.0, 256.0), (256.0", "(0.0, 256.0) (256.0");
    let cases = [
        ("bom", format!("\u{feff}{base}")),
        ("crlf", mc.replace('\n', "\r\n")),
        ("cr", mc.replace('\n', "\r")),
        ("utf8", mc.replace("(0.0, 0.0), (0.0, 256.0)", "(0.0, 0.0), /* ÄÖÜ */ (0.0, 256.0)")),
        ("tab", mc.replace("        (0.0, 0.0)", "\t(0.0, 0.0)")),
        ("trailing", format!("{base}extra")),
        ("comment only", "// nothing\n".to_string()),
        ("sectr", base.replace("Sector(floor: 24.0", "Sectr(floor: 24.0")),
        ("nocomma line", base.replace("middle: \"BRICK\")),", "middle: \"BRICK\"))")),
        ("extra paren", base.replace("Side(sector: 1)),\n        Line(from: 3", "Side(sector: 1))),\n        Line(from: 3")),
        ("str vertex", base.replace("(512.0, 0.0)", "(\"a\", 0.0)")),
        ("light str", base.replace("light: 160,", "light: \"bright\",")),
        ("light str2", base.replace("light: 160,", "light:\"bright\",")),
        ("map only", "Map()".to_string()),
        ("number", "42".to_string()),
        ("deep", format!("{}{}", "[".repeat(100000), "]".repeat(100000))),
        ("deep2", base.replace("things: [", &format!("things: {}", "[".repeat(100000)))),
    ];
    for (n, t) in cases {
        match parse_map(&t, "x.ron") { Ok(_) => println!("{n}: OK"), Err(e) => println!("{n}: {e} // {e:?}") }
    }
}
