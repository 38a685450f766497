use sightline::autopilot::nav::{Heights, NavGrid};
use sightline::level::open_level;

fn main() {
    let path = std::env::args().nth(1).unwrap();
    let level = open_level(std::path::Path::new(&path), &Default::default()).unwrap();
    let nav = NavGrid::new(&level.compiled);
    let h = Heights::of(&level.compiled.map);
    let mut n = 0;
    for c in 0..nav.cells() as u32 {
        if !nav.standable(c) {
            continue;
        }
        let from = nav.span(c, &h);
        for d in 0..8 {
            let Some(nb) = nav.neighbour(c, d) else { continue };
            if !nav.open(c, d) || from.high - nav.span(nb, &h).high <= 24.0 {
                continue;
            }
            n += 1;
            if let Some(l) = nav.leap(c, d, &h, |_| false) {
                println!("leap {:?} d{d} -> {:?} {l:?}", nav.centre_of(c), nav.centre_of(l.to));
            }
        }
    }
    println!("{n} edges");
}
