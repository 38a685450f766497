//! Writes a generated puzzle level (tests/puzzle.rs) for a person to look
//! at: `cargo run -p sightline-tests --example puzzle -- SEED [monsters] > puzzle.ron`,
//! then `sightline check puzzle.ron -o plan.png` or `sightline play puzzle.ron`.

fn main() {
    let mut args = std::env::args().skip(1);
    let Some(seed) = args.next().and_then(|s| s.parse::<u64>().ok()) else {
        eprintln!("usage: puzzle SEED [monsters]  (writes the level's RON text to standard output)");
        std::process::exit(2);
    };
    let monsters = args.next().is_some_and(|a| a == "monsters");
    let puzzle = sightline_tests::puzzle::generate(seed, monsters);
    eprintln!("{}", puzzle.describe());
    print!("{}", puzzle.ron);
}
