//! `Fixed`, Doom's 16.16 fixed-point number (`fixed_t` in `m_fixed.h`), with
//! `FixedMul` and `FixedDiv` reproduced bit for bit, overflow included.
//!
//! Doom's C adds, subtracts and negates `int`s and lets them overflow; on the
//! x86 it ran on (and in Chocolate Doom on today's machines) they wrap in
//! two's complement. Vanilla demos cross those wraps (long distances, huge
//! momenta), so every operator here wraps too and none of them panics.

use std::fmt;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Shl, Shr, Sub, SubAssign};

use serde::{Deserialize, Serialize};

/// Bits of fraction in a [`Fixed`] (`FRACBITS`).
pub const FRACBITS: u32 = 16;
/// One map unit as a raw fixed-point value (`FRACUNIT`, 65536).
pub const FRACUNIT: i32 = 1 << FRACBITS;

/// A 16.16 fixed-point number: `self.0 / 65536` map units (or tics, or
/// whatever the quantity is). The raw value is public because Doom's code
/// mixes fixed and plain integers freely; say which one you mean.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default, Serialize, Deserialize)]
#[serde(transparent)]
#[repr(transparent)]
pub struct Fixed(pub i32);

impl Fixed {
    pub const ZERO: Fixed = Fixed(0);
    /// One unit, `FRACUNIT`.
    pub const ONE: Fixed = Fixed(FRACUNIT);
    pub const MIN: Fixed = Fixed(i32::MIN);
    pub const MAX: Fixed = Fixed(i32::MAX);

    /// `n << FRACBITS`, as Doom writes `n*FRACUNIT`: outside ±32768 the high
    /// bits are lost, as they were in C.
    pub const fn from_int(n: i32) -> Fixed {
        Fixed(n << FRACBITS)
    }

    /// `self >> FRACBITS`: the whole units, rounded toward minus infinity
    /// (Doom's `x>>FRACBITS`, not C's `x/FRACUNIT`, which rounds toward zero).
    pub const fn to_int(self) -> i32 {
        self.0 >> FRACBITS
    }

    /// The value in units. Exact: every 16.16 value is an f64.
    pub fn to_f64(self) -> f64 {
        f64::from(self.0) / f64::from(FRACUNIT)
    }

    /// The nearest fixed-point value to `units`, for tools and tests, never
    /// for the simulation (Doom had no floats). Saturates outside the range;
    /// NaN gives zero (Rust's `as` from float).
    pub fn from_f64(units: f64) -> Fixed {
        Fixed((units * f64::from(FRACUNIT)).round() as i32)
    }

    /// C's `abs()` on the x86: `abs(i32::MIN)` is `i32::MIN` (the negation
    /// wraps). `FixedDiv` and `P_AproxDistance` depend on that.
    pub const fn abs(self) -> Fixed {
        Fixed(self.0.wrapping_abs())
    }

    /// `FixedMul` (`m_fixed.c`): the 64-bit product shifted down 16 bits
    /// (an arithmetic shift, so rounding toward minus infinity), then
    /// truncated to 32 bits. Vanilla's assembly (`imul` then `shrd`) and
    /// Chocolate Doom's C give the same bits, overflow included.
    pub const fn fixed_mul(self, rhs: Fixed) -> Fixed {
        Fixed(((self.0 as i64 * rhs.0 as i64) >> FRACBITS) as i32)
    }

