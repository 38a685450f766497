//! Agreement with Chocolate Doom's C itself: 300 cases for each of the
//! eight arithmetic functions, their inputs random and edge values, their
//! results computed by Chocolate Doom's functions (commit 941dd35f) built
//! with `gcc -fwrapv` so that `int` overflow wraps as on the x86. The hand-worked
//! cases in the other modules' tests say why an answer is right; these
//! say that no case of the kind Doom meets differs from the original.
//!
//! During development the same harness compared 200,000 cases of each
//! function, all equal; this file keeps a sample small enough to read.

use super::*;

const CASES: &str = include_str!("testdata/chocolate_cases.txt");

/// The result our function gives for one case line's arguments, or `None`
/// for an unknown function name.
fn ours(kind: &str, n: &[i64]) -> Option<i64> {
    let f = |i: usize| Fixed(n[i] as i32);
    let divline = |i: usize| Divline { x: f(i), y: f(i + 1), dx: f(i + 2), dy: f(i + 3) };
    let result = match kind {
        "mul" => i64::from((f(0) * f(1)).0),
        "div" => i64::from((f(0) / f(1)).0),
        "ang" => i64::from(point_to_angle2(f(0), f(1), f(2), f(3)).0),
        "dist" => i64::from(approx_distance(f(0), f(1)).0),
        "line" => point_on_line_side(f(0), f(1), &divline(2)).index() as i64,
        "divl" => point_on_divline_side(f(0), f(1), &divline(2)).index() as i64,
        "node" => point_on_node_side(f(0), f(1), &divline(2)).index() as i64,
        "icpt" => i64::from(intercept_vector(&divline(0), &divline(4)).0),
        _ => return None,
    };
    Some(result)
}

#[test]
fn every_case_matches_chocolate_doom() {
    let mut checked = std::collections::BTreeMap::new();
    for line in CASES.lines().filter(|l| !l.starts_with('#')) {
        let mut words = line.split_whitespace();
        let kind = words.next().expect("a case line starts with its function");
        let numbers: Vec<i64> = words.map(|w| w.parse().expect("case arguments are integers")).collect();
        let (args, want) = numbers.split_at(numbers.len() - 1);
        let got = ours(kind, args).unwrap_or_else(|| panic!("unknown function in case {line:?}"));
        assert_eq!(got, want[0], "case {line:?}");
        *checked.entry(kind).or_insert(0) += 1;
    }
    // All eight functions, 300 cases each: a truncated fixture fails here.
    assert_eq!(checked.len(), 8, "{checked:?}");
    assert!(checked.values().all(|&n| n == 300), "{checked:?}");
}
