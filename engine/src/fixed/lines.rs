//! The fixed-point geometry questions of `p_maputl.c` and `r_main.c`:
//! which side of a line a point is on, where a trace crosses a line, and
//! Doom's cheap distance. Collision, line crossing, hitscan and the BSP
//! walk all ask them, and each of Doom's versions rounds differently, so
//! there is one function per Doom function and they are not merged:
//!
//! | here                      | Doom                  | shifts before `FixedMul` | sign-bit shortcut |
//! |---------------------------|-----------------------|--------------------------|-------------------|
//! | [`point_on_line_side`]    | `P_PointOnLineSide`   | line's `dx`, `dy` >> 16  | no                |
//! | [`point_on_divline_side`] | `P_PointOnDivlineSide`| all four >> 8            | yes               |
//! | [`point_on_node_side`]    | `R_PointOnSide`       | node's `dx`, `dy` >> 16  | yes               |
//!
//! The shortcut decides from the signs alone whenever the two cross
//! products must differ in sign, before their truncated values can tie at
//! zero; dropping it changes answers near the line (room4doom lost demo sync
//! that way). `P_PointOnLineSide` never had it, and adding it would be as
//! wrong as dropping it elsewhere.

use serde::{Deserialize, Serialize};

use super::number::{Fixed, FRACBITS};

/// A line as a point and a direction (`divline_t`): a trace, a BSP node's
/// partition, or a map line through its first vertex (`P_MakeDivline`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
pub struct Divline {
    pub x: Fixed,
    pub y: Fixed,
    pub dx: Fixed,
    pub dy: Fixed,
}

impl Divline {
    /// The line from `(x1, y1)` to `(x2, y2)`: `P_MakeDivline` of a line
    /// whose `dx`, `dy` were set as `v2 - v1` (`P_LoadLineDefs`), wrapping.
    pub fn from_points(x1: Fixed, y1: Fixed, x2: Fixed, y2: Fixed) -> Divline {
        Divline { x: x1, y: y1, dx: x2 - x1, dy: y2 - y1 }
    }
}

/// The side of a directed line a point is on. Doom returns 0 for the front
/// (the right-hand side, looking along the line) and 1 for the back, and
/// uses the number as an index (`sidenum[side]`); [`Side::index`] gives it.
/// A point exactly on a sloped line is a tie of the two products, which
/// every function here calls the back; on a vertical or horizontal line the
/// test is `x <= line.x` (or `y <= line.y`), so it is the back of a line
/// going north or west and the front of one going south or east.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Side {
    Front,
    Back,
}

impl Side {
    /// Doom's number for the side: 0 front, 1 back.
    pub const fn index(self) -> usize {
        match self {
            Side::Front => 0,
            Side::Back => 1,
        }
    }

    const fn back_if(back: bool) -> Side {
        if back {
            Side::Back
        } else {
            Side::Front
        }
    }
}

/// `P_AproxDistance`: `|dx| + |dy| - min(|dx|, |dy|) / 2`, up to 12% long
/// on the diagonal but what Doom's ranges and damage are measured in.
/// `abs` is C's on the x86 (`abs(i32::MIN)` stays negative) and the sums
/// wrap.
pub fn approx_distance(dx: Fixed, dy: Fixed) -> Fixed {
    let (dx, dy) = (dx.abs(), dy.abs());
    if dx < dy {
        dx + dy - (dx >> 1)
    } else {
        dx + dy - (dy >> 1)
    }
}

/// The answer all three side tests give for a vertical or horizontal line,
/// from a comparison alone: the same preamble in each of Doom's functions.
fn axis_side(x: Fixed, y: Fixed, line: &Divline) -> Option<Side> {
    if line.dx.0 == 0 {
        let back = if x <= line.x { line.dy.0 > 0 } else { line.dy.0 < 0 };
        return Some(Side::back_if(back));
    }
    if line.dy.0 == 0 {
        let back = if y <= line.y { line.dx.0 < 0 } else { line.dx.0 > 0 };
        return Some(Side::back_if(back));
    }
    None
}

/// The sign-bit shortcut of `P_PointOnDivlineSide` and `R_PointOnSide`:
/// when `line.dy * dx` and `dy * line.dx` have opposite signs (by the sign
/// bits, counting zero as positive), the first one's sign is the answer.
fn sign_side(line: &Divline, dx: Fixed, dy: Fixed) -> Option<Side> {
    if (line.dy.0 ^ line.dx.0 ^ dx.0 ^ dy.0) < 0 {
        // The left product negative means the back.
        return Some(Side::back_if((line.dy.0 ^ dx.0) < 0));
    }
    None
}