    /// `FixedDiv` (`m_fixed.c`): `self / rhs` in 16.16, rounded toward zero,
    /// or the overflow answer.
    ///
    /// Doom tests for overflow with `(abs(a)>>14) >= abs(b)`: whenever the
    /// quotient would be 16384 units or more in size it answers `i32::MIN`
    /// if the signs differ (`(a^b) < 0`) and `i32::MAX` otherwise. The test
    /// is conservative (the 32 bits would hold up to 32768 units), and the
    /// saturation is part of the game: demos depend on it. Dividing by zero
    /// is caught by the same test, as `abs(a)>>14 >= 0`.
    ///
    /// `abs(i32::MIN)` is `i32::MIN` in C on the x86, so for `a == i32::MIN`
    /// the left side is negative and the test passes only for
    /// `b == i32::MIN` (answer `i32::MAX`: equal signs). Every other `b` goes
    /// on to the division, whose 64-bit quotient Chocolate Doom truncates to
    /// 32 bits; we do the same. Vanilla's `idiv` would have faulted there,
    /// so no vanilla demo can reach it. The one case with no answer in
    /// either, `i32::MIN / 0` (a divide-by-zero fault), gives the overflow
    /// answer here, `i32::MIN`, so that nothing panics.
    pub const fn fixed_div(self, rhs: Fixed) -> Fixed {
        let (a, b) = (self.0, rhs.0);
        if (a.wrapping_abs() >> 14) >= b.wrapping_abs() || b == 0 {
            return if (a ^ b) < 0 { Fixed::MIN } else { Fixed::MAX };
        }
        Fixed((((a as i64) << FRACBITS) / b as i64) as i32)
    }
}

impl fmt::Debug for Fixed {
    /// The value in units, e.g. `Fixed(-1.5)`; the f64 prints as the
    /// shortest decimal that reads back to it, so the raw bits are
    /// recoverable.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Fixed({})", self.to_f64())
    }
}

impl Add for Fixed {
    type Output = Fixed;
    fn add(self, rhs: Fixed) -> Fixed {
        Fixed(self.0.wrapping_add(rhs.0))
    }
}

impl Sub for Fixed {
    type Output = Fixed;
    fn sub(self, rhs: Fixed) -> Fixed {
        Fixed(self.0.wrapping_sub(rhs.0))
    }
}

impl AddAssign for Fixed {
    fn add_assign(&mut self, rhs: Fixed) {
        *self = *self + rhs;
    }
}

impl SubAssign for Fixed {
    fn sub_assign(&mut self, rhs: Fixed) {
        *self = *self - rhs;
    }
}

impl Neg for Fixed {
    type Output = Fixed;
    fn neg(self) -> Fixed {
        Fixed(self.0.wrapping_neg())
    }
}

/// `a * b` between two fixed values is `FixedMul`, as in Managed Doom's
/// `Fixed`; a product with a plain integer is the `Mul<i32>` below.
impl Mul for Fixed {
    type Output = Fixed;
    fn mul(self, rhs: Fixed) -> Fixed {
        self.fixed_mul(rhs)
    }
}

/// `a / b` between two fixed values is `FixedDiv`, saturating as Doom does.
impl Div for Fixed {
    type Output = Fixed;
    fn div(self, rhs: Fixed) -> Fixed {
        self.fixed_div(rhs)
    }
}

/// A fixed value times a plain integer (Doom's `mo->momx * 3`), wrapping.
impl Mul<i32> for Fixed {
    type Output = Fixed;
    fn mul(self, rhs: i32) -> Fixed {
        Fixed(self.0.wrapping_mul(rhs))
    }
}

/// Doom's `x >> n` on a `fixed_t`: arithmetic, rounding toward minus
/// infinity. `n` must be below 32 (C leaves larger shifts undefined).
impl Shr<u32> for Fixed {
    type Output = Fixed;
    fn shr(self, n: u32) -> Fixed {
        Fixed(self.0 >> n)
    }
}

