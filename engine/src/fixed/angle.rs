//! `Angle`, Doom's binary angle (`angle_t`, "BAM" in `tables.h`): a turn is
//! 2^32, so adding and subtracting angles wraps around the circle for free,
//! and the top 13 bits index the fine tables.
//!
//! Convention (Doom's): 0 faces east (+x), angles grow counter-clockwise,
//! `ANG90` faces north (+y).

use std::fmt;
use std::ops::{Add, AddAssign, Neg, Sub, SubAssign};

use serde::{Deserialize, Serialize};

use super::number::Fixed;
use super::tables::{finecosine, finesine};

/// A binary angle: `self.0 / 2^32` of a turn.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default, Serialize, Deserialize)]
#[serde(transparent)]
#[repr(transparent)]
pub struct Angle(pub u32);

/// `ANG45 / 45`, truncated: 11930464, a little under one degree (the exact
/// degree is 11930464.7). Doom's own constant, kept for what uses it.
pub const ANG1: Angle = Angle(ANG45.0 / 45);
pub const ANG45: Angle = Angle(0x2000_0000);
pub const ANG90: Angle = Angle(0x4000_0000);
pub const ANG180: Angle = Angle(0x8000_0000);
pub const ANG270: Angle = Angle(0xc000_0000);
/// The largest angle, one step short of a full turn (`ANG_MAX`).
pub const ANG_MAX: Angle = Angle(u32::MAX);

/// From a 32-bit angle to an index into the fine tables (8192 to the turn):
/// `angle >> 19` (`ANGLETOFINESHIFT`).
pub const ANGLETOFINESHIFT: u32 = 19;

/// 2^32 as a float, the number of binary angles in a turn.
const TURN: f64 = 4_294_967_296.0;

impl Angle {
    pub const ZERO: Angle = Angle(0);

    /// `angle >> ANGLETOFINESHIFT`: which of the 8192 fine angles this is,
    /// always below `FINEANGLES`.
    pub const fn fine_index(self) -> usize {
        (self.0 >> ANGLETOFINESHIFT) as usize
    }

    /// `finesine[angle >> ANGLETOFINESHIFT]`.
    pub fn sin(self) -> Fixed {
        finesine(self.fine_index())
    }

    /// `finecosine[angle >> ANGLETOFINESHIFT]`.
    pub fn cos(self) -> Fixed {
        finecosine(self.fine_index())
    }

    /// Degrees in `[0, 360)`, exact: `value * 360` is below 2^53 and the
    /// division is by a power of two.
    pub fn to_degrees(self) -> f64 {
        f64::from(self.0) * 360.0 / TURN
    }

    /// The nearest binary angle to `degrees`, any number of turns either way,
    /// for tools and tests (the simulation never meets a float). Non-finite
    /// input gives 0.
    pub fn from_degrees(degrees: f64) -> Angle {
        let turns = degrees / 360.0;
        let fraction = turns - turns.floor();
        // A fraction that rounds up to a whole turn is angle 0: the u64 holds
        // 2^32 and the u32 keeps its low bits. NaN casts to 0.
        Angle((fraction * TURN).round() as u64 as u32)
    }
}

impl fmt::Debug for Angle {
    /// The bits and the degrees, e.g. `Angle(0x40000000 = 90°)`: a
    /// mismatch in sync shows in the bits, a wrong direction in the degrees.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Angle({:#010x} = {}°)", self.0, self.to_degrees())
    }
}

impl Add for Angle {
    type Output = Angle;
    fn add(self, rhs: Angle) -> Angle {
        Angle(self.0.wrapping_add(rhs.0))
    }
}

impl Sub for Angle {
    type Output = Angle;
    fn sub(self, rhs: Angle) -> Angle {
        Angle(self.0.wrapping_sub(rhs.0))
    }
}

impl AddAssign for Angle {
    fn add_assign(&mut self, rhs: Angle) {
        *self = *self + rhs;
    }
}

impl SubAssign for Angle {
    fn sub_assign(&mut self, rhs: Angle) {
        *self = *self - rhs;
    }
}

/// The opposite turn, `-angle` on an unsigned `angle_t`: `2^32 - angle`.
impl Neg for Angle {
    type Output = Angle;
    fn neg(self) -> Angle {
        Angle(self.0.wrapping_neg())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixed::number::FRACUNIT;

    #[test]
    fn constants_are_dooms() {
        assert_eq!(ANG1.0, 11_930_464);
        assert_eq!(ANG90.0, 1 << 30);
        assert_eq!(ANG180 + ANG180, Angle::ZERO);
        assert_eq!(ANG90 + ANG180, ANG270);
        assert_eq!(ANG_MAX + Angle(1), Angle::ZERO);
    }

    #[test]
    fn arithmetic_wraps_at_zero_and_a_full_turn() {
        assert_eq!(Angle(u32::MAX - 9) + Angle(20), Angle(10));
        assert_eq!(Angle(5) - Angle(10), Angle(u32::MAX - 4));
        assert_eq!(-Angle(1), ANG_MAX);
        assert_eq!(-Angle::ZERO, Angle::ZERO);
        assert_eq!(-ANG180, ANG180);
        let mut a = ANG270;
        a += ANG180;
        assert_eq!(a, ANG90);
        a -= ANG180;
        assert_eq!(a, ANG270);
    }

    #[test]
    fn fine_index_takes_the_top_13_bits() {
        assert_eq!(Angle::ZERO.fine_index(), 0);
        assert_eq!(Angle((1 << 19) - 1).fine_index(), 0);
        assert_eq!(Angle(1 << 19).fine_index(), 1);
        assert_eq!(ANG90.fine_index(), 2048);
        assert_eq!(ANG_MAX.fine_index(), 8191);
    }

    #[test]
    fn sine_and_cosine_read_the_fine_tables() {
        // finesine[0] and finesine[2048] in tables.c: the centre of the first
        // fine angle, not the angle itself, so sin(0) reads 25, not 0.
        assert_eq!(Angle::ZERO.sin(), Fixed(25));
        assert_eq!(Angle::ZERO.cos(), Fixed(FRACUNIT - 1));
        assert_eq!(ANG90.sin(), Fixed(FRACUNIT - 1));
        assert_eq!(ANG180.sin(), Fixed(-25));
        assert_eq!(ANG270.cos(), Fixed(25));
    }

    #[test]
    fn degrees_both_ways() {
        assert_eq!(ANG90.to_degrees(), 90.0);
        assert_eq!(ANG270.to_degrees(), 270.0);
        assert_eq!(Angle(1).to_degrees(), 360.0 / TURN);
        assert!(ANG_MAX.to_degrees() < 360.0);
        assert_eq!(Angle::from_degrees(45.0), ANG45);
        assert_eq!(Angle::from_degrees(-90.0), ANG270);
        assert_eq!(Angle::from_degrees(720.0 + 180.0), ANG180);
        assert_eq!(Angle::from_degrees(360.0 - 1e-12), Angle::ZERO);
        assert_eq!(Angle::from_degrees(f64::NAN), Angle::ZERO);
        for bits in [0, 1, 12345, ANG1.0, u32::MAX] {
            assert_eq!(Angle::from_degrees(Angle(bits).to_degrees()), Angle(bits));
        }
        assert_eq!(format!("{:?}", ANG90), "Angle(0x40000000 = 90°)");
    }
}