/// `P_PointOnLineSide`: the side of a map line (given through its first
/// vertex and `v2 - v1`). No sign-bit shortcut; the line's deltas lose
/// their fraction (`>> FRACBITS`) before the products.
pub fn point_on_line_side(x: Fixed, y: Fixed, line: &Divline) -> Side {
    if let Some(side) = axis_side(x, y, line) {
        return side;
    }
    let (dx, dy) = (x - line.x, y - line.y);
    let left = (line.dy >> FRACBITS) * dx;
    let right = dy * (line.dx >> FRACBITS);
    Side::back_if(right >= left)
}

/// `P_PointOnDivlineSide`: the side of a trace or other divline, with the
/// sign-bit shortcut; all four values lose 8 bits before the products.
pub fn point_on_divline_side(x: Fixed, y: Fixed, line: &Divline) -> Side {
    if let Some(side) = axis_side(x, y, line) {
        return side;
    }
    let (dx, dy) = (x - line.x, y - line.y);
    if let Some(side) = sign_side(line, dx, dy) {
        return side;
    }
    let left = (line.dy >> 8) * (dx >> 8);
    let right = (dy >> 8) * (line.dx >> 8);
    Side::back_if(right >= left)
}

/// `R_PointOnSide`: the side of a BSP node's partition, with the sign-bit
/// shortcut; the node's deltas lose their fraction. `R_PointOnSegSide` is
/// the same computation on a seg's first vertex and `v2 - v1`.
pub fn point_on_node_side(x: Fixed, y: Fixed, node: &Divline) -> Side {
    if let Some(side) = axis_side(x, y, node) {
        return side;
    }
    let (dx, dy) = (x - node.x, y - node.y);
    if let Some(side) = sign_side(node, dx, dy) {
        return side;
    }
    let left = (node.dy >> FRACBITS) * dx;
    let right = dy * (node.dx >> FRACBITS);
    Side::back_if(right >= left)
}

/// `P_InterceptVector(v2, v1)`: how far along `along` (as a 16.16 fraction
/// of its `dx, dy`) it crosses `crossing`; 0 when they are parallel.
///
/// Argument order as Doom's: the path traversers pass the trace first and
/// the line second. The `>> 8` on some factors and not others, the wrapping
/// sums and `FixedDiv`'s saturation are Doom's; a crossing far beyond the
/// trace's end saturates rather than overflowing.
pub fn intercept_vector(along: &Divline, crossing: &Divline) -> Fixed {
    let (v2, v1) = (along, crossing);
    let den = (v1.dy >> 8) * v2.dx - (v1.dx >> 8) * v2.dy;
    if den.0 == 0 {
        return Fixed::ZERO;
    }
    let num = ((v1.x - v2.x) >> 8) * v1.dy + ((v2.y - v1.y) >> 8) * v1.dx;
    num / den
}

#[cfg(test)]
mod tests {
    use super::*;

    fn u(n: i32) -> Fixed {
        Fixed::from_int(n)
    }

    /// Every side test, for the cases where all three must agree.
    fn sides(x: Fixed, y: Fixed, line: &Divline) -> [Side; 3] {
        [point_on_line_side(x, y, line), point_on_divline_side(x, y, line), point_on_node_side(x, y, line)]
    }

    #[test]
    fn approx_distance_is_dooms_octagon() {
        // 3-4-5: 3 + 4 - 1.5 = 5.5 units, whichever way round and whatever the signs.
        assert_eq!(approx_distance(u(3), u(4)), Fixed::from_f64(5.5));
        assert_eq!(approx_distance(u(-4), u(3)), Fixed::from_f64(5.5));
        assert_eq!(approx_distance(u(0), u(-7)), u(7));
        assert_eq!(approx_distance(Fixed(3), Fixed(0)), Fixed(3));
        // Odd raw values: the half is floored, 5 + 3 - 1.
        assert_eq!(approx_distance(Fixed(5), Fixed(3)), Fixed(7));
        // abs(INT_MIN) stays negative: -2^31 - (-2^30) = -2^30.
        assert_eq!(approx_distance(Fixed::MIN, Fixed(0)), Fixed(-(1 << 30)));
    }