/// Doom's `x << n` on a `fixed_t`: the bits shifted out are lost. `n` must
/// be below 32.
impl Shl<u32> for Fixed {
    type Output = Fixed;
    fn shl(self, n: u32) -> Fixed {
        Fixed(self.0 << n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const ONE: i32 = FRACUNIT;

    fn mul(a: i32, b: i32) -> i32 {
        Fixed(a).fixed_mul(Fixed(b)).0
    }

    fn div(a: i32, b: i32) -> i32 {
        Fixed(a).fixed_div(Fixed(b)).0
    }

    #[test]
    fn whole_units_round_trip_and_floor() {
        assert_eq!(Fixed::from_int(3), Fixed(3 * ONE));
        assert_eq!(Fixed::from_int(-2).to_int(), -2);
        // -0.5 units: >> rounds toward minus infinity, to -1.
        assert_eq!(Fixed(-ONE / 2).to_int(), -1);
        // 32768 units do not fit: the sign bit is all that is left, as in C.
        assert_eq!(Fixed::from_int(32768), Fixed::MIN);
        assert_eq!(Fixed(98304).to_f64(), 1.5);
        assert_eq!(Fixed::from_f64(-1.5), Fixed(-98304));
        assert_eq!(Fixed::from_f64(1e12), Fixed::MAX);
        assert_eq!(format!("{:?}", Fixed(-98304)), "Fixed(-1.5)");
    }

    #[test]
    fn add_sub_neg_wrap_like_x86() {
        assert_eq!(Fixed::MAX + Fixed(1), Fixed::MIN);
        assert_eq!(Fixed::MIN - Fixed(1), Fixed::MAX);
        assert_eq!(-Fixed::MIN, Fixed::MIN);
        assert_eq!(Fixed::MIN.abs(), Fixed::MIN);
        assert_eq!(Fixed(-5).abs(), Fixed(5));
        let mut x = Fixed::ONE;
        x += Fixed::ONE;
        x -= Fixed(1);
        assert_eq!(x, Fixed(2 * ONE - 1));
        assert_eq!(Fixed::MAX * 2, Fixed(-2));
        assert_eq!(Fixed(-3) >> 1, Fixed(-2));
        assert_eq!(Fixed(0x4000_0000) << 1, Fixed::MIN);
    }

    #[test]
    fn fixed_mul_edges() {
        assert_eq!(mul(0, i32::MAX), 0);
        assert_eq!(mul(ONE, ONE), ONE);
        assert_eq!(mul(ONE, -ONE), -ONE);
        assert_eq!(mul(3 * ONE / 2, 2 * ONE), 3 * ONE);
        // One raw step times one raw step is 2^-32 units: 0, and -2^-32 floors to -1.
        assert_eq!(mul(1, 1), 0);
        assert_eq!(mul(1, -1), -1);
        assert_eq!(mul(-1, -1), 0);
        assert_eq!(mul(i32::MAX, ONE), i32::MAX);
        assert_eq!(mul(i32::MIN, ONE), i32::MIN);
        // 2^31 * 2^31 >> 16 = 2^46, whose low 32 bits are zero.
        assert_eq!(mul(i32::MIN, i32::MIN), 0);
        // (2^31 - 1)^2 >> 16 = 2^46 - 2^16 (the low bits shifted out), truncated to 32 bits.
        assert_eq!(mul(i32::MAX, i32::MAX), -ONE);
        assert_eq!(mul(i32::MIN, -ONE), i32::MIN);
        assert_eq!(Fixed(ONE) * Fixed(-2 * ONE), Fixed(-2 * ONE));
    }

    #[test]
    fn fixed_div_ordinary_quotients_truncate_toward_zero() {
        assert_eq!(div(ONE, ONE), ONE);
        assert_eq!(div(3 * ONE, 2 * ONE), 3 * ONE / 2);
        assert_eq!(div(-3 * ONE, 2 * ONE), -3 * ONE / 2);
        assert_eq!(div(ONE, 3 * ONE), 21845);
        assert_eq!(div(-ONE, 3 * ONE), -21845);
        assert_eq!(div(ONE, -3 * ONE), -21845);
        assert_eq!(div(-ONE, -3 * ONE), 21845);
        assert_eq!(div(0, ONE), 0);
        assert_eq!(div(0, -1), 0);
        assert_eq!(Fixed(ONE) / Fixed(4 * ONE), Fixed(ONE / 4));
    }

    #[test]
    fn fixed_div_overflow_boundary_on_both_sides() {
        // b = 1 raw: |a| >> 14 >= 1 from |a| = 2^14 on.
        assert_eq!(div((1 << 14) - 1, 1), ((1 << 14) - 1) << 16);
        assert_eq!(div(1 << 14, 1), i32::MAX);
        assert_eq!(div(-(1 << 14) + 1, 1), (-(1 << 14) + 1) << 16);
        assert_eq!(div(-(1 << 14), 1), i32::MIN);
        // Negative divisors: the answer's sign is the xor of the signs.
        assert_eq!(div(1 << 14, -1), i32::MIN);
        assert_eq!(div(-(1 << 14), -1), i32::MAX);
        // With b = 1 unit the line sits at |a| = 16384 units.
        assert_eq!(div(16383 * ONE + (ONE - 1), ONE), 16383 * ONE + (ONE - 1));
        assert_eq!(div(16384 * ONE, ONE), i32::MAX);
        assert_eq!(div(-16384 * ONE, ONE), i32::MIN);
        assert_eq!(div(-16384 * ONE, -ONE), i32::MAX);
        assert_eq!(div(i32::MAX, ONE), i32::MAX);
    }

    #[test]
    fn fixed_div_by_zero_is_the_overflow_answer() {
        assert_eq!(div(0, 0), i32::MAX);
        assert_eq!(div(ONE, 0), i32::MAX);
        assert_eq!(div(-1, 0), i32::MIN);
        assert_eq!(div(i32::MAX, 0), i32::MAX);
        // Vanilla faults here; we answer as the overflow test would.
        assert_eq!(div(i32::MIN, 0), i32::MIN);
    }

    #[test]
    fn fixed_div_of_i32_min_follows_chocolate_doom() {
        // abs(INT_MIN) >> 14 is negative, so only b == INT_MIN saturates,
        // and to INT_MAX (equal signs).
        assert_eq!(div(i32::MIN, i32::MIN), i32::MAX);
        // Otherwise the 64-bit quotient is truncated: -2^47 / 1 keeps no low bits.
        assert_eq!(div(i32::MIN, 1), 0);
        assert_eq!(div(i32::MIN, -1), 0);
        // -2^47 / 2^16 = -2^31, which fits.
        assert_eq!(div(i32::MIN, ONE), i32::MIN);
        assert_eq!(div(i32::MIN, -ONE), i32::MIN);
        // A divisor of 2^31 - 1: a true quotient just under -1 unit, truncated toward zero.
        assert_eq!(div(i32::MIN, i32::MAX), -ONE);
        // As a divisor INT_MIN has a negative abs(), so the test fires for every a.
        assert_eq!(div(i32::MAX, i32::MIN), i32::MIN);
        assert_eq!(div(1, i32::MIN), i32::MIN);
    }

    proptest! {
        #[test]
        fn fixed_mul_is_the_floored_product_truncated(a in any::<i32>(), b in any::<i32>()) {
            let exact = i128::from(a) * i128::from(b);
            prop_assert_eq!(mul(a, b), exact.div_euclid(1 << 16) as i32);
        }

        #[test]
        fn fixed_div_never_panics_and_is_exact_when_it_does_not_saturate(
            a in any::<i32>(),
            b in any::<i32>(),
        ) {
            let q = div(a, b);
            let saturates = b == 0 || (a.wrapping_abs() >> 14) >= b.wrapping_abs();
            if saturates {
                prop_assert!(q == i32::MIN || q == i32::MAX);
            } else {
                let exact = (i128::from(a) << 16) / i128::from(b);
                prop_assert_eq!(q, exact as i32);
            }
        }
    }

    #[test]
    fn fixed_div_saturates_with_the_sign_of_the_true_quotient() {
        // Everywhere the overflow test fires with a != INT_MIN, the true quotient is
        // at least 16384 units in size and the answer has its sign.
        let cases: [(i32, i32); 5] =
            [(1 << 20, 3), (-(1 << 20), 3), (1 << 20, -3), (i32::MAX, 1 << 16), (-(1 << 30), -(1 << 16))];
        for (a, b) in cases {
            assert!((a.wrapping_abs() >> 14) >= b.wrapping_abs());
            let q = div(a, b);
            let exact = (i64::from(a) << 16) / i64::from(b);
            assert!(exact.abs() >= 16384 * i64::from(ONE));
            assert_eq!(i64::from(q.signum()), exact.signum(), "{a} / {b}");
        }
    }
}
