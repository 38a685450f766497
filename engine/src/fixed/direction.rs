//! The direction from one point to another as a binary angle, as Doom finds
//! it: `R_PointToAngle` / `R_PointToAngle2` (`r_main.c`) folding the vector
//! into the first octant and looking its slope up with `SlopeDiv`
//! (`tables.c`) in `tantoangle`. Monsters' facing, missiles' aim and the
//! renderer's wall angles all come from here, so its quirks are the game's.
//!
//! The quirks, kept on purpose:
//! - the vector is `x2 - x1` in 32 bits and wraps past ±32768 units, so two
//!   points further apart than that see each other in the wrong direction;
//! - `SlopeDiv` shifts its numerator left by 3 in 32 bits, losing the top
//!   bits once the smaller coordinate reaches 8192 units;
//! - a denominator under 512 raw (1/128 unit) reads as slope 1, 45 degrees;
//! - octants measured from the y axis subtract from `ANG90 - 1` or
//!   `ANG180 - 1`, so due north is `0x3fffffff`, one short of `ANG90`.

use super::angle::{Angle, ANG180, ANG270, ANG90};
use super::number::Fixed;
use super::tables::{tantoangle, SLOPERANGE};

/// `SlopeDiv(num, den)`: the `tantoangle` index of the slope `num / den`
/// (with `num <= den`), in 1/2048ths, at most `SLOPERANGE`.
///
/// `(num << 3) / (den >> 8)` in unsigned 32 bits: `<< 3` drops the top
/// three bits of `num`, as in C; `den < 512` (where `den >> 8` would be 0
/// or 1) answers `SLOPERANGE`, which also spares the division by zero.
pub const fn slope_div(num: u32, den: u32) -> usize {
    if den < 512 {
        return SLOPERANGE;
    }
    let ans = (num << 3) / (den >> 8);
    if ans as usize <= SLOPERANGE {
        ans as usize
    } else {
        SLOPERANGE
    }
}

/// `R_PointToAngle` once the viewpoint has been subtracted: the angle of the
/// vector `(dx, dy)`, 0 for the zero vector.
///
/// The folding works on signed 32-bit values as Doom's does: a coordinate
/// is negated with wrapping (so `i32::MIN` stays negative), compared as
/// signed, then handed to [`slope_div`] as unsigned.
pub fn point_to_angle(dx: Fixed, dy: Fixed) -> Angle {
    let (x, y) = (dx.0, dy.0);
    if x == 0 && y == 0 {
        return Angle(0);
    }
    // tantoangle of the slope num/den, where num <= den in the folded octant.
    let atan = |num: i32, den: i32| tantoangle(slope_div(num as u32, den as u32));
    let one = Angle(1);
    if x >= 0 {
        if y >= 0 {
            if x > y {
                atan(y, x) // 0 to 45 degrees
            } else {
                ANG90 - one - atan(x, y) // 45 to 90
            }
        } else {
            let y = y.wrapping_neg();
            if x > y {
                -atan(y, x) // 315 to 360
            } else {
                ANG270 + atan(x, y) // 270 to 315
            }
        }
    } else {
        let x = x.wrapping_neg();
        if y >= 0 {
            if x > y {
                ANG180 - one - atan(y, x) // 135 to 180
            } else {
                ANG90 + atan(x, y) // 90 to 135
            }
        } else {
            let y = y.wrapping_neg();
            if x > y {
                ANG180 + atan(y, x) // 180 to 225
            } else {
                ANG270 - one - atan(x, y) // 225 to 270
            }
        }
    }
}

