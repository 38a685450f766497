use sightline::bsp::{build, check::check_invariants, file, BuildOptions};
use sightline::level::level_from_bytes;
use sightline::map::parse_map;
use sightline::render::{Renderer, Shade, View};
#[test]
fn explore() {
    for name in ["two_rooms", "pillars"] {
        let base =
            std::fs::read_to_string(format!("{}/../maps/{name}.ron", env!("CARGO_MANIFEST_DIR")))
                .unwrap();
        let map = parse_map(&base, "x").unwrap();
        let c = build(&map, &BuildOptions::default()).unwrap();
        let bytes = file::to_bytes(&c);
        println!(
            "len {} {:?}",
            bytes.len(),
            level_from_bytes(&bytes, "c", &BuildOptions::default()).map(|m| m == c)
        );
        let (mut ok, mut bad, mut err) = (0, 0, 0);
        let mut msgs = std::collections::BTreeMap::new();
        for i in 0..bytes.len() {
            for x in [0x01u8, 0x10, 0x80, 0xff] {
                let mut b = bytes.clone();
                b[i] ^= x;
                match level_from_bytes(&b, "c.slbsp", &BuildOptions::default()) {
                    Ok(m) => {
                        ok += 1;
                        if let Err(e) = check_invariants(&m.map, &m.bsp) {
                            bad += 1;
                            if bad < 5 {
                                println!("{i} {x}: {e}");
                            }
                        }
                        let v = View::at_start(&m.map).unwrap();
                        for r in Renderer::ALL {
                            let t = std::time::Instant::now();
                            let _ = sightline_tests::render(&m, &v, (64, 40), r, Shade::Ids);
                            let el = t.elapsed();
                            if el.as_millis() > 20 {
                                println!("slow {i} {x} {el:?}");
                            }
                        }
                    }
                    Err(e) => {
                        err += 1;
                        let s = e.to_string();
                        *msgs
                            .entry(s.chars().take(70).collect::<String>())
                            .or_insert(0) += 1;
                    }
                }
            }
        }
        println!("ok {ok} bad {bad} err {err}");
        for (k, v) in msgs {
            println!("{v}: {k}");
        }
    }
}