    #[test]
    fn axis_aligned_lines_decide_by_comparison() {
        // A line going north from the origin: its front is the east (right-hand) side.
        let north = Divline { x: u(0), y: u(0), dx: u(0), dy: u(10) };
        assert_eq!(sides(u(1), u(5), &north), [Side::Front; 3]);
        assert_eq!(sides(u(-1), u(5), &north), [Side::Back; 3]);
        assert_eq!(sides(u(0), u(5), &north), [Side::Back; 3]);
        let south = Divline { dy: u(-10), ..north };
        assert_eq!(sides(u(1), u(5), &south), [Side::Back; 3]);
        // A line going east: its front is the south.
        let east = Divline { x: u(0), y: u(0), dx: u(10), dy: u(0) };
        assert_eq!(sides(u(5), u(-1), &east), [Side::Front; 3]);
        assert_eq!(sides(u(5), u(1), &east), [Side::Back; 3]);
        // On an axis-aligned line the comparison is `<=`, so where a point on
        // the line goes depends on the line's direction.
        assert_eq!(sides(u(5), u(0), &east), [Side::Front; 3]);
        let west = Divline { dx: u(-10), ..east };
        assert_eq!(sides(u(5), u(1), &west), [Side::Front; 3]);
        assert_eq!(Side::Front.index(), 0);
        assert_eq!(Side::Back.index(), 1);
    }

    #[test]
    fn diagonal_lines_agree_away_from_the_line() {
        let line = Divline::from_points(u(0), u(0), u(64), u(32));
        assert_eq!(line.dx, u(64));
        assert_eq!(sides(u(32), u(0), &line), [Side::Front; 3]);
        assert_eq!(sides(u(0), u(32), &line), [Side::Back; 3]);
        assert_eq!(sides(u(-32), u(-32), &line), [Side::Front; 3]);
        // On the line: right == left, the back.
        assert_eq!(sides(u(32), u(16), &line), [Side::Back; 3]);
    }

    #[test]
    fn the_sign_shortcut_is_where_doom_has_it() {
        // A line almost due north (dx one raw step) and a point straight
        // south of its start. Exactly, the point is in front (dy * line.dx < 0 =
        // line.dy * dx). Truncated, both products are 0 and the tie says back;
        // the shortcut sees the signs differ and says front.
        let line = Divline { x: u(0), y: u(0), dx: Fixed(1), dy: u(1) };
        let (x, y) = (u(0), u(-1));
        assert_eq!(point_on_divline_side(x, y, &line), Side::Front);
        assert_eq!(point_on_node_side(x, y, &line), Side::Front);
        assert_eq!(point_on_line_side(x, y, &line), Side::Back);
    }

    #[test]
    fn divline_side_keeps_sub_unit_deltas_and_node_side_does_not() {
        // A line of slope 1/2 whose deltas are under a unit (40000 and 20000
        // raw). P_PointOnDivlineSide's >> 8 keeps them (156 and 78); R_PointOnSide's
        // >> 16 leaves 0 and 0, so both products are 0 and every point ties to the back.
        let line = Divline { x: u(0), y: u(0), dx: Fixed(40000), dy: Fixed(20000) };
        // left = FixedMul(78, 51200) = 60; right = FixedMul(26112, 156) = 62: the back.
        assert_eq!(point_on_divline_side(u(200), u(102), &line), Side::Back);
        assert_eq!(point_on_node_side(u(200), u(102), &line), Side::Back);
        // right = FixedMul(25088, 156) = 59 < 60: the front, but not for the node test.
        assert_eq!(point_on_divline_side(u(200), u(98), &line), Side::Front);
        assert_eq!(point_on_node_side(u(200), u(98), &line), Side::Back);
    }

    #[test]
    fn intercept_vector_finds_the_crossing_fraction() {
        // A trace 100 units east and a wall at x = 25 from y = -10 to 10:
        // a quarter of the way along.
        let trace = Divline { x: u(0), y: u(0), dx: u(100), dy: u(0) };
        let wall = Divline::from_points(u(25), u(-10), u(25), u(10));
        assert_eq!(intercept_vector(&trace, &wall), Fixed(16384));
        // Walls behind the start give negative fractions, beyond the end more than one.
        let behind = Divline::from_points(u(-50), u(-10), u(-50), u(10));
        assert_eq!(intercept_vector(&trace, &behind), Fixed(-32768));
        let beyond = Divline::from_points(u(150), u(-10), u(150), u(10));
        assert_eq!(intercept_vector(&trace, &beyond), Fixed(98304));
        // Parallel: zero, not a division by zero.
        let parallel = Divline::from_points(u(0), u(5), u(10), u(5));
        assert_eq!(intercept_vector(&trace, &parallel), Fixed::ZERO);
    }

    #[test]
    fn intercept_vector_rounds_as_doom() {
        // den = FixedMul(20u >> 8, 3u) = (5120 * 196608) >> 16 = 15360;
        // num = FixedMul(1u >> 8, 20u) = (256 * 1310720) >> 16 = 5120;
        // FixedDiv(5120, 15360) = (5120 << 16) / 15360 = 21845, a third truncated.
        let trace = Divline { x: u(0), y: u(0), dx: u(3), dy: u(0) };
        let wall = Divline::from_points(u(1), u(-10), u(1), u(10));
        assert_eq!(intercept_vector(&trace, &wall), Fixed(21845));
    }
}