/// `R_PointToAngle2(x1, y1, x2, y2)`: the angle from `(x1, y1)` to
/// `(x2, y2)`, with the difference taken in wrapping 32 bits.
///
/// Vanilla did this by storing `(x1, y1)` in the renderer's `viewx`/`viewy`
/// globals and calling `R_PointToAngle`, so a play-side call clobbered the
/// view position; that affected only drawing, never the simulation, and a
/// pure function leaves nothing to clobber.
pub fn point_to_angle2(x1: Fixed, y1: Fixed, x2: Fixed, y2: Fixed) -> Angle {
    point_to_angle(x2 - x1, y2 - y1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixed::angle::ANG45;
    use crate::fixed::number::FRACUNIT;

    /// `(dx, dy)` in whole units.
    fn angle_of(dx: i32, dy: i32) -> u32 {
        point_to_angle(Fixed::from_int(dx), Fixed::from_int(dy)).0
    }

    /// tantoangle[1024] in tables.c: atan(1/2), 26.57 degrees.
    const ATAN_HALF: u32 = 316_933_408;

    #[test]
    fn slope_div_cases() {
        assert_eq!(slope_div(0, FRACUNIT as u32), 0);
        // 1/2 of a unit over a unit: (32768 << 3) / 256 = 1024.
        assert_eq!(slope_div(FRACUNIT as u32 / 2, FRACUNIT as u32), 1024);
        assert_eq!(slope_div(FRACUNIT as u32, FRACUNIT as u32), SLOPERANGE);
        // Small denominators read as the diagonal, whatever the numerator.
        assert_eq!(slope_div(0, 511), SLOPERANGE);
        assert_eq!(slope_div(0, 512), 0);
        // The numerator's top bits are lost: 2^29 << 3 is 0 in 32 bits, so a
        // slope of one half at 8192 units reads as slope 0.
        assert_eq!(slope_div(0x2000_0000, 0x4000_0000), 0);
        assert_eq!(slope_div(0x1fff_0000, 0x3ffe_0000), 1024);
        // A numerator above the denominator is clamped.
        assert_eq!(slope_div(u32::MAX >> 3, 1 << 16), SLOPERANGE);
    }

    #[test]
    fn axes() {
        assert_eq!(angle_of(0, 0), 0);
        assert_eq!(angle_of(1, 0), 0);
        // Due north falls in the octant that subtracts from ANG90 - 1.
        assert_eq!(angle_of(0, 1), ANG90.0 - 1);
        assert_eq!(angle_of(-1, 0), ANG180.0 - 1);
        assert_eq!(angle_of(0, -1), ANG270.0);
        assert_eq!(angle_of(0, 1000), ANG90.0 - 1);
    }

    #[test]
    fn diagonals() {
        // x > y fails on the diagonal, so it is measured from the y axis.
        assert_eq!(angle_of(1, 1), ANG45.0 - 1);
        assert_eq!(angle_of(-1, 1), ANG90.0 + ANG45.0);
        assert_eq!(angle_of(-1, -1), ANG270.0 - 1 - ANG45.0);
        assert_eq!(angle_of(1, -1), ANG270.0 + ANG45.0);
    }

    #[test]
    fn all_eight_octants() {
        // Each vector has slope 1/2 or 2 in its octant; the expectations
        // follow R_PointToAngle's branches by hand with tantoangle[1024].
        assert_eq!(angle_of(2, 1), ATAN_HALF); // 26.57 degrees
        assert_eq!(angle_of(1, 2), ANG90.0 - 1 - ATAN_HALF); // 63.43
        assert_eq!(angle_of(-1, 2), ANG90.0 + ATAN_HALF); // 116.57
        assert_eq!(angle_of(-2, 1), ANG180.0 - 1 - ATAN_HALF); // 153.43
        assert_eq!(angle_of(-2, -1), ANG180.0 + ATAN_HALF); // 206.57
        assert_eq!(angle_of(-1, -2), ANG270.0 - 1 - ATAN_HALF); // 243.43
        assert_eq!(angle_of(1, -2), ANG270.0 + ATAN_HALF); // 296.57
        assert_eq!(angle_of(2, -1), ATAN_HALF.wrapping_neg()); // 333.43

        // The same numbers written out, as a check on the constants.
        assert_eq!(angle_of(1, 2), 756_808_415);
        assert_eq!(angle_of(2, -1), 3_978_033_888);
    }

    #[test]
    fn point_to_angle2_is_relative_to_the_first_point() {
        let p = |x: i32| Fixed::from_int(x);
        assert_eq!(point_to_angle2(p(100), p(100), p(102), p(101)).0, ATAN_HALF);
        assert_eq!(point_to_angle2(p(-50), p(7), p(-50), p(3)).0, ANG270.0);
    }

    #[test]
    fn tiny_vectors_read_as_diagonals() {
        // 100 raw east, 1 raw north: den < 512, so 45 degrees, not 0.
        assert_eq!(point_to_angle(Fixed(100), Fixed(1)), ANG45);
    }

    #[test]
    fn far_points_wrap_as_in_vanilla() {
        // 40000 units east does not fit in 32 bits: x2 - x1 wraps negative and
        // the target is seen to the west.
        let east = point_to_angle2(Fixed::from_int(-20000), Fixed(0), Fixed::from_int(20000), Fixed(0));
        assert_eq!(east, ANG180 - Angle(1));
    }

    #[test]
    fn i32_min_stays_negative_when_folded() {
        // x = -2^31 negates to itself; x > y fails, so the 90-135 branch runs
        // with slope_div(2^31, 0): den < 512, the diagonal. Vanilla's answer.
        assert_eq!(point_to_angle(Fixed::MIN, Fixed(0)), ANG90 + ANG45);
        // y = -2^31 likewise: x > y holds (y is negative), and slope_div(2^31, x)
        // shifts the numerator out to 0: a point 32768 units south reads as east.
        assert_eq!(point_to_angle(Fixed::ONE, Fixed::MIN), Angle(0));
    }
}
